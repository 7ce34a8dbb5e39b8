

module top(clock,load_en,load_addr,load_data,t_valid,t_set,t_side,t_entry,t_last,t_data,a_valid,a_first,a_lanes,a_set,a_entry,e,busy,overlap_l,overlap_r,flags_valid);
    
    // Module arguments
    input wire  clock;
    input wire  load_en;
    input wire  [7:0] load_addr;
    input wire  [31:0] load_data;
    input wire  t_valid;
    input wire  t_set;
    input wire  t_side;
    input wire  [1:0] t_entry;
    input wire  t_last;
    input wire  [255:0] t_data;
    input wire  a_valid;
    input wire  a_first;
    input wire  [7:0] a_lanes;
    input wire  a_set;
    input wire  [1:0] a_entry;
    input wire  [255:0] e;
    output reg  [1:0] busy;
    output reg  overlap_l;
    output reg  overlap_r;
    output reg  flags_valid;
    
    // Constant declarations
    localparam  mmm_field$0 = 3'b0;
    localparam  mmm_field$1 = 3'b1;
    localparam  mmm_field$2 = 3'b10;
    localparam  mmm_field$3 = 3'b11;
    localparam  mmm_field$4 = 3'b100;
    localparam  entry_of$0 = 2'b0;
    localparam  entry_of$1 = 2'b0;
    localparam  entry_of$2 = 2'b0;
    localparam  entry_of$3 = 2'b0;
    localparam  entry_of$4 = 2'b0;
    localparam  entry_of$5 = 2'b0;
    localparam  entry_of$6 = 2'b0;
    localparam  entry_of$7 = 2'b0;
    localparam  entry_of$8 = 2'b1;
    localparam  entry_of$9 = 2'b1;
    localparam  entry_of$10 = 2'b1;
    localparam  entry_of$11 = 2'b1;
    localparam  entry_of$12 = 2'b1;
    localparam  entry_of$13 = 2'b1;
    localparam  entry_of$14 = 2'b1;
    localparam  entry_of$15 = 2'b1;
    localparam  entry_of$16 = 2'b10;
    localparam  entry_of$17 = 2'b10;
    localparam  entry_of$18 = 2'b10;
    localparam  entry_of$19 = 2'b10;
    localparam  entry_of$20 = 2'b10;
    localparam  entry_of$21 = 2'b10;
    localparam  entry_of$22 = 2'b10;
    localparam  entry_of$23 = 2'b10;
    localparam  last_row = 5'b10111;
    
    // Stub signals
    reg  [4:0] mmm$0$read_address;
    reg  mmm$0$read_clock;
    wire  [31:0] mmm$0$read_data;
    reg  [4:0] mmm$0$write_address;
    reg  mmm$0$write_clock;
    reg  [31:0] mmm$0$write_data;
    reg  mmm$0$write_enable;
    reg  [4:0] mmm$1$read_address;
    reg  mmm$1$read_clock;
    wire  [31:0] mmm$1$read_data;
    reg  [4:0] mmm$1$write_address;
    reg  mmm$1$write_clock;
    reg  [31:0] mmm$1$write_data;
    reg  mmm$1$write_enable;
    reg  [4:0] mmm$2$read_address;
    reg  mmm$2$read_clock;
    wire  [31:0] mmm$2$read_data;
    reg  [4:0] mmm$2$write_address;
    reg  mmm$2$write_clock;
    reg  [31:0] mmm$2$write_data;
    reg  mmm$2$write_enable;
    reg  [4:0] mmm$3$read_address;
    reg  mmm$3$read_clock;
    wire  [31:0] mmm$3$read_data;
    reg  [4:0] mmm$3$write_address;
    reg  mmm$3$write_clock;
    reg  [31:0] mmm$3$write_data;
    reg  mmm$3$write_enable;
    reg  [4:0] mmm$4$read_address;
    reg  mmm$4$read_clock;
    wire  [31:0] mmm$4$read_data;
    reg  [4:0] mmm$4$write_address;
    reg  mmm$4$write_clock;
    reg  [31:0] mmm$4$write_data;
    reg  mmm$4$write_enable;
    reg  [31:0] tin_l0$0$d;
    wire  [31:0] tin_l0$0$q;
    reg  tin_l0$0$clock;
    reg  [31:0] tin_l0$1$d;
    wire  [31:0] tin_l0$1$q;
    reg  tin_l0$1$clock;
    reg  [31:0] tin_l0$2$d;
    wire  [31:0] tin_l0$2$q;
    reg  tin_l0$2$clock;
    reg  [31:0] tin_l0$3$d;
    wire  [31:0] tin_l0$3$q;
    reg  tin_l0$3$clock;
    reg  [31:0] tin_l0$4$d;
    wire  [31:0] tin_l0$4$q;
    reg  tin_l0$4$clock;
    reg  [31:0] tin_l0$5$d;
    wire  [31:0] tin_l0$5$q;
    reg  tin_l0$5$clock;
    reg  [31:0] tin_l0$6$d;
    wire  [31:0] tin_l0$6$q;
    reg  tin_l0$6$clock;
    reg  [31:0] tin_l0$7$d;
    wire  [31:0] tin_l0$7$q;
    reg  tin_l0$7$clock;
    reg  [31:0] tin_l0$8$d;
    wire  [31:0] tin_l0$8$q;
    reg  tin_l0$8$clock;
    reg  [31:0] tin_l0$9$d;
    wire  [31:0] tin_l0$9$q;
    reg  tin_l0$9$clock;
    reg  [31:0] tin_l0$10$d;
    wire  [31:0] tin_l0$10$q;
    reg  tin_l0$10$clock;
    reg  [31:0] tin_l0$11$d;
    wire  [31:0] tin_l0$11$q;
    reg  tin_l0$11$clock;
    reg  [31:0] tin_l0$12$d;
    wire  [31:0] tin_l0$12$q;
    reg  tin_l0$12$clock;
    reg  [31:0] tin_l0$13$d;
    wire  [31:0] tin_l0$13$q;
    reg  tin_l0$13$clock;
    reg  [31:0] tin_l0$14$d;
    wire  [31:0] tin_l0$14$q;
    reg  tin_l0$14$clock;
    reg  [31:0] tin_l0$15$d;
    wire  [31:0] tin_l0$15$q;
    reg  tin_l0$15$clock;
    reg  [31:0] tin_l0$16$d;
    wire  [31:0] tin_l0$16$q;
    reg  tin_l0$16$clock;
    reg  [31:0] tin_l0$17$d;
    wire  [31:0] tin_l0$17$q;
    reg  tin_l0$17$clock;
    reg  [31:0] tin_l0$18$d;
    wire  [31:0] tin_l0$18$q;
    reg  tin_l0$18$clock;
    reg  [31:0] tin_l0$19$d;
    wire  [31:0] tin_l0$19$q;
    reg  tin_l0$19$clock;
    reg  [31:0] tin_l0$20$d;
    wire  [31:0] tin_l0$20$q;
    reg  tin_l0$20$clock;
    reg  [31:0] tin_l0$21$d;
    wire  [31:0] tin_l0$21$q;
    reg  tin_l0$21$clock;
    reg  [31:0] tin_l0$22$d;
    wire  [31:0] tin_l0$22$q;
    reg  tin_l0$22$clock;
    reg  [31:0] tin_l0$23$d;
    wire  [31:0] tin_l0$23$q;
    reg  tin_l0$23$clock;
    reg  [31:0] tin_r0$0$d;
    wire  [31:0] tin_r0$0$q;
    reg  tin_r0$0$clock;
    reg  [31:0] tin_r0$1$d;
    wire  [31:0] tin_r0$1$q;
    reg  tin_r0$1$clock;
    reg  [31:0] tin_r0$2$d;
    wire  [31:0] tin_r0$2$q;
    reg  tin_r0$2$clock;
    reg  [31:0] tin_r0$3$d;
    wire  [31:0] tin_r0$3$q;
    reg  tin_r0$3$clock;
    reg  [31:0] tin_r0$4$d;
    wire  [31:0] tin_r0$4$q;
    reg  tin_r0$4$clock;
    reg  [31:0] tin_r0$5$d;
    wire  [31:0] tin_r0$5$q;
    reg  tin_r0$5$clock;
    reg  [31:0] tin_r0$6$d;
    wire  [31:0] tin_r0$6$q;
    reg  tin_r0$6$clock;
    reg  [31:0] tin_r0$7$d;
    wire  [31:0] tin_r0$7$q;
    reg  tin_r0$7$clock;
    reg  [31:0] tin_r0$8$d;
    wire  [31:0] tin_r0$8$q;
    reg  tin_r0$8$clock;
    reg  [31:0] tin_r0$9$d;
    wire  [31:0] tin_r0$9$q;
    reg  tin_r0$9$clock;
    reg  [31:0] tin_r0$10$d;
    wire  [31:0] tin_r0$10$q;
    reg  tin_r0$10$clock;
    reg  [31:0] tin_r0$11$d;
    wire  [31:0] tin_r0$11$q;
    reg  tin_r0$11$clock;
    reg  [31:0] tin_r0$12$d;
    wire  [31:0] tin_r0$12$q;
    reg  tin_r0$12$clock;
    reg  [31:0] tin_r0$13$d;
    wire  [31:0] tin_r0$13$q;
    reg  tin_r0$13$clock;
    reg  [31:0] tin_r0$14$d;
    wire  [31:0] tin_r0$14$q;
    reg  tin_r0$14$clock;
    reg  [31:0] tin_r0$15$d;
    wire  [31:0] tin_r0$15$q;
    reg  tin_r0$15$clock;
    reg  [31:0] tin_r0$16$d;
    wire  [31:0] tin_r0$16$q;
    reg  tin_r0$16$clock;
    reg  [31:0] tin_r0$17$d;
    wire  [31:0] tin_r0$17$q;
    reg  tin_r0$17$clock;
    reg  [31:0] tin_r0$18$d;
    wire  [31:0] tin_r0$18$q;
    reg  tin_r0$18$clock;
    reg  [31:0] tin_r0$19$d;
    wire  [31:0] tin_r0$19$q;
    reg  tin_r0$19$clock;
    reg  [31:0] tin_r0$20$d;
    wire  [31:0] tin_r0$20$q;
    reg  tin_r0$20$clock;
    reg  [31:0] tin_r0$21$d;
    wire  [31:0] tin_r0$21$q;
    reg  tin_r0$21$clock;
    reg  [31:0] tin_r0$22$d;
    wire  [31:0] tin_r0$22$q;
    reg  tin_r0$22$clock;
    reg  [31:0] tin_r0$23$d;
    wire  [31:0] tin_r0$23$q;
    reg  tin_r0$23$clock;
    reg  [31:0] tin_l1$0$d;
    wire  [31:0] tin_l1$0$q;
    reg  tin_l1$0$clock;
    reg  [31:0] tin_l1$1$d;
    wire  [31:0] tin_l1$1$q;
    reg  tin_l1$1$clock;
    reg  [31:0] tin_l1$2$d;
    wire  [31:0] tin_l1$2$q;
    reg  tin_l1$2$clock;
    reg  [31:0] tin_l1$3$d;
    wire  [31:0] tin_l1$3$q;
    reg  tin_l1$3$clock;
    reg  [31:0] tin_l1$4$d;
    wire  [31:0] tin_l1$4$q;
    reg  tin_l1$4$clock;
    reg  [31:0] tin_l1$5$d;
    wire  [31:0] tin_l1$5$q;
    reg  tin_l1$5$clock;
    reg  [31:0] tin_l1$6$d;
    wire  [31:0] tin_l1$6$q;
    reg  tin_l1$6$clock;
    reg  [31:0] tin_l1$7$d;
    wire  [31:0] tin_l1$7$q;
    reg  tin_l1$7$clock;
    reg  [31:0] tin_l1$8$d;
    wire  [31:0] tin_l1$8$q;
    reg  tin_l1$8$clock;
    reg  [31:0] tin_l1$9$d;
    wire  [31:0] tin_l1$9$q;
    reg  tin_l1$9$clock;
    reg  [31:0] tin_l1$10$d;
    wire  [31:0] tin_l1$10$q;
    reg  tin_l1$10$clock;
    reg  [31:0] tin_l1$11$d;
    wire  [31:0] tin_l1$11$q;
    reg  tin_l1$11$clock;
    reg  [31:0] tin_l1$12$d;
    wire  [31:0] tin_l1$12$q;
    reg  tin_l1$12$clock;
    reg  [31:0] tin_l1$13$d;
    wire  [31:0] tin_l1$13$q;
    reg  tin_l1$13$clock;
    reg  [31:0] tin_l1$14$d;
    wire  [31:0] tin_l1$14$q;
    reg  tin_l1$14$clock;
    reg  [31:0] tin_l1$15$d;
    wire  [31:0] tin_l1$15$q;
    reg  tin_l1$15$clock;
    reg  [31:0] tin_l1$16$d;
    wire  [31:0] tin_l1$16$q;
    reg  tin_l1$16$clock;
    reg  [31:0] tin_l1$17$d;
    wire  [31:0] tin_l1$17$q;
    reg  tin_l1$17$clock;
    reg  [31:0] tin_l1$18$d;
    wire  [31:0] tin_l1$18$q;
    reg  tin_l1$18$clock;
    reg  [31:0] tin_l1$19$d;
    wire  [31:0] tin_l1$19$q;
    reg  tin_l1$19$clock;
    reg  [31:0] tin_l1$20$d;
    wire  [31:0] tin_l1$20$q;
    reg  tin_l1$20$clock;
    reg  [31:0] tin_l1$21$d;
    wire  [31:0] tin_l1$21$q;
    reg  tin_l1$21$clock;
    reg  [31:0] tin_l1$22$d;
    wire  [31:0] tin_l1$22$q;
    reg  tin_l1$22$clock;
    reg  [31:0] tin_l1$23$d;
    wire  [31:0] tin_l1$23$q;
    reg  tin_l1$23$clock;
    reg  [31:0] tin_r1$0$d;
    wire  [31:0] tin_r1$0$q;
    reg  tin_r1$0$clock;
    reg  [31:0] tin_r1$1$d;
    wire  [31:0] tin_r1$1$q;
    reg  tin_r1$1$clock;
    reg  [31:0] tin_r1$2$d;
    wire  [31:0] tin_r1$2$q;
    reg  tin_r1$2$clock;
    reg  [31:0] tin_r1$3$d;
    wire  [31:0] tin_r1$3$q;
    reg  tin_r1$3$clock;
    reg  [31:0] tin_r1$4$d;
    wire  [31:0] tin_r1$4$q;
    reg  tin_r1$4$clock;
    reg  [31:0] tin_r1$5$d;
    wire  [31:0] tin_r1$5$q;
    reg  tin_r1$5$clock;
    reg  [31:0] tin_r1$6$d;
    wire  [31:0] tin_r1$6$q;
    reg  tin_r1$6$clock;
    reg  [31:0] tin_r1$7$d;
    wire  [31:0] tin_r1$7$q;
    reg  tin_r1$7$clock;
    reg  [31:0] tin_r1$8$d;
    wire  [31:0] tin_r1$8$q;
    reg  tin_r1$8$clock;
    reg  [31:0] tin_r1$9$d;
    wire  [31:0] tin_r1$9$q;
    reg  tin_r1$9$clock;
    reg  [31:0] tin_r1$10$d;
    wire  [31:0] tin_r1$10$q;
    reg  tin_r1$10$clock;
    reg  [31:0] tin_r1$11$d;
    wire  [31:0] tin_r1$11$q;
    reg  tin_r1$11$clock;
    reg  [31:0] tin_r1$12$d;
    wire  [31:0] tin_r1$12$q;
    reg  tin_r1$12$clock;
    reg  [31:0] tin_r1$13$d;
    wire  [31:0] tin_r1$13$q;
    reg  tin_r1$13$clock;
    reg  [31:0] tin_r1$14$d;
    wire  [31:0] tin_r1$14$q;
    reg  tin_r1$14$clock;
    reg  [31:0] tin_r1$15$d;
    wire  [31:0] tin_r1$15$q;
    reg  tin_r1$15$clock;
    reg  [31:0] tin_r1$16$d;
    wire  [31:0] tin_r1$16$q;
    reg  tin_r1$16$clock;
    reg  [31:0] tin_r1$17$d;
    wire  [31:0] tin_r1$17$q;
    reg  tin_r1$17$clock;
    reg  [31:0] tin_r1$18$d;
    wire  [31:0] tin_r1$18$q;
    reg  tin_r1$18$clock;
    reg  [31:0] tin_r1$19$d;
    wire  [31:0] tin_r1$19$q;
    reg  tin_r1$19$clock;
    reg  [31:0] tin_r1$20$d;
    wire  [31:0] tin_r1$20$q;
    reg  tin_r1$20$clock;
    reg  [31:0] tin_r1$21$d;
    wire  [31:0] tin_r1$21$q;
    reg  tin_r1$21$clock;
    reg  [31:0] tin_r1$22$d;
    wire  [31:0] tin_r1$22$q;
    reg  tin_r1$22$clock;
    reg  [31:0] tin_r1$23$d;
    wire  [31:0] tin_r1$23$q;
    reg  tin_r1$23$clock;
    reg  gen_run$d;
    wire  gen_run$q;
    reg  gen_run$clock;
    reg  [4:0] gen_cnt$d;
    wire  [4:0] gen_cnt$q;
    reg  gen_cnt$clock;
    reg  gen_set$d;
    wire  gen_set$q;
    reg  gen_set$clock;
    reg  [1:0] pend$d;
    wire  [1:0] pend$q;
    reg  pend$clock;
    reg  [1:0] busy_r$d;
    wire  [1:0] busy_r$q;
    reg  busy_r$clock;
    reg  s1_valid$d;
    wire  s1_valid$q;
    reg  s1_valid$clock;
    reg  s1_set$d;
    wire  s1_set$q;
    reg  s1_set$clock;
    reg  [4:0] s1_lane$d;
    wire  [4:0] s1_lane$q;
    reg  s1_lane$clock;
    reg  s1_last$d;
    wire  s1_last$q;
    reg  s1_last$clock;
    reg  [31:0] klm_l$d$0;
    reg  [31:0] klm_l$d$1;
    reg  [31:0] klm_l$d$2;
    reg  [31:0] klm_l$d$3;
    reg  [31:0] klm_l$d$4;
    reg  [31:0] klm_l$d$5;
    reg  [31:0] klm_l$d$6;
    reg  [31:0] klm_l$d$7;
    reg  [31:0] klm_l$d$8;
    reg  [31:0] klm_l$d$9;
    reg  [31:0] klm_l$d$10;
    reg  [31:0] klm_l$d$11;
    reg  [31:0] klm_l$d$12;
    reg  [31:0] klm_l$d$13;
    reg  [31:0] klm_l$d$14;
    reg  [31:0] klm_l$d$15;
    reg  [31:0] klm_l$d$16;
    reg  [31:0] klm_l$d$17;
    reg  [31:0] klm_l$d$18;
    reg  [31:0] klm_l$d$19;
    reg  [31:0] klm_l$d$20;
    reg  [31:0] klm_l$d$21;
    reg  [31:0] klm_l$d$22;
    reg  [31:0] klm_l$d$23;
    reg  [4:0] klm_l$j0$0;
    reg  [4:0] klm_l$j1$0;
    reg  [4:0] klm_l$j2$0;
    wire  [31:0] klm_l$y0$0;
    wire  [31:0] klm_l$y1$0;
    wire  [31:0] klm_l$y2$0;
    reg  [31:0] klm_r$d$0;
    reg  [31:0] klm_r$d$1;
    reg  [31:0] klm_r$d$2;
    reg  [31:0] klm_r$d$3;
    reg  [31:0] klm_r$d$4;
    reg  [31:0] klm_r$d$5;
    reg  [31:0] klm_r$d$6;
    reg  [31:0] klm_r$d$7;
    reg  [31:0] klm_r$d$8;
    reg  [31:0] klm_r$d$9;
    reg  [31:0] klm_r$d$10;
    reg  [31:0] klm_r$d$11;
    reg  [31:0] klm_r$d$12;
    reg  [31:0] klm_r$d$13;
    reg  [31:0] klm_r$d$14;
    reg  [31:0] klm_r$d$15;
    reg  [31:0] klm_r$d$16;
    reg  [31:0] klm_r$d$17;
    reg  [31:0] klm_r$d$18;
    reg  [31:0] klm_r$d$19;
    reg  [31:0] klm_r$d$20;
    reg  [31:0] klm_r$d$21;
    reg  [31:0] klm_r$d$22;
    reg  [31:0] klm_r$d$23;
    reg  [4:0] klm_r$j0$0;
    reg  [4:0] klm_r$j1$0;
    reg  [4:0] klm_r$j2$0;
    wire  [31:0] klm_r$y0$0;
    wire  [31:0] klm_r$y1$0;
    wire  [31:0] klm_r$y2$0;
    reg  dot_l$clock;
    reg  [31:0] dot_l$d0;
    reg  [31:0] dot_l$d1;
    reg  [31:0] dot_l$d2;
    reg  [31:0] dot_l$c0;
    reg  [31:0] dot_l$c1;
    reg  [31:0] dot_l$c2;
    reg  [31:0] dot_l$c;
    reg  dot_l$valid_in;
    reg  dot_l$round_up;
    wire  [31:0] dot_l$u;
    wire  dot_l$valid_out;
    reg  dot_r$clock;
    reg  [31:0] dot_r$d0;
    reg  [31:0] dot_r$d1;
    reg  [31:0] dot_r$d2;
    reg  [31:0] dot_r$c0;
    reg  [31:0] dot_r$c1;
    reg  [31:0] dot_r$c2;
    reg  [31:0] dot_r$c;
    reg  dot_r$valid_in;
    reg  dot_r$round_up;
    wire  [31:0] dot_r$u;
    wire  dot_r$valid_out;
    reg  wr_tag$clock;
    reg  [6:0] wr_tag$d;
    wire  [6:0] wr_tag$q;
    reg  dprime$clock;
    reg  dprime$wr_valid;
    reg  dprime$wr_set;
    reg  [4:0] dprime$wr_lane;
    reg  [31:0] dprime$wr_l;
    reg  [31:0] dprime$wr_r;
    reg  dprime$rd_set;
    reg  [1:0] dprime$rd_entry;
    wire  [255:0] dprime$dl;
    wire  [255:0] dprime$dr;
    reg  sa_valid$d;
    wire  sa_valid$q;
    reg  sa_valid$clock;
    reg  sa_first$d;
    wire  sa_first$q;
    reg  sa_first$clock;
    reg  [7:0] sa_lanes$d;
    wire  [7:0] sa_lanes$q;
    reg  sa_lanes$clock;
    reg  [255:0] sa_e$d;
    wire  [255:0] sa_e$q;
    reg  sa_e$clock;
    reg  bank$clock;
    reg  bank$valid_in;
    reg  bank$first;
    reg  [7:0] bank$lanes;
    reg  [255:0] bank$e;
    reg  [255:0] bank$dl;
    reg  [255:0] bank$dr;
    wire  bank$overlap_l;
    wire  bank$overlap_r;
    wire  bank$valid_out;
    
    // Local signals
    reg  [4:0] c_row;
    reg  [2:0] c_field;
    reg  [31:0] c_slot$0;
    reg  [31:0] c_slot$1;
    reg  [31:0] c_slot$2;
    reg  [31:0] c_slot$3;
    reg  [31:0] c_slot$4;
    reg  [31:0] c_slot$5;
    reg  [31:0] c_slot$6;
    reg  [31:0] c_slot$7;
    reg  c_row_last;
    reg  c_go;
    reg  c_go_set;
    reg  [1:0] c_t_set;
    reg  [1:0] c_go_mask;
    reg  [1:0] c_pend_set;
    reg  [1:0] c_busy_set;
    reg  [1:0] c_busy_clr;
    reg  [31:0] c_ctl;
    reg  c_wr_set;
    
    // Sub module instances
    top$mmm$0 mmm$0(
        .read_address(mmm$0$read_address),
        .read_clock(mmm$0$read_clock),
        .read_data(mmm$0$read_data),
        .write_address(mmm$0$write_address),
        .write_clock(mmm$0$write_clock),
        .write_data(mmm$0$write_data),
        .write_enable(mmm$0$write_enable)
    );
    top$mmm$0 mmm$1(
        .read_address(mmm$1$read_address),
        .read_clock(mmm$1$read_clock),
        .read_data(mmm$1$read_data),
        .write_address(mmm$1$write_address),
        .write_clock(mmm$1$write_clock),
        .write_data(mmm$1$write_data),
        .write_enable(mmm$1$write_enable)
    );
    top$mmm$0 mmm$2(
        .read_address(mmm$2$read_address),
        .read_clock(mmm$2$read_clock),
        .read_data(mmm$2$read_data),
        .write_address(mmm$2$write_address),
        .write_clock(mmm$2$write_clock),
        .write_data(mmm$2$write_data),
        .write_enable(mmm$2$write_enable)
    );
    top$mmm$0 mmm$3(
        .read_address(mmm$3$read_address),
        .read_clock(mmm$3$read_clock),
        .read_data(mmm$3$read_data),
        .write_address(mmm$3$write_address),
        .write_clock(mmm$3$write_clock),
        .write_data(mmm$3$write_data),
        .write_enable(mmm$3$write_enable)
    );
    top$mmm$0 mmm$4(
        .read_address(mmm$4$read_address),
        .read_clock(mmm$4$read_clock),
        .read_data(mmm$4$read_data),
        .write_address(mmm$4$write_address),
        .write_clock(mmm$4$write_clock),
        .write_data(mmm$4$write_data),
        .write_enable(mmm$4$write_enable)
    );
    top$dot_l$add_0$s3_y tin_l0$0(
        .d(tin_l0$0$d),
        .q(tin_l0$0$q),
        .clock(tin_l0$0$clock)
    );
    top$dot_l$add_0$s3_y tin_l0$1(
        .d(tin_l0$1$d),
        .q(tin_l0$1$q),
        .clock(tin_l0$1$clock)
    );
    top$dot_l$add_0$s3_y tin_l0$2(
        .d(tin_l0$2$d),
        .q(tin_l0$2$q),
        .clock(tin_l0$2$clock)
    );
    top$dot_l$add_0$s3_y tin_l0$3(
        .d(tin_l0$3$d),
        .q(tin_l0$3$q),
        .clock(tin_l0$3$clock)
    );
    top$dot_l$add_0$s3_y tin_l0$4(
        .d(tin_l0$4$d),
        .q(tin_l0$4$q),
        .clock(tin_l0$4$clock)
    );
    top$dot_l$add_0$s3_y tin_l0$5(
        .d(tin_l0$5$d),
        .q(tin_l0$5$q),
        .clock(tin_l0$5$clock)
    );
    top$dot_l$add_0$s3_y tin_l0$6(
        .d(tin_l0$6$d),
        .q(tin_l0$6$q),
        .clock(tin_l0$6$clock)
    );
    top$dot_l$add_0$s3_y tin_l0$7(
        .d(tin_l0$7$d),
        .q(tin_l0$7$q),
        .clock(tin_l0$7$clock)
    );
    top$dot_l$add_0$s3_y tin_l0$8(
        .d(tin_l0$8$d),
        .q(tin_l0$8$q),
        .clock(tin_l0$8$clock)
    );
    top$dot_l$add_0$s3_y tin_l0$9(
        .d(tin_l0$9$d),
        .q(tin_l0$9$q),
        .clock(tin_l0$9$clock)
    );
    top$dot_l$add_0$s3_y tin_l0$10(
        .d(tin_l0$10$d),
        .q(tin_l0$10$q),
        .clock(tin_l0$10$clock)
    );
    top$dot_l$add_0$s3_y tin_l0$11(
        .d(tin_l0$11$d),
        .q(tin_l0$11$q),
        .clock(tin_l0$11$clock)
    );
    top$dot_l$add_0$s3_y tin_l0$12(
        .d(tin_l0$12$d),
        .q(tin_l0$12$q),
        .clock(tin_l0$12$clock)
    );
    top$dot_l$add_0$s3_y tin_l0$13(
        .d(tin_l0$13$d),
        .q(tin_l0$13$q),
        .clock(tin_l0$13$clock)
    );
    top$dot_l$add_0$s3_y tin_l0$14(
        .d(tin_l0$14$d),
        .q(tin_l0$14$q),
        .clock(tin_l0$14$clock)
    );
    top$dot_l$add_0$s3_y tin_l0$15(
        .d(tin_l0$15$d),
        .q(tin_l0$15$q),
        .clock(tin_l0$15$clock)
    );
    top$dot_l$add_0$s3_y tin_l0$16(
        .d(tin_l0$16$d),
        .q(tin_l0$16$q),
        .clock(tin_l0$16$clock)
    );
    top$dot_l$add_0$s3_y tin_l0$17(
        .d(tin_l0$17$d),
        .q(tin_l0$17$q),
        .clock(tin_l0$17$clock)
    );
    top$dot_l$add_0$s3_y tin_l0$18(
        .d(tin_l0$18$d),
        .q(tin_l0$18$q),
        .clock(tin_l0$18$clock)
    );
    top$dot_l$add_0$s3_y tin_l0$19(
        .d(tin_l0$19$d),
        .q(tin_l0$19$q),
        .clock(tin_l0$19$clock)
    );
    top$dot_l$add_0$s3_y tin_l0$20(
        .d(tin_l0$20$d),
        .q(tin_l0$20$q),
        .clock(tin_l0$20$clock)
    );
    top$dot_l$add_0$s3_y tin_l0$21(
        .d(tin_l0$21$d),
        .q(tin_l0$21$q),
        .clock(tin_l0$21$clock)
    );
    top$dot_l$add_0$s3_y tin_l0$22(
        .d(tin_l0$22$d),
        .q(tin_l0$22$q),
        .clock(tin_l0$22$clock)
    );
    top$dot_l$add_0$s3_y tin_l0$23(
        .d(tin_l0$23$d),
        .q(tin_l0$23$q),
        .clock(tin_l0$23$clock)
    );
    top$dot_l$add_0$s3_y tin_r0$0(
        .d(tin_r0$0$d),
        .q(tin_r0$0$q),
        .clock(tin_r0$0$clock)
    );
    top$dot_l$add_0$s3_y tin_r0$1(
        .d(tin_r0$1$d),
        .q(tin_r0$1$q),
        .clock(tin_r0$1$clock)
    );
    top$dot_l$add_0$s3_y tin_r0$2(
        .d(tin_r0$2$d),
        .q(tin_r0$2$q),
        .clock(tin_r0$2$clock)
    );
    top$dot_l$add_0$s3_y tin_r0$3(
        .d(tin_r0$3$d),
        .q(tin_r0$3$q),
        .clock(tin_r0$3$clock)
    );
    top$dot_l$add_0$s3_y tin_r0$4(
        .d(tin_r0$4$d),
        .q(tin_r0$4$q),
        .clock(tin_r0$4$clock)
    );
    top$dot_l$add_0$s3_y tin_r0$5(
        .d(tin_r0$5$d),
        .q(tin_r0$5$q),
        .clock(tin_r0$5$clock)
    );
    top$dot_l$add_0$s3_y tin_r0$6(
        .d(tin_r0$6$d),
        .q(tin_r0$6$q),
        .clock(tin_r0$6$clock)
    );
    top$dot_l$add_0$s3_y tin_r0$7(
        .d(tin_r0$7$d),
        .q(tin_r0$7$q),
        .clock(tin_r0$7$clock)
    );
    top$dot_l$add_0$s3_y tin_r0$8(
        .d(tin_r0$8$d),
        .q(tin_r0$8$q),
        .clock(tin_r0$8$clock)
    );
    top$dot_l$add_0$s3_y tin_r0$9(
        .d(tin_r0$9$d),
        .q(tin_r0$9$q),
        .clock(tin_r0$9$clock)
    );
    top$dot_l$add_0$s3_y tin_r0$10(
        .d(tin_r0$10$d),
        .q(tin_r0$10$q),
        .clock(tin_r0$10$clock)
    );
    top$dot_l$add_0$s3_y tin_r0$11(
        .d(tin_r0$11$d),
        .q(tin_r0$11$q),
        .clock(tin_r0$11$clock)
    );
    top$dot_l$add_0$s3_y tin_r0$12(
        .d(tin_r0$12$d),
        .q(tin_r0$12$q),
        .clock(tin_r0$12$clock)
    );
    top$dot_l$add_0$s3_y tin_r0$13(
        .d(tin_r0$13$d),
        .q(tin_r0$13$q),
        .clock(tin_r0$13$clock)
    );
    top$dot_l$add_0$s3_y tin_r0$14(
        .d(tin_r0$14$d),
        .q(tin_r0$14$q),
        .clock(tin_r0$14$clock)
    );
    top$dot_l$add_0$s3_y tin_r0$15(
        .d(tin_r0$15$d),
        .q(tin_r0$15$q),
        .clock(tin_r0$15$clock)
    );
    top$dot_l$add_0$s3_y tin_r0$16(
        .d(tin_r0$16$d),
        .q(tin_r0$16$q),
        .clock(tin_r0$16$clock)
    );
    top$dot_l$add_0$s3_y tin_r0$17(
        .d(tin_r0$17$d),
        .q(tin_r0$17$q),
        .clock(tin_r0$17$clock)
    );
    top$dot_l$add_0$s3_y tin_r0$18(
        .d(tin_r0$18$d),
        .q(tin_r0$18$q),
        .clock(tin_r0$18$clock)
    );
    top$dot_l$add_0$s3_y tin_r0$19(
        .d(tin_r0$19$d),
        .q(tin_r0$19$q),
        .clock(tin_r0$19$clock)
    );
    top$dot_l$add_0$s3_y tin_r0$20(
        .d(tin_r0$20$d),
        .q(tin_r0$20$q),
        .clock(tin_r0$20$clock)
    );
    top$dot_l$add_0$s3_y tin_r0$21(
        .d(tin_r0$21$d),
        .q(tin_r0$21$q),
        .clock(tin_r0$21$clock)
    );
    top$dot_l$add_0$s3_y tin_r0$22(
        .d(tin_r0$22$d),
        .q(tin_r0$22$q),
        .clock(tin_r0$22$clock)
    );
    top$dot_l$add_0$s3_y tin_r0$23(
        .d(tin_r0$23$d),
        .q(tin_r0$23$q),
        .clock(tin_r0$23$clock)
    );
    top$dot_l$add_0$s3_y tin_l1$0(
        .d(tin_l1$0$d),
        .q(tin_l1$0$q),
        .clock(tin_l1$0$clock)
    );
    top$dot_l$add_0$s3_y tin_l1$1(
        .d(tin_l1$1$d),
        .q(tin_l1$1$q),
        .clock(tin_l1$1$clock)
    );
    top$dot_l$add_0$s3_y tin_l1$2(
        .d(tin_l1$2$d),
        .q(tin_l1$2$q),
        .clock(tin_l1$2$clock)
    );
    top$dot_l$add_0$s3_y tin_l1$3(
        .d(tin_l1$3$d),
        .q(tin_l1$3$q),
        .clock(tin_l1$3$clock)
    );
    top$dot_l$add_0$s3_y tin_l1$4(
        .d(tin_l1$4$d),
        .q(tin_l1$4$q),
        .clock(tin_l1$4$clock)
    );
    top$dot_l$add_0$s3_y tin_l1$5(
        .d(tin_l1$5$d),
        .q(tin_l1$5$q),
        .clock(tin_l1$5$clock)
    );
    top$dot_l$add_0$s3_y tin_l1$6(
        .d(tin_l1$6$d),
        .q(tin_l1$6$q),
        .clock(tin_l1$6$clock)
    );
    top$dot_l$add_0$s3_y tin_l1$7(
        .d(tin_l1$7$d),
        .q(tin_l1$7$q),
        .clock(tin_l1$7$clock)
    );
    top$dot_l$add_0$s3_y tin_l1$8(
        .d(tin_l1$8$d),
        .q(tin_l1$8$q),
        .clock(tin_l1$8$clock)
    );
    top$dot_l$add_0$s3_y tin_l1$9(
        .d(tin_l1$9$d),
        .q(tin_l1$9$q),
        .clock(tin_l1$9$clock)
    );
    top$dot_l$add_0$s3_y tin_l1$10(
        .d(tin_l1$10$d),
        .q(tin_l1$10$q),
        .clock(tin_l1$10$clock)
    );
    top$dot_l$add_0$s3_y tin_l1$11(
        .d(tin_l1$11$d),
        .q(tin_l1$11$q),
        .clock(tin_l1$11$clock)
    );
    top$dot_l$add_0$s3_y tin_l1$12(
        .d(tin_l1$12$d),
        .q(tin_l1$12$q),
        .clock(tin_l1$12$clock)
    );
    top$dot_l$add_0$s3_y tin_l1$13(
        .d(tin_l1$13$d),
        .q(tin_l1$13$q),
        .clock(tin_l1$13$clock)
    );
    top$dot_l$add_0$s3_y tin_l1$14(
        .d(tin_l1$14$d),
        .q(tin_l1$14$q),
        .clock(tin_l1$14$clock)
    );
    top$dot_l$add_0$s3_y tin_l1$15(
        .d(tin_l1$15$d),
        .q(tin_l1$15$q),
        .clock(tin_l1$15$clock)
    );
    top$dot_l$add_0$s3_y tin_l1$16(
        .d(tin_l1$16$d),
        .q(tin_l1$16$q),
        .clock(tin_l1$16$clock)
    );
    top$dot_l$add_0$s3_y tin_l1$17(
        .d(tin_l1$17$d),
        .q(tin_l1$17$q),
        .clock(tin_l1$17$clock)
    );
    top$dot_l$add_0$s3_y tin_l1$18(
        .d(tin_l1$18$d),
        .q(tin_l1$18$q),
        .clock(tin_l1$18$clock)
    );
    top$dot_l$add_0$s3_y tin_l1$19(
        .d(tin_l1$19$d),
        .q(tin_l1$19$q),
        .clock(tin_l1$19$clock)
    );
    top$dot_l$add_0$s3_y tin_l1$20(
        .d(tin_l1$20$d),
        .q(tin_l1$20$q),
        .clock(tin_l1$20$clock)
    );
    top$dot_l$add_0$s3_y tin_l1$21(
        .d(tin_l1$21$d),
        .q(tin_l1$21$q),
        .clock(tin_l1$21$clock)
    );
    top$dot_l$add_0$s3_y tin_l1$22(
        .d(tin_l1$22$d),
        .q(tin_l1$22$q),
        .clock(tin_l1$22$clock)
    );
    top$dot_l$add_0$s3_y tin_l1$23(
        .d(tin_l1$23$d),
        .q(tin_l1$23$q),
        .clock(tin_l1$23$clock)
    );
    top$dot_l$add_0$s3_y tin_r1$0(
        .d(tin_r1$0$d),
        .q(tin_r1$0$q),
        .clock(tin_r1$0$clock)
    );
    top$dot_l$add_0$s3_y tin_r1$1(
        .d(tin_r1$1$d),
        .q(tin_r1$1$q),
        .clock(tin_r1$1$clock)
    );
    top$dot_l$add_0$s3_y tin_r1$2(
        .d(tin_r1$2$d),
        .q(tin_r1$2$q),
        .clock(tin_r1$2$clock)
    );
    top$dot_l$add_0$s3_y tin_r1$3(
        .d(tin_r1$3$d),
        .q(tin_r1$3$q),
        .clock(tin_r1$3$clock)
    );
    top$dot_l$add_0$s3_y tin_r1$4(
        .d(tin_r1$4$d),
        .q(tin_r1$4$q),
        .clock(tin_r1$4$clock)
    );
    top$dot_l$add_0$s3_y tin_r1$5(
        .d(tin_r1$5$d),
        .q(tin_r1$5$q),
        .clock(tin_r1$5$clock)
    );
    top$dot_l$add_0$s3_y tin_r1$6(
        .d(tin_r1$6$d),
        .q(tin_r1$6$q),
        .clock(tin_r1$6$clock)
    );
    top$dot_l$add_0$s3_y tin_r1$7(
        .d(tin_r1$7$d),
        .q(tin_r1$7$q),
        .clock(tin_r1$7$clock)
    );
    top$dot_l$add_0$s3_y tin_r1$8(
        .d(tin_r1$8$d),
        .q(tin_r1$8$q),
        .clock(tin_r1$8$clock)
    );
    top$dot_l$add_0$s3_y tin_r1$9(
        .d(tin_r1$9$d),
        .q(tin_r1$9$q),
        .clock(tin_r1$9$clock)
    );
    top$dot_l$add_0$s3_y tin_r1$10(
        .d(tin_r1$10$d),
        .q(tin_r1$10$q),
        .clock(tin_r1$10$clock)
    );
    top$dot_l$add_0$s3_y tin_r1$11(
        .d(tin_r1$11$d),
        .q(tin_r1$11$q),
        .clock(tin_r1$11$clock)
    );
    top$dot_l$add_0$s3_y tin_r1$12(
        .d(tin_r1$12$d),
        .q(tin_r1$12$q),
        .clock(tin_r1$12$clock)
    );
    top$dot_l$add_0$s3_y tin_r1$13(
        .d(tin_r1$13$d),
        .q(tin_r1$13$q),
        .clock(tin_r1$13$clock)
    );
    top$dot_l$add_0$s3_y tin_r1$14(
        .d(tin_r1$14$d),
        .q(tin_r1$14$q),
        .clock(tin_r1$14$clock)
    );
    top$dot_l$add_0$s3_y tin_r1$15(
        .d(tin_r1$15$d),
        .q(tin_r1$15$q),
        .clock(tin_r1$15$clock)
    );
    top$dot_l$add_0$s3_y tin_r1$16(
        .d(tin_r1$16$d),
        .q(tin_r1$16$q),
        .clock(tin_r1$16$clock)
    );
    top$dot_l$add_0$s3_y tin_r1$17(
        .d(tin_r1$17$d),
        .q(tin_r1$17$q),
        .clock(tin_r1$17$clock)
    );
    top$dot_l$add_0$s3_y tin_r1$18(
        .d(tin_r1$18$d),
        .q(tin_r1$18$q),
        .clock(tin_r1$18$clock)
    );
    top$dot_l$add_0$s3_y tin_r1$19(
        .d(tin_r1$19$d),
        .q(tin_r1$19$q),
        .clock(tin_r1$19$clock)
    );
    top$dot_l$add_0$s3_y tin_r1$20(
        .d(tin_r1$20$d),
        .q(tin_r1$20$q),
        .clock(tin_r1$20$clock)
    );
    top$dot_l$add_0$s3_y tin_r1$21(
        .d(tin_r1$21$d),
        .q(tin_r1$21$q),
        .clock(tin_r1$21$clock)
    );
    top$dot_l$add_0$s3_y tin_r1$22(
        .d(tin_r1$22$d),
        .q(tin_r1$22$q),
        .clock(tin_r1$22$clock)
    );
    top$dot_l$add_0$s3_y tin_r1$23(
        .d(tin_r1$23$d),
        .q(tin_r1$23$q),
        .clock(tin_r1$23$clock)
    );
    top$bank$cmp_l0$s1_flag gen_run(
        .d(gen_run$d),
        .q(gen_run$q),
        .clock(gen_run$clock)
    );
    top$gen_cnt gen_cnt(
        .d(gen_cnt$d),
        .q(gen_cnt$q),
        .clock(gen_cnt$clock)
    );
    top$bank$cmp_l0$s1_flag gen_set(
        .d(gen_set$d),
        .q(gen_set$q),
        .clock(gen_set$clock)
    );
    top$busy_r pend(
        .d(pend$d),
        .q(pend$q),
        .clock(pend$clock)
    );
    top$busy_r busy_r(
        .d(busy_r$d),
        .q(busy_r$q),
        .clock(busy_r$clock)
    );
    top$bank$cmp_l0$s1_flag s1_valid(
        .d(s1_valid$d),
        .q(s1_valid$q),
        .clock(s1_valid$clock)
    );
    top$bank$cmp_l0$s1_flag s1_set(
        .d(s1_set$d),
        .q(s1_set$q),
        .clock(s1_set$clock)
    );
    top$gen_cnt s1_lane(
        .d(s1_lane$d),
        .q(s1_lane$q),
        .clock(s1_lane$clock)
    );
    top$bank$cmp_l0$s1_flag s1_last(
        .d(s1_last$d),
        .q(s1_last$q),
        .clock(s1_last$clock)
    );
    top$klm_l klm_l(
        .d$0(klm_l$d$0),
        .d$1(klm_l$d$1),
        .d$2(klm_l$d$2),
        .d$3(klm_l$d$3),
        .d$4(klm_l$d$4),
        .d$5(klm_l$d$5),
        .d$6(klm_l$d$6),
        .d$7(klm_l$d$7),
        .d$8(klm_l$d$8),
        .d$9(klm_l$d$9),
        .d$10(klm_l$d$10),
        .d$11(klm_l$d$11),
        .d$12(klm_l$d$12),
        .d$13(klm_l$d$13),
        .d$14(klm_l$d$14),
        .d$15(klm_l$d$15),
        .d$16(klm_l$d$16),
        .d$17(klm_l$d$17),
        .d$18(klm_l$d$18),
        .d$19(klm_l$d$19),
        .d$20(klm_l$d$20),
        .d$21(klm_l$d$21),
        .d$22(klm_l$d$22),
        .d$23(klm_l$d$23),
        .j0$0(klm_l$j0$0),
        .j1$0(klm_l$j1$0),
        .j2$0(klm_l$j2$0),
        .y0$0(klm_l$y0$0),
        .y1$0(klm_l$y1$0),
        .y2$0(klm_l$y2$0)
    );
    top$klm_l klm_r(
        .d$0(klm_r$d$0),
        .d$1(klm_r$d$1),
        .d$2(klm_r$d$2),
        .d$3(klm_r$d$3),
        .d$4(klm_r$d$4),
        .d$5(klm_r$d$5),
        .d$6(klm_r$d$6),
        .d$7(klm_r$d$7),
        .d$8(klm_r$d$8),
        .d$9(klm_r$d$9),
        .d$10(klm_r$d$10),
        .d$11(klm_r$d$11),
        .d$12(klm_r$d$12),
        .d$13(klm_r$d$13),
        .d$14(klm_r$d$14),
        .d$15(klm_r$d$15),
        .d$16(klm_r$d$16),
        .d$17(klm_r$d$17),
        .d$18(klm_r$d$18),
        .d$19(klm_r$d$19),
        .d$20(klm_r$d$20),
        .d$21(klm_r$d$21),
        .d$22(klm_r$d$22),
        .d$23(klm_r$d$23),
        .j0$0(klm_r$j0$0),
        .j1$0(klm_r$j1$0),
        .j2$0(klm_r$j2$0),
        .y0$0(klm_r$y0$0),
        .y1$0(klm_r$y1$0),
        .y2$0(klm_r$y2$0)
    );
    top$dot_l dot_l(
        .clock(dot_l$clock),
        .d0(dot_l$d0),
        .d1(dot_l$d1),
        .d2(dot_l$d2),
        .c0(dot_l$c0),
        .c1(dot_l$c1),
        .c2(dot_l$c2),
        .c(dot_l$c),
        .valid_in(dot_l$valid_in),
        .round_up(dot_l$round_up),
        .u(dot_l$u),
        .valid_out(dot_l$valid_out)
    );
    top$dot_l dot_r(
        .clock(dot_r$clock),
        .d0(dot_r$d0),
        .d1(dot_r$d1),
        .d2(dot_r$d2),
        .c0(dot_r$c0),
        .c1(dot_r$c1),
        .c2(dot_r$c2),
        .c(dot_r$c),
        .valid_in(dot_r$valid_in),
        .round_up(dot_r$round_up),
        .u(dot_r$u),
        .valid_out(dot_r$valid_out)
    );
    top$wr_tag wr_tag(
        .clock(wr_tag$clock),
        .d(wr_tag$d),
        .q(wr_tag$q)
    );
    top$dprime dprime(
        .clock(dprime$clock),
        .wr_valid(dprime$wr_valid),
        .wr_set(dprime$wr_set),
        .wr_lane(dprime$wr_lane),
        .wr_l(dprime$wr_l),
        .wr_r(dprime$wr_r),
        .rd_set(dprime$rd_set),
        .rd_entry(dprime$rd_entry),
        .dl(dprime$dl),
        .dr(dprime$dr)
    );
    top$bank$cmp_l0$s1_flag sa_valid(
        .d(sa_valid$d),
        .q(sa_valid$q),
        .clock(sa_valid$clock)
    );
    top$bank$cmp_l0$s1_flag sa_first(
        .d(sa_first$d),
        .q(sa_first$q),
        .clock(sa_first$clock)
    );
    top$bank$s1_lanes sa_lanes(
        .d(sa_lanes$d),
        .q(sa_lanes$q),
        .clock(sa_lanes$clock)
    );
    top$sa_e sa_e(
        .d(sa_e$d),
        .q(sa_e$q),
        .clock(sa_e$clock)
    );
    top$bank bank(
        .clock(bank$clock),
        .valid_in(bank$valid_in),
        .first(bank$first),
        .lanes(bank$lanes),
        .e(bank$e),
        .dl(bank$dl),
        .dr(bank$dr),
        .overlap_l(bank$overlap_l),
        .overlap_r(bank$overlap_r),
        .valid_out(bank$valid_out)
    );
    
    // Update code
    always @(*) begin
        c_row = load_addr[(32'h3)+:(5)];
        c_field = load_addr[(32'h0)+:(3)];
        mmm$0$read_clock = clock;
        mmm$0$write_clock = clock;
        mmm$0$read_address = gen_cnt$q;
        mmm$0$write_address = c_row;
        mmm$0$write_data = load_data;
        mmm$0$write_enable = load_en & (c_field == mmm_field$0);
        mmm$1$read_clock = clock;
        mmm$1$write_clock = clock;
        mmm$1$read_address = gen_cnt$q;
        mmm$1$write_address = c_row;
        mmm$1$write_data = load_data;
        mmm$1$write_enable = load_en & (c_field == mmm_field$1);
        mmm$2$read_clock = clock;
        mmm$2$write_clock = clock;
        mmm$2$read_address = gen_cnt$q;
        mmm$2$write_address = c_row;
        mmm$2$write_data = load_data;
        mmm$2$write_enable = load_en & (c_field == mmm_field$2);
        mmm$3$read_clock = clock;
        mmm$3$write_clock = clock;
        mmm$3$read_address = gen_cnt$q;
        mmm$3$write_address = c_row;
        mmm$3$write_data = load_data;
        mmm$3$write_enable = load_en & (c_field == mmm_field$3);
        mmm$4$read_clock = clock;
        mmm$4$write_clock = clock;
        mmm$4$read_address = gen_cnt$q;
        mmm$4$write_address = c_row;
        mmm$4$write_data = load_data;
        mmm$4$write_enable = load_en & (c_field == mmm_field$4);
        c_slot$0 = t_data[(32'h0)+:(32)];
        c_slot$1 = t_data[(32'h20)+:(32)];
        c_slot$2 = t_data[(32'h40)+:(32)];
        c_slot$3 = t_data[(32'h60)+:(32)];
        c_slot$4 = t_data[(32'h80)+:(32)];
        c_slot$5 = t_data[(32'ha0)+:(32)];
        c_slot$6 = t_data[(32'hc0)+:(32)];
        c_slot$7 = t_data[(32'he0)+:(32)];
        tin_l0$0$clock = clock;
        tin_r0$0$clock = clock;
        tin_l1$0$clock = clock;
        tin_r1$0$clock = clock;
        tin_l0$0$d = tin_l0$0$q;
        tin_r0$0$d = tin_r0$0$q;
        tin_l1$0$d = tin_l1$0$q;
        tin_r1$0$d = tin_r1$0$q;
        if (t_valid & (t_entry == entry_of$0)) begin
            if (t_set == 32'h1) begin
                if (t_side) begin
                    tin_r1$0$d = c_slot$0;
                end
                else begin
                    tin_l1$0$d = c_slot$0;
                end
            end
            else if (t_side) begin
                tin_r0$0$d = c_slot$0;
            end
            else begin
                tin_l0$0$d = c_slot$0;
            end
        end
        tin_l0$1$clock = clock;
        tin_r0$1$clock = clock;
        tin_l1$1$clock = clock;
        tin_r1$1$clock = clock;
        tin_l0$1$d = tin_l0$1$q;
        tin_r0$1$d = tin_r0$1$q;
        tin_l1$1$d = tin_l1$1$q;
        tin_r1$1$d = tin_r1$1$q;
        if (t_valid & (t_entry == entry_of$1)) begin
            if (t_set == 32'h1) begin
                if (t_side) begin
                    tin_r1$1$d = c_slot$1;
                end
                else begin
                    tin_l1$1$d = c_slot$1;
                end
            end
            else if (t_side) begin
                tin_r0$1$d = c_slot$1;
            end
            else begin
                tin_l0$1$d = c_slot$1;
            end
        end
        tin_l0$2$clock = clock;
        tin_r0$2$clock = clock;
        tin_l1$2$clock = clock;
        tin_r1$2$clock = clock;
        tin_l0$2$d = tin_l0$2$q;
        tin_r0$2$d = tin_r0$2$q;
        tin_l1$2$d = tin_l1$2$q;
        tin_r1$2$d = tin_r1$2$q;
        if (t_valid & (t_entry == entry_of$2)) begin
            if (t_set == 32'h1) begin
                if (t_side) begin
                    tin_r1$2$d = c_slot$2;
                end
                else begin
                    tin_l1$2$d = c_slot$2;
                end
            end
            else if (t_side) begin
                tin_r0$2$d = c_slot$2;
            end
            else begin
                tin_l0$2$d = c_slot$2;
            end
        end
        tin_l0$3$clock = clock;
        tin_r0$3$clock = clock;
        tin_l1$3$clock = clock;
        tin_r1$3$clock = clock;
        tin_l0$3$d = tin_l0$3$q;
        tin_r0$3$d = tin_r0$3$q;
        tin_l1$3$d = tin_l1$3$q;
        tin_r1$3$d = tin_r1$3$q;
        if (t_valid & (t_entry == entry_of$3)) begin
            if (t_set == 32'h1) begin
                if (t_side) begin
                    tin_r1$3$d = c_slot$3;
                end
                else begin
                    tin_l1$3$d = c_slot$3;
                end
            end
            else if (t_side) begin
                tin_r0$3$d = c_slot$3;
            end
            else begin
                tin_l0$3$d = c_slot$3;
            end
        end
        tin_l0$4$clock = clock;
        tin_r0$4$clock = clock;
        tin_l1$4$clock = clock;
        tin_r1$4$clock = clock;
        tin_l0$4$d = tin_l0$4$q;
        tin_r0$4$d = tin_r0$4$q;
        tin_l1$4$d = tin_l1$4$q;
        tin_r1$4$d = tin_r1$4$q;
        if (t_valid & (t_entry == entry_of$4)) begin
            if (t_set == 32'h1) begin
                if (t_side) begin
                    tin_r1$4$d = c_slot$4;
                end
                else begin
                    tin_l1$4$d = c_slot$4;
                end
            end
            else if (t_side) begin
                tin_r0$4$d = c_slot$4;
            end
            else begin
                tin_l0$4$d = c_slot$4;
            end
        end
        tin_l0$5$clock = clock;
        tin_r0$5$clock = clock;
        tin_l1$5$clock = clock;
        tin_r1$5$clock = clock;
        tin_l0$5$d = tin_l0$5$q;
        tin_r0$5$d = tin_r0$5$q;
        tin_l1$5$d = tin_l1$5$q;
        tin_r1$5$d = tin_r1$5$q;
        if (t_valid & (t_entry == entry_of$5)) begin
            if (t_set == 32'h1) begin
                if (t_side) begin
                    tin_r1$5$d = c_slot$5;
                end
                else begin
                    tin_l1$5$d = c_slot$5;
                end
            end
            else if (t_side) begin
                tin_r0$5$d = c_slot$5;
            end
            else begin
                tin_l0$5$d = c_slot$5;
            end
        end
        tin_l0$6$clock = clock;
        tin_r0$6$clock = clock;
        tin_l1$6$clock = clock;
        tin_r1$6$clock = clock;
        tin_l0$6$d = tin_l0$6$q;
        tin_r0$6$d = tin_r0$6$q;
        tin_l1$6$d = tin_l1$6$q;
        tin_r1$6$d = tin_r1$6$q;
        if (t_valid & (t_entry == entry_of$6)) begin
            if (t_set == 32'h1) begin
                if (t_side) begin
                    tin_r1$6$d = c_slot$6;
                end
                else begin
                    tin_l1$6$d = c_slot$6;
                end
            end
            else if (t_side) begin
                tin_r0$6$d = c_slot$6;
            end
            else begin
                tin_l0$6$d = c_slot$6;
            end
        end
        tin_l0$7$clock = clock;
        tin_r0$7$clock = clock;
        tin_l1$7$clock = clock;
        tin_r1$7$clock = clock;
        tin_l0$7$d = tin_l0$7$q;
        tin_r0$7$d = tin_r0$7$q;
        tin_l1$7$d = tin_l1$7$q;
        tin_r1$7$d = tin_r1$7$q;
        if (t_valid & (t_entry == entry_of$7)) begin
            if (t_set == 32'h1) begin
                if (t_side) begin
                    tin_r1$7$d = c_slot$7;
                end
                else begin
                    tin_l1$7$d = c_slot$7;
                end
            end
            else if (t_side) begin
                tin_r0$7$d = c_slot$7;
            end
            else begin
                tin_l0$7$d = c_slot$7;
            end
        end
        tin_l0$8$clock = clock;
        tin_r0$8$clock = clock;
        tin_l1$8$clock = clock;
        tin_r1$8$clock = clock;
        tin_l0$8$d = tin_l0$8$q;
        tin_r0$8$d = tin_r0$8$q;
        tin_l1$8$d = tin_l1$8$q;
        tin_r1$8$d = tin_r1$8$q;
        if (t_valid & (t_entry == entry_of$8)) begin
            if (t_set == 32'h1) begin
                if (t_side) begin
                    tin_r1$8$d = c_slot$0;
                end
                else begin
                    tin_l1$8$d = c_slot$0;
                end
            end
            else if (t_side) begin
                tin_r0$8$d = c_slot$0;
            end
            else begin
                tin_l0$8$d = c_slot$0;
            end
        end
        tin_l0$9$clock = clock;
        tin_r0$9$clock = clock;
        tin_l1$9$clock = clock;
        tin_r1$9$clock = clock;
        tin_l0$9$d = tin_l0$9$q;
        tin_r0$9$d = tin_r0$9$q;
        tin_l1$9$d = tin_l1$9$q;
        tin_r1$9$d = tin_r1$9$q;
        if (t_valid & (t_entry == entry_of$9)) begin
            if (t_set == 32'h1) begin
                if (t_side) begin
                    tin_r1$9$d = c_slot$1;
                end
                else begin
                    tin_l1$9$d = c_slot$1;
                end
            end
            else if (t_side) begin
                tin_r0$9$d = c_slot$1;
            end
            else begin
                tin_l0$9$d = c_slot$1;
            end
        end
        tin_l0$10$clock = clock;
        tin_r0$10$clock = clock;
        tin_l1$10$clock = clock;
        tin_r1$10$clock = clock;
        tin_l0$10$d = tin_l0$10$q;
        tin_r0$10$d = tin_r0$10$q;
        tin_l1$10$d = tin_l1$10$q;
        tin_r1$10$d = tin_r1$10$q;
        if (t_valid & (t_entry == entry_of$10)) begin
            if (t_set == 32'h1) begin
                if (t_side) begin
                    tin_r1$10$d = c_slot$2;
                end
                else begin
                    tin_l1$10$d = c_slot$2;
                end
            end
            else if (t_side) begin
                tin_r0$10$d = c_slot$2;
            end
            else begin
                tin_l0$10$d = c_slot$2;
            end
        end
        tin_l0$11$clock = clock;
        tin_r0$11$clock = clock;
        tin_l1$11$clock = clock;
        tin_r1$11$clock = clock;
        tin_l0$11$d = tin_l0$11$q;
        tin_r0$11$d = tin_r0$11$q;
        tin_l1$11$d = tin_l1$11$q;
        tin_r1$11$d = tin_r1$11$q;
        if (t_valid & (t_entry == entry_of$11)) begin
            if (t_set == 32'h1) begin
                if (t_side) begin
                    tin_r1$11$d = c_slot$3;
                end
                else begin
                    tin_l1$11$d = c_slot$3;
                end
            end
            else if (t_side) begin
                tin_r0$11$d = c_slot$3;
            end
            else begin
                tin_l0$11$d = c_slot$3;
            end
        end
        tin_l0$12$clock = clock;
        tin_r0$12$clock = clock;
        tin_l1$12$clock = clock;
        tin_r1$12$clock = clock;
        tin_l0$12$d = tin_l0$12$q;
        tin_r0$12$d = tin_r0$12$q;
        tin_l1$12$d = tin_l1$12$q;
        tin_r1$12$d = tin_r1$12$q;
        if (t_valid & (t_entry == entry_of$12)) begin
            if (t_set == 32'h1) begin
                if (t_side) begin
                    tin_r1$12$d = c_slot$4;
                end
                else begin
                    tin_l1$12$d = c_slot$4;
                end
            end
            else if (t_side) begin
                tin_r0$12$d = c_slot$4;
            end
            else begin
                tin_l0$12$d = c_slot$4;
            end
        end
        tin_l0$13$clock = clock;
        tin_r0$13$clock = clock;
        tin_l1$13$clock = clock;
        tin_r1$13$clock = clock;
        tin_l0$13$d = tin_l0$13$q;
        tin_r0$13$d = tin_r0$13$q;
        tin_l1$13$d = tin_l1$13$q;
        tin_r1$13$d = tin_r1$13$q;
        if (t_valid & (t_entry == entry_of$13)) begin
            if (t_set == 32'h1) begin
                if (t_side) begin
                    tin_r1$13$d = c_slot$5;
                end
                else begin
                    tin_l1$13$d = c_slot$5;
                end
            end
            else if (t_side) begin
                tin_r0$13$d = c_slot$5;
            end
            else begin
                tin_l0$13$d = c_slot$5;
            end
        end
        tin_l0$14$clock = clock;
        tin_r0$14$clock = clock;
        tin_l1$14$clock = clock;
        tin_r1$14$clock = clock;
        tin_l0$14$d = tin_l0$14$q;
        tin_r0$14$d = tin_r0$14$q;
        tin_l1$14$d = tin_l1$14$q;
        tin_r1$14$d = tin_r1$14$q;
        if (t_valid & (t_entry == entry_of$14)) begin
            if (t_set == 32'h1) begin
                if (t_side) begin
                    tin_r1$14$d = c_slot$6;
                end
                else begin
                    tin_l1$14$d = c_slot$6;
                end
            end
            else if (t_side) begin
                tin_r0$14$d = c_slot$6;
            end
            else begin
                tin_l0$14$d = c_slot$6;
            end
        end
        tin_l0$15$clock = clock;
        tin_r0$15$clock = clock;
        tin_l1$15$clock = clock;
        tin_r1$15$clock = clock;
        tin_l0$15$d = tin_l0$15$q;
        tin_r0$15$d = tin_r0$15$q;
        tin_l1$15$d = tin_l1$15$q;
        tin_r1$15$d = tin_r1$15$q;
        if (t_valid & (t_entry == entry_of$15)) begin
            if (t_set == 32'h1) begin
                if (t_side) begin
                    tin_r1$15$d = c_slot$7;
                end
                else begin
                    tin_l1$15$d = c_slot$7;
                end
            end
            else if (t_side) begin
                tin_r0$15$d = c_slot$7;
            end
            else begin
                tin_l0$15$d = c_slot$7;
            end
        end
        tin_l0$16$clock = clock;
        tin_r0$16$clock = clock;
        tin_l1$16$clock = clock;
        tin_r1$16$clock = clock;
        tin_l0$16$d = tin_l0$16$q;
        tin_r0$16$d = tin_r0$16$q;
        tin_l1$16$d = tin_l1$16$q;
        tin_r1$16$d = tin_r1$16$q;
        if (t_valid & (t_entry == entry_of$16)) begin
            if (t_set == 32'h1) begin
                if (t_side) begin
                    tin_r1$16$d = c_slot$0;
                end
                else begin
                    tin_l1$16$d = c_slot$0;
                end
            end
            else if (t_side) begin
                tin_r0$16$d = c_slot$0;
            end
            else begin
                tin_l0$16$d = c_slot$0;
            end
        end
        tin_l0$17$clock = clock;
        tin_r0$17$clock = clock;
        tin_l1$17$clock = clock;
        tin_r1$17$clock = clock;
        tin_l0$17$d = tin_l0$17$q;
        tin_r0$17$d = tin_r0$17$q;
        tin_l1$17$d = tin_l1$17$q;
        tin_r1$17$d = tin_r1$17$q;
        if (t_valid & (t_entry == entry_of$17)) begin
            if (t_set == 32'h1) begin
                if (t_side) begin
                    tin_r1$17$d = c_slot$1;
                end
                else begin
                    tin_l1$17$d = c_slot$1;
                end
            end
            else if (t_side) begin
                tin_r0$17$d = c_slot$1;
            end
            else begin
                tin_l0$17$d = c_slot$1;
            end
        end
        tin_l0$18$clock = clock;
        tin_r0$18$clock = clock;
        tin_l1$18$clock = clock;
        tin_r1$18$clock = clock;
        tin_l0$18$d = tin_l0$18$q;
        tin_r0$18$d = tin_r0$18$q;
        tin_l1$18$d = tin_l1$18$q;
        tin_r1$18$d = tin_r1$18$q;
        if (t_valid & (t_entry == entry_of$18)) begin
            if (t_set == 32'h1) begin
                if (t_side) begin
                    tin_r1$18$d = c_slot$2;
                end
                else begin
                    tin_l1$18$d = c_slot$2;
                end
            end
            else if (t_side) begin
                tin_r0$18$d = c_slot$2;
            end
            else begin
                tin_l0$18$d = c_slot$2;
            end
        end
        tin_l0$19$clock = clock;
        tin_r0$19$clock = clock;
        tin_l1$19$clock = clock;
        tin_r1$19$clock = clock;
        tin_l0$19$d = tin_l0$19$q;
        tin_r0$19$d = tin_r0$19$q;
        tin_l1$19$d = tin_l1$19$q;
        tin_r1$19$d = tin_r1$19$q;
        if (t_valid & (t_entry == entry_of$19)) begin
            if (t_set == 32'h1) begin
                if (t_side) begin
                    tin_r1$19$d = c_slot$3;
                end
                else begin
                    tin_l1$19$d = c_slot$3;
                end
            end
            else if (t_side) begin
                tin_r0$19$d = c_slot$3;
            end
            else begin
                tin_l0$19$d = c_slot$3;
            end
        end
        tin_l0$20$clock = clock;
        tin_r0$20$clock = clock;
        tin_l1$20$clock = clock;
        tin_r1$20$clock = clock;
        tin_l0$20$d = tin_l0$20$q;
        tin_r0$20$d = tin_r0$20$q;
        tin_l1$20$d = tin_l1$20$q;
        tin_r1$20$d = tin_r1$20$q;
        if (t_valid & (t_entry == entry_of$20)) begin
            if (t_set == 32'h1) begin
                if (t_side) begin
                    tin_r1$20$d = c_slot$4;
                end
                else begin
                    tin_l1$20$d = c_slot$4;
                end
            end
            else if (t_side) begin
                tin_r0$20$d = c_slot$4;
            end
            else begin
                tin_l0$20$d = c_slot$4;
            end
        end
        tin_l0$21$clock = clock;
        tin_r0$21$clock = clock;
        tin_l1$21$clock = clock;
        tin_r1$21$clock = clock;
        tin_l0$21$d = tin_l0$21$q;
        tin_r0$21$d = tin_r0$21$q;
        tin_l1$21$d = tin_l1$21$q;
        tin_r1$21$d = tin_r1$21$q;
        if (t_valid & (t_entry == entry_of$21)) begin
            if (t_set == 32'h1) begin
                if (t_side) begin
                    tin_r1$21$d = c_slot$5;
                end
                else begin
                    tin_l1$21$d = c_slot$5;
                end
            end
            else if (t_side) begin
                tin_r0$21$d = c_slot$5;
            end
            else begin
                tin_l0$21$d = c_slot$5;
            end
        end
        tin_l0$22$clock = clock;
        tin_r0$22$clock = clock;
        tin_l1$22$clock = clock;
        tin_r1$22$clock = clock;
        tin_l0$22$d = tin_l0$22$q;
        tin_r0$22$d = tin_r0$22$q;
        tin_l1$22$d = tin_l1$22$q;
        tin_r1$22$d = tin_r1$22$q;
        if (t_valid & (t_entry == entry_of$22)) begin
            if (t_set == 32'h1) begin
                if (t_side) begin
                    tin_r1$22$d = c_slot$6;
                end
                else begin
                    tin_l1$22$d = c_slot$6;
                end
            end
            else if (t_side) begin
                tin_r0$22$d = c_slot$6;
            end
            else begin
                tin_l0$22$d = c_slot$6;
            end
        end
        tin_l0$23$clock = clock;
        tin_r0$23$clock = clock;
        tin_l1$23$clock = clock;
        tin_r1$23$clock = clock;
        tin_l0$23$d = tin_l0$23$q;
        tin_r0$23$d = tin_r0$23$q;
        tin_l1$23$d = tin_l1$23$q;
        tin_r1$23$d = tin_r1$23$q;
        if (t_valid & (t_entry == entry_of$23)) begin
            if (t_set == 32'h1) begin
                if (t_side) begin
                    tin_r1$23$d = c_slot$7;
                end
                else begin
                    tin_l1$23$d = c_slot$7;
                end
            end
            else if (t_side) begin
                tin_r0$23$d = c_slot$7;
            end
            else begin
                tin_l0$23$d = c_slot$7;
            end
        end
        gen_run$clock = clock;
        gen_cnt$clock = clock;
        gen_set$clock = clock;
        pend$clock = clock;
        s1_valid$clock = clock;
        s1_set$clock = clock;
        s1_lane$clock = clock;
        s1_last$clock = clock;
        gen_run$d = gen_run$q;
        gen_cnt$d = gen_cnt$q;
        gen_set$d = gen_set$q;
        pend$d = pend$q;
        s1_valid$d = s1_valid$q;
        s1_set$d = s1_set$q;
        s1_lane$d = s1_lane$q;
        s1_last$d = s1_last$q;
        c_row_last = gen_run$q & (gen_cnt$q == last_row);
        c_go = (~gen_run$q | c_row_last) & ((pend$q != 32'h0) | (t_valid & t_last));
        c_go_set = t_set;
        if (pend$q[32'h1]) begin
            c_go_set = 32'h1;
        end
        if (pend$q[32'h0]) begin
            c_go_set = 32'h0;
        end
        c_t_set = 32'h1;
        if (t_set == 32'h1) begin
            c_t_set = 32'h2;
        end
        c_go_mask = 32'h0;
        if (c_go) begin
            c_go_mask = 32'h1;
            if (c_go_set == 32'h1) begin
                c_go_mask = 32'h2;
            end
        end
        c_pend_set = 32'h0;
        c_busy_set = 32'h0;
        if (t_valid) begin
            c_busy_set = c_t_set;
            if (t_last) begin
                c_pend_set = c_t_set;
            end
        end
        pend$d = (pend$q | c_pend_set) & ~c_go_mask;
        gen_run$d = gen_run$q & ~c_row_last;
        gen_cnt$d = 32'h0;
        if (gen_run$q & ~c_row_last) begin
            gen_cnt$d = gen_cnt$q + 32'h1;
        end
        gen_set$d = gen_set$q;
        if (c_go) begin
            gen_run$d = 1'b1;
            gen_set$d = c_go_set;
        end
        s1_valid$d = gen_run$q;
        s1_set$d = gen_set$q;
        s1_lane$d = gen_cnt$q;
        s1_last$d = 32'h0;
        if (c_row_last) begin
            s1_last$d = 32'h1;
        end
        c_ctl = mmm$4$read_data;
        if (s1_set$q == 32'h1) begin
            klm_l$d$0 = tin_l1$0$q;
            klm_r$d$0 = tin_r1$0$q;
        end
        else begin
            klm_l$d$0 = tin_l0$0$q;
            klm_r$d$0 = tin_r0$0$q;
        end
        if (s1_set$q == 32'h1) begin
            klm_l$d$1 = tin_l1$1$q;
            klm_r$d$1 = tin_r1$1$q;
        end
        else begin
            klm_l$d$1 = tin_l0$1$q;
            klm_r$d$1 = tin_r0$1$q;
        end
        if (s1_set$q == 32'h1) begin
            klm_l$d$2 = tin_l1$2$q;
            klm_r$d$2 = tin_r1$2$q;
        end
        else begin
            klm_l$d$2 = tin_l0$2$q;
            klm_r$d$2 = tin_r0$2$q;
        end
        if (s1_set$q == 32'h1) begin
            klm_l$d$3 = tin_l1$3$q;
            klm_r$d$3 = tin_r1$3$q;
        end
        else begin
            klm_l$d$3 = tin_l0$3$q;
            klm_r$d$3 = tin_r0$3$q;
        end
        if (s1_set$q == 32'h1) begin
            klm_l$d$4 = tin_l1$4$q;
            klm_r$d$4 = tin_r1$4$q;
        end
        else begin
            klm_l$d$4 = tin_l0$4$q;
            klm_r$d$4 = tin_r0$4$q;
        end
        if (s1_set$q == 32'h1) begin
            klm_l$d$5 = tin_l1$5$q;
            klm_r$d$5 = tin_r1$5$q;
        end
        else begin
            klm_l$d$5 = tin_l0$5$q;
            klm_r$d$5 = tin_r0$5$q;
        end
        if (s1_set$q == 32'h1) begin
            klm_l$d$6 = tin_l1$6$q;
            klm_r$d$6 = tin_r1$6$q;
        end
        else begin
            klm_l$d$6 = tin_l0$6$q;
            klm_r$d$6 = tin_r0$6$q;
        end
        if (s1_set$q == 32'h1) begin
            klm_l$d$7 = tin_l1$7$q;
            klm_r$d$7 = tin_r1$7$q;
        end
        else begin
            klm_l$d$7 = tin_l0$7$q;
            klm_r$d$7 = tin_r0$7$q;
        end
        if (s1_set$q == 32'h1) begin
            klm_l$d$8 = tin_l1$8$q;
            klm_r$d$8 = tin_r1$8$q;
        end
        else begin
            klm_l$d$8 = tin_l0$8$q;
            klm_r$d$8 = tin_r0$8$q;
        end
        if (s1_set$q == 32'h1) begin
            klm_l$d$9 = tin_l1$9$q;
            klm_r$d$9 = tin_r1$9$q;
        end
        else begin
            klm_l$d$9 = tin_l0$9$q;
            klm_r$d$9 = tin_r0$9$q;
        end
        if (s1_set$q == 32'h1) begin
            klm_l$d$10 = tin_l1$10$q;
            klm_r$d$10 = tin_r1$10$q;
        end
        else begin
            klm_l$d$10 = tin_l0$10$q;
            klm_r$d$10 = tin_r0$10$q;
        end
        if (s1_set$q == 32'h1) begin
            klm_l$d$11 = tin_l1$11$q;
            klm_r$d$11 = tin_r1$11$q;
        end
        else begin
            klm_l$d$11 = tin_l0$11$q;
            klm_r$d$11 = tin_r0$11$q;
        end
        if (s1_set$q == 32'h1) begin
            klm_l$d$12 = tin_l1$12$q;
            klm_r$d$12 = tin_r1$12$q;
        end
        else begin
            klm_l$d$12 = tin_l0$12$q;
            klm_r$d$12 = tin_r0$12$q;
        end
        if (s1_set$q == 32'h1) begin
            klm_l$d$13 = tin_l1$13$q;
            klm_r$d$13 = tin_r1$13$q;
        end
        else begin
            klm_l$d$13 = tin_l0$13$q;
            klm_r$d$13 = tin_r0$13$q;
        end
        if (s1_set$q == 32'h1) begin
            klm_l$d$14 = tin_l1$14$q;
            klm_r$d$14 = tin_r1$14$q;
        end
        else begin
            klm_l$d$14 = tin_l0$14$q;
            klm_r$d$14 = tin_r0$14$q;
        end
        if (s1_set$q == 32'h1) begin
            klm_l$d$15 = tin_l1$15$q;
            klm_r$d$15 = tin_r1$15$q;
        end
        else begin
            klm_l$d$15 = tin_l0$15$q;
            klm_r$d$15 = tin_r0$15$q;
        end
        if (s1_set$q == 32'h1) begin
            klm_l$d$16 = tin_l1$16$q;
            klm_r$d$16 = tin_r1$16$q;
        end
        else begin
            klm_l$d$16 = tin_l0$16$q;
            klm_r$d$16 = tin_r0$16$q;
        end
        if (s1_set$q == 32'h1) begin
            klm_l$d$17 = tin_l1$17$q;
            klm_r$d$17 = tin_r1$17$q;
        end
        else begin
            klm_l$d$17 = tin_l0$17$q;
            klm_r$d$17 = tin_r0$17$q;
        end
        if (s1_set$q == 32'h1) begin
            klm_l$d$18 = tin_l1$18$q;
            klm_r$d$18 = tin_r1$18$q;
        end
        else begin
            klm_l$d$18 = tin_l0$18$q;
            klm_r$d$18 = tin_r0$18$q;
        end
        if (s1_set$q == 32'h1) begin
            klm_l$d$19 = tin_l1$19$q;
            klm_r$d$19 = tin_r1$19$q;
        end
        else begin
            klm_l$d$19 = tin_l0$19$q;
            klm_r$d$19 = tin_r0$19$q;
        end
        if (s1_set$q == 32'h1) begin
            klm_l$d$20 = tin_l1$20$q;
            klm_r$d$20 = tin_r1$20$q;
        end
        else begin
            klm_l$d$20 = tin_l0$20$q;
            klm_r$d$20 = tin_r0$20$q;
        end
        if (s1_set$q == 32'h1) begin
            klm_l$d$21 = tin_l1$21$q;
            klm_r$d$21 = tin_r1$21$q;
        end
        else begin
            klm_l$d$21 = tin_l0$21$q;
            klm_r$d$21 = tin_r0$21$q;
        end
        if (s1_set$q == 32'h1) begin
            klm_l$d$22 = tin_l1$22$q;
            klm_r$d$22 = tin_r1$22$q;
        end
        else begin
            klm_l$d$22 = tin_l0$22$q;
            klm_r$d$22 = tin_r0$22$q;
        end
        if (s1_set$q == 32'h1) begin
            klm_l$d$23 = tin_l1$23$q;
            klm_r$d$23 = tin_r1$23$q;
        end
        else begin
            klm_l$d$23 = tin_l0$23$q;
            klm_r$d$23 = tin_r0$23$q;
        end
        klm_l$j0$0 = c_ctl[(32'h0)+:(5)];
        klm_l$j1$0 = c_ctl[(32'h5)+:(5)];
        klm_l$j2$0 = c_ctl[(32'ha)+:(5)];
        klm_r$j0$0 = c_ctl[(32'h0)+:(5)];
        klm_r$j1$0 = c_ctl[(32'h5)+:(5)];
        klm_r$j2$0 = c_ctl[(32'ha)+:(5)];
        dot_l$clock = clock;
        dot_l$valid_in = s1_valid$q;
        dot_l$round_up = c_ctl[32'hf];
        dot_l$c0 = mmm$0$read_data;
        dot_l$c1 = mmm$1$read_data;
        dot_l$c2 = mmm$2$read_data;
        dot_l$c = mmm$3$read_data;
        dot_l$d0 = klm_l$y0$0;
        dot_l$d1 = klm_l$y1$0;
        dot_l$d2 = klm_l$y2$0;
        dot_r$clock = clock;
        dot_r$valid_in = s1_valid$q;
        dot_r$round_up = c_ctl[32'hf];
        dot_r$c0 = mmm$0$read_data;
        dot_r$c1 = mmm$1$read_data;
        dot_r$c2 = mmm$2$read_data;
        dot_r$c = mmm$3$read_data;
        dot_r$d0 = klm_r$y0$0;
        dot_r$d1 = klm_r$y1$0;
        dot_r$d2 = klm_r$y2$0;
        busy_r$clock = clock;
        sa_valid$clock = clock;
        sa_first$clock = clock;
        sa_lanes$clock = clock;
        sa_e$clock = clock;
        busy_r$d = busy_r$q;
        sa_valid$d = sa_valid$q;
        sa_first$d = sa_first$q;
        sa_lanes$d = sa_lanes$q;
        sa_e$d = sa_e$q;
        wr_tag$clock = clock;
        wr_tag$d = ((s1_lane$q) & 7'h7f) | (((s1_set$q) & 7'h7f) << 32'h5) | (((s1_last$q) & 7'h7f) << 32'h6);
        c_wr_set = wr_tag$q[(32'h5)+:(1)];
        dprime$clock = clock;
        dprime$wr_valid = dot_l$valid_out;
        dprime$wr_set = c_wr_set;
        dprime$wr_lane = wr_tag$q[(32'h0)+:(5)];
        dprime$wr_l = dot_l$u;
        dprime$wr_r = dot_r$u;
        c_busy_clr = 32'h0;
        if (dot_l$valid_out & wr_tag$q[32'h6]) begin
            c_busy_clr = 32'h1;
            if (c_wr_set == 32'h1) begin
                c_busy_clr = 32'h2;
            end
        end
        busy_r$d = (busy_r$q & ~c_busy_clr) | c_busy_set;
        busy = busy_r$q;
        dprime$rd_set = a_set;
        dprime$rd_entry = a_entry;
        sa_valid$d = a_valid;
        sa_first$d = a_first;
        sa_lanes$d = a_lanes;
        sa_e$d = e;
        bank$clock = clock;
        bank$valid_in = sa_valid$q;
        bank$first = sa_first$q;
        bank$lanes = sa_lanes$q;
        bank$e = sa_e$q;
        bank$dl = dprime$dl;
        bank$dr = dprime$dr;
        overlap_l = bank$overlap_l;
        overlap_r = bank$overlap_r;
        flags_valid = bank$valid_out;
    end
    
endmodule // top


module top$bank(clock,valid_in,first,lanes,e,dl,dr,overlap_l,overlap_r,valid_out);
    
    // Module arguments
    input wire  clock;
    input wire  valid_in;
    input wire  first;
    input wire  [7:0] lanes;
    input wire  [255:0] e;
    input wire  [255:0] dl;
    input wire  [255:0] dr;
    output reg  overlap_l;
    output reg  overlap_r;
    output reg  valid_out;
    
    // Stub signals
    reg  cmp_l0$clock;
    reg  [31:0] cmp_l0$a;
    reg  [31:0] cmp_l0$b;
    reg  cmp_l0$valid_in;
    wire  cmp_l0$flag;
    wire  cmp_l0$valid_out;
    reg  cmp_r0$clock;
    reg  [31:0] cmp_r0$a;
    reg  [31:0] cmp_r0$b;
    reg  cmp_r0$valid_in;
    wire  cmp_r0$flag;
    wire  cmp_r0$valid_out;
    reg  cmp_l1$clock;
    reg  [31:0] cmp_l1$a;
    reg  [31:0] cmp_l1$b;
    reg  cmp_l1$valid_in;
    wire  cmp_l1$flag;
    wire  cmp_l1$valid_out;
    reg  cmp_r1$clock;
    reg  [31:0] cmp_r1$a;
    reg  [31:0] cmp_r1$b;
    reg  cmp_r1$valid_in;
    wire  cmp_r1$flag;
    wire  cmp_r1$valid_out;
    reg  cmp_l2$clock;
    reg  [31:0] cmp_l2$a;
    reg  [31:0] cmp_l2$b;
    reg  cmp_l2$valid_in;
    wire  cmp_l2$flag;
    wire  cmp_l2$valid_out;
    reg  cmp_r2$clock;
    reg  [31:0] cmp_r2$a;
    reg  [31:0] cmp_r2$b;
    reg  cmp_r2$valid_in;
    wire  cmp_r2$flag;
    wire  cmp_r2$valid_out;
    reg  cmp_l3$clock;
    reg  [31:0] cmp_l3$a;
    reg  [31:0] cmp_l3$b;
    reg  cmp_l3$valid_in;
    wire  cmp_l3$flag;
    wire  cmp_l3$valid_out;
    reg  cmp_r3$clock;
    reg  [31:0] cmp_r3$a;
    reg  [31:0] cmp_r3$b;
    reg  cmp_r3$valid_in;
    wire  cmp_r3$flag;
    wire  cmp_r3$valid_out;
    reg  cmp_l4$clock;
    reg  [31:0] cmp_l4$a;
    reg  [31:0] cmp_l4$b;
    reg  cmp_l4$valid_in;
    wire  cmp_l4$flag;
    wire  cmp_l4$valid_out;
    reg  cmp_r4$clock;
    reg  [31:0] cmp_r4$a;
    reg  [31:0] cmp_r4$b;
    reg  cmp_r4$valid_in;
    wire  cmp_r4$flag;
    wire  cmp_r4$valid_out;
    reg  cmp_l5$clock;
    reg  [31:0] cmp_l5$a;
    reg  [31:0] cmp_l5$b;
    reg  cmp_l5$valid_in;
    wire  cmp_l5$flag;
    wire  cmp_l5$valid_out;
    reg  cmp_r5$clock;
    reg  [31:0] cmp_r5$a;
    reg  [31:0] cmp_r5$b;
    reg  cmp_r5$valid_in;
    wire  cmp_r5$flag;
    wire  cmp_r5$valid_out;
    reg  cmp_l6$clock;
    reg  [31:0] cmp_l6$a;
    reg  [31:0] cmp_l6$b;
    reg  cmp_l6$valid_in;
    wire  cmp_l6$flag;
    wire  cmp_l6$valid_out;
    reg  cmp_r6$clock;
    reg  [31:0] cmp_r6$a;
    reg  [31:0] cmp_r6$b;
    reg  cmp_r6$valid_in;
    wire  cmp_r6$flag;
    wire  cmp_r6$valid_out;
    reg  cmp_l7$clock;
    reg  [31:0] cmp_l7$a;
    reg  [31:0] cmp_l7$b;
    reg  cmp_l7$valid_in;
    wire  cmp_l7$flag;
    wire  cmp_l7$valid_out;
    reg  cmp_r7$clock;
    reg  [31:0] cmp_r7$a;
    reg  [31:0] cmp_r7$b;
    reg  cmp_r7$valid_in;
    wire  cmp_r7$flag;
    wire  cmp_r7$valid_out;
    reg  s1_first$d;
    wire  s1_first$q;
    reg  s1_first$clock;
    reg  [7:0] s1_lanes$d;
    wire  [7:0] s1_lanes$q;
    reg  s1_lanes$clock;
    reg  s2_sep_l$d;
    wire  s2_sep_l$q;
    reg  s2_sep_l$clock;
    reg  s2_sep_r$d;
    wire  s2_sep_r$q;
    reg  s2_sep_r$clock;
    reg  s2_valid$d;
    wire  s2_valid$q;
    reg  s2_valid$clock;
    
    // Local signals
    reg  c2_any_l;
    reg  c2_any_r;
    
    // Sub module instances
    top$bank$cmp_l0 cmp_l0(
        .clock(cmp_l0$clock),
        .a(cmp_l0$a),
        .b(cmp_l0$b),
        .valid_in(cmp_l0$valid_in),
        .flag(cmp_l0$flag),
        .valid_out(cmp_l0$valid_out)
    );
    top$bank$cmp_l0 cmp_r0(
        .clock(cmp_r0$clock),
        .a(cmp_r0$a),
        .b(cmp_r0$b),
        .valid_in(cmp_r0$valid_in),
        .flag(cmp_r0$flag),
        .valid_out(cmp_r0$valid_out)
    );
    top$bank$cmp_l0 cmp_l1(
        .clock(cmp_l1$clock),
        .a(cmp_l1$a),
        .b(cmp_l1$b),
        .valid_in(cmp_l1$valid_in),
        .flag(cmp_l1$flag),
        .valid_out(cmp_l1$valid_out)
    );
    top$bank$cmp_l0 cmp_r1(
        .clock(cmp_r1$clock),
        .a(cmp_r1$a),
        .b(cmp_r1$b),
        .valid_in(cmp_r1$valid_in),
        .flag(cmp_r1$flag),
        .valid_out(cmp_r1$valid_out)
    );
    top$bank$cmp_l0 cmp_l2(
        .clock(cmp_l2$clock),
        .a(cmp_l2$a),
        .b(cmp_l2$b),
        .valid_in(cmp_l2$valid_in),
        .flag(cmp_l2$flag),
        .valid_out(cmp_l2$valid_out)
    );
    top$bank$cmp_l0 cmp_r2(
        .clock(cmp_r2$clock),
        .a(cmp_r2$a),
        .b(cmp_r2$b),
        .valid_in(cmp_r2$valid_in),
        .flag(cmp_r2$flag),
        .valid_out(cmp_r2$valid_out)
    );
    top$bank$cmp_l0 cmp_l3(
        .clock(cmp_l3$clock),
        .a(cmp_l3$a),
        .b(cmp_l3$b),
        .valid_in(cmp_l3$valid_in),
        .flag(cmp_l3$flag),
        .valid_out(cmp_l3$valid_out)
    );
    top$bank$cmp_l0 cmp_r3(
        .clock(cmp_r3$clock),
        .a(cmp_r3$a),
        .b(cmp_r3$b),
        .valid_in(cmp_r3$valid_in),
        .flag(cmp_r3$flag),
        .valid_out(cmp_r3$valid_out)
    );
    top$bank$cmp_l0 cmp_l4(
        .clock(cmp_l4$clock),
        .a(cmp_l4$a),
        .b(cmp_l4$b),
        .valid_in(cmp_l4$valid_in),
        .flag(cmp_l4$flag),
        .valid_out(cmp_l4$valid_out)
    );
    top$bank$cmp_l0 cmp_r4(
        .clock(cmp_r4$clock),
        .a(cmp_r4$a),
        .b(cmp_r4$b),
        .valid_in(cmp_r4$valid_in),
        .flag(cmp_r4$flag),
        .valid_out(cmp_r4$valid_out)
    );
    top$bank$cmp_l0 cmp_l5(
        .clock(cmp_l5$clock),
        .a(cmp_l5$a),
        .b(cmp_l5$b),
        .valid_in(cmp_l5$valid_in),
        .flag(cmp_l5$flag),
        .valid_out(cmp_l5$valid_out)
    );
    top$bank$cmp_l0 cmp_r5(
        .clock(cmp_r5$clock),
        .a(cmp_r5$a),
        .b(cmp_r5$b),
        .valid_in(cmp_r5$valid_in),
        .flag(cmp_r5$flag),
        .valid_out(cmp_r5$valid_out)
    );
    top$bank$cmp_l0 cmp_l6(
        .clock(cmp_l6$clock),
        .a(cmp_l6$a),
        .b(cmp_l6$b),
        .valid_in(cmp_l6$valid_in),
        .flag(cmp_l6$flag),
        .valid_out(cmp_l6$valid_out)
    );
    top$bank$cmp_l0 cmp_r6(
        .clock(cmp_r6$clock),
        .a(cmp_r6$a),
        .b(cmp_r6$b),
        .valid_in(cmp_r6$valid_in),
        .flag(cmp_r6$flag),
        .valid_out(cmp_r6$valid_out)
    );
    top$bank$cmp_l0 cmp_l7(
        .clock(cmp_l7$clock),
        .a(cmp_l7$a),
        .b(cmp_l7$b),
        .valid_in(cmp_l7$valid_in),
        .flag(cmp_l7$flag),
        .valid_out(cmp_l7$valid_out)
    );
    top$bank$cmp_l0 cmp_r7(
        .clock(cmp_r7$clock),
        .a(cmp_r7$a),
        .b(cmp_r7$b),
        .valid_in(cmp_r7$valid_in),
        .flag(cmp_r7$flag),
        .valid_out(cmp_r7$valid_out)
    );
    top$bank$cmp_l0$s1_flag s1_first(
        .d(s1_first$d),
        .q(s1_first$q),
        .clock(s1_first$clock)
    );
    top$bank$s1_lanes s1_lanes(
        .d(s1_lanes$d),
        .q(s1_lanes$q),
        .clock(s1_lanes$clock)
    );
    top$bank$cmp_l0$s1_flag s2_sep_l(
        .d(s2_sep_l$d),
        .q(s2_sep_l$q),
        .clock(s2_sep_l$clock)
    );
    top$bank$cmp_l0$s1_flag s2_sep_r(
        .d(s2_sep_r$d),
        .q(s2_sep_r$q),
        .clock(s2_sep_r$clock)
    );
    top$bank$cmp_l0$s1_flag s2_valid(
        .d(s2_valid$d),
        .q(s2_valid$q),
        .clock(s2_valid$clock)
    );
    
    // Update code
    always @(*) begin
        s1_first$clock = clock;
        s1_lanes$clock = clock;
        s2_sep_l$clock = clock;
        s2_sep_r$clock = clock;
        s2_valid$clock = clock;
        s1_first$d = s1_first$q;
        s1_lanes$d = s1_lanes$q;
        s2_sep_l$d = s2_sep_l$q;
        s2_sep_r$d = s2_sep_r$q;
        s2_valid$d = s2_valid$q;
        cmp_l0$clock = clock;
        cmp_l0$a = dl[(32'h0)+:(32)];
        cmp_l0$b = e[(32'h0)+:(32)];
        cmp_l0$valid_in = valid_in;
        cmp_r0$clock = clock;
        cmp_r0$a = dr[(32'h0)+:(32)];
        cmp_r0$b = e[(32'h0)+:(32)];
        cmp_r0$valid_in = valid_in;
        cmp_l1$clock = clock;
        cmp_l1$a = dl[(32'h20)+:(32)];
        cmp_l1$b = e[(32'h20)+:(32)];
        cmp_l1$valid_in = valid_in;
        cmp_r1$clock = clock;
        cmp_r1$a = dr[(32'h20)+:(32)];
        cmp_r1$b = e[(32'h20)+:(32)];
        cmp_r1$valid_in = valid_in;
        cmp_l2$clock = clock;
        cmp_l2$a = dl[(32'h40)+:(32)];
        cmp_l2$b = e[(32'h40)+:(32)];
        cmp_l2$valid_in = valid_in;
        cmp_r2$clock = clock;
        cmp_r2$a = dr[(32'h40)+:(32)];
        cmp_r2$b = e[(32'h40)+:(32)];
        cmp_r2$valid_in = valid_in;
        cmp_l3$clock = clock;
        cmp_l3$a = dl[(32'h60)+:(32)];
        cmp_l3$b = e[(32'h60)+:(32)];
        cmp_l3$valid_in = valid_in;
        cmp_r3$clock = clock;
        cmp_r3$a = dr[(32'h60)+:(32)];
        cmp_r3$b = e[(32'h60)+:(32)];
        cmp_r3$valid_in = valid_in;
        cmp_l4$clock = clock;
        cmp_l4$a = dl[(32'h80)+:(32)];
        cmp_l4$b = e[(32'h80)+:(32)];
        cmp_l4$valid_in = valid_in;
        cmp_r4$clock = clock;
        cmp_r4$a = dr[(32'h80)+:(32)];
        cmp_r4$b = e[(32'h80)+:(32)];
        cmp_r4$valid_in = valid_in;
        cmp_l5$clock = clock;
        cmp_l5$a = dl[(32'ha0)+:(32)];
        cmp_l5$b = e[(32'ha0)+:(32)];
        cmp_l5$valid_in = valid_in;
        cmp_r5$clock = clock;
        cmp_r5$a = dr[(32'ha0)+:(32)];
        cmp_r5$b = e[(32'ha0)+:(32)];
        cmp_r5$valid_in = valid_in;
        cmp_l6$clock = clock;
        cmp_l6$a = dl[(32'hc0)+:(32)];
        cmp_l6$b = e[(32'hc0)+:(32)];
        cmp_l6$valid_in = valid_in;
        cmp_r6$clock = clock;
        cmp_r6$a = dr[(32'hc0)+:(32)];
        cmp_r6$b = e[(32'hc0)+:(32)];
        cmp_r6$valid_in = valid_in;
        cmp_l7$clock = clock;
        cmp_l7$a = dl[(32'he0)+:(32)];
        cmp_l7$b = e[(32'he0)+:(32)];
        cmp_l7$valid_in = valid_in;
        cmp_r7$clock = clock;
        cmp_r7$a = dr[(32'he0)+:(32)];
        cmp_r7$b = e[(32'he0)+:(32)];
        cmp_r7$valid_in = valid_in;
        s1_first$d = first;
        s1_lanes$d = lanes;
        c2_any_l = 1'b0;
        c2_any_r = 1'b0;
        if (cmp_l0$flag & s1_lanes$q[32'h0]) begin
            c2_any_l = 1'b1;
        end
        if (cmp_r0$flag & s1_lanes$q[32'h0]) begin
            c2_any_r = 1'b1;
        end
        if (cmp_l1$flag & s1_lanes$q[32'h1]) begin
            c2_any_l = 1'b1;
        end
        if (cmp_r1$flag & s1_lanes$q[32'h1]) begin
            c2_any_r = 1'b1;
        end
        if (cmp_l2$flag & s1_lanes$q[32'h2]) begin
            c2_any_l = 1'b1;
        end
        if (cmp_r2$flag & s1_lanes$q[32'h2]) begin
            c2_any_r = 1'b1;
        end
        if (cmp_l3$flag & s1_lanes$q[32'h3]) begin
            c2_any_l = 1'b1;
        end
        if (cmp_r3$flag & s1_lanes$q[32'h3]) begin
            c2_any_r = 1'b1;
        end
        if (cmp_l4$flag & s1_lanes$q[32'h4]) begin
            c2_any_l = 1'b1;
        end
        if (cmp_r4$flag & s1_lanes$q[32'h4]) begin
            c2_any_r = 1'b1;
        end
        if (cmp_l5$flag & s1_lanes$q[32'h5]) begin
            c2_any_l = 1'b1;
        end
        if (cmp_r5$flag & s1_lanes$q[32'h5]) begin
            c2_any_r = 1'b1;
        end
        if (cmp_l6$flag & s1_lanes$q[32'h6]) begin
            c2_any_l = 1'b1;
        end
        if (cmp_r6$flag & s1_lanes$q[32'h6]) begin
            c2_any_r = 1'b1;
        end
        if (cmp_l7$flag & s1_lanes$q[32'h7]) begin
            c2_any_l = 1'b1;
        end
        if (cmp_r7$flag & s1_lanes$q[32'h7]) begin
            c2_any_r = 1'b1;
        end
        s2_valid$d = cmp_l0$valid_out;
        if (cmp_l0$valid_out) begin
            s2_sep_l$d = c2_any_l | (s2_sep_l$q & ~s1_first$q);
            s2_sep_r$d = c2_any_r | (s2_sep_r$q & ~s1_first$q);
        end
        overlap_l = ~s2_sep_l$q;
        overlap_r = ~s2_sep_r$q;
        valid_out = s2_valid$q;
    end
    
endmodule // top$bank


module top$bank$cmp_l0(clock,a,b,valid_in,flag,valid_out);
    
    // Module arguments
    input wire  clock;
    input wire  [31:0] a;
    input wire  [31:0] b;
    input wire  valid_in;
    output reg  flag;
    output reg  valid_out;
    
    // Constant declarations
    localparam  c_inf = 31'h7f800000;
    
    // Stub signals
    reg  s1_flag$d;
    wire  s1_flag$q;
    reg  s1_flag$clock;
    reg  s1_valid$d;
    wire  s1_valid$q;
    reg  s1_valid$clock;
    
    // Local signals
    reg  [30:0] mag_a;
    reg  [30:0] mag_b;
    
    // Sub module instances
    top$bank$cmp_l0$s1_flag s1_flag(
        .d(s1_flag$d),
        .q(s1_flag$q),
        .clock(s1_flag$clock)
    );
    top$bank$cmp_l0$s1_flag s1_valid(
        .d(s1_valid$d),
        .q(s1_valid$q),
        .clock(s1_valid$clock)
    );
    
    // Update code
    always @(*) begin
        s1_flag$clock = clock;
        s1_valid$clock = clock;
        s1_flag$d = s1_flag$q;
        s1_valid$d = s1_valid$q;
        mag_a = a[(32'h0)+:(31)];
        mag_b = b[(32'h0)+:(31)];
        s1_flag$d = 1'b0;
        if ((mag_a <= c_inf) & (mag_b <= c_inf)) begin
            if (a[32'h1f] & b[32'h1f]) begin
                s1_flag$d = |mag_a | |mag_b;
            end
            if (a[32'h1f] & ~b[32'h1f]) begin
                s1_flag$d = mag_a > mag_b;
            end
            if (~a[32'h1f] & b[32'h1f]) begin
                s1_flag$d = mag_b > mag_a;
            end
        end
        s1_valid$d = valid_in;
        flag = s1_flag$q;
        valid_out = s1_valid$q;
    end
    
endmodule // top$bank$cmp_l0


module top$bank$cmp_l0$s1_flag(d,q,clock);
    
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
          
endmodule // top$bank$cmp_l0$s1_flag


module top$bank$s1_lanes(d,q,clock);
    
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
          
endmodule // top$bank$s1_lanes


module top$busy_r(d,q,clock);
    
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
          
endmodule // top$busy_r


module top$dot_l(clock,d0,d1,d2,c0,c1,c2,c,valid_in,round_up,u,valid_out);
    
    // Module arguments
    input wire  clock;
    input wire  [31:0] d0;
    input wire  [31:0] d1;
    input wire  [31:0] d2;
    input wire  [31:0] c0;
    input wire  [31:0] c1;
    input wire  [31:0] c2;
    input wire  [31:0] c;
    input wire  valid_in;
    input wire  round_up;
    output reg  [31:0] u;
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
    reg  s12_valid$d;
    wire  s12_valid$q;
    reg  s12_valid$clock;
    reg  [31:0] s12_u$d;
    wire  [31:0] s12_u$q;
    reg  s12_u$clock;
    
    // Sub module instances
    top$bank$cmp_l0$s1_flag s1_valid(
        .d(s1_valid$d),
        .q(s1_valid$q),
        .clock(s1_valid$clock)
    );
    top$dot_l$add_0$s3_y s1_d0(
        .d(s1_d0$d),
        .q(s1_d0$q),
        .clock(s1_d0$clock)
    );
    top$dot_l$add_0$s3_y s1_d1(
        .d(s1_d1$d),
        .q(s1_d1$q),
        .clock(s1_d1$clock)
    );
    top$dot_l$add_0$s3_y s1_d2(
        .d(s1_d2$d),
        .q(s1_d2$q),
        .clock(s1_d2$clock)
    );
    top$dot_l$add_0$s3_y s1_c0(
        .d(s1_c0$d),
        .q(s1_c0$q),
        .clock(s1_c0$clock)
    );
    top$dot_l$add_0$s3_y s1_c1(
        .d(s1_c1$d),
        .q(s1_c1$q),
        .clock(s1_c1$clock)
    );
    top$dot_l$add_0$s3_y s1_c2(
        .d(s1_c2$d),
        .q(s1_c2$q),
        .clock(s1_c2$clock)
    );
    top$dot_l$add_0$s3_y s1_c(
        .d(s1_c$d),
        .q(s1_c$q),
        .clock(s1_c$clock)
    );
    top$bank$cmp_l0$s1_flag s1_round(
        .d(s1_round$d),
        .q(s1_round$q),
        .clock(s1_round$clock)
    );
    top$dot_l$r_mul r_mul(
        .clock(r_mul$clock),
        .d(r_mul$d),
        .q(r_mul$q)
    );
    top$dot_l$r_mul r_sum(
        .clock(r_sum$clock),
        .d(r_sum$d),
        .q(r_sum$q)
    );
    top$dot_l$r_mul r_u(
        .clock(r_u$clock),
        .d(r_u$d),
        .q(r_u$q)
    );
    top$dot_l$mul_0 mul_0(
        .clock(mul_0$clock),
        .a(mul_0$a),
        .b(mul_0$b),
        .valid_in(mul_0$valid_in),
        .y(mul_0$y),
        .valid_out(mul_0$valid_out),
        .round_up(mul_0$round_up)
    );
    top$dot_l$mul_0 mul_1(
        .clock(mul_1$clock),
        .a(mul_1$a),
        .b(mul_1$b),
        .valid_in(mul_1$valid_in),
        .y(mul_1$y),
        .valid_out(mul_1$valid_out),
        .round_up(mul_1$round_up)
    );
    top$dot_l$mul_0 mul_2(
        .clock(mul_2$clock),
        .a(mul_2$a),
        .b(mul_2$b),
        .valid_in(mul_2$valid_in),
        .y(mul_2$y),
        .valid_out(mul_2$valid_out),
        .round_up(mul_2$round_up)
    );
    top$dot_l$add_0$s3_y c_2(
        .d(c_2$d),
        .q(c_2$q),
        .clock(c_2$clock)
    );
    top$dot_l$add_0$s3_y c_3(
        .d(c_3$d),
        .q(c_3$q),
        .clock(c_3$clock)
    );
    top$dot_l$add_0$s3_y c_4(
        .d(c_4$d),
        .q(c_4$q),
        .clock(c_4$clock)
    );
    top$dot_l$add_0$s3_y c_5(
        .d(c_5$d),
        .q(c_5$q),
        .clock(c_5$clock)
    );
    top$dot_l$add_0 add_0(
        .clock(add_0$clock),
        .a(add_0$a),
        .b(add_0$b),
        .sub(add_0$sub),
        .valid_in(add_0$valid_in),
        .y(add_0$y),
        .valid_out(add_0$valid_out),
        .round_up(add_0$round_up)
    );
    top$dot_l$add_0 add_1(
        .clock(add_1$clock),
        .a(add_1$a),
        .b(add_1$b),
        .sub(add_1$sub),
        .valid_in(add_1$valid_in),
        .y(add_1$y),
        .valid_out(add_1$valid_out),
        .round_up(add_1$round_up)
    );
    top$dot_l$add_0 add_2(
        .clock(add_2$clock),
        .a(add_2$a),
        .b(add_2$b),
        .sub(add_2$sub),
        .valid_in(add_2$valid_in),
        .y(add_2$y),
        .valid_out(add_2$valid_out),
        .round_up(add_2$round_up)
    );
    top$bank$cmp_l0$s1_flag s12_valid(
        .d(s12_valid$d),
        .q(s12_valid$q),
        .clock(s12_valid$clock)
    );
    top$dot_l$add_0$s3_y s12_u(
        .d(s12_u$d),
        .q(s12_u$q),
        .clock(s12_u$clock)
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
        s1_round$clock = clock;
        s1_valid$d = s1_valid$q;
        s1_d0$d = s1_d0$q;
        s1_d1$d = s1_d1$q;
        s1_d2$d = s1_d2$q;
        s1_c0$d = s1_c0$q;
        s1_c1$d = s1_c1$q;
        s1_c2$d = s1_c2$q;
        s1_c$d = s1_c$q;
        s1_round$d = s1_round$q;
        r_mul$clock = clock;
        r_sum$clock = clock;
        r_u$clock = clock;
        c_2$clock = clock;
        c_3$clock = clock;
        c_4$clock = clock;
        c_5$clock = clock;
        c_2$d = c_2$q;
        c_3$d = c_3$q;
        c_4$d = c_4$q;
        c_5$d = c_5$q;
        s12_valid$clock = clock;
        s12_u$clock = clock;
        s12_valid$d = s12_valid$q;
        s12_u$d = s12_u$q;
        mul_0$clock = clock;
        mul_1$clock = clock;
        mul_2$clock = clock;
        add_0$clock = clock;
        add_1$clock = clock;
        add_2$clock = clock;
        mul_0$round_up = r_mul$q;
        mul_1$round_up = r_mul$q;
        mul_2$round_up = r_mul$q;
        add_0$round_up = r_sum$q;
        add_1$round_up = r_sum$q;
        add_2$round_up = r_u$q;
        s1_valid$d = valid_in;
        s1_d0$d = d0;
        s1_d1$d = d1;
        s1_d2$d = d2;
        s1_c0$d = c0;
        s1_c1$d = c1;
        s1_c2$d = c2;
        s1_c$d = c;
        s1_round$d = round_up;
        r_mul$d = s1_round$q;
        r_sum$d = r_mul$q;
        r_u$d = r_sum$q;
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
        add_0$a = mul_0$y;
        add_0$b = mul_1$y;
        add_0$sub = 1'b0;
        add_0$valid_in = mul_0$valid_out;
        add_1$a = mul_2$y;
        add_1$b = c_5$q;
        add_1$sub = 1'b0;
        add_1$valid_in = mul_0$valid_out;
        add_2$a = add_0$y;
        add_2$b = add_1$y;
        add_2$sub = 1'b0;
        add_2$valid_in = add_0$valid_out;
        s12_valid$d = add_2$valid_out;
        s12_u$d = add_2$y;
        u = s12_u$q;
        valid_out = s12_valid$q;
    end
    
endmodule // top$dot_l


module top$dot_l$add_0(clock,a,b,sub,valid_in,y,valid_out,round_up);
    
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
    top$dot_l$add_0$unpack_a unpack_a(
        .x(unpack_a$x),
        .sign(unpack_a$sign),
        .exp(unpack_a$exp),
        .sig(unpack_a$sig),
        .is_zero(unpack_a$is_zero),
        .is_inf(unpack_a$is_inf),
        .is_nan(unpack_a$is_nan)
    );
    top$dot_l$add_0$unpack_a unpack_b(
        .x(unpack_b$x),
        .sign(unpack_b$sign),
        .exp(unpack_b$exp),
        .sig(unpack_b$sig),
        .is_zero(unpack_b$is_zero),
        .is_inf(unpack_b$is_inf),
        .is_nan(unpack_b$is_nan)
    );
    top$bank$cmp_l0$s1_flag s1_valid(
        .d(s1_valid$d),
        .q(s1_valid$q),
        .clock(s1_valid$clock)
    );
    top$bank$cmp_l0$s1_flag s1_nan(
        .d(s1_nan$d),
        .q(s1_nan$q),
        .clock(s1_nan$clock)
    );
    top$bank$cmp_l0$s1_flag s1_inf(
        .d(s1_inf$d),
        .q(s1_inf$q),
        .clock(s1_inf$clock)
    );
    top$bank$cmp_l0$s1_flag s1_inf_sign(
        .d(s1_inf_sign$d),
        .q(s1_inf_sign$q),
        .clock(s1_inf_sign$clock)
    );
    top$bank$cmp_l0$s1_flag s1_zero_sign(
        .d(s1_zero_sign$d),
        .q(s1_zero_sign$q),
        .clock(s1_zero_sign$clock)
    );
    top$bank$cmp_l0$s1_flag s1_sign(
        .d(s1_sign$d),
        .q(s1_sign$q),
        .clock(s1_sign$clock)
    );
    top$bank$cmp_l0$s1_flag s1_eff_sub(
        .d(s1_eff_sub$d),
        .q(s1_eff_sub$q),
        .clock(s1_eff_sub$clock)
    );
    top$bank$s1_lanes s1_exp(
        .d(s1_exp$d),
        .q(s1_exp$q),
        .clock(s1_exp$clock)
    );
    top$dot_l$add_0$s1_big s1_big(
        .d(s1_big$d),
        .q(s1_big$q),
        .clock(s1_big$clock)
    );
    top$dot_l$add_0$s1_big s1_small(
        .d(s1_small$d),
        .q(s1_small$q),
        .clock(s1_small$clock)
    );
    top$dot_l$add_0$norm norm(
        .x(norm$x),
        .y(norm$y),
        .lz(norm$lz)
    );
    top$bank$cmp_l0$s1_flag s2_valid(
        .d(s2_valid$d),
        .q(s2_valid$q),
        .clock(s2_valid$clock)
    );
    top$bank$cmp_l0$s1_flag s2_sign(
        .d(s2_sign$d),
        .q(s2_sign$q),
        .clock(s2_sign$clock)
    );
    top$bank$cmp_l0$s1_flag s2_nan(
        .d(s2_nan$d),
        .q(s2_nan$q),
        .clock(s2_nan$clock)
    );
    top$bank$cmp_l0$s1_flag s2_inf(
        .d(s2_inf$d),
        .q(s2_inf$q),
        .clock(s2_inf$clock)
    );
    top$bank$cmp_l0$s1_flag s2_zero(
        .d(s2_zero$d),
        .q(s2_zero$q),
        .clock(s2_zero$clock)
    );
    top$bank$cmp_l0$s1_flag s2_ovf(
        .d(s2_ovf$d),
        .q(s2_ovf$q),
        .clock(s2_ovf$clock)
    );
    top$bank$s1_lanes s2_efield(
        .d(s2_efield$d),
        .q(s2_efield$q),
        .clock(s2_efield$clock)
    );
    top$dot_l$add_0$s2_nm s2_nm(
        .d(s2_nm$d),
        .q(s2_nm$q),
        .clock(s2_nm$clock)
    );
    top$dot_l$add_0$round round(
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
    top$bank$cmp_l0$s1_flag s3_valid(
        .d(s3_valid$d),
        .q(s3_valid$q),
        .clock(s3_valid$clock)
    );
    top$dot_l$add_0$s3_y s3_y(
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
    
endmodule // top$dot_l$add_0


module top$dot_l$add_0$norm(x,y,lz);
    
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
    
endmodule // top$dot_l$add_0$norm


module top$dot_l$add_0$round(round_up,sign,nan,inf,zero,ovf,efield,nm,y);
    
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
    
endmodule // top$dot_l$add_0$round


module top$dot_l$add_0$s1_big(d,q,clock);
    
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
          
endmodule // top$dot_l$add_0$s1_big


module top$dot_l$add_0$s2_nm(d,q,clock);
    
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
          
endmodule // top$dot_l$add_0$s2_nm


module top$dot_l$add_0$s3_y(d,q,clock);
    
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
          
endmodule // top$dot_l$add_0$s3_y


module top$dot_l$add_0$unpack_a(x,sign,exp,sig,is_zero,is_inf,is_nan);
    
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
    
endmodule // top$dot_l$add_0$unpack_a


module top$dot_l$mul_0(clock,a,b,valid_in,y,valid_out,round_up);
    
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
    reg  [23:0] norm_a$x;
    wire  [23:0] norm_a$y;
    wire  [4:0] norm_a$lz;
    reg  [23:0] norm_b$x;
    wire  [23:0] norm_b$y;
    wire  [4:0] norm_b$lz;
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
    reg  [9:0] s1_exp$d;
    wire  [9:0] s1_exp$q;
    reg  s1_exp$clock;
    reg  [23:0] s1_sig_a$d;
    wire  [23:0] s1_sig_a$q;
    reg  s1_sig_a$clock;
    reg  [23:0] s1_sig_b$d;
    wire  [23:0] s1_sig_b$q;
    reg  s1_sig_b$clock;
    reg  [23:0] sig_mul$a;
    reg  [23:0] sig_mul$b;
    wire  [25:0] sig_mul$hi;
    wire  sig_mul$sticky;
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
    reg  [25:0] s2_hi$d;
    wire  [25:0] s2_hi$q;
    reg  s2_hi$clock;
    reg  s2_sticky$d;
    wire  s2_sticky$q;
    reg  s2_sticky$clock;
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
    reg  s3_ovf$d;
    wire  s3_ovf$q;
    reg  s3_ovf$clock;
    reg  [7:0] s3_efield$d;
    wire  [7:0] s3_efield$q;
    reg  s3_efield$clock;
    reg  [25:0] s3_nm$d;
    wire  [25:0] s3_nm$q;
    reg  s3_nm$clock;
    reg  round$round_up;
    reg  round$sign;
    reg  round$nan;
    reg  round$inf;
    reg  round$zero;
    reg  round$ovf;
    reg  [7:0] round$efield;
    reg  [25:0] round$nm;
    wire  [31:0] round$y;
    reg  s4_valid$d;
    wire  s4_valid$q;
    reg  s4_valid$clock;
    reg  [31:0] s4_y$d;
    wire  [31:0] s4_y$q;
    reg  s4_y$clock;
    
    // Local signals
    reg  [9:0] c1_exp;
    reg  c3_top;
    reg  [25:0] c3_nm;
    reg  [9:0] c3_exp;
    reg  [9:0] c3_shift;
    reg  [9:0] c3_shift_cap;
    reg  [25:0] c3_shifted;
    reg  [25:0] c3_back;
    reg  c3_lost;
    reg  [7:0] c3_efield;
    
    // Sub module instances
    top$dot_l$add_0$unpack_a unpack_a(
        .x(unpack_a$x),
        .sign(unpack_a$sign),
        .exp(unpack_a$exp),
        .sig(unpack_a$sig),
        .is_zero(unpack_a$is_zero),
        .is_inf(unpack_a$is_inf),
        .is_nan(unpack_a$is_nan)
    );
    top$dot_l$add_0$unpack_a unpack_b(
        .x(unpack_b$x),
        .sign(unpack_b$sign),
        .exp(unpack_b$exp),
        .sig(unpack_b$sig),
        .is_zero(unpack_b$is_zero),
        .is_inf(unpack_b$is_inf),
        .is_nan(unpack_b$is_nan)
    );
    top$dot_l$mul_0$norm_a norm_a(
        .x(norm_a$x),
        .y(norm_a$y),
        .lz(norm_a$lz)
    );
    top$dot_l$mul_0$norm_a norm_b(
        .x(norm_b$x),
        .y(norm_b$y),
        .lz(norm_b$lz)
    );
    top$bank$cmp_l0$s1_flag s1_valid(
        .d(s1_valid$d),
        .q(s1_valid$q),
        .clock(s1_valid$clock)
    );
    top$bank$cmp_l0$s1_flag s1_sign(
        .d(s1_sign$d),
        .q(s1_sign$q),
        .clock(s1_sign$clock)
    );
    top$bank$cmp_l0$s1_flag s1_nan(
        .d(s1_nan$d),
        .q(s1_nan$q),
        .clock(s1_nan$clock)
    );
    top$bank$cmp_l0$s1_flag s1_inf(
        .d(s1_inf$d),
        .q(s1_inf$q),
        .clock(s1_inf$clock)
    );
    top$bank$cmp_l0$s1_flag s1_zero(
        .d(s1_zero$d),
        .q(s1_zero$q),
        .clock(s1_zero$clock)
    );
    top$dot_l$mul_0$s1_exp s1_exp(
        .d(s1_exp$d),
        .q(s1_exp$q),
        .clock(s1_exp$clock)
    );
    top$dot_l$mul_0$s1_sig_a s1_sig_a(
        .d(s1_sig_a$d),
        .q(s1_sig_a$q),
        .clock(s1_sig_a$clock)
    );
    top$dot_l$mul_0$s1_sig_a s1_sig_b(
        .d(s1_sig_b$d),
        .q(s1_sig_b$q),
        .clock(s1_sig_b$clock)
    );
    top$dot_l$mul_0$sig_mul sig_mul(
        .a(sig_mul$a),
        .b(sig_mul$b),
        .hi(sig_mul$hi),
        .sticky(sig_mul$sticky)
    );
    top$bank$cmp_l0$s1_flag s2_valid(
        .d(s2_valid$d),
        .q(s2_valid$q),
        .clock(s2_valid$clock)
    );
    top$bank$cmp_l0$s1_flag s2_sign(
        .d(s2_sign$d),
        .q(s2_sign$q),
        .clock(s2_sign$clock)
    );
    top$bank$cmp_l0$s1_flag s2_nan(
        .d(s2_nan$d),
        .q(s2_nan$q),
        .clock(s2_nan$clock)
    );
    top$bank$cmp_l0$s1_flag s2_inf(
        .d(s2_inf$d),
        .q(s2_inf$q),
        .clock(s2_inf$clock)
    );
    top$bank$cmp_l0$s1_flag s2_zero(
        .d(s2_zero$d),
        .q(s2_zero$q),
        .clock(s2_zero$clock)
    );
    top$dot_l$mul_0$s1_exp s2_exp(
        .d(s2_exp$d),
        .q(s2_exp$q),
        .clock(s2_exp$clock)
    );
    top$dot_l$add_0$s2_nm s2_hi(
        .d(s2_hi$d),
        .q(s2_hi$q),
        .clock(s2_hi$clock)
    );
    top$bank$cmp_l0$s1_flag s2_sticky(
        .d(s2_sticky$d),
        .q(s2_sticky$q),
        .clock(s2_sticky$clock)
    );
    top$bank$cmp_l0$s1_flag s3_valid(
        .d(s3_valid$d),
        .q(s3_valid$q),
        .clock(s3_valid$clock)
    );
    top$bank$cmp_l0$s1_flag s3_sign(
        .d(s3_sign$d),
        .q(s3_sign$q),
        .clock(s3_sign$clock)
    );
    top$bank$cmp_l0$s1_flag s3_nan(
        .d(s3_nan$d),
        .q(s3_nan$q),
        .clock(s3_nan$clock)
    );
    top$bank$cmp_l0$s1_flag s3_inf(
        .d(s3_inf$d),
        .q(s3_inf$q),
        .clock(s3_inf$clock)
    );
    top$bank$cmp_l0$s1_flag s3_zero(
        .d(s3_zero$d),
        .q(s3_zero$q),
        .clock(s3_zero$clock)
    );
    top$bank$cmp_l0$s1_flag s3_ovf(
        .d(s3_ovf$d),
        .q(s3_ovf$q),
        .clock(s3_ovf$clock)
    );
    top$bank$s1_lanes s3_efield(
        .d(s3_efield$d),
        .q(s3_efield$q),
        .clock(s3_efield$clock)
    );
    top$dot_l$add_0$s2_nm s3_nm(
        .d(s3_nm$d),
        .q(s3_nm$q),
        .clock(s3_nm$clock)
    );
    top$dot_l$add_0$round round(
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
    top$bank$cmp_l0$s1_flag s4_valid(
        .d(s4_valid$d),
        .q(s4_valid$q),
        .clock(s4_valid$clock)
    );
    top$dot_l$add_0$s3_y s4_y(
        .d(s4_y$d),
        .q(s4_y$q),
        .clock(s4_y$clock)
    );
    
    // Update code
    always @(*) begin
        s1_valid$clock = clock;
        s1_sign$clock = clock;
        s1_nan$clock = clock;
        s1_inf$clock = clock;
        s1_zero$clock = clock;
        s1_exp$clock = clock;
        s1_sig_a$clock = clock;
        s1_sig_b$clock = clock;
        s1_valid$d = s1_valid$q;
        s1_sign$d = s1_sign$q;
        s1_nan$d = s1_nan$q;
        s1_inf$d = s1_inf$q;
        s1_zero$d = s1_zero$q;
        s1_exp$d = s1_exp$q;
        s1_sig_a$d = s1_sig_a$q;
        s1_sig_b$d = s1_sig_b$q;
        s2_valid$clock = clock;
        s2_sign$clock = clock;
        s2_nan$clock = clock;
        s2_inf$clock = clock;
        s2_zero$clock = clock;
        s2_exp$clock = clock;
        s2_hi$clock = clock;
        s2_sticky$clock = clock;
        s2_valid$d = s2_valid$q;
        s2_sign$d = s2_sign$q;
        s2_nan$d = s2_nan$q;
        s2_inf$d = s2_inf$q;
        s2_zero$d = s2_zero$q;
        s2_exp$d = s2_exp$q;
        s2_hi$d = s2_hi$q;
        s2_sticky$d = s2_sticky$q;
        s3_valid$clock = clock;
        s3_sign$clock = clock;
        s3_nan$clock = clock;
        s3_inf$clock = clock;
        s3_zero$clock = clock;
        s3_ovf$clock = clock;
        s3_efield$clock = clock;
        s3_nm$clock = clock;
        s3_valid$d = s3_valid$q;
        s3_sign$d = s3_sign$q;
        s3_nan$d = s3_nan$q;
        s3_inf$d = s3_inf$q;
        s3_zero$d = s3_zero$q;
        s3_ovf$d = s3_ovf$q;
        s3_efield$d = s3_efield$q;
        s3_nm$d = s3_nm$q;
        s4_valid$clock = clock;
        s4_y$clock = clock;
        s4_valid$d = s4_valid$q;
        s4_y$d = s4_y$q;
        unpack_a$x = a;
        unpack_b$x = b;
        norm_a$x = unpack_a$sig;
        norm_b$x = unpack_b$sig;
        c1_exp = ((unpack_a$exp) & 10'h3ff) + ((unpack_b$exp) & 10'h3ff) - ((norm_a$lz) & 10'h3ff) - ((norm_b$lz) & 10'h3ff) + c_exp_adj;
        s1_valid$d = valid_in;
        s1_sign$d = unpack_a$sign ^ unpack_b$sign;
        s1_nan$d = unpack_a$is_nan | unpack_b$is_nan | (unpack_a$is_inf & unpack_b$is_zero) | (unpack_a$is_zero & unpack_b$is_inf);
        s1_inf$d = unpack_a$is_inf | unpack_b$is_inf;
        s1_zero$d = unpack_a$is_zero | unpack_b$is_zero;
        s1_exp$d = c1_exp;
        s1_sig_a$d = norm_a$y;
        s1_sig_b$d = norm_b$y;
        sig_mul$a = s1_sig_a$q;
        sig_mul$b = s1_sig_b$q;
        s2_valid$d = s1_valid$q;
        s2_sign$d = s1_sign$q;
        s2_nan$d = s1_nan$q;
        s2_inf$d = s1_inf$q;
        s2_zero$d = s1_zero$q;
        s2_exp$d = s1_exp$q;
        s2_hi$d = sig_mul$hi;
        s2_sticky$d = sig_mul$sticky;
        c3_top = s2_hi$q[32'h18 + 32'h1];
        c3_nm = ((s2_hi$q << 32'h1) & ~(1 << (32'h0)) | ((s2_sticky$q) << (32'h0)));
        if (c3_top) begin
            c3_nm = (s2_hi$q & ~(1 << (32'h0)) | ((s2_hi$q[32'h0] | s2_sticky$q) << (32'h0)));
        end
        c3_exp = s2_exp$q + c3_top;
        c3_shift = 32'h0;
        if (c3_exp < c_exp_norm_min) begin
            c3_shift = c_exp_norm_min - c3_exp;
        end
        c3_shift_cap = c3_shift;
        if (c3_shift > c_shift_cap) begin
            c3_shift_cap = c_shift_cap;
        end
        c3_shifted = c3_nm >> c3_shift_cap;
        c3_back = c3_shifted << c3_shift_cap;
        c3_lost = c3_back != c3_nm;
        c3_efield = 32'h0;
        if (c3_shift == 32'h0) begin
            c3_efield = ((c3_exp - c_exp_ofs) & 8'hff);
        end
        s3_valid$d = s2_valid$q;
        s3_sign$d = s2_sign$q;
        s3_nan$d = s2_nan$q;
        s3_inf$d = s2_inf$q;
        s3_zero$d = s2_zero$q;
        s3_ovf$d = c3_exp >= c_exp_ovf;
        s3_efield$d = c3_efield;
        s3_nm$d = (c3_shifted & ~(1 << (32'h0)) | ((c3_shifted[32'h0] | c3_lost) << (32'h0)));
        round$round_up = round_up;
        round$sign = s3_sign$q;
        round$nan = s3_nan$q;
        round$inf = s3_inf$q;
        round$zero = s3_zero$q;
        round$ovf = s3_ovf$q;
        round$efield = s3_efield$q;
        round$nm = s3_nm$q;
        s4_valid$d = s3_valid$q;
        s4_y$d = round$y;
        y = s4_y$q;
        valid_out = s4_valid$q;
    end
    
endmodule // top$dot_l$mul_0


module top$dot_l$mul_0$norm_a(x,y,lz);
    
    // Module arguments
    input wire  [23:0] x;
    output reg  [23:0] y;
    output reg  [4:0] lz;
    
    // Local signals
    reg  z16;
    reg  z8;
    reg  z4;
    reg  z2;
    reg  z1;
    reg  [23:0] x16;
    reg  [23:0] x8;
    reg  [23:0] x4;
    reg  [23:0] x2;
    
    // Update code
    always @(*) begin
        z16 = x[(32'h8)+:(16)] == 32'h0;
        x16 = x;
        if (z16) begin
            x16 = x << 32'h10;
        end
        z8 = x16[(32'h10)+:(8)] == 32'h0;
        x8 = x16;
        if (z8) begin
            x8 = x16 << 32'h8;
        end
        z4 = x8[(32'h14)+:(4)] == 32'h0;
        x4 = x8;
        if (z4) begin
            x4 = x8 << 32'h4;
        end
        z2 = x4[(32'h16)+:(2)] == 32'h0;
        x2 = x4;
        if (z2) begin
            x2 = x4 << 32'h2;
        end
        z1 = ~x2[32'h17];
        y = x2;
        if (z1) begin
            y = x2 << 32'h1;
        end
        lz = (((((((32'h0) & 5'h1f) & ~(1 << (32'h4)) | ((z16) << (32'h4))) & ~(1 << (32'h3)) | ((z8) << (32'h3))) & ~(1 << (32'h2)) | ((z4) << (32'h2))) & ~(1 << (32'h1)) | ((z2) << (32'h1))) & ~(1 << (32'h0)) | ((z1) << (32'h0)));
    end
    
endmodule // top$dot_l$mul_0$norm_a


module top$dot_l$mul_0$s1_exp(d,q,clock);
    
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
          
endmodule // top$dot_l$mul_0$s1_exp


module top$dot_l$mul_0$s1_sig_a(d,q,clock);
    
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
          
endmodule // top$dot_l$mul_0$s1_sig_a


module top$dot_l$mul_0$sig_mul(a,b,hi,sticky);
    
    // Module arguments
    input wire  [23:0] a;
    input wire  [23:0] b;
    output reg  [25:0] hi;
    output reg  sticky;
    
    // Update code (custom)
    wire [47:0] prod;
    assign prod = a * b;
    always @(*) begin
        hi = prod[47:22];
        sticky = |prod[21:0];
    end
endmodule // top$dot_l$mul_0$sig_mul


module top$dot_l$r_mul(clock,d,q);
    
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
    
    // Sub module instances
    top$bank$cmp_l0$s1_flag line$0(
        .d(line$0$d),
        .q(line$0$q),
        .clock(line$0$clock)
    );
    top$bank$cmp_l0$s1_flag line$1(
        .d(line$1$d),
        .q(line$1$q),
        .clock(line$1$clock)
    );
    top$bank$cmp_l0$s1_flag line$2(
        .d(line$2$d),
        .q(line$2$q),
        .clock(line$2$clock)
    );
    
    // Update code
    always @(*) begin
        line$0$clock = clock;
        line$0$d = d;
        line$1$clock = clock;
        line$1$d = d;
        line$2$clock = clock;
        line$2$d = d;
        line$0$d = line$1$q;
        line$1$d = line$2$q;
        q = line$0$q;
    end
    
endmodule // top$dot_l$r_mul


module top$dprime(clock,wr_valid,wr_set,wr_lane,wr_l,wr_r,rd_set,rd_entry,dl,dr);
    
    // Module arguments
    input wire  clock;
    input wire  wr_valid;
    input wire  wr_set;
    input wire  [4:0] wr_lane;
    input wire  [31:0] wr_l;
    input wire  [31:0] wr_r;
    input wire  rd_set;
    input wire  [1:0] rd_entry;
    output reg  [255:0] dl;
    output reg  [255:0] dr;
    
    // Constant declarations
    localparam  c_half = 5'b1100;
    
    // Stub signals
    reg  [2:0] ram_l0$read_address;
    reg  ram_l0$read_clock;
    wire  [31:0] ram_l0$read_data;
    reg  [2:0] ram_l0$write_address;
    reg  ram_l0$write_clock;
    reg  [31:0] ram_l0$write_data;
    reg  ram_l0$write_enable;
    reg  [2:0] ram_r0$read_address;
    reg  ram_r0$read_clock;
    wire  [31:0] ram_r0$read_data;
    reg  [2:0] ram_r0$write_address;
    reg  ram_r0$write_clock;
    reg  [31:0] ram_r0$write_data;
    reg  ram_r0$write_enable;
    reg  [2:0] ram_l1$read_address;
    reg  ram_l1$read_clock;
    wire  [31:0] ram_l1$read_data;
    reg  [2:0] ram_l1$write_address;
    reg  ram_l1$write_clock;
    reg  [31:0] ram_l1$write_data;
    reg  ram_l1$write_enable;
    reg  [2:0] ram_r1$read_address;
    reg  ram_r1$read_clock;
    wire  [31:0] ram_r1$read_data;
    reg  [2:0] ram_r1$write_address;
    reg  ram_r1$write_clock;
    reg  [31:0] ram_r1$write_data;
    reg  ram_r1$write_enable;
    reg  [2:0] ram_l2$read_address;
    reg  ram_l2$read_clock;
    wire  [31:0] ram_l2$read_data;
    reg  [2:0] ram_l2$write_address;
    reg  ram_l2$write_clock;
    reg  [31:0] ram_l2$write_data;
    reg  ram_l2$write_enable;
    reg  [2:0] ram_r2$read_address;
    reg  ram_r2$read_clock;
    wire  [31:0] ram_r2$read_data;
    reg  [2:0] ram_r2$write_address;
    reg  ram_r2$write_clock;
    reg  [31:0] ram_r2$write_data;
    reg  ram_r2$write_enable;
    reg  [2:0] ram_l3$read_address;
    reg  ram_l3$read_clock;
    wire  [31:0] ram_l3$read_data;
    reg  [2:0] ram_l3$write_address;
    reg  ram_l3$write_clock;
    reg  [31:0] ram_l3$write_data;
    reg  ram_l3$write_enable;
    reg  [2:0] ram_r3$read_address;
    reg  ram_r3$read_clock;
    wire  [31:0] ram_r3$read_data;
    reg  [2:0] ram_r3$write_address;
    reg  ram_r3$write_clock;
    reg  [31:0] ram_r3$write_data;
    reg  ram_r3$write_enable;
    reg  [2:0] ram_l4$read_address;
    reg  ram_l4$read_clock;
    wire  [31:0] ram_l4$read_data;
    reg  [2:0] ram_l4$write_address;
    reg  ram_l4$write_clock;
    reg  [31:0] ram_l4$write_data;
    reg  ram_l4$write_enable;
    reg  [2:0] ram_r4$read_address;
    reg  ram_r4$read_clock;
    wire  [31:0] ram_r4$read_data;
    reg  [2:0] ram_r4$write_address;
    reg  ram_r4$write_clock;
    reg  [31:0] ram_r4$write_data;
    reg  ram_r4$write_enable;
    reg  [2:0] ram_l5$read_address;
    reg  ram_l5$read_clock;
    wire  [31:0] ram_l5$read_data;
    reg  [2:0] ram_l5$write_address;
    reg  ram_l5$write_clock;
    reg  [31:0] ram_l5$write_data;
    reg  ram_l5$write_enable;
    reg  [2:0] ram_r5$read_address;
    reg  ram_r5$read_clock;
    wire  [31:0] ram_r5$read_data;
    reg  [2:0] ram_r5$write_address;
    reg  ram_r5$write_clock;
    reg  [31:0] ram_r5$write_data;
    reg  ram_r5$write_enable;
    reg  [2:0] ram_l6$read_address;
    reg  ram_l6$read_clock;
    wire  [31:0] ram_l6$read_data;
    reg  [2:0] ram_l6$write_address;
    reg  ram_l6$write_clock;
    reg  [31:0] ram_l6$write_data;
    reg  ram_l6$write_enable;
    reg  [2:0] ram_r6$read_address;
    reg  ram_r6$read_clock;
    wire  [31:0] ram_r6$read_data;
    reg  [2:0] ram_r6$write_address;
    reg  ram_r6$write_clock;
    reg  [31:0] ram_r6$write_data;
    reg  ram_r6$write_enable;
    reg  [2:0] ram_l7$read_address;
    reg  ram_l7$read_clock;
    wire  [31:0] ram_l7$read_data;
    reg  [2:0] ram_l7$write_address;
    reg  ram_l7$write_clock;
    reg  [31:0] ram_l7$write_data;
    reg  ram_l7$write_enable;
    reg  [2:0] ram_r7$read_address;
    reg  ram_r7$read_clock;
    wire  [31:0] ram_r7$read_data;
    reg  [2:0] ram_r7$write_address;
    reg  ram_r7$write_clock;
    reg  [31:0] ram_r7$write_data;
    reg  ram_r7$write_enable;
    
    // Local signals
    reg  [4:0] pos;
    reg  [2:0] wr_addr;
    reg  [2:0] rd_addr;
    
    // Sub module instances
    top$dprime$ram_l0 ram_l0(
        .read_address(ram_l0$read_address),
        .read_clock(ram_l0$read_clock),
        .read_data(ram_l0$read_data),
        .write_address(ram_l0$write_address),
        .write_clock(ram_l0$write_clock),
        .write_data(ram_l0$write_data),
        .write_enable(ram_l0$write_enable)
    );
    top$dprime$ram_l0 ram_r0(
        .read_address(ram_r0$read_address),
        .read_clock(ram_r0$read_clock),
        .read_data(ram_r0$read_data),
        .write_address(ram_r0$write_address),
        .write_clock(ram_r0$write_clock),
        .write_data(ram_r0$write_data),
        .write_enable(ram_r0$write_enable)
    );
    top$dprime$ram_l0 ram_l1(
        .read_address(ram_l1$read_address),
        .read_clock(ram_l1$read_clock),
        .read_data(ram_l1$read_data),
        .write_address(ram_l1$write_address),
        .write_clock(ram_l1$write_clock),
        .write_data(ram_l1$write_data),
        .write_enable(ram_l1$write_enable)
    );
    top$dprime$ram_l0 ram_r1(
        .read_address(ram_r1$read_address),
        .read_clock(ram_r1$read_clock),
        .read_data(ram_r1$read_data),
        .write_address(ram_r1$write_address),
        .write_clock(ram_r1$write_clock),
        .write_data(ram_r1$write_data),
        .write_enable(ram_r1$write_enable)
    );
    top$dprime$ram_l0 ram_l2(
        .read_address(ram_l2$read_address),
        .read_clock(ram_l2$read_clock),
        .read_data(ram_l2$read_data),
        .write_address(ram_l2$write_address),
        .write_clock(ram_l2$write_clock),
        .write_data(ram_l2$write_data),
        .write_enable(ram_l2$write_enable)
    );
    top$dprime$ram_l0 ram_r2(
        .read_address(ram_r2$read_address),
        .read_clock(ram_r2$read_clock),
        .read_data(ram_r2$read_data),
        .write_address(ram_r2$write_address),
        .write_clock(ram_r2$write_clock),
        .write_data(ram_r2$write_data),
        .write_enable(ram_r2$write_enable)
    );
    top$dprime$ram_l0 ram_l3(
        .read_address(ram_l3$read_address),
        .read_clock(ram_l3$read_clock),
        .read_data(ram_l3$read_data),
        .write_address(ram_l3$write_address),
        .write_clock(ram_l3$write_clock),
        .write_data(ram_l3$write_data),
        .write_enable(ram_l3$write_enable)
    );
    top$dprime$ram_l0 ram_r3(
        .read_address(ram_r3$read_address),
        .read_clock(ram_r3$read_clock),
        .read_data(ram_r3$read_data),
        .write_address(ram_r3$write_address),
        .write_clock(ram_r3$write_clock),
        .write_data(ram_r3$write_data),
        .write_enable(ram_r3$write_enable)
    );
    top$dprime$ram_l0 ram_l4(
        .read_address(ram_l4$read_address),
        .read_clock(ram_l4$read_clock),
        .read_data(ram_l4$read_data),
        .write_address(ram_l4$write_address),
        .write_clock(ram_l4$write_clock),
        .write_data(ram_l4$write_data),
        .write_enable(ram_l4$write_enable)
    );
    top$dprime$ram_l0 ram_r4(
        .read_address(ram_r4$read_address),
        .read_clock(ram_r4$read_clock),
        .read_data(ram_r4$read_data),
        .write_address(ram_r4$write_address),
        .write_clock(ram_r4$write_clock),
        .write_data(ram_r4$write_data),
        .write_enable(ram_r4$write_enable)
    );
    top$dprime$ram_l0 ram_l5(
        .read_address(ram_l5$read_address),
        .read_clock(ram_l5$read_clock),
        .read_data(ram_l5$read_data),
        .write_address(ram_l5$write_address),
        .write_clock(ram_l5$write_clock),
        .write_data(ram_l5$write_data),
        .write_enable(ram_l5$write_enable)
    );
    top$dprime$ram_l0 ram_r5(
        .read_address(ram_r5$read_address),
        .read_clock(ram_r5$read_clock),
        .read_data(ram_r5$read_data),
        .write_address(ram_r5$write_address),
        .write_clock(ram_r5$write_clock),
        .write_data(ram_r5$write_data),
        .write_enable(ram_r5$write_enable)
    );
    top$dprime$ram_l0 ram_l6(
        .read_address(ram_l6$read_address),
        .read_clock(ram_l6$read_clock),
        .read_data(ram_l6$read_data),
        .write_address(ram_l6$write_address),
        .write_clock(ram_l6$write_clock),
        .write_data(ram_l6$write_data),
        .write_enable(ram_l6$write_enable)
    );
    top$dprime$ram_l0 ram_r6(
        .read_address(ram_r6$read_address),
        .read_clock(ram_r6$read_clock),
        .read_data(ram_r6$read_data),
        .write_address(ram_r6$write_address),
        .write_clock(ram_r6$write_clock),
        .write_data(ram_r6$write_data),
        .write_enable(ram_r6$write_enable)
    );
    top$dprime$ram_l0 ram_l7(
        .read_address(ram_l7$read_address),
        .read_clock(ram_l7$read_clock),
        .read_data(ram_l7$read_data),
        .write_address(ram_l7$write_address),
        .write_clock(ram_l7$write_clock),
        .write_data(ram_l7$write_data),
        .write_enable(ram_l7$write_enable)
    );
    top$dprime$ram_l0 ram_r7(
        .read_address(ram_r7$read_address),
        .read_clock(ram_r7$read_clock),
        .read_data(ram_r7$read_data),
        .write_address(ram_r7$write_address),
        .write_clock(ram_r7$write_clock),
        .write_data(ram_r7$write_data),
        .write_enable(ram_r7$write_enable)
    );
    
    // Update code
    always @(*) begin
        pos = wr_lane - c_half;
        if (wr_lane < c_half) begin
            pos = wr_lane + c_half;
        end
        wr_addr = ((pos[(32'h3)+:(2)]) & 3'h7) | (((wr_set) & 3'h7) << 32'h2);
        rd_addr = ((rd_entry) & 3'h7) | (((rd_set) & 3'h7) << 32'h2);
        ram_l0$read_clock = clock;
        ram_l0$write_clock = clock;
        ram_l0$read_address = rd_addr;
        ram_l0$write_address = wr_addr;
        ram_l0$write_data = wr_l;
        ram_l0$write_enable = wr_valid & (pos[(32'h0)+:(3)] == 32'h0);
        ram_r0$read_clock = clock;
        ram_r0$write_clock = clock;
        ram_r0$read_address = rd_addr;
        ram_r0$write_address = wr_addr;
        ram_r0$write_data = wr_r;
        ram_r0$write_enable = wr_valid & (pos[(32'h0)+:(3)] == 32'h0);
        ram_l1$read_clock = clock;
        ram_l1$write_clock = clock;
        ram_l1$read_address = rd_addr;
        ram_l1$write_address = wr_addr;
        ram_l1$write_data = wr_l;
        ram_l1$write_enable = wr_valid & (pos[(32'h0)+:(3)] == 32'h1);
        ram_r1$read_clock = clock;
        ram_r1$write_clock = clock;
        ram_r1$read_address = rd_addr;
        ram_r1$write_address = wr_addr;
        ram_r1$write_data = wr_r;
        ram_r1$write_enable = wr_valid & (pos[(32'h0)+:(3)] == 32'h1);
        ram_l2$read_clock = clock;
        ram_l2$write_clock = clock;
        ram_l2$read_address = rd_addr;
        ram_l2$write_address = wr_addr;
        ram_l2$write_data = wr_l;
        ram_l2$write_enable = wr_valid & (pos[(32'h0)+:(3)] == 32'h2);
        ram_r2$read_clock = clock;
        ram_r2$write_clock = clock;
        ram_r2$read_address = rd_addr;
        ram_r2$write_address = wr_addr;
        ram_r2$write_data = wr_r;
        ram_r2$write_enable = wr_valid & (pos[(32'h0)+:(3)] == 32'h2);
        ram_l3$read_clock = clock;
        ram_l3$write_clock = clock;
        ram_l3$read_address = rd_addr;
        ram_l3$write_address = wr_addr;
        ram_l3$write_data = wr_l;
        ram_l3$write_enable = wr_valid & (pos[(32'h0)+:(3)] == 32'h3);
        ram_r3$read_clock = clock;
        ram_r3$write_clock = clock;
        ram_r3$read_address = rd_addr;
        ram_r3$write_address = wr_addr;
        ram_r3$write_data = wr_r;
        ram_r3$write_enable = wr_valid & (pos[(32'h0)+:(3)] == 32'h3);
        ram_l4$read_clock = clock;
        ram_l4$write_clock = clock;
        ram_l4$read_address = rd_addr;
        ram_l4$write_address = wr_addr;
        ram_l4$write_data = wr_l;
        ram_l4$write_enable = wr_valid & (pos[(32'h0)+:(3)] == 32'h4);
        ram_r4$read_clock = clock;
        ram_r4$write_clock = clock;
        ram_r4$read_address = rd_addr;
        ram_r4$write_address = wr_addr;
        ram_r4$write_data = wr_r;
        ram_r4$write_enable = wr_valid & (pos[(32'h0)+:(3)] == 32'h4);
        ram_l5$read_clock = clock;
        ram_l5$write_clock = clock;
        ram_l5$read_address = rd_addr;
        ram_l5$write_address = wr_addr;
        ram_l5$write_data = wr_l;
        ram_l5$write_enable = wr_valid & (pos[(32'h0)+:(3)] == 32'h5);
        ram_r5$read_clock = clock;
        ram_r5$write_clock = clock;
        ram_r5$read_address = rd_addr;
        ram_r5$write_address = wr_addr;
        ram_r5$write_data = wr_r;
        ram_r5$write_enable = wr_valid & (pos[(32'h0)+:(3)] == 32'h5);
        ram_l6$read_clock = clock;
        ram_l6$write_clock = clock;
        ram_l6$read_address = rd_addr;
        ram_l6$write_address = wr_addr;
        ram_l6$write_data = wr_l;
        ram_l6$write_enable = wr_valid & (pos[(32'h0)+:(3)] == 32'h6);
        ram_r6$read_clock = clock;
        ram_r6$write_clock = clock;
        ram_r6$read_address = rd_addr;
        ram_r6$write_address = wr_addr;
        ram_r6$write_data = wr_r;
        ram_r6$write_enable = wr_valid & (pos[(32'h0)+:(3)] == 32'h6);
        ram_l7$read_clock = clock;
        ram_l7$write_clock = clock;
        ram_l7$read_address = rd_addr;
        ram_l7$write_address = wr_addr;
        ram_l7$write_data = wr_l;
        ram_l7$write_enable = wr_valid & (pos[(32'h0)+:(3)] == 32'h7);
        ram_r7$read_clock = clock;
        ram_r7$write_clock = clock;
        ram_r7$read_address = rd_addr;
        ram_r7$write_address = wr_addr;
        ram_r7$write_data = wr_r;
        ram_r7$write_enable = wr_valid & (pos[(32'h0)+:(3)] == 32'h7);
        dl = (((ram_l0$read_data) & 256'hffffffffffffffffffffffffffffffffffffffffffffffffffffffffffffffff) << 32'h0) | (((ram_l1$read_data) & 256'hffffffffffffffffffffffffffffffffffffffffffffffffffffffffffffffff) << 32'h20) | (((ram_l2$read_data) & 256'hffffffffffffffffffffffffffffffffffffffffffffffffffffffffffffffff) << 32'h40) | (((ram_l3$read_data) & 256'hffffffffffffffffffffffffffffffffffffffffffffffffffffffffffffffff) << 32'h60) | (((ram_l4$read_data) & 256'hffffffffffffffffffffffffffffffffffffffffffffffffffffffffffffffff) << 32'h80) | (((ram_l5$read_data) & 256'hffffffffffffffffffffffffffffffffffffffffffffffffffffffffffffffff) << 32'ha0) | (((ram_l6$read_data) & 256'hffffffffffffffffffffffffffffffffffffffffffffffffffffffffffffffff) << 32'hc0) | (((ram_l7$read_data) & 256'hffffffffffffffffffffffffffffffffffffffffffffffffffffffffffffffff) << 32'he0);
        dr = (((ram_r0$read_data) & 256'hffffffffffffffffffffffffffffffffffffffffffffffffffffffffffffffff) << 32'h0) | (((ram_r1$read_data) & 256'hffffffffffffffffffffffffffffffffffffffffffffffffffffffffffffffff) << 32'h20) | (((ram_r2$read_data) & 256'hffffffffffffffffffffffffffffffffffffffffffffffffffffffffffffffff) << 32'h40) | (((ram_r3$read_data) & 256'hffffffffffffffffffffffffffffffffffffffffffffffffffffffffffffffff) << 32'h60) | (((ram_r4$read_data) & 256'hffffffffffffffffffffffffffffffffffffffffffffffffffffffffffffffff) << 32'h80) | (((ram_r5$read_data) & 256'hffffffffffffffffffffffffffffffffffffffffffffffffffffffffffffffff) << 32'ha0) | (((ram_r6$read_data) & 256'hffffffffffffffffffffffffffffffffffffffffffffffffffffffffffffffff) << 32'hc0) | (((ram_r7$read_data) & 256'hffffffffffffffffffffffffffffffffffffffffffffffffffffffffffffffff) << 32'he0);
    end
    
endmodule // top$dprime


module top$dprime$ram_l0(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [2:0] read_address;
    input wire  read_clock;
    output reg  [31:0] read_data;
    input wire  [2:0] write_address;
    input wire  write_clock;
    input wire  [31:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    reg[31:0] mem[7:0];
    
    
    
    always @(posedge read_clock) begin
       read_data <= mem[read_address];
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address] <= write_data;
       end
    end
                
endmodule // top$dprime$ram_l0


module top$gen_cnt(d,q,clock);
    
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
          
endmodule // top$gen_cnt


module top$klm_l(d$0,d$1,d$2,d$3,d$4,d$5,d$6,d$7,d$8,d$9,d$10,d$11,d$12,d$13,d$14,d$15,d$16,d$17,d$18,d$19,d$20,d$21,d$22,d$23,j0$0,j1$0,j2$0,y0$0,y1$0,y2$0);
    
    // Module arguments
    input wire  [31:0] d$0;
    input wire  [31:0] d$1;
    input wire  [31:0] d$2;
    input wire  [31:0] d$3;
    input wire  [31:0] d$4;
    input wire  [31:0] d$5;
    input wire  [31:0] d$6;
    input wire  [31:0] d$7;
    input wire  [31:0] d$8;
    input wire  [31:0] d$9;
    input wire  [31:0] d$10;
    input wire  [31:0] d$11;
    input wire  [31:0] d$12;
    input wire  [31:0] d$13;
    input wire  [31:0] d$14;
    input wire  [31:0] d$15;
    input wire  [31:0] d$16;
    input wire  [31:0] d$17;
    input wire  [31:0] d$18;
    input wire  [31:0] d$19;
    input wire  [31:0] d$20;
    input wire  [31:0] d$21;
    input wire  [31:0] d$22;
    input wire  [31:0] d$23;
    input wire  [4:0] j0$0;
    input wire  [4:0] j1$0;
    input wire  [4:0] j2$0;
    output reg  [31:0] y0$0;
    output reg  [31:0] y1$0;
    output reg  [31:0] y2$0;
    
    // Constant declarations
    localparam  idx$0 = 5'b0;
    localparam  idx$1 = 5'b1;
    localparam  idx$2 = 5'b10;
    localparam  idx$3 = 5'b11;
    localparam  idx$4 = 5'b100;
    localparam  idx$5 = 5'b101;
    localparam  idx$6 = 5'b110;
    localparam  idx$7 = 5'b111;
    localparam  idx$8 = 5'b1000;
    localparam  idx$9 = 5'b1001;
    localparam  idx$10 = 5'b1010;
    localparam  idx$11 = 5'b1011;
    localparam  idx$12 = 5'b1100;
    localparam  idx$13 = 5'b1101;
    localparam  idx$14 = 5'b1110;
    localparam  idx$15 = 5'b1111;
    localparam  idx$16 = 5'b10000;
    localparam  idx$17 = 5'b10001;
    localparam  idx$18 = 5'b10010;
    localparam  idx$19 = 5'b10011;
    localparam  idx$20 = 5'b10100;
    localparam  idx$21 = 5'b10101;
    localparam  idx$22 = 5'b10110;
    localparam  idx$23 = 5'b10111;
    
    // Update code
    always @(*) begin
        y0$0 = 32'h0;
        y1$0 = 32'h0;
        y2$0 = 32'h0;
        if (j0$0 == idx$0) begin
            y0$0 = d$0;
        end
        if (j1$0 == idx$0) begin
            y1$0 = d$0;
        end
        if (j2$0 == idx$0) begin
            y2$0 = d$0;
        end
        if (j0$0 == idx$1) begin
            y0$0 = d$1;
        end
        if (j1$0 == idx$1) begin
            y1$0 = d$1;
        end
        if (j2$0 == idx$1) begin
            y2$0 = d$1;
        end
        if (j0$0 == idx$2) begin
            y0$0 = d$2;
        end
        if (j1$0 == idx$2) begin
            y1$0 = d$2;
        end
        if (j2$0 == idx$2) begin
            y2$0 = d$2;
        end
        if (j0$0 == idx$3) begin
            y0$0 = d$3;
        end
        if (j1$0 == idx$3) begin
            y1$0 = d$3;
        end
        if (j2$0 == idx$3) begin
            y2$0 = d$3;
        end
        if (j0$0 == idx$4) begin
            y0$0 = d$4;
        end
        if (j1$0 == idx$4) begin
            y1$0 = d$4;
        end
        if (j2$0 == idx$4) begin
            y2$0 = d$4;
        end
        if (j0$0 == idx$5) begin
            y0$0 = d$5;
        end
        if (j1$0 == idx$5) begin
            y1$0 = d$5;
        end
        if (j2$0 == idx$5) begin
            y2$0 = d$5;
        end
        if (j0$0 == idx$6) begin
            y0$0 = d$6;
        end
        if (j1$0 == idx$6) begin
            y1$0 = d$6;
        end
        if (j2$0 == idx$6) begin
            y2$0 = d$6;
        end
        if (j0$0 == idx$7) begin
            y0$0 = d$7;
        end
        if (j1$0 == idx$7) begin
            y1$0 = d$7;
        end
        if (j2$0 == idx$7) begin
            y2$0 = d$7;
        end
        if (j0$0 == idx$8) begin
            y0$0 = d$8;
        end
        if (j1$0 == idx$8) begin
            y1$0 = d$8;
        end
        if (j2$0 == idx$8) begin
            y2$0 = d$8;
        end
        if (j0$0 == idx$9) begin
            y0$0 = d$9;
        end
        if (j1$0 == idx$9) begin
            y1$0 = d$9;
        end
        if (j2$0 == idx$9) begin
            y2$0 = d$9;
        end
        if (j0$0 == idx$10) begin
            y0$0 = d$10;
        end
        if (j1$0 == idx$10) begin
            y1$0 = d$10;
        end
        if (j2$0 == idx$10) begin
            y2$0 = d$10;
        end
        if (j0$0 == idx$11) begin
            y0$0 = d$11;
        end
        if (j1$0 == idx$11) begin
            y1$0 = d$11;
        end
        if (j2$0 == idx$11) begin
            y2$0 = d$11;
        end
        if (j0$0 == idx$12) begin
            y0$0 = d$12;
        end
        if (j1$0 == idx$12) begin
            y1$0 = d$12;
        end
        if (j2$0 == idx$12) begin
            y2$0 = d$12;
        end
        if (j0$0 == idx$13) begin
            y0$0 = d$13;
        end
        if (j1$0 == idx$13) begin
            y1$0 = d$13;
        end
        if (j2$0 == idx$13) begin
            y2$0 = d$13;
        end
        if (j0$0 == idx$14) begin
            y0$0 = d$14;
        end
        if (j1$0 == idx$14) begin
            y1$0 = d$14;
        end
        if (j2$0 == idx$14) begin
            y2$0 = d$14;
        end
        if (j0$0 == idx$15) begin
            y0$0 = d$15;
        end
        if (j1$0 == idx$15) begin
            y1$0 = d$15;
        end
        if (j2$0 == idx$15) begin
            y2$0 = d$15;
        end
        if (j0$0 == idx$16) begin
            y0$0 = d$16;
        end
        if (j1$0 == idx$16) begin
            y1$0 = d$16;
        end
        if (j2$0 == idx$16) begin
            y2$0 = d$16;
        end
        if (j0$0 == idx$17) begin
            y0$0 = d$17;
        end
        if (j1$0 == idx$17) begin
            y1$0 = d$17;
        end
        if (j2$0 == idx$17) begin
            y2$0 = d$17;
        end
        if (j0$0 == idx$18) begin
            y0$0 = d$18;
        end
        if (j1$0 == idx$18) begin
            y1$0 = d$18;
        end
        if (j2$0 == idx$18) begin
            y2$0 = d$18;
        end
        if (j0$0 == idx$19) begin
            y0$0 = d$19;
        end
        if (j1$0 == idx$19) begin
            y1$0 = d$19;
        end
        if (j2$0 == idx$19) begin
            y2$0 = d$19;
        end
        if (j0$0 == idx$20) begin
            y0$0 = d$20;
        end
        if (j1$0 == idx$20) begin
            y1$0 = d$20;
        end
        if (j2$0 == idx$20) begin
            y2$0 = d$20;
        end
        if (j0$0 == idx$21) begin
            y0$0 = d$21;
        end
        if (j1$0 == idx$21) begin
            y1$0 = d$21;
        end
        if (j2$0 == idx$21) begin
            y2$0 = d$21;
        end
        if (j0$0 == idx$22) begin
            y0$0 = d$22;
        end
        if (j1$0 == idx$22) begin
            y1$0 = d$22;
        end
        if (j2$0 == idx$22) begin
            y2$0 = d$22;
        end
        if (j0$0 == idx$23) begin
            y0$0 = d$23;
        end
        if (j1$0 == idx$23) begin
            y1$0 = d$23;
        end
        if (j2$0 == idx$23) begin
            y2$0 = d$23;
        end
    end
    
endmodule // top$klm_l


module top$mmm$0(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [4:0] read_address;
    input wire  read_clock;
    output reg  [31:0] read_data;
    input wire  [4:0] write_address;
    input wire  write_clock;
    input wire  [31:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    reg[31:0] mem[31:0];
    
    
    
    always @(posedge read_clock) begin
       read_data <= mem[read_address];
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address] <= write_data;
       end
    end
                
endmodule // top$mmm$0


module top$sa_e(d,q,clock);
    
    // Module arguments
    input wire  [255:0] d;
    output reg  [255:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 256'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$sa_e


module top$wr_tag(clock,d,q);
    
    // Module arguments
    input wire  clock;
    input wire  [6:0] d;
    output reg  [6:0] q;
    
    // Stub signals
    reg  [6:0] line$0$d;
    wire  [6:0] line$0$q;
    reg  line$0$clock;
    reg  [6:0] line$1$d;
    wire  [6:0] line$1$q;
    reg  line$1$clock;
    reg  [6:0] line$2$d;
    wire  [6:0] line$2$q;
    reg  line$2$clock;
    reg  [6:0] line$3$d;
    wire  [6:0] line$3$q;
    reg  line$3$clock;
    reg  [6:0] line$4$d;
    wire  [6:0] line$4$q;
    reg  line$4$clock;
    reg  [6:0] line$5$d;
    wire  [6:0] line$5$q;
    reg  line$5$clock;
    reg  [6:0] line$6$d;
    wire  [6:0] line$6$q;
    reg  line$6$clock;
    reg  [6:0] line$7$d;
    wire  [6:0] line$7$q;
    reg  line$7$clock;
    reg  [6:0] line$8$d;
    wire  [6:0] line$8$q;
    reg  line$8$clock;
    reg  [6:0] line$9$d;
    wire  [6:0] line$9$q;
    reg  line$9$clock;
    reg  [6:0] line$10$d;
    wire  [6:0] line$10$q;
    reg  line$10$clock;
    reg  [6:0] line$11$d;
    wire  [6:0] line$11$q;
    reg  line$11$clock;
    
    // Sub module instances
    top$wr_tag$line$0 line$0(
        .d(line$0$d),
        .q(line$0$q),
        .clock(line$0$clock)
    );
    top$wr_tag$line$0 line$1(
        .d(line$1$d),
        .q(line$1$q),
        .clock(line$1$clock)
    );
    top$wr_tag$line$0 line$2(
        .d(line$2$d),
        .q(line$2$q),
        .clock(line$2$clock)
    );
    top$wr_tag$line$0 line$3(
        .d(line$3$d),
        .q(line$3$q),
        .clock(line$3$clock)
    );
    top$wr_tag$line$0 line$4(
        .d(line$4$d),
        .q(line$4$q),
        .clock(line$4$clock)
    );
    top$wr_tag$line$0 line$5(
        .d(line$5$d),
        .q(line$5$q),
        .clock(line$5$clock)
    );
    top$wr_tag$line$0 line$6(
        .d(line$6$d),
        .q(line$6$q),
        .clock(line$6$clock)
    );
    top$wr_tag$line$0 line$7(
        .d(line$7$d),
        .q(line$7$q),
        .clock(line$7$clock)
    );
    top$wr_tag$line$0 line$8(
        .d(line$8$d),
        .q(line$8$q),
        .clock(line$8$clock)
    );
    top$wr_tag$line$0 line$9(
        .d(line$9$d),
        .q(line$9$q),
        .clock(line$9$clock)
    );
    top$wr_tag$line$0 line$10(
        .d(line$10$d),
        .q(line$10$q),
        .clock(line$10$clock)
    );
    top$wr_tag$line$0 line$11(
        .d(line$11$d),
        .q(line$11$q),
        .clock(line$11$clock)
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
        line$6$clock = clock;
        line$6$d = d;
        line$7$clock = clock;
        line$7$d = d;
        line$8$clock = clock;
        line$8$d = d;
        line$9$clock = clock;
        line$9$d = d;
        line$10$clock = clock;
        line$10$d = d;
        line$11$clock = clock;
        line$11$d = d;
        line$0$d = line$1$q;
        line$1$d = line$2$q;
        line$2$d = line$3$q;
        line$3$d = line$4$q;
        line$4$d = line$5$q;
        line$5$d = line$6$q;
        line$6$d = line$7$q;
        line$7$d = line$8$q;
        line$8$d = line$9$q;
        line$9$d = line$10$q;
        line$10$d = line$11$q;
        q = line$0$q;
    end
    
endmodule // top$wr_tag


module top$wr_tag$line$0(d,q,clock);
    
    // Module arguments
    input wire  [6:0] d;
    output reg  [6:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 7'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$wr_tag$line$0
