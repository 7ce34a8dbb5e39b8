

module top(clock,r,q,ef,valid_in,round_up,y,valid_out);
    
    // Module arguments
    input wire  clock;
    input wire  [31:0] r;
    input wire  [3:0] q;
    input wire  [8:0] ef;
    input wire  valid_in;
    input wire  round_up;
    output reg  [31:0] y;
    output reg  valid_out;
    
    // Constant declarations
    localparam  c_f = 16'h17;
    localparam  c_b = 16'h4;
    
    // Stub signals
    reg  [31:0] s0_r$d;
    wire  [31:0] s0_r$q;
    reg  s0_r$clock;
    reg  [3:0] s0_q$d;
    wire  [3:0] s0_q$q;
    reg  s0_q$clock;
    reg  [8:0] s0_ef$d;
    wire  [8:0] s0_ef$q;
    reg  s0_ef$clock;
    reg  s0_valid$d;
    wire  s0_valid$q;
    reg  s0_valid$clock;
    reg  s0_round$d;
    wire  s0_round$q;
    reg  s0_round$clock;
    reg  r_add$clock;
    reg  r_add$d;
    wire  r_add$q;
    reg  add$clock;
    reg  [31:0] add$a;
    reg  [31:0] add$b;
    reg  add$sub;
    reg  add$valid_in;
    wire  [31:0] add$y;
    wire  add$valid_out;
    reg  add$round_up;
    
    // Local signals
    reg  [3:0] norm$0;
    reg  [3:0] norm$1;
    reg  [3:0] norm$2;
    reg  [3:0] norm$3;
    reg  [15:0] lz$0;
    reg  [15:0] lz$1;
    reg  [15:0] lz$2;
    reg  [15:0] lz$3;
    reg  [15:0] expo;
    reg  [22:0] frac;
    reg  [31:0] step;
    
    // Sub module instances
    top$add$s3_y s0_r(
        .d(s0_r$d),
        .q(s0_r$q),
        .clock(s0_r$clock)
    );
    top$s0_q s0_q(
        .d(s0_q$d),
        .q(s0_q$q),
        .clock(s0_q$clock)
    );
    top$s0_ef s0_ef(
        .d(s0_ef$d),
        .q(s0_ef$q),
        .clock(s0_ef$clock)
    );
    top$add$s1_eff_sub s0_valid(
        .d(s0_valid$d),
        .q(s0_valid$q),
        .clock(s0_valid$clock)
    );
    top$add$s1_eff_sub s0_round(
        .d(s0_round$d),
        .q(s0_round$q),
        .clock(s0_round$clock)
    );
    top$r_add r_add(
        .clock(r_add$clock),
        .d(r_add$d),
        .q(r_add$q)
    );
    top$add add(
        .clock(add$clock),
        .a(add$a),
        .b(add$b),
        .sub(add$sub),
        .valid_in(add$valid_in),
        .y(add$y),
        .valid_out(add$valid_out),
        .round_up(add$round_up)
    );
    
    // Update code
    always @(*) begin
        add$clock = clock;
        r_add$clock = clock;
        s0_r$clock = clock;
        s0_q$clock = clock;
        s0_ef$clock = clock;
        s0_valid$clock = clock;
        s0_round$clock = clock;
        s0_r$d = s0_r$q;
        s0_q$d = s0_q$q;
        s0_ef$d = s0_ef$q;
        s0_valid$d = s0_valid$q;
        s0_round$d = s0_round$q;
        s0_round$d = round_up;
        r_add$d = s0_round$q;
        add$round_up = r_add$q;
        s0_r$d = r;
        s0_q$d = q;
        s0_ef$d = ef;
        s0_valid$d = valid_in;
        norm$0 = s0_q$q;
        lz$0 = 32'h0;
        norm$1 = norm$0;
        lz$1 = lz$0;
        if (~norm$0[32'h4 - 32'h1]) begin
            norm$1 = norm$0 << 32'h1;
            lz$1 = lz$0 + 32'h1;
        end
        norm$2 = norm$1;
        lz$2 = lz$1;
        if (~norm$1[32'h4 - 32'h1]) begin
            norm$2 = norm$1 << 32'h1;
            lz$2 = lz$1 + 32'h1;
        end
        norm$3 = norm$2;
        lz$3 = lz$2;
        if (~norm$2[32'h4 - 32'h1]) begin
            norm$3 = norm$2 << 32'h1;
            lz$3 = lz$2 + 32'h1;
        end
        expo = 32'h0;
        frac = ((s0_q$q) & 23'h7fffff) << s0_ef$q;
        if (((s0_ef$q) & 16'hffff) + c_b > c_f + lz$3) begin
            expo = ((s0_ef$q) & 16'hffff) + c_b - lz$3 - c_f;
            frac = ((norm$3) & 23'h7fffff) << (32'h17 + 32'h1 - 32'h4);
        end
        step = (((expo) & 32'hffffffff) << 32'h17) | ((frac) & 32'hffffffff);
        if (s0_q$q == 32'h0) begin
            step = 32'h0;
        end
        add$a = s0_r$q;
        add$b = step;
        add$sub = 1'b1;
        add$valid_in = s0_valid$q;
        y = add$y;
        valid_out = add$valid_out;
    end
    
endmodule // top


module top$add(clock,a,b,sub,valid_in,y,valid_out,round_up);
    
    // Module arguments
    input wire  clock;
    input wire  [31:0] a;
    input wire  [31:0] b;
    input wire  sub;
    input wire  valid_in;
    output reg  [31:0] y;
    output reg  valid_out;
    input wire  round_up;
    
    // Constant declarations
    localparam  c_align_cap = 8'h1b;
    localparam  c_exp_ones = 10'b11111111;
    
    // Stub signals
    reg  [31:0] unpack_a$x;
    wire  unpack_a$sign;
    wire  [7:0] unpack_a$exp;
    wire  [23:0] unpack_a$sig;
    wire  unpack_a$is_zero;
    wire  unpack_a$is_inf;
    wire  unpack_a$is_nan;
    reg  [31:0] unpack_b$x;
    wire  unpack_b$sign;
    wire  [7:0] unpack_b$exp;
    wire  [23:0] unpack_b$sig;
    wire  unpack_b$is_zero;
    wire  unpack_b$is_inf;
    wire  unpack_b$is_nan;
    reg  s1_valid$d;
    wire  s1_valid$q;
    reg  s1_valid$clock;
    reg  s1_nan$d;
    wire  s1_nan$q;
    reg  s1_nan$clock;
    reg  s1_inf$d;
    wire  s1_inf$q;
    reg  s1_inf$clock;
    reg  s1_inf_sign$d;
    wire  s1_inf_sign$q;
    reg  s1_inf_sign$clock;
    reg  s1_zero_sign$d;
    wire  s1_zero_sign$q;
    reg  s1_zero_sign$clock;
    reg  s1_sign$d;
    wire  s1_sign$q;
    reg  s1_sign$clock;
    reg  s1_eff_sub$d;
    wire  s1_eff_sub$q;
    reg  s1_eff_sub$clock;
    reg  [7:0] s1_exp$d;
    wire  [7:0] s1_exp$q;
    reg  s1_exp$clock;
    reg  [26:0] s1_big$d;
    wire  [26:0] s1_big$q;
    reg  s1_big$clock;
    reg  [26:0] s1_small$d;
    wire  [26:0] s1_small$q;
    reg  s1_small$clock;
    reg  [26:0] norm$x;
    wire  [26:0] norm$y;
    wire  [4:0] norm$lz;
    reg  s2_valid$d;
    wire  s2_valid$q;
    reg  s2_valid$clock;
    reg  s2_sign$d;
    wire  s2_sign$q;
    reg  s2_sign$clock;
    reg  s2_nan$d;
    wire  s2_nan$q;
    reg  s2_nan$clock;
    reg  s2_inf$d;
    wire  s2_inf$q;
    reg  s2_inf$clock;
    reg  s2_zero$d;
    wire  s2_zero$q;
    reg  s2_zero$clock;
    reg  s2_ovf$d;
    wire  s2_ovf$q;
    reg  s2_ovf$clock;
    reg  [7:0] s2_efield$d;
    wire  [7:0] s2_efield$q;
    reg  s2_efield$clock;
    reg  [25:0] s2_nm$d;
    wire  [25:0] s2_nm$q;
    reg  s2_nm$clock;
    reg  round$round_up;
    reg  round$sign;
    reg  round$nan;
    reg  round$inf;
    reg  round$zero;
    reg  round$ovf;
    reg  [7:0] round$efield;
    reg  [25:0] round$nm;
    wire  [31:0] round$y;
    reg  s3_valid$d;
    wire  s3_valid$q;
    reg  s3_valid$clock;
    reg  [31:0] s3_y$d;
    wire  [31:0] s3_y$q;
    reg  s3_y$clock;
    
    // Local signals
    reg  c1_b_sign;
    reg  c1_swap;
    reg  c1_big_sign;
    reg  [7:0] c1_big_exp;
    reg  [23:0] c1_big_sig;
    reg  c1_small_sign;
    reg  [7:0] c1_small_exp;
    reg  [23:0] c1_small_sig;
    reg  [7:0] c1_diff;
    reg  [7:0] c1_shift;
    reg  [26:0] c1_small_ext;
    reg  [26:0] c1_aligned;
    reg  [26:0] c1_back;
    reg  c1_lost;
    reg  c1_inf_sign;
    reg  [27:0] c2_sum;
    reg  c2_carry;
    reg  c2_zero;
    reg  [7:0] c2_limit;
    reg  [7:0] c2_lz;
    reg  [7:0] c2_shift;
    reg  [26:0] c2_shifted;
    reg  [9:0] c2_exp;
    reg  [25:0] c2_nm;
    reg  c2_sign;
    
    // Sub module instances
    top$add$unpack_a unpack_a(
        .x(unpack_a$x),
        .sign(unpack_a$sign),
        .exp(unpack_a$exp),
        .sig(unpack_a$sig),
        .is_zero(unpack_a$is_zero),
        .is_inf(unpack_a$is_inf),
        .is_nan(unpack_a$is_nan)
    );
    top$add$unpack_a unpack_b(
        .x(unpack_b$x),
        .sign(unpack_b$sign),
        .exp(unpack_b$exp),
        .sig(unpack_b$sig),
        .is_zero(unpack_b$is_zero),
        .is_inf(unpack_b$is_inf),
        .is_nan(unpack_b$is_nan)
    );
    top$add$s1_eff_sub s1_valid(
        .d(s1_valid$d),
        .q(s1_valid$q),
        .clock(s1_valid$clock)
    );
    top$add$s1_eff_sub s1_nan(
        .d(s1_nan$d),
        .q(s1_nan$q),
        .clock(s1_nan$clock)
    );
    top$add$s1_eff_sub s1_inf(
        .d(s1_inf$d),
        .q(s1_inf$q),
        .clock(s1_inf$clock)
    );
    top$add$s1_eff_sub s1_inf_sign(
        .d(s1_inf_sign$d),
        .q(s1_inf_sign$q),
        .clock(s1_inf_sign$clock)
    );
    top$add$s1_eff_sub s1_zero_sign(
        .d(s1_zero_sign$d),
        .q(s1_zero_sign$q),
        .clock(s1_zero_sign$clock)
    );
    top$add$s1_eff_sub s1_sign(
        .d(s1_sign$d),
        .q(s1_sign$q),
        .clock(s1_sign$clock)
    );
    top$add$s1_eff_sub s1_eff_sub(
        .d(s1_eff_sub$d),
        .q(s1_eff_sub$q),
        .clock(s1_eff_sub$clock)
    );
    top$add$s1_exp s1_exp(
        .d(s1_exp$d),
        .q(s1_exp$q),
        .clock(s1_exp$clock)
    );
    top$add$s1_big s1_big(
        .d(s1_big$d),
        .q(s1_big$q),
        .clock(s1_big$clock)
    );
    top$add$s1_big s1_small(
        .d(s1_small$d),
        .q(s1_small$q),
        .clock(s1_small$clock)
    );
    top$add$norm norm(
        .x(norm$x),
        .y(norm$y),
        .lz(norm$lz)
    );
    top$add$s1_eff_sub s2_valid(
        .d(s2_valid$d),
        .q(s2_valid$q),
        .clock(s2_valid$clock)
    );
    top$add$s1_eff_sub s2_sign(
        .d(s2_sign$d),
        .q(s2_sign$q),
        .clock(s2_sign$clock)
    );
    top$add$s1_eff_sub s2_nan(
        .d(s2_nan$d),
        .q(s2_nan$q),
        .clock(s2_nan$clock)
    );
    top$add$s1_eff_sub s2_inf(
        .d(s2_inf$d),
        .q(s2_inf$q),
        .clock(s2_inf$clock)
    );
    top$add$s1_eff_sub s2_zero(
        .d(s2_zero$d),
        .q(s2_zero$q),
        .clock(s2_zero$clock)
    );
    top$add$s1_eff_sub s2_ovf(
        .d(s2_ovf$d),
        .q(s2_ovf$q),
        .clock(s2_ovf$clock)
    );
    top$add$s1_exp s2_efield(
        .d(s2_efield$d),
        .q(s2_efield$q),
        .clock(s2_efield$clock)
    );
    top$add$s2_nm s2_nm(
        .d(s2_nm$d),
        .q(s2_nm$q),
        .clock(s2_nm$clock)
    );
    top$add$round round(
        .round_up(round$round_up),
        .sign(round$sign),
        .nan(round$nan),
        .inf(round$inf),
        .zero(round$zero),
        .ovf(round$ovf),
        .efield(round$efield),
        .nm(round$nm),
        .y(round$y)
    );
    top$add$s1_eff_sub s3_valid(
        .d(s3_valid$d),
        .q(s3_valid$q),
        .clock(s3_valid$clock)
    );
    top$add$s3_y s3_y(
        .d(s3_y$d),
        .q(s3_y$q),
        .clock(s3_y$clock)
    );
    
    // Update code
    always @(*) begin
        s1_valid$clock = clock;
        s1_nan$clock = clock;
        s1_inf$clock = clock;
        s1_inf_sign$clock = clock;
        s1_zero_sign$clock = clock;
        s1_sign$clock = clock;
        s1_eff_sub$clock = clock;
        s1_exp$clock = clock;
        s1_big$clock = clock;
        s1_small$clock = clock;
        s1_valid$d = s1_valid$q;
        s1_nan$d = s1_nan$q;
        s1_inf$d = s1_inf$q;
        s1_inf_sign$d = s1_inf_sign$q;
        s1_zero_sign$d = s1_zero_sign$q;
        s1_sign$d = s1_sign$q;
        s1_eff_sub$d = s1_eff_sub$q;
        s1_exp$d = s1_exp$q;
        s1_big$d = s1_big$q;
        s1_small$d = s1_small$q;
        s2_valid$clock = clock;
        s2_sign$clock = clock;
        s2_nan$clock = clock;
        s2_inf$clock = clock;
        s2_zero$clock = clock;
        s2_ovf$clock = clock;
        s2_efield$clock = clock;
        s2_nm$clock = clock;
        s2_valid$d = s2_valid$q;
        s2_sign$d = s2_sign$q;
        s2_nan$d = s2_nan$q;
        s2_inf$d = s2_inf$q;
        s2_zero$d = s2_zero$q;
        s2_ovf$d = s2_ovf$q;
        s2_efield$d = s2_efield$q;
        s2_nm$d = s2_nm$q;
        s3_valid$clock = clock;
        s3_y$clock = clock;
        s3_valid$d = s3_valid$q;
        s3_y$d = s3_y$q;
        unpack_a$x = a;
        unpack_b$x = b;
        c1_b_sign = unpack_b$sign ^ sub;
        c1_swap = a[(32'h0)+:(31)] < b[(32'h0)+:(31)];
        c1_big_sign = unpack_a$sign;
        c1_big_exp = unpack_a$exp;
        c1_big_sig = unpack_a$sig;
        c1_small_sign = c1_b_sign;
        c1_small_exp = unpack_b$exp;
        c1_small_sig = unpack_b$sig;
        if (c1_swap) begin
            c1_big_sign = c1_b_sign;
            c1_big_exp = unpack_b$exp;
            c1_big_sig = unpack_b$sig;
            c1_small_sign = unpack_a$sign;
            c1_small_exp = unpack_a$exp;
            c1_small_sig = unpack_a$sig;
        end
        c1_diff = c1_big_exp - c1_small_exp;
        c1_shift = c1_diff;
        if (c1_diff > c_align_cap) begin
            c1_shift = c_align_cap;
        end
        c1_small_ext = ((c1_small_sig) & 27'h7ffffff) << 32'h3;
        c1_aligned = c1_small_ext >> c1_shift;
        c1_back = c1_aligned << c1_shift;
        c1_lost = c1_back != c1_small_ext;
        c1_inf_sign = c1_b_sign;
        if (unpack_a$is_inf) begin
            c1_inf_sign = unpack_a$sign;
        end
        s1_valid$d = valid_in;
        s1_nan$d = unpack_a$is_nan | unpack_b$is_nan | (unpack_a$is_inf & unpack_b$is_inf & (unpack_a$sign ^ c1_b_sign));
        s1_inf$d = unpack_a$is_inf | unpack_b$is_inf;
        s1_inf_sign$d = c1_inf_sign;
        s1_zero_sign$d = unpack_a$sign & c1_b_sign;
        s1_sign$d = c1_big_sign;
        s1_eff_sub$d = c1_big_sign ^ c1_small_sign;
        s1_exp$d = c1_big_exp;
        s1_big$d = ((c1_big_sig) & 27'h7ffffff) << 32'h3;
        s1_small$d = (c1_aligned & ~(1 << (32'h0)) | ((c1_aligned[32'h0] | c1_lost) << (32'h0)));
        c2_sum = ((s1_big$q) & 28'hfffffff) + ((s1_small$q) & 28'hfffffff);
        if (s1_eff_sub$q) begin
            c2_sum = ((s1_big$q) & 28'hfffffff) - ((s1_small$q) & 28'hfffffff);
        end
        c2_carry = c2_sum[32'h1b];
        c2_zero = c2_sum == 32'h0;
        norm$x = c2_sum[(32'h0)+:(27)];
        c2_limit = s1_exp$q - 32'h1;
        c2_lz = ((norm$lz) & 8'hff);
        c2_shift = c2_lz;
        if (c2_lz > c2_limit) begin
            c2_shift = c2_limit;
        end
        c2_shifted = c2_sum[(32'h0)+:(27)] << c2_shift;
        c2_exp = ((s1_exp$q) & 10'h3ff) - ((c2_shift) & 10'h3ff);
        c2_nm = (((c2_shifted >> 32'h1) & 26'h3ffffff) & ~(1 << (32'h0)) | ((c2_shifted[32'h1] | c2_shifted[32'h0]) << (32'h0)));
        if (c2_carry) begin
            c2_exp = ((s1_exp$q) & 10'h3ff) + 32'h1;
            c2_nm = (((c2_sum >> 32'h2) & 26'h3ffffff) & ~(1 << (32'h0)) | ((c2_sum[32'h2] | c2_sum[32'h1] | c2_sum[32'h0]) << (32'h0)));
        end
        c2_sign = s1_sign$q;
        if (c2_zero) begin
            c2_sign = s1_zero_sign$q;
        end
        if (s1_inf$q) begin
            c2_sign = s1_inf_sign$q;
        end
        s2_valid$d = s1_valid$q;
        s2_sign$d = c2_sign;
        s2_nan$d = s1_nan$q;
        s2_inf$d = s1_inf$q;
        s2_zero$d = c2_zero;
        s2_ovf$d = c2_exp >= c_exp_ones;
        s2_efield$d = 32'h0;
        if (c2_nm[32'h18 + 32'h1]) begin
            s2_efield$d = ((c2_exp) & 8'hff);
        end
        s2_nm$d = c2_nm;
        round$round_up = round_up;
        round$sign = s2_sign$q;
        round$nan = s2_nan$q;
        round$inf = s2_inf$q;
        round$zero = s2_zero$q;
        round$ovf = s2_ovf$q;
        round$efield = s2_efield$q;
        round$nm = s2_nm$q;
        s3_valid$d = s2_valid$q;
        s3_y$d = round$y;
        y = s3_y$q;
        valid_out = s3_valid$q;
    end
    
endmodule // top$add


module top$add$norm(x,y,lz);
    
    // Module arguments
    input wire  [26:0] x;
    output reg  [26:0] y;
    output reg  [4:0] lz;
    
    // Local signals
    reg  z16;
    reg  z8;
    reg  z4;
    reg  z2;
    reg  z1;
    reg  [26:0] x16;
    reg  [26:0] x8;
    reg  [26:0] x4;
    reg  [26:0] x2;
    
    // Update code
    always @(*) begin
        z16 = x[(32'hb)+:(16)] == 32'h0;
        x16 = x;
        if (z16) begin
            x16 = x << 32'h10;
        end
        z8 = x16[(32'h13)+:(8)] == 32'h0;
        x8 = x16;
        if (z8) begin
            x8 = x16 << 32'h8;
        end
        z4 = x8[(32'h17)+:(4)] == 32'h0;
        x4 = x8;
        if (z4) begin
            x4 = x8 << 32'h4;
        end
        z2 = x4[(32'h19)+:(2)] == 32'h0;
        x2 = x4;
        if (z2) begin
            x2 = x4 << 32'h2;
        end
        z1 = ~x2[32'h1a];
        y = x2;
        if (z1) begin
            y = x2 << 32'h1;
        end
        lz = (((((((32'h0) & 5'h1f) & ~(1 << (32'h4)) | ((z16) << (32'h4))) & ~(1 << (32'h3)) | ((z8) << (32'h3))) & ~(1 << (32'h2)) | ((z4) << (32'h2))) & ~(1 << (32'h1)) | ((z2) << (32'h1))) & ~(1 << (32'h0)) | ((z1) << (32'h0)));
    end
    
endmodule // top$add$norm


module top$add$round(round_up,sign,nan,inf,zero,ovf,efield,nm,y);
    
    // Module arguments
    input wire  round_up;
    input wire  sign;
    input wire  nan;
    input wire  inf;
    input wire  zero;
    input wire  ovf;
    input wire  [7:0] efield;
    input wire  [25:0] nm;
    output reg  [31:0] y;
    
    // Constant declarations
    localparam  c_nan = 32'h7fc00000;
    localparam  c_sign = 32'h80000000;
    localparam  c_inf = 31'h7f800000;
    localparam  c_max_finite = 31'h7f7fffff;
    
    // Local signals
    reg  lsb;
    reg  guard;
    reg  sticky;
    reg  inc;
    reg  [30:0] pack_word;
    reg  [30:0] rounded;
    reg  rexp_ones;
    reg  [30:0] mag;
    
    // Update code
    always @(*) begin
        lsb = nm[32'h2];
        guard = nm[32'h1];
        sticky = nm[32'h0];
        inc = guard & (sticky | lsb);
        if (round_up) begin
            inc = ~sign & (guard | sticky);
        end
        pack_word = (((efield) & 31'h7fffffff) << 32'h17) | ((nm[(32'h2)+:(23)]) & 31'h7fffffff);
        rounded = pack_word + inc;
        rexp_ones = &rounded[(32'h17)+:(8)];
        mag = rounded;
        if (ovf | rexp_ones) begin
            mag = c_inf;
            if (round_up & sign) begin
                mag = c_max_finite;
            end
        end
        if (zero) begin
            mag = 32'h0;
        end
        if (inf) begin
            mag = c_inf;
        end
        y = ((mag) & 32'hffffffff);
        if (sign) begin
            y = ((mag) & 32'hffffffff) | c_sign;
        end
        if (nan) begin
            y = c_nan;
        end
    end
    
endmodule // top$add$round


module top$add$s1_big(d,q,clock);
    
    // Module arguments
    input wire  [26:0] d;
    output reg  [26:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 27'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$add$s1_big


module top$add$s1_eff_sub(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$add$s1_eff_sub


module top$add$s1_exp(d,q,clock);
    
    // Module arguments
    input wire  [7:0] d;
    output reg  [7:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 8'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$add$s1_exp


module top$add$s2_nm(d,q,clock);
    
    // Module arguments
    input wire  [25:0] d;
    output reg  [25:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 26'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$add$s2_nm


module top$add$s3_y(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$add$s3_y


module top$add$unpack_a(x,sign,exp,sig,is_zero,is_inf,is_nan);
    
    // Module arguments
    input wire  [31:0] x;
    output reg  sign;
    output reg  [7:0] exp;
    output reg  [23:0] sig;
    output reg  is_zero;
    output reg  is_inf;
    output reg  is_nan;
    
    // Local signals
    reg  [7:0] field;
    reg  [22:0] frac;
    reg  exp_zero;
    reg  exp_ones;
    reg  frac_zero;
    
    // Update code
    always @(*) begin
        field = x[(32'h17)+:(8)];
        frac = x[(32'h0)+:(23)];
        sign = x[32'h1f];
        exp_zero = field == 32'h0;
        exp_ones = &field;
        frac_zero = frac == 32'h0;
        is_zero = exp_zero & frac_zero;
        is_inf = exp_ones & frac_zero;
        is_nan = exp_ones & ~frac_zero;
        exp = field;
        sig = (((frac) & 24'hffffff) & ~(1 << (32'h17)) | ((1'b1) << (32'h17)));
        if (exp_zero) begin
            exp = 32'h1;
            sig = ((frac) & 24'hffffff);
        end
    end
    
endmodule // top$add$unpack_a


module top$r_add(clock,d,q);
    
    // Module arguments
    input wire  clock;
    input wire  d;
    output reg  q;
    
    // Stub signals
    reg  line$0$d;
    wire  line$0$q;
    reg  line$0$clock;
    reg  line$1$d;
    wire  line$1$q;
    reg  line$1$clock;
    
    // Sub module instances
    top$add$s1_eff_sub line$0(
        .d(line$0$d),
        .q(line$0$q),
        .clock(line$0$clock)
    );
    top$add$s1_eff_sub line$1(
        .d(line$1$d),
        .q(line$1$q),
        .clock(line$1$clock)
    );
    
    // Update code
    always @(*) begin
        line$0$clock = clock;
        line$0$d = d;
        line$1$clock = clock;
        line$1$d = d;
        line$0$d = line$1$q;
        q = line$0$q;
    end
    
endmodule // top$r_add


module top$s0_ef(d,q,clock);
    
    // Module arguments
    input wire  [8:0] d;
    output reg  [8:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 9'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$s0_ef


module top$s0_q(d,q,clock);
    
    // Module arguments
    input wire  [3:0] d;
    output reg  [3:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 4'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$s0_q
