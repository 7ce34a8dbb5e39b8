

module top(clock,load_en,load_addr,load_data,a_m_0$0,a_m_0$1,a_m_0$2,a_m_0$3,a_m_1$0,a_m_1$1,a_m_1$2,a_m_1$3,a_m_2$0,a_m_2$1,a_m_2$2,a_m_2$3,a_alpha_m,a_alpha_f,a_v_x$0,a_v_x$1,a_v_x$2,a_v_y$0,a_v_y$1,a_v_y$2,a_v_z$0,a_v_z$1,a_v_z$2,a_v_exact,a_degenerate,b_m_0$0,b_m_0$1,b_m_0$2,b_m_0$3,b_m_1$0,b_m_1$1,b_m_1$2,b_m_1$3,b_m_2$0,b_m_2$1,b_m_2$2,b_m_2$3,b_alpha_m,b_alpha_f,b_v_x$0,b_v_x$1,b_v_x$2,b_v_y$0,b_v_y$1,b_v_y$2,b_v_z$0,b_v_z$1,b_v_z$2,b_v_exact,b_degenerate,tag,in_valid,in_ready,out_tag,out_hit,out_uncertain,out_valid,out_ready);
    
    // Module arguments
    input wire  clock;
    input wire  load_en;
    input wire  [4:0] load_addr;
    input wire  [23:0] load_data;
    input wire  [23:0] a_m_0$0;
    input wire  [23:0] a_m_0$1;
    input wire  [23:0] a_m_0$2;
    input wire  [23:0] a_m_0$3;
    input wire  [23:0] a_m_1$0;
    input wire  [23:0] a_m_1$1;
    input wire  [23:0] a_m_1$2;
    input wire  [23:0] a_m_1$3;
    input wire  [23:0] a_m_2$0;
    input wire  [23:0] a_m_2$1;
    input wire  [23:0] a_m_2$2;
    input wire  [23:0] a_m_2$3;
    input wire  [23:0] a_alpha_m;
    input wire  [23:0] a_alpha_f;
    input wire  [23:0] a_v_x$0;
    input wire  [23:0] a_v_x$1;
    input wire  [23:0] a_v_x$2;
    input wire  [23:0] a_v_y$0;
    input wire  [23:0] a_v_y$1;
    input wire  [23:0] a_v_y$2;
    input wire  [23:0] a_v_z$0;
    input wire  [23:0] a_v_z$1;
    input wire  [23:0] a_v_z$2;
    input wire  a_v_exact;
    input wire  a_degenerate;
    input wire  [23:0] b_m_0$0;
    input wire  [23:0] b_m_0$1;
    input wire  [23:0] b_m_0$2;
    input wire  [23:0] b_m_0$3;
    input wire  [23:0] b_m_1$0;
    input wire  [23:0] b_m_1$1;
    input wire  [23:0] b_m_1$2;
    input wire  [23:0] b_m_1$3;
    input wire  [23:0] b_m_2$0;
    input wire  [23:0] b_m_2$1;
    input wire  [23:0] b_m_2$2;
    input wire  [23:0] b_m_2$3;
    input wire  [23:0] b_alpha_m;
    input wire  [23:0] b_alpha_f;
    input wire  [23:0] b_v_x$0;
    input wire  [23:0] b_v_x$1;
    input wire  [23:0] b_v_x$2;
    input wire  [23:0] b_v_y$0;
    input wire  [23:0] b_v_y$1;
    input wire  [23:0] b_v_y$2;
    input wire  [23:0] b_v_z$0;
    input wire  [23:0] b_v_z$1;
    input wire  [23:0] b_v_z$2;
    input wire  b_v_exact;
    input wire  b_degenerate;
    input wire  [31:0] tag;
    input wire  in_valid;
    output reg  in_ready;
    output reg  [31:0] out_tag;
    output reg  out_hit;
    output reg  out_uncertain;
    output reg  out_valid;
    input wire  out_ready;
    
    // Stub signals
    reg  run$d;
    wire  run$q;
    reg  run$clock;
    reg  [7:0] counter$d;
    wire  [7:0] counter$q;
    reg  counter$clock;
    reg  [23:0] frame$0$d;
    wire  [23:0] frame$0$q;
    reg  frame$0$clock;
    reg  [23:0] frame$1$d;
    wire  [23:0] frame$1$q;
    reg  frame$1$clock;
    reg  [23:0] frame$2$d;
    wire  [23:0] frame$2$q;
    reg  frame$2$clock;
    reg  [23:0] frame$3$d;
    wire  [23:0] frame$3$q;
    reg  frame$3$clock;
    reg  [23:0] frame$4$d;
    wire  [23:0] frame$4$q;
    reg  frame$4$clock;
    reg  [23:0] frame$5$d;
    wire  [23:0] frame$5$q;
    reg  frame$5$clock;
    reg  [23:0] frame$6$d;
    wire  [23:0] frame$6$q;
    reg  frame$6$clock;
    reg  [23:0] frame$7$d;
    wire  [23:0] frame$7$q;
    reg  frame$7$clock;
    reg  [23:0] frame$8$d;
    wire  [23:0] frame$8$q;
    reg  frame$8$clock;
    reg  [23:0] frame$9$d;
    wire  [23:0] frame$9$q;
    reg  frame$9$clock;
    reg  [23:0] frame$10$d;
    wire  [23:0] frame$10$q;
    reg  frame$10$clock;
    reg  [23:0] frame$11$d;
    wire  [23:0] frame$11$q;
    reg  frame$11$clock;
    reg  [23:0] frame$12$d;
    wire  [23:0] frame$12$q;
    reg  frame$12$clock;
    reg  [23:0] frame$13$d;
    wire  [23:0] frame$13$q;
    reg  frame$13$clock;
    reg  [23:0] frame$14$d;
    wire  [23:0] frame$14$q;
    reg  frame$14$clock;
    reg  [23:0] frame$15$d;
    wire  [23:0] frame$15$q;
    reg  frame$15$clock;
    reg  [23:0] frame$16$d;
    wire  [23:0] frame$16$q;
    reg  frame$16$clock;
    reg  [23:0] frame$17$d;
    wire  [23:0] frame$17$q;
    reg  frame$17$clock;
    reg  [23:0] frame$18$d;
    wire  [23:0] frame$18$q;
    reg  frame$18$clock;
    reg  [23:0] frame$19$d;
    wire  [23:0] frame$19$q;
    reg  frame$19$clock;
    reg  [23:0] frame$20$d;
    wire  [23:0] frame$20$q;
    reg  frame$20$clock;
    reg  [23:0] frame$21$d;
    wire  [23:0] frame$21$q;
    reg  frame$21$clock;
    reg  [23:0] frame$22$d;
    wire  [23:0] frame$22$q;
    reg  frame$22$clock;
    reg  [23:0] frame$23$d;
    wire  [23:0] frame$23$q;
    reg  frame$23$clock;
    reg  [23:0] frame$24$d;
    wire  [23:0] frame$24$q;
    reg  frame$24$clock;
    reg  [23:0] frame$25$d;
    wire  [23:0] frame$25$q;
    reg  frame$25$clock;
    reg  [23:0] frame$26$d;
    wire  [23:0] frame$26$q;
    reg  frame$26$clock;
    reg  [23:0] frame$27$d;
    wire  [23:0] frame$27$q;
    reg  frame$27$clock;
    reg  [23:0] frame$28$d;
    wire  [23:0] frame$28$q;
    reg  frame$28$clock;
    reg  [23:0] frame$29$d;
    wire  [23:0] frame$29$q;
    reg  frame$29$clock;
    reg  [23:0] held$0$d;
    wire  [23:0] held$0$q;
    reg  held$0$clock;
    reg  [23:0] held$1$d;
    wire  [23:0] held$1$q;
    reg  held$1$clock;
    reg  [23:0] held$2$d;
    wire  [23:0] held$2$q;
    reg  held$2$clock;
    reg  [23:0] held$3$d;
    wire  [23:0] held$3$q;
    reg  held$3$clock;
    reg  [23:0] held$4$d;
    wire  [23:0] held$4$q;
    reg  held$4$clock;
    reg  [23:0] held$5$d;
    wire  [23:0] held$5$q;
    reg  held$5$clock;
    reg  [23:0] held$6$d;
    wire  [23:0] held$6$q;
    reg  held$6$clock;
    reg  [23:0] held$7$d;
    wire  [23:0] held$7$q;
    reg  held$7$clock;
    reg  [23:0] held$8$d;
    wire  [23:0] held$8$q;
    reg  held$8$clock;
    reg  [23:0] held$9$d;
    wire  [23:0] held$9$q;
    reg  held$9$clock;
    reg  [23:0] held$10$d;
    wire  [23:0] held$10$q;
    reg  held$10$clock;
    reg  [23:0] held$11$d;
    wire  [23:0] held$11$q;
    reg  held$11$clock;
    reg  [23:0] held$12$d;
    wire  [23:0] held$12$q;
    reg  held$12$clock;
    reg  [23:0] held$13$d;
    wire  [23:0] held$13$q;
    reg  held$13$clock;
    reg  [23:0] held$14$d;
    wire  [23:0] held$14$q;
    reg  held$14$clock;
    reg  [23:0] held$15$d;
    wire  [23:0] held$15$q;
    reg  held$15$clock;
    reg  [23:0] held$16$d;
    wire  [23:0] held$16$q;
    reg  held$16$clock;
    reg  [23:0] held$17$d;
    wire  [23:0] held$17$q;
    reg  held$17$clock;
    reg  [23:0] held$18$d;
    wire  [23:0] held$18$q;
    reg  held$18$clock;
    reg  [23:0] held$19$d;
    wire  [23:0] held$19$q;
    reg  held$19$clock;
    reg  [23:0] held$20$d;
    wire  [23:0] held$20$q;
    reg  held$20$clock;
    reg  [23:0] held$21$d;
    wire  [23:0] held$21$q;
    reg  held$21$clock;
    reg  [23:0] held$22$d;
    wire  [23:0] held$22$q;
    reg  held$22$clock;
    reg  [23:0] held$23$d;
    wire  [23:0] held$23$q;
    reg  held$23$clock;
    reg  [23:0] held$24$d;
    wire  [23:0] held$24$q;
    reg  held$24$clock;
    reg  [23:0] held$25$d;
    wire  [23:0] held$25$q;
    reg  held$25$clock;
    reg  [23:0] held$26$d;
    wire  [23:0] held$26$q;
    reg  held$26$clock;
    reg  [23:0] held$27$d;
    wire  [23:0] held$27$q;
    reg  held$27$clock;
    reg  [23:0] held$28$d;
    wire  [23:0] held$28$q;
    reg  held$28$clock;
    reg  [23:0] held$29$d;
    wire  [23:0] held$29$q;
    reg  held$29$clock;
    reg  [23:0] held$30$d;
    wire  [23:0] held$30$q;
    reg  held$30$clock;
    reg  [23:0] held$31$d;
    wire  [23:0] held$31$q;
    reg  held$31$clock;
    reg  [23:0] held$32$d;
    wire  [23:0] held$32$q;
    reg  held$32$clock;
    reg  [23:0] held$33$d;
    wire  [23:0] held$33$q;
    reg  held$33$clock;
    reg  [23:0] held$34$d;
    wire  [23:0] held$34$q;
    reg  held$34$clock;
    reg  [23:0] held$35$d;
    wire  [23:0] held$35$q;
    reg  held$35$clock;
    reg  [23:0] held$36$d;
    wire  [23:0] held$36$q;
    reg  held$36$clock;
    reg  [23:0] held$37$d;
    wire  [23:0] held$37$q;
    reg  held$37$clock;
    reg  held_exact$d;
    wire  held_exact$q;
    reg  held_exact$clock;
    reg  [31:0] held_tag$d;
    wire  [31:0] held_tag$q;
    reg  held_tag$clock;
    reg  held_valid$d;
    wire  held_valid$q;
    reg  held_valid$clock;
    reg  [23:0] tin$0$d;
    wire  [23:0] tin$0$q;
    reg  tin$0$clock;
    reg  [23:0] tin$1$d;
    wire  [23:0] tin$1$q;
    reg  tin$1$clock;
    reg  [23:0] tin$2$d;
    wire  [23:0] tin$2$q;
    reg  tin$2$clock;
    reg  [23:0] tin$3$d;
    wire  [23:0] tin$3$q;
    reg  tin$3$clock;
    reg  [23:0] tin$4$d;
    wire  [23:0] tin$4$q;
    reg  tin$4$clock;
    reg  [23:0] tin$5$d;
    wire  [23:0] tin$5$q;
    reg  tin$5$clock;
    reg  [23:0] tin$6$d;
    wire  [23:0] tin$6$q;
    reg  tin$6$clock;
    reg  [23:0] tin$7$d;
    wire  [23:0] tin$7$q;
    reg  tin$7$clock;
    reg  [23:0] tin$8$d;
    wire  [23:0] tin$8$q;
    reg  tin$8$clock;
    reg  [23:0] tin$9$d;
    wire  [23:0] tin$9$q;
    reg  tin$9$clock;
    reg  [23:0] tin$10$d;
    wire  [23:0] tin$10$q;
    reg  tin$10$clock;
    reg  [23:0] tin$11$d;
    wire  [23:0] tin$11$q;
    reg  tin$11$clock;
    reg  [23:0] tin$12$d;
    wire  [23:0] tin$12$q;
    reg  tin$12$clock;
    reg  [23:0] tin$13$d;
    wire  [23:0] tin$13$q;
    reg  tin$13$clock;
    reg  [23:0] tin$14$d;
    wire  [23:0] tin$14$q;
    reg  tin$14$clock;
    reg  [23:0] tin$15$d;
    wire  [23:0] tin$15$q;
    reg  tin$15$clock;
    reg  [23:0] tin$16$d;
    wire  [23:0] tin$16$q;
    reg  tin$16$clock;
    reg  [23:0] tin$17$d;
    wire  [23:0] tin$17$q;
    reg  tin$17$clock;
    reg  [23:0] tin$18$d;
    wire  [23:0] tin$18$q;
    reg  tin$18$clock;
    reg  [23:0] tin$19$d;
    wire  [23:0] tin$19$q;
    reg  tin$19$clock;
    reg  [23:0] tin$20$d;
    wire  [23:0] tin$20$q;
    reg  tin$20$clock;
    reg  [23:0] tin$21$d;
    wire  [23:0] tin$21$q;
    reg  tin$21$clock;
    reg  [23:0] tin$22$d;
    wire  [23:0] tin$22$q;
    reg  tin$22$clock;
    reg  [23:0] tin$23$d;
    wire  [23:0] tin$23$q;
    reg  tin$23$clock;
    reg  [23:0] tin$24$d;
    wire  [23:0] tin$24$q;
    reg  tin$24$clock;
    reg  [23:0] tin$25$d;
    wire  [23:0] tin$25$q;
    reg  tin$25$clock;
    reg  [23:0] tin$26$d;
    wire  [23:0] tin$26$q;
    reg  tin$26$clock;
    reg  [23:0] tin$27$d;
    wire  [23:0] tin$27$q;
    reg  tin$27$clock;
    reg  [23:0] tin$28$d;
    wire  [23:0] tin$28$q;
    reg  tin$28$clock;
    reg  [23:0] tin$29$d;
    wire  [23:0] tin$29$q;
    reg  tin$29$clock;
    reg  [23:0] tin$30$d;
    wire  [23:0] tin$30$q;
    reg  tin$30$clock;
    reg  [23:0] tin$31$d;
    wire  [23:0] tin$31$q;
    reg  tin$31$clock;
    reg  [23:0] tin$32$d;
    wire  [23:0] tin$32$q;
    reg  tin$32$clock;
    reg  [23:0] tin$33$d;
    wire  [23:0] tin$33$q;
    reg  tin$33$clock;
    reg  [23:0] tin$34$d;
    wire  [23:0] tin$34$q;
    reg  tin$34$clock;
    reg  [23:0] tin$35$d;
    wire  [23:0] tin$35$q;
    reg  tin$35$clock;
    reg  [23:0] tin$36$d;
    wire  [23:0] tin$36$q;
    reg  tin$36$clock;
    reg  [23:0] tin$37$d;
    wire  [23:0] tin$37$q;
    reg  tin$37$clock;
    reg  tin_bits$0$d;
    wire  tin_bits$0$q;
    reg  tin_bits$0$clock;
    reg  tin_bits$1$d;
    wire  tin_bits$1$q;
    reg  tin_bits$1$clock;
    reg  [31:0] tin_tag$0$d;
    wire  [31:0] tin_tag$0$q;
    reg  tin_tag$0$clock;
    reg  flags$0$d;
    wire  flags$0$q;
    reg  flags$0$clock;
    reg  flags$1$d;
    wire  flags$1$q;
    reg  flags$1$clock;
    reg  tc$clock;
    reg  [23:0] tc$m_0$0;
    reg  [23:0] tc$m_0$1;
    reg  [23:0] tc$m_0$2;
    reg  [23:0] tc$m_0$3;
    reg  [23:0] tc$m_1$0;
    reg  [23:0] tc$m_1$1;
    reg  [23:0] tc$m_1$2;
    reg  [23:0] tc$m_1$3;
    reg  [23:0] tc$m_2$0;
    reg  [23:0] tc$m_2$1;
    reg  [23:0] tc$m_2$2;
    reg  [23:0] tc$m_2$3;
    reg  [23:0] tc$alpha_m;
    reg  [23:0] tc$alpha_f;
    reg  [23:0] tc$f_0$0;
    reg  [23:0] tc$f_0$1;
    reg  [23:0] tc$f_0$2;
    reg  [23:0] tc$f_0$3;
    reg  [23:0] tc$f_1$0;
    reg  [23:0] tc$f_1$1;
    reg  [23:0] tc$f_1$2;
    reg  [23:0] tc$f_1$3;
    reg  [23:0] tc$f_2$0;
    reg  [23:0] tc$f_2$1;
    reg  [23:0] tc$f_2$2;
    reg  [23:0] tc$f_2$3;
    reg  [23:0] tc$beta_m;
    reg  [23:0] tc$beta_f;
    reg  [23:0] tc$scale;
    reg  [23:0] tc$v_x$0;
    reg  [23:0] tc$v_x$1;
    reg  [23:0] tc$v_x$2;
    reg  [23:0] tc$v_y$0;
    reg  [23:0] tc$v_y$1;
    reg  [23:0] tc$v_y$2;
    reg  [23:0] tc$v_z$0;
    reg  [23:0] tc$v_z$1;
    reg  [23:0] tc$v_z$2;
    reg  tc$v_exact;
    reg  [31:0] tc$tag;
    reg  tc$valid_in;
    wire  [23:0] tc$s_x$0;
    wire  [23:0] tc$s_x$1;
    wire  [23:0] tc$s_x$2;
    wire  [23:0] tc$s_b$0;
    wire  [23:0] tc$s_b$1;
    wire  [23:0] tc$s_b$2;
    wire  tc$cross_t$0;
    wire  tc$cross_t$1;
    wire  tc$cross_t$2;
    wire  tc$cross_f$0;
    wire  tc$cross_f$1;
    wire  tc$cross_f$2;
    wire  tc$hit;
    wire  tc$miss;
    wire  [31:0] tc$tag_out;
    wire  tc$valid_out;
    reg  ab_t$d;
    wire  ab_t$q;
    reg  ab_t$clock;
    reg  ab_f$d;
    wire  ab_f$q;
    reg  ab_f$clock;
    reg  a_deg$d;
    wire  a_deg$q;
    reg  a_deg$clock;
    reg  fifo$clock;
    reg  fifo$read;
    wire  [33:0] fifo$data_out;
    wire  fifo$empty;
    wire  fifo$almost_empty;
    wire  fifo$underflow;
    reg  fifo$write;
    reg  [33:0] fifo$data_in;
    wire  fifo$full;
    wire  fifo$almost_full;
    wire  fifo$overflow;
    reg  [8:0] count$d;
    wire  [8:0] count$q;
    reg  count$clock;
    
    // Sub module instances
    top$a_deg run(
        .d(run$d),
        .q(run$q),
        .clock(run$clock)
    );
    top$counter counter(
        .d(counter$d),
        .q(counter$q),
        .clock(counter$clock)
    );
    top$frame$0 frame$0(
        .d(frame$0$d),
        .q(frame$0$q),
        .clock(frame$0$clock)
    );
    top$frame$0 frame$1(
        .d(frame$1$d),
        .q(frame$1$q),
        .clock(frame$1$clock)
    );
    top$frame$0 frame$2(
        .d(frame$2$d),
        .q(frame$2$q),
        .clock(frame$2$clock)
    );
    top$frame$0 frame$3(
        .d(frame$3$d),
        .q(frame$3$q),
        .clock(frame$3$clock)
    );
    top$frame$0 frame$4(
        .d(frame$4$d),
        .q(frame$4$q),
        .clock(frame$4$clock)
    );
    top$frame$0 frame$5(
        .d(frame$5$d),
        .q(frame$5$q),
        .clock(frame$5$clock)
    );
    top$frame$0 frame$6(
        .d(frame$6$d),
        .q(frame$6$q),
        .clock(frame$6$clock)
    );
    top$frame$0 frame$7(
        .d(frame$7$d),
        .q(frame$7$q),
        .clock(frame$7$clock)
    );
    top$frame$0 frame$8(
        .d(frame$8$d),
        .q(frame$8$q),
        .clock(frame$8$clock)
    );
    top$frame$0 frame$9(
        .d(frame$9$d),
        .q(frame$9$q),
        .clock(frame$9$clock)
    );
    top$frame$0 frame$10(
        .d(frame$10$d),
        .q(frame$10$q),
        .clock(frame$10$clock)
    );
    top$frame$0 frame$11(
        .d(frame$11$d),
        .q(frame$11$q),
        .clock(frame$11$clock)
    );
    top$frame$0 frame$12(
        .d(frame$12$d),
        .q(frame$12$q),
        .clock(frame$12$clock)
    );
    top$frame$0 frame$13(
        .d(frame$13$d),
        .q(frame$13$q),
        .clock(frame$13$clock)
    );
    top$frame$0 frame$14(
        .d(frame$14$d),
        .q(frame$14$q),
        .clock(frame$14$clock)
    );
    top$frame$0 frame$15(
        .d(frame$15$d),
        .q(frame$15$q),
        .clock(frame$15$clock)
    );
    top$frame$0 frame$16(
        .d(frame$16$d),
        .q(frame$16$q),
        .clock(frame$16$clock)
    );
    top$frame$0 frame$17(
        .d(frame$17$d),
        .q(frame$17$q),
        .clock(frame$17$clock)
    );
    top$frame$0 frame$18(
        .d(frame$18$d),
        .q(frame$18$q),
        .clock(frame$18$clock)
    );
    top$frame$0 frame$19(
        .d(frame$19$d),
        .q(frame$19$q),
        .clock(frame$19$clock)
    );
    top$frame$0 frame$20(
        .d(frame$20$d),
        .q(frame$20$q),
        .clock(frame$20$clock)
    );
    top$frame$0 frame$21(
        .d(frame$21$d),
        .q(frame$21$q),
        .clock(frame$21$clock)
    );
    top$frame$0 frame$22(
        .d(frame$22$d),
        .q(frame$22$q),
        .clock(frame$22$clock)
    );
    top$frame$0 frame$23(
        .d(frame$23$d),
        .q(frame$23$q),
        .clock(frame$23$clock)
    );
    top$frame$0 frame$24(
        .d(frame$24$d),
        .q(frame$24$q),
        .clock(frame$24$clock)
    );
    top$frame$0 frame$25(
        .d(frame$25$d),
        .q(frame$25$q),
        .clock(frame$25$clock)
    );
    top$frame$0 frame$26(
        .d(frame$26$d),
        .q(frame$26$q),
        .clock(frame$26$clock)
    );
    top$frame$0 frame$27(
        .d(frame$27$d),
        .q(frame$27$q),
        .clock(frame$27$clock)
    );
    top$frame$0 frame$28(
        .d(frame$28$d),
        .q(frame$28$q),
        .clock(frame$28$clock)
    );
    top$frame$0 frame$29(
        .d(frame$29$d),
        .q(frame$29$q),
        .clock(frame$29$clock)
    );
    top$frame$0 held$0(
        .d(held$0$d),
        .q(held$0$q),
        .clock(held$0$clock)
    );
    top$frame$0 held$1(
        .d(held$1$d),
        .q(held$1$q),
        .clock(held$1$clock)
    );
    top$frame$0 held$2(
        .d(held$2$d),
        .q(held$2$q),
        .clock(held$2$clock)
    );
    top$frame$0 held$3(
        .d(held$3$d),
        .q(held$3$q),
        .clock(held$3$clock)
    );
    top$frame$0 held$4(
        .d(held$4$d),
        .q(held$4$q),
        .clock(held$4$clock)
    );
    top$frame$0 held$5(
        .d(held$5$d),
        .q(held$5$q),
        .clock(held$5$clock)
    );
    top$frame$0 held$6(
        .d(held$6$d),
        .q(held$6$q),
        .clock(held$6$clock)
    );
    top$frame$0 held$7(
        .d(held$7$d),
        .q(held$7$q),
        .clock(held$7$clock)
    );
    top$frame$0 held$8(
        .d(held$8$d),
        .q(held$8$q),
        .clock(held$8$clock)
    );
    top$frame$0 held$9(
        .d(held$9$d),
        .q(held$9$q),
        .clock(held$9$clock)
    );
    top$frame$0 held$10(
        .d(held$10$d),
        .q(held$10$q),
        .clock(held$10$clock)
    );
    top$frame$0 held$11(
        .d(held$11$d),
        .q(held$11$q),
        .clock(held$11$clock)
    );
    top$frame$0 held$12(
        .d(held$12$d),
        .q(held$12$q),
        .clock(held$12$clock)
    );
    top$frame$0 held$13(
        .d(held$13$d),
        .q(held$13$q),
        .clock(held$13$clock)
    );
    top$frame$0 held$14(
        .d(held$14$d),
        .q(held$14$q),
        .clock(held$14$clock)
    );
    top$frame$0 held$15(
        .d(held$15$d),
        .q(held$15$q),
        .clock(held$15$clock)
    );
    top$frame$0 held$16(
        .d(held$16$d),
        .q(held$16$q),
        .clock(held$16$clock)
    );
    top$frame$0 held$17(
        .d(held$17$d),
        .q(held$17$q),
        .clock(held$17$clock)
    );
    top$frame$0 held$18(
        .d(held$18$d),
        .q(held$18$q),
        .clock(held$18$clock)
    );
    top$frame$0 held$19(
        .d(held$19$d),
        .q(held$19$q),
        .clock(held$19$clock)
    );
    top$frame$0 held$20(
        .d(held$20$d),
        .q(held$20$q),
        .clock(held$20$clock)
    );
    top$frame$0 held$21(
        .d(held$21$d),
        .q(held$21$q),
        .clock(held$21$clock)
    );
    top$frame$0 held$22(
        .d(held$22$d),
        .q(held$22$q),
        .clock(held$22$clock)
    );
    top$frame$0 held$23(
        .d(held$23$d),
        .q(held$23$q),
        .clock(held$23$clock)
    );
    top$frame$0 held$24(
        .d(held$24$d),
        .q(held$24$q),
        .clock(held$24$clock)
    );
    top$frame$0 held$25(
        .d(held$25$d),
        .q(held$25$q),
        .clock(held$25$clock)
    );
    top$frame$0 held$26(
        .d(held$26$d),
        .q(held$26$q),
        .clock(held$26$clock)
    );
    top$frame$0 held$27(
        .d(held$27$d),
        .q(held$27$q),
        .clock(held$27$clock)
    );
    top$frame$0 held$28(
        .d(held$28$d),
        .q(held$28$q),
        .clock(held$28$clock)
    );
    top$frame$0 held$29(
        .d(held$29$d),
        .q(held$29$q),
        .clock(held$29$clock)
    );
    top$frame$0 held$30(
        .d(held$30$d),
        .q(held$30$q),
        .clock(held$30$clock)
    );
    top$frame$0 held$31(
        .d(held$31$d),
        .q(held$31$q),
        .clock(held$31$clock)
    );
    top$frame$0 held$32(
        .d(held$32$d),
        .q(held$32$q),
        .clock(held$32$clock)
    );
    top$frame$0 held$33(
        .d(held$33$d),
        .q(held$33$q),
        .clock(held$33$clock)
    );
    top$frame$0 held$34(
        .d(held$34$d),
        .q(held$34$q),
        .clock(held$34$clock)
    );
    top$frame$0 held$35(
        .d(held$35$d),
        .q(held$35$q),
        .clock(held$35$clock)
    );
    top$frame$0 held$36(
        .d(held$36$d),
        .q(held$36$q),
        .clock(held$36$clock)
    );
    top$frame$0 held$37(
        .d(held$37$d),
        .q(held$37$q),
        .clock(held$37$clock)
    );
    top$a_deg held_exact(
        .d(held_exact$d),
        .q(held_exact$q),
        .clock(held_exact$clock)
    );
    top$held_tag held_tag(
        .d(held_tag$d),
        .q(held_tag$q),
        .clock(held_tag$clock)
    );
    top$a_deg held_valid(
        .d(held_valid$d),
        .q(held_valid$q),
        .clock(held_valid$clock)
    );
    top$frame$0 tin$0(
        .d(tin$0$d),
        .q(tin$0$q),
        .clock(tin$0$clock)
    );
    top$frame$0 tin$1(
        .d(tin$1$d),
        .q(tin$1$q),
        .clock(tin$1$clock)
    );
    top$frame$0 tin$2(
        .d(tin$2$d),
        .q(tin$2$q),
        .clock(tin$2$clock)
    );
    top$frame$0 tin$3(
        .d(tin$3$d),
        .q(tin$3$q),
        .clock(tin$3$clock)
    );
    top$frame$0 tin$4(
        .d(tin$4$d),
        .q(tin$4$q),
        .clock(tin$4$clock)
    );
    top$frame$0 tin$5(
        .d(tin$5$d),
        .q(tin$5$q),
        .clock(tin$5$clock)
    );
    top$frame$0 tin$6(
        .d(tin$6$d),
        .q(tin$6$q),
        .clock(tin$6$clock)
    );
    top$frame$0 tin$7(
        .d(tin$7$d),
        .q(tin$7$q),
        .clock(tin$7$clock)
    );
    top$frame$0 tin$8(
        .d(tin$8$d),
        .q(tin$8$q),
        .clock(tin$8$clock)
    );
    top$frame$0 tin$9(
        .d(tin$9$d),
        .q(tin$9$q),
        .clock(tin$9$clock)
    );
    top$frame$0 tin$10(
        .d(tin$10$d),
        .q(tin$10$q),
        .clock(tin$10$clock)
    );
    top$frame$0 tin$11(
        .d(tin$11$d),
        .q(tin$11$q),
        .clock(tin$11$clock)
    );
    top$frame$0 tin$12(
        .d(tin$12$d),
        .q(tin$12$q),
        .clock(tin$12$clock)
    );
    top$frame$0 tin$13(
        .d(tin$13$d),
        .q(tin$13$q),
        .clock(tin$13$clock)
    );
    top$frame$0 tin$14(
        .d(tin$14$d),
        .q(tin$14$q),
        .clock(tin$14$clock)
    );
    top$frame$0 tin$15(
        .d(tin$15$d),
        .q(tin$15$q),
        .clock(tin$15$clock)
    );
    top$frame$0 tin$16(
        .d(tin$16$d),
        .q(tin$16$q),
        .clock(tin$16$clock)
    );
    top$frame$0 tin$17(
        .d(tin$17$d),
        .q(tin$17$q),
        .clock(tin$17$clock)
    );
    top$frame$0 tin$18(
        .d(tin$18$d),
        .q(tin$18$q),
        .clock(tin$18$clock)
    );
    top$frame$0 tin$19(
        .d(tin$19$d),
        .q(tin$19$q),
        .clock(tin$19$clock)
    );
    top$frame$0 tin$20(
        .d(tin$20$d),
        .q(tin$20$q),
        .clock(tin$20$clock)
    );
    top$frame$0 tin$21(
        .d(tin$21$d),
        .q(tin$21$q),
        .clock(tin$21$clock)
    );
    top$frame$0 tin$22(
        .d(tin$22$d),
        .q(tin$22$q),
        .clock(tin$22$clock)
    );
    top$frame$0 tin$23(
        .d(tin$23$d),
        .q(tin$23$q),
        .clock(tin$23$clock)
    );
    top$frame$0 tin$24(
        .d(tin$24$d),
        .q(tin$24$q),
        .clock(tin$24$clock)
    );
    top$frame$0 tin$25(
        .d(tin$25$d),
        .q(tin$25$q),
        .clock(tin$25$clock)
    );
    top$frame$0 tin$26(
        .d(tin$26$d),
        .q(tin$26$q),
        .clock(tin$26$clock)
    );
    top$frame$0 tin$27(
        .d(tin$27$d),
        .q(tin$27$q),
        .clock(tin$27$clock)
    );
    top$frame$0 tin$28(
        .d(tin$28$d),
        .q(tin$28$q),
        .clock(tin$28$clock)
    );
    top$frame$0 tin$29(
        .d(tin$29$d),
        .q(tin$29$q),
        .clock(tin$29$clock)
    );
    top$frame$0 tin$30(
        .d(tin$30$d),
        .q(tin$30$q),
        .clock(tin$30$clock)
    );
    top$frame$0 tin$31(
        .d(tin$31$d),
        .q(tin$31$q),
        .clock(tin$31$clock)
    );
    top$frame$0 tin$32(
        .d(tin$32$d),
        .q(tin$32$q),
        .clock(tin$32$clock)
    );
    top$frame$0 tin$33(
        .d(tin$33$d),
        .q(tin$33$q),
        .clock(tin$33$clock)
    );
    top$frame$0 tin$34(
        .d(tin$34$d),
        .q(tin$34$q),
        .clock(tin$34$clock)
    );
    top$frame$0 tin$35(
        .d(tin$35$d),
        .q(tin$35$q),
        .clock(tin$35$clock)
    );
    top$frame$0 tin$36(
        .d(tin$36$d),
        .q(tin$36$q),
        .clock(tin$36$clock)
    );
    top$frame$0 tin$37(
        .d(tin$37$d),
        .q(tin$37$q),
        .clock(tin$37$clock)
    );
    top$a_deg tin_bits$0(
        .d(tin_bits$0$d),
        .q(tin_bits$0$q),
        .clock(tin_bits$0$clock)
    );
    top$a_deg tin_bits$1(
        .d(tin_bits$1$d),
        .q(tin_bits$1$q),
        .clock(tin_bits$1$clock)
    );
    top$held_tag tin_tag$0(
        .d(tin_tag$0$d),
        .q(tin_tag$0$q),
        .clock(tin_tag$0$clock)
    );
    top$a_deg flags$0(
        .d(flags$0$d),
        .q(flags$0$q),
        .clock(flags$0$clock)
    );
    top$a_deg flags$1(
        .d(flags$1$d),
        .q(flags$1$q),
        .clock(flags$1$clock)
    );
    top$tc tc(
        .clock(tc$clock),
        .m_0$0(tc$m_0$0),
        .m_0$1(tc$m_0$1),
        .m_0$2(tc$m_0$2),
        .m_0$3(tc$m_0$3),
        .m_1$0(tc$m_1$0),
        .m_1$1(tc$m_1$1),
        .m_1$2(tc$m_1$2),
        .m_1$3(tc$m_1$3),
        .m_2$0(tc$m_2$0),
        .m_2$1(tc$m_2$1),
        .m_2$2(tc$m_2$2),
        .m_2$3(tc$m_2$3),
        .alpha_m(tc$alpha_m),
        .alpha_f(tc$alpha_f),
        .f_0$0(tc$f_0$0),
        .f_0$1(tc$f_0$1),
        .f_0$2(tc$f_0$2),
        .f_0$3(tc$f_0$3),
        .f_1$0(tc$f_1$0),
        .f_1$1(tc$f_1$1),
        .f_1$2(tc$f_1$2),
        .f_1$3(tc$f_1$3),
        .f_2$0(tc$f_2$0),
        .f_2$1(tc$f_2$1),
        .f_2$2(tc$f_2$2),
        .f_2$3(tc$f_2$3),
        .beta_m(tc$beta_m),
        .beta_f(tc$beta_f),
        .scale(tc$scale),
        .v_x$0(tc$v_x$0),
        .v_x$1(tc$v_x$1),
        .v_x$2(tc$v_x$2),
        .v_y$0(tc$v_y$0),
        .v_y$1(tc$v_y$1),
        .v_y$2(tc$v_y$2),
        .v_z$0(tc$v_z$0),
        .v_z$1(tc$v_z$1),
        .v_z$2(tc$v_z$2),
        .v_exact(tc$v_exact),
        .tag(tc$tag),
        .valid_in(tc$valid_in),
        .s_x$0(tc$s_x$0),
        .s_x$1(tc$s_x$1),
        .s_x$2(tc$s_x$2),
        .s_b$0(tc$s_b$0),
        .s_b$1(tc$s_b$1),
        .s_b$2(tc$s_b$2),
        .cross_t$0(tc$cross_t$0),
        .cross_t$1(tc$cross_t$1),
        .cross_t$2(tc$cross_t$2),
        .cross_f$0(tc$cross_f$0),
        .cross_f$1(tc$cross_f$1),
        .cross_f$2(tc$cross_f$2),
        .hit(tc$hit),
        .miss(tc$miss),
        .tag_out(tc$tag_out),
        .valid_out(tc$valid_out)
    );
    top$a_deg ab_t(
        .d(ab_t$d),
        .q(ab_t$q),
        .clock(ab_t$clock)
    );
    top$a_deg ab_f(
        .d(ab_f$d),
        .q(ab_f$q),
        .clock(ab_f$clock)
    );
    top$a_deg a_deg(
        .d(a_deg$d),
        .q(a_deg$q),
        .clock(a_deg$clock)
    );
    top$fifo fifo(
        .clock(fifo$clock),
        .read(fifo$read),
        .data_out(fifo$data_out),
        .empty(fifo$empty),
        .almost_empty(fifo$almost_empty),
        .underflow(fifo$underflow),
        .write(fifo$write),
        .data_in(fifo$data_in),
        .full(fifo$full),
        .almost_full(fifo$almost_full),
        .overflow(fifo$overflow)
    );
    top$count count(
        .d(count$d),
        .q(count$q),
        .clock(count$clock)
    );
    
    // Update code (custom)
    always @(*) begin
      in_ready = (counter$q == 8'd0) && (count$q != 9'd256);
      run$clock = clock;
      run$d = run$q | (in_valid && counter$q == 8'd0 && count$q != 9'd256);
      counter$clock = clock;
      counter$d = (!(run$q | (in_valid && counter$q == 8'd0 && count$q != 9'd256)) || counter$q == 8'd31) ? 8'd0 : counter$q + 8'd1;
      flags$0$clock = clock;
      flags$0$d = counter$d != 8'd0;
      flags$1$clock = clock;
      flags$1$d = counter$d == 8'd16;
      frame$0$clock = clock;
      frame$0$d = (load_en && load_addr == 5'd0) ? load_data : frame$0$q;
      frame$1$clock = clock;
      frame$1$d = (load_en && load_addr == 5'd1) ? load_data : frame$1$q;
      frame$2$clock = clock;
      frame$2$d = (load_en && load_addr == 5'd2) ? load_data : frame$2$q;
      frame$3$clock = clock;
      frame$3$d = (load_en && load_addr == 5'd3) ? load_data : frame$3$q;
      frame$4$clock = clock;
      frame$4$d = (load_en && load_addr == 5'd4) ? load_data : frame$4$q;
      frame$5$clock = clock;
      frame$5$d = (load_en && load_addr == 5'd5) ? load_data : frame$5$q;
      frame$6$clock = clock;
      frame$6$d = (load_en && load_addr == 5'd6) ? load_data : frame$6$q;
      frame$7$clock = clock;
      frame$7$d = (load_en && load_addr == 5'd7) ? load_data : frame$7$q;
      frame$8$clock = clock;
      frame$8$d = (load_en && load_addr == 5'd8) ? load_data : frame$8$q;
      frame$9$clock = clock;
      frame$9$d = (load_en && load_addr == 5'd9) ? load_data : frame$9$q;
      frame$10$clock = clock;
      frame$10$d = (load_en && load_addr == 5'd10) ? load_data : frame$10$q;
      frame$11$clock = clock;
      frame$11$d = (load_en && load_addr == 5'd11) ? load_data : frame$11$q;
      frame$12$clock = clock;
      frame$12$d = (load_en && load_addr == 5'd12) ? load_data : frame$12$q;
      frame$13$clock = clock;
      frame$13$d = (load_en && load_addr == 5'd13) ? load_data : frame$13$q;
      frame$14$clock = clock;
      frame$14$d = (load_en && load_addr == 5'd14) ? load_data : frame$14$q;
      frame$15$clock = clock;
      frame$15$d = (load_en && load_addr == 5'd16) ? load_data : frame$15$q;
      frame$16$clock = clock;
      frame$16$d = (load_en && load_addr == 5'd17) ? load_data : frame$16$q;
      frame$17$clock = clock;
      frame$17$d = (load_en && load_addr == 5'd18) ? load_data : frame$17$q;
      frame$18$clock = clock;
      frame$18$d = (load_en && load_addr == 5'd19) ? load_data : frame$18$q;
      frame$19$clock = clock;
      frame$19$d = (load_en && load_addr == 5'd20) ? load_data : frame$19$q;
      frame$20$clock = clock;
      frame$20$d = (load_en && load_addr == 5'd21) ? load_data : frame$20$q;
      frame$21$clock = clock;
      frame$21$d = (load_en && load_addr == 5'd22) ? load_data : frame$21$q;
      frame$22$clock = clock;
      frame$22$d = (load_en && load_addr == 5'd23) ? load_data : frame$22$q;
      frame$23$clock = clock;
      frame$23$d = (load_en && load_addr == 5'd24) ? load_data : frame$23$q;
      frame$24$clock = clock;
      frame$24$d = (load_en && load_addr == 5'd25) ? load_data : frame$24$q;
      frame$25$clock = clock;
      frame$25$d = (load_en && load_addr == 5'd26) ? load_data : frame$25$q;
      frame$26$clock = clock;
      frame$26$d = (load_en && load_addr == 5'd27) ? load_data : frame$26$q;
      frame$27$clock = clock;
      frame$27$d = (load_en && load_addr == 5'd28) ? load_data : frame$27$q;
      frame$28$clock = clock;
      frame$28$d = (load_en && load_addr == 5'd29) ? load_data : frame$28$q;
      frame$29$clock = clock;
      frame$29$d = (load_en && load_addr == 5'd30) ? load_data : frame$29$q;
      held$0$clock = clock;
      held$0$d = !flags$0$q ? a_m_0$0 : held$0$q;
      tin$0$clock = clock;
      tin$0$d = flags$1$q ? held$0$q : b_m_0$0;
      tc$m_0$0 = tin$0$q;
      held$1$clock = clock;
      held$1$d = !flags$0$q ? a_m_0$1 : held$1$q;
      tin$1$clock = clock;
      tin$1$d = flags$1$q ? held$1$q : b_m_0$1;
      tc$m_0$1 = tin$1$q;
      held$2$clock = clock;
      held$2$d = !flags$0$q ? a_m_0$2 : held$2$q;
      tin$2$clock = clock;
      tin$2$d = flags$1$q ? held$2$q : b_m_0$2;
      tc$m_0$2 = tin$2$q;
      held$3$clock = clock;
      held$3$d = !flags$0$q ? a_m_0$3 : held$3$q;
      tin$3$clock = clock;
      tin$3$d = flags$1$q ? held$3$q : b_m_0$3;
      tc$m_0$3 = tin$3$q;
      held$4$clock = clock;
      held$4$d = !flags$0$q ? a_m_1$0 : held$4$q;
      tin$4$clock = clock;
      tin$4$d = flags$1$q ? held$4$q : b_m_1$0;
      tc$m_1$0 = tin$4$q;
      held$5$clock = clock;
      held$5$d = !flags$0$q ? a_m_1$1 : held$5$q;
      tin$5$clock = clock;
      tin$5$d = flags$1$q ? held$5$q : b_m_1$1;
      tc$m_1$1 = tin$5$q;
      held$6$clock = clock;
      held$6$d = !flags$0$q ? a_m_1$2 : held$6$q;
      tin$6$clock = clock;
      tin$6$d = flags$1$q ? held$6$q : b_m_1$2;
      tc$m_1$2 = tin$6$q;
      held$7$clock = clock;
      held$7$d = !flags$0$q ? a_m_1$3 : held$7$q;
      tin$7$clock = clock;
      tin$7$d = flags$1$q ? held$7$q : b_m_1$3;
      tc$m_1$3 = tin$7$q;
      held$8$clock = clock;
      held$8$d = !flags$0$q ? a_m_2$0 : held$8$q;
      tin$8$clock = clock;
      tin$8$d = flags$1$q ? held$8$q : b_m_2$0;
      tc$m_2$0 = tin$8$q;
      held$9$clock = clock;
      held$9$d = !flags$0$q ? a_m_2$1 : held$9$q;
      tin$9$clock = clock;
      tin$9$d = flags$1$q ? held$9$q : b_m_2$1;
      tc$m_2$1 = tin$9$q;
      held$10$clock = clock;
      held$10$d = !flags$0$q ? a_m_2$2 : held$10$q;
      tin$10$clock = clock;
      tin$10$d = flags$1$q ? held$10$q : b_m_2$2;
      tc$m_2$2 = tin$10$q;
      held$11$clock = clock;
      held$11$d = !flags$0$q ? a_m_2$3 : held$11$q;
      tin$11$clock = clock;
      tin$11$d = flags$1$q ? held$11$q : b_m_2$3;
      tc$m_2$3 = tin$11$q;
      held$12$clock = clock;
      held$12$d = !flags$0$q ? a_alpha_m : held$12$q;
      tin$12$clock = clock;
      tin$12$d = flags$1$q ? held$12$q : b_alpha_m;
      tc$alpha_m = tin$12$q;
      held$13$clock = clock;
      held$13$d = !flags$0$q ? a_alpha_f : held$13$q;
      tin$13$clock = clock;
      tin$13$d = flags$1$q ? held$13$q : b_alpha_f;
      tc$alpha_f = tin$13$q;
      held$14$clock = clock;
      held$14$d = !flags$0$q ? frame$15$q : held$14$q;
      tin$14$clock = clock;
      tin$14$d = flags$1$q ? held$14$q : frame$0$q;
      tc$f_0$0 = tin$14$q;
      held$15$clock = clock;
      held$15$d = !flags$0$q ? frame$16$q : held$15$q;
      tin$15$clock = clock;
      tin$15$d = flags$1$q ? held$15$q : frame$1$q;
      tc$f_0$1 = tin$15$q;
      held$16$clock = clock;
      held$16$d = !flags$0$q ? frame$17$q : held$16$q;
      tin$16$clock = clock;
      tin$16$d = flags$1$q ? held$16$q : frame$2$q;
      tc$f_0$2 = tin$16$q;
      held$17$clock = clock;
      held$17$d = !flags$0$q ? frame$18$q : held$17$q;
      tin$17$clock = clock;
      tin$17$d = flags$1$q ? held$17$q : frame$3$q;
      tc$f_0$3 = tin$17$q;
      held$18$clock = clock;
      held$18$d = !flags$0$q ? frame$19$q : held$18$q;
      tin$18$clock = clock;
      tin$18$d = flags$1$q ? held$18$q : frame$4$q;
      tc$f_1$0 = tin$18$q;
      held$19$clock = clock;
      held$19$d = !flags$0$q ? frame$20$q : held$19$q;
      tin$19$clock = clock;
      tin$19$d = flags$1$q ? held$19$q : frame$5$q;
      tc$f_1$1 = tin$19$q;
      held$20$clock = clock;
      held$20$d = !flags$0$q ? frame$21$q : held$20$q;
      tin$20$clock = clock;
      tin$20$d = flags$1$q ? held$20$q : frame$6$q;
      tc$f_1$2 = tin$20$q;
      held$21$clock = clock;
      held$21$d = !flags$0$q ? frame$22$q : held$21$q;
      tin$21$clock = clock;
      tin$21$d = flags$1$q ? held$21$q : frame$7$q;
      tc$f_1$3 = tin$21$q;
      held$22$clock = clock;
      held$22$d = !flags$0$q ? frame$23$q : held$22$q;
      tin$22$clock = clock;
      tin$22$d = flags$1$q ? held$22$q : frame$8$q;
      tc$f_2$0 = tin$22$q;
      held$23$clock = clock;
      held$23$d = !flags$0$q ? frame$24$q : held$23$q;
      tin$23$clock = clock;
      tin$23$d = flags$1$q ? held$23$q : frame$9$q;
      tc$f_2$1 = tin$23$q;
      held$24$clock = clock;
      held$24$d = !flags$0$q ? frame$25$q : held$24$q;
      tin$24$clock = clock;
      tin$24$d = flags$1$q ? held$24$q : frame$10$q;
      tc$f_2$2 = tin$24$q;
      held$25$clock = clock;
      held$25$d = !flags$0$q ? frame$26$q : held$25$q;
      tin$25$clock = clock;
      tin$25$d = flags$1$q ? held$25$q : frame$11$q;
      tc$f_2$3 = tin$25$q;
      held$26$clock = clock;
      held$26$d = !flags$0$q ? frame$27$q : held$26$q;
      tin$26$clock = clock;
      tin$26$d = flags$1$q ? held$26$q : frame$12$q;
      tc$beta_m = tin$26$q;
      held$27$clock = clock;
      held$27$d = !flags$0$q ? frame$28$q : held$27$q;
      tin$27$clock = clock;
      tin$27$d = flags$1$q ? held$27$q : frame$13$q;
      tc$beta_f = tin$27$q;
      held$28$clock = clock;
      held$28$d = !flags$0$q ? frame$29$q : held$28$q;
      tin$28$clock = clock;
      tin$28$d = flags$1$q ? held$28$q : frame$14$q;
      tc$scale = tin$28$q;
      held$29$clock = clock;
      held$29$d = !flags$0$q ? b_v_x$0 : held$29$q;
      tin$29$clock = clock;
      tin$29$d = flags$1$q ? held$29$q : a_v_x$0;
      tc$v_x$0 = tin$29$q;
      held$30$clock = clock;
      held$30$d = !flags$0$q ? b_v_y$0 : held$30$q;
      tin$30$clock = clock;
      tin$30$d = flags$1$q ? held$30$q : a_v_y$0;
      tc$v_y$0 = tin$30$q;
      held$31$clock = clock;
      held$31$d = !flags$0$q ? b_v_z$0 : held$31$q;
      tin$31$clock = clock;
      tin$31$d = flags$1$q ? held$31$q : a_v_z$0;
      tc$v_z$0 = tin$31$q;
      held$32$clock = clock;
      held$32$d = !flags$0$q ? b_v_x$1 : held$32$q;
      tin$32$clock = clock;
      tin$32$d = flags$1$q ? held$32$q : a_v_x$1;
      tc$v_x$1 = tin$32$q;
      held$33$clock = clock;
      held$33$d = !flags$0$q ? b_v_y$1 : held$33$q;
      tin$33$clock = clock;
      tin$33$d = flags$1$q ? held$33$q : a_v_y$1;
      tc$v_y$1 = tin$33$q;
      held$34$clock = clock;
      held$34$d = !flags$0$q ? b_v_z$1 : held$34$q;
      tin$34$clock = clock;
      tin$34$d = flags$1$q ? held$34$q : a_v_z$1;
      tc$v_z$1 = tin$34$q;
      held$35$clock = clock;
      held$35$d = !flags$0$q ? b_v_x$2 : held$35$q;
      tin$35$clock = clock;
      tin$35$d = flags$1$q ? held$35$q : a_v_x$2;
      tc$v_x$2 = tin$35$q;
      held$36$clock = clock;
      held$36$d = !flags$0$q ? b_v_y$2 : held$36$q;
      tin$36$clock = clock;
      tin$36$d = flags$1$q ? held$36$q : a_v_y$2;
      tc$v_y$2 = tin$36$q;
      held$37$clock = clock;
      held$37$d = !flags$0$q ? b_v_z$2 : held$37$q;
      tin$37$clock = clock;
      tin$37$d = flags$1$q ? held$37$q : a_v_z$2;
      tc$v_z$2 = tin$37$q;
      held_exact$clock = clock;
      held_exact$d = !flags$0$q ? b_v_exact : held_exact$q;
      held_tag$clock = clock;
      held_tag$d = !flags$0$q ? tag : held_tag$q;
      held_valid$clock = clock;
      held_valid$d = !flags$0$q ? (in_valid && counter$q == 8'd0 && count$q != 9'd256) : held_valid$q;
      tc$clock = clock;
      tin_bits$0$clock = clock;
      tin_bits$0$d = flags$1$q ? held_exact$q : a_v_exact;
      tc$v_exact = tin_bits$0$q;
      tin_tag$0$clock = clock;
      tin_tag$0$d = flags$1$q ? held_tag$q : {30'd0, a_degenerate, b_degenerate};
      tc$tag = tin_tag$0$q;
      tin_bits$1$clock = clock;
      tin_bits$1$d = flags$1$q ? held_valid$q : (in_valid && counter$q == 8'd0 && count$q != 9'd256);
      tc$valid_in = tin_bits$1$q;
      ab_t$clock = clock;
      ab_t$d = (tc$valid_out && counter$q == 8'd21) ? (tc$hit & !tc$tag_out[0]) : ab_t$q;
      ab_f$clock = clock;
      ab_f$d = (tc$valid_out && counter$q == 8'd21) ? (tc$miss & !tc$tag_out[0]) : ab_f$q;
      a_deg$clock = clock;
      a_deg$d = (tc$valid_out && counter$q == 8'd21) ? (tc$tag_out[1]) : a_deg$q;
      fifo$clock = clock;
      fifo$write = tc$valid_out && counter$q == 8'd5;
      fifo$data_in = {tc$tag_out, (ab_t$q | (tc$hit & !a_deg$q)), !(ab_t$q | (tc$hit & !a_deg$q)) & !(ab_f$q & tc$miss & !a_deg$q)};
      fifo$read = (out_ready && !fifo$empty);
      count$clock = clock;
      count$d = ((in_valid && counter$q == 8'd0 && count$q != 9'd256) && !(out_ready && !fifo$empty)) ? count$q + 9'd1 : ((out_ready && !fifo$empty) && !(in_valid && counter$q == 8'd0 && count$q != 9'd256)) ? count$q - 9'd1 : count$q;
      out_valid = !fifo$empty;
      out_tag = fifo$data_out[33:2];
      out_hit = fifo$data_out[1];
      out_uncertain = fifo$data_out[0];
    end
endmodule // top


module top$a_deg(d,q,clock);
    
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
          
endmodule // top$a_deg


module top$count(d,q,clock);
    
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
          
endmodule // top$count


module top$counter(d,q,clock);
    
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
          
endmodule // top$counter


module top$fifo(clock,read,data_out,empty,almost_empty,underflow,write,data_in,full,almost_full,overflow);
    
    // Module arguments
    input wire  clock;
    input wire  read;
    output reg  [33:0] data_out;
    output reg  empty;
    output reg  almost_empty;
    output reg  underflow;
    input wire  write;
    input wire  [33:0] data_in;
    output reg  full;
    output reg  almost_full;
    output reg  overflow;
    
    // Stub signals
    reg  [7:0] ram$read_address;
    reg  ram$read_clock;
    wire  [33:0] ram$read_data;
    reg  [7:0] ram$write_address;
    reg  ram$write_clock;
    reg  [33:0] ram$write_data;
    reg  ram$write_enable;
    reg  read_logic$clock;
    reg  read_logic$read;
    wire  [33:0] read_logic$data_out;
    wire  read_logic$empty;
    wire  read_logic$almost_empty;
    wire  read_logic$underflow;
    reg  [8:0] read_logic$write_address_delayed;
    wire  [7:0] read_logic$ram_read_address;
    reg  [33:0] read_logic$ram_read_data;
    wire  read_logic$ram_read_clock;
    wire  [8:0] read_logic$read_address_out;
    wire  [8:0] read_logic$fill_level;
    reg  write_logic$write;
    reg  [33:0] write_logic$data_in;
    wire  write_logic$full;
    wire  write_logic$almost_full;
    wire  write_logic$overflow;
    reg  write_logic$clock;
    wire  [7:0] write_logic$ram_write_address;
    wire  write_logic$ram_write_clock;
    wire  [33:0] write_logic$ram_write_data;
    wire  write_logic$ram_write_enable;
    reg  [8:0] write_logic$read_address;
    wire  [8:0] write_logic$write_address_delayed;
    wire  [8:0] write_logic$fill_level;
    
    // Sub module instances
    top$fifo$ram ram(
        .read_address(ram$read_address),
        .read_clock(ram$read_clock),
        .read_data(ram$read_data),
        .write_address(ram$write_address),
        .write_clock(ram$write_clock),
        .write_data(ram$write_data),
        .write_enable(ram$write_enable)
    );
    top$fifo$read_logic read_logic(
        .clock(read_logic$clock),
        .read(read_logic$read),
        .data_out(read_logic$data_out),
        .empty(read_logic$empty),
        .almost_empty(read_logic$almost_empty),
        .underflow(read_logic$underflow),
        .write_address_delayed(read_logic$write_address_delayed),
        .ram_read_address(read_logic$ram_read_address),
        .ram_read_data(read_logic$ram_read_data),
        .ram_read_clock(read_logic$ram_read_clock),
        .read_address_out(read_logic$read_address_out),
        .fill_level(read_logic$fill_level)
    );
    top$fifo$write_logic write_logic(
        .write(write_logic$write),
        .data_in(write_logic$data_in),
        .full(write_logic$full),
        .almost_full(write_logic$almost_full),
        .overflow(write_logic$overflow),
        .clock(write_logic$clock),
        .ram_write_address(write_logic$ram_write_address),
        .ram_write_clock(write_logic$ram_write_clock),
        .ram_write_data(write_logic$ram_write_data),
        .ram_write_enable(write_logic$ram_write_enable),
        .read_address(write_logic$read_address),
        .write_address_delayed(write_logic$write_address_delayed),
        .fill_level(write_logic$fill_level)
    );
    
    // Update code
    always @(*) begin
        read_logic$clock = clock;
        write_logic$clock = clock;
        read_logic$read = read;
        empty = read_logic$empty;
        almost_empty = read_logic$almost_empty;
        data_out = read_logic$data_out;
        underflow = read_logic$underflow;
        overflow = write_logic$overflow;
        almost_full = write_logic$almost_full;
        full = write_logic$full;
        write_logic$write = write;
        write_logic$data_in = data_in;
        ram$write_clock = clock;
        ram$write_enable = write_logic$ram_write_enable;
        ram$write_address = write_logic$ram_write_address;
        ram$write_data = write_logic$ram_write_data;
        ram$read_clock = clock;
        ram$read_address = read_logic$ram_read_address;
        read_logic$ram_read_data = ram$read_data;
        read_logic$write_address_delayed = write_logic$write_address_delayed;
        write_logic$read_address = read_logic$read_address_out;
    end
    
endmodule // top$fifo


module top$fifo$ram(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [7:0] read_address;
    input wire  read_clock;
    output reg  [33:0] read_data;
    input wire  [7:0] write_address;
    input wire  write_clock;
    input wire  [33:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    reg[33:0] mem[255:0];
    
    
    
    always @(posedge read_clock) begin
       read_data <= mem[read_address];
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address] <= write_data;
       end
    end
                
endmodule // top$fifo$ram


module top$fifo$read_logic(clock,read,data_out,empty,almost_empty,underflow,write_address_delayed,ram_read_address,ram_read_data,ram_read_clock,read_address_out,fill_level);
    
    // Module arguments
    input wire  clock;
    input wire  read;
    output reg  [33:0] data_out;
    output reg  empty;
    output reg  almost_empty;
    output reg  underflow;
    input wire  [8:0] write_address_delayed;
    output reg  [7:0] ram_read_address;
    input wire  [33:0] ram_read_data;
    output reg  ram_read_clock;
    output reg  [8:0] read_address_out;
    output reg  [8:0] fill_level;
    
    // Constant declarations
    localparam  fifo_address_mask = 9'b11111111;
    localparam  fifo_size = 9'b100000000;
    localparam  block_size = 9'b1;
    
    // Stub signals
    reg  [8:0] read_address$d;
    wire  [8:0] read_address$q;
    reg  read_address$clock;
    reg  dff_underflow$d;
    wire  dff_underflow$q;
    reg  dff_underflow$clock;
    
    // Local signals
    reg  is_empty;
    reg  is_full;
    
    // Sub module instances
    top$count read_address(
        .d(read_address$d),
        .q(read_address$q),
        .clock(read_address$clock)
    );
    top$a_deg dff_underflow(
        .d(dff_underflow$d),
        .q(dff_underflow$q),
        .clock(dff_underflow$clock)
    );
    
    // Update code
    always @(*) begin
        read_address$clock = clock;
        dff_underflow$clock = clock;
        read_address$d = read_address$q;
        dff_underflow$d = dff_underflow$q;
        ram_read_clock = clock;
        is_empty = (read_address$q == write_address_delayed);
        is_full = ~is_empty & ((read_address$q & fifo_address_mask) == (write_address_delayed & fifo_address_mask));
        fill_level = ((write_address_delayed & fifo_address_mask) + fifo_size - (read_address$q & fifo_address_mask)) & fifo_address_mask;
        if (is_full) begin
            fill_level = fifo_size;
        end
        almost_empty = (fill_level < block_size);
        empty = is_empty;
        ram_read_address = ((read_address$q & fifo_address_mask) & 8'hff);
        data_out = ram_read_data;
        if (read & ~is_empty) begin
            read_address$d = read_address$q + 32'h1;
            ram_read_address = (((read_address$q + 32'h1) & fifo_address_mask) & 8'hff);
        end
        else begin
            read_address$d = read_address$q;
        end
        dff_underflow$d = dff_underflow$q | (is_empty & read);
        underflow = dff_underflow$q;
        read_address_out = read_address$q;
    end
    
endmodule // top$fifo$read_logic


module top$fifo$write_logic(write,data_in,full,almost_full,overflow,clock,ram_write_address,ram_write_clock,ram_write_data,ram_write_enable,read_address,write_address_delayed,fill_level);
    
    // Module arguments
    input wire  write;
    input wire  [33:0] data_in;
    output reg  full;
    output reg  almost_full;
    output reg  overflow;
    input wire  clock;
    output reg  [7:0] ram_write_address;
    output reg  ram_write_clock;
    output reg  [33:0] ram_write_data;
    output reg  ram_write_enable;
    input wire  [8:0] read_address;
    output reg  [8:0] write_address_delayed;
    output reg  [8:0] fill_level;
    
    // Constant declarations
    localparam  fifo_address_mask = 9'b11111111;
    localparam  fifo_size = 9'b100000000;
    localparam  almost_full_level = 9'b11111111;
    
    // Stub signals
    reg  [8:0] write_address$d;
    wire  [8:0] write_address$q;
    reg  write_address$clock;
    reg  [8:0] dff_write_address_delay$d;
    wire  [8:0] dff_write_address_delay$q;
    reg  dff_write_address_delay$clock;
    reg  dff_overflow$d;
    wire  dff_overflow$q;
    reg  dff_overflow$clock;
    
    // Local signals
    reg  is_empty;
    reg  is_full;
    
    // Sub module instances
    top$count write_address(
        .d(write_address$d),
        .q(write_address$q),
        .clock(write_address$clock)
    );
    top$count dff_write_address_delay(
        .d(dff_write_address_delay$d),
        .q(dff_write_address_delay$q),
        .clock(dff_write_address_delay$clock)
    );
    top$a_deg dff_overflow(
        .d(dff_overflow$d),
        .q(dff_overflow$q),
        .clock(dff_overflow$clock)
    );
    
    // Update code
    always @(*) begin
        dff_overflow$clock = clock;
        write_address$clock = clock;
        dff_write_address_delay$clock = clock;
        dff_overflow$d = dff_overflow$q;
        write_address$d = write_address$q;
        dff_write_address_delay$d = dff_write_address_delay$q;
        ram_write_clock = clock;
        dff_write_address_delay$d = write_address$q;
        write_address_delayed = dff_write_address_delay$q;
        ram_write_enable = 1'b0;
        is_empty = (read_address == dff_write_address_delay$q);
        is_full = ~is_empty & ((read_address & fifo_address_mask) == (write_address$q & fifo_address_mask));
        fill_level = ((dff_write_address_delay$q & fifo_address_mask) + fifo_size - (read_address & fifo_address_mask)) & fifo_address_mask;
        if (is_full) begin
            fill_level = fifo_size;
        end
        almost_full = (fill_level >= almost_full_level);
        full = is_full;
        ram_write_address = ((write_address$q & fifo_address_mask) & 8'hff);
        ram_write_data = data_in;
        if (write & ~is_full) begin
            write_address$d = write_address$q + 32'h1;
            ram_write_enable = 1'b1;
        end
        else begin
            write_address$d = write_address$q;
            ram_write_enable = 1'b0;
        end
        dff_overflow$d = dff_overflow$q | (is_full & write);
        overflow = dff_overflow$q;
    end
    
endmodule // top$fifo$write_logic


module top$frame$0(d,q,clock);
    
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
          
endmodule // top$frame$0


module top$held_tag(d,q,clock);
    
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
          
endmodule // top$held_tag


module top$tc(clock,m_0$0,m_0$1,m_0$2,m_0$3,m_1$0,m_1$1,m_1$2,m_1$3,m_2$0,m_2$1,m_2$2,m_2$3,alpha_m,alpha_f,f_0$0,f_0$1,f_0$2,f_0$3,f_1$0,f_1$1,f_1$2,f_1$3,f_2$0,f_2$1,f_2$2,f_2$3,beta_m,beta_f,scale,v_x$0,v_x$1,v_x$2,v_y$0,v_y$1,v_y$2,v_z$0,v_z$1,v_z$2,v_exact,tag,valid_in,s_x$0,s_x$1,s_x$2,s_b$0,s_b$1,s_b$2,cross_t$0,cross_t$1,cross_t$2,cross_f$0,cross_f$1,cross_f$2,hit,miss,tag_out,valid_out);
    
    // Module arguments
    input wire  clock;
    input wire  [23:0] m_0$0;
    input wire  [23:0] m_0$1;
    input wire  [23:0] m_0$2;
    input wire  [23:0] m_0$3;
    input wire  [23:0] m_1$0;
    input wire  [23:0] m_1$1;
    input wire  [23:0] m_1$2;
    input wire  [23:0] m_1$3;
    input wire  [23:0] m_2$0;
    input wire  [23:0] m_2$1;
    input wire  [23:0] m_2$2;
    input wire  [23:0] m_2$3;
    input wire  [23:0] alpha_m;
    input wire  [23:0] alpha_f;
    input wire  [23:0] f_0$0;
    input wire  [23:0] f_0$1;
    input wire  [23:0] f_0$2;
    input wire  [23:0] f_0$3;
    input wire  [23:0] f_1$0;
    input wire  [23:0] f_1$1;
    input wire  [23:0] f_1$2;
    input wire  [23:0] f_1$3;
    input wire  [23:0] f_2$0;
    input wire  [23:0] f_2$1;
    input wire  [23:0] f_2$2;
    input wire  [23:0] f_2$3;
    input wire  [23:0] beta_m;
    input wire  [23:0] beta_f;
    input wire  [23:0] scale;
    input wire  [23:0] v_x$0;
    input wire  [23:0] v_x$1;
    input wire  [23:0] v_x$2;
    input wire  [23:0] v_y$0;
    input wire  [23:0] v_y$1;
    input wire  [23:0] v_y$2;
    input wire  [23:0] v_z$0;
    input wire  [23:0] v_z$1;
    input wire  [23:0] v_z$2;
    input wire  v_exact;
    input wire  [31:0] tag;
    input wire  valid_in;
    output reg  [23:0] s_x$0;
    output reg  [23:0] s_x$1;
    output reg  [23:0] s_x$2;
    output reg  [23:0] s_b$0;
    output reg  [23:0] s_b$1;
    output reg  [23:0] s_b$2;
    output reg  cross_t$0;
    output reg  cross_t$1;
    output reg  cross_t$2;
    output reg  cross_f$0;
    output reg  cross_f$1;
    output reg  cross_f$2;
    output reg  hit;
    output reg  miss;
    output reg  [31:0] tag_out;
    output reg  valid_out;
    
    // Stub signals
    reg  run$d;
    wire  run$q;
    reg  run$clock;
    reg  [7:0] counter$d;
    wire  [7:0] counter$q;
    reg  counter$clock;
    reg  [23:0] regs$0$d;
    wire  [23:0] regs$0$q;
    reg  regs$0$clock;
    reg  [23:0] regs$1$d;
    wire  [23:0] regs$1$q;
    reg  regs$1$clock;
    reg  [23:0] regs$2$d;
    wire  [23:0] regs$2$q;
    reg  regs$2$clock;
    reg  [23:0] regs$3$d;
    wire  [23:0] regs$3$q;
    reg  regs$3$clock;
    reg  [23:0] regs$4$d;
    wire  [23:0] regs$4$q;
    reg  regs$4$clock;
    reg  [23:0] regs$5$d;
    wire  [23:0] regs$5$q;
    reg  regs$5$clock;
    reg  [23:0] regs$6$d;
    wire  [23:0] regs$6$q;
    reg  regs$6$clock;
    reg  [23:0] regs$7$d;
    wire  [23:0] regs$7$q;
    reg  regs$7$clock;
    reg  [23:0] regs$8$d;
    wire  [23:0] regs$8$q;
    reg  regs$8$clock;
    reg  [23:0] regs$9$d;
    wire  [23:0] regs$9$q;
    reg  regs$9$clock;
    reg  [23:0] regs$10$d;
    wire  [23:0] regs$10$q;
    reg  regs$10$clock;
    reg  [23:0] regs$11$d;
    wire  [23:0] regs$11$q;
    reg  regs$11$clock;
    reg  [23:0] regs$12$d;
    wire  [23:0] regs$12$q;
    reg  regs$12$clock;
    reg  [23:0] regs$13$d;
    wire  [23:0] regs$13$q;
    reg  regs$13$clock;
    reg  [23:0] regs$14$d;
    wire  [23:0] regs$14$q;
    reg  regs$14$clock;
    reg  [23:0] regs$15$d;
    wire  [23:0] regs$15$q;
    reg  regs$15$clock;
    reg  [23:0] regs$16$d;
    wire  [23:0] regs$16$q;
    reg  regs$16$clock;
    reg  [23:0] regs$17$d;
    wire  [23:0] regs$17$q;
    reg  regs$17$clock;
    reg  [23:0] regs$18$d;
    wire  [23:0] regs$18$q;
    reg  regs$18$clock;
    reg  [23:0] regs$19$d;
    wire  [23:0] regs$19$q;
    reg  regs$19$clock;
    reg  [23:0] regs$20$d;
    wire  [23:0] regs$20$q;
    reg  regs$20$clock;
    reg  [23:0] regs$21$d;
    wire  [23:0] regs$21$q;
    reg  regs$21$clock;
    reg  [23:0] regs$22$d;
    wire  [23:0] regs$22$q;
    reg  regs$22$clock;
    reg  [23:0] regs$23$d;
    wire  [23:0] regs$23$q;
    reg  regs$23$clock;
    reg  [23:0] regs$24$d;
    wire  [23:0] regs$24$q;
    reg  regs$24$clock;
    reg  [23:0] regs$25$d;
    wire  [23:0] regs$25$q;
    reg  regs$25$clock;
    reg  [23:0] regs$26$d;
    wire  [23:0] regs$26$q;
    reg  regs$26$clock;
    reg  [23:0] regs$27$d;
    wire  [23:0] regs$27$q;
    reg  regs$27$clock;
    reg  [23:0] regs$28$d;
    wire  [23:0] regs$28$q;
    reg  regs$28$clock;
    reg  [23:0] regs$29$d;
    wire  [23:0] regs$29$q;
    reg  regs$29$clock;
    reg  [23:0] regs$30$d;
    wire  [23:0] regs$30$q;
    reg  regs$30$clock;
    reg  [23:0] regs$31$d;
    wire  [23:0] regs$31$q;
    reg  regs$31$clock;
    reg  [23:0] regs$32$d;
    wire  [23:0] regs$32$q;
    reg  regs$32$clock;
    reg  [23:0] regs$33$d;
    wire  [23:0] regs$33$q;
    reg  regs$33$clock;
    reg  [23:0] regs$34$d;
    wire  [23:0] regs$34$q;
    reg  regs$34$clock;
    reg  [23:0] regs$35$d;
    wire  [23:0] regs$35$q;
    reg  regs$35$clock;
    reg  [23:0] regs$36$d;
    wire  [23:0] regs$36$q;
    reg  regs$36$clock;
    reg  [23:0] regs$37$d;
    wire  [23:0] regs$37$q;
    reg  regs$37$clock;
    reg  [23:0] regs$38$d;
    wire  [23:0] regs$38$q;
    reg  regs$38$clock;
    reg  [23:0] regs$39$d;
    wire  [23:0] regs$39$q;
    reg  regs$39$clock;
    reg  [23:0] regs$40$d;
    wire  [23:0] regs$40$q;
    reg  regs$40$clock;
    reg  [23:0] regs$41$d;
    wire  [23:0] regs$41$q;
    reg  regs$41$clock;
    reg  [23:0] regs$42$d;
    wire  [23:0] regs$42$q;
    reg  regs$42$clock;
    reg  [23:0] regs$43$d;
    wire  [23:0] regs$43$q;
    reg  regs$43$clock;
    reg  [23:0] regs$44$d;
    wire  [23:0] regs$44$q;
    reg  regs$44$clock;
    reg  [23:0] regs$45$d;
    wire  [23:0] regs$45$q;
    reg  regs$45$clock;
    reg  [23:0] regs$46$d;
    wire  [23:0] regs$46$q;
    reg  regs$46$clock;
    reg  [23:0] regs$47$d;
    wire  [23:0] regs$47$q;
    reg  regs$47$clock;
    reg  [23:0] regs$48$d;
    wire  [23:0] regs$48$q;
    reg  regs$48$clock;
    reg  [23:0] regs$49$d;
    wire  [23:0] regs$49$q;
    reg  regs$49$clock;
    reg  [23:0] regs$50$d;
    wire  [23:0] regs$50$q;
    reg  regs$50$clock;
    reg  [23:0] regs$51$d;
    wire  [23:0] regs$51$q;
    reg  regs$51$clock;
    reg  [23:0] regs$52$d;
    wire  [23:0] regs$52$q;
    reg  regs$52$clock;
    reg  [23:0] regs$53$d;
    wire  [23:0] regs$53$q;
    reg  regs$53$clock;
    reg  [23:0] regs$54$d;
    wire  [23:0] regs$54$q;
    reg  regs$54$clock;
    reg  [23:0] regs$55$d;
    wire  [23:0] regs$55$q;
    reg  regs$55$clock;
    reg  [23:0] regs$56$d;
    wire  [23:0] regs$56$q;
    reg  regs$56$clock;
    reg  [23:0] regs$57$d;
    wire  [23:0] regs$57$q;
    reg  regs$57$clock;
    reg  [23:0] regs$58$d;
    wire  [23:0] regs$58$q;
    reg  regs$58$clock;
    reg  [23:0] regs$59$d;
    wire  [23:0] regs$59$q;
    reg  regs$59$clock;
    reg  [23:0] regs$60$d;
    wire  [23:0] regs$60$q;
    reg  regs$60$clock;
    reg  [23:0] regs$61$d;
    wire  [23:0] regs$61$q;
    reg  regs$61$clock;
    reg  [23:0] regs$62$d;
    wire  [23:0] regs$62$q;
    reg  regs$62$clock;
    reg  [23:0] regs$63$d;
    wire  [23:0] regs$63$q;
    reg  regs$63$clock;
    reg  [23:0] regs$64$d;
    wire  [23:0] regs$64$q;
    reg  regs$64$clock;
    reg  [23:0] regs$65$d;
    wire  [23:0] regs$65$q;
    reg  regs$65$clock;
    reg  [23:0] regs$66$d;
    wire  [23:0] regs$66$q;
    reg  regs$66$clock;
    reg  [23:0] regs$67$d;
    wire  [23:0] regs$67$q;
    reg  regs$67$clock;
    reg  [23:0] regs$68$d;
    wire  [23:0] regs$68$q;
    reg  regs$68$clock;
    reg  [23:0] regs$69$d;
    wire  [23:0] regs$69$q;
    reg  regs$69$clock;
    reg  [23:0] regs$70$d;
    wire  [23:0] regs$70$q;
    reg  regs$70$clock;
    reg  [23:0] regs$71$d;
    wire  [23:0] regs$71$q;
    reg  regs$71$clock;
    reg  [23:0] regs$72$d;
    wire  [23:0] regs$72$q;
    reg  regs$72$clock;
    reg  [23:0] regs$73$d;
    wire  [23:0] regs$73$q;
    reg  regs$73$clock;
    reg  [23:0] regs$74$d;
    wire  [23:0] regs$74$q;
    reg  regs$74$clock;
    reg  [23:0] regs$75$d;
    wire  [23:0] regs$75$q;
    reg  regs$75$clock;
    reg  [23:0] regs$76$d;
    wire  [23:0] regs$76$q;
    reg  regs$76$clock;
    reg  [23:0] regs$77$d;
    wire  [23:0] regs$77$q;
    reg  regs$77$clock;
    reg  [23:0] regs$78$d;
    wire  [23:0] regs$78$q;
    reg  regs$78$clock;
    reg  [23:0] regs$79$d;
    wire  [23:0] regs$79$q;
    reg  regs$79$clock;
    reg  [23:0] regs$80$d;
    wire  [23:0] regs$80$q;
    reg  regs$80$clock;
    reg  [23:0] regs$81$d;
    wire  [23:0] regs$81$q;
    reg  regs$81$clock;
    reg  [23:0] regs$82$d;
    wire  [23:0] regs$82$q;
    reg  regs$82$clock;
    reg  [23:0] regs$83$d;
    wire  [23:0] regs$83$q;
    reg  regs$83$clock;
    reg  [23:0] regs$84$d;
    wire  [23:0] regs$84$q;
    reg  regs$84$clock;
    reg  [23:0] regs$85$d;
    wire  [23:0] regs$85$q;
    reg  regs$85$clock;
    reg  [23:0] regs$86$d;
    wire  [23:0] regs$86$q;
    reg  regs$86$clock;
    reg  [23:0] regs$87$d;
    wire  [23:0] regs$87$q;
    reg  regs$87$clock;
    reg  [23:0] regs$88$d;
    wire  [23:0] regs$88$q;
    reg  regs$88$clock;
    reg  [23:0] regs$89$d;
    wire  [23:0] regs$89$q;
    reg  regs$89$clock;
    reg  [23:0] regs$90$d;
    wire  [23:0] regs$90$q;
    reg  regs$90$clock;
    reg  [23:0] regs$91$d;
    wire  [23:0] regs$91$q;
    reg  regs$91$clock;
    reg  [23:0] regs$92$d;
    wire  [23:0] regs$92$q;
    reg  regs$92$clock;
    reg  [23:0] regs$93$d;
    wire  [23:0] regs$93$q;
    reg  regs$93$clock;
    reg  [23:0] regs$94$d;
    wire  [23:0] regs$94$q;
    reg  regs$94$clock;
    reg  [23:0] regs$95$d;
    wire  [23:0] regs$95$q;
    reg  regs$95$clock;
    reg  [23:0] regs$96$d;
    wire  [23:0] regs$96$q;
    reg  regs$96$clock;
    reg  [23:0] regs$97$d;
    wire  [23:0] regs$97$q;
    reg  regs$97$clock;
    reg  [23:0] regs$98$d;
    wire  [23:0] regs$98$q;
    reg  regs$98$clock;
    reg  [23:0] regs$99$d;
    wire  [23:0] regs$99$q;
    reg  regs$99$clock;
    reg  [23:0] regs$100$d;
    wire  [23:0] regs$100$q;
    reg  regs$100$clock;
    reg  [23:0] regs$101$d;
    wire  [23:0] regs$101$q;
    reg  regs$101$clock;
    reg  [23:0] regs$102$d;
    wire  [23:0] regs$102$q;
    reg  regs$102$clock;
    reg  [23:0] regs$103$d;
    wire  [23:0] regs$103$q;
    reg  regs$103$clock;
    reg  [23:0] regs$104$d;
    wire  [23:0] regs$104$q;
    reg  regs$104$clock;
    reg  [23:0] regs$105$d;
    wire  [23:0] regs$105$q;
    reg  regs$105$clock;
    reg  [23:0] regs$106$d;
    wire  [23:0] regs$106$q;
    reg  regs$106$clock;
    reg  [23:0] regs$107$d;
    wire  [23:0] regs$107$q;
    reg  regs$107$clock;
    reg  [23:0] regs$108$d;
    wire  [23:0] regs$108$q;
    reg  regs$108$clock;
    reg  [23:0] regs$109$d;
    wire  [23:0] regs$109$q;
    reg  regs$109$clock;
    reg  [23:0] regs$110$d;
    wire  [23:0] regs$110$q;
    reg  regs$110$clock;
    reg  [23:0] regs$111$d;
    wire  [23:0] regs$111$q;
    reg  regs$111$clock;
    reg  [23:0] regs$112$d;
    wire  [23:0] regs$112$q;
    reg  regs$112$clock;
    reg  [23:0] regs$113$d;
    wire  [23:0] regs$113$q;
    reg  regs$113$clock;
    reg  [23:0] regs$114$d;
    wire  [23:0] regs$114$q;
    reg  regs$114$clock;
    reg  [23:0] regs$115$d;
    wire  [23:0] regs$115$q;
    reg  regs$115$clock;
    reg  [23:0] regs$116$d;
    wire  [23:0] regs$116$q;
    reg  regs$116$clock;
    reg  [23:0] regs$117$d;
    wire  [23:0] regs$117$q;
    reg  regs$117$clock;
    reg  [23:0] regs$118$d;
    wire  [23:0] regs$118$q;
    reg  regs$118$clock;
    reg  [23:0] regs$119$d;
    wire  [23:0] regs$119$q;
    reg  regs$119$clock;
    reg  [23:0] regs$120$d;
    wire  [23:0] regs$120$q;
    reg  regs$120$clock;
    reg  [23:0] regs$121$d;
    wire  [23:0] regs$121$q;
    reg  regs$121$clock;
    reg  [23:0] regs$122$d;
    wire  [23:0] regs$122$q;
    reg  regs$122$clock;
    reg  [23:0] regs$123$d;
    wire  [23:0] regs$123$q;
    reg  regs$123$clock;
    reg  [23:0] regs$124$d;
    wire  [23:0] regs$124$q;
    reg  regs$124$clock;
    reg  [23:0] regs$125$d;
    wire  [23:0] regs$125$q;
    reg  regs$125$clock;
    reg  [23:0] regs$126$d;
    wire  [23:0] regs$126$q;
    reg  regs$126$clock;
    reg  [23:0] regs$127$d;
    wire  [23:0] regs$127$q;
    reg  regs$127$clock;
    reg  [23:0] regs$128$d;
    wire  [23:0] regs$128$q;
    reg  regs$128$clock;
    reg  [23:0] regs$129$d;
    wire  [23:0] regs$129$q;
    reg  regs$129$clock;
    reg  [23:0] regs$130$d;
    wire  [23:0] regs$130$q;
    reg  regs$130$clock;
    reg  [23:0] regs$131$d;
    wire  [23:0] regs$131$q;
    reg  regs$131$clock;
    reg  [23:0] regs$132$d;
    wire  [23:0] regs$132$q;
    reg  regs$132$clock;
    reg  [23:0] regs$133$d;
    wire  [23:0] regs$133$q;
    reg  regs$133$clock;
    reg  [23:0] regs$134$d;
    wire  [23:0] regs$134$q;
    reg  regs$134$clock;
    reg  [23:0] regs$135$d;
    wire  [23:0] regs$135$q;
    reg  regs$135$clock;
    reg  [23:0] regs$136$d;
    wire  [23:0] regs$136$q;
    reg  regs$136$clock;
    reg  [23:0] regs$137$d;
    wire  [23:0] regs$137$q;
    reg  regs$137$clock;
    reg  [23:0] regs$138$d;
    wire  [23:0] regs$138$q;
    reg  regs$138$clock;
    reg  [23:0] regs$139$d;
    wire  [23:0] regs$139$q;
    reg  regs$139$clock;
    reg  [23:0] regs$140$d;
    wire  [23:0] regs$140$q;
    reg  regs$140$clock;
    reg  [23:0] regs$141$d;
    wire  [23:0] regs$141$q;
    reg  regs$141$clock;
    reg  [23:0] regs$142$d;
    wire  [23:0] regs$142$q;
    reg  regs$142$clock;
    reg  [23:0] regs$143$d;
    wire  [23:0] regs$143$q;
    reg  regs$143$clock;
    reg  [23:0] regs$144$d;
    wire  [23:0] regs$144$q;
    reg  regs$144$clock;
    reg  [23:0] regs$145$d;
    wire  [23:0] regs$145$q;
    reg  regs$145$clock;
    reg  [23:0] regs$146$d;
    wire  [23:0] regs$146$q;
    reg  regs$146$clock;
    reg  [23:0] regs$147$d;
    wire  [23:0] regs$147$q;
    reg  regs$147$clock;
    reg  [23:0] regs$148$d;
    wire  [23:0] regs$148$q;
    reg  regs$148$clock;
    reg  [23:0] regs$149$d;
    wire  [23:0] regs$149$q;
    reg  regs$149$clock;
    reg  [23:0] regs$150$d;
    wire  [23:0] regs$150$q;
    reg  regs$150$clock;
    reg  [23:0] regs$151$d;
    wire  [23:0] regs$151$q;
    reg  regs$151$clock;
    reg  [23:0] regs$152$d;
    wire  [23:0] regs$152$q;
    reg  regs$152$clock;
    reg  [23:0] regs$153$d;
    wire  [23:0] regs$153$q;
    reg  regs$153$clock;
    reg  [23:0] regs$154$d;
    wire  [23:0] regs$154$q;
    reg  regs$154$clock;
    reg  [23:0] regs$155$d;
    wire  [23:0] regs$155$q;
    reg  regs$155$clock;
    reg  [23:0] regs$156$d;
    wire  [23:0] regs$156$q;
    reg  regs$156$clock;
    reg  [23:0] regs$157$d;
    wire  [23:0] regs$157$q;
    reg  regs$157$clock;
    reg  [23:0] regs$158$d;
    wire  [23:0] regs$158$q;
    reg  regs$158$clock;
    reg  [23:0] regs$159$d;
    wire  [23:0] regs$159$q;
    reg  regs$159$clock;
    reg  [23:0] regs$160$d;
    wire  [23:0] regs$160$q;
    reg  regs$160$clock;
    reg  [23:0] regs$161$d;
    wire  [23:0] regs$161$q;
    reg  regs$161$clock;
    reg  [23:0] regs$162$d;
    wire  [23:0] regs$162$q;
    reg  regs$162$clock;
    reg  [23:0] regs$163$d;
    wire  [23:0] regs$163$q;
    reg  regs$163$clock;
    reg  [23:0] regs$164$d;
    wire  [23:0] regs$164$q;
    reg  regs$164$clock;
    reg  [23:0] regs$165$d;
    wire  [23:0] regs$165$q;
    reg  regs$165$clock;
    reg  [23:0] regs$166$d;
    wire  [23:0] regs$166$q;
    reg  regs$166$clock;
    reg  [23:0] regs$167$d;
    wire  [23:0] regs$167$q;
    reg  regs$167$clock;
    reg  [23:0] regs$168$d;
    wire  [23:0] regs$168$q;
    reg  regs$168$clock;
    reg  [23:0] regs$169$d;
    wire  [23:0] regs$169$q;
    reg  regs$169$clock;
    reg  [23:0] regs$170$d;
    wire  [23:0] regs$170$q;
    reg  regs$170$clock;
    reg  [23:0] regs$171$d;
    wire  [23:0] regs$171$q;
    reg  regs$171$clock;
    reg  [23:0] regs$172$d;
    wire  [23:0] regs$172$q;
    reg  regs$172$clock;
    reg  [23:0] regs$173$d;
    wire  [23:0] regs$173$q;
    reg  regs$173$clock;
    reg  [23:0] regs$174$d;
    wire  [23:0] regs$174$q;
    reg  regs$174$clock;
    reg  [23:0] regs$175$d;
    wire  [23:0] regs$175$q;
    reg  regs$175$clock;
    reg  [23:0] regs$176$d;
    wire  [23:0] regs$176$q;
    reg  regs$176$clock;
    reg  [23:0] regs$177$d;
    wire  [23:0] regs$177$q;
    reg  regs$177$clock;
    reg  [23:0] regs$178$d;
    wire  [23:0] regs$178$q;
    reg  regs$178$clock;
    reg  [23:0] regs$179$d;
    wire  [23:0] regs$179$q;
    reg  regs$179$clock;
    reg  [23:0] regs$180$d;
    wire  [23:0] regs$180$q;
    reg  regs$180$clock;
    reg  [23:0] regs$181$d;
    wire  [23:0] regs$181$q;
    reg  regs$181$clock;
    reg  [23:0] regs$182$d;
    wire  [23:0] regs$182$q;
    reg  regs$182$clock;
    reg  [23:0] regs$183$d;
    wire  [23:0] regs$183$q;
    reg  regs$183$clock;
    reg  [23:0] regs$184$d;
    wire  [23:0] regs$184$q;
    reg  regs$184$clock;
    reg  [23:0] regs$185$d;
    wire  [23:0] regs$185$q;
    reg  regs$185$clock;
    reg  [23:0] regs$186$d;
    wire  [23:0] regs$186$q;
    reg  regs$186$clock;
    reg  [23:0] regs$187$d;
    wire  [23:0] regs$187$q;
    reg  regs$187$clock;
    reg  [23:0] regs$188$d;
    wire  [23:0] regs$188$q;
    reg  regs$188$clock;
    reg  [23:0] regs$189$d;
    wire  [23:0] regs$189$q;
    reg  regs$189$clock;
    reg  [23:0] regs$190$d;
    wire  [23:0] regs$190$q;
    reg  regs$190$clock;
    reg  [23:0] regs$191$d;
    wire  [23:0] regs$191$q;
    reg  regs$191$clock;
    reg  [23:0] regs$192$d;
    wire  [23:0] regs$192$q;
    reg  regs$192$clock;
    reg  [23:0] regs$193$d;
    wire  [23:0] regs$193$q;
    reg  regs$193$clock;
    reg  [23:0] regs$194$d;
    wire  [23:0] regs$194$q;
    reg  regs$194$clock;
    reg  [23:0] regs$195$d;
    wire  [23:0] regs$195$q;
    reg  regs$195$clock;
    reg  [23:0] regs$196$d;
    wire  [23:0] regs$196$q;
    reg  regs$196$clock;
    reg  [23:0] regs$197$d;
    wire  [23:0] regs$197$q;
    reg  regs$197$clock;
    reg  [23:0] regs$198$d;
    wire  [23:0] regs$198$q;
    reg  regs$198$clock;
    reg  [23:0] regs$199$d;
    wire  [23:0] regs$199$q;
    reg  regs$199$clock;
    reg  [23:0] regs$200$d;
    wire  [23:0] regs$200$q;
    reg  regs$200$clock;
    reg  [23:0] regs$201$d;
    wire  [23:0] regs$201$q;
    reg  regs$201$clock;
    reg  [23:0] regs$202$d;
    wire  [23:0] regs$202$q;
    reg  regs$202$clock;
    reg  [23:0] regs$203$d;
    wire  [23:0] regs$203$q;
    reg  regs$203$clock;
    reg  [23:0] regs$204$d;
    wire  [23:0] regs$204$q;
    reg  regs$204$clock;
    reg  [23:0] regs$205$d;
    wire  [23:0] regs$205$q;
    reg  regs$205$clock;
    reg  [23:0] regs$206$d;
    wire  [23:0] regs$206$q;
    reg  regs$206$clock;
    reg  [23:0] regs$207$d;
    wire  [23:0] regs$207$q;
    reg  regs$207$clock;
    reg  [23:0] regs$208$d;
    wire  [23:0] regs$208$q;
    reg  regs$208$clock;
    reg  [23:0] regs$209$d;
    wire  [23:0] regs$209$q;
    reg  regs$209$clock;
    reg  [23:0] regs$210$d;
    wire  [23:0] regs$210$q;
    reg  regs$210$clock;
    reg  [23:0] regs$211$d;
    wire  [23:0] regs$211$q;
    reg  regs$211$clock;
    reg  [23:0] regs$212$d;
    wire  [23:0] regs$212$q;
    reg  regs$212$clock;
    reg  [23:0] regs$213$d;
    wire  [23:0] regs$213$q;
    reg  regs$213$clock;
    reg  [23:0] regs$214$d;
    wire  [23:0] regs$214$q;
    reg  regs$214$clock;
    reg  [23:0] regs$215$d;
    wire  [23:0] regs$215$q;
    reg  regs$215$clock;
    reg  [23:0] regs$216$d;
    wire  [23:0] regs$216$q;
    reg  regs$216$clock;
    reg  [23:0] regs$217$d;
    wire  [23:0] regs$217$q;
    reg  regs$217$clock;
    reg  [23:0] regs$218$d;
    wire  [23:0] regs$218$q;
    reg  regs$218$clock;
    reg  [23:0] regs$219$d;
    wire  [23:0] regs$219$q;
    reg  regs$219$clock;
    reg  [23:0] regs$220$d;
    wire  [23:0] regs$220$q;
    reg  regs$220$clock;
    reg  [23:0] regs$221$d;
    wire  [23:0] regs$221$q;
    reg  regs$221$clock;
    reg  [23:0] regs$222$d;
    wire  [23:0] regs$222$q;
    reg  regs$222$clock;
    reg  [23:0] regs$223$d;
    wire  [23:0] regs$223$q;
    reg  regs$223$clock;
    reg  [23:0] regs$224$d;
    wire  [23:0] regs$224$q;
    reg  regs$224$clock;
    reg  [23:0] regs$225$d;
    wire  [23:0] regs$225$q;
    reg  regs$225$clock;
    reg  [23:0] regs$226$d;
    wire  [23:0] regs$226$q;
    reg  regs$226$clock;
    reg  [23:0] regs$227$d;
    wire  [23:0] regs$227$q;
    reg  regs$227$clock;
    reg  [23:0] regs$228$d;
    wire  [23:0] regs$228$q;
    reg  regs$228$clock;
    reg  [23:0] regs$229$d;
    wire  [23:0] regs$229$q;
    reg  regs$229$clock;
    reg  [23:0] regs$230$d;
    wire  [23:0] regs$230$q;
    reg  regs$230$clock;
    reg  [23:0] regs$231$d;
    wire  [23:0] regs$231$q;
    reg  regs$231$clock;
    reg  [23:0] regs$232$d;
    wire  [23:0] regs$232$q;
    reg  regs$232$clock;
    reg  [23:0] regs$233$d;
    wire  [23:0] regs$233$q;
    reg  regs$233$clock;
    reg  [23:0] regs$234$d;
    wire  [23:0] regs$234$q;
    reg  regs$234$clock;
    reg  [23:0] regs$235$d;
    wire  [23:0] regs$235$q;
    reg  regs$235$clock;
    reg  [23:0] regs$236$d;
    wire  [23:0] regs$236$q;
    reg  regs$236$clock;
    reg  [23:0] regs$237$d;
    wire  [23:0] regs$237$q;
    reg  regs$237$clock;
    reg  [23:0] regs$238$d;
    wire  [23:0] regs$238$q;
    reg  regs$238$clock;
    reg  [23:0] regs$239$d;
    wire  [23:0] regs$239$q;
    reg  regs$239$clock;
    reg  [23:0] regs$240$d;
    wire  [23:0] regs$240$q;
    reg  regs$240$clock;
    reg  [23:0] regs$241$d;
    wire  [23:0] regs$241$q;
    reg  regs$241$clock;
    reg  [23:0] regs$242$d;
    wire  [23:0] regs$242$q;
    reg  regs$242$clock;
    reg  [23:0] regs$243$d;
    wire  [23:0] regs$243$q;
    reg  regs$243$clock;
    reg  [23:0] regs$244$d;
    wire  [23:0] regs$244$q;
    reg  regs$244$clock;
    reg  [23:0] regs$245$d;
    wire  [23:0] regs$245$q;
    reg  regs$245$clock;
    reg  [23:0] regs$246$d;
    wire  [23:0] regs$246$q;
    reg  regs$246$clock;
    reg  [23:0] regs$247$d;
    wire  [23:0] regs$247$q;
    reg  regs$247$clock;
    reg  [23:0] regs$248$d;
    wire  [23:0] regs$248$q;
    reg  regs$248$clock;
    reg  [23:0] regs$249$d;
    wire  [23:0] regs$249$q;
    reg  regs$249$clock;
    reg  [23:0] regs$250$d;
    wire  [23:0] regs$250$q;
    reg  regs$250$clock;
    reg  [23:0] regs$251$d;
    wire  [23:0] regs$251$q;
    reg  regs$251$clock;
    reg  [23:0] regs$252$d;
    wire  [23:0] regs$252$q;
    reg  regs$252$clock;
    reg  [23:0] regs$253$d;
    wire  [23:0] regs$253$q;
    reg  regs$253$clock;
    reg  [23:0] regs$254$d;
    wire  [23:0] regs$254$q;
    reg  regs$254$clock;
    reg  [23:0] regs$255$d;
    wire  [23:0] regs$255$q;
    reg  regs$255$clock;
    reg  [23:0] regs$256$d;
    wire  [23:0] regs$256$q;
    reg  regs$256$clock;
    reg  [23:0] regs$257$d;
    wire  [23:0] regs$257$q;
    reg  regs$257$clock;
    reg  [23:0] regs$258$d;
    wire  [23:0] regs$258$q;
    reg  regs$258$clock;
    reg  [23:0] regs$259$d;
    wire  [23:0] regs$259$q;
    reg  regs$259$clock;
    reg  [23:0] regs$260$d;
    wire  [23:0] regs$260$q;
    reg  regs$260$clock;
    reg  [23:0] regs$261$d;
    wire  [23:0] regs$261$q;
    reg  regs$261$clock;
    reg  [23:0] regs$262$d;
    wire  [23:0] regs$262$q;
    reg  regs$262$clock;
    reg  [23:0] regs$263$d;
    wire  [23:0] regs$263$q;
    reg  regs$263$clock;
    reg  [23:0] regs$264$d;
    wire  [23:0] regs$264$q;
    reg  regs$264$clock;
    reg  [23:0] regs$265$d;
    wire  [23:0] regs$265$q;
    reg  regs$265$clock;
    reg  [23:0] regs$266$d;
    wire  [23:0] regs$266$q;
    reg  regs$266$clock;
    reg  [23:0] regs$267$d;
    wire  [23:0] regs$267$q;
    reg  regs$267$clock;
    reg  [23:0] regs$268$d;
    wire  [23:0] regs$268$q;
    reg  regs$268$clock;
    reg  [23:0] regs$269$d;
    wire  [23:0] regs$269$q;
    reg  regs$269$clock;
    reg  [23:0] regs$270$d;
    wire  [23:0] regs$270$q;
    reg  regs$270$clock;
    reg  [23:0] regs$271$d;
    wire  [23:0] regs$271$q;
    reg  regs$271$clock;
    reg  [23:0] regs$272$d;
    wire  [23:0] regs$272$q;
    reg  regs$272$clock;
    reg  [23:0] regs$273$d;
    wire  [23:0] regs$273$q;
    reg  regs$273$clock;
    reg  [23:0] regs$274$d;
    wire  [23:0] regs$274$q;
    reg  regs$274$clock;
    reg  [23:0] regs$275$d;
    wire  [23:0] regs$275$q;
    reg  regs$275$clock;
    reg  [23:0] regs$276$d;
    wire  [23:0] regs$276$q;
    reg  regs$276$clock;
    reg  [23:0] regs$277$d;
    wire  [23:0] regs$277$q;
    reg  regs$277$clock;
    reg  [23:0] regs$278$d;
    wire  [23:0] regs$278$q;
    reg  regs$278$clock;
    reg  [23:0] regs$279$d;
    wire  [23:0] regs$279$q;
    reg  regs$279$clock;
    reg  [23:0] regs$280$d;
    wire  [23:0] regs$280$q;
    reg  regs$280$clock;
    reg  [23:0] regs$281$d;
    wire  [23:0] regs$281$q;
    reg  regs$281$clock;
    reg  [23:0] regs$282$d;
    wire  [23:0] regs$282$q;
    reg  regs$282$clock;
    reg  [23:0] regs$283$d;
    wire  [23:0] regs$283$q;
    reg  regs$283$clock;
    reg  [23:0] regs$284$d;
    wire  [23:0] regs$284$q;
    reg  regs$284$clock;
    reg  [23:0] regs$285$d;
    wire  [23:0] regs$285$q;
    reg  regs$285$clock;
    reg  [23:0] regs$286$d;
    wire  [23:0] regs$286$q;
    reg  regs$286$clock;
    reg  [23:0] regs$287$d;
    wire  [23:0] regs$287$q;
    reg  regs$287$clock;
    reg  [23:0] regs$288$d;
    wire  [23:0] regs$288$q;
    reg  regs$288$clock;
    reg  [23:0] regs$289$d;
    wire  [23:0] regs$289$q;
    reg  regs$289$clock;
    reg  [23:0] regs$290$d;
    wire  [23:0] regs$290$q;
    reg  regs$290$clock;
    reg  [23:0] regs$291$d;
    wire  [23:0] regs$291$q;
    reg  regs$291$clock;
    reg  [23:0] regs$292$d;
    wire  [23:0] regs$292$q;
    reg  regs$292$clock;
    reg  [23:0] regs$293$d;
    wire  [23:0] regs$293$q;
    reg  regs$293$clock;
    reg  [23:0] regs$294$d;
    wire  [23:0] regs$294$q;
    reg  regs$294$clock;
    reg  [23:0] regs$295$d;
    wire  [23:0] regs$295$q;
    reg  regs$295$clock;
    reg  [23:0] regs$296$d;
    wire  [23:0] regs$296$q;
    reg  regs$296$clock;
    reg  [23:0] regs$297$d;
    wire  [23:0] regs$297$q;
    reg  regs$297$clock;
    reg  [23:0] regs$298$d;
    wire  [23:0] regs$298$q;
    reg  regs$298$clock;
    reg  [23:0] regs$299$d;
    wire  [23:0] regs$299$q;
    reg  regs$299$clock;
    reg  [23:0] regs$300$d;
    wire  [23:0] regs$300$q;
    reg  regs$300$clock;
    reg  [23:0] regs$301$d;
    wire  [23:0] regs$301$q;
    reg  regs$301$clock;
    reg  [23:0] regs$302$d;
    wire  [23:0] regs$302$q;
    reg  regs$302$clock;
    reg  [23:0] regs$303$d;
    wire  [23:0] regs$303$q;
    reg  regs$303$clock;
    reg  [23:0] regs$304$d;
    wire  [23:0] regs$304$q;
    reg  regs$304$clock;
    reg  [23:0] regs$305$d;
    wire  [23:0] regs$305$q;
    reg  regs$305$clock;
    reg  [23:0] regs$306$d;
    wire  [23:0] regs$306$q;
    reg  regs$306$clock;
    reg  [23:0] regs$307$d;
    wire  [23:0] regs$307$q;
    reg  regs$307$clock;
    reg  [23:0] regs$308$d;
    wire  [23:0] regs$308$q;
    reg  regs$308$clock;
    reg  [23:0] regs$309$d;
    wire  [23:0] regs$309$q;
    reg  regs$309$clock;
    reg  [23:0] regs$310$d;
    wire  [23:0] regs$310$q;
    reg  regs$310$clock;
    reg  [23:0] regs$311$d;
    wire  [23:0] regs$311$q;
    reg  regs$311$clock;
    reg  [23:0] regs$312$d;
    wire  [23:0] regs$312$q;
    reg  regs$312$clock;
    reg  [23:0] regs$313$d;
    wire  [23:0] regs$313$q;
    reg  regs$313$clock;
    reg  [23:0] regs$314$d;
    wire  [23:0] regs$314$q;
    reg  regs$314$clock;
    reg  [23:0] regs$315$d;
    wire  [23:0] regs$315$q;
    reg  regs$315$clock;
    reg  [23:0] regs$316$d;
    wire  [23:0] regs$316$q;
    reg  regs$316$clock;
    reg  [23:0] regs$317$d;
    wire  [23:0] regs$317$q;
    reg  regs$317$clock;
    reg  [23:0] regs$318$d;
    wire  [23:0] regs$318$q;
    reg  regs$318$clock;
    reg  [23:0] regs$319$d;
    wire  [23:0] regs$319$q;
    reg  regs$319$clock;
    reg  [23:0] regs$320$d;
    wire  [23:0] regs$320$q;
    reg  regs$320$clock;
    reg  [23:0] regs$321$d;
    wire  [23:0] regs$321$q;
    reg  regs$321$clock;
    reg  [23:0] regs$322$d;
    wire  [23:0] regs$322$q;
    reg  regs$322$clock;
    reg  [23:0] regs$323$d;
    wire  [23:0] regs$323$q;
    reg  regs$323$clock;
    reg  [23:0] regs$324$d;
    wire  [23:0] regs$324$q;
    reg  regs$324$clock;
    reg  [23:0] regs$325$d;
    wire  [23:0] regs$325$q;
    reg  regs$325$clock;
    reg  [23:0] regs$326$d;
    wire  [23:0] regs$326$q;
    reg  regs$326$clock;
    reg  [23:0] regs$327$d;
    wire  [23:0] regs$327$q;
    reg  regs$327$clock;
    reg  [23:0] regs$328$d;
    wire  [23:0] regs$328$q;
    reg  regs$328$clock;
    reg  [23:0] regs$329$d;
    wire  [23:0] regs$329$q;
    reg  regs$329$clock;
    reg  [23:0] regs$330$d;
    wire  [23:0] regs$330$q;
    reg  regs$330$clock;
    reg  [23:0] regs$331$d;
    wire  [23:0] regs$331$q;
    reg  regs$331$clock;
    reg  [23:0] regs$332$d;
    wire  [23:0] regs$332$q;
    reg  regs$332$clock;
    reg  [23:0] regs$333$d;
    wire  [23:0] regs$333$q;
    reg  regs$333$clock;
    reg  [23:0] regs$334$d;
    wire  [23:0] regs$334$q;
    reg  regs$334$clock;
    reg  [23:0] regs$335$d;
    wire  [23:0] regs$335$q;
    reg  regs$335$clock;
    reg  [23:0] regs$336$d;
    wire  [23:0] regs$336$q;
    reg  regs$336$clock;
    reg  [23:0] regs$337$d;
    wire  [23:0] regs$337$q;
    reg  regs$337$clock;
    reg  [23:0] regs$338$d;
    wire  [23:0] regs$338$q;
    reg  regs$338$clock;
    reg  [23:0] regs$339$d;
    wire  [23:0] regs$339$q;
    reg  regs$339$clock;
    reg  [23:0] regs$340$d;
    wire  [23:0] regs$340$q;
    reg  regs$340$clock;
    reg  [23:0] regs$341$d;
    wire  [23:0] regs$341$q;
    reg  regs$341$clock;
    reg  [23:0] regs$342$d;
    wire  [23:0] regs$342$q;
    reg  regs$342$clock;
    reg  [23:0] regs$343$d;
    wire  [23:0] regs$343$q;
    reg  regs$343$clock;
    reg  [23:0] regs$344$d;
    wire  [23:0] regs$344$q;
    reg  regs$344$clock;
    reg  [23:0] regs$345$d;
    wire  [23:0] regs$345$q;
    reg  regs$345$clock;
    reg  [23:0] regs$346$d;
    wire  [23:0] regs$346$q;
    reg  regs$346$clock;
    reg  [23:0] regs$347$d;
    wire  [23:0] regs$347$q;
    reg  regs$347$clock;
    reg  [23:0] regs$348$d;
    wire  [23:0] regs$348$q;
    reg  regs$348$clock;
    reg  [23:0] regs$349$d;
    wire  [23:0] regs$349$q;
    reg  regs$349$clock;
    reg  [23:0] regs$350$d;
    wire  [23:0] regs$350$q;
    reg  regs$350$clock;
    reg  [23:0] regs$351$d;
    wire  [23:0] regs$351$q;
    reg  regs$351$clock;
    reg  [23:0] regs$352$d;
    wire  [23:0] regs$352$q;
    reg  regs$352$clock;
    reg  [23:0] regs$353$d;
    wire  [23:0] regs$353$q;
    reg  regs$353$clock;
    reg  [23:0] regs$354$d;
    wire  [23:0] regs$354$q;
    reg  regs$354$clock;
    reg  [23:0] regs$355$d;
    wire  [23:0] regs$355$q;
    reg  regs$355$clock;
    reg  [23:0] regs$356$d;
    wire  [23:0] regs$356$q;
    reg  regs$356$clock;
    reg  [23:0] regs$357$d;
    wire  [23:0] regs$357$q;
    reg  regs$357$clock;
    reg  [23:0] regs$358$d;
    wire  [23:0] regs$358$q;
    reg  regs$358$clock;
    reg  [23:0] regs$359$d;
    wire  [23:0] regs$359$q;
    reg  regs$359$clock;
    reg  [23:0] regs$360$d;
    wire  [23:0] regs$360$q;
    reg  regs$360$clock;
    reg  [23:0] regs$361$d;
    wire  [23:0] regs$361$q;
    reg  regs$361$clock;
    reg  [23:0] regs$362$d;
    wire  [23:0] regs$362$q;
    reg  regs$362$clock;
    reg  [23:0] regs$363$d;
    wire  [23:0] regs$363$q;
    reg  regs$363$clock;
    reg  [23:0] regs$364$d;
    wire  [23:0] regs$364$q;
    reg  regs$364$clock;
    reg  [23:0] regs$365$d;
    wire  [23:0] regs$365$q;
    reg  regs$365$clock;
    reg  [23:0] regs$366$d;
    wire  [23:0] regs$366$q;
    reg  regs$366$clock;
    reg  [23:0] regs$367$d;
    wire  [23:0] regs$367$q;
    reg  regs$367$clock;
    reg  [23:0] regs$368$d;
    wire  [23:0] regs$368$q;
    reg  regs$368$clock;
    reg  [23:0] regs$369$d;
    wire  [23:0] regs$369$q;
    reg  regs$369$clock;
    reg  [23:0] regs$370$d;
    wire  [23:0] regs$370$q;
    reg  regs$370$clock;
    reg  [23:0] regs$371$d;
    wire  [23:0] regs$371$q;
    reg  regs$371$clock;
    reg  [23:0] regs$372$d;
    wire  [23:0] regs$372$q;
    reg  regs$372$clock;
    reg  [23:0] regs$373$d;
    wire  [23:0] regs$373$q;
    reg  regs$373$clock;
    reg  [23:0] regs$374$d;
    wire  [23:0] regs$374$q;
    reg  regs$374$clock;
    reg  [23:0] regs$375$d;
    wire  [23:0] regs$375$q;
    reg  regs$375$clock;
    reg  [23:0] regs$376$d;
    wire  [23:0] regs$376$q;
    reg  regs$376$clock;
    reg  [23:0] regs$377$d;
    wire  [23:0] regs$377$q;
    reg  regs$377$clock;
    reg  [23:0] regs$378$d;
    wire  [23:0] regs$378$q;
    reg  regs$378$clock;
    reg  [23:0] regs$379$d;
    wire  [23:0] regs$379$q;
    reg  regs$379$clock;
    reg  [23:0] regs$380$d;
    wire  [23:0] regs$380$q;
    reg  regs$380$clock;
    reg  [23:0] regs$381$d;
    wire  [23:0] regs$381$q;
    reg  regs$381$clock;
    reg  [23:0] regs$382$d;
    wire  [23:0] regs$382$q;
    reg  regs$382$clock;
    reg  [23:0] regs$383$d;
    wire  [23:0] regs$383$q;
    reg  regs$383$clock;
    reg  [23:0] regs$384$d;
    wire  [23:0] regs$384$q;
    reg  regs$384$clock;
    reg  [23:0] regs$385$d;
    wire  [23:0] regs$385$q;
    reg  regs$385$clock;
    reg  [23:0] regs$386$d;
    wire  [23:0] regs$386$q;
    reg  regs$386$clock;
    reg  [23:0] regs$387$d;
    wire  [23:0] regs$387$q;
    reg  regs$387$clock;
    reg  [23:0] regs$388$d;
    wire  [23:0] regs$388$q;
    reg  regs$388$clock;
    reg  [23:0] regs$389$d;
    wire  [23:0] regs$389$q;
    reg  regs$389$clock;
    reg  [23:0] regs$390$d;
    wire  [23:0] regs$390$q;
    reg  regs$390$clock;
    reg  [23:0] regs$391$d;
    wire  [23:0] regs$391$q;
    reg  regs$391$clock;
    reg  [23:0] regs$392$d;
    wire  [23:0] regs$392$q;
    reg  regs$392$clock;
    reg  [23:0] regs$393$d;
    wire  [23:0] regs$393$q;
    reg  regs$393$clock;
    reg  [23:0] regs$394$d;
    wire  [23:0] regs$394$q;
    reg  regs$394$clock;
    reg  [23:0] regs$395$d;
    wire  [23:0] regs$395$q;
    reg  regs$395$clock;
    reg  [23:0] regs$396$d;
    wire  [23:0] regs$396$q;
    reg  regs$396$clock;
    reg  [23:0] regs$397$d;
    wire  [23:0] regs$397$q;
    reg  regs$397$clock;
    reg  [23:0] regs$398$d;
    wire  [23:0] regs$398$q;
    reg  regs$398$clock;
    reg  [23:0] regs$399$d;
    wire  [23:0] regs$399$q;
    reg  regs$399$clock;
    reg  [23:0] regs$400$d;
    wire  [23:0] regs$400$q;
    reg  regs$400$clock;
    reg  [23:0] regs$401$d;
    wire  [23:0] regs$401$q;
    reg  regs$401$clock;
    reg  [23:0] regs$402$d;
    wire  [23:0] regs$402$q;
    reg  regs$402$clock;
    reg  [23:0] regs$403$d;
    wire  [23:0] regs$403$q;
    reg  regs$403$clock;
    reg  [23:0] regs$404$d;
    wire  [23:0] regs$404$q;
    reg  regs$404$clock;
    reg  [23:0] regs$405$d;
    wire  [23:0] regs$405$q;
    reg  regs$405$clock;
    reg  [23:0] regs$406$d;
    wire  [23:0] regs$406$q;
    reg  regs$406$clock;
    reg  [23:0] regs$407$d;
    wire  [23:0] regs$407$q;
    reg  regs$407$clock;
    reg  [23:0] regs$408$d;
    wire  [23:0] regs$408$q;
    reg  regs$408$clock;
    reg  [23:0] regs$409$d;
    wire  [23:0] regs$409$q;
    reg  regs$409$clock;
    reg  [23:0] regs$410$d;
    wire  [23:0] regs$410$q;
    reg  regs$410$clock;
    reg  [23:0] regs$411$d;
    wire  [23:0] regs$411$q;
    reg  regs$411$clock;
    reg  [23:0] regs$412$d;
    wire  [23:0] regs$412$q;
    reg  regs$412$clock;
    reg  [23:0] regs$413$d;
    wire  [23:0] regs$413$q;
    reg  regs$413$clock;
    reg  [23:0] regs$414$d;
    wire  [23:0] regs$414$q;
    reg  regs$414$clock;
    reg  [23:0] regs$415$d;
    wire  [23:0] regs$415$q;
    reg  regs$415$clock;
    reg  [23:0] regs$416$d;
    wire  [23:0] regs$416$q;
    reg  regs$416$clock;
    reg  [23:0] regs$417$d;
    wire  [23:0] regs$417$q;
    reg  regs$417$clock;
    reg  [23:0] regs$418$d;
    wire  [23:0] regs$418$q;
    reg  regs$418$clock;
    reg  [23:0] regs$419$d;
    wire  [23:0] regs$419$q;
    reg  regs$419$clock;
    reg  [23:0] regs$420$d;
    wire  [23:0] regs$420$q;
    reg  regs$420$clock;
    reg  [23:0] regs$421$d;
    wire  [23:0] regs$421$q;
    reg  regs$421$clock;
    reg  [23:0] regs$422$d;
    wire  [23:0] regs$422$q;
    reg  regs$422$clock;
    reg  [23:0] regs$423$d;
    wire  [23:0] regs$423$q;
    reg  regs$423$clock;
    reg  [23:0] regs$424$d;
    wire  [23:0] regs$424$q;
    reg  regs$424$clock;
    reg  [23:0] regs$425$d;
    wire  [23:0] regs$425$q;
    reg  regs$425$clock;
    reg  [23:0] regs$426$d;
    wire  [23:0] regs$426$q;
    reg  regs$426$clock;
    reg  [23:0] regs$427$d;
    wire  [23:0] regs$427$q;
    reg  regs$427$clock;
    reg  [23:0] regs$428$d;
    wire  [23:0] regs$428$q;
    reg  regs$428$clock;
    reg  [23:0] regs$429$d;
    wire  [23:0] regs$429$q;
    reg  regs$429$clock;
    reg  [23:0] regs$430$d;
    wire  [23:0] regs$430$q;
    reg  regs$430$clock;
    reg  [23:0] regs$431$d;
    wire  [23:0] regs$431$q;
    reg  regs$431$clock;
    reg  [23:0] regs$432$d;
    wire  [23:0] regs$432$q;
    reg  regs$432$clock;
    reg  [23:0] regs$433$d;
    wire  [23:0] regs$433$q;
    reg  regs$433$clock;
    reg  [23:0] regs$434$d;
    wire  [23:0] regs$434$q;
    reg  regs$434$clock;
    reg  [23:0] regs$435$d;
    wire  [23:0] regs$435$q;
    reg  regs$435$clock;
    reg  [23:0] regs$436$d;
    wire  [23:0] regs$436$q;
    reg  regs$436$clock;
    reg  [23:0] regs$437$d;
    wire  [23:0] regs$437$q;
    reg  regs$437$clock;
    reg  [23:0] regs$438$d;
    wire  [23:0] regs$438$q;
    reg  regs$438$clock;
    reg  [23:0] regs$439$d;
    wire  [23:0] regs$439$q;
    reg  regs$439$clock;
    reg  [23:0] regs$440$d;
    wire  [23:0] regs$440$q;
    reg  regs$440$clock;
    reg  [23:0] regs$441$d;
    wire  [23:0] regs$441$q;
    reg  regs$441$clock;
    reg  [23:0] regs$442$d;
    wire  [23:0] regs$442$q;
    reg  regs$442$clock;
    reg  [23:0] regs$443$d;
    wire  [23:0] regs$443$q;
    reg  regs$443$clock;
    reg  [23:0] regs$444$d;
    wire  [23:0] regs$444$q;
    reg  regs$444$clock;
    reg  [23:0] regs$445$d;
    wire  [23:0] regs$445$q;
    reg  regs$445$clock;
    reg  [23:0] regs$446$d;
    wire  [23:0] regs$446$q;
    reg  regs$446$clock;
    reg  [23:0] regs$447$d;
    wire  [23:0] regs$447$q;
    reg  regs$447$clock;
    reg  [23:0] regs$448$d;
    wire  [23:0] regs$448$q;
    reg  regs$448$clock;
    reg  [23:0] regs$449$d;
    wire  [23:0] regs$449$q;
    reg  regs$449$clock;
    reg  [23:0] regs$450$d;
    wire  [23:0] regs$450$q;
    reg  regs$450$clock;
    reg  [23:0] regs$451$d;
    wire  [23:0] regs$451$q;
    reg  regs$451$clock;
    reg  [23:0] regs$452$d;
    wire  [23:0] regs$452$q;
    reg  regs$452$clock;
    reg  [23:0] regs$453$d;
    wire  [23:0] regs$453$q;
    reg  regs$453$clock;
    reg  [23:0] regs$454$d;
    wire  [23:0] regs$454$q;
    reg  regs$454$clock;
    reg  [23:0] regs$455$d;
    wire  [23:0] regs$455$q;
    reg  regs$455$clock;
    reg  [23:0] regs$456$d;
    wire  [23:0] regs$456$q;
    reg  regs$456$clock;
    reg  [23:0] regs$457$d;
    wire  [23:0] regs$457$q;
    reg  regs$457$clock;
    reg  [23:0] regs$458$d;
    wire  [23:0] regs$458$q;
    reg  regs$458$clock;
    reg  [23:0] regs$459$d;
    wire  [23:0] regs$459$q;
    reg  regs$459$clock;
    reg  [23:0] regs$460$d;
    wire  [23:0] regs$460$q;
    reg  regs$460$clock;
    reg  [23:0] regs$461$d;
    wire  [23:0] regs$461$q;
    reg  regs$461$clock;
    reg  [23:0] regs$462$d;
    wire  [23:0] regs$462$q;
    reg  regs$462$clock;
    reg  [23:0] regs$463$d;
    wire  [23:0] regs$463$q;
    reg  regs$463$clock;
    reg  [23:0] regs$464$d;
    wire  [23:0] regs$464$q;
    reg  regs$464$clock;
    reg  [23:0] regs$465$d;
    wire  [23:0] regs$465$q;
    reg  regs$465$clock;
    reg  [23:0] regs$466$d;
    wire  [23:0] regs$466$q;
    reg  regs$466$clock;
    reg  [23:0] regs$467$d;
    wire  [23:0] regs$467$q;
    reg  regs$467$clock;
    reg  [23:0] regs$468$d;
    wire  [23:0] regs$468$q;
    reg  regs$468$clock;
    reg  [23:0] regs$469$d;
    wire  [23:0] regs$469$q;
    reg  regs$469$clock;
    reg  [23:0] regs$470$d;
    wire  [23:0] regs$470$q;
    reg  regs$470$clock;
    reg  [23:0] regs$471$d;
    wire  [23:0] regs$471$q;
    reg  regs$471$clock;
    reg  [23:0] regs$472$d;
    wire  [23:0] regs$472$q;
    reg  regs$472$clock;
    reg  [23:0] regs$473$d;
    wire  [23:0] regs$473$q;
    reg  regs$473$clock;
    reg  [23:0] regs$474$d;
    wire  [23:0] regs$474$q;
    reg  regs$474$clock;
    reg  [23:0] regs$475$d;
    wire  [23:0] regs$475$q;
    reg  regs$475$clock;
    reg  [23:0] regs$476$d;
    wire  [23:0] regs$476$q;
    reg  regs$476$clock;
    reg  [23:0] regs$477$d;
    wire  [23:0] regs$477$q;
    reg  regs$477$clock;
    reg  [23:0] regs$478$d;
    wire  [23:0] regs$478$q;
    reg  regs$478$clock;
    reg  [23:0] regs$479$d;
    wire  [23:0] regs$479$q;
    reg  regs$479$clock;
    reg  [23:0] regs$480$d;
    wire  [23:0] regs$480$q;
    reg  regs$480$clock;
    reg  [23:0] regs$481$d;
    wire  [23:0] regs$481$q;
    reg  regs$481$clock;
    reg  [23:0] regs$482$d;
    wire  [23:0] regs$482$q;
    reg  regs$482$clock;
    reg  [23:0] regs$483$d;
    wire  [23:0] regs$483$q;
    reg  regs$483$clock;
    reg  [23:0] regs$484$d;
    wire  [23:0] regs$484$q;
    reg  regs$484$clock;
    reg  [23:0] regs$485$d;
    wire  [23:0] regs$485$q;
    reg  regs$485$clock;
    reg  [23:0] regs$486$d;
    wire  [23:0] regs$486$q;
    reg  regs$486$clock;
    reg  [23:0] regs$487$d;
    wire  [23:0] regs$487$q;
    reg  regs$487$clock;
    reg  [23:0] regs$488$d;
    wire  [23:0] regs$488$q;
    reg  regs$488$clock;
    reg  [23:0] regs$489$d;
    wire  [23:0] regs$489$q;
    reg  regs$489$clock;
    reg  [23:0] regs$490$d;
    wire  [23:0] regs$490$q;
    reg  regs$490$clock;
    reg  [23:0] regs$491$d;
    wire  [23:0] regs$491$q;
    reg  regs$491$clock;
    reg  [23:0] regs$492$d;
    wire  [23:0] regs$492$q;
    reg  regs$492$clock;
    reg  [23:0] regs$493$d;
    wire  [23:0] regs$493$q;
    reg  regs$493$clock;
    reg  [23:0] regs$494$d;
    wire  [23:0] regs$494$q;
    reg  regs$494$clock;
    reg  [23:0] regs$495$d;
    wire  [23:0] regs$495$q;
    reg  regs$495$clock;
    reg  [23:0] regs$496$d;
    wire  [23:0] regs$496$q;
    reg  regs$496$clock;
    reg  [23:0] regs$497$d;
    wire  [23:0] regs$497$q;
    reg  regs$497$clock;
    reg  [23:0] regs$498$d;
    wire  [23:0] regs$498$q;
    reg  regs$498$clock;
    reg  [23:0] regs$499$d;
    wire  [23:0] regs$499$q;
    reg  regs$499$clock;
    reg  [23:0] regs$500$d;
    wire  [23:0] regs$500$q;
    reg  regs$500$clock;
    reg  [23:0] regs$501$d;
    wire  [23:0] regs$501$q;
    reg  regs$501$clock;
    reg  [23:0] regs$502$d;
    wire  [23:0] regs$502$q;
    reg  regs$502$clock;
    reg  [23:0] regs$503$d;
    wire  [23:0] regs$503$q;
    reg  regs$503$clock;
    reg  [23:0] regs$504$d;
    wire  [23:0] regs$504$q;
    reg  regs$504$clock;
    reg  [23:0] regs$505$d;
    wire  [23:0] regs$505$q;
    reg  regs$505$clock;
    reg  [23:0] regs$506$d;
    wire  [23:0] regs$506$q;
    reg  regs$506$clock;
    reg  [23:0] regs$507$d;
    wire  [23:0] regs$507$q;
    reg  regs$507$clock;
    reg  [23:0] regs$508$d;
    wire  [23:0] regs$508$q;
    reg  regs$508$clock;
    reg  [23:0] regs$509$d;
    wire  [23:0] regs$509$q;
    reg  regs$509$clock;
    reg  [23:0] regs$510$d;
    wire  [23:0] regs$510$q;
    reg  regs$510$clock;
    reg  [23:0] regs$511$d;
    wire  [23:0] regs$511$q;
    reg  regs$511$clock;
    reg  [23:0] regs$512$d;
    wire  [23:0] regs$512$q;
    reg  regs$512$clock;
    reg  [23:0] regs$513$d;
    wire  [23:0] regs$513$q;
    reg  regs$513$clock;
    reg  [23:0] regs$514$d;
    wire  [23:0] regs$514$q;
    reg  regs$514$clock;
    reg  [23:0] regs$515$d;
    wire  [23:0] regs$515$q;
    reg  regs$515$clock;
    reg  [23:0] regs$516$d;
    wire  [23:0] regs$516$q;
    reg  regs$516$clock;
    reg  [23:0] regs$517$d;
    wire  [23:0] regs$517$q;
    reg  regs$517$clock;
    reg  [23:0] regs$518$d;
    wire  [23:0] regs$518$q;
    reg  regs$518$clock;
    reg  [23:0] regs$519$d;
    wire  [23:0] regs$519$q;
    reg  regs$519$clock;
    reg  [23:0] regs$520$d;
    wire  [23:0] regs$520$q;
    reg  regs$520$clock;
    reg  [23:0] regs$521$d;
    wire  [23:0] regs$521$q;
    reg  regs$521$clock;
    reg  [23:0] regs$522$d;
    wire  [23:0] regs$522$q;
    reg  regs$522$clock;
    reg  [23:0] regs$523$d;
    wire  [23:0] regs$523$q;
    reg  regs$523$clock;
    reg  [23:0] regs$524$d;
    wire  [23:0] regs$524$q;
    reg  regs$524$clock;
    reg  [23:0] regs$525$d;
    wire  [23:0] regs$525$q;
    reg  regs$525$clock;
    reg  [23:0] regs$526$d;
    wire  [23:0] regs$526$q;
    reg  regs$526$clock;
    reg  [23:0] regs$527$d;
    wire  [23:0] regs$527$q;
    reg  regs$527$clock;
    reg  [23:0] regs$528$d;
    wire  [23:0] regs$528$q;
    reg  regs$528$clock;
    reg  [23:0] regs$529$d;
    wire  [23:0] regs$529$q;
    reg  regs$529$clock;
    reg  [23:0] regs$530$d;
    wire  [23:0] regs$530$q;
    reg  regs$530$clock;
    reg  [23:0] regs$531$d;
    wire  [23:0] regs$531$q;
    reg  regs$531$clock;
    reg  [23:0] regs$532$d;
    wire  [23:0] regs$532$q;
    reg  regs$532$clock;
    reg  [23:0] regs$533$d;
    wire  [23:0] regs$533$q;
    reg  regs$533$clock;
    reg  [23:0] regs$534$d;
    wire  [23:0] regs$534$q;
    reg  regs$534$clock;
    reg  [23:0] regs$535$d;
    wire  [23:0] regs$535$q;
    reg  regs$535$clock;
    reg  [23:0] regs$536$d;
    wire  [23:0] regs$536$q;
    reg  regs$536$clock;
    reg  [23:0] regs$537$d;
    wire  [23:0] regs$537$q;
    reg  regs$537$clock;
    reg  [23:0] regs$538$d;
    wire  [23:0] regs$538$q;
    reg  regs$538$clock;
    reg  [23:0] regs$539$d;
    wire  [23:0] regs$539$q;
    reg  regs$539$clock;
    reg  [23:0] regs$540$d;
    wire  [23:0] regs$540$q;
    reg  regs$540$clock;
    reg  [23:0] regs$541$d;
    wire  [23:0] regs$541$q;
    reg  regs$541$clock;
    reg  [23:0] regs$542$d;
    wire  [23:0] regs$542$q;
    reg  regs$542$clock;
    reg  [23:0] regs$543$d;
    wire  [23:0] regs$543$q;
    reg  regs$543$clock;
    reg  [23:0] regs$544$d;
    wire  [23:0] regs$544$q;
    reg  regs$544$clock;
    reg  [23:0] regs$545$d;
    wire  [23:0] regs$545$q;
    reg  regs$545$clock;
    reg  [23:0] regs$546$d;
    wire  [23:0] regs$546$q;
    reg  regs$546$clock;
    reg  [23:0] regs$547$d;
    wire  [23:0] regs$547$q;
    reg  regs$547$clock;
    reg  [23:0] regs$548$d;
    wire  [23:0] regs$548$q;
    reg  regs$548$clock;
    reg  [23:0] regs$549$d;
    wire  [23:0] regs$549$q;
    reg  regs$549$clock;
    reg  [23:0] regs$550$d;
    wire  [23:0] regs$550$q;
    reg  regs$550$clock;
    reg  [23:0] regs$551$d;
    wire  [23:0] regs$551$q;
    reg  regs$551$clock;
    reg  [23:0] regs$552$d;
    wire  [23:0] regs$552$q;
    reg  regs$552$clock;
    reg  [23:0] regs$553$d;
    wire  [23:0] regs$553$q;
    reg  regs$553$clock;
    reg  [23:0] regs$554$d;
    wire  [23:0] regs$554$q;
    reg  regs$554$clock;
    reg  [23:0] regs$555$d;
    wire  [23:0] regs$555$q;
    reg  regs$555$clock;
    reg  [23:0] regs$556$d;
    wire  [23:0] regs$556$q;
    reg  regs$556$clock;
    reg  [23:0] regs$557$d;
    wire  [23:0] regs$557$q;
    reg  regs$557$clock;
    reg  [23:0] regs$558$d;
    wire  [23:0] regs$558$q;
    reg  regs$558$clock;
    reg  [23:0] regs$559$d;
    wire  [23:0] regs$559$q;
    reg  regs$559$clock;
    reg  [23:0] regs$560$d;
    wire  [23:0] regs$560$q;
    reg  regs$560$clock;
    reg  [23:0] regs$561$d;
    wire  [23:0] regs$561$q;
    reg  regs$561$clock;
    reg  [23:0] regs$562$d;
    wire  [23:0] regs$562$q;
    reg  regs$562$clock;
    reg  [23:0] regs$563$d;
    wire  [23:0] regs$563$q;
    reg  regs$563$clock;
    reg  [23:0] regs$564$d;
    wire  [23:0] regs$564$q;
    reg  regs$564$clock;
    reg  [23:0] regs$565$d;
    wire  [23:0] regs$565$q;
    reg  regs$565$clock;
    reg  [23:0] regs$566$d;
    wire  [23:0] regs$566$q;
    reg  regs$566$clock;
    reg  [23:0] regs$567$d;
    wire  [23:0] regs$567$q;
    reg  regs$567$clock;
    reg  [23:0] regs$568$d;
    wire  [23:0] regs$568$q;
    reg  regs$568$clock;
    reg  [23:0] regs$569$d;
    wire  [23:0] regs$569$q;
    reg  regs$569$clock;
    reg  [23:0] regs$570$d;
    wire  [23:0] regs$570$q;
    reg  regs$570$clock;
    reg  [23:0] regs$571$d;
    wire  [23:0] regs$571$q;
    reg  regs$571$clock;
    reg  [23:0] regs$572$d;
    wire  [23:0] regs$572$q;
    reg  regs$572$clock;
    reg  [23:0] regs$573$d;
    wire  [23:0] regs$573$q;
    reg  regs$573$clock;
    reg  [23:0] regs$574$d;
    wire  [23:0] regs$574$q;
    reg  regs$574$clock;
    reg  [23:0] regs$575$d;
    wire  [23:0] regs$575$q;
    reg  regs$575$clock;
    reg  [23:0] regs$576$d;
    wire  [23:0] regs$576$q;
    reg  regs$576$clock;
    reg  [23:0] regs$577$d;
    wire  [23:0] regs$577$q;
    reg  regs$577$clock;
    reg  [23:0] regs$578$d;
    wire  [23:0] regs$578$q;
    reg  regs$578$clock;
    reg  [23:0] regs$579$d;
    wire  [23:0] regs$579$q;
    reg  regs$579$clock;
    reg  [23:0] regs$580$d;
    wire  [23:0] regs$580$q;
    reg  regs$580$clock;
    reg  [23:0] regs$581$d;
    wire  [23:0] regs$581$q;
    reg  regs$581$clock;
    reg  [23:0] regs$582$d;
    wire  [23:0] regs$582$q;
    reg  regs$582$clock;
    reg  [23:0] regs$583$d;
    wire  [23:0] regs$583$q;
    reg  regs$583$clock;
    reg  [23:0] regs$584$d;
    wire  [23:0] regs$584$q;
    reg  regs$584$clock;
    reg  [23:0] regs$585$d;
    wire  [23:0] regs$585$q;
    reg  regs$585$clock;
    reg  [23:0] regs$586$d;
    wire  [23:0] regs$586$q;
    reg  regs$586$clock;
    reg  [23:0] regs$587$d;
    wire  [23:0] regs$587$q;
    reg  regs$587$clock;
    reg  [23:0] regs$588$d;
    wire  [23:0] regs$588$q;
    reg  regs$588$clock;
    reg  [23:0] regs$589$d;
    wire  [23:0] regs$589$q;
    reg  regs$589$clock;
    reg  [23:0] regs$590$d;
    wire  [23:0] regs$590$q;
    reg  regs$590$clock;
    reg  [23:0] regs$591$d;
    wire  [23:0] regs$591$q;
    reg  regs$591$clock;
    reg  [23:0] regs$592$d;
    wire  [23:0] regs$592$q;
    reg  regs$592$clock;
    reg  [23:0] regs$593$d;
    wire  [23:0] regs$593$q;
    reg  regs$593$clock;
    reg  [23:0] regs$594$d;
    wire  [23:0] regs$594$q;
    reg  regs$594$clock;
    reg  [23:0] regs$595$d;
    wire  [23:0] regs$595$q;
    reg  regs$595$clock;
    reg  [23:0] regs$596$d;
    wire  [23:0] regs$596$q;
    reg  regs$596$clock;
    reg  [23:0] regs$597$d;
    wire  [23:0] regs$597$q;
    reg  regs$597$clock;
    reg  [23:0] regs$598$d;
    wire  [23:0] regs$598$q;
    reg  regs$598$clock;
    reg  [23:0] regs$599$d;
    wire  [23:0] regs$599$q;
    reg  regs$599$clock;
    reg  [23:0] regs$600$d;
    wire  [23:0] regs$600$q;
    reg  regs$600$clock;
    reg  [23:0] regs$601$d;
    wire  [23:0] regs$601$q;
    reg  regs$601$clock;
    reg  [23:0] regs$602$d;
    wire  [23:0] regs$602$q;
    reg  regs$602$clock;
    reg  [23:0] regs$603$d;
    wire  [23:0] regs$603$q;
    reg  regs$603$clock;
    reg  [23:0] regs$604$d;
    wire  [23:0] regs$604$q;
    reg  regs$604$clock;
    reg  [23:0] regs$605$d;
    wire  [23:0] regs$605$q;
    reg  regs$605$clock;
    reg  [23:0] regs$606$d;
    wire  [23:0] regs$606$q;
    reg  regs$606$clock;
    reg  [23:0] regs$607$d;
    wire  [23:0] regs$607$q;
    reg  regs$607$clock;
    reg  [23:0] regs$608$d;
    wire  [23:0] regs$608$q;
    reg  regs$608$clock;
    reg  [23:0] regs$609$d;
    wire  [23:0] regs$609$q;
    reg  regs$609$clock;
    reg  [23:0] regs$610$d;
    wire  [23:0] regs$610$q;
    reg  regs$610$clock;
    reg  [23:0] regs$611$d;
    wire  [23:0] regs$611$q;
    reg  regs$611$clock;
    reg  [23:0] regs$612$d;
    wire  [23:0] regs$612$q;
    reg  regs$612$clock;
    reg  [23:0] regs$613$d;
    wire  [23:0] regs$613$q;
    reg  regs$613$clock;
    reg  [23:0] regs$614$d;
    wire  [23:0] regs$614$q;
    reg  regs$614$clock;
    reg  [23:0] regs$615$d;
    wire  [23:0] regs$615$q;
    reg  regs$615$clock;
    reg  [23:0] regs$616$d;
    wire  [23:0] regs$616$q;
    reg  regs$616$clock;
    reg  [23:0] regs$617$d;
    wire  [23:0] regs$617$q;
    reg  regs$617$clock;
    reg  [23:0] regs$618$d;
    wire  [23:0] regs$618$q;
    reg  regs$618$clock;
    reg  [23:0] regs$619$d;
    wire  [23:0] regs$619$q;
    reg  regs$619$clock;
    reg  [23:0] regs$620$d;
    wire  [23:0] regs$620$q;
    reg  regs$620$clock;
    reg  [23:0] regs$621$d;
    wire  [23:0] regs$621$q;
    reg  regs$621$clock;
    reg  [23:0] regs$622$d;
    wire  [23:0] regs$622$q;
    reg  regs$622$clock;
    reg  [23:0] regs$623$d;
    wire  [23:0] regs$623$q;
    reg  regs$623$clock;
    reg  [23:0] regs$624$d;
    wire  [23:0] regs$624$q;
    reg  regs$624$clock;
    reg  [23:0] regs$625$d;
    wire  [23:0] regs$625$q;
    reg  regs$625$clock;
    reg  [23:0] regs$626$d;
    wire  [23:0] regs$626$q;
    reg  regs$626$clock;
    reg  [23:0] regs$627$d;
    wire  [23:0] regs$627$q;
    reg  regs$627$clock;
    reg  [23:0] regs$628$d;
    wire  [23:0] regs$628$q;
    reg  regs$628$clock;
    reg  [23:0] regs$629$d;
    wire  [23:0] regs$629$q;
    reg  regs$629$clock;
    reg  [23:0] regs$630$d;
    wire  [23:0] regs$630$q;
    reg  regs$630$clock;
    reg  [23:0] regs$631$d;
    wire  [23:0] regs$631$q;
    reg  regs$631$clock;
    reg  [23:0] regs$632$d;
    wire  [23:0] regs$632$q;
    reg  regs$632$clock;
    reg  [23:0] regs$633$d;
    wire  [23:0] regs$633$q;
    reg  regs$633$clock;
    reg  [23:0] regs$634$d;
    wire  [23:0] regs$634$q;
    reg  regs$634$clock;
    reg  [23:0] regs$635$d;
    wire  [23:0] regs$635$q;
    reg  regs$635$clock;
    reg  [23:0] regs$636$d;
    wire  [23:0] regs$636$q;
    reg  regs$636$clock;
    reg  [23:0] regs$637$d;
    wire  [23:0] regs$637$q;
    reg  regs$637$clock;
    reg  [23:0] regs$638$d;
    wire  [23:0] regs$638$q;
    reg  regs$638$clock;
    reg  [23:0] regs$639$d;
    wire  [23:0] regs$639$q;
    reg  regs$639$clock;
    reg  [23:0] regs$640$d;
    wire  [23:0] regs$640$q;
    reg  regs$640$clock;
    reg  [23:0] regs$641$d;
    wire  [23:0] regs$641$q;
    reg  regs$641$clock;
    reg  [23:0] regs$642$d;
    wire  [23:0] regs$642$q;
    reg  regs$642$clock;
    reg  [23:0] regs$643$d;
    wire  [23:0] regs$643$q;
    reg  regs$643$clock;
    reg  [23:0] regs$644$d;
    wire  [23:0] regs$644$q;
    reg  regs$644$clock;
    reg  [23:0] regs$645$d;
    wire  [23:0] regs$645$q;
    reg  regs$645$clock;
    reg  [23:0] regs$646$d;
    wire  [23:0] regs$646$q;
    reg  regs$646$clock;
    reg  [23:0] regs$647$d;
    wire  [23:0] regs$647$q;
    reg  regs$647$clock;
    reg  [23:0] regs$648$d;
    wire  [23:0] regs$648$q;
    reg  regs$648$clock;
    reg  [23:0] regs$649$d;
    wire  [23:0] regs$649$q;
    reg  regs$649$clock;
    reg  [23:0] regs$650$d;
    wire  [23:0] regs$650$q;
    reg  regs$650$clock;
    reg  [23:0] regs$651$d;
    wire  [23:0] regs$651$q;
    reg  regs$651$clock;
    reg  [23:0] regs$652$d;
    wire  [23:0] regs$652$q;
    reg  regs$652$clock;
    reg  [23:0] regs$653$d;
    wire  [23:0] regs$653$q;
    reg  regs$653$clock;
    reg  [23:0] regs$654$d;
    wire  [23:0] regs$654$q;
    reg  regs$654$clock;
    reg  [23:0] regs$655$d;
    wire  [23:0] regs$655$q;
    reg  regs$655$clock;
    reg  [23:0] regs$656$d;
    wire  [23:0] regs$656$q;
    reg  regs$656$clock;
    reg  [23:0] regs$657$d;
    wire  [23:0] regs$657$q;
    reg  regs$657$clock;
    reg  [23:0] regs$658$d;
    wire  [23:0] regs$658$q;
    reg  regs$658$clock;
    reg  [23:0] regs$659$d;
    wire  [23:0] regs$659$q;
    reg  regs$659$clock;
    reg  [23:0] regs$660$d;
    wire  [23:0] regs$660$q;
    reg  regs$660$clock;
    reg  [23:0] regs$661$d;
    wire  [23:0] regs$661$q;
    reg  regs$661$clock;
    reg  [23:0] regs$662$d;
    wire  [23:0] regs$662$q;
    reg  regs$662$clock;
    reg  [23:0] regs$663$d;
    wire  [23:0] regs$663$q;
    reg  regs$663$clock;
    reg  [23:0] regs$664$d;
    wire  [23:0] regs$664$q;
    reg  regs$664$clock;
    reg  [23:0] regs$665$d;
    wire  [23:0] regs$665$q;
    reg  regs$665$clock;
    reg  [23:0] regs$666$d;
    wire  [23:0] regs$666$q;
    reg  regs$666$clock;
    reg  [23:0] regs$667$d;
    wire  [23:0] regs$667$q;
    reg  regs$667$clock;
    reg  [23:0] regs$668$d;
    wire  [23:0] regs$668$q;
    reg  regs$668$clock;
    reg  [23:0] regs$669$d;
    wire  [23:0] regs$669$q;
    reg  regs$669$clock;
    reg  [23:0] regs$670$d;
    wire  [23:0] regs$670$q;
    reg  regs$670$clock;
    reg  [23:0] regs$671$d;
    wire  [23:0] regs$671$q;
    reg  regs$671$clock;
    reg  [23:0] regs$672$d;
    wire  [23:0] regs$672$q;
    reg  regs$672$clock;
    reg  [23:0] regs$673$d;
    wire  [23:0] regs$673$q;
    reg  regs$673$clock;
    reg  [23:0] regs$674$d;
    wire  [23:0] regs$674$q;
    reg  regs$674$clock;
    reg  [23:0] regs$675$d;
    wire  [23:0] regs$675$q;
    reg  regs$675$clock;
    reg  [23:0] regs$676$d;
    wire  [23:0] regs$676$q;
    reg  regs$676$clock;
    reg  [23:0] regs$677$d;
    wire  [23:0] regs$677$q;
    reg  regs$677$clock;
    reg  [23:0] regs$678$d;
    wire  [23:0] regs$678$q;
    reg  regs$678$clock;
    reg  [23:0] regs$679$d;
    wire  [23:0] regs$679$q;
    reg  regs$679$clock;
    reg  [23:0] regs$680$d;
    wire  [23:0] regs$680$q;
    reg  regs$680$clock;
    reg  [23:0] regs$681$d;
    wire  [23:0] regs$681$q;
    reg  regs$681$clock;
    reg  [23:0] regs$682$d;
    wire  [23:0] regs$682$q;
    reg  regs$682$clock;
    reg  [23:0] regs$683$d;
    wire  [23:0] regs$683$q;
    reg  regs$683$clock;
    reg  [23:0] regs$684$d;
    wire  [23:0] regs$684$q;
    reg  regs$684$clock;
    reg  [23:0] regs$685$d;
    wire  [23:0] regs$685$q;
    reg  regs$685$clock;
    reg  [23:0] regs$686$d;
    wire  [23:0] regs$686$q;
    reg  regs$686$clock;
    reg  [23:0] regs$687$d;
    wire  [23:0] regs$687$q;
    reg  regs$687$clock;
    reg  [23:0] regs$688$d;
    wire  [23:0] regs$688$q;
    reg  regs$688$clock;
    reg  [23:0] regs$689$d;
    wire  [23:0] regs$689$q;
    reg  regs$689$clock;
    reg  [23:0] regs$690$d;
    wire  [23:0] regs$690$q;
    reg  regs$690$clock;
    reg  [23:0] regs$691$d;
    wire  [23:0] regs$691$q;
    reg  regs$691$clock;
    reg  [23:0] regs$692$d;
    wire  [23:0] regs$692$q;
    reg  regs$692$clock;
    reg  [23:0] regs$693$d;
    wire  [23:0] regs$693$q;
    reg  regs$693$clock;
    reg  [23:0] regs$694$d;
    wire  [23:0] regs$694$q;
    reg  regs$694$clock;
    reg  [23:0] regs$695$d;
    wire  [23:0] regs$695$q;
    reg  regs$695$clock;
    reg  [23:0] regs$696$d;
    wire  [23:0] regs$696$q;
    reg  regs$696$clock;
    reg  [23:0] regs$697$d;
    wire  [23:0] regs$697$q;
    reg  regs$697$clock;
    reg  [23:0] regs$698$d;
    wire  [23:0] regs$698$q;
    reg  regs$698$clock;
    reg  [23:0] regs$699$d;
    wire  [23:0] regs$699$q;
    reg  regs$699$clock;
    reg  [23:0] regs$700$d;
    wire  [23:0] regs$700$q;
    reg  regs$700$clock;
    reg  [23:0] regs$701$d;
    wire  [23:0] regs$701$q;
    reg  regs$701$clock;
    reg  [23:0] regs$702$d;
    wire  [23:0] regs$702$q;
    reg  regs$702$clock;
    reg  [23:0] regs$703$d;
    wire  [23:0] regs$703$q;
    reg  regs$703$clock;
    reg  [23:0] regs$704$d;
    wire  [23:0] regs$704$q;
    reg  regs$704$clock;
    reg  [23:0] regs$705$d;
    wire  [23:0] regs$705$q;
    reg  regs$705$clock;
    reg  [23:0] regs$706$d;
    wire  [23:0] regs$706$q;
    reg  regs$706$clock;
    reg  [23:0] regs$707$d;
    wire  [23:0] regs$707$q;
    reg  regs$707$clock;
    reg  [23:0] regs$708$d;
    wire  [23:0] regs$708$q;
    reg  regs$708$clock;
    reg  [23:0] regs$709$d;
    wire  [23:0] regs$709$q;
    reg  regs$709$clock;
    reg  [23:0] regs$710$d;
    wire  [23:0] regs$710$q;
    reg  regs$710$clock;
    reg  [23:0] regs$711$d;
    wire  [23:0] regs$711$q;
    reg  regs$711$clock;
    reg  [23:0] regs$712$d;
    wire  [23:0] regs$712$q;
    reg  regs$712$clock;
    reg  [23:0] regs$713$d;
    wire  [23:0] regs$713$q;
    reg  regs$713$clock;
    reg  [23:0] regs$714$d;
    wire  [23:0] regs$714$q;
    reg  regs$714$clock;
    reg  [23:0] regs$715$d;
    wire  [23:0] regs$715$q;
    reg  regs$715$clock;
    reg  [23:0] regs$716$d;
    wire  [23:0] regs$716$q;
    reg  regs$716$clock;
    reg  [23:0] regs$717$d;
    wire  [23:0] regs$717$q;
    reg  regs$717$clock;
    reg  [23:0] regs$718$d;
    wire  [23:0] regs$718$q;
    reg  regs$718$clock;
    reg  [23:0] regs$719$d;
    wire  [23:0] regs$719$q;
    reg  regs$719$clock;
    reg  [23:0] regs$720$d;
    wire  [23:0] regs$720$q;
    reg  regs$720$clock;
    reg  [23:0] regs$721$d;
    wire  [23:0] regs$721$q;
    reg  regs$721$clock;
    reg  [23:0] regs$722$d;
    wire  [23:0] regs$722$q;
    reg  regs$722$clock;
    reg  [23:0] regs$723$d;
    wire  [23:0] regs$723$q;
    reg  regs$723$clock;
    reg  [23:0] regs$724$d;
    wire  [23:0] regs$724$q;
    reg  regs$724$clock;
    reg  [23:0] regs$725$d;
    wire  [23:0] regs$725$q;
    reg  regs$725$clock;
    reg  [23:0] regs$726$d;
    wire  [23:0] regs$726$q;
    reg  regs$726$clock;
    reg  [23:0] regs$727$d;
    wire  [23:0] regs$727$q;
    reg  regs$727$clock;
    reg  [23:0] regs$728$d;
    wire  [23:0] regs$728$q;
    reg  regs$728$clock;
    reg  [23:0] regs$729$d;
    wire  [23:0] regs$729$q;
    reg  regs$729$clock;
    reg  [23:0] regs$730$d;
    wire  [23:0] regs$730$q;
    reg  regs$730$clock;
    reg  [23:0] regs$731$d;
    wire  [23:0] regs$731$q;
    reg  regs$731$clock;
    reg  [23:0] regs$732$d;
    wire  [23:0] regs$732$q;
    reg  regs$732$clock;
    reg  [23:0] regs$733$d;
    wire  [23:0] regs$733$q;
    reg  regs$733$clock;
    reg  [23:0] regs$734$d;
    wire  [23:0] regs$734$q;
    reg  regs$734$clock;
    reg  [23:0] regs$735$d;
    wire  [23:0] regs$735$q;
    reg  regs$735$clock;
    reg  [23:0] regs$736$d;
    wire  [23:0] regs$736$q;
    reg  regs$736$clock;
    reg  [23:0] regs$737$d;
    wire  [23:0] regs$737$q;
    reg  regs$737$clock;
    reg  [23:0] regs$738$d;
    wire  [23:0] regs$738$q;
    reg  regs$738$clock;
    reg  [23:0] regs$739$d;
    wire  [23:0] regs$739$q;
    reg  regs$739$clock;
    reg  [23:0] regs$740$d;
    wire  [23:0] regs$740$q;
    reg  regs$740$clock;
    reg  [23:0] regs$741$d;
    wire  [23:0] regs$741$q;
    reg  regs$741$clock;
    reg  [23:0] regs$742$d;
    wire  [23:0] regs$742$q;
    reg  regs$742$clock;
    reg  [23:0] regs$743$d;
    wire  [23:0] regs$743$q;
    reg  regs$743$clock;
    reg  [23:0] regs$744$d;
    wire  [23:0] regs$744$q;
    reg  regs$744$clock;
    reg  [23:0] regs$745$d;
    wire  [23:0] regs$745$q;
    reg  regs$745$clock;
    reg  [23:0] regs$746$d;
    wire  [23:0] regs$746$q;
    reg  regs$746$clock;
    reg  [23:0] regs$747$d;
    wire  [23:0] regs$747$q;
    reg  regs$747$clock;
    reg  [23:0] regs$748$d;
    wire  [23:0] regs$748$q;
    reg  regs$748$clock;
    reg  [23:0] regs$749$d;
    wire  [23:0] regs$749$q;
    reg  regs$749$clock;
    reg  [23:0] regs$750$d;
    wire  [23:0] regs$750$q;
    reg  regs$750$clock;
    reg  [23:0] regs$751$d;
    wire  [23:0] regs$751$q;
    reg  regs$751$clock;
    reg  [23:0] regs$752$d;
    wire  [23:0] regs$752$q;
    reg  regs$752$clock;
    reg  [23:0] regs$753$d;
    wire  [23:0] regs$753$q;
    reg  regs$753$clock;
    reg  [23:0] regs$754$d;
    wire  [23:0] regs$754$q;
    reg  regs$754$clock;
    reg  [23:0] regs$755$d;
    wire  [23:0] regs$755$q;
    reg  regs$755$clock;
    reg  [23:0] regs$756$d;
    wire  [23:0] regs$756$q;
    reg  regs$756$clock;
    reg  [23:0] regs$757$d;
    wire  [23:0] regs$757$q;
    reg  regs$757$clock;
    reg  [23:0] regs$758$d;
    wire  [23:0] regs$758$q;
    reg  regs$758$clock;
    reg  [23:0] regs$759$d;
    wire  [23:0] regs$759$q;
    reg  regs$759$clock;
    reg  [23:0] regs$760$d;
    wire  [23:0] regs$760$q;
    reg  regs$760$clock;
    reg  [23:0] regs$761$d;
    wire  [23:0] regs$761$q;
    reg  regs$761$clock;
    reg  [23:0] regs$762$d;
    wire  [23:0] regs$762$q;
    reg  regs$762$clock;
    reg  [23:0] regs$763$d;
    wire  [23:0] regs$763$q;
    reg  regs$763$clock;
    reg  [23:0] regs$764$d;
    wire  [23:0] regs$764$q;
    reg  regs$764$clock;
    reg  [23:0] regs$765$d;
    wire  [23:0] regs$765$q;
    reg  regs$765$clock;
    reg  [23:0] regs$766$d;
    wire  [23:0] regs$766$q;
    reg  regs$766$clock;
    reg  [23:0] regs$767$d;
    wire  [23:0] regs$767$q;
    reg  regs$767$clock;
    reg  [23:0] regs$768$d;
    wire  [23:0] regs$768$q;
    reg  regs$768$clock;
    reg  [23:0] regs$769$d;
    wire  [23:0] regs$769$q;
    reg  regs$769$clock;
    reg  [23:0] regs$770$d;
    wire  [23:0] regs$770$q;
    reg  regs$770$clock;
    reg  [23:0] regs$771$d;
    wire  [23:0] regs$771$q;
    reg  regs$771$clock;
    reg  [23:0] regs$772$d;
    wire  [23:0] regs$772$q;
    reg  regs$772$clock;
    reg  [23:0] regs$773$d;
    wire  [23:0] regs$773$q;
    reg  regs$773$clock;
    reg  [23:0] regs$774$d;
    wire  [23:0] regs$774$q;
    reg  regs$774$clock;
    reg  [23:0] regs$775$d;
    wire  [23:0] regs$775$q;
    reg  regs$775$clock;
    reg  [23:0] regs$776$d;
    wire  [23:0] regs$776$q;
    reg  regs$776$clock;
    reg  [23:0] regs$777$d;
    wire  [23:0] regs$777$q;
    reg  regs$777$clock;
    reg  [23:0] regs$778$d;
    wire  [23:0] regs$778$q;
    reg  regs$778$clock;
    reg  [23:0] regs$779$d;
    wire  [23:0] regs$779$q;
    reg  regs$779$clock;
    reg  [23:0] regs$780$d;
    wire  [23:0] regs$780$q;
    reg  regs$780$clock;
    reg  [23:0] regs$781$d;
    wire  [23:0] regs$781$q;
    reg  regs$781$clock;
    reg  [23:0] regs$782$d;
    wire  [23:0] regs$782$q;
    reg  regs$782$clock;
    reg  [23:0] regs$783$d;
    wire  [23:0] regs$783$q;
    reg  regs$783$clock;
    reg  [23:0] regs$784$d;
    wire  [23:0] regs$784$q;
    reg  regs$784$clock;
    reg  [23:0] regs$785$d;
    wire  [23:0] regs$785$q;
    reg  regs$785$clock;
    reg  [23:0] regs$786$d;
    wire  [23:0] regs$786$q;
    reg  regs$786$clock;
    reg  [23:0] regs$787$d;
    wire  [23:0] regs$787$q;
    reg  regs$787$clock;
    reg  [23:0] regs$788$d;
    wire  [23:0] regs$788$q;
    reg  regs$788$clock;
    reg  [23:0] regs$789$d;
    wire  [23:0] regs$789$q;
    reg  regs$789$clock;
    reg  [23:0] regs$790$d;
    wire  [23:0] regs$790$q;
    reg  regs$790$clock;
    reg  [23:0] regs$791$d;
    wire  [23:0] regs$791$q;
    reg  regs$791$clock;
    reg  [23:0] regs$792$d;
    wire  [23:0] regs$792$q;
    reg  regs$792$clock;
    reg  [23:0] regs$793$d;
    wire  [23:0] regs$793$q;
    reg  regs$793$clock;
    reg  [23:0] regs$794$d;
    wire  [23:0] regs$794$q;
    reg  regs$794$clock;
    reg  [23:0] regs$795$d;
    wire  [23:0] regs$795$q;
    reg  regs$795$clock;
    reg  [23:0] regs$796$d;
    wire  [23:0] regs$796$q;
    reg  regs$796$clock;
    reg  [23:0] regs$797$d;
    wire  [23:0] regs$797$q;
    reg  regs$797$clock;
    reg  [23:0] regs$798$d;
    wire  [23:0] regs$798$q;
    reg  regs$798$clock;
    reg  [23:0] regs$799$d;
    wire  [23:0] regs$799$q;
    reg  regs$799$clock;
    reg  [23:0] regs$800$d;
    wire  [23:0] regs$800$q;
    reg  regs$800$clock;
    reg  [23:0] regs$801$d;
    wire  [23:0] regs$801$q;
    reg  regs$801$clock;
    reg  [23:0] regs$802$d;
    wire  [23:0] regs$802$q;
    reg  regs$802$clock;
    reg  [23:0] regs$803$d;
    wire  [23:0] regs$803$q;
    reg  regs$803$clock;
    reg  [23:0] regs$804$d;
    wire  [23:0] regs$804$q;
    reg  regs$804$clock;
    reg  [23:0] regs$805$d;
    wire  [23:0] regs$805$q;
    reg  regs$805$clock;
    reg  [23:0] regs$806$d;
    wire  [23:0] regs$806$q;
    reg  regs$806$clock;
    reg  [23:0] regs$807$d;
    wire  [23:0] regs$807$q;
    reg  regs$807$clock;
    reg  [23:0] regs$808$d;
    wire  [23:0] regs$808$q;
    reg  regs$808$clock;
    reg  [23:0] regs$809$d;
    wire  [23:0] regs$809$q;
    reg  regs$809$clock;
    reg  [23:0] regs$810$d;
    wire  [23:0] regs$810$q;
    reg  regs$810$clock;
    reg  [23:0] regs$811$d;
    wire  [23:0] regs$811$q;
    reg  regs$811$clock;
    reg  [23:0] regs$812$d;
    wire  [23:0] regs$812$q;
    reg  regs$812$clock;
    reg  [23:0] regs$813$d;
    wire  [23:0] regs$813$q;
    reg  regs$813$clock;
    reg  [23:0] regs$814$d;
    wire  [23:0] regs$814$q;
    reg  regs$814$clock;
    reg  [23:0] regs$815$d;
    wire  [23:0] regs$815$q;
    reg  regs$815$clock;
    reg  [23:0] regs$816$d;
    wire  [23:0] regs$816$q;
    reg  regs$816$clock;
    reg  [23:0] regs$817$d;
    wire  [23:0] regs$817$q;
    reg  regs$817$clock;
    reg  exact$0$d;
    wire  exact$0$q;
    reg  exact$0$clock;
    reg  exact$1$d;
    wire  exact$1$q;
    reg  exact$1$clock;
    reg  exact$2$d;
    wire  exact$2$q;
    reg  exact$2$clock;
    reg  exact$3$d;
    wire  exact$3$q;
    reg  exact$3$clock;
    reg  valid$0$d;
    wire  valid$0$q;
    reg  valid$0$clock;
    reg  valid$1$d;
    wire  valid$1$q;
    reg  valid$1$clock;
    reg  valid$2$d;
    wire  valid$2$q;
    reg  valid$2$clock;
    reg  valid$3$d;
    wire  valid$3$q;
    reg  valid$3$clock;
    reg  valid$4$d;
    wire  valid$4$q;
    reg  valid$4$clock;
    reg  valid$5$d;
    wire  valid$5$q;
    reg  valid$5$clock;
    reg  valid$6$d;
    wire  valid$6$q;
    reg  valid$6$clock;
    reg  valid$7$d;
    wire  valid$7$q;
    reg  valid$7$clock;
    reg  valid$8$d;
    wire  valid$8$q;
    reg  valid$8$clock;
    reg  valid$9$d;
    wire  valid$9$q;
    reg  valid$9$clock;
    reg  [31:0] tags$0$d;
    wire  [31:0] tags$0$q;
    reg  tags$0$clock;
    reg  [31:0] tags$1$d;
    wire  [31:0] tags$1$q;
    reg  tags$1$clock;
    reg  [31:0] tags$2$d;
    wire  [31:0] tags$2$q;
    reg  tags$2$clock;
    reg  [31:0] tags$3$d;
    wire  [31:0] tags$3$q;
    reg  tags$3$clock;
    reg  [31:0] tags$4$d;
    wire  [31:0] tags$4$q;
    reg  tags$4$clock;
    reg  [31:0] tags$5$d;
    wire  [31:0] tags$5$q;
    reg  tags$5$clock;
    reg  [31:0] tags$6$d;
    wire  [31:0] tags$6$q;
    reg  tags$6$clock;
    reg  [31:0] tags$7$d;
    wire  [31:0] tags$7$q;
    reg  tags$7$clock;
    reg  [31:0] tags$8$d;
    wire  [31:0] tags$8$q;
    reg  tags$8$clock;
    reg  [31:0] tags$9$d;
    wire  [31:0] tags$9$q;
    reg  tags$9$clock;
    reg  [7:0] cnt$0$d;
    wire  [7:0] cnt$0$q;
    reg  cnt$0$clock;
    reg  [7:0] cnt$1$d;
    wire  [7:0] cnt$1$q;
    reg  cnt$1$clock;
    reg  [7:0] cnt$2$d;
    wire  [7:0] cnt$2$q;
    reg  cnt$2$clock;
    reg  [7:0] cnt$3$d;
    wire  [7:0] cnt$3$q;
    reg  cnt$3$clock;
    reg  [7:0] cnt$4$d;
    wire  [7:0] cnt$4$q;
    reg  cnt$4$clock;
    reg  [7:0] cnt$5$d;
    wire  [7:0] cnt$5$q;
    reg  cnt$5$clock;
    reg  [7:0] cnt$6$d;
    wire  [7:0] cnt$6$q;
    reg  cnt$6$clock;
    reg  [7:0] cnt$7$d;
    wire  [7:0] cnt$7$q;
    reg  cnt$7$clock;
    reg  [7:0] cnt$8$d;
    wire  [7:0] cnt$8$q;
    reg  cnt$8$clock;
    reg  [7:0] cnt$9$d;
    wire  [7:0] cnt$9$q;
    reg  cnt$9$clock;
    reg  [7:0] cnt$10$d;
    wire  [7:0] cnt$10$q;
    reg  cnt$10$clock;
    reg  [7:0] cnt$11$d;
    wire  [7:0] cnt$11$q;
    reg  cnt$11$clock;
    reg  [7:0] cnt$12$d;
    wire  [7:0] cnt$12$q;
    reg  cnt$12$clock;
    reg  [7:0] cnt$13$d;
    wire  [7:0] cnt$13$q;
    reg  cnt$13$clock;
    reg  [7:0] cnt$14$d;
    wire  [7:0] cnt$14$q;
    reg  cnt$14$clock;
    reg  [7:0] cnt$15$d;
    wire  [7:0] cnt$15$q;
    reg  cnt$15$clock;
    reg  [7:0] cnt$16$d;
    wire  [7:0] cnt$16$q;
    reg  cnt$16$clock;
    reg  [7:0] cnt$17$d;
    wire  [7:0] cnt$17$q;
    reg  cnt$17$clock;
    reg  [7:0] cnt$18$d;
    wire  [7:0] cnt$18$q;
    reg  cnt$18$clock;
    reg  [7:0] cnt$19$d;
    wire  [7:0] cnt$19$q;
    reg  cnt$19$clock;
    reg  [7:0] cnt$20$d;
    wire  [7:0] cnt$20$q;
    reg  cnt$20$clock;
    reg  [7:0] cnt$21$d;
    wire  [7:0] cnt$21$q;
    reg  cnt$21$clock;
    reg  [7:0] cnt$22$d;
    wire  [7:0] cnt$22$q;
    reg  cnt$22$clock;
    reg  [7:0] cnt$23$d;
    wire  [7:0] cnt$23$q;
    reg  cnt$23$clock;
    reg  [7:0] cnt$24$d;
    wire  [7:0] cnt$24$q;
    reg  cnt$24$clock;
    reg  [7:0] cnt$25$d;
    wire  [7:0] cnt$25$q;
    reg  cnt$25$clock;
    reg  [7:0] cnt$26$d;
    wire  [7:0] cnt$26$q;
    reg  cnt$26$clock;
    reg  [7:0] cnt$27$d;
    wire  [7:0] cnt$27$q;
    reg  cnt$27$clock;
    reg  [7:0] cnt$28$d;
    wire  [7:0] cnt$28$q;
    reg  cnt$28$clock;
    reg  [7:0] cnt$29$d;
    wire  [7:0] cnt$29$q;
    reg  cnt$29$clock;
    reg  [7:0] cnt$30$d;
    wire  [7:0] cnt$30$q;
    reg  cnt$30$clock;
    reg  [7:0] cnt$31$d;
    wire  [7:0] cnt$31$q;
    reg  cnt$31$clock;
    reg  [7:0] cnt$32$d;
    wire  [7:0] cnt$32$q;
    reg  cnt$32$clock;
    reg  [7:0] cnt$33$d;
    wire  [7:0] cnt$33$q;
    reg  cnt$33$clock;
    reg  [7:0] cnt$34$d;
    wire  [7:0] cnt$34$q;
    reg  cnt$34$clock;
    reg  [7:0] cnt$35$d;
    wire  [7:0] cnt$35$q;
    reg  cnt$35$clock;
    reg  [7:0] cnt$36$d;
    wire  [7:0] cnt$36$q;
    reg  cnt$36$clock;
    reg  [7:0] cnt$37$d;
    wire  [7:0] cnt$37$q;
    reg  cnt$37$clock;
    reg  [7:0] cnt$38$d;
    wire  [7:0] cnt$38$q;
    reg  cnt$38$clock;
    reg  [7:0] cnt$39$d;
    wire  [7:0] cnt$39$q;
    reg  cnt$39$clock;
    reg  [7:0] cnt$40$d;
    wire  [7:0] cnt$40$q;
    reg  cnt$40$clock;
    reg  [7:0] cnt$41$d;
    wire  [7:0] cnt$41$q;
    reg  cnt$41$clock;
    reg  [7:0] cnt$42$d;
    wire  [7:0] cnt$42$q;
    reg  cnt$42$clock;
    reg  [7:0] cnt$43$d;
    wire  [7:0] cnt$43$q;
    reg  cnt$43$clock;
    reg  [7:0] cnt$44$d;
    wire  [7:0] cnt$44$q;
    reg  cnt$44$clock;
    reg  [7:0] cnt$45$d;
    wire  [7:0] cnt$45$q;
    reg  cnt$45$clock;
    reg  [7:0] cnt$46$d;
    wire  [7:0] cnt$46$q;
    reg  cnt$46$clock;
    reg  [7:0] cnt$47$d;
    wire  [7:0] cnt$47$q;
    reg  cnt$47$clock;
    reg  [7:0] cnt$48$d;
    wire  [7:0] cnt$48$q;
    reg  cnt$48$clock;
    reg  [7:0] cnt$49$d;
    wire  [7:0] cnt$49$q;
    reg  cnt$49$clock;
    reg  [7:0] cnt$50$d;
    wire  [7:0] cnt$50$q;
    reg  cnt$50$clock;
    reg  [7:0] cnt$51$d;
    wire  [7:0] cnt$51$q;
    reg  cnt$51$clock;
    reg  [7:0] cnt$52$d;
    wire  [7:0] cnt$52$q;
    reg  cnt$52$clock;
    reg  [7:0] cnt$53$d;
    wire  [7:0] cnt$53$q;
    reg  cnt$53$clock;
    reg  [7:0] cnt$54$d;
    wire  [7:0] cnt$54$q;
    reg  cnt$54$clock;
    reg  [7:0] cnt$55$d;
    wire  [7:0] cnt$55$q;
    reg  cnt$55$clock;
    reg  [7:0] cnt$56$d;
    wire  [7:0] cnt$56$q;
    reg  cnt$56$clock;
    reg  [7:0] cnt$57$d;
    wire  [7:0] cnt$57$q;
    reg  cnt$57$clock;
    reg  [7:0] cnt$58$d;
    wire  [7:0] cnt$58$q;
    reg  cnt$58$clock;
    reg  [7:0] cnt$59$d;
    wire  [7:0] cnt$59$q;
    reg  cnt$59$clock;
    reg  [7:0] cnt$60$d;
    wire  [7:0] cnt$60$q;
    reg  cnt$60$clock;
    reg  [7:0] cnt$61$d;
    wire  [7:0] cnt$61$q;
    reg  cnt$61$clock;
    reg  [7:0] cnt$62$d;
    wire  [7:0] cnt$62$q;
    reg  cnt$62$clock;
    reg  [7:0] cnt$63$d;
    wire  [7:0] cnt$63$q;
    reg  cnt$63$clock;
    reg  [7:0] cnt$64$d;
    wire  [7:0] cnt$64$q;
    reg  cnt$64$clock;
    reg  [7:0] cnt$65$d;
    wire  [7:0] cnt$65$q;
    reg  cnt$65$clock;
    reg  [7:0] cnt$66$d;
    wire  [7:0] cnt$66$q;
    reg  cnt$66$clock;
    reg  [7:0] cnt$67$d;
    wire  [7:0] cnt$67$q;
    reg  cnt$67$clock;
    reg  [7:0] cnt$68$d;
    wire  [7:0] cnt$68$q;
    reg  cnt$68$clock;
    reg  [7:0] cnt$69$d;
    wire  [7:0] cnt$69$q;
    reg  cnt$69$clock;
    reg  [7:0] cnt$70$d;
    wire  [7:0] cnt$70$q;
    reg  cnt$70$clock;
    reg  [7:0] cnt$71$d;
    wire  [7:0] cnt$71$q;
    reg  cnt$71$clock;
    reg  [7:0] cnt$72$d;
    wire  [7:0] cnt$72$q;
    reg  cnt$72$clock;
    reg  [7:0] cnt$73$d;
    wire  [7:0] cnt$73$q;
    reg  cnt$73$clock;
    reg  [7:0] cnt$74$d;
    wire  [7:0] cnt$74$q;
    reg  cnt$74$clock;
    reg  [7:0] cnt$75$d;
    wire  [7:0] cnt$75$q;
    reg  cnt$75$clock;
    reg  [7:0] cnt$76$d;
    wire  [7:0] cnt$76$q;
    reg  cnt$76$clock;
    reg  [7:0] cnt$77$d;
    wire  [7:0] cnt$77$q;
    reg  cnt$77$clock;
    reg  [7:0] cnt$78$d;
    wire  [7:0] cnt$78$q;
    reg  cnt$78$clock;
    reg  [7:0] cnt$79$d;
    wire  [7:0] cnt$79$q;
    reg  cnt$79$clock;
    reg  [7:0] cnt$80$d;
    wire  [7:0] cnt$80$q;
    reg  cnt$80$clock;
    reg  [7:0] cnt$81$d;
    wire  [7:0] cnt$81$q;
    reg  cnt$81$clock;
    reg  [7:0] cnt$82$d;
    wire  [7:0] cnt$82$q;
    reg  cnt$82$clock;
    reg  [7:0] cnt$83$d;
    wire  [7:0] cnt$83$q;
    reg  cnt$83$clock;
    reg  [7:0] cnt$84$d;
    wire  [7:0] cnt$84$q;
    reg  cnt$84$clock;
    reg  [7:0] cnt$85$d;
    wire  [7:0] cnt$85$q;
    reg  cnt$85$clock;
    reg  [7:0] cnt$86$d;
    wire  [7:0] cnt$86$q;
    reg  cnt$86$clock;
    reg  [7:0] cnt$87$d;
    wire  [7:0] cnt$87$q;
    reg  cnt$87$clock;
    reg  [7:0] cnt$88$d;
    wire  [7:0] cnt$88$q;
    reg  cnt$88$clock;
    reg  [7:0] cnt$89$d;
    wire  [7:0] cnt$89$q;
    reg  cnt$89$clock;
    reg  [7:0] cnt$90$d;
    wire  [7:0] cnt$90$q;
    reg  cnt$90$clock;
    reg  [7:0] cnt$91$d;
    wire  [7:0] cnt$91$q;
    reg  cnt$91$clock;
    reg  [23:0] op_a$0$d;
    wire  [23:0] op_a$0$q;
    reg  op_a$0$clock;
    reg  [23:0] op_a$1$d;
    wire  [23:0] op_a$1$q;
    reg  op_a$1$clock;
    reg  [23:0] op_a$2$d;
    wire  [23:0] op_a$2$q;
    reg  op_a$2$clock;
    reg  [23:0] op_a$3$d;
    wire  [23:0] op_a$3$q;
    reg  op_a$3$clock;
    reg  [23:0] op_a$4$d;
    wire  [23:0] op_a$4$q;
    reg  op_a$4$clock;
    reg  [23:0] op_a$5$d;
    wire  [23:0] op_a$5$q;
    reg  op_a$5$clock;
    reg  [23:0] op_a$6$d;
    wire  [23:0] op_a$6$q;
    reg  op_a$6$clock;
    reg  [23:0] op_a$7$d;
    wire  [23:0] op_a$7$q;
    reg  op_a$7$clock;
    reg  [23:0] op_a$8$d;
    wire  [23:0] op_a$8$q;
    reg  op_a$8$clock;
    reg  [23:0] op_a$9$d;
    wire  [23:0] op_a$9$q;
    reg  op_a$9$clock;
    reg  [23:0] op_a$10$d;
    wire  [23:0] op_a$10$q;
    reg  op_a$10$clock;
    reg  [23:0] op_a$11$d;
    wire  [23:0] op_a$11$q;
    reg  op_a$11$clock;
    reg  [23:0] op_a$12$d;
    wire  [23:0] op_a$12$q;
    reg  op_a$12$clock;
    reg  [23:0] op_a$13$d;
    wire  [23:0] op_a$13$q;
    reg  op_a$13$clock;
    reg  [23:0] op_a$14$d;
    wire  [23:0] op_a$14$q;
    reg  op_a$14$clock;
    reg  [23:0] op_a$15$d;
    wire  [23:0] op_a$15$q;
    reg  op_a$15$clock;
    reg  [23:0] op_a$16$d;
    wire  [23:0] op_a$16$q;
    reg  op_a$16$clock;
    reg  [23:0] op_a$17$d;
    wire  [23:0] op_a$17$q;
    reg  op_a$17$clock;
    reg  [23:0] op_a$18$d;
    wire  [23:0] op_a$18$q;
    reg  op_a$18$clock;
    reg  [23:0] op_a$19$d;
    wire  [23:0] op_a$19$q;
    reg  op_a$19$clock;
    reg  [23:0] op_a$20$d;
    wire  [23:0] op_a$20$q;
    reg  op_a$20$clock;
    reg  [23:0] op_a$21$d;
    wire  [23:0] op_a$21$q;
    reg  op_a$21$clock;
    reg  [23:0] op_a$22$d;
    wire  [23:0] op_a$22$q;
    reg  op_a$22$clock;
    reg  [23:0] op_a$23$d;
    wire  [23:0] op_a$23$q;
    reg  op_a$23$clock;
    reg  [23:0] op_a$24$d;
    wire  [23:0] op_a$24$q;
    reg  op_a$24$clock;
    reg  [23:0] op_a$25$d;
    wire  [23:0] op_a$25$q;
    reg  op_a$25$clock;
    reg  [23:0] op_a$26$d;
    wire  [23:0] op_a$26$q;
    reg  op_a$26$clock;
    reg  [23:0] op_b$0$d;
    wire  [23:0] op_b$0$q;
    reg  op_b$0$clock;
    reg  [23:0] op_b$1$d;
    wire  [23:0] op_b$1$q;
    reg  op_b$1$clock;
    reg  [23:0] op_b$2$d;
    wire  [23:0] op_b$2$q;
    reg  op_b$2$clock;
    reg  [23:0] op_b$3$d;
    wire  [23:0] op_b$3$q;
    reg  op_b$3$clock;
    reg  [23:0] op_b$4$d;
    wire  [23:0] op_b$4$q;
    reg  op_b$4$clock;
    reg  [23:0] op_b$5$d;
    wire  [23:0] op_b$5$q;
    reg  op_b$5$clock;
    reg  [23:0] op_b$6$d;
    wire  [23:0] op_b$6$q;
    reg  op_b$6$clock;
    reg  [23:0] op_b$7$d;
    wire  [23:0] op_b$7$q;
    reg  op_b$7$clock;
    reg  [23:0] op_b$8$d;
    wire  [23:0] op_b$8$q;
    reg  op_b$8$clock;
    reg  [23:0] op_b$9$d;
    wire  [23:0] op_b$9$q;
    reg  op_b$9$clock;
    reg  [23:0] op_b$10$d;
    wire  [23:0] op_b$10$q;
    reg  op_b$10$clock;
    reg  [23:0] op_b$11$d;
    wire  [23:0] op_b$11$q;
    reg  op_b$11$clock;
    reg  [23:0] op_b$12$d;
    wire  [23:0] op_b$12$q;
    reg  op_b$12$clock;
    reg  [23:0] op_b$13$d;
    wire  [23:0] op_b$13$q;
    reg  op_b$13$clock;
    reg  [23:0] op_b$14$d;
    wire  [23:0] op_b$14$q;
    reg  op_b$14$clock;
    reg  [23:0] op_b$15$d;
    wire  [23:0] op_b$15$q;
    reg  op_b$15$clock;
    reg  [23:0] op_b$16$d;
    wire  [23:0] op_b$16$q;
    reg  op_b$16$clock;
    reg  [23:0] op_b$17$d;
    wire  [23:0] op_b$17$q;
    reg  op_b$17$clock;
    reg  [23:0] op_b$18$d;
    wire  [23:0] op_b$18$q;
    reg  op_b$18$clock;
    reg  [23:0] op_b$19$d;
    wire  [23:0] op_b$19$q;
    reg  op_b$19$clock;
    reg  [23:0] op_b$20$d;
    wire  [23:0] op_b$20$q;
    reg  op_b$20$clock;
    reg  [23:0] op_b$21$d;
    wire  [23:0] op_b$21$q;
    reg  op_b$21$clock;
    reg  [23:0] op_b$22$d;
    wire  [23:0] op_b$22$q;
    reg  op_b$22$clock;
    reg  [23:0] op_b$23$d;
    wire  [23:0] op_b$23$q;
    reg  op_b$23$clock;
    reg  op_sub$0$d;
    wire  op_sub$0$q;
    reg  op_sub$0$clock;
    reg  op_sub$1$d;
    wire  op_sub$1$q;
    reg  op_sub$1$clock;
    reg  op_sub$2$d;
    wire  op_sub$2$q;
    reg  op_sub$2$clock;
    reg  op_sub$3$d;
    wire  op_sub$3$q;
    reg  op_sub$3$clock;
    reg  op_sub$4$d;
    wire  op_sub$4$q;
    reg  op_sub$4$clock;
    reg  op_sub$5$d;
    wire  op_sub$5$q;
    reg  op_sub$5$clock;
    reg  op_sub$6$d;
    wire  op_sub$6$q;
    reg  op_sub$6$clock;
    reg  op_sub$7$d;
    wire  op_sub$7$q;
    reg  op_sub$7$clock;
    reg  op_sub$8$d;
    wire  op_sub$8$q;
    reg  op_sub$8$clock;
    reg  op_sub$9$d;
    wire  op_sub$9$q;
    reg  op_sub$9$clock;
    reg  op_sub$10$d;
    wire  op_sub$10$q;
    reg  op_sub$10$clock;
    reg  op_sub$11$d;
    wire  op_sub$11$q;
    reg  op_sub$11$clock;
    reg  op_sub$12$d;
    wire  op_sub$12$q;
    reg  op_sub$12$clock;
    reg  op_sel$0$d;
    wire  op_sel$0$q;
    reg  op_sel$0$clock;
    reg  op_sel$1$d;
    wire  op_sel$1$q;
    reg  op_sel$1$clock;
    reg  op_sel$2$d;
    wire  op_sel$2$q;
    reg  op_sel$2$clock;
    reg  mul_v$0$clock;
    reg  [23:0] mul_v$0$a;
    reg  [23:0] mul_v$0$b;
    reg  mul_v$0$valid_in;
    wire  [23:0] mul_v$0$y;
    wire  mul_v$0$valid_out;
    reg  mul_v$1$clock;
    reg  [23:0] mul_v$1$a;
    reg  [23:0] mul_v$1$b;
    reg  mul_v$1$valid_in;
    wire  [23:0] mul_v$1$y;
    wire  mul_v$1$valid_out;
    reg  mul_v$2$clock;
    reg  [23:0] mul_v$2$a;
    reg  [23:0] mul_v$2$b;
    reg  mul_v$2$valid_in;
    wire  [23:0] mul_v$2$y;
    wire  mul_v$2$valid_out;
    reg  mul_v$3$clock;
    reg  [23:0] mul_v$3$a;
    reg  [23:0] mul_v$3$b;
    reg  mul_v$3$valid_in;
    wire  [23:0] mul_v$3$y;
    wire  mul_v$3$valid_out;
    reg  mul_v$4$clock;
    reg  [23:0] mul_v$4$a;
    reg  [23:0] mul_v$4$b;
    reg  mul_v$4$valid_in;
    wire  [23:0] mul_v$4$y;
    wire  mul_v$4$valid_out;
    reg  mul_up$0$clock;
    reg  [23:0] mul_up$0$a;
    reg  [23:0] mul_up$0$b;
    reg  mul_up$0$valid_in;
    wire  [23:0] mul_up$0$y;
    wire  mul_up$0$valid_out;
    reg  mul_up$1$clock;
    reg  [23:0] mul_up$1$a;
    reg  [23:0] mul_up$1$b;
    reg  mul_up$1$valid_in;
    wire  [23:0] mul_up$1$y;
    wire  mul_up$1$valid_out;
    reg  mul_up$2$clock;
    reg  [23:0] mul_up$2$a;
    reg  [23:0] mul_up$2$b;
    reg  mul_up$2$valid_in;
    wire  [23:0] mul_up$2$y;
    wire  mul_up$2$valid_out;
    reg  mul_up$3$clock;
    reg  [23:0] mul_up$3$a;
    reg  [23:0] mul_up$3$b;
    reg  mul_up$3$valid_in;
    wire  [23:0] mul_up$3$y;
    wire  mul_up$3$valid_out;
    reg  mul_up$4$clock;
    reg  [23:0] mul_up$4$a;
    reg  [23:0] mul_up$4$b;
    reg  mul_up$4$valid_in;
    wire  [23:0] mul_up$4$y;
    wire  mul_up$4$valid_out;
    reg  mul_up$5$clock;
    reg  [23:0] mul_up$5$a;
    reg  [23:0] mul_up$5$b;
    reg  mul_up$5$valid_in;
    wire  [23:0] mul_up$5$y;
    wire  mul_up$5$valid_out;
    reg  add_v$0$clock;
    reg  [23:0] add_v$0$a;
    reg  [23:0] add_v$0$b;
    reg  add_v$0$sub;
    reg  add_v$0$valid_in;
    wire  [23:0] add_v$0$y;
    wire  add_v$0$valid_out;
    reg  add_v$1$clock;
    reg  [23:0] add_v$1$a;
    reg  [23:0] add_v$1$b;
    reg  add_v$1$sub;
    reg  add_v$1$valid_in;
    wire  [23:0] add_v$1$y;
    wire  add_v$1$valid_out;
    reg  add_v$2$clock;
    reg  [23:0] add_v$2$a;
    reg  [23:0] add_v$2$b;
    reg  add_v$2$sub;
    reg  add_v$2$valid_in;
    wire  [23:0] add_v$2$y;
    wire  add_v$2$valid_out;
    reg  add_v$3$clock;
    reg  [23:0] add_v$3$a;
    reg  [23:0] add_v$3$b;
    reg  add_v$3$sub;
    reg  add_v$3$valid_in;
    wire  [23:0] add_v$3$y;
    wire  add_v$3$valid_out;
    reg  add_v$4$clock;
    reg  [23:0] add_v$4$a;
    reg  [23:0] add_v$4$b;
    reg  add_v$4$sub;
    reg  add_v$4$valid_in;
    wire  [23:0] add_v$4$y;
    wire  add_v$4$valid_out;
    reg  add_up$0$clock;
    reg  [23:0] add_up$0$a;
    reg  [23:0] add_up$0$b;
    reg  add_up$0$sub;
    reg  add_up$0$valid_in;
    wire  [23:0] add_up$0$y;
    wire  add_up$0$valid_out;
    reg  add_up$1$clock;
    reg  [23:0] add_up$1$a;
    reg  [23:0] add_up$1$b;
    reg  add_up$1$sub;
    reg  add_up$1$valid_in;
    wire  [23:0] add_up$1$y;
    wire  add_up$1$valid_out;
    reg  add_up$2$clock;
    reg  [23:0] add_up$2$a;
    reg  [23:0] add_up$2$b;
    reg  add_up$2$sub;
    reg  add_up$2$valid_in;
    wire  [23:0] add_up$2$y;
    wire  add_up$2$valid_out;
    reg  add_up$3$clock;
    reg  [23:0] add_up$3$a;
    reg  [23:0] add_up$3$b;
    reg  add_up$3$sub;
    reg  add_up$3$valid_in;
    wire  [23:0] add_up$3$y;
    wire  add_up$3$valid_out;
    reg  add_up$4$clock;
    reg  [23:0] add_up$4$a;
    reg  [23:0] add_up$4$b;
    reg  add_up$4$sub;
    reg  add_up$4$valid_in;
    wire  [23:0] add_up$4$y;
    wire  add_up$4$valid_out;
    reg  add_up$5$clock;
    reg  [23:0] add_up$5$a;
    reg  [23:0] add_up$5$b;
    reg  add_up$5$sub;
    reg  add_up$5$valid_in;
    wire  [23:0] add_up$5$y;
    wire  add_up$5$valid_out;
    reg  add_up$6$clock;
    reg  [23:0] add_up$6$a;
    reg  [23:0] add_up$6$b;
    reg  add_up$6$sub;
    reg  add_up$6$valid_in;
    wire  [23:0] add_up$6$y;
    wire  add_up$6$valid_out;
    reg  add_up$7$clock;
    reg  [23:0] add_up$7$a;
    reg  [23:0] add_up$7$b;
    reg  add_up$7$sub;
    reg  add_up$7$valid_in;
    wire  [23:0] add_up$7$y;
    wire  add_up$7$valid_out;
    reg  scale_e$0$clock;
    reg  [23:0] scale_e$0$a;
    reg  scale_e$0$sel;
    wire  [23:0] scale_e$0$y;
    reg  scale_z$0$clock;
    reg  [23:0] scale_z$0$a;
    reg  scale_z$0$sel;
    wire  [23:0] scale_z$0$y;
    reg  scale_s$0$clock;
    reg  [23:0] scale_s$0$a;
    reg  scale_s$0$sel;
    wire  [23:0] scale_s$0$y;
    reg  [23:0] signs$0$x;
    reg  [23:0] signs$0$e;
    wire  [1:0] signs$0$sgn;
    reg  [23:0] signs$1$x;
    reg  [23:0] signs$1$e;
    wire  [1:0] signs$1$sgn;
    reg  [23:0] signs$2$x;
    reg  [23:0] signs$2$e;
    wire  [1:0] signs$2$sgn;
    reg  [23:0] signs$3$x;
    reg  [23:0] signs$3$e;
    wire  [1:0] signs$3$sgn;
    reg  [23:0] signs$4$x;
    reg  [23:0] signs$4$e;
    wire  [1:0] signs$4$sgn;
    reg  [23:0] signs$5$x;
    reg  [23:0] signs$5$e;
    wire  [1:0] signs$5$sgn;
    reg  [23:0] signs$6$x;
    reg  [23:0] signs$6$e;
    wire  [1:0] signs$6$sgn;
    reg  [23:0] signs$7$x;
    reg  [23:0] signs$7$e;
    wire  [1:0] signs$7$sgn;
    reg  [23:0] signs$8$x;
    reg  [23:0] signs$8$e;
    wire  [1:0] signs$8$sgn;
    reg  [23:0] signs$9$x;
    reg  [23:0] signs$9$e;
    wire  [1:0] signs$9$sgn;
    reg  [23:0] signs$10$x;
    reg  [23:0] signs$10$e;
    wire  [1:0] signs$10$sgn;
    reg  [23:0] signs$11$x;
    reg  [23:0] signs$11$e;
    wire  [1:0] signs$11$sgn;
    reg  [23:0] signs$12$x;
    reg  [23:0] signs$12$e;
    wire  [1:0] signs$12$sgn;
    reg  [23:0] signs$13$x;
    reg  [23:0] signs$13$e;
    wire  [1:0] signs$13$sgn;
    reg  [23:0] signs$14$x;
    reg  [23:0] signs$14$e;
    wire  [1:0] signs$14$sgn;
    reg  [23:0] signs$15$x;
    reg  [23:0] signs$15$e;
    wire  [1:0] signs$15$sgn;
    reg  [23:0] signs$16$x;
    reg  [23:0] signs$16$e;
    wire  [1:0] signs$16$sgn;
    reg  [23:0] signs$17$x;
    reg  [23:0] signs$17$e;
    wire  [1:0] signs$17$sgn;
    reg  [23:0] out_s_x$0$d;
    wire  [23:0] out_s_x$0$q;
    reg  out_s_x$0$clock;
    reg  [23:0] out_s_x$1$d;
    wire  [23:0] out_s_x$1$q;
    reg  out_s_x$1$clock;
    reg  [23:0] out_s_x$2$d;
    wire  [23:0] out_s_x$2$q;
    reg  out_s_x$2$clock;
    reg  [23:0] out_s_b$0$d;
    wire  [23:0] out_s_b$0$q;
    reg  out_s_b$0$clock;
    reg  [23:0] out_s_b$1$d;
    wire  [23:0] out_s_b$1$q;
    reg  out_s_b$1$clock;
    reg  [23:0] out_s_b$2$d;
    wire  [23:0] out_s_b$2$q;
    reg  out_s_b$2$clock;
    reg  out_cross_t$0$d;
    wire  out_cross_t$0$q;
    reg  out_cross_t$0$clock;
    reg  out_cross_t$1$d;
    wire  out_cross_t$1$q;
    reg  out_cross_t$1$clock;
    reg  out_cross_t$2$d;
    wire  out_cross_t$2$q;
    reg  out_cross_t$2$clock;
    reg  out_cross_f$0$d;
    wire  out_cross_f$0$q;
    reg  out_cross_f$0$clock;
    reg  out_cross_f$1$d;
    wire  out_cross_f$1$q;
    reg  out_cross_f$1$clock;
    reg  out_cross_f$2$d;
    wire  out_cross_f$2$q;
    reg  out_cross_f$2$clock;
    reg  out_hit$d;
    wire  out_hit$q;
    reg  out_hit$clock;
    reg  out_miss$d;
    wire  out_miss$q;
    reg  out_miss$clock;
    reg  [31:0] out_tag$d;
    wire  [31:0] out_tag$q;
    reg  out_tag$clock;
    reg  out_valid$d;
    wire  out_valid$q;
    reg  out_valid$clock;
    
    // Sub module instances
    top$a_deg run(
        .d(run$d),
        .q(run$q),
        .clock(run$clock)
    );
    top$counter counter(
        .d(counter$d),
        .q(counter$q),
        .clock(counter$clock)
    );
    top$tc$regs$0 regs$0(
        .d(regs$0$d),
        .q(regs$0$q),
        .clock(regs$0$clock)
    );
    top$tc$regs$0 regs$1(
        .d(regs$1$d),
        .q(regs$1$q),
        .clock(regs$1$clock)
    );
    top$tc$regs$0 regs$2(
        .d(regs$2$d),
        .q(regs$2$q),
        .clock(regs$2$clock)
    );
    top$tc$regs$0 regs$3(
        .d(regs$3$d),
        .q(regs$3$q),
        .clock(regs$3$clock)
    );
    top$tc$regs$0 regs$4(
        .d(regs$4$d),
        .q(regs$4$q),
        .clock(regs$4$clock)
    );
    top$tc$regs$0 regs$5(
        .d(regs$5$d),
        .q(regs$5$q),
        .clock(regs$5$clock)
    );
    top$tc$regs$0 regs$6(
        .d(regs$6$d),
        .q(regs$6$q),
        .clock(regs$6$clock)
    );
    top$tc$regs$0 regs$7(
        .d(regs$7$d),
        .q(regs$7$q),
        .clock(regs$7$clock)
    );
    top$tc$regs$0 regs$8(
        .d(regs$8$d),
        .q(regs$8$q),
        .clock(regs$8$clock)
    );
    top$tc$regs$0 regs$9(
        .d(regs$9$d),
        .q(regs$9$q),
        .clock(regs$9$clock)
    );
    top$tc$regs$0 regs$10(
        .d(regs$10$d),
        .q(regs$10$q),
        .clock(regs$10$clock)
    );
    top$tc$regs$0 regs$11(
        .d(regs$11$d),
        .q(regs$11$q),
        .clock(regs$11$clock)
    );
    top$tc$regs$0 regs$12(
        .d(regs$12$d),
        .q(regs$12$q),
        .clock(regs$12$clock)
    );
    top$tc$regs$0 regs$13(
        .d(regs$13$d),
        .q(regs$13$q),
        .clock(regs$13$clock)
    );
    top$tc$regs$0 regs$14(
        .d(regs$14$d),
        .q(regs$14$q),
        .clock(regs$14$clock)
    );
    top$tc$regs$0 regs$15(
        .d(regs$15$d),
        .q(regs$15$q),
        .clock(regs$15$clock)
    );
    top$tc$regs$0 regs$16(
        .d(regs$16$d),
        .q(regs$16$q),
        .clock(regs$16$clock)
    );
    top$tc$regs$0 regs$17(
        .d(regs$17$d),
        .q(regs$17$q),
        .clock(regs$17$clock)
    );
    top$tc$regs$0 regs$18(
        .d(regs$18$d),
        .q(regs$18$q),
        .clock(regs$18$clock)
    );
    top$tc$regs$0 regs$19(
        .d(regs$19$d),
        .q(regs$19$q),
        .clock(regs$19$clock)
    );
    top$tc$regs$0 regs$20(
        .d(regs$20$d),
        .q(regs$20$q),
        .clock(regs$20$clock)
    );
    top$tc$regs$0 regs$21(
        .d(regs$21$d),
        .q(regs$21$q),
        .clock(regs$21$clock)
    );
    top$tc$regs$0 regs$22(
        .d(regs$22$d),
        .q(regs$22$q),
        .clock(regs$22$clock)
    );
    top$tc$regs$0 regs$23(
        .d(regs$23$d),
        .q(regs$23$q),
        .clock(regs$23$clock)
    );
    top$tc$regs$0 regs$24(
        .d(regs$24$d),
        .q(regs$24$q),
        .clock(regs$24$clock)
    );
    top$tc$regs$0 regs$25(
        .d(regs$25$d),
        .q(regs$25$q),
        .clock(regs$25$clock)
    );
    top$tc$regs$0 regs$26(
        .d(regs$26$d),
        .q(regs$26$q),
        .clock(regs$26$clock)
    );
    top$tc$regs$0 regs$27(
        .d(regs$27$d),
        .q(regs$27$q),
        .clock(regs$27$clock)
    );
    top$tc$regs$0 regs$28(
        .d(regs$28$d),
        .q(regs$28$q),
        .clock(regs$28$clock)
    );
    top$tc$regs$0 regs$29(
        .d(regs$29$d),
        .q(regs$29$q),
        .clock(regs$29$clock)
    );
    top$tc$regs$0 regs$30(
        .d(regs$30$d),
        .q(regs$30$q),
        .clock(regs$30$clock)
    );
    top$tc$regs$0 regs$31(
        .d(regs$31$d),
        .q(regs$31$q),
        .clock(regs$31$clock)
    );
    top$tc$regs$0 regs$32(
        .d(regs$32$d),
        .q(regs$32$q),
        .clock(regs$32$clock)
    );
    top$tc$regs$0 regs$33(
        .d(regs$33$d),
        .q(regs$33$q),
        .clock(regs$33$clock)
    );
    top$tc$regs$0 regs$34(
        .d(regs$34$d),
        .q(regs$34$q),
        .clock(regs$34$clock)
    );
    top$tc$regs$0 regs$35(
        .d(regs$35$d),
        .q(regs$35$q),
        .clock(regs$35$clock)
    );
    top$tc$regs$0 regs$36(
        .d(regs$36$d),
        .q(regs$36$q),
        .clock(regs$36$clock)
    );
    top$tc$regs$0 regs$37(
        .d(regs$37$d),
        .q(regs$37$q),
        .clock(regs$37$clock)
    );
    top$tc$regs$0 regs$38(
        .d(regs$38$d),
        .q(regs$38$q),
        .clock(regs$38$clock)
    );
    top$tc$regs$0 regs$39(
        .d(regs$39$d),
        .q(regs$39$q),
        .clock(regs$39$clock)
    );
    top$tc$regs$0 regs$40(
        .d(regs$40$d),
        .q(regs$40$q),
        .clock(regs$40$clock)
    );
    top$tc$regs$0 regs$41(
        .d(regs$41$d),
        .q(regs$41$q),
        .clock(regs$41$clock)
    );
    top$tc$regs$0 regs$42(
        .d(regs$42$d),
        .q(regs$42$q),
        .clock(regs$42$clock)
    );
    top$tc$regs$0 regs$43(
        .d(regs$43$d),
        .q(regs$43$q),
        .clock(regs$43$clock)
    );
    top$tc$regs$0 regs$44(
        .d(regs$44$d),
        .q(regs$44$q),
        .clock(regs$44$clock)
    );
    top$tc$regs$0 regs$45(
        .d(regs$45$d),
        .q(regs$45$q),
        .clock(regs$45$clock)
    );
    top$tc$regs$0 regs$46(
        .d(regs$46$d),
        .q(regs$46$q),
        .clock(regs$46$clock)
    );
    top$tc$regs$0 regs$47(
        .d(regs$47$d),
        .q(regs$47$q),
        .clock(regs$47$clock)
    );
    top$tc$regs$0 regs$48(
        .d(regs$48$d),
        .q(regs$48$q),
        .clock(regs$48$clock)
    );
    top$tc$regs$0 regs$49(
        .d(regs$49$d),
        .q(regs$49$q),
        .clock(regs$49$clock)
    );
    top$tc$regs$0 regs$50(
        .d(regs$50$d),
        .q(regs$50$q),
        .clock(regs$50$clock)
    );
    top$tc$regs$0 regs$51(
        .d(regs$51$d),
        .q(regs$51$q),
        .clock(regs$51$clock)
    );
    top$tc$regs$0 regs$52(
        .d(regs$52$d),
        .q(regs$52$q),
        .clock(regs$52$clock)
    );
    top$tc$regs$0 regs$53(
        .d(regs$53$d),
        .q(regs$53$q),
        .clock(regs$53$clock)
    );
    top$tc$regs$0 regs$54(
        .d(regs$54$d),
        .q(regs$54$q),
        .clock(regs$54$clock)
    );
    top$tc$regs$0 regs$55(
        .d(regs$55$d),
        .q(regs$55$q),
        .clock(regs$55$clock)
    );
    top$tc$regs$0 regs$56(
        .d(regs$56$d),
        .q(regs$56$q),
        .clock(regs$56$clock)
    );
    top$tc$regs$0 regs$57(
        .d(regs$57$d),
        .q(regs$57$q),
        .clock(regs$57$clock)
    );
    top$tc$regs$0 regs$58(
        .d(regs$58$d),
        .q(regs$58$q),
        .clock(regs$58$clock)
    );
    top$tc$regs$0 regs$59(
        .d(regs$59$d),
        .q(regs$59$q),
        .clock(regs$59$clock)
    );
    top$tc$regs$0 regs$60(
        .d(regs$60$d),
        .q(regs$60$q),
        .clock(regs$60$clock)
    );
    top$tc$regs$0 regs$61(
        .d(regs$61$d),
        .q(regs$61$q),
        .clock(regs$61$clock)
    );
    top$tc$regs$0 regs$62(
        .d(regs$62$d),
        .q(regs$62$q),
        .clock(regs$62$clock)
    );
    top$tc$regs$0 regs$63(
        .d(regs$63$d),
        .q(regs$63$q),
        .clock(regs$63$clock)
    );
    top$tc$regs$0 regs$64(
        .d(regs$64$d),
        .q(regs$64$q),
        .clock(regs$64$clock)
    );
    top$tc$regs$0 regs$65(
        .d(regs$65$d),
        .q(regs$65$q),
        .clock(regs$65$clock)
    );
    top$tc$regs$0 regs$66(
        .d(regs$66$d),
        .q(regs$66$q),
        .clock(regs$66$clock)
    );
    top$tc$regs$0 regs$67(
        .d(regs$67$d),
        .q(regs$67$q),
        .clock(regs$67$clock)
    );
    top$tc$regs$0 regs$68(
        .d(regs$68$d),
        .q(regs$68$q),
        .clock(regs$68$clock)
    );
    top$tc$regs$0 regs$69(
        .d(regs$69$d),
        .q(regs$69$q),
        .clock(regs$69$clock)
    );
    top$tc$regs$0 regs$70(
        .d(regs$70$d),
        .q(regs$70$q),
        .clock(regs$70$clock)
    );
    top$tc$regs$0 regs$71(
        .d(regs$71$d),
        .q(regs$71$q),
        .clock(regs$71$clock)
    );
    top$tc$regs$0 regs$72(
        .d(regs$72$d),
        .q(regs$72$q),
        .clock(regs$72$clock)
    );
    top$tc$regs$0 regs$73(
        .d(regs$73$d),
        .q(regs$73$q),
        .clock(regs$73$clock)
    );
    top$tc$regs$0 regs$74(
        .d(regs$74$d),
        .q(regs$74$q),
        .clock(regs$74$clock)
    );
    top$tc$regs$0 regs$75(
        .d(regs$75$d),
        .q(regs$75$q),
        .clock(regs$75$clock)
    );
    top$tc$regs$0 regs$76(
        .d(regs$76$d),
        .q(regs$76$q),
        .clock(regs$76$clock)
    );
    top$tc$regs$0 regs$77(
        .d(regs$77$d),
        .q(regs$77$q),
        .clock(regs$77$clock)
    );
    top$tc$regs$0 regs$78(
        .d(regs$78$d),
        .q(regs$78$q),
        .clock(regs$78$clock)
    );
    top$tc$regs$0 regs$79(
        .d(regs$79$d),
        .q(regs$79$q),
        .clock(regs$79$clock)
    );
    top$tc$regs$0 regs$80(
        .d(regs$80$d),
        .q(regs$80$q),
        .clock(regs$80$clock)
    );
    top$tc$regs$0 regs$81(
        .d(regs$81$d),
        .q(regs$81$q),
        .clock(regs$81$clock)
    );
    top$tc$regs$0 regs$82(
        .d(regs$82$d),
        .q(regs$82$q),
        .clock(regs$82$clock)
    );
    top$tc$regs$0 regs$83(
        .d(regs$83$d),
        .q(regs$83$q),
        .clock(regs$83$clock)
    );
    top$tc$regs$0 regs$84(
        .d(regs$84$d),
        .q(regs$84$q),
        .clock(regs$84$clock)
    );
    top$tc$regs$0 regs$85(
        .d(regs$85$d),
        .q(regs$85$q),
        .clock(regs$85$clock)
    );
    top$tc$regs$0 regs$86(
        .d(regs$86$d),
        .q(regs$86$q),
        .clock(regs$86$clock)
    );
    top$tc$regs$0 regs$87(
        .d(regs$87$d),
        .q(regs$87$q),
        .clock(regs$87$clock)
    );
    top$tc$regs$0 regs$88(
        .d(regs$88$d),
        .q(regs$88$q),
        .clock(regs$88$clock)
    );
    top$tc$regs$0 regs$89(
        .d(regs$89$d),
        .q(regs$89$q),
        .clock(regs$89$clock)
    );
    top$tc$regs$0 regs$90(
        .d(regs$90$d),
        .q(regs$90$q),
        .clock(regs$90$clock)
    );
    top$tc$regs$0 regs$91(
        .d(regs$91$d),
        .q(regs$91$q),
        .clock(regs$91$clock)
    );
    top$tc$regs$0 regs$92(
        .d(regs$92$d),
        .q(regs$92$q),
        .clock(regs$92$clock)
    );
    top$tc$regs$0 regs$93(
        .d(regs$93$d),
        .q(regs$93$q),
        .clock(regs$93$clock)
    );
    top$tc$regs$0 regs$94(
        .d(regs$94$d),
        .q(regs$94$q),
        .clock(regs$94$clock)
    );
    top$tc$regs$0 regs$95(
        .d(regs$95$d),
        .q(regs$95$q),
        .clock(regs$95$clock)
    );
    top$tc$regs$0 regs$96(
        .d(regs$96$d),
        .q(regs$96$q),
        .clock(regs$96$clock)
    );
    top$tc$regs$0 regs$97(
        .d(regs$97$d),
        .q(regs$97$q),
        .clock(regs$97$clock)
    );
    top$tc$regs$0 regs$98(
        .d(regs$98$d),
        .q(regs$98$q),
        .clock(regs$98$clock)
    );
    top$tc$regs$0 regs$99(
        .d(regs$99$d),
        .q(regs$99$q),
        .clock(regs$99$clock)
    );
    top$tc$regs$0 regs$100(
        .d(regs$100$d),
        .q(regs$100$q),
        .clock(regs$100$clock)
    );
    top$tc$regs$0 regs$101(
        .d(regs$101$d),
        .q(regs$101$q),
        .clock(regs$101$clock)
    );
    top$tc$regs$0 regs$102(
        .d(regs$102$d),
        .q(regs$102$q),
        .clock(regs$102$clock)
    );
    top$tc$regs$0 regs$103(
        .d(regs$103$d),
        .q(regs$103$q),
        .clock(regs$103$clock)
    );
    top$tc$regs$0 regs$104(
        .d(regs$104$d),
        .q(regs$104$q),
        .clock(regs$104$clock)
    );
    top$tc$regs$0 regs$105(
        .d(regs$105$d),
        .q(regs$105$q),
        .clock(regs$105$clock)
    );
    top$tc$regs$0 regs$106(
        .d(regs$106$d),
        .q(regs$106$q),
        .clock(regs$106$clock)
    );
    top$tc$regs$0 regs$107(
        .d(regs$107$d),
        .q(regs$107$q),
        .clock(regs$107$clock)
    );
    top$tc$regs$0 regs$108(
        .d(regs$108$d),
        .q(regs$108$q),
        .clock(regs$108$clock)
    );
    top$tc$regs$0 regs$109(
        .d(regs$109$d),
        .q(regs$109$q),
        .clock(regs$109$clock)
    );
    top$tc$regs$0 regs$110(
        .d(regs$110$d),
        .q(regs$110$q),
        .clock(regs$110$clock)
    );
    top$tc$regs$0 regs$111(
        .d(regs$111$d),
        .q(regs$111$q),
        .clock(regs$111$clock)
    );
    top$tc$regs$0 regs$112(
        .d(regs$112$d),
        .q(regs$112$q),
        .clock(regs$112$clock)
    );
    top$tc$regs$0 regs$113(
        .d(regs$113$d),
        .q(regs$113$q),
        .clock(regs$113$clock)
    );
    top$tc$regs$0 regs$114(
        .d(regs$114$d),
        .q(regs$114$q),
        .clock(regs$114$clock)
    );
    top$tc$regs$0 regs$115(
        .d(regs$115$d),
        .q(regs$115$q),
        .clock(regs$115$clock)
    );
    top$tc$regs$0 regs$116(
        .d(regs$116$d),
        .q(regs$116$q),
        .clock(regs$116$clock)
    );
    top$tc$regs$0 regs$117(
        .d(regs$117$d),
        .q(regs$117$q),
        .clock(regs$117$clock)
    );
    top$tc$regs$0 regs$118(
        .d(regs$118$d),
        .q(regs$118$q),
        .clock(regs$118$clock)
    );
    top$tc$regs$0 regs$119(
        .d(regs$119$d),
        .q(regs$119$q),
        .clock(regs$119$clock)
    );
    top$tc$regs$0 regs$120(
        .d(regs$120$d),
        .q(regs$120$q),
        .clock(regs$120$clock)
    );
    top$tc$regs$0 regs$121(
        .d(regs$121$d),
        .q(regs$121$q),
        .clock(regs$121$clock)
    );
    top$tc$regs$0 regs$122(
        .d(regs$122$d),
        .q(regs$122$q),
        .clock(regs$122$clock)
    );
    top$tc$regs$0 regs$123(
        .d(regs$123$d),
        .q(regs$123$q),
        .clock(regs$123$clock)
    );
    top$tc$regs$0 regs$124(
        .d(regs$124$d),
        .q(regs$124$q),
        .clock(regs$124$clock)
    );
    top$tc$regs$0 regs$125(
        .d(regs$125$d),
        .q(regs$125$q),
        .clock(regs$125$clock)
    );
    top$tc$regs$0 regs$126(
        .d(regs$126$d),
        .q(regs$126$q),
        .clock(regs$126$clock)
    );
    top$tc$regs$0 regs$127(
        .d(regs$127$d),
        .q(regs$127$q),
        .clock(regs$127$clock)
    );
    top$tc$regs$0 regs$128(
        .d(regs$128$d),
        .q(regs$128$q),
        .clock(regs$128$clock)
    );
    top$tc$regs$0 regs$129(
        .d(regs$129$d),
        .q(regs$129$q),
        .clock(regs$129$clock)
    );
    top$tc$regs$0 regs$130(
        .d(regs$130$d),
        .q(regs$130$q),
        .clock(regs$130$clock)
    );
    top$tc$regs$0 regs$131(
        .d(regs$131$d),
        .q(regs$131$q),
        .clock(regs$131$clock)
    );
    top$tc$regs$0 regs$132(
        .d(regs$132$d),
        .q(regs$132$q),
        .clock(regs$132$clock)
    );
    top$tc$regs$0 regs$133(
        .d(regs$133$d),
        .q(regs$133$q),
        .clock(regs$133$clock)
    );
    top$tc$regs$0 regs$134(
        .d(regs$134$d),
        .q(regs$134$q),
        .clock(regs$134$clock)
    );
    top$tc$regs$0 regs$135(
        .d(regs$135$d),
        .q(regs$135$q),
        .clock(regs$135$clock)
    );
    top$tc$regs$0 regs$136(
        .d(regs$136$d),
        .q(regs$136$q),
        .clock(regs$136$clock)
    );
    top$tc$regs$0 regs$137(
        .d(regs$137$d),
        .q(regs$137$q),
        .clock(regs$137$clock)
    );
    top$tc$regs$0 regs$138(
        .d(regs$138$d),
        .q(regs$138$q),
        .clock(regs$138$clock)
    );
    top$tc$regs$0 regs$139(
        .d(regs$139$d),
        .q(regs$139$q),
        .clock(regs$139$clock)
    );
    top$tc$regs$0 regs$140(
        .d(regs$140$d),
        .q(regs$140$q),
        .clock(regs$140$clock)
    );
    top$tc$regs$0 regs$141(
        .d(regs$141$d),
        .q(regs$141$q),
        .clock(regs$141$clock)
    );
    top$tc$regs$0 regs$142(
        .d(regs$142$d),
        .q(regs$142$q),
        .clock(regs$142$clock)
    );
    top$tc$regs$0 regs$143(
        .d(regs$143$d),
        .q(regs$143$q),
        .clock(regs$143$clock)
    );
    top$tc$regs$0 regs$144(
        .d(regs$144$d),
        .q(regs$144$q),
        .clock(regs$144$clock)
    );
    top$tc$regs$0 regs$145(
        .d(regs$145$d),
        .q(regs$145$q),
        .clock(regs$145$clock)
    );
    top$tc$regs$0 regs$146(
        .d(regs$146$d),
        .q(regs$146$q),
        .clock(regs$146$clock)
    );
    top$tc$regs$0 regs$147(
        .d(regs$147$d),
        .q(regs$147$q),
        .clock(regs$147$clock)
    );
    top$tc$regs$0 regs$148(
        .d(regs$148$d),
        .q(regs$148$q),
        .clock(regs$148$clock)
    );
    top$tc$regs$0 regs$149(
        .d(regs$149$d),
        .q(regs$149$q),
        .clock(regs$149$clock)
    );
    top$tc$regs$0 regs$150(
        .d(regs$150$d),
        .q(regs$150$q),
        .clock(regs$150$clock)
    );
    top$tc$regs$0 regs$151(
        .d(regs$151$d),
        .q(regs$151$q),
        .clock(regs$151$clock)
    );
    top$tc$regs$0 regs$152(
        .d(regs$152$d),
        .q(regs$152$q),
        .clock(regs$152$clock)
    );
    top$tc$regs$0 regs$153(
        .d(regs$153$d),
        .q(regs$153$q),
        .clock(regs$153$clock)
    );
    top$tc$regs$0 regs$154(
        .d(regs$154$d),
        .q(regs$154$q),
        .clock(regs$154$clock)
    );
    top$tc$regs$0 regs$155(
        .d(regs$155$d),
        .q(regs$155$q),
        .clock(regs$155$clock)
    );
    top$tc$regs$0 regs$156(
        .d(regs$156$d),
        .q(regs$156$q),
        .clock(regs$156$clock)
    );
    top$tc$regs$0 regs$157(
        .d(regs$157$d),
        .q(regs$157$q),
        .clock(regs$157$clock)
    );
    top$tc$regs$0 regs$158(
        .d(regs$158$d),
        .q(regs$158$q),
        .clock(regs$158$clock)
    );
    top$tc$regs$0 regs$159(
        .d(regs$159$d),
        .q(regs$159$q),
        .clock(regs$159$clock)
    );
    top$tc$regs$0 regs$160(
        .d(regs$160$d),
        .q(regs$160$q),
        .clock(regs$160$clock)
    );
    top$tc$regs$0 regs$161(
        .d(regs$161$d),
        .q(regs$161$q),
        .clock(regs$161$clock)
    );
    top$tc$regs$0 regs$162(
        .d(regs$162$d),
        .q(regs$162$q),
        .clock(regs$162$clock)
    );
    top$tc$regs$0 regs$163(
        .d(regs$163$d),
        .q(regs$163$q),
        .clock(regs$163$clock)
    );
    top$tc$regs$0 regs$164(
        .d(regs$164$d),
        .q(regs$164$q),
        .clock(regs$164$clock)
    );
    top$tc$regs$0 regs$165(
        .d(regs$165$d),
        .q(regs$165$q),
        .clock(regs$165$clock)
    );
    top$tc$regs$0 regs$166(
        .d(regs$166$d),
        .q(regs$166$q),
        .clock(regs$166$clock)
    );
    top$tc$regs$0 regs$167(
        .d(regs$167$d),
        .q(regs$167$q),
        .clock(regs$167$clock)
    );
    top$tc$regs$0 regs$168(
        .d(regs$168$d),
        .q(regs$168$q),
        .clock(regs$168$clock)
    );
    top$tc$regs$0 regs$169(
        .d(regs$169$d),
        .q(regs$169$q),
        .clock(regs$169$clock)
    );
    top$tc$regs$0 regs$170(
        .d(regs$170$d),
        .q(regs$170$q),
        .clock(regs$170$clock)
    );
    top$tc$regs$0 regs$171(
        .d(regs$171$d),
        .q(regs$171$q),
        .clock(regs$171$clock)
    );
    top$tc$regs$0 regs$172(
        .d(regs$172$d),
        .q(regs$172$q),
        .clock(regs$172$clock)
    );
    top$tc$regs$0 regs$173(
        .d(regs$173$d),
        .q(regs$173$q),
        .clock(regs$173$clock)
    );
    top$tc$regs$0 regs$174(
        .d(regs$174$d),
        .q(regs$174$q),
        .clock(regs$174$clock)
    );
    top$tc$regs$0 regs$175(
        .d(regs$175$d),
        .q(regs$175$q),
        .clock(regs$175$clock)
    );
    top$tc$regs$0 regs$176(
        .d(regs$176$d),
        .q(regs$176$q),
        .clock(regs$176$clock)
    );
    top$tc$regs$0 regs$177(
        .d(regs$177$d),
        .q(regs$177$q),
        .clock(regs$177$clock)
    );
    top$tc$regs$0 regs$178(
        .d(regs$178$d),
        .q(regs$178$q),
        .clock(regs$178$clock)
    );
    top$tc$regs$0 regs$179(
        .d(regs$179$d),
        .q(regs$179$q),
        .clock(regs$179$clock)
    );
    top$tc$regs$0 regs$180(
        .d(regs$180$d),
        .q(regs$180$q),
        .clock(regs$180$clock)
    );
    top$tc$regs$0 regs$181(
        .d(regs$181$d),
        .q(regs$181$q),
        .clock(regs$181$clock)
    );
    top$tc$regs$0 regs$182(
        .d(regs$182$d),
        .q(regs$182$q),
        .clock(regs$182$clock)
    );
    top$tc$regs$0 regs$183(
        .d(regs$183$d),
        .q(regs$183$q),
        .clock(regs$183$clock)
    );
    top$tc$regs$0 regs$184(
        .d(regs$184$d),
        .q(regs$184$q),
        .clock(regs$184$clock)
    );
    top$tc$regs$0 regs$185(
        .d(regs$185$d),
        .q(regs$185$q),
        .clock(regs$185$clock)
    );
    top$tc$regs$0 regs$186(
        .d(regs$186$d),
        .q(regs$186$q),
        .clock(regs$186$clock)
    );
    top$tc$regs$0 regs$187(
        .d(regs$187$d),
        .q(regs$187$q),
        .clock(regs$187$clock)
    );
    top$tc$regs$0 regs$188(
        .d(regs$188$d),
        .q(regs$188$q),
        .clock(regs$188$clock)
    );
    top$tc$regs$0 regs$189(
        .d(regs$189$d),
        .q(regs$189$q),
        .clock(regs$189$clock)
    );
    top$tc$regs$0 regs$190(
        .d(regs$190$d),
        .q(regs$190$q),
        .clock(regs$190$clock)
    );
    top$tc$regs$0 regs$191(
        .d(regs$191$d),
        .q(regs$191$q),
        .clock(regs$191$clock)
    );
    top$tc$regs$0 regs$192(
        .d(regs$192$d),
        .q(regs$192$q),
        .clock(regs$192$clock)
    );
    top$tc$regs$0 regs$193(
        .d(regs$193$d),
        .q(regs$193$q),
        .clock(regs$193$clock)
    );
    top$tc$regs$0 regs$194(
        .d(regs$194$d),
        .q(regs$194$q),
        .clock(regs$194$clock)
    );
    top$tc$regs$0 regs$195(
        .d(regs$195$d),
        .q(regs$195$q),
        .clock(regs$195$clock)
    );
    top$tc$regs$0 regs$196(
        .d(regs$196$d),
        .q(regs$196$q),
        .clock(regs$196$clock)
    );
    top$tc$regs$0 regs$197(
        .d(regs$197$d),
        .q(regs$197$q),
        .clock(regs$197$clock)
    );
    top$tc$regs$0 regs$198(
        .d(regs$198$d),
        .q(regs$198$q),
        .clock(regs$198$clock)
    );
    top$tc$regs$0 regs$199(
        .d(regs$199$d),
        .q(regs$199$q),
        .clock(regs$199$clock)
    );
    top$tc$regs$0 regs$200(
        .d(regs$200$d),
        .q(regs$200$q),
        .clock(regs$200$clock)
    );
    top$tc$regs$0 regs$201(
        .d(regs$201$d),
        .q(regs$201$q),
        .clock(regs$201$clock)
    );
    top$tc$regs$0 regs$202(
        .d(regs$202$d),
        .q(regs$202$q),
        .clock(regs$202$clock)
    );
    top$tc$regs$0 regs$203(
        .d(regs$203$d),
        .q(regs$203$q),
        .clock(regs$203$clock)
    );
    top$tc$regs$0 regs$204(
        .d(regs$204$d),
        .q(regs$204$q),
        .clock(regs$204$clock)
    );
    top$tc$regs$0 regs$205(
        .d(regs$205$d),
        .q(regs$205$q),
        .clock(regs$205$clock)
    );
    top$tc$regs$0 regs$206(
        .d(regs$206$d),
        .q(regs$206$q),
        .clock(regs$206$clock)
    );
    top$tc$regs$0 regs$207(
        .d(regs$207$d),
        .q(regs$207$q),
        .clock(regs$207$clock)
    );
    top$tc$regs$0 regs$208(
        .d(regs$208$d),
        .q(regs$208$q),
        .clock(regs$208$clock)
    );
    top$tc$regs$0 regs$209(
        .d(regs$209$d),
        .q(regs$209$q),
        .clock(regs$209$clock)
    );
    top$tc$regs$0 regs$210(
        .d(regs$210$d),
        .q(regs$210$q),
        .clock(regs$210$clock)
    );
    top$tc$regs$0 regs$211(
        .d(regs$211$d),
        .q(regs$211$q),
        .clock(regs$211$clock)
    );
    top$tc$regs$0 regs$212(
        .d(regs$212$d),
        .q(regs$212$q),
        .clock(regs$212$clock)
    );
    top$tc$regs$0 regs$213(
        .d(regs$213$d),
        .q(regs$213$q),
        .clock(regs$213$clock)
    );
    top$tc$regs$0 regs$214(
        .d(regs$214$d),
        .q(regs$214$q),
        .clock(regs$214$clock)
    );
    top$tc$regs$0 regs$215(
        .d(regs$215$d),
        .q(regs$215$q),
        .clock(regs$215$clock)
    );
    top$tc$regs$0 regs$216(
        .d(regs$216$d),
        .q(regs$216$q),
        .clock(regs$216$clock)
    );
    top$tc$regs$0 regs$217(
        .d(regs$217$d),
        .q(regs$217$q),
        .clock(regs$217$clock)
    );
    top$tc$regs$0 regs$218(
        .d(regs$218$d),
        .q(regs$218$q),
        .clock(regs$218$clock)
    );
    top$tc$regs$0 regs$219(
        .d(regs$219$d),
        .q(regs$219$q),
        .clock(regs$219$clock)
    );
    top$tc$regs$0 regs$220(
        .d(regs$220$d),
        .q(regs$220$q),
        .clock(regs$220$clock)
    );
    top$tc$regs$0 regs$221(
        .d(regs$221$d),
        .q(regs$221$q),
        .clock(regs$221$clock)
    );
    top$tc$regs$0 regs$222(
        .d(regs$222$d),
        .q(regs$222$q),
        .clock(regs$222$clock)
    );
    top$tc$regs$0 regs$223(
        .d(regs$223$d),
        .q(regs$223$q),
        .clock(regs$223$clock)
    );
    top$tc$regs$0 regs$224(
        .d(regs$224$d),
        .q(regs$224$q),
        .clock(regs$224$clock)
    );
    top$tc$regs$0 regs$225(
        .d(regs$225$d),
        .q(regs$225$q),
        .clock(regs$225$clock)
    );
    top$tc$regs$0 regs$226(
        .d(regs$226$d),
        .q(regs$226$q),
        .clock(regs$226$clock)
    );
    top$tc$regs$0 regs$227(
        .d(regs$227$d),
        .q(regs$227$q),
        .clock(regs$227$clock)
    );
    top$tc$regs$0 regs$228(
        .d(regs$228$d),
        .q(regs$228$q),
        .clock(regs$228$clock)
    );
    top$tc$regs$0 regs$229(
        .d(regs$229$d),
        .q(regs$229$q),
        .clock(regs$229$clock)
    );
    top$tc$regs$0 regs$230(
        .d(regs$230$d),
        .q(regs$230$q),
        .clock(regs$230$clock)
    );
    top$tc$regs$0 regs$231(
        .d(regs$231$d),
        .q(regs$231$q),
        .clock(regs$231$clock)
    );
    top$tc$regs$0 regs$232(
        .d(regs$232$d),
        .q(regs$232$q),
        .clock(regs$232$clock)
    );
    top$tc$regs$0 regs$233(
        .d(regs$233$d),
        .q(regs$233$q),
        .clock(regs$233$clock)
    );
    top$tc$regs$0 regs$234(
        .d(regs$234$d),
        .q(regs$234$q),
        .clock(regs$234$clock)
    );
    top$tc$regs$0 regs$235(
        .d(regs$235$d),
        .q(regs$235$q),
        .clock(regs$235$clock)
    );
    top$tc$regs$0 regs$236(
        .d(regs$236$d),
        .q(regs$236$q),
        .clock(regs$236$clock)
    );
    top$tc$regs$0 regs$237(
        .d(regs$237$d),
        .q(regs$237$q),
        .clock(regs$237$clock)
    );
    top$tc$regs$0 regs$238(
        .d(regs$238$d),
        .q(regs$238$q),
        .clock(regs$238$clock)
    );
    top$tc$regs$0 regs$239(
        .d(regs$239$d),
        .q(regs$239$q),
        .clock(regs$239$clock)
    );
    top$tc$regs$0 regs$240(
        .d(regs$240$d),
        .q(regs$240$q),
        .clock(regs$240$clock)
    );
    top$tc$regs$0 regs$241(
        .d(regs$241$d),
        .q(regs$241$q),
        .clock(regs$241$clock)
    );
    top$tc$regs$0 regs$242(
        .d(regs$242$d),
        .q(regs$242$q),
        .clock(regs$242$clock)
    );
    top$tc$regs$0 regs$243(
        .d(regs$243$d),
        .q(regs$243$q),
        .clock(regs$243$clock)
    );
    top$tc$regs$0 regs$244(
        .d(regs$244$d),
        .q(regs$244$q),
        .clock(regs$244$clock)
    );
    top$tc$regs$0 regs$245(
        .d(regs$245$d),
        .q(regs$245$q),
        .clock(regs$245$clock)
    );
    top$tc$regs$0 regs$246(
        .d(regs$246$d),
        .q(regs$246$q),
        .clock(regs$246$clock)
    );
    top$tc$regs$0 regs$247(
        .d(regs$247$d),
        .q(regs$247$q),
        .clock(regs$247$clock)
    );
    top$tc$regs$0 regs$248(
        .d(regs$248$d),
        .q(regs$248$q),
        .clock(regs$248$clock)
    );
    top$tc$regs$0 regs$249(
        .d(regs$249$d),
        .q(regs$249$q),
        .clock(regs$249$clock)
    );
    top$tc$regs$0 regs$250(
        .d(regs$250$d),
        .q(regs$250$q),
        .clock(regs$250$clock)
    );
    top$tc$regs$0 regs$251(
        .d(regs$251$d),
        .q(regs$251$q),
        .clock(regs$251$clock)
    );
    top$tc$regs$0 regs$252(
        .d(regs$252$d),
        .q(regs$252$q),
        .clock(regs$252$clock)
    );
    top$tc$regs$0 regs$253(
        .d(regs$253$d),
        .q(regs$253$q),
        .clock(regs$253$clock)
    );
    top$tc$regs$0 regs$254(
        .d(regs$254$d),
        .q(regs$254$q),
        .clock(regs$254$clock)
    );
    top$tc$regs$0 regs$255(
        .d(regs$255$d),
        .q(regs$255$q),
        .clock(regs$255$clock)
    );
    top$tc$regs$0 regs$256(
        .d(regs$256$d),
        .q(regs$256$q),
        .clock(regs$256$clock)
    );
    top$tc$regs$0 regs$257(
        .d(regs$257$d),
        .q(regs$257$q),
        .clock(regs$257$clock)
    );
    top$tc$regs$0 regs$258(
        .d(regs$258$d),
        .q(regs$258$q),
        .clock(regs$258$clock)
    );
    top$tc$regs$0 regs$259(
        .d(regs$259$d),
        .q(regs$259$q),
        .clock(regs$259$clock)
    );
    top$tc$regs$0 regs$260(
        .d(regs$260$d),
        .q(regs$260$q),
        .clock(regs$260$clock)
    );
    top$tc$regs$0 regs$261(
        .d(regs$261$d),
        .q(regs$261$q),
        .clock(regs$261$clock)
    );
    top$tc$regs$0 regs$262(
        .d(regs$262$d),
        .q(regs$262$q),
        .clock(regs$262$clock)
    );
    top$tc$regs$0 regs$263(
        .d(regs$263$d),
        .q(regs$263$q),
        .clock(regs$263$clock)
    );
    top$tc$regs$0 regs$264(
        .d(regs$264$d),
        .q(regs$264$q),
        .clock(regs$264$clock)
    );
    top$tc$regs$0 regs$265(
        .d(regs$265$d),
        .q(regs$265$q),
        .clock(regs$265$clock)
    );
    top$tc$regs$0 regs$266(
        .d(regs$266$d),
        .q(regs$266$q),
        .clock(regs$266$clock)
    );
    top$tc$regs$0 regs$267(
        .d(regs$267$d),
        .q(regs$267$q),
        .clock(regs$267$clock)
    );
    top$tc$regs$0 regs$268(
        .d(regs$268$d),
        .q(regs$268$q),
        .clock(regs$268$clock)
    );
    top$tc$regs$0 regs$269(
        .d(regs$269$d),
        .q(regs$269$q),
        .clock(regs$269$clock)
    );
    top$tc$regs$0 regs$270(
        .d(regs$270$d),
        .q(regs$270$q),
        .clock(regs$270$clock)
    );
    top$tc$regs$0 regs$271(
        .d(regs$271$d),
        .q(regs$271$q),
        .clock(regs$271$clock)
    );
    top$tc$regs$0 regs$272(
        .d(regs$272$d),
        .q(regs$272$q),
        .clock(regs$272$clock)
    );
    top$tc$regs$0 regs$273(
        .d(regs$273$d),
        .q(regs$273$q),
        .clock(regs$273$clock)
    );
    top$tc$regs$0 regs$274(
        .d(regs$274$d),
        .q(regs$274$q),
        .clock(regs$274$clock)
    );
    top$tc$regs$0 regs$275(
        .d(regs$275$d),
        .q(regs$275$q),
        .clock(regs$275$clock)
    );
    top$tc$regs$0 regs$276(
        .d(regs$276$d),
        .q(regs$276$q),
        .clock(regs$276$clock)
    );
    top$tc$regs$0 regs$277(
        .d(regs$277$d),
        .q(regs$277$q),
        .clock(regs$277$clock)
    );
    top$tc$regs$0 regs$278(
        .d(regs$278$d),
        .q(regs$278$q),
        .clock(regs$278$clock)
    );
    top$tc$regs$0 regs$279(
        .d(regs$279$d),
        .q(regs$279$q),
        .clock(regs$279$clock)
    );
    top$tc$regs$0 regs$280(
        .d(regs$280$d),
        .q(regs$280$q),
        .clock(regs$280$clock)
    );
    top$tc$regs$0 regs$281(
        .d(regs$281$d),
        .q(regs$281$q),
        .clock(regs$281$clock)
    );
    top$tc$regs$0 regs$282(
        .d(regs$282$d),
        .q(regs$282$q),
        .clock(regs$282$clock)
    );
    top$tc$regs$0 regs$283(
        .d(regs$283$d),
        .q(regs$283$q),
        .clock(regs$283$clock)
    );
    top$tc$regs$0 regs$284(
        .d(regs$284$d),
        .q(regs$284$q),
        .clock(regs$284$clock)
    );
    top$tc$regs$0 regs$285(
        .d(regs$285$d),
        .q(regs$285$q),
        .clock(regs$285$clock)
    );
    top$tc$regs$0 regs$286(
        .d(regs$286$d),
        .q(regs$286$q),
        .clock(regs$286$clock)
    );
    top$tc$regs$0 regs$287(
        .d(regs$287$d),
        .q(regs$287$q),
        .clock(regs$287$clock)
    );
    top$tc$regs$0 regs$288(
        .d(regs$288$d),
        .q(regs$288$q),
        .clock(regs$288$clock)
    );
    top$tc$regs$0 regs$289(
        .d(regs$289$d),
        .q(regs$289$q),
        .clock(regs$289$clock)
    );
    top$tc$regs$0 regs$290(
        .d(regs$290$d),
        .q(regs$290$q),
        .clock(regs$290$clock)
    );
    top$tc$regs$0 regs$291(
        .d(regs$291$d),
        .q(regs$291$q),
        .clock(regs$291$clock)
    );
    top$tc$regs$0 regs$292(
        .d(regs$292$d),
        .q(regs$292$q),
        .clock(regs$292$clock)
    );
    top$tc$regs$0 regs$293(
        .d(regs$293$d),
        .q(regs$293$q),
        .clock(regs$293$clock)
    );
    top$tc$regs$0 regs$294(
        .d(regs$294$d),
        .q(regs$294$q),
        .clock(regs$294$clock)
    );
    top$tc$regs$0 regs$295(
        .d(regs$295$d),
        .q(regs$295$q),
        .clock(regs$295$clock)
    );
    top$tc$regs$0 regs$296(
        .d(regs$296$d),
        .q(regs$296$q),
        .clock(regs$296$clock)
    );
    top$tc$regs$0 regs$297(
        .d(regs$297$d),
        .q(regs$297$q),
        .clock(regs$297$clock)
    );
    top$tc$regs$0 regs$298(
        .d(regs$298$d),
        .q(regs$298$q),
        .clock(regs$298$clock)
    );
    top$tc$regs$0 regs$299(
        .d(regs$299$d),
        .q(regs$299$q),
        .clock(regs$299$clock)
    );
    top$tc$regs$0 regs$300(
        .d(regs$300$d),
        .q(regs$300$q),
        .clock(regs$300$clock)
    );
    top$tc$regs$0 regs$301(
        .d(regs$301$d),
        .q(regs$301$q),
        .clock(regs$301$clock)
    );
    top$tc$regs$0 regs$302(
        .d(regs$302$d),
        .q(regs$302$q),
        .clock(regs$302$clock)
    );
    top$tc$regs$0 regs$303(
        .d(regs$303$d),
        .q(regs$303$q),
        .clock(regs$303$clock)
    );
    top$tc$regs$0 regs$304(
        .d(regs$304$d),
        .q(regs$304$q),
        .clock(regs$304$clock)
    );
    top$tc$regs$0 regs$305(
        .d(regs$305$d),
        .q(regs$305$q),
        .clock(regs$305$clock)
    );
    top$tc$regs$0 regs$306(
        .d(regs$306$d),
        .q(regs$306$q),
        .clock(regs$306$clock)
    );
    top$tc$regs$0 regs$307(
        .d(regs$307$d),
        .q(regs$307$q),
        .clock(regs$307$clock)
    );
    top$tc$regs$0 regs$308(
        .d(regs$308$d),
        .q(regs$308$q),
        .clock(regs$308$clock)
    );
    top$tc$regs$0 regs$309(
        .d(regs$309$d),
        .q(regs$309$q),
        .clock(regs$309$clock)
    );
    top$tc$regs$0 regs$310(
        .d(regs$310$d),
        .q(regs$310$q),
        .clock(regs$310$clock)
    );
    top$tc$regs$0 regs$311(
        .d(regs$311$d),
        .q(regs$311$q),
        .clock(regs$311$clock)
    );
    top$tc$regs$0 regs$312(
        .d(regs$312$d),
        .q(regs$312$q),
        .clock(regs$312$clock)
    );
    top$tc$regs$0 regs$313(
        .d(regs$313$d),
        .q(regs$313$q),
        .clock(regs$313$clock)
    );
    top$tc$regs$0 regs$314(
        .d(regs$314$d),
        .q(regs$314$q),
        .clock(regs$314$clock)
    );
    top$tc$regs$0 regs$315(
        .d(regs$315$d),
        .q(regs$315$q),
        .clock(regs$315$clock)
    );
    top$tc$regs$0 regs$316(
        .d(regs$316$d),
        .q(regs$316$q),
        .clock(regs$316$clock)
    );
    top$tc$regs$0 regs$317(
        .d(regs$317$d),
        .q(regs$317$q),
        .clock(regs$317$clock)
    );
    top$tc$regs$0 regs$318(
        .d(regs$318$d),
        .q(regs$318$q),
        .clock(regs$318$clock)
    );
    top$tc$regs$0 regs$319(
        .d(regs$319$d),
        .q(regs$319$q),
        .clock(regs$319$clock)
    );
    top$tc$regs$0 regs$320(
        .d(regs$320$d),
        .q(regs$320$q),
        .clock(regs$320$clock)
    );
    top$tc$regs$0 regs$321(
        .d(regs$321$d),
        .q(regs$321$q),
        .clock(regs$321$clock)
    );
    top$tc$regs$0 regs$322(
        .d(regs$322$d),
        .q(regs$322$q),
        .clock(regs$322$clock)
    );
    top$tc$regs$0 regs$323(
        .d(regs$323$d),
        .q(regs$323$q),
        .clock(regs$323$clock)
    );
    top$tc$regs$0 regs$324(
        .d(regs$324$d),
        .q(regs$324$q),
        .clock(regs$324$clock)
    );
    top$tc$regs$0 regs$325(
        .d(regs$325$d),
        .q(regs$325$q),
        .clock(regs$325$clock)
    );
    top$tc$regs$0 regs$326(
        .d(regs$326$d),
        .q(regs$326$q),
        .clock(regs$326$clock)
    );
    top$tc$regs$0 regs$327(
        .d(regs$327$d),
        .q(regs$327$q),
        .clock(regs$327$clock)
    );
    top$tc$regs$0 regs$328(
        .d(regs$328$d),
        .q(regs$328$q),
        .clock(regs$328$clock)
    );
    top$tc$regs$0 regs$329(
        .d(regs$329$d),
        .q(regs$329$q),
        .clock(regs$329$clock)
    );
    top$tc$regs$0 regs$330(
        .d(regs$330$d),
        .q(regs$330$q),
        .clock(regs$330$clock)
    );
    top$tc$regs$0 regs$331(
        .d(regs$331$d),
        .q(regs$331$q),
        .clock(regs$331$clock)
    );
    top$tc$regs$0 regs$332(
        .d(regs$332$d),
        .q(regs$332$q),
        .clock(regs$332$clock)
    );
    top$tc$regs$0 regs$333(
        .d(regs$333$d),
        .q(regs$333$q),
        .clock(regs$333$clock)
    );
    top$tc$regs$0 regs$334(
        .d(regs$334$d),
        .q(regs$334$q),
        .clock(regs$334$clock)
    );
    top$tc$regs$0 regs$335(
        .d(regs$335$d),
        .q(regs$335$q),
        .clock(regs$335$clock)
    );
    top$tc$regs$0 regs$336(
        .d(regs$336$d),
        .q(regs$336$q),
        .clock(regs$336$clock)
    );
    top$tc$regs$0 regs$337(
        .d(regs$337$d),
        .q(regs$337$q),
        .clock(regs$337$clock)
    );
    top$tc$regs$0 regs$338(
        .d(regs$338$d),
        .q(regs$338$q),
        .clock(regs$338$clock)
    );
    top$tc$regs$0 regs$339(
        .d(regs$339$d),
        .q(regs$339$q),
        .clock(regs$339$clock)
    );
    top$tc$regs$0 regs$340(
        .d(regs$340$d),
        .q(regs$340$q),
        .clock(regs$340$clock)
    );
    top$tc$regs$0 regs$341(
        .d(regs$341$d),
        .q(regs$341$q),
        .clock(regs$341$clock)
    );
    top$tc$regs$0 regs$342(
        .d(regs$342$d),
        .q(regs$342$q),
        .clock(regs$342$clock)
    );
    top$tc$regs$0 regs$343(
        .d(regs$343$d),
        .q(regs$343$q),
        .clock(regs$343$clock)
    );
    top$tc$regs$0 regs$344(
        .d(regs$344$d),
        .q(regs$344$q),
        .clock(regs$344$clock)
    );
    top$tc$regs$0 regs$345(
        .d(regs$345$d),
        .q(regs$345$q),
        .clock(regs$345$clock)
    );
    top$tc$regs$0 regs$346(
        .d(regs$346$d),
        .q(regs$346$q),
        .clock(regs$346$clock)
    );
    top$tc$regs$0 regs$347(
        .d(regs$347$d),
        .q(regs$347$q),
        .clock(regs$347$clock)
    );
    top$tc$regs$0 regs$348(
        .d(regs$348$d),
        .q(regs$348$q),
        .clock(regs$348$clock)
    );
    top$tc$regs$0 regs$349(
        .d(regs$349$d),
        .q(regs$349$q),
        .clock(regs$349$clock)
    );
    top$tc$regs$0 regs$350(
        .d(regs$350$d),
        .q(regs$350$q),
        .clock(regs$350$clock)
    );
    top$tc$regs$0 regs$351(
        .d(regs$351$d),
        .q(regs$351$q),
        .clock(regs$351$clock)
    );
    top$tc$regs$0 regs$352(
        .d(regs$352$d),
        .q(regs$352$q),
        .clock(regs$352$clock)
    );
    top$tc$regs$0 regs$353(
        .d(regs$353$d),
        .q(regs$353$q),
        .clock(regs$353$clock)
    );
    top$tc$regs$0 regs$354(
        .d(regs$354$d),
        .q(regs$354$q),
        .clock(regs$354$clock)
    );
    top$tc$regs$0 regs$355(
        .d(regs$355$d),
        .q(regs$355$q),
        .clock(regs$355$clock)
    );
    top$tc$regs$0 regs$356(
        .d(regs$356$d),
        .q(regs$356$q),
        .clock(regs$356$clock)
    );
    top$tc$regs$0 regs$357(
        .d(regs$357$d),
        .q(regs$357$q),
        .clock(regs$357$clock)
    );
    top$tc$regs$0 regs$358(
        .d(regs$358$d),
        .q(regs$358$q),
        .clock(regs$358$clock)
    );
    top$tc$regs$0 regs$359(
        .d(regs$359$d),
        .q(regs$359$q),
        .clock(regs$359$clock)
    );
    top$tc$regs$0 regs$360(
        .d(regs$360$d),
        .q(regs$360$q),
        .clock(regs$360$clock)
    );
    top$tc$regs$0 regs$361(
        .d(regs$361$d),
        .q(regs$361$q),
        .clock(regs$361$clock)
    );
    top$tc$regs$0 regs$362(
        .d(regs$362$d),
        .q(regs$362$q),
        .clock(regs$362$clock)
    );
    top$tc$regs$0 regs$363(
        .d(regs$363$d),
        .q(regs$363$q),
        .clock(regs$363$clock)
    );
    top$tc$regs$0 regs$364(
        .d(regs$364$d),
        .q(regs$364$q),
        .clock(regs$364$clock)
    );
    top$tc$regs$0 regs$365(
        .d(regs$365$d),
        .q(regs$365$q),
        .clock(regs$365$clock)
    );
    top$tc$regs$0 regs$366(
        .d(regs$366$d),
        .q(regs$366$q),
        .clock(regs$366$clock)
    );
    top$tc$regs$0 regs$367(
        .d(regs$367$d),
        .q(regs$367$q),
        .clock(regs$367$clock)
    );
    top$tc$regs$0 regs$368(
        .d(regs$368$d),
        .q(regs$368$q),
        .clock(regs$368$clock)
    );
    top$tc$regs$0 regs$369(
        .d(regs$369$d),
        .q(regs$369$q),
        .clock(regs$369$clock)
    );
    top$tc$regs$0 regs$370(
        .d(regs$370$d),
        .q(regs$370$q),
        .clock(regs$370$clock)
    );
    top$tc$regs$0 regs$371(
        .d(regs$371$d),
        .q(regs$371$q),
        .clock(regs$371$clock)
    );
    top$tc$regs$0 regs$372(
        .d(regs$372$d),
        .q(regs$372$q),
        .clock(regs$372$clock)
    );
    top$tc$regs$0 regs$373(
        .d(regs$373$d),
        .q(regs$373$q),
        .clock(regs$373$clock)
    );
    top$tc$regs$0 regs$374(
        .d(regs$374$d),
        .q(regs$374$q),
        .clock(regs$374$clock)
    );
    top$tc$regs$0 regs$375(
        .d(regs$375$d),
        .q(regs$375$q),
        .clock(regs$375$clock)
    );
    top$tc$regs$0 regs$376(
        .d(regs$376$d),
        .q(regs$376$q),
        .clock(regs$376$clock)
    );
    top$tc$regs$0 regs$377(
        .d(regs$377$d),
        .q(regs$377$q),
        .clock(regs$377$clock)
    );
    top$tc$regs$0 regs$378(
        .d(regs$378$d),
        .q(regs$378$q),
        .clock(regs$378$clock)
    );
    top$tc$regs$0 regs$379(
        .d(regs$379$d),
        .q(regs$379$q),
        .clock(regs$379$clock)
    );
    top$tc$regs$0 regs$380(
        .d(regs$380$d),
        .q(regs$380$q),
        .clock(regs$380$clock)
    );
    top$tc$regs$0 regs$381(
        .d(regs$381$d),
        .q(regs$381$q),
        .clock(regs$381$clock)
    );
    top$tc$regs$0 regs$382(
        .d(regs$382$d),
        .q(regs$382$q),
        .clock(regs$382$clock)
    );
    top$tc$regs$0 regs$383(
        .d(regs$383$d),
        .q(regs$383$q),
        .clock(regs$383$clock)
    );
    top$tc$regs$0 regs$384(
        .d(regs$384$d),
        .q(regs$384$q),
        .clock(regs$384$clock)
    );
    top$tc$regs$0 regs$385(
        .d(regs$385$d),
        .q(regs$385$q),
        .clock(regs$385$clock)
    );
    top$tc$regs$0 regs$386(
        .d(regs$386$d),
        .q(regs$386$q),
        .clock(regs$386$clock)
    );
    top$tc$regs$0 regs$387(
        .d(regs$387$d),
        .q(regs$387$q),
        .clock(regs$387$clock)
    );
    top$tc$regs$0 regs$388(
        .d(regs$388$d),
        .q(regs$388$q),
        .clock(regs$388$clock)
    );
    top$tc$regs$0 regs$389(
        .d(regs$389$d),
        .q(regs$389$q),
        .clock(regs$389$clock)
    );
    top$tc$regs$0 regs$390(
        .d(regs$390$d),
        .q(regs$390$q),
        .clock(regs$390$clock)
    );
    top$tc$regs$0 regs$391(
        .d(regs$391$d),
        .q(regs$391$q),
        .clock(regs$391$clock)
    );
    top$tc$regs$0 regs$392(
        .d(regs$392$d),
        .q(regs$392$q),
        .clock(regs$392$clock)
    );
    top$tc$regs$0 regs$393(
        .d(regs$393$d),
        .q(regs$393$q),
        .clock(regs$393$clock)
    );
    top$tc$regs$0 regs$394(
        .d(regs$394$d),
        .q(regs$394$q),
        .clock(regs$394$clock)
    );
    top$tc$regs$0 regs$395(
        .d(regs$395$d),
        .q(regs$395$q),
        .clock(regs$395$clock)
    );
    top$tc$regs$0 regs$396(
        .d(regs$396$d),
        .q(regs$396$q),
        .clock(regs$396$clock)
    );
    top$tc$regs$0 regs$397(
        .d(regs$397$d),
        .q(regs$397$q),
        .clock(regs$397$clock)
    );
    top$tc$regs$0 regs$398(
        .d(regs$398$d),
        .q(regs$398$q),
        .clock(regs$398$clock)
    );
    top$tc$regs$0 regs$399(
        .d(regs$399$d),
        .q(regs$399$q),
        .clock(regs$399$clock)
    );
    top$tc$regs$0 regs$400(
        .d(regs$400$d),
        .q(regs$400$q),
        .clock(regs$400$clock)
    );
    top$tc$regs$0 regs$401(
        .d(regs$401$d),
        .q(regs$401$q),
        .clock(regs$401$clock)
    );
    top$tc$regs$0 regs$402(
        .d(regs$402$d),
        .q(regs$402$q),
        .clock(regs$402$clock)
    );
    top$tc$regs$0 regs$403(
        .d(regs$403$d),
        .q(regs$403$q),
        .clock(regs$403$clock)
    );
    top$tc$regs$0 regs$404(
        .d(regs$404$d),
        .q(regs$404$q),
        .clock(regs$404$clock)
    );
    top$tc$regs$0 regs$405(
        .d(regs$405$d),
        .q(regs$405$q),
        .clock(regs$405$clock)
    );
    top$tc$regs$0 regs$406(
        .d(regs$406$d),
        .q(regs$406$q),
        .clock(regs$406$clock)
    );
    top$tc$regs$0 regs$407(
        .d(regs$407$d),
        .q(regs$407$q),
        .clock(regs$407$clock)
    );
    top$tc$regs$0 regs$408(
        .d(regs$408$d),
        .q(regs$408$q),
        .clock(regs$408$clock)
    );
    top$tc$regs$0 regs$409(
        .d(regs$409$d),
        .q(regs$409$q),
        .clock(regs$409$clock)
    );
    top$tc$regs$0 regs$410(
        .d(regs$410$d),
        .q(regs$410$q),
        .clock(regs$410$clock)
    );
    top$tc$regs$0 regs$411(
        .d(regs$411$d),
        .q(regs$411$q),
        .clock(regs$411$clock)
    );
    top$tc$regs$0 regs$412(
        .d(regs$412$d),
        .q(regs$412$q),
        .clock(regs$412$clock)
    );
    top$tc$regs$0 regs$413(
        .d(regs$413$d),
        .q(regs$413$q),
        .clock(regs$413$clock)
    );
    top$tc$regs$0 regs$414(
        .d(regs$414$d),
        .q(regs$414$q),
        .clock(regs$414$clock)
    );
    top$tc$regs$0 regs$415(
        .d(regs$415$d),
        .q(regs$415$q),
        .clock(regs$415$clock)
    );
    top$tc$regs$0 regs$416(
        .d(regs$416$d),
        .q(regs$416$q),
        .clock(regs$416$clock)
    );
    top$tc$regs$0 regs$417(
        .d(regs$417$d),
        .q(regs$417$q),
        .clock(regs$417$clock)
    );
    top$tc$regs$0 regs$418(
        .d(regs$418$d),
        .q(regs$418$q),
        .clock(regs$418$clock)
    );
    top$tc$regs$0 regs$419(
        .d(regs$419$d),
        .q(regs$419$q),
        .clock(regs$419$clock)
    );
    top$tc$regs$0 regs$420(
        .d(regs$420$d),
        .q(regs$420$q),
        .clock(regs$420$clock)
    );
    top$tc$regs$0 regs$421(
        .d(regs$421$d),
        .q(regs$421$q),
        .clock(regs$421$clock)
    );
    top$tc$regs$0 regs$422(
        .d(regs$422$d),
        .q(regs$422$q),
        .clock(regs$422$clock)
    );
    top$tc$regs$0 regs$423(
        .d(regs$423$d),
        .q(regs$423$q),
        .clock(regs$423$clock)
    );
    top$tc$regs$0 regs$424(
        .d(regs$424$d),
        .q(regs$424$q),
        .clock(regs$424$clock)
    );
    top$tc$regs$0 regs$425(
        .d(regs$425$d),
        .q(regs$425$q),
        .clock(regs$425$clock)
    );
    top$tc$regs$0 regs$426(
        .d(regs$426$d),
        .q(regs$426$q),
        .clock(regs$426$clock)
    );
    top$tc$regs$0 regs$427(
        .d(regs$427$d),
        .q(regs$427$q),
        .clock(regs$427$clock)
    );
    top$tc$regs$0 regs$428(
        .d(regs$428$d),
        .q(regs$428$q),
        .clock(regs$428$clock)
    );
    top$tc$regs$0 regs$429(
        .d(regs$429$d),
        .q(regs$429$q),
        .clock(regs$429$clock)
    );
    top$tc$regs$0 regs$430(
        .d(regs$430$d),
        .q(regs$430$q),
        .clock(regs$430$clock)
    );
    top$tc$regs$0 regs$431(
        .d(regs$431$d),
        .q(regs$431$q),
        .clock(regs$431$clock)
    );
    top$tc$regs$0 regs$432(
        .d(regs$432$d),
        .q(regs$432$q),
        .clock(regs$432$clock)
    );
    top$tc$regs$0 regs$433(
        .d(regs$433$d),
        .q(regs$433$q),
        .clock(regs$433$clock)
    );
    top$tc$regs$0 regs$434(
        .d(regs$434$d),
        .q(regs$434$q),
        .clock(regs$434$clock)
    );
    top$tc$regs$0 regs$435(
        .d(regs$435$d),
        .q(regs$435$q),
        .clock(regs$435$clock)
    );
    top$tc$regs$0 regs$436(
        .d(regs$436$d),
        .q(regs$436$q),
        .clock(regs$436$clock)
    );
    top$tc$regs$0 regs$437(
        .d(regs$437$d),
        .q(regs$437$q),
        .clock(regs$437$clock)
    );
    top$tc$regs$0 regs$438(
        .d(regs$438$d),
        .q(regs$438$q),
        .clock(regs$438$clock)
    );
    top$tc$regs$0 regs$439(
        .d(regs$439$d),
        .q(regs$439$q),
        .clock(regs$439$clock)
    );
    top$tc$regs$0 regs$440(
        .d(regs$440$d),
        .q(regs$440$q),
        .clock(regs$440$clock)
    );
    top$tc$regs$0 regs$441(
        .d(regs$441$d),
        .q(regs$441$q),
        .clock(regs$441$clock)
    );
    top$tc$regs$0 regs$442(
        .d(regs$442$d),
        .q(regs$442$q),
        .clock(regs$442$clock)
    );
    top$tc$regs$0 regs$443(
        .d(regs$443$d),
        .q(regs$443$q),
        .clock(regs$443$clock)
    );
    top$tc$regs$0 regs$444(
        .d(regs$444$d),
        .q(regs$444$q),
        .clock(regs$444$clock)
    );
    top$tc$regs$0 regs$445(
        .d(regs$445$d),
        .q(regs$445$q),
        .clock(regs$445$clock)
    );
    top$tc$regs$0 regs$446(
        .d(regs$446$d),
        .q(regs$446$q),
        .clock(regs$446$clock)
    );
    top$tc$regs$0 regs$447(
        .d(regs$447$d),
        .q(regs$447$q),
        .clock(regs$447$clock)
    );
    top$tc$regs$0 regs$448(
        .d(regs$448$d),
        .q(regs$448$q),
        .clock(regs$448$clock)
    );
    top$tc$regs$0 regs$449(
        .d(regs$449$d),
        .q(regs$449$q),
        .clock(regs$449$clock)
    );
    top$tc$regs$0 regs$450(
        .d(regs$450$d),
        .q(regs$450$q),
        .clock(regs$450$clock)
    );
    top$tc$regs$0 regs$451(
        .d(regs$451$d),
        .q(regs$451$q),
        .clock(regs$451$clock)
    );
    top$tc$regs$0 regs$452(
        .d(regs$452$d),
        .q(regs$452$q),
        .clock(regs$452$clock)
    );
    top$tc$regs$0 regs$453(
        .d(regs$453$d),
        .q(regs$453$q),
        .clock(regs$453$clock)
    );
    top$tc$regs$0 regs$454(
        .d(regs$454$d),
        .q(regs$454$q),
        .clock(regs$454$clock)
    );
    top$tc$regs$0 regs$455(
        .d(regs$455$d),
        .q(regs$455$q),
        .clock(regs$455$clock)
    );
    top$tc$regs$0 regs$456(
        .d(regs$456$d),
        .q(regs$456$q),
        .clock(regs$456$clock)
    );
    top$tc$regs$0 regs$457(
        .d(regs$457$d),
        .q(regs$457$q),
        .clock(regs$457$clock)
    );
    top$tc$regs$0 regs$458(
        .d(regs$458$d),
        .q(regs$458$q),
        .clock(regs$458$clock)
    );
    top$tc$regs$0 regs$459(
        .d(regs$459$d),
        .q(regs$459$q),
        .clock(regs$459$clock)
    );
    top$tc$regs$0 regs$460(
        .d(regs$460$d),
        .q(regs$460$q),
        .clock(regs$460$clock)
    );
    top$tc$regs$0 regs$461(
        .d(regs$461$d),
        .q(regs$461$q),
        .clock(regs$461$clock)
    );
    top$tc$regs$0 regs$462(
        .d(regs$462$d),
        .q(regs$462$q),
        .clock(regs$462$clock)
    );
    top$tc$regs$0 regs$463(
        .d(regs$463$d),
        .q(regs$463$q),
        .clock(regs$463$clock)
    );
    top$tc$regs$0 regs$464(
        .d(regs$464$d),
        .q(regs$464$q),
        .clock(regs$464$clock)
    );
    top$tc$regs$0 regs$465(
        .d(regs$465$d),
        .q(regs$465$q),
        .clock(regs$465$clock)
    );
    top$tc$regs$0 regs$466(
        .d(regs$466$d),
        .q(regs$466$q),
        .clock(regs$466$clock)
    );
    top$tc$regs$0 regs$467(
        .d(regs$467$d),
        .q(regs$467$q),
        .clock(regs$467$clock)
    );
    top$tc$regs$0 regs$468(
        .d(regs$468$d),
        .q(regs$468$q),
        .clock(regs$468$clock)
    );
    top$tc$regs$0 regs$469(
        .d(regs$469$d),
        .q(regs$469$q),
        .clock(regs$469$clock)
    );
    top$tc$regs$0 regs$470(
        .d(regs$470$d),
        .q(regs$470$q),
        .clock(regs$470$clock)
    );
    top$tc$regs$0 regs$471(
        .d(regs$471$d),
        .q(regs$471$q),
        .clock(regs$471$clock)
    );
    top$tc$regs$0 regs$472(
        .d(regs$472$d),
        .q(regs$472$q),
        .clock(regs$472$clock)
    );
    top$tc$regs$0 regs$473(
        .d(regs$473$d),
        .q(regs$473$q),
        .clock(regs$473$clock)
    );
    top$tc$regs$0 regs$474(
        .d(regs$474$d),
        .q(regs$474$q),
        .clock(regs$474$clock)
    );
    top$tc$regs$0 regs$475(
        .d(regs$475$d),
        .q(regs$475$q),
        .clock(regs$475$clock)
    );
    top$tc$regs$0 regs$476(
        .d(regs$476$d),
        .q(regs$476$q),
        .clock(regs$476$clock)
    );
    top$tc$regs$0 regs$477(
        .d(regs$477$d),
        .q(regs$477$q),
        .clock(regs$477$clock)
    );
    top$tc$regs$0 regs$478(
        .d(regs$478$d),
        .q(regs$478$q),
        .clock(regs$478$clock)
    );
    top$tc$regs$0 regs$479(
        .d(regs$479$d),
        .q(regs$479$q),
        .clock(regs$479$clock)
    );
    top$tc$regs$0 regs$480(
        .d(regs$480$d),
        .q(regs$480$q),
        .clock(regs$480$clock)
    );
    top$tc$regs$0 regs$481(
        .d(regs$481$d),
        .q(regs$481$q),
        .clock(regs$481$clock)
    );
    top$tc$regs$0 regs$482(
        .d(regs$482$d),
        .q(regs$482$q),
        .clock(regs$482$clock)
    );
    top$tc$regs$0 regs$483(
        .d(regs$483$d),
        .q(regs$483$q),
        .clock(regs$483$clock)
    );
    top$tc$regs$0 regs$484(
        .d(regs$484$d),
        .q(regs$484$q),
        .clock(regs$484$clock)
    );
    top$tc$regs$0 regs$485(
        .d(regs$485$d),
        .q(regs$485$q),
        .clock(regs$485$clock)
    );
    top$tc$regs$0 regs$486(
        .d(regs$486$d),
        .q(regs$486$q),
        .clock(regs$486$clock)
    );
    top$tc$regs$0 regs$487(
        .d(regs$487$d),
        .q(regs$487$q),
        .clock(regs$487$clock)
    );
    top$tc$regs$0 regs$488(
        .d(regs$488$d),
        .q(regs$488$q),
        .clock(regs$488$clock)
    );
    top$tc$regs$0 regs$489(
        .d(regs$489$d),
        .q(regs$489$q),
        .clock(regs$489$clock)
    );
    top$tc$regs$0 regs$490(
        .d(regs$490$d),
        .q(regs$490$q),
        .clock(regs$490$clock)
    );
    top$tc$regs$0 regs$491(
        .d(regs$491$d),
        .q(regs$491$q),
        .clock(regs$491$clock)
    );
    top$tc$regs$0 regs$492(
        .d(regs$492$d),
        .q(regs$492$q),
        .clock(regs$492$clock)
    );
    top$tc$regs$0 regs$493(
        .d(regs$493$d),
        .q(regs$493$q),
        .clock(regs$493$clock)
    );
    top$tc$regs$0 regs$494(
        .d(regs$494$d),
        .q(regs$494$q),
        .clock(regs$494$clock)
    );
    top$tc$regs$0 regs$495(
        .d(regs$495$d),
        .q(regs$495$q),
        .clock(regs$495$clock)
    );
    top$tc$regs$0 regs$496(
        .d(regs$496$d),
        .q(regs$496$q),
        .clock(regs$496$clock)
    );
    top$tc$regs$0 regs$497(
        .d(regs$497$d),
        .q(regs$497$q),
        .clock(regs$497$clock)
    );
    top$tc$regs$0 regs$498(
        .d(regs$498$d),
        .q(regs$498$q),
        .clock(regs$498$clock)
    );
    top$tc$regs$0 regs$499(
        .d(regs$499$d),
        .q(regs$499$q),
        .clock(regs$499$clock)
    );
    top$tc$regs$0 regs$500(
        .d(regs$500$d),
        .q(regs$500$q),
        .clock(regs$500$clock)
    );
    top$tc$regs$0 regs$501(
        .d(regs$501$d),
        .q(regs$501$q),
        .clock(regs$501$clock)
    );
    top$tc$regs$0 regs$502(
        .d(regs$502$d),
        .q(regs$502$q),
        .clock(regs$502$clock)
    );
    top$tc$regs$0 regs$503(
        .d(regs$503$d),
        .q(regs$503$q),
        .clock(regs$503$clock)
    );
    top$tc$regs$0 regs$504(
        .d(regs$504$d),
        .q(regs$504$q),
        .clock(regs$504$clock)
    );
    top$tc$regs$0 regs$505(
        .d(regs$505$d),
        .q(regs$505$q),
        .clock(regs$505$clock)
    );
    top$tc$regs$0 regs$506(
        .d(regs$506$d),
        .q(regs$506$q),
        .clock(regs$506$clock)
    );
    top$tc$regs$0 regs$507(
        .d(regs$507$d),
        .q(regs$507$q),
        .clock(regs$507$clock)
    );
    top$tc$regs$0 regs$508(
        .d(regs$508$d),
        .q(regs$508$q),
        .clock(regs$508$clock)
    );
    top$tc$regs$0 regs$509(
        .d(regs$509$d),
        .q(regs$509$q),
        .clock(regs$509$clock)
    );
    top$tc$regs$0 regs$510(
        .d(regs$510$d),
        .q(regs$510$q),
        .clock(regs$510$clock)
    );
    top$tc$regs$0 regs$511(
        .d(regs$511$d),
        .q(regs$511$q),
        .clock(regs$511$clock)
    );
    top$tc$regs$0 regs$512(
        .d(regs$512$d),
        .q(regs$512$q),
        .clock(regs$512$clock)
    );
    top$tc$regs$0 regs$513(
        .d(regs$513$d),
        .q(regs$513$q),
        .clock(regs$513$clock)
    );
    top$tc$regs$0 regs$514(
        .d(regs$514$d),
        .q(regs$514$q),
        .clock(regs$514$clock)
    );
    top$tc$regs$0 regs$515(
        .d(regs$515$d),
        .q(regs$515$q),
        .clock(regs$515$clock)
    );
    top$tc$regs$0 regs$516(
        .d(regs$516$d),
        .q(regs$516$q),
        .clock(regs$516$clock)
    );
    top$tc$regs$0 regs$517(
        .d(regs$517$d),
        .q(regs$517$q),
        .clock(regs$517$clock)
    );
    top$tc$regs$0 regs$518(
        .d(regs$518$d),
        .q(regs$518$q),
        .clock(regs$518$clock)
    );
    top$tc$regs$0 regs$519(
        .d(regs$519$d),
        .q(regs$519$q),
        .clock(regs$519$clock)
    );
    top$tc$regs$0 regs$520(
        .d(regs$520$d),
        .q(regs$520$q),
        .clock(regs$520$clock)
    );
    top$tc$regs$0 regs$521(
        .d(regs$521$d),
        .q(regs$521$q),
        .clock(regs$521$clock)
    );
    top$tc$regs$0 regs$522(
        .d(regs$522$d),
        .q(regs$522$q),
        .clock(regs$522$clock)
    );
    top$tc$regs$0 regs$523(
        .d(regs$523$d),
        .q(regs$523$q),
        .clock(regs$523$clock)
    );
    top$tc$regs$0 regs$524(
        .d(regs$524$d),
        .q(regs$524$q),
        .clock(regs$524$clock)
    );
    top$tc$regs$0 regs$525(
        .d(regs$525$d),
        .q(regs$525$q),
        .clock(regs$525$clock)
    );
    top$tc$regs$0 regs$526(
        .d(regs$526$d),
        .q(regs$526$q),
        .clock(regs$526$clock)
    );
    top$tc$regs$0 regs$527(
        .d(regs$527$d),
        .q(regs$527$q),
        .clock(regs$527$clock)
    );
    top$tc$regs$0 regs$528(
        .d(regs$528$d),
        .q(regs$528$q),
        .clock(regs$528$clock)
    );
    top$tc$regs$0 regs$529(
        .d(regs$529$d),
        .q(regs$529$q),
        .clock(regs$529$clock)
    );
    top$tc$regs$0 regs$530(
        .d(regs$530$d),
        .q(regs$530$q),
        .clock(regs$530$clock)
    );
    top$tc$regs$0 regs$531(
        .d(regs$531$d),
        .q(regs$531$q),
        .clock(regs$531$clock)
    );
    top$tc$regs$0 regs$532(
        .d(regs$532$d),
        .q(regs$532$q),
        .clock(regs$532$clock)
    );
    top$tc$regs$0 regs$533(
        .d(regs$533$d),
        .q(regs$533$q),
        .clock(regs$533$clock)
    );
    top$tc$regs$0 regs$534(
        .d(regs$534$d),
        .q(regs$534$q),
        .clock(regs$534$clock)
    );
    top$tc$regs$0 regs$535(
        .d(regs$535$d),
        .q(regs$535$q),
        .clock(regs$535$clock)
    );
    top$tc$regs$0 regs$536(
        .d(regs$536$d),
        .q(regs$536$q),
        .clock(regs$536$clock)
    );
    top$tc$regs$0 regs$537(
        .d(regs$537$d),
        .q(regs$537$q),
        .clock(regs$537$clock)
    );
    top$tc$regs$0 regs$538(
        .d(regs$538$d),
        .q(regs$538$q),
        .clock(regs$538$clock)
    );
    top$tc$regs$0 regs$539(
        .d(regs$539$d),
        .q(regs$539$q),
        .clock(regs$539$clock)
    );
    top$tc$regs$0 regs$540(
        .d(regs$540$d),
        .q(regs$540$q),
        .clock(regs$540$clock)
    );
    top$tc$regs$0 regs$541(
        .d(regs$541$d),
        .q(regs$541$q),
        .clock(regs$541$clock)
    );
    top$tc$regs$0 regs$542(
        .d(regs$542$d),
        .q(regs$542$q),
        .clock(regs$542$clock)
    );
    top$tc$regs$0 regs$543(
        .d(regs$543$d),
        .q(regs$543$q),
        .clock(regs$543$clock)
    );
    top$tc$regs$0 regs$544(
        .d(regs$544$d),
        .q(regs$544$q),
        .clock(regs$544$clock)
    );
    top$tc$regs$0 regs$545(
        .d(regs$545$d),
        .q(regs$545$q),
        .clock(regs$545$clock)
    );
    top$tc$regs$0 regs$546(
        .d(regs$546$d),
        .q(regs$546$q),
        .clock(regs$546$clock)
    );
    top$tc$regs$0 regs$547(
        .d(regs$547$d),
        .q(regs$547$q),
        .clock(regs$547$clock)
    );
    top$tc$regs$0 regs$548(
        .d(regs$548$d),
        .q(regs$548$q),
        .clock(regs$548$clock)
    );
    top$tc$regs$0 regs$549(
        .d(regs$549$d),
        .q(regs$549$q),
        .clock(regs$549$clock)
    );
    top$tc$regs$0 regs$550(
        .d(regs$550$d),
        .q(regs$550$q),
        .clock(regs$550$clock)
    );
    top$tc$regs$0 regs$551(
        .d(regs$551$d),
        .q(regs$551$q),
        .clock(regs$551$clock)
    );
    top$tc$regs$0 regs$552(
        .d(regs$552$d),
        .q(regs$552$q),
        .clock(regs$552$clock)
    );
    top$tc$regs$0 regs$553(
        .d(regs$553$d),
        .q(regs$553$q),
        .clock(regs$553$clock)
    );
    top$tc$regs$0 regs$554(
        .d(regs$554$d),
        .q(regs$554$q),
        .clock(regs$554$clock)
    );
    top$tc$regs$0 regs$555(
        .d(regs$555$d),
        .q(regs$555$q),
        .clock(regs$555$clock)
    );
    top$tc$regs$0 regs$556(
        .d(regs$556$d),
        .q(regs$556$q),
        .clock(regs$556$clock)
    );
    top$tc$regs$0 regs$557(
        .d(regs$557$d),
        .q(regs$557$q),
        .clock(regs$557$clock)
    );
    top$tc$regs$0 regs$558(
        .d(regs$558$d),
        .q(regs$558$q),
        .clock(regs$558$clock)
    );
    top$tc$regs$0 regs$559(
        .d(regs$559$d),
        .q(regs$559$q),
        .clock(regs$559$clock)
    );
    top$tc$regs$0 regs$560(
        .d(regs$560$d),
        .q(regs$560$q),
        .clock(regs$560$clock)
    );
    top$tc$regs$0 regs$561(
        .d(regs$561$d),
        .q(regs$561$q),
        .clock(regs$561$clock)
    );
    top$tc$regs$0 regs$562(
        .d(regs$562$d),
        .q(regs$562$q),
        .clock(regs$562$clock)
    );
    top$tc$regs$0 regs$563(
        .d(regs$563$d),
        .q(regs$563$q),
        .clock(regs$563$clock)
    );
    top$tc$regs$0 regs$564(
        .d(regs$564$d),
        .q(regs$564$q),
        .clock(regs$564$clock)
    );
    top$tc$regs$0 regs$565(
        .d(regs$565$d),
        .q(regs$565$q),
        .clock(regs$565$clock)
    );
    top$tc$regs$0 regs$566(
        .d(regs$566$d),
        .q(regs$566$q),
        .clock(regs$566$clock)
    );
    top$tc$regs$0 regs$567(
        .d(regs$567$d),
        .q(regs$567$q),
        .clock(regs$567$clock)
    );
    top$tc$regs$0 regs$568(
        .d(regs$568$d),
        .q(regs$568$q),
        .clock(regs$568$clock)
    );
    top$tc$regs$0 regs$569(
        .d(regs$569$d),
        .q(regs$569$q),
        .clock(regs$569$clock)
    );
    top$tc$regs$0 regs$570(
        .d(regs$570$d),
        .q(regs$570$q),
        .clock(regs$570$clock)
    );
    top$tc$regs$0 regs$571(
        .d(regs$571$d),
        .q(regs$571$q),
        .clock(regs$571$clock)
    );
    top$tc$regs$0 regs$572(
        .d(regs$572$d),
        .q(regs$572$q),
        .clock(regs$572$clock)
    );
    top$tc$regs$0 regs$573(
        .d(regs$573$d),
        .q(regs$573$q),
        .clock(regs$573$clock)
    );
    top$tc$regs$0 regs$574(
        .d(regs$574$d),
        .q(regs$574$q),
        .clock(regs$574$clock)
    );
    top$tc$regs$0 regs$575(
        .d(regs$575$d),
        .q(regs$575$q),
        .clock(regs$575$clock)
    );
    top$tc$regs$0 regs$576(
        .d(regs$576$d),
        .q(regs$576$q),
        .clock(regs$576$clock)
    );
    top$tc$regs$0 regs$577(
        .d(regs$577$d),
        .q(regs$577$q),
        .clock(regs$577$clock)
    );
    top$tc$regs$0 regs$578(
        .d(regs$578$d),
        .q(regs$578$q),
        .clock(regs$578$clock)
    );
    top$tc$regs$0 regs$579(
        .d(regs$579$d),
        .q(regs$579$q),
        .clock(regs$579$clock)
    );
    top$tc$regs$0 regs$580(
        .d(regs$580$d),
        .q(regs$580$q),
        .clock(regs$580$clock)
    );
    top$tc$regs$0 regs$581(
        .d(regs$581$d),
        .q(regs$581$q),
        .clock(regs$581$clock)
    );
    top$tc$regs$0 regs$582(
        .d(regs$582$d),
        .q(regs$582$q),
        .clock(regs$582$clock)
    );
    top$tc$regs$0 regs$583(
        .d(regs$583$d),
        .q(regs$583$q),
        .clock(regs$583$clock)
    );
    top$tc$regs$0 regs$584(
        .d(regs$584$d),
        .q(regs$584$q),
        .clock(regs$584$clock)
    );
    top$tc$regs$0 regs$585(
        .d(regs$585$d),
        .q(regs$585$q),
        .clock(regs$585$clock)
    );
    top$tc$regs$0 regs$586(
        .d(regs$586$d),
        .q(regs$586$q),
        .clock(regs$586$clock)
    );
    top$tc$regs$0 regs$587(
        .d(regs$587$d),
        .q(regs$587$q),
        .clock(regs$587$clock)
    );
    top$tc$regs$0 regs$588(
        .d(regs$588$d),
        .q(regs$588$q),
        .clock(regs$588$clock)
    );
    top$tc$regs$0 regs$589(
        .d(regs$589$d),
        .q(regs$589$q),
        .clock(regs$589$clock)
    );
    top$tc$regs$0 regs$590(
        .d(regs$590$d),
        .q(regs$590$q),
        .clock(regs$590$clock)
    );
    top$tc$regs$0 regs$591(
        .d(regs$591$d),
        .q(regs$591$q),
        .clock(regs$591$clock)
    );
    top$tc$regs$0 regs$592(
        .d(regs$592$d),
        .q(regs$592$q),
        .clock(regs$592$clock)
    );
    top$tc$regs$0 regs$593(
        .d(regs$593$d),
        .q(regs$593$q),
        .clock(regs$593$clock)
    );
    top$tc$regs$0 regs$594(
        .d(regs$594$d),
        .q(regs$594$q),
        .clock(regs$594$clock)
    );
    top$tc$regs$0 regs$595(
        .d(regs$595$d),
        .q(regs$595$q),
        .clock(regs$595$clock)
    );
    top$tc$regs$0 regs$596(
        .d(regs$596$d),
        .q(regs$596$q),
        .clock(regs$596$clock)
    );
    top$tc$regs$0 regs$597(
        .d(regs$597$d),
        .q(regs$597$q),
        .clock(regs$597$clock)
    );
    top$tc$regs$0 regs$598(
        .d(regs$598$d),
        .q(regs$598$q),
        .clock(regs$598$clock)
    );
    top$tc$regs$0 regs$599(
        .d(regs$599$d),
        .q(regs$599$q),
        .clock(regs$599$clock)
    );
    top$tc$regs$0 regs$600(
        .d(regs$600$d),
        .q(regs$600$q),
        .clock(regs$600$clock)
    );
    top$tc$regs$0 regs$601(
        .d(regs$601$d),
        .q(regs$601$q),
        .clock(regs$601$clock)
    );
    top$tc$regs$0 regs$602(
        .d(regs$602$d),
        .q(regs$602$q),
        .clock(regs$602$clock)
    );
    top$tc$regs$0 regs$603(
        .d(regs$603$d),
        .q(regs$603$q),
        .clock(regs$603$clock)
    );
    top$tc$regs$0 regs$604(
        .d(regs$604$d),
        .q(regs$604$q),
        .clock(regs$604$clock)
    );
    top$tc$regs$0 regs$605(
        .d(regs$605$d),
        .q(regs$605$q),
        .clock(regs$605$clock)
    );
    top$tc$regs$0 regs$606(
        .d(regs$606$d),
        .q(regs$606$q),
        .clock(regs$606$clock)
    );
    top$tc$regs$0 regs$607(
        .d(regs$607$d),
        .q(regs$607$q),
        .clock(regs$607$clock)
    );
    top$tc$regs$0 regs$608(
        .d(regs$608$d),
        .q(regs$608$q),
        .clock(regs$608$clock)
    );
    top$tc$regs$0 regs$609(
        .d(regs$609$d),
        .q(regs$609$q),
        .clock(regs$609$clock)
    );
    top$tc$regs$0 regs$610(
        .d(regs$610$d),
        .q(regs$610$q),
        .clock(regs$610$clock)
    );
    top$tc$regs$0 regs$611(
        .d(regs$611$d),
        .q(regs$611$q),
        .clock(regs$611$clock)
    );
    top$tc$regs$0 regs$612(
        .d(regs$612$d),
        .q(regs$612$q),
        .clock(regs$612$clock)
    );
    top$tc$regs$0 regs$613(
        .d(regs$613$d),
        .q(regs$613$q),
        .clock(regs$613$clock)
    );
    top$tc$regs$0 regs$614(
        .d(regs$614$d),
        .q(regs$614$q),
        .clock(regs$614$clock)
    );
    top$tc$regs$0 regs$615(
        .d(regs$615$d),
        .q(regs$615$q),
        .clock(regs$615$clock)
    );
    top$tc$regs$0 regs$616(
        .d(regs$616$d),
        .q(regs$616$q),
        .clock(regs$616$clock)
    );
    top$tc$regs$0 regs$617(
        .d(regs$617$d),
        .q(regs$617$q),
        .clock(regs$617$clock)
    );
    top$tc$regs$0 regs$618(
        .d(regs$618$d),
        .q(regs$618$q),
        .clock(regs$618$clock)
    );
    top$tc$regs$0 regs$619(
        .d(regs$619$d),
        .q(regs$619$q),
        .clock(regs$619$clock)
    );
    top$tc$regs$0 regs$620(
        .d(regs$620$d),
        .q(regs$620$q),
        .clock(regs$620$clock)
    );
    top$tc$regs$0 regs$621(
        .d(regs$621$d),
        .q(regs$621$q),
        .clock(regs$621$clock)
    );
    top$tc$regs$0 regs$622(
        .d(regs$622$d),
        .q(regs$622$q),
        .clock(regs$622$clock)
    );
    top$tc$regs$0 regs$623(
        .d(regs$623$d),
        .q(regs$623$q),
        .clock(regs$623$clock)
    );
    top$tc$regs$0 regs$624(
        .d(regs$624$d),
        .q(regs$624$q),
        .clock(regs$624$clock)
    );
    top$tc$regs$0 regs$625(
        .d(regs$625$d),
        .q(regs$625$q),
        .clock(regs$625$clock)
    );
    top$tc$regs$0 regs$626(
        .d(regs$626$d),
        .q(regs$626$q),
        .clock(regs$626$clock)
    );
    top$tc$regs$0 regs$627(
        .d(regs$627$d),
        .q(regs$627$q),
        .clock(regs$627$clock)
    );
    top$tc$regs$0 regs$628(
        .d(regs$628$d),
        .q(regs$628$q),
        .clock(regs$628$clock)
    );
    top$tc$regs$0 regs$629(
        .d(regs$629$d),
        .q(regs$629$q),
        .clock(regs$629$clock)
    );
    top$tc$regs$0 regs$630(
        .d(regs$630$d),
        .q(regs$630$q),
        .clock(regs$630$clock)
    );
    top$tc$regs$0 regs$631(
        .d(regs$631$d),
        .q(regs$631$q),
        .clock(regs$631$clock)
    );
    top$tc$regs$0 regs$632(
        .d(regs$632$d),
        .q(regs$632$q),
        .clock(regs$632$clock)
    );
    top$tc$regs$0 regs$633(
        .d(regs$633$d),
        .q(regs$633$q),
        .clock(regs$633$clock)
    );
    top$tc$regs$0 regs$634(
        .d(regs$634$d),
        .q(regs$634$q),
        .clock(regs$634$clock)
    );
    top$tc$regs$0 regs$635(
        .d(regs$635$d),
        .q(regs$635$q),
        .clock(regs$635$clock)
    );
    top$tc$regs$0 regs$636(
        .d(regs$636$d),
        .q(regs$636$q),
        .clock(regs$636$clock)
    );
    top$tc$regs$0 regs$637(
        .d(regs$637$d),
        .q(regs$637$q),
        .clock(regs$637$clock)
    );
    top$tc$regs$0 regs$638(
        .d(regs$638$d),
        .q(regs$638$q),
        .clock(regs$638$clock)
    );
    top$tc$regs$0 regs$639(
        .d(regs$639$d),
        .q(regs$639$q),
        .clock(regs$639$clock)
    );
    top$tc$regs$0 regs$640(
        .d(regs$640$d),
        .q(regs$640$q),
        .clock(regs$640$clock)
    );
    top$tc$regs$0 regs$641(
        .d(regs$641$d),
        .q(regs$641$q),
        .clock(regs$641$clock)
    );
    top$tc$regs$0 regs$642(
        .d(regs$642$d),
        .q(regs$642$q),
        .clock(regs$642$clock)
    );
    top$tc$regs$0 regs$643(
        .d(regs$643$d),
        .q(regs$643$q),
        .clock(regs$643$clock)
    );
    top$tc$regs$0 regs$644(
        .d(regs$644$d),
        .q(regs$644$q),
        .clock(regs$644$clock)
    );
    top$tc$regs$0 regs$645(
        .d(regs$645$d),
        .q(regs$645$q),
        .clock(regs$645$clock)
    );
    top$tc$regs$0 regs$646(
        .d(regs$646$d),
        .q(regs$646$q),
        .clock(regs$646$clock)
    );
    top$tc$regs$0 regs$647(
        .d(regs$647$d),
        .q(regs$647$q),
        .clock(regs$647$clock)
    );
    top$tc$regs$0 regs$648(
        .d(regs$648$d),
        .q(regs$648$q),
        .clock(regs$648$clock)
    );
    top$tc$regs$0 regs$649(
        .d(regs$649$d),
        .q(regs$649$q),
        .clock(regs$649$clock)
    );
    top$tc$regs$0 regs$650(
        .d(regs$650$d),
        .q(regs$650$q),
        .clock(regs$650$clock)
    );
    top$tc$regs$0 regs$651(
        .d(regs$651$d),
        .q(regs$651$q),
        .clock(regs$651$clock)
    );
    top$tc$regs$0 regs$652(
        .d(regs$652$d),
        .q(regs$652$q),
        .clock(regs$652$clock)
    );
    top$tc$regs$0 regs$653(
        .d(regs$653$d),
        .q(regs$653$q),
        .clock(regs$653$clock)
    );
    top$tc$regs$0 regs$654(
        .d(regs$654$d),
        .q(regs$654$q),
        .clock(regs$654$clock)
    );
    top$tc$regs$0 regs$655(
        .d(regs$655$d),
        .q(regs$655$q),
        .clock(regs$655$clock)
    );
    top$tc$regs$0 regs$656(
        .d(regs$656$d),
        .q(regs$656$q),
        .clock(regs$656$clock)
    );
    top$tc$regs$0 regs$657(
        .d(regs$657$d),
        .q(regs$657$q),
        .clock(regs$657$clock)
    );
    top$tc$regs$0 regs$658(
        .d(regs$658$d),
        .q(regs$658$q),
        .clock(regs$658$clock)
    );
    top$tc$regs$0 regs$659(
        .d(regs$659$d),
        .q(regs$659$q),
        .clock(regs$659$clock)
    );
    top$tc$regs$0 regs$660(
        .d(regs$660$d),
        .q(regs$660$q),
        .clock(regs$660$clock)
    );
    top$tc$regs$0 regs$661(
        .d(regs$661$d),
        .q(regs$661$q),
        .clock(regs$661$clock)
    );
    top$tc$regs$0 regs$662(
        .d(regs$662$d),
        .q(regs$662$q),
        .clock(regs$662$clock)
    );
    top$tc$regs$0 regs$663(
        .d(regs$663$d),
        .q(regs$663$q),
        .clock(regs$663$clock)
    );
    top$tc$regs$0 regs$664(
        .d(regs$664$d),
        .q(regs$664$q),
        .clock(regs$664$clock)
    );
    top$tc$regs$0 regs$665(
        .d(regs$665$d),
        .q(regs$665$q),
        .clock(regs$665$clock)
    );
    top$tc$regs$0 regs$666(
        .d(regs$666$d),
        .q(regs$666$q),
        .clock(regs$666$clock)
    );
    top$tc$regs$0 regs$667(
        .d(regs$667$d),
        .q(regs$667$q),
        .clock(regs$667$clock)
    );
    top$tc$regs$0 regs$668(
        .d(regs$668$d),
        .q(regs$668$q),
        .clock(regs$668$clock)
    );
    top$tc$regs$0 regs$669(
        .d(regs$669$d),
        .q(regs$669$q),
        .clock(regs$669$clock)
    );
    top$tc$regs$0 regs$670(
        .d(regs$670$d),
        .q(regs$670$q),
        .clock(regs$670$clock)
    );
    top$tc$regs$0 regs$671(
        .d(regs$671$d),
        .q(regs$671$q),
        .clock(regs$671$clock)
    );
    top$tc$regs$0 regs$672(
        .d(regs$672$d),
        .q(regs$672$q),
        .clock(regs$672$clock)
    );
    top$tc$regs$0 regs$673(
        .d(regs$673$d),
        .q(regs$673$q),
        .clock(regs$673$clock)
    );
    top$tc$regs$0 regs$674(
        .d(regs$674$d),
        .q(regs$674$q),
        .clock(regs$674$clock)
    );
    top$tc$regs$0 regs$675(
        .d(regs$675$d),
        .q(regs$675$q),
        .clock(regs$675$clock)
    );
    top$tc$regs$0 regs$676(
        .d(regs$676$d),
        .q(regs$676$q),
        .clock(regs$676$clock)
    );
    top$tc$regs$0 regs$677(
        .d(regs$677$d),
        .q(regs$677$q),
        .clock(regs$677$clock)
    );
    top$tc$regs$0 regs$678(
        .d(regs$678$d),
        .q(regs$678$q),
        .clock(regs$678$clock)
    );
    top$tc$regs$0 regs$679(
        .d(regs$679$d),
        .q(regs$679$q),
        .clock(regs$679$clock)
    );
    top$tc$regs$0 regs$680(
        .d(regs$680$d),
        .q(regs$680$q),
        .clock(regs$680$clock)
    );
    top$tc$regs$0 regs$681(
        .d(regs$681$d),
        .q(regs$681$q),
        .clock(regs$681$clock)
    );
    top$tc$regs$0 regs$682(
        .d(regs$682$d),
        .q(regs$682$q),
        .clock(regs$682$clock)
    );
    top$tc$regs$0 regs$683(
        .d(regs$683$d),
        .q(regs$683$q),
        .clock(regs$683$clock)
    );
    top$tc$regs$0 regs$684(
        .d(regs$684$d),
        .q(regs$684$q),
        .clock(regs$684$clock)
    );
    top$tc$regs$0 regs$685(
        .d(regs$685$d),
        .q(regs$685$q),
        .clock(regs$685$clock)
    );
    top$tc$regs$0 regs$686(
        .d(regs$686$d),
        .q(regs$686$q),
        .clock(regs$686$clock)
    );
    top$tc$regs$0 regs$687(
        .d(regs$687$d),
        .q(regs$687$q),
        .clock(regs$687$clock)
    );
    top$tc$regs$0 regs$688(
        .d(regs$688$d),
        .q(regs$688$q),
        .clock(regs$688$clock)
    );
    top$tc$regs$0 regs$689(
        .d(regs$689$d),
        .q(regs$689$q),
        .clock(regs$689$clock)
    );
    top$tc$regs$0 regs$690(
        .d(regs$690$d),
        .q(regs$690$q),
        .clock(regs$690$clock)
    );
    top$tc$regs$0 regs$691(
        .d(regs$691$d),
        .q(regs$691$q),
        .clock(regs$691$clock)
    );
    top$tc$regs$0 regs$692(
        .d(regs$692$d),
        .q(regs$692$q),
        .clock(regs$692$clock)
    );
    top$tc$regs$0 regs$693(
        .d(regs$693$d),
        .q(regs$693$q),
        .clock(regs$693$clock)
    );
    top$tc$regs$0 regs$694(
        .d(regs$694$d),
        .q(regs$694$q),
        .clock(regs$694$clock)
    );
    top$tc$regs$0 regs$695(
        .d(regs$695$d),
        .q(regs$695$q),
        .clock(regs$695$clock)
    );
    top$tc$regs$0 regs$696(
        .d(regs$696$d),
        .q(regs$696$q),
        .clock(regs$696$clock)
    );
    top$tc$regs$0 regs$697(
        .d(regs$697$d),
        .q(regs$697$q),
        .clock(regs$697$clock)
    );
    top$tc$regs$0 regs$698(
        .d(regs$698$d),
        .q(regs$698$q),
        .clock(regs$698$clock)
    );
    top$tc$regs$0 regs$699(
        .d(regs$699$d),
        .q(regs$699$q),
        .clock(regs$699$clock)
    );
    top$tc$regs$0 regs$700(
        .d(regs$700$d),
        .q(regs$700$q),
        .clock(regs$700$clock)
    );
    top$tc$regs$0 regs$701(
        .d(regs$701$d),
        .q(regs$701$q),
        .clock(regs$701$clock)
    );
    top$tc$regs$0 regs$702(
        .d(regs$702$d),
        .q(regs$702$q),
        .clock(regs$702$clock)
    );
    top$tc$regs$0 regs$703(
        .d(regs$703$d),
        .q(regs$703$q),
        .clock(regs$703$clock)
    );
    top$tc$regs$0 regs$704(
        .d(regs$704$d),
        .q(regs$704$q),
        .clock(regs$704$clock)
    );
    top$tc$regs$0 regs$705(
        .d(regs$705$d),
        .q(regs$705$q),
        .clock(regs$705$clock)
    );
    top$tc$regs$0 regs$706(
        .d(regs$706$d),
        .q(regs$706$q),
        .clock(regs$706$clock)
    );
    top$tc$regs$0 regs$707(
        .d(regs$707$d),
        .q(regs$707$q),
        .clock(regs$707$clock)
    );
    top$tc$regs$0 regs$708(
        .d(regs$708$d),
        .q(regs$708$q),
        .clock(regs$708$clock)
    );
    top$tc$regs$0 regs$709(
        .d(regs$709$d),
        .q(regs$709$q),
        .clock(regs$709$clock)
    );
    top$tc$regs$0 regs$710(
        .d(regs$710$d),
        .q(regs$710$q),
        .clock(regs$710$clock)
    );
    top$tc$regs$0 regs$711(
        .d(regs$711$d),
        .q(regs$711$q),
        .clock(regs$711$clock)
    );
    top$tc$regs$0 regs$712(
        .d(regs$712$d),
        .q(regs$712$q),
        .clock(regs$712$clock)
    );
    top$tc$regs$0 regs$713(
        .d(regs$713$d),
        .q(regs$713$q),
        .clock(regs$713$clock)
    );
    top$tc$regs$0 regs$714(
        .d(regs$714$d),
        .q(regs$714$q),
        .clock(regs$714$clock)
    );
    top$tc$regs$0 regs$715(
        .d(regs$715$d),
        .q(regs$715$q),
        .clock(regs$715$clock)
    );
    top$tc$regs$0 regs$716(
        .d(regs$716$d),
        .q(regs$716$q),
        .clock(regs$716$clock)
    );
    top$tc$regs$0 regs$717(
        .d(regs$717$d),
        .q(regs$717$q),
        .clock(regs$717$clock)
    );
    top$tc$regs$0 regs$718(
        .d(regs$718$d),
        .q(regs$718$q),
        .clock(regs$718$clock)
    );
    top$tc$regs$0 regs$719(
        .d(regs$719$d),
        .q(regs$719$q),
        .clock(regs$719$clock)
    );
    top$tc$regs$0 regs$720(
        .d(regs$720$d),
        .q(regs$720$q),
        .clock(regs$720$clock)
    );
    top$tc$regs$0 regs$721(
        .d(regs$721$d),
        .q(regs$721$q),
        .clock(regs$721$clock)
    );
    top$tc$regs$0 regs$722(
        .d(regs$722$d),
        .q(regs$722$q),
        .clock(regs$722$clock)
    );
    top$tc$regs$0 regs$723(
        .d(regs$723$d),
        .q(regs$723$q),
        .clock(regs$723$clock)
    );
    top$tc$regs$0 regs$724(
        .d(regs$724$d),
        .q(regs$724$q),
        .clock(regs$724$clock)
    );
    top$tc$regs$0 regs$725(
        .d(regs$725$d),
        .q(regs$725$q),
        .clock(regs$725$clock)
    );
    top$tc$regs$0 regs$726(
        .d(regs$726$d),
        .q(regs$726$q),
        .clock(regs$726$clock)
    );
    top$tc$regs$0 regs$727(
        .d(regs$727$d),
        .q(regs$727$q),
        .clock(regs$727$clock)
    );
    top$tc$regs$0 regs$728(
        .d(regs$728$d),
        .q(regs$728$q),
        .clock(regs$728$clock)
    );
    top$tc$regs$0 regs$729(
        .d(regs$729$d),
        .q(regs$729$q),
        .clock(regs$729$clock)
    );
    top$tc$regs$0 regs$730(
        .d(regs$730$d),
        .q(regs$730$q),
        .clock(regs$730$clock)
    );
    top$tc$regs$0 regs$731(
        .d(regs$731$d),
        .q(regs$731$q),
        .clock(regs$731$clock)
    );
    top$tc$regs$0 regs$732(
        .d(regs$732$d),
        .q(regs$732$q),
        .clock(regs$732$clock)
    );
    top$tc$regs$0 regs$733(
        .d(regs$733$d),
        .q(regs$733$q),
        .clock(regs$733$clock)
    );
    top$tc$regs$0 regs$734(
        .d(regs$734$d),
        .q(regs$734$q),
        .clock(regs$734$clock)
    );
    top$tc$regs$0 regs$735(
        .d(regs$735$d),
        .q(regs$735$q),
        .clock(regs$735$clock)
    );
    top$tc$regs$0 regs$736(
        .d(regs$736$d),
        .q(regs$736$q),
        .clock(regs$736$clock)
    );
    top$tc$regs$0 regs$737(
        .d(regs$737$d),
        .q(regs$737$q),
        .clock(regs$737$clock)
    );
    top$tc$regs$0 regs$738(
        .d(regs$738$d),
        .q(regs$738$q),
        .clock(regs$738$clock)
    );
    top$tc$regs$0 regs$739(
        .d(regs$739$d),
        .q(regs$739$q),
        .clock(regs$739$clock)
    );
    top$tc$regs$0 regs$740(
        .d(regs$740$d),
        .q(regs$740$q),
        .clock(regs$740$clock)
    );
    top$tc$regs$0 regs$741(
        .d(regs$741$d),
        .q(regs$741$q),
        .clock(regs$741$clock)
    );
    top$tc$regs$0 regs$742(
        .d(regs$742$d),
        .q(regs$742$q),
        .clock(regs$742$clock)
    );
    top$tc$regs$0 regs$743(
        .d(regs$743$d),
        .q(regs$743$q),
        .clock(regs$743$clock)
    );
    top$tc$regs$0 regs$744(
        .d(regs$744$d),
        .q(regs$744$q),
        .clock(regs$744$clock)
    );
    top$tc$regs$0 regs$745(
        .d(regs$745$d),
        .q(regs$745$q),
        .clock(regs$745$clock)
    );
    top$tc$regs$0 regs$746(
        .d(regs$746$d),
        .q(regs$746$q),
        .clock(regs$746$clock)
    );
    top$tc$regs$0 regs$747(
        .d(regs$747$d),
        .q(regs$747$q),
        .clock(regs$747$clock)
    );
    top$tc$regs$0 regs$748(
        .d(regs$748$d),
        .q(regs$748$q),
        .clock(regs$748$clock)
    );
    top$tc$regs$0 regs$749(
        .d(regs$749$d),
        .q(regs$749$q),
        .clock(regs$749$clock)
    );
    top$tc$regs$0 regs$750(
        .d(regs$750$d),
        .q(regs$750$q),
        .clock(regs$750$clock)
    );
    top$tc$regs$0 regs$751(
        .d(regs$751$d),
        .q(regs$751$q),
        .clock(regs$751$clock)
    );
    top$tc$regs$0 regs$752(
        .d(regs$752$d),
        .q(regs$752$q),
        .clock(regs$752$clock)
    );
    top$tc$regs$0 regs$753(
        .d(regs$753$d),
        .q(regs$753$q),
        .clock(regs$753$clock)
    );
    top$tc$regs$0 regs$754(
        .d(regs$754$d),
        .q(regs$754$q),
        .clock(regs$754$clock)
    );
    top$tc$regs$0 regs$755(
        .d(regs$755$d),
        .q(regs$755$q),
        .clock(regs$755$clock)
    );
    top$tc$regs$0 regs$756(
        .d(regs$756$d),
        .q(regs$756$q),
        .clock(regs$756$clock)
    );
    top$tc$regs$0 regs$757(
        .d(regs$757$d),
        .q(regs$757$q),
        .clock(regs$757$clock)
    );
    top$tc$regs$0 regs$758(
        .d(regs$758$d),
        .q(regs$758$q),
        .clock(regs$758$clock)
    );
    top$tc$regs$0 regs$759(
        .d(regs$759$d),
        .q(regs$759$q),
        .clock(regs$759$clock)
    );
    top$tc$regs$0 regs$760(
        .d(regs$760$d),
        .q(regs$760$q),
        .clock(regs$760$clock)
    );
    top$tc$regs$0 regs$761(
        .d(regs$761$d),
        .q(regs$761$q),
        .clock(regs$761$clock)
    );
    top$tc$regs$0 regs$762(
        .d(regs$762$d),
        .q(regs$762$q),
        .clock(regs$762$clock)
    );
    top$tc$regs$0 regs$763(
        .d(regs$763$d),
        .q(regs$763$q),
        .clock(regs$763$clock)
    );
    top$tc$regs$0 regs$764(
        .d(regs$764$d),
        .q(regs$764$q),
        .clock(regs$764$clock)
    );
    top$tc$regs$0 regs$765(
        .d(regs$765$d),
        .q(regs$765$q),
        .clock(regs$765$clock)
    );
    top$tc$regs$0 regs$766(
        .d(regs$766$d),
        .q(regs$766$q),
        .clock(regs$766$clock)
    );
    top$tc$regs$0 regs$767(
        .d(regs$767$d),
        .q(regs$767$q),
        .clock(regs$767$clock)
    );
    top$tc$regs$0 regs$768(
        .d(regs$768$d),
        .q(regs$768$q),
        .clock(regs$768$clock)
    );
    top$tc$regs$0 regs$769(
        .d(regs$769$d),
        .q(regs$769$q),
        .clock(regs$769$clock)
    );
    top$tc$regs$0 regs$770(
        .d(regs$770$d),
        .q(regs$770$q),
        .clock(regs$770$clock)
    );
    top$tc$regs$0 regs$771(
        .d(regs$771$d),
        .q(regs$771$q),
        .clock(regs$771$clock)
    );
    top$tc$regs$0 regs$772(
        .d(regs$772$d),
        .q(regs$772$q),
        .clock(regs$772$clock)
    );
    top$tc$regs$0 regs$773(
        .d(regs$773$d),
        .q(regs$773$q),
        .clock(regs$773$clock)
    );
    top$tc$regs$0 regs$774(
        .d(regs$774$d),
        .q(regs$774$q),
        .clock(regs$774$clock)
    );
    top$tc$regs$0 regs$775(
        .d(regs$775$d),
        .q(regs$775$q),
        .clock(regs$775$clock)
    );
    top$tc$regs$0 regs$776(
        .d(regs$776$d),
        .q(regs$776$q),
        .clock(regs$776$clock)
    );
    top$tc$regs$0 regs$777(
        .d(regs$777$d),
        .q(regs$777$q),
        .clock(regs$777$clock)
    );
    top$tc$regs$0 regs$778(
        .d(regs$778$d),
        .q(regs$778$q),
        .clock(regs$778$clock)
    );
    top$tc$regs$0 regs$779(
        .d(regs$779$d),
        .q(regs$779$q),
        .clock(regs$779$clock)
    );
    top$tc$regs$0 regs$780(
        .d(regs$780$d),
        .q(regs$780$q),
        .clock(regs$780$clock)
    );
    top$tc$regs$0 regs$781(
        .d(regs$781$d),
        .q(regs$781$q),
        .clock(regs$781$clock)
    );
    top$tc$regs$0 regs$782(
        .d(regs$782$d),
        .q(regs$782$q),
        .clock(regs$782$clock)
    );
    top$tc$regs$0 regs$783(
        .d(regs$783$d),
        .q(regs$783$q),
        .clock(regs$783$clock)
    );
    top$tc$regs$0 regs$784(
        .d(regs$784$d),
        .q(regs$784$q),
        .clock(regs$784$clock)
    );
    top$tc$regs$0 regs$785(
        .d(regs$785$d),
        .q(regs$785$q),
        .clock(regs$785$clock)
    );
    top$tc$regs$0 regs$786(
        .d(regs$786$d),
        .q(regs$786$q),
        .clock(regs$786$clock)
    );
    top$tc$regs$0 regs$787(
        .d(regs$787$d),
        .q(regs$787$q),
        .clock(regs$787$clock)
    );
    top$tc$regs$0 regs$788(
        .d(regs$788$d),
        .q(regs$788$q),
        .clock(regs$788$clock)
    );
    top$tc$regs$0 regs$789(
        .d(regs$789$d),
        .q(regs$789$q),
        .clock(regs$789$clock)
    );
    top$tc$regs$0 regs$790(
        .d(regs$790$d),
        .q(regs$790$q),
        .clock(regs$790$clock)
    );
    top$tc$regs$0 regs$791(
        .d(regs$791$d),
        .q(regs$791$q),
        .clock(regs$791$clock)
    );
    top$tc$regs$0 regs$792(
        .d(regs$792$d),
        .q(regs$792$q),
        .clock(regs$792$clock)
    );
    top$tc$regs$0 regs$793(
        .d(regs$793$d),
        .q(regs$793$q),
        .clock(regs$793$clock)
    );
    top$tc$regs$0 regs$794(
        .d(regs$794$d),
        .q(regs$794$q),
        .clock(regs$794$clock)
    );
    top$tc$regs$0 regs$795(
        .d(regs$795$d),
        .q(regs$795$q),
        .clock(regs$795$clock)
    );
    top$tc$regs$0 regs$796(
        .d(regs$796$d),
        .q(regs$796$q),
        .clock(regs$796$clock)
    );
    top$tc$regs$0 regs$797(
        .d(regs$797$d),
        .q(regs$797$q),
        .clock(regs$797$clock)
    );
    top$tc$regs$0 regs$798(
        .d(regs$798$d),
        .q(regs$798$q),
        .clock(regs$798$clock)
    );
    top$tc$regs$0 regs$799(
        .d(regs$799$d),
        .q(regs$799$q),
        .clock(regs$799$clock)
    );
    top$tc$regs$0 regs$800(
        .d(regs$800$d),
        .q(regs$800$q),
        .clock(regs$800$clock)
    );
    top$tc$regs$0 regs$801(
        .d(regs$801$d),
        .q(regs$801$q),
        .clock(regs$801$clock)
    );
    top$tc$regs$0 regs$802(
        .d(regs$802$d),
        .q(regs$802$q),
        .clock(regs$802$clock)
    );
    top$tc$regs$0 regs$803(
        .d(regs$803$d),
        .q(regs$803$q),
        .clock(regs$803$clock)
    );
    top$tc$regs$0 regs$804(
        .d(regs$804$d),
        .q(regs$804$q),
        .clock(regs$804$clock)
    );
    top$tc$regs$0 regs$805(
        .d(regs$805$d),
        .q(regs$805$q),
        .clock(regs$805$clock)
    );
    top$tc$regs$0 regs$806(
        .d(regs$806$d),
        .q(regs$806$q),
        .clock(regs$806$clock)
    );
    top$tc$regs$0 regs$807(
        .d(regs$807$d),
        .q(regs$807$q),
        .clock(regs$807$clock)
    );
    top$tc$regs$0 regs$808(
        .d(regs$808$d),
        .q(regs$808$q),
        .clock(regs$808$clock)
    );
    top$tc$regs$0 regs$809(
        .d(regs$809$d),
        .q(regs$809$q),
        .clock(regs$809$clock)
    );
    top$tc$regs$0 regs$810(
        .d(regs$810$d),
        .q(regs$810$q),
        .clock(regs$810$clock)
    );
    top$tc$regs$0 regs$811(
        .d(regs$811$d),
        .q(regs$811$q),
        .clock(regs$811$clock)
    );
    top$tc$regs$0 regs$812(
        .d(regs$812$d),
        .q(regs$812$q),
        .clock(regs$812$clock)
    );
    top$tc$regs$0 regs$813(
        .d(regs$813$d),
        .q(regs$813$q),
        .clock(regs$813$clock)
    );
    top$tc$regs$0 regs$814(
        .d(regs$814$d),
        .q(regs$814$q),
        .clock(regs$814$clock)
    );
    top$tc$regs$0 regs$815(
        .d(regs$815$d),
        .q(regs$815$q),
        .clock(regs$815$clock)
    );
    top$tc$regs$0 regs$816(
        .d(regs$816$d),
        .q(regs$816$q),
        .clock(regs$816$clock)
    );
    top$tc$regs$0 regs$817(
        .d(regs$817$d),
        .q(regs$817$q),
        .clock(regs$817$clock)
    );
    top$a_deg exact$0(
        .d(exact$0$d),
        .q(exact$0$q),
        .clock(exact$0$clock)
    );
    top$a_deg exact$1(
        .d(exact$1$d),
        .q(exact$1$q),
        .clock(exact$1$clock)
    );
    top$a_deg exact$2(
        .d(exact$2$d),
        .q(exact$2$q),
        .clock(exact$2$clock)
    );
    top$a_deg exact$3(
        .d(exact$3$d),
        .q(exact$3$q),
        .clock(exact$3$clock)
    );
    top$a_deg valid$0(
        .d(valid$0$d),
        .q(valid$0$q),
        .clock(valid$0$clock)
    );
    top$a_deg valid$1(
        .d(valid$1$d),
        .q(valid$1$q),
        .clock(valid$1$clock)
    );
    top$a_deg valid$2(
        .d(valid$2$d),
        .q(valid$2$q),
        .clock(valid$2$clock)
    );
    top$a_deg valid$3(
        .d(valid$3$d),
        .q(valid$3$q),
        .clock(valid$3$clock)
    );
    top$a_deg valid$4(
        .d(valid$4$d),
        .q(valid$4$q),
        .clock(valid$4$clock)
    );
    top$a_deg valid$5(
        .d(valid$5$d),
        .q(valid$5$q),
        .clock(valid$5$clock)
    );
    top$a_deg valid$6(
        .d(valid$6$d),
        .q(valid$6$q),
        .clock(valid$6$clock)
    );
    top$a_deg valid$7(
        .d(valid$7$d),
        .q(valid$7$q),
        .clock(valid$7$clock)
    );
    top$a_deg valid$8(
        .d(valid$8$d),
        .q(valid$8$q),
        .clock(valid$8$clock)
    );
    top$a_deg valid$9(
        .d(valid$9$d),
        .q(valid$9$q),
        .clock(valid$9$clock)
    );
    top$held_tag tags$0(
        .d(tags$0$d),
        .q(tags$0$q),
        .clock(tags$0$clock)
    );
    top$held_tag tags$1(
        .d(tags$1$d),
        .q(tags$1$q),
        .clock(tags$1$clock)
    );
    top$held_tag tags$2(
        .d(tags$2$d),
        .q(tags$2$q),
        .clock(tags$2$clock)
    );
    top$held_tag tags$3(
        .d(tags$3$d),
        .q(tags$3$q),
        .clock(tags$3$clock)
    );
    top$held_tag tags$4(
        .d(tags$4$d),
        .q(tags$4$q),
        .clock(tags$4$clock)
    );
    top$held_tag tags$5(
        .d(tags$5$d),
        .q(tags$5$q),
        .clock(tags$5$clock)
    );
    top$held_tag tags$6(
        .d(tags$6$d),
        .q(tags$6$q),
        .clock(tags$6$clock)
    );
    top$held_tag tags$7(
        .d(tags$7$d),
        .q(tags$7$q),
        .clock(tags$7$clock)
    );
    top$held_tag tags$8(
        .d(tags$8$d),
        .q(tags$8$q),
        .clock(tags$8$clock)
    );
    top$held_tag tags$9(
        .d(tags$9$d),
        .q(tags$9$q),
        .clock(tags$9$clock)
    );
    top$tc$cnt$0 cnt$0(
        .d(cnt$0$d),
        .q(cnt$0$q),
        .clock(cnt$0$clock)
    );
    top$tc$cnt$0 cnt$1(
        .d(cnt$1$d),
        .q(cnt$1$q),
        .clock(cnt$1$clock)
    );
    top$tc$cnt$0 cnt$2(
        .d(cnt$2$d),
        .q(cnt$2$q),
        .clock(cnt$2$clock)
    );
    top$tc$cnt$0 cnt$3(
        .d(cnt$3$d),
        .q(cnt$3$q),
        .clock(cnt$3$clock)
    );
    top$tc$cnt$0 cnt$4(
        .d(cnt$4$d),
        .q(cnt$4$q),
        .clock(cnt$4$clock)
    );
    top$tc$cnt$0 cnt$5(
        .d(cnt$5$d),
        .q(cnt$5$q),
        .clock(cnt$5$clock)
    );
    top$tc$cnt$0 cnt$6(
        .d(cnt$6$d),
        .q(cnt$6$q),
        .clock(cnt$6$clock)
    );
    top$tc$cnt$0 cnt$7(
        .d(cnt$7$d),
        .q(cnt$7$q),
        .clock(cnt$7$clock)
    );
    top$tc$cnt$0 cnt$8(
        .d(cnt$8$d),
        .q(cnt$8$q),
        .clock(cnt$8$clock)
    );
    top$tc$cnt$0 cnt$9(
        .d(cnt$9$d),
        .q(cnt$9$q),
        .clock(cnt$9$clock)
    );
    top$tc$cnt$0 cnt$10(
        .d(cnt$10$d),
        .q(cnt$10$q),
        .clock(cnt$10$clock)
    );
    top$tc$cnt$0 cnt$11(
        .d(cnt$11$d),
        .q(cnt$11$q),
        .clock(cnt$11$clock)
    );
    top$tc$cnt$0 cnt$12(
        .d(cnt$12$d),
        .q(cnt$12$q),
        .clock(cnt$12$clock)
    );
    top$tc$cnt$0 cnt$13(
        .d(cnt$13$d),
        .q(cnt$13$q),
        .clock(cnt$13$clock)
    );
    top$tc$cnt$0 cnt$14(
        .d(cnt$14$d),
        .q(cnt$14$q),
        .clock(cnt$14$clock)
    );
    top$tc$cnt$0 cnt$15(
        .d(cnt$15$d),
        .q(cnt$15$q),
        .clock(cnt$15$clock)
    );
    top$tc$cnt$0 cnt$16(
        .d(cnt$16$d),
        .q(cnt$16$q),
        .clock(cnt$16$clock)
    );
    top$tc$cnt$0 cnt$17(
        .d(cnt$17$d),
        .q(cnt$17$q),
        .clock(cnt$17$clock)
    );
    top$tc$cnt$0 cnt$18(
        .d(cnt$18$d),
        .q(cnt$18$q),
        .clock(cnt$18$clock)
    );
    top$tc$cnt$0 cnt$19(
        .d(cnt$19$d),
        .q(cnt$19$q),
        .clock(cnt$19$clock)
    );
    top$tc$cnt$0 cnt$20(
        .d(cnt$20$d),
        .q(cnt$20$q),
        .clock(cnt$20$clock)
    );
    top$tc$cnt$0 cnt$21(
        .d(cnt$21$d),
        .q(cnt$21$q),
        .clock(cnt$21$clock)
    );
    top$tc$cnt$0 cnt$22(
        .d(cnt$22$d),
        .q(cnt$22$q),
        .clock(cnt$22$clock)
    );
    top$tc$cnt$0 cnt$23(
        .d(cnt$23$d),
        .q(cnt$23$q),
        .clock(cnt$23$clock)
    );
    top$tc$cnt$0 cnt$24(
        .d(cnt$24$d),
        .q(cnt$24$q),
        .clock(cnt$24$clock)
    );
    top$tc$cnt$0 cnt$25(
        .d(cnt$25$d),
        .q(cnt$25$q),
        .clock(cnt$25$clock)
    );
    top$tc$cnt$0 cnt$26(
        .d(cnt$26$d),
        .q(cnt$26$q),
        .clock(cnt$26$clock)
    );
    top$tc$cnt$0 cnt$27(
        .d(cnt$27$d),
        .q(cnt$27$q),
        .clock(cnt$27$clock)
    );
    top$tc$cnt$0 cnt$28(
        .d(cnt$28$d),
        .q(cnt$28$q),
        .clock(cnt$28$clock)
    );
    top$tc$cnt$0 cnt$29(
        .d(cnt$29$d),
        .q(cnt$29$q),
        .clock(cnt$29$clock)
    );
    top$tc$cnt$0 cnt$30(
        .d(cnt$30$d),
        .q(cnt$30$q),
        .clock(cnt$30$clock)
    );
    top$tc$cnt$0 cnt$31(
        .d(cnt$31$d),
        .q(cnt$31$q),
        .clock(cnt$31$clock)
    );
    top$tc$cnt$0 cnt$32(
        .d(cnt$32$d),
        .q(cnt$32$q),
        .clock(cnt$32$clock)
    );
    top$tc$cnt$0 cnt$33(
        .d(cnt$33$d),
        .q(cnt$33$q),
        .clock(cnt$33$clock)
    );
    top$tc$cnt$0 cnt$34(
        .d(cnt$34$d),
        .q(cnt$34$q),
        .clock(cnt$34$clock)
    );
    top$tc$cnt$0 cnt$35(
        .d(cnt$35$d),
        .q(cnt$35$q),
        .clock(cnt$35$clock)
    );
    top$tc$cnt$0 cnt$36(
        .d(cnt$36$d),
        .q(cnt$36$q),
        .clock(cnt$36$clock)
    );
    top$tc$cnt$0 cnt$37(
        .d(cnt$37$d),
        .q(cnt$37$q),
        .clock(cnt$37$clock)
    );
    top$tc$cnt$0 cnt$38(
        .d(cnt$38$d),
        .q(cnt$38$q),
        .clock(cnt$38$clock)
    );
    top$tc$cnt$0 cnt$39(
        .d(cnt$39$d),
        .q(cnt$39$q),
        .clock(cnt$39$clock)
    );
    top$tc$cnt$0 cnt$40(
        .d(cnt$40$d),
        .q(cnt$40$q),
        .clock(cnt$40$clock)
    );
    top$tc$cnt$0 cnt$41(
        .d(cnt$41$d),
        .q(cnt$41$q),
        .clock(cnt$41$clock)
    );
    top$tc$cnt$0 cnt$42(
        .d(cnt$42$d),
        .q(cnt$42$q),
        .clock(cnt$42$clock)
    );
    top$tc$cnt$0 cnt$43(
        .d(cnt$43$d),
        .q(cnt$43$q),
        .clock(cnt$43$clock)
    );
    top$tc$cnt$0 cnt$44(
        .d(cnt$44$d),
        .q(cnt$44$q),
        .clock(cnt$44$clock)
    );
    top$tc$cnt$0 cnt$45(
        .d(cnt$45$d),
        .q(cnt$45$q),
        .clock(cnt$45$clock)
    );
    top$tc$cnt$0 cnt$46(
        .d(cnt$46$d),
        .q(cnt$46$q),
        .clock(cnt$46$clock)
    );
    top$tc$cnt$0 cnt$47(
        .d(cnt$47$d),
        .q(cnt$47$q),
        .clock(cnt$47$clock)
    );
    top$tc$cnt$0 cnt$48(
        .d(cnt$48$d),
        .q(cnt$48$q),
        .clock(cnt$48$clock)
    );
    top$tc$cnt$0 cnt$49(
        .d(cnt$49$d),
        .q(cnt$49$q),
        .clock(cnt$49$clock)
    );
    top$tc$cnt$0 cnt$50(
        .d(cnt$50$d),
        .q(cnt$50$q),
        .clock(cnt$50$clock)
    );
    top$tc$cnt$0 cnt$51(
        .d(cnt$51$d),
        .q(cnt$51$q),
        .clock(cnt$51$clock)
    );
    top$tc$cnt$0 cnt$52(
        .d(cnt$52$d),
        .q(cnt$52$q),
        .clock(cnt$52$clock)
    );
    top$tc$cnt$0 cnt$53(
        .d(cnt$53$d),
        .q(cnt$53$q),
        .clock(cnt$53$clock)
    );
    top$tc$cnt$0 cnt$54(
        .d(cnt$54$d),
        .q(cnt$54$q),
        .clock(cnt$54$clock)
    );
    top$tc$cnt$0 cnt$55(
        .d(cnt$55$d),
        .q(cnt$55$q),
        .clock(cnt$55$clock)
    );
    top$tc$cnt$0 cnt$56(
        .d(cnt$56$d),
        .q(cnt$56$q),
        .clock(cnt$56$clock)
    );
    top$tc$cnt$0 cnt$57(
        .d(cnt$57$d),
        .q(cnt$57$q),
        .clock(cnt$57$clock)
    );
    top$tc$cnt$0 cnt$58(
        .d(cnt$58$d),
        .q(cnt$58$q),
        .clock(cnt$58$clock)
    );
    top$tc$cnt$0 cnt$59(
        .d(cnt$59$d),
        .q(cnt$59$q),
        .clock(cnt$59$clock)
    );
    top$tc$cnt$0 cnt$60(
        .d(cnt$60$d),
        .q(cnt$60$q),
        .clock(cnt$60$clock)
    );
    top$tc$cnt$0 cnt$61(
        .d(cnt$61$d),
        .q(cnt$61$q),
        .clock(cnt$61$clock)
    );
    top$tc$cnt$0 cnt$62(
        .d(cnt$62$d),
        .q(cnt$62$q),
        .clock(cnt$62$clock)
    );
    top$tc$cnt$0 cnt$63(
        .d(cnt$63$d),
        .q(cnt$63$q),
        .clock(cnt$63$clock)
    );
    top$tc$cnt$0 cnt$64(
        .d(cnt$64$d),
        .q(cnt$64$q),
        .clock(cnt$64$clock)
    );
    top$tc$cnt$0 cnt$65(
        .d(cnt$65$d),
        .q(cnt$65$q),
        .clock(cnt$65$clock)
    );
    top$tc$cnt$0 cnt$66(
        .d(cnt$66$d),
        .q(cnt$66$q),
        .clock(cnt$66$clock)
    );
    top$tc$cnt$0 cnt$67(
        .d(cnt$67$d),
        .q(cnt$67$q),
        .clock(cnt$67$clock)
    );
    top$tc$cnt$0 cnt$68(
        .d(cnt$68$d),
        .q(cnt$68$q),
        .clock(cnt$68$clock)
    );
    top$tc$cnt$0 cnt$69(
        .d(cnt$69$d),
        .q(cnt$69$q),
        .clock(cnt$69$clock)
    );
    top$tc$cnt$0 cnt$70(
        .d(cnt$70$d),
        .q(cnt$70$q),
        .clock(cnt$70$clock)
    );
    top$tc$cnt$0 cnt$71(
        .d(cnt$71$d),
        .q(cnt$71$q),
        .clock(cnt$71$clock)
    );
    top$tc$cnt$0 cnt$72(
        .d(cnt$72$d),
        .q(cnt$72$q),
        .clock(cnt$72$clock)
    );
    top$tc$cnt$0 cnt$73(
        .d(cnt$73$d),
        .q(cnt$73$q),
        .clock(cnt$73$clock)
    );
    top$tc$cnt$0 cnt$74(
        .d(cnt$74$d),
        .q(cnt$74$q),
        .clock(cnt$74$clock)
    );
    top$tc$cnt$0 cnt$75(
        .d(cnt$75$d),
        .q(cnt$75$q),
        .clock(cnt$75$clock)
    );
    top$tc$cnt$0 cnt$76(
        .d(cnt$76$d),
        .q(cnt$76$q),
        .clock(cnt$76$clock)
    );
    top$tc$cnt$0 cnt$77(
        .d(cnt$77$d),
        .q(cnt$77$q),
        .clock(cnt$77$clock)
    );
    top$tc$cnt$0 cnt$78(
        .d(cnt$78$d),
        .q(cnt$78$q),
        .clock(cnt$78$clock)
    );
    top$tc$cnt$0 cnt$79(
        .d(cnt$79$d),
        .q(cnt$79$q),
        .clock(cnt$79$clock)
    );
    top$tc$cnt$0 cnt$80(
        .d(cnt$80$d),
        .q(cnt$80$q),
        .clock(cnt$80$clock)
    );
    top$tc$cnt$0 cnt$81(
        .d(cnt$81$d),
        .q(cnt$81$q),
        .clock(cnt$81$clock)
    );
    top$tc$cnt$0 cnt$82(
        .d(cnt$82$d),
        .q(cnt$82$q),
        .clock(cnt$82$clock)
    );
    top$tc$cnt$0 cnt$83(
        .d(cnt$83$d),
        .q(cnt$83$q),
        .clock(cnt$83$clock)
    );
    top$tc$cnt$0 cnt$84(
        .d(cnt$84$d),
        .q(cnt$84$q),
        .clock(cnt$84$clock)
    );
    top$tc$cnt$0 cnt$85(
        .d(cnt$85$d),
        .q(cnt$85$q),
        .clock(cnt$85$clock)
    );
    top$tc$cnt$0 cnt$86(
        .d(cnt$86$d),
        .q(cnt$86$q),
        .clock(cnt$86$clock)
    );
    top$tc$cnt$0 cnt$87(
        .d(cnt$87$d),
        .q(cnt$87$q),
        .clock(cnt$87$clock)
    );
    top$tc$cnt$0 cnt$88(
        .d(cnt$88$d),
        .q(cnt$88$q),
        .clock(cnt$88$clock)
    );
    top$tc$cnt$0 cnt$89(
        .d(cnt$89$d),
        .q(cnt$89$q),
        .clock(cnt$89$clock)
    );
    top$tc$cnt$0 cnt$90(
        .d(cnt$90$d),
        .q(cnt$90$q),
        .clock(cnt$90$clock)
    );
    top$tc$cnt$0 cnt$91(
        .d(cnt$91$d),
        .q(cnt$91$q),
        .clock(cnt$91$clock)
    );
    top$frame$0 op_a$0(
        .d(op_a$0$d),
        .q(op_a$0$q),
        .clock(op_a$0$clock)
    );
    top$frame$0 op_a$1(
        .d(op_a$1$d),
        .q(op_a$1$q),
        .clock(op_a$1$clock)
    );
    top$frame$0 op_a$2(
        .d(op_a$2$d),
        .q(op_a$2$q),
        .clock(op_a$2$clock)
    );
    top$frame$0 op_a$3(
        .d(op_a$3$d),
        .q(op_a$3$q),
        .clock(op_a$3$clock)
    );
    top$frame$0 op_a$4(
        .d(op_a$4$d),
        .q(op_a$4$q),
        .clock(op_a$4$clock)
    );
    top$frame$0 op_a$5(
        .d(op_a$5$d),
        .q(op_a$5$q),
        .clock(op_a$5$clock)
    );
    top$frame$0 op_a$6(
        .d(op_a$6$d),
        .q(op_a$6$q),
        .clock(op_a$6$clock)
    );
    top$frame$0 op_a$7(
        .d(op_a$7$d),
        .q(op_a$7$q),
        .clock(op_a$7$clock)
    );
    top$frame$0 op_a$8(
        .d(op_a$8$d),
        .q(op_a$8$q),
        .clock(op_a$8$clock)
    );
    top$frame$0 op_a$9(
        .d(op_a$9$d),
        .q(op_a$9$q),
        .clock(op_a$9$clock)
    );
    top$frame$0 op_a$10(
        .d(op_a$10$d),
        .q(op_a$10$q),
        .clock(op_a$10$clock)
    );
    top$frame$0 op_a$11(
        .d(op_a$11$d),
        .q(op_a$11$q),
        .clock(op_a$11$clock)
    );
    top$frame$0 op_a$12(
        .d(op_a$12$d),
        .q(op_a$12$q),
        .clock(op_a$12$clock)
    );
    top$frame$0 op_a$13(
        .d(op_a$13$d),
        .q(op_a$13$q),
        .clock(op_a$13$clock)
    );
    top$frame$0 op_a$14(
        .d(op_a$14$d),
        .q(op_a$14$q),
        .clock(op_a$14$clock)
    );
    top$frame$0 op_a$15(
        .d(op_a$15$d),
        .q(op_a$15$q),
        .clock(op_a$15$clock)
    );
    top$frame$0 op_a$16(
        .d(op_a$16$d),
        .q(op_a$16$q),
        .clock(op_a$16$clock)
    );
    top$frame$0 op_a$17(
        .d(op_a$17$d),
        .q(op_a$17$q),
        .clock(op_a$17$clock)
    );
    top$frame$0 op_a$18(
        .d(op_a$18$d),
        .q(op_a$18$q),
        .clock(op_a$18$clock)
    );
    top$frame$0 op_a$19(
        .d(op_a$19$d),
        .q(op_a$19$q),
        .clock(op_a$19$clock)
    );
    top$frame$0 op_a$20(
        .d(op_a$20$d),
        .q(op_a$20$q),
        .clock(op_a$20$clock)
    );
    top$frame$0 op_a$21(
        .d(op_a$21$d),
        .q(op_a$21$q),
        .clock(op_a$21$clock)
    );
    top$frame$0 op_a$22(
        .d(op_a$22$d),
        .q(op_a$22$q),
        .clock(op_a$22$clock)
    );
    top$frame$0 op_a$23(
        .d(op_a$23$d),
        .q(op_a$23$q),
        .clock(op_a$23$clock)
    );
    top$frame$0 op_a$24(
        .d(op_a$24$d),
        .q(op_a$24$q),
        .clock(op_a$24$clock)
    );
    top$frame$0 op_a$25(
        .d(op_a$25$d),
        .q(op_a$25$q),
        .clock(op_a$25$clock)
    );
    top$frame$0 op_a$26(
        .d(op_a$26$d),
        .q(op_a$26$q),
        .clock(op_a$26$clock)
    );
    top$frame$0 op_b$0(
        .d(op_b$0$d),
        .q(op_b$0$q),
        .clock(op_b$0$clock)
    );
    top$frame$0 op_b$1(
        .d(op_b$1$d),
        .q(op_b$1$q),
        .clock(op_b$1$clock)
    );
    top$frame$0 op_b$2(
        .d(op_b$2$d),
        .q(op_b$2$q),
        .clock(op_b$2$clock)
    );
    top$frame$0 op_b$3(
        .d(op_b$3$d),
        .q(op_b$3$q),
        .clock(op_b$3$clock)
    );
    top$frame$0 op_b$4(
        .d(op_b$4$d),
        .q(op_b$4$q),
        .clock(op_b$4$clock)
    );
    top$frame$0 op_b$5(
        .d(op_b$5$d),
        .q(op_b$5$q),
        .clock(op_b$5$clock)
    );
    top$frame$0 op_b$6(
        .d(op_b$6$d),
        .q(op_b$6$q),
        .clock(op_b$6$clock)
    );
    top$frame$0 op_b$7(
        .d(op_b$7$d),
        .q(op_b$7$q),
        .clock(op_b$7$clock)
    );
    top$frame$0 op_b$8(
        .d(op_b$8$d),
        .q(op_b$8$q),
        .clock(op_b$8$clock)
    );
    top$frame$0 op_b$9(
        .d(op_b$9$d),
        .q(op_b$9$q),
        .clock(op_b$9$clock)
    );
    top$frame$0 op_b$10(
        .d(op_b$10$d),
        .q(op_b$10$q),
        .clock(op_b$10$clock)
    );
    top$frame$0 op_b$11(
        .d(op_b$11$d),
        .q(op_b$11$q),
        .clock(op_b$11$clock)
    );
    top$frame$0 op_b$12(
        .d(op_b$12$d),
        .q(op_b$12$q),
        .clock(op_b$12$clock)
    );
    top$frame$0 op_b$13(
        .d(op_b$13$d),
        .q(op_b$13$q),
        .clock(op_b$13$clock)
    );
    top$frame$0 op_b$14(
        .d(op_b$14$d),
        .q(op_b$14$q),
        .clock(op_b$14$clock)
    );
    top$frame$0 op_b$15(
        .d(op_b$15$d),
        .q(op_b$15$q),
        .clock(op_b$15$clock)
    );
    top$frame$0 op_b$16(
        .d(op_b$16$d),
        .q(op_b$16$q),
        .clock(op_b$16$clock)
    );
    top$frame$0 op_b$17(
        .d(op_b$17$d),
        .q(op_b$17$q),
        .clock(op_b$17$clock)
    );
    top$frame$0 op_b$18(
        .d(op_b$18$d),
        .q(op_b$18$q),
        .clock(op_b$18$clock)
    );
    top$frame$0 op_b$19(
        .d(op_b$19$d),
        .q(op_b$19$q),
        .clock(op_b$19$clock)
    );
    top$frame$0 op_b$20(
        .d(op_b$20$d),
        .q(op_b$20$q),
        .clock(op_b$20$clock)
    );
    top$frame$0 op_b$21(
        .d(op_b$21$d),
        .q(op_b$21$q),
        .clock(op_b$21$clock)
    );
    top$frame$0 op_b$22(
        .d(op_b$22$d),
        .q(op_b$22$q),
        .clock(op_b$22$clock)
    );
    top$frame$0 op_b$23(
        .d(op_b$23$d),
        .q(op_b$23$q),
        .clock(op_b$23$clock)
    );
    top$a_deg op_sub$0(
        .d(op_sub$0$d),
        .q(op_sub$0$q),
        .clock(op_sub$0$clock)
    );
    top$a_deg op_sub$1(
        .d(op_sub$1$d),
        .q(op_sub$1$q),
        .clock(op_sub$1$clock)
    );
    top$a_deg op_sub$2(
        .d(op_sub$2$d),
        .q(op_sub$2$q),
        .clock(op_sub$2$clock)
    );
    top$a_deg op_sub$3(
        .d(op_sub$3$d),
        .q(op_sub$3$q),
        .clock(op_sub$3$clock)
    );
    top$a_deg op_sub$4(
        .d(op_sub$4$d),
        .q(op_sub$4$q),
        .clock(op_sub$4$clock)
    );
    top$a_deg op_sub$5(
        .d(op_sub$5$d),
        .q(op_sub$5$q),
        .clock(op_sub$5$clock)
    );
    top$a_deg op_sub$6(
        .d(op_sub$6$d),
        .q(op_sub$6$q),
        .clock(op_sub$6$clock)
    );
    top$a_deg op_sub$7(
        .d(op_sub$7$d),
        .q(op_sub$7$q),
        .clock(op_sub$7$clock)
    );
    top$a_deg op_sub$8(
        .d(op_sub$8$d),
        .q(op_sub$8$q),
        .clock(op_sub$8$clock)
    );
    top$a_deg op_sub$9(
        .d(op_sub$9$d),
        .q(op_sub$9$q),
        .clock(op_sub$9$clock)
    );
    top$a_deg op_sub$10(
        .d(op_sub$10$d),
        .q(op_sub$10$q),
        .clock(op_sub$10$clock)
    );
    top$a_deg op_sub$11(
        .d(op_sub$11$d),
        .q(op_sub$11$q),
        .clock(op_sub$11$clock)
    );
    top$a_deg op_sub$12(
        .d(op_sub$12$d),
        .q(op_sub$12$q),
        .clock(op_sub$12$clock)
    );
    top$a_deg op_sel$0(
        .d(op_sel$0$d),
        .q(op_sel$0$q),
        .clock(op_sel$0$clock)
    );
    top$a_deg op_sel$1(
        .d(op_sel$1$d),
        .q(op_sel$1$q),
        .clock(op_sel$1$clock)
    );
    top$a_deg op_sel$2(
        .d(op_sel$2$d),
        .q(op_sel$2$q),
        .clock(op_sel$2$clock)
    );
    top$tc$mul_v$0 mul_v$0(
        .clock(mul_v$0$clock),
        .a(mul_v$0$a),
        .b(mul_v$0$b),
        .valid_in(mul_v$0$valid_in),
        .y(mul_v$0$y),
        .valid_out(mul_v$0$valid_out)
    );
    top$tc$mul_v$0 mul_v$1(
        .clock(mul_v$1$clock),
        .a(mul_v$1$a),
        .b(mul_v$1$b),
        .valid_in(mul_v$1$valid_in),
        .y(mul_v$1$y),
        .valid_out(mul_v$1$valid_out)
    );
    top$tc$mul_v$0 mul_v$2(
        .clock(mul_v$2$clock),
        .a(mul_v$2$a),
        .b(mul_v$2$b),
        .valid_in(mul_v$2$valid_in),
        .y(mul_v$2$y),
        .valid_out(mul_v$2$valid_out)
    );
    top$tc$mul_v$0 mul_v$3(
        .clock(mul_v$3$clock),
        .a(mul_v$3$a),
        .b(mul_v$3$b),
        .valid_in(mul_v$3$valid_in),
        .y(mul_v$3$y),
        .valid_out(mul_v$3$valid_out)
    );
    top$tc$mul_v$0 mul_v$4(
        .clock(mul_v$4$clock),
        .a(mul_v$4$a),
        .b(mul_v$4$b),
        .valid_in(mul_v$4$valid_in),
        .y(mul_v$4$y),
        .valid_out(mul_v$4$valid_out)
    );
    top$tc$mul_up$0 mul_up$0(
        .clock(mul_up$0$clock),
        .a(mul_up$0$a),
        .b(mul_up$0$b),
        .valid_in(mul_up$0$valid_in),
        .y(mul_up$0$y),
        .valid_out(mul_up$0$valid_out)
    );
    top$tc$mul_up$0 mul_up$1(
        .clock(mul_up$1$clock),
        .a(mul_up$1$a),
        .b(mul_up$1$b),
        .valid_in(mul_up$1$valid_in),
        .y(mul_up$1$y),
        .valid_out(mul_up$1$valid_out)
    );
    top$tc$mul_up$0 mul_up$2(
        .clock(mul_up$2$clock),
        .a(mul_up$2$a),
        .b(mul_up$2$b),
        .valid_in(mul_up$2$valid_in),
        .y(mul_up$2$y),
        .valid_out(mul_up$2$valid_out)
    );
    top$tc$mul_up$0 mul_up$3(
        .clock(mul_up$3$clock),
        .a(mul_up$3$a),
        .b(mul_up$3$b),
        .valid_in(mul_up$3$valid_in),
        .y(mul_up$3$y),
        .valid_out(mul_up$3$valid_out)
    );
    top$tc$mul_up$0 mul_up$4(
        .clock(mul_up$4$clock),
        .a(mul_up$4$a),
        .b(mul_up$4$b),
        .valid_in(mul_up$4$valid_in),
        .y(mul_up$4$y),
        .valid_out(mul_up$4$valid_out)
    );
    top$tc$mul_up$0 mul_up$5(
        .clock(mul_up$5$clock),
        .a(mul_up$5$a),
        .b(mul_up$5$b),
        .valid_in(mul_up$5$valid_in),
        .y(mul_up$5$y),
        .valid_out(mul_up$5$valid_out)
    );
    top$tc$add_v$0 add_v$0(
        .clock(add_v$0$clock),
        .a(add_v$0$a),
        .b(add_v$0$b),
        .sub(add_v$0$sub),
        .valid_in(add_v$0$valid_in),
        .y(add_v$0$y),
        .valid_out(add_v$0$valid_out)
    );
    top$tc$add_v$0 add_v$1(
        .clock(add_v$1$clock),
        .a(add_v$1$a),
        .b(add_v$1$b),
        .sub(add_v$1$sub),
        .valid_in(add_v$1$valid_in),
        .y(add_v$1$y),
        .valid_out(add_v$1$valid_out)
    );
    top$tc$add_v$0 add_v$2(
        .clock(add_v$2$clock),
        .a(add_v$2$a),
        .b(add_v$2$b),
        .sub(add_v$2$sub),
        .valid_in(add_v$2$valid_in),
        .y(add_v$2$y),
        .valid_out(add_v$2$valid_out)
    );
    top$tc$add_v$0 add_v$3(
        .clock(add_v$3$clock),
        .a(add_v$3$a),
        .b(add_v$3$b),
        .sub(add_v$3$sub),
        .valid_in(add_v$3$valid_in),
        .y(add_v$3$y),
        .valid_out(add_v$3$valid_out)
    );
    top$tc$add_v$0 add_v$4(
        .clock(add_v$4$clock),
        .a(add_v$4$a),
        .b(add_v$4$b),
        .sub(add_v$4$sub),
        .valid_in(add_v$4$valid_in),
        .y(add_v$4$y),
        .valid_out(add_v$4$valid_out)
    );
    top$tc$add_up$0 add_up$0(
        .clock(add_up$0$clock),
        .a(add_up$0$a),
        .b(add_up$0$b),
        .sub(add_up$0$sub),
        .valid_in(add_up$0$valid_in),
        .y(add_up$0$y),
        .valid_out(add_up$0$valid_out)
    );
    top$tc$add_up$0 add_up$1(
        .clock(add_up$1$clock),
        .a(add_up$1$a),
        .b(add_up$1$b),
        .sub(add_up$1$sub),
        .valid_in(add_up$1$valid_in),
        .y(add_up$1$y),
        .valid_out(add_up$1$valid_out)
    );
    top$tc$add_up$0 add_up$2(
        .clock(add_up$2$clock),
        .a(add_up$2$a),
        .b(add_up$2$b),
        .sub(add_up$2$sub),
        .valid_in(add_up$2$valid_in),
        .y(add_up$2$y),
        .valid_out(add_up$2$valid_out)
    );
    top$tc$add_up$0 add_up$3(
        .clock(add_up$3$clock),
        .a(add_up$3$a),
        .b(add_up$3$b),
        .sub(add_up$3$sub),
        .valid_in(add_up$3$valid_in),
        .y(add_up$3$y),
        .valid_out(add_up$3$valid_out)
    );
    top$tc$add_up$0 add_up$4(
        .clock(add_up$4$clock),
        .a(add_up$4$a),
        .b(add_up$4$b),
        .sub(add_up$4$sub),
        .valid_in(add_up$4$valid_in),
        .y(add_up$4$y),
        .valid_out(add_up$4$valid_out)
    );
    top$tc$add_up$0 add_up$5(
        .clock(add_up$5$clock),
        .a(add_up$5$a),
        .b(add_up$5$b),
        .sub(add_up$5$sub),
        .valid_in(add_up$5$valid_in),
        .y(add_up$5$y),
        .valid_out(add_up$5$valid_out)
    );
    top$tc$add_up$0 add_up$6(
        .clock(add_up$6$clock),
        .a(add_up$6$a),
        .b(add_up$6$b),
        .sub(add_up$6$sub),
        .valid_in(add_up$6$valid_in),
        .y(add_up$6$y),
        .valid_out(add_up$6$valid_out)
    );
    top$tc$add_up$0 add_up$7(
        .clock(add_up$7$clock),
        .a(add_up$7$a),
        .b(add_up$7$b),
        .sub(add_up$7$sub),
        .valid_in(add_up$7$valid_in),
        .y(add_up$7$y),
        .valid_out(add_up$7$valid_out)
    );
    top$tc$scale_e$0 scale_e$0(
        .clock(scale_e$0$clock),
        .a(scale_e$0$a),
        .sel(scale_e$0$sel),
        .y(scale_e$0$y)
    );
    top$tc$scale_z$0 scale_z$0(
        .clock(scale_z$0$clock),
        .a(scale_z$0$a),
        .sel(scale_z$0$sel),
        .y(scale_z$0$y)
    );
    top$tc$scale_s$0 scale_s$0(
        .clock(scale_s$0$clock),
        .a(scale_s$0$a),
        .sel(scale_s$0$sel),
        .y(scale_s$0$y)
    );
    top$tc$signs$0 signs$0(
        .x(signs$0$x),
        .e(signs$0$e),
        .sgn(signs$0$sgn)
    );
    top$tc$signs$0 signs$1(
        .x(signs$1$x),
        .e(signs$1$e),
        .sgn(signs$1$sgn)
    );
    top$tc$signs$0 signs$2(
        .x(signs$2$x),
        .e(signs$2$e),
        .sgn(signs$2$sgn)
    );
    top$tc$signs$0 signs$3(
        .x(signs$3$x),
        .e(signs$3$e),
        .sgn(signs$3$sgn)
    );
    top$tc$signs$0 signs$4(
        .x(signs$4$x),
        .e(signs$4$e),
        .sgn(signs$4$sgn)
    );
    top$tc$signs$0 signs$5(
        .x(signs$5$x),
        .e(signs$5$e),
        .sgn(signs$5$sgn)
    );
    top$tc$signs$0 signs$6(
        .x(signs$6$x),
        .e(signs$6$e),
        .sgn(signs$6$sgn)
    );
    top$tc$signs$0 signs$7(
        .x(signs$7$x),
        .e(signs$7$e),
        .sgn(signs$7$sgn)
    );
    top$tc$signs$0 signs$8(
        .x(signs$8$x),
        .e(signs$8$e),
        .sgn(signs$8$sgn)
    );
    top$tc$signs$0 signs$9(
        .x(signs$9$x),
        .e(signs$9$e),
        .sgn(signs$9$sgn)
    );
    top$tc$signs$0 signs$10(
        .x(signs$10$x),
        .e(signs$10$e),
        .sgn(signs$10$sgn)
    );
    top$tc$signs$0 signs$11(
        .x(signs$11$x),
        .e(signs$11$e),
        .sgn(signs$11$sgn)
    );
    top$tc$signs$0 signs$12(
        .x(signs$12$x),
        .e(signs$12$e),
        .sgn(signs$12$sgn)
    );
    top$tc$signs$0 signs$13(
        .x(signs$13$x),
        .e(signs$13$e),
        .sgn(signs$13$sgn)
    );
    top$tc$signs$0 signs$14(
        .x(signs$14$x),
        .e(signs$14$e),
        .sgn(signs$14$sgn)
    );
    top$tc$signs$0 signs$15(
        .x(signs$15$x),
        .e(signs$15$e),
        .sgn(signs$15$sgn)
    );
    top$tc$signs$0 signs$16(
        .x(signs$16$x),
        .e(signs$16$e),
        .sgn(signs$16$sgn)
    );
    top$tc$signs$0 signs$17(
        .x(signs$17$x),
        .e(signs$17$e),
        .sgn(signs$17$sgn)
    );
    top$frame$0 out_s_x$0(
        .d(out_s_x$0$d),
        .q(out_s_x$0$q),
        .clock(out_s_x$0$clock)
    );
    top$frame$0 out_s_x$1(
        .d(out_s_x$1$d),
        .q(out_s_x$1$q),
        .clock(out_s_x$1$clock)
    );
    top$frame$0 out_s_x$2(
        .d(out_s_x$2$d),
        .q(out_s_x$2$q),
        .clock(out_s_x$2$clock)
    );
    top$frame$0 out_s_b$0(
        .d(out_s_b$0$d),
        .q(out_s_b$0$q),
        .clock(out_s_b$0$clock)
    );
    top$frame$0 out_s_b$1(
        .d(out_s_b$1$d),
        .q(out_s_b$1$q),
        .clock(out_s_b$1$clock)
    );
    top$frame$0 out_s_b$2(
        .d(out_s_b$2$d),
        .q(out_s_b$2$q),
        .clock(out_s_b$2$clock)
    );
    top$a_deg out_cross_t$0(
        .d(out_cross_t$0$d),
        .q(out_cross_t$0$q),
        .clock(out_cross_t$0$clock)
    );
    top$a_deg out_cross_t$1(
        .d(out_cross_t$1$d),
        .q(out_cross_t$1$q),
        .clock(out_cross_t$1$clock)
    );
    top$a_deg out_cross_t$2(
        .d(out_cross_t$2$d),
        .q(out_cross_t$2$q),
        .clock(out_cross_t$2$clock)
    );
    top$a_deg out_cross_f$0(
        .d(out_cross_f$0$d),
        .q(out_cross_f$0$q),
        .clock(out_cross_f$0$clock)
    );
    top$a_deg out_cross_f$1(
        .d(out_cross_f$1$d),
        .q(out_cross_f$1$q),
        .clock(out_cross_f$1$clock)
    );
    top$a_deg out_cross_f$2(
        .d(out_cross_f$2$d),
        .q(out_cross_f$2$q),
        .clock(out_cross_f$2$clock)
    );
    top$a_deg out_hit(
        .d(out_hit$d),
        .q(out_hit$q),
        .clock(out_hit$clock)
    );
    top$a_deg out_miss(
        .d(out_miss$d),
        .q(out_miss$q),
        .clock(out_miss$clock)
    );
    top$held_tag out_tag(
        .d(out_tag$d),
        .q(out_tag$q),
        .clock(out_tag$clock)
    );
    top$a_deg out_valid(
        .d(out_valid$d),
        .q(out_valid$q),
        .clock(out_valid$clock)
    );
    
    // Update code (custom)
    always @(*) begin
      run$clock = clock;
      run$d = run$q | valid_in;
      counter$clock = clock;
      counter$d = (!(run$q | valid_in) || counter$q == 8'd15) ? 8'd0 : counter$q + 8'd1;
      cnt$0$clock = clock;
      cnt$0$d = counter$d;
      cnt$1$clock = clock;
      cnt$1$d = counter$d;
      cnt$2$clock = clock;
      cnt$2$d = counter$d;
      cnt$3$clock = clock;
      cnt$3$d = counter$d;
      cnt$4$clock = clock;
      cnt$4$d = counter$d;
      cnt$5$clock = clock;
      cnt$5$d = counter$d;
      cnt$6$clock = clock;
      cnt$6$d = counter$d;
      cnt$7$clock = clock;
      cnt$7$d = counter$d;
      cnt$8$clock = clock;
      cnt$8$d = counter$d;
      cnt$9$clock = clock;
      cnt$9$d = counter$d;
      cnt$10$clock = clock;
      cnt$10$d = counter$d;
      cnt$11$clock = clock;
      cnt$11$d = counter$d;
      cnt$12$clock = clock;
      cnt$12$d = counter$d;
      cnt$13$clock = clock;
      cnt$13$d = counter$d;
      cnt$14$clock = clock;
      cnt$14$d = counter$d;
      cnt$15$clock = clock;
      cnt$15$d = counter$d;
      cnt$16$clock = clock;
      cnt$16$d = counter$d;
      cnt$17$clock = clock;
      cnt$17$d = counter$d;
      cnt$18$clock = clock;
      cnt$18$d = counter$d;
      cnt$19$clock = clock;
      cnt$19$d = counter$d;
      cnt$20$clock = clock;
      cnt$20$d = counter$d;
      cnt$21$clock = clock;
      cnt$21$d = counter$d;
      cnt$22$clock = clock;
      cnt$22$d = counter$d;
      cnt$23$clock = clock;
      cnt$23$d = counter$d;
      cnt$24$clock = clock;
      cnt$24$d = counter$d;
      cnt$25$clock = clock;
      cnt$25$d = counter$d;
      cnt$26$clock = clock;
      cnt$26$d = counter$d;
      cnt$27$clock = clock;
      cnt$27$d = counter$d;
      cnt$28$clock = clock;
      cnt$28$d = counter$d;
      cnt$29$clock = clock;
      cnt$29$d = counter$d;
      cnt$30$clock = clock;
      cnt$30$d = counter$d;
      cnt$31$clock = clock;
      cnt$31$d = counter$d;
      cnt$32$clock = clock;
      cnt$32$d = counter$d;
      cnt$33$clock = clock;
      cnt$33$d = counter$d;
      cnt$34$clock = clock;
      cnt$34$d = counter$d;
      cnt$35$clock = clock;
      cnt$35$d = counter$d;
      cnt$36$clock = clock;
      cnt$36$d = counter$d;
      cnt$37$clock = clock;
      cnt$37$d = counter$d;
      cnt$38$clock = clock;
      cnt$38$d = counter$d;
      cnt$39$clock = clock;
      cnt$39$d = counter$d;
      cnt$40$clock = clock;
      cnt$40$d = counter$d;
      cnt$41$clock = clock;
      cnt$41$d = counter$d;
      cnt$42$clock = clock;
      cnt$42$d = counter$d;
      cnt$43$clock = clock;
      cnt$43$d = counter$d;
      cnt$44$clock = clock;
      cnt$44$d = counter$d;
      cnt$45$clock = clock;
      cnt$45$d = counter$d;
      cnt$46$clock = clock;
      cnt$46$d = counter$d;
      cnt$47$clock = clock;
      cnt$47$d = counter$d;
      cnt$48$clock = clock;
      cnt$48$d = counter$d;
      cnt$49$clock = clock;
      cnt$49$d = counter$d;
      cnt$50$clock = clock;
      cnt$50$d = counter$d;
      cnt$51$clock = clock;
      cnt$51$d = counter$d;
      cnt$52$clock = clock;
      cnt$52$d = counter$d;
      cnt$53$clock = clock;
      cnt$53$d = counter$d;
      cnt$54$clock = clock;
      cnt$54$d = counter$d;
      cnt$55$clock = clock;
      cnt$55$d = counter$d;
      cnt$56$clock = clock;
      cnt$56$d = counter$d;
      cnt$57$clock = clock;
      cnt$57$d = counter$d;
      cnt$58$clock = clock;
      cnt$58$d = counter$d;
      cnt$59$clock = clock;
      cnt$59$d = counter$d;
      cnt$60$clock = clock;
      cnt$60$d = counter$d;
      cnt$61$clock = clock;
      cnt$61$d = counter$d;
      cnt$62$clock = clock;
      cnt$62$d = counter$d;
      cnt$63$clock = clock;
      cnt$63$d = counter$d;
      cnt$64$clock = clock;
      cnt$64$d = counter$d;
      cnt$65$clock = clock;
      cnt$65$d = counter$d;
      cnt$66$clock = clock;
      cnt$66$d = counter$d;
      cnt$67$clock = clock;
      cnt$67$d = counter$d;
      cnt$68$clock = clock;
      cnt$68$d = counter$d;
      cnt$69$clock = clock;
      cnt$69$d = counter$d;
      cnt$70$clock = clock;
      cnt$70$d = counter$d;
      cnt$71$clock = clock;
      cnt$71$d = counter$d;
      cnt$72$clock = clock;
      cnt$72$d = counter$d;
      cnt$73$clock = clock;
      cnt$73$d = counter$d;
      cnt$74$clock = clock;
      cnt$74$d = counter$d;
      cnt$75$clock = clock;
      cnt$75$d = counter$d;
      cnt$76$clock = clock;
      cnt$76$d = counter$d;
      cnt$77$clock = clock;
      cnt$77$d = counter$d;
      cnt$78$clock = clock;
      cnt$78$d = counter$d;
      cnt$79$clock = clock;
      cnt$79$d = counter$d;
      cnt$80$clock = clock;
      cnt$80$d = counter$d;
      cnt$81$clock = clock;
      cnt$81$d = counter$d;
      cnt$82$clock = clock;
      cnt$82$d = counter$d;
      cnt$83$clock = clock;
      cnt$83$d = counter$d;
      cnt$84$clock = clock;
      cnt$84$d = counter$d;
      cnt$85$clock = clock;
      cnt$85$d = counter$d;
      cnt$86$clock = clock;
      cnt$86$d = counter$d;
      cnt$87$clock = clock;
      cnt$87$d = counter$d;
      cnt$88$clock = clock;
      cnt$88$d = counter$d;
      cnt$89$clock = clock;
      cnt$89$d = counter$d;
      cnt$90$clock = clock;
      cnt$90$d = counter$d;
      cnt$91$clock = clock;
      cnt$91$d = counter$d;
      regs$0$clock = clock;
      regs$0$d = (cnt$54$q == 8'd0) ? m_0$0 : regs$0$q;
      regs$1$clock = clock;
      regs$1$d = (cnt$55$q == 8'd0) ? m_0$1 : regs$1$q;
      regs$2$clock = clock;
      regs$2$d = (cnt$56$q == 8'd0) ? m_0$2 : regs$2$q;
      regs$3$clock = clock;
      regs$3$d = (cnt$58$q == 8'd0) ? m_1$0 : regs$3$q;
      regs$4$clock = clock;
      regs$4$d = (cnt$60$q == 8'd0) ? m_1$2 : regs$4$q;
      regs$5$clock = clock;
      regs$5$d = (cnt$62$q == 8'd0) ? m_2$0 : regs$5$q;
      regs$6$clock = clock;
      regs$6$d = (cnt$63$q == 8'd0) ? m_2$1 : regs$6$q;
      regs$7$clock = clock;
      regs$7$d = (cnt$64$q == 8'd0) ? m_2$2 : regs$7$q;
      regs$8$clock = clock;
      regs$8$d = (cnt$68$q == 8'd0) ? f_0$0 : regs$8$q;
      regs$9$clock = clock;
      regs$9$d = (cnt$69$q == 8'd0) ? f_0$1 : regs$9$q;
      regs$10$clock = clock;
      regs$10$d = (cnt$70$q == 8'd0) ? f_0$2 : regs$10$q;
      regs$11$clock = clock;
      regs$11$d = (cnt$72$q == 8'd0) ? f_1$0 : regs$11$q;
      regs$12$clock = clock;
      regs$12$d = (cnt$75$q == 8'd0) ? f_1$3 : regs$12$q;
      regs$13$clock = clock;
      regs$13$d = (cnt$77$q == 8'd0) ? f_2$1 : regs$13$q;
      regs$14$clock = clock;
      regs$14$d = (cnt$78$q == 8'd0) ? f_2$2 : regs$14$q;
      regs$15$clock = clock;
      regs$15$d = (cnt$79$q == 8'd0) ? f_2$3 : regs$15$q;
      regs$16$clock = clock;
      regs$16$d = (cnt$83$q == 8'd0) ? v_x$0 : regs$16$q;
      regs$17$clock = clock;
      regs$17$d = (cnt$83$q == 8'd0) ? regs$16$q : regs$17$q;
      regs$18$clock = clock;
      regs$18$d = (cnt$84$q == 8'd0) ? v_y$0 : regs$18$q;
      regs$19$clock = clock;
      regs$19$d = (cnt$84$q == 8'd0) ? regs$18$q : regs$19$q;
      regs$20$clock = clock;
      regs$20$d = (cnt$85$q == 8'd0) ? v_z$0 : regs$20$q;
      regs$21$clock = clock;
      regs$21$d = (cnt$85$q == 8'd0) ? regs$20$q : regs$21$q;
      regs$22$clock = clock;
      regs$22$d = (cnt$91$q == 8'd0) ? v_z$2 : regs$22$q;
      regs$23$clock = clock;
      regs$23$d = (cnt$91$q == 8'd0) ? regs$22$q : regs$23$q;
      regs$24$clock = clock;
      regs$24$d = (cnt$23$q == 8'd8) ? add_v$0$y : regs$24$q;
      regs$25$clock = clock;
      regs$25$d = (cnt$23$q == 8'd9) ? add_v$0$y : regs$25$q;
      regs$26$clock = clock;
      regs$26$d = (cnt$25$q == 8'd10) ? add_v$1$y : regs$26$q;
      regs$27$clock = clock;
      regs$27$d = (cnt$23$q == 8'd11) ? add_v$0$y : regs$27$q;
      regs$28$clock = clock;
      regs$28$d = (cnt$25$q == 8'd11) ? add_v$1$y : regs$28$q;
      regs$29$clock = clock;
      regs$29$d = (cnt$23$q == 8'd13) ? add_v$0$y : regs$29$q;
      regs$30$clock = clock;
      regs$30$d = (cnt$23$q == 8'd14) ? add_v$0$y : regs$30$q;
      regs$31$clock = clock;
      regs$31$d = (cnt$54$q == 8'd0) ? m_0$0 : regs$31$q;
      regs$32$clock = clock;
      regs$32$d = (cnt$55$q == 8'd0) ? m_0$1 : regs$32$q;
      regs$33$clock = clock;
      regs$33$d = (cnt$56$q == 8'd0) ? m_0$2 : regs$33$q;
      regs$34$clock = clock;
      regs$34$d = (cnt$58$q == 8'd0) ? m_1$0 : regs$34$q;
      regs$35$clock = clock;
      regs$35$d = (cnt$59$q == 8'd0) ? m_1$1 : regs$35$q;
      regs$36$clock = clock;
      regs$36$d = (cnt$63$q == 8'd0) ? m_2$1 : regs$36$q;
      regs$37$clock = clock;
      regs$37$d = (cnt$64$q == 8'd0) ? m_2$2 : regs$37$q;
      regs$38$clock = clock;
      regs$38$d = (cnt$70$q == 8'd0) ? f_0$2 : regs$38$q;
      regs$39$clock = clock;
      regs$39$d = (cnt$71$q == 8'd0) ? f_0$3 : regs$39$q;
      regs$40$clock = clock;
      regs$40$d = (cnt$72$q == 8'd0) ? f_1$0 : regs$40$q;
      regs$41$clock = clock;
      regs$41$d = (cnt$73$q == 8'd0) ? f_1$1 : regs$41$q;
      regs$42$clock = clock;
      regs$42$d = (cnt$74$q == 8'd0) ? f_1$2 : regs$42$q;
      regs$43$clock = clock;
      regs$43$d = (cnt$76$q == 8'd0) ? f_2$0 : regs$43$q;
      regs$44$clock = clock;
      regs$44$d = (cnt$79$q == 8'd0) ? f_2$3 : regs$44$q;
      regs$45$clock = clock;
      regs$45$d = (cnt$84$q == 8'd0) ? v_y$0 : regs$45$q;
      regs$46$clock = clock;
      regs$46$d = (cnt$84$q == 8'd0) ? regs$45$q : regs$46$q;
      regs$47$clock = clock;
      regs$47$d = (cnt$85$q == 8'd0) ? v_z$0 : regs$47$q;
      regs$48$clock = clock;
      regs$48$d = (cnt$85$q == 8'd0) ? regs$47$q : regs$48$q;
      regs$49$clock = clock;
      regs$49$d = (cnt$86$q == 8'd0) ? v_x$1 : regs$49$q;
      regs$50$clock = clock;
      regs$50$d = (cnt$86$q == 8'd0) ? regs$49$q : regs$50$q;
      regs$51$clock = clock;
      regs$51$d = (cnt$88$q == 8'd0) ? v_z$1 : regs$51$q;
      regs$52$clock = clock;
      regs$52$d = (cnt$88$q == 8'd0) ? regs$51$q : regs$52$q;
      regs$53$clock = clock;
      regs$53$d = (cnt$25$q == 8'd8) ? add_v$1$y : regs$53$q;
      regs$54$clock = clock;
      regs$54$d = (cnt$23$q == 8'd9) ? add_v$0$y : regs$54$q;
      regs$55$clock = clock;
      regs$55$d = (cnt$25$q == 8'd10) ? add_v$1$y : regs$55$q;
      regs$56$clock = clock;
      regs$56$d = (cnt$25$q == 8'd11) ? add_v$1$y : regs$56$q;
      regs$57$clock = clock;
      regs$57$d = (cnt$25$q == 8'd13) ? add_v$1$y : regs$57$q;
      regs$58$clock = clock;
      regs$58$d = (cnt$23$q == 8'd14) ? add_v$0$y : regs$58$q;
      regs$59$clock = clock;
      regs$59$d = (cnt$25$q == 8'd1) ? add_v$1$y : regs$59$q;
      regs$60$clock = clock;
      regs$60$d = (cnt$29$q == 8'd6) ? add_v$3$y : regs$60$q;
      regs$61$clock = clock;
      regs$61$d = (cnt$29$q == 8'd4) ? add_v$3$y : regs$61$q;
      regs$62$clock = clock;
      regs$62$d = (cnt$55$q == 8'd0) ? m_0$1 : regs$62$q;
      regs$63$clock = clock;
      regs$63$d = (cnt$56$q == 8'd0) ? m_0$2 : regs$63$q;
      regs$64$clock = clock;
      regs$64$d = (cnt$58$q == 8'd0) ? m_1$0 : regs$64$q;
      regs$65$clock = clock;
      regs$65$d = (cnt$59$q == 8'd0) ? m_1$1 : regs$65$q;
      regs$66$clock = clock;
      regs$66$d = (cnt$60$q == 8'd0) ? m_1$2 : regs$66$q;
      regs$67$clock = clock;
      regs$67$d = (cnt$62$q == 8'd0) ? m_2$0 : regs$67$q;
      regs$68$clock = clock;
      regs$68$d = (cnt$64$q == 8'd0) ? m_2$2 : regs$68$q;
      regs$69$clock = clock;
      regs$69$d = (cnt$68$q == 8'd0) ? f_0$0 : regs$69$q;
      regs$70$clock = clock;
      regs$70$d = (cnt$69$q == 8'd0) ? f_0$1 : regs$70$q;
      regs$71$clock = clock;
      regs$71$d = (cnt$74$q == 8'd0) ? f_1$2 : regs$71$q;
      regs$72$clock = clock;
      regs$72$d = (cnt$75$q == 8'd0) ? f_1$3 : regs$72$q;
      regs$73$clock = clock;
      regs$73$d = (cnt$76$q == 8'd0) ? f_2$0 : regs$73$q;
      regs$74$clock = clock;
      regs$74$d = (cnt$77$q == 8'd0) ? f_2$1 : regs$74$q;
      regs$75$clock = clock;
      regs$75$d = (cnt$78$q == 8'd0) ? f_2$2 : regs$75$q;
      regs$76$clock = clock;
      regs$76$d = (cnt$86$q == 8'd0) ? v_x$1 : regs$76$q;
      regs$77$clock = clock;
      regs$77$d = (cnt$86$q == 8'd0) ? regs$76$q : regs$77$q;
      regs$78$clock = clock;
      regs$78$d = (cnt$87$q == 8'd0) ? v_y$1 : regs$78$q;
      regs$79$clock = clock;
      regs$79$d = (cnt$87$q == 8'd0) ? regs$78$q : regs$79$q;
      regs$80$clock = clock;
      regs$80$d = (cnt$89$q == 8'd0) ? v_x$2 : regs$80$q;
      regs$81$clock = clock;
      regs$81$d = (cnt$89$q == 8'd0) ? regs$80$q : regs$81$q;
      regs$82$clock = clock;
      regs$82$d = (cnt$90$q == 8'd0) ? v_y$2 : regs$82$q;
      regs$83$clock = clock;
      regs$83$d = (cnt$90$q == 8'd0) ? regs$82$q : regs$83$q;
      regs$84$clock = clock;
      regs$84$d = (cnt$23$q == 8'd8) ? add_v$0$y : regs$84$q;
      regs$85$clock = clock;
      regs$85$d = (cnt$25$q == 8'd8) ? add_v$1$y : regs$85$q;
      regs$86$clock = clock;
      regs$86$d = (cnt$25$q == 8'd10) ? add_v$1$y : regs$86$q;
      regs$87$clock = clock;
      regs$87$d = (cnt$23$q == 8'd11) ? add_v$0$y : regs$87$q;
      regs$88$clock = clock;
      regs$88$d = (cnt$23$q == 8'd13) ? add_v$0$y : regs$88$q;
      regs$89$clock = clock;
      regs$89$d = (cnt$25$q == 8'd13) ? add_v$1$y : regs$89$q;
      regs$90$clock = clock;
      regs$90$d = (cnt$27$q == 8'd6) ? add_v$2$y : regs$90$q;
      regs$91$clock = clock;
      regs$91$d = (cnt$27$q == 8'd1) ? add_v$2$y : regs$91$q;
      regs$92$clock = clock;
      regs$92$d = (cnt$29$q == 8'd1) ? add_v$3$y : regs$92$q;
      regs$93$clock = clock;
      regs$93$d = (cnt$54$q == 8'd0) ? m_0$0 : regs$93$q;
      regs$94$clock = clock;
      regs$94$d = (cnt$56$q == 8'd0) ? m_0$2 : regs$94$q;
      regs$95$clock = clock;
      regs$95$d = (cnt$58$q == 8'd0) ? m_1$0 : regs$95$q;
      regs$96$clock = clock;
      regs$96$d = (cnt$59$q == 8'd0) ? m_1$1 : regs$96$q;
      regs$97$clock = clock;
      regs$97$d = (cnt$60$q == 8'd0) ? m_1$2 : regs$97$q;
      regs$98$clock = clock;
      regs$98$d = (cnt$62$q == 8'd0) ? m_2$0 : regs$98$q;
      regs$99$clock = clock;
      regs$99$d = (cnt$63$q == 8'd0) ? m_2$1 : regs$99$q;
      regs$100$clock = clock;
      regs$100$d = (cnt$69$q == 8'd0) ? f_0$1 : regs$100$q;
      regs$101$clock = clock;
      regs$101$d = (cnt$70$q == 8'd0) ? f_0$2 : regs$101$q;
      regs$102$clock = clock;
      regs$102$d = (cnt$71$q == 8'd0) ? f_0$3 : regs$102$q;
      regs$103$clock = clock;
      regs$103$d = (cnt$72$q == 8'd0) ? f_1$0 : regs$103$q;
      regs$104$clock = clock;
      regs$104$d = (cnt$73$q == 8'd0) ? f_1$1 : regs$104$q;
      regs$105$clock = clock;
      regs$105$d = (cnt$78$q == 8'd0) ? f_2$2 : regs$105$q;
      regs$106$clock = clock;
      regs$106$d = (cnt$79$q == 8'd0) ? f_2$3 : regs$106$q;
      regs$107$clock = clock;
      regs$107$d = (cnt$87$q == 8'd0) ? v_y$1 : regs$107$q;
      regs$108$clock = clock;
      regs$108$d = (cnt$87$q == 8'd0) ? regs$107$q : regs$108$q;
      regs$109$clock = clock;
      regs$109$d = (cnt$88$q == 8'd0) ? v_z$1 : regs$109$q;
      regs$110$clock = clock;
      regs$110$d = (cnt$88$q == 8'd0) ? regs$109$q : regs$110$q;
      regs$111$clock = clock;
      regs$111$d = (cnt$91$q == 8'd0) ? v_z$2 : regs$111$q;
      regs$112$clock = clock;
      regs$112$d = (cnt$91$q == 8'd0) ? regs$111$q : regs$112$q;
      regs$113$clock = clock;
      regs$113$d = (cnt$25$q == 8'd8) ? add_v$1$y : regs$113$q;
      regs$114$clock = clock;
      regs$114$d = (cnt$23$q == 8'd9) ? add_v$0$y : regs$114$q;
      regs$115$clock = clock;
      regs$115$d = (cnt$25$q == 8'd11) ? add_v$1$y : regs$115$q;
      regs$116$clock = clock;
      regs$116$d = (cnt$25$q == 8'd13) ? add_v$1$y : regs$116$q;
      regs$117$clock = clock;
      regs$117$d = (cnt$23$q == 8'd14) ? add_v$0$y : regs$117$q;
      regs$118$clock = clock;
      regs$118$d = (cnt$25$q == 8'd1) ? add_v$1$y : regs$118$q;
      regs$119$clock = clock;
      regs$119$d = (cnt$27$q == 8'd3) ? add_v$2$y : regs$119$q;
      regs$120$clock = clock;
      regs$120$d = (cnt$29$q == 8'd6) ? add_v$3$y : regs$120$q;
      regs$121$clock = clock;
      regs$121$d = (cnt$29$q == 8'd1) ? add_v$3$y : regs$121$q;
      regs$122$clock = clock;
      regs$122$d = (cnt$31$q == 8'd6) ? add_v$4$y : regs$122$q;
      regs$123$clock = clock;
      regs$123$d = (cnt$54$q == 8'd0) ? m_0$0 : regs$123$q;
      regs$124$clock = clock;
      regs$124$d = (cnt$55$q == 8'd0) ? m_0$1 : regs$124$q;
      regs$125$clock = clock;
      regs$125$d = (cnt$59$q == 8'd0) ? m_1$1 : regs$125$q;
      regs$126$clock = clock;
      regs$126$d = (cnt$60$q == 8'd0) ? m_1$2 : regs$126$q;
      regs$127$clock = clock;
      regs$127$d = (cnt$62$q == 8'd0) ? m_2$0 : regs$127$q;
      regs$128$clock = clock;
      regs$128$d = (cnt$63$q == 8'd0) ? m_2$1 : regs$128$q;
      regs$129$clock = clock;
      regs$129$d = (cnt$64$q == 8'd0) ? m_2$2 : regs$129$q;
      regs$130$clock = clock;
      regs$130$d = (cnt$68$q == 8'd0) ? f_0$0 : regs$130$q;
      regs$131$clock = clock;
      regs$131$d = (cnt$71$q == 8'd0) ? f_0$3 : regs$131$q;
      regs$132$clock = clock;
      regs$132$d = (cnt$73$q == 8'd0) ? f_1$1 : regs$132$q;
      regs$133$clock = clock;
      regs$133$d = (cnt$74$q == 8'd0) ? f_1$2 : regs$133$q;
      regs$134$clock = clock;
      regs$134$d = (cnt$75$q == 8'd0) ? f_1$3 : regs$134$q;
      regs$135$clock = clock;
      regs$135$d = (cnt$76$q == 8'd0) ? f_2$0 : regs$135$q;
      regs$136$clock = clock;
      regs$136$d = (cnt$77$q == 8'd0) ? f_2$1 : regs$136$q;
      regs$137$clock = clock;
      regs$137$d = (cnt$89$q == 8'd0) ? v_x$2 : regs$137$q;
      regs$138$clock = clock;
      regs$138$d = (cnt$89$q == 8'd0) ? regs$137$q : regs$138$q;
      regs$139$clock = clock;
      regs$139$d = (cnt$90$q == 8'd0) ? v_y$2 : regs$139$q;
      regs$140$clock = clock;
      regs$140$d = (cnt$90$q == 8'd0) ? regs$139$q : regs$140$q;
      regs$141$clock = clock;
      regs$141$d = (cnt$23$q == 8'd8) ? add_v$0$y : regs$141$q;
      regs$142$clock = clock;
      regs$142$d = (cnt$23$q == 8'd11) ? add_v$0$y : regs$142$q;
      regs$143$clock = clock;
      regs$143$d = (cnt$23$q == 8'd13) ? add_v$0$y : regs$143$q;
      regs$144$clock = clock;
      regs$144$d = (cnt$27$q == 8'd3) ? add_v$2$y : regs$144$q;
      regs$145$clock = clock;
      regs$145$d = (cnt$27$q == 8'd6) ? add_v$2$y : regs$145$q;
      regs$146$clock = clock;
      regs$146$d = (cnt$27$q == 8'd1) ? add_v$2$y : regs$146$q;
      regs$147$clock = clock;
      regs$147$d = (cnt$27$q == 8'd4) ? add_v$2$y : regs$147$q;
      regs$148$clock = clock;
      regs$148$d = (cnt$29$q == 8'd4) ? add_v$3$y : regs$148$q;
      regs$149$clock = clock;
      regs$149$d = (cnt$31$q == 8'd6) ? add_v$4$y : regs$149$q;
      regs$150$clock = clock;
      regs$150$d = (cnt$54$q == 8'd0) ? m_0$0 : regs$150$q;
      regs$151$clock = clock;
      regs$151$d = (cnt$58$q == 8'd0) ? m_1$0 : regs$151$q;
      regs$152$clock = clock;
      regs$152$d = (cnt$62$q == 8'd0) ? m_2$0 : regs$152$q;
      regs$153$clock = clock;
      regs$153$d = (cnt$66$q == 8'd0) ? alpha_m : regs$153$q;
      regs$154$clock = clock;
      regs$154$d = (cnt$68$q == 8'd0) ? f_0$0 : regs$154$q;
      regs$155$clock = clock;
      regs$155$d = (cnt$70$q == 8'd0) ? f_0$2 : regs$155$q;
      regs$156$clock = clock;
      regs$156$d = (cnt$80$q == 8'd0) ? beta_m : regs$156$q;
      regs$157$clock = clock;
      regs$157$d = (cnt$83$q == 8'd0) ? v_x$0 : regs$157$q;
      regs$158$clock = clock;
      regs$158$d = (cnt$83$q == 8'd0) ? regs$157$q : regs$158$q;
      regs$159$clock = clock;
      regs$159$d = (cnt$85$q == 8'd0) ? v_z$0 : regs$159$q;
      regs$160$clock = clock;
      regs$160$d = (cnt$85$q == 8'd0) ? regs$159$q : regs$160$q;
      regs$161$clock = clock;
      regs$161$d = (cnt$45$q == 8'd8) ? add_up$6$y : regs$161$q;
      regs$162$clock = clock;
      regs$162$d = (cnt$33$q == 8'd9) ? add_up$0$y : regs$162$q;
      regs$163$clock = clock;
      regs$163$d = (cnt$33$q == 8'd10) ? add_up$0$y : regs$163$q;
      regs$164$clock = clock;
      regs$164$d = (cnt$33$q == 8'd11) ? add_up$0$y : regs$164$q;
      regs$165$clock = clock;
      regs$165$d = (cnt$33$q == 8'd12) ? add_up$0$y : regs$165$q;
      regs$166$clock = clock;
      regs$166$d = (cnt$33$q == 8'd13) ? add_up$0$y : regs$166$q;
      regs$167$clock = clock;
      regs$167$d = (cnt$25$q == 8'd1) ? add_v$1$y : regs$167$q;
      regs$168$clock = clock;
      regs$168$d = (cnt$25$q == 8'd1) ? regs$167$q : regs$168$q;
      regs$169$clock = clock;
      regs$169$d = (cnt$25$q == 8'd1) ? regs$168$q : regs$169$q;
      regs$170$clock = clock;
      regs$170$d = (cnt$45$q == 8'd10) ? add_up$6$y : regs$170$q;
      regs$171$clock = clock;
      regs$171$d = (cnt$49$q == 8'd1) ? scale_e$0$y : regs$171$q;
      regs$172$clock = clock;
      regs$172$d = (cnt$37$q == 8'd13) ? add_up$2$y : regs$172$q;
      regs$173$clock = clock;
      regs$173$d = (cnt$39$q == 8'd13) ? add_up$3$y : regs$173$q;
      regs$174$clock = clock;
      regs$174$d = (cnt$55$q == 8'd0) ? m_0$1 : regs$174$q;
      regs$175$clock = clock;
      regs$175$d = (cnt$59$q == 8'd0) ? m_1$1 : regs$175$q;
      regs$176$clock = clock;
      regs$176$d = (cnt$63$q == 8'd0) ? m_2$1 : regs$176$q;
      regs$177$clock = clock;
      regs$177$d = (cnt$67$q == 8'd0) ? alpha_f : regs$177$q;
      regs$178$clock = clock;
      regs$178$d = (cnt$72$q == 8'd0) ? f_1$0 : regs$178$q;
      regs$179$clock = clock;
      regs$179$d = (cnt$74$q == 8'd0) ? f_1$2 : regs$179$q;
      regs$180$clock = clock;
      regs$180$d = (cnt$81$q == 8'd0) ? beta_f : regs$180$q;
      regs$181$clock = clock;
      regs$181$d = (cnt$84$q == 8'd0) ? v_y$0 : regs$181$q;
      regs$182$clock = clock;
      regs$182$d = (cnt$84$q == 8'd0) ? regs$181$q : regs$182$q;
      regs$183$clock = clock;
      regs$183$d = (cnt$88$q == 8'd0) ? v_z$1 : regs$183$q;
      regs$184$clock = clock;
      regs$184$d = (cnt$88$q == 8'd0) ? regs$183$q : regs$184$q;
      regs$185$clock = clock;
      regs$185$d = (cnt$47$q == 8'd8) ? add_up$7$y : regs$185$q;
      regs$186$clock = clock;
      regs$186$d = (cnt$33$q == 8'd9) ? add_up$0$y : regs$186$q;
      regs$187$clock = clock;
      regs$187$d = (cnt$35$q == 8'd10) ? add_up$1$y : regs$187$q;
      regs$188$clock = clock;
      regs$188$d = (cnt$33$q == 8'd11) ? add_up$0$y : regs$188$q;
      regs$189$clock = clock;
      regs$189$d = (cnt$35$q == 8'd12) ? add_up$1$y : regs$189$q;
      regs$190$clock = clock;
      regs$190$d = (cnt$33$q == 8'd13) ? add_up$0$y : regs$190$q;
      regs$191$clock = clock;
      regs$191$d = (cnt$43$q == 8'd10) ? add_up$5$y : regs$191$q;
      regs$192$clock = clock;
      regs$192$d = (cnt$45$q == 8'd10) ? add_up$6$y : regs$192$q;
      regs$193$clock = clock;
      regs$193$d = (cnt$27$q == 8'd4) ? add_v$2$y : regs$193$q;
      regs$194$clock = clock;
      regs$194$d = (cnt$27$q == 8'd4) ? regs$193$q : regs$194$q;
      regs$195$clock = clock;
      regs$195$d = (cnt$49$q == 8'd4) ? scale_e$0$y : regs$195$q;
      regs$196$clock = clock;
      regs$196$d = (cnt$49$q == 8'd4) ? regs$195$q : regs$196$q;
      regs$197$clock = clock;
      regs$197$d = (cnt$37$q == 8'd13) ? add_up$2$y : regs$197$q;
      regs$198$clock = clock;
      regs$198$d = (cnt$56$q == 8'd0) ? m_0$2 : regs$198$q;
      regs$199$clock = clock;
      regs$199$d = (cnt$60$q == 8'd0) ? m_1$2 : regs$199$q;
      regs$200$clock = clock;
      regs$200$d = (cnt$64$q == 8'd0) ? m_2$2 : regs$200$q;
      regs$201$clock = clock;
      regs$201$d = (cnt$76$q == 8'd0) ? f_2$0 : regs$201$q;
      regs$202$clock = clock;
      regs$202$d = (cnt$78$q == 8'd0) ? f_2$2 : regs$202$q;
      regs$203$clock = clock;
      regs$203$d = (cnt$86$q == 8'd0) ? v_x$1 : regs$203$q;
      regs$204$clock = clock;
      regs$204$d = (cnt$86$q == 8'd0) ? regs$203$q : regs$204$q;
      regs$205$clock = clock;
      regs$205$d = (cnt$91$q == 8'd0) ? v_z$2 : regs$205$q;
      regs$206$clock = clock;
      regs$206$d = (cnt$91$q == 8'd0) ? regs$205$q : regs$206$q;
      regs$207$clock = clock;
      regs$207$d = (cnt$45$q == 8'd8) ? add_up$6$y : regs$207$q;
      regs$208$clock = clock;
      regs$208$d = (cnt$33$q == 8'd9) ? add_up$0$y : regs$208$q;
      regs$209$clock = clock;
      regs$209$d = (cnt$33$q == 8'd10) ? add_up$0$y : regs$209$q;
      regs$210$clock = clock;
      regs$210$d = (cnt$33$q == 8'd11) ? add_up$0$y : regs$210$q;
      regs$211$clock = clock;
      regs$211$d = (cnt$33$q == 8'd12) ? add_up$0$y : regs$211$q;
      regs$212$clock = clock;
      regs$212$d = (cnt$33$q == 8'd13) ? add_up$0$y : regs$212$q;
      regs$213$clock = clock;
      regs$213$d = (cnt$33$q == 8'd6) ? add_up$0$y : regs$213$q;
      regs$214$clock = clock;
      regs$214$d = (cnt$37$q == 8'd0) ? add_up$2$y : regs$214$q;
      regs$215$clock = clock;
      regs$215$d = (cnt$43$q == 8'd10) ? add_up$5$y : regs$215$q;
      regs$216$clock = clock;
      regs$216$d = (cnt$49$q == 8'd0) ? scale_e$0$y : regs$216$q;
      regs$217$clock = clock;
      regs$217$d = (cnt$37$q == 8'd11) ? add_up$2$y : regs$217$q;
      regs$218$clock = clock;
      regs$218$d = (cnt$29$q == 8'd4) ? add_v$3$y : regs$218$q;
      regs$219$clock = clock;
      regs$219$d = (cnt$29$q == 8'd4) ? regs$218$q : regs$219$q;
      regs$220$clock = clock;
      regs$220$d = (cnt$29$q == 8'd4) ? regs$219$q : regs$220$q;
      regs$221$clock = clock;
      regs$221$d = (cnt$49$q == 8'd4) ? scale_e$0$y : regs$221$q;
      regs$222$clock = clock;
      regs$222$d = (cnt$39$q == 8'd13) ? add_up$3$y : regs$222$q;
      regs$223$clock = clock;
      regs$223$d = (cnt$54$q == 8'd0) ? m_0$0 : regs$223$q;
      regs$224$clock = clock;
      regs$224$d = (cnt$58$q == 8'd0) ? m_1$0 : regs$224$q;
      regs$225$clock = clock;
      regs$225$d = (cnt$62$q == 8'd0) ? m_2$0 : regs$225$q;
      regs$226$clock = clock;
      regs$226$d = (cnt$69$q == 8'd0) ? f_0$1 : regs$226$q;
      regs$227$clock = clock;
      regs$227$d = (cnt$71$q == 8'd0) ? f_0$3 : regs$227$q;
      regs$228$clock = clock;
      regs$228$d = (cnt$87$q == 8'd0) ? v_y$1 : regs$228$q;
      regs$229$clock = clock;
      regs$229$d = (cnt$87$q == 8'd0) ? regs$228$q : regs$229$q;
      regs$230$clock = clock;
      regs$230$d = (cnt$47$q == 8'd8) ? add_up$7$y : regs$230$q;
      regs$231$clock = clock;
      regs$231$d = (cnt$35$q == 8'd10) ? add_up$1$y : regs$231$q;
      regs$232$clock = clock;
      regs$232$d = (cnt$35$q == 8'd12) ? add_up$1$y : regs$232$q;
      regs$233$clock = clock;
      regs$233$d = (cnt$33$q == 8'd6) ? add_up$0$y : regs$233$q;
      regs$234$clock = clock;
      regs$234$d = (cnt$49$q == 8'd13) ? scale_e$0$y : regs$234$q;
      regs$235$clock = clock;
      regs$235$d = (cnt$49$q == 8'd14) ? scale_e$0$y : regs$235$q;
      regs$236$clock = clock;
      regs$236$d = (cnt$49$q == 8'd14) ? regs$235$q : regs$236$q;
      regs$237$clock = clock;
      regs$237$d = (cnt$43$q == 8'd10) ? add_up$5$y : regs$237$q;
      regs$238$clock = clock;
      regs$238$d = (cnt$39$q == 8'd0) ? add_up$3$y : regs$238$q;
      regs$239$clock = clock;
      regs$239$d = (cnt$27$q == 8'd1) ? add_v$2$y : regs$239$q;
      regs$240$clock = clock;
      regs$240$d = (cnt$27$q == 8'd1) ? regs$239$q : regs$240$q;
      regs$241$clock = clock;
      regs$241$d = (cnt$47$q == 8'd10) ? add_up$7$y : regs$241$q;
      regs$242$clock = clock;
      regs$242$d = (cnt$37$q == 8'd11) ? add_up$2$y : regs$242$q;
      regs$243$clock = clock;
      regs$243$d = (cnt$29$q == 8'd4) ? add_v$3$y : regs$243$q;
      regs$244$clock = clock;
      regs$244$d = (cnt$29$q == 8'd4) ? regs$243$q : regs$244$q;
      regs$245$clock = clock;
      regs$245$d = (cnt$37$q == 8'd13) ? add_up$2$y : regs$245$q;
      regs$246$clock = clock;
      regs$246$d = (cnt$39$q == 8'd13) ? add_up$3$y : regs$246$q;
      regs$247$clock = clock;
      regs$247$d = (cnt$55$q == 8'd0) ? m_0$1 : regs$247$q;
      regs$248$clock = clock;
      regs$248$d = (cnt$59$q == 8'd0) ? m_1$1 : regs$248$q;
      regs$249$clock = clock;
      regs$249$d = (cnt$63$q == 8'd0) ? m_2$1 : regs$249$q;
      regs$250$clock = clock;
      regs$250$d = (cnt$73$q == 8'd0) ? f_1$1 : regs$250$q;
      regs$251$clock = clock;
      regs$251$d = (cnt$75$q == 8'd0) ? f_1$3 : regs$251$q;
      regs$252$clock = clock;
      regs$252$d = (cnt$89$q == 8'd0) ? v_x$2 : regs$252$q;
      regs$253$clock = clock;
      regs$253$d = (cnt$89$q == 8'd0) ? regs$252$q : regs$253$q;
      regs$254$clock = clock;
      regs$254$d = (cnt$45$q == 8'd8) ? add_up$6$y : regs$254$q;
      regs$255$clock = clock;
      regs$255$d = (cnt$33$q == 8'd10) ? add_up$0$y : regs$255$q;
      regs$256$clock = clock;
      regs$256$d = (cnt$33$q == 8'd12) ? add_up$0$y : regs$256$q;
      regs$257$clock = clock;
      regs$257$d = (cnt$33$q == 8'd6) ? add_up$0$y : regs$257$q;
      regs$258$clock = clock;
      regs$258$d = (cnt$25$q == 8'd1) ? add_v$1$y : regs$258$q;
      regs$259$clock = clock;
      regs$259$d = (cnt$25$q == 8'd1) ? regs$258$q : regs$259$q;
      regs$260$clock = clock;
      regs$260$d = (cnt$27$q == 8'd3) ? add_v$2$y : regs$260$q;
      regs$261$clock = clock;
      regs$261$d = (cnt$27$q == 8'd3) ? regs$260$q : regs$261$q;
      regs$262$clock = clock;
      regs$262$d = (cnt$27$q == 8'd3) ? regs$261$q : regs$262$q;
      regs$263$clock = clock;
      regs$263$d = (cnt$49$q == 8'd14) ? scale_e$0$y : regs$263$q;
      regs$264$clock = clock;
      regs$264$d = (cnt$45$q == 8'd10) ? add_up$6$y : regs$264$q;
      regs$265$clock = clock;
      regs$265$d = (cnt$47$q == 8'd10) ? add_up$7$y : regs$265$q;
      regs$266$clock = clock;
      regs$266$d = (cnt$37$q == 8'd11) ? add_up$2$y : regs$266$q;
      regs$267$clock = clock;
      regs$267$d = (cnt$41$q == 8'd0) ? add_up$4$y : regs$267$q;
      regs$268$clock = clock;
      regs$268$d = (cnt$49$q == 8'd3) ? scale_e$0$y : regs$268$q;
      regs$269$clock = clock;
      regs$269$d = (cnt$37$q == 8'd13) ? add_up$2$y : regs$269$q;
      regs$270$clock = clock;
      regs$270$d = (cnt$56$q == 8'd0) ? m_0$2 : regs$270$q;
      regs$271$clock = clock;
      regs$271$d = (cnt$60$q == 8'd0) ? m_1$2 : regs$271$q;
      regs$272$clock = clock;
      regs$272$d = (cnt$64$q == 8'd0) ? m_2$2 : regs$272$q;
      regs$273$clock = clock;
      regs$273$d = (cnt$77$q == 8'd0) ? f_2$1 : regs$273$q;
      regs$274$clock = clock;
      regs$274$d = (cnt$79$q == 8'd0) ? f_2$3 : regs$274$q;
      regs$275$clock = clock;
      regs$275$d = (cnt$90$q == 8'd0) ? v_y$2 : regs$275$q;
      regs$276$clock = clock;
      regs$276$d = (cnt$90$q == 8'd0) ? regs$275$q : regs$276$q;
      regs$277$clock = clock;
      regs$277$d = (cnt$47$q == 8'd8) ? add_up$7$y : regs$277$q;
      regs$278$clock = clock;
      regs$278$d = (cnt$35$q == 8'd10) ? add_up$1$y : regs$278$q;
      regs$279$clock = clock;
      regs$279$d = (cnt$35$q == 8'd12) ? add_up$1$y : regs$279$q;
      regs$280$clock = clock;
      regs$280$d = (cnt$49$q == 8'd13) ? scale_e$0$y : regs$280$q;
      regs$281$clock = clock;
      regs$281$d = (cnt$49$q == 8'd13) ? regs$280$q : regs$281$q;
      regs$282$clock = clock;
      regs$282$d = (cnt$27$q == 8'd3) ? add_v$2$y : regs$282$q;
      regs$283$clock = clock;
      regs$283$d = (cnt$27$q == 8'd3) ? regs$282$q : regs$283$q;
      regs$284$clock = clock;
      regs$284$d = (cnt$43$q == 8'd10) ? add_up$5$y : regs$284$q;
      regs$285$clock = clock;
      regs$285$d = (cnt$45$q == 8'd10) ? add_up$6$y : regs$285$q;
      regs$286$clock = clock;
      regs$286$d = (cnt$49$q == 8'd0) ? scale_e$0$y : regs$286$q;
      regs$287$clock = clock;
      regs$287$d = (cnt$47$q == 8'd10) ? add_up$7$y : regs$287$q;
      regs$288$clock = clock;
      regs$288$d = (cnt$29$q == 8'd1) ? add_v$3$y : regs$288$q;
      regs$289$clock = clock;
      regs$289$d = (cnt$29$q == 8'd1) ? regs$288$q : regs$289$q;
      regs$290$clock = clock;
      regs$290$d = (cnt$39$q == 8'd13) ? add_up$3$y : regs$290$q;
      regs$291$clock = clock;
      regs$291$d = (cnt$65$q == 8'd0) ? m_2$3 : regs$291$q;
      regs$292$clock = clock;
      regs$292$d = (cnt$1$q == 8'd8) ? mul_v$0$y : regs$292$q;
      regs$293$clock = clock;
      regs$293$d = (cnt$3$q == 8'd8) ? mul_v$1$y : regs$293$q;
      regs$294$clock = clock;
      regs$294$d = (cnt$5$q == 8'd8) ? mul_v$2$y : regs$294$q;
      regs$295$clock = clock;
      regs$295$d = (cnt$23$q == 8'd0) ? add_v$0$y : regs$295$q;
      regs$296$clock = clock;
      regs$296$d = (cnt$3$q == 8'd9) ? mul_v$1$y : regs$296$q;
      regs$297$clock = clock;
      regs$297$d = (cnt$5$q == 8'd9) ? mul_v$2$y : regs$297$q;
      regs$298$clock = clock;
      regs$298$d = (cnt$7$q == 8'd9) ? mul_v$3$y : regs$298$q;
      regs$299$clock = clock;
      regs$299$d = (cnt$23$q == 8'd1) ? add_v$0$y : regs$299$q;
      regs$300$clock = clock;
      regs$300$d = (cnt$9$q == 8'd9) ? mul_v$4$y : regs$300$q;
      regs$301$clock = clock;
      regs$301$d = (cnt$1$q == 8'd10) ? mul_v$0$y : regs$301$q;
      regs$302$clock = clock;
      regs$302$d = (cnt$23$q == 8'd2) ? add_v$0$y : regs$302$q;
      regs$303$clock = clock;
      regs$303$d = (cnt$25$q == 8'd2) ? add_v$1$y : regs$303$q;
      regs$304$clock = clock;
      regs$304$d = (cnt$1$q == 8'd11) ? mul_v$0$y : regs$304$q;
      regs$305$clock = clock;
      regs$305$d = (cnt$3$q == 8'd11) ? mul_v$1$y : regs$305$q;
      regs$306$clock = clock;
      regs$306$d = (cnt$5$q == 8'd11) ? mul_v$2$y : regs$306$q;
      regs$307$clock = clock;
      regs$307$d = (cnt$23$q == 8'd3) ? add_v$0$y : regs$307$q;
      regs$308$clock = clock;
      regs$308$d = (cnt$3$q == 8'd12) ? mul_v$1$y : regs$308$q;
      regs$309$clock = clock;
      regs$309$d = (cnt$5$q == 8'd12) ? mul_v$2$y : regs$309$q;
      regs$310$clock = clock;
      regs$310$d = (cnt$23$q == 8'd4) ? add_v$0$y : regs$310$q;
      regs$311$clock = clock;
      regs$311$d = (cnt$25$q == 8'd4) ? add_v$1$y : regs$311$q;
      regs$312$clock = clock;
      regs$312$d = (cnt$9$q == 8'd12) ? mul_v$4$y : regs$312$q;
      regs$313$clock = clock;
      regs$313$d = (cnt$1$q == 8'd13) ? mul_v$0$y : regs$313$q;
      regs$314$clock = clock;
      regs$314$d = (cnt$3$q == 8'd13) ? mul_v$1$y : regs$314$q;
      regs$315$clock = clock;
      regs$315$d = (cnt$23$q == 8'd5) ? add_v$0$y : regs$315$q;
      regs$316$clock = clock;
      regs$316$d = (cnt$1$q == 8'd14) ? mul_v$0$y : regs$316$q;
      regs$317$clock = clock;
      regs$317$d = (cnt$3$q == 8'd14) ? mul_v$1$y : regs$317$q;
      regs$318$clock = clock;
      regs$318$d = (cnt$5$q == 8'd14) ? mul_v$2$y : regs$318$q;
      regs$319$clock = clock;
      regs$319$d = (cnt$23$q == 8'd6) ? add_v$0$y : regs$319$q;
      regs$320$clock = clock;
      regs$320$d = (cnt$1$q == 8'd15) ? mul_v$0$y : regs$320$q;
      regs$321$clock = clock;
      regs$321$d = (cnt$25$q == 8'd6) ? add_v$1$y : regs$321$q;
      regs$322$clock = clock;
      regs$322$d = (cnt$23$q == 8'd7) ? add_v$0$y : regs$322$q;
      regs$323$clock = clock;
      regs$323$d = (cnt$57$q == 8'd0) ? m_0$3 : regs$323$q;
      regs$324$clock = clock;
      regs$324$d = (cnt$61$q == 8'd0) ? m_1$3 : regs$324$q;
      regs$325$clock = clock;
      regs$325$d = (cnt$7$q == 8'd8) ? mul_v$3$y : regs$325$q;
      regs$326$clock = clock;
      regs$326$d = (cnt$9$q == 8'd8) ? mul_v$4$y : regs$326$q;
      regs$327$clock = clock;
      regs$327$d = (cnt$1$q == 8'd9) ? mul_v$0$y : regs$327$q;
      regs$328$clock = clock;
      regs$328$d = (cnt$25$q == 8'd0) ? add_v$1$y : regs$328$q;
      regs$329$clock = clock;
      regs$329$d = (cnt$3$q == 8'd10) ? mul_v$1$y : regs$329$q;
      regs$330$clock = clock;
      regs$330$d = (cnt$23$q == 8'd10) ? add_v$0$y : regs$330$q;
      regs$331$clock = clock;
      regs$331$d = (cnt$9$q == 8'd10) ? mul_v$4$y : regs$331$q;
      regs$332$clock = clock;
      regs$332$d = (cnt$27$q == 8'd2) ? add_v$2$y : regs$332$q;
      regs$333$clock = clock;
      regs$333$d = (cnt$7$q == 8'd11) ? mul_v$3$y : regs$333$q;
      regs$334$clock = clock;
      regs$334$d = (cnt$9$q == 8'd11) ? mul_v$4$y : regs$334$q;
      regs$335$clock = clock;
      regs$335$d = (cnt$1$q == 8'd12) ? mul_v$0$y : regs$335$q;
      regs$336$clock = clock;
      regs$336$d = (cnt$25$q == 8'd3) ? add_v$1$y : regs$336$q;
      regs$337$clock = clock;
      regs$337$d = (cnt$7$q == 8'd12) ? mul_v$3$y : regs$337$q;
      regs$338$clock = clock;
      regs$338$d = (cnt$23$q == 8'd12) ? add_v$0$y : regs$338$q;
      regs$339$clock = clock;
      regs$339$d = (cnt$5$q == 8'd13) ? mul_v$2$y : regs$339$q;
      regs$340$clock = clock;
      regs$340$d = (cnt$7$q == 8'd13) ? mul_v$3$y : regs$340$q;
      regs$341$clock = clock;
      regs$341$d = (cnt$9$q == 8'd13) ? mul_v$4$y : regs$341$q;
      regs$342$clock = clock;
      regs$342$d = (cnt$25$q == 8'd5) ? add_v$1$y : regs$342$q;
      regs$343$clock = clock;
      regs$343$d = (cnt$7$q == 8'd14) ? mul_v$3$y : regs$343$q;
      regs$344$clock = clock;
      regs$344$d = (cnt$9$q == 8'd14) ? mul_v$4$y : regs$344$q;
      regs$345$clock = clock;
      regs$345$d = (cnt$23$q == 8'd15) ? add_v$0$y : regs$345$q;
      regs$346$clock = clock;
      regs$346$d = (cnt$1$q == 8'd1) ? mul_v$0$y : regs$346$q;
      regs$347$clock = clock;
      regs$347$d = (cnt$27$q == 8'd8) ? add_v$2$y : regs$347$q;
      regs$348$clock = clock;
      regs$348$d = (cnt$25$q == 8'd9) ? add_v$1$y : regs$348$q;
      regs$349$clock = clock;
      regs$349$d = (cnt$1$q == 8'd6) ? mul_v$0$y : regs$349$q;
      regs$350$clock = clock;
      regs$350$d = (cnt$27$q == 8'd6) ? add_v$2$y : regs$350$q;
      regs$351$clock = clock;
      regs$351$d = (cnt$7$q == 8'd3) ? mul_v$3$y : regs$351$q;
      regs$352$clock = clock;
      regs$352$d = (cnt$29$q == 8'd6) ? add_v$3$y : regs$352$q;
      regs$353$clock = clock;
      regs$353$d = (cnt$3$q == 8'd15) ? mul_v$1$y : regs$353$q;
      regs$354$clock = clock;
      regs$354$d = (cnt$5$q == 8'd15) ? mul_v$2$y : regs$354$q;
      regs$355$clock = clock;
      regs$355$d = (cnt$23$q == 8'd10) ? add_v$0$y : regs$355$q;
      regs$356$clock = clock;
      regs$356$d = (cnt$5$q == 8'd10) ? mul_v$2$y : regs$356$q;
      regs$357$clock = clock;
      regs$357$d = (cnt$7$q == 8'd10) ? mul_v$3$y : regs$357$q;
      regs$358$clock = clock;
      regs$358$d = (cnt$23$q == 8'd15) ? add_v$0$y : regs$358$q;
      regs$359$clock = clock;
      regs$359$d = (cnt$1$q == 8'd0) ? mul_v$0$y : regs$359$q;
      regs$360$clock = clock;
      regs$360$d = (cnt$3$q == 8'd0) ? mul_v$1$y : regs$360$q;
      regs$361$clock = clock;
      regs$361$d = (cnt$1$q == 8'd2) ? mul_v$0$y : regs$361$q;
      regs$362$clock = clock;
      regs$362$d = (cnt$1$q == 8'd3) ? mul_v$0$y : regs$362$q;
      regs$363$clock = clock;
      regs$363$d = (cnt$27$q == 8'd11) ? add_v$2$y : regs$363$q;
      regs$364$clock = clock;
      regs$364$d = (cnt$29$q == 8'd11) ? add_v$3$y : regs$364$q;
      regs$365$clock = clock;
      regs$365$d = (cnt$1$q == 8'd5) ? mul_v$0$y : regs$365$q;
      regs$366$clock = clock;
      regs$366$d = (cnt$3$q == 8'd5) ? mul_v$1$y : regs$366$q;
      regs$367$clock = clock;
      regs$367$d = (cnt$27$q == 8'd13) ? add_v$2$y : regs$367$q;
      regs$368$clock = clock;
      regs$368$d = (cnt$25$q == 8'd14) ? add_v$1$y : regs$368$q;
      regs$369$clock = clock;
      regs$369$d = (cnt$3$q == 8'd1) ? mul_v$1$y : regs$369$q;
      regs$370$clock = clock;
      regs$370$d = (cnt$29$q == 8'd8) ? add_v$3$y : regs$370$q;
      regs$371$clock = clock;
      regs$371$d = (cnt$27$q == 8'd9) ? add_v$2$y : regs$371$q;
      regs$372$clock = clock;
      regs$372$d = (cnt$31$q == 8'd11) ? add_v$4$y : regs$372$q;
      regs$373$clock = clock;
      regs$373$d = (cnt$25$q == 8'd12) ? add_v$1$y : regs$373$q;
      regs$374$clock = clock;
      regs$374$d = (cnt$3$q == 8'd6) ? mul_v$1$y : regs$374$q;
      regs$375$clock = clock;
      regs$375$d = (cnt$29$q == 8'd6) ? add_v$3$y : regs$375$q;
      regs$376$clock = clock;
      regs$376$d = (cnt$5$q == 8'd2) ? mul_v$2$y : regs$376$q;
      regs$377$clock = clock;
      regs$377$d = (cnt$9$q == 8'd3) ? mul_v$4$y : regs$377$q;
      regs$378$clock = clock;
      regs$378$d = (cnt$31$q == 8'd6) ? add_v$4$y : regs$378$q;
      regs$379$clock = clock;
      regs$379$d = (cnt$25$q == 8'd7) ? add_v$1$y : regs$379$q;
      regs$380$clock = clock;
      regs$380$d = (cnt$7$q == 8'd15) ? mul_v$3$y : regs$380$q;
      regs$381$clock = clock;
      regs$381$d = (cnt$9$q == 8'd15) ? mul_v$4$y : regs$381$q;
      regs$382$clock = clock;
      regs$382$d = (cnt$27$q == 8'd7) ? add_v$2$y : regs$382$q;
      regs$383$clock = clock;
      regs$383$d = (cnt$9$q == 8'd1) ? mul_v$4$y : regs$383$q;
      regs$384$clock = clock;
      regs$384$d = (cnt$7$q == 8'd2) ? mul_v$3$y : regs$384$q;
      regs$385$clock = clock;
      regs$385$d = (cnt$23$q == 8'd12) ? add_v$0$y : regs$385$q;
      regs$386$clock = clock;
      regs$386$d = (cnt$3$q == 8'd3) ? mul_v$1$y : regs$386$q;
      regs$387$clock = clock;
      regs$387$d = (cnt$27$q == 8'd6) ? add_v$2$y : regs$387$q;
      regs$388$clock = clock;
      regs$388$d = (cnt$5$q == 8'd0) ? mul_v$2$y : regs$388$q;
      regs$389$clock = clock;
      regs$389$d = (cnt$7$q == 8'd0) ? mul_v$3$y : regs$389$q;
      regs$390$clock = clock;
      regs$390$d = (cnt$5$q == 8'd5) ? mul_v$2$y : regs$390$q;
      regs$391$clock = clock;
      regs$391$d = (cnt$7$q == 8'd5) ? mul_v$3$y : regs$391$q;
      regs$392$clock = clock;
      regs$392$d = (cnt$29$q == 8'd13) ? add_v$3$y : regs$392$q;
      regs$393$clock = clock;
      regs$393$d = (cnt$27$q == 8'd14) ? add_v$2$y : regs$393$q;
      regs$394$clock = clock;
      regs$394$d = (cnt$9$q == 8'd0) ? mul_v$4$y : regs$394$q;
      regs$395$clock = clock;
      regs$395$d = (cnt$5$q == 8'd1) ? mul_v$2$y : regs$395$q;
      regs$396$clock = clock;
      regs$396$d = (cnt$29$q == 8'd9) ? add_v$3$y : regs$396$q;
      regs$397$clock = clock;
      regs$397$d = (cnt$31$q == 8'd9) ? add_v$4$y : regs$397$q;
      regs$398$clock = clock;
      regs$398$d = (cnt$1$q == 8'd4) ? mul_v$0$y : regs$398$q;
      regs$399$clock = clock;
      regs$399$d = (cnt$27$q == 8'd12) ? add_v$2$y : regs$399$q;
      regs$400$clock = clock;
      regs$400$d = (cnt$29$q == 8'd12) ? add_v$3$y : regs$400$q;
      regs$401$clock = clock;
      regs$401$d = (cnt$9$q == 8'd5) ? mul_v$4$y : regs$401$q;
      regs$402$clock = clock;
      regs$402$d = (cnt$5$q == 8'd6) ? mul_v$2$y : regs$402$q;
      regs$403$clock = clock;
      regs$403$d = (cnt$31$q == 8'd6) ? add_v$4$y : regs$403$q;
      regs$404$clock = clock;
      regs$404$d = (cnt$27$q == 8'd15) ? add_v$2$y : regs$404$q;
      regs$405$clock = clock;
      regs$405$d = (cnt$27$q == 8'd15) ? regs$404$q : regs$405$q;
      regs$406$clock = clock;
      regs$406$d = (cnt$31$q == 8'd4) ? add_v$4$y : regs$406$q;
      regs$407$clock = clock;
      regs$407$d = (cnt$31$q == 8'd13) ? add_v$4$y : regs$407$q;
      regs$408$clock = clock;
      regs$408$d = (cnt$31$q == 8'd15) ? add_v$4$y : regs$408$q;
      regs$409$clock = clock;
      regs$409$d = (cnt$23$q == 8'd10) ? add_v$0$y : regs$409$q;
      regs$410$clock = clock;
      regs$410$d = (cnt$23$q == 8'd15) ? add_v$0$y : regs$410$q;
      regs$411$clock = clock;
      regs$411$d = (cnt$3$q == 8'd2) ? mul_v$1$y : regs$411$q;
      regs$412$clock = clock;
      regs$412$d = (cnt$5$q == 8'd3) ? mul_v$2$y : regs$412$q;
      regs$413$clock = clock;
      regs$413$d = (cnt$7$q == 8'd1) ? mul_v$3$y : regs$413$q;
      regs$414$clock = clock;
      regs$414$d = (cnt$7$q == 8'd6) ? mul_v$3$y : regs$414$q;
      regs$415$clock = clock;
      regs$415$d = (cnt$29$q == 8'd14) ? add_v$3$y : regs$415$q;
      regs$416$clock = clock;
      regs$416$d = (cnt$31$q == 8'd14) ? add_v$4$y : regs$416$q;
      regs$417$clock = clock;
      regs$417$d = (cnt$25$q == 8'd15) ? add_v$1$y : regs$417$q;
      regs$418$clock = clock;
      regs$418$d = (cnt$25$q == 8'd15) ? regs$417$q : regs$418$q;
      regs$419$clock = clock;
      regs$419$d = (cnt$27$q == 8'd0) ? add_v$2$y : regs$419$q;
      regs$420$clock = clock;
      regs$420$d = (cnt$27$q == 8'd10) ? add_v$2$y : regs$420$q;
      regs$421$clock = clock;
      regs$421$d = (cnt$9$q == 8'd2) ? mul_v$4$y : regs$421$q;
      regs$422$clock = clock;
      regs$422$d = (cnt$3$q == 8'd4) ? mul_v$1$y : regs$422$q;
      regs$423$clock = clock;
      regs$423$d = (cnt$31$q == 8'd12) ? add_v$4$y : regs$423$q;
      regs$424$clock = clock;
      regs$424$d = (cnt$5$q == 8'd4) ? mul_v$2$y : regs$424$q;
      regs$425$clock = clock;
      regs$425$d = (cnt$7$q == 8'd4) ? mul_v$3$y : regs$425$q;
      regs$426$clock = clock;
      regs$426$d = (cnt$9$q == 8'd4) ? mul_v$4$y : regs$426$q;
      regs$427$clock = clock;
      regs$427$d = (cnt$9$q == 8'd6) ? mul_v$4$y : regs$427$q;
      regs$428$clock = clock;
      regs$428$d = (cnt$29$q == 8'd15) ? add_v$3$y : regs$428$q;
      regs$429$clock = clock;
      regs$429$d = (cnt$29$q == 8'd15) ? regs$428$q : regs$429$q;
      regs$430$clock = clock;
      regs$430$d = (cnt$29$q == 8'd7) ? add_v$3$y : regs$430$q;
      regs$431$clock = clock;
      regs$431$d = (cnt$83$q == 8'd0) ? v_x$0 : regs$431$q;
      regs$432$clock = clock;
      regs$432$d = (cnt$84$q == 8'd0) ? v_y$0 : regs$432$q;
      regs$433$clock = clock;
      regs$433$d = (cnt$11$q == 8'd8) ? mul_up$0$y : regs$433$q;
      regs$434$clock = clock;
      regs$434$d = (cnt$13$q == 8'd8) ? mul_up$1$y : regs$434$q;
      regs$435$clock = clock;
      regs$435$d = (cnt$11$q == 8'd9) ? mul_up$0$y : regs$435$q;
      regs$436$clock = clock;
      regs$436$d = (cnt$13$q == 8'd9) ? mul_up$1$y : regs$436$q;
      regs$437$clock = clock;
      regs$437$d = (cnt$15$q == 8'd9) ? mul_up$2$y : regs$437$q;
      regs$438$clock = clock;
      regs$438$d = (cnt$33$q == 8'd1) ? add_up$0$y : regs$438$q;
      regs$439$clock = clock;
      regs$439$d = (cnt$11$q == 8'd10) ? mul_up$0$y : regs$439$q;
      regs$440$clock = clock;
      regs$440$d = (cnt$13$q == 8'd10) ? mul_up$1$y : regs$440$q;
      regs$441$clock = clock;
      regs$441$d = (cnt$15$q == 8'd10) ? mul_up$2$y : regs$441$q;
      regs$442$clock = clock;
      regs$442$d = (cnt$33$q == 8'd2) ? add_up$0$y : regs$442$q;
      regs$443$clock = clock;
      regs$443$d = (cnt$11$q == 8'd11) ? mul_up$0$y : regs$443$q;
      regs$444$clock = clock;
      regs$444$d = (cnt$13$q == 8'd11) ? mul_up$1$y : regs$444$q;
      regs$445$clock = clock;
      regs$445$d = (cnt$15$q == 8'd11) ? mul_up$2$y : regs$445$q;
      regs$446$clock = clock;
      regs$446$d = (cnt$33$q == 8'd3) ? add_up$0$y : regs$446$q;
      regs$447$clock = clock;
      regs$447$d = (cnt$35$q == 8'd11) ? add_up$1$y : regs$447$q;
      regs$448$clock = clock;
      regs$448$d = (cnt$11$q == 8'd12) ? mul_up$0$y : regs$448$q;
      regs$449$clock = clock;
      regs$449$d = (cnt$13$q == 8'd12) ? mul_up$1$y : regs$449$q;
      regs$450$clock = clock;
      regs$450$d = (cnt$15$q == 8'd12) ? mul_up$2$y : regs$450$q;
      regs$451$clock = clock;
      regs$451$d = (cnt$33$q == 8'd4) ? add_up$0$y : regs$451$q;
      regs$452$clock = clock;
      regs$452$d = (cnt$11$q == 8'd13) ? mul_up$0$y : regs$452$q;
      regs$453$clock = clock;
      regs$453$d = (cnt$13$q == 8'd13) ? mul_up$1$y : regs$453$q;
      regs$454$clock = clock;
      regs$454$d = (cnt$15$q == 8'd13) ? mul_up$2$y : regs$454$q;
      regs$455$clock = clock;
      regs$455$d = (cnt$33$q == 8'd5) ? add_up$0$y : regs$455$q;
      regs$456$clock = clock;
      regs$456$d = (cnt$11$q == 8'd14) ? mul_up$0$y : regs$456$q;
      regs$457$clock = clock;
      regs$457$d = (cnt$13$q == 8'd14) ? mul_up$1$y : regs$457$q;
      regs$458$clock = clock;
      regs$458$d = (cnt$35$q == 8'd6) ? add_up$1$y : regs$458$q;
      regs$459$clock = clock;
      regs$459$d = (cnt$11$q == 8'd1) ? mul_up$0$y : regs$459$q;
      regs$460$clock = clock;
      regs$460$d = (cnt$19$q == 8'd14) ? mul_up$4$y : regs$460$q;
      regs$461$clock = clock;
      regs$461$d = (cnt$33$q == 8'd7) ? add_up$0$y : regs$461$q;
      regs$462$clock = clock;
      regs$462$d = (cnt$15$q == 8'd3) ? mul_up$2$y : regs$462$q;
      regs$463$clock = clock;
      regs$463$d = (cnt$82$q == 8'd0) ? scale : regs$463$q;
      regs$464$clock = clock;
      regs$464$d = (cnt$85$q == 8'd0) ? v_z$0 : regs$464$q;
      regs$465$clock = clock;
      regs$465$d = (cnt$17$q == 8'd8) ? mul_up$3$y : regs$465$q;
      regs$466$clock = clock;
      regs$466$d = (cnt$19$q == 8'd8) ? mul_up$4$y : regs$466$q;
      regs$467$clock = clock;
      regs$467$d = (cnt$17$q == 8'd9) ? mul_up$3$y : regs$467$q;
      regs$468$clock = clock;
      regs$468$d = (cnt$19$q == 8'd9) ? mul_up$4$y : regs$468$q;
      regs$469$clock = clock;
      regs$469$d = (cnt$35$q == 8'd1) ? add_up$1$y : regs$469$q;
      regs$470$clock = clock;
      regs$470$d = (cnt$37$q == 8'd1) ? add_up$2$y : regs$470$q;
      regs$471$clock = clock;
      regs$471$d = (cnt$35$q == 8'd9) ? add_up$1$y : regs$471$q;
      regs$472$clock = clock;
      regs$472$d = (cnt$17$q == 8'd10) ? mul_up$3$y : regs$472$q;
      regs$473$clock = clock;
      regs$473$d = (cnt$19$q == 8'd10) ? mul_up$4$y : regs$473$q;
      regs$474$clock = clock;
      regs$474$d = (cnt$21$q == 8'd10) ? mul_up$5$y : regs$474$q;
      regs$475$clock = clock;
      regs$475$d = (cnt$35$q == 8'd2) ? add_up$1$y : regs$475$q;
      regs$476$clock = clock;
      regs$476$d = (cnt$17$q == 8'd11) ? mul_up$3$y : regs$476$q;
      regs$477$clock = clock;
      regs$477$d = (cnt$19$q == 8'd11) ? mul_up$4$y : regs$477$q;
      regs$478$clock = clock;
      regs$478$d = (cnt$35$q == 8'd3) ? add_up$1$y : regs$478$q;
      regs$479$clock = clock;
      regs$479$d = (cnt$37$q == 8'd3) ? add_up$2$y : regs$479$q;
      regs$480$clock = clock;
      regs$480$d = (cnt$17$q == 8'd12) ? mul_up$3$y : regs$480$q;
      regs$481$clock = clock;
      regs$481$d = (cnt$19$q == 8'd12) ? mul_up$4$y : regs$481$q;
      regs$482$clock = clock;
      regs$482$d = (cnt$21$q == 8'd12) ? mul_up$5$y : regs$482$q;
      regs$483$clock = clock;
      regs$483$d = (cnt$35$q == 8'd4) ? add_up$1$y : regs$483$q;
      regs$484$clock = clock;
      regs$484$d = (cnt$17$q == 8'd13) ? mul_up$3$y : regs$484$q;
      regs$485$clock = clock;
      regs$485$d = (cnt$19$q == 8'd13) ? mul_up$4$y : regs$485$q;
      regs$486$clock = clock;
      regs$486$d = (cnt$35$q == 8'd5) ? add_up$1$y : regs$486$q;
      regs$487$clock = clock;
      regs$487$d = (cnt$37$q == 8'd5) ? add_up$2$y : regs$487$q;
      regs$488$clock = clock;
      regs$488$d = (cnt$35$q == 8'd13) ? add_up$1$y : regs$488$q;
      regs$489$clock = clock;
      regs$489$d = (cnt$15$q == 8'd14) ? mul_up$2$y : regs$489$q;
      regs$490$clock = clock;
      regs$490$d = (cnt$37$q == 8'd6) ? add_up$2$y : regs$490$q;
      regs$491$clock = clock;
      regs$491$d = (cnt$11$q == 8'd3) ? mul_up$0$y : regs$491$q;
      regs$492$clock = clock;
      regs$492$d = (cnt$19$q == 8'd14) ? mul_up$4$y : regs$492$q;
      regs$493$clock = clock;
      regs$493$d = (cnt$35$q == 8'd7) ? add_up$1$y : regs$493$q;
      regs$494$clock = clock;
      regs$494$d = (cnt$15$q == 8'd5) ? mul_up$2$y : regs$494$q;
      regs$495$clock = clock;
      regs$495$d = (cnt$57$q == 8'd0) ? m_0$3 : regs$495$q;
      regs$496$clock = clock;
      regs$496$d = (cnt$61$q == 8'd0) ? m_1$3 : regs$496$q;
      regs$497$clock = clock;
      regs$497$d = (cnt$65$q == 8'd0) ? m_2$3 : regs$497$q;
      regs$498$clock = clock;
      regs$498$d = (cnt$86$q == 8'd0) ? v_x$1 : regs$498$q;
      regs$499$clock = clock;
      regs$499$d = (cnt$87$q == 8'd0) ? v_y$1 : regs$499$q;
      regs$500$clock = clock;
      regs$500$d = (cnt$21$q == 8'd9) ? mul_up$5$y : regs$500$q;
      regs$501$clock = clock;
      regs$501$d = (cnt$21$q == 8'd11) ? mul_up$5$y : regs$501$q;
      regs$502$clock = clock;
      regs$502$d = (cnt$35$q == 8'd11) ? add_up$1$y : regs$502$q;
      regs$503$clock = clock;
      regs$503$d = (cnt$21$q == 8'd13) ? mul_up$5$y : regs$503$q;
      regs$504$clock = clock;
      regs$504$d = (cnt$33$q == 8'd8) ? add_up$0$y : regs$504$q;
      regs$505$clock = clock;
      regs$505$d = (cnt$35$q == 8'd8) ? add_up$1$y : regs$505$q;
      regs$506$clock = clock;
      regs$506$d = (cnt$15$q == 8'd14) ? mul_up$2$y : regs$506$q;
      regs$507$clock = clock;
      regs$507$d = (cnt$11$q == 8'd0) ? mul_up$0$y : regs$507$q;
      regs$508$clock = clock;
      regs$508$d = (cnt$13$q == 8'd0) ? mul_up$1$y : regs$508$q;
      regs$509$clock = clock;
      regs$509$d = (cnt$37$q == 8'd9) ? add_up$2$y : regs$509$q;
      regs$510$clock = clock;
      regs$510$d = (cnt$33$q == 8'd14) ? add_up$0$y : regs$510$q;
      regs$511$clock = clock;
      regs$511$d = (cnt$11$q == 8'd2) ? mul_up$0$y : regs$511$q;
      regs$512$clock = clock;
      regs$512$d = (cnt$13$q == 8'd2) ? mul_up$1$y : regs$512$q;
      regs$513$clock = clock;
      regs$513$d = (cnt$39$q == 8'd6) ? add_up$3$y : regs$513$q;
      regs$514$clock = clock;
      regs$514$d = (cnt$11$q == 8'd4) ? mul_up$0$y : regs$514$q;
      regs$515$clock = clock;
      regs$515$d = (cnt$13$q == 8'd4) ? mul_up$1$y : regs$515$q;
      regs$516$clock = clock;
      regs$516$d = (cnt$11$q == 8'd5) ? mul_up$0$y : regs$516$q;
      regs$517$clock = clock;
      regs$517$d = (cnt$29$q == 8'd6) ? add_v$3$y : regs$517$q;
      regs$518$clock = clock;
      regs$518$d = (cnt$49$q == 8'd2) ? scale_e$0$y : regs$518$q;
      regs$519$clock = clock;
      regs$519$d = (cnt$49$q == 8'd5) ? scale_e$0$y : regs$519$q;
      regs$520$clock = clock;
      regs$520$d = (cnt$53$q == 8'd14) ? scale_s$0$y : regs$520$q;
      regs$521$clock = clock;
      regs$521$d = (cnt$25$q == 8'd7) ? add_v$1$y : regs$521$q;
      regs$522$clock = clock;
      regs$522$d = (cnt$27$q == 8'd7) ? add_v$2$y : regs$522$q;
      regs$523$clock = clock;
      regs$523$d = (cnt$27$q == 8'd10) ? add_v$2$y : regs$523$q;
      regs$524$clock = clock;
      regs$524$d = (cnt$31$q == 8'd12) ? add_v$4$y : regs$524$q;
      regs$525$clock = clock;
      regs$525$d = (cnt$43$q == 8'd11) ? add_up$5$y : regs$525$q;
      regs$526$clock = clock;
      regs$526$d = (cnt$43$q == 8'd11) ? regs$525$q : regs$526$q;
      regs$527$clock = clock;
      regs$527$d = (cnt$53$q == 8'd9) ? scale_s$0$y : regs$527$q;
      regs$528$clock = clock;
      regs$528$d = (cnt$82$q == 8'd0) ? scale : regs$528$q;
      regs$529$clock = clock;
      regs$529$d = (cnt$88$q == 8'd0) ? v_z$1 : regs$529$q;
      regs$530$clock = clock;
      regs$530$d = (cnt$35$q == 8'd13) ? add_up$1$y : regs$530$q;
      regs$531$clock = clock;
      regs$531$d = (cnt$15$q == 8'd14) ? mul_up$2$y : regs$531$q;
      regs$532$clock = clock;
      regs$532$d = (cnt$37$q == 8'd10) ? add_up$2$y : regs$532$q;
      regs$533$clock = clock;
      regs$533$d = (cnt$35$q == 8'd14) ? add_up$1$y : regs$533$q;
      regs$534$clock = clock;
      regs$534$d = (cnt$51$q == 8'd13) ? scale_z$0$y : regs$534$q;
      regs$535$clock = clock;
      regs$535$d = (cnt$37$q == 8'd8) ? add_up$2$y : regs$535$q;
      regs$536$clock = clock;
      regs$536$d = (cnt$39$q == 8'd8) ? add_up$3$y : regs$536$q;
      regs$537$clock = clock;
      regs$537$d = (cnt$41$q == 8'd6) ? add_up$4$y : regs$537$q;
      regs$538$clock = clock;
      regs$538$d = (cnt$15$q == 8'd0) ? mul_up$2$y : regs$538$q;
      regs$539$clock = clock;
      regs$539$d = (cnt$17$q == 8'd0) ? mul_up$3$y : regs$539$q;
      regs$540$clock = clock;
      regs$540$d = (cnt$13$q == 8'd1) ? mul_up$1$y : regs$540$q;
      regs$541$clock = clock;
      regs$541$d = (cnt$15$q == 8'd2) ? mul_up$2$y : regs$541$q;
      regs$542$clock = clock;
      regs$542$d = (cnt$17$q == 8'd2) ? mul_up$3$y : regs$542$q;
      regs$543$clock = clock;
      regs$543$d = (cnt$15$q == 8'd4) ? mul_up$2$y : regs$543$q;
      regs$544$clock = clock;
      regs$544$d = (cnt$17$q == 8'd4) ? mul_up$3$y : regs$544$q;
      regs$545$clock = clock;
      regs$545$d = (cnt$51$q == 8'd14) ? scale_z$0$y : regs$545$q;
      regs$546$clock = clock;
      regs$546$d = (cnt$31$q == 8'd6) ? add_v$4$y : regs$546$q;
      regs$547$clock = clock;
      regs$547$d = (cnt$49$q == 8'd5) ? scale_e$0$y : regs$547$q;
      regs$548$clock = clock;
      regs$548$d = (cnt$47$q == 8'd11) ? add_up$7$y : regs$548$q;
      regs$549$clock = clock;
      regs$549$d = (cnt$41$q == 8'd13) ? add_up$4$y : regs$549$q;
      regs$550$clock = clock;
      regs$550$d = (cnt$39$q == 8'd5) ? add_up$3$y : regs$550$q;
      regs$551$clock = clock;
      regs$551$d = (cnt$39$q == 8'd5) ? regs$550$q : regs$551$q;
      regs$552$clock = clock;
      regs$552$d = (cnt$43$q == 8'd0) ? add_up$5$y : regs$552$q;
      regs$553$clock = clock;
      regs$553$d = (cnt$39$q == 8'd1) ? add_up$3$y : regs$553$q;
      regs$554$clock = clock;
      regs$554$d = (cnt$41$q == 8'd1) ? add_up$4$y : regs$554$q;
      regs$555$clock = clock;
      regs$555$d = (cnt$41$q == 8'd1) ? regs$554$q : regs$555$q;
      regs$556$clock = clock;
      regs$556$d = (cnt$15$q == 8'd6) ? mul_up$2$y : regs$556$q;
      regs$557$clock = clock;
      regs$557$d = (cnt$17$q == 8'd6) ? mul_up$3$y : regs$557$q;
      regs$558$clock = clock;
      regs$558$d = (cnt$47$q == 8'd15) ? add_up$7$y : regs$558$q;
      regs$559$clock = clock;
      regs$559$d = (cnt$43$q == 8'd12) ? add_up$5$y : regs$559$q;
      regs$560$clock = clock;
      regs$560$d = (cnt$29$q == 8'd15) ? add_v$3$y : regs$560$q;
      regs$561$clock = clock;
      regs$561$d = (cnt$29$q == 8'd15) ? regs$560$q : regs$561$q;
      regs$562$clock = clock;
      regs$562$d = (cnt$45$q == 8'd11) ? add_up$6$y : regs$562$q;
      regs$563$clock = clock;
      regs$563$d = (cnt$89$q == 8'd0) ? v_x$2 : regs$563$q;
      regs$564$clock = clock;
      regs$564$d = (cnt$90$q == 8'd0) ? v_y$2 : regs$564$q;
      regs$565$clock = clock;
      regs$565$d = (cnt$35$q == 8'd9) ? add_up$1$y : regs$565$q;
      regs$566$clock = clock;
      regs$566$d = (cnt$37$q == 8'd12) ? add_up$2$y : regs$566$q;
      regs$567$clock = clock;
      regs$567$d = (cnt$37$q == 8'd14) ? add_up$2$y : regs$567$q;
      regs$568$clock = clock;
      regs$568$d = (cnt$17$q == 8'd14) ? mul_up$3$y : regs$568$q;
      regs$569$clock = clock;
      regs$569$d = (cnt$43$q == 8'd6) ? add_up$5$y : regs$569$q;
      regs$570$clock = clock;
      regs$570$d = (cnt$13$q == 8'd3) ? mul_up$1$y : regs$570$q;
      regs$571$clock = clock;
      regs$571$d = (cnt$51$q == 8'd14) ? scale_z$0$y : regs$571$q;
      regs$572$clock = clock;
      regs$572$d = (cnt$41$q == 8'd8) ? add_up$4$y : regs$572$q;
      regs$573$clock = clock;
      regs$573$d = (cnt$43$q == 8'd8) ? add_up$5$y : regs$573$q;
      regs$574$clock = clock;
      regs$574$d = (cnt$19$q == 8'd0) ? mul_up$4$y : regs$574$q;
      regs$575$clock = clock;
      regs$575$d = (cnt$21$q == 8'd0) ? mul_up$5$y : regs$575$q;
      regs$576$clock = clock;
      regs$576$d = (cnt$19$q == 8'd2) ? mul_up$4$y : regs$576$q;
      regs$577$clock = clock;
      regs$577$d = (cnt$21$q == 8'd2) ? mul_up$5$y : regs$577$q;
      regs$578$clock = clock;
      regs$578$d = (cnt$19$q == 8'd4) ? mul_up$4$y : regs$578$q;
      regs$579$clock = clock;
      regs$579$d = (cnt$21$q == 8'd4) ? mul_up$5$y : regs$579$q;
      regs$580$clock = clock;
      regs$580$d = (cnt$51$q == 8'd15) ? scale_z$0$y : regs$580$q;
      regs$581$clock = clock;
      regs$581$d = (cnt$21$q == 8'd3) ? mul_up$5$y : regs$581$q;
      regs$582$clock = clock;
      regs$582$d = (cnt$17$q == 8'd5) ? mul_up$3$y : regs$582$q;
      regs$583$clock = clock;
      regs$583$d = (cnt$39$q == 8'd11) ? add_up$3$y : regs$583$q;
      regs$584$clock = clock;
      regs$584$d = (cnt$39$q == 8'd11) ? regs$583$q : regs$584$q;
      regs$585$clock = clock;
      regs$585$d = (cnt$53$q == 8'd3) ? scale_s$0$y : regs$585$q;
      regs$586$clock = clock;
      regs$586$d = (cnt$19$q == 8'd6) ? mul_up$4$y : regs$586$q;
      regs$587$clock = clock;
      regs$587$d = (cnt$21$q == 8'd6) ? mul_up$5$y : regs$587$q;
      regs$588$clock = clock;
      regs$588$d = (cnt$43$q == 8'd1) ? add_up$5$y : regs$588$q;
      regs$589$clock = clock;
      regs$589$d = (cnt$45$q == 8'd1) ? add_up$6$y : regs$589$q;
      regs$590$clock = clock;
      regs$590$d = (cnt$45$q == 8'd1) ? regs$589$q : regs$590$q;
      regs$591$clock = clock;
      regs$591$d = (cnt$45$q == 8'd12) ? add_up$6$y : regs$591$q;
      regs$592$clock = clock;
      regs$592$d = (cnt$47$q == 8'd12) ? add_up$7$y : regs$592$q;
      regs$593$clock = clock;
      regs$593$d = (cnt$82$q == 8'd0) ? scale : regs$593$q;
      regs$594$clock = clock;
      regs$594$d = (cnt$91$q == 8'd0) ? v_z$2 : regs$594$q;
      regs$595$clock = clock;
      regs$595$d = (cnt$35$q == 8'd11) ? add_up$1$y : regs$595$q;
      regs$596$clock = clock;
      regs$596$d = (cnt$51$q == 8'd13) ? scale_z$0$y : regs$596$q;
      regs$597$clock = clock;
      regs$597$d = (cnt$49$q == 8'd15) ? scale_e$0$y : regs$597$q;
      regs$598$clock = clock;
      regs$598$d = (cnt$53$q == 8'd12) ? scale_s$0$y : regs$598$q;
      regs$599$clock = clock;
      regs$599$d = (cnt$17$q == 8'd14) ? mul_up$3$y : regs$599$q;
      regs$600$clock = clock;
      regs$600$d = (cnt$39$q == 8'd9) ? add_up$3$y : regs$600$q;
      regs$601$clock = clock;
      regs$601$d = (cnt$39$q == 8'd14) ? add_up$3$y : regs$601$q;
      regs$602$clock = clock;
      regs$602$d = (cnt$45$q == 8'd6) ? add_up$6$y : regs$602$q;
      regs$603$clock = clock;
      regs$603$d = (cnt$13$q == 8'd5) ? mul_up$1$y : regs$603$q;
      regs$604$clock = clock;
      regs$604$d = (cnt$41$q == 8'd9) ? add_up$4$y : regs$604$q;
      regs$605$clock = clock;
      regs$605$d = (cnt$45$q == 8'd14) ? add_up$6$y : regs$605$q;
      regs$606$clock = clock;
      regs$606$d = (cnt$51$q == 8'd15) ? scale_z$0$y : regs$606$q;
      regs$607$clock = clock;
      regs$607$d = (cnt$19$q == 8'd5) ? mul_up$4$y : regs$607$q;
      regs$608$clock = clock;
      regs$608$d = (cnt$21$q == 8'd5) ? mul_up$5$y : regs$608$q;
      regs$609$clock = clock;
      regs$609$d = (cnt$43$q == 8'd13) ? add_up$5$y : regs$609$q;
      regs$610$clock = clock;
      regs$610$d = (cnt$47$q == 8'd14) ? add_up$7$y : regs$610$q;
      regs$611$clock = clock;
      regs$611$d = (cnt$45$q == 8'd0) ? add_up$6$y : regs$611$q;
      regs$612$clock = clock;
      regs$612$d = (cnt$11$q == 8'd7) ? mul_up$0$y : regs$612$q;
      regs$613$clock = clock;
      regs$613$d = (cnt$13$q == 8'd7) ? mul_up$1$y : regs$613$q;
      regs$614$clock = clock;
      regs$614$d = (cnt$47$q == 8'd0) ? add_up$7$y : regs$614$q;
      regs$615$clock = clock;
      regs$615$d = (cnt$21$q == 8'd14) ? mul_up$5$y : regs$615$q;
      regs$616$clock = clock;
      regs$616$d = (cnt$11$q == 8'd15) ? mul_up$0$y : regs$616$q;
      regs$617$clock = clock;
      regs$617$d = (cnt$47$q == 8'd1) ? add_up$7$y : regs$617$q;
      regs$618$clock = clock;
      regs$618$d = (cnt$37$q == 8'd2) ? add_up$2$y : regs$618$q;
      regs$619$clock = clock;
      regs$619$d = (cnt$37$q == 8'd2) ? regs$618$q : regs$619$q;
      regs$620$clock = clock;
      regs$620$d = (cnt$15$q == 8'd8) ? mul_up$2$y : regs$620$q;
      regs$621$clock = clock;
      regs$621$d = (cnt$33$q == 8'd0) ? add_up$0$y : regs$621$q;
      regs$622$clock = clock;
      regs$622$d = (cnt$35$q == 8'd13) ? add_up$1$y : regs$622$q;
      regs$623$clock = clock;
      regs$623$d = (cnt$27$q == 8'd6) ? add_v$2$y : regs$623$q;
      regs$624$clock = clock;
      regs$624$d = (cnt$49$q == 8'd15) ? scale_e$0$y : regs$624$q;
      regs$625$clock = clock;
      regs$625$d = (cnt$17$q == 8'd14) ? mul_up$3$y : regs$625$q;
      regs$626$clock = clock;
      regs$626$d = (cnt$39$q == 8'd10) ? add_up$3$y : regs$626$q;
      regs$627$clock = clock;
      regs$627$d = (cnt$41$q == 8'd14) ? add_up$4$y : regs$627$q;
      regs$628$clock = clock;
      regs$628$d = (cnt$47$q == 8'd6) ? add_up$7$y : regs$628$q;
      regs$629$clock = clock;
      regs$629$d = (cnt$15$q == 8'd1) ? mul_up$2$y : regs$629$q;
      regs$630$clock = clock;
      regs$630$d = (cnt$41$q == 8'd10) ? add_up$4$y : regs$630$q;
      regs$631$clock = clock;
      regs$631$d = (cnt$33$q == 8'd15) ? add_up$0$y : regs$631$q;
      regs$632$clock = clock;
      regs$632$d = (cnt$25$q == 8'd15) ? add_v$1$y : regs$632$q;
      regs$633$clock = clock;
      regs$633$d = (cnt$25$q == 8'd15) ? regs$632$q : regs$633$q;
      regs$634$clock = clock;
      regs$634$d = (cnt$37$q == 8'd15) ? add_up$2$y : regs$634$q;
      regs$635$clock = clock;
      regs$635$d = (cnt$39$q == 8'd15) ? add_up$3$y : regs$635$q;
      regs$636$clock = clock;
      regs$636$d = (cnt$41$q == 8'd15) ? add_up$4$y : regs$636$q;
      regs$637$clock = clock;
      regs$637$d = (cnt$15$q == 8'd7) ? mul_up$2$y : regs$637$q;
      regs$638$clock = clock;
      regs$638$d = (cnt$17$q == 8'd7) ? mul_up$3$y : regs$638$q;
      regs$639$clock = clock;
      regs$639$d = (cnt$41$q == 8'd11) ? add_up$4$y : regs$639$q;
      regs$640$clock = clock;
      regs$640$d = (cnt$41$q == 8'd11) ? regs$639$q : regs$640$q;
      regs$641$clock = clock;
      regs$641$d = (cnt$53$q == 8'd4) ? scale_s$0$y : regs$641$q;
      regs$642$clock = clock;
      regs$642$d = (cnt$31$q == 8'd13) ? add_v$4$y : regs$642$q;
      regs$643$clock = clock;
      regs$643$d = (cnt$31$q == 8'd15) ? add_v$4$y : regs$643$q;
      regs$644$clock = clock;
      regs$644$d = (cnt$13$q == 8'd15) ? mul_up$1$y : regs$644$q;
      regs$645$clock = clock;
      regs$645$d = (cnt$15$q == 8'd15) ? mul_up$2$y : regs$645$q;
      regs$646$clock = clock;
      regs$646$d = (cnt$21$q == 8'd8) ? mul_up$5$y : regs$646$q;
      regs$647$clock = clock;
      regs$647$d = (cnt$35$q == 8'd0) ? add_up$1$y : regs$647$q;
      regs$648$clock = clock;
      regs$648$d = (cnt$35$q == 8'd9) ? add_up$1$y : regs$648$q;
      regs$649$clock = clock;
      regs$649$d = (cnt$39$q == 8'd12) ? add_up$3$y : regs$649$q;
      regs$650$clock = clock;
      regs$650$d = (cnt$43$q == 8'd14) ? add_up$5$y : regs$650$q;
      regs$651$clock = clock;
      regs$651$d = (cnt$49$q == 8'd2) ? scale_e$0$y : regs$651$q;
      regs$652$clock = clock;
      regs$652$d = (cnt$53$q == 8'd13) ? scale_s$0$y : regs$652$q;
      regs$653$clock = clock;
      regs$653$d = (cnt$19$q == 8'd14) ? mul_up$4$y : regs$653$q;
      regs$654$clock = clock;
      regs$654$d = (cnt$41$q == 8'd12) ? add_up$4$y : regs$654$q;
      regs$655$clock = clock;
      regs$655$d = (cnt$35$q == 8'd15) ? add_up$1$y : regs$655$q;
      regs$656$clock = clock;
      regs$656$d = (cnt$17$q == 8'd3) ? mul_up$3$y : regs$656$q;
      regs$657$clock = clock;
      regs$657$d = (cnt$19$q == 8'd3) ? mul_up$4$y : regs$657$q;
      regs$658$clock = clock;
      regs$658$d = (cnt$11$q == 8'd6) ? mul_up$0$y : regs$658$q;
      regs$659$clock = clock;
      regs$659$d = (cnt$13$q == 8'd6) ? mul_up$1$y : regs$659$q;
      regs$660$clock = clock;
      regs$660$d = (cnt$43$q == 8'd15) ? add_up$5$y : regs$660$q;
      regs$661$clock = clock;
      regs$661$d = (cnt$45$q == 8'd15) ? add_up$6$y : regs$661$q;
      regs$662$clock = clock;
      regs$662$d = (cnt$27$q == 8'd15) ? add_v$2$y : regs$662$q;
      regs$663$clock = clock;
      regs$663$d = (cnt$27$q == 8'd15) ? regs$662$q : regs$663$q;
      regs$664$clock = clock;
      regs$664$d = (cnt$37$q == 8'd4) ? add_up$2$y : regs$664$q;
      regs$665$clock = clock;
      regs$665$d = (cnt$19$q == 8'd7) ? mul_up$4$y : regs$665$q;
      regs$666$clock = clock;
      regs$666$d = (cnt$21$q == 8'd7) ? mul_up$5$y : regs$666$q;
      regs$667$clock = clock;
      regs$667$d = (cnt$39$q == 8'd4) ? add_up$3$y : regs$667$q;
      regs$668$clock = clock;
      regs$668$d = (cnt$17$q == 8'd15) ? mul_up$3$y : regs$668$q;
      regs$669$clock = clock;
      regs$669$d = (cnt$19$q == 8'd15) ? mul_up$4$y : regs$669$q;
      regs$670$clock = clock;
      regs$670$d = (cnt$41$q == 8'd4) ? add_up$4$y : regs$670$q;
      regs$671$clock = clock;
      regs$671$d = (cnt$37$q == 8'd7) ? add_up$2$y : regs$671$q;
      regs$672$clock = clock;
      regs$672$d = (cnt$39$q == 8'd7) ? add_up$3$y : regs$672$q;
      regs$673$clock = clock;
      regs$673$d = (cnt$41$q == 8'd7) ? add_up$4$y : regs$673$q;
      regs$674$clock = clock;
      regs$674$d = (cnt$43$q == 8'd7) ? add_up$5$y : regs$674$q;
      regs$675$clock = clock;
      regs$675$d = (cnt$45$q == 8'd7) ? add_up$6$y : regs$675$q;
      regs$676$clock = clock;
      regs$676$d = (cnt$47$q == 8'd7) ? add_up$7$y : regs$676$q;
      regs$677$clock = clock;
      regs$677$d = (cnt$43$q == 8'd9) ? add_up$5$y : regs$677$q;
      regs$678$clock = clock;
      regs$678$d = (cnt$45$q == 8'd9) ? add_up$6$y : regs$678$q;
      regs$679$clock = clock;
      regs$679$d = (cnt$47$q == 8'd9) ? add_up$7$y : regs$679$q;
      regs$680$clock = clock;
      regs$680$d = (cnt$41$q == 8'd7) ? add_up$4$y : regs$680$q;
      regs$681$clock = clock;
      regs$681$d = (cnt$47$q == 8'd7) ? add_up$7$y : regs$681$q;
      regs$682$clock = clock;
      regs$682$d = (cnt$47$q == 8'd9) ? add_up$7$y : regs$682$q;
      regs$683$clock = clock;
      regs$683$d = (cnt$27$q == 8'd6) ? add_v$2$y : regs$683$q;
      regs$684$clock = clock;
      regs$684$d = (cnt$29$q == 8'd6) ? add_v$3$y : regs$684$q;
      regs$685$clock = clock;
      regs$685$d = (cnt$31$q == 8'd6) ? add_v$4$y : regs$685$q;
      regs$686$clock = clock;
      regs$686$d = (cnt$45$q == 8'd13) ? add_up$6$y : regs$686$q;
      regs$687$clock = clock;
      regs$687$d = (cnt$47$q == 8'd13) ? add_up$7$y : regs$687$q;
      regs$688$clock = clock;
      regs$688$d = (cnt$39$q == 8'd3) ? add_up$3$y : regs$688$q;
      regs$689$clock = clock;
      regs$689$d = (cnt$27$q == 8'd6) ? add_v$2$y : regs$689$q;
      regs$690$clock = clock;
      regs$690$d = (cnt$27$q == 8'd6) ? regs$689$q : regs$690$q;
      regs$691$clock = clock;
      regs$691$d = (cnt$27$q == 8'd6) ? regs$690$q : regs$691$q;
      regs$692$clock = clock;
      regs$692$d = (cnt$27$q == 8'd6) ? regs$691$q : regs$692$q;
      regs$693$clock = clock;
      regs$693$d = (cnt$27$q == 8'd6) ? regs$692$q : regs$693$q;
      regs$694$clock = clock;
      regs$694$d = (cnt$27$q == 8'd6) ? regs$693$q : regs$694$q;
      regs$695$clock = clock;
      regs$695$d = (cnt$49$q == 8'd15) ? scale_e$0$y : regs$695$q;
      regs$696$clock = clock;
      regs$696$d = (cnt$49$q == 8'd15) ? regs$695$q : regs$696$q;
      regs$697$clock = clock;
      regs$697$d = (cnt$49$q == 8'd15) ? regs$696$q : regs$697$q;
      regs$698$clock = clock;
      regs$698$d = (cnt$49$q == 8'd15) ? regs$697$q : regs$698$q;
      regs$699$clock = clock;
      regs$699$d = (cnt$49$q == 8'd15) ? regs$698$q : regs$699$q;
      regs$700$clock = clock;
      regs$700$d = (cnt$49$q == 8'd15) ? regs$699$q : regs$700$q;
      regs$701$clock = clock;
      regs$701$d = (cnt$29$q == 8'd6) ? add_v$3$y : regs$701$q;
      regs$702$clock = clock;
      regs$702$d = (cnt$29$q == 8'd6) ? regs$701$q : regs$702$q;
      regs$703$clock = clock;
      regs$703$d = (cnt$29$q == 8'd6) ? regs$702$q : regs$703$q;
      regs$704$clock = clock;
      regs$704$d = (cnt$29$q == 8'd6) ? regs$703$q : regs$704$q;
      regs$705$clock = clock;
      regs$705$d = (cnt$29$q == 8'd6) ? regs$704$q : regs$705$q;
      regs$706$clock = clock;
      regs$706$d = (cnt$29$q == 8'd6) ? regs$705$q : regs$706$q;
      regs$707$clock = clock;
      regs$707$d = (cnt$49$q == 8'd2) ? scale_e$0$y : regs$707$q;
      regs$708$clock = clock;
      regs$708$d = (cnt$49$q == 8'd2) ? regs$707$q : regs$708$q;
      regs$709$clock = clock;
      regs$709$d = (cnt$49$q == 8'd2) ? regs$708$q : regs$709$q;
      regs$710$clock = clock;
      regs$710$d = (cnt$49$q == 8'd2) ? regs$709$q : regs$710$q;
      regs$711$clock = clock;
      regs$711$d = (cnt$49$q == 8'd2) ? regs$710$q : regs$711$q;
      regs$712$clock = clock;
      regs$712$d = (cnt$49$q == 8'd2) ? regs$711$q : regs$712$q;
      regs$713$clock = clock;
      regs$713$d = (cnt$31$q == 8'd6) ? add_v$4$y : regs$713$q;
      regs$714$clock = clock;
      regs$714$d = (cnt$31$q == 8'd6) ? regs$713$q : regs$714$q;
      regs$715$clock = clock;
      regs$715$d = (cnt$31$q == 8'd6) ? regs$714$q : regs$715$q;
      regs$716$clock = clock;
      regs$716$d = (cnt$31$q == 8'd6) ? regs$715$q : regs$716$q;
      regs$717$clock = clock;
      regs$717$d = (cnt$31$q == 8'd6) ? regs$716$q : regs$717$q;
      regs$718$clock = clock;
      regs$718$d = (cnt$31$q == 8'd6) ? regs$717$q : regs$718$q;
      regs$719$clock = clock;
      regs$719$d = (cnt$49$q == 8'd5) ? scale_e$0$y : regs$719$q;
      regs$720$clock = clock;
      regs$720$d = (cnt$49$q == 8'd5) ? regs$719$q : regs$720$q;
      regs$721$clock = clock;
      regs$721$d = (cnt$49$q == 8'd5) ? regs$720$q : regs$721$q;
      regs$722$clock = clock;
      regs$722$d = (cnt$49$q == 8'd5) ? regs$721$q : regs$722$q;
      regs$723$clock = clock;
      regs$723$d = (cnt$49$q == 8'd5) ? regs$722$q : regs$723$q;
      regs$724$clock = clock;
      regs$724$d = (cnt$25$q == 8'd7) ? add_v$1$y : regs$724$q;
      regs$725$clock = clock;
      regs$725$d = (cnt$25$q == 8'd7) ? regs$724$q : regs$725$q;
      regs$726$clock = clock;
      regs$726$d = (cnt$25$q == 8'd7) ? regs$725$q : regs$726$q;
      regs$727$clock = clock;
      regs$727$d = (cnt$25$q == 8'd7) ? regs$726$q : regs$727$q;
      regs$728$clock = clock;
      regs$728$d = (cnt$25$q == 8'd7) ? regs$727$q : regs$728$q;
      regs$729$clock = clock;
      regs$729$d = (cnt$39$q == 8'd5) ? add_up$3$y : regs$729$q;
      regs$730$clock = clock;
      regs$730$d = (cnt$39$q == 8'd5) ? regs$729$q : regs$730$q;
      regs$731$clock = clock;
      regs$731$d = (cnt$39$q == 8'd5) ? regs$730$q : regs$731$q;
      regs$732$clock = clock;
      regs$732$d = (cnt$27$q == 8'd7) ? add_v$2$y : regs$732$q;
      regs$733$clock = clock;
      regs$733$d = (cnt$27$q == 8'd7) ? regs$732$q : regs$733$q;
      regs$734$clock = clock;
      regs$734$d = (cnt$27$q == 8'd7) ? regs$733$q : regs$734$q;
      regs$735$clock = clock;
      regs$735$d = (cnt$27$q == 8'd7) ? regs$734$q : regs$735$q;
      regs$736$clock = clock;
      regs$736$d = (cnt$27$q == 8'd7) ? regs$735$q : regs$736$q;
      regs$737$clock = clock;
      regs$737$d = (cnt$43$q == 8'd0) ? add_up$5$y : regs$737$q;
      regs$738$clock = clock;
      regs$738$d = (cnt$43$q == 8'd0) ? regs$737$q : regs$738$q;
      regs$739$clock = clock;
      regs$739$d = (cnt$43$q == 8'd0) ? regs$738$q : regs$739$q;
      regs$740$clock = clock;
      regs$740$d = (cnt$25$q == 8'd15) ? add_v$1$y : regs$740$q;
      regs$741$clock = clock;
      regs$741$d = (cnt$25$q == 8'd15) ? regs$740$q : regs$741$q;
      regs$742$clock = clock;
      regs$742$d = (cnt$25$q == 8'd15) ? regs$741$q : regs$742$q;
      regs$743$clock = clock;
      regs$743$d = (cnt$25$q == 8'd15) ? regs$742$q : regs$743$q;
      regs$744$clock = clock;
      regs$744$d = (cnt$25$q == 8'd15) ? regs$743$q : regs$744$q;
      regs$745$clock = clock;
      regs$745$d = (cnt$25$q == 8'd15) ? regs$744$q : regs$745$q;
      regs$746$clock = clock;
      regs$746$d = (cnt$39$q == 8'd11) ? add_up$3$y : regs$746$q;
      regs$747$clock = clock;
      regs$747$d = (cnt$39$q == 8'd11) ? regs$746$q : regs$747$q;
      regs$748$clock = clock;
      regs$748$d = (cnt$39$q == 8'd11) ? regs$747$q : regs$748$q;
      regs$749$clock = clock;
      regs$749$d = (cnt$39$q == 8'd11) ? regs$748$q : regs$749$q;
      regs$750$clock = clock;
      regs$750$d = (cnt$39$q == 8'd11) ? regs$749$q : regs$750$q;
      regs$751$clock = clock;
      regs$751$d = (cnt$31$q == 8'd8) ? add_v$4$y : regs$751$q;
      regs$752$clock = clock;
      regs$752$d = (cnt$31$q == 8'd8) ? regs$751$q : regs$752$q;
      regs$753$clock = clock;
      regs$753$d = (cnt$31$q == 8'd8) ? regs$752$q : regs$753$q;
      regs$754$clock = clock;
      regs$754$d = (cnt$31$q == 8'd8) ? regs$753$q : regs$754$q;
      regs$755$clock = clock;
      regs$755$d = (cnt$39$q == 8'd2) ? add_up$3$y : regs$755$q;
      regs$756$clock = clock;
      regs$756$d = (cnt$27$q == 8'd10) ? add_v$2$y : regs$756$q;
      regs$757$clock = clock;
      regs$757$d = (cnt$27$q == 8'd10) ? regs$756$q : regs$757$q;
      regs$758$clock = clock;
      regs$758$d = (cnt$27$q == 8'd10) ? regs$757$q : regs$758$q;
      regs$759$clock = clock;
      regs$759$d = (cnt$27$q == 8'd10) ? regs$758$q : regs$759$q;
      regs$760$clock = clock;
      regs$760$d = (cnt$27$q == 8'd10) ? regs$759$q : regs$760$q;
      regs$761$clock = clock;
      regs$761$d = (cnt$45$q == 8'd0) ? add_up$6$y : regs$761$q;
      regs$762$clock = clock;
      regs$762$d = (cnt$45$q == 8'd0) ? regs$761$q : regs$762$q;
      regs$763$clock = clock;
      regs$763$d = (cnt$45$q == 8'd0) ? regs$762$q : regs$763$q;
      regs$764$clock = clock;
      regs$764$d = (cnt$31$q == 8'd12) ? add_v$4$y : regs$764$q;
      regs$765$clock = clock;
      regs$765$d = (cnt$31$q == 8'd12) ? regs$764$q : regs$765$q;
      regs$766$clock = clock;
      regs$766$d = (cnt$31$q == 8'd12) ? regs$765$q : regs$766$q;
      regs$767$clock = clock;
      regs$767$d = (cnt$31$q == 8'd12) ? regs$766$q : regs$767$q;
      regs$768$clock = clock;
      regs$768$d = (cnt$31$q == 8'd12) ? regs$767$q : regs$768$q;
      regs$769$clock = clock;
      regs$769$d = (cnt$47$q == 8'd0) ? add_up$7$y : regs$769$q;
      regs$770$clock = clock;
      regs$770$d = (cnt$47$q == 8'd0) ? regs$769$q : regs$770$q;
      regs$771$clock = clock;
      regs$771$d = (cnt$47$q == 8'd0) ? regs$770$q : regs$771$q;
      regs$772$clock = clock;
      regs$772$d = (cnt$27$q == 8'd15) ? add_v$2$y : regs$772$q;
      regs$773$clock = clock;
      regs$773$d = (cnt$27$q == 8'd15) ? regs$772$q : regs$773$q;
      regs$774$clock = clock;
      regs$774$d = (cnt$27$q == 8'd15) ? regs$773$q : regs$774$q;
      regs$775$clock = clock;
      regs$775$d = (cnt$27$q == 8'd15) ? regs$774$q : regs$775$q;
      regs$776$clock = clock;
      regs$776$d = (cnt$27$q == 8'd15) ? regs$775$q : regs$776$q;
      regs$777$clock = clock;
      regs$777$d = (cnt$27$q == 8'd15) ? regs$776$q : regs$777$q;
      regs$778$clock = clock;
      regs$778$d = (cnt$41$q == 8'd11) ? add_up$4$y : regs$778$q;
      regs$779$clock = clock;
      regs$779$d = (cnt$41$q == 8'd11) ? regs$778$q : regs$779$q;
      regs$780$clock = clock;
      regs$780$d = (cnt$41$q == 8'd11) ? regs$779$q : regs$780$q;
      regs$781$clock = clock;
      regs$781$d = (cnt$41$q == 8'd11) ? regs$780$q : regs$781$q;
      regs$782$clock = clock;
      regs$782$d = (cnt$41$q == 8'd11) ? regs$781$q : regs$782$q;
      regs$783$clock = clock;
      regs$783$d = (cnt$29$q == 8'd0) ? add_v$3$y : regs$783$q;
      regs$784$clock = clock;
      regs$784$d = (cnt$29$q == 8'd0) ? regs$783$q : regs$784$q;
      regs$785$clock = clock;
      regs$785$d = (cnt$29$q == 8'd0) ? regs$784$q : regs$785$q;
      regs$786$clock = clock;
      regs$786$d = (cnt$29$q == 8'd0) ? regs$785$q : regs$786$q;
      regs$787$clock = clock;
      regs$787$d = (cnt$41$q == 8'd2) ? add_up$4$y : regs$787$q;
      regs$788$clock = clock;
      regs$788$d = (cnt$31$q == 8'd13) ? add_v$4$y : regs$788$q;
      regs$789$clock = clock;
      regs$789$d = (cnt$31$q == 8'd13) ? regs$788$q : regs$789$q;
      regs$790$clock = clock;
      regs$790$d = (cnt$31$q == 8'd13) ? regs$789$q : regs$790$q;
      regs$791$clock = clock;
      regs$791$d = (cnt$31$q == 8'd13) ? regs$790$q : regs$791$q;
      regs$792$clock = clock;
      regs$792$d = (cnt$31$q == 8'd13) ? regs$791$q : regs$792$q;
      regs$793$clock = clock;
      regs$793$d = (cnt$39$q == 8'd4) ? add_up$3$y : regs$793$q;
      regs$794$clock = clock;
      regs$794$d = (cnt$39$q == 8'd4) ? regs$793$q : regs$794$q;
      regs$795$clock = clock;
      regs$795$d = (cnt$31$q == 8'd15) ? add_v$4$y : regs$795$q;
      regs$796$clock = clock;
      regs$796$d = (cnt$31$q == 8'd15) ? regs$795$q : regs$796$q;
      regs$797$clock = clock;
      regs$797$d = (cnt$31$q == 8'd15) ? regs$796$q : regs$797$q;
      regs$798$clock = clock;
      regs$798$d = (cnt$31$q == 8'd15) ? regs$797$q : regs$798$q;
      regs$799$clock = clock;
      regs$799$d = (cnt$31$q == 8'd15) ? regs$798$q : regs$799$q;
      regs$800$clock = clock;
      regs$800$d = (cnt$41$q == 8'd4) ? add_up$4$y : regs$800$q;
      regs$801$clock = clock;
      regs$801$d = (cnt$41$q == 8'd4) ? regs$800$q : regs$801$q;
      regs$802$clock = clock;
      regs$802$d = (cnt$29$q == 8'd15) ? add_v$3$y : regs$802$q;
      regs$803$clock = clock;
      regs$803$d = (cnt$29$q == 8'd15) ? regs$802$q : regs$803$q;
      regs$804$clock = clock;
      regs$804$d = (cnt$29$q == 8'd15) ? regs$803$q : regs$804$q;
      regs$805$clock = clock;
      regs$805$d = (cnt$29$q == 8'd15) ? regs$804$q : regs$805$q;
      regs$806$clock = clock;
      regs$806$d = (cnt$29$q == 8'd15) ? regs$805$q : regs$806$q;
      regs$807$clock = clock;
      regs$807$d = (cnt$29$q == 8'd15) ? regs$806$q : regs$807$q;
      regs$808$clock = clock;
      regs$808$d = (cnt$43$q == 8'd11) ? add_up$5$y : regs$808$q;
      regs$809$clock = clock;
      regs$809$d = (cnt$43$q == 8'd11) ? regs$808$q : regs$809$q;
      regs$810$clock = clock;
      regs$810$d = (cnt$43$q == 8'd11) ? regs$809$q : regs$810$q;
      regs$811$clock = clock;
      regs$811$d = (cnt$43$q == 8'd11) ? regs$810$q : regs$811$q;
      regs$812$clock = clock;
      regs$812$d = (cnt$43$q == 8'd11) ? regs$811$q : regs$812$q;
      regs$813$clock = clock;
      regs$813$d = (cnt$31$q == 8'd0) ? add_v$4$y : regs$813$q;
      regs$814$clock = clock;
      regs$814$d = (cnt$31$q == 8'd0) ? regs$813$q : regs$814$q;
      regs$815$clock = clock;
      regs$815$d = (cnt$31$q == 8'd0) ? regs$814$q : regs$815$q;
      regs$816$clock = clock;
      regs$816$d = (cnt$31$q == 8'd0) ? regs$815$q : regs$816$q;
      regs$817$clock = clock;
      regs$817$d = (cnt$43$q == 8'd2) ? add_up$5$y : regs$817$q;
      exact$0$clock = clock;
      exact$0$d = (counter$q == 8'd0) ? v_exact : exact$0$q;
      exact$1$clock = clock;
      exact$1$d = (counter$q == 8'd0) ? exact$0$q : exact$1$q;
      exact$2$clock = clock;
      exact$2$d = (counter$q == 8'd0) ? exact$1$q : exact$2$q;
      exact$3$clock = clock;
      exact$3$d = (counter$q == 8'd0) ? exact$2$q : exact$3$q;
      valid$0$clock = clock;
      valid$0$d = (counter$q == 8'd0) ? valid_in : valid$0$q;
      valid$1$clock = clock;
      valid$1$d = (counter$q == 8'd0) ? valid$0$q : valid$1$q;
      valid$2$clock = clock;
      valid$2$d = (counter$q == 8'd0) ? valid$1$q : valid$2$q;
      valid$3$clock = clock;
      valid$3$d = (counter$q == 8'd0) ? valid$2$q : valid$3$q;
      valid$4$clock = clock;
      valid$4$d = (counter$q == 8'd0) ? valid$3$q : valid$4$q;
      valid$5$clock = clock;
      valid$5$d = (counter$q == 8'd0) ? valid$4$q : valid$5$q;
      valid$6$clock = clock;
      valid$6$d = (counter$q == 8'd0) ? valid$5$q : valid$6$q;
      valid$7$clock = clock;
      valid$7$d = (counter$q == 8'd0) ? valid$6$q : valid$7$q;
      valid$8$clock = clock;
      valid$8$d = (counter$q == 8'd0) ? valid$7$q : valid$8$q;
      valid$9$clock = clock;
      valid$9$d = (counter$q == 8'd0) ? valid$8$q : valid$9$q;
      tags$0$clock = clock;
      tags$0$d = (counter$q == 8'd0) ? tag : tags$0$q;
      tags$1$clock = clock;
      tags$1$d = (counter$q == 8'd0) ? tags$0$q : tags$1$q;
      tags$2$clock = clock;
      tags$2$d = (counter$q == 8'd0) ? tags$1$q : tags$2$q;
      tags$3$clock = clock;
      tags$3$d = (counter$q == 8'd0) ? tags$2$q : tags$3$q;
      tags$4$clock = clock;
      tags$4$d = (counter$q == 8'd0) ? tags$3$q : tags$4$q;
      tags$5$clock = clock;
      tags$5$d = (counter$q == 8'd0) ? tags$4$q : tags$5$q;
      tags$6$clock = clock;
      tags$6$d = (counter$q == 8'd0) ? tags$5$q : tags$6$q;
      tags$7$clock = clock;
      tags$7$d = (counter$q == 8'd0) ? tags$6$q : tags$7$q;
      tags$8$clock = clock;
      tags$8$d = (counter$q == 8'd0) ? tags$7$q : tags$8$q;
      tags$9$clock = clock;
      tags$9$d = (counter$q == 8'd0) ? tags$8$q : tags$9$q;
      mul_v$0$clock = clock;
      mul_v$0$valid_in = 1'b0;
      op_a$0$clock = clock;
      mul_v$0$a = op_a$0$q;
      op_b$0$clock = clock;
      mul_v$0$b = op_b$0$q;
      case (cnt$0$q)
        8'd1: begin op_a$0$d = regs$0$q; op_b$0$d = regs$8$q; end
        8'd2: begin op_a$0$d = regs$2$q; op_b$0$d = regs$13$q; end
        8'd3: begin op_a$0$d = regs$1$q; op_b$0$d = regs$12$q; end
        8'd4: begin op_a$0$d = regs$3$q; op_b$0$d = regs$9$q; end
        8'd5: begin op_a$0$d = regs$4$q; op_b$0$d = regs$14$q; end
        8'd6: begin op_a$0$d = regs$6$q; op_b$0$d = regs$11$q; end
        8'd7: begin op_a$0$d = regs$5$q; op_b$0$d = regs$10$q; end
        8'd8: begin op_a$0$d = regs$7$q; op_b$0$d = regs$15$q; end
        8'd9: begin op_a$0$d = regs$24$q; op_b$0$d = regs$17$q; end
        8'd10: begin op_a$0$d = regs$25$q; op_b$0$d = regs$21$q; end
        8'd11: begin op_a$0$d = regs$26$q; op_b$0$d = regs$17$q; end
        8'd12: begin op_a$0$d = regs$27$q; op_b$0$d = regs$19$q; end
        8'd13: begin op_a$0$d = regs$28$q; op_b$0$d = regs$23$q; end
        8'd14: begin op_a$0$d = regs$29$q; op_b$0$d = regs$17$q; end
        8'd15: begin op_a$0$d = regs$30$q; op_b$0$d = regs$21$q; end
        default: begin op_a$0$d = 24'd0; op_b$0$d = 24'd0; end
      endcase
      mul_v$1$clock = clock;
      mul_v$1$valid_in = 1'b0;
      op_a$1$clock = clock;
      mul_v$1$a = op_a$1$q;
      op_b$1$clock = clock;
      mul_v$1$b = op_b$1$q;
      case (cnt$2$q)
        8'd1: begin op_a$1$d = regs$32$q; op_b$1$d = regs$40$q; end
        8'd2: begin op_a$1$d = regs$31$q; op_b$1$d = regs$38$q; end
        8'd3: begin op_a$1$d = regs$33$q; op_b$1$d = regs$44$q; end
        8'd4: begin op_a$1$d = regs$35$q; op_b$1$d = regs$41$q; end
        8'd5: begin op_a$1$d = regs$34$q; op_b$1$d = regs$39$q; end
        8'd6: begin op_a$1$d = regs$37$q; op_b$1$d = regs$43$q; end
        8'd7: begin op_a$1$d = regs$36$q; op_b$1$d = regs$42$q; end
        8'd8: begin op_a$1$d = regs$59$q; op_b$1$d = regs$60$q; end
        8'd9: begin op_a$1$d = regs$53$q; op_b$1$d = regs$46$q; end
        8'd10: begin op_a$1$d = regs$54$q; op_b$1$d = regs$52$q; end
        8'd11: begin op_a$1$d = regs$55$q; op_b$1$d = regs$50$q; end
        8'd12: begin op_a$1$d = regs$56$q; op_b$1$d = regs$48$q; end
        8'd13: begin op_a$1$d = regs$61$q; op_b$1$d = regs$60$q; end
        8'd14: begin op_a$1$d = regs$57$q; op_b$1$d = regs$46$q; end
        8'd15: begin op_a$1$d = regs$58$q; op_b$1$d = regs$52$q; end
        default: begin op_a$1$d = 24'd0; op_b$1$d = 24'd0; end
      endcase
      mul_v$2$clock = clock;
      mul_v$2$valid_in = 1'b0;
      op_a$2$clock = clock;
      mul_v$2$a = op_a$2$q;
      op_b$2$clock = clock;
      mul_v$2$b = op_b$2$q;
      case (cnt$4$q)
        8'd1: begin op_a$2$d = regs$63$q; op_b$2$d = regs$73$q; end
        8'd2: begin op_a$2$d = regs$62$q; op_b$2$d = regs$71$q; end
        8'd3: begin op_a$2$d = regs$64$q; op_b$2$d = regs$69$q; end
        8'd4: begin op_a$2$d = regs$66$q; op_b$2$d = regs$74$q; end
        8'd5: begin op_a$2$d = regs$65$q; op_b$2$d = regs$72$q; end
        8'd6: begin op_a$2$d = regs$67$q; op_b$2$d = regs$70$q; end
        8'd7: begin op_a$2$d = regs$68$q; op_b$2$d = regs$75$q; end
        8'd8: begin op_a$2$d = regs$91$q; op_b$2$d = regs$90$q; end
        8'd9: begin op_a$2$d = regs$84$q; op_b$2$d = regs$77$q; end
        8'd10: begin op_a$2$d = regs$85$q; op_b$2$d = regs$83$q; end
        8'd11: begin op_a$2$d = regs$86$q; op_b$2$d = regs$81$q; end
        8'd12: begin op_a$2$d = regs$87$q; op_b$2$d = regs$79$q; end
        8'd13: begin op_a$2$d = regs$92$q; op_b$2$d = regs$90$q; end
        8'd14: begin op_a$2$d = regs$88$q; op_b$2$d = regs$77$q; end
        8'd15: begin op_a$2$d = regs$89$q; op_b$2$d = regs$83$q; end
        default: begin op_a$2$d = 24'd0; op_b$2$d = 24'd0; end
      endcase
      mul_v$3$clock = clock;
      mul_v$3$valid_in = 1'b0;
      op_a$3$clock = clock;
      mul_v$3$a = op_a$3$q;
      op_b$3$clock = clock;
      mul_v$3$b = op_b$3$q;
      case (cnt$6$q)
        8'd1: begin op_a$3$d = regs$93$q; op_b$3$d = regs$100$q; end
        8'd2: begin op_a$3$d = regs$94$q; op_b$3$d = regs$105$q; end
        8'd3: begin op_a$3$d = regs$96$q; op_b$3$d = regs$103$q; end
        8'd4: begin op_a$3$d = regs$95$q; op_b$3$d = regs$101$q; end
        8'd5: begin op_a$3$d = regs$97$q; op_b$3$d = regs$106$q; end
        8'd6: begin op_a$3$d = regs$99$q; op_b$3$d = regs$104$q; end
        8'd7: begin op_a$3$d = regs$98$q; op_b$3$d = regs$102$q; end
        8'd8: begin op_a$3$d = regs$119$q; op_b$3$d = regs$120$q; end
        8'd9: begin op_a$3$d = regs$113$q; op_b$3$d = regs$108$q; end
        8'd10: begin op_a$3$d = regs$114$q; op_b$3$d = regs$112$q; end
        8'd11: begin op_a$3$d = regs$121$q; op_b$3$d = regs$120$q; end
        8'd12: begin op_a$3$d = regs$115$q; op_b$3$d = regs$110$q; end
        8'd13: begin op_a$3$d = regs$118$q; op_b$3$d = regs$122$q; end
        8'd14: begin op_a$3$d = regs$116$q; op_b$3$d = regs$108$q; end
        8'd15: begin op_a$3$d = regs$117$q; op_b$3$d = regs$112$q; end
        default: begin op_a$3$d = 24'd0; op_b$3$d = 24'd0; end
      endcase
      mul_v$4$clock = clock;
      mul_v$4$valid_in = 1'b0;
      op_a$4$clock = clock;
      mul_v$4$a = op_a$4$q;
      op_b$4$clock = clock;
      mul_v$4$b = op_b$4$q;
      case (cnt$8$q)
        8'd1: begin op_a$4$d = regs$124$q; op_b$4$d = regs$132$q; end
        8'd2: begin op_a$4$d = regs$123$q; op_b$4$d = regs$131$q; end
        8'd3: begin op_a$4$d = regs$126$q; op_b$4$d = regs$135$q; end
        8'd4: begin op_a$4$d = regs$125$q; op_b$4$d = regs$133$q; end
        8'd5: begin op_a$4$d = regs$127$q; op_b$4$d = regs$130$q; end
        8'd6: begin op_a$4$d = regs$129$q; op_b$4$d = regs$136$q; end
        8'd7: begin op_a$4$d = regs$128$q; op_b$4$d = regs$134$q; end
        8'd8: begin op_a$4$d = regs$147$q; op_b$4$d = regs$145$q; end
        8'd9: begin op_a$4$d = regs$141$q; op_b$4$d = regs$138$q; end
        8'd10: begin op_a$4$d = regs$146$q; op_b$4$d = regs$149$q; end
        8'd11: begin op_a$4$d = regs$147$q; op_b$4$d = regs$149$q; end
        8'd12: begin op_a$4$d = regs$142$q; op_b$4$d = regs$140$q; end
        8'd13: begin op_a$4$d = regs$148$q; op_b$4$d = regs$145$q; end
        8'd14: begin op_a$4$d = regs$143$q; op_b$4$d = regs$138$q; end
        8'd15: begin op_a$4$d = regs$144$q; op_b$4$d = regs$149$q; end
        default: begin op_a$4$d = 24'd0; op_b$4$d = 24'd0; end
      endcase
      mul_up$0$clock = clock;
      mul_up$0$valid_in = 1'b0;
      op_a$5$clock = clock;
      mul_up$0$a = op_a$5$q;
      op_b$5$clock = clock;
      mul_up$0$b = op_b$5$q;
      case (cnt$10$q)
        8'd0: begin op_a$5$d = regs$171$q; op_b$5$d = regs$173$q; end
        8'd1: begin op_a$5$d = {1'b0, regs$150$q[22:0]}; op_b$5$d = {1'b0, regs$154$q[22:0]}; end
        8'd2: begin op_a$5$d = {1'b0, regs$150$q[22:0]}; op_b$5$d = {1'b0, regs$155$q[22:0]}; end
        8'd3: begin op_a$5$d = {1'b0, regs$151$q[22:0]}; op_b$5$d = {1'b0, regs$154$q[22:0]}; end
        8'd4: begin op_a$5$d = {1'b0, regs$151$q[22:0]}; op_b$5$d = {1'b0, regs$155$q[22:0]}; end
        8'd5: begin op_a$5$d = {1'b0, regs$152$q[22:0]}; op_b$5$d = {1'b0, regs$154$q[22:0]}; end
        8'd6: begin op_a$5$d = {1'b0, regs$152$q[22:0]}; op_b$5$d = {1'b0, regs$155$q[22:0]}; end
        8'd7: begin op_a$5$d = regs$153$q; op_b$5$d = regs$156$q; end
        8'd8: begin op_a$5$d = {1'b0, regs$169$q[22:0]}; op_b$5$d = regs$172$q; end
        8'd9: begin op_a$5$d = {1'b0, regs$161$q[22:0]}; op_b$5$d = {1'b0, regs$158$q[22:0]}; end
        8'd10: begin op_a$5$d = {1'b0, regs$162$q[22:0]}; op_b$5$d = {1'b0, regs$160$q[22:0]}; end
        8'd11: begin op_a$5$d = {1'b0, regs$163$q[22:0]}; op_b$5$d = {1'b0, regs$158$q[22:0]}; end
        8'd12: begin op_a$5$d = {1'b0, regs$164$q[22:0]}; op_b$5$d = {1'b0, regs$160$q[22:0]}; end
        8'd13: begin op_a$5$d = {1'b0, regs$165$q[22:0]}; op_b$5$d = {1'b0, regs$158$q[22:0]}; end
        8'd14: begin op_a$5$d = {1'b0, regs$166$q[22:0]}; op_b$5$d = {1'b0, regs$160$q[22:0]}; end
        8'd15: begin op_a$5$d = regs$171$q; op_b$5$d = regs$170$q; end
        default: begin op_a$5$d = 24'd0; op_b$5$d = 24'd0; end
      endcase
      mul_up$1$clock = clock;
      mul_up$1$valid_in = 1'b0;
      op_a$6$clock = clock;
      mul_up$1$a = op_a$6$q;
      op_b$6$clock = clock;
      mul_up$1$b = op_b$6$q;
      case (cnt$12$q)
        8'd0: begin op_a$6$d = {1'b0, regs$194$q[22:0]}; op_b$6$d = regs$197$q; end
        8'd1: begin op_a$6$d = {1'b0, regs$174$q[22:0]}; op_b$6$d = {1'b0, regs$178$q[22:0]}; end
        8'd2: begin op_a$6$d = {1'b0, regs$174$q[22:0]}; op_b$6$d = {1'b0, regs$179$q[22:0]}; end
        8'd3: begin op_a$6$d = {1'b0, regs$175$q[22:0]}; op_b$6$d = {1'b0, regs$178$q[22:0]}; end
        8'd4: begin op_a$6$d = {1'b0, regs$175$q[22:0]}; op_b$6$d = {1'b0, regs$179$q[22:0]}; end
        8'd5: begin op_a$6$d = {1'b0, regs$176$q[22:0]}; op_b$6$d = {1'b0, regs$178$q[22:0]}; end
        8'd6: begin op_a$6$d = {1'b0, regs$176$q[22:0]}; op_b$6$d = {1'b0, regs$179$q[22:0]}; end
        8'd7: begin op_a$6$d = regs$177$q; op_b$6$d = regs$180$q; end
        8'd8: begin op_a$6$d = regs$196$q; op_b$6$d = regs$192$q; end
        8'd9: begin op_a$6$d = {1'b0, regs$185$q[22:0]}; op_b$6$d = {1'b0, regs$182$q[22:0]}; end
        8'd10: begin op_a$6$d = {1'b0, regs$186$q[22:0]}; op_b$6$d = {1'b0, regs$184$q[22:0]}; end
        8'd11: begin op_a$6$d = {1'b0, regs$187$q[22:0]}; op_b$6$d = {1'b0, regs$182$q[22:0]}; end
        8'd12: begin op_a$6$d = {1'b0, regs$188$q[22:0]}; op_b$6$d = {1'b0, regs$184$q[22:0]}; end
        8'd13: begin op_a$6$d = {1'b0, regs$189$q[22:0]}; op_b$6$d = {1'b0, regs$182$q[22:0]}; end
        8'd14: begin op_a$6$d = {1'b0, regs$190$q[22:0]}; op_b$6$d = {1'b0, regs$184$q[22:0]}; end
        8'd15: begin op_a$6$d = {1'b0, regs$194$q[22:0]}; op_b$6$d = regs$191$q; end
        default: begin op_a$6$d = 24'd0; op_b$6$d = 24'd0; end
      endcase
      mul_up$2$clock = clock;
      mul_up$2$valid_in = 1'b0;
      op_a$7$clock = clock;
      mul_up$2$a = op_a$7$q;
      op_b$7$clock = clock;
      mul_up$2$b = op_b$7$q;
      case (cnt$14$q)
        8'd0: begin op_a$7$d = regs$221$q; op_b$7$d = regs$217$q; end
        8'd1: begin op_a$7$d = {1'b0, regs$198$q[22:0]}; op_b$7$d = {1'b0, regs$201$q[22:0]}; end
        8'd2: begin op_a$7$d = {1'b0, regs$198$q[22:0]}; op_b$7$d = {1'b0, regs$202$q[22:0]}; end
        8'd3: begin op_a$7$d = {1'b0, regs$199$q[22:0]}; op_b$7$d = {1'b0, regs$201$q[22:0]}; end
        8'd4: begin op_a$7$d = {1'b0, regs$199$q[22:0]}; op_b$7$d = {1'b0, regs$202$q[22:0]}; end
        8'd5: begin op_a$7$d = {1'b0, regs$200$q[22:0]}; op_b$7$d = {1'b0, regs$201$q[22:0]}; end
        8'd6: begin op_a$7$d = {1'b0, regs$200$q[22:0]}; op_b$7$d = {1'b0, regs$202$q[22:0]}; end
        8'd7: begin op_a$7$d = regs$213$q; op_b$7$d = regs$214$q; end
        8'd8: begin op_a$7$d = {1'b0, regs$220$q[22:0]}; op_b$7$d = regs$215$q; end
        8'd9: begin op_a$7$d = {1'b0, regs$207$q[22:0]}; op_b$7$d = {1'b0, regs$204$q[22:0]}; end
        8'd10: begin op_a$7$d = {1'b0, regs$208$q[22:0]}; op_b$7$d = {1'b0, regs$206$q[22:0]}; end
        8'd11: begin op_a$7$d = {1'b0, regs$209$q[22:0]}; op_b$7$d = {1'b0, regs$204$q[22:0]}; end
        8'd12: begin op_a$7$d = {1'b0, regs$210$q[22:0]}; op_b$7$d = {1'b0, regs$206$q[22:0]}; end
        8'd13: begin op_a$7$d = {1'b0, regs$211$q[22:0]}; op_b$7$d = {1'b0, regs$204$q[22:0]}; end
        8'd14: begin op_a$7$d = {1'b0, regs$212$q[22:0]}; op_b$7$d = {1'b0, regs$206$q[22:0]}; end
        8'd15: begin op_a$7$d = regs$216$q; op_b$7$d = regs$222$q; end
        default: begin op_a$7$d = 24'd0; op_b$7$d = 24'd0; end
      endcase
      mul_up$3$clock = clock;
      mul_up$3$valid_in = 1'b0;
      op_a$8$clock = clock;
      mul_up$3$a = op_a$8$q;
      op_b$8$clock = clock;
      mul_up$3$b = op_b$8$q;
      case (cnt$16$q)
        8'd0: begin op_a$8$d = {1'b0, regs$244$q[22:0]}; op_b$8$d = regs$241$q; end
        8'd1: begin op_a$8$d = {1'b0, regs$223$q[22:0]}; op_b$8$d = {1'b0, regs$226$q[22:0]}; end
        8'd2: begin op_a$8$d = {1'b0, regs$223$q[22:0]}; op_b$8$d = {1'b0, regs$227$q[22:0]}; end
        8'd3: begin op_a$8$d = {1'b0, regs$224$q[22:0]}; op_b$8$d = {1'b0, regs$226$q[22:0]}; end
        8'd4: begin op_a$8$d = {1'b0, regs$224$q[22:0]}; op_b$8$d = {1'b0, regs$227$q[22:0]}; end
        8'd5: begin op_a$8$d = {1'b0, regs$225$q[22:0]}; op_b$8$d = {1'b0, regs$226$q[22:0]}; end
        8'd6: begin op_a$8$d = {1'b0, regs$225$q[22:0]}; op_b$8$d = {1'b0, regs$227$q[22:0]}; end
        8'd7: begin op_a$8$d = regs$233$q; op_b$8$d = regs$238$q; end
        8'd8: begin op_a$8$d = regs$236$q; op_b$8$d = regs$246$q; end
        8'd9: begin op_a$8$d = {1'b0, regs$230$q[22:0]}; op_b$8$d = {1'b0, regs$229$q[22:0]}; end
        8'd11: begin op_a$8$d = {1'b0, regs$231$q[22:0]}; op_b$8$d = {1'b0, regs$229$q[22:0]}; end
        8'd12: begin op_a$8$d = regs$234$q; op_b$8$d = regs$242$q; end
        8'd13: begin op_a$8$d = {1'b0, regs$232$q[22:0]}; op_b$8$d = {1'b0, regs$229$q[22:0]}; end
        8'd14: begin op_a$8$d = {1'b0, regs$240$q[22:0]}; op_b$8$d = regs$237$q; end
        8'd15: begin op_a$8$d = {1'b0, regs$240$q[22:0]}; op_b$8$d = regs$245$q; end
        default: begin op_a$8$d = 24'd0; op_b$8$d = 24'd0; end
      endcase
      mul_up$4$clock = clock;
      mul_up$4$valid_in = 1'b0;
      op_a$9$clock = clock;
      mul_up$4$a = op_a$9$q;
      op_b$9$clock = clock;
      mul_up$4$b = op_b$9$q;
      case (cnt$18$q)
        8'd0: begin op_a$9$d = regs$268$q; op_b$9$d = regs$264$q; end
        8'd1: begin op_a$9$d = {1'b0, regs$247$q[22:0]}; op_b$9$d = {1'b0, regs$250$q[22:0]}; end
        8'd2: begin op_a$9$d = {1'b0, regs$247$q[22:0]}; op_b$9$d = {1'b0, regs$251$q[22:0]}; end
        8'd3: begin op_a$9$d = {1'b0, regs$248$q[22:0]}; op_b$9$d = {1'b0, regs$250$q[22:0]}; end
        8'd4: begin op_a$9$d = {1'b0, regs$248$q[22:0]}; op_b$9$d = {1'b0, regs$251$q[22:0]}; end
        8'd5: begin op_a$9$d = {1'b0, regs$249$q[22:0]}; op_b$9$d = {1'b0, regs$250$q[22:0]}; end
        8'd6: begin op_a$9$d = {1'b0, regs$249$q[22:0]}; op_b$9$d = {1'b0, regs$251$q[22:0]}; end
        8'd7: begin op_a$9$d = regs$257$q; op_b$9$d = regs$267$q; end
        8'd8: begin op_a$9$d = {1'b0, regs$262$q[22:0]}; op_b$9$d = regs$269$q; end
        8'd9: begin op_a$9$d = {1'b0, regs$254$q[22:0]}; op_b$9$d = {1'b0, regs$253$q[22:0]}; end
        8'd11: begin op_a$9$d = {1'b0, regs$255$q[22:0]}; op_b$9$d = {1'b0, regs$253$q[22:0]}; end
        8'd12: begin op_a$9$d = {1'b0, regs$259$q[22:0]}; op_b$9$d = regs$265$q; end
        8'd13: begin op_a$9$d = {1'b0, regs$256$q[22:0]}; op_b$9$d = {1'b0, regs$253$q[22:0]}; end
        8'd14: begin op_a$9$d = regs$263$q; op_b$9$d = regs$266$q; end
        8'd15: begin op_a$9$d = regs$268$q; op_b$9$d = regs$266$q; end
        default: begin op_a$9$d = 24'd0; op_b$9$d = 24'd0; end
      endcase
      mul_up$5$clock = clock;
      mul_up$5$valid_in = 1'b0;
      op_a$10$clock = clock;
      mul_up$5$a = op_a$10$q;
      op_b$10$clock = clock;
      mul_up$5$b = op_b$10$q;
      case (cnt$20$q)
        8'd0: begin op_a$10$d = {1'b0, regs$289$q[22:0]}; op_b$10$d = regs$284$q; end
        8'd1: begin op_a$10$d = {1'b0, regs$270$q[22:0]}; op_b$10$d = {1'b0, regs$273$q[22:0]}; end
        8'd2: begin op_a$10$d = {1'b0, regs$270$q[22:0]}; op_b$10$d = {1'b0, regs$274$q[22:0]}; end
        8'd3: begin op_a$10$d = {1'b0, regs$271$q[22:0]}; op_b$10$d = {1'b0, regs$273$q[22:0]}; end
        8'd4: begin op_a$10$d = {1'b0, regs$271$q[22:0]}; op_b$10$d = {1'b0, regs$274$q[22:0]}; end
        8'd5: begin op_a$10$d = {1'b0, regs$272$q[22:0]}; op_b$10$d = {1'b0, regs$273$q[22:0]}; end
        8'd6: begin op_a$10$d = {1'b0, regs$272$q[22:0]}; op_b$10$d = {1'b0, regs$274$q[22:0]}; end
        8'd7: begin op_a$10$d = regs$281$q; op_b$10$d = regs$290$q; end
        8'd9: begin op_a$10$d = {1'b0, regs$277$q[22:0]}; op_b$10$d = {1'b0, regs$276$q[22:0]}; end
        8'd11: begin op_a$10$d = {1'b0, regs$278$q[22:0]}; op_b$10$d = {1'b0, regs$276$q[22:0]}; end
        8'd12: begin op_a$10$d = regs$286$q; op_b$10$d = regs$285$q; end
        8'd13: begin op_a$10$d = {1'b0, regs$279$q[22:0]}; op_b$10$d = {1'b0, regs$276$q[22:0]}; end
        8'd14: begin op_a$10$d = {1'b0, regs$283$q[22:0]}; op_b$10$d = regs$287$q; end
        8'd15: begin op_a$10$d = {1'b0, regs$289$q[22:0]}; op_b$10$d = regs$287$q; end
        default: begin op_a$10$d = 24'd0; op_b$10$d = 24'd0; end
      endcase
      add_v$0$clock = clock;
      add_v$0$valid_in = 1'b0;
      op_a$11$clock = clock;
      add_v$0$a = op_a$11$q;
      op_b$11$clock = clock;
      add_v$0$b = op_b$11$q;
      op_sub$0$clock = clock;
      add_v$0$sub = op_sub$0$q;
      case (cnt$22$q)
        8'd0: begin op_a$11$d = regs$320$q; op_b$11$d = regs$291$q; op_sub$0$d = 1'b0; end
        8'd1: begin op_a$11$d = regs$295$q; op_b$11$d = regs$294$q; op_sub$0$d = 1'b0; end
        8'd2: begin op_a$11$d = regs$299$q; op_b$11$d = regs$298$q; op_sub$0$d = 1'b0; end
        8'd3: begin op_a$11$d = regs$302$q; op_b$11$d = regs$303$q; op_sub$0$d = 1'b0; end
        8'd4: begin op_a$11$d = regs$307$q; op_b$11$d = regs$306$q; op_sub$0$d = 1'b0; end
        8'd5: begin op_a$11$d = regs$310$q; op_b$11$d = regs$311$q; op_sub$0$d = 1'b0; end
        8'd6: begin op_a$11$d = regs$315$q; op_b$11$d = regs$314$q; op_sub$0$d = 1'b0; end
        8'd7: begin op_a$11$d = regs$319$q; op_b$11$d = regs$318$q; op_sub$0$d = 1'b0; end
        8'd8: begin op_a$11$d = regs$321$q; op_b$11$d = regs$322$q; op_sub$0$d = 1'b0; end
        8'd9: begin op_a$11$d = regs$292$q; op_b$11$d = regs$293$q; op_sub$0$d = 1'b0; end
        8'd10: begin op_a$11$d = regs$296$q; op_b$11$d = regs$297$q; op_sub$0$d = 1'b0; end
        8'd11: begin op_a$11$d = regs$300$q; op_b$11$d = regs$301$q; op_sub$0$d = 1'b0; end
        8'd12: begin op_a$11$d = regs$304$q; op_b$11$d = regs$305$q; op_sub$0$d = 1'b0; end
        8'd13: begin op_a$11$d = regs$308$q; op_b$11$d = regs$309$q; op_sub$0$d = 1'b0; end
        8'd14: begin op_a$11$d = regs$312$q; op_b$11$d = regs$313$q; op_sub$0$d = 1'b0; end
        8'd15: begin op_a$11$d = regs$316$q; op_b$11$d = regs$317$q; op_sub$0$d = 1'b0; end
        default: begin op_a$11$d = 24'd0; op_b$11$d = 24'd0; op_sub$0$d = 1'b0; end
      endcase
      add_v$1$clock = clock;
      add_v$1$valid_in = 1'b0;
      op_a$12$clock = clock;
      add_v$1$a = op_a$12$q;
      op_b$12$clock = clock;
      add_v$1$b = op_b$12$q;
      op_sub$1$clock = clock;
      add_v$1$sub = op_sub$1$q;
      case (cnt$24$q)
        8'd0: begin op_a$12$d = regs$353$q; op_b$12$d = regs$354$q; op_sub$1$d = 1'b1; end
        8'd1: begin op_a$12$d = regs$328$q; op_b$12$d = regs$327$q; op_sub$1$d = 1'b0; end
        8'd2: begin op_a$12$d = regs$346$q; op_b$12$d = regs$330$q; op_sub$1$d = 1'b0; end
        8'd3: begin op_a$12$d = regs$332$q; op_b$12$d = regs$331$q; op_sub$1$d = 1'b0; end
        8'd4: begin op_a$12$d = regs$336$q; op_b$12$d = regs$335$q; op_sub$1$d = 1'b0; end
        8'd5: begin op_a$12$d = regs$351$q; op_b$12$d = regs$338$q; op_sub$1$d = 1'b0; end
        8'd6: begin op_a$12$d = regs$342$q; op_b$12$d = regs$341$q; op_sub$1$d = 1'b0; end
        8'd7: begin op_a$12$d = regs$349$q; op_b$12$d = regs$345$q; op_sub$1$d = 1'b0; end
        8'd8: begin op_a$12$d = regs$352$q; op_b$12$d = regs$350$q; op_sub$1$d = 1'b1; end
        8'd9: begin op_a$12$d = regs$325$q; op_b$12$d = regs$326$q; op_sub$1$d = 1'b0; end
        8'd10: begin op_a$12$d = regs$347$q; op_b$12$d = regs$348$q; op_sub$1$d = 1'b0; end
        8'd11: begin op_a$12$d = regs$329$q; op_b$12$d = regs$323$q; op_sub$1$d = 1'b0; end
        8'd12: begin op_a$12$d = regs$333$q; op_b$12$d = regs$334$q; op_sub$1$d = 1'b0; end
        8'd13: begin op_a$12$d = regs$337$q; op_b$12$d = regs$324$q; op_sub$1$d = 1'b0; end
        8'd14: begin op_a$12$d = regs$339$q; op_b$12$d = regs$340$q; op_sub$1$d = 1'b0; end
        8'd15: begin op_a$12$d = regs$343$q; op_b$12$d = regs$344$q; op_sub$1$d = 1'b0; end
        default: begin op_a$12$d = 24'd0; op_b$12$d = 24'd0; op_sub$1$d = 1'b0; end
      endcase
      add_v$2$clock = clock;
      add_v$2$valid_in = 1'b0;
      op_a$13$clock = clock;
      add_v$2$a = op_a$13$q;
      op_b$13$clock = clock;
      add_v$2$b = op_b$13$q;
      op_sub$2$clock = clock;
      add_v$2$sub = op_sub$2$q;
      case (cnt$26$q)
        8'd0: begin op_a$13$d = regs$380$q; op_b$13$d = regs$381$q; op_sub$2$d = 1'b1; end
        8'd1: begin op_a$13$d = regs$359$q; op_b$13$d = regs$360$q; op_sub$2$d = 1'b0; end
        8'd2: begin op_a$13$d = regs$369$q; op_b$13$d = regs$355$q; op_sub$2$d = 1'b0; end
        8'd3: begin op_a$13$d = regs$383$q; op_b$13$d = regs$384$q; op_sub$2$d = 1'b1; end
        8'd4: begin op_a$13$d = regs$361$q; op_b$13$d = regs$362$q; op_sub$2$d = 1'b0; end
        8'd5: begin op_a$13$d = regs$376$q; op_b$13$d = regs$377$q; op_sub$2$d = 1'b0; end
        8'd6: begin op_a$13$d = regs$365$q; op_b$13$d = regs$366$q; op_sub$2$d = 1'b0; end
        8'd7: begin op_a$13$d = regs$374$q; op_b$13$d = regs$358$q; op_sub$2$d = 1'b0; end
        8'd8: begin op_a$13$d = regs$378$q; op_b$13$d = regs$375$q; op_sub$2$d = 1'b1; end
        8'd9: begin op_a$13$d = regs$379$q; op_b$13$d = regs$382$q; op_sub$2$d = 1'b0; end
        8'd10: begin op_a$13$d = regs$370$q; op_b$13$d = regs$371$q; op_sub$2$d = 1'b0; end
        8'd11: begin op_a$13$d = regs$356$q; op_b$13$d = regs$357$q; op_sub$2$d = 1'b0; end
        8'd12: begin op_a$13$d = regs$363$q; op_b$13$d = regs$364$q; op_sub$2$d = 1'b0; end
        8'd13: begin op_a$13$d = regs$372$q; op_b$13$d = regs$373$q; op_sub$2$d = 1'b0; end
        8'd15: begin op_a$13$d = regs$367$q; op_b$13$d = regs$368$q; op_sub$2$d = 1'b0; end
        default: begin op_a$13$d = 24'd0; op_b$13$d = 24'd0; op_sub$2$d = 1'b0; end
      endcase
      add_v$3$clock = clock;
      add_v$3$valid_in = 1'b0;
      op_a$14$clock = clock;
      add_v$3$a = op_a$14$q;
      op_b$14$clock = clock;
      add_v$3$b = op_b$14$q;
      op_sub$3$clock = clock;
      add_v$3$sub = op_sub$3$q;
      case (cnt$28$q)
        8'd0: begin op_a$14$d = regs$407$q; op_b$14$d = regs$408$q; op_sub$3$d = 1'b0; end
        8'd1: begin op_a$14$d = regs$388$q; op_b$14$d = regs$389$q; op_sub$3$d = 1'b0; end
        8'd2: begin op_a$14$d = regs$394$q; op_b$14$d = regs$395$q; op_sub$3$d = 1'b0; end
        8'd4: begin op_a$14$d = regs$386$q; op_b$14$d = regs$385$q; op_sub$3$d = 1'b0; end
        8'd5: begin op_a$14$d = regs$398$q; op_b$14$d = regs$385$q; op_sub$3$d = 1'b0; end
        8'd6: begin op_a$14$d = regs$390$q; op_b$14$d = regs$391$q; op_sub$3$d = 1'b0; end
        8'd7: begin op_a$14$d = regs$401$q; op_b$14$d = regs$402$q; op_sub$3$d = 1'b0; end
        8'd8: begin op_a$14$d = regs$387$q; op_b$14$d = regs$403$q; op_sub$3$d = 1'b1; end
        8'd9: begin op_a$14$d = regs$406$q; op_b$14$d = regs$405$q; op_sub$3$d = 1'b1; end
        8'd10: begin op_a$14$d = regs$396$q; op_b$14$d = regs$397$q; op_sub$3$d = 1'b0; end
        8'd13: begin op_a$14$d = regs$399$q; op_b$14$d = regs$400$q; op_sub$3$d = 1'b0; end
        8'd15: begin op_a$14$d = regs$392$q; op_b$14$d = regs$393$q; op_sub$3$d = 1'b0; end
        default: begin op_a$14$d = 24'd0; op_b$14$d = 24'd0; op_sub$3$d = 1'b0; end
      endcase
      add_v$4$clock = clock;
      add_v$4$valid_in = 1'b0;
      op_a$15$clock = clock;
      add_v$4$a = op_a$15$q;
      op_b$15$clock = clock;
      add_v$4$b = op_b$15$q;
      op_sub$4$clock = clock;
      add_v$4$sub = op_sub$4$q;
      case (cnt$30$q)
        8'd1: begin op_a$15$d = regs$419$q; op_b$15$d = regs$418$q; op_sub$4$d = 1'b1; end
        8'd2: begin op_a$15$d = regs$413$q; op_b$15$d = regs$409$q; op_sub$4$d = 1'b0; end
        8'd4: begin op_a$15$d = regs$411$q; op_b$15$d = regs$412$q; op_sub$4$d = 1'b0; end
        8'd5: begin op_a$15$d = regs$421$q; op_b$15$d = regs$422$q; op_sub$4$d = 1'b1; end
        8'd6: begin op_a$15$d = regs$424$q; op_b$15$d = regs$425$q; op_sub$4$d = 1'b1; end
        8'd7: begin op_a$15$d = regs$414$q; op_b$15$d = regs$410$q; op_sub$4$d = 1'b0; end
        8'd8: begin op_a$15$d = regs$426$q; op_b$15$d = regs$427$q; op_sub$4$d = 1'b1; end
        8'd9: begin op_a$15$d = regs$430$q; op_b$15$d = regs$429$q; op_sub$4$d = 1'b1; end
        8'd13: begin op_a$15$d = regs$420$q; op_b$15$d = regs$423$q; op_sub$4$d = 1'b0; end
        8'd15: begin op_a$15$d = regs$415$q; op_b$15$d = regs$416$q; op_sub$4$d = 1'b0; end
        default: begin op_a$15$d = 24'd0; op_b$15$d = 24'd0; op_sub$4$d = 1'b0; end
      endcase
      add_up$0$clock = clock;
      add_up$0$valid_in = 1'b0;
      op_a$16$clock = clock;
      add_up$0$a = op_a$16$q;
      op_b$16$clock = clock;
      add_up$0$b = op_b$16$q;
      op_sub$5$clock = clock;
      add_up$0$sub = op_sub$5$q;
      case (cnt$32$q)
        8'd0: begin op_a$16$d = regs$447$q; op_b$16$d = regs$460$q; op_sub$5$d = 1'b0; end
        8'd1: begin op_a$16$d = {1'b0, regs$431$q[22:0]}; op_b$16$d = {1'b0, regs$432$q[22:0]}; op_sub$5$d = 1'b0; end
        8'd2: begin op_a$16$d = regs$438$q; op_b$16$d = regs$437$q; op_sub$5$d = 1'b0; end
        8'd3: begin op_a$16$d = regs$442$q; op_b$16$d = regs$441$q; op_sub$5$d = 1'b0; end
        8'd4: begin op_a$16$d = regs$446$q; op_b$16$d = regs$445$q; op_sub$5$d = 1'b0; end
        8'd5: begin op_a$16$d = regs$451$q; op_b$16$d = regs$450$q; op_sub$5$d = 1'b0; end
        8'd6: begin op_a$16$d = regs$455$q; op_b$16$d = regs$454$q; op_sub$5$d = 1'b0; end
        8'd7: begin op_a$16$d = regs$459$q; op_b$16$d = {1'b0, regs$458$q[22:0]}; op_sub$5$d = 1'b0; end
        8'd8: begin op_a$16$d = regs$462$q; op_b$16$d = {1'b0, regs$461$q[22:0]}; op_sub$5$d = 1'b0; end
        8'd9: begin op_a$16$d = regs$433$q; op_b$16$d = regs$434$q; op_sub$5$d = 1'b0; end
        8'd10: begin op_a$16$d = regs$435$q; op_b$16$d = regs$436$q; op_sub$5$d = 1'b0; end
        8'd11: begin op_a$16$d = regs$439$q; op_b$16$d = regs$440$q; op_sub$5$d = 1'b0; end
        8'd12: begin op_a$16$d = regs$443$q; op_b$16$d = regs$444$q; op_sub$5$d = 1'b0; end
        8'd13: begin op_a$16$d = regs$448$q; op_b$16$d = regs$449$q; op_sub$5$d = 1'b0; end
        8'd14: begin op_a$16$d = regs$452$q; op_b$16$d = regs$453$q; op_sub$5$d = 1'b0; end
        8'd15: begin op_a$16$d = regs$456$q; op_b$16$d = regs$457$q; op_sub$5$d = 1'b0; end
        default: begin op_a$16$d = 24'd0; op_b$16$d = 24'd0; op_sub$5$d = 1'b0; end
      endcase
      add_up$1$clock = clock;
      add_up$1$valid_in = 1'b0;
      op_a$17$clock = clock;
      add_up$1$a = op_a$17$q;
      op_b$17$clock = clock;
      add_up$1$b = op_b$17$q;
      op_sub$6$clock = clock;
      add_up$1$sub = op_sub$6$q;
      case (cnt$34$q)
        8'd0: begin op_a$17$d = regs$488$q; op_b$17$d = regs$492$q; op_sub$6$d = 1'b0; end
        8'd1: begin op_a$17$d = {1'b0, regs$464$q[22:0]}; op_b$17$d = regs$463$q; op_sub$6$d = 1'b0; end
        8'd2: begin op_a$17$d = regs$469$q; op_b$17$d = regs$470$q; op_sub$6$d = 1'b0; end
        8'd3: begin op_a$17$d = regs$475$q; op_b$17$d = regs$474$q; op_sub$6$d = 1'b0; end
        8'd4: begin op_a$17$d = regs$478$q; op_b$17$d = regs$479$q; op_sub$6$d = 1'b0; end
        8'd5: begin op_a$17$d = regs$483$q; op_b$17$d = regs$482$q; op_sub$6$d = 1'b0; end
        8'd6: begin op_a$17$d = regs$486$q; op_b$17$d = regs$487$q; op_sub$6$d = 1'b0; end
        8'd7: begin op_a$17$d = regs$491$q; op_b$17$d = {1'b0, regs$490$q[22:0]}; op_sub$6$d = 1'b0; end
        8'd8: begin op_a$17$d = regs$494$q; op_b$17$d = {1'b0, regs$493$q[22:0]}; op_sub$6$d = 1'b0; end
        8'd9: begin op_a$17$d = regs$465$q; op_b$17$d = regs$466$q; op_sub$6$d = 1'b0; end
        8'd10: begin op_a$17$d = regs$467$q; op_b$17$d = regs$468$q; op_sub$6$d = 1'b0; end
        8'd11: begin op_a$17$d = regs$472$q; op_b$17$d = regs$473$q; op_sub$6$d = 1'b0; end
        8'd12: begin op_a$17$d = regs$476$q; op_b$17$d = regs$477$q; op_sub$6$d = 1'b0; end
        8'd13: begin op_a$17$d = regs$480$q; op_b$17$d = regs$481$q; op_sub$6$d = 1'b0; end
        8'd14: begin op_a$17$d = regs$484$q; op_b$17$d = regs$485$q; op_sub$6$d = 1'b0; end
        8'd15: begin op_a$17$d = regs$471$q; op_b$17$d = regs$489$q; op_sub$6$d = 1'b0; end
        default: begin op_a$17$d = 24'd0; op_b$17$d = 24'd0; op_sub$6$d = 1'b0; end
      endcase
      add_up$2$clock = clock;
      add_up$2$valid_in = 1'b0;
      op_a$18$clock = clock;
      add_up$2$a = op_a$18$q;
      op_b$18$clock = clock;
      add_up$2$b = op_b$18$q;
      op_sub$7$clock = clock;
      add_up$2$sub = op_sub$7$q;
      case (cnt$36$q)
        8'd0: begin op_a$18$d = regs$509$q; op_b$18$d = regs$510$q; op_sub$7$d = 1'b0; end
        8'd1: begin op_a$18$d = {1'b0, regs$498$q[22:0]}; op_b$18$d = {1'b0, regs$499$q[22:0]}; op_sub$7$d = 1'b0; end
        8'd2: begin op_a$18$d = regs$507$q; op_b$18$d = regs$508$q; op_sub$7$d = 1'b0; end
        8'd3: begin op_a$18$d = regs$511$q; op_b$18$d = regs$512$q; op_sub$7$d = 1'b0; end
        8'd4: begin op_a$18$d = {1'b0, regs$517$q[22:0]}; op_b$18$d = (((regs$518$q[22:15] != 8'd0) && (regs$518$q[22:15] != 8'd255)) ? regs$518$q + 24'd32768 : regs$518$q); op_sub$7$d = 1'b0; end
        8'd5: begin op_a$18$d = regs$514$q; op_b$18$d = regs$515$q; op_sub$7$d = 1'b0; end
        8'd6: begin op_a$18$d = regs$519$q; op_b$18$d = regs$520$q; op_sub$7$d = 1'b0; end
        8'd7: begin op_a$18$d = regs$516$q; op_b$18$d = {1'b0, regs$513$q[22:0]}; op_sub$7$d = 1'b0; end
        8'd8: begin op_a$18$d = {1'b0, regs$521$q[22:0]}; op_b$18$d = {1'b0, regs$522$q[22:0]}; op_sub$7$d = 1'b0; end
        8'd9: begin op_a$18$d = regs$504$q; op_b$18$d = regs$505$q; op_sub$7$d = 1'b0; end
        8'd10: begin op_a$18$d = regs$500$q; op_b$18$d = {1'b0, regs$495$q[22:0]}; op_sub$7$d = 1'b0; end
        8'd11: begin op_a$18$d = regs$526$q; op_b$18$d = regs$527$q; op_sub$7$d = 1'b0; end
        8'd12: begin op_a$18$d = regs$501$q; op_b$18$d = {1'b0, regs$496$q[22:0]}; op_sub$7$d = 1'b0; end
        8'd13: begin op_a$18$d = {1'b0, regs$523$q[22:0]}; op_b$18$d = {1'b0, regs$524$q[22:0]}; op_sub$7$d = 1'b0; end
        8'd14: begin op_a$18$d = regs$503$q; op_b$18$d = {1'b0, regs$497$q[22:0]}; op_sub$7$d = 1'b0; end
        8'd15: begin op_a$18$d = regs$502$q; op_b$18$d = regs$506$q; op_sub$7$d = 1'b0; end
        default: begin op_a$18$d = 24'd0; op_b$18$d = 24'd0; op_sub$7$d = 1'b0; end
      endcase
      add_up$3$clock = clock;
      add_up$3$valid_in = 1'b0;
      op_a$19$clock = clock;
      add_up$3$a = op_a$19$q;
      op_b$19$clock = clock;
      add_up$3$b = op_b$19$q;
      op_sub$8$clock = clock;
      add_up$3$sub = op_sub$8$q;
      case (cnt$38$q)
        8'd0: begin op_a$19$d = regs$532$q; op_b$19$d = regs$533$q; op_sub$8$d = 1'b0; end
        8'd1: begin op_a$19$d = {1'b0, regs$529$q[22:0]}; op_b$19$d = regs$528$q; op_sub$8$d = 1'b0; end
        8'd2: begin op_a$19$d = regs$538$q; op_b$19$d = regs$539$q; op_sub$8$d = 1'b0; end
        8'd3: begin op_a$19$d = regs$541$q; op_b$19$d = regs$542$q; op_sub$8$d = 1'b0; end
        8'd4: begin op_a$19$d = regs$545$q; op_b$19$d = regs$534$q; op_sub$8$d = 1'b0; end
        8'd5: begin op_a$19$d = regs$543$q; op_b$19$d = regs$544$q; op_sub$8$d = 1'b0; end
        8'd6: begin op_a$19$d = {1'b0, regs$546$q[22:0]}; op_b$19$d = (((regs$547$q[22:15] != 8'd0) && (regs$547$q[22:15] != 8'd255)) ? regs$547$q + 24'd32768 : regs$547$q); op_sub$8$d = 1'b0; end
        8'd7: begin op_a$19$d = regs$540$q; op_b$19$d = {1'b0, regs$537$q[22:0]}; op_sub$8$d = 1'b0; end
        8'd8: begin op_a$19$d = regs$556$q; op_b$19$d = regs$557$q; op_sub$8$d = 1'b0; end
        8'd9: begin op_a$19$d = regs$535$q; op_b$19$d = regs$536$q; op_sub$8$d = 1'b0; end
        8'd10: begin op_a$19$d = regs$551$q; op_b$19$d = regs$552$q; op_sub$8$d = 1'b0; end
        8'd11: begin op_a$19$d = regs$553$q; op_b$19$d = regs$555$q; op_sub$8$d = 1'b0; end
        8'd12: begin op_a$19$d = regs$562$q; op_b$19$d = {1'b0, regs$561$q[22:0]}; op_sub$8$d = 1'b0; end
        8'd13: begin op_a$19$d = regs$558$q; op_b$19$d = regs$559$q; op_sub$8$d = 1'b0; end
        8'd14: begin op_a$19$d = regs$548$q; op_b$19$d = regs$549$q; op_sub$8$d = 1'b0; end
        8'd15: begin op_a$19$d = regs$530$q; op_b$19$d = regs$531$q; op_sub$8$d = 1'b0; end
        default: begin op_a$19$d = 24'd0; op_b$19$d = 24'd0; op_sub$8$d = 1'b0; end
      endcase
      add_up$4$clock = clock;
      add_up$4$valid_in = 1'b0;
      op_a$20$clock = clock;
      add_up$4$a = op_a$20$q;
      op_b$20$clock = clock;
      add_up$4$b = op_b$20$q;
      op_sub$9$clock = clock;
      add_up$4$sub = op_sub$9$q;
      case (cnt$40$q)
        8'd0: begin op_a$20$d = regs$566$q; op_b$20$d = regs$567$q; op_sub$9$d = 1'b0; end
        8'd1: begin op_a$20$d = {1'b0, regs$563$q[22:0]}; op_b$20$d = {1'b0, regs$564$q[22:0]}; op_sub$9$d = 1'b0; end
        8'd2: begin op_a$20$d = regs$574$q; op_b$20$d = regs$575$q; op_sub$9$d = 1'b0; end
        8'd3: begin op_a$20$d = regs$576$q; op_b$20$d = regs$577$q; op_sub$9$d = 1'b0; end
        8'd4: begin op_a$20$d = regs$580$q; op_b$20$d = regs$571$q; op_sub$9$d = 1'b0; end
        8'd5: begin op_a$20$d = regs$578$q; op_b$20$d = regs$579$q; op_sub$9$d = 1'b0; end
        8'd6: begin op_a$20$d = regs$581$q; op_b$20$d = regs$582$q; op_sub$9$d = 1'b0; end
        8'd7: begin op_a$20$d = regs$570$q; op_b$20$d = {1'b0, regs$569$q[22:0]}; op_sub$9$d = 1'b0; end
        8'd8: begin op_a$20$d = regs$586$q; op_b$20$d = regs$587$q; op_sub$9$d = 1'b0; end
        8'd9: begin op_a$20$d = regs$572$q; op_b$20$d = regs$573$q; op_sub$9$d = 1'b0; end
        8'd10: begin op_a$20$d = regs$584$q; op_b$20$d = regs$585$q; op_sub$9$d = 1'b0; end
        8'd11: begin op_a$20$d = regs$588$q; op_b$20$d = regs$590$q; op_sub$9$d = 1'b0; end
        8'd13: begin op_a$20$d = regs$591$q; op_b$20$d = regs$592$q; op_sub$9$d = 1'b0; end
        8'd15: begin op_a$20$d = regs$565$q; op_b$20$d = regs$568$q; op_sub$9$d = 1'b0; end
        default: begin op_a$20$d = 24'd0; op_b$20$d = 24'd0; op_sub$9$d = 1'b0; end
      endcase
      add_up$5$clock = clock;
      add_up$5$valid_in = 1'b0;
      op_a$21$clock = clock;
      add_up$5$a = op_a$21$q;
      op_b$21$clock = clock;
      add_up$5$b = op_b$21$q;
      op_sub$10$clock = clock;
      add_up$5$sub = op_sub$10$q;
      case (cnt$42$q)
        8'd0: begin op_a$21$d = regs$600$q; op_b$21$d = regs$601$q; op_sub$10$d = 1'b0; end
        8'd1: begin op_a$21$d = {1'b0, regs$594$q[22:0]}; op_b$21$d = regs$593$q; op_sub$10$d = 1'b0; end
        8'd2: begin op_a$21$d = regs$604$q; op_b$21$d = regs$605$q; op_sub$10$d = 1'b0; end
        8'd3: begin op_a$21$d = regs$597$q; op_b$21$d = regs$598$q; op_sub$10$d = 1'b0; end
        8'd4: begin op_a$21$d = regs$596$q; op_b$21$d = regs$606$q; op_sub$10$d = 1'b0; end
        8'd5: begin op_a$21$d = regs$615$q; op_b$21$d = regs$616$q; op_sub$10$d = 1'b0; end
        8'd6: begin op_a$21$d = regs$607$q; op_b$21$d = regs$608$q; op_sub$10$d = 1'b0; end
        8'd7: begin op_a$21$d = regs$603$q; op_b$21$d = {1'b0, regs$602$q[22:0]}; op_sub$10$d = 1'b0; end
        8'd8: begin op_a$21$d = regs$612$q; op_b$21$d = regs$613$q; op_sub$10$d = 1'b0; end
        8'd9: begin op_a$21$d = regs$609$q; op_b$21$d = regs$610$q; op_sub$10$d = 1'b0; end
        8'd10: begin op_a$21$d = regs$611$q; op_b$21$d = regs$614$q; op_sub$10$d = 1'b0; end
        8'd11: begin op_a$21$d = regs$617$q; op_b$21$d = regs$619$q; op_sub$10$d = 1'b0; end
        8'd15: begin op_a$21$d = regs$595$q; op_b$21$d = regs$599$q; op_sub$10$d = 1'b0; end
        default: begin op_a$21$d = 24'd0; op_b$21$d = 24'd0; op_sub$10$d = 1'b0; end
      endcase
      add_up$6$clock = clock;
      add_up$6$valid_in = 1'b0;
      op_a$22$clock = clock;
      add_up$6$a = op_a$22$q;
      op_b$22$clock = clock;
      add_up$6$b = op_b$22$q;
      op_sub$11$clock = clock;
      add_up$6$sub = op_sub$11$q;
      case (cnt$44$q)
        8'd0: begin op_a$22$d = regs$626$q; op_b$22$d = regs$627$q; op_sub$11$d = 1'b0; end
        8'd1: begin op_a$22$d = regs$621$q; op_b$22$d = regs$620$q; op_sub$11$d = 1'b0; end
        8'd2: begin op_a$22$d = regs$630$q; op_b$22$d = regs$631$q; op_sub$11$d = 1'b0; end
        8'd3: begin op_a$22$d = {1'b0, regs$623$q[22:0]}; op_b$22$d = (((regs$624$q[22:15] != 8'd0) && (regs$624$q[22:15] != 8'd255)) ? regs$624$q + 24'd32768 : regs$624$q); op_sub$11$d = 1'b0; end
        8'd4: begin op_a$22$d = {1'b0, regs$642$q[22:0]}; op_b$22$d = {1'b0, regs$643$q[22:0]}; op_sub$11$d = 1'b0; end
        8'd5: begin op_a$22$d = regs$644$q; op_b$22$d = regs$645$q; op_sub$11$d = 1'b0; end
        8'd6: begin op_a$22$d = regs$634$q; op_b$22$d = {1'b0, regs$633$q[22:0]}; op_sub$11$d = 1'b0; end
        8'd7: begin op_a$22$d = regs$629$q; op_b$22$d = {1'b0, regs$628$q[22:0]}; op_sub$11$d = 1'b0; end
        8'd8: begin op_a$22$d = regs$637$q; op_b$22$d = regs$638$q; op_sub$11$d = 1'b0; end
        8'd9: begin op_a$22$d = regs$635$q; op_b$22$d = regs$636$q; op_sub$11$d = 1'b0; end
        8'd10: begin op_a$22$d = regs$640$q; op_b$22$d = regs$641$q; op_sub$11$d = 1'b0; end
        8'd15: begin op_a$22$d = regs$622$q; op_b$22$d = regs$625$q; op_sub$11$d = 1'b0; end
        default: begin op_a$22$d = 24'd0; op_b$22$d = 24'd0; op_sub$11$d = 1'b0; end
      endcase
      add_up$7$clock = clock;
      add_up$7$valid_in = 1'b0;
      op_a$23$clock = clock;
      add_up$7$a = op_a$23$q;
      op_b$23$clock = clock;
      add_up$7$b = op_b$23$q;
      op_sub$12$clock = clock;
      add_up$7$sub = op_sub$12$q;
      case (cnt$46$q)
        8'd0: begin op_a$23$d = regs$649$q; op_b$23$d = regs$650$q; op_sub$12$d = 1'b0; end
        8'd1: begin op_a$23$d = regs$647$q; op_b$23$d = regs$646$q; op_sub$12$d = 1'b0; end
        8'd2: begin op_a$23$d = regs$654$q; op_b$23$d = regs$655$q; op_sub$12$d = 1'b0; end
        8'd3: begin op_a$23$d = regs$651$q; op_b$23$d = regs$652$q; op_sub$12$d = 1'b0; end
        8'd4: begin op_a$23$d = regs$656$q; op_b$23$d = regs$657$q; op_sub$12$d = 1'b0; end
        8'd5: begin op_a$23$d = regs$668$q; op_b$23$d = regs$669$q; op_sub$12$d = 1'b0; end
        8'd6: begin op_a$23$d = regs$664$q; op_b$23$d = {1'b0, regs$663$q[22:0]}; op_sub$12$d = 1'b0; end
        8'd7: begin op_a$23$d = regs$658$q; op_b$23$d = regs$659$q; op_sub$12$d = 1'b0; end
        8'd8: begin op_a$23$d = regs$665$q; op_b$23$d = regs$666$q; op_sub$12$d = 1'b0; end
        8'd9: begin op_a$23$d = regs$660$q; op_b$23$d = regs$661$q; op_sub$12$d = 1'b0; end
        8'd10: begin op_a$23$d = regs$667$q; op_b$23$d = regs$670$q; op_sub$12$d = 1'b0; end
        8'd15: begin op_a$23$d = regs$648$q; op_b$23$d = regs$653$q; op_sub$12$d = 1'b0; end
        default: begin op_a$23$d = 24'd0; op_b$23$d = 24'd0; op_sub$12$d = 1'b0; end
      endcase
      scale_e$0$clock = clock;
      op_a$24$clock = clock;
      scale_e$0$a = op_a$24$q;
      op_sel$0$clock = clock;
      scale_e$0$sel = op_sel$0$q;
      case (cnt$48$q)
        8'd0: begin op_a$24$d = regs$679$q; op_sel$0$d = exact$3$q; end
        8'd8: begin op_a$24$d = regs$671$q; op_sel$0$d = exact$3$q; end
        8'd9: begin op_a$24$d = regs$672$q; op_sel$0$d = exact$3$q; end
        8'd10: begin op_a$24$d = regs$673$q; op_sel$0$d = exact$3$q; end
        8'd11: begin op_a$24$d = regs$674$q; op_sel$0$d = exact$3$q; end
        8'd12: begin op_a$24$d = regs$675$q; op_sel$0$d = exact$3$q; end
        8'd13: begin op_a$24$d = regs$676$q; op_sel$0$d = exact$3$q; end
        8'd14: begin op_a$24$d = regs$677$q; op_sel$0$d = exact$3$q; end
        8'd15: begin op_a$24$d = regs$678$q; op_sel$0$d = exact$3$q; end
        default: begin op_a$24$d = 24'd0; op_sel$0$d = 1'b0; end
      endcase
      scale_z$0$clock = clock;
      op_a$25$clock = clock;
      scale_z$0$a = op_a$25$q;
      op_sel$1$clock = clock;
      scale_z$0$sel = op_sel$1$q;
      case (cnt$50$q)
        8'd8: begin op_a$25$d = regs$680$q; op_sel$1$d = exact$3$q; end
        8'd9: begin op_a$25$d = regs$681$q; op_sel$1$d = exact$3$q; end
        8'd10: begin op_a$25$d = regs$682$q; op_sel$1$d = exact$3$q; end
        default: begin op_a$25$d = 24'd0; op_sel$1$d = 1'b0; end
      endcase
      scale_s$0$clock = clock;
      op_a$26$clock = clock;
      scale_s$0$a = op_a$26$q;
      op_sel$2$clock = clock;
      scale_s$0$sel = op_sel$2$q;
      case (cnt$52$q)
        8'd4: begin op_a$26$d = regs$688$q; op_sel$2$d = 1'b0; end
        8'd7: begin op_a$26$d = regs$683$q; op_sel$2$d = 1'b0; end
        8'd8: begin op_a$26$d = regs$684$q; op_sel$2$d = 1'b0; end
        8'd9: begin op_a$26$d = regs$685$q; op_sel$2$d = 1'b0; end
        8'd14: begin op_a$26$d = regs$686$q; op_sel$2$d = 1'b0; end
        8'd15: begin op_a$26$d = regs$687$q; op_sel$2$d = 1'b0; end
        default: begin op_a$26$d = 24'd0; op_sel$2$d = 1'b0; end
      endcase
      signs$0$x = regs$694$q;
      signs$0$e = regs$700$q;
      signs$1$x = regs$706$q;
      signs$1$e = regs$712$q;
      signs$2$x = regs$745$q;
      signs$2$e = regs$750$q;
      signs$3$x = regs$728$q;
      signs$3$e = regs$731$q;
      signs$4$x = regs$736$q;
      signs$4$e = regs$739$q;
      signs$5$x = regs$754$q;
      signs$5$e = regs$755$q;
      out_s_x$0$clock = clock;
      out_s_x$0$d = (counter$q == 8'd3) ? regs$754$q : out_s_x$0$q;
      out_s_b$0$clock = clock;
      out_s_b$0$d = (counter$q == 8'd3) ? regs$755$q : out_s_b$0$q;
      out_cross_t$0$clock = clock;
      out_cross_t$0$d = (counter$q == 8'd3) ? ((signs$0$sgn[1] & signs$1$sgn[0] & signs$2$sgn[0] & signs$3$sgn[0] & signs$4$sgn[0] & signs$5$sgn[1]) | (signs$0$sgn[0] & signs$1$sgn[1] & signs$2$sgn[1] & signs$3$sgn[1] & signs$4$sgn[1] & signs$5$sgn[0])) : out_cross_t$0$q;
      out_cross_f$0$clock = clock;
      out_cross_f$0$d = (counter$q == 8'd3) ? ((signs$0$sgn[0] | signs$1$sgn[1] | signs$2$sgn[1] | signs$3$sgn[1] | signs$4$sgn[1] | signs$5$sgn[0]) & (signs$0$sgn[1] | signs$1$sgn[0] | signs$2$sgn[0] | signs$3$sgn[0] | signs$4$sgn[0] | signs$5$sgn[1])) : out_cross_f$0$q;
      s_x$0 = out_s_x$0$q;
      s_b$0 = out_s_b$0$q;
      cross_t$0 = out_cross_t$0$q;
      cross_f$0 = out_cross_f$0$q;
      signs$6$x = regs$706$q;
      signs$6$e = regs$712$q;
      signs$7$x = regs$718$q;
      signs$7$e = regs$723$q;
      signs$8$x = regs$777$q;
      signs$8$e = regs$782$q;
      signs$9$x = regs$760$q;
      signs$9$e = regs$763$q;
      signs$10$x = regs$768$q;
      signs$10$e = regs$771$q;
      signs$11$x = regs$786$q;
      signs$11$e = regs$787$q;
      out_s_x$1$clock = clock;
      out_s_x$1$d = (counter$q == 8'd3) ? regs$786$q : out_s_x$1$q;
      out_s_b$1$clock = clock;
      out_s_b$1$d = (counter$q == 8'd3) ? regs$787$q : out_s_b$1$q;
      out_cross_t$1$clock = clock;
      out_cross_t$1$d = (counter$q == 8'd3) ? ((signs$6$sgn[1] & signs$7$sgn[0] & signs$8$sgn[0] & signs$9$sgn[0] & signs$10$sgn[0] & signs$11$sgn[1]) | (signs$6$sgn[0] & signs$7$sgn[1] & signs$8$sgn[1] & signs$9$sgn[1] & signs$10$sgn[1] & signs$11$sgn[0])) : out_cross_t$1$q;
      out_cross_f$1$clock = clock;
      out_cross_f$1$d = (counter$q == 8'd3) ? ((signs$6$sgn[0] | signs$7$sgn[1] | signs$8$sgn[1] | signs$9$sgn[1] | signs$10$sgn[1] | signs$11$sgn[0]) & (signs$6$sgn[1] | signs$7$sgn[0] | signs$8$sgn[0] | signs$9$sgn[0] | signs$10$sgn[0] | signs$11$sgn[1])) : out_cross_f$1$q;
      s_x$1 = out_s_x$1$q;
      s_b$1 = out_s_b$1$q;
      cross_t$1 = out_cross_t$1$q;
      cross_f$1 = out_cross_f$1$q;
      signs$12$x = regs$718$q;
      signs$12$e = regs$723$q;
      signs$13$x = regs$694$q;
      signs$13$e = regs$700$q;
      signs$14$x = regs$807$q;
      signs$14$e = regs$812$q;
      signs$15$x = regs$792$q;
      signs$15$e = regs$794$q;
      signs$16$x = regs$799$q;
      signs$16$e = regs$801$q;
      signs$17$x = regs$816$q;
      signs$17$e = regs$817$q;
      out_s_x$2$clock = clock;
      out_s_x$2$d = (counter$q == 8'd3) ? regs$816$q : out_s_x$2$q;
      out_s_b$2$clock = clock;
      out_s_b$2$d = (counter$q == 8'd3) ? regs$817$q : out_s_b$2$q;
      out_cross_t$2$clock = clock;
      out_cross_t$2$d = (counter$q == 8'd3) ? ((signs$12$sgn[1] & signs$13$sgn[0] & signs$14$sgn[0] & signs$15$sgn[0] & signs$16$sgn[0] & signs$17$sgn[1]) | (signs$12$sgn[0] & signs$13$sgn[1] & signs$14$sgn[1] & signs$15$sgn[1] & signs$16$sgn[1] & signs$17$sgn[0])) : out_cross_t$2$q;
      out_cross_f$2$clock = clock;
      out_cross_f$2$d = (counter$q == 8'd3) ? ((signs$12$sgn[0] | signs$13$sgn[1] | signs$14$sgn[1] | signs$15$sgn[1] | signs$16$sgn[1] | signs$17$sgn[0]) & (signs$12$sgn[1] | signs$13$sgn[0] | signs$14$sgn[0] | signs$15$sgn[0] | signs$16$sgn[0] | signs$17$sgn[1])) : out_cross_f$2$q;
      s_x$2 = out_s_x$2$q;
      s_b$2 = out_s_b$2$q;
      cross_t$2 = out_cross_t$2$q;
      cross_f$2 = out_cross_f$2$q;
      out_hit$clock = clock;
      out_hit$d = (counter$q == 8'd3) ? (((signs$0$sgn[1] & signs$1$sgn[0] & signs$2$sgn[0] & signs$3$sgn[0] & signs$4$sgn[0] & signs$5$sgn[1]) | (signs$0$sgn[0] & signs$1$sgn[1] & signs$2$sgn[1] & signs$3$sgn[1] & signs$4$sgn[1] & signs$5$sgn[0])) | ((signs$6$sgn[1] & signs$7$sgn[0] & signs$8$sgn[0] & signs$9$sgn[0] & signs$10$sgn[0] & signs$11$sgn[1]) | (signs$6$sgn[0] & signs$7$sgn[1] & signs$8$sgn[1] & signs$9$sgn[1] & signs$10$sgn[1] & signs$11$sgn[0])) | ((signs$12$sgn[1] & signs$13$sgn[0] & signs$14$sgn[0] & signs$15$sgn[0] & signs$16$sgn[0] & signs$17$sgn[1]) | (signs$12$sgn[0] & signs$13$sgn[1] & signs$14$sgn[1] & signs$15$sgn[1] & signs$16$sgn[1] & signs$17$sgn[0]))) : out_hit$q;
      out_miss$clock = clock;
      out_miss$d = (counter$q == 8'd3) ? (((signs$0$sgn[0] | signs$1$sgn[1] | signs$2$sgn[1] | signs$3$sgn[1] | signs$4$sgn[1] | signs$5$sgn[0]) & (signs$0$sgn[1] | signs$1$sgn[0] | signs$2$sgn[0] | signs$3$sgn[0] | signs$4$sgn[0] | signs$5$sgn[1])) & ((signs$6$sgn[0] | signs$7$sgn[1] | signs$8$sgn[1] | signs$9$sgn[1] | signs$10$sgn[1] | signs$11$sgn[0]) & (signs$6$sgn[1] | signs$7$sgn[0] | signs$8$sgn[0] | signs$9$sgn[0] | signs$10$sgn[0] | signs$11$sgn[1])) & ((signs$12$sgn[0] | signs$13$sgn[1] | signs$14$sgn[1] | signs$15$sgn[1] | signs$16$sgn[1] | signs$17$sgn[0]) & (signs$12$sgn[1] | signs$13$sgn[0] | signs$14$sgn[0] | signs$15$sgn[0] | signs$16$sgn[0] | signs$17$sgn[1]))) : out_miss$q;
      out_tag$clock = clock;
      out_tag$d = (counter$q == 8'd3) ? tags$9$q : out_tag$q;
      out_valid$clock = clock;
      out_valid$d = (counter$q == 8'd3) & valid$9$q;
      hit = out_hit$q;
      miss = out_miss$q;
      tag_out = out_tag$q;
      valid_out = out_valid$q;
    end
endmodule // top$tc


module top$tc$add_up$0(clock,a,b,sub,valid_in,y,valid_out);
    
    // Module arguments
    input wire  clock;
    input wire  [23:0] a;
    input wire  [23:0] b;
    input wire  sub;
    input wire  valid_in;
    output reg  [23:0] y;
    output reg  valid_out;
    
    // Constant declarations
    localparam  round_up = 1'b1;
    localparam  c_align_cap = 8'h13;
    localparam  c_exp_ones = 10'b11111111;
    localparam  c_ones = 19'b1111111111111111111;
    localparam  c_top = 19'b1000000000000000000;
    
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
    reg  [15:0] s1_big$d;
    wire  [15:0] s1_big$q;
    reg  s1_big$clock;
    reg  [15:0] s1_small$d;
    wire  [15:0] s1_small$q;
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
    reg  [18:0] s2_big$d;
    wire  [18:0] s2_big$q;
    reg  s2_big$clock;
    reg  [18:0] s2_small$d;
    wire  [18:0] s2_small$q;
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
    reg  [19:0] s3_sum$d;
    wire  [19:0] s3_sum$q;
    reg  s3_sum$clock;
    reg  [18:0] s3_marker$d;
    wire  [18:0] s3_marker$q;
    reg  s3_marker$clock;
    reg  [18:0] lzc$x;
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
    reg  [19:0] s4_sum$d;
    wire  [19:0] s4_sum$q;
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
    reg  c1_b_sign;
    reg  c1_swap;
    reg  [7:0] c1_d_ab;
    reg  [7:0] c1_d_ba;
    reg  [7:0] c1_sh_ab;
    reg  [7:0] c1_sh_ba;
    reg  c1_inf_sign;
    reg  [18:0] c2_small_ext;
    reg  [18:0] c2_aligned;
    reg  [18:0] c2_mask;
    reg  c2_lost;
    reg  [19:0] c3_sum;
    reg  [7:0] c3_limit;
    reg  c4_zero;
    reg  c4_sign;
    reg  [18:0] c5_shifted;
    reg  [9:0] c5_exp;
    reg  [17:0] c5_nm;
    
    // Sub module instances
    top$tc$add_up$0$unpack_a unpack_a(
        .x(unpack_a$x),
        .sign(unpack_a$sign),
        .exp(unpack_a$exp),
        .sig(unpack_a$sig),
        .is_zero(unpack_a$is_zero),
        .is_inf(unpack_a$is_inf),
        .is_nan(unpack_a$is_nan)
    );
    top$tc$add_up$0$unpack_a unpack_b(
        .x(unpack_b$x),
        .sign(unpack_b$sign),
        .exp(unpack_b$exp),
        .sig(unpack_b$sig),
        .is_zero(unpack_b$is_zero),
        .is_inf(unpack_b$is_inf),
        .is_nan(unpack_b$is_nan)
    );
    top$a_deg s1_valid(
        .d(s1_valid$d),
        .q(s1_valid$q),
        .clock(s1_valid$clock)
    );
    top$a_deg s1_nan(
        .d(s1_nan$d),
        .q(s1_nan$q),
        .clock(s1_nan$clock)
    );
    top$a_deg s1_inf(
        .d(s1_inf$d),
        .q(s1_inf$q),
        .clock(s1_inf$clock)
    );
    top$a_deg s1_inf_sign(
        .d(s1_inf_sign$d),
        .q(s1_inf_sign$q),
        .clock(s1_inf_sign$clock)
    );
    top$a_deg s1_zero_sign(
        .d(s1_zero_sign$d),
        .q(s1_zero_sign$q),
        .clock(s1_zero_sign$clock)
    );
    top$a_deg s1_sign(
        .d(s1_sign$d),
        .q(s1_sign$q),
        .clock(s1_sign$clock)
    );
    top$a_deg s1_eff_sub(
        .d(s1_eff_sub$d),
        .q(s1_eff_sub$q),
        .clock(s1_eff_sub$clock)
    );
    top$counter s1_exp(
        .d(s1_exp$d),
        .q(s1_exp$q),
        .clock(s1_exp$clock)
    );
    top$tc$add_up$0$s1_big s1_big(
        .d(s1_big$d),
        .q(s1_big$q),
        .clock(s1_big$clock)
    );
    top$tc$add_up$0$s1_big s1_small(
        .d(s1_small$d),
        .q(s1_small$q),
        .clock(s1_small$clock)
    );
    top$counter s1_shift(
        .d(s1_shift$d),
        .q(s1_shift$q),
        .clock(s1_shift$clock)
    );
    top$a_deg s2_valid(
        .d(s2_valid$d),
        .q(s2_valid$q),
        .clock(s2_valid$clock)
    );
    top$a_deg s2_nan(
        .d(s2_nan$d),
        .q(s2_nan$q),
        .clock(s2_nan$clock)
    );
    top$a_deg s2_inf(
        .d(s2_inf$d),
        .q(s2_inf$q),
        .clock(s2_inf$clock)
    );
    top$a_deg s2_inf_sign(
        .d(s2_inf_sign$d),
        .q(s2_inf_sign$q),
        .clock(s2_inf_sign$clock)
    );
    top$a_deg s2_zero_sign(
        .d(s2_zero_sign$d),
        .q(s2_zero_sign$q),
        .clock(s2_zero_sign$clock)
    );
    top$a_deg s2_sign(
        .d(s2_sign$d),
        .q(s2_sign$q),
        .clock(s2_sign$clock)
    );
    top$a_deg s2_eff_sub(
        .d(s2_eff_sub$d),
        .q(s2_eff_sub$q),
        .clock(s2_eff_sub$clock)
    );
    top$counter s2_exp(
        .d(s2_exp$d),
        .q(s2_exp$q),
        .clock(s2_exp$clock)
    );
    top$tc$add_up$0$s2_big s2_big(
        .d(s2_big$d),
        .q(s2_big$q),
        .clock(s2_big$clock)
    );
    top$tc$add_up$0$s2_big s2_small(
        .d(s2_small$d),
        .q(s2_small$q),
        .clock(s2_small$clock)
    );
    top$a_deg s3_valid(
        .d(s3_valid$d),
        .q(s3_valid$q),
        .clock(s3_valid$clock)
    );
    top$a_deg s3_nan(
        .d(s3_nan$d),
        .q(s3_nan$q),
        .clock(s3_nan$clock)
    );
    top$a_deg s3_inf(
        .d(s3_inf$d),
        .q(s3_inf$q),
        .clock(s3_inf$clock)
    );
    top$a_deg s3_inf_sign(
        .d(s3_inf_sign$d),
        .q(s3_inf_sign$q),
        .clock(s3_inf_sign$clock)
    );
    top$a_deg s3_zero_sign(
        .d(s3_zero_sign$d),
        .q(s3_zero_sign$q),
        .clock(s3_zero_sign$clock)
    );
    top$a_deg s3_sign(
        .d(s3_sign$d),
        .q(s3_sign$q),
        .clock(s3_sign$clock)
    );
    top$counter s3_exp(
        .d(s3_exp$d),
        .q(s3_exp$q),
        .clock(s3_exp$clock)
    );
    top$tc$add_up$0$s3_sum s3_sum(
        .d(s3_sum$d),
        .q(s3_sum$q),
        .clock(s3_sum$clock)
    );
    top$tc$add_up$0$s2_big s3_marker(
        .d(s3_marker$d),
        .q(s3_marker$q),
        .clock(s3_marker$clock)
    );
    top$tc$add_up$0$lzc lzc(
        .x(lzc$x),
        .lz(lzc$lz)
    );
    top$a_deg s4_valid(
        .d(s4_valid$d),
        .q(s4_valid$q),
        .clock(s4_valid$clock)
    );
    top$a_deg s4_sign(
        .d(s4_sign$d),
        .q(s4_sign$q),
        .clock(s4_sign$clock)
    );
    top$a_deg s4_nan(
        .d(s4_nan$d),
        .q(s4_nan$q),
        .clock(s4_nan$clock)
    );
    top$a_deg s4_inf(
        .d(s4_inf$d),
        .q(s4_inf$q),
        .clock(s4_inf$clock)
    );
    top$a_deg s4_zero(
        .d(s4_zero$d),
        .q(s4_zero$q),
        .clock(s4_zero$clock)
    );
    top$counter s4_exp(
        .d(s4_exp$d),
        .q(s4_exp$q),
        .clock(s4_exp$clock)
    );
    top$counter s4_shift(
        .d(s4_shift$d),
        .q(s4_shift$q),
        .clock(s4_shift$clock)
    );
    top$tc$add_up$0$s3_sum s4_sum(
        .d(s4_sum$d),
        .q(s4_sum$q),
        .clock(s4_sum$clock)
    );
    top$a_deg s5_valid(
        .d(s5_valid$d),
        .q(s5_valid$q),
        .clock(s5_valid$clock)
    );
    top$a_deg s5_sign(
        .d(s5_sign$d),
        .q(s5_sign$q),
        .clock(s5_sign$clock)
    );
    top$a_deg s5_nan(
        .d(s5_nan$d),
        .q(s5_nan$q),
        .clock(s5_nan$clock)
    );
    top$a_deg s5_inf(
        .d(s5_inf$d),
        .q(s5_inf$q),
        .clock(s5_inf$clock)
    );
    top$a_deg s5_zero(
        .d(s5_zero$d),
        .q(s5_zero$q),
        .clock(s5_zero$clock)
    );
    top$a_deg s5_ovf(
        .d(s5_ovf$d),
        .q(s5_ovf$q),
        .clock(s5_ovf$clock)
    );
    top$counter s5_efield(
        .d(s5_efield$d),
        .q(s5_efield$q),
        .clock(s5_efield$clock)
    );
    top$tc$add_up$0$s5_nm s5_nm(
        .d(s5_nm$d),
        .q(s5_nm$q),
        .clock(s5_nm$clock)
    );
    top$tc$add_up$0$round round(
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
    top$a_deg s6_valid(
        .d(s6_valid$d),
        .q(s6_valid$q),
        .clock(s6_valid$clock)
    );
    top$frame$0 s6_y(
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
        c1_swap = a[(32'h0)+:(23)] < b[(32'h0)+:(23)];
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
        c2_small_ext = ((s1_small$q) & 19'h7ffff) << 32'h3;
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
        s2_big$d = ((s1_big$q) & 19'h7ffff) << 32'h3;
        s2_small$d = (c2_aligned & ~(1 << (32'h0)) | ((c2_aligned[32'h0] | c2_lost) << (32'h0)));
        c3_sum = ((s2_big$q) & 20'hfffff) + ((s2_small$q) & 20'hfffff);
        if (s2_eff_sub$q) begin
            c3_sum = ((s2_big$q) & 20'hfffff) - ((s2_small$q) & 20'hfffff);
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
        lzc$x = s3_sum$q[(32'h0)+:(19)] | s3_marker$q;
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
        c5_shifted = s4_sum$q[(32'h0)+:(19)] << s4_shift$q;
        c5_exp = ((s4_exp$q) & 10'h3ff) - ((s4_shift$q) & 10'h3ff);
        c5_nm = (((c5_shifted >> 32'h1) & 18'h3ffff) & ~(1 << (32'h0)) | ((c5_shifted[32'h1] | c5_shifted[32'h0]) << (32'h0)));
        if (s4_sum$q[32'h13]) begin
            c5_exp = ((s4_exp$q) & 10'h3ff) + 32'h1;
            c5_nm = (((s4_sum$q >> 32'h2) & 18'h3ffff) & ~(1 << (32'h0)) | ((s4_sum$q[32'h2] | s4_sum$q[32'h1] | s4_sum$q[32'h0]) << (32'h0)));
        end
        s5_valid$d = s4_valid$q;
        s5_sign$d = s4_sign$q;
        s5_nan$d = s4_nan$q;
        s5_inf$d = s4_inf$q;
        s5_zero$d = s4_zero$q;
        s5_ovf$d = c5_exp >= c_exp_ones;
        s5_efield$d = 32'h0;
        if (c5_nm[32'h10 + 32'h1]) begin
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
    
endmodule // top$tc$add_up$0


module top$tc$add_up$0$lzc(x,lz);
    
    // Module arguments
    input wire  [18:0] x;
    output reg  [4:0] lz;
    
    // Constant declarations
    localparam  mask0 = 19'b101010101010101010;
    localparam  mask1 = 19'b11001100110011001;
    localparam  mask2 = 19'b111100001111000;
    localparam  mask3 = 19'b11111111000;
    localparam  mask4 = 19'b111;
    
    // Local signals
    reg  [18:0] p1;
    reg  [18:0] p2;
    reg  [18:0] p4;
    reg  [18:0] p8;
    reg  [18:0] p16;
    reg  [18:0] lead;
    
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
    
endmodule // top$tc$add_up$0$lzc


module top$tc$add_up$0$round(round_up,sign,nan,inf,zero,ovf,efield,nm,y);
    
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
    
endmodule // top$tc$add_up$0$round


module top$tc$add_up$0$s1_big(d,q,clock);
    
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
          
endmodule // top$tc$add_up$0$s1_big


module top$tc$add_up$0$s2_big(d,q,clock);
    
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
          
endmodule // top$tc$add_up$0$s2_big


module top$tc$add_up$0$s3_sum(d,q,clock);
    
    // Module arguments
    input wire  [19:0] d;
    output reg  [19:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 20'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$tc$add_up$0$s3_sum


module top$tc$add_up$0$s5_nm(d,q,clock);
    
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
          
endmodule // top$tc$add_up$0$s5_nm


module top$tc$add_up$0$unpack_a(x,sign,exp,sig,is_zero,is_inf,is_nan);
    
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
    
endmodule // top$tc$add_up$0$unpack_a


module top$tc$add_v$0(clock,a,b,sub,valid_in,y,valid_out);
    
    // Module arguments
    input wire  clock;
    input wire  [23:0] a;
    input wire  [23:0] b;
    input wire  sub;
    input wire  valid_in;
    output reg  [23:0] y;
    output reg  valid_out;
    
    // Constant declarations
    localparam  round_up = 1'b0;
    localparam  c_align_cap = 8'h13;
    localparam  c_exp_ones = 10'b11111111;
    localparam  c_ones = 19'b1111111111111111111;
    localparam  c_top = 19'b1000000000000000000;
    
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
    reg  [15:0] s1_big$d;
    wire  [15:0] s1_big$q;
    reg  s1_big$clock;
    reg  [15:0] s1_small$d;
    wire  [15:0] s1_small$q;
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
    reg  [18:0] s2_big$d;
    wire  [18:0] s2_big$q;
    reg  s2_big$clock;
    reg  [18:0] s2_small$d;
    wire  [18:0] s2_small$q;
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
    reg  [19:0] s3_sum$d;
    wire  [19:0] s3_sum$q;
    reg  s3_sum$clock;
    reg  [18:0] s3_marker$d;
    wire  [18:0] s3_marker$q;
    reg  s3_marker$clock;
    reg  [18:0] lzc$x;
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
    reg  [19:0] s4_sum$d;
    wire  [19:0] s4_sum$q;
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
    reg  c1_b_sign;
    reg  c1_swap;
    reg  [7:0] c1_d_ab;
    reg  [7:0] c1_d_ba;
    reg  [7:0] c1_sh_ab;
    reg  [7:0] c1_sh_ba;
    reg  c1_inf_sign;
    reg  [18:0] c2_small_ext;
    reg  [18:0] c2_aligned;
    reg  [18:0] c2_mask;
    reg  c2_lost;
    reg  [19:0] c3_sum;
    reg  [7:0] c3_limit;
    reg  c4_zero;
    reg  c4_sign;
    reg  [18:0] c5_shifted;
    reg  [9:0] c5_exp;
    reg  [17:0] c5_nm;
    
    // Sub module instances
    top$tc$add_up$0$unpack_a unpack_a(
        .x(unpack_a$x),
        .sign(unpack_a$sign),
        .exp(unpack_a$exp),
        .sig(unpack_a$sig),
        .is_zero(unpack_a$is_zero),
        .is_inf(unpack_a$is_inf),
        .is_nan(unpack_a$is_nan)
    );
    top$tc$add_up$0$unpack_a unpack_b(
        .x(unpack_b$x),
        .sign(unpack_b$sign),
        .exp(unpack_b$exp),
        .sig(unpack_b$sig),
        .is_zero(unpack_b$is_zero),
        .is_inf(unpack_b$is_inf),
        .is_nan(unpack_b$is_nan)
    );
    top$a_deg s1_valid(
        .d(s1_valid$d),
        .q(s1_valid$q),
        .clock(s1_valid$clock)
    );
    top$a_deg s1_nan(
        .d(s1_nan$d),
        .q(s1_nan$q),
        .clock(s1_nan$clock)
    );
    top$a_deg s1_inf(
        .d(s1_inf$d),
        .q(s1_inf$q),
        .clock(s1_inf$clock)
    );
    top$a_deg s1_inf_sign(
        .d(s1_inf_sign$d),
        .q(s1_inf_sign$q),
        .clock(s1_inf_sign$clock)
    );
    top$a_deg s1_zero_sign(
        .d(s1_zero_sign$d),
        .q(s1_zero_sign$q),
        .clock(s1_zero_sign$clock)
    );
    top$a_deg s1_sign(
        .d(s1_sign$d),
        .q(s1_sign$q),
        .clock(s1_sign$clock)
    );
    top$a_deg s1_eff_sub(
        .d(s1_eff_sub$d),
        .q(s1_eff_sub$q),
        .clock(s1_eff_sub$clock)
    );
    top$counter s1_exp(
        .d(s1_exp$d),
        .q(s1_exp$q),
        .clock(s1_exp$clock)
    );
    top$tc$add_up$0$s1_big s1_big(
        .d(s1_big$d),
        .q(s1_big$q),
        .clock(s1_big$clock)
    );
    top$tc$add_up$0$s1_big s1_small(
        .d(s1_small$d),
        .q(s1_small$q),
        .clock(s1_small$clock)
    );
    top$counter s1_shift(
        .d(s1_shift$d),
        .q(s1_shift$q),
        .clock(s1_shift$clock)
    );
    top$a_deg s2_valid(
        .d(s2_valid$d),
        .q(s2_valid$q),
        .clock(s2_valid$clock)
    );
    top$a_deg s2_nan(
        .d(s2_nan$d),
        .q(s2_nan$q),
        .clock(s2_nan$clock)
    );
    top$a_deg s2_inf(
        .d(s2_inf$d),
        .q(s2_inf$q),
        .clock(s2_inf$clock)
    );
    top$a_deg s2_inf_sign(
        .d(s2_inf_sign$d),
        .q(s2_inf_sign$q),
        .clock(s2_inf_sign$clock)
    );
    top$a_deg s2_zero_sign(
        .d(s2_zero_sign$d),
        .q(s2_zero_sign$q),
        .clock(s2_zero_sign$clock)
    );
    top$a_deg s2_sign(
        .d(s2_sign$d),
        .q(s2_sign$q),
        .clock(s2_sign$clock)
    );
    top$a_deg s2_eff_sub(
        .d(s2_eff_sub$d),
        .q(s2_eff_sub$q),
        .clock(s2_eff_sub$clock)
    );
    top$counter s2_exp(
        .d(s2_exp$d),
        .q(s2_exp$q),
        .clock(s2_exp$clock)
    );
    top$tc$add_up$0$s2_big s2_big(
        .d(s2_big$d),
        .q(s2_big$q),
        .clock(s2_big$clock)
    );
    top$tc$add_up$0$s2_big s2_small(
        .d(s2_small$d),
        .q(s2_small$q),
        .clock(s2_small$clock)
    );
    top$a_deg s3_valid(
        .d(s3_valid$d),
        .q(s3_valid$q),
        .clock(s3_valid$clock)
    );
    top$a_deg s3_nan(
        .d(s3_nan$d),
        .q(s3_nan$q),
        .clock(s3_nan$clock)
    );
    top$a_deg s3_inf(
        .d(s3_inf$d),
        .q(s3_inf$q),
        .clock(s3_inf$clock)
    );
    top$a_deg s3_inf_sign(
        .d(s3_inf_sign$d),
        .q(s3_inf_sign$q),
        .clock(s3_inf_sign$clock)
    );
    top$a_deg s3_zero_sign(
        .d(s3_zero_sign$d),
        .q(s3_zero_sign$q),
        .clock(s3_zero_sign$clock)
    );
    top$a_deg s3_sign(
        .d(s3_sign$d),
        .q(s3_sign$q),
        .clock(s3_sign$clock)
    );
    top$counter s3_exp(
        .d(s3_exp$d),
        .q(s3_exp$q),
        .clock(s3_exp$clock)
    );
    top$tc$add_up$0$s3_sum s3_sum(
        .d(s3_sum$d),
        .q(s3_sum$q),
        .clock(s3_sum$clock)
    );
    top$tc$add_up$0$s2_big s3_marker(
        .d(s3_marker$d),
        .q(s3_marker$q),
        .clock(s3_marker$clock)
    );
    top$tc$add_up$0$lzc lzc(
        .x(lzc$x),
        .lz(lzc$lz)
    );
    top$a_deg s4_valid(
        .d(s4_valid$d),
        .q(s4_valid$q),
        .clock(s4_valid$clock)
    );
    top$a_deg s4_sign(
        .d(s4_sign$d),
        .q(s4_sign$q),
        .clock(s4_sign$clock)
    );
    top$a_deg s4_nan(
        .d(s4_nan$d),
        .q(s4_nan$q),
        .clock(s4_nan$clock)
    );
    top$a_deg s4_inf(
        .d(s4_inf$d),
        .q(s4_inf$q),
        .clock(s4_inf$clock)
    );
    top$a_deg s4_zero(
        .d(s4_zero$d),
        .q(s4_zero$q),
        .clock(s4_zero$clock)
    );
    top$counter s4_exp(
        .d(s4_exp$d),
        .q(s4_exp$q),
        .clock(s4_exp$clock)
    );
    top$counter s4_shift(
        .d(s4_shift$d),
        .q(s4_shift$q),
        .clock(s4_shift$clock)
    );
    top$tc$add_up$0$s3_sum s4_sum(
        .d(s4_sum$d),
        .q(s4_sum$q),
        .clock(s4_sum$clock)
    );
    top$a_deg s5_valid(
        .d(s5_valid$d),
        .q(s5_valid$q),
        .clock(s5_valid$clock)
    );
    top$a_deg s5_sign(
        .d(s5_sign$d),
        .q(s5_sign$q),
        .clock(s5_sign$clock)
    );
    top$a_deg s5_nan(
        .d(s5_nan$d),
        .q(s5_nan$q),
        .clock(s5_nan$clock)
    );
    top$a_deg s5_inf(
        .d(s5_inf$d),
        .q(s5_inf$q),
        .clock(s5_inf$clock)
    );
    top$a_deg s5_zero(
        .d(s5_zero$d),
        .q(s5_zero$q),
        .clock(s5_zero$clock)
    );
    top$a_deg s5_ovf(
        .d(s5_ovf$d),
        .q(s5_ovf$q),
        .clock(s5_ovf$clock)
    );
    top$counter s5_efield(
        .d(s5_efield$d),
        .q(s5_efield$q),
        .clock(s5_efield$clock)
    );
    top$tc$add_up$0$s5_nm s5_nm(
        .d(s5_nm$d),
        .q(s5_nm$q),
        .clock(s5_nm$clock)
    );
    top$tc$add_up$0$round round(
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
    top$a_deg s6_valid(
        .d(s6_valid$d),
        .q(s6_valid$q),
        .clock(s6_valid$clock)
    );
    top$frame$0 s6_y(
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
        c1_swap = a[(32'h0)+:(23)] < b[(32'h0)+:(23)];
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
        c2_small_ext = ((s1_small$q) & 19'h7ffff) << 32'h3;
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
        s2_big$d = ((s1_big$q) & 19'h7ffff) << 32'h3;
        s2_small$d = (c2_aligned & ~(1 << (32'h0)) | ((c2_aligned[32'h0] | c2_lost) << (32'h0)));
        c3_sum = ((s2_big$q) & 20'hfffff) + ((s2_small$q) & 20'hfffff);
        if (s2_eff_sub$q) begin
            c3_sum = ((s2_big$q) & 20'hfffff) - ((s2_small$q) & 20'hfffff);
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
        lzc$x = s3_sum$q[(32'h0)+:(19)] | s3_marker$q;
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
        c5_shifted = s4_sum$q[(32'h0)+:(19)] << s4_shift$q;
        c5_exp = ((s4_exp$q) & 10'h3ff) - ((s4_shift$q) & 10'h3ff);
        c5_nm = (((c5_shifted >> 32'h1) & 18'h3ffff) & ~(1 << (32'h0)) | ((c5_shifted[32'h1] | c5_shifted[32'h0]) << (32'h0)));
        if (s4_sum$q[32'h13]) begin
            c5_exp = ((s4_exp$q) & 10'h3ff) + 32'h1;
            c5_nm = (((s4_sum$q >> 32'h2) & 18'h3ffff) & ~(1 << (32'h0)) | ((s4_sum$q[32'h2] | s4_sum$q[32'h1] | s4_sum$q[32'h0]) << (32'h0)));
        end
        s5_valid$d = s4_valid$q;
        s5_sign$d = s4_sign$q;
        s5_nan$d = s4_nan$q;
        s5_inf$d = s4_inf$q;
        s5_zero$d = s4_zero$q;
        s5_ovf$d = c5_exp >= c_exp_ones;
        s5_efield$d = 32'h0;
        if (c5_nm[32'h10 + 32'h1]) begin
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
    
endmodule // top$tc$add_v$0


module top$tc$cnt$0(d,q,clock);
    
    // Module arguments
    input wire  [7:0] d;
    output reg  [7:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 8'h0;
    end
    
    (* keep *) always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$tc$cnt$0


module top$tc$mul_up$0(clock,a,b,valid_in,y,valid_out);
    
    // Module arguments
    input wire  clock;
    input wire  [23:0] a;
    input wire  [23:0] b;
    input wire  valid_in;
    output reg  [23:0] y;
    output reg  valid_out;
    
    // Constant declarations
    localparam  round_up = 1'b1;
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
    top$tc$add_up$0$unpack_a unpack_a(
        .x(unpack_a$x),
        .sign(unpack_a$sign),
        .exp(unpack_a$exp),
        .sig(unpack_a$sig),
        .is_zero(unpack_a$is_zero),
        .is_inf(unpack_a$is_inf),
        .is_nan(unpack_a$is_nan)
    );
    top$tc$add_up$0$unpack_a unpack_b(
        .x(unpack_b$x),
        .sign(unpack_b$sign),
        .exp(unpack_b$exp),
        .sig(unpack_b$sig),
        .is_zero(unpack_b$is_zero),
        .is_inf(unpack_b$is_inf),
        .is_nan(unpack_b$is_nan)
    );
    top$tc$mul_up$0$lzc_a lzc_a(
        .x(lzc_a$x),
        .lz(lzc_a$lz)
    );
    top$tc$mul_up$0$lzc_a lzc_b(
        .x(lzc_b$x),
        .lz(lzc_b$lz)
    );
    top$a_deg s1_valid(
        .d(s1_valid$d),
        .q(s1_valid$q),
        .clock(s1_valid$clock)
    );
    top$a_deg s1_sign(
        .d(s1_sign$d),
        .q(s1_sign$q),
        .clock(s1_sign$clock)
    );
    top$a_deg s1_nan(
        .d(s1_nan$d),
        .q(s1_nan$q),
        .clock(s1_nan$clock)
    );
    top$a_deg s1_inf(
        .d(s1_inf$d),
        .q(s1_inf$q),
        .clock(s1_inf$clock)
    );
    top$a_deg s1_zero(
        .d(s1_zero$d),
        .q(s1_zero$q),
        .clock(s1_zero$clock)
    );
    top$counter s1_exp_a(
        .d(s1_exp_a$d),
        .q(s1_exp_a$q),
        .clock(s1_exp_a$clock)
    );
    top$counter s1_exp_b(
        .d(s1_exp_b$d),
        .q(s1_exp_b$q),
        .clock(s1_exp_b$clock)
    );
    top$tc$add_up$0$s1_big s1_sig_a(
        .d(s1_sig_a$d),
        .q(s1_sig_a$q),
        .clock(s1_sig_a$clock)
    );
    top$tc$add_up$0$s1_big s1_sig_b(
        .d(s1_sig_b$d),
        .q(s1_sig_b$q),
        .clock(s1_sig_b$clock)
    );
    top$tc$mul_up$0$s1_lz_a s1_lz_a(
        .d(s1_lz_a$d),
        .q(s1_lz_a$q),
        .clock(s1_lz_a$clock)
    );
    top$tc$mul_up$0$s1_lz_a s1_lz_b(
        .d(s1_lz_b$d),
        .q(s1_lz_b$q),
        .clock(s1_lz_b$clock)
    );
    top$a_deg s2_valid(
        .d(s2_valid$d),
        .q(s2_valid$q),
        .clock(s2_valid$clock)
    );
    top$a_deg s2_sign(
        .d(s2_sign$d),
        .q(s2_sign$q),
        .clock(s2_sign$clock)
    );
    top$a_deg s2_nan(
        .d(s2_nan$d),
        .q(s2_nan$q),
        .clock(s2_nan$clock)
    );
    top$a_deg s2_inf(
        .d(s2_inf$d),
        .q(s2_inf$q),
        .clock(s2_inf$clock)
    );
    top$a_deg s2_zero(
        .d(s2_zero$d),
        .q(s2_zero$q),
        .clock(s2_zero$clock)
    );
    top$tc$mul_up$0$s2_exp s2_exp(
        .d(s2_exp$d),
        .q(s2_exp$q),
        .clock(s2_exp$clock)
    );
    top$tc$add_up$0$s1_big s2_sig_a(
        .d(s2_sig_a$d),
        .q(s2_sig_a$q),
        .clock(s2_sig_a$clock)
    );
    top$tc$add_up$0$s1_big s2_sig_b(
        .d(s2_sig_b$d),
        .q(s2_sig_b$q),
        .clock(s2_sig_b$clock)
    );
    top$a_deg s3_valid(
        .d(s3_valid$d),
        .q(s3_valid$q),
        .clock(s3_valid$clock)
    );
    top$a_deg s3_sign(
        .d(s3_sign$d),
        .q(s3_sign$q),
        .clock(s3_sign$clock)
    );
    top$a_deg s3_nan(
        .d(s3_nan$d),
        .q(s3_nan$q),
        .clock(s3_nan$clock)
    );
    top$a_deg s3_inf(
        .d(s3_inf$d),
        .q(s3_inf$q),
        .clock(s3_inf$clock)
    );
    top$a_deg s3_zero(
        .d(s3_zero$d),
        .q(s3_zero$q),
        .clock(s3_zero$clock)
    );
    top$held_tag s3_ll(
        .d(s3_ll$d),
        .q(s3_ll$q),
        .clock(s3_ll$clock)
    );
    top$held_tag s3_lh(
        .d(s3_lh$d),
        .q(s3_lh$q),
        .clock(s3_lh$clock)
    );
    top$held_tag s3_hl(
        .d(s3_hl$d),
        .q(s3_hl$q),
        .clock(s3_hl$clock)
    );
    top$held_tag s3_hh(
        .d(s3_hh$d),
        .q(s3_hh$q),
        .clock(s3_hh$clock)
    );
    top$a_deg s3_lt0(
        .d(s3_lt0$d),
        .q(s3_lt0$q),
        .clock(s3_lt0$clock)
    );
    top$a_deg s3_lt1(
        .d(s3_lt1$d),
        .q(s3_lt1$q),
        .clock(s3_lt1$clock)
    );
    top$tc$mul_up$0$s2_exp s3_u0(
        .d(s3_u0$d),
        .q(s3_u0$q),
        .clock(s3_u0$clock)
    );
    top$tc$mul_up$0$s2_exp s3_u1(
        .d(s3_u1$d),
        .q(s3_u1$q),
        .clock(s3_u1$clock)
    );
    top$a_deg s3_ovf0(
        .d(s3_ovf0$d),
        .q(s3_ovf0$q),
        .clock(s3_ovf0$clock)
    );
    top$a_deg s3_ovf1(
        .d(s3_ovf1$d),
        .q(s3_ovf1$q),
        .clock(s3_ovf1$clock)
    );
    top$counter s3_efield0(
        .d(s3_efield0$d),
        .q(s3_efield0$q),
        .clock(s3_efield0$clock)
    );
    top$counter s3_efield1(
        .d(s3_efield1$d),
        .q(s3_efield1$q),
        .clock(s3_efield1$clock)
    );
    top$a_deg s4_valid(
        .d(s4_valid$d),
        .q(s4_valid$q),
        .clock(s4_valid$clock)
    );
    top$a_deg s4_sign(
        .d(s4_sign$d),
        .q(s4_sign$q),
        .clock(s4_sign$clock)
    );
    top$a_deg s4_nan(
        .d(s4_nan$d),
        .q(s4_nan$q),
        .clock(s4_nan$clock)
    );
    top$a_deg s4_inf(
        .d(s4_inf$d),
        .q(s4_inf$q),
        .clock(s4_inf$clock)
    );
    top$a_deg s4_zero(
        .d(s4_zero$d),
        .q(s4_zero$q),
        .clock(s4_zero$clock)
    );
    top$tc$add_up$0$s5_nm s4_nm(
        .d(s4_nm$d),
        .q(s4_nm$q),
        .clock(s4_nm$clock)
    );
    top$tc$mul_up$0$s2_exp s4_cap(
        .d(s4_cap$d),
        .q(s4_cap$q),
        .clock(s4_cap$clock)
    );
    top$a_deg s4_ovf(
        .d(s4_ovf$d),
        .q(s4_ovf$q),
        .clock(s4_ovf$clock)
    );
    top$counter s4_efield(
        .d(s4_efield$d),
        .q(s4_efield$q),
        .clock(s4_efield$clock)
    );
    top$a_deg s5_valid(
        .d(s5_valid$d),
        .q(s5_valid$q),
        .clock(s5_valid$clock)
    );
    top$a_deg s5_sign(
        .d(s5_sign$d),
        .q(s5_sign$q),
        .clock(s5_sign$clock)
    );
    top$a_deg s5_nan(
        .d(s5_nan$d),
        .q(s5_nan$q),
        .clock(s5_nan$clock)
    );
    top$a_deg s5_inf(
        .d(s5_inf$d),
        .q(s5_inf$q),
        .clock(s5_inf$clock)
    );
    top$a_deg s5_zero(
        .d(s5_zero$d),
        .q(s5_zero$q),
        .clock(s5_zero$clock)
    );
    top$a_deg s5_ovf(
        .d(s5_ovf$d),
        .q(s5_ovf$q),
        .clock(s5_ovf$clock)
    );
    top$counter s5_efield(
        .d(s5_efield$d),
        .q(s5_efield$q),
        .clock(s5_efield$clock)
    );
    top$tc$add_up$0$s5_nm s5_nm(
        .d(s5_nm$d),
        .q(s5_nm$q),
        .clock(s5_nm$clock)
    );
    top$tc$add_up$0$round round(
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
    top$a_deg s6_valid(
        .d(s6_valid$d),
        .q(s6_valid$q),
        .clock(s6_valid$clock)
    );
    top$frame$0 s6_y(
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
    
endmodule // top$tc$mul_up$0


module top$tc$mul_up$0$lzc_a(x,lz);
    
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
    
endmodule // top$tc$mul_up$0$lzc_a


module top$tc$mul_up$0$s1_lz_a(d,q,clock);
    
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
          
endmodule // top$tc$mul_up$0$s1_lz_a


module top$tc$mul_up$0$s2_exp(d,q,clock);
    
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
          
endmodule // top$tc$mul_up$0$s2_exp


module top$tc$mul_v$0(clock,a,b,valid_in,y,valid_out);
    
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
    top$tc$add_up$0$unpack_a unpack_a(
        .x(unpack_a$x),
        .sign(unpack_a$sign),
        .exp(unpack_a$exp),
        .sig(unpack_a$sig),
        .is_zero(unpack_a$is_zero),
        .is_inf(unpack_a$is_inf),
        .is_nan(unpack_a$is_nan)
    );
    top$tc$add_up$0$unpack_a unpack_b(
        .x(unpack_b$x),
        .sign(unpack_b$sign),
        .exp(unpack_b$exp),
        .sig(unpack_b$sig),
        .is_zero(unpack_b$is_zero),
        .is_inf(unpack_b$is_inf),
        .is_nan(unpack_b$is_nan)
    );
    top$tc$mul_up$0$lzc_a lzc_a(
        .x(lzc_a$x),
        .lz(lzc_a$lz)
    );
    top$tc$mul_up$0$lzc_a lzc_b(
        .x(lzc_b$x),
        .lz(lzc_b$lz)
    );
    top$a_deg s1_valid(
        .d(s1_valid$d),
        .q(s1_valid$q),
        .clock(s1_valid$clock)
    );
    top$a_deg s1_sign(
        .d(s1_sign$d),
        .q(s1_sign$q),
        .clock(s1_sign$clock)
    );
    top$a_deg s1_nan(
        .d(s1_nan$d),
        .q(s1_nan$q),
        .clock(s1_nan$clock)
    );
    top$a_deg s1_inf(
        .d(s1_inf$d),
        .q(s1_inf$q),
        .clock(s1_inf$clock)
    );
    top$a_deg s1_zero(
        .d(s1_zero$d),
        .q(s1_zero$q),
        .clock(s1_zero$clock)
    );
    top$counter s1_exp_a(
        .d(s1_exp_a$d),
        .q(s1_exp_a$q),
        .clock(s1_exp_a$clock)
    );
    top$counter s1_exp_b(
        .d(s1_exp_b$d),
        .q(s1_exp_b$q),
        .clock(s1_exp_b$clock)
    );
    top$tc$add_up$0$s1_big s1_sig_a(
        .d(s1_sig_a$d),
        .q(s1_sig_a$q),
        .clock(s1_sig_a$clock)
    );
    top$tc$add_up$0$s1_big s1_sig_b(
        .d(s1_sig_b$d),
        .q(s1_sig_b$q),
        .clock(s1_sig_b$clock)
    );
    top$tc$mul_up$0$s1_lz_a s1_lz_a(
        .d(s1_lz_a$d),
        .q(s1_lz_a$q),
        .clock(s1_lz_a$clock)
    );
    top$tc$mul_up$0$s1_lz_a s1_lz_b(
        .d(s1_lz_b$d),
        .q(s1_lz_b$q),
        .clock(s1_lz_b$clock)
    );
    top$a_deg s2_valid(
        .d(s2_valid$d),
        .q(s2_valid$q),
        .clock(s2_valid$clock)
    );
    top$a_deg s2_sign(
        .d(s2_sign$d),
        .q(s2_sign$q),
        .clock(s2_sign$clock)
    );
    top$a_deg s2_nan(
        .d(s2_nan$d),
        .q(s2_nan$q),
        .clock(s2_nan$clock)
    );
    top$a_deg s2_inf(
        .d(s2_inf$d),
        .q(s2_inf$q),
        .clock(s2_inf$clock)
    );
    top$a_deg s2_zero(
        .d(s2_zero$d),
        .q(s2_zero$q),
        .clock(s2_zero$clock)
    );
    top$tc$mul_up$0$s2_exp s2_exp(
        .d(s2_exp$d),
        .q(s2_exp$q),
        .clock(s2_exp$clock)
    );
    top$tc$add_up$0$s1_big s2_sig_a(
        .d(s2_sig_a$d),
        .q(s2_sig_a$q),
        .clock(s2_sig_a$clock)
    );
    top$tc$add_up$0$s1_big s2_sig_b(
        .d(s2_sig_b$d),
        .q(s2_sig_b$q),
        .clock(s2_sig_b$clock)
    );
    top$a_deg s3_valid(
        .d(s3_valid$d),
        .q(s3_valid$q),
        .clock(s3_valid$clock)
    );
    top$a_deg s3_sign(
        .d(s3_sign$d),
        .q(s3_sign$q),
        .clock(s3_sign$clock)
    );
    top$a_deg s3_nan(
        .d(s3_nan$d),
        .q(s3_nan$q),
        .clock(s3_nan$clock)
    );
    top$a_deg s3_inf(
        .d(s3_inf$d),
        .q(s3_inf$q),
        .clock(s3_inf$clock)
    );
    top$a_deg s3_zero(
        .d(s3_zero$d),
        .q(s3_zero$q),
        .clock(s3_zero$clock)
    );
    top$held_tag s3_ll(
        .d(s3_ll$d),
        .q(s3_ll$q),
        .clock(s3_ll$clock)
    );
    top$held_tag s3_lh(
        .d(s3_lh$d),
        .q(s3_lh$q),
        .clock(s3_lh$clock)
    );
    top$held_tag s3_hl(
        .d(s3_hl$d),
        .q(s3_hl$q),
        .clock(s3_hl$clock)
    );
    top$held_tag s3_hh(
        .d(s3_hh$d),
        .q(s3_hh$q),
        .clock(s3_hh$clock)
    );
    top$a_deg s3_lt0(
        .d(s3_lt0$d),
        .q(s3_lt0$q),
        .clock(s3_lt0$clock)
    );
    top$a_deg s3_lt1(
        .d(s3_lt1$d),
        .q(s3_lt1$q),
        .clock(s3_lt1$clock)
    );
    top$tc$mul_up$0$s2_exp s3_u0(
        .d(s3_u0$d),
        .q(s3_u0$q),
        .clock(s3_u0$clock)
    );
    top$tc$mul_up$0$s2_exp s3_u1(
        .d(s3_u1$d),
        .q(s3_u1$q),
        .clock(s3_u1$clock)
    );
    top$a_deg s3_ovf0(
        .d(s3_ovf0$d),
        .q(s3_ovf0$q),
        .clock(s3_ovf0$clock)
    );
    top$a_deg s3_ovf1(
        .d(s3_ovf1$d),
        .q(s3_ovf1$q),
        .clock(s3_ovf1$clock)
    );
    top$counter s3_efield0(
        .d(s3_efield0$d),
        .q(s3_efield0$q),
        .clock(s3_efield0$clock)
    );
    top$counter s3_efield1(
        .d(s3_efield1$d),
        .q(s3_efield1$q),
        .clock(s3_efield1$clock)
    );
    top$a_deg s4_valid(
        .d(s4_valid$d),
        .q(s4_valid$q),
        .clock(s4_valid$clock)
    );
    top$a_deg s4_sign(
        .d(s4_sign$d),
        .q(s4_sign$q),
        .clock(s4_sign$clock)
    );
    top$a_deg s4_nan(
        .d(s4_nan$d),
        .q(s4_nan$q),
        .clock(s4_nan$clock)
    );
    top$a_deg s4_inf(
        .d(s4_inf$d),
        .q(s4_inf$q),
        .clock(s4_inf$clock)
    );
    top$a_deg s4_zero(
        .d(s4_zero$d),
        .q(s4_zero$q),
        .clock(s4_zero$clock)
    );
    top$tc$add_up$0$s5_nm s4_nm(
        .d(s4_nm$d),
        .q(s4_nm$q),
        .clock(s4_nm$clock)
    );
    top$tc$mul_up$0$s2_exp s4_cap(
        .d(s4_cap$d),
        .q(s4_cap$q),
        .clock(s4_cap$clock)
    );
    top$a_deg s4_ovf(
        .d(s4_ovf$d),
        .q(s4_ovf$q),
        .clock(s4_ovf$clock)
    );
    top$counter s4_efield(
        .d(s4_efield$d),
        .q(s4_efield$q),
        .clock(s4_efield$clock)
    );
    top$a_deg s5_valid(
        .d(s5_valid$d),
        .q(s5_valid$q),
        .clock(s5_valid$clock)
    );
    top$a_deg s5_sign(
        .d(s5_sign$d),
        .q(s5_sign$q),
        .clock(s5_sign$clock)
    );
    top$a_deg s5_nan(
        .d(s5_nan$d),
        .q(s5_nan$q),
        .clock(s5_nan$clock)
    );
    top$a_deg s5_inf(
        .d(s5_inf$d),
        .q(s5_inf$q),
        .clock(s5_inf$clock)
    );
    top$a_deg s5_zero(
        .d(s5_zero$d),
        .q(s5_zero$q),
        .clock(s5_zero$clock)
    );
    top$a_deg s5_ovf(
        .d(s5_ovf$d),
        .q(s5_ovf$q),
        .clock(s5_ovf$clock)
    );
    top$counter s5_efield(
        .d(s5_efield$d),
        .q(s5_efield$q),
        .clock(s5_efield$clock)
    );
    top$tc$add_up$0$s5_nm s5_nm(
        .d(s5_nm$d),
        .q(s5_nm$q),
        .clock(s5_nm$clock)
    );
    top$tc$add_up$0$round round(
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
    top$a_deg s6_valid(
        .d(s6_valid$d),
        .q(s6_valid$q),
        .clock(s6_valid$clock)
    );
    top$frame$0 s6_y(
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
    
endmodule // top$tc$mul_v$0


module top$tc$regs$0(d,q,clock);
    
    // Module arguments
    input wire  [23:0] d;
    output reg  [23:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 24'h0;
    end
    
    (* keep *) always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$tc$regs$0


module top$tc$scale_e$0(clock,a,sel,y);
    
    // Module arguments
    input wire  clock;
    input wire  [23:0] a;
    input wire  sel;
    output reg  [23:0] y;
    
    // Constant declarations
    localparam  c_k0 = 10'b11110011;
    localparam  c_k1 = 10'b11110011;
    localparam  c_sh0 = 8'he;
    localparam  c_sh1 = 8'h0;
    localparam  c_t0 = 8'h1;
    localparam  c_t1 = 8'h0;
    localparam  c_en0 = 1'b1;
    localparam  c_en1 = 1'b0;
    localparam  c_j = 8'h11;
    localparam  c_j1 = 8'h12;
    localparam  c_f = 8'hf;
    localparam  c_ofs = 10'b100000000;
    localparam  c_norm_min = 10'b100000001;
    localparam  c_min = 24'h8000;
    localparam  c_inf = 24'h7f8000;
    localparam  c_nan = 24'h7fc000;
    
    // Stub signals
    reg  out$clock;
    reg  [23:0] out$d;
    wire  [23:0] out$q;
    
    // Local signals
    reg  [7:0] field;
    reg  [14:0] frac;
    reg  [33:0] m;
    reg  [7:0] lo_sh;
    reg  [7:0] t_sh;
    reg  t_en;
    reg  [9:0] kk;
    reg  [33:0] third;
    reg  [33:0] sum;
    reg  top;
    reg  [7:0] sh;
    reg  [33:0] hi;
    reg  lost;
    reg  [33:0] rnd;
    reg  [9:0] eb;
    reg  [9:0] e10;
    reg  [23:0] res;
    
    // Sub module instances
    top$tc$scale_e$0$out out(
        .clock(out$clock),
        .d(out$d),
        .q(out$q)
    );
    
    // Update code
    always @(*) begin
        out$clock = clock;
        field = a[(32'hf)+:(8)];
        frac = a[(32'h0)+:(15)];
        m = (((frac) & 34'h3ffffffff) & ~(1 << (32'hf)) | ((1'b1) << (32'hf)));
        lo_sh = c_sh0;
        t_sh = c_t0;
        t_en = c_en0;
        kk = c_k0;
        if (sel) begin
            lo_sh = c_sh1;
            t_sh = c_t1;
            t_en = c_en1;
            kk = c_k1;
        end
        third = 32'h0;
        if (t_en) begin
            third = m << t_sh;
        end
        sum = (m << c_j) + (m << lo_sh) + third;
        eb = ((field) & 10'h3ff) + kk;
        top = sum[32'h22 - 32'h1];
        sh = c_j;
        if (top) begin
            sh = c_j1;
        end
        hi = sum >> sh;
        lost = (hi << sh) != sum;
        rnd = hi + lost;
        e10 = eb + top + rnd[32'hf + 32'h1];
        res = (((e10 - c_ofs) & 24'hffffff) << c_f) | ((((rnd) & 15'h7fff)) & 24'hffffff);
        if ((field == 32'h0) | (e10 < c_norm_min)) begin
            res = c_min;
        end
        if ((field == 32'h0) & (frac == 32'h0)) begin
            res = 32'h0;
        end
        if (&field) begin
            res = c_inf;
            if (frac != 32'h0) begin
                res = c_nan;
            end
        end
        out$d = res;
        y = out$q;
    end
    
endmodule // top$tc$scale_e$0


module top$tc$scale_e$0$out(clock,d,q);
    
    // Module arguments
    input wire  clock;
    input wire  [23:0] d;
    output reg  [23:0] q;
    
    // Stub signals
    reg  [23:0] line$0$d;
    wire  [23:0] line$0$q;
    reg  line$0$clock;
    reg  [23:0] line$1$d;
    wire  [23:0] line$1$q;
    reg  line$1$clock;
    reg  [23:0] line$2$d;
    wire  [23:0] line$2$q;
    reg  line$2$clock;
    reg  [23:0] line$3$d;
    wire  [23:0] line$3$q;
    reg  line$3$clock;
    
    // Sub module instances
    top$frame$0 line$0(
        .d(line$0$d),
        .q(line$0$q),
        .clock(line$0$clock)
    );
    top$frame$0 line$1(
        .d(line$1$d),
        .q(line$1$q),
        .clock(line$1$clock)
    );
    top$frame$0 line$2(
        .d(line$2$d),
        .q(line$2$q),
        .clock(line$2$clock)
    );
    top$frame$0 line$3(
        .d(line$3$d),
        .q(line$3$q),
        .clock(line$3$clock)
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
        line$0$d = line$1$q;
        line$1$d = line$2$q;
        line$2$d = line$3$q;
        q = line$0$q;
    end
    
endmodule // top$tc$scale_e$0$out


module top$tc$scale_s$0(clock,a,sel,y);
    
    // Module arguments
    input wire  clock;
    input wire  [23:0] a;
    input wire  sel;
    output reg  [23:0] y;
    
    // Constant declarations
    localparam  c_k0 = 10'b11110001;
    localparam  c_k1 = 10'b11110001;
    localparam  c_sh0 = 8'h1;
    localparam  c_sh1 = 8'h1;
    localparam  c_t0 = 8'h1;
    localparam  c_t1 = 8'h1;
    localparam  c_en0 = 1'b0;
    localparam  c_en1 = 1'b0;
    localparam  c_j = 8'h11;
    localparam  c_j1 = 8'h12;
    localparam  c_f = 8'hf;
    localparam  c_ofs = 10'b100000000;
    localparam  c_norm_min = 10'b100000001;
    localparam  c_min = 24'h8000;
    localparam  c_inf = 24'h7f8000;
    localparam  c_nan = 24'h7fc000;
    
    // Stub signals
    reg  out$clock;
    reg  [23:0] out$d;
    wire  [23:0] out$q;
    
    // Local signals
    reg  [7:0] field;
    reg  [14:0] frac;
    reg  [33:0] m;
    reg  [7:0] lo_sh;
    reg  [7:0] t_sh;
    reg  t_en;
    reg  [9:0] kk;
    reg  [33:0] third;
    reg  [33:0] sum;
    reg  top;
    reg  [7:0] sh;
    reg  [33:0] hi;
    reg  lost;
    reg  [33:0] rnd;
    reg  [9:0] eb;
    reg  [9:0] e10;
    reg  [23:0] res;
    
    // Sub module instances
    top$tc$scale_e$0$out out(
        .clock(out$clock),
        .d(out$d),
        .q(out$q)
    );
    
    // Update code
    always @(*) begin
        out$clock = clock;
        field = a[(32'hf)+:(8)];
        frac = a[(32'h0)+:(15)];
        m = (((frac) & 34'h3ffffffff) & ~(1 << (32'hf)) | ((1'b1) << (32'hf)));
        lo_sh = c_sh0;
        t_sh = c_t0;
        t_en = c_en0;
        kk = c_k0;
        if (sel) begin
            lo_sh = c_sh1;
            t_sh = c_t1;
            t_en = c_en1;
            kk = c_k1;
        end
        third = 32'h0;
        if (t_en) begin
            third = m << t_sh;
        end
        sum = (m << c_j) + (m << lo_sh) + third;
        eb = ((field) & 10'h3ff) + kk;
        top = sum[32'h22 - 32'h1];
        sh = c_j;
        if (top) begin
            sh = c_j1;
        end
        hi = sum >> sh;
        lost = (hi << sh) != sum;
        rnd = hi + lost;
        e10 = eb + top + rnd[32'hf + 32'h1];
        res = (((e10 - c_ofs) & 24'hffffff) << c_f) | ((((rnd) & 15'h7fff)) & 24'hffffff);
        if ((field == 32'h0) | (e10 < c_norm_min)) begin
            res = c_min;
        end
        if ((field == 32'h0) & (frac == 32'h0)) begin
            res = 32'h0;
        end
        if (&field) begin
            res = c_inf;
            if (frac != 32'h0) begin
                res = c_nan;
            end
        end
        out$d = res;
        y = out$q;
    end
    
endmodule // top$tc$scale_s$0


module top$tc$scale_z$0(clock,a,sel,y);
    
    // Module arguments
    input wire  clock;
    input wire  [23:0] a;
    input wire  sel;
    output reg  [23:0] y;
    
    // Constant declarations
    localparam  c_k0 = 10'b11110011;
    localparam  c_k1 = 10'b11110011;
    localparam  c_sh0 = 8'hf;
    localparam  c_sh1 = 8'he;
    localparam  c_t0 = 8'h1;
    localparam  c_t1 = 8'h1;
    localparam  c_en0 = 1'b1;
    localparam  c_en1 = 1'b1;
    localparam  c_j = 8'h11;
    localparam  c_j1 = 8'h12;
    localparam  c_f = 8'hf;
    localparam  c_ofs = 10'b100000000;
    localparam  c_norm_min = 10'b100000001;
    localparam  c_min = 24'h8000;
    localparam  c_inf = 24'h7f8000;
    localparam  c_nan = 24'h7fc000;
    
    // Stub signals
    reg  out$clock;
    reg  [23:0] out$d;
    wire  [23:0] out$q;
    
    // Local signals
    reg  [7:0] field;
    reg  [14:0] frac;
    reg  [33:0] m;
    reg  [7:0] lo_sh;
    reg  [7:0] t_sh;
    reg  t_en;
    reg  [9:0] kk;
    reg  [33:0] third;
    reg  [33:0] sum;
    reg  top;
    reg  [7:0] sh;
    reg  [33:0] hi;
    reg  lost;
    reg  [33:0] rnd;
    reg  [9:0] eb;
    reg  [9:0] e10;
    reg  [23:0] res;
    
    // Sub module instances
    top$tc$scale_e$0$out out(
        .clock(out$clock),
        .d(out$d),
        .q(out$q)
    );
    
    // Update code
    always @(*) begin
        out$clock = clock;
        field = a[(32'hf)+:(8)];
        frac = a[(32'h0)+:(15)];
        m = (((frac) & 34'h3ffffffff) & ~(1 << (32'hf)) | ((1'b1) << (32'hf)));
        lo_sh = c_sh0;
        t_sh = c_t0;
        t_en = c_en0;
        kk = c_k0;
        if (sel) begin
            lo_sh = c_sh1;
            t_sh = c_t1;
            t_en = c_en1;
            kk = c_k1;
        end
        third = 32'h0;
        if (t_en) begin
            third = m << t_sh;
        end
        sum = (m << c_j) + (m << lo_sh) + third;
        eb = ((field) & 10'h3ff) + kk;
        top = sum[32'h22 - 32'h1];
        sh = c_j;
        if (top) begin
            sh = c_j1;
        end
        hi = sum >> sh;
        lost = (hi << sh) != sum;
        rnd = hi + lost;
        e10 = eb + top + rnd[32'hf + 32'h1];
        res = (((e10 - c_ofs) & 24'hffffff) << c_f) | ((((rnd) & 15'h7fff)) & 24'hffffff);
        if ((field == 32'h0) | (e10 < c_norm_min)) begin
            res = c_min;
        end
        if ((field == 32'h0) & (frac == 32'h0)) begin
            res = 32'h0;
        end
        if (&field) begin
            res = c_inf;
            if (frac != 32'h0) begin
                res = c_nan;
            end
        end
        out$d = res;
        y = out$q;
    end
    
endmodule // top$tc$scale_z$0


module top$tc$signs$0(x,e,sgn);
    
    // Module arguments
    input wire  [23:0] x;
    input wire  [23:0] e;
    output reg  [1:0] sgn;
    
    // Constant declarations
    localparam  c_pos = 2'b1;
    localparam  c_neg = 2'b10;
    
    // Local signals
    reg  nan;
    reg  big;
    
    // Update code
    always @(*) begin
        nan = &x[(32'hf)+:(8)] & (x[(32'h0)+:(15)] != 32'h0);
        big = ((x[(32'h0)+:(23)]) & 24'hffffff) > e;
        sgn = 32'h0;
        if (big & ~nan) begin
            sgn = c_pos;
            if (x[32'h17]) begin
                sgn = c_neg;
            end
        end
    end
    
endmodule // top$tc$signs$0
