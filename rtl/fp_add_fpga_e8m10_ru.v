

module top(clock,a,b,sub,valid_in,y,valid_out);
    
    // Module arguments
    input wire  clock;
    input wire  [18:0] a;
    input wire  [18:0] b;
    input wire  sub;
    input wire  valid_in;
    output reg  [18:0] y;
    output reg  valid_out;
    
    // Constant declarations
    localparam  round_up = 1'b1;
    localparam  c_align_cap = 8'he;
    localparam  c_exp_ones = 10'b11111111;
    localparam  c_ones = 14'b11111111111111;
    localparam  c_top = 14'b10000000000000;
    
    // Stub signals
    reg  [18:0] unpack_a$x;
    wire  unpack_a$sign;
    wire  [7:0] unpack_a$exp;
    wire  [10:0] unpack_a$sig;
    wire  unpack_a$is_zero;
    wire  unpack_a$is_inf;
    wire  unpack_a$is_nan;
    reg  [18:0] unpack_b$x;
    wire  unpack_b$sign;
    wire  [7:0] unpack_b$exp;
    wire  [10:0] unpack_b$sig;
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
    reg  [10:0] s1_big$d;
    wire  [10:0] s1_big$q;
    reg  s1_big$clock;
    reg  [10:0] s1_small$d;
    wire  [10:0] s1_small$q;
    reg  s1_small$clock;
    reg  [7:0] s1_shift$d;
    wire  [7:0] s1_shift$q;
    reg  s1_shift$clock;
    reg  s2_valid$d;
    wire  s2_valid$q;
    reg  s2_valid$clock;
    reg  s2_nan$d;
    wire  s2_nan$q;
    reg  s2_nan$clock;
    reg  s2_inf$d;
    wire  s2_inf$q;
    reg  s2_inf$clock;
    reg  s2_inf_sign$d;
    wire  s2_inf_sign$q;
    reg  s2_inf_sign$clock;
    reg  s2_zero_sign$d;
    wire  s2_zero_sign$q;
    reg  s2_zero_sign$clock;
    reg  s2_sign$d;
    wire  s2_sign$q;
    reg  s2_sign$clock;
    reg  s2_eff_sub$d;
    wire  s2_eff_sub$q;
    reg  s2_eff_sub$clock;
    reg  [7:0] s2_exp$d;
    wire  [7:0] s2_exp$q;
    reg  s2_exp$clock;
    reg  [13:0] s2_big$d;
    wire  [13:0] s2_big$q;
    reg  s2_big$clock;
    reg  [13:0] s2_small$d;
    wire  [13:0] s2_small$q;
    reg  s2_small$clock;
    reg  s3_valid$d;
    wire  s3_valid$q;
    reg  s3_valid$clock;
    reg  s3_nan$d;
    wire  s3_nan$q;
    reg  s3_nan$clock;
    reg  s3_inf$d;
    wire  s3_inf$q;
    reg  s3_inf$clock;
    reg  s3_inf_sign$d;
    wire  s3_inf_sign$q;
    reg  s3_inf_sign$clock;
    reg  s3_zero_sign$d;
    wire  s3_zero_sign$q;
    reg  s3_zero_sign$clock;
    reg  s3_sign$d;
    wire  s3_sign$q;
    reg  s3_sign$clock;
    reg  [7:0] s3_exp$d;
    wire  [7:0] s3_exp$q;
    reg  s3_exp$clock;
    reg  [14:0] s3_sum$d;
    wire  [14:0] s3_sum$q;
    reg  s3_sum$clock;
    reg  [13:0] s3_marker$d;
    wire  [13:0] s3_marker$q;
    reg  s3_marker$clock;
    reg  [13:0] lzc$x;
    wire  [4:0] lzc$lz;
    reg  s4_valid$d;
    wire  s4_valid$q;
    reg  s4_valid$clock;
    reg  s4_sign$d;
    wire  s4_sign$q;
    reg  s4_sign$clock;
    reg  s4_nan$d;
    wire  s4_nan$q;
    reg  s4_nan$clock;
    reg  s4_inf$d;
    wire  s4_inf$q;
    reg  s4_inf$clock;
    reg  s4_zero$d;
    wire  s4_zero$q;
    reg  s4_zero$clock;
    reg  [7:0] s4_exp$d;
    wire  [7:0] s4_exp$q;
    reg  s4_exp$clock;
    reg  [7:0] s4_shift$d;
    wire  [7:0] s4_shift$q;
    reg  s4_shift$clock;
    reg  [14:0] s4_sum$d;
    wire  [14:0] s4_sum$q;
    reg  s4_sum$clock;
    reg  s5_valid$d;
    wire  s5_valid$q;
    reg  s5_valid$clock;
    reg  s5_sign$d;
    wire  s5_sign$q;
    reg  s5_sign$clock;
    reg  s5_nan$d;
    wire  s5_nan$q;
    reg  s5_nan$clock;
    reg  s5_inf$d;
    wire  s5_inf$q;
    reg  s5_inf$clock;
    reg  s5_zero$d;
    wire  s5_zero$q;
    reg  s5_zero$clock;
    reg  s5_ovf$d;
    wire  s5_ovf$q;
    reg  s5_ovf$clock;
    reg  [7:0] s5_efield$d;
    wire  [7:0] s5_efield$q;
    reg  s5_efield$clock;
    reg  [12:0] s5_nm$d;
    wire  [12:0] s5_nm$q;
    reg  s5_nm$clock;
    reg  round$round_up;
    reg  round$sign;
    reg  round$nan;
    reg  round$inf;
    reg  round$zero;
    reg  round$ovf;
    reg  [7:0] round$efield;
    reg  [12:0] round$nm;
    wire  [18:0] round$y;
    reg  s6_valid$d;
    wire  s6_valid$q;
    reg  s6_valid$clock;
    reg  [18:0] s6_y$d;
    wire  [18:0] s6_y$q;
    reg  s6_y$clock;
    
    // Local signals
    reg  c1_b_sign;
    reg  c1_swap;
    reg  [7:0] c1_d_ab;
    reg  [7:0] c1_d_ba;
    reg  [7:0] c1_sh_ab;
    reg  [7:0] c1_sh_ba;
    reg  c1_inf_sign;
    reg  [13:0] c2_small_ext;
    reg  [13:0] c2_aligned;
    reg  [13:0] c2_mask;
    reg  c2_lost;
    reg  [14:0] c3_sum;
    reg  [7:0] c3_limit;
    reg  c4_zero;
    reg  c4_sign;
    reg  [13:0] c5_shifted;
    reg  [9:0] c5_exp;
    reg  [12:0] c5_nm;
    
    // Sub module instances
    top$unpack_a unpack_a(
        .x(unpack_a$x),
        .sign(unpack_a$sign),
        .exp(unpack_a$exp),
        .sig(unpack_a$sig),
        .is_zero(unpack_a$is_zero),
        .is_inf(unpack_a$is_inf),
        .is_nan(unpack_a$is_nan)
    );
    top$unpack_a unpack_b(
        .x(unpack_b$x),
        .sign(unpack_b$sign),
        .exp(unpack_b$exp),
        .sig(unpack_b$sig),
        .is_zero(unpack_b$is_zero),
        .is_inf(unpack_b$is_inf),
        .is_nan(unpack_b$is_nan)
    );
    top$s1_eff_sub s1_valid(
        .d(s1_valid$d),
        .q(s1_valid$q),
        .clock(s1_valid$clock)
    );
    top$s1_eff_sub s1_nan(
        .d(s1_nan$d),
        .q(s1_nan$q),
        .clock(s1_nan$clock)
    );
    top$s1_eff_sub s1_inf(
        .d(s1_inf$d),
        .q(s1_inf$q),
        .clock(s1_inf$clock)
    );
    top$s1_eff_sub s1_inf_sign(
        .d(s1_inf_sign$d),
        .q(s1_inf_sign$q),
        .clock(s1_inf_sign$clock)
    );
    top$s1_eff_sub s1_zero_sign(
        .d(s1_zero_sign$d),
        .q(s1_zero_sign$q),
        .clock(s1_zero_sign$clock)
    );
    top$s1_eff_sub s1_sign(
        .d(s1_sign$d),
        .q(s1_sign$q),
        .clock(s1_sign$clock)
    );
    top$s1_eff_sub s1_eff_sub(
        .d(s1_eff_sub$d),
        .q(s1_eff_sub$q),
        .clock(s1_eff_sub$clock)
    );
    top$s1_exp s1_exp(
        .d(s1_exp$d),
        .q(s1_exp$q),
        .clock(s1_exp$clock)
    );
    top$s1_big s1_big(
        .d(s1_big$d),
        .q(s1_big$q),
        .clock(s1_big$clock)
    );
    top$s1_big s1_small(
        .d(s1_small$d),
        .q(s1_small$q),
        .clock(s1_small$clock)
    );
    top$s1_exp s1_shift(
        .d(s1_shift$d),
        .q(s1_shift$q),
        .clock(s1_shift$clock)
    );
    top$s1_eff_sub s2_valid(
        .d(s2_valid$d),
        .q(s2_valid$q),
        .clock(s2_valid$clock)
    );
    top$s1_eff_sub s2_nan(
        .d(s2_nan$d),
        .q(s2_nan$q),
        .clock(s2_nan$clock)
    );
    top$s1_eff_sub s2_inf(
        .d(s2_inf$d),
        .q(s2_inf$q),
        .clock(s2_inf$clock)
    );
    top$s1_eff_sub s2_inf_sign(
        .d(s2_inf_sign$d),
        .q(s2_inf_sign$q),
        .clock(s2_inf_sign$clock)
    );
    top$s1_eff_sub s2_zero_sign(
        .d(s2_zero_sign$d),
        .q(s2_zero_sign$q),
        .clock(s2_zero_sign$clock)
    );
    top$s1_eff_sub s2_sign(
        .d(s2_sign$d),
        .q(s2_sign$q),
        .clock(s2_sign$clock)
    );
    top$s1_eff_sub s2_eff_sub(
        .d(s2_eff_sub$d),
        .q(s2_eff_sub$q),
        .clock(s2_eff_sub$clock)
    );
    top$s1_exp s2_exp(
        .d(s2_exp$d),
        .q(s2_exp$q),
        .clock(s2_exp$clock)
    );
    top$s2_big s2_big(
        .d(s2_big$d),
        .q(s2_big$q),
        .clock(s2_big$clock)
    );
    top$s2_big s2_small(
        .d(s2_small$d),
        .q(s2_small$q),
        .clock(s2_small$clock)
    );
    top$s1_eff_sub s3_valid(
        .d(s3_valid$d),
        .q(s3_valid$q),
        .clock(s3_valid$clock)
    );
    top$s1_eff_sub s3_nan(
        .d(s3_nan$d),
        .q(s3_nan$q),
        .clock(s3_nan$clock)
    );
    top$s1_eff_sub s3_inf(
        .d(s3_inf$d),
        .q(s3_inf$q),
        .clock(s3_inf$clock)
    );
    top$s1_eff_sub s3_inf_sign(
        .d(s3_inf_sign$d),
        .q(s3_inf_sign$q),
        .clock(s3_inf_sign$clock)
    );
    top$s1_eff_sub s3_zero_sign(
        .d(s3_zero_sign$d),
        .q(s3_zero_sign$q),
        .clock(s3_zero_sign$clock)
    );
    top$s1_eff_sub s3_sign(
        .d(s3_sign$d),
        .q(s3_sign$q),
        .clock(s3_sign$clock)
    );
    top$s1_exp s3_exp(
        .d(s3_exp$d),
        .q(s3_exp$q),
        .clock(s3_exp$clock)
    );
    top$s3_sum s3_sum(
        .d(s3_sum$d),
        .q(s3_sum$q),
        .clock(s3_sum$clock)
    );
    top$s2_big s3_marker(
        .d(s3_marker$d),
        .q(s3_marker$q),
        .clock(s3_marker$clock)
    );
    top$lzc lzc(
        .x(lzc$x),
        .lz(lzc$lz)
    );
    top$s1_eff_sub s4_valid(
        .d(s4_valid$d),
        .q(s4_valid$q),
        .clock(s4_valid$clock)
    );
    top$s1_eff_sub s4_sign(
        .d(s4_sign$d),
        .q(s4_sign$q),
        .clock(s4_sign$clock)
    );
    top$s1_eff_sub s4_nan(
        .d(s4_nan$d),
        .q(s4_nan$q),
        .clock(s4_nan$clock)
    );
    top$s1_eff_sub s4_inf(
        .d(s4_inf$d),
        .q(s4_inf$q),
        .clock(s4_inf$clock)
    );
    top$s1_eff_sub s4_zero(
        .d(s4_zero$d),
        .q(s4_zero$q),
        .clock(s4_zero$clock)
    );
    top$s1_exp s4_exp(
        .d(s4_exp$d),
        .q(s4_exp$q),
        .clock(s4_exp$clock)
    );
    top$s1_exp s4_shift(
        .d(s4_shift$d),
        .q(s4_shift$q),
        .clock(s4_shift$clock)
    );
    top$s3_sum s4_sum(
        .d(s4_sum$d),
        .q(s4_sum$q),
        .clock(s4_sum$clock)
    );
    top$s1_eff_sub s5_valid(
        .d(s5_valid$d),
        .q(s5_valid$q),
        .clock(s5_valid$clock)
    );
    top$s1_eff_sub s5_sign(
        .d(s5_sign$d),
        .q(s5_sign$q),
        .clock(s5_sign$clock)
    );
    top$s1_eff_sub s5_nan(
        .d(s5_nan$d),
        .q(s5_nan$q),
        .clock(s5_nan$clock)
    );
    top$s1_eff_sub s5_inf(
        .d(s5_inf$d),
        .q(s5_inf$q),
        .clock(s5_inf$clock)
    );
    top$s1_eff_sub s5_zero(
        .d(s5_zero$d),
        .q(s5_zero$q),
        .clock(s5_zero$clock)
    );
    top$s1_eff_sub s5_ovf(
        .d(s5_ovf$d),
        .q(s5_ovf$q),
        .clock(s5_ovf$clock)
    );
    top$s1_exp s5_efield(
        .d(s5_efield$d),
        .q(s5_efield$q),
        .clock(s5_efield$clock)
    );
    top$s5_nm s5_nm(
        .d(s5_nm$d),
        .q(s5_nm$q),
        .clock(s5_nm$clock)
    );
    top$round round(
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
    top$s1_eff_sub s6_valid(
        .d(s6_valid$d),
        .q(s6_valid$q),
        .clock(s6_valid$clock)
    );
    top$s6_y s6_y(
        .d(s6_y$d),
        .q(s6_y$q),
        .clock(s6_y$clock)
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
        s1_shift$clock = clock;
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
        s1_shift$d = s1_shift$q;
        s2_valid$clock = clock;
        s2_nan$clock = clock;
        s2_inf$clock = clock;
        s2_inf_sign$clock = clock;
        s2_zero_sign$clock = clock;
        s2_sign$clock = clock;
        s2_eff_sub$clock = clock;
        s2_exp$clock = clock;
        s2_big$clock = clock;
        s2_small$clock = clock;
        s2_valid$d = s2_valid$q;
        s2_nan$d = s2_nan$q;
        s2_inf$d = s2_inf$q;
        s2_inf_sign$d = s2_inf_sign$q;
        s2_zero_sign$d = s2_zero_sign$q;
        s2_sign$d = s2_sign$q;
        s2_eff_sub$d = s2_eff_sub$q;
        s2_exp$d = s2_exp$q;
        s2_big$d = s2_big$q;
        s2_small$d = s2_small$q;
        s3_valid$clock = clock;
        s3_nan$clock = clock;
        s3_inf$clock = clock;
        s3_inf_sign$clock = clock;
        s3_zero_sign$clock = clock;
        s3_sign$clock = clock;
        s3_exp$clock = clock;
        s3_sum$clock = clock;
        s3_marker$clock = clock;
        s3_valid$d = s3_valid$q;
        s3_nan$d = s3_nan$q;
        s3_inf$d = s3_inf$q;
        s3_inf_sign$d = s3_inf_sign$q;
        s3_zero_sign$d = s3_zero_sign$q;
        s3_sign$d = s3_sign$q;
        s3_exp$d = s3_exp$q;
        s3_sum$d = s3_sum$q;
        s3_marker$d = s3_marker$q;
        s4_valid$clock = clock;
        s4_sign$clock = clock;
        s4_nan$clock = clock;
        s4_inf$clock = clock;
        s4_zero$clock = clock;
        s4_exp$clock = clock;
        s4_shift$clock = clock;
        s4_sum$clock = clock;
        s4_valid$d = s4_valid$q;
        s4_sign$d = s4_sign$q;
        s4_nan$d = s4_nan$q;
        s4_inf$d = s4_inf$q;
        s4_zero$d = s4_zero$q;
        s4_exp$d = s4_exp$q;
        s4_shift$d = s4_shift$q;
        s4_sum$d = s4_sum$q;
        s5_valid$clock = clock;
        s5_sign$clock = clock;
        s5_nan$clock = clock;
        s5_inf$clock = clock;
        s5_zero$clock = clock;
        s5_ovf$clock = clock;
        s5_efield$clock = clock;
        s5_nm$clock = clock;
        s5_valid$d = s5_valid$q;
        s5_sign$d = s5_sign$q;
        s5_nan$d = s5_nan$q;
        s5_inf$d = s5_inf$q;
        s5_zero$d = s5_zero$q;
        s5_ovf$d = s5_ovf$q;
        s5_efield$d = s5_efield$q;
        s5_nm$d = s5_nm$q;
        s6_valid$clock = clock;
        s6_y$clock = clock;
        s6_valid$d = s6_valid$q;
        s6_y$d = s6_y$q;
        unpack_a$x = a;
        unpack_b$x = b;
        c1_b_sign = unpack_b$sign ^ sub;
        c1_swap = a[(32'h0)+:(18)] < b[(32'h0)+:(18)];
        c1_d_ab = unpack_a$exp - unpack_b$exp;
        c1_d_ba = unpack_b$exp - unpack_a$exp;
        c1_sh_ab = c1_d_ab;
        if (c1_d_ab > c_align_cap) begin
            c1_sh_ab = c_align_cap;
        end
        c1_sh_ba = c1_d_ba;
        if (c1_d_ba > c_align_cap) begin
            c1_sh_ba = c_align_cap;
        end
        c1_inf_sign = c1_b_sign;
        if (unpack_a$is_inf) begin
            c1_inf_sign = unpack_a$sign;
        end
        s1_valid$d = valid_in;
        s1_nan$d = unpack_a$is_nan | unpack_b$is_nan | (unpack_a$is_inf & unpack_b$is_inf & (unpack_a$sign ^ c1_b_sign));
        s1_inf$d = unpack_a$is_inf | unpack_b$is_inf;
        s1_inf_sign$d = c1_inf_sign;
        s1_zero_sign$d = unpack_a$sign & c1_b_sign;
        s1_sign$d = unpack_a$sign;
        s1_exp$d = unpack_a$exp;
        s1_big$d = unpack_a$sig;
        s1_small$d = unpack_b$sig;
        s1_shift$d = c1_sh_ab;
        if (c1_swap) begin
            s1_sign$d = c1_b_sign;
            s1_exp$d = unpack_b$exp;
            s1_big$d = unpack_b$sig;
            s1_small$d = unpack_a$sig;
            s1_shift$d = c1_sh_ba;
        end
        s1_eff_sub$d = unpack_a$sign ^ c1_b_sign;
        c2_small_ext = ((s1_small$q) & 14'h3fff) << 32'h3;
        c2_aligned = c2_small_ext >> s1_shift$q;
        c2_mask = ~(c_ones << s1_shift$q);
        c2_lost = |(c2_small_ext & c2_mask);
        s2_valid$d = s1_valid$q;
        s2_nan$d = s1_nan$q;
        s2_inf$d = s1_inf$q;
        s2_inf_sign$d = s1_inf_sign$q;
        s2_zero_sign$d = s1_zero_sign$q;
        s2_eff_sub$d = s1_eff_sub$q;
        s2_sign$d = s1_sign$q;
        s2_exp$d = s1_exp$q;
        s2_big$d = ((s1_big$q) & 14'h3fff) << 32'h3;
        s2_small$d = (c2_aligned & ~(1 << (32'h0)) | ((c2_aligned[32'h0] | c2_lost) << (32'h0)));
        c3_sum = ((s2_big$q) & 15'h7fff) + ((s2_small$q) & 15'h7fff);
        if (s2_eff_sub$q) begin
            c3_sum = ((s2_big$q) & 15'h7fff) - ((s2_small$q) & 15'h7fff);
        end
        s3_valid$d = s2_valid$q;
        s3_nan$d = s2_nan$q;
        s3_inf$d = s2_inf$q;
        s3_inf_sign$d = s2_inf_sign$q;
        s3_zero_sign$d = s2_zero_sign$q;
        s3_sign$d = s2_sign$q;
        s3_exp$d = s2_exp$q;
        s3_sum$d = c3_sum;
        c3_limit = s2_exp$q - 32'h1;
        s3_marker$d = c_top >> c3_limit;
        lzc$x = s3_sum$q[(32'h0)+:(14)] | s3_marker$q;
        c4_zero = s3_sum$q == 32'h0;
        c4_sign = s3_sign$q;
        if (c4_zero) begin
            c4_sign = s3_zero_sign$q;
        end
        if (s3_inf$q) begin
            c4_sign = s3_inf_sign$q;
        end
        s4_valid$d = s3_valid$q;
        s4_sign$d = c4_sign;
        s4_nan$d = s3_nan$q;
        s4_inf$d = s3_inf$q;
        s4_zero$d = c4_zero;
        s4_exp$d = s3_exp$q;
        s4_shift$d = ((lzc$lz) & 8'hff);
        s4_sum$d = s3_sum$q;
        c5_shifted = s4_sum$q[(32'h0)+:(14)] << s4_shift$q;
        c5_exp = ((s4_exp$q) & 10'h3ff) - ((s4_shift$q) & 10'h3ff);
        c5_nm = (((c5_shifted >> 32'h1) & 13'h1fff) & ~(1 << (32'h0)) | ((c5_shifted[32'h1] | c5_shifted[32'h0]) << (32'h0)));
        if (s4_sum$q[32'he]) begin
            c5_exp = ((s4_exp$q) & 10'h3ff) + 32'h1;
            c5_nm = (((s4_sum$q >> 32'h2) & 13'h1fff) & ~(1 << (32'h0)) | ((s4_sum$q[32'h2] | s4_sum$q[32'h1] | s4_sum$q[32'h0]) << (32'h0)));
        end
        s5_valid$d = s4_valid$q;
        s5_sign$d = s4_sign$q;
        s5_nan$d = s4_nan$q;
        s5_inf$d = s4_inf$q;
        s5_zero$d = s4_zero$q;
        s5_ovf$d = c5_exp >= c_exp_ones;
        s5_efield$d = 32'h0;
        if (c5_nm[32'hb + 32'h1]) begin
            s5_efield$d = ((c5_exp) & 8'hff);
        end
        s5_nm$d = c5_nm;
        round$round_up = round_up;
        round$sign = s5_sign$q;
        round$nan = s5_nan$q;
        round$inf = s5_inf$q;
        round$zero = s5_zero$q;
        round$ovf = s5_ovf$q;
        round$efield = s5_efield$q;
        round$nm = s5_nm$q;
        s6_valid$d = s5_valid$q;
        s6_y$d = round$y;
        y = s6_y$q;
        valid_out = s6_valid$q;
    end
    
endmodule // top


module top$lzc(x,lz);
    
    // Module arguments
    input wire  [13:0] x;
    output reg  [4:0] lz;
    
    // Constant declarations
    localparam  mask0 = 14'b1010101010101;
    localparam  mask1 = 14'b110011001100;
    localparam  mask2 = 14'b1111000011;
    localparam  mask3 = 14'b111111;
    localparam  mask4 = 14'b0;
    
    // Local signals
    reg  [13:0] p1;
    reg  [13:0] p2;
    reg  [13:0] p4;
    reg  [13:0] p8;
    reg  [13:0] p16;
    reg  [13:0] lead;
    
    // Update code
    always @(*) begin
        p1 = x | (x >> 32'h1);
        p2 = p1 | (p1 >> 32'h2);
        p4 = p2 | (p2 >> 32'h4);
        p8 = p4 | (p4 >> 32'h8);
        p16 = p8 | (p8 >> 32'h10);
        lead = p16 & ~(p16 >> 32'h1);
        lz = (((((((32'h0) & 5'h1f) & ~(1 << (32'h4)) | ((|(lead & mask4)) << (32'h4))) & ~(1 << (32'h3)) | ((|(lead & mask3)) << (32'h3))) & ~(1 << (32'h2)) | ((|(lead & mask2)) << (32'h2))) & ~(1 << (32'h1)) | ((|(lead & mask1)) << (32'h1))) & ~(1 << (32'h0)) | ((|(lead & mask0)) << (32'h0)));
    end
    
endmodule // top$lzc


module top$round(round_up,sign,nan,inf,zero,ovf,efield,nm,y);
    
    // Module arguments
    input wire  round_up;
    input wire  sign;
    input wire  nan;
    input wire  inf;
    input wire  zero;
    input wire  ovf;
    input wire  [7:0] efield;
    input wire  [12:0] nm;
    output reg  [18:0] y;
    
    // Constant declarations
    localparam  c_nan = 19'b111111111000000000;
    localparam  c_sign = 19'b1000000000000000000;
    localparam  c_inf = 18'b111111110000000000;
    localparam  c_max_finite = 18'b111111101111111111;
    
    // Local signals
    reg  lsb;
    reg  guard;
    reg  sticky;
    reg  inc;
    reg  [17:0] pack_word;
    reg  [17:0] rounded;
    reg  rexp_ones;
    reg  [17:0] mag;
    
    // Update code
    always @(*) begin
        lsb = nm[32'h2];
        guard = nm[32'h1];
        sticky = nm[32'h0];
        inc = guard & (sticky | lsb);
        if (round_up) begin
            inc = ~sign & (guard | sticky);
        end
        pack_word = (((efield) & 18'h3ffff) << 32'ha) | ((nm[(32'h2)+:(10)]) & 18'h3ffff);
        rounded = pack_word + inc;
        rexp_ones = &rounded[(32'ha)+:(8)];
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
        y = ((mag) & 19'h7ffff);
        if (sign) begin
            y = ((mag) & 19'h7ffff) | c_sign;
        end
        if (nan) begin
            y = c_nan;
        end
    end
    
endmodule // top$round


module top$s1_big(d,q,clock);
    
    // Module arguments
    input wire  [10:0] d;
    output reg  [10:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 11'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$s1_big


module top$s1_eff_sub(d,q,clock);
    
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
          
endmodule // top$s1_eff_sub


module top$s1_exp(d,q,clock);
    
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
          
endmodule // top$s1_exp


module top$s2_big(d,q,clock);
    
    // Module arguments
    input wire  [13:0] d;
    output reg  [13:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 14'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$s2_big


module top$s3_sum(d,q,clock);
    
    // Module arguments
    input wire  [14:0] d;
    output reg  [14:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 15'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$s3_sum


module top$s5_nm(d,q,clock);
    
    // Module arguments
    input wire  [12:0] d;
    output reg  [12:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 13'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$s5_nm


module top$s6_y(d,q,clock);
    
    // Module arguments
    input wire  [18:0] d;
    output reg  [18:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 19'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$s6_y


module top$unpack_a(x,sign,exp,sig,is_zero,is_inf,is_nan);
    
    // Module arguments
    input wire  [18:0] x;
    output reg  sign;
    output reg  [7:0] exp;
    output reg  [10:0] sig;
    output reg  is_zero;
    output reg  is_inf;
    output reg  is_nan;
    
    // Local signals
    reg  [7:0] field;
    reg  [9:0] frac;
    reg  exp_zero;
    reg  exp_ones;
    reg  frac_zero;
    
    // Update code
    always @(*) begin
        field = x[(32'ha)+:(8)];
        frac = x[(32'h0)+:(10)];
        sign = x[32'h12];
        exp_zero = field == 32'h0;
        exp_ones = &field;
        frac_zero = frac == 32'h0;
        is_zero = exp_zero & frac_zero;
        is_inf = exp_ones & frac_zero;
        is_nan = exp_ones & ~frac_zero;
        exp = field;
        sig = (((frac) & 11'h7ff) & ~(1 << (32'ha)) | ((1'b1) << (32'ha)));
        if (exp_zero) begin
            exp = 32'h1;
            sig = ((frac) & 11'h7ff);
        end
    end
    
endmodule // top$unpack_a
