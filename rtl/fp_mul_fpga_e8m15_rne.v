

module top(clock,a,b,valid_in,y,valid_out);
    
    // Module arguments
    input wire  clock;
    input wire  [23:0] a;
    input wire  [23:0] b;
    input wire  valid_in;
    output reg  [23:0] y;
    output reg  valid_out;
    
    // Constant declarations
    localparam  round_up = 1'b0;
    localparam  c_exp_adj = 10'b10000001;
    localparam  c_exp_ofs = 10'b100000000;
    localparam  c_exp_norm_min = 10'b100000001;
    localparam  c_exp_ovf = 10'b111111111;
    localparam  c_shift_cap = 10'b10010;
    localparam  c_ones = 18'b111111111111111111;
    
    // Stub signals
    reg  [23:0] unpack_a$x;
    wire  unpack_a$sign;
    wire  [7:0] unpack_a$exp;
    wire  [15:0] unpack_a$sig;
    wire  unpack_a$is_zero;
    wire  unpack_a$is_inf;
    wire  unpack_a$is_nan;
    reg  [23:0] unpack_b$x;
    wire  unpack_b$sign;
    wire  [7:0] unpack_b$exp;
    wire  [15:0] unpack_b$sig;
    wire  unpack_b$is_zero;
    wire  unpack_b$is_inf;
    wire  unpack_b$is_nan;
    reg  [15:0] lzc_a$x;
    wire  [4:0] lzc_a$lz;
    reg  [15:0] lzc_b$x;
    wire  [4:0] lzc_b$lz;
    reg  s1_valid$d;
    wire  s1_valid$q;
    reg  s1_valid$clock;
    reg  s1_sign$d;
    wire  s1_sign$q;
    reg  s1_sign$clock;
    reg  s1_nan$d;
    wire  s1_nan$q;
    reg  s1_nan$clock;
    reg  s1_inf$d;
    wire  s1_inf$q;
    reg  s1_inf$clock;
    reg  s1_zero$d;
    wire  s1_zero$q;
    reg  s1_zero$clock;
    reg  [7:0] s1_exp_a$d;
    wire  [7:0] s1_exp_a$q;
    reg  s1_exp_a$clock;
    reg  [7:0] s1_exp_b$d;
    wire  [7:0] s1_exp_b$q;
    reg  s1_exp_b$clock;
    reg  [15:0] s1_sig_a$d;
    wire  [15:0] s1_sig_a$q;
    reg  s1_sig_a$clock;
    reg  [15:0] s1_sig_b$d;
    wire  [15:0] s1_sig_b$q;
    reg  s1_sig_b$clock;
    reg  [4:0] s1_lz_a$d;
    wire  [4:0] s1_lz_a$q;
    reg  s1_lz_a$clock;
    reg  [4:0] s1_lz_b$d;
    wire  [4:0] s1_lz_b$q;
    reg  s1_lz_b$clock;
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
    reg  [9:0] s2_exp$d;
    wire  [9:0] s2_exp$q;
    reg  s2_exp$clock;
    reg  [15:0] s2_sig_a$d;
    wire  [15:0] s2_sig_a$q;
    reg  s2_sig_a$clock;
    reg  [15:0] s2_sig_b$d;
    wire  [15:0] s2_sig_b$q;
    reg  s2_sig_b$clock;
    reg  s3_valid$d;
    wire  s3_valid$q;
    reg  s3_valid$clock;
    reg  s3_sign$d;
    wire  s3_sign$q;
    reg  s3_sign$clock;
    reg  s3_nan$d;
    wire  s3_nan$q;
    reg  s3_nan$clock;
    reg  s3_inf$d;
    wire  s3_inf$q;
    reg  s3_inf$clock;
    reg  s3_zero$d;
    wire  s3_zero$q;
    reg  s3_zero$clock;
    reg  [31:0] s3_ll$d;
    wire  [31:0] s3_ll$q;
    reg  s3_ll$clock;
    reg  [31:0] s3_lh$d;
    wire  [31:0] s3_lh$q;
    reg  s3_lh$clock;
    reg  [31:0] s3_hl$d;
    wire  [31:0] s3_hl$q;
    reg  s3_hl$clock;
    reg  [31:0] s3_hh$d;
    wire  [31:0] s3_hh$q;
    reg  s3_hh$clock;
    reg  s3_lt0$d;
    wire  s3_lt0$q;
    reg  s3_lt0$clock;
    reg  s3_lt1$d;
    wire  s3_lt1$q;
    reg  s3_lt1$clock;
    reg  [9:0] s3_u0$d;
    wire  [9:0] s3_u0$q;
    reg  s3_u0$clock;
    reg  [9:0] s3_u1$d;
    wire  [9:0] s3_u1$q;
    reg  s3_u1$clock;
    reg  s3_ovf0$d;
    wire  s3_ovf0$q;
    reg  s3_ovf0$clock;
    reg  s3_ovf1$d;
    wire  s3_ovf1$q;
    reg  s3_ovf1$clock;
    reg  [7:0] s3_efield0$d;
    wire  [7:0] s3_efield0$q;
    reg  s3_efield0$clock;
    reg  [7:0] s3_efield1$d;
    wire  [7:0] s3_efield1$q;
    reg  s3_efield1$clock;
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
    reg  [17:0] s4_nm$d;
    wire  [17:0] s4_nm$q;
    reg  s4_nm$clock;
    reg  [9:0] s4_cap$d;
    wire  [9:0] s4_cap$q;
    reg  s4_cap$clock;
    reg  s4_ovf$d;
    wire  s4_ovf$q;
    reg  s4_ovf$clock;
    reg  [7:0] s4_efield$d;
    wire  [7:0] s4_efield$q;
    reg  s4_efield$clock;
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
    reg  [17:0] s5_nm$d;
    wire  [17:0] s5_nm$q;
    reg  s5_nm$clock;
    reg  round$round_up;
    reg  round$sign;
    reg  round$nan;
    reg  round$inf;
    reg  round$zero;
    reg  round$ovf;
    reg  [7:0] round$efield;
    reg  [17:0] round$nm;
    wire  [23:0] round$y;
    reg  s6_valid$d;
    wire  s6_valid$q;
    reg  s6_valid$clock;
    reg  [23:0] s6_y$d;
    wire  [23:0] s6_y$q;
    reg  s6_y$clock;
    
    // Local signals
    reg  [15:0] c3_a_lo;
    reg  [15:0] c3_a_hi;
    reg  [15:0] c3_b_lo;
    reg  [15:0] c3_b_hi;
    reg  [9:0] c3_e1;
    reg  [31:0] c4_prod;
    reg  [17:0] c4_hi;
    reg  c4_sticky;
    reg  [9:0] c4_cap0;
    reg  [9:0] c4_cap1;
    reg  [17:0] c5_shifted;
    reg  [17:0] c5_mask;
    reg  c5_lost;
    
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
    top$lzc_a lzc_a(
        .x(lzc_a$x),
        .lz(lzc_a$lz)
    );
    top$lzc_a lzc_b(
        .x(lzc_b$x),
        .lz(lzc_b$lz)
    );
    top$s1_inf s1_valid(
        .d(s1_valid$d),
        .q(s1_valid$q),
        .clock(s1_valid$clock)
    );
    top$s1_inf s1_sign(
        .d(s1_sign$d),
        .q(s1_sign$q),
        .clock(s1_sign$clock)
    );
    top$s1_inf s1_nan(
        .d(s1_nan$d),
        .q(s1_nan$q),
        .clock(s1_nan$clock)
    );
    top$s1_inf s1_inf(
        .d(s1_inf$d),
        .q(s1_inf$q),
        .clock(s1_inf$clock)
    );
    top$s1_inf s1_zero(
        .d(s1_zero$d),
        .q(s1_zero$q),
        .clock(s1_zero$clock)
    );
    top$s1_exp_a s1_exp_a(
        .d(s1_exp_a$d),
        .q(s1_exp_a$q),
        .clock(s1_exp_a$clock)
    );
    top$s1_exp_a s1_exp_b(
        .d(s1_exp_b$d),
        .q(s1_exp_b$q),
        .clock(s1_exp_b$clock)
    );
    top$s1_sig_a s1_sig_a(
        .d(s1_sig_a$d),
        .q(s1_sig_a$q),
        .clock(s1_sig_a$clock)
    );
    top$s1_sig_a s1_sig_b(
        .d(s1_sig_b$d),
        .q(s1_sig_b$q),
        .clock(s1_sig_b$clock)
    );
    top$s1_lz_a s1_lz_a(
        .d(s1_lz_a$d),
        .q(s1_lz_a$q),
        .clock(s1_lz_a$clock)
    );
    top$s1_lz_a s1_lz_b(
        .d(s1_lz_b$d),
        .q(s1_lz_b$q),
        .clock(s1_lz_b$clock)
    );
    top$s1_inf s2_valid(
        .d(s2_valid$d),
        .q(s2_valid$q),
        .clock(s2_valid$clock)
    );
    top$s1_inf s2_sign(
        .d(s2_sign$d),
        .q(s2_sign$q),
        .clock(s2_sign$clock)
    );
    top$s1_inf s2_nan(
        .d(s2_nan$d),
        .q(s2_nan$q),
        .clock(s2_nan$clock)
    );
    top$s1_inf s2_inf(
        .d(s2_inf$d),
        .q(s2_inf$q),
        .clock(s2_inf$clock)
    );
    top$s1_inf s2_zero(
        .d(s2_zero$d),
        .q(s2_zero$q),
        .clock(s2_zero$clock)
    );
    top$s2_exp s2_exp(
        .d(s2_exp$d),
        .q(s2_exp$q),
        .clock(s2_exp$clock)
    );
    top$s1_sig_a s2_sig_a(
        .d(s2_sig_a$d),
        .q(s2_sig_a$q),
        .clock(s2_sig_a$clock)
    );
    top$s1_sig_a s2_sig_b(
        .d(s2_sig_b$d),
        .q(s2_sig_b$q),
        .clock(s2_sig_b$clock)
    );
    top$s1_inf s3_valid(
        .d(s3_valid$d),
        .q(s3_valid$q),
        .clock(s3_valid$clock)
    );
    top$s1_inf s3_sign(
        .d(s3_sign$d),
        .q(s3_sign$q),
        .clock(s3_sign$clock)
    );
    top$s1_inf s3_nan(
        .d(s3_nan$d),
        .q(s3_nan$q),
        .clock(s3_nan$clock)
    );
    top$s1_inf s3_inf(
        .d(s3_inf$d),
        .q(s3_inf$q),
        .clock(s3_inf$clock)
    );
    top$s1_inf s3_zero(
        .d(s3_zero$d),
        .q(s3_zero$q),
        .clock(s3_zero$clock)
    );
    top$s3_hh s3_ll(
        .d(s3_ll$d),
        .q(s3_ll$q),
        .clock(s3_ll$clock)
    );
    top$s3_hh s3_lh(
        .d(s3_lh$d),
        .q(s3_lh$q),
        .clock(s3_lh$clock)
    );
    top$s3_hh s3_hl(
        .d(s3_hl$d),
        .q(s3_hl$q),
        .clock(s3_hl$clock)
    );
    top$s3_hh s3_hh(
        .d(s3_hh$d),
        .q(s3_hh$q),
        .clock(s3_hh$clock)
    );
    top$s1_inf s3_lt0(
        .d(s3_lt0$d),
        .q(s3_lt0$q),
        .clock(s3_lt0$clock)
    );
    top$s1_inf s3_lt1(
        .d(s3_lt1$d),
        .q(s3_lt1$q),
        .clock(s3_lt1$clock)
    );
    top$s2_exp s3_u0(
        .d(s3_u0$d),
        .q(s3_u0$q),
        .clock(s3_u0$clock)
    );
    top$s2_exp s3_u1(
        .d(s3_u1$d),
        .q(s3_u1$q),
        .clock(s3_u1$clock)
    );
    top$s1_inf s3_ovf0(
        .d(s3_ovf0$d),
        .q(s3_ovf0$q),
        .clock(s3_ovf0$clock)
    );
    top$s1_inf s3_ovf1(
        .d(s3_ovf1$d),
        .q(s3_ovf1$q),
        .clock(s3_ovf1$clock)
    );
    top$s1_exp_a s3_efield0(
        .d(s3_efield0$d),
        .q(s3_efield0$q),
        .clock(s3_efield0$clock)
    );
    top$s1_exp_a s3_efield1(
        .d(s3_efield1$d),
        .q(s3_efield1$q),
        .clock(s3_efield1$clock)
    );
    top$s1_inf s4_valid(
        .d(s4_valid$d),
        .q(s4_valid$q),
        .clock(s4_valid$clock)
    );
    top$s1_inf s4_sign(
        .d(s4_sign$d),
        .q(s4_sign$q),
        .clock(s4_sign$clock)
    );
    top$s1_inf s4_nan(
        .d(s4_nan$d),
        .q(s4_nan$q),
        .clock(s4_nan$clock)
    );
    top$s1_inf s4_inf(
        .d(s4_inf$d),
        .q(s4_inf$q),
        .clock(s4_inf$clock)
    );
    top$s1_inf s4_zero(
        .d(s4_zero$d),
        .q(s4_zero$q),
        .clock(s4_zero$clock)
    );
    top$s4_nm s4_nm(
        .d(s4_nm$d),
        .q(s4_nm$q),
        .clock(s4_nm$clock)
    );
    top$s2_exp s4_cap(
        .d(s4_cap$d),
        .q(s4_cap$q),
        .clock(s4_cap$clock)
    );
    top$s1_inf s4_ovf(
        .d(s4_ovf$d),
        .q(s4_ovf$q),
        .clock(s4_ovf$clock)
    );
    top$s1_exp_a s4_efield(
        .d(s4_efield$d),
        .q(s4_efield$q),
        .clock(s4_efield$clock)
    );
    top$s1_inf s5_valid(
        .d(s5_valid$d),
        .q(s5_valid$q),
        .clock(s5_valid$clock)
    );
    top$s1_inf s5_sign(
        .d(s5_sign$d),
        .q(s5_sign$q),
        .clock(s5_sign$clock)
    );
    top$s1_inf s5_nan(
        .d(s5_nan$d),
        .q(s5_nan$q),
        .clock(s5_nan$clock)
    );
    top$s1_inf s5_inf(
        .d(s5_inf$d),
        .q(s5_inf$q),
        .clock(s5_inf$clock)
    );
    top$s1_inf s5_zero(
        .d(s5_zero$d),
        .q(s5_zero$q),
        .clock(s5_zero$clock)
    );
    top$s1_inf s5_ovf(
        .d(s5_ovf$d),
        .q(s5_ovf$q),
        .clock(s5_ovf$clock)
    );
    top$s1_exp_a s5_efield(
        .d(s5_efield$d),
        .q(s5_efield$q),
        .clock(s5_efield$clock)
    );
    top$s4_nm s5_nm(
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
    top$s1_inf s6_valid(
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
        s1_sign$clock = clock;
        s1_nan$clock = clock;
        s1_inf$clock = clock;
        s1_zero$clock = clock;
        s1_exp_a$clock = clock;
        s1_exp_b$clock = clock;
        s1_sig_a$clock = clock;
        s1_sig_b$clock = clock;
        s1_lz_a$clock = clock;
        s1_lz_b$clock = clock;
        s1_valid$d = s1_valid$q;
        s1_sign$d = s1_sign$q;
        s1_nan$d = s1_nan$q;
        s1_inf$d = s1_inf$q;
        s1_zero$d = s1_zero$q;
        s1_exp_a$d = s1_exp_a$q;
        s1_exp_b$d = s1_exp_b$q;
        s1_sig_a$d = s1_sig_a$q;
        s1_sig_b$d = s1_sig_b$q;
        s1_lz_a$d = s1_lz_a$q;
        s1_lz_b$d = s1_lz_b$q;
        s2_valid$clock = clock;
        s2_sign$clock = clock;
        s2_nan$clock = clock;
        s2_inf$clock = clock;
        s2_zero$clock = clock;
        s2_exp$clock = clock;
        s2_sig_a$clock = clock;
        s2_sig_b$clock = clock;
        s2_valid$d = s2_valid$q;
        s2_sign$d = s2_sign$q;
        s2_nan$d = s2_nan$q;
        s2_inf$d = s2_inf$q;
        s2_zero$d = s2_zero$q;
        s2_exp$d = s2_exp$q;
        s2_sig_a$d = s2_sig_a$q;
        s2_sig_b$d = s2_sig_b$q;
        s3_valid$clock = clock;
        s3_sign$clock = clock;
        s3_nan$clock = clock;
        s3_inf$clock = clock;
        s3_zero$clock = clock;
        s3_ll$clock = clock;
        s3_lh$clock = clock;
        s3_hl$clock = clock;
        s3_hh$clock = clock;
        s3_lt0$clock = clock;
        s3_lt1$clock = clock;
        s3_u0$clock = clock;
        s3_u1$clock = clock;
        s3_ovf0$clock = clock;
        s3_ovf1$clock = clock;
        s3_efield0$clock = clock;
        s3_efield1$clock = clock;
        s3_valid$d = s3_valid$q;
        s3_sign$d = s3_sign$q;
        s3_nan$d = s3_nan$q;
        s3_inf$d = s3_inf$q;
        s3_zero$d = s3_zero$q;
        s3_ll$d = s3_ll$q;
        s3_lh$d = s3_lh$q;
        s3_hl$d = s3_hl$q;
        s3_hh$d = s3_hh$q;
        s3_lt0$d = s3_lt0$q;
        s3_lt1$d = s3_lt1$q;
        s3_u0$d = s3_u0$q;
        s3_u1$d = s3_u1$q;
        s3_ovf0$d = s3_ovf0$q;
        s3_ovf1$d = s3_ovf1$q;
        s3_efield0$d = s3_efield0$q;
        s3_efield1$d = s3_efield1$q;
        s4_valid$clock = clock;
        s4_sign$clock = clock;
        s4_nan$clock = clock;
        s4_inf$clock = clock;
        s4_zero$clock = clock;
        s4_nm$clock = clock;
        s4_cap$clock = clock;
        s4_ovf$clock = clock;
        s4_efield$clock = clock;
        s4_valid$d = s4_valid$q;
        s4_sign$d = s4_sign$q;
        s4_nan$d = s4_nan$q;
        s4_inf$d = s4_inf$q;
        s4_zero$d = s4_zero$q;
        s4_nm$d = s4_nm$q;
        s4_cap$d = s4_cap$q;
        s4_ovf$d = s4_ovf$q;
        s4_efield$d = s4_efield$q;
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
        lzc_a$x = unpack_a$sig;
        lzc_b$x = unpack_b$sig;
        s1_valid$d = valid_in;
        s1_sign$d = unpack_a$sign ^ unpack_b$sign;
        s1_nan$d = unpack_a$is_nan | unpack_b$is_nan | (unpack_a$is_inf & unpack_b$is_zero) | (unpack_a$is_zero & unpack_b$is_inf);
        s1_inf$d = unpack_a$is_inf | unpack_b$is_inf;
        s1_zero$d = unpack_a$is_zero | unpack_b$is_zero;
        s1_exp_a$d = unpack_a$exp;
        s1_exp_b$d = unpack_b$exp;
        s1_sig_a$d = unpack_a$sig;
        s1_sig_b$d = unpack_b$sig;
        s1_lz_a$d = lzc_a$lz;
        s1_lz_b$d = lzc_b$lz;
        s2_valid$d = s1_valid$q;
        s2_sign$d = s1_sign$q;
        s2_nan$d = s1_nan$q;
        s2_inf$d = s1_inf$q;
        s2_zero$d = s1_zero$q;
        s2_exp$d = ((s1_exp_a$q) & 10'h3ff) + ((s1_exp_b$q) & 10'h3ff) - ((s1_lz_a$q) & 10'h3ff) - ((s1_lz_b$q) & 10'h3ff) + c_exp_adj;
        s2_sig_a$d = s1_sig_a$q << s1_lz_a$q;
        s2_sig_b$d = s1_sig_b$q << s1_lz_b$q;
        c3_a_lo = ((s2_sig_a$q[(32'h0)+:(8)]) & 16'hffff);
        c3_a_hi = ((s2_sig_a$q[(32'h8)+:(8)]) & 16'hffff);
        c3_b_lo = ((s2_sig_b$q[(32'h0)+:(8)]) & 16'hffff);
        c3_b_hi = ((s2_sig_b$q[(32'h8)+:(8)]) & 16'hffff);
        s3_ll$d = c3_a_lo * c3_b_lo;
        s3_lh$d = c3_a_lo * c3_b_hi;
        s3_hl$d = c3_a_hi * c3_b_lo;
        s3_hh$d = c3_a_hi * c3_b_hi;
        c3_e1 = s2_exp$q + 32'h1;
        s3_lt0$d = s2_exp$q < c_exp_norm_min;
        s3_lt1$d = c3_e1 < c_exp_norm_min;
        s3_u0$d = c_exp_norm_min - s2_exp$q;
        s3_u1$d = c_exp_norm_min - c3_e1;
        s3_ovf0$d = s2_exp$q >= c_exp_ovf;
        s3_ovf1$d = c3_e1 >= c_exp_ovf;
        s3_efield0$d = ((s2_exp$q - c_exp_ofs) & 8'hff);
        s3_efield1$d = ((c3_e1 - c_exp_ofs) & 8'hff);
        s3_valid$d = s2_valid$q;
        s3_sign$d = s2_sign$q;
        s3_nan$d = s2_nan$q;
        s3_inf$d = s2_inf$q;
        s3_zero$d = s2_zero$q;
        c4_prod = ((s3_ll$q) & 32'hffffffff) + (((s3_lh$q) & 32'hffffffff) << 32'h8) + (((s3_hl$q) & 32'hffffffff) << 32'h8) + (((s3_hh$q) & 32'hffffffff) << 32'h10);
        c4_hi = ((c4_prod >> 32'he) & 18'h3ffff);
        c4_sticky = |c4_prod[(32'h0)+:(14)];
        c4_cap0 = 32'h0;
        if (s3_lt0$q) begin
            c4_cap0 = s3_u0$q;
            if (s3_u0$q > c_shift_cap) begin
                c4_cap0 = c_shift_cap;
            end
        end
        c4_cap1 = 32'h0;
        if (s3_lt1$q) begin
            c4_cap1 = s3_u1$q;
            if (s3_u1$q > c_shift_cap) begin
                c4_cap1 = c_shift_cap;
            end
        end
        s4_nm$d = ((c4_hi << 32'h1) & ~(1 << (32'h0)) | ((c4_sticky) << (32'h0)));
        s4_cap$d = c4_cap0;
        s4_ovf$d = s3_ovf0$q;
        s4_efield$d = 32'h0;
        if (~s3_lt0$q) begin
            s4_efield$d = s3_efield0$q;
        end
        if (c4_hi[32'h10 + 32'h1]) begin
            s4_nm$d = (c4_hi & ~(1 << (32'h0)) | ((c4_hi[32'h0] | c4_sticky) << (32'h0)));
            s4_cap$d = c4_cap1;
            s4_ovf$d = s3_ovf1$q;
            s4_efield$d = 32'h0;
            if (~s3_lt1$q) begin
                s4_efield$d = s3_efield1$q;
            end
        end
        s4_valid$d = s3_valid$q;
        s4_sign$d = s3_sign$q;
        s4_nan$d = s3_nan$q;
        s4_inf$d = s3_inf$q;
        s4_zero$d = s3_zero$q;
        s5_ovf$d = s4_ovf$q;
        s5_efield$d = s4_efield$q;
        c5_shifted = s4_nm$q >> s4_cap$q;
        c5_mask = ~(c_ones << s4_cap$q);
        c5_lost = |(s4_nm$q & c5_mask);
        s5_valid$d = s4_valid$q;
        s5_sign$d = s4_sign$q;
        s5_nan$d = s4_nan$q;
        s5_inf$d = s4_inf$q;
        s5_zero$d = s4_zero$q;
        s5_nm$d = (c5_shifted & ~(1 << (32'h0)) | ((c5_shifted[32'h0] | c5_lost) << (32'h0)));
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


module top$lzc_a(x,lz);
    
    // Module arguments
    input wire  [15:0] x;
    output reg  [4:0] lz;
    
    // Constant declarations
    localparam  mask0 = 16'h5555;
    localparam  mask1 = 16'h3333;
    localparam  mask2 = 16'hf0f;
    localparam  mask3 = 16'hff;
    localparam  mask4 = 16'h0;
    
    // Local signals
    reg  [15:0] p1;
    reg  [15:0] p2;
    reg  [15:0] p4;
    reg  [15:0] p8;
    reg  [15:0] p16;
    reg  [15:0] lead;
    
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
    
endmodule // top$lzc_a


module top$round(round_up,sign,nan,inf,zero,ovf,efield,nm,y);
    
    // Module arguments
    input wire  round_up;
    input wire  sign;
    input wire  nan;
    input wire  inf;
    input wire  zero;
    input wire  ovf;
    input wire  [7:0] efield;
    input wire  [17:0] nm;
    output reg  [23:0] y;
    
    // Constant declarations
    localparam  c_nan = 24'h7fc000;
    localparam  c_sign = 24'h800000;
    localparam  c_inf = 23'h7f8000;
    localparam  c_max_finite = 23'h7f7fff;
    
    // Local signals
    reg  lsb;
    reg  guard;
    reg  sticky;
    reg  inc;
    reg  [22:0] pack_word;
    reg  [22:0] rounded;
    reg  rexp_ones;
    reg  [22:0] mag;
    
    // Update code
    always @(*) begin
        lsb = nm[32'h2];
        guard = nm[32'h1];
        sticky = nm[32'h0];
        inc = guard & (sticky | lsb);
        if (round_up) begin
            inc = ~sign & (guard | sticky);
        end
        pack_word = (((efield) & 23'h7fffff) << 32'hf) | ((nm[(32'h2)+:(15)]) & 23'h7fffff);
        rounded = pack_word + inc;
        rexp_ones = &rounded[(32'hf)+:(8)];
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
        y = ((mag) & 24'hffffff);
        if (sign) begin
            y = ((mag) & 24'hffffff) | c_sign;
        end
        if (nan) begin
            y = c_nan;
        end
    end
    
endmodule // top$round


module top$s1_exp_a(d,q,clock);
    
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
          
endmodule // top$s1_exp_a


module top$s1_inf(d,q,clock);
    
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
          
endmodule // top$s1_inf


module top$s1_lz_a(d,q,clock);
    
    // Module arguments
    input wire  [4:0] d;
    output reg  [4:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 5'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$s1_lz_a


module top$s1_sig_a(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$s1_sig_a


module top$s2_exp(d,q,clock);
    
    // Module arguments
    input wire  [9:0] d;
    output reg  [9:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 10'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$s2_exp


module top$s3_hh(d,q,clock);
    
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
          
endmodule // top$s3_hh


module top$s4_nm(d,q,clock);
    
    // Module arguments
    input wire  [17:0] d;
    output reg  [17:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 18'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$s4_nm


module top$s6_y(d,q,clock);
    
    // Module arguments
    input wire  [23:0] d;
    output reg  [23:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 24'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$s6_y


module top$unpack_a(x,sign,exp,sig,is_zero,is_inf,is_nan);
    
    // Module arguments
    input wire  [23:0] x;
    output reg  sign;
    output reg  [7:0] exp;
    output reg  [15:0] sig;
    output reg  is_zero;
    output reg  is_inf;
    output reg  is_nan;
    
    // Local signals
    reg  [7:0] field;
    reg  [14:0] frac;
    reg  exp_zero;
    reg  exp_ones;
    reg  frac_zero;
    
    // Update code
    always @(*) begin
        field = x[(32'hf)+:(8)];
        frac = x[(32'h0)+:(15)];
        sign = x[32'h17];
        exp_zero = field == 32'h0;
        exp_ones = &field;
        frac_zero = frac == 32'h0;
        is_zero = exp_zero & frac_zero;
        is_inf = exp_ones & frac_zero;
        is_nan = exp_ones & ~frac_zero;
        exp = field;
        sig = (((frac) & 16'hffff) & ~(1 << (32'hf)) | ((1'b1) << (32'hf)));
        if (exp_zero) begin
            exp = 32'h1;
            sig = ((frac) & 16'hffff);
        end
    end
    
endmodule // top$unpack_a
