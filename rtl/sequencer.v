

module top(clock,clear,halt,level,branch,remaining,ls_busy,ls_done,rd_valid,rd_ptr,flags_valid,overlap,room,a_valid,al_valid,al_id,al_leaf,al_f0,al_f1,ld_valid,ld_set,ld_pair,ld_id,ld_leaf0,ld_leaf1,ld_f00,ld_f01,ld_f10,ld_f11,leaf_ready,append,wr_side,wr_ptr,read,next_list,push,push_load,push_set,push_pair,push_id,leaf_valid,leaf_ida,leaf_idb,leaf_tag,leaf_side,idle,lists,dop_tests);
    
    // Module arguments
    input wire  clock;
    input wire  clear;
    input wire  halt;
    input wire  [4:0] level;
    input wire  branch;
    input wire  [15:0] remaining;
    input wire  ls_busy;
    input wire  ls_done;
    input wire  rd_valid;
    input wire  [15:0] rd_ptr;
    input wire  flags_valid;
    input wire  [1:0] overlap;
    input wire  [3:0] room;
    input wire  a_valid;
    input wire  al_valid;
    input wire  [15:0] al_id;
    input wire  al_leaf;
    input wire  [31:0] al_f0;
    input wire  [31:0] al_f1;
    input wire  ld_valid;
    input wire  ld_set;
    input wire  ld_pair;
    input wire  [15:0] ld_id;
    input wire  ld_leaf0;
    input wire  ld_leaf1;
    input wire  [31:0] ld_f00;
    input wire  [31:0] ld_f01;
    input wire  [31:0] ld_f10;
    input wire  [31:0] ld_f11;
    input wire  leaf_ready;
    output reg  append;
    output reg  wr_side;
    output reg  [15:0] wr_ptr;
    output reg  read;
    output reg  next_list;
    output reg  push;
    output reg  push_load;
    output reg  push_set;
    output reg  push_pair;
    output reg  [15:0] push_id;
    output reg  leaf_valid;
    output reg  [15:0] leaf_ida;
    output reg  [15:0] leaf_idb;
    output reg  [31:0] leaf_tag;
    output reg  leaf_side;
    output reg  idle;
    output reg  [31:0] lists;
    output reg  [31:0] dop_tests;
    
    // Constant declarations
    localparam  idx_act$0 = 6'b0;
    localparam  idx_act$1 = 6'b1;
    localparam  idx_act$2 = 6'b10;
    localparam  idx_act$3 = 6'b11;
    localparam  idx_act$4 = 6'b100;
    localparam  idx_act$5 = 6'b101;
    localparam  idx_act$6 = 6'b110;
    localparam  idx_act$7 = 6'b111;
    localparam  idx_act$8 = 6'b1000;
    localparam  idx_act$9 = 6'b1001;
    localparam  idx_act$10 = 6'b1010;
    localparam  idx_act$11 = 6'b1011;
    localparam  idx_act$12 = 6'b1100;
    localparam  idx_act$13 = 6'b1101;
    localparam  idx_act$14 = 6'b1110;
    localparam  idx_act$15 = 6'b1111;
    localparam  idx_act$16 = 6'b10000;
    localparam  idx_act$17 = 6'b10001;
    localparam  idx_act$18 = 6'b10010;
    localparam  idx_act$19 = 6'b10011;
    localparam  idx_act$20 = 6'b10100;
    localparam  idx_act$21 = 6'b10101;
    localparam  idx_act$22 = 6'b10110;
    localparam  idx_act$23 = 6'b10111;
    localparam  idx_act$24 = 6'b11000;
    localparam  idx_act$25 = 6'b11001;
    localparam  idx_act$26 = 6'b11010;
    localparam  idx_act$27 = 6'b11011;
    localparam  idx_act$28 = 6'b11100;
    localparam  idx_act$29 = 6'b11101;
    localparam  idx_act$30 = 6'b11110;
    localparam  idx_act$31 = 6'b11111;
    localparam  idx_act$32 = 6'b100000;
    localparam  idx_act$33 = 6'b100001;
    localparam  idx_act$34 = 6'b100010;
    localparam  idx_lvl$0 = 5'b0;
    localparam  idx_lvl$1 = 5'b1;
    localparam  idx_lvl$2 = 5'b10;
    localparam  idx_lvl$3 = 5'b11;
    localparam  idx_lvl$4 = 5'b100;
    localparam  idx_lvl$5 = 5'b101;
    localparam  idx_lvl$6 = 5'b110;
    localparam  idx_lvl$7 = 5'b111;
    localparam  idx_lvl$8 = 5'b1000;
    localparam  idx_lvl$9 = 5'b1001;
    localparam  idx_lvl$10 = 5'b1010;
    localparam  idx_lvl$11 = 5'b1011;
    localparam  idx_lvl$12 = 5'b1100;
    localparam  idx_lvl$13 = 5'b1101;
    localparam  idx_lvl$14 = 5'b1110;
    localparam  idx_lvl$15 = 5'b1111;
    localparam  idx_lvl$16 = 5'b10000;
    localparam  idx_lvl$17 = 5'b10001;
    localparam  idx_lvl$18 = 5'b10010;
    localparam  idx_lvl$19 = 5'b10011;
    localparam  idx_lvl$20 = 5'b10100;
    localparam  idx_lvl$21 = 5'b10101;
    localparam  idx_lvl$22 = 5'b10110;
    localparam  idx_lvl$23 = 5'b10111;
    localparam  idx_lvl$24 = 5'b11000;
    localparam  idx_lvl$25 = 5'b11001;
    localparam  idx_lvl$26 = 5'b11010;
    localparam  idx_lvl$27 = 5'b11011;
    localparam  idx_lvl$28 = 5'b11100;
    localparam  idx_lvl$29 = 5'b11101;
    localparam  idx_lvl$30 = 5'b11110;
    localparam  idx_lvl$31 = 5'b11111;
    localparam  idx_cmp$0 = 2'b0;
    localparam  idx_cmp$1 = 2'b1;
    localparam  idx_cmp$2 = 2'b10;
    
    // Stub signals
    reg  [65:0] act_e$0$d;
    wire  [65:0] act_e$0$q;
    reg  act_e$0$clock;
    reg  [65:0] act_e$1$d;
    wire  [65:0] act_e$1$q;
    reg  act_e$1$clock;
    reg  [65:0] act_e$2$d;
    wire  [65:0] act_e$2$q;
    reg  act_e$2$clock;
    reg  [65:0] act_e$3$d;
    wire  [65:0] act_e$3$q;
    reg  act_e$3$clock;
    reg  [65:0] act_e$4$d;
    wire  [65:0] act_e$4$q;
    reg  act_e$4$clock;
    reg  [65:0] act_e$5$d;
    wire  [65:0] act_e$5$q;
    reg  act_e$5$clock;
    reg  [65:0] act_e$6$d;
    wire  [65:0] act_e$6$q;
    reg  act_e$6$clock;
    reg  [65:0] act_e$7$d;
    wire  [65:0] act_e$7$q;
    reg  act_e$7$clock;
    reg  [65:0] act_e$8$d;
    wire  [65:0] act_e$8$q;
    reg  act_e$8$clock;
    reg  [65:0] act_e$9$d;
    wire  [65:0] act_e$9$q;
    reg  act_e$9$clock;
    reg  [65:0] act_e$10$d;
    wire  [65:0] act_e$10$q;
    reg  act_e$10$clock;
    reg  [65:0] act_e$11$d;
    wire  [65:0] act_e$11$q;
    reg  act_e$11$clock;
    reg  [65:0] act_e$12$d;
    wire  [65:0] act_e$12$q;
    reg  act_e$12$clock;
    reg  [65:0] act_e$13$d;
    wire  [65:0] act_e$13$q;
    reg  act_e$13$clock;
    reg  [65:0] act_e$14$d;
    wire  [65:0] act_e$14$q;
    reg  act_e$14$clock;
    reg  [65:0] act_e$15$d;
    wire  [65:0] act_e$15$q;
    reg  act_e$15$clock;
    reg  [65:0] act_e$16$d;
    wire  [65:0] act_e$16$q;
    reg  act_e$16$clock;
    reg  [65:0] act_e$17$d;
    wire  [65:0] act_e$17$q;
    reg  act_e$17$clock;
    reg  [65:0] act_e$18$d;
    wire  [65:0] act_e$18$q;
    reg  act_e$18$clock;
    reg  [65:0] act_e$19$d;
    wire  [65:0] act_e$19$q;
    reg  act_e$19$clock;
    reg  [65:0] act_e$20$d;
    wire  [65:0] act_e$20$q;
    reg  act_e$20$clock;
    reg  [65:0] act_e$21$d;
    wire  [65:0] act_e$21$q;
    reg  act_e$21$clock;
    reg  [65:0] act_e$22$d;
    wire  [65:0] act_e$22$q;
    reg  act_e$22$clock;
    reg  [65:0] act_e$23$d;
    wire  [65:0] act_e$23$q;
    reg  act_e$23$clock;
    reg  [65:0] act_e$24$d;
    wire  [65:0] act_e$24$q;
    reg  act_e$24$clock;
    reg  [65:0] act_e$25$d;
    wire  [65:0] act_e$25$q;
    reg  act_e$25$clock;
    reg  [65:0] act_e$26$d;
    wire  [65:0] act_e$26$q;
    reg  act_e$26$clock;
    reg  [65:0] act_e$27$d;
    wire  [65:0] act_e$27$q;
    reg  act_e$27$clock;
    reg  [65:0] act_e$28$d;
    wire  [65:0] act_e$28$q;
    reg  act_e$28$clock;
    reg  [65:0] act_e$29$d;
    wire  [65:0] act_e$29$q;
    reg  act_e$29$clock;
    reg  [65:0] act_e$30$d;
    wire  [65:0] act_e$30$q;
    reg  act_e$30$clock;
    reg  [65:0] act_e$31$d;
    wire  [65:0] act_e$31$q;
    reg  act_e$31$clock;
    reg  [65:0] act_e$32$d;
    wire  [65:0] act_e$32$q;
    reg  act_e$32$clock;
    reg  [65:0] act_e$33$d;
    wire  [65:0] act_e$33$q;
    reg  act_e$33$clock;
    reg  [65:0] act_e$34$d;
    wire  [65:0] act_e$34$q;
    reg  act_e$34$clock;
    reg  [5:0] act_n$d;
    wire  [5:0] act_n$q;
    reg  act_n$clock;
    reg  [33:0] grp$0$d;
    wire  [33:0] grp$0$q;
    reg  grp$0$clock;
    reg  [33:0] grp$1$d;
    wire  [33:0] grp$1$q;
    reg  grp$1$clock;
    reg  [33:0] grp$2$d;
    wire  [33:0] grp$2$q;
    reg  grp$2$clock;
    reg  [33:0] grp$3$d;
    wire  [33:0] grp$3$q;
    reg  grp$3$clock;
    reg  [33:0] grp$4$d;
    wire  [33:0] grp$4$q;
    reg  grp$4$clock;
    reg  [33:0] grp$5$d;
    wire  [33:0] grp$5$q;
    reg  grp$5$clock;
    reg  [33:0] grp$6$d;
    wire  [33:0] grp$6$q;
    reg  grp$6$clock;
    reg  [33:0] grp$7$d;
    wire  [33:0] grp$7$q;
    reg  grp$7$clock;
    reg  [33:0] grp$8$d;
    wire  [33:0] grp$8$q;
    reg  grp$8$clock;
    reg  [33:0] grp$9$d;
    wire  [33:0] grp$9$q;
    reg  grp$9$clock;
    reg  [33:0] grp$10$d;
    wire  [33:0] grp$10$q;
    reg  grp$10$clock;
    reg  [33:0] grp$11$d;
    wire  [33:0] grp$11$q;
    reg  grp$11$clock;
    reg  [33:0] grp$12$d;
    wire  [33:0] grp$12$q;
    reg  grp$12$clock;
    reg  [33:0] grp$13$d;
    wire  [33:0] grp$13$q;
    reg  grp$13$clock;
    reg  [33:0] grp$14$d;
    wire  [33:0] grp$14$q;
    reg  grp$14$clock;
    reg  [33:0] grp$15$d;
    wire  [33:0] grp$15$q;
    reg  grp$15$clock;
    reg  [33:0] grp$16$d;
    wire  [33:0] grp$16$q;
    reg  grp$16$clock;
    reg  [33:0] grp$17$d;
    wire  [33:0] grp$17$q;
    reg  grp$17$clock;
    reg  [33:0] grp$18$d;
    wire  [33:0] grp$18$q;
    reg  grp$18$clock;
    reg  [33:0] grp$19$d;
    wire  [33:0] grp$19$q;
    reg  grp$19$clock;
    reg  [33:0] grp$20$d;
    wire  [33:0] grp$20$q;
    reg  grp$20$clock;
    reg  [33:0] grp$21$d;
    wire  [33:0] grp$21$q;
    reg  grp$21$clock;
    reg  [33:0] grp$22$d;
    wire  [33:0] grp$22$q;
    reg  grp$22$clock;
    reg  [33:0] grp$23$d;
    wire  [33:0] grp$23$q;
    reg  grp$23$clock;
    reg  [33:0] grp$24$d;
    wire  [33:0] grp$24$q;
    reg  grp$24$clock;
    reg  [33:0] grp$25$d;
    wire  [33:0] grp$25$q;
    reg  grp$25$clock;
    reg  [33:0] grp$26$d;
    wire  [33:0] grp$26$q;
    reg  grp$26$clock;
    reg  [33:0] grp$27$d;
    wire  [33:0] grp$27$q;
    reg  grp$27$clock;
    reg  [33:0] grp$28$d;
    wire  [33:0] grp$28$q;
    reg  grp$28$clock;
    reg  [33:0] grp$29$d;
    wire  [33:0] grp$29$q;
    reg  grp$29$clock;
    reg  [33:0] grp$30$d;
    wire  [33:0] grp$30$q;
    reg  grp$30$clock;
    reg  [33:0] grp$31$d;
    wire  [33:0] grp$31$q;
    reg  grp$31$clock;
    reg  entered$d;
    wire  entered$q;
    reg  entered$clock;
    reg  spec$d;
    wire  spec$q;
    reg  spec$clock;
    reg  cur$d;
    wire  cur$q;
    reg  cur$clock;
    reg  [17:0] hold$0$d;
    wire  [17:0] hold$0$q;
    reg  hold$0$clock;
    reg  [17:0] hold$1$d;
    wire  [17:0] hold$1$q;
    reg  hold$1$clock;
    reg  [147:0] ldd$0$d;
    wire  [147:0] ldd$0$q;
    reg  ldd$0$clock;
    reg  [147:0] ldd$1$d;
    wire  [147:0] ldd$1$q;
    reg  ldd$1$clock;
    reg  [3:0] inflight$d;
    wire  [3:0] inflight$q;
    reg  inflight$clock;
    reg  [81:0] cmp_e$0$d;
    wire  [81:0] cmp_e$0$q;
    reg  cmp_e$0$clock;
    reg  [81:0] cmp_e$1$d;
    wire  [81:0] cmp_e$1$q;
    reg  cmp_e$1$clock;
    reg  [81:0] cmp_e$2$d;
    wire  [81:0] cmp_e$2$q;
    reg  cmp_e$2$clock;
    reg  [1:0] cmp_n$d;
    wire  [1:0] cmp_n$q;
    reg  cmp_n$clock;
    reg  [31:0] n_lists$d;
    wire  [31:0] n_lists$q;
    reg  n_lists$clock;
    reg  [31:0] n_tests$d;
    wire  [31:0] n_tests$q;
    reg  n_tests$clock;
    
    // Local signals
    reg  c_idle;
    reg  [65:0] c_front;
    reg  c_has;
    reg  c_taken;
    reg  [33:0] c_grp;
    reg  [16:0] c_gm;
    reg  [15:0] c_g_id;
    reg  c_g_pair;
    reg  c_h0;
    reg  c_h1;
    reg  [17:0] c_hc;
    reg  [17:0] c_ho;
    reg  [147:0] c_lc;
    reg  c_loaded;
    reg  c_ho_children;
    reg  [16:0] c_gw0;
    reg  [16:0] c_gw1;
    reg  [33:0] c_gw;
    reg  [17:0] c_hold_w;
    reg  [147:0] c_ldd_w;
    reg  c_enter;
    reg  c_enter_set;
    reg  c_spec_done;
    reg  c_flag;
    reg  [81:0] c_n;
    reg  c_nleaf;
    reg  c_v0;
    reg  c_v1;
    reg  [65:0] c_e0;
    reg  [65:0] c_e1;
    reg  [65:0] c_e2;
    reg  [65:0] c_e3;
    reg  c_nv1;
    reg  c_nv3;
    reg  [5:0] c_p0;
    reg  [5:0] c_p2;
    reg  [1:0] c_pm;
    
    // Sub module instances
    top$act_e$0 act_e$0(
        .d(act_e$0$d),
        .q(act_e$0$q),
        .clock(act_e$0$clock)
    );
    top$act_e$0 act_e$1(
        .d(act_e$1$d),
        .q(act_e$1$q),
        .clock(act_e$1$clock)
    );
    top$act_e$0 act_e$2(
        .d(act_e$2$d),
        .q(act_e$2$q),
        .clock(act_e$2$clock)
    );
    top$act_e$0 act_e$3(
        .d(act_e$3$d),
        .q(act_e$3$q),
        .clock(act_e$3$clock)
    );
    top$act_e$0 act_e$4(
        .d(act_e$4$d),
        .q(act_e$4$q),
        .clock(act_e$4$clock)
    );
    top$act_e$0 act_e$5(
        .d(act_e$5$d),
        .q(act_e$5$q),
        .clock(act_e$5$clock)
    );
    top$act_e$0 act_e$6(
        .d(act_e$6$d),
        .q(act_e$6$q),
        .clock(act_e$6$clock)
    );
    top$act_e$0 act_e$7(
        .d(act_e$7$d),
        .q(act_e$7$q),
        .clock(act_e$7$clock)
    );
    top$act_e$0 act_e$8(
        .d(act_e$8$d),
        .q(act_e$8$q),
        .clock(act_e$8$clock)
    );
    top$act_e$0 act_e$9(
        .d(act_e$9$d),
        .q(act_e$9$q),
        .clock(act_e$9$clock)
    );
    top$act_e$0 act_e$10(
        .d(act_e$10$d),
        .q(act_e$10$q),
        .clock(act_e$10$clock)
    );
    top$act_e$0 act_e$11(
        .d(act_e$11$d),
        .q(act_e$11$q),
        .clock(act_e$11$clock)
    );
    top$act_e$0 act_e$12(
        .d(act_e$12$d),
        .q(act_e$12$q),
        .clock(act_e$12$clock)
    );
    top$act_e$0 act_e$13(
        .d(act_e$13$d),
        .q(act_e$13$q),
        .clock(act_e$13$clock)
    );
    top$act_e$0 act_e$14(
        .d(act_e$14$d),
        .q(act_e$14$q),
        .clock(act_e$14$clock)
    );
    top$act_e$0 act_e$15(
        .d(act_e$15$d),
        .q(act_e$15$q),
        .clock(act_e$15$clock)
    );
    top$act_e$0 act_e$16(
        .d(act_e$16$d),
        .q(act_e$16$q),
        .clock(act_e$16$clock)
    );
    top$act_e$0 act_e$17(
        .d(act_e$17$d),
        .q(act_e$17$q),
        .clock(act_e$17$clock)
    );
    top$act_e$0 act_e$18(
        .d(act_e$18$d),
        .q(act_e$18$q),
        .clock(act_e$18$clock)
    );
    top$act_e$0 act_e$19(
        .d(act_e$19$d),
        .q(act_e$19$q),
        .clock(act_e$19$clock)
    );
    top$act_e$0 act_e$20(
        .d(act_e$20$d),
        .q(act_e$20$q),
        .clock(act_e$20$clock)
    );
    top$act_e$0 act_e$21(
        .d(act_e$21$d),
        .q(act_e$21$q),
        .clock(act_e$21$clock)
    );
    top$act_e$0 act_e$22(
        .d(act_e$22$d),
        .q(act_e$22$q),
        .clock(act_e$22$clock)
    );
    top$act_e$0 act_e$23(
        .d(act_e$23$d),
        .q(act_e$23$q),
        .clock(act_e$23$clock)
    );
    top$act_e$0 act_e$24(
        .d(act_e$24$d),
        .q(act_e$24$q),
        .clock(act_e$24$clock)
    );
    top$act_e$0 act_e$25(
        .d(act_e$25$d),
        .q(act_e$25$q),
        .clock(act_e$25$clock)
    );
    top$act_e$0 act_e$26(
        .d(act_e$26$d),
        .q(act_e$26$q),
        .clock(act_e$26$clock)
    );
    top$act_e$0 act_e$27(
        .d(act_e$27$d),
        .q(act_e$27$q),
        .clock(act_e$27$clock)
    );
    top$act_e$0 act_e$28(
        .d(act_e$28$d),
        .q(act_e$28$q),
        .clock(act_e$28$clock)
    );
    top$act_e$0 act_e$29(
        .d(act_e$29$d),
        .q(act_e$29$q),
        .clock(act_e$29$clock)
    );
    top$act_e$0 act_e$30(
        .d(act_e$30$d),
        .q(act_e$30$q),
        .clock(act_e$30$clock)
    );
    top$act_e$0 act_e$31(
        .d(act_e$31$d),
        .q(act_e$31$q),
        .clock(act_e$31$clock)
    );
    top$act_e$0 act_e$32(
        .d(act_e$32$d),
        .q(act_e$32$q),
        .clock(act_e$32$clock)
    );
    top$act_e$0 act_e$33(
        .d(act_e$33$d),
        .q(act_e$33$q),
        .clock(act_e$33$clock)
    );
    top$act_e$0 act_e$34(
        .d(act_e$34$d),
        .q(act_e$34$q),
        .clock(act_e$34$clock)
    );
    top$act_n act_n(
        .d(act_n$d),
        .q(act_n$q),
        .clock(act_n$clock)
    );
    top$grp$0 grp$0(
        .d(grp$0$d),
        .q(grp$0$q),
        .clock(grp$0$clock)
    );
    top$grp$0 grp$1(
        .d(grp$1$d),
        .q(grp$1$q),
        .clock(grp$1$clock)
    );
    top$grp$0 grp$2(
        .d(grp$2$d),
        .q(grp$2$q),
        .clock(grp$2$clock)
    );
    top$grp$0 grp$3(
        .d(grp$3$d),
        .q(grp$3$q),
        .clock(grp$3$clock)
    );
    top$grp$0 grp$4(
        .d(grp$4$d),
        .q(grp$4$q),
        .clock(grp$4$clock)
    );
    top$grp$0 grp$5(
        .d(grp$5$d),
        .q(grp$5$q),
        .clock(grp$5$clock)
    );
    top$grp$0 grp$6(
        .d(grp$6$d),
        .q(grp$6$q),
        .clock(grp$6$clock)
    );
    top$grp$0 grp$7(
        .d(grp$7$d),
        .q(grp$7$q),
        .clock(grp$7$clock)
    );
    top$grp$0 grp$8(
        .d(grp$8$d),
        .q(grp$8$q),
        .clock(grp$8$clock)
    );
    top$grp$0 grp$9(
        .d(grp$9$d),
        .q(grp$9$q),
        .clock(grp$9$clock)
    );
    top$grp$0 grp$10(
        .d(grp$10$d),
        .q(grp$10$q),
        .clock(grp$10$clock)
    );
    top$grp$0 grp$11(
        .d(grp$11$d),
        .q(grp$11$q),
        .clock(grp$11$clock)
    );
    top$grp$0 grp$12(
        .d(grp$12$d),
        .q(grp$12$q),
        .clock(grp$12$clock)
    );
    top$grp$0 grp$13(
        .d(grp$13$d),
        .q(grp$13$q),
        .clock(grp$13$clock)
    );
    top$grp$0 grp$14(
        .d(grp$14$d),
        .q(grp$14$q),
        .clock(grp$14$clock)
    );
    top$grp$0 grp$15(
        .d(grp$15$d),
        .q(grp$15$q),
        .clock(grp$15$clock)
    );
    top$grp$0 grp$16(
        .d(grp$16$d),
        .q(grp$16$q),
        .clock(grp$16$clock)
    );
    top$grp$0 grp$17(
        .d(grp$17$d),
        .q(grp$17$q),
        .clock(grp$17$clock)
    );
    top$grp$0 grp$18(
        .d(grp$18$d),
        .q(grp$18$q),
        .clock(grp$18$clock)
    );
    top$grp$0 grp$19(
        .d(grp$19$d),
        .q(grp$19$q),
        .clock(grp$19$clock)
    );
    top$grp$0 grp$20(
        .d(grp$20$d),
        .q(grp$20$q),
        .clock(grp$20$clock)
    );
    top$grp$0 grp$21(
        .d(grp$21$d),
        .q(grp$21$q),
        .clock(grp$21$clock)
    );
    top$grp$0 grp$22(
        .d(grp$22$d),
        .q(grp$22$q),
        .clock(grp$22$clock)
    );
    top$grp$0 grp$23(
        .d(grp$23$d),
        .q(grp$23$q),
        .clock(grp$23$clock)
    );
    top$grp$0 grp$24(
        .d(grp$24$d),
        .q(grp$24$q),
        .clock(grp$24$clock)
    );
    top$grp$0 grp$25(
        .d(grp$25$d),
        .q(grp$25$q),
        .clock(grp$25$clock)
    );
    top$grp$0 grp$26(
        .d(grp$26$d),
        .q(grp$26$q),
        .clock(grp$26$clock)
    );
    top$grp$0 grp$27(
        .d(grp$27$d),
        .q(grp$27$q),
        .clock(grp$27$clock)
    );
    top$grp$0 grp$28(
        .d(grp$28$d),
        .q(grp$28$q),
        .clock(grp$28$clock)
    );
    top$grp$0 grp$29(
        .d(grp$29$d),
        .q(grp$29$q),
        .clock(grp$29$clock)
    );
    top$grp$0 grp$30(
        .d(grp$30$d),
        .q(grp$30$q),
        .clock(grp$30$clock)
    );
    top$grp$0 grp$31(
        .d(grp$31$d),
        .q(grp$31$q),
        .clock(grp$31$clock)
    );
    top$cur entered(
        .d(entered$d),
        .q(entered$q),
        .clock(entered$clock)
    );
    top$cur spec(
        .d(spec$d),
        .q(spec$q),
        .clock(spec$clock)
    );
    top$cur cur(
        .d(cur$d),
        .q(cur$q),
        .clock(cur$clock)
    );
    top$hold$0 hold$0(
        .d(hold$0$d),
        .q(hold$0$q),
        .clock(hold$0$clock)
    );
    top$hold$0 hold$1(
        .d(hold$1$d),
        .q(hold$1$q),
        .clock(hold$1$clock)
    );
    top$ldd$0 ldd$0(
        .d(ldd$0$d),
        .q(ldd$0$q),
        .clock(ldd$0$clock)
    );
    top$ldd$0 ldd$1(
        .d(ldd$1$d),
        .q(ldd$1$q),
        .clock(ldd$1$clock)
    );
    top$inflight inflight(
        .d(inflight$d),
        .q(inflight$q),
        .clock(inflight$clock)
    );
    top$cmp_e$0 cmp_e$0(
        .d(cmp_e$0$d),
        .q(cmp_e$0$q),
        .clock(cmp_e$0$clock)
    );
    top$cmp_e$0 cmp_e$1(
        .d(cmp_e$1$d),
        .q(cmp_e$1$q),
        .clock(cmp_e$1$clock)
    );
    top$cmp_e$0 cmp_e$2(
        .d(cmp_e$2$d),
        .q(cmp_e$2$q),
        .clock(cmp_e$2$clock)
    );
    top$cmp_n cmp_n(
        .d(cmp_n$d),
        .q(cmp_n$q),
        .clock(cmp_n$clock)
    );
    top$n_lists n_lists(
        .d(n_lists$d),
        .q(n_lists$q),
        .clock(n_lists$clock)
    );
    top$n_lists n_tests(
        .d(n_tests$d),
        .q(n_tests$q),
        .clock(n_tests$clock)
    );
    
    // Update code
    always @(*) begin
        c_idle = ~ls_busy & ~ls_done & ~halt;
        c_front = act_e$0$q;
        c_has = act_n$q != 32'h0;
        append = c_has & ~c_front[32'h0] & c_idle;
        leaf_valid = c_has & c_front[32'h0] & ~halt;
        c_taken = append | (leaf_valid & leaf_ready);
        wr_side = 1'b0;
        wr_ptr = 32'h0;
        if (append) begin
            wr_side = c_front[32'h1];
            wr_ptr = c_front[(32'h2)+:(16)];
        end
        leaf_side = 1'b0;
        leaf_ida = 32'h0;
        leaf_idb = 32'h0;
        leaf_tag = 32'h0;
        if (leaf_valid) begin
            leaf_side = c_front[32'h1];
            leaf_ida = c_front[(32'h2)+:(16)];
            leaf_idb = c_front[(32'h12)+:(16)];
            leaf_tag = c_front[(32'h22)+:(32)];
        end
        c_grp = 32'h0;
        if (level == idx_lvl$0 + 32'h1) begin
            c_grp = grp$0$q;
        end
        if (level == idx_lvl$1 + 32'h1) begin
            c_grp = grp$1$q;
        end
        if (level == idx_lvl$2 + 32'h1) begin
            c_grp = grp$2$q;
        end
        if (level == idx_lvl$3 + 32'h1) begin
            c_grp = grp$3$q;
        end
        if (level == idx_lvl$4 + 32'h1) begin
            c_grp = grp$4$q;
        end
        if (level == idx_lvl$5 + 32'h1) begin
            c_grp = grp$5$q;
        end
        if (level == idx_lvl$6 + 32'h1) begin
            c_grp = grp$6$q;
        end
        if (level == idx_lvl$7 + 32'h1) begin
            c_grp = grp$7$q;
        end
        if (level == idx_lvl$8 + 32'h1) begin
            c_grp = grp$8$q;
        end
        if (level == idx_lvl$9 + 32'h1) begin
            c_grp = grp$9$q;
        end
        if (level == idx_lvl$10 + 32'h1) begin
            c_grp = grp$10$q;
        end
        if (level == idx_lvl$11 + 32'h1) begin
            c_grp = grp$11$q;
        end
        if (level == idx_lvl$12 + 32'h1) begin
            c_grp = grp$12$q;
        end
        if (level == idx_lvl$13 + 32'h1) begin
            c_grp = grp$13$q;
        end
        if (level == idx_lvl$14 + 32'h1) begin
            c_grp = grp$14$q;
        end
        if (level == idx_lvl$15 + 32'h1) begin
            c_grp = grp$15$q;
        end
        if (level == idx_lvl$16 + 32'h1) begin
            c_grp = grp$16$q;
        end
        if (level == idx_lvl$17 + 32'h1) begin
            c_grp = grp$17$q;
        end
        if (level == idx_lvl$18 + 32'h1) begin
            c_grp = grp$18$q;
        end
        if (level == idx_lvl$19 + 32'h1) begin
            c_grp = grp$19$q;
        end
        if (level == idx_lvl$20 + 32'h1) begin
            c_grp = grp$20$q;
        end
        if (level == idx_lvl$21 + 32'h1) begin
            c_grp = grp$21$q;
        end
        if (level == idx_lvl$22 + 32'h1) begin
            c_grp = grp$22$q;
        end
        if (level == idx_lvl$23 + 32'h1) begin
            c_grp = grp$23$q;
        end
        if (level == idx_lvl$24 + 32'h1) begin
            c_grp = grp$24$q;
        end
        if (level == idx_lvl$25 + 32'h1) begin
            c_grp = grp$25$q;
        end
        if (level == idx_lvl$26 + 32'h1) begin
            c_grp = grp$26$q;
        end
        if (level == idx_lvl$27 + 32'h1) begin
            c_grp = grp$27$q;
        end
        if (level == idx_lvl$28 + 32'h1) begin
            c_grp = grp$28$q;
        end
        if (level == idx_lvl$29 + 32'h1) begin
            c_grp = grp$29$q;
        end
        if (level == idx_lvl$30 + 32'h1) begin
            c_grp = grp$30$q;
        end
        if (level == idx_lvl$31 + 32'h1) begin
            c_grp = grp$31$q;
        end
        if (branch) begin
            c_gm = c_grp[(32'h11)+:(17)];
        end
        else begin
            c_gm = c_grp[(32'h0)+:(17)];
        end
        c_g_id = 32'h0;
        c_g_pair = 1'b0;
        if (level != 32'h1) begin
            c_g_id = c_gm[(32'h1)+:(16)];
            c_g_pair = ~c_gm[32'h0];
        end
        c_h0 = hold$0$q[32'h0] & (hold$0$q[32'h1] == c_g_pair) & (hold$0$q[(32'h2)+:(16)] == c_g_id);
        c_h1 = hold$1$q[32'h0] & (hold$1$q[32'h1] == c_g_pair) & (hold$1$q[(32'h2)+:(16)] == c_g_id);
        if (cur$q) begin
            c_hc = hold$1$q;
            c_ho = hold$0$q;
            c_lc = ldd$1$q;
        end
        else begin
            c_hc = hold$0$q;
            c_ho = hold$1$q;
            c_lc = ldd$0$q;
        end
        c_loaded = c_lc[(32'h0)+:(18)] == c_hc;
        c_ho_children = c_ho[32'h0] & c_ho[32'h1] & (((c_ho[(32'h2)+:(16)]) & 32'hffffffff) == c_lc[(32'h14)+:(32)]);
        c_enter = 1'b0;
        c_enter_set = 1'b0;
        c_spec_done = 1'b0;
        push = 1'b0;
        push_load = 1'b0;
        push_set = 1'b0;
        push_pair = 1'b0;
        push_id = 32'h0;
        if (rd_valid) begin
            push = 1'b1;
            push_set = cur$q;
            push_id = rd_ptr;
        end
        else if (c_idle & (room != 32'h0) & ~entered$q & (level != 32'h0)) begin
            c_enter = 1'b1;
            if (c_h0) begin
                c_enter_set = 1'b0;
            end
            else if (c_h1) begin
                c_enter_set = 1'b1;
            end
            else begin
                c_enter_set = ~cur$q;
                push = 1'b1;
                push_load = 1'b1;
                push_set = ~cur$q;
                push_pair = c_g_pair;
                push_id = c_g_id;
            end
        end
        else if (c_idle & (room != 32'h0) & entered$q & spec$q & c_loaded & c_lc[32'h0]) begin
            c_spec_done = 1'b1;
            if (~c_lc[32'h12] & ~c_ho_children) begin
                push = 1'b1;
                push_load = 1'b1;
                push_set = ~cur$q;
                push_pair = 1'b1;
                push_id = c_lc[(32'h14)+:(16)];
            end
        end
        read = c_idle & entered$q & (remaining != 32'h0) & (room > 32'h2) & (inflight$q < 32'h8) & (act_n$q < 32'h4) & (level != 32'h0);
        next_list = c_idle & entered$q & (remaining == 32'h0) & (inflight$q == 32'h0) & ~c_has;
        idle = ~c_has;
        lists = n_lists$q;
        dop_tests = n_tests$q;
        c_n = cmp_e$0$q;
        c_flag = flags_valid & c_n[32'h0];
        c_nleaf = c_n[32'h11];
        c_v0 = c_flag & overlap[32'h0] & c_lc[32'h0];
        c_v1 = c_flag & overlap[32'h1] & c_lc[32'h0] & c_lc[32'h1];
        c_nv1 = c_v0 & ~c_nleaf;
        c_nv3 = c_v1 & ~c_nleaf;
        if (c_nleaf & c_lc[32'h12]) begin
            c_e0 = 32'h1 | (((c_n[(32'h32)+:(16)]) & 66'h3ffffffffffffffff) << 32'h2) | (((c_lc[(32'h34)+:(16)]) & 66'h3ffffffffffffffff) << 32'h12) | (((c_n[(32'h12)+:(32)] | (c_lc[(32'h14)+:(32)] << 32'h10)) & 66'h3ffffffffffffffff) << 32'h22);
        end
        else if (c_nleaf) begin
            c_e0 = ((c_n[(32'h1)+:(16)]) & 66'h3ffffffffffffffff) << 32'h2;
        end
        else begin
            c_e0 = ((c_n[(32'h12)+:(16)]) & 66'h3ffffffffffffffff) << 32'h2;
        end
        if (c_nleaf & c_lc[32'h13]) begin
            c_e2 = 32'h3 | (((c_n[(32'h32)+:(16)]) & 66'h3ffffffffffffffff) << 32'h2) | (((c_lc[(32'h74)+:(16)]) & 66'h3ffffffffffffffff) << 32'h12) | (((c_n[(32'h12)+:(32)] | (c_lc[(32'h54)+:(32)] << 32'h10)) & 66'h3ffffffffffffffff) << 32'h22);
        end
        else if (c_nleaf) begin
            c_e2 = 32'h2 | (((c_n[(32'h1)+:(16)]) & 66'h3ffffffffffffffff) << 32'h2);
        end
        else begin
            c_e2 = 32'h2 | (((c_n[(32'h12)+:(16)]) & 66'h3ffffffffffffffff) << 32'h2);
        end
        c_e1 = ((c_n[(32'h32)+:(16)]) & 66'h3ffffffffffffffff) << 32'h2;
        c_e3 = 32'h2 | (((c_n[(32'h32)+:(16)]) & 66'h3ffffffffffffffff) << 32'h2);
        c_p0 = act_n$q - ((c_taken) & 6'h3f);
        c_p2 = c_p0;
        if (c_v0) begin
            c_p2 = c_p0 + 32'h1 + ((c_nv1) & 6'h3f);
        end
        c_pm = cmp_n$q - ((flags_valid) & 2'h3);
        c_hold_w = 32'h1 | (((push_pair) & 18'h3ffff) << 32'h1) | (((push_id) & 18'h3ffff) << 32'h2);
        c_ldd_w = 32'h1 | (((ld_pair) & 148'hfffffffffffffffffffffffffffffffffffff) << 32'h1) | (((ld_id) & 148'hfffffffffffffffffffffffffffffffffffff) << 32'h2) | (((ld_leaf0) & 148'hfffffffffffffffffffffffffffffffffffff) << 32'h12) | (((ld_leaf1) & 148'hfffffffffffffffffffffffffffffffffffff) << 32'h13) | (((ld_f00) & 148'hfffffffffffffffffffffffffffffffffffff) << 32'h14) | (((ld_f01) & 148'hfffffffffffffffffffffffffffffffffffff) << 32'h34) | (((ld_f10) & 148'hfffffffffffffffffffffffffffffffffffff) << 32'h54) | (((ld_f11) & 148'hfffffffffffffffffffffffffffffffffffff) << 32'h74);
        if (c_lc[32'h12]) begin
            c_gw0 = 32'h1 | (((c_lc[(32'h2)+:(16)]) & 17'h1ffff) << 32'h1);
        end
        else begin
            c_gw0 = ((c_lc[(32'h14)+:(16)]) & 17'h1ffff) << 32'h1;
        end
        if (c_lc[32'h13]) begin
            c_gw1 = 32'h1 | (((c_lc[(32'h2)+:(16)] + 32'h1) & 17'h1ffff) << 32'h1);
        end
        else begin
            c_gw1 = ((c_lc[(32'h54)+:(16)]) & 17'h1ffff) << 32'h1;
        end
        c_gw = ((c_gw0) & 34'h3ffffffff) | (((c_gw1) & 34'h3ffffffff) << 32'h11);
        act_n$clock = clock;
        entered$clock = clock;
        spec$clock = clock;
        cur$clock = clock;
        inflight$clock = clock;
        cmp_n$clock = clock;
        n_lists$clock = clock;
        n_tests$clock = clock;
        act_n$d = act_n$q;
        entered$d = entered$q;
        spec$d = spec$q;
        cur$d = cur$q;
        inflight$d = inflight$q;
        cmp_n$d = cmp_n$q;
        n_lists$d = n_lists$q;
        n_tests$d = n_tests$q;
        act_n$d = c_p2 + ((c_v1) & 6'h3f) + ((c_nv3) & 6'h3f);
        act_e$0$clock = clock;
        act_e$0$d = act_e$0$q;
        act_e$1$clock = clock;
        act_e$1$d = act_e$1$q;
        act_e$2$clock = clock;
        act_e$2$d = act_e$2$q;
        act_e$3$clock = clock;
        act_e$3$d = act_e$3$q;
        act_e$4$clock = clock;
        act_e$4$d = act_e$4$q;
        act_e$5$clock = clock;
        act_e$5$d = act_e$5$q;
        act_e$6$clock = clock;
        act_e$6$d = act_e$6$q;
        act_e$7$clock = clock;
        act_e$7$d = act_e$7$q;
        act_e$8$clock = clock;
        act_e$8$d = act_e$8$q;
        act_e$9$clock = clock;
        act_e$9$d = act_e$9$q;
        act_e$10$clock = clock;
        act_e$10$d = act_e$10$q;
        act_e$11$clock = clock;
        act_e$11$d = act_e$11$q;
        act_e$12$clock = clock;
        act_e$12$d = act_e$12$q;
        act_e$13$clock = clock;
        act_e$13$d = act_e$13$q;
        act_e$14$clock = clock;
        act_e$14$d = act_e$14$q;
        act_e$15$clock = clock;
        act_e$15$d = act_e$15$q;
        act_e$16$clock = clock;
        act_e$16$d = act_e$16$q;
        act_e$17$clock = clock;
        act_e$17$d = act_e$17$q;
        act_e$18$clock = clock;
        act_e$18$d = act_e$18$q;
        act_e$19$clock = clock;
        act_e$19$d = act_e$19$q;
        act_e$20$clock = clock;
        act_e$20$d = act_e$20$q;
        act_e$21$clock = clock;
        act_e$21$d = act_e$21$q;
        act_e$22$clock = clock;
        act_e$22$d = act_e$22$q;
        act_e$23$clock = clock;
        act_e$23$d = act_e$23$q;
        act_e$24$clock = clock;
        act_e$24$d = act_e$24$q;
        act_e$25$clock = clock;
        act_e$25$d = act_e$25$q;
        act_e$26$clock = clock;
        act_e$26$d = act_e$26$q;
        act_e$27$clock = clock;
        act_e$27$d = act_e$27$q;
        act_e$28$clock = clock;
        act_e$28$d = act_e$28$q;
        act_e$29$clock = clock;
        act_e$29$d = act_e$29$q;
        act_e$30$clock = clock;
        act_e$30$d = act_e$30$q;
        act_e$31$clock = clock;
        act_e$31$d = act_e$31$q;
        act_e$32$clock = clock;
        act_e$32$d = act_e$32$q;
        act_e$33$clock = clock;
        act_e$33$d = act_e$33$q;
        act_e$34$clock = clock;
        act_e$34$d = act_e$34$q;
        if (c_taken) begin
            act_e$0$d = act_e$1$q;
        end
        if (c_taken) begin
            act_e$1$d = act_e$2$q;
        end
        if (c_taken) begin
            act_e$2$d = act_e$3$q;
        end
        if (c_taken) begin
            act_e$3$d = act_e$4$q;
        end
        if (c_taken) begin
            act_e$4$d = act_e$5$q;
        end
        if (c_taken) begin
            act_e$5$d = act_e$6$q;
        end
        if (c_taken) begin
            act_e$6$d = act_e$7$q;
        end
        if (c_taken) begin
            act_e$7$d = act_e$8$q;
        end
        if (c_taken) begin
            act_e$8$d = act_e$9$q;
        end
        if (c_taken) begin
            act_e$9$d = act_e$10$q;
        end
        if (c_taken) begin
            act_e$10$d = act_e$11$q;
        end
        if (c_taken) begin
            act_e$11$d = act_e$12$q;
        end
        if (c_taken) begin
            act_e$12$d = act_e$13$q;
        end
        if (c_taken) begin
            act_e$13$d = act_e$14$q;
        end
        if (c_taken) begin
            act_e$14$d = act_e$15$q;
        end
        if (c_taken) begin
            act_e$15$d = act_e$16$q;
        end
        if (c_taken) begin
            act_e$16$d = act_e$17$q;
        end
        if (c_taken) begin
            act_e$17$d = act_e$18$q;
        end
        if (c_taken) begin
            act_e$18$d = act_e$19$q;
        end
        if (c_taken) begin
            act_e$19$d = act_e$20$q;
        end
        if (c_taken) begin
            act_e$20$d = act_e$21$q;
        end
        if (c_taken) begin
            act_e$21$d = act_e$22$q;
        end
        if (c_taken) begin
            act_e$22$d = act_e$23$q;
        end
        if (c_taken) begin
            act_e$23$d = act_e$24$q;
        end
        if (c_taken) begin
            act_e$24$d = act_e$25$q;
        end
        if (c_taken) begin
            act_e$25$d = act_e$26$q;
        end
        if (c_taken) begin
            act_e$26$d = act_e$27$q;
        end
        if (c_taken) begin
            act_e$27$d = act_e$28$q;
        end
        if (c_taken) begin
            act_e$28$d = act_e$29$q;
        end
        if (c_taken) begin
            act_e$29$d = act_e$30$q;
        end
        if (c_taken) begin
            act_e$30$d = act_e$31$q;
        end
        if (c_taken) begin
            act_e$31$d = act_e$32$q;
        end
        if (c_taken) begin
            act_e$32$d = act_e$33$q;
        end
        if (c_taken) begin
            act_e$33$d = act_e$34$q;
        end
        if (c_v0 & (c_p0 == idx_act$0)) begin
            act_e$0$d = c_e0;
        end
        if (c_nv1 & (c_p0 + 32'h1 == idx_act$0)) begin
            act_e$0$d = c_e1;
        end
        if (c_v1 & (c_p2 == idx_act$0)) begin
            act_e$0$d = c_e2;
        end
        if (c_nv3 & (c_p2 + 32'h1 == idx_act$0)) begin
            act_e$0$d = c_e3;
        end
        if (c_v0 & (c_p0 == idx_act$1)) begin
            act_e$1$d = c_e0;
        end
        if (c_nv1 & (c_p0 + 32'h1 == idx_act$1)) begin
            act_e$1$d = c_e1;
        end
        if (c_v1 & (c_p2 == idx_act$1)) begin
            act_e$1$d = c_e2;
        end
        if (c_nv3 & (c_p2 + 32'h1 == idx_act$1)) begin
            act_e$1$d = c_e3;
        end
        if (c_v0 & (c_p0 == idx_act$2)) begin
            act_e$2$d = c_e0;
        end
        if (c_nv1 & (c_p0 + 32'h1 == idx_act$2)) begin
            act_e$2$d = c_e1;
        end
        if (c_v1 & (c_p2 == idx_act$2)) begin
            act_e$2$d = c_e2;
        end
        if (c_nv3 & (c_p2 + 32'h1 == idx_act$2)) begin
            act_e$2$d = c_e3;
        end
        if (c_v0 & (c_p0 == idx_act$3)) begin
            act_e$3$d = c_e0;
        end
        if (c_nv1 & (c_p0 + 32'h1 == idx_act$3)) begin
            act_e$3$d = c_e1;
        end
        if (c_v1 & (c_p2 == idx_act$3)) begin
            act_e$3$d = c_e2;
        end
        if (c_nv3 & (c_p2 + 32'h1 == idx_act$3)) begin
            act_e$3$d = c_e3;
        end
        if (c_v0 & (c_p0 == idx_act$4)) begin
            act_e$4$d = c_e0;
        end
        if (c_nv1 & (c_p0 + 32'h1 == idx_act$4)) begin
            act_e$4$d = c_e1;
        end
        if (c_v1 & (c_p2 == idx_act$4)) begin
            act_e$4$d = c_e2;
        end
        if (c_nv3 & (c_p2 + 32'h1 == idx_act$4)) begin
            act_e$4$d = c_e3;
        end
        if (c_v0 & (c_p0 == idx_act$5)) begin
            act_e$5$d = c_e0;
        end
        if (c_nv1 & (c_p0 + 32'h1 == idx_act$5)) begin
            act_e$5$d = c_e1;
        end
        if (c_v1 & (c_p2 == idx_act$5)) begin
            act_e$5$d = c_e2;
        end
        if (c_nv3 & (c_p2 + 32'h1 == idx_act$5)) begin
            act_e$5$d = c_e3;
        end
        if (c_v0 & (c_p0 == idx_act$6)) begin
            act_e$6$d = c_e0;
        end
        if (c_nv1 & (c_p0 + 32'h1 == idx_act$6)) begin
            act_e$6$d = c_e1;
        end
        if (c_v1 & (c_p2 == idx_act$6)) begin
            act_e$6$d = c_e2;
        end
        if (c_nv3 & (c_p2 + 32'h1 == idx_act$6)) begin
            act_e$6$d = c_e3;
        end
        if (c_v0 & (c_p0 == idx_act$7)) begin
            act_e$7$d = c_e0;
        end
        if (c_nv1 & (c_p0 + 32'h1 == idx_act$7)) begin
            act_e$7$d = c_e1;
        end
        if (c_v1 & (c_p2 == idx_act$7)) begin
            act_e$7$d = c_e2;
        end
        if (c_nv3 & (c_p2 + 32'h1 == idx_act$7)) begin
            act_e$7$d = c_e3;
        end
        if (c_v0 & (c_p0 == idx_act$8)) begin
            act_e$8$d = c_e0;
        end
        if (c_nv1 & (c_p0 + 32'h1 == idx_act$8)) begin
            act_e$8$d = c_e1;
        end
        if (c_v1 & (c_p2 == idx_act$8)) begin
            act_e$8$d = c_e2;
        end
        if (c_nv3 & (c_p2 + 32'h1 == idx_act$8)) begin
            act_e$8$d = c_e3;
        end
        if (c_v0 & (c_p0 == idx_act$9)) begin
            act_e$9$d = c_e0;
        end
        if (c_nv1 & (c_p0 + 32'h1 == idx_act$9)) begin
            act_e$9$d = c_e1;
        end
        if (c_v1 & (c_p2 == idx_act$9)) begin
            act_e$9$d = c_e2;
        end
        if (c_nv3 & (c_p2 + 32'h1 == idx_act$9)) begin
            act_e$9$d = c_e3;
        end
        if (c_v0 & (c_p0 == idx_act$10)) begin
            act_e$10$d = c_e0;
        end
        if (c_nv1 & (c_p0 + 32'h1 == idx_act$10)) begin
            act_e$10$d = c_e1;
        end
        if (c_v1 & (c_p2 == idx_act$10)) begin
            act_e$10$d = c_e2;
        end
        if (c_nv3 & (c_p2 + 32'h1 == idx_act$10)) begin
            act_e$10$d = c_e3;
        end
        if (c_v0 & (c_p0 == idx_act$11)) begin
            act_e$11$d = c_e0;
        end
        if (c_nv1 & (c_p0 + 32'h1 == idx_act$11)) begin
            act_e$11$d = c_e1;
        end
        if (c_v1 & (c_p2 == idx_act$11)) begin
            act_e$11$d = c_e2;
        end
        if (c_nv3 & (c_p2 + 32'h1 == idx_act$11)) begin
            act_e$11$d = c_e3;
        end
        if (c_v0 & (c_p0 == idx_act$12)) begin
            act_e$12$d = c_e0;
        end
        if (c_nv1 & (c_p0 + 32'h1 == idx_act$12)) begin
            act_e$12$d = c_e1;
        end
        if (c_v1 & (c_p2 == idx_act$12)) begin
            act_e$12$d = c_e2;
        end
        if (c_nv3 & (c_p2 + 32'h1 == idx_act$12)) begin
            act_e$12$d = c_e3;
        end
        if (c_v0 & (c_p0 == idx_act$13)) begin
            act_e$13$d = c_e0;
        end
        if (c_nv1 & (c_p0 + 32'h1 == idx_act$13)) begin
            act_e$13$d = c_e1;
        end
        if (c_v1 & (c_p2 == idx_act$13)) begin
            act_e$13$d = c_e2;
        end
        if (c_nv3 & (c_p2 + 32'h1 == idx_act$13)) begin
            act_e$13$d = c_e3;
        end
        if (c_v0 & (c_p0 == idx_act$14)) begin
            act_e$14$d = c_e0;
        end
        if (c_nv1 & (c_p0 + 32'h1 == idx_act$14)) begin
            act_e$14$d = c_e1;
        end
        if (c_v1 & (c_p2 == idx_act$14)) begin
            act_e$14$d = c_e2;
        end
        if (c_nv3 & (c_p2 + 32'h1 == idx_act$14)) begin
            act_e$14$d = c_e3;
        end
        if (c_v0 & (c_p0 == idx_act$15)) begin
            act_e$15$d = c_e0;
        end
        if (c_nv1 & (c_p0 + 32'h1 == idx_act$15)) begin
            act_e$15$d = c_e1;
        end
        if (c_v1 & (c_p2 == idx_act$15)) begin
            act_e$15$d = c_e2;
        end
        if (c_nv3 & (c_p2 + 32'h1 == idx_act$15)) begin
            act_e$15$d = c_e3;
        end
        if (c_v0 & (c_p0 == idx_act$16)) begin
            act_e$16$d = c_e0;
        end
        if (c_nv1 & (c_p0 + 32'h1 == idx_act$16)) begin
            act_e$16$d = c_e1;
        end
        if (c_v1 & (c_p2 == idx_act$16)) begin
            act_e$16$d = c_e2;
        end
        if (c_nv3 & (c_p2 + 32'h1 == idx_act$16)) begin
            act_e$16$d = c_e3;
        end
        if (c_v0 & (c_p0 == idx_act$17)) begin
            act_e$17$d = c_e0;
        end
        if (c_nv1 & (c_p0 + 32'h1 == idx_act$17)) begin
            act_e$17$d = c_e1;
        end
        if (c_v1 & (c_p2 == idx_act$17)) begin
            act_e$17$d = c_e2;
        end
        if (c_nv3 & (c_p2 + 32'h1 == idx_act$17)) begin
            act_e$17$d = c_e3;
        end
        if (c_v0 & (c_p0 == idx_act$18)) begin
            act_e$18$d = c_e0;
        end
        if (c_nv1 & (c_p0 + 32'h1 == idx_act$18)) begin
            act_e$18$d = c_e1;
        end
        if (c_v1 & (c_p2 == idx_act$18)) begin
            act_e$18$d = c_e2;
        end
        if (c_nv3 & (c_p2 + 32'h1 == idx_act$18)) begin
            act_e$18$d = c_e3;
        end
        if (c_v0 & (c_p0 == idx_act$19)) begin
            act_e$19$d = c_e0;
        end
        if (c_nv1 & (c_p0 + 32'h1 == idx_act$19)) begin
            act_e$19$d = c_e1;
        end
        if (c_v1 & (c_p2 == idx_act$19)) begin
            act_e$19$d = c_e2;
        end
        if (c_nv3 & (c_p2 + 32'h1 == idx_act$19)) begin
            act_e$19$d = c_e3;
        end
        if (c_v0 & (c_p0 == idx_act$20)) begin
            act_e$20$d = c_e0;
        end
        if (c_nv1 & (c_p0 + 32'h1 == idx_act$20)) begin
            act_e$20$d = c_e1;
        end
        if (c_v1 & (c_p2 == idx_act$20)) begin
            act_e$20$d = c_e2;
        end
        if (c_nv3 & (c_p2 + 32'h1 == idx_act$20)) begin
            act_e$20$d = c_e3;
        end
        if (c_v0 & (c_p0 == idx_act$21)) begin
            act_e$21$d = c_e0;
        end
        if (c_nv1 & (c_p0 + 32'h1 == idx_act$21)) begin
            act_e$21$d = c_e1;
        end
        if (c_v1 & (c_p2 == idx_act$21)) begin
            act_e$21$d = c_e2;
        end
        if (c_nv3 & (c_p2 + 32'h1 == idx_act$21)) begin
            act_e$21$d = c_e3;
        end
        if (c_v0 & (c_p0 == idx_act$22)) begin
            act_e$22$d = c_e0;
        end
        if (c_nv1 & (c_p0 + 32'h1 == idx_act$22)) begin
            act_e$22$d = c_e1;
        end
        if (c_v1 & (c_p2 == idx_act$22)) begin
            act_e$22$d = c_e2;
        end
        if (c_nv3 & (c_p2 + 32'h1 == idx_act$22)) begin
            act_e$22$d = c_e3;
        end
        if (c_v0 & (c_p0 == idx_act$23)) begin
            act_e$23$d = c_e0;
        end
        if (c_nv1 & (c_p0 + 32'h1 == idx_act$23)) begin
            act_e$23$d = c_e1;
        end
        if (c_v1 & (c_p2 == idx_act$23)) begin
            act_e$23$d = c_e2;
        end
        if (c_nv3 & (c_p2 + 32'h1 == idx_act$23)) begin
            act_e$23$d = c_e3;
        end
        if (c_v0 & (c_p0 == idx_act$24)) begin
            act_e$24$d = c_e0;
        end
        if (c_nv1 & (c_p0 + 32'h1 == idx_act$24)) begin
            act_e$24$d = c_e1;
        end
        if (c_v1 & (c_p2 == idx_act$24)) begin
            act_e$24$d = c_e2;
        end
        if (c_nv3 & (c_p2 + 32'h1 == idx_act$24)) begin
            act_e$24$d = c_e3;
        end
        if (c_v0 & (c_p0 == idx_act$25)) begin
            act_e$25$d = c_e0;
        end
        if (c_nv1 & (c_p0 + 32'h1 == idx_act$25)) begin
            act_e$25$d = c_e1;
        end
        if (c_v1 & (c_p2 == idx_act$25)) begin
            act_e$25$d = c_e2;
        end
        if (c_nv3 & (c_p2 + 32'h1 == idx_act$25)) begin
            act_e$25$d = c_e3;
        end
        if (c_v0 & (c_p0 == idx_act$26)) begin
            act_e$26$d = c_e0;
        end
        if (c_nv1 & (c_p0 + 32'h1 == idx_act$26)) begin
            act_e$26$d = c_e1;
        end
        if (c_v1 & (c_p2 == idx_act$26)) begin
            act_e$26$d = c_e2;
        end
        if (c_nv3 & (c_p2 + 32'h1 == idx_act$26)) begin
            act_e$26$d = c_e3;
        end
        if (c_v0 & (c_p0 == idx_act$27)) begin
            act_e$27$d = c_e0;
        end
        if (c_nv1 & (c_p0 + 32'h1 == idx_act$27)) begin
            act_e$27$d = c_e1;
        end
        if (c_v1 & (c_p2 == idx_act$27)) begin
            act_e$27$d = c_e2;
        end
        if (c_nv3 & (c_p2 + 32'h1 == idx_act$27)) begin
            act_e$27$d = c_e3;
        end
        if (c_v0 & (c_p0 == idx_act$28)) begin
            act_e$28$d = c_e0;
        end
        if (c_nv1 & (c_p0 + 32'h1 == idx_act$28)) begin
            act_e$28$d = c_e1;
        end
        if (c_v1 & (c_p2 == idx_act$28)) begin
            act_e$28$d = c_e2;
        end
        if (c_nv3 & (c_p2 + 32'h1 == idx_act$28)) begin
            act_e$28$d = c_e3;
        end
        if (c_v0 & (c_p0 == idx_act$29)) begin
            act_e$29$d = c_e0;
        end
        if (c_nv1 & (c_p0 + 32'h1 == idx_act$29)) begin
            act_e$29$d = c_e1;
        end
        if (c_v1 & (c_p2 == idx_act$29)) begin
            act_e$29$d = c_e2;
        end
        if (c_nv3 & (c_p2 + 32'h1 == idx_act$29)) begin
            act_e$29$d = c_e3;
        end
        if (c_v0 & (c_p0 == idx_act$30)) begin
            act_e$30$d = c_e0;
        end
        if (c_nv1 & (c_p0 + 32'h1 == idx_act$30)) begin
            act_e$30$d = c_e1;
        end
        if (c_v1 & (c_p2 == idx_act$30)) begin
            act_e$30$d = c_e2;
        end
        if (c_nv3 & (c_p2 + 32'h1 == idx_act$30)) begin
            act_e$30$d = c_e3;
        end
        if (c_v0 & (c_p0 == idx_act$31)) begin
            act_e$31$d = c_e0;
        end
        if (c_nv1 & (c_p0 + 32'h1 == idx_act$31)) begin
            act_e$31$d = c_e1;
        end
        if (c_v1 & (c_p2 == idx_act$31)) begin
            act_e$31$d = c_e2;
        end
        if (c_nv3 & (c_p2 + 32'h1 == idx_act$31)) begin
            act_e$31$d = c_e3;
        end
        if (c_v0 & (c_p0 == idx_act$32)) begin
            act_e$32$d = c_e0;
        end
        if (c_nv1 & (c_p0 + 32'h1 == idx_act$32)) begin
            act_e$32$d = c_e1;
        end
        if (c_v1 & (c_p2 == idx_act$32)) begin
            act_e$32$d = c_e2;
        end
        if (c_nv3 & (c_p2 + 32'h1 == idx_act$32)) begin
            act_e$32$d = c_e3;
        end
        if (c_v0 & (c_p0 == idx_act$33)) begin
            act_e$33$d = c_e0;
        end
        if (c_nv1 & (c_p0 + 32'h1 == idx_act$33)) begin
            act_e$33$d = c_e1;
        end
        if (c_v1 & (c_p2 == idx_act$33)) begin
            act_e$33$d = c_e2;
        end
        if (c_nv3 & (c_p2 + 32'h1 == idx_act$33)) begin
            act_e$33$d = c_e3;
        end
        if (c_v0 & (c_p0 == idx_act$34)) begin
            act_e$34$d = c_e0;
        end
        if (c_nv1 & (c_p0 + 32'h1 == idx_act$34)) begin
            act_e$34$d = c_e1;
        end
        if (c_v1 & (c_p2 == idx_act$34)) begin
            act_e$34$d = c_e2;
        end
        if (c_nv3 & (c_p2 + 32'h1 == idx_act$34)) begin
            act_e$34$d = c_e3;
        end
        grp$0$clock = clock;
        grp$0$d = grp$0$q;
        if (c_flag & (level == idx_lvl$0)) begin
            grp$0$d = c_gw;
        end
        grp$1$clock = clock;
        grp$1$d = grp$1$q;
        if (c_flag & (level == idx_lvl$1)) begin
            grp$1$d = c_gw;
        end
        grp$2$clock = clock;
        grp$2$d = grp$2$q;
        if (c_flag & (level == idx_lvl$2)) begin
            grp$2$d = c_gw;
        end
        grp$3$clock = clock;
        grp$3$d = grp$3$q;
        if (c_flag & (level == idx_lvl$3)) begin
            grp$3$d = c_gw;
        end
        grp$4$clock = clock;
        grp$4$d = grp$4$q;
        if (c_flag & (level == idx_lvl$4)) begin
            grp$4$d = c_gw;
        end
        grp$5$clock = clock;
        grp$5$d = grp$5$q;
        if (c_flag & (level == idx_lvl$5)) begin
            grp$5$d = c_gw;
        end
        grp$6$clock = clock;
        grp$6$d = grp$6$q;
        if (c_flag & (level == idx_lvl$6)) begin
            grp$6$d = c_gw;
        end
        grp$7$clock = clock;
        grp$7$d = grp$7$q;
        if (c_flag & (level == idx_lvl$7)) begin
            grp$7$d = c_gw;
        end
        grp$8$clock = clock;
        grp$8$d = grp$8$q;
        if (c_flag & (level == idx_lvl$8)) begin
            grp$8$d = c_gw;
        end
        grp$9$clock = clock;
        grp$9$d = grp$9$q;
        if (c_flag & (level == idx_lvl$9)) begin
            grp$9$d = c_gw;
        end
        grp$10$clock = clock;
        grp$10$d = grp$10$q;
        if (c_flag & (level == idx_lvl$10)) begin
            grp$10$d = c_gw;
        end
        grp$11$clock = clock;
        grp$11$d = grp$11$q;
        if (c_flag & (level == idx_lvl$11)) begin
            grp$11$d = c_gw;
        end
        grp$12$clock = clock;
        grp$12$d = grp$12$q;
        if (c_flag & (level == idx_lvl$12)) begin
            grp$12$d = c_gw;
        end
        grp$13$clock = clock;
        grp$13$d = grp$13$q;
        if (c_flag & (level == idx_lvl$13)) begin
            grp$13$d = c_gw;
        end
        grp$14$clock = clock;
        grp$14$d = grp$14$q;
        if (c_flag & (level == idx_lvl$14)) begin
            grp$14$d = c_gw;
        end
        grp$15$clock = clock;
        grp$15$d = grp$15$q;
        if (c_flag & (level == idx_lvl$15)) begin
            grp$15$d = c_gw;
        end
        grp$16$clock = clock;
        grp$16$d = grp$16$q;
        if (c_flag & (level == idx_lvl$16)) begin
            grp$16$d = c_gw;
        end
        grp$17$clock = clock;
        grp$17$d = grp$17$q;
        if (c_flag & (level == idx_lvl$17)) begin
            grp$17$d = c_gw;
        end
        grp$18$clock = clock;
        grp$18$d = grp$18$q;
        if (c_flag & (level == idx_lvl$18)) begin
            grp$18$d = c_gw;
        end
        grp$19$clock = clock;
        grp$19$d = grp$19$q;
        if (c_flag & (level == idx_lvl$19)) begin
            grp$19$d = c_gw;
        end
        grp$20$clock = clock;
        grp$20$d = grp$20$q;
        if (c_flag & (level == idx_lvl$20)) begin
            grp$20$d = c_gw;
        end
        grp$21$clock = clock;
        grp$21$d = grp$21$q;
        if (c_flag & (level == idx_lvl$21)) begin
            grp$21$d = c_gw;
        end
        grp$22$clock = clock;
        grp$22$d = grp$22$q;
        if (c_flag & (level == idx_lvl$22)) begin
            grp$22$d = c_gw;
        end
        grp$23$clock = clock;
        grp$23$d = grp$23$q;
        if (c_flag & (level == idx_lvl$23)) begin
            grp$23$d = c_gw;
        end
        grp$24$clock = clock;
        grp$24$d = grp$24$q;
        if (c_flag & (level == idx_lvl$24)) begin
            grp$24$d = c_gw;
        end
        grp$25$clock = clock;
        grp$25$d = grp$25$q;
        if (c_flag & (level == idx_lvl$25)) begin
            grp$25$d = c_gw;
        end
        grp$26$clock = clock;
        grp$26$d = grp$26$q;
        if (c_flag & (level == idx_lvl$26)) begin
            grp$26$d = c_gw;
        end
        grp$27$clock = clock;
        grp$27$d = grp$27$q;
        if (c_flag & (level == idx_lvl$27)) begin
            grp$27$d = c_gw;
        end
        grp$28$clock = clock;
        grp$28$d = grp$28$q;
        if (c_flag & (level == idx_lvl$28)) begin
            grp$28$d = c_gw;
        end
        grp$29$clock = clock;
        grp$29$d = grp$29$q;
        if (c_flag & (level == idx_lvl$29)) begin
            grp$29$d = c_gw;
        end
        grp$30$clock = clock;
        grp$30$d = grp$30$q;
        if (c_flag & (level == idx_lvl$30)) begin
            grp$30$d = c_gw;
        end
        grp$31$clock = clock;
        grp$31$d = grp$31$q;
        if (c_flag & (level == idx_lvl$31)) begin
            grp$31$d = c_gw;
        end
        if (c_flag) begin
            n_tests$d = n_tests$q + ((c_lc[(32'h0)+:(1)]) & 32'hffffffff) + ((c_lc[(32'h1)+:(1)]) & 32'hffffffff);
        end
        inflight$d = inflight$q + ((read) & 4'hf) - ((c_flag) & 4'hf);
        cmp_n$d = c_pm + ((a_valid) & 2'h3);
        cmp_e$0$clock = clock;
        cmp_e$0$d = cmp_e$0$q;
        cmp_e$1$clock = clock;
        cmp_e$1$d = cmp_e$1$q;
        cmp_e$2$clock = clock;
        cmp_e$2$d = cmp_e$2$q;
        if (flags_valid) begin
            cmp_e$0$d = cmp_e$1$q;
        end
        if (flags_valid) begin
            cmp_e$1$d = cmp_e$2$q;
        end
        if (a_valid & (c_pm == idx_cmp$0)) begin
            cmp_e$0$d = ((al_valid) & 82'h3ffffffffffffffffffff) | (((al_id) & 82'h3ffffffffffffffffffff) << 32'h1) | (((al_leaf) & 82'h3ffffffffffffffffffff) << 32'h11) | (((al_f0) & 82'h3ffffffffffffffffffff) << 32'h12) | (((al_f1) & 82'h3ffffffffffffffffffff) << 32'h32);
        end
        if (a_valid & (c_pm == idx_cmp$1)) begin
            cmp_e$1$d = ((al_valid) & 82'h3ffffffffffffffffffff) | (((al_id) & 82'h3ffffffffffffffffffff) << 32'h1) | (((al_leaf) & 82'h3ffffffffffffffffffff) << 32'h11) | (((al_f0) & 82'h3ffffffffffffffffffff) << 32'h12) | (((al_f1) & 82'h3ffffffffffffffffffff) << 32'h32);
        end
        if (a_valid & (c_pm == idx_cmp$2)) begin
            cmp_e$2$d = ((al_valid) & 82'h3ffffffffffffffffffff) | (((al_id) & 82'h3ffffffffffffffffffff) << 32'h1) | (((al_leaf) & 82'h3ffffffffffffffffffff) << 32'h11) | (((al_f0) & 82'h3ffffffffffffffffffff) << 32'h12) | (((al_f1) & 82'h3ffffffffffffffffffff) << 32'h32);
        end
        hold$0$clock = clock;
        ldd$0$clock = clock;
        hold$0$d = hold$0$q;
        ldd$0$d = ldd$0$q;
        hold$1$clock = clock;
        ldd$1$clock = clock;
        hold$1$d = hold$1$q;
        ldd$1$d = ldd$1$q;
        if (push_load & ~push_set) begin
            hold$0$d = c_hold_w;
        end
        if (push_load & push_set) begin
            hold$1$d = c_hold_w;
        end
        if (ld_valid & ~ld_set) begin
            ldd$0$d = c_ldd_w;
        end
        if (ld_valid & ld_set) begin
            ldd$1$d = c_ldd_w;
        end
        if (c_enter) begin
            entered$d = 1'b1;
            spec$d = 1'b1;
            cur$d = c_enter_set;
            n_lists$d = n_lists$q + 32'h1;
        end
        if (c_spec_done) begin
            spec$d = 1'b0;
        end
        if (next_list) begin
            entered$d = 1'b0;
        end
        if (clear) begin
            act_n$d = 32'h1;
            act_e$0$d = 32'h0;
            entered$d = 1'b1;
            spec$d = 1'b0;
            cur$d = 1'b0;
            hold$0$d = 32'h0;
            hold$1$d = 32'h0;
            ldd$0$d = 32'h0;
            ldd$1$d = 32'h0;
            inflight$d = 32'h0;
            cmp_n$d = 32'h0;
            n_lists$d = 32'h0;
            n_tests$d = 32'h0;
        end
    end
    
endmodule // top


module top$act_e$0(d,q,clock);
    
    // Module arguments
    input wire  [65:0] d;
    output reg  [65:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 66'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$act_e$0


module top$act_n(d,q,clock);
    
    // Module arguments
    input wire  [5:0] d;
    output reg  [5:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 6'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$act_n


module top$cmp_e$0(d,q,clock);
    
    // Module arguments
    input wire  [81:0] d;
    output reg  [81:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 82'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cmp_e$0


module top$cmp_n(d,q,clock);
    
    // Module arguments
    input wire  [1:0] d;
    output reg  [1:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 2'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cmp_n


module top$cur(d,q,clock);
    
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
          
endmodule // top$cur


module top$grp$0(d,q,clock);
    
    // Module arguments
    input wire  [33:0] d;
    output reg  [33:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 34'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$grp$0


module top$hold$0(d,q,clock);
    
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
          
endmodule // top$hold$0


module top$inflight(d,q,clock);
    
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
          
endmodule // top$inflight


module top$ldd$0(d,q,clock);
    
    // Module arguments
    input wire  [147:0] d;
    output reg  [147:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 148'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$ldd$0


module top$n_lists(d,q,clock);
    
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
          
endmodule // top$n_lists
