

module top(clock,clear,append,wr_side,wr_ptr,read,next_list,level,branch,remaining,busy,done,rd_valid,rd_ptr,overflow);
    
    // Module arguments
    input wire  clock;
    input wire  clear;
    input wire  append;
    input wire  wr_side;
    input wire  [15:0] wr_ptr;
    input wire  read;
    input wire  next_list;
    output reg  [4:0] level;
    output reg  branch;
    output reg  [15:0] remaining;
    output reg  busy;
    output reg  done;
    output reg  rd_valid;
    output reg  [15:0] rd_ptr;
    output reg  overflow;
    
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
    localparam  idx$24 = 5'b11000;
    localparam  idx$25 = 5'b11001;
    localparam  idx$26 = 5'b11010;
    localparam  idx$27 = 5'b11011;
    localparam  idx$28 = 5'b11100;
    localparam  idx$29 = 5'b11101;
    localparam  idx$30 = 5'b11110;
    localparam  idx$31 = 5'b11111;
    localparam  cap = 16'h100;
    
    // Stub signals
    reg  [7:0] sram_l$read_address;
    reg  sram_l$read_clock;
    wire  [15:0] sram_l$read_data;
    reg  [7:0] sram_l$write_address;
    reg  sram_l$write_clock;
    reg  [15:0] sram_l$write_data;
    reg  sram_l$write_enable;
    reg  [7:0] sram_r$read_address;
    reg  sram_r$read_clock;
    wire  [15:0] sram_r$read_data;
    reg  [7:0] sram_r$write_address;
    reg  sram_r$write_clock;
    reg  [15:0] sram_r$write_data;
    reg  sram_r$write_enable;
    reg  [4:0] lvl$d;
    wire  [4:0] lvl$q;
    reg  lvl$clock;
    reg  [15:0] pos$d;
    wire  [15:0] pos$q;
    reg  pos$clock;
    reg  [15:0] rem$d;
    wire  [15:0] rem$q;
    reg  rem$clock;
    reg  cur_b$d;
    wire  cur_b$q;
    reg  cur_b$clock;
    reg  [15:0] wa_l$d;
    wire  [15:0] wa_l$q;
    reg  wa_l$clock;
    reg  [15:0] wa_r$d;
    wire  [15:0] wa_r$q;
    reg  wa_r$clock;
    reg  up$d;
    wire  up$q;
    reg  up$clock;
    reg  done_r$d;
    wire  done_r$q;
    reg  done_r$clock;
    reg  ovf$d;
    wire  ovf$q;
    reg  ovf$clock;
    reg  rd_v$d;
    wire  rd_v$q;
    reg  rd_v$clock;
    reg  rd_side$d;
    wire  rd_side$q;
    reg  rd_side$clock;
    reg  br$0$d;
    wire  br$0$q;
    reg  br$0$clock;
    reg  br$1$d;
    wire  br$1$q;
    reg  br$1$clock;
    reg  br$2$d;
    wire  br$2$q;
    reg  br$2$clock;
    reg  br$3$d;
    wire  br$3$q;
    reg  br$3$clock;
    reg  br$4$d;
    wire  br$4$q;
    reg  br$4$clock;
    reg  br$5$d;
    wire  br$5$q;
    reg  br$5$clock;
    reg  br$6$d;
    wire  br$6$q;
    reg  br$6$clock;
    reg  br$7$d;
    wire  br$7$q;
    reg  br$7$clock;
    reg  br$8$d;
    wire  br$8$q;
    reg  br$8$clock;
    reg  br$9$d;
    wire  br$9$q;
    reg  br$9$clock;
    reg  br$10$d;
    wire  br$10$q;
    reg  br$10$clock;
    reg  br$11$d;
    wire  br$11$q;
    reg  br$11$clock;
    reg  br$12$d;
    wire  br$12$q;
    reg  br$12$clock;
    reg  br$13$d;
    wire  br$13$q;
    reg  br$13$clock;
    reg  br$14$d;
    wire  br$14$q;
    reg  br$14$clock;
    reg  br$15$d;
    wire  br$15$q;
    reg  br$15$clock;
    reg  br$16$d;
    wire  br$16$q;
    reg  br$16$clock;
    reg  br$17$d;
    wire  br$17$q;
    reg  br$17$clock;
    reg  br$18$d;
    wire  br$18$q;
    reg  br$18$clock;
    reg  br$19$d;
    wire  br$19$q;
    reg  br$19$clock;
    reg  br$20$d;
    wire  br$20$q;
    reg  br$20$clock;
    reg  br$21$d;
    wire  br$21$q;
    reg  br$21$clock;
    reg  br$22$d;
    wire  br$22$q;
    reg  br$22$clock;
    reg  br$23$d;
    wire  br$23$q;
    reg  br$23$clock;
    reg  br$24$d;
    wire  br$24$q;
    reg  br$24$clock;
    reg  br$25$d;
    wire  br$25$q;
    reg  br$25$clock;
    reg  br$26$d;
    wire  br$26$q;
    reg  br$26$clock;
    reg  br$27$d;
    wire  br$27$q;
    reg  br$27$clock;
    reg  br$28$d;
    wire  br$28$q;
    reg  br$28$clock;
    reg  br$29$d;
    wire  br$29$q;
    reg  br$29$clock;
    reg  br$30$d;
    wire  br$30$q;
    reg  br$30$clock;
    reg  br$31$d;
    wire  br$31$q;
    reg  br$31$clock;
    reg  [15:0] start_l$0$d;
    wire  [15:0] start_l$0$q;
    reg  start_l$0$clock;
    reg  [15:0] start_l$1$d;
    wire  [15:0] start_l$1$q;
    reg  start_l$1$clock;
    reg  [15:0] start_l$2$d;
    wire  [15:0] start_l$2$q;
    reg  start_l$2$clock;
    reg  [15:0] start_l$3$d;
    wire  [15:0] start_l$3$q;
    reg  start_l$3$clock;
    reg  [15:0] start_l$4$d;
    wire  [15:0] start_l$4$q;
    reg  start_l$4$clock;
    reg  [15:0] start_l$5$d;
    wire  [15:0] start_l$5$q;
    reg  start_l$5$clock;
    reg  [15:0] start_l$6$d;
    wire  [15:0] start_l$6$q;
    reg  start_l$6$clock;
    reg  [15:0] start_l$7$d;
    wire  [15:0] start_l$7$q;
    reg  start_l$7$clock;
    reg  [15:0] start_l$8$d;
    wire  [15:0] start_l$8$q;
    reg  start_l$8$clock;
    reg  [15:0] start_l$9$d;
    wire  [15:0] start_l$9$q;
    reg  start_l$9$clock;
    reg  [15:0] start_l$10$d;
    wire  [15:0] start_l$10$q;
    reg  start_l$10$clock;
    reg  [15:0] start_l$11$d;
    wire  [15:0] start_l$11$q;
    reg  start_l$11$clock;
    reg  [15:0] start_l$12$d;
    wire  [15:0] start_l$12$q;
    reg  start_l$12$clock;
    reg  [15:0] start_l$13$d;
    wire  [15:0] start_l$13$q;
    reg  start_l$13$clock;
    reg  [15:0] start_l$14$d;
    wire  [15:0] start_l$14$q;
    reg  start_l$14$clock;
    reg  [15:0] start_l$15$d;
    wire  [15:0] start_l$15$q;
    reg  start_l$15$clock;
    reg  [15:0] start_l$16$d;
    wire  [15:0] start_l$16$q;
    reg  start_l$16$clock;
    reg  [15:0] start_l$17$d;
    wire  [15:0] start_l$17$q;
    reg  start_l$17$clock;
    reg  [15:0] start_l$18$d;
    wire  [15:0] start_l$18$q;
    reg  start_l$18$clock;
    reg  [15:0] start_l$19$d;
    wire  [15:0] start_l$19$q;
    reg  start_l$19$clock;
    reg  [15:0] start_l$20$d;
    wire  [15:0] start_l$20$q;
    reg  start_l$20$clock;
    reg  [15:0] start_l$21$d;
    wire  [15:0] start_l$21$q;
    reg  start_l$21$clock;
    reg  [15:0] start_l$22$d;
    wire  [15:0] start_l$22$q;
    reg  start_l$22$clock;
    reg  [15:0] start_l$23$d;
    wire  [15:0] start_l$23$q;
    reg  start_l$23$clock;
    reg  [15:0] start_l$24$d;
    wire  [15:0] start_l$24$q;
    reg  start_l$24$clock;
    reg  [15:0] start_l$25$d;
    wire  [15:0] start_l$25$q;
    reg  start_l$25$clock;
    reg  [15:0] start_l$26$d;
    wire  [15:0] start_l$26$q;
    reg  start_l$26$clock;
    reg  [15:0] start_l$27$d;
    wire  [15:0] start_l$27$q;
    reg  start_l$27$clock;
    reg  [15:0] start_l$28$d;
    wire  [15:0] start_l$28$q;
    reg  start_l$28$clock;
    reg  [15:0] start_l$29$d;
    wire  [15:0] start_l$29$q;
    reg  start_l$29$clock;
    reg  [15:0] start_l$30$d;
    wire  [15:0] start_l$30$q;
    reg  start_l$30$clock;
    reg  [15:0] start_l$31$d;
    wire  [15:0] start_l$31$q;
    reg  start_l$31$clock;
    reg  [15:0] start_r$0$d;
    wire  [15:0] start_r$0$q;
    reg  start_r$0$clock;
    reg  [15:0] start_r$1$d;
    wire  [15:0] start_r$1$q;
    reg  start_r$1$clock;
    reg  [15:0] start_r$2$d;
    wire  [15:0] start_r$2$q;
    reg  start_r$2$clock;
    reg  [15:0] start_r$3$d;
    wire  [15:0] start_r$3$q;
    reg  start_r$3$clock;
    reg  [15:0] start_r$4$d;
    wire  [15:0] start_r$4$q;
    reg  start_r$4$clock;
    reg  [15:0] start_r$5$d;
    wire  [15:0] start_r$5$q;
    reg  start_r$5$clock;
    reg  [15:0] start_r$6$d;
    wire  [15:0] start_r$6$q;
    reg  start_r$6$clock;
    reg  [15:0] start_r$7$d;
    wire  [15:0] start_r$7$q;
    reg  start_r$7$clock;
    reg  [15:0] start_r$8$d;
    wire  [15:0] start_r$8$q;
    reg  start_r$8$clock;
    reg  [15:0] start_r$9$d;
    wire  [15:0] start_r$9$q;
    reg  start_r$9$clock;
    reg  [15:0] start_r$10$d;
    wire  [15:0] start_r$10$q;
    reg  start_r$10$clock;
    reg  [15:0] start_r$11$d;
    wire  [15:0] start_r$11$q;
    reg  start_r$11$clock;
    reg  [15:0] start_r$12$d;
    wire  [15:0] start_r$12$q;
    reg  start_r$12$clock;
    reg  [15:0] start_r$13$d;
    wire  [15:0] start_r$13$q;
    reg  start_r$13$clock;
    reg  [15:0] start_r$14$d;
    wire  [15:0] start_r$14$q;
    reg  start_r$14$clock;
    reg  [15:0] start_r$15$d;
    wire  [15:0] start_r$15$q;
    reg  start_r$15$clock;
    reg  [15:0] start_r$16$d;
    wire  [15:0] start_r$16$q;
    reg  start_r$16$clock;
    reg  [15:0] start_r$17$d;
    wire  [15:0] start_r$17$q;
    reg  start_r$17$clock;
    reg  [15:0] start_r$18$d;
    wire  [15:0] start_r$18$q;
    reg  start_r$18$clock;
    reg  [15:0] start_r$19$d;
    wire  [15:0] start_r$19$q;
    reg  start_r$19$clock;
    reg  [15:0] start_r$20$d;
    wire  [15:0] start_r$20$q;
    reg  start_r$20$clock;
    reg  [15:0] start_r$21$d;
    wire  [15:0] start_r$21$q;
    reg  start_r$21$clock;
    reg  [15:0] start_r$22$d;
    wire  [15:0] start_r$22$q;
    reg  start_r$22$clock;
    reg  [15:0] start_r$23$d;
    wire  [15:0] start_r$23$q;
    reg  start_r$23$clock;
    reg  [15:0] start_r$24$d;
    wire  [15:0] start_r$24$q;
    reg  start_r$24$clock;
    reg  [15:0] start_r$25$d;
    wire  [15:0] start_r$25$q;
    reg  start_r$25$clock;
    reg  [15:0] start_r$26$d;
    wire  [15:0] start_r$26$q;
    reg  start_r$26$clock;
    reg  [15:0] start_r$27$d;
    wire  [15:0] start_r$27$q;
    reg  start_r$27$clock;
    reg  [15:0] start_r$28$d;
    wire  [15:0] start_r$28$q;
    reg  start_r$28$clock;
    reg  [15:0] start_r$29$d;
    wire  [15:0] start_r$29$q;
    reg  start_r$29$clock;
    reg  [15:0] start_r$30$d;
    wire  [15:0] start_r$30$q;
    reg  start_r$30$clock;
    reg  [15:0] start_r$31$d;
    wire  [15:0] start_r$31$q;
    reg  start_r$31$clock;
    reg  [15:0] len_l$0$d;
    wire  [15:0] len_l$0$q;
    reg  len_l$0$clock;
    reg  [15:0] len_l$1$d;
    wire  [15:0] len_l$1$q;
    reg  len_l$1$clock;
    reg  [15:0] len_l$2$d;
    wire  [15:0] len_l$2$q;
    reg  len_l$2$clock;
    reg  [15:0] len_l$3$d;
    wire  [15:0] len_l$3$q;
    reg  len_l$3$clock;
    reg  [15:0] len_l$4$d;
    wire  [15:0] len_l$4$q;
    reg  len_l$4$clock;
    reg  [15:0] len_l$5$d;
    wire  [15:0] len_l$5$q;
    reg  len_l$5$clock;
    reg  [15:0] len_l$6$d;
    wire  [15:0] len_l$6$q;
    reg  len_l$6$clock;
    reg  [15:0] len_l$7$d;
    wire  [15:0] len_l$7$q;
    reg  len_l$7$clock;
    reg  [15:0] len_l$8$d;
    wire  [15:0] len_l$8$q;
    reg  len_l$8$clock;
    reg  [15:0] len_l$9$d;
    wire  [15:0] len_l$9$q;
    reg  len_l$9$clock;
    reg  [15:0] len_l$10$d;
    wire  [15:0] len_l$10$q;
    reg  len_l$10$clock;
    reg  [15:0] len_l$11$d;
    wire  [15:0] len_l$11$q;
    reg  len_l$11$clock;
    reg  [15:0] len_l$12$d;
    wire  [15:0] len_l$12$q;
    reg  len_l$12$clock;
    reg  [15:0] len_l$13$d;
    wire  [15:0] len_l$13$q;
    reg  len_l$13$clock;
    reg  [15:0] len_l$14$d;
    wire  [15:0] len_l$14$q;
    reg  len_l$14$clock;
    reg  [15:0] len_l$15$d;
    wire  [15:0] len_l$15$q;
    reg  len_l$15$clock;
    reg  [15:0] len_l$16$d;
    wire  [15:0] len_l$16$q;
    reg  len_l$16$clock;
    reg  [15:0] len_l$17$d;
    wire  [15:0] len_l$17$q;
    reg  len_l$17$clock;
    reg  [15:0] len_l$18$d;
    wire  [15:0] len_l$18$q;
    reg  len_l$18$clock;
    reg  [15:0] len_l$19$d;
    wire  [15:0] len_l$19$q;
    reg  len_l$19$clock;
    reg  [15:0] len_l$20$d;
    wire  [15:0] len_l$20$q;
    reg  len_l$20$clock;
    reg  [15:0] len_l$21$d;
    wire  [15:0] len_l$21$q;
    reg  len_l$21$clock;
    reg  [15:0] len_l$22$d;
    wire  [15:0] len_l$22$q;
    reg  len_l$22$clock;
    reg  [15:0] len_l$23$d;
    wire  [15:0] len_l$23$q;
    reg  len_l$23$clock;
    reg  [15:0] len_l$24$d;
    wire  [15:0] len_l$24$q;
    reg  len_l$24$clock;
    reg  [15:0] len_l$25$d;
    wire  [15:0] len_l$25$q;
    reg  len_l$25$clock;
    reg  [15:0] len_l$26$d;
    wire  [15:0] len_l$26$q;
    reg  len_l$26$clock;
    reg  [15:0] len_l$27$d;
    wire  [15:0] len_l$27$q;
    reg  len_l$27$clock;
    reg  [15:0] len_l$28$d;
    wire  [15:0] len_l$28$q;
    reg  len_l$28$clock;
    reg  [15:0] len_l$29$d;
    wire  [15:0] len_l$29$q;
    reg  len_l$29$clock;
    reg  [15:0] len_l$30$d;
    wire  [15:0] len_l$30$q;
    reg  len_l$30$clock;
    reg  [15:0] len_l$31$d;
    wire  [15:0] len_l$31$q;
    reg  len_l$31$clock;
    reg  [15:0] len_r$0$d;
    wire  [15:0] len_r$0$q;
    reg  len_r$0$clock;
    reg  [15:0] len_r$1$d;
    wire  [15:0] len_r$1$q;
    reg  len_r$1$clock;
    reg  [15:0] len_r$2$d;
    wire  [15:0] len_r$2$q;
    reg  len_r$2$clock;
    reg  [15:0] len_r$3$d;
    wire  [15:0] len_r$3$q;
    reg  len_r$3$clock;
    reg  [15:0] len_r$4$d;
    wire  [15:0] len_r$4$q;
    reg  len_r$4$clock;
    reg  [15:0] len_r$5$d;
    wire  [15:0] len_r$5$q;
    reg  len_r$5$clock;
    reg  [15:0] len_r$6$d;
    wire  [15:0] len_r$6$q;
    reg  len_r$6$clock;
    reg  [15:0] len_r$7$d;
    wire  [15:0] len_r$7$q;
    reg  len_r$7$clock;
    reg  [15:0] len_r$8$d;
    wire  [15:0] len_r$8$q;
    reg  len_r$8$clock;
    reg  [15:0] len_r$9$d;
    wire  [15:0] len_r$9$q;
    reg  len_r$9$clock;
    reg  [15:0] len_r$10$d;
    wire  [15:0] len_r$10$q;
    reg  len_r$10$clock;
    reg  [15:0] len_r$11$d;
    wire  [15:0] len_r$11$q;
    reg  len_r$11$clock;
    reg  [15:0] len_r$12$d;
    wire  [15:0] len_r$12$q;
    reg  len_r$12$clock;
    reg  [15:0] len_r$13$d;
    wire  [15:0] len_r$13$q;
    reg  len_r$13$clock;
    reg  [15:0] len_r$14$d;
    wire  [15:0] len_r$14$q;
    reg  len_r$14$clock;
    reg  [15:0] len_r$15$d;
    wire  [15:0] len_r$15$q;
    reg  len_r$15$clock;
    reg  [15:0] len_r$16$d;
    wire  [15:0] len_r$16$q;
    reg  len_r$16$clock;
    reg  [15:0] len_r$17$d;
    wire  [15:0] len_r$17$q;
    reg  len_r$17$clock;
    reg  [15:0] len_r$18$d;
    wire  [15:0] len_r$18$q;
    reg  len_r$18$clock;
    reg  [15:0] len_r$19$d;
    wire  [15:0] len_r$19$q;
    reg  len_r$19$clock;
    reg  [15:0] len_r$20$d;
    wire  [15:0] len_r$20$q;
    reg  len_r$20$clock;
    reg  [15:0] len_r$21$d;
    wire  [15:0] len_r$21$q;
    reg  len_r$21$clock;
    reg  [15:0] len_r$22$d;
    wire  [15:0] len_r$22$q;
    reg  len_r$22$clock;
    reg  [15:0] len_r$23$d;
    wire  [15:0] len_r$23$q;
    reg  len_r$23$clock;
    reg  [15:0] len_r$24$d;
    wire  [15:0] len_r$24$q;
    reg  len_r$24$clock;
    reg  [15:0] len_r$25$d;
    wire  [15:0] len_r$25$q;
    reg  len_r$25$clock;
    reg  [15:0] len_r$26$d;
    wire  [15:0] len_r$26$q;
    reg  len_r$26$clock;
    reg  [15:0] len_r$27$d;
    wire  [15:0] len_r$27$q;
    reg  len_r$27$clock;
    reg  [15:0] len_r$28$d;
    wire  [15:0] len_r$28$q;
    reg  len_r$28$clock;
    reg  [15:0] len_r$29$d;
    wire  [15:0] len_r$29$q;
    reg  len_r$29$clock;
    reg  [15:0] len_r$30$d;
    wire  [15:0] len_r$30$q;
    reg  len_r$30$clock;
    reg  [15:0] len_r$31$d;
    wire  [15:0] len_r$31$q;
    reg  len_r$31$clock;
    
    // Local signals
    reg  c_b_up;
    reg  [15:0] c_cs_l;
    reg  [15:0] c_cs_r;
    reg  [15:0] c_cl_l;
    reg  [15:0] c_cl_r;
    reg  [15:0] c_ns_l;
    reg  [15:0] c_ns_r;
    reg  [15:0] c_nl_l;
    reg  [15:0] c_nl_r;
    reg  [4:0] c_l1;
    reg  [15:0] c_cur_start;
    reg  [15:0] c_raddr;
    reg  c_idle;
    reg  c_read;
    reg  [15:0] c_waddr;
    reg  c_wok;
    reg  c_next;
    reg  c_desc;
    reg  c_desc_b;
    reg  c_u_right;
    reg  c_u_zero;
    reg  c_open;
    reg  [4:0] c_open_lvl;
    reg  [15:0] c_open_l;
    reg  [15:0] c_open_r;
    
    // Sub module instances
    top$sram_l sram_l(
        .read_address(sram_l$read_address),
        .read_clock(sram_l$read_clock),
        .read_data(sram_l$read_data),
        .write_address(sram_l$write_address),
        .write_clock(sram_l$write_clock),
        .write_data(sram_l$write_data),
        .write_enable(sram_l$write_enable)
    );
    top$sram_l sram_r(
        .read_address(sram_r$read_address),
        .read_clock(sram_r$read_clock),
        .read_data(sram_r$read_data),
        .write_address(sram_r$write_address),
        .write_clock(sram_r$write_clock),
        .write_data(sram_r$write_data),
        .write_enable(sram_r$write_enable)
    );
    top$lvl lvl(
        .d(lvl$d),
        .q(lvl$q),
        .clock(lvl$clock)
    );
    top$len_l$0 pos(
        .d(pos$d),
        .q(pos$q),
        .clock(pos$clock)
    );
    top$len_l$0 rem(
        .d(rem$d),
        .q(rem$q),
        .clock(rem$clock)
    );
    top$br$0 cur_b(
        .d(cur_b$d),
        .q(cur_b$q),
        .clock(cur_b$clock)
    );
    top$len_l$0 wa_l(
        .d(wa_l$d),
        .q(wa_l$q),
        .clock(wa_l$clock)
    );
    top$len_l$0 wa_r(
        .d(wa_r$d),
        .q(wa_r$q),
        .clock(wa_r$clock)
    );
    top$br$0 up(
        .d(up$d),
        .q(up$q),
        .clock(up$clock)
    );
    top$br$0 done_r(
        .d(done_r$d),
        .q(done_r$q),
        .clock(done_r$clock)
    );
    top$br$0 ovf(
        .d(ovf$d),
        .q(ovf$q),
        .clock(ovf$clock)
    );
    top$br$0 rd_v(
        .d(rd_v$d),
        .q(rd_v$q),
        .clock(rd_v$clock)
    );
    top$br$0 rd_side(
        .d(rd_side$d),
        .q(rd_side$q),
        .clock(rd_side$clock)
    );
    top$br$0 br$0(
        .d(br$0$d),
        .q(br$0$q),
        .clock(br$0$clock)
    );
    top$br$0 br$1(
        .d(br$1$d),
        .q(br$1$q),
        .clock(br$1$clock)
    );
    top$br$0 br$2(
        .d(br$2$d),
        .q(br$2$q),
        .clock(br$2$clock)
    );
    top$br$0 br$3(
        .d(br$3$d),
        .q(br$3$q),
        .clock(br$3$clock)
    );
    top$br$0 br$4(
        .d(br$4$d),
        .q(br$4$q),
        .clock(br$4$clock)
    );
    top$br$0 br$5(
        .d(br$5$d),
        .q(br$5$q),
        .clock(br$5$clock)
    );
    top$br$0 br$6(
        .d(br$6$d),
        .q(br$6$q),
        .clock(br$6$clock)
    );
    top$br$0 br$7(
        .d(br$7$d),
        .q(br$7$q),
        .clock(br$7$clock)
    );
    top$br$0 br$8(
        .d(br$8$d),
        .q(br$8$q),
        .clock(br$8$clock)
    );
    top$br$0 br$9(
        .d(br$9$d),
        .q(br$9$q),
        .clock(br$9$clock)
    );
    top$br$0 br$10(
        .d(br$10$d),
        .q(br$10$q),
        .clock(br$10$clock)
    );
    top$br$0 br$11(
        .d(br$11$d),
        .q(br$11$q),
        .clock(br$11$clock)
    );
    top$br$0 br$12(
        .d(br$12$d),
        .q(br$12$q),
        .clock(br$12$clock)
    );
    top$br$0 br$13(
        .d(br$13$d),
        .q(br$13$q),
        .clock(br$13$clock)
    );
    top$br$0 br$14(
        .d(br$14$d),
        .q(br$14$q),
        .clock(br$14$clock)
    );
    top$br$0 br$15(
        .d(br$15$d),
        .q(br$15$q),
        .clock(br$15$clock)
    );
    top$br$0 br$16(
        .d(br$16$d),
        .q(br$16$q),
        .clock(br$16$clock)
    );
    top$br$0 br$17(
        .d(br$17$d),
        .q(br$17$q),
        .clock(br$17$clock)
    );
    top$br$0 br$18(
        .d(br$18$d),
        .q(br$18$q),
        .clock(br$18$clock)
    );
    top$br$0 br$19(
        .d(br$19$d),
        .q(br$19$q),
        .clock(br$19$clock)
    );
    top$br$0 br$20(
        .d(br$20$d),
        .q(br$20$q),
        .clock(br$20$clock)
    );
    top$br$0 br$21(
        .d(br$21$d),
        .q(br$21$q),
        .clock(br$21$clock)
    );
    top$br$0 br$22(
        .d(br$22$d),
        .q(br$22$q),
        .clock(br$22$clock)
    );
    top$br$0 br$23(
        .d(br$23$d),
        .q(br$23$q),
        .clock(br$23$clock)
    );
    top$br$0 br$24(
        .d(br$24$d),
        .q(br$24$q),
        .clock(br$24$clock)
    );
    top$br$0 br$25(
        .d(br$25$d),
        .q(br$25$q),
        .clock(br$25$clock)
    );
    top$br$0 br$26(
        .d(br$26$d),
        .q(br$26$q),
        .clock(br$26$clock)
    );
    top$br$0 br$27(
        .d(br$27$d),
        .q(br$27$q),
        .clock(br$27$clock)
    );
    top$br$0 br$28(
        .d(br$28$d),
        .q(br$28$q),
        .clock(br$28$clock)
    );
    top$br$0 br$29(
        .d(br$29$d),
        .q(br$29$q),
        .clock(br$29$clock)
    );
    top$br$0 br$30(
        .d(br$30$d),
        .q(br$30$q),
        .clock(br$30$clock)
    );
    top$br$0 br$31(
        .d(br$31$d),
        .q(br$31$q),
        .clock(br$31$clock)
    );
    top$len_l$0 start_l$0(
        .d(start_l$0$d),
        .q(start_l$0$q),
        .clock(start_l$0$clock)
    );
    top$len_l$0 start_l$1(
        .d(start_l$1$d),
        .q(start_l$1$q),
        .clock(start_l$1$clock)
    );
    top$len_l$0 start_l$2(
        .d(start_l$2$d),
        .q(start_l$2$q),
        .clock(start_l$2$clock)
    );
    top$len_l$0 start_l$3(
        .d(start_l$3$d),
        .q(start_l$3$q),
        .clock(start_l$3$clock)
    );
    top$len_l$0 start_l$4(
        .d(start_l$4$d),
        .q(start_l$4$q),
        .clock(start_l$4$clock)
    );
    top$len_l$0 start_l$5(
        .d(start_l$5$d),
        .q(start_l$5$q),
        .clock(start_l$5$clock)
    );
    top$len_l$0 start_l$6(
        .d(start_l$6$d),
        .q(start_l$6$q),
        .clock(start_l$6$clock)
    );
    top$len_l$0 start_l$7(
        .d(start_l$7$d),
        .q(start_l$7$q),
        .clock(start_l$7$clock)
    );
    top$len_l$0 start_l$8(
        .d(start_l$8$d),
        .q(start_l$8$q),
        .clock(start_l$8$clock)
    );
    top$len_l$0 start_l$9(
        .d(start_l$9$d),
        .q(start_l$9$q),
        .clock(start_l$9$clock)
    );
    top$len_l$0 start_l$10(
        .d(start_l$10$d),
        .q(start_l$10$q),
        .clock(start_l$10$clock)
    );
    top$len_l$0 start_l$11(
        .d(start_l$11$d),
        .q(start_l$11$q),
        .clock(start_l$11$clock)
    );
    top$len_l$0 start_l$12(
        .d(start_l$12$d),
        .q(start_l$12$q),
        .clock(start_l$12$clock)
    );
    top$len_l$0 start_l$13(
        .d(start_l$13$d),
        .q(start_l$13$q),
        .clock(start_l$13$clock)
    );
    top$len_l$0 start_l$14(
        .d(start_l$14$d),
        .q(start_l$14$q),
        .clock(start_l$14$clock)
    );
    top$len_l$0 start_l$15(
        .d(start_l$15$d),
        .q(start_l$15$q),
        .clock(start_l$15$clock)
    );
    top$len_l$0 start_l$16(
        .d(start_l$16$d),
        .q(start_l$16$q),
        .clock(start_l$16$clock)
    );
    top$len_l$0 start_l$17(
        .d(start_l$17$d),
        .q(start_l$17$q),
        .clock(start_l$17$clock)
    );
    top$len_l$0 start_l$18(
        .d(start_l$18$d),
        .q(start_l$18$q),
        .clock(start_l$18$clock)
    );
    top$len_l$0 start_l$19(
        .d(start_l$19$d),
        .q(start_l$19$q),
        .clock(start_l$19$clock)
    );
    top$len_l$0 start_l$20(
        .d(start_l$20$d),
        .q(start_l$20$q),
        .clock(start_l$20$clock)
    );
    top$len_l$0 start_l$21(
        .d(start_l$21$d),
        .q(start_l$21$q),
        .clock(start_l$21$clock)
    );
    top$len_l$0 start_l$22(
        .d(start_l$22$d),
        .q(start_l$22$q),
        .clock(start_l$22$clock)
    );
    top$len_l$0 start_l$23(
        .d(start_l$23$d),
        .q(start_l$23$q),
        .clock(start_l$23$clock)
    );
    top$len_l$0 start_l$24(
        .d(start_l$24$d),
        .q(start_l$24$q),
        .clock(start_l$24$clock)
    );
    top$len_l$0 start_l$25(
        .d(start_l$25$d),
        .q(start_l$25$q),
        .clock(start_l$25$clock)
    );
    top$len_l$0 start_l$26(
        .d(start_l$26$d),
        .q(start_l$26$q),
        .clock(start_l$26$clock)
    );
    top$len_l$0 start_l$27(
        .d(start_l$27$d),
        .q(start_l$27$q),
        .clock(start_l$27$clock)
    );
    top$len_l$0 start_l$28(
        .d(start_l$28$d),
        .q(start_l$28$q),
        .clock(start_l$28$clock)
    );
    top$len_l$0 start_l$29(
        .d(start_l$29$d),
        .q(start_l$29$q),
        .clock(start_l$29$clock)
    );
    top$len_l$0 start_l$30(
        .d(start_l$30$d),
        .q(start_l$30$q),
        .clock(start_l$30$clock)
    );
    top$len_l$0 start_l$31(
        .d(start_l$31$d),
        .q(start_l$31$q),
        .clock(start_l$31$clock)
    );
    top$len_l$0 start_r$0(
        .d(start_r$0$d),
        .q(start_r$0$q),
        .clock(start_r$0$clock)
    );
    top$len_l$0 start_r$1(
        .d(start_r$1$d),
        .q(start_r$1$q),
        .clock(start_r$1$clock)
    );
    top$len_l$0 start_r$2(
        .d(start_r$2$d),
        .q(start_r$2$q),
        .clock(start_r$2$clock)
    );
    top$len_l$0 start_r$3(
        .d(start_r$3$d),
        .q(start_r$3$q),
        .clock(start_r$3$clock)
    );
    top$len_l$0 start_r$4(
        .d(start_r$4$d),
        .q(start_r$4$q),
        .clock(start_r$4$clock)
    );
    top$len_l$0 start_r$5(
        .d(start_r$5$d),
        .q(start_r$5$q),
        .clock(start_r$5$clock)
    );
    top$len_l$0 start_r$6(
        .d(start_r$6$d),
        .q(start_r$6$q),
        .clock(start_r$6$clock)
    );
    top$len_l$0 start_r$7(
        .d(start_r$7$d),
        .q(start_r$7$q),
        .clock(start_r$7$clock)
    );
    top$len_l$0 start_r$8(
        .d(start_r$8$d),
        .q(start_r$8$q),
        .clock(start_r$8$clock)
    );
    top$len_l$0 start_r$9(
        .d(start_r$9$d),
        .q(start_r$9$q),
        .clock(start_r$9$clock)
    );
    top$len_l$0 start_r$10(
        .d(start_r$10$d),
        .q(start_r$10$q),
        .clock(start_r$10$clock)
    );
    top$len_l$0 start_r$11(
        .d(start_r$11$d),
        .q(start_r$11$q),
        .clock(start_r$11$clock)
    );
    top$len_l$0 start_r$12(
        .d(start_r$12$d),
        .q(start_r$12$q),
        .clock(start_r$12$clock)
    );
    top$len_l$0 start_r$13(
        .d(start_r$13$d),
        .q(start_r$13$q),
        .clock(start_r$13$clock)
    );
    top$len_l$0 start_r$14(
        .d(start_r$14$d),
        .q(start_r$14$q),
        .clock(start_r$14$clock)
    );
    top$len_l$0 start_r$15(
        .d(start_r$15$d),
        .q(start_r$15$q),
        .clock(start_r$15$clock)
    );
    top$len_l$0 start_r$16(
        .d(start_r$16$d),
        .q(start_r$16$q),
        .clock(start_r$16$clock)
    );
    top$len_l$0 start_r$17(
        .d(start_r$17$d),
        .q(start_r$17$q),
        .clock(start_r$17$clock)
    );
    top$len_l$0 start_r$18(
        .d(start_r$18$d),
        .q(start_r$18$q),
        .clock(start_r$18$clock)
    );
    top$len_l$0 start_r$19(
        .d(start_r$19$d),
        .q(start_r$19$q),
        .clock(start_r$19$clock)
    );
    top$len_l$0 start_r$20(
        .d(start_r$20$d),
        .q(start_r$20$q),
        .clock(start_r$20$clock)
    );
    top$len_l$0 start_r$21(
        .d(start_r$21$d),
        .q(start_r$21$q),
        .clock(start_r$21$clock)
    );
    top$len_l$0 start_r$22(
        .d(start_r$22$d),
        .q(start_r$22$q),
        .clock(start_r$22$clock)
    );
    top$len_l$0 start_r$23(
        .d(start_r$23$d),
        .q(start_r$23$q),
        .clock(start_r$23$clock)
    );
    top$len_l$0 start_r$24(
        .d(start_r$24$d),
        .q(start_r$24$q),
        .clock(start_r$24$clock)
    );
    top$len_l$0 start_r$25(
        .d(start_r$25$d),
        .q(start_r$25$q),
        .clock(start_r$25$clock)
    );
    top$len_l$0 start_r$26(
        .d(start_r$26$d),
        .q(start_r$26$q),
        .clock(start_r$26$clock)
    );
    top$len_l$0 start_r$27(
        .d(start_r$27$d),
        .q(start_r$27$q),
        .clock(start_r$27$clock)
    );
    top$len_l$0 start_r$28(
        .d(start_r$28$d),
        .q(start_r$28$q),
        .clock(start_r$28$clock)
    );
    top$len_l$0 start_r$29(
        .d(start_r$29$d),
        .q(start_r$29$q),
        .clock(start_r$29$clock)
    );
    top$len_l$0 start_r$30(
        .d(start_r$30$d),
        .q(start_r$30$q),
        .clock(start_r$30$clock)
    );
    top$len_l$0 start_r$31(
        .d(start_r$31$d),
        .q(start_r$31$q),
        .clock(start_r$31$clock)
    );
    top$len_l$0 len_l$0(
        .d(len_l$0$d),
        .q(len_l$0$q),
        .clock(len_l$0$clock)
    );
    top$len_l$0 len_l$1(
        .d(len_l$1$d),
        .q(len_l$1$q),
        .clock(len_l$1$clock)
    );
    top$len_l$0 len_l$2(
        .d(len_l$2$d),
        .q(len_l$2$q),
        .clock(len_l$2$clock)
    );
    top$len_l$0 len_l$3(
        .d(len_l$3$d),
        .q(len_l$3$q),
        .clock(len_l$3$clock)
    );
    top$len_l$0 len_l$4(
        .d(len_l$4$d),
        .q(len_l$4$q),
        .clock(len_l$4$clock)
    );
    top$len_l$0 len_l$5(
        .d(len_l$5$d),
        .q(len_l$5$q),
        .clock(len_l$5$clock)
    );
    top$len_l$0 len_l$6(
        .d(len_l$6$d),
        .q(len_l$6$q),
        .clock(len_l$6$clock)
    );
    top$len_l$0 len_l$7(
        .d(len_l$7$d),
        .q(len_l$7$q),
        .clock(len_l$7$clock)
    );
    top$len_l$0 len_l$8(
        .d(len_l$8$d),
        .q(len_l$8$q),
        .clock(len_l$8$clock)
    );
    top$len_l$0 len_l$9(
        .d(len_l$9$d),
        .q(len_l$9$q),
        .clock(len_l$9$clock)
    );
    top$len_l$0 len_l$10(
        .d(len_l$10$d),
        .q(len_l$10$q),
        .clock(len_l$10$clock)
    );
    top$len_l$0 len_l$11(
        .d(len_l$11$d),
        .q(len_l$11$q),
        .clock(len_l$11$clock)
    );
    top$len_l$0 len_l$12(
        .d(len_l$12$d),
        .q(len_l$12$q),
        .clock(len_l$12$clock)
    );
    top$len_l$0 len_l$13(
        .d(len_l$13$d),
        .q(len_l$13$q),
        .clock(len_l$13$clock)
    );
    top$len_l$0 len_l$14(
        .d(len_l$14$d),
        .q(len_l$14$q),
        .clock(len_l$14$clock)
    );
    top$len_l$0 len_l$15(
        .d(len_l$15$d),
        .q(len_l$15$q),
        .clock(len_l$15$clock)
    );
    top$len_l$0 len_l$16(
        .d(len_l$16$d),
        .q(len_l$16$q),
        .clock(len_l$16$clock)
    );
    top$len_l$0 len_l$17(
        .d(len_l$17$d),
        .q(len_l$17$q),
        .clock(len_l$17$clock)
    );
    top$len_l$0 len_l$18(
        .d(len_l$18$d),
        .q(len_l$18$q),
        .clock(len_l$18$clock)
    );
    top$len_l$0 len_l$19(
        .d(len_l$19$d),
        .q(len_l$19$q),
        .clock(len_l$19$clock)
    );
    top$len_l$0 len_l$20(
        .d(len_l$20$d),
        .q(len_l$20$q),
        .clock(len_l$20$clock)
    );
    top$len_l$0 len_l$21(
        .d(len_l$21$d),
        .q(len_l$21$q),
        .clock(len_l$21$clock)
    );
    top$len_l$0 len_l$22(
        .d(len_l$22$d),
        .q(len_l$22$q),
        .clock(len_l$22$clock)
    );
    top$len_l$0 len_l$23(
        .d(len_l$23$d),
        .q(len_l$23$q),
        .clock(len_l$23$clock)
    );
    top$len_l$0 len_l$24(
        .d(len_l$24$d),
        .q(len_l$24$q),
        .clock(len_l$24$clock)
    );
    top$len_l$0 len_l$25(
        .d(len_l$25$d),
        .q(len_l$25$q),
        .clock(len_l$25$clock)
    );
    top$len_l$0 len_l$26(
        .d(len_l$26$d),
        .q(len_l$26$q),
        .clock(len_l$26$clock)
    );
    top$len_l$0 len_l$27(
        .d(len_l$27$d),
        .q(len_l$27$q),
        .clock(len_l$27$clock)
    );
    top$len_l$0 len_l$28(
        .d(len_l$28$d),
        .q(len_l$28$q),
        .clock(len_l$28$clock)
    );
    top$len_l$0 len_l$29(
        .d(len_l$29$d),
        .q(len_l$29$q),
        .clock(len_l$29$clock)
    );
    top$len_l$0 len_l$30(
        .d(len_l$30$d),
        .q(len_l$30$q),
        .clock(len_l$30$clock)
    );
    top$len_l$0 len_l$31(
        .d(len_l$31$d),
        .q(len_l$31$q),
        .clock(len_l$31$clock)
    );
    top$len_l$0 len_r$0(
        .d(len_r$0$d),
        .q(len_r$0$q),
        .clock(len_r$0$clock)
    );
    top$len_l$0 len_r$1(
        .d(len_r$1$d),
        .q(len_r$1$q),
        .clock(len_r$1$clock)
    );
    top$len_l$0 len_r$2(
        .d(len_r$2$d),
        .q(len_r$2$q),
        .clock(len_r$2$clock)
    );
    top$len_l$0 len_r$3(
        .d(len_r$3$d),
        .q(len_r$3$q),
        .clock(len_r$3$clock)
    );
    top$len_l$0 len_r$4(
        .d(len_r$4$d),
        .q(len_r$4$q),
        .clock(len_r$4$clock)
    );
    top$len_l$0 len_r$5(
        .d(len_r$5$d),
        .q(len_r$5$q),
        .clock(len_r$5$clock)
    );
    top$len_l$0 len_r$6(
        .d(len_r$6$d),
        .q(len_r$6$q),
        .clock(len_r$6$clock)
    );
    top$len_l$0 len_r$7(
        .d(len_r$7$d),
        .q(len_r$7$q),
        .clock(len_r$7$clock)
    );
    top$len_l$0 len_r$8(
        .d(len_r$8$d),
        .q(len_r$8$q),
        .clock(len_r$8$clock)
    );
    top$len_l$0 len_r$9(
        .d(len_r$9$d),
        .q(len_r$9$q),
        .clock(len_r$9$clock)
    );
    top$len_l$0 len_r$10(
        .d(len_r$10$d),
        .q(len_r$10$q),
        .clock(len_r$10$clock)
    );
    top$len_l$0 len_r$11(
        .d(len_r$11$d),
        .q(len_r$11$q),
        .clock(len_r$11$clock)
    );
    top$len_l$0 len_r$12(
        .d(len_r$12$d),
        .q(len_r$12$q),
        .clock(len_r$12$clock)
    );
    top$len_l$0 len_r$13(
        .d(len_r$13$d),
        .q(len_r$13$q),
        .clock(len_r$13$clock)
    );
    top$len_l$0 len_r$14(
        .d(len_r$14$d),
        .q(len_r$14$q),
        .clock(len_r$14$clock)
    );
    top$len_l$0 len_r$15(
        .d(len_r$15$d),
        .q(len_r$15$q),
        .clock(len_r$15$clock)
    );
    top$len_l$0 len_r$16(
        .d(len_r$16$d),
        .q(len_r$16$q),
        .clock(len_r$16$clock)
    );
    top$len_l$0 len_r$17(
        .d(len_r$17$d),
        .q(len_r$17$q),
        .clock(len_r$17$clock)
    );
    top$len_l$0 len_r$18(
        .d(len_r$18$d),
        .q(len_r$18$q),
        .clock(len_r$18$clock)
    );
    top$len_l$0 len_r$19(
        .d(len_r$19$d),
        .q(len_r$19$q),
        .clock(len_r$19$clock)
    );
    top$len_l$0 len_r$20(
        .d(len_r$20$d),
        .q(len_r$20$q),
        .clock(len_r$20$clock)
    );
    top$len_l$0 len_r$21(
        .d(len_r$21$d),
        .q(len_r$21$q),
        .clock(len_r$21$clock)
    );
    top$len_l$0 len_r$22(
        .d(len_r$22$d),
        .q(len_r$22$q),
        .clock(len_r$22$clock)
    );
    top$len_l$0 len_r$23(
        .d(len_r$23$d),
        .q(len_r$23$q),
        .clock(len_r$23$clock)
    );
    top$len_l$0 len_r$24(
        .d(len_r$24$d),
        .q(len_r$24$q),
        .clock(len_r$24$clock)
    );
    top$len_l$0 len_r$25(
        .d(len_r$25$d),
        .q(len_r$25$q),
        .clock(len_r$25$clock)
    );
    top$len_l$0 len_r$26(
        .d(len_r$26$d),
        .q(len_r$26$q),
        .clock(len_r$26$clock)
    );
    top$len_l$0 len_r$27(
        .d(len_r$27$d),
        .q(len_r$27$q),
        .clock(len_r$27$clock)
    );
    top$len_l$0 len_r$28(
        .d(len_r$28$d),
        .q(len_r$28$q),
        .clock(len_r$28$clock)
    );
    top$len_l$0 len_r$29(
        .d(len_r$29$d),
        .q(len_r$29$q),
        .clock(len_r$29$clock)
    );
    top$len_l$0 len_r$30(
        .d(len_r$30$d),
        .q(len_r$30$q),
        .clock(len_r$30$clock)
    );
    top$len_l$0 len_r$31(
        .d(len_r$31$d),
        .q(len_r$31$q),
        .clock(len_r$31$clock)
    );
    
    // Update code
    always @(*) begin
        ovf$clock = clock;
        rd_v$clock = clock;
        rd_side$clock = clock;
        ovf$d = ovf$q;
        rd_v$d = rd_v$q;
        rd_side$d = rd_side$q;
        c_l1 = lvl$q + 32'h1;
        c_b_up = 1'b0;
        c_cs_l = 32'h0;
        c_cs_r = 32'h0;
        c_cl_l = 32'h0;
        c_cl_r = 32'h0;
        c_ns_l = 32'h0;
        c_ns_r = 32'h0;
        c_nl_l = 32'h0;
        c_nl_r = 32'h0;
        if (lvl$q == idx$0) begin
            c_cs_l = start_l$0$q;
            c_cs_r = start_r$0$q;
            c_cl_l = len_l$0$q;
            c_cl_r = len_r$0$q;
        end
        if (lvl$q == idx$0 + 32'h1) begin
            c_b_up = br$0$q;
        end
        if ((c_l1 == idx$0) & (lvl$q != 32'h1f)) begin
            c_ns_l = start_l$0$q;
            c_ns_r = start_r$0$q;
            c_nl_l = len_l$0$q;
            c_nl_r = len_r$0$q;
        end
        if (lvl$q == idx$1) begin
            c_cs_l = start_l$1$q;
            c_cs_r = start_r$1$q;
            c_cl_l = len_l$1$q;
            c_cl_r = len_r$1$q;
        end
        if (lvl$q == idx$1 + 32'h1) begin
            c_b_up = br$1$q;
        end
        if ((c_l1 == idx$1) & (lvl$q != 32'h1f)) begin
            c_ns_l = start_l$1$q;
            c_ns_r = start_r$1$q;
            c_nl_l = len_l$1$q;
            c_nl_r = len_r$1$q;
        end
        if (lvl$q == idx$2) begin
            c_cs_l = start_l$2$q;
            c_cs_r = start_r$2$q;
            c_cl_l = len_l$2$q;
            c_cl_r = len_r$2$q;
        end
        if (lvl$q == idx$2 + 32'h1) begin
            c_b_up = br$2$q;
        end
        if ((c_l1 == idx$2) & (lvl$q != 32'h1f)) begin
            c_ns_l = start_l$2$q;
            c_ns_r = start_r$2$q;
            c_nl_l = len_l$2$q;
            c_nl_r = len_r$2$q;
        end
        if (lvl$q == idx$3) begin
            c_cs_l = start_l$3$q;
            c_cs_r = start_r$3$q;
            c_cl_l = len_l$3$q;
            c_cl_r = len_r$3$q;
        end
        if (lvl$q == idx$3 + 32'h1) begin
            c_b_up = br$3$q;
        end
        if ((c_l1 == idx$3) & (lvl$q != 32'h1f)) begin
            c_ns_l = start_l$3$q;
            c_ns_r = start_r$3$q;
            c_nl_l = len_l$3$q;
            c_nl_r = len_r$3$q;
        end
        if (lvl$q == idx$4) begin
            c_cs_l = start_l$4$q;
            c_cs_r = start_r$4$q;
            c_cl_l = len_l$4$q;
            c_cl_r = len_r$4$q;
        end
        if (lvl$q == idx$4 + 32'h1) begin
            c_b_up = br$4$q;
        end
        if ((c_l1 == idx$4) & (lvl$q != 32'h1f)) begin
            c_ns_l = start_l$4$q;
            c_ns_r = start_r$4$q;
            c_nl_l = len_l$4$q;
            c_nl_r = len_r$4$q;
        end
        if (lvl$q == idx$5) begin
            c_cs_l = start_l$5$q;
            c_cs_r = start_r$5$q;
            c_cl_l = len_l$5$q;
            c_cl_r = len_r$5$q;
        end
        if (lvl$q == idx$5 + 32'h1) begin
            c_b_up = br$5$q;
        end
        if ((c_l1 == idx$5) & (lvl$q != 32'h1f)) begin
            c_ns_l = start_l$5$q;
            c_ns_r = start_r$5$q;
            c_nl_l = len_l$5$q;
            c_nl_r = len_r$5$q;
        end
        if (lvl$q == idx$6) begin
            c_cs_l = start_l$6$q;
            c_cs_r = start_r$6$q;
            c_cl_l = len_l$6$q;
            c_cl_r = len_r$6$q;
        end
        if (lvl$q == idx$6 + 32'h1) begin
            c_b_up = br$6$q;
        end
        if ((c_l1 == idx$6) & (lvl$q != 32'h1f)) begin
            c_ns_l = start_l$6$q;
            c_ns_r = start_r$6$q;
            c_nl_l = len_l$6$q;
            c_nl_r = len_r$6$q;
        end
        if (lvl$q == idx$7) begin
            c_cs_l = start_l$7$q;
            c_cs_r = start_r$7$q;
            c_cl_l = len_l$7$q;
            c_cl_r = len_r$7$q;
        end
        if (lvl$q == idx$7 + 32'h1) begin
            c_b_up = br$7$q;
        end
        if ((c_l1 == idx$7) & (lvl$q != 32'h1f)) begin
            c_ns_l = start_l$7$q;
            c_ns_r = start_r$7$q;
            c_nl_l = len_l$7$q;
            c_nl_r = len_r$7$q;
        end
        if (lvl$q == idx$8) begin
            c_cs_l = start_l$8$q;
            c_cs_r = start_r$8$q;
            c_cl_l = len_l$8$q;
            c_cl_r = len_r$8$q;
        end
        if (lvl$q == idx$8 + 32'h1) begin
            c_b_up = br$8$q;
        end
        if ((c_l1 == idx$8) & (lvl$q != 32'h1f)) begin
            c_ns_l = start_l$8$q;
            c_ns_r = start_r$8$q;
            c_nl_l = len_l$8$q;
            c_nl_r = len_r$8$q;
        end
        if (lvl$q == idx$9) begin
            c_cs_l = start_l$9$q;
            c_cs_r = start_r$9$q;
            c_cl_l = len_l$9$q;
            c_cl_r = len_r$9$q;
        end
        if (lvl$q == idx$9 + 32'h1) begin
            c_b_up = br$9$q;
        end
        if ((c_l1 == idx$9) & (lvl$q != 32'h1f)) begin
            c_ns_l = start_l$9$q;
            c_ns_r = start_r$9$q;
            c_nl_l = len_l$9$q;
            c_nl_r = len_r$9$q;
        end
        if (lvl$q == idx$10) begin
            c_cs_l = start_l$10$q;
            c_cs_r = start_r$10$q;
            c_cl_l = len_l$10$q;
            c_cl_r = len_r$10$q;
        end
        if (lvl$q == idx$10 + 32'h1) begin
            c_b_up = br$10$q;
        end
        if ((c_l1 == idx$10) & (lvl$q != 32'h1f)) begin
            c_ns_l = start_l$10$q;
            c_ns_r = start_r$10$q;
            c_nl_l = len_l$10$q;
            c_nl_r = len_r$10$q;
        end
        if (lvl$q == idx$11) begin
            c_cs_l = start_l$11$q;
            c_cs_r = start_r$11$q;
            c_cl_l = len_l$11$q;
            c_cl_r = len_r$11$q;
        end
        if (lvl$q == idx$11 + 32'h1) begin
            c_b_up = br$11$q;
        end
        if ((c_l1 == idx$11) & (lvl$q != 32'h1f)) begin
            c_ns_l = start_l$11$q;
            c_ns_r = start_r$11$q;
            c_nl_l = len_l$11$q;
            c_nl_r = len_r$11$q;
        end
        if (lvl$q == idx$12) begin
            c_cs_l = start_l$12$q;
            c_cs_r = start_r$12$q;
            c_cl_l = len_l$12$q;
            c_cl_r = len_r$12$q;
        end
        if (lvl$q == idx$12 + 32'h1) begin
            c_b_up = br$12$q;
        end
        if ((c_l1 == idx$12) & (lvl$q != 32'h1f)) begin
            c_ns_l = start_l$12$q;
            c_ns_r = start_r$12$q;
            c_nl_l = len_l$12$q;
            c_nl_r = len_r$12$q;
        end
        if (lvl$q == idx$13) begin
            c_cs_l = start_l$13$q;
            c_cs_r = start_r$13$q;
            c_cl_l = len_l$13$q;
            c_cl_r = len_r$13$q;
        end
        if (lvl$q == idx$13 + 32'h1) begin
            c_b_up = br$13$q;
        end
        if ((c_l1 == idx$13) & (lvl$q != 32'h1f)) begin
            c_ns_l = start_l$13$q;
            c_ns_r = start_r$13$q;
            c_nl_l = len_l$13$q;
            c_nl_r = len_r$13$q;
        end
        if (lvl$q == idx$14) begin
            c_cs_l = start_l$14$q;
            c_cs_r = start_r$14$q;
            c_cl_l = len_l$14$q;
            c_cl_r = len_r$14$q;
        end
        if (lvl$q == idx$14 + 32'h1) begin
            c_b_up = br$14$q;
        end
        if ((c_l1 == idx$14) & (lvl$q != 32'h1f)) begin
            c_ns_l = start_l$14$q;
            c_ns_r = start_r$14$q;
            c_nl_l = len_l$14$q;
            c_nl_r = len_r$14$q;
        end
        if (lvl$q == idx$15) begin
            c_cs_l = start_l$15$q;
            c_cs_r = start_r$15$q;
            c_cl_l = len_l$15$q;
            c_cl_r = len_r$15$q;
        end
        if (lvl$q == idx$15 + 32'h1) begin
            c_b_up = br$15$q;
        end
        if ((c_l1 == idx$15) & (lvl$q != 32'h1f)) begin
            c_ns_l = start_l$15$q;
            c_ns_r = start_r$15$q;
            c_nl_l = len_l$15$q;
            c_nl_r = len_r$15$q;
        end
        if (lvl$q == idx$16) begin
            c_cs_l = start_l$16$q;
            c_cs_r = start_r$16$q;
            c_cl_l = len_l$16$q;
            c_cl_r = len_r$16$q;
        end
        if (lvl$q == idx$16 + 32'h1) begin
            c_b_up = br$16$q;
        end
        if ((c_l1 == idx$16) & (lvl$q != 32'h1f)) begin
            c_ns_l = start_l$16$q;
            c_ns_r = start_r$16$q;
            c_nl_l = len_l$16$q;
            c_nl_r = len_r$16$q;
        end
        if (lvl$q == idx$17) begin
            c_cs_l = start_l$17$q;
            c_cs_r = start_r$17$q;
            c_cl_l = len_l$17$q;
            c_cl_r = len_r$17$q;
        end
        if (lvl$q == idx$17 + 32'h1) begin
            c_b_up = br$17$q;
        end
        if ((c_l1 == idx$17) & (lvl$q != 32'h1f)) begin
            c_ns_l = start_l$17$q;
            c_ns_r = start_r$17$q;
            c_nl_l = len_l$17$q;
            c_nl_r = len_r$17$q;
        end
        if (lvl$q == idx$18) begin
            c_cs_l = start_l$18$q;
            c_cs_r = start_r$18$q;
            c_cl_l = len_l$18$q;
            c_cl_r = len_r$18$q;
        end
        if (lvl$q == idx$18 + 32'h1) begin
            c_b_up = br$18$q;
        end
        if ((c_l1 == idx$18) & (lvl$q != 32'h1f)) begin
            c_ns_l = start_l$18$q;
            c_ns_r = start_r$18$q;
            c_nl_l = len_l$18$q;
            c_nl_r = len_r$18$q;
        end
        if (lvl$q == idx$19) begin
            c_cs_l = start_l$19$q;
            c_cs_r = start_r$19$q;
            c_cl_l = len_l$19$q;
            c_cl_r = len_r$19$q;
        end
        if (lvl$q == idx$19 + 32'h1) begin
            c_b_up = br$19$q;
        end
        if ((c_l1 == idx$19) & (lvl$q != 32'h1f)) begin
            c_ns_l = start_l$19$q;
            c_ns_r = start_r$19$q;
            c_nl_l = len_l$19$q;
            c_nl_r = len_r$19$q;
        end
        if (lvl$q == idx$20) begin
            c_cs_l = start_l$20$q;
            c_cs_r = start_r$20$q;
            c_cl_l = len_l$20$q;
            c_cl_r = len_r$20$q;
        end
        if (lvl$q == idx$20 + 32'h1) begin
            c_b_up = br$20$q;
        end
        if ((c_l1 == idx$20) & (lvl$q != 32'h1f)) begin
            c_ns_l = start_l$20$q;
            c_ns_r = start_r$20$q;
            c_nl_l = len_l$20$q;
            c_nl_r = len_r$20$q;
        end
        if (lvl$q == idx$21) begin
            c_cs_l = start_l$21$q;
            c_cs_r = start_r$21$q;
            c_cl_l = len_l$21$q;
            c_cl_r = len_r$21$q;
        end
        if (lvl$q == idx$21 + 32'h1) begin
            c_b_up = br$21$q;
        end
        if ((c_l1 == idx$21) & (lvl$q != 32'h1f)) begin
            c_ns_l = start_l$21$q;
            c_ns_r = start_r$21$q;
            c_nl_l = len_l$21$q;
            c_nl_r = len_r$21$q;
        end
        if (lvl$q == idx$22) begin
            c_cs_l = start_l$22$q;
            c_cs_r = start_r$22$q;
            c_cl_l = len_l$22$q;
            c_cl_r = len_r$22$q;
        end
        if (lvl$q == idx$22 + 32'h1) begin
            c_b_up = br$22$q;
        end
        if ((c_l1 == idx$22) & (lvl$q != 32'h1f)) begin
            c_ns_l = start_l$22$q;
            c_ns_r = start_r$22$q;
            c_nl_l = len_l$22$q;
            c_nl_r = len_r$22$q;
        end
        if (lvl$q == idx$23) begin
            c_cs_l = start_l$23$q;
            c_cs_r = start_r$23$q;
            c_cl_l = len_l$23$q;
            c_cl_r = len_r$23$q;
        end
        if (lvl$q == idx$23 + 32'h1) begin
            c_b_up = br$23$q;
        end
        if ((c_l1 == idx$23) & (lvl$q != 32'h1f)) begin
            c_ns_l = start_l$23$q;
            c_ns_r = start_r$23$q;
            c_nl_l = len_l$23$q;
            c_nl_r = len_r$23$q;
        end
        if (lvl$q == idx$24) begin
            c_cs_l = start_l$24$q;
            c_cs_r = start_r$24$q;
            c_cl_l = len_l$24$q;
            c_cl_r = len_r$24$q;
        end
        if (lvl$q == idx$24 + 32'h1) begin
            c_b_up = br$24$q;
        end
        if ((c_l1 == idx$24) & (lvl$q != 32'h1f)) begin
            c_ns_l = start_l$24$q;
            c_ns_r = start_r$24$q;
            c_nl_l = len_l$24$q;
            c_nl_r = len_r$24$q;
        end
        if (lvl$q == idx$25) begin
            c_cs_l = start_l$25$q;
            c_cs_r = start_r$25$q;
            c_cl_l = len_l$25$q;
            c_cl_r = len_r$25$q;
        end
        if (lvl$q == idx$25 + 32'h1) begin
            c_b_up = br$25$q;
        end
        if ((c_l1 == idx$25) & (lvl$q != 32'h1f)) begin
            c_ns_l = start_l$25$q;
            c_ns_r = start_r$25$q;
            c_nl_l = len_l$25$q;
            c_nl_r = len_r$25$q;
        end
        if (lvl$q == idx$26) begin
            c_cs_l = start_l$26$q;
            c_cs_r = start_r$26$q;
            c_cl_l = len_l$26$q;
            c_cl_r = len_r$26$q;
        end
        if (lvl$q == idx$26 + 32'h1) begin
            c_b_up = br$26$q;
        end
        if ((c_l1 == idx$26) & (lvl$q != 32'h1f)) begin
            c_ns_l = start_l$26$q;
            c_ns_r = start_r$26$q;
            c_nl_l = len_l$26$q;
            c_nl_r = len_r$26$q;
        end
        if (lvl$q == idx$27) begin
            c_cs_l = start_l$27$q;
            c_cs_r = start_r$27$q;
            c_cl_l = len_l$27$q;
            c_cl_r = len_r$27$q;
        end
        if (lvl$q == idx$27 + 32'h1) begin
            c_b_up = br$27$q;
        end
        if ((c_l1 == idx$27) & (lvl$q != 32'h1f)) begin
            c_ns_l = start_l$27$q;
            c_ns_r = start_r$27$q;
            c_nl_l = len_l$27$q;
            c_nl_r = len_r$27$q;
        end
        if (lvl$q == idx$28) begin
            c_cs_l = start_l$28$q;
            c_cs_r = start_r$28$q;
            c_cl_l = len_l$28$q;
            c_cl_r = len_r$28$q;
        end
        if (lvl$q == idx$28 + 32'h1) begin
            c_b_up = br$28$q;
        end
        if ((c_l1 == idx$28) & (lvl$q != 32'h1f)) begin
            c_ns_l = start_l$28$q;
            c_ns_r = start_r$28$q;
            c_nl_l = len_l$28$q;
            c_nl_r = len_r$28$q;
        end
        if (lvl$q == idx$29) begin
            c_cs_l = start_l$29$q;
            c_cs_r = start_r$29$q;
            c_cl_l = len_l$29$q;
            c_cl_r = len_r$29$q;
        end
        if (lvl$q == idx$29 + 32'h1) begin
            c_b_up = br$29$q;
        end
        if ((c_l1 == idx$29) & (lvl$q != 32'h1f)) begin
            c_ns_l = start_l$29$q;
            c_ns_r = start_r$29$q;
            c_nl_l = len_l$29$q;
            c_nl_r = len_r$29$q;
        end
        if (lvl$q == idx$30) begin
            c_cs_l = start_l$30$q;
            c_cs_r = start_r$30$q;
            c_cl_l = len_l$30$q;
            c_cl_r = len_r$30$q;
        end
        if (lvl$q == idx$30 + 32'h1) begin
            c_b_up = br$30$q;
        end
        if ((c_l1 == idx$30) & (lvl$q != 32'h1f)) begin
            c_ns_l = start_l$30$q;
            c_ns_r = start_r$30$q;
            c_nl_l = len_l$30$q;
            c_nl_r = len_r$30$q;
        end
        if (lvl$q == idx$31) begin
            c_cs_l = start_l$31$q;
            c_cs_r = start_r$31$q;
            c_cl_l = len_l$31$q;
            c_cl_r = len_r$31$q;
        end
        if (lvl$q == idx$31 + 32'h1) begin
            c_b_up = br$31$q;
        end
        if ((c_l1 == idx$31) & (lvl$q != 32'h1f)) begin
            c_ns_l = start_l$31$q;
            c_ns_r = start_r$31$q;
            c_nl_l = len_l$31$q;
            c_nl_r = len_r$31$q;
        end
        c_idle = ~up$q & ~done_r$q;
        c_cur_start = c_cs_l;
        if (cur_b$q) begin
            c_cur_start = c_cs_r;
        end
        c_read = read & c_idle & (rem$q != 32'h0);
        c_waddr = wa_l$q;
        if (wr_side) begin
            c_waddr = wa_r$q;
        end
        c_wok = append & c_idle & (lvl$q != 32'h1f) & (c_waddr < cap);
        ovf$d = ovf$q | (append & c_idle & ~c_wok);
        sram_l$read_clock = clock;
        sram_r$read_clock = clock;
        sram_l$write_clock = clock;
        sram_r$write_clock = clock;
        c_raddr = c_cur_start + pos$q;
        sram_l$read_address = c_raddr[(32'h0)+:(8)];
        sram_r$read_address = c_raddr[(32'h0)+:(8)];
        sram_l$write_address = c_waddr[(32'h0)+:(8)];
        sram_r$write_address = c_waddr[(32'h0)+:(8)];
        sram_l$write_data = wr_ptr;
        sram_r$write_data = wr_ptr;
        sram_l$write_enable = c_wok & ~wr_side;
        sram_r$write_enable = c_wok & wr_side;
        rd_v$d = c_read;
        rd_side$d = cur_b$q;
        rd_ptr = 32'h0;
        if (rd_v$q) begin
            rd_ptr = sram_l$read_data;
            if (rd_side$q) begin
                rd_ptr = sram_r$read_data;
            end
        end
        lvl$clock = clock;
        pos$clock = clock;
        rem$clock = clock;
        cur_b$clock = clock;
        wa_l$clock = clock;
        wa_r$clock = clock;
        up$clock = clock;
        done_r$clock = clock;
        lvl$d = lvl$q;
        pos$d = pos$q;
        rem$d = rem$q;
        cur_b$d = cur_b$q;
        wa_l$d = wa_l$q;
        wa_r$d = wa_r$q;
        up$d = up$q;
        done_r$d = done_r$q;
        c_next = next_list & c_idle & ~append;
        c_desc = c_next & (lvl$q != 32'h1f) & ((c_nl_l != 32'h0) | (c_nl_r != 32'h0));
        c_desc_b = c_nl_l == 32'h0;
        c_u_right = up$q & ~cur_b$q & (c_cl_r != 32'h0);
        c_u_zero = lvl$q == 32'h0;
        c_open = (c_desc & (lvl$q < 32'h1e)) | (c_u_right & (lvl$q != 32'h1f));
        c_open_lvl = lvl$q + 32'h1;
        c_open_l = c_cs_l + c_cl_l;
        c_open_r = c_cs_r + c_cl_r;
        if (c_desc) begin
            c_open_lvl = lvl$q + 32'h2;
            c_open_l = wa_l$q;
            c_open_r = wa_r$q;
        end
        if (c_wok & ~wr_side) begin
            wa_l$d = wa_l$q + 32'h1;
        end
        if (c_wok & wr_side) begin
            wa_r$d = wa_r$q + 32'h1;
        end
        if (c_desc | c_u_right | (up$q & ~c_u_zero)) begin
            wa_l$d = c_open_l;
            wa_r$d = c_open_r;
        end
        if (c_read) begin
            pos$d = pos$q + 32'h1;
            rem$d = rem$q - 32'h1;
        end
        if (c_desc | c_u_right) begin
            pos$d = 32'h0;
        end
        if (c_desc) begin
            rem$d = c_nl_l;
            if (c_desc_b) begin
                rem$d = c_nl_r;
            end
        end
        if (c_u_right) begin
            rem$d = c_cl_r;
        end
        if (c_desc) begin
            lvl$d = c_l1;
            cur_b$d = c_desc_b;
        end
        if (c_u_right) begin
            cur_b$d = 1'b1;
        end
        if (up$q & ~c_u_right & ~c_u_zero) begin
            lvl$d = lvl$q - 32'h1;
            cur_b$d = c_b_up;
        end
        if (c_next & ~c_desc) begin
            up$d = 1'b1;
            pos$d = 32'h0;
        end
        if (up$q & (c_u_right | c_u_zero)) begin
            up$d = 1'b0;
            done_r$d = ~c_u_right;
        end
        br$0$clock = clock;
        start_l$0$clock = clock;
        start_r$0$clock = clock;
        len_l$0$clock = clock;
        len_r$0$clock = clock;
        br$0$d = br$0$q;
        start_l$0$d = start_l$0$q;
        start_r$0$d = start_r$0$q;
        len_l$0$d = len_l$0$q;
        len_r$0$d = len_r$0$q;
        if (c_l1 == idx$0) begin
            if (c_desc) begin
                br$0$d = c_desc_b;
            end
            if (c_wok & ~wr_side) begin
                len_l$0$d = len_l$0$q + 32'h1;
            end
            if (c_wok & wr_side) begin
                len_r$0$d = len_r$0$q + 32'h1;
            end
        end
        if (c_u_right & (lvl$q == idx$0)) begin
            br$0$d = 1'b1;
        end
        if (c_open & (c_open_lvl == idx$0)) begin
            start_l$0$d = c_open_l;
            start_r$0$d = c_open_r;
            len_l$0$d = 32'h0;
            len_r$0$d = 32'h0;
        end
        if (clear) begin
            br$0$d = 1'b0;
            start_l$0$d = 32'h0;
            start_r$0$d = 32'h0;
            len_l$0$d = 32'h0;
            len_r$0$d = 32'h0;
        end
        br$1$clock = clock;
        start_l$1$clock = clock;
        start_r$1$clock = clock;
        len_l$1$clock = clock;
        len_r$1$clock = clock;
        br$1$d = br$1$q;
        start_l$1$d = start_l$1$q;
        start_r$1$d = start_r$1$q;
        len_l$1$d = len_l$1$q;
        len_r$1$d = len_r$1$q;
        if (c_l1 == idx$1) begin
            if (c_desc) begin
                br$1$d = c_desc_b;
            end
            if (c_wok & ~wr_side) begin
                len_l$1$d = len_l$1$q + 32'h1;
            end
            if (c_wok & wr_side) begin
                len_r$1$d = len_r$1$q + 32'h1;
            end
        end
        if (c_u_right & (lvl$q == idx$1)) begin
            br$1$d = 1'b1;
        end
        if (c_open & (c_open_lvl == idx$1)) begin
            start_l$1$d = c_open_l;
            start_r$1$d = c_open_r;
            len_l$1$d = 32'h0;
            len_r$1$d = 32'h0;
        end
        if (clear) begin
            br$1$d = 1'b0;
            start_l$1$d = 32'h0;
            start_r$1$d = 32'h0;
            len_l$1$d = 32'h0;
            len_r$1$d = 32'h0;
        end
        br$2$clock = clock;
        start_l$2$clock = clock;
        start_r$2$clock = clock;
        len_l$2$clock = clock;
        len_r$2$clock = clock;
        br$2$d = br$2$q;
        start_l$2$d = start_l$2$q;
        start_r$2$d = start_r$2$q;
        len_l$2$d = len_l$2$q;
        len_r$2$d = len_r$2$q;
        if (c_l1 == idx$2) begin
            if (c_desc) begin
                br$2$d = c_desc_b;
            end
            if (c_wok & ~wr_side) begin
                len_l$2$d = len_l$2$q + 32'h1;
            end
            if (c_wok & wr_side) begin
                len_r$2$d = len_r$2$q + 32'h1;
            end
        end
        if (c_u_right & (lvl$q == idx$2)) begin
            br$2$d = 1'b1;
        end
        if (c_open & (c_open_lvl == idx$2)) begin
            start_l$2$d = c_open_l;
            start_r$2$d = c_open_r;
            len_l$2$d = 32'h0;
            len_r$2$d = 32'h0;
        end
        if (clear) begin
            br$2$d = 1'b0;
            start_l$2$d = 32'h0;
            start_r$2$d = 32'h0;
            len_l$2$d = 32'h0;
            len_r$2$d = 32'h0;
        end
        br$3$clock = clock;
        start_l$3$clock = clock;
        start_r$3$clock = clock;
        len_l$3$clock = clock;
        len_r$3$clock = clock;
        br$3$d = br$3$q;
        start_l$3$d = start_l$3$q;
        start_r$3$d = start_r$3$q;
        len_l$3$d = len_l$3$q;
        len_r$3$d = len_r$3$q;
        if (c_l1 == idx$3) begin
            if (c_desc) begin
                br$3$d = c_desc_b;
            end
            if (c_wok & ~wr_side) begin
                len_l$3$d = len_l$3$q + 32'h1;
            end
            if (c_wok & wr_side) begin
                len_r$3$d = len_r$3$q + 32'h1;
            end
        end
        if (c_u_right & (lvl$q == idx$3)) begin
            br$3$d = 1'b1;
        end
        if (c_open & (c_open_lvl == idx$3)) begin
            start_l$3$d = c_open_l;
            start_r$3$d = c_open_r;
            len_l$3$d = 32'h0;
            len_r$3$d = 32'h0;
        end
        if (clear) begin
            br$3$d = 1'b0;
            start_l$3$d = 32'h0;
            start_r$3$d = 32'h0;
            len_l$3$d = 32'h0;
            len_r$3$d = 32'h0;
        end
        br$4$clock = clock;
        start_l$4$clock = clock;
        start_r$4$clock = clock;
        len_l$4$clock = clock;
        len_r$4$clock = clock;
        br$4$d = br$4$q;
        start_l$4$d = start_l$4$q;
        start_r$4$d = start_r$4$q;
        len_l$4$d = len_l$4$q;
        len_r$4$d = len_r$4$q;
        if (c_l1 == idx$4) begin
            if (c_desc) begin
                br$4$d = c_desc_b;
            end
            if (c_wok & ~wr_side) begin
                len_l$4$d = len_l$4$q + 32'h1;
            end
            if (c_wok & wr_side) begin
                len_r$4$d = len_r$4$q + 32'h1;
            end
        end
        if (c_u_right & (lvl$q == idx$4)) begin
            br$4$d = 1'b1;
        end
        if (c_open & (c_open_lvl == idx$4)) begin
            start_l$4$d = c_open_l;
            start_r$4$d = c_open_r;
            len_l$4$d = 32'h0;
            len_r$4$d = 32'h0;
        end
        if (clear) begin
            br$4$d = 1'b0;
            start_l$4$d = 32'h0;
            start_r$4$d = 32'h0;
            len_l$4$d = 32'h0;
            len_r$4$d = 32'h0;
        end
        br$5$clock = clock;
        start_l$5$clock = clock;
        start_r$5$clock = clock;
        len_l$5$clock = clock;
        len_r$5$clock = clock;
        br$5$d = br$5$q;
        start_l$5$d = start_l$5$q;
        start_r$5$d = start_r$5$q;
        len_l$5$d = len_l$5$q;
        len_r$5$d = len_r$5$q;
        if (c_l1 == idx$5) begin
            if (c_desc) begin
                br$5$d = c_desc_b;
            end
            if (c_wok & ~wr_side) begin
                len_l$5$d = len_l$5$q + 32'h1;
            end
            if (c_wok & wr_side) begin
                len_r$5$d = len_r$5$q + 32'h1;
            end
        end
        if (c_u_right & (lvl$q == idx$5)) begin
            br$5$d = 1'b1;
        end
        if (c_open & (c_open_lvl == idx$5)) begin
            start_l$5$d = c_open_l;
            start_r$5$d = c_open_r;
            len_l$5$d = 32'h0;
            len_r$5$d = 32'h0;
        end
        if (clear) begin
            br$5$d = 1'b0;
            start_l$5$d = 32'h0;
            start_r$5$d = 32'h0;
            len_l$5$d = 32'h0;
            len_r$5$d = 32'h0;
        end
        br$6$clock = clock;
        start_l$6$clock = clock;
        start_r$6$clock = clock;
        len_l$6$clock = clock;
        len_r$6$clock = clock;
        br$6$d = br$6$q;
        start_l$6$d = start_l$6$q;
        start_r$6$d = start_r$6$q;
        len_l$6$d = len_l$6$q;
        len_r$6$d = len_r$6$q;
        if (c_l1 == idx$6) begin
            if (c_desc) begin
                br$6$d = c_desc_b;
            end
            if (c_wok & ~wr_side) begin
                len_l$6$d = len_l$6$q + 32'h1;
            end
            if (c_wok & wr_side) begin
                len_r$6$d = len_r$6$q + 32'h1;
            end
        end
        if (c_u_right & (lvl$q == idx$6)) begin
            br$6$d = 1'b1;
        end
        if (c_open & (c_open_lvl == idx$6)) begin
            start_l$6$d = c_open_l;
            start_r$6$d = c_open_r;
            len_l$6$d = 32'h0;
            len_r$6$d = 32'h0;
        end
        if (clear) begin
            br$6$d = 1'b0;
            start_l$6$d = 32'h0;
            start_r$6$d = 32'h0;
            len_l$6$d = 32'h0;
            len_r$6$d = 32'h0;
        end
        br$7$clock = clock;
        start_l$7$clock = clock;
        start_r$7$clock = clock;
        len_l$7$clock = clock;
        len_r$7$clock = clock;
        br$7$d = br$7$q;
        start_l$7$d = start_l$7$q;
        start_r$7$d = start_r$7$q;
        len_l$7$d = len_l$7$q;
        len_r$7$d = len_r$7$q;
        if (c_l1 == idx$7) begin
            if (c_desc) begin
                br$7$d = c_desc_b;
            end
            if (c_wok & ~wr_side) begin
                len_l$7$d = len_l$7$q + 32'h1;
            end
            if (c_wok & wr_side) begin
                len_r$7$d = len_r$7$q + 32'h1;
            end
        end
        if (c_u_right & (lvl$q == idx$7)) begin
            br$7$d = 1'b1;
        end
        if (c_open & (c_open_lvl == idx$7)) begin
            start_l$7$d = c_open_l;
            start_r$7$d = c_open_r;
            len_l$7$d = 32'h0;
            len_r$7$d = 32'h0;
        end
        if (clear) begin
            br$7$d = 1'b0;
            start_l$7$d = 32'h0;
            start_r$7$d = 32'h0;
            len_l$7$d = 32'h0;
            len_r$7$d = 32'h0;
        end
        br$8$clock = clock;
        start_l$8$clock = clock;
        start_r$8$clock = clock;
        len_l$8$clock = clock;
        len_r$8$clock = clock;
        br$8$d = br$8$q;
        start_l$8$d = start_l$8$q;
        start_r$8$d = start_r$8$q;
        len_l$8$d = len_l$8$q;
        len_r$8$d = len_r$8$q;
        if (c_l1 == idx$8) begin
            if (c_desc) begin
                br$8$d = c_desc_b;
            end
            if (c_wok & ~wr_side) begin
                len_l$8$d = len_l$8$q + 32'h1;
            end
            if (c_wok & wr_side) begin
                len_r$8$d = len_r$8$q + 32'h1;
            end
        end
        if (c_u_right & (lvl$q == idx$8)) begin
            br$8$d = 1'b1;
        end
        if (c_open & (c_open_lvl == idx$8)) begin
            start_l$8$d = c_open_l;
            start_r$8$d = c_open_r;
            len_l$8$d = 32'h0;
            len_r$8$d = 32'h0;
        end
        if (clear) begin
            br$8$d = 1'b0;
            start_l$8$d = 32'h0;
            start_r$8$d = 32'h0;
            len_l$8$d = 32'h0;
            len_r$8$d = 32'h0;
        end
        br$9$clock = clock;
        start_l$9$clock = clock;
        start_r$9$clock = clock;
        len_l$9$clock = clock;
        len_r$9$clock = clock;
        br$9$d = br$9$q;
        start_l$9$d = start_l$9$q;
        start_r$9$d = start_r$9$q;
        len_l$9$d = len_l$9$q;
        len_r$9$d = len_r$9$q;
        if (c_l1 == idx$9) begin
            if (c_desc) begin
                br$9$d = c_desc_b;
            end
            if (c_wok & ~wr_side) begin
                len_l$9$d = len_l$9$q + 32'h1;
            end
            if (c_wok & wr_side) begin
                len_r$9$d = len_r$9$q + 32'h1;
            end
        end
        if (c_u_right & (lvl$q == idx$9)) begin
            br$9$d = 1'b1;
        end
        if (c_open & (c_open_lvl == idx$9)) begin
            start_l$9$d = c_open_l;
            start_r$9$d = c_open_r;
            len_l$9$d = 32'h0;
            len_r$9$d = 32'h0;
        end
        if (clear) begin
            br$9$d = 1'b0;
            start_l$9$d = 32'h0;
            start_r$9$d = 32'h0;
            len_l$9$d = 32'h0;
            len_r$9$d = 32'h0;
        end
        br$10$clock = clock;
        start_l$10$clock = clock;
        start_r$10$clock = clock;
        len_l$10$clock = clock;
        len_r$10$clock = clock;
        br$10$d = br$10$q;
        start_l$10$d = start_l$10$q;
        start_r$10$d = start_r$10$q;
        len_l$10$d = len_l$10$q;
        len_r$10$d = len_r$10$q;
        if (c_l1 == idx$10) begin
            if (c_desc) begin
                br$10$d = c_desc_b;
            end
            if (c_wok & ~wr_side) begin
                len_l$10$d = len_l$10$q + 32'h1;
            end
            if (c_wok & wr_side) begin
                len_r$10$d = len_r$10$q + 32'h1;
            end
        end
        if (c_u_right & (lvl$q == idx$10)) begin
            br$10$d = 1'b1;
        end
        if (c_open & (c_open_lvl == idx$10)) begin
            start_l$10$d = c_open_l;
            start_r$10$d = c_open_r;
            len_l$10$d = 32'h0;
            len_r$10$d = 32'h0;
        end
        if (clear) begin
            br$10$d = 1'b0;
            start_l$10$d = 32'h0;
            start_r$10$d = 32'h0;
            len_l$10$d = 32'h0;
            len_r$10$d = 32'h0;
        end
        br$11$clock = clock;
        start_l$11$clock = clock;
        start_r$11$clock = clock;
        len_l$11$clock = clock;
        len_r$11$clock = clock;
        br$11$d = br$11$q;
        start_l$11$d = start_l$11$q;
        start_r$11$d = start_r$11$q;
        len_l$11$d = len_l$11$q;
        len_r$11$d = len_r$11$q;
        if (c_l1 == idx$11) begin
            if (c_desc) begin
                br$11$d = c_desc_b;
            end
            if (c_wok & ~wr_side) begin
                len_l$11$d = len_l$11$q + 32'h1;
            end
            if (c_wok & wr_side) begin
                len_r$11$d = len_r$11$q + 32'h1;
            end
        end
        if (c_u_right & (lvl$q == idx$11)) begin
            br$11$d = 1'b1;
        end
        if (c_open & (c_open_lvl == idx$11)) begin
            start_l$11$d = c_open_l;
            start_r$11$d = c_open_r;
            len_l$11$d = 32'h0;
            len_r$11$d = 32'h0;
        end
        if (clear) begin
            br$11$d = 1'b0;
            start_l$11$d = 32'h0;
            start_r$11$d = 32'h0;
            len_l$11$d = 32'h0;
            len_r$11$d = 32'h0;
        end
        br$12$clock = clock;
        start_l$12$clock = clock;
        start_r$12$clock = clock;
        len_l$12$clock = clock;
        len_r$12$clock = clock;
        br$12$d = br$12$q;
        start_l$12$d = start_l$12$q;
        start_r$12$d = start_r$12$q;
        len_l$12$d = len_l$12$q;
        len_r$12$d = len_r$12$q;
        if (c_l1 == idx$12) begin
            if (c_desc) begin
                br$12$d = c_desc_b;
            end
            if (c_wok & ~wr_side) begin
                len_l$12$d = len_l$12$q + 32'h1;
            end
            if (c_wok & wr_side) begin
                len_r$12$d = len_r$12$q + 32'h1;
            end
        end
        if (c_u_right & (lvl$q == idx$12)) begin
            br$12$d = 1'b1;
        end
        if (c_open & (c_open_lvl == idx$12)) begin
            start_l$12$d = c_open_l;
            start_r$12$d = c_open_r;
            len_l$12$d = 32'h0;
            len_r$12$d = 32'h0;
        end
        if (clear) begin
            br$12$d = 1'b0;
            start_l$12$d = 32'h0;
            start_r$12$d = 32'h0;
            len_l$12$d = 32'h0;
            len_r$12$d = 32'h0;
        end
        br$13$clock = clock;
        start_l$13$clock = clock;
        start_r$13$clock = clock;
        len_l$13$clock = clock;
        len_r$13$clock = clock;
        br$13$d = br$13$q;
        start_l$13$d = start_l$13$q;
        start_r$13$d = start_r$13$q;
        len_l$13$d = len_l$13$q;
        len_r$13$d = len_r$13$q;
        if (c_l1 == idx$13) begin
            if (c_desc) begin
                br$13$d = c_desc_b;
            end
            if (c_wok & ~wr_side) begin
                len_l$13$d = len_l$13$q + 32'h1;
            end
            if (c_wok & wr_side) begin
                len_r$13$d = len_r$13$q + 32'h1;
            end
        end
        if (c_u_right & (lvl$q == idx$13)) begin
            br$13$d = 1'b1;
        end
        if (c_open & (c_open_lvl == idx$13)) begin
            start_l$13$d = c_open_l;
            start_r$13$d = c_open_r;
            len_l$13$d = 32'h0;
            len_r$13$d = 32'h0;
        end
        if (clear) begin
            br$13$d = 1'b0;
            start_l$13$d = 32'h0;
            start_r$13$d = 32'h0;
            len_l$13$d = 32'h0;
            len_r$13$d = 32'h0;
        end
        br$14$clock = clock;
        start_l$14$clock = clock;
        start_r$14$clock = clock;
        len_l$14$clock = clock;
        len_r$14$clock = clock;
        br$14$d = br$14$q;
        start_l$14$d = start_l$14$q;
        start_r$14$d = start_r$14$q;
        len_l$14$d = len_l$14$q;
        len_r$14$d = len_r$14$q;
        if (c_l1 == idx$14) begin
            if (c_desc) begin
                br$14$d = c_desc_b;
            end
            if (c_wok & ~wr_side) begin
                len_l$14$d = len_l$14$q + 32'h1;
            end
            if (c_wok & wr_side) begin
                len_r$14$d = len_r$14$q + 32'h1;
            end
        end
        if (c_u_right & (lvl$q == idx$14)) begin
            br$14$d = 1'b1;
        end
        if (c_open & (c_open_lvl == idx$14)) begin
            start_l$14$d = c_open_l;
            start_r$14$d = c_open_r;
            len_l$14$d = 32'h0;
            len_r$14$d = 32'h0;
        end
        if (clear) begin
            br$14$d = 1'b0;
            start_l$14$d = 32'h0;
            start_r$14$d = 32'h0;
            len_l$14$d = 32'h0;
            len_r$14$d = 32'h0;
        end
        br$15$clock = clock;
        start_l$15$clock = clock;
        start_r$15$clock = clock;
        len_l$15$clock = clock;
        len_r$15$clock = clock;
        br$15$d = br$15$q;
        start_l$15$d = start_l$15$q;
        start_r$15$d = start_r$15$q;
        len_l$15$d = len_l$15$q;
        len_r$15$d = len_r$15$q;
        if (c_l1 == idx$15) begin
            if (c_desc) begin
                br$15$d = c_desc_b;
            end
            if (c_wok & ~wr_side) begin
                len_l$15$d = len_l$15$q + 32'h1;
            end
            if (c_wok & wr_side) begin
                len_r$15$d = len_r$15$q + 32'h1;
            end
        end
        if (c_u_right & (lvl$q == idx$15)) begin
            br$15$d = 1'b1;
        end
        if (c_open & (c_open_lvl == idx$15)) begin
            start_l$15$d = c_open_l;
            start_r$15$d = c_open_r;
            len_l$15$d = 32'h0;
            len_r$15$d = 32'h0;
        end
        if (clear) begin
            br$15$d = 1'b0;
            start_l$15$d = 32'h0;
            start_r$15$d = 32'h0;
            len_l$15$d = 32'h0;
            len_r$15$d = 32'h0;
        end
        br$16$clock = clock;
        start_l$16$clock = clock;
        start_r$16$clock = clock;
        len_l$16$clock = clock;
        len_r$16$clock = clock;
        br$16$d = br$16$q;
        start_l$16$d = start_l$16$q;
        start_r$16$d = start_r$16$q;
        len_l$16$d = len_l$16$q;
        len_r$16$d = len_r$16$q;
        if (c_l1 == idx$16) begin
            if (c_desc) begin
                br$16$d = c_desc_b;
            end
            if (c_wok & ~wr_side) begin
                len_l$16$d = len_l$16$q + 32'h1;
            end
            if (c_wok & wr_side) begin
                len_r$16$d = len_r$16$q + 32'h1;
            end
        end
        if (c_u_right & (lvl$q == idx$16)) begin
            br$16$d = 1'b1;
        end
        if (c_open & (c_open_lvl == idx$16)) begin
            start_l$16$d = c_open_l;
            start_r$16$d = c_open_r;
            len_l$16$d = 32'h0;
            len_r$16$d = 32'h0;
        end
        if (clear) begin
            br$16$d = 1'b0;
            start_l$16$d = 32'h0;
            start_r$16$d = 32'h0;
            len_l$16$d = 32'h0;
            len_r$16$d = 32'h0;
        end
        br$17$clock = clock;
        start_l$17$clock = clock;
        start_r$17$clock = clock;
        len_l$17$clock = clock;
        len_r$17$clock = clock;
        br$17$d = br$17$q;
        start_l$17$d = start_l$17$q;
        start_r$17$d = start_r$17$q;
        len_l$17$d = len_l$17$q;
        len_r$17$d = len_r$17$q;
        if (c_l1 == idx$17) begin
            if (c_desc) begin
                br$17$d = c_desc_b;
            end
            if (c_wok & ~wr_side) begin
                len_l$17$d = len_l$17$q + 32'h1;
            end
            if (c_wok & wr_side) begin
                len_r$17$d = len_r$17$q + 32'h1;
            end
        end
        if (c_u_right & (lvl$q == idx$17)) begin
            br$17$d = 1'b1;
        end
        if (c_open & (c_open_lvl == idx$17)) begin
            start_l$17$d = c_open_l;
            start_r$17$d = c_open_r;
            len_l$17$d = 32'h0;
            len_r$17$d = 32'h0;
        end
        if (clear) begin
            br$17$d = 1'b0;
            start_l$17$d = 32'h0;
            start_r$17$d = 32'h0;
            len_l$17$d = 32'h0;
            len_r$17$d = 32'h0;
        end
        br$18$clock = clock;
        start_l$18$clock = clock;
        start_r$18$clock = clock;
        len_l$18$clock = clock;
        len_r$18$clock = clock;
        br$18$d = br$18$q;
        start_l$18$d = start_l$18$q;
        start_r$18$d = start_r$18$q;
        len_l$18$d = len_l$18$q;
        len_r$18$d = len_r$18$q;
        if (c_l1 == idx$18) begin
            if (c_desc) begin
                br$18$d = c_desc_b;
            end
            if (c_wok & ~wr_side) begin
                len_l$18$d = len_l$18$q + 32'h1;
            end
            if (c_wok & wr_side) begin
                len_r$18$d = len_r$18$q + 32'h1;
            end
        end
        if (c_u_right & (lvl$q == idx$18)) begin
            br$18$d = 1'b1;
        end
        if (c_open & (c_open_lvl == idx$18)) begin
            start_l$18$d = c_open_l;
            start_r$18$d = c_open_r;
            len_l$18$d = 32'h0;
            len_r$18$d = 32'h0;
        end
        if (clear) begin
            br$18$d = 1'b0;
            start_l$18$d = 32'h0;
            start_r$18$d = 32'h0;
            len_l$18$d = 32'h0;
            len_r$18$d = 32'h0;
        end
        br$19$clock = clock;
        start_l$19$clock = clock;
        start_r$19$clock = clock;
        len_l$19$clock = clock;
        len_r$19$clock = clock;
        br$19$d = br$19$q;
        start_l$19$d = start_l$19$q;
        start_r$19$d = start_r$19$q;
        len_l$19$d = len_l$19$q;
        len_r$19$d = len_r$19$q;
        if (c_l1 == idx$19) begin
            if (c_desc) begin
                br$19$d = c_desc_b;
            end
            if (c_wok & ~wr_side) begin
                len_l$19$d = len_l$19$q + 32'h1;
            end
            if (c_wok & wr_side) begin
                len_r$19$d = len_r$19$q + 32'h1;
            end
        end
        if (c_u_right & (lvl$q == idx$19)) begin
            br$19$d = 1'b1;
        end
        if (c_open & (c_open_lvl == idx$19)) begin
            start_l$19$d = c_open_l;
            start_r$19$d = c_open_r;
            len_l$19$d = 32'h0;
            len_r$19$d = 32'h0;
        end
        if (clear) begin
            br$19$d = 1'b0;
            start_l$19$d = 32'h0;
            start_r$19$d = 32'h0;
            len_l$19$d = 32'h0;
            len_r$19$d = 32'h0;
        end
        br$20$clock = clock;
        start_l$20$clock = clock;
        start_r$20$clock = clock;
        len_l$20$clock = clock;
        len_r$20$clock = clock;
        br$20$d = br$20$q;
        start_l$20$d = start_l$20$q;
        start_r$20$d = start_r$20$q;
        len_l$20$d = len_l$20$q;
        len_r$20$d = len_r$20$q;
        if (c_l1 == idx$20) begin
            if (c_desc) begin
                br$20$d = c_desc_b;
            end
            if (c_wok & ~wr_side) begin
                len_l$20$d = len_l$20$q + 32'h1;
            end
            if (c_wok & wr_side) begin
                len_r$20$d = len_r$20$q + 32'h1;
            end
        end
        if (c_u_right & (lvl$q == idx$20)) begin
            br$20$d = 1'b1;
        end
        if (c_open & (c_open_lvl == idx$20)) begin
            start_l$20$d = c_open_l;
            start_r$20$d = c_open_r;
            len_l$20$d = 32'h0;
            len_r$20$d = 32'h0;
        end
        if (clear) begin
            br$20$d = 1'b0;
            start_l$20$d = 32'h0;
            start_r$20$d = 32'h0;
            len_l$20$d = 32'h0;
            len_r$20$d = 32'h0;
        end
        br$21$clock = clock;
        start_l$21$clock = clock;
        start_r$21$clock = clock;
        len_l$21$clock = clock;
        len_r$21$clock = clock;
        br$21$d = br$21$q;
        start_l$21$d = start_l$21$q;
        start_r$21$d = start_r$21$q;
        len_l$21$d = len_l$21$q;
        len_r$21$d = len_r$21$q;
        if (c_l1 == idx$21) begin
            if (c_desc) begin
                br$21$d = c_desc_b;
            end
            if (c_wok & ~wr_side) begin
                len_l$21$d = len_l$21$q + 32'h1;
            end
            if (c_wok & wr_side) begin
                len_r$21$d = len_r$21$q + 32'h1;
            end
        end
        if (c_u_right & (lvl$q == idx$21)) begin
            br$21$d = 1'b1;
        end
        if (c_open & (c_open_lvl == idx$21)) begin
            start_l$21$d = c_open_l;
            start_r$21$d = c_open_r;
            len_l$21$d = 32'h0;
            len_r$21$d = 32'h0;
        end
        if (clear) begin
            br$21$d = 1'b0;
            start_l$21$d = 32'h0;
            start_r$21$d = 32'h0;
            len_l$21$d = 32'h0;
            len_r$21$d = 32'h0;
        end
        br$22$clock = clock;
        start_l$22$clock = clock;
        start_r$22$clock = clock;
        len_l$22$clock = clock;
        len_r$22$clock = clock;
        br$22$d = br$22$q;
        start_l$22$d = start_l$22$q;
        start_r$22$d = start_r$22$q;
        len_l$22$d = len_l$22$q;
        len_r$22$d = len_r$22$q;
        if (c_l1 == idx$22) begin
            if (c_desc) begin
                br$22$d = c_desc_b;
            end
            if (c_wok & ~wr_side) begin
                len_l$22$d = len_l$22$q + 32'h1;
            end
            if (c_wok & wr_side) begin
                len_r$22$d = len_r$22$q + 32'h1;
            end
        end
        if (c_u_right & (lvl$q == idx$22)) begin
            br$22$d = 1'b1;
        end
        if (c_open & (c_open_lvl == idx$22)) begin
            start_l$22$d = c_open_l;
            start_r$22$d = c_open_r;
            len_l$22$d = 32'h0;
            len_r$22$d = 32'h0;
        end
        if (clear) begin
            br$22$d = 1'b0;
            start_l$22$d = 32'h0;
            start_r$22$d = 32'h0;
            len_l$22$d = 32'h0;
            len_r$22$d = 32'h0;
        end
        br$23$clock = clock;
        start_l$23$clock = clock;
        start_r$23$clock = clock;
        len_l$23$clock = clock;
        len_r$23$clock = clock;
        br$23$d = br$23$q;
        start_l$23$d = start_l$23$q;
        start_r$23$d = start_r$23$q;
        len_l$23$d = len_l$23$q;
        len_r$23$d = len_r$23$q;
        if (c_l1 == idx$23) begin
            if (c_desc) begin
                br$23$d = c_desc_b;
            end
            if (c_wok & ~wr_side) begin
                len_l$23$d = len_l$23$q + 32'h1;
            end
            if (c_wok & wr_side) begin
                len_r$23$d = len_r$23$q + 32'h1;
            end
        end
        if (c_u_right & (lvl$q == idx$23)) begin
            br$23$d = 1'b1;
        end
        if (c_open & (c_open_lvl == idx$23)) begin
            start_l$23$d = c_open_l;
            start_r$23$d = c_open_r;
            len_l$23$d = 32'h0;
            len_r$23$d = 32'h0;
        end
        if (clear) begin
            br$23$d = 1'b0;
            start_l$23$d = 32'h0;
            start_r$23$d = 32'h0;
            len_l$23$d = 32'h0;
            len_r$23$d = 32'h0;
        end
        br$24$clock = clock;
        start_l$24$clock = clock;
        start_r$24$clock = clock;
        len_l$24$clock = clock;
        len_r$24$clock = clock;
        br$24$d = br$24$q;
        start_l$24$d = start_l$24$q;
        start_r$24$d = start_r$24$q;
        len_l$24$d = len_l$24$q;
        len_r$24$d = len_r$24$q;
        if (c_l1 == idx$24) begin
            if (c_desc) begin
                br$24$d = c_desc_b;
            end
            if (c_wok & ~wr_side) begin
                len_l$24$d = len_l$24$q + 32'h1;
            end
            if (c_wok & wr_side) begin
                len_r$24$d = len_r$24$q + 32'h1;
            end
        end
        if (c_u_right & (lvl$q == idx$24)) begin
            br$24$d = 1'b1;
        end
        if (c_open & (c_open_lvl == idx$24)) begin
            start_l$24$d = c_open_l;
            start_r$24$d = c_open_r;
            len_l$24$d = 32'h0;
            len_r$24$d = 32'h0;
        end
        if (clear) begin
            br$24$d = 1'b0;
            start_l$24$d = 32'h0;
            start_r$24$d = 32'h0;
            len_l$24$d = 32'h0;
            len_r$24$d = 32'h0;
        end
        br$25$clock = clock;
        start_l$25$clock = clock;
        start_r$25$clock = clock;
        len_l$25$clock = clock;
        len_r$25$clock = clock;
        br$25$d = br$25$q;
        start_l$25$d = start_l$25$q;
        start_r$25$d = start_r$25$q;
        len_l$25$d = len_l$25$q;
        len_r$25$d = len_r$25$q;
        if (c_l1 == idx$25) begin
            if (c_desc) begin
                br$25$d = c_desc_b;
            end
            if (c_wok & ~wr_side) begin
                len_l$25$d = len_l$25$q + 32'h1;
            end
            if (c_wok & wr_side) begin
                len_r$25$d = len_r$25$q + 32'h1;
            end
        end
        if (c_u_right & (lvl$q == idx$25)) begin
            br$25$d = 1'b1;
        end
        if (c_open & (c_open_lvl == idx$25)) begin
            start_l$25$d = c_open_l;
            start_r$25$d = c_open_r;
            len_l$25$d = 32'h0;
            len_r$25$d = 32'h0;
        end
        if (clear) begin
            br$25$d = 1'b0;
            start_l$25$d = 32'h0;
            start_r$25$d = 32'h0;
            len_l$25$d = 32'h0;
            len_r$25$d = 32'h0;
        end
        br$26$clock = clock;
        start_l$26$clock = clock;
        start_r$26$clock = clock;
        len_l$26$clock = clock;
        len_r$26$clock = clock;
        br$26$d = br$26$q;
        start_l$26$d = start_l$26$q;
        start_r$26$d = start_r$26$q;
        len_l$26$d = len_l$26$q;
        len_r$26$d = len_r$26$q;
        if (c_l1 == idx$26) begin
            if (c_desc) begin
                br$26$d = c_desc_b;
            end
            if (c_wok & ~wr_side) begin
                len_l$26$d = len_l$26$q + 32'h1;
            end
            if (c_wok & wr_side) begin
                len_r$26$d = len_r$26$q + 32'h1;
            end
        end
        if (c_u_right & (lvl$q == idx$26)) begin
            br$26$d = 1'b1;
        end
        if (c_open & (c_open_lvl == idx$26)) begin
            start_l$26$d = c_open_l;
            start_r$26$d = c_open_r;
            len_l$26$d = 32'h0;
            len_r$26$d = 32'h0;
        end
        if (clear) begin
            br$26$d = 1'b0;
            start_l$26$d = 32'h0;
            start_r$26$d = 32'h0;
            len_l$26$d = 32'h0;
            len_r$26$d = 32'h0;
        end
        br$27$clock = clock;
        start_l$27$clock = clock;
        start_r$27$clock = clock;
        len_l$27$clock = clock;
        len_r$27$clock = clock;
        br$27$d = br$27$q;
        start_l$27$d = start_l$27$q;
        start_r$27$d = start_r$27$q;
        len_l$27$d = len_l$27$q;
        len_r$27$d = len_r$27$q;
        if (c_l1 == idx$27) begin
            if (c_desc) begin
                br$27$d = c_desc_b;
            end
            if (c_wok & ~wr_side) begin
                len_l$27$d = len_l$27$q + 32'h1;
            end
            if (c_wok & wr_side) begin
                len_r$27$d = len_r$27$q + 32'h1;
            end
        end
        if (c_u_right & (lvl$q == idx$27)) begin
            br$27$d = 1'b1;
        end
        if (c_open & (c_open_lvl == idx$27)) begin
            start_l$27$d = c_open_l;
            start_r$27$d = c_open_r;
            len_l$27$d = 32'h0;
            len_r$27$d = 32'h0;
        end
        if (clear) begin
            br$27$d = 1'b0;
            start_l$27$d = 32'h0;
            start_r$27$d = 32'h0;
            len_l$27$d = 32'h0;
            len_r$27$d = 32'h0;
        end
        br$28$clock = clock;
        start_l$28$clock = clock;
        start_r$28$clock = clock;
        len_l$28$clock = clock;
        len_r$28$clock = clock;
        br$28$d = br$28$q;
        start_l$28$d = start_l$28$q;
        start_r$28$d = start_r$28$q;
        len_l$28$d = len_l$28$q;
        len_r$28$d = len_r$28$q;
        if (c_l1 == idx$28) begin
            if (c_desc) begin
                br$28$d = c_desc_b;
            end
            if (c_wok & ~wr_side) begin
                len_l$28$d = len_l$28$q + 32'h1;
            end
            if (c_wok & wr_side) begin
                len_r$28$d = len_r$28$q + 32'h1;
            end
        end
        if (c_u_right & (lvl$q == idx$28)) begin
            br$28$d = 1'b1;
        end
        if (c_open & (c_open_lvl == idx$28)) begin
            start_l$28$d = c_open_l;
            start_r$28$d = c_open_r;
            len_l$28$d = 32'h0;
            len_r$28$d = 32'h0;
        end
        if (clear) begin
            br$28$d = 1'b0;
            start_l$28$d = 32'h0;
            start_r$28$d = 32'h0;
            len_l$28$d = 32'h0;
            len_r$28$d = 32'h0;
        end
        br$29$clock = clock;
        start_l$29$clock = clock;
        start_r$29$clock = clock;
        len_l$29$clock = clock;
        len_r$29$clock = clock;
        br$29$d = br$29$q;
        start_l$29$d = start_l$29$q;
        start_r$29$d = start_r$29$q;
        len_l$29$d = len_l$29$q;
        len_r$29$d = len_r$29$q;
        if (c_l1 == idx$29) begin
            if (c_desc) begin
                br$29$d = c_desc_b;
            end
            if (c_wok & ~wr_side) begin
                len_l$29$d = len_l$29$q + 32'h1;
            end
            if (c_wok & wr_side) begin
                len_r$29$d = len_r$29$q + 32'h1;
            end
        end
        if (c_u_right & (lvl$q == idx$29)) begin
            br$29$d = 1'b1;
        end
        if (c_open & (c_open_lvl == idx$29)) begin
            start_l$29$d = c_open_l;
            start_r$29$d = c_open_r;
            len_l$29$d = 32'h0;
            len_r$29$d = 32'h0;
        end
        if (clear) begin
            br$29$d = 1'b0;
            start_l$29$d = 32'h0;
            start_r$29$d = 32'h0;
            len_l$29$d = 32'h0;
            len_r$29$d = 32'h0;
        end
        br$30$clock = clock;
        start_l$30$clock = clock;
        start_r$30$clock = clock;
        len_l$30$clock = clock;
        len_r$30$clock = clock;
        br$30$d = br$30$q;
        start_l$30$d = start_l$30$q;
        start_r$30$d = start_r$30$q;
        len_l$30$d = len_l$30$q;
        len_r$30$d = len_r$30$q;
        if (c_l1 == idx$30) begin
            if (c_desc) begin
                br$30$d = c_desc_b;
            end
            if (c_wok & ~wr_side) begin
                len_l$30$d = len_l$30$q + 32'h1;
            end
            if (c_wok & wr_side) begin
                len_r$30$d = len_r$30$q + 32'h1;
            end
        end
        if (c_u_right & (lvl$q == idx$30)) begin
            br$30$d = 1'b1;
        end
        if (c_open & (c_open_lvl == idx$30)) begin
            start_l$30$d = c_open_l;
            start_r$30$d = c_open_r;
            len_l$30$d = 32'h0;
            len_r$30$d = 32'h0;
        end
        if (clear) begin
            br$30$d = 1'b0;
            start_l$30$d = 32'h0;
            start_r$30$d = 32'h0;
            len_l$30$d = 32'h0;
            len_r$30$d = 32'h0;
        end
        br$31$clock = clock;
        start_l$31$clock = clock;
        start_r$31$clock = clock;
        len_l$31$clock = clock;
        len_r$31$clock = clock;
        br$31$d = br$31$q;
        start_l$31$d = start_l$31$q;
        start_r$31$d = start_r$31$q;
        len_l$31$d = len_l$31$q;
        len_r$31$d = len_r$31$q;
        if (c_l1 == idx$31) begin
            if (c_desc) begin
                br$31$d = c_desc_b;
            end
            if (c_wok & ~wr_side) begin
                len_l$31$d = len_l$31$q + 32'h1;
            end
            if (c_wok & wr_side) begin
                len_r$31$d = len_r$31$q + 32'h1;
            end
        end
        if (c_u_right & (lvl$q == idx$31)) begin
            br$31$d = 1'b1;
        end
        if (c_open & (c_open_lvl == idx$31)) begin
            start_l$31$d = c_open_l;
            start_r$31$d = c_open_r;
            len_l$31$d = 32'h0;
            len_r$31$d = 32'h0;
        end
        if (clear) begin
            br$31$d = 1'b0;
            start_l$31$d = 32'h0;
            start_r$31$d = 32'h0;
            len_l$31$d = 32'h0;
            len_r$31$d = 32'h0;
        end
        if (clear) begin
            lvl$d = 32'h0;
            pos$d = 32'h0;
            rem$d = 32'h0;
            cur_b$d = 1'b0;
            wa_l$d = 32'h0;
            wa_r$d = 32'h0;
            up$d = 1'b0;
            done_r$d = 1'b0;
            ovf$d = 1'b0;
            rd_v$d = 1'b0;
        end
        level = lvl$q;
        branch = cur_b$q;
        remaining = 32'h0;
        if (c_idle) begin
            remaining = rem$q;
        end
        busy = up$q;
        done = done_r$q;
        rd_valid = rd_v$q;
        overflow = ovf$q;
    end
    
endmodule // top


module top$br$0(d,q,clock);
    
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
          
endmodule // top$br$0


module top$len_l$0(d,q,clock);
    
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
          
endmodule // top$len_l$0


module top$lvl(d,q,clock);
    
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
          
endmodule // top$lvl


module top$sram_l(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [7:0] read_address;
    input wire  read_clock;
    output reg  [15:0] read_data;
    input wire  [7:0] write_address;
    input wire  write_clock;
    input wire  [15:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    reg[15:0] mem[255:0];
    
    
    
    always @(posedge read_clock) begin
       read_data <= mem[read_address];
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address] <= write_data;
       end
    end
                
endmodule // top$sram_l
