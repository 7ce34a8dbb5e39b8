

module top(clock,d0,d1,d2,c0,c1,c2,c,e,valid_in,round_up,s,flag,valid_out);
    
    // Module arguments
    input wire  clock;
    input wire  [31:0] d0;
    input wire  [31:0] d1;
    input wire  [31:0] d2;
    input wire  [31:0] c0;
    input wire  [31:0] c1;
    input wire  [31:0] c2;
    input wire  [31:0] c;
    input wire  [31:0] e;
    input wire  valid_in;
    input wire  round_up;
    output reg  [31:0] s;
    output reg  flag;
    output reg  valid_out;
    
    // Stub signals
    reg  s1_valid$d;
    wire  s1_valid$q;
    reg  s1_valid$clock;
    reg  [31:0] s1_d0$d;
    wire  [31:0] s1_d0$q;
    reg  s1_d0$clock;
    reg  [31:0] s1_d1$d;
    wire  [31:0] s1_d1$q;
    reg  s1_d1$clock;
    reg  [31:0] s1_d2$d;
    wire  [31:0] s1_d2$q;
    reg  s1_d2$clock;
    reg  [31:0] s1_c0$d;
    wire  [31:0] s1_c0$q;
    reg  s1_c0$clock;
    reg  [31:0] s1_c1$d;
    wire  [31:0] s1_c1$q;
    reg  s1_c1$clock;
    reg  [31:0] s1_c2$d;
    wire  [31:0] s1_c2$q;
    reg  s1_c2$clock;
    reg  [31:0] s1_c$d;
    wire  [31:0] s1_c$q;
    reg  s1_c$clock;
    reg  [31:0] s1_e$d;
    wire  [31:0] s1_e$q;
    reg  s1_e$clock;
    reg  s1_round$d;
    wire  s1_round$q;
    reg  s1_round$clock;
    reg  r_mul$clock;
    reg  r_mul$d;
    wire  r_mul$q;
    reg  r_sum$clock;
    reg  r_sum$d;
    wire  r_sum$q;
    reg  r_u$clock;
    reg  r_u$d;
    wire  r_u$q;
    reg  r_s$clock;
    reg  r_s$d;
    wire  r_s$q;
    reg  mul_0$clock;
    reg  [31:0] mul_0$a;
    reg  [31:0] mul_0$b;
    reg  mul_0$valid_in;
    wire  [31:0] mul_0$y;
    wire  mul_0$valid_out;
    reg  mul_0$round_up;
    reg  mul_1$clock;
    reg  [31:0] mul_1$a;
    reg  [31:0] mul_1$b;
    reg  mul_1$valid_in;
    wire  [31:0] mul_1$y;
    wire  mul_1$valid_out;
    reg  mul_1$round_up;
    reg  mul_2$clock;
    reg  [31:0] mul_2$a;
    reg  [31:0] mul_2$b;
    reg  mul_2$valid_in;
    wire  [31:0] mul_2$y;
    wire  mul_2$valid_out;
    reg  mul_2$round_up;
    reg  [31:0] c_2$d;
    wire  [31:0] c_2$q;
    reg  c_2$clock;
    reg  [31:0] c_3$d;
    wire  [31:0] c_3$q;
    reg  c_3$clock;
    reg  [31:0] c_4$d;
    wire  [31:0] c_4$q;
    reg  c_4$clock;
    reg  [31:0] c_5$d;
    wire  [31:0] c_5$q;
    reg  c_5$clock;
    reg  [31:0] c_6$d;
    wire  [31:0] c_6$q;
    reg  c_6$clock;
    reg  [31:0] c_7$d;
    wire  [31:0] c_7$q;
    reg  c_7$clock;
    reg  add_0$clock;
    reg  [31:0] add_0$a;
    reg  [31:0] add_0$b;
    reg  add_0$sub;
    reg  add_0$valid_in;
    wire  [31:0] add_0$y;
    wire  add_0$valid_out;
    reg  add_0$round_up;
    reg  add_1$clock;
    reg  [31:0] add_1$a;
    reg  [31:0] add_1$b;
    reg  add_1$sub;
    reg  add_1$valid_in;
    wire  [31:0] add_1$y;
    wire  add_1$valid_out;
    reg  add_1$round_up;
    reg  add_2$clock;
    reg  [31:0] add_2$a;
    reg  [31:0] add_2$b;
    reg  add_2$sub;
    reg  add_2$valid_in;
    wire  [31:0] add_2$y;
    wire  add_2$valid_out;
    reg  add_2$round_up;
    reg  add_3$clock;
    reg  [31:0] add_3$a;
    reg  [31:0] add_3$b;
    reg  add_3$sub;
    reg  add_3$valid_in;
    wire  [31:0] add_3$y;
    wire  add_3$valid_out;
    reg  add_3$round_up;
    reg  [31:0] e_2$d;
    wire  [31:0] e_2$q;
    reg  e_2$clock;
    reg  [31:0] e_3$d;
    wire  [31:0] e_3$q;
    reg  e_3$clock;
    reg  [31:0] e_4$d;
    wire  [31:0] e_4$q;
    reg  e_4$clock;
    reg  [31:0] e_5$d;
    wire  [31:0] e_5$q;
    reg  e_5$clock;
    reg  [31:0] e_6$d;
    wire  [31:0] e_6$q;
    reg  e_6$clock;
    reg  [31:0] e_7$d;
    wire  [31:0] e_7$q;
    reg  e_7$clock;
    reg  [31:0] e_8$d;
    wire  [31:0] e_8$q;
    reg  e_8$clock;
    reg  [31:0] e_9$d;
    wire  [31:0] e_9$q;
    reg  e_9$clock;
    reg  [31:0] e_10$d;
    wire  [31:0] e_10$q;
    reg  e_10$clock;
    reg  [31:0] e_11$d;
    wire  [31:0] e_11$q;
    reg  e_11$clock;
    reg  [31:0] e_12$d;
    wire  [31:0] e_12$q;
    reg  e_12$clock;
    reg  [31:0] e_13$d;
    wire  [31:0] e_13$q;
    reg  e_13$clock;
    reg  [31:0] e_14$d;
    wire  [31:0] e_14$q;
    reg  e_14$clock;
    reg  [31:0] e_15$d;
    wire  [31:0] e_15$q;
    reg  e_15$clock;
    reg  [31:0] e_16$d;
    wire  [31:0] e_16$q;
    reg  e_16$clock;
    reg  [31:0] e_17$d;
    wire  [31:0] e_17$q;
    reg  e_17$clock;
    reg  [31:0] e_18$d;
    wire  [31:0] e_18$q;
    reg  e_18$clock;
    reg  [31:0] e_19$d;
    wire  [31:0] e_19$q;
    reg  e_19$clock;
    reg  s26_valid$d;
    wire  s26_valid$q;
    reg  s26_valid$clock;
    reg  [31:0] s26_s$d;
    wire  [31:0] s26_s$q;
    reg  s26_s$clock;
    reg  s26_flag$d;
    wire  s26_flag$q;
    reg  s26_flag$clock;
    
    // Local signals
    reg  [7:0] c15_exp;
    reg  [22:0] c15_frac;
    reg  [30:0] c15_mag;
    reg  c15_nan;
    
    // Sub module instances
    top$add_0$s1_eff_sub s1_valid(
        .d(s1_valid$d),
        .q(s1_valid$q),
        .clock(s1_valid$clock)
    );
    top$add_0$s6_y s1_d0(
        .d(s1_d0$d),
        .q(s1_d0$q),
        .clock(s1_d0$clock)
    );
    top$add_0$s6_y s1_d1(
        .d(s1_d1$d),
        .q(s1_d1$q),
        .clock(s1_d1$clock)
    );
    top$add_0$s6_y s1_d2(
        .d(s1_d2$d),
        .q(s1_d2$q),
        .clock(s1_d2$clock)
    );
    top$add_0$s6_y s1_c0(
        .d(s1_c0$d),
        .q(s1_c0$q),
        .clock(s1_c0$clock)
    );
    top$add_0$s6_y s1_c1(
        .d(s1_c1$d),
        .q(s1_c1$q),
        .clock(s1_c1$clock)
    );
    top$add_0$s6_y s1_c2(
        .d(s1_c2$d),
        .q(s1_c2$q),
        .clock(s1_c2$clock)
    );
    top$add_0$s6_y s1_c(
        .d(s1_c$d),
        .q(s1_c$q),
        .clock(s1_c$clock)
    );
    top$add_0$s6_y s1_e(
        .d(s1_e$d),
        .q(s1_e$q),
        .clock(s1_e$clock)
    );
    top$add_0$s1_eff_sub s1_round(
        .d(s1_round$d),
        .q(s1_round$q),
        .clock(s1_round$clock)
    );
    top$r_mul r_mul(
        .clock(r_mul$clock),
        .d(r_mul$d),
        .q(r_mul$q)
    );
    top$r_s r_sum(
        .clock(r_sum$clock),
        .d(r_sum$d),
        .q(r_sum$q)
    );
    top$r_s r_u(
        .clock(r_u$clock),
        .d(r_u$d),
        .q(r_u$q)
    );
    top$r_s r_s(
        .clock(r_s$clock),
        .d(r_s$d),
        .q(r_s$q)
    );
    top$mul_0 mul_0(
        .clock(mul_0$clock),
        .a(mul_0$a),
        .b(mul_0$b),
        .valid_in(mul_0$valid_in),
        .y(mul_0$y),
        .valid_out(mul_0$valid_out),
        .round_up(mul_0$round_up)
    );
    top$mul_0 mul_1(
        .clock(mul_1$clock),
        .a(mul_1$a),
        .b(mul_1$b),
        .valid_in(mul_1$valid_in),
        .y(mul_1$y),
        .valid_out(mul_1$valid_out),
        .round_up(mul_1$round_up)
    );
    top$mul_0 mul_2(
        .clock(mul_2$clock),
        .a(mul_2$a),
        .b(mul_2$b),
        .valid_in(mul_2$valid_in),
        .y(mul_2$y),
        .valid_out(mul_2$valid_out),
        .round_up(mul_2$round_up)
    );
    top$add_0$s6_y c_2(
        .d(c_2$d),
        .q(c_2$q),
        .clock(c_2$clock)
    );
    top$add_0$s6_y c_3(
        .d(c_3$d),
        .q(c_3$q),
        .clock(c_3$clock)
    );
    top$add_0$s6_y c_4(
        .d(c_4$d),
        .q(c_4$q),
        .clock(c_4$clock)
    );
    top$add_0$s6_y c_5(
        .d(c_5$d),
        .q(c_5$q),
        .clock(c_5$clock)
    );
    top$add_0$s6_y c_6(
        .d(c_6$d),
        .q(c_6$q),
        .clock(c_6$clock)
    );
    top$add_0$s6_y c_7(
        .d(c_7$d),
        .q(c_7$q),
        .clock(c_7$clock)
    );
    top$add_0 add_0(
        .clock(add_0$clock),
        .a(add_0$a),
        .b(add_0$b),
        .sub(add_0$sub),
        .valid_in(add_0$valid_in),
        .y(add_0$y),
        .valid_out(add_0$valid_out),
        .round_up(add_0$round_up)
    );
    top$add_0 add_1(
        .clock(add_1$clock),
        .a(add_1$a),
        .b(add_1$b),
        .sub(add_1$sub),
        .valid_in(add_1$valid_in),
        .y(add_1$y),
        .valid_out(add_1$valid_out),
        .round_up(add_1$round_up)
    );
    top$add_0 add_2(
        .clock(add_2$clock),
        .a(add_2$a),
        .b(add_2$b),
        .sub(add_2$sub),
        .valid_in(add_2$valid_in),
        .y(add_2$y),
        .valid_out(add_2$valid_out),
        .round_up(add_2$round_up)
    );
    top$add_0 add_3(
        .clock(add_3$clock),
        .a(add_3$a),
        .b(add_3$b),
        .sub(add_3$sub),
        .valid_in(add_3$valid_in),
        .y(add_3$y),
        .valid_out(add_3$valid_out),
        .round_up(add_3$round_up)
    );
    top$add_0$s6_y e_2(
        .d(e_2$d),
        .q(e_2$q),
        .clock(e_2$clock)
    );
    top$add_0$s6_y e_3(
        .d(e_3$d),
        .q(e_3$q),
        .clock(e_3$clock)
    );
    top$add_0$s6_y e_4(
        .d(e_4$d),
        .q(e_4$q),
        .clock(e_4$clock)
    );
    top$add_0$s6_y e_5(
        .d(e_5$d),
        .q(e_5$q),
        .clock(e_5$clock)
    );
    top$add_0$s6_y e_6(
        .d(e_6$d),
        .q(e_6$q),
        .clock(e_6$clock)
    );
    top$add_0$s6_y e_7(
        .d(e_7$d),
        .q(e_7$q),
        .clock(e_7$clock)
    );
    top$add_0$s6_y e_8(
        .d(e_8$d),
        .q(e_8$q),
        .clock(e_8$clock)
    );
    top$add_0$s6_y e_9(
        .d(e_9$d),
        .q(e_9$q),
        .clock(e_9$clock)
    );
    top$add_0$s6_y e_10(
        .d(e_10$d),
        .q(e_10$q),
        .clock(e_10$clock)
    );
    top$add_0$s6_y e_11(
        .d(e_11$d),
        .q(e_11$q),
        .clock(e_11$clock)
    );
    top$add_0$s6_y e_12(
        .d(e_12$d),
        .q(e_12$q),
        .clock(e_12$clock)
    );
    top$add_0$s6_y e_13(
        .d(e_13$d),
        .q(e_13$q),
        .clock(e_13$clock)
    );
    top$add_0$s6_y e_14(
        .d(e_14$d),
        .q(e_14$q),
        .clock(e_14$clock)
    );
    top$add_0$s6_y e_15(
        .d(e_15$d),
        .q(e_15$q),
        .clock(e_15$clock)
    );
    top$add_0$s6_y e_16(
        .d(e_16$d),
        .q(e_16$q),
        .clock(e_16$clock)
    );
    top$add_0$s6_y e_17(
        .d(e_17$d),
        .q(e_17$q),
        .clock(e_17$clock)
    );
    top$add_0$s6_y e_18(
        .d(e_18$d),
        .q(e_18$q),
        .clock(e_18$clock)
    );
    top$add_0$s6_y e_19(
        .d(e_19$d),
        .q(e_19$q),
        .clock(e_19$clock)
    );
    top$add_0$s1_eff_sub s26_valid(
        .d(s26_valid$d),
        .q(s26_valid$q),
        .clock(s26_valid$clock)
    );
    top$add_0$s6_y s26_s(
        .d(s26_s$d),
        .q(s26_s$q),
        .clock(s26_s$clock)
    );
    top$add_0$s1_eff_sub s26_flag(
        .d(s26_flag$d),
        .q(s26_flag$q),
        .clock(s26_flag$clock)
    );
    
    // Update code
    always @(*) begin
        s1_valid$clock = clock;
        s1_d0$clock = clock;
        s1_d1$clock = clock;
        s1_d2$clock = clock;
        s1_c0$clock = clock;
        s1_c1$clock = clock;
        s1_c2$clock = clock;
        s1_c$clock = clock;
        s1_e$clock = clock;
        s1_round$clock = clock;
        s1_valid$d = s1_valid$q;
        s1_d0$d = s1_d0$q;
        s1_d1$d = s1_d1$q;
        s1_d2$d = s1_d2$q;
        s1_c0$d = s1_c0$q;
        s1_c1$d = s1_c1$q;
        s1_c2$d = s1_c2$q;
        s1_c$d = s1_c$q;
        s1_e$d = s1_e$q;
        s1_round$d = s1_round$q;
        r_mul$clock = clock;
        r_sum$clock = clock;
        r_u$clock = clock;
        r_s$clock = clock;
        c_2$clock = clock;
        c_3$clock = clock;
        c_4$clock = clock;
        c_5$clock = clock;
        c_6$clock = clock;
        c_7$clock = clock;
        c_2$d = c_2$q;
        c_3$d = c_3$q;
        c_4$d = c_4$q;
        c_5$d = c_5$q;
        c_6$d = c_6$q;
        c_7$d = c_7$q;
        e_2$clock = clock;
        e_3$clock = clock;
        e_4$clock = clock;
        e_5$clock = clock;
        e_6$clock = clock;
        e_7$clock = clock;
        e_8$clock = clock;
        e_9$clock = clock;
        e_10$clock = clock;
        e_11$clock = clock;
        e_12$clock = clock;
        e_13$clock = clock;
        e_14$clock = clock;
        e_15$clock = clock;
        e_16$clock = clock;
        e_17$clock = clock;
        e_18$clock = clock;
        e_19$clock = clock;
        e_2$d = e_2$q;
        e_3$d = e_3$q;
        e_4$d = e_4$q;
        e_5$d = e_5$q;
        e_6$d = e_6$q;
        e_7$d = e_7$q;
        e_8$d = e_8$q;
        e_9$d = e_9$q;
        e_10$d = e_10$q;
        e_11$d = e_11$q;
        e_12$d = e_12$q;
        e_13$d = e_13$q;
        e_14$d = e_14$q;
        e_15$d = e_15$q;
        e_16$d = e_16$q;
        e_17$d = e_17$q;
        e_18$d = e_18$q;
        e_19$d = e_19$q;
        s26_valid$clock = clock;
        s26_s$clock = clock;
        s26_flag$clock = clock;
        s26_valid$d = s26_valid$q;
        s26_s$d = s26_s$q;
        s26_flag$d = s26_flag$q;
        mul_0$clock = clock;
        mul_1$clock = clock;
        mul_2$clock = clock;
        add_0$clock = clock;
        add_1$clock = clock;
        add_2$clock = clock;
        add_3$clock = clock;
        mul_0$round_up = r_mul$q;
        mul_1$round_up = r_mul$q;
        mul_2$round_up = r_mul$q;
        add_0$round_up = r_sum$q;
        add_1$round_up = r_sum$q;
        add_2$round_up = r_u$q;
        add_3$round_up = r_s$q;
        s1_valid$d = valid_in;
        s1_d0$d = d0;
        s1_d1$d = d1;
        s1_d2$d = d2;
        s1_c0$d = c0;
        s1_c1$d = c1;
        s1_c2$d = c2;
        s1_c$d = c;
        s1_e$d = e;
        s1_round$d = round_up;
        r_mul$d = s1_round$q;
        r_sum$d = r_mul$q;
        r_u$d = r_sum$q;
        r_s$d = r_u$q;
        mul_0$a = s1_d0$q;
        mul_0$b = s1_c0$q;
        mul_0$valid_in = s1_valid$q;
        mul_1$a = s1_d1$q;
        mul_1$b = s1_c1$q;
        mul_1$valid_in = s1_valid$q;
        mul_2$a = s1_d2$q;
        mul_2$b = s1_c2$q;
        mul_2$valid_in = s1_valid$q;
        c_2$d = s1_c$q;
        c_3$d = c_2$q;
        c_4$d = c_3$q;
        c_5$d = c_4$q;
        c_6$d = c_5$q;
        c_7$d = c_6$q;
        add_0$a = mul_0$y;
        add_0$b = mul_1$y;
        add_0$sub = 1'b0;
        add_0$valid_in = mul_0$valid_out;
        add_1$a = mul_2$y;
        add_1$b = c_7$q;
        add_1$sub = 1'b0;
        add_1$valid_in = mul_0$valid_out;
        add_2$a = add_0$y;
        add_2$b = add_1$y;
        add_2$sub = 1'b0;
        add_2$valid_in = add_0$valid_out;
        e_2$d = s1_e$q;
        e_3$d = e_2$q;
        e_4$d = e_3$q;
        e_5$d = e_4$q;
        e_6$d = e_5$q;
        e_7$d = e_6$q;
        e_8$d = e_7$q;
        e_9$d = e_8$q;
        e_10$d = e_9$q;
        e_11$d = e_10$q;
        e_12$d = e_11$q;
        e_13$d = e_12$q;
        e_14$d = e_13$q;
        e_15$d = e_14$q;
        e_16$d = e_15$q;
        e_17$d = e_16$q;
        e_18$d = e_17$q;
        e_19$d = e_18$q;
        add_3$a = add_2$y;
        add_3$b = e_19$q;
        add_3$sub = 1'b0;
        add_3$valid_in = add_2$valid_out;
        c15_exp = add_3$y[(32'h17)+:(8)];
        c15_frac = add_3$y[(32'h0)+:(23)];
        c15_mag = add_3$y[(32'h0)+:(31)];
        c15_nan = &c15_exp & (c15_frac != 32'h0);
        s26_valid$d = add_3$valid_out;
        s26_s$d = add_3$y;
        s26_flag$d = add_3$y[32'h1f] & (c15_mag != 32'h0) & ~c15_nan;
        s = s26_s$q;
        flag = s26_flag$q;
        valid_out = s26_valid$q;
    end
    
endmodule // top


module top$add_0(clock,a,b,sub,valid_in,y,valid_out,round_up);
    
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
    localparam  c_ones = 27'h7ffffff;
    localparam  c_top = 27'h4000000;
    
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
    reg  [23:0] s1_big$d;
    wire  [23:0] s1_big$q;
    reg  s1_big$clock;
    reg  [23:0] s1_small$d;
    wire  [23:0] s1_small$q;
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
    reg  [26:0] s2_big$d;
    wire  [26:0] s2_big$q;
    reg  s2_big$clock;
    reg  [26:0] s2_small$d;
    wire  [26:0] s2_small$q;
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
    reg  [27:0] s3_sum$d;
    wire  [27:0] s3_sum$q;
    reg  s3_sum$clock;
    reg  [26:0] s3_marker$d;
    wire  [26:0] s3_marker$q;
    reg  s3_marker$clock;
    reg  [26:0] lzc$x;
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
    reg  [27:0] s4_sum$d;
    wire  [27:0] s4_sum$q;
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
    reg  [25:0] s5_nm$d;
    wire  [25:0] s5_nm$q;
    reg  s5_nm$clock;
    reg  round$round_up;
    reg  round$sign;
    reg  round$nan;
    reg  round$inf;
    reg  round$zero;
    reg  round$ovf;
    reg  [7:0] round$efield;
    reg  [25:0] round$nm;
    wire  [31:0] round$y;
    reg  s6_valid$d;
    wire  s6_valid$q;
    reg  s6_valid$clock;
    reg  [31:0] s6_y$d;
    wire  [31:0] s6_y$q;
    reg  s6_y$clock;
    
    // Local signals
    reg  c1_b_sign;
    reg  c1_swap;
    reg  [7:0] c1_d_ab;
    reg  [7:0] c1_d_ba;
    reg  [7:0] c1_sh_ab;
    reg  [7:0] c1_sh_ba;
    reg  c1_inf_sign;
    reg  [26:0] c2_small_ext;
    reg  [26:0] c2_aligned;
    reg  [26:0] c2_mask;
    reg  c2_lost;
    reg  [27:0] c3_sum;
    reg  [7:0] c3_limit;
    reg  c4_zero;
    reg  c4_sign;
    reg  [26:0] c5_shifted;
    reg  [9:0] c5_exp;
    reg  [25:0] c5_nm;
    
    // Sub module instances
    top$add_0$unpack_a unpack_a(
        .x(unpack_a$x),
        .sign(unpack_a$sign),
        .exp(unpack_a$exp),
        .sig(unpack_a$sig),
        .is_zero(unpack_a$is_zero),
        .is_inf(unpack_a$is_inf),
        .is_nan(unpack_a$is_nan)
    );
    top$add_0$unpack_a unpack_b(
        .x(unpack_b$x),
        .sign(unpack_b$sign),
        .exp(unpack_b$exp),
        .sig(unpack_b$sig),
        .is_zero(unpack_b$is_zero),
        .is_inf(unpack_b$is_inf),
        .is_nan(unpack_b$is_nan)
    );
    top$add_0$s1_eff_sub s1_valid(
        .d(s1_valid$d),
        .q(s1_valid$q),
        .clock(s1_valid$clock)
    );
    top$add_0$s1_eff_sub s1_nan(
        .d(s1_nan$d),
        .q(s1_nan$q),
        .clock(s1_nan$clock)
    );
    top$add_0$s1_eff_sub s1_inf(
        .d(s1_inf$d),
        .q(s1_inf$q),
        .clock(s1_inf$clock)
    );
    top$add_0$s1_eff_sub s1_inf_sign(
        .d(s1_inf_sign$d),
        .q(s1_inf_sign$q),
        .clock(s1_inf_sign$clock)
    );
    top$add_0$s1_eff_sub s1_zero_sign(
        .d(s1_zero_sign$d),
        .q(s1_zero_sign$q),
        .clock(s1_zero_sign$clock)
    );
    top$add_0$s1_eff_sub s1_sign(
        .d(s1_sign$d),
        .q(s1_sign$q),
        .clock(s1_sign$clock)
    );
    top$add_0$s1_eff_sub s1_eff_sub(
        .d(s1_eff_sub$d),
        .q(s1_eff_sub$q),
        .clock(s1_eff_sub$clock)
    );
    top$add_0$s1_exp s1_exp(
        .d(s1_exp$d),
        .q(s1_exp$q),
        .clock(s1_exp$clock)
    );
    top$add_0$s1_big s1_big(
        .d(s1_big$d),
        .q(s1_big$q),
        .clock(s1_big$clock)
    );
    top$add_0$s1_big s1_small(
        .d(s1_small$d),
        .q(s1_small$q),
        .clock(s1_small$clock)
    );
    top$add_0$s1_exp s1_shift(
        .d(s1_shift$d),
        .q(s1_shift$q),
        .clock(s1_shift$clock)
    );
    top$add_0$s1_eff_sub s2_valid(
        .d(s2_valid$d),
        .q(s2_valid$q),
        .clock(s2_valid$clock)
    );
    top$add_0$s1_eff_sub s2_nan(
        .d(s2_nan$d),
        .q(s2_nan$q),
        .clock(s2_nan$clock)
    );
    top$add_0$s1_eff_sub s2_inf(
        .d(s2_inf$d),
        .q(s2_inf$q),
        .clock(s2_inf$clock)
    );
    top$add_0$s1_eff_sub s2_inf_sign(
        .d(s2_inf_sign$d),
        .q(s2_inf_sign$q),
        .clock(s2_inf_sign$clock)
    );
    top$add_0$s1_eff_sub s2_zero_sign(
        .d(s2_zero_sign$d),
        .q(s2_zero_sign$q),
        .clock(s2_zero_sign$clock)
    );
    top$add_0$s1_eff_sub s2_sign(
        .d(s2_sign$d),
        .q(s2_sign$q),
        .clock(s2_sign$clock)
    );
    top$add_0$s1_eff_sub s2_eff_sub(
        .d(s2_eff_sub$d),
        .q(s2_eff_sub$q),
        .clock(s2_eff_sub$clock)
    );
    top$add_0$s1_exp s2_exp(
        .d(s2_exp$d),
        .q(s2_exp$q),
        .clock(s2_exp$clock)
    );
    top$add_0$s2_big s2_big(
        .d(s2_big$d),
        .q(s2_big$q),
        .clock(s2_big$clock)
    );
    top$add_0$s2_big s2_small(
        .d(s2_small$d),
        .q(s2_small$q),
        .clock(s2_small$clock)
    );
    top$add_0$s1_eff_sub s3_valid(
        .d(s3_valid$d),
        .q(s3_valid$q),
        .clock(s3_valid$clock)
    );
    top$add_0$s1_eff_sub s3_nan(
        .d(s3_nan$d),
        .q(s3_nan$q),
        .clock(s3_nan$clock)
    );
    top$add_0$s1_eff_sub s3_inf(
        .d(s3_inf$d),
        .q(s3_inf$q),
        .clock(s3_inf$clock)
    );
    top$add_0$s1_eff_sub s3_inf_sign(
        .d(s3_inf_sign$d),
        .q(s3_inf_sign$q),
        .clock(s3_inf_sign$clock)
    );
    top$add_0$s1_eff_sub s3_zero_sign(
        .d(s3_zero_sign$d),
        .q(s3_zero_sign$q),
        .clock(s3_zero_sign$clock)
    );
    top$add_0$s1_eff_sub s3_sign(
        .d(s3_sign$d),
        .q(s3_sign$q),
        .clock(s3_sign$clock)
    );
    top$add_0$s1_exp s3_exp(
        .d(s3_exp$d),
        .q(s3_exp$q),
        .clock(s3_exp$clock)
    );
    top$add_0$s3_sum s3_sum(
        .d(s3_sum$d),
        .q(s3_sum$q),
        .clock(s3_sum$clock)
    );
    top$add_0$s2_big s3_marker(
        .d(s3_marker$d),
        .q(s3_marker$q),
        .clock(s3_marker$clock)
    );
    top$add_0$lzc lzc(
        .x(lzc$x),
        .lz(lzc$lz)
    );
    top$add_0$s1_eff_sub s4_valid(
        .d(s4_valid$d),
        .q(s4_valid$q),
        .clock(s4_valid$clock)
    );
    top$add_0$s1_eff_sub s4_sign(
        .d(s4_sign$d),
        .q(s4_sign$q),
        .clock(s4_sign$clock)
    );
    top$add_0$s1_eff_sub s4_nan(
        .d(s4_nan$d),
        .q(s4_nan$q),
        .clock(s4_nan$clock)
    );
    top$add_0$s1_eff_sub s4_inf(
        .d(s4_inf$d),
        .q(s4_inf$q),
        .clock(s4_inf$clock)
    );
    top$add_0$s1_eff_sub s4_zero(
        .d(s4_zero$d),
        .q(s4_zero$q),
        .clock(s4_zero$clock)
    );
    top$add_0$s1_exp s4_exp(
        .d(s4_exp$d),
        .q(s4_exp$q),
        .clock(s4_exp$clock)
    );
    top$add_0$s1_exp s4_shift(
        .d(s4_shift$d),
        .q(s4_shift$q),
        .clock(s4_shift$clock)
    );
    top$add_0$s3_sum s4_sum(
        .d(s4_sum$d),
        .q(s4_sum$q),
        .clock(s4_sum$clock)
    );
    top$add_0$s1_eff_sub s5_valid(
        .d(s5_valid$d),
        .q(s5_valid$q),
        .clock(s5_valid$clock)
    );
    top$add_0$s1_eff_sub s5_sign(
        .d(s5_sign$d),
        .q(s5_sign$q),
        .clock(s5_sign$clock)
    );
    top$add_0$s1_eff_sub s5_nan(
        .d(s5_nan$d),
        .q(s5_nan$q),
        .clock(s5_nan$clock)
    );
    top$add_0$s1_eff_sub s5_inf(
        .d(s5_inf$d),
        .q(s5_inf$q),
        .clock(s5_inf$clock)
    );
    top$add_0$s1_eff_sub s5_zero(
        .d(s5_zero$d),
        .q(s5_zero$q),
        .clock(s5_zero$clock)
    );
    top$add_0$s1_eff_sub s5_ovf(
        .d(s5_ovf$d),
        .q(s5_ovf$q),
        .clock(s5_ovf$clock)
    );
    top$add_0$s1_exp s5_efield(
        .d(s5_efield$d),
        .q(s5_efield$q),
        .clock(s5_efield$clock)
    );
    top$add_0$s5_nm s5_nm(
        .d(s5_nm$d),
        .q(s5_nm$q),
        .clock(s5_nm$clock)
    );
    top$add_0$round round(
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
    top$add_0$s1_eff_sub s6_valid(
        .d(s6_valid$d),
        .q(s6_valid$q),
        .clock(s6_valid$clock)
    );
    top$add_0$s6_y s6_y(
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
        c1_swap = a[(32'h0)+:(31)] < b[(32'h0)+:(31)];
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
        c2_small_ext = ((s1_small$q) & 27'h7ffffff) << 32'h3;
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
        s2_big$d = ((s1_big$q) & 27'h7ffffff) << 32'h3;
        s2_small$d = (c2_aligned & ~(1 << (32'h0)) | ((c2_aligned[32'h0] | c2_lost) << (32'h0)));
        c3_sum = ((s2_big$q) & 28'hfffffff) + ((s2_small$q) & 28'hfffffff);
        if (s2_eff_sub$q) begin
            c3_sum = ((s2_big$q) & 28'hfffffff) - ((s2_small$q) & 28'hfffffff);
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
        lzc$x = s3_sum$q[(32'h0)+:(27)] | s3_marker$q;
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
        c5_shifted = s4_sum$q[(32'h0)+:(27)] << s4_shift$q;
        c5_exp = ((s4_exp$q) & 10'h3ff) - ((s4_shift$q) & 10'h3ff);
        c5_nm = (((c5_shifted >> 32'h1) & 26'h3ffffff) & ~(1 << (32'h0)) | ((c5_shifted[32'h1] | c5_shifted[32'h0]) << (32'h0)));
        if (s4_sum$q[32'h1b]) begin
            c5_exp = ((s4_exp$q) & 10'h3ff) + 32'h1;
            c5_nm = (((s4_sum$q >> 32'h2) & 26'h3ffffff) & ~(1 << (32'h0)) | ((s4_sum$q[32'h2] | s4_sum$q[32'h1] | s4_sum$q[32'h0]) << (32'h0)));
        end
        s5_valid$d = s4_valid$q;
        s5_sign$d = s4_sign$q;
        s5_nan$d = s4_nan$q;
        s5_inf$d = s4_inf$q;
        s5_zero$d = s4_zero$q;
        s5_ovf$d = c5_exp >= c_exp_ones;
        s5_efield$d = 32'h0;
        if (c5_nm[32'h18 + 32'h1]) begin
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
    
endmodule // top$add_0


module top$add_0$lzc(x,lz);
    
    // Module arguments
    input wire  [26:0] x;
    output reg  [4:0] lz;
    
    // Constant declarations
    localparam  mask0 = 27'h2aaaaaa;
    localparam  mask1 = 27'h1999999;
    localparam  mask2 = 27'h787878;
    localparam  mask3 = 27'h7f807;
    localparam  mask4 = 27'h7ff;
    
    // Local signals
    reg  [26:0] p1;
    reg  [26:0] p2;
    reg  [26:0] p4;
    reg  [26:0] p8;
    reg  [26:0] p16;
    reg  [26:0] lead;
    
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
    
endmodule // top$add_0$lzc


module top$add_0$round(round_up,sign,nan,inf,zero,ovf,efield,nm,y);
    
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
    
endmodule // top$add_0$round


module top$add_0$s1_big(d,q,clock);
    
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
          
endmodule // top$add_0$s1_big


module top$add_0$s1_eff_sub(d,q,clock);
    
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
          
endmodule // top$add_0$s1_eff_sub


module top$add_0$s1_exp(d,q,clock);
    
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
          
endmodule // top$add_0$s1_exp


module top$add_0$s2_big(d,q,clock);
    
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
          
endmodule // top$add_0$s2_big


module top$add_0$s3_sum(d,q,clock);
    
    // Module arguments
    input wire  [27:0] d;
    output reg  [27:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 28'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$add_0$s3_sum


module top$add_0$s5_nm(d,q,clock);
    
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
          
endmodule // top$add_0$s5_nm


module top$add_0$s6_y(d,q,clock);
    
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
          
endmodule // top$add_0$s6_y


module top$add_0$unpack_a(x,sign,exp,sig,is_zero,is_inf,is_nan);
    
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
    
endmodule // top$add_0$unpack_a


module top$mul_0(clock,a,b,valid_in,y,valid_out,round_up);
    
    // Module arguments
    input wire  clock;
    input wire  [31:0] a;
    input wire  [31:0] b;
    input wire  valid_in;
    output reg  [31:0] y;
    output reg  valid_out;
    input wire  round_up;
    
    // Constant declarations
    localparam  c_exp_adj = 10'b10000001;
    localparam  c_exp_ofs = 10'b100000000;
    localparam  c_exp_norm_min = 10'b100000001;
    localparam  c_exp_ovf = 10'b111111111;
    localparam  c_shift_cap = 10'b11010;
    localparam  c_ones = 26'h3ffffff;
    
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
    reg  [23:0] lzc_a$x;
    wire  [4:0] lzc_a$lz;
    reg  [23:0] lzc_b$x;
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
    reg  [23:0] s1_sig_a$d;
    wire  [23:0] s1_sig_a$q;
    reg  s1_sig_a$clock;
    reg  [23:0] s1_sig_b$d;
    wire  [23:0] s1_sig_b$q;
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
    reg  [23:0] s2_sig_a$d;
    wire  [23:0] s2_sig_a$q;
    reg  s2_sig_a$clock;
    reg  [23:0] s2_sig_b$d;
    wire  [23:0] s2_sig_b$q;
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
    reg  [25:0] s4_nm$d;
    wire  [25:0] s4_nm$q;
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
    reg  [25:0] s5_nm$d;
    wire  [25:0] s5_nm$q;
    reg  s5_nm$clock;
    reg  round$round_up;
    reg  round$sign;
    reg  round$nan;
    reg  round$inf;
    reg  round$zero;
    reg  round$ovf;
    reg  [7:0] round$efield;
    reg  [25:0] round$nm;
    wire  [31:0] round$y;
    reg  s6_valid$d;
    wire  s6_valid$q;
    reg  s6_valid$clock;
    reg  [31:0] s6_y$d;
    wire  [31:0] s6_y$q;
    reg  s6_y$clock;
    
    // Local signals
    reg  [15:0] c3_a_lo;
    reg  [15:0] c3_a_hi;
    reg  [15:0] c3_b_lo;
    reg  [15:0] c3_b_hi;
    reg  [9:0] c3_e1;
    reg  [47:0] c4_prod;
    reg  [25:0] c4_hi;
    reg  c4_sticky;
    reg  [9:0] c4_cap0;
    reg  [9:0] c4_cap1;
    reg  [25:0] c5_shifted;
    reg  [25:0] c5_mask;
    reg  c5_lost;
    
    // Sub module instances
    top$add_0$unpack_a unpack_a(
        .x(unpack_a$x),
        .sign(unpack_a$sign),
        .exp(unpack_a$exp),
        .sig(unpack_a$sig),
        .is_zero(unpack_a$is_zero),
        .is_inf(unpack_a$is_inf),
        .is_nan(unpack_a$is_nan)
    );
    top$add_0$unpack_a unpack_b(
        .x(unpack_b$x),
        .sign(unpack_b$sign),
        .exp(unpack_b$exp),
        .sig(unpack_b$sig),
        .is_zero(unpack_b$is_zero),
        .is_inf(unpack_b$is_inf),
        .is_nan(unpack_b$is_nan)
    );
    top$mul_0$lzc_a lzc_a(
        .x(lzc_a$x),
        .lz(lzc_a$lz)
    );
    top$mul_0$lzc_a lzc_b(
        .x(lzc_b$x),
        .lz(lzc_b$lz)
    );
    top$add_0$s1_eff_sub s1_valid(
        .d(s1_valid$d),
        .q(s1_valid$q),
        .clock(s1_valid$clock)
    );
    top$add_0$s1_eff_sub s1_sign(
        .d(s1_sign$d),
        .q(s1_sign$q),
        .clock(s1_sign$clock)
    );
    top$add_0$s1_eff_sub s1_nan(
        .d(s1_nan$d),
        .q(s1_nan$q),
        .clock(s1_nan$clock)
    );
    top$add_0$s1_eff_sub s1_inf(
        .d(s1_inf$d),
        .q(s1_inf$q),
        .clock(s1_inf$clock)
    );
    top$add_0$s1_eff_sub s1_zero(
        .d(s1_zero$d),
        .q(s1_zero$q),
        .clock(s1_zero$clock)
    );
    top$add_0$s1_exp s1_exp_a(
        .d(s1_exp_a$d),
        .q(s1_exp_a$q),
        .clock(s1_exp_a$clock)
    );
    top$add_0$s1_exp s1_exp_b(
        .d(s1_exp_b$d),
        .q(s1_exp_b$q),
        .clock(s1_exp_b$clock)
    );
    top$add_0$s1_big s1_sig_a(
        .d(s1_sig_a$d),
        .q(s1_sig_a$q),
        .clock(s1_sig_a$clock)
    );
    top$add_0$s1_big s1_sig_b(
        .d(s1_sig_b$d),
        .q(s1_sig_b$q),
        .clock(s1_sig_b$clock)
    );
    top$mul_0$s1_lz_a s1_lz_a(
        .d(s1_lz_a$d),
        .q(s1_lz_a$q),
        .clock(s1_lz_a$clock)
    );
    top$mul_0$s1_lz_a s1_lz_b(
        .d(s1_lz_b$d),
        .q(s1_lz_b$q),
        .clock(s1_lz_b$clock)
    );
    top$add_0$s1_eff_sub s2_valid(
        .d(s2_valid$d),
        .q(s2_valid$q),
        .clock(s2_valid$clock)
    );
    top$add_0$s1_eff_sub s2_sign(
        .d(s2_sign$d),
        .q(s2_sign$q),
        .clock(s2_sign$clock)
    );
    top$add_0$s1_eff_sub s2_nan(
        .d(s2_nan$d),
        .q(s2_nan$q),
        .clock(s2_nan$clock)
    );
    top$add_0$s1_eff_sub s2_inf(
        .d(s2_inf$d),
        .q(s2_inf$q),
        .clock(s2_inf$clock)
    );
    top$add_0$s1_eff_sub s2_zero(
        .d(s2_zero$d),
        .q(s2_zero$q),
        .clock(s2_zero$clock)
    );
    top$mul_0$s2_exp s2_exp(
        .d(s2_exp$d),
        .q(s2_exp$q),
        .clock(s2_exp$clock)
    );
    top$add_0$s1_big s2_sig_a(
        .d(s2_sig_a$d),
        .q(s2_sig_a$q),
        .clock(s2_sig_a$clock)
    );
    top$add_0$s1_big s2_sig_b(
        .d(s2_sig_b$d),
        .q(s2_sig_b$q),
        .clock(s2_sig_b$clock)
    );
    top$add_0$s1_eff_sub s3_valid(
        .d(s3_valid$d),
        .q(s3_valid$q),
        .clock(s3_valid$clock)
    );
    top$add_0$s1_eff_sub s3_sign(
        .d(s3_sign$d),
        .q(s3_sign$q),
        .clock(s3_sign$clock)
    );
    top$add_0$s1_eff_sub s3_nan(
        .d(s3_nan$d),
        .q(s3_nan$q),
        .clock(s3_nan$clock)
    );
    top$add_0$s1_eff_sub s3_inf(
        .d(s3_inf$d),
        .q(s3_inf$q),
        .clock(s3_inf$clock)
    );
    top$add_0$s1_eff_sub s3_zero(
        .d(s3_zero$d),
        .q(s3_zero$q),
        .clock(s3_zero$clock)
    );
    top$add_0$s6_y s3_ll(
        .d(s3_ll$d),
        .q(s3_ll$q),
        .clock(s3_ll$clock)
    );
    top$add_0$s6_y s3_lh(
        .d(s3_lh$d),
        .q(s3_lh$q),
        .clock(s3_lh$clock)
    );
    top$add_0$s6_y s3_hl(
        .d(s3_hl$d),
        .q(s3_hl$q),
        .clock(s3_hl$clock)
    );
    top$add_0$s6_y s3_hh(
        .d(s3_hh$d),
        .q(s3_hh$q),
        .clock(s3_hh$clock)
    );
    top$add_0$s1_eff_sub s3_lt0(
        .d(s3_lt0$d),
        .q(s3_lt0$q),
        .clock(s3_lt0$clock)
    );
    top$add_0$s1_eff_sub s3_lt1(
        .d(s3_lt1$d),
        .q(s3_lt1$q),
        .clock(s3_lt1$clock)
    );
    top$mul_0$s2_exp s3_u0(
        .d(s3_u0$d),
        .q(s3_u0$q),
        .clock(s3_u0$clock)
    );
    top$mul_0$s2_exp s3_u1(
        .d(s3_u1$d),
        .q(s3_u1$q),
        .clock(s3_u1$clock)
    );
    top$add_0$s1_eff_sub s3_ovf0(
        .d(s3_ovf0$d),
        .q(s3_ovf0$q),
        .clock(s3_ovf0$clock)
    );
    top$add_0$s1_eff_sub s3_ovf1(
        .d(s3_ovf1$d),
        .q(s3_ovf1$q),
        .clock(s3_ovf1$clock)
    );
    top$add_0$s1_exp s3_efield0(
        .d(s3_efield0$d),
        .q(s3_efield0$q),
        .clock(s3_efield0$clock)
    );
    top$add_0$s1_exp s3_efield1(
        .d(s3_efield1$d),
        .q(s3_efield1$q),
        .clock(s3_efield1$clock)
    );
    top$add_0$s1_eff_sub s4_valid(
        .d(s4_valid$d),
        .q(s4_valid$q),
        .clock(s4_valid$clock)
    );
    top$add_0$s1_eff_sub s4_sign(
        .d(s4_sign$d),
        .q(s4_sign$q),
        .clock(s4_sign$clock)
    );
    top$add_0$s1_eff_sub s4_nan(
        .d(s4_nan$d),
        .q(s4_nan$q),
        .clock(s4_nan$clock)
    );
    top$add_0$s1_eff_sub s4_inf(
        .d(s4_inf$d),
        .q(s4_inf$q),
        .clock(s4_inf$clock)
    );
    top$add_0$s1_eff_sub s4_zero(
        .d(s4_zero$d),
        .q(s4_zero$q),
        .clock(s4_zero$clock)
    );
    top$add_0$s5_nm s4_nm(
        .d(s4_nm$d),
        .q(s4_nm$q),
        .clock(s4_nm$clock)
    );
    top$mul_0$s2_exp s4_cap(
        .d(s4_cap$d),
        .q(s4_cap$q),
        .clock(s4_cap$clock)
    );
    top$add_0$s1_eff_sub s4_ovf(
        .d(s4_ovf$d),
        .q(s4_ovf$q),
        .clock(s4_ovf$clock)
    );
    top$add_0$s1_exp s4_efield(
        .d(s4_efield$d),
        .q(s4_efield$q),
        .clock(s4_efield$clock)
    );
    top$add_0$s1_eff_sub s5_valid(
        .d(s5_valid$d),
        .q(s5_valid$q),
        .clock(s5_valid$clock)
    );
    top$add_0$s1_eff_sub s5_sign(
        .d(s5_sign$d),
        .q(s5_sign$q),
        .clock(s5_sign$clock)
    );
    top$add_0$s1_eff_sub s5_nan(
        .d(s5_nan$d),
        .q(s5_nan$q),
        .clock(s5_nan$clock)
    );
    top$add_0$s1_eff_sub s5_inf(
        .d(s5_inf$d),
        .q(s5_inf$q),
        .clock(s5_inf$clock)
    );
    top$add_0$s1_eff_sub s5_zero(
        .d(s5_zero$d),
        .q(s5_zero$q),
        .clock(s5_zero$clock)
    );
    top$add_0$s1_eff_sub s5_ovf(
        .d(s5_ovf$d),
        .q(s5_ovf$q),
        .clock(s5_ovf$clock)
    );
    top$add_0$s1_exp s5_efield(
        .d(s5_efield$d),
        .q(s5_efield$q),
        .clock(s5_efield$clock)
    );
    top$add_0$s5_nm s5_nm(
        .d(s5_nm$d),
        .q(s5_nm$q),
        .clock(s5_nm$clock)
    );
    top$add_0$round round(
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
    top$add_0$s1_eff_sub s6_valid(
        .d(s6_valid$d),
        .q(s6_valid$q),
        .clock(s6_valid$clock)
    );
    top$add_0$s6_y s6_y(
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
        c3_a_lo = ((s2_sig_a$q[(32'h0)+:(12)]) & 16'hffff);
        c3_a_hi = ((s2_sig_a$q[(32'hc)+:(12)]) & 16'hffff);
        c3_b_lo = ((s2_sig_b$q[(32'h0)+:(12)]) & 16'hffff);
        c3_b_hi = ((s2_sig_b$q[(32'hc)+:(12)]) & 16'hffff);
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
        c4_prod = ((s3_ll$q) & 48'hffffffffffff) + (((s3_lh$q) & 48'hffffffffffff) << 32'hc) + (((s3_hl$q) & 48'hffffffffffff) << 32'hc) + (((s3_hh$q) & 48'hffffffffffff) << 32'h18);
        c4_hi = ((c4_prod >> 32'h16) & 26'h3ffffff);
        c4_sticky = |c4_prod[(32'h0)+:(22)];
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
        if (c4_hi[32'h18 + 32'h1]) begin
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
    
endmodule // top$mul_0


module top$mul_0$lzc_a(x,lz);
    
    // Module arguments
    input wire  [23:0] x;
    output reg  [4:0] lz;
    
    // Constant declarations
    localparam  mask0 = 24'h555555;
    localparam  mask1 = 24'h333333;
    localparam  mask2 = 24'hf0f0f;
    localparam  mask3 = 24'hff00;
    localparam  mask4 = 24'hff;
    
    // Local signals
    reg  [23:0] p1;
    reg  [23:0] p2;
    reg  [23:0] p4;
    reg  [23:0] p8;
    reg  [23:0] p16;
    reg  [23:0] lead;
    
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
    
endmodule // top$mul_0$lzc_a


module top$mul_0$s1_lz_a(d,q,clock);
    
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
          
endmodule // top$mul_0$s1_lz_a


module top$mul_0$s2_exp(d,q,clock);
    
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
          
endmodule // top$mul_0$s2_exp


module top$r_mul(clock,d,q);
    
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
    reg  line$2$d;
    wire  line$2$q;
    reg  line$2$clock;
    reg  line$3$d;
    wire  line$3$q;
    reg  line$3$clock;
    reg  line$4$d;
    wire  line$4$q;
    reg  line$4$clock;
    
    // Sub module instances
    top$add_0$s1_eff_sub line$0(
        .d(line$0$d),
        .q(line$0$q),
        .clock(line$0$clock)
    );
    top$add_0$s1_eff_sub line$1(
        .d(line$1$d),
        .q(line$1$q),
        .clock(line$1$clock)
    );
    top$add_0$s1_eff_sub line$2(
        .d(line$2$d),
        .q(line$2$q),
        .clock(line$2$clock)
    );
    top$add_0$s1_eff_sub line$3(
        .d(line$3$d),
        .q(line$3$q),
        .clock(line$3$clock)
    );
    top$add_0$s1_eff_sub line$4(
        .d(line$4$d),
        .q(line$4$q),
        .clock(line$4$clock)
    );
    
    // Update code
    always @(*) begin
        line$0$clock = clock;
        line$0$d = d;
        line$1$clock = clock;
        line$1$d = d;
        line$2$clock = clock;
        line$2$d = d;
        line$3$clock = clock;
        line$3$d = d;
        line$4$clock = clock;
        line$4$d = d;
        line$0$d = line$1$q;
        line$1$d = line$2$q;
        line$2$d = line$3$q;
        line$3$d = line$4$q;
        q = line$0$q;
    end
    
endmodule // top$r_mul


module top$r_s(clock,d,q);
    
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
    reg  line$2$d;
    wire  line$2$q;
    reg  line$2$clock;
    reg  line$3$d;
    wire  line$3$q;
    reg  line$3$clock;
    reg  line$4$d;
    wire  line$4$q;
    reg  line$4$clock;
    reg  line$5$d;
    wire  line$5$q;
    reg  line$5$clock;
    
    // Sub module instances
    top$add_0$s1_eff_sub line$0(
        .d(line$0$d),
        .q(line$0$q),
        .clock(line$0$clock)
    );
    top$add_0$s1_eff_sub line$1(
        .d(line$1$d),
        .q(line$1$q),
        .clock(line$1$clock)
    );
    top$add_0$s1_eff_sub line$2(
        .d(line$2$d),
        .q(line$2$q),
        .clock(line$2$clock)
    );
    top$add_0$s1_eff_sub line$3(
        .d(line$3$d),
        .q(line$3$q),
        .clock(line$3$clock)
    );
    top$add_0$s1_eff_sub line$4(
        .d(line$4$d),
        .q(line$4$q),
        .clock(line$4$clock)
    );
    top$add_0$s1_eff_sub line$5(
        .d(line$5$d),
        .q(line$5$q),
        .clock(line$5$clock)
    );
    
    // Update code
    always @(*) begin
        line$0$clock = clock;
        line$0$d = d;
        line$1$clock = clock;
        line$1$d = d;
        line$2$clock = clock;
        line$2$d = d;
        line$3$clock = clock;
        line$3$d = d;
        line$4$clock = clock;
        line$4$d = d;
        line$5$clock = clock;
        line$5$d = d;
        line$0$d = line$1$q;
        line$1$d = line$2$q;
        line$2$d = line$3$q;
        line$3$d = line$4$q;
        line$4$d = line$5$q;
        q = line$0$q;
    end
    
endmodule // top$r_s
