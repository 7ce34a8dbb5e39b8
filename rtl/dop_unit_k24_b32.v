

module top(clock,load_en,load_addr,load_data,d$0,d$1,d$2,d$3,d$4,d$5,d$6,d$7,d$8,d$9,d$10,d$11,d$12,d$13,d$14,d$15,d$16,d$17,d$18,d$19,d$20,d$21,d$22,d$23,e$0,e$1,e$2,e$3,e$4,e$5,e$6,e$7,e$8,e$9,e$10,e$11,e$12,e$13,e$14,e$15,e$16,e$17,e$18,e$19,e$20,e$21,e$22,e$23,tag,valid_in,overlap,tag_out,valid_out);
    
    // Module arguments
    input wire  clock;
    input wire  load_en;
    input wire  [7:0] load_addr;
    input wire  [31:0] load_data;
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
    input wire  [31:0] e$0;
    input wire  [31:0] e$1;
    input wire  [31:0] e$2;
    input wire  [31:0] e$3;
    input wire  [31:0] e$4;
    input wire  [31:0] e$5;
    input wire  [31:0] e$6;
    input wire  [31:0] e$7;
    input wire  [31:0] e$8;
    input wire  [31:0] e$9;
    input wire  [31:0] e$10;
    input wire  [31:0] e$11;
    input wire  [31:0] e$12;
    input wire  [31:0] e$13;
    input wire  [31:0] e$14;
    input wire  [31:0] e$15;
    input wire  [31:0] e$16;
    input wire  [31:0] e$17;
    input wire  [31:0] e$18;
    input wire  [31:0] e$19;
    input wire  [31:0] e$20;
    input wire  [31:0] e$21;
    input wire  [31:0] e$22;
    input wire  [31:0] e$23;
    input wire  [15:0] tag;
    input wire  valid_in;
    output reg  overlap;
    output reg  [15:0] tag_out;
    output reg  valid_out;
    
    // Stub signals
    reg  setup$clock;
    reg  setup$load_en;
    reg  [7:0] setup$load_addr;
    reg  [31:0] setup$load_data;
    wire  [31:0] setup$c0$0;
    wire  [31:0] setup$c0$1;
    wire  [31:0] setup$c0$2;
    wire  [31:0] setup$c0$3;
    wire  [31:0] setup$c0$4;
    wire  [31:0] setup$c0$5;
    wire  [31:0] setup$c0$6;
    wire  [31:0] setup$c0$7;
    wire  [31:0] setup$c0$8;
    wire  [31:0] setup$c0$9;
    wire  [31:0] setup$c0$10;
    wire  [31:0] setup$c0$11;
    wire  [31:0] setup$c0$12;
    wire  [31:0] setup$c0$13;
    wire  [31:0] setup$c0$14;
    wire  [31:0] setup$c0$15;
    wire  [31:0] setup$c0$16;
    wire  [31:0] setup$c0$17;
    wire  [31:0] setup$c0$18;
    wire  [31:0] setup$c0$19;
    wire  [31:0] setup$c0$20;
    wire  [31:0] setup$c0$21;
    wire  [31:0] setup$c0$22;
    wire  [31:0] setup$c0$23;
    wire  [31:0] setup$c1$0;
    wire  [31:0] setup$c1$1;
    wire  [31:0] setup$c1$2;
    wire  [31:0] setup$c1$3;
    wire  [31:0] setup$c1$4;
    wire  [31:0] setup$c1$5;
    wire  [31:0] setup$c1$6;
    wire  [31:0] setup$c1$7;
    wire  [31:0] setup$c1$8;
    wire  [31:0] setup$c1$9;
    wire  [31:0] setup$c1$10;
    wire  [31:0] setup$c1$11;
    wire  [31:0] setup$c1$12;
    wire  [31:0] setup$c1$13;
    wire  [31:0] setup$c1$14;
    wire  [31:0] setup$c1$15;
    wire  [31:0] setup$c1$16;
    wire  [31:0] setup$c1$17;
    wire  [31:0] setup$c1$18;
    wire  [31:0] setup$c1$19;
    wire  [31:0] setup$c1$20;
    wire  [31:0] setup$c1$21;
    wire  [31:0] setup$c1$22;
    wire  [31:0] setup$c1$23;
    wire  [31:0] setup$c2$0;
    wire  [31:0] setup$c2$1;
    wire  [31:0] setup$c2$2;
    wire  [31:0] setup$c2$3;
    wire  [31:0] setup$c2$4;
    wire  [31:0] setup$c2$5;
    wire  [31:0] setup$c2$6;
    wire  [31:0] setup$c2$7;
    wire  [31:0] setup$c2$8;
    wire  [31:0] setup$c2$9;
    wire  [31:0] setup$c2$10;
    wire  [31:0] setup$c2$11;
    wire  [31:0] setup$c2$12;
    wire  [31:0] setup$c2$13;
    wire  [31:0] setup$c2$14;
    wire  [31:0] setup$c2$15;
    wire  [31:0] setup$c2$16;
    wire  [31:0] setup$c2$17;
    wire  [31:0] setup$c2$18;
    wire  [31:0] setup$c2$19;
    wire  [31:0] setup$c2$20;
    wire  [31:0] setup$c2$21;
    wire  [31:0] setup$c2$22;
    wire  [31:0] setup$c2$23;
    wire  [31:0] setup$c$0;
    wire  [31:0] setup$c$1;
    wire  [31:0] setup$c$2;
    wire  [31:0] setup$c$3;
    wire  [31:0] setup$c$4;
    wire  [31:0] setup$c$5;
    wire  [31:0] setup$c$6;
    wire  [31:0] setup$c$7;
    wire  [31:0] setup$c$8;
    wire  [31:0] setup$c$9;
    wire  [31:0] setup$c$10;
    wire  [31:0] setup$c$11;
    wire  [31:0] setup$c$12;
    wire  [31:0] setup$c$13;
    wire  [31:0] setup$c$14;
    wire  [31:0] setup$c$15;
    wire  [31:0] setup$c$16;
    wire  [31:0] setup$c$17;
    wire  [31:0] setup$c$18;
    wire  [31:0] setup$c$19;
    wire  [31:0] setup$c$20;
    wire  [31:0] setup$c$21;
    wire  [31:0] setup$c$22;
    wire  [31:0] setup$c$23;
    wire  [4:0] setup$j0$0;
    wire  [4:0] setup$j0$1;
    wire  [4:0] setup$j0$2;
    wire  [4:0] setup$j0$3;
    wire  [4:0] setup$j0$4;
    wire  [4:0] setup$j0$5;
    wire  [4:0] setup$j0$6;
    wire  [4:0] setup$j0$7;
    wire  [4:0] setup$j0$8;
    wire  [4:0] setup$j0$9;
    wire  [4:0] setup$j0$10;
    wire  [4:0] setup$j0$11;
    wire  [4:0] setup$j0$12;
    wire  [4:0] setup$j0$13;
    wire  [4:0] setup$j0$14;
    wire  [4:0] setup$j0$15;
    wire  [4:0] setup$j0$16;
    wire  [4:0] setup$j0$17;
    wire  [4:0] setup$j0$18;
    wire  [4:0] setup$j0$19;
    wire  [4:0] setup$j0$20;
    wire  [4:0] setup$j0$21;
    wire  [4:0] setup$j0$22;
    wire  [4:0] setup$j0$23;
    wire  [4:0] setup$j1$0;
    wire  [4:0] setup$j1$1;
    wire  [4:0] setup$j1$2;
    wire  [4:0] setup$j1$3;
    wire  [4:0] setup$j1$4;
    wire  [4:0] setup$j1$5;
    wire  [4:0] setup$j1$6;
    wire  [4:0] setup$j1$7;
    wire  [4:0] setup$j1$8;
    wire  [4:0] setup$j1$9;
    wire  [4:0] setup$j1$10;
    wire  [4:0] setup$j1$11;
    wire  [4:0] setup$j1$12;
    wire  [4:0] setup$j1$13;
    wire  [4:0] setup$j1$14;
    wire  [4:0] setup$j1$15;
    wire  [4:0] setup$j1$16;
    wire  [4:0] setup$j1$17;
    wire  [4:0] setup$j1$18;
    wire  [4:0] setup$j1$19;
    wire  [4:0] setup$j1$20;
    wire  [4:0] setup$j1$21;
    wire  [4:0] setup$j1$22;
    wire  [4:0] setup$j1$23;
    wire  [4:0] setup$j2$0;
    wire  [4:0] setup$j2$1;
    wire  [4:0] setup$j2$2;
    wire  [4:0] setup$j2$3;
    wire  [4:0] setup$j2$4;
    wire  [4:0] setup$j2$5;
    wire  [4:0] setup$j2$6;
    wire  [4:0] setup$j2$7;
    wire  [4:0] setup$j2$8;
    wire  [4:0] setup$j2$9;
    wire  [4:0] setup$j2$10;
    wire  [4:0] setup$j2$11;
    wire  [4:0] setup$j2$12;
    wire  [4:0] setup$j2$13;
    wire  [4:0] setup$j2$14;
    wire  [4:0] setup$j2$15;
    wire  [4:0] setup$j2$16;
    wire  [4:0] setup$j2$17;
    wire  [4:0] setup$j2$18;
    wire  [4:0] setup$j2$19;
    wire  [4:0] setup$j2$20;
    wire  [4:0] setup$j2$21;
    wire  [4:0] setup$j2$22;
    wire  [4:0] setup$j2$23;
    wire  setup$round_up$0;
    wire  setup$round_up$1;
    wire  setup$round_up$2;
    wire  setup$round_up$3;
    wire  setup$round_up$4;
    wire  setup$round_up$5;
    wire  setup$round_up$6;
    wire  setup$round_up$7;
    wire  setup$round_up$8;
    wire  setup$round_up$9;
    wire  setup$round_up$10;
    wire  setup$round_up$11;
    wire  setup$round_up$12;
    wire  setup$round_up$13;
    wire  setup$round_up$14;
    wire  setup$round_up$15;
    wire  setup$round_up$16;
    wire  setup$round_up$17;
    wire  setup$round_up$18;
    wire  setup$round_up$19;
    wire  setup$round_up$20;
    wire  setup$round_up$21;
    wire  setup$round_up$22;
    wire  setup$round_up$23;
    reg  [31:0] klmsel$d$0;
    reg  [31:0] klmsel$d$1;
    reg  [31:0] klmsel$d$2;
    reg  [31:0] klmsel$d$3;
    reg  [31:0] klmsel$d$4;
    reg  [31:0] klmsel$d$5;
    reg  [31:0] klmsel$d$6;
    reg  [31:0] klmsel$d$7;
    reg  [31:0] klmsel$d$8;
    reg  [31:0] klmsel$d$9;
    reg  [31:0] klmsel$d$10;
    reg  [31:0] klmsel$d$11;
    reg  [31:0] klmsel$d$12;
    reg  [31:0] klmsel$d$13;
    reg  [31:0] klmsel$d$14;
    reg  [31:0] klmsel$d$15;
    reg  [31:0] klmsel$d$16;
    reg  [31:0] klmsel$d$17;
    reg  [31:0] klmsel$d$18;
    reg  [31:0] klmsel$d$19;
    reg  [31:0] klmsel$d$20;
    reg  [31:0] klmsel$d$21;
    reg  [31:0] klmsel$d$22;
    reg  [31:0] klmsel$d$23;
    reg  [4:0] klmsel$j0$0;
    reg  [4:0] klmsel$j0$1;
    reg  [4:0] klmsel$j0$2;
    reg  [4:0] klmsel$j0$3;
    reg  [4:0] klmsel$j0$4;
    reg  [4:0] klmsel$j0$5;
    reg  [4:0] klmsel$j0$6;
    reg  [4:0] klmsel$j0$7;
    reg  [4:0] klmsel$j0$8;
    reg  [4:0] klmsel$j0$9;
    reg  [4:0] klmsel$j0$10;
    reg  [4:0] klmsel$j0$11;
    reg  [4:0] klmsel$j0$12;
    reg  [4:0] klmsel$j0$13;
    reg  [4:0] klmsel$j0$14;
    reg  [4:0] klmsel$j0$15;
    reg  [4:0] klmsel$j0$16;
    reg  [4:0] klmsel$j0$17;
    reg  [4:0] klmsel$j0$18;
    reg  [4:0] klmsel$j0$19;
    reg  [4:0] klmsel$j0$20;
    reg  [4:0] klmsel$j0$21;
    reg  [4:0] klmsel$j0$22;
    reg  [4:0] klmsel$j0$23;
    reg  [4:0] klmsel$j1$0;
    reg  [4:0] klmsel$j1$1;
    reg  [4:0] klmsel$j1$2;
    reg  [4:0] klmsel$j1$3;
    reg  [4:0] klmsel$j1$4;
    reg  [4:0] klmsel$j1$5;
    reg  [4:0] klmsel$j1$6;
    reg  [4:0] klmsel$j1$7;
    reg  [4:0] klmsel$j1$8;
    reg  [4:0] klmsel$j1$9;
    reg  [4:0] klmsel$j1$10;
    reg  [4:0] klmsel$j1$11;
    reg  [4:0] klmsel$j1$12;
    reg  [4:0] klmsel$j1$13;
    reg  [4:0] klmsel$j1$14;
    reg  [4:0] klmsel$j1$15;
    reg  [4:0] klmsel$j1$16;
    reg  [4:0] klmsel$j1$17;
    reg  [4:0] klmsel$j1$18;
    reg  [4:0] klmsel$j1$19;
    reg  [4:0] klmsel$j1$20;
    reg  [4:0] klmsel$j1$21;
    reg  [4:0] klmsel$j1$22;
    reg  [4:0] klmsel$j1$23;
    reg  [4:0] klmsel$j2$0;
    reg  [4:0] klmsel$j2$1;
    reg  [4:0] klmsel$j2$2;
    reg  [4:0] klmsel$j2$3;
    reg  [4:0] klmsel$j2$4;
    reg  [4:0] klmsel$j2$5;
    reg  [4:0] klmsel$j2$6;
    reg  [4:0] klmsel$j2$7;
    reg  [4:0] klmsel$j2$8;
    reg  [4:0] klmsel$j2$9;
    reg  [4:0] klmsel$j2$10;
    reg  [4:0] klmsel$j2$11;
    reg  [4:0] klmsel$j2$12;
    reg  [4:0] klmsel$j2$13;
    reg  [4:0] klmsel$j2$14;
    reg  [4:0] klmsel$j2$15;
    reg  [4:0] klmsel$j2$16;
    reg  [4:0] klmsel$j2$17;
    reg  [4:0] klmsel$j2$18;
    reg  [4:0] klmsel$j2$19;
    reg  [4:0] klmsel$j2$20;
    reg  [4:0] klmsel$j2$21;
    reg  [4:0] klmsel$j2$22;
    reg  [4:0] klmsel$j2$23;
    wire  [31:0] klmsel$y0$0;
    wire  [31:0] klmsel$y0$1;
    wire  [31:0] klmsel$y0$2;
    wire  [31:0] klmsel$y0$3;
    wire  [31:0] klmsel$y0$4;
    wire  [31:0] klmsel$y0$5;
    wire  [31:0] klmsel$y0$6;
    wire  [31:0] klmsel$y0$7;
    wire  [31:0] klmsel$y0$8;
    wire  [31:0] klmsel$y0$9;
    wire  [31:0] klmsel$y0$10;
    wire  [31:0] klmsel$y0$11;
    wire  [31:0] klmsel$y0$12;
    wire  [31:0] klmsel$y0$13;
    wire  [31:0] klmsel$y0$14;
    wire  [31:0] klmsel$y0$15;
    wire  [31:0] klmsel$y0$16;
    wire  [31:0] klmsel$y0$17;
    wire  [31:0] klmsel$y0$18;
    wire  [31:0] klmsel$y0$19;
    wire  [31:0] klmsel$y0$20;
    wire  [31:0] klmsel$y0$21;
    wire  [31:0] klmsel$y0$22;
    wire  [31:0] klmsel$y0$23;
    wire  [31:0] klmsel$y1$0;
    wire  [31:0] klmsel$y1$1;
    wire  [31:0] klmsel$y1$2;
    wire  [31:0] klmsel$y1$3;
    wire  [31:0] klmsel$y1$4;
    wire  [31:0] klmsel$y1$5;
    wire  [31:0] klmsel$y1$6;
    wire  [31:0] klmsel$y1$7;
    wire  [31:0] klmsel$y1$8;
    wire  [31:0] klmsel$y1$9;
    wire  [31:0] klmsel$y1$10;
    wire  [31:0] klmsel$y1$11;
    wire  [31:0] klmsel$y1$12;
    wire  [31:0] klmsel$y1$13;
    wire  [31:0] klmsel$y1$14;
    wire  [31:0] klmsel$y1$15;
    wire  [31:0] klmsel$y1$16;
    wire  [31:0] klmsel$y1$17;
    wire  [31:0] klmsel$y1$18;
    wire  [31:0] klmsel$y1$19;
    wire  [31:0] klmsel$y1$20;
    wire  [31:0] klmsel$y1$21;
    wire  [31:0] klmsel$y1$22;
    wire  [31:0] klmsel$y1$23;
    wire  [31:0] klmsel$y2$0;
    wire  [31:0] klmsel$y2$1;
    wire  [31:0] klmsel$y2$2;
    wire  [31:0] klmsel$y2$3;
    wire  [31:0] klmsel$y2$4;
    wire  [31:0] klmsel$y2$5;
    wire  [31:0] klmsel$y2$6;
    wire  [31:0] klmsel$y2$7;
    wire  [31:0] klmsel$y2$8;
    wire  [31:0] klmsel$y2$9;
    wire  [31:0] klmsel$y2$10;
    wire  [31:0] klmsel$y2$11;
    wire  [31:0] klmsel$y2$12;
    wire  [31:0] klmsel$y2$13;
    wire  [31:0] klmsel$y2$14;
    wire  [31:0] klmsel$y2$15;
    wire  [31:0] klmsel$y2$16;
    wire  [31:0] klmsel$y2$17;
    wire  [31:0] klmsel$y2$18;
    wire  [31:0] klmsel$y2$19;
    wire  [31:0] klmsel$y2$20;
    wire  [31:0] klmsel$y2$21;
    wire  [31:0] klmsel$y2$22;
    wire  [31:0] klmsel$y2$23;
    reg  doptrf$0$clock;
    reg  [31:0] doptrf$0$d0;
    reg  [31:0] doptrf$0$d1;
    reg  [31:0] doptrf$0$d2;
    reg  [31:0] doptrf$0$c0;
    reg  [31:0] doptrf$0$c1;
    reg  [31:0] doptrf$0$c2;
    reg  [31:0] doptrf$0$c;
    reg  [31:0] doptrf$0$e;
    reg  doptrf$0$valid_in;
    reg  doptrf$0$round_up;
    wire  [31:0] doptrf$0$s;
    wire  doptrf$0$flag;
    wire  doptrf$0$valid_out;
    reg  doptrf$1$clock;
    reg  [31:0] doptrf$1$d0;
    reg  [31:0] doptrf$1$d1;
    reg  [31:0] doptrf$1$d2;
    reg  [31:0] doptrf$1$c0;
    reg  [31:0] doptrf$1$c1;
    reg  [31:0] doptrf$1$c2;
    reg  [31:0] doptrf$1$c;
    reg  [31:0] doptrf$1$e;
    reg  doptrf$1$valid_in;
    reg  doptrf$1$round_up;
    wire  [31:0] doptrf$1$s;
    wire  doptrf$1$flag;
    wire  doptrf$1$valid_out;
    reg  doptrf$2$clock;
    reg  [31:0] doptrf$2$d0;
    reg  [31:0] doptrf$2$d1;
    reg  [31:0] doptrf$2$d2;
    reg  [31:0] doptrf$2$c0;
    reg  [31:0] doptrf$2$c1;
    reg  [31:0] doptrf$2$c2;
    reg  [31:0] doptrf$2$c;
    reg  [31:0] doptrf$2$e;
    reg  doptrf$2$valid_in;
    reg  doptrf$2$round_up;
    wire  [31:0] doptrf$2$s;
    wire  doptrf$2$flag;
    wire  doptrf$2$valid_out;
    reg  doptrf$3$clock;
    reg  [31:0] doptrf$3$d0;
    reg  [31:0] doptrf$3$d1;
    reg  [31:0] doptrf$3$d2;
    reg  [31:0] doptrf$3$c0;
    reg  [31:0] doptrf$3$c1;
    reg  [31:0] doptrf$3$c2;
    reg  [31:0] doptrf$3$c;
    reg  [31:0] doptrf$3$e;
    reg  doptrf$3$valid_in;
    reg  doptrf$3$round_up;
    wire  [31:0] doptrf$3$s;
    wire  doptrf$3$flag;
    wire  doptrf$3$valid_out;
    reg  doptrf$4$clock;
    reg  [31:0] doptrf$4$d0;
    reg  [31:0] doptrf$4$d1;
    reg  [31:0] doptrf$4$d2;
    reg  [31:0] doptrf$4$c0;
    reg  [31:0] doptrf$4$c1;
    reg  [31:0] doptrf$4$c2;
    reg  [31:0] doptrf$4$c;
    reg  [31:0] doptrf$4$e;
    reg  doptrf$4$valid_in;
    reg  doptrf$4$round_up;
    wire  [31:0] doptrf$4$s;
    wire  doptrf$4$flag;
    wire  doptrf$4$valid_out;
    reg  doptrf$5$clock;
    reg  [31:0] doptrf$5$d0;
    reg  [31:0] doptrf$5$d1;
    reg  [31:0] doptrf$5$d2;
    reg  [31:0] doptrf$5$c0;
    reg  [31:0] doptrf$5$c1;
    reg  [31:0] doptrf$5$c2;
    reg  [31:0] doptrf$5$c;
    reg  [31:0] doptrf$5$e;
    reg  doptrf$5$valid_in;
    reg  doptrf$5$round_up;
    wire  [31:0] doptrf$5$s;
    wire  doptrf$5$flag;
    wire  doptrf$5$valid_out;
    reg  doptrf$6$clock;
    reg  [31:0] doptrf$6$d0;
    reg  [31:0] doptrf$6$d1;
    reg  [31:0] doptrf$6$d2;
    reg  [31:0] doptrf$6$c0;
    reg  [31:0] doptrf$6$c1;
    reg  [31:0] doptrf$6$c2;
    reg  [31:0] doptrf$6$c;
    reg  [31:0] doptrf$6$e;
    reg  doptrf$6$valid_in;
    reg  doptrf$6$round_up;
    wire  [31:0] doptrf$6$s;
    wire  doptrf$6$flag;
    wire  doptrf$6$valid_out;
    reg  doptrf$7$clock;
    reg  [31:0] doptrf$7$d0;
    reg  [31:0] doptrf$7$d1;
    reg  [31:0] doptrf$7$d2;
    reg  [31:0] doptrf$7$c0;
    reg  [31:0] doptrf$7$c1;
    reg  [31:0] doptrf$7$c2;
    reg  [31:0] doptrf$7$c;
    reg  [31:0] doptrf$7$e;
    reg  doptrf$7$valid_in;
    reg  doptrf$7$round_up;
    wire  [31:0] doptrf$7$s;
    wire  doptrf$7$flag;
    wire  doptrf$7$valid_out;
    reg  doptrf$8$clock;
    reg  [31:0] doptrf$8$d0;
    reg  [31:0] doptrf$8$d1;
    reg  [31:0] doptrf$8$d2;
    reg  [31:0] doptrf$8$c0;
    reg  [31:0] doptrf$8$c1;
    reg  [31:0] doptrf$8$c2;
    reg  [31:0] doptrf$8$c;
    reg  [31:0] doptrf$8$e;
    reg  doptrf$8$valid_in;
    reg  doptrf$8$round_up;
    wire  [31:0] doptrf$8$s;
    wire  doptrf$8$flag;
    wire  doptrf$8$valid_out;
    reg  doptrf$9$clock;
    reg  [31:0] doptrf$9$d0;
    reg  [31:0] doptrf$9$d1;
    reg  [31:0] doptrf$9$d2;
    reg  [31:0] doptrf$9$c0;
    reg  [31:0] doptrf$9$c1;
    reg  [31:0] doptrf$9$c2;
    reg  [31:0] doptrf$9$c;
    reg  [31:0] doptrf$9$e;
    reg  doptrf$9$valid_in;
    reg  doptrf$9$round_up;
    wire  [31:0] doptrf$9$s;
    wire  doptrf$9$flag;
    wire  doptrf$9$valid_out;
    reg  doptrf$10$clock;
    reg  [31:0] doptrf$10$d0;
    reg  [31:0] doptrf$10$d1;
    reg  [31:0] doptrf$10$d2;
    reg  [31:0] doptrf$10$c0;
    reg  [31:0] doptrf$10$c1;
    reg  [31:0] doptrf$10$c2;
    reg  [31:0] doptrf$10$c;
    reg  [31:0] doptrf$10$e;
    reg  doptrf$10$valid_in;
    reg  doptrf$10$round_up;
    wire  [31:0] doptrf$10$s;
    wire  doptrf$10$flag;
    wire  doptrf$10$valid_out;
    reg  doptrf$11$clock;
    reg  [31:0] doptrf$11$d0;
    reg  [31:0] doptrf$11$d1;
    reg  [31:0] doptrf$11$d2;
    reg  [31:0] doptrf$11$c0;
    reg  [31:0] doptrf$11$c1;
    reg  [31:0] doptrf$11$c2;
    reg  [31:0] doptrf$11$c;
    reg  [31:0] doptrf$11$e;
    reg  doptrf$11$valid_in;
    reg  doptrf$11$round_up;
    wire  [31:0] doptrf$11$s;
    wire  doptrf$11$flag;
    wire  doptrf$11$valid_out;
    reg  doptrf$12$clock;
    reg  [31:0] doptrf$12$d0;
    reg  [31:0] doptrf$12$d1;
    reg  [31:0] doptrf$12$d2;
    reg  [31:0] doptrf$12$c0;
    reg  [31:0] doptrf$12$c1;
    reg  [31:0] doptrf$12$c2;
    reg  [31:0] doptrf$12$c;
    reg  [31:0] doptrf$12$e;
    reg  doptrf$12$valid_in;
    reg  doptrf$12$round_up;
    wire  [31:0] doptrf$12$s;
    wire  doptrf$12$flag;
    wire  doptrf$12$valid_out;
    reg  doptrf$13$clock;
    reg  [31:0] doptrf$13$d0;
    reg  [31:0] doptrf$13$d1;
    reg  [31:0] doptrf$13$d2;
    reg  [31:0] doptrf$13$c0;
    reg  [31:0] doptrf$13$c1;
    reg  [31:0] doptrf$13$c2;
    reg  [31:0] doptrf$13$c;
    reg  [31:0] doptrf$13$e;
    reg  doptrf$13$valid_in;
    reg  doptrf$13$round_up;
    wire  [31:0] doptrf$13$s;
    wire  doptrf$13$flag;
    wire  doptrf$13$valid_out;
    reg  doptrf$14$clock;
    reg  [31:0] doptrf$14$d0;
    reg  [31:0] doptrf$14$d1;
    reg  [31:0] doptrf$14$d2;
    reg  [31:0] doptrf$14$c0;
    reg  [31:0] doptrf$14$c1;
    reg  [31:0] doptrf$14$c2;
    reg  [31:0] doptrf$14$c;
    reg  [31:0] doptrf$14$e;
    reg  doptrf$14$valid_in;
    reg  doptrf$14$round_up;
    wire  [31:0] doptrf$14$s;
    wire  doptrf$14$flag;
    wire  doptrf$14$valid_out;
    reg  doptrf$15$clock;
    reg  [31:0] doptrf$15$d0;
    reg  [31:0] doptrf$15$d1;
    reg  [31:0] doptrf$15$d2;
    reg  [31:0] doptrf$15$c0;
    reg  [31:0] doptrf$15$c1;
    reg  [31:0] doptrf$15$c2;
    reg  [31:0] doptrf$15$c;
    reg  [31:0] doptrf$15$e;
    reg  doptrf$15$valid_in;
    reg  doptrf$15$round_up;
    wire  [31:0] doptrf$15$s;
    wire  doptrf$15$flag;
    wire  doptrf$15$valid_out;
    reg  doptrf$16$clock;
    reg  [31:0] doptrf$16$d0;
    reg  [31:0] doptrf$16$d1;
    reg  [31:0] doptrf$16$d2;
    reg  [31:0] doptrf$16$c0;
    reg  [31:0] doptrf$16$c1;
    reg  [31:0] doptrf$16$c2;
    reg  [31:0] doptrf$16$c;
    reg  [31:0] doptrf$16$e;
    reg  doptrf$16$valid_in;
    reg  doptrf$16$round_up;
    wire  [31:0] doptrf$16$s;
    wire  doptrf$16$flag;
    wire  doptrf$16$valid_out;
    reg  doptrf$17$clock;
    reg  [31:0] doptrf$17$d0;
    reg  [31:0] doptrf$17$d1;
    reg  [31:0] doptrf$17$d2;
    reg  [31:0] doptrf$17$c0;
    reg  [31:0] doptrf$17$c1;
    reg  [31:0] doptrf$17$c2;
    reg  [31:0] doptrf$17$c;
    reg  [31:0] doptrf$17$e;
    reg  doptrf$17$valid_in;
    reg  doptrf$17$round_up;
    wire  [31:0] doptrf$17$s;
    wire  doptrf$17$flag;
    wire  doptrf$17$valid_out;
    reg  doptrf$18$clock;
    reg  [31:0] doptrf$18$d0;
    reg  [31:0] doptrf$18$d1;
    reg  [31:0] doptrf$18$d2;
    reg  [31:0] doptrf$18$c0;
    reg  [31:0] doptrf$18$c1;
    reg  [31:0] doptrf$18$c2;
    reg  [31:0] doptrf$18$c;
    reg  [31:0] doptrf$18$e;
    reg  doptrf$18$valid_in;
    reg  doptrf$18$round_up;
    wire  [31:0] doptrf$18$s;
    wire  doptrf$18$flag;
    wire  doptrf$18$valid_out;
    reg  doptrf$19$clock;
    reg  [31:0] doptrf$19$d0;
    reg  [31:0] doptrf$19$d1;
    reg  [31:0] doptrf$19$d2;
    reg  [31:0] doptrf$19$c0;
    reg  [31:0] doptrf$19$c1;
    reg  [31:0] doptrf$19$c2;
    reg  [31:0] doptrf$19$c;
    reg  [31:0] doptrf$19$e;
    reg  doptrf$19$valid_in;
    reg  doptrf$19$round_up;
    wire  [31:0] doptrf$19$s;
    wire  doptrf$19$flag;
    wire  doptrf$19$valid_out;
    reg  doptrf$20$clock;
    reg  [31:0] doptrf$20$d0;
    reg  [31:0] doptrf$20$d1;
    reg  [31:0] doptrf$20$d2;
    reg  [31:0] doptrf$20$c0;
    reg  [31:0] doptrf$20$c1;
    reg  [31:0] doptrf$20$c2;
    reg  [31:0] doptrf$20$c;
    reg  [31:0] doptrf$20$e;
    reg  doptrf$20$valid_in;
    reg  doptrf$20$round_up;
    wire  [31:0] doptrf$20$s;
    wire  doptrf$20$flag;
    wire  doptrf$20$valid_out;
    reg  doptrf$21$clock;
    reg  [31:0] doptrf$21$d0;
    reg  [31:0] doptrf$21$d1;
    reg  [31:0] doptrf$21$d2;
    reg  [31:0] doptrf$21$c0;
    reg  [31:0] doptrf$21$c1;
    reg  [31:0] doptrf$21$c2;
    reg  [31:0] doptrf$21$c;
    reg  [31:0] doptrf$21$e;
    reg  doptrf$21$valid_in;
    reg  doptrf$21$round_up;
    wire  [31:0] doptrf$21$s;
    wire  doptrf$21$flag;
    wire  doptrf$21$valid_out;
    reg  doptrf$22$clock;
    reg  [31:0] doptrf$22$d0;
    reg  [31:0] doptrf$22$d1;
    reg  [31:0] doptrf$22$d2;
    reg  [31:0] doptrf$22$c0;
    reg  [31:0] doptrf$22$c1;
    reg  [31:0] doptrf$22$c2;
    reg  [31:0] doptrf$22$c;
    reg  [31:0] doptrf$22$e;
    reg  doptrf$22$valid_in;
    reg  doptrf$22$round_up;
    wire  [31:0] doptrf$22$s;
    wire  doptrf$22$flag;
    wire  doptrf$22$valid_out;
    reg  doptrf$23$clock;
    reg  [31:0] doptrf$23$d0;
    reg  [31:0] doptrf$23$d1;
    reg  [31:0] doptrf$23$d2;
    reg  [31:0] doptrf$23$c0;
    reg  [31:0] doptrf$23$c1;
    reg  [31:0] doptrf$23$c2;
    reg  [31:0] doptrf$23$c;
    reg  [31:0] doptrf$23$e;
    reg  doptrf$23$valid_in;
    reg  doptrf$23$round_up;
    wire  [31:0] doptrf$23$s;
    wire  doptrf$23$flag;
    wire  doptrf$23$valid_out;
    reg  [15:0] tag_1$d;
    wire  [15:0] tag_1$q;
    reg  tag_1$clock;
    reg  [15:0] tag_2$d;
    wire  [15:0] tag_2$q;
    reg  tag_2$clock;
    reg  [15:0] tag_3$d;
    wire  [15:0] tag_3$q;
    reg  tag_3$clock;
    reg  [15:0] tag_4$d;
    wire  [15:0] tag_4$q;
    reg  tag_4$clock;
    reg  [15:0] tag_5$d;
    wire  [15:0] tag_5$q;
    reg  tag_5$clock;
    reg  [15:0] tag_6$d;
    wire  [15:0] tag_6$q;
    reg  tag_6$clock;
    reg  [15:0] tag_7$d;
    wire  [15:0] tag_7$q;
    reg  tag_7$clock;
    reg  [15:0] tag_8$d;
    wire  [15:0] tag_8$q;
    reg  tag_8$clock;
    reg  [15:0] tag_9$d;
    wire  [15:0] tag_9$q;
    reg  tag_9$clock;
    reg  [15:0] tag_10$d;
    wire  [15:0] tag_10$q;
    reg  tag_10$clock;
    reg  [15:0] tag_11$d;
    wire  [15:0] tag_11$q;
    reg  tag_11$clock;
    reg  [15:0] tag_12$d;
    wire  [15:0] tag_12$q;
    reg  tag_12$clock;
    reg  [15:0] tag_13$d;
    wire  [15:0] tag_13$q;
    reg  tag_13$clock;
    reg  [15:0] tag_14$d;
    wire  [15:0] tag_14$q;
    reg  tag_14$clock;
    reg  [15:0] tag_15$d;
    wire  [15:0] tag_15$q;
    reg  tag_15$clock;
    
    // Local signals
    reg  c_any;
    
    // Sub module instances
    top$setup setup(
        .clock(setup$clock),
        .load_en(setup$load_en),
        .load_addr(setup$load_addr),
        .load_data(setup$load_data),
        .c0$0(setup$c0$0),
        .c0$1(setup$c0$1),
        .c0$2(setup$c0$2),
        .c0$3(setup$c0$3),
        .c0$4(setup$c0$4),
        .c0$5(setup$c0$5),
        .c0$6(setup$c0$6),
        .c0$7(setup$c0$7),
        .c0$8(setup$c0$8),
        .c0$9(setup$c0$9),
        .c0$10(setup$c0$10),
        .c0$11(setup$c0$11),
        .c0$12(setup$c0$12),
        .c0$13(setup$c0$13),
        .c0$14(setup$c0$14),
        .c0$15(setup$c0$15),
        .c0$16(setup$c0$16),
        .c0$17(setup$c0$17),
        .c0$18(setup$c0$18),
        .c0$19(setup$c0$19),
        .c0$20(setup$c0$20),
        .c0$21(setup$c0$21),
        .c0$22(setup$c0$22),
        .c0$23(setup$c0$23),
        .c1$0(setup$c1$0),
        .c1$1(setup$c1$1),
        .c1$2(setup$c1$2),
        .c1$3(setup$c1$3),
        .c1$4(setup$c1$4),
        .c1$5(setup$c1$5),
        .c1$6(setup$c1$6),
        .c1$7(setup$c1$7),
        .c1$8(setup$c1$8),
        .c1$9(setup$c1$9),
        .c1$10(setup$c1$10),
        .c1$11(setup$c1$11),
        .c1$12(setup$c1$12),
        .c1$13(setup$c1$13),
        .c1$14(setup$c1$14),
        .c1$15(setup$c1$15),
        .c1$16(setup$c1$16),
        .c1$17(setup$c1$17),
        .c1$18(setup$c1$18),
        .c1$19(setup$c1$19),
        .c1$20(setup$c1$20),
        .c1$21(setup$c1$21),
        .c1$22(setup$c1$22),
        .c1$23(setup$c1$23),
        .c2$0(setup$c2$0),
        .c2$1(setup$c2$1),
        .c2$2(setup$c2$2),
        .c2$3(setup$c2$3),
        .c2$4(setup$c2$4),
        .c2$5(setup$c2$5),
        .c2$6(setup$c2$6),
        .c2$7(setup$c2$7),
        .c2$8(setup$c2$8),
        .c2$9(setup$c2$9),
        .c2$10(setup$c2$10),
        .c2$11(setup$c2$11),
        .c2$12(setup$c2$12),
        .c2$13(setup$c2$13),
        .c2$14(setup$c2$14),
        .c2$15(setup$c2$15),
        .c2$16(setup$c2$16),
        .c2$17(setup$c2$17),
        .c2$18(setup$c2$18),
        .c2$19(setup$c2$19),
        .c2$20(setup$c2$20),
        .c2$21(setup$c2$21),
        .c2$22(setup$c2$22),
        .c2$23(setup$c2$23),
        .c$0(setup$c$0),
        .c$1(setup$c$1),
        .c$2(setup$c$2),
        .c$3(setup$c$3),
        .c$4(setup$c$4),
        .c$5(setup$c$5),
        .c$6(setup$c$6),
        .c$7(setup$c$7),
        .c$8(setup$c$8),
        .c$9(setup$c$9),
        .c$10(setup$c$10),
        .c$11(setup$c$11),
        .c$12(setup$c$12),
        .c$13(setup$c$13),
        .c$14(setup$c$14),
        .c$15(setup$c$15),
        .c$16(setup$c$16),
        .c$17(setup$c$17),
        .c$18(setup$c$18),
        .c$19(setup$c$19),
        .c$20(setup$c$20),
        .c$21(setup$c$21),
        .c$22(setup$c$22),
        .c$23(setup$c$23),
        .j0$0(setup$j0$0),
        .j0$1(setup$j0$1),
        .j0$2(setup$j0$2),
        .j0$3(setup$j0$3),
        .j0$4(setup$j0$4),
        .j0$5(setup$j0$5),
        .j0$6(setup$j0$6),
        .j0$7(setup$j0$7),
        .j0$8(setup$j0$8),
        .j0$9(setup$j0$9),
        .j0$10(setup$j0$10),
        .j0$11(setup$j0$11),
        .j0$12(setup$j0$12),
        .j0$13(setup$j0$13),
        .j0$14(setup$j0$14),
        .j0$15(setup$j0$15),
        .j0$16(setup$j0$16),
        .j0$17(setup$j0$17),
        .j0$18(setup$j0$18),
        .j0$19(setup$j0$19),
        .j0$20(setup$j0$20),
        .j0$21(setup$j0$21),
        .j0$22(setup$j0$22),
        .j0$23(setup$j0$23),
        .j1$0(setup$j1$0),
        .j1$1(setup$j1$1),
        .j1$2(setup$j1$2),
        .j1$3(setup$j1$3),
        .j1$4(setup$j1$4),
        .j1$5(setup$j1$5),
        .j1$6(setup$j1$6),
        .j1$7(setup$j1$7),
        .j1$8(setup$j1$8),
        .j1$9(setup$j1$9),
        .j1$10(setup$j1$10),
        .j1$11(setup$j1$11),
        .j1$12(setup$j1$12),
        .j1$13(setup$j1$13),
        .j1$14(setup$j1$14),
        .j1$15(setup$j1$15),
        .j1$16(setup$j1$16),
        .j1$17(setup$j1$17),
        .j1$18(setup$j1$18),
        .j1$19(setup$j1$19),
        .j1$20(setup$j1$20),
        .j1$21(setup$j1$21),
        .j1$22(setup$j1$22),
        .j1$23(setup$j1$23),
        .j2$0(setup$j2$0),
        .j2$1(setup$j2$1),
        .j2$2(setup$j2$2),
        .j2$3(setup$j2$3),
        .j2$4(setup$j2$4),
        .j2$5(setup$j2$5),
        .j2$6(setup$j2$6),
        .j2$7(setup$j2$7),
        .j2$8(setup$j2$8),
        .j2$9(setup$j2$9),
        .j2$10(setup$j2$10),
        .j2$11(setup$j2$11),
        .j2$12(setup$j2$12),
        .j2$13(setup$j2$13),
        .j2$14(setup$j2$14),
        .j2$15(setup$j2$15),
        .j2$16(setup$j2$16),
        .j2$17(setup$j2$17),
        .j2$18(setup$j2$18),
        .j2$19(setup$j2$19),
        .j2$20(setup$j2$20),
        .j2$21(setup$j2$21),
        .j2$22(setup$j2$22),
        .j2$23(setup$j2$23),
        .round_up$0(setup$round_up$0),
        .round_up$1(setup$round_up$1),
        .round_up$2(setup$round_up$2),
        .round_up$3(setup$round_up$3),
        .round_up$4(setup$round_up$4),
        .round_up$5(setup$round_up$5),
        .round_up$6(setup$round_up$6),
        .round_up$7(setup$round_up$7),
        .round_up$8(setup$round_up$8),
        .round_up$9(setup$round_up$9),
        .round_up$10(setup$round_up$10),
        .round_up$11(setup$round_up$11),
        .round_up$12(setup$round_up$12),
        .round_up$13(setup$round_up$13),
        .round_up$14(setup$round_up$14),
        .round_up$15(setup$round_up$15),
        .round_up$16(setup$round_up$16),
        .round_up$17(setup$round_up$17),
        .round_up$18(setup$round_up$18),
        .round_up$19(setup$round_up$19),
        .round_up$20(setup$round_up$20),
        .round_up$21(setup$round_up$21),
        .round_up$22(setup$round_up$22),
        .round_up$23(setup$round_up$23)
    );
    top$klmsel klmsel(
        .d$0(klmsel$d$0),
        .d$1(klmsel$d$1),
        .d$2(klmsel$d$2),
        .d$3(klmsel$d$3),
        .d$4(klmsel$d$4),
        .d$5(klmsel$d$5),
        .d$6(klmsel$d$6),
        .d$7(klmsel$d$7),
        .d$8(klmsel$d$8),
        .d$9(klmsel$d$9),
        .d$10(klmsel$d$10),
        .d$11(klmsel$d$11),
        .d$12(klmsel$d$12),
        .d$13(klmsel$d$13),
        .d$14(klmsel$d$14),
        .d$15(klmsel$d$15),
        .d$16(klmsel$d$16),
        .d$17(klmsel$d$17),
        .d$18(klmsel$d$18),
        .d$19(klmsel$d$19),
        .d$20(klmsel$d$20),
        .d$21(klmsel$d$21),
        .d$22(klmsel$d$22),
        .d$23(klmsel$d$23),
        .j0$0(klmsel$j0$0),
        .j0$1(klmsel$j0$1),
        .j0$2(klmsel$j0$2),
        .j0$3(klmsel$j0$3),
        .j0$4(klmsel$j0$4),
        .j0$5(klmsel$j0$5),
        .j0$6(klmsel$j0$6),
        .j0$7(klmsel$j0$7),
        .j0$8(klmsel$j0$8),
        .j0$9(klmsel$j0$9),
        .j0$10(klmsel$j0$10),
        .j0$11(klmsel$j0$11),
        .j0$12(klmsel$j0$12),
        .j0$13(klmsel$j0$13),
        .j0$14(klmsel$j0$14),
        .j0$15(klmsel$j0$15),
        .j0$16(klmsel$j0$16),
        .j0$17(klmsel$j0$17),
        .j0$18(klmsel$j0$18),
        .j0$19(klmsel$j0$19),
        .j0$20(klmsel$j0$20),
        .j0$21(klmsel$j0$21),
        .j0$22(klmsel$j0$22),
        .j0$23(klmsel$j0$23),
        .j1$0(klmsel$j1$0),
        .j1$1(klmsel$j1$1),
        .j1$2(klmsel$j1$2),
        .j1$3(klmsel$j1$3),
        .j1$4(klmsel$j1$4),
        .j1$5(klmsel$j1$5),
        .j1$6(klmsel$j1$6),
        .j1$7(klmsel$j1$7),
        .j1$8(klmsel$j1$8),
        .j1$9(klmsel$j1$9),
        .j1$10(klmsel$j1$10),
        .j1$11(klmsel$j1$11),
        .j1$12(klmsel$j1$12),
        .j1$13(klmsel$j1$13),
        .j1$14(klmsel$j1$14),
        .j1$15(klmsel$j1$15),
        .j1$16(klmsel$j1$16),
        .j1$17(klmsel$j1$17),
        .j1$18(klmsel$j1$18),
        .j1$19(klmsel$j1$19),
        .j1$20(klmsel$j1$20),
        .j1$21(klmsel$j1$21),
        .j1$22(klmsel$j1$22),
        .j1$23(klmsel$j1$23),
        .j2$0(klmsel$j2$0),
        .j2$1(klmsel$j2$1),
        .j2$2(klmsel$j2$2),
        .j2$3(klmsel$j2$3),
        .j2$4(klmsel$j2$4),
        .j2$5(klmsel$j2$5),
        .j2$6(klmsel$j2$6),
        .j2$7(klmsel$j2$7),
        .j2$8(klmsel$j2$8),
        .j2$9(klmsel$j2$9),
        .j2$10(klmsel$j2$10),
        .j2$11(klmsel$j2$11),
        .j2$12(klmsel$j2$12),
        .j2$13(klmsel$j2$13),
        .j2$14(klmsel$j2$14),
        .j2$15(klmsel$j2$15),
        .j2$16(klmsel$j2$16),
        .j2$17(klmsel$j2$17),
        .j2$18(klmsel$j2$18),
        .j2$19(klmsel$j2$19),
        .j2$20(klmsel$j2$20),
        .j2$21(klmsel$j2$21),
        .j2$22(klmsel$j2$22),
        .j2$23(klmsel$j2$23),
        .y0$0(klmsel$y0$0),
        .y0$1(klmsel$y0$1),
        .y0$2(klmsel$y0$2),
        .y0$3(klmsel$y0$3),
        .y0$4(klmsel$y0$4),
        .y0$5(klmsel$y0$5),
        .y0$6(klmsel$y0$6),
        .y0$7(klmsel$y0$7),
        .y0$8(klmsel$y0$8),
        .y0$9(klmsel$y0$9),
        .y0$10(klmsel$y0$10),
        .y0$11(klmsel$y0$11),
        .y0$12(klmsel$y0$12),
        .y0$13(klmsel$y0$13),
        .y0$14(klmsel$y0$14),
        .y0$15(klmsel$y0$15),
        .y0$16(klmsel$y0$16),
        .y0$17(klmsel$y0$17),
        .y0$18(klmsel$y0$18),
        .y0$19(klmsel$y0$19),
        .y0$20(klmsel$y0$20),
        .y0$21(klmsel$y0$21),
        .y0$22(klmsel$y0$22),
        .y0$23(klmsel$y0$23),
        .y1$0(klmsel$y1$0),
        .y1$1(klmsel$y1$1),
        .y1$2(klmsel$y1$2),
        .y1$3(klmsel$y1$3),
        .y1$4(klmsel$y1$4),
        .y1$5(klmsel$y1$5),
        .y1$6(klmsel$y1$6),
        .y1$7(klmsel$y1$7),
        .y1$8(klmsel$y1$8),
        .y1$9(klmsel$y1$9),
        .y1$10(klmsel$y1$10),
        .y1$11(klmsel$y1$11),
        .y1$12(klmsel$y1$12),
        .y1$13(klmsel$y1$13),
        .y1$14(klmsel$y1$14),
        .y1$15(klmsel$y1$15),
        .y1$16(klmsel$y1$16),
        .y1$17(klmsel$y1$17),
        .y1$18(klmsel$y1$18),
        .y1$19(klmsel$y1$19),
        .y1$20(klmsel$y1$20),
        .y1$21(klmsel$y1$21),
        .y1$22(klmsel$y1$22),
        .y1$23(klmsel$y1$23),
        .y2$0(klmsel$y2$0),
        .y2$1(klmsel$y2$1),
        .y2$2(klmsel$y2$2),
        .y2$3(klmsel$y2$3),
        .y2$4(klmsel$y2$4),
        .y2$5(klmsel$y2$5),
        .y2$6(klmsel$y2$6),
        .y2$7(klmsel$y2$7),
        .y2$8(klmsel$y2$8),
        .y2$9(klmsel$y2$9),
        .y2$10(klmsel$y2$10),
        .y2$11(klmsel$y2$11),
        .y2$12(klmsel$y2$12),
        .y2$13(klmsel$y2$13),
        .y2$14(klmsel$y2$14),
        .y2$15(klmsel$y2$15),
        .y2$16(klmsel$y2$16),
        .y2$17(klmsel$y2$17),
        .y2$18(klmsel$y2$18),
        .y2$19(klmsel$y2$19),
        .y2$20(klmsel$y2$20),
        .y2$21(klmsel$y2$21),
        .y2$22(klmsel$y2$22),
        .y2$23(klmsel$y2$23)
    );
    top$doptrf$0 doptrf$0(
        .clock(doptrf$0$clock),
        .d0(doptrf$0$d0),
        .d1(doptrf$0$d1),
        .d2(doptrf$0$d2),
        .c0(doptrf$0$c0),
        .c1(doptrf$0$c1),
        .c2(doptrf$0$c2),
        .c(doptrf$0$c),
        .e(doptrf$0$e),
        .valid_in(doptrf$0$valid_in),
        .round_up(doptrf$0$round_up),
        .s(doptrf$0$s),
        .flag(doptrf$0$flag),
        .valid_out(doptrf$0$valid_out)
    );
    top$doptrf$0 doptrf$1(
        .clock(doptrf$1$clock),
        .d0(doptrf$1$d0),
        .d1(doptrf$1$d1),
        .d2(doptrf$1$d2),
        .c0(doptrf$1$c0),
        .c1(doptrf$1$c1),
        .c2(doptrf$1$c2),
        .c(doptrf$1$c),
        .e(doptrf$1$e),
        .valid_in(doptrf$1$valid_in),
        .round_up(doptrf$1$round_up),
        .s(doptrf$1$s),
        .flag(doptrf$1$flag),
        .valid_out(doptrf$1$valid_out)
    );
    top$doptrf$0 doptrf$2(
        .clock(doptrf$2$clock),
        .d0(doptrf$2$d0),
        .d1(doptrf$2$d1),
        .d2(doptrf$2$d2),
        .c0(doptrf$2$c0),
        .c1(doptrf$2$c1),
        .c2(doptrf$2$c2),
        .c(doptrf$2$c),
        .e(doptrf$2$e),
        .valid_in(doptrf$2$valid_in),
        .round_up(doptrf$2$round_up),
        .s(doptrf$2$s),
        .flag(doptrf$2$flag),
        .valid_out(doptrf$2$valid_out)
    );
    top$doptrf$0 doptrf$3(
        .clock(doptrf$3$clock),
        .d0(doptrf$3$d0),
        .d1(doptrf$3$d1),
        .d2(doptrf$3$d2),
        .c0(doptrf$3$c0),
        .c1(doptrf$3$c1),
        .c2(doptrf$3$c2),
        .c(doptrf$3$c),
        .e(doptrf$3$e),
        .valid_in(doptrf$3$valid_in),
        .round_up(doptrf$3$round_up),
        .s(doptrf$3$s),
        .flag(doptrf$3$flag),
        .valid_out(doptrf$3$valid_out)
    );
    top$doptrf$0 doptrf$4(
        .clock(doptrf$4$clock),
        .d0(doptrf$4$d0),
        .d1(doptrf$4$d1),
        .d2(doptrf$4$d2),
        .c0(doptrf$4$c0),
        .c1(doptrf$4$c1),
        .c2(doptrf$4$c2),
        .c(doptrf$4$c),
        .e(doptrf$4$e),
        .valid_in(doptrf$4$valid_in),
        .round_up(doptrf$4$round_up),
        .s(doptrf$4$s),
        .flag(doptrf$4$flag),
        .valid_out(doptrf$4$valid_out)
    );
    top$doptrf$0 doptrf$5(
        .clock(doptrf$5$clock),
        .d0(doptrf$5$d0),
        .d1(doptrf$5$d1),
        .d2(doptrf$5$d2),
        .c0(doptrf$5$c0),
        .c1(doptrf$5$c1),
        .c2(doptrf$5$c2),
        .c(doptrf$5$c),
        .e(doptrf$5$e),
        .valid_in(doptrf$5$valid_in),
        .round_up(doptrf$5$round_up),
        .s(doptrf$5$s),
        .flag(doptrf$5$flag),
        .valid_out(doptrf$5$valid_out)
    );
    top$doptrf$0 doptrf$6(
        .clock(doptrf$6$clock),
        .d0(doptrf$6$d0),
        .d1(doptrf$6$d1),
        .d2(doptrf$6$d2),
        .c0(doptrf$6$c0),
        .c1(doptrf$6$c1),
        .c2(doptrf$6$c2),
        .c(doptrf$6$c),
        .e(doptrf$6$e),
        .valid_in(doptrf$6$valid_in),
        .round_up(doptrf$6$round_up),
        .s(doptrf$6$s),
        .flag(doptrf$6$flag),
        .valid_out(doptrf$6$valid_out)
    );
    top$doptrf$0 doptrf$7(
        .clock(doptrf$7$clock),
        .d0(doptrf$7$d0),
        .d1(doptrf$7$d1),
        .d2(doptrf$7$d2),
        .c0(doptrf$7$c0),
        .c1(doptrf$7$c1),
        .c2(doptrf$7$c2),
        .c(doptrf$7$c),
        .e(doptrf$7$e),
        .valid_in(doptrf$7$valid_in),
        .round_up(doptrf$7$round_up),
        .s(doptrf$7$s),
        .flag(doptrf$7$flag),
        .valid_out(doptrf$7$valid_out)
    );
    top$doptrf$0 doptrf$8(
        .clock(doptrf$8$clock),
        .d0(doptrf$8$d0),
        .d1(doptrf$8$d1),
        .d2(doptrf$8$d2),
        .c0(doptrf$8$c0),
        .c1(doptrf$8$c1),
        .c2(doptrf$8$c2),
        .c(doptrf$8$c),
        .e(doptrf$8$e),
        .valid_in(doptrf$8$valid_in),
        .round_up(doptrf$8$round_up),
        .s(doptrf$8$s),
        .flag(doptrf$8$flag),
        .valid_out(doptrf$8$valid_out)
    );
    top$doptrf$0 doptrf$9(
        .clock(doptrf$9$clock),
        .d0(doptrf$9$d0),
        .d1(doptrf$9$d1),
        .d2(doptrf$9$d2),
        .c0(doptrf$9$c0),
        .c1(doptrf$9$c1),
        .c2(doptrf$9$c2),
        .c(doptrf$9$c),
        .e(doptrf$9$e),
        .valid_in(doptrf$9$valid_in),
        .round_up(doptrf$9$round_up),
        .s(doptrf$9$s),
        .flag(doptrf$9$flag),
        .valid_out(doptrf$9$valid_out)
    );
    top$doptrf$0 doptrf$10(
        .clock(doptrf$10$clock),
        .d0(doptrf$10$d0),
        .d1(doptrf$10$d1),
        .d2(doptrf$10$d2),
        .c0(doptrf$10$c0),
        .c1(doptrf$10$c1),
        .c2(doptrf$10$c2),
        .c(doptrf$10$c),
        .e(doptrf$10$e),
        .valid_in(doptrf$10$valid_in),
        .round_up(doptrf$10$round_up),
        .s(doptrf$10$s),
        .flag(doptrf$10$flag),
        .valid_out(doptrf$10$valid_out)
    );
    top$doptrf$0 doptrf$11(
        .clock(doptrf$11$clock),
        .d0(doptrf$11$d0),
        .d1(doptrf$11$d1),
        .d2(doptrf$11$d2),
        .c0(doptrf$11$c0),
        .c1(doptrf$11$c1),
        .c2(doptrf$11$c2),
        .c(doptrf$11$c),
        .e(doptrf$11$e),
        .valid_in(doptrf$11$valid_in),
        .round_up(doptrf$11$round_up),
        .s(doptrf$11$s),
        .flag(doptrf$11$flag),
        .valid_out(doptrf$11$valid_out)
    );
    top$doptrf$0 doptrf$12(
        .clock(doptrf$12$clock),
        .d0(doptrf$12$d0),
        .d1(doptrf$12$d1),
        .d2(doptrf$12$d2),
        .c0(doptrf$12$c0),
        .c1(doptrf$12$c1),
        .c2(doptrf$12$c2),
        .c(doptrf$12$c),
        .e(doptrf$12$e),
        .valid_in(doptrf$12$valid_in),
        .round_up(doptrf$12$round_up),
        .s(doptrf$12$s),
        .flag(doptrf$12$flag),
        .valid_out(doptrf$12$valid_out)
    );
    top$doptrf$0 doptrf$13(
        .clock(doptrf$13$clock),
        .d0(doptrf$13$d0),
        .d1(doptrf$13$d1),
        .d2(doptrf$13$d2),
        .c0(doptrf$13$c0),
        .c1(doptrf$13$c1),
        .c2(doptrf$13$c2),
        .c(doptrf$13$c),
        .e(doptrf$13$e),
        .valid_in(doptrf$13$valid_in),
        .round_up(doptrf$13$round_up),
        .s(doptrf$13$s),
        .flag(doptrf$13$flag),
        .valid_out(doptrf$13$valid_out)
    );
    top$doptrf$0 doptrf$14(
        .clock(doptrf$14$clock),
        .d0(doptrf$14$d0),
        .d1(doptrf$14$d1),
        .d2(doptrf$14$d2),
        .c0(doptrf$14$c0),
        .c1(doptrf$14$c1),
        .c2(doptrf$14$c2),
        .c(doptrf$14$c),
        .e(doptrf$14$e),
        .valid_in(doptrf$14$valid_in),
        .round_up(doptrf$14$round_up),
        .s(doptrf$14$s),
        .flag(doptrf$14$flag),
        .valid_out(doptrf$14$valid_out)
    );
    top$doptrf$0 doptrf$15(
        .clock(doptrf$15$clock),
        .d0(doptrf$15$d0),
        .d1(doptrf$15$d1),
        .d2(doptrf$15$d2),
        .c0(doptrf$15$c0),
        .c1(doptrf$15$c1),
        .c2(doptrf$15$c2),
        .c(doptrf$15$c),
        .e(doptrf$15$e),
        .valid_in(doptrf$15$valid_in),
        .round_up(doptrf$15$round_up),
        .s(doptrf$15$s),
        .flag(doptrf$15$flag),
        .valid_out(doptrf$15$valid_out)
    );
    top$doptrf$0 doptrf$16(
        .clock(doptrf$16$clock),
        .d0(doptrf$16$d0),
        .d1(doptrf$16$d1),
        .d2(doptrf$16$d2),
        .c0(doptrf$16$c0),
        .c1(doptrf$16$c1),
        .c2(doptrf$16$c2),
        .c(doptrf$16$c),
        .e(doptrf$16$e),
        .valid_in(doptrf$16$valid_in),
        .round_up(doptrf$16$round_up),
        .s(doptrf$16$s),
        .flag(doptrf$16$flag),
        .valid_out(doptrf$16$valid_out)
    );
    top$doptrf$0 doptrf$17(
        .clock(doptrf$17$clock),
        .d0(doptrf$17$d0),
        .d1(doptrf$17$d1),
        .d2(doptrf$17$d2),
        .c0(doptrf$17$c0),
        .c1(doptrf$17$c1),
        .c2(doptrf$17$c2),
        .c(doptrf$17$c),
        .e(doptrf$17$e),
        .valid_in(doptrf$17$valid_in),
        .round_up(doptrf$17$round_up),
        .s(doptrf$17$s),
        .flag(doptrf$17$flag),
        .valid_out(doptrf$17$valid_out)
    );
    top$doptrf$0 doptrf$18(
        .clock(doptrf$18$clock),
        .d0(doptrf$18$d0),
        .d1(doptrf$18$d1),
        .d2(doptrf$18$d2),
        .c0(doptrf$18$c0),
        .c1(doptrf$18$c1),
        .c2(doptrf$18$c2),
        .c(doptrf$18$c),
        .e(doptrf$18$e),
        .valid_in(doptrf$18$valid_in),
        .round_up(doptrf$18$round_up),
        .s(doptrf$18$s),
        .flag(doptrf$18$flag),
        .valid_out(doptrf$18$valid_out)
    );
    top$doptrf$0 doptrf$19(
        .clock(doptrf$19$clock),
        .d0(doptrf$19$d0),
        .d1(doptrf$19$d1),
        .d2(doptrf$19$d2),
        .c0(doptrf$19$c0),
        .c1(doptrf$19$c1),
        .c2(doptrf$19$c2),
        .c(doptrf$19$c),
        .e(doptrf$19$e),
        .valid_in(doptrf$19$valid_in),
        .round_up(doptrf$19$round_up),
        .s(doptrf$19$s),
        .flag(doptrf$19$flag),
        .valid_out(doptrf$19$valid_out)
    );
    top$doptrf$0 doptrf$20(
        .clock(doptrf$20$clock),
        .d0(doptrf$20$d0),
        .d1(doptrf$20$d1),
        .d2(doptrf$20$d2),
        .c0(doptrf$20$c0),
        .c1(doptrf$20$c1),
        .c2(doptrf$20$c2),
        .c(doptrf$20$c),
        .e(doptrf$20$e),
        .valid_in(doptrf$20$valid_in),
        .round_up(doptrf$20$round_up),
        .s(doptrf$20$s),
        .flag(doptrf$20$flag),
        .valid_out(doptrf$20$valid_out)
    );
    top$doptrf$0 doptrf$21(
        .clock(doptrf$21$clock),
        .d0(doptrf$21$d0),
        .d1(doptrf$21$d1),
        .d2(doptrf$21$d2),
        .c0(doptrf$21$c0),
        .c1(doptrf$21$c1),
        .c2(doptrf$21$c2),
        .c(doptrf$21$c),
        .e(doptrf$21$e),
        .valid_in(doptrf$21$valid_in),
        .round_up(doptrf$21$round_up),
        .s(doptrf$21$s),
        .flag(doptrf$21$flag),
        .valid_out(doptrf$21$valid_out)
    );
    top$doptrf$0 doptrf$22(
        .clock(doptrf$22$clock),
        .d0(doptrf$22$d0),
        .d1(doptrf$22$d1),
        .d2(doptrf$22$d2),
        .c0(doptrf$22$c0),
        .c1(doptrf$22$c1),
        .c2(doptrf$22$c2),
        .c(doptrf$22$c),
        .e(doptrf$22$e),
        .valid_in(doptrf$22$valid_in),
        .round_up(doptrf$22$round_up),
        .s(doptrf$22$s),
        .flag(doptrf$22$flag),
        .valid_out(doptrf$22$valid_out)
    );
    top$doptrf$0 doptrf$23(
        .clock(doptrf$23$clock),
        .d0(doptrf$23$d0),
        .d1(doptrf$23$d1),
        .d2(doptrf$23$d2),
        .c0(doptrf$23$c0),
        .c1(doptrf$23$c1),
        .c2(doptrf$23$c2),
        .c(doptrf$23$c),
        .e(doptrf$23$e),
        .valid_in(doptrf$23$valid_in),
        .round_up(doptrf$23$round_up),
        .s(doptrf$23$s),
        .flag(doptrf$23$flag),
        .valid_out(doptrf$23$valid_out)
    );
    top$tag_1 tag_1(
        .d(tag_1$d),
        .q(tag_1$q),
        .clock(tag_1$clock)
    );
    top$tag_1 tag_2(
        .d(tag_2$d),
        .q(tag_2$q),
        .clock(tag_2$clock)
    );
    top$tag_1 tag_3(
        .d(tag_3$d),
        .q(tag_3$q),
        .clock(tag_3$clock)
    );
    top$tag_1 tag_4(
        .d(tag_4$d),
        .q(tag_4$q),
        .clock(tag_4$clock)
    );
    top$tag_1 tag_5(
        .d(tag_5$d),
        .q(tag_5$q),
        .clock(tag_5$clock)
    );
    top$tag_1 tag_6(
        .d(tag_6$d),
        .q(tag_6$q),
        .clock(tag_6$clock)
    );
    top$tag_1 tag_7(
        .d(tag_7$d),
        .q(tag_7$q),
        .clock(tag_7$clock)
    );
    top$tag_1 tag_8(
        .d(tag_8$d),
        .q(tag_8$q),
        .clock(tag_8$clock)
    );
    top$tag_1 tag_9(
        .d(tag_9$d),
        .q(tag_9$q),
        .clock(tag_9$clock)
    );
    top$tag_1 tag_10(
        .d(tag_10$d),
        .q(tag_10$q),
        .clock(tag_10$clock)
    );
    top$tag_1 tag_11(
        .d(tag_11$d),
        .q(tag_11$q),
        .clock(tag_11$clock)
    );
    top$tag_1 tag_12(
        .d(tag_12$d),
        .q(tag_12$q),
        .clock(tag_12$clock)
    );
    top$tag_1 tag_13(
        .d(tag_13$d),
        .q(tag_13$q),
        .clock(tag_13$clock)
    );
    top$tag_1 tag_14(
        .d(tag_14$d),
        .q(tag_14$q),
        .clock(tag_14$clock)
    );
    top$tag_1 tag_15(
        .d(tag_15$d),
        .q(tag_15$q),
        .clock(tag_15$clock)
    );
    
    // Update code
    always @(*) begin
        tag_1$clock = clock;
        tag_2$clock = clock;
        tag_3$clock = clock;
        tag_4$clock = clock;
        tag_5$clock = clock;
        tag_6$clock = clock;
        tag_7$clock = clock;
        tag_8$clock = clock;
        tag_1$d = tag_1$q;
        tag_2$d = tag_2$q;
        tag_3$d = tag_3$q;
        tag_4$d = tag_4$q;
        tag_5$d = tag_5$q;
        tag_6$d = tag_6$q;
        tag_7$d = tag_7$q;
        tag_8$d = tag_8$q;
        tag_9$clock = clock;
        tag_10$clock = clock;
        tag_11$clock = clock;
        tag_12$clock = clock;
        tag_13$clock = clock;
        tag_14$clock = clock;
        tag_15$clock = clock;
        tag_9$d = tag_9$q;
        tag_10$d = tag_10$q;
        tag_11$d = tag_11$q;
        tag_12$d = tag_12$q;
        tag_13$d = tag_13$q;
        tag_14$d = tag_14$q;
        tag_15$d = tag_15$q;
        setup$clock = clock;
        setup$load_en = load_en;
        setup$load_addr = load_addr;
        setup$load_data = load_data;
        doptrf$0$clock = clock;
        klmsel$d$0 = d$0;
        klmsel$j0$0 = setup$j0$0;
        klmsel$j1$0 = setup$j1$0;
        klmsel$j2$0 = setup$j2$0;
        doptrf$0$d0 = klmsel$y0$0;
        doptrf$0$d1 = klmsel$y1$0;
        doptrf$0$d2 = klmsel$y2$0;
        doptrf$0$c0 = setup$c0$0;
        doptrf$0$c1 = setup$c1$0;
        doptrf$0$c2 = setup$c2$0;
        doptrf$0$c = setup$c$0;
        doptrf$0$round_up = setup$round_up$0;
        doptrf$0$valid_in = valid_in;
        doptrf$1$clock = clock;
        klmsel$d$1 = d$1;
        klmsel$j0$1 = setup$j0$1;
        klmsel$j1$1 = setup$j1$1;
        klmsel$j2$1 = setup$j2$1;
        doptrf$1$d0 = klmsel$y0$1;
        doptrf$1$d1 = klmsel$y1$1;
        doptrf$1$d2 = klmsel$y2$1;
        doptrf$1$c0 = setup$c0$1;
        doptrf$1$c1 = setup$c1$1;
        doptrf$1$c2 = setup$c2$1;
        doptrf$1$c = setup$c$1;
        doptrf$1$round_up = setup$round_up$1;
        doptrf$1$valid_in = valid_in;
        doptrf$2$clock = clock;
        klmsel$d$2 = d$2;
        klmsel$j0$2 = setup$j0$2;
        klmsel$j1$2 = setup$j1$2;
        klmsel$j2$2 = setup$j2$2;
        doptrf$2$d0 = klmsel$y0$2;
        doptrf$2$d1 = klmsel$y1$2;
        doptrf$2$d2 = klmsel$y2$2;
        doptrf$2$c0 = setup$c0$2;
        doptrf$2$c1 = setup$c1$2;
        doptrf$2$c2 = setup$c2$2;
        doptrf$2$c = setup$c$2;
        doptrf$2$round_up = setup$round_up$2;
        doptrf$2$valid_in = valid_in;
        doptrf$3$clock = clock;
        klmsel$d$3 = d$3;
        klmsel$j0$3 = setup$j0$3;
        klmsel$j1$3 = setup$j1$3;
        klmsel$j2$3 = setup$j2$3;
        doptrf$3$d0 = klmsel$y0$3;
        doptrf$3$d1 = klmsel$y1$3;
        doptrf$3$d2 = klmsel$y2$3;
        doptrf$3$c0 = setup$c0$3;
        doptrf$3$c1 = setup$c1$3;
        doptrf$3$c2 = setup$c2$3;
        doptrf$3$c = setup$c$3;
        doptrf$3$round_up = setup$round_up$3;
        doptrf$3$valid_in = valid_in;
        doptrf$4$clock = clock;
        klmsel$d$4 = d$4;
        klmsel$j0$4 = setup$j0$4;
        klmsel$j1$4 = setup$j1$4;
        klmsel$j2$4 = setup$j2$4;
        doptrf$4$d0 = klmsel$y0$4;
        doptrf$4$d1 = klmsel$y1$4;
        doptrf$4$d2 = klmsel$y2$4;
        doptrf$4$c0 = setup$c0$4;
        doptrf$4$c1 = setup$c1$4;
        doptrf$4$c2 = setup$c2$4;
        doptrf$4$c = setup$c$4;
        doptrf$4$round_up = setup$round_up$4;
        doptrf$4$valid_in = valid_in;
        doptrf$5$clock = clock;
        klmsel$d$5 = d$5;
        klmsel$j0$5 = setup$j0$5;
        klmsel$j1$5 = setup$j1$5;
        klmsel$j2$5 = setup$j2$5;
        doptrf$5$d0 = klmsel$y0$5;
        doptrf$5$d1 = klmsel$y1$5;
        doptrf$5$d2 = klmsel$y2$5;
        doptrf$5$c0 = setup$c0$5;
        doptrf$5$c1 = setup$c1$5;
        doptrf$5$c2 = setup$c2$5;
        doptrf$5$c = setup$c$5;
        doptrf$5$round_up = setup$round_up$5;
        doptrf$5$valid_in = valid_in;
        doptrf$6$clock = clock;
        klmsel$d$6 = d$6;
        klmsel$j0$6 = setup$j0$6;
        klmsel$j1$6 = setup$j1$6;
        klmsel$j2$6 = setup$j2$6;
        doptrf$6$d0 = klmsel$y0$6;
        doptrf$6$d1 = klmsel$y1$6;
        doptrf$6$d2 = klmsel$y2$6;
        doptrf$6$c0 = setup$c0$6;
        doptrf$6$c1 = setup$c1$6;
        doptrf$6$c2 = setup$c2$6;
        doptrf$6$c = setup$c$6;
        doptrf$6$round_up = setup$round_up$6;
        doptrf$6$valid_in = valid_in;
        doptrf$7$clock = clock;
        klmsel$d$7 = d$7;
        klmsel$j0$7 = setup$j0$7;
        klmsel$j1$7 = setup$j1$7;
        klmsel$j2$7 = setup$j2$7;
        doptrf$7$d0 = klmsel$y0$7;
        doptrf$7$d1 = klmsel$y1$7;
        doptrf$7$d2 = klmsel$y2$7;
        doptrf$7$c0 = setup$c0$7;
        doptrf$7$c1 = setup$c1$7;
        doptrf$7$c2 = setup$c2$7;
        doptrf$7$c = setup$c$7;
        doptrf$7$round_up = setup$round_up$7;
        doptrf$7$valid_in = valid_in;
        doptrf$8$clock = clock;
        klmsel$d$8 = d$8;
        klmsel$j0$8 = setup$j0$8;
        klmsel$j1$8 = setup$j1$8;
        klmsel$j2$8 = setup$j2$8;
        doptrf$8$d0 = klmsel$y0$8;
        doptrf$8$d1 = klmsel$y1$8;
        doptrf$8$d2 = klmsel$y2$8;
        doptrf$8$c0 = setup$c0$8;
        doptrf$8$c1 = setup$c1$8;
        doptrf$8$c2 = setup$c2$8;
        doptrf$8$c = setup$c$8;
        doptrf$8$round_up = setup$round_up$8;
        doptrf$8$valid_in = valid_in;
        doptrf$9$clock = clock;
        klmsel$d$9 = d$9;
        klmsel$j0$9 = setup$j0$9;
        klmsel$j1$9 = setup$j1$9;
        klmsel$j2$9 = setup$j2$9;
        doptrf$9$d0 = klmsel$y0$9;
        doptrf$9$d1 = klmsel$y1$9;
        doptrf$9$d2 = klmsel$y2$9;
        doptrf$9$c0 = setup$c0$9;
        doptrf$9$c1 = setup$c1$9;
        doptrf$9$c2 = setup$c2$9;
        doptrf$9$c = setup$c$9;
        doptrf$9$round_up = setup$round_up$9;
        doptrf$9$valid_in = valid_in;
        doptrf$10$clock = clock;
        klmsel$d$10 = d$10;
        klmsel$j0$10 = setup$j0$10;
        klmsel$j1$10 = setup$j1$10;
        klmsel$j2$10 = setup$j2$10;
        doptrf$10$d0 = klmsel$y0$10;
        doptrf$10$d1 = klmsel$y1$10;
        doptrf$10$d2 = klmsel$y2$10;
        doptrf$10$c0 = setup$c0$10;
        doptrf$10$c1 = setup$c1$10;
        doptrf$10$c2 = setup$c2$10;
        doptrf$10$c = setup$c$10;
        doptrf$10$round_up = setup$round_up$10;
        doptrf$10$valid_in = valid_in;
        doptrf$11$clock = clock;
        klmsel$d$11 = d$11;
        klmsel$j0$11 = setup$j0$11;
        klmsel$j1$11 = setup$j1$11;
        klmsel$j2$11 = setup$j2$11;
        doptrf$11$d0 = klmsel$y0$11;
        doptrf$11$d1 = klmsel$y1$11;
        doptrf$11$d2 = klmsel$y2$11;
        doptrf$11$c0 = setup$c0$11;
        doptrf$11$c1 = setup$c1$11;
        doptrf$11$c2 = setup$c2$11;
        doptrf$11$c = setup$c$11;
        doptrf$11$round_up = setup$round_up$11;
        doptrf$11$valid_in = valid_in;
        doptrf$12$clock = clock;
        klmsel$d$12 = d$12;
        klmsel$j0$12 = setup$j0$12;
        klmsel$j1$12 = setup$j1$12;
        klmsel$j2$12 = setup$j2$12;
        doptrf$12$d0 = klmsel$y0$12;
        doptrf$12$d1 = klmsel$y1$12;
        doptrf$12$d2 = klmsel$y2$12;
        doptrf$12$c0 = setup$c0$12;
        doptrf$12$c1 = setup$c1$12;
        doptrf$12$c2 = setup$c2$12;
        doptrf$12$c = setup$c$12;
        doptrf$12$round_up = setup$round_up$12;
        doptrf$12$valid_in = valid_in;
        doptrf$13$clock = clock;
        klmsel$d$13 = d$13;
        klmsel$j0$13 = setup$j0$13;
        klmsel$j1$13 = setup$j1$13;
        klmsel$j2$13 = setup$j2$13;
        doptrf$13$d0 = klmsel$y0$13;
        doptrf$13$d1 = klmsel$y1$13;
        doptrf$13$d2 = klmsel$y2$13;
        doptrf$13$c0 = setup$c0$13;
        doptrf$13$c1 = setup$c1$13;
        doptrf$13$c2 = setup$c2$13;
        doptrf$13$c = setup$c$13;
        doptrf$13$round_up = setup$round_up$13;
        doptrf$13$valid_in = valid_in;
        doptrf$14$clock = clock;
        klmsel$d$14 = d$14;
        klmsel$j0$14 = setup$j0$14;
        klmsel$j1$14 = setup$j1$14;
        klmsel$j2$14 = setup$j2$14;
        doptrf$14$d0 = klmsel$y0$14;
        doptrf$14$d1 = klmsel$y1$14;
        doptrf$14$d2 = klmsel$y2$14;
        doptrf$14$c0 = setup$c0$14;
        doptrf$14$c1 = setup$c1$14;
        doptrf$14$c2 = setup$c2$14;
        doptrf$14$c = setup$c$14;
        doptrf$14$round_up = setup$round_up$14;
        doptrf$14$valid_in = valid_in;
        doptrf$15$clock = clock;
        klmsel$d$15 = d$15;
        klmsel$j0$15 = setup$j0$15;
        klmsel$j1$15 = setup$j1$15;
        klmsel$j2$15 = setup$j2$15;
        doptrf$15$d0 = klmsel$y0$15;
        doptrf$15$d1 = klmsel$y1$15;
        doptrf$15$d2 = klmsel$y2$15;
        doptrf$15$c0 = setup$c0$15;
        doptrf$15$c1 = setup$c1$15;
        doptrf$15$c2 = setup$c2$15;
        doptrf$15$c = setup$c$15;
        doptrf$15$round_up = setup$round_up$15;
        doptrf$15$valid_in = valid_in;
        doptrf$16$clock = clock;
        klmsel$d$16 = d$16;
        klmsel$j0$16 = setup$j0$16;
        klmsel$j1$16 = setup$j1$16;
        klmsel$j2$16 = setup$j2$16;
        doptrf$16$d0 = klmsel$y0$16;
        doptrf$16$d1 = klmsel$y1$16;
        doptrf$16$d2 = klmsel$y2$16;
        doptrf$16$c0 = setup$c0$16;
        doptrf$16$c1 = setup$c1$16;
        doptrf$16$c2 = setup$c2$16;
        doptrf$16$c = setup$c$16;
        doptrf$16$round_up = setup$round_up$16;
        doptrf$16$valid_in = valid_in;
        doptrf$17$clock = clock;
        klmsel$d$17 = d$17;
        klmsel$j0$17 = setup$j0$17;
        klmsel$j1$17 = setup$j1$17;
        klmsel$j2$17 = setup$j2$17;
        doptrf$17$d0 = klmsel$y0$17;
        doptrf$17$d1 = klmsel$y1$17;
        doptrf$17$d2 = klmsel$y2$17;
        doptrf$17$c0 = setup$c0$17;
        doptrf$17$c1 = setup$c1$17;
        doptrf$17$c2 = setup$c2$17;
        doptrf$17$c = setup$c$17;
        doptrf$17$round_up = setup$round_up$17;
        doptrf$17$valid_in = valid_in;
        doptrf$18$clock = clock;
        klmsel$d$18 = d$18;
        klmsel$j0$18 = setup$j0$18;
        klmsel$j1$18 = setup$j1$18;
        klmsel$j2$18 = setup$j2$18;
        doptrf$18$d0 = klmsel$y0$18;
        doptrf$18$d1 = klmsel$y1$18;
        doptrf$18$d2 = klmsel$y2$18;
        doptrf$18$c0 = setup$c0$18;
        doptrf$18$c1 = setup$c1$18;
        doptrf$18$c2 = setup$c2$18;
        doptrf$18$c = setup$c$18;
        doptrf$18$round_up = setup$round_up$18;
        doptrf$18$valid_in = valid_in;
        doptrf$19$clock = clock;
        klmsel$d$19 = d$19;
        klmsel$j0$19 = setup$j0$19;
        klmsel$j1$19 = setup$j1$19;
        klmsel$j2$19 = setup$j2$19;
        doptrf$19$d0 = klmsel$y0$19;
        doptrf$19$d1 = klmsel$y1$19;
        doptrf$19$d2 = klmsel$y2$19;
        doptrf$19$c0 = setup$c0$19;
        doptrf$19$c1 = setup$c1$19;
        doptrf$19$c2 = setup$c2$19;
        doptrf$19$c = setup$c$19;
        doptrf$19$round_up = setup$round_up$19;
        doptrf$19$valid_in = valid_in;
        doptrf$20$clock = clock;
        klmsel$d$20 = d$20;
        klmsel$j0$20 = setup$j0$20;
        klmsel$j1$20 = setup$j1$20;
        klmsel$j2$20 = setup$j2$20;
        doptrf$20$d0 = klmsel$y0$20;
        doptrf$20$d1 = klmsel$y1$20;
        doptrf$20$d2 = klmsel$y2$20;
        doptrf$20$c0 = setup$c0$20;
        doptrf$20$c1 = setup$c1$20;
        doptrf$20$c2 = setup$c2$20;
        doptrf$20$c = setup$c$20;
        doptrf$20$round_up = setup$round_up$20;
        doptrf$20$valid_in = valid_in;
        doptrf$21$clock = clock;
        klmsel$d$21 = d$21;
        klmsel$j0$21 = setup$j0$21;
        klmsel$j1$21 = setup$j1$21;
        klmsel$j2$21 = setup$j2$21;
        doptrf$21$d0 = klmsel$y0$21;
        doptrf$21$d1 = klmsel$y1$21;
        doptrf$21$d2 = klmsel$y2$21;
        doptrf$21$c0 = setup$c0$21;
        doptrf$21$c1 = setup$c1$21;
        doptrf$21$c2 = setup$c2$21;
        doptrf$21$c = setup$c$21;
        doptrf$21$round_up = setup$round_up$21;
        doptrf$21$valid_in = valid_in;
        doptrf$22$clock = clock;
        klmsel$d$22 = d$22;
        klmsel$j0$22 = setup$j0$22;
        klmsel$j1$22 = setup$j1$22;
        klmsel$j2$22 = setup$j2$22;
        doptrf$22$d0 = klmsel$y0$22;
        doptrf$22$d1 = klmsel$y1$22;
        doptrf$22$d2 = klmsel$y2$22;
        doptrf$22$c0 = setup$c0$22;
        doptrf$22$c1 = setup$c1$22;
        doptrf$22$c2 = setup$c2$22;
        doptrf$22$c = setup$c$22;
        doptrf$22$round_up = setup$round_up$22;
        doptrf$22$valid_in = valid_in;
        doptrf$23$clock = clock;
        klmsel$d$23 = d$23;
        klmsel$j0$23 = setup$j0$23;
        klmsel$j1$23 = setup$j1$23;
        klmsel$j2$23 = setup$j2$23;
        doptrf$23$d0 = klmsel$y0$23;
        doptrf$23$d1 = klmsel$y1$23;
        doptrf$23$d2 = klmsel$y2$23;
        doptrf$23$c0 = setup$c0$23;
        doptrf$23$c1 = setup$c1$23;
        doptrf$23$c2 = setup$c2$23;
        doptrf$23$c = setup$c$23;
        doptrf$23$round_up = setup$round_up$23;
        doptrf$23$valid_in = valid_in;
        doptrf$0$e = e$12;
        doptrf$1$e = e$13;
        doptrf$2$e = e$14;
        doptrf$3$e = e$15;
        doptrf$4$e = e$16;
        doptrf$5$e = e$17;
        doptrf$6$e = e$18;
        doptrf$7$e = e$19;
        doptrf$8$e = e$20;
        doptrf$9$e = e$21;
        doptrf$10$e = e$22;
        doptrf$11$e = e$23;
        doptrf$12$e = e$0;
        doptrf$13$e = e$1;
        doptrf$14$e = e$2;
        doptrf$15$e = e$3;
        doptrf$16$e = e$4;
        doptrf$17$e = e$5;
        doptrf$18$e = e$6;
        doptrf$19$e = e$7;
        doptrf$20$e = e$8;
        doptrf$21$e = e$9;
        doptrf$22$e = e$10;
        doptrf$23$e = e$11;
        tag_1$d = tag;
        tag_2$d = tag_1$q;
        tag_3$d = tag_2$q;
        tag_4$d = tag_3$q;
        tag_5$d = tag_4$q;
        tag_6$d = tag_5$q;
        tag_7$d = tag_6$q;
        tag_8$d = tag_7$q;
        tag_9$d = tag_8$q;
        tag_10$d = tag_9$q;
        tag_11$d = tag_10$q;
        tag_12$d = tag_11$q;
        tag_13$d = tag_12$q;
        tag_14$d = tag_13$q;
        tag_15$d = tag_14$q;
        c_any = 1'b0;
        if (doptrf$0$flag) begin
            c_any = 1'b1;
        end
        if (doptrf$1$flag) begin
            c_any = 1'b1;
        end
        if (doptrf$2$flag) begin
            c_any = 1'b1;
        end
        if (doptrf$3$flag) begin
            c_any = 1'b1;
        end
        if (doptrf$4$flag) begin
            c_any = 1'b1;
        end
        if (doptrf$5$flag) begin
            c_any = 1'b1;
        end
        if (doptrf$6$flag) begin
            c_any = 1'b1;
        end
        if (doptrf$7$flag) begin
            c_any = 1'b1;
        end
        if (doptrf$8$flag) begin
            c_any = 1'b1;
        end
        if (doptrf$9$flag) begin
            c_any = 1'b1;
        end
        if (doptrf$10$flag) begin
            c_any = 1'b1;
        end
        if (doptrf$11$flag) begin
            c_any = 1'b1;
        end
        if (doptrf$12$flag) begin
            c_any = 1'b1;
        end
        if (doptrf$13$flag) begin
            c_any = 1'b1;
        end
        if (doptrf$14$flag) begin
            c_any = 1'b1;
        end
        if (doptrf$15$flag) begin
            c_any = 1'b1;
        end
        if (doptrf$16$flag) begin
            c_any = 1'b1;
        end
        if (doptrf$17$flag) begin
            c_any = 1'b1;
        end
        if (doptrf$18$flag) begin
            c_any = 1'b1;
        end
        if (doptrf$19$flag) begin
            c_any = 1'b1;
        end
        if (doptrf$20$flag) begin
            c_any = 1'b1;
        end
        if (doptrf$21$flag) begin
            c_any = 1'b1;
        end
        if (doptrf$22$flag) begin
            c_any = 1'b1;
        end
        if (doptrf$23$flag) begin
            c_any = 1'b1;
        end
        overlap = ~c_any;
        tag_out = tag_15$q;
        valid_out = doptrf$0$valid_out;
    end
    
endmodule // top


module top$doptrf$0(clock,d0,d1,d2,c0,c1,c2,c,e,valid_in,round_up,s,flag,valid_out);
    
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
    reg  s15_valid$d;
    wire  s15_valid$q;
    reg  s15_valid$clock;
    reg  [31:0] s15_s$d;
    wire  [31:0] s15_s$q;
    reg  s15_s$clock;
    reg  s15_flag$d;
    wire  s15_flag$q;
    reg  s15_flag$clock;
    
    // Local signals
    reg  [7:0] c15_exp;
    reg  [22:0] c15_frac;
    reg  [30:0] c15_mag;
    reg  c15_nan;
    
    // Sub module instances
    top$doptrf$0$add_0$s1_eff_sub s1_valid(
        .d(s1_valid$d),
        .q(s1_valid$q),
        .clock(s1_valid$clock)
    );
    top$doptrf$0$add_0$s3_y s1_d0(
        .d(s1_d0$d),
        .q(s1_d0$q),
        .clock(s1_d0$clock)
    );
    top$doptrf$0$add_0$s3_y s1_d1(
        .d(s1_d1$d),
        .q(s1_d1$q),
        .clock(s1_d1$clock)
    );
    top$doptrf$0$add_0$s3_y s1_d2(
        .d(s1_d2$d),
        .q(s1_d2$q),
        .clock(s1_d2$clock)
    );
    top$doptrf$0$add_0$s3_y s1_c0(
        .d(s1_c0$d),
        .q(s1_c0$q),
        .clock(s1_c0$clock)
    );
    top$doptrf$0$add_0$s3_y s1_c1(
        .d(s1_c1$d),
        .q(s1_c1$q),
        .clock(s1_c1$clock)
    );
    top$doptrf$0$add_0$s3_y s1_c2(
        .d(s1_c2$d),
        .q(s1_c2$q),
        .clock(s1_c2$clock)
    );
    top$doptrf$0$add_0$s3_y s1_c(
        .d(s1_c$d),
        .q(s1_c$q),
        .clock(s1_c$clock)
    );
    top$doptrf$0$add_0$s3_y s1_e(
        .d(s1_e$d),
        .q(s1_e$q),
        .clock(s1_e$clock)
    );
    top$doptrf$0$add_0$s1_eff_sub s1_round(
        .d(s1_round$d),
        .q(s1_round$q),
        .clock(s1_round$clock)
    );
    top$doptrf$0$r_mul r_mul(
        .clock(r_mul$clock),
        .d(r_mul$d),
        .q(r_mul$q)
    );
    top$doptrf$0$r_mul r_sum(
        .clock(r_sum$clock),
        .d(r_sum$d),
        .q(r_sum$q)
    );
    top$doptrf$0$r_mul r_u(
        .clock(r_u$clock),
        .d(r_u$d),
        .q(r_u$q)
    );
    top$doptrf$0$r_mul r_s(
        .clock(r_s$clock),
        .d(r_s$d),
        .q(r_s$q)
    );
    top$doptrf$0$mul_0 mul_0(
        .clock(mul_0$clock),
        .a(mul_0$a),
        .b(mul_0$b),
        .valid_in(mul_0$valid_in),
        .y(mul_0$y),
        .valid_out(mul_0$valid_out),
        .round_up(mul_0$round_up)
    );
    top$doptrf$0$mul_0 mul_1(
        .clock(mul_1$clock),
        .a(mul_1$a),
        .b(mul_1$b),
        .valid_in(mul_1$valid_in),
        .y(mul_1$y),
        .valid_out(mul_1$valid_out),
        .round_up(mul_1$round_up)
    );
    top$doptrf$0$mul_0 mul_2(
        .clock(mul_2$clock),
        .a(mul_2$a),
        .b(mul_2$b),
        .valid_in(mul_2$valid_in),
        .y(mul_2$y),
        .valid_out(mul_2$valid_out),
        .round_up(mul_2$round_up)
    );
    top$doptrf$0$add_0$s3_y c_2(
        .d(c_2$d),
        .q(c_2$q),
        .clock(c_2$clock)
    );
    top$doptrf$0$add_0$s3_y c_3(
        .d(c_3$d),
        .q(c_3$q),
        .clock(c_3$clock)
    );
    top$doptrf$0$add_0$s3_y c_4(
        .d(c_4$d),
        .q(c_4$q),
        .clock(c_4$clock)
    );
    top$doptrf$0$add_0$s3_y c_5(
        .d(c_5$d),
        .q(c_5$q),
        .clock(c_5$clock)
    );
    top$doptrf$0$add_0 add_0(
        .clock(add_0$clock),
        .a(add_0$a),
        .b(add_0$b),
        .sub(add_0$sub),
        .valid_in(add_0$valid_in),
        .y(add_0$y),
        .valid_out(add_0$valid_out),
        .round_up(add_0$round_up)
    );
    top$doptrf$0$add_0 add_1(
        .clock(add_1$clock),
        .a(add_1$a),
        .b(add_1$b),
        .sub(add_1$sub),
        .valid_in(add_1$valid_in),
        .y(add_1$y),
        .valid_out(add_1$valid_out),
        .round_up(add_1$round_up)
    );
    top$doptrf$0$add_0 add_2(
        .clock(add_2$clock),
        .a(add_2$a),
        .b(add_2$b),
        .sub(add_2$sub),
        .valid_in(add_2$valid_in),
        .y(add_2$y),
        .valid_out(add_2$valid_out),
        .round_up(add_2$round_up)
    );
    top$doptrf$0$add_0 add_3(
        .clock(add_3$clock),
        .a(add_3$a),
        .b(add_3$b),
        .sub(add_3$sub),
        .valid_in(add_3$valid_in),
        .y(add_3$y),
        .valid_out(add_3$valid_out),
        .round_up(add_3$round_up)
    );
    top$doptrf$0$add_0$s3_y e_2(
        .d(e_2$d),
        .q(e_2$q),
        .clock(e_2$clock)
    );
    top$doptrf$0$add_0$s3_y e_3(
        .d(e_3$d),
        .q(e_3$q),
        .clock(e_3$clock)
    );
    top$doptrf$0$add_0$s3_y e_4(
        .d(e_4$d),
        .q(e_4$q),
        .clock(e_4$clock)
    );
    top$doptrf$0$add_0$s3_y e_5(
        .d(e_5$d),
        .q(e_5$q),
        .clock(e_5$clock)
    );
    top$doptrf$0$add_0$s3_y e_6(
        .d(e_6$d),
        .q(e_6$q),
        .clock(e_6$clock)
    );
    top$doptrf$0$add_0$s3_y e_7(
        .d(e_7$d),
        .q(e_7$q),
        .clock(e_7$clock)
    );
    top$doptrf$0$add_0$s3_y e_8(
        .d(e_8$d),
        .q(e_8$q),
        .clock(e_8$clock)
    );
    top$doptrf$0$add_0$s3_y e_9(
        .d(e_9$d),
        .q(e_9$q),
        .clock(e_9$clock)
    );
    top$doptrf$0$add_0$s3_y e_10(
        .d(e_10$d),
        .q(e_10$q),
        .clock(e_10$clock)
    );
    top$doptrf$0$add_0$s3_y e_11(
        .d(e_11$d),
        .q(e_11$q),
        .clock(e_11$clock)
    );
    top$doptrf$0$add_0$s1_eff_sub s15_valid(
        .d(s15_valid$d),
        .q(s15_valid$q),
        .clock(s15_valid$clock)
    );
    top$doptrf$0$add_0$s3_y s15_s(
        .d(s15_s$d),
        .q(s15_s$q),
        .clock(s15_s$clock)
    );
    top$doptrf$0$add_0$s1_eff_sub s15_flag(
        .d(s15_flag$d),
        .q(s15_flag$q),
        .clock(s15_flag$clock)
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
        c_2$d = c_2$q;
        c_3$d = c_3$q;
        c_4$d = c_4$q;
        c_5$d = c_5$q;
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
        s15_valid$clock = clock;
        s15_s$clock = clock;
        s15_flag$clock = clock;
        s15_valid$d = s15_valid$q;
        s15_s$d = s15_s$q;
        s15_flag$d = s15_flag$q;
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
        add_3$a = add_2$y;
        add_3$b = e_11$q;
        add_3$sub = 1'b0;
        add_3$valid_in = add_2$valid_out;
        c15_exp = add_3$y[(32'h17)+:(8)];
        c15_frac = add_3$y[(32'h0)+:(23)];
        c15_mag = add_3$y[(32'h0)+:(31)];
        c15_nan = &c15_exp & (c15_frac != 32'h0);
        s15_valid$d = add_3$valid_out;
        s15_s$d = add_3$y;
        s15_flag$d = add_3$y[32'h1f] & (c15_mag != 32'h0) & ~c15_nan;
        s = s15_s$q;
        flag = s15_flag$q;
        valid_out = s15_valid$q;
    end
    
endmodule // top$doptrf$0


module top$doptrf$0$add_0(clock,a,b,sub,valid_in,y,valid_out,round_up);
    
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
    top$doptrf$0$add_0$unpack_a unpack_a(
        .x(unpack_a$x),
        .sign(unpack_a$sign),
        .exp(unpack_a$exp),
        .sig(unpack_a$sig),
        .is_zero(unpack_a$is_zero),
        .is_inf(unpack_a$is_inf),
        .is_nan(unpack_a$is_nan)
    );
    top$doptrf$0$add_0$unpack_a unpack_b(
        .x(unpack_b$x),
        .sign(unpack_b$sign),
        .exp(unpack_b$exp),
        .sig(unpack_b$sig),
        .is_zero(unpack_b$is_zero),
        .is_inf(unpack_b$is_inf),
        .is_nan(unpack_b$is_nan)
    );
    top$doptrf$0$add_0$s1_eff_sub s1_valid(
        .d(s1_valid$d),
        .q(s1_valid$q),
        .clock(s1_valid$clock)
    );
    top$doptrf$0$add_0$s1_eff_sub s1_nan(
        .d(s1_nan$d),
        .q(s1_nan$q),
        .clock(s1_nan$clock)
    );
    top$doptrf$0$add_0$s1_eff_sub s1_inf(
        .d(s1_inf$d),
        .q(s1_inf$q),
        .clock(s1_inf$clock)
    );
    top$doptrf$0$add_0$s1_eff_sub s1_inf_sign(
        .d(s1_inf_sign$d),
        .q(s1_inf_sign$q),
        .clock(s1_inf_sign$clock)
    );
    top$doptrf$0$add_0$s1_eff_sub s1_zero_sign(
        .d(s1_zero_sign$d),
        .q(s1_zero_sign$q),
        .clock(s1_zero_sign$clock)
    );
    top$doptrf$0$add_0$s1_eff_sub s1_sign(
        .d(s1_sign$d),
        .q(s1_sign$q),
        .clock(s1_sign$clock)
    );
    top$doptrf$0$add_0$s1_eff_sub s1_eff_sub(
        .d(s1_eff_sub$d),
        .q(s1_eff_sub$q),
        .clock(s1_eff_sub$clock)
    );
    top$doptrf$0$add_0$s1_exp s1_exp(
        .d(s1_exp$d),
        .q(s1_exp$q),
        .clock(s1_exp$clock)
    );
    top$doptrf$0$add_0$s1_big s1_big(
        .d(s1_big$d),
        .q(s1_big$q),
        .clock(s1_big$clock)
    );
    top$doptrf$0$add_0$s1_big s1_small(
        .d(s1_small$d),
        .q(s1_small$q),
        .clock(s1_small$clock)
    );
    top$doptrf$0$add_0$norm norm(
        .x(norm$x),
        .y(norm$y),
        .lz(norm$lz)
    );
    top$doptrf$0$add_0$s1_eff_sub s2_valid(
        .d(s2_valid$d),
        .q(s2_valid$q),
        .clock(s2_valid$clock)
    );
    top$doptrf$0$add_0$s1_eff_sub s2_sign(
        .d(s2_sign$d),
        .q(s2_sign$q),
        .clock(s2_sign$clock)
    );
    top$doptrf$0$add_0$s1_eff_sub s2_nan(
        .d(s2_nan$d),
        .q(s2_nan$q),
        .clock(s2_nan$clock)
    );
    top$doptrf$0$add_0$s1_eff_sub s2_inf(
        .d(s2_inf$d),
        .q(s2_inf$q),
        .clock(s2_inf$clock)
    );
    top$doptrf$0$add_0$s1_eff_sub s2_zero(
        .d(s2_zero$d),
        .q(s2_zero$q),
        .clock(s2_zero$clock)
    );
    top$doptrf$0$add_0$s1_eff_sub s2_ovf(
        .d(s2_ovf$d),
        .q(s2_ovf$q),
        .clock(s2_ovf$clock)
    );
    top$doptrf$0$add_0$s1_exp s2_efield(
        .d(s2_efield$d),
        .q(s2_efield$q),
        .clock(s2_efield$clock)
    );
    top$doptrf$0$add_0$s2_nm s2_nm(
        .d(s2_nm$d),
        .q(s2_nm$q),
        .clock(s2_nm$clock)
    );
    top$doptrf$0$add_0$round round(
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
    top$doptrf$0$add_0$s1_eff_sub s3_valid(
        .d(s3_valid$d),
        .q(s3_valid$q),
        .clock(s3_valid$clock)
    );
    top$doptrf$0$add_0$s3_y s3_y(
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
    
endmodule // top$doptrf$0$add_0


module top$doptrf$0$add_0$norm(x,y,lz);
    
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
    
endmodule // top$doptrf$0$add_0$norm


module top$doptrf$0$add_0$round(round_up,sign,nan,inf,zero,ovf,efield,nm,y);
    
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
    
endmodule // top$doptrf$0$add_0$round


module top$doptrf$0$add_0$s1_big(d,q,clock);
    
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
          
endmodule // top$doptrf$0$add_0$s1_big


module top$doptrf$0$add_0$s1_eff_sub(d,q,clock);
    
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
          
endmodule // top$doptrf$0$add_0$s1_eff_sub


module top$doptrf$0$add_0$s1_exp(d,q,clock);
    
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
          
endmodule // top$doptrf$0$add_0$s1_exp


module top$doptrf$0$add_0$s2_nm(d,q,clock);
    
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
          
endmodule // top$doptrf$0$add_0$s2_nm


module top$doptrf$0$add_0$s3_y(d,q,clock);
    
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
          
endmodule // top$doptrf$0$add_0$s3_y


module top$doptrf$0$add_0$unpack_a(x,sign,exp,sig,is_zero,is_inf,is_nan);
    
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
    
endmodule // top$doptrf$0$add_0$unpack_a


module top$doptrf$0$mul_0(clock,a,b,valid_in,y,valid_out,round_up);
    
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
    top$doptrf$0$add_0$unpack_a unpack_a(
        .x(unpack_a$x),
        .sign(unpack_a$sign),
        .exp(unpack_a$exp),
        .sig(unpack_a$sig),
        .is_zero(unpack_a$is_zero),
        .is_inf(unpack_a$is_inf),
        .is_nan(unpack_a$is_nan)
    );
    top$doptrf$0$add_0$unpack_a unpack_b(
        .x(unpack_b$x),
        .sign(unpack_b$sign),
        .exp(unpack_b$exp),
        .sig(unpack_b$sig),
        .is_zero(unpack_b$is_zero),
        .is_inf(unpack_b$is_inf),
        .is_nan(unpack_b$is_nan)
    );
    top$doptrf$0$mul_0$norm_a norm_a(
        .x(norm_a$x),
        .y(norm_a$y),
        .lz(norm_a$lz)
    );
    top$doptrf$0$mul_0$norm_a norm_b(
        .x(norm_b$x),
        .y(norm_b$y),
        .lz(norm_b$lz)
    );
    top$doptrf$0$add_0$s1_eff_sub s1_valid(
        .d(s1_valid$d),
        .q(s1_valid$q),
        .clock(s1_valid$clock)
    );
    top$doptrf$0$add_0$s1_eff_sub s1_sign(
        .d(s1_sign$d),
        .q(s1_sign$q),
        .clock(s1_sign$clock)
    );
    top$doptrf$0$add_0$s1_eff_sub s1_nan(
        .d(s1_nan$d),
        .q(s1_nan$q),
        .clock(s1_nan$clock)
    );
    top$doptrf$0$add_0$s1_eff_sub s1_inf(
        .d(s1_inf$d),
        .q(s1_inf$q),
        .clock(s1_inf$clock)
    );
    top$doptrf$0$add_0$s1_eff_sub s1_zero(
        .d(s1_zero$d),
        .q(s1_zero$q),
        .clock(s1_zero$clock)
    );
    top$doptrf$0$mul_0$s1_exp s1_exp(
        .d(s1_exp$d),
        .q(s1_exp$q),
        .clock(s1_exp$clock)
    );
    top$doptrf$0$mul_0$s1_sig_a s1_sig_a(
        .d(s1_sig_a$d),
        .q(s1_sig_a$q),
        .clock(s1_sig_a$clock)
    );
    top$doptrf$0$mul_0$s1_sig_a s1_sig_b(
        .d(s1_sig_b$d),
        .q(s1_sig_b$q),
        .clock(s1_sig_b$clock)
    );
    top$doptrf$0$mul_0$sig_mul sig_mul(
        .a(sig_mul$a),
        .b(sig_mul$b),
        .hi(sig_mul$hi),
        .sticky(sig_mul$sticky)
    );
    top$doptrf$0$add_0$s1_eff_sub s2_valid(
        .d(s2_valid$d),
        .q(s2_valid$q),
        .clock(s2_valid$clock)
    );
    top$doptrf$0$add_0$s1_eff_sub s2_sign(
        .d(s2_sign$d),
        .q(s2_sign$q),
        .clock(s2_sign$clock)
    );
    top$doptrf$0$add_0$s1_eff_sub s2_nan(
        .d(s2_nan$d),
        .q(s2_nan$q),
        .clock(s2_nan$clock)
    );
    top$doptrf$0$add_0$s1_eff_sub s2_inf(
        .d(s2_inf$d),
        .q(s2_inf$q),
        .clock(s2_inf$clock)
    );
    top$doptrf$0$add_0$s1_eff_sub s2_zero(
        .d(s2_zero$d),
        .q(s2_zero$q),
        .clock(s2_zero$clock)
    );
    top$doptrf$0$mul_0$s1_exp s2_exp(
        .d(s2_exp$d),
        .q(s2_exp$q),
        .clock(s2_exp$clock)
    );
    top$doptrf$0$add_0$s2_nm s2_hi(
        .d(s2_hi$d),
        .q(s2_hi$q),
        .clock(s2_hi$clock)
    );
    top$doptrf$0$add_0$s1_eff_sub s2_sticky(
        .d(s2_sticky$d),
        .q(s2_sticky$q),
        .clock(s2_sticky$clock)
    );
    top$doptrf$0$add_0$s1_eff_sub s3_valid(
        .d(s3_valid$d),
        .q(s3_valid$q),
        .clock(s3_valid$clock)
    );
    top$doptrf$0$add_0$s1_eff_sub s3_sign(
        .d(s3_sign$d),
        .q(s3_sign$q),
        .clock(s3_sign$clock)
    );
    top$doptrf$0$add_0$s1_eff_sub s3_nan(
        .d(s3_nan$d),
        .q(s3_nan$q),
        .clock(s3_nan$clock)
    );
    top$doptrf$0$add_0$s1_eff_sub s3_inf(
        .d(s3_inf$d),
        .q(s3_inf$q),
        .clock(s3_inf$clock)
    );
    top$doptrf$0$add_0$s1_eff_sub s3_zero(
        .d(s3_zero$d),
        .q(s3_zero$q),
        .clock(s3_zero$clock)
    );
    top$doptrf$0$add_0$s1_eff_sub s3_ovf(
        .d(s3_ovf$d),
        .q(s3_ovf$q),
        .clock(s3_ovf$clock)
    );
    top$doptrf$0$add_0$s1_exp s3_efield(
        .d(s3_efield$d),
        .q(s3_efield$q),
        .clock(s3_efield$clock)
    );
    top$doptrf$0$add_0$s2_nm s3_nm(
        .d(s3_nm$d),
        .q(s3_nm$q),
        .clock(s3_nm$clock)
    );
    top$doptrf$0$add_0$round round(
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
    top$doptrf$0$add_0$s1_eff_sub s4_valid(
        .d(s4_valid$d),
        .q(s4_valid$q),
        .clock(s4_valid$clock)
    );
    top$doptrf$0$add_0$s3_y s4_y(
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
    
endmodule // top$doptrf$0$mul_0


module top$doptrf$0$mul_0$norm_a(x,y,lz);
    
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
    
endmodule // top$doptrf$0$mul_0$norm_a


module top$doptrf$0$mul_0$s1_exp(d,q,clock);
    
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
          
endmodule // top$doptrf$0$mul_0$s1_exp


module top$doptrf$0$mul_0$s1_sig_a(d,q,clock);
    
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
          
endmodule // top$doptrf$0$mul_0$s1_sig_a


module top$doptrf$0$mul_0$sig_mul(a,b,hi,sticky);
    
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
endmodule // top$doptrf$0$mul_0$sig_mul


module top$doptrf$0$r_mul(clock,d,q);
    
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
    top$doptrf$0$add_0$s1_eff_sub line$0(
        .d(line$0$d),
        .q(line$0$q),
        .clock(line$0$clock)
    );
    top$doptrf$0$add_0$s1_eff_sub line$1(
        .d(line$1$d),
        .q(line$1$q),
        .clock(line$1$clock)
    );
    top$doptrf$0$add_0$s1_eff_sub line$2(
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
    
endmodule // top$doptrf$0$r_mul


module top$klmsel(d$0,d$1,d$2,d$3,d$4,d$5,d$6,d$7,d$8,d$9,d$10,d$11,d$12,d$13,d$14,d$15,d$16,d$17,d$18,d$19,d$20,d$21,d$22,d$23,j0$0,j0$1,j0$2,j0$3,j0$4,j0$5,j0$6,j0$7,j0$8,j0$9,j0$10,j0$11,j0$12,j0$13,j0$14,j0$15,j0$16,j0$17,j0$18,j0$19,j0$20,j0$21,j0$22,j0$23,j1$0,j1$1,j1$2,j1$3,j1$4,j1$5,j1$6,j1$7,j1$8,j1$9,j1$10,j1$11,j1$12,j1$13,j1$14,j1$15,j1$16,j1$17,j1$18,j1$19,j1$20,j1$21,j1$22,j1$23,j2$0,j2$1,j2$2,j2$3,j2$4,j2$5,j2$6,j2$7,j2$8,j2$9,j2$10,j2$11,j2$12,j2$13,j2$14,j2$15,j2$16,j2$17,j2$18,j2$19,j2$20,j2$21,j2$22,j2$23,y0$0,y0$1,y0$2,y0$3,y0$4,y0$5,y0$6,y0$7,y0$8,y0$9,y0$10,y0$11,y0$12,y0$13,y0$14,y0$15,y0$16,y0$17,y0$18,y0$19,y0$20,y0$21,y0$22,y0$23,y1$0,y1$1,y1$2,y1$3,y1$4,y1$5,y1$6,y1$7,y1$8,y1$9,y1$10,y1$11,y1$12,y1$13,y1$14,y1$15,y1$16,y1$17,y1$18,y1$19,y1$20,y1$21,y1$22,y1$23,y2$0,y2$1,y2$2,y2$3,y2$4,y2$5,y2$6,y2$7,y2$8,y2$9,y2$10,y2$11,y2$12,y2$13,y2$14,y2$15,y2$16,y2$17,y2$18,y2$19,y2$20,y2$21,y2$22,y2$23);
    
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
    input wire  [4:0] j0$1;
    input wire  [4:0] j0$2;
    input wire  [4:0] j0$3;
    input wire  [4:0] j0$4;
    input wire  [4:0] j0$5;
    input wire  [4:0] j0$6;
    input wire  [4:0] j0$7;
    input wire  [4:0] j0$8;
    input wire  [4:0] j0$9;
    input wire  [4:0] j0$10;
    input wire  [4:0] j0$11;
    input wire  [4:0] j0$12;
    input wire  [4:0] j0$13;
    input wire  [4:0] j0$14;
    input wire  [4:0] j0$15;
    input wire  [4:0] j0$16;
    input wire  [4:0] j0$17;
    input wire  [4:0] j0$18;
    input wire  [4:0] j0$19;
    input wire  [4:0] j0$20;
    input wire  [4:0] j0$21;
    input wire  [4:0] j0$22;
    input wire  [4:0] j0$23;
    input wire  [4:0] j1$0;
    input wire  [4:0] j1$1;
    input wire  [4:0] j1$2;
    input wire  [4:0] j1$3;
    input wire  [4:0] j1$4;
    input wire  [4:0] j1$5;
    input wire  [4:0] j1$6;
    input wire  [4:0] j1$7;
    input wire  [4:0] j1$8;
    input wire  [4:0] j1$9;
    input wire  [4:0] j1$10;
    input wire  [4:0] j1$11;
    input wire  [4:0] j1$12;
    input wire  [4:0] j1$13;
    input wire  [4:0] j1$14;
    input wire  [4:0] j1$15;
    input wire  [4:0] j1$16;
    input wire  [4:0] j1$17;
    input wire  [4:0] j1$18;
    input wire  [4:0] j1$19;
    input wire  [4:0] j1$20;
    input wire  [4:0] j1$21;
    input wire  [4:0] j1$22;
    input wire  [4:0] j1$23;
    input wire  [4:0] j2$0;
    input wire  [4:0] j2$1;
    input wire  [4:0] j2$2;
    input wire  [4:0] j2$3;
    input wire  [4:0] j2$4;
    input wire  [4:0] j2$5;
    input wire  [4:0] j2$6;
    input wire  [4:0] j2$7;
    input wire  [4:0] j2$8;
    input wire  [4:0] j2$9;
    input wire  [4:0] j2$10;
    input wire  [4:0] j2$11;
    input wire  [4:0] j2$12;
    input wire  [4:0] j2$13;
    input wire  [4:0] j2$14;
    input wire  [4:0] j2$15;
    input wire  [4:0] j2$16;
    input wire  [4:0] j2$17;
    input wire  [4:0] j2$18;
    input wire  [4:0] j2$19;
    input wire  [4:0] j2$20;
    input wire  [4:0] j2$21;
    input wire  [4:0] j2$22;
    input wire  [4:0] j2$23;
    output reg  [31:0] y0$0;
    output reg  [31:0] y0$1;
    output reg  [31:0] y0$2;
    output reg  [31:0] y0$3;
    output reg  [31:0] y0$4;
    output reg  [31:0] y0$5;
    output reg  [31:0] y0$6;
    output reg  [31:0] y0$7;
    output reg  [31:0] y0$8;
    output reg  [31:0] y0$9;
    output reg  [31:0] y0$10;
    output reg  [31:0] y0$11;
    output reg  [31:0] y0$12;
    output reg  [31:0] y0$13;
    output reg  [31:0] y0$14;
    output reg  [31:0] y0$15;
    output reg  [31:0] y0$16;
    output reg  [31:0] y0$17;
    output reg  [31:0] y0$18;
    output reg  [31:0] y0$19;
    output reg  [31:0] y0$20;
    output reg  [31:0] y0$21;
    output reg  [31:0] y0$22;
    output reg  [31:0] y0$23;
    output reg  [31:0] y1$0;
    output reg  [31:0] y1$1;
    output reg  [31:0] y1$2;
    output reg  [31:0] y1$3;
    output reg  [31:0] y1$4;
    output reg  [31:0] y1$5;
    output reg  [31:0] y1$6;
    output reg  [31:0] y1$7;
    output reg  [31:0] y1$8;
    output reg  [31:0] y1$9;
    output reg  [31:0] y1$10;
    output reg  [31:0] y1$11;
    output reg  [31:0] y1$12;
    output reg  [31:0] y1$13;
    output reg  [31:0] y1$14;
    output reg  [31:0] y1$15;
    output reg  [31:0] y1$16;
    output reg  [31:0] y1$17;
    output reg  [31:0] y1$18;
    output reg  [31:0] y1$19;
    output reg  [31:0] y1$20;
    output reg  [31:0] y1$21;
    output reg  [31:0] y1$22;
    output reg  [31:0] y1$23;
    output reg  [31:0] y2$0;
    output reg  [31:0] y2$1;
    output reg  [31:0] y2$2;
    output reg  [31:0] y2$3;
    output reg  [31:0] y2$4;
    output reg  [31:0] y2$5;
    output reg  [31:0] y2$6;
    output reg  [31:0] y2$7;
    output reg  [31:0] y2$8;
    output reg  [31:0] y2$9;
    output reg  [31:0] y2$10;
    output reg  [31:0] y2$11;
    output reg  [31:0] y2$12;
    output reg  [31:0] y2$13;
    output reg  [31:0] y2$14;
    output reg  [31:0] y2$15;
    output reg  [31:0] y2$16;
    output reg  [31:0] y2$17;
    output reg  [31:0] y2$18;
    output reg  [31:0] y2$19;
    output reg  [31:0] y2$20;
    output reg  [31:0] y2$21;
    output reg  [31:0] y2$22;
    output reg  [31:0] y2$23;
    
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
        y0$1 = 32'h0;
        y1$1 = 32'h0;
        y2$1 = 32'h0;
        if (j0$1 == idx$0) begin
            y0$1 = d$0;
        end
        if (j1$1 == idx$0) begin
            y1$1 = d$0;
        end
        if (j2$1 == idx$0) begin
            y2$1 = d$0;
        end
        if (j0$1 == idx$1) begin
            y0$1 = d$1;
        end
        if (j1$1 == idx$1) begin
            y1$1 = d$1;
        end
        if (j2$1 == idx$1) begin
            y2$1 = d$1;
        end
        if (j0$1 == idx$2) begin
            y0$1 = d$2;
        end
        if (j1$1 == idx$2) begin
            y1$1 = d$2;
        end
        if (j2$1 == idx$2) begin
            y2$1 = d$2;
        end
        if (j0$1 == idx$3) begin
            y0$1 = d$3;
        end
        if (j1$1 == idx$3) begin
            y1$1 = d$3;
        end
        if (j2$1 == idx$3) begin
            y2$1 = d$3;
        end
        if (j0$1 == idx$4) begin
            y0$1 = d$4;
        end
        if (j1$1 == idx$4) begin
            y1$1 = d$4;
        end
        if (j2$1 == idx$4) begin
            y2$1 = d$4;
        end
        if (j0$1 == idx$5) begin
            y0$1 = d$5;
        end
        if (j1$1 == idx$5) begin
            y1$1 = d$5;
        end
        if (j2$1 == idx$5) begin
            y2$1 = d$5;
        end
        if (j0$1 == idx$6) begin
            y0$1 = d$6;
        end
        if (j1$1 == idx$6) begin
            y1$1 = d$6;
        end
        if (j2$1 == idx$6) begin
            y2$1 = d$6;
        end
        if (j0$1 == idx$7) begin
            y0$1 = d$7;
        end
        if (j1$1 == idx$7) begin
            y1$1 = d$7;
        end
        if (j2$1 == idx$7) begin
            y2$1 = d$7;
        end
        if (j0$1 == idx$8) begin
            y0$1 = d$8;
        end
        if (j1$1 == idx$8) begin
            y1$1 = d$8;
        end
        if (j2$1 == idx$8) begin
            y2$1 = d$8;
        end
        if (j0$1 == idx$9) begin
            y0$1 = d$9;
        end
        if (j1$1 == idx$9) begin
            y1$1 = d$9;
        end
        if (j2$1 == idx$9) begin
            y2$1 = d$9;
        end
        if (j0$1 == idx$10) begin
            y0$1 = d$10;
        end
        if (j1$1 == idx$10) begin
            y1$1 = d$10;
        end
        if (j2$1 == idx$10) begin
            y2$1 = d$10;
        end
        if (j0$1 == idx$11) begin
            y0$1 = d$11;
        end
        if (j1$1 == idx$11) begin
            y1$1 = d$11;
        end
        if (j2$1 == idx$11) begin
            y2$1 = d$11;
        end
        if (j0$1 == idx$12) begin
            y0$1 = d$12;
        end
        if (j1$1 == idx$12) begin
            y1$1 = d$12;
        end
        if (j2$1 == idx$12) begin
            y2$1 = d$12;
        end
        if (j0$1 == idx$13) begin
            y0$1 = d$13;
        end
        if (j1$1 == idx$13) begin
            y1$1 = d$13;
        end
        if (j2$1 == idx$13) begin
            y2$1 = d$13;
        end
        if (j0$1 == idx$14) begin
            y0$1 = d$14;
        end
        if (j1$1 == idx$14) begin
            y1$1 = d$14;
        end
        if (j2$1 == idx$14) begin
            y2$1 = d$14;
        end
        if (j0$1 == idx$15) begin
            y0$1 = d$15;
        end
        if (j1$1 == idx$15) begin
            y1$1 = d$15;
        end
        if (j2$1 == idx$15) begin
            y2$1 = d$15;
        end
        if (j0$1 == idx$16) begin
            y0$1 = d$16;
        end
        if (j1$1 == idx$16) begin
            y1$1 = d$16;
        end
        if (j2$1 == idx$16) begin
            y2$1 = d$16;
        end
        if (j0$1 == idx$17) begin
            y0$1 = d$17;
        end
        if (j1$1 == idx$17) begin
            y1$1 = d$17;
        end
        if (j2$1 == idx$17) begin
            y2$1 = d$17;
        end
        if (j0$1 == idx$18) begin
            y0$1 = d$18;
        end
        if (j1$1 == idx$18) begin
            y1$1 = d$18;
        end
        if (j2$1 == idx$18) begin
            y2$1 = d$18;
        end
        if (j0$1 == idx$19) begin
            y0$1 = d$19;
        end
        if (j1$1 == idx$19) begin
            y1$1 = d$19;
        end
        if (j2$1 == idx$19) begin
            y2$1 = d$19;
        end
        if (j0$1 == idx$20) begin
            y0$1 = d$20;
        end
        if (j1$1 == idx$20) begin
            y1$1 = d$20;
        end
        if (j2$1 == idx$20) begin
            y2$1 = d$20;
        end
        if (j0$1 == idx$21) begin
            y0$1 = d$21;
        end
        if (j1$1 == idx$21) begin
            y1$1 = d$21;
        end
        if (j2$1 == idx$21) begin
            y2$1 = d$21;
        end
        if (j0$1 == idx$22) begin
            y0$1 = d$22;
        end
        if (j1$1 == idx$22) begin
            y1$1 = d$22;
        end
        if (j2$1 == idx$22) begin
            y2$1 = d$22;
        end
        if (j0$1 == idx$23) begin
            y0$1 = d$23;
        end
        if (j1$1 == idx$23) begin
            y1$1 = d$23;
        end
        if (j2$1 == idx$23) begin
            y2$1 = d$23;
        end
        y0$2 = 32'h0;
        y1$2 = 32'h0;
        y2$2 = 32'h0;
        if (j0$2 == idx$0) begin
            y0$2 = d$0;
        end
        if (j1$2 == idx$0) begin
            y1$2 = d$0;
        end
        if (j2$2 == idx$0) begin
            y2$2 = d$0;
        end
        if (j0$2 == idx$1) begin
            y0$2 = d$1;
        end
        if (j1$2 == idx$1) begin
            y1$2 = d$1;
        end
        if (j2$2 == idx$1) begin
            y2$2 = d$1;
        end
        if (j0$2 == idx$2) begin
            y0$2 = d$2;
        end
        if (j1$2 == idx$2) begin
            y1$2 = d$2;
        end
        if (j2$2 == idx$2) begin
            y2$2 = d$2;
        end
        if (j0$2 == idx$3) begin
            y0$2 = d$3;
        end
        if (j1$2 == idx$3) begin
            y1$2 = d$3;
        end
        if (j2$2 == idx$3) begin
            y2$2 = d$3;
        end
        if (j0$2 == idx$4) begin
            y0$2 = d$4;
        end
        if (j1$2 == idx$4) begin
            y1$2 = d$4;
        end
        if (j2$2 == idx$4) begin
            y2$2 = d$4;
        end
        if (j0$2 == idx$5) begin
            y0$2 = d$5;
        end
        if (j1$2 == idx$5) begin
            y1$2 = d$5;
        end
        if (j2$2 == idx$5) begin
            y2$2 = d$5;
        end
        if (j0$2 == idx$6) begin
            y0$2 = d$6;
        end
        if (j1$2 == idx$6) begin
            y1$2 = d$6;
        end
        if (j2$2 == idx$6) begin
            y2$2 = d$6;
        end
        if (j0$2 == idx$7) begin
            y0$2 = d$7;
        end
        if (j1$2 == idx$7) begin
            y1$2 = d$7;
        end
        if (j2$2 == idx$7) begin
            y2$2 = d$7;
        end
        if (j0$2 == idx$8) begin
            y0$2 = d$8;
        end
        if (j1$2 == idx$8) begin
            y1$2 = d$8;
        end
        if (j2$2 == idx$8) begin
            y2$2 = d$8;
        end
        if (j0$2 == idx$9) begin
            y0$2 = d$9;
        end
        if (j1$2 == idx$9) begin
            y1$2 = d$9;
        end
        if (j2$2 == idx$9) begin
            y2$2 = d$9;
        end
        if (j0$2 == idx$10) begin
            y0$2 = d$10;
        end
        if (j1$2 == idx$10) begin
            y1$2 = d$10;
        end
        if (j2$2 == idx$10) begin
            y2$2 = d$10;
        end
        if (j0$2 == idx$11) begin
            y0$2 = d$11;
        end
        if (j1$2 == idx$11) begin
            y1$2 = d$11;
        end
        if (j2$2 == idx$11) begin
            y2$2 = d$11;
        end
        if (j0$2 == idx$12) begin
            y0$2 = d$12;
        end
        if (j1$2 == idx$12) begin
            y1$2 = d$12;
        end
        if (j2$2 == idx$12) begin
            y2$2 = d$12;
        end
        if (j0$2 == idx$13) begin
            y0$2 = d$13;
        end
        if (j1$2 == idx$13) begin
            y1$2 = d$13;
        end
        if (j2$2 == idx$13) begin
            y2$2 = d$13;
        end
        if (j0$2 == idx$14) begin
            y0$2 = d$14;
        end
        if (j1$2 == idx$14) begin
            y1$2 = d$14;
        end
        if (j2$2 == idx$14) begin
            y2$2 = d$14;
        end
        if (j0$2 == idx$15) begin
            y0$2 = d$15;
        end
        if (j1$2 == idx$15) begin
            y1$2 = d$15;
        end
        if (j2$2 == idx$15) begin
            y2$2 = d$15;
        end
        if (j0$2 == idx$16) begin
            y0$2 = d$16;
        end
        if (j1$2 == idx$16) begin
            y1$2 = d$16;
        end
        if (j2$2 == idx$16) begin
            y2$2 = d$16;
        end
        if (j0$2 == idx$17) begin
            y0$2 = d$17;
        end
        if (j1$2 == idx$17) begin
            y1$2 = d$17;
        end
        if (j2$2 == idx$17) begin
            y2$2 = d$17;
        end
        if (j0$2 == idx$18) begin
            y0$2 = d$18;
        end
        if (j1$2 == idx$18) begin
            y1$2 = d$18;
        end
        if (j2$2 == idx$18) begin
            y2$2 = d$18;
        end
        if (j0$2 == idx$19) begin
            y0$2 = d$19;
        end
        if (j1$2 == idx$19) begin
            y1$2 = d$19;
        end
        if (j2$2 == idx$19) begin
            y2$2 = d$19;
        end
        if (j0$2 == idx$20) begin
            y0$2 = d$20;
        end
        if (j1$2 == idx$20) begin
            y1$2 = d$20;
        end
        if (j2$2 == idx$20) begin
            y2$2 = d$20;
        end
        if (j0$2 == idx$21) begin
            y0$2 = d$21;
        end
        if (j1$2 == idx$21) begin
            y1$2 = d$21;
        end
        if (j2$2 == idx$21) begin
            y2$2 = d$21;
        end
        if (j0$2 == idx$22) begin
            y0$2 = d$22;
        end
        if (j1$2 == idx$22) begin
            y1$2 = d$22;
        end
        if (j2$2 == idx$22) begin
            y2$2 = d$22;
        end
        if (j0$2 == idx$23) begin
            y0$2 = d$23;
        end
        if (j1$2 == idx$23) begin
            y1$2 = d$23;
        end
        if (j2$2 == idx$23) begin
            y2$2 = d$23;
        end
        y0$3 = 32'h0;
        y1$3 = 32'h0;
        y2$3 = 32'h0;
        if (j0$3 == idx$0) begin
            y0$3 = d$0;
        end
        if (j1$3 == idx$0) begin
            y1$3 = d$0;
        end
        if (j2$3 == idx$0) begin
            y2$3 = d$0;
        end
        if (j0$3 == idx$1) begin
            y0$3 = d$1;
        end
        if (j1$3 == idx$1) begin
            y1$3 = d$1;
        end
        if (j2$3 == idx$1) begin
            y2$3 = d$1;
        end
        if (j0$3 == idx$2) begin
            y0$3 = d$2;
        end
        if (j1$3 == idx$2) begin
            y1$3 = d$2;
        end
        if (j2$3 == idx$2) begin
            y2$3 = d$2;
        end
        if (j0$3 == idx$3) begin
            y0$3 = d$3;
        end
        if (j1$3 == idx$3) begin
            y1$3 = d$3;
        end
        if (j2$3 == idx$3) begin
            y2$3 = d$3;
        end
        if (j0$3 == idx$4) begin
            y0$3 = d$4;
        end
        if (j1$3 == idx$4) begin
            y1$3 = d$4;
        end
        if (j2$3 == idx$4) begin
            y2$3 = d$4;
        end
        if (j0$3 == idx$5) begin
            y0$3 = d$5;
        end
        if (j1$3 == idx$5) begin
            y1$3 = d$5;
        end
        if (j2$3 == idx$5) begin
            y2$3 = d$5;
        end
        if (j0$3 == idx$6) begin
            y0$3 = d$6;
        end
        if (j1$3 == idx$6) begin
            y1$3 = d$6;
        end
        if (j2$3 == idx$6) begin
            y2$3 = d$6;
        end
        if (j0$3 == idx$7) begin
            y0$3 = d$7;
        end
        if (j1$3 == idx$7) begin
            y1$3 = d$7;
        end
        if (j2$3 == idx$7) begin
            y2$3 = d$7;
        end
        if (j0$3 == idx$8) begin
            y0$3 = d$8;
        end
        if (j1$3 == idx$8) begin
            y1$3 = d$8;
        end
        if (j2$3 == idx$8) begin
            y2$3 = d$8;
        end
        if (j0$3 == idx$9) begin
            y0$3 = d$9;
        end
        if (j1$3 == idx$9) begin
            y1$3 = d$9;
        end
        if (j2$3 == idx$9) begin
            y2$3 = d$9;
        end
        if (j0$3 == idx$10) begin
            y0$3 = d$10;
        end
        if (j1$3 == idx$10) begin
            y1$3 = d$10;
        end
        if (j2$3 == idx$10) begin
            y2$3 = d$10;
        end
        if (j0$3 == idx$11) begin
            y0$3 = d$11;
        end
        if (j1$3 == idx$11) begin
            y1$3 = d$11;
        end
        if (j2$3 == idx$11) begin
            y2$3 = d$11;
        end
        if (j0$3 == idx$12) begin
            y0$3 = d$12;
        end
        if (j1$3 == idx$12) begin
            y1$3 = d$12;
        end
        if (j2$3 == idx$12) begin
            y2$3 = d$12;
        end
        if (j0$3 == idx$13) begin
            y0$3 = d$13;
        end
        if (j1$3 == idx$13) begin
            y1$3 = d$13;
        end
        if (j2$3 == idx$13) begin
            y2$3 = d$13;
        end
        if (j0$3 == idx$14) begin
            y0$3 = d$14;
        end
        if (j1$3 == idx$14) begin
            y1$3 = d$14;
        end
        if (j2$3 == idx$14) begin
            y2$3 = d$14;
        end
        if (j0$3 == idx$15) begin
            y0$3 = d$15;
        end
        if (j1$3 == idx$15) begin
            y1$3 = d$15;
        end
        if (j2$3 == idx$15) begin
            y2$3 = d$15;
        end
        if (j0$3 == idx$16) begin
            y0$3 = d$16;
        end
        if (j1$3 == idx$16) begin
            y1$3 = d$16;
        end
        if (j2$3 == idx$16) begin
            y2$3 = d$16;
        end
        if (j0$3 == idx$17) begin
            y0$3 = d$17;
        end
        if (j1$3 == idx$17) begin
            y1$3 = d$17;
        end
        if (j2$3 == idx$17) begin
            y2$3 = d$17;
        end
        if (j0$3 == idx$18) begin
            y0$3 = d$18;
        end
        if (j1$3 == idx$18) begin
            y1$3 = d$18;
        end
        if (j2$3 == idx$18) begin
            y2$3 = d$18;
        end
        if (j0$3 == idx$19) begin
            y0$3 = d$19;
        end
        if (j1$3 == idx$19) begin
            y1$3 = d$19;
        end
        if (j2$3 == idx$19) begin
            y2$3 = d$19;
        end
        if (j0$3 == idx$20) begin
            y0$3 = d$20;
        end
        if (j1$3 == idx$20) begin
            y1$3 = d$20;
        end
        if (j2$3 == idx$20) begin
            y2$3 = d$20;
        end
        if (j0$3 == idx$21) begin
            y0$3 = d$21;
        end
        if (j1$3 == idx$21) begin
            y1$3 = d$21;
        end
        if (j2$3 == idx$21) begin
            y2$3 = d$21;
        end
        if (j0$3 == idx$22) begin
            y0$3 = d$22;
        end
        if (j1$3 == idx$22) begin
            y1$3 = d$22;
        end
        if (j2$3 == idx$22) begin
            y2$3 = d$22;
        end
        if (j0$3 == idx$23) begin
            y0$3 = d$23;
        end
        if (j1$3 == idx$23) begin
            y1$3 = d$23;
        end
        if (j2$3 == idx$23) begin
            y2$3 = d$23;
        end
        y0$4 = 32'h0;
        y1$4 = 32'h0;
        y2$4 = 32'h0;
        if (j0$4 == idx$0) begin
            y0$4 = d$0;
        end
        if (j1$4 == idx$0) begin
            y1$4 = d$0;
        end
        if (j2$4 == idx$0) begin
            y2$4 = d$0;
        end
        if (j0$4 == idx$1) begin
            y0$4 = d$1;
        end
        if (j1$4 == idx$1) begin
            y1$4 = d$1;
        end
        if (j2$4 == idx$1) begin
            y2$4 = d$1;
        end
        if (j0$4 == idx$2) begin
            y0$4 = d$2;
        end
        if (j1$4 == idx$2) begin
            y1$4 = d$2;
        end
        if (j2$4 == idx$2) begin
            y2$4 = d$2;
        end
        if (j0$4 == idx$3) begin
            y0$4 = d$3;
        end
        if (j1$4 == idx$3) begin
            y1$4 = d$3;
        end
        if (j2$4 == idx$3) begin
            y2$4 = d$3;
        end
        if (j0$4 == idx$4) begin
            y0$4 = d$4;
        end
        if (j1$4 == idx$4) begin
            y1$4 = d$4;
        end
        if (j2$4 == idx$4) begin
            y2$4 = d$4;
        end
        if (j0$4 == idx$5) begin
            y0$4 = d$5;
        end
        if (j1$4 == idx$5) begin
            y1$4 = d$5;
        end
        if (j2$4 == idx$5) begin
            y2$4 = d$5;
        end
        if (j0$4 == idx$6) begin
            y0$4 = d$6;
        end
        if (j1$4 == idx$6) begin
            y1$4 = d$6;
        end
        if (j2$4 == idx$6) begin
            y2$4 = d$6;
        end
        if (j0$4 == idx$7) begin
            y0$4 = d$7;
        end
        if (j1$4 == idx$7) begin
            y1$4 = d$7;
        end
        if (j2$4 == idx$7) begin
            y2$4 = d$7;
        end
        if (j0$4 == idx$8) begin
            y0$4 = d$8;
        end
        if (j1$4 == idx$8) begin
            y1$4 = d$8;
        end
        if (j2$4 == idx$8) begin
            y2$4 = d$8;
        end
        if (j0$4 == idx$9) begin
            y0$4 = d$9;
        end
        if (j1$4 == idx$9) begin
            y1$4 = d$9;
        end
        if (j2$4 == idx$9) begin
            y2$4 = d$9;
        end
        if (j0$4 == idx$10) begin
            y0$4 = d$10;
        end
        if (j1$4 == idx$10) begin
            y1$4 = d$10;
        end
        if (j2$4 == idx$10) begin
            y2$4 = d$10;
        end
        if (j0$4 == idx$11) begin
            y0$4 = d$11;
        end
        if (j1$4 == idx$11) begin
            y1$4 = d$11;
        end
        if (j2$4 == idx$11) begin
            y2$4 = d$11;
        end
        if (j0$4 == idx$12) begin
            y0$4 = d$12;
        end
        if (j1$4 == idx$12) begin
            y1$4 = d$12;
        end
        if (j2$4 == idx$12) begin
            y2$4 = d$12;
        end
        if (j0$4 == idx$13) begin
            y0$4 = d$13;
        end
        if (j1$4 == idx$13) begin
            y1$4 = d$13;
        end
        if (j2$4 == idx$13) begin
            y2$4 = d$13;
        end
        if (j0$4 == idx$14) begin
            y0$4 = d$14;
        end
        if (j1$4 == idx$14) begin
            y1$4 = d$14;
        end
        if (j2$4 == idx$14) begin
            y2$4 = d$14;
        end
        if (j0$4 == idx$15) begin
            y0$4 = d$15;
        end
        if (j1$4 == idx$15) begin
            y1$4 = d$15;
        end
        if (j2$4 == idx$15) begin
            y2$4 = d$15;
        end
        if (j0$4 == idx$16) begin
            y0$4 = d$16;
        end
        if (j1$4 == idx$16) begin
            y1$4 = d$16;
        end
        if (j2$4 == idx$16) begin
            y2$4 = d$16;
        end
        if (j0$4 == idx$17) begin
            y0$4 = d$17;
        end
        if (j1$4 == idx$17) begin
            y1$4 = d$17;
        end
        if (j2$4 == idx$17) begin
            y2$4 = d$17;
        end
        if (j0$4 == idx$18) begin
            y0$4 = d$18;
        end
        if (j1$4 == idx$18) begin
            y1$4 = d$18;
        end
        if (j2$4 == idx$18) begin
            y2$4 = d$18;
        end
        if (j0$4 == idx$19) begin
            y0$4 = d$19;
        end
        if (j1$4 == idx$19) begin
            y1$4 = d$19;
        end
        if (j2$4 == idx$19) begin
            y2$4 = d$19;
        end
        if (j0$4 == idx$20) begin
            y0$4 = d$20;
        end
        if (j1$4 == idx$20) begin
            y1$4 = d$20;
        end
        if (j2$4 == idx$20) begin
            y2$4 = d$20;
        end
        if (j0$4 == idx$21) begin
            y0$4 = d$21;
        end
        if (j1$4 == idx$21) begin
            y1$4 = d$21;
        end
        if (j2$4 == idx$21) begin
            y2$4 = d$21;
        end
        if (j0$4 == idx$22) begin
            y0$4 = d$22;
        end
        if (j1$4 == idx$22) begin
            y1$4 = d$22;
        end
        if (j2$4 == idx$22) begin
            y2$4 = d$22;
        end
        if (j0$4 == idx$23) begin
            y0$4 = d$23;
        end
        if (j1$4 == idx$23) begin
            y1$4 = d$23;
        end
        if (j2$4 == idx$23) begin
            y2$4 = d$23;
        end
        y0$5 = 32'h0;
        y1$5 = 32'h0;
        y2$5 = 32'h0;
        if (j0$5 == idx$0) begin
            y0$5 = d$0;
        end
        if (j1$5 == idx$0) begin
            y1$5 = d$0;
        end
        if (j2$5 == idx$0) begin
            y2$5 = d$0;
        end
        if (j0$5 == idx$1) begin
            y0$5 = d$1;
        end
        if (j1$5 == idx$1) begin
            y1$5 = d$1;
        end
        if (j2$5 == idx$1) begin
            y2$5 = d$1;
        end
        if (j0$5 == idx$2) begin
            y0$5 = d$2;
        end
        if (j1$5 == idx$2) begin
            y1$5 = d$2;
        end
        if (j2$5 == idx$2) begin
            y2$5 = d$2;
        end
        if (j0$5 == idx$3) begin
            y0$5 = d$3;
        end
        if (j1$5 == idx$3) begin
            y1$5 = d$3;
        end
        if (j2$5 == idx$3) begin
            y2$5 = d$3;
        end
        if (j0$5 == idx$4) begin
            y0$5 = d$4;
        end
        if (j1$5 == idx$4) begin
            y1$5 = d$4;
        end
        if (j2$5 == idx$4) begin
            y2$5 = d$4;
        end
        if (j0$5 == idx$5) begin
            y0$5 = d$5;
        end
        if (j1$5 == idx$5) begin
            y1$5 = d$5;
        end
        if (j2$5 == idx$5) begin
            y2$5 = d$5;
        end
        if (j0$5 == idx$6) begin
            y0$5 = d$6;
        end
        if (j1$5 == idx$6) begin
            y1$5 = d$6;
        end
        if (j2$5 == idx$6) begin
            y2$5 = d$6;
        end
        if (j0$5 == idx$7) begin
            y0$5 = d$7;
        end
        if (j1$5 == idx$7) begin
            y1$5 = d$7;
        end
        if (j2$5 == idx$7) begin
            y2$5 = d$7;
        end
        if (j0$5 == idx$8) begin
            y0$5 = d$8;
        end
        if (j1$5 == idx$8) begin
            y1$5 = d$8;
        end
        if (j2$5 == idx$8) begin
            y2$5 = d$8;
        end
        if (j0$5 == idx$9) begin
            y0$5 = d$9;
        end
        if (j1$5 == idx$9) begin
            y1$5 = d$9;
        end
        if (j2$5 == idx$9) begin
            y2$5 = d$9;
        end
        if (j0$5 == idx$10) begin
            y0$5 = d$10;
        end
        if (j1$5 == idx$10) begin
            y1$5 = d$10;
        end
        if (j2$5 == idx$10) begin
            y2$5 = d$10;
        end
        if (j0$5 == idx$11) begin
            y0$5 = d$11;
        end
        if (j1$5 == idx$11) begin
            y1$5 = d$11;
        end
        if (j2$5 == idx$11) begin
            y2$5 = d$11;
        end
        if (j0$5 == idx$12) begin
            y0$5 = d$12;
        end
        if (j1$5 == idx$12) begin
            y1$5 = d$12;
        end
        if (j2$5 == idx$12) begin
            y2$5 = d$12;
        end
        if (j0$5 == idx$13) begin
            y0$5 = d$13;
        end
        if (j1$5 == idx$13) begin
            y1$5 = d$13;
        end
        if (j2$5 == idx$13) begin
            y2$5 = d$13;
        end
        if (j0$5 == idx$14) begin
            y0$5 = d$14;
        end
        if (j1$5 == idx$14) begin
            y1$5 = d$14;
        end
        if (j2$5 == idx$14) begin
            y2$5 = d$14;
        end
        if (j0$5 == idx$15) begin
            y0$5 = d$15;
        end
        if (j1$5 == idx$15) begin
            y1$5 = d$15;
        end
        if (j2$5 == idx$15) begin
            y2$5 = d$15;
        end
        if (j0$5 == idx$16) begin
            y0$5 = d$16;
        end
        if (j1$5 == idx$16) begin
            y1$5 = d$16;
        end
        if (j2$5 == idx$16) begin
            y2$5 = d$16;
        end
        if (j0$5 == idx$17) begin
            y0$5 = d$17;
        end
        if (j1$5 == idx$17) begin
            y1$5 = d$17;
        end
        if (j2$5 == idx$17) begin
            y2$5 = d$17;
        end
        if (j0$5 == idx$18) begin
            y0$5 = d$18;
        end
        if (j1$5 == idx$18) begin
            y1$5 = d$18;
        end
        if (j2$5 == idx$18) begin
            y2$5 = d$18;
        end
        if (j0$5 == idx$19) begin
            y0$5 = d$19;
        end
        if (j1$5 == idx$19) begin
            y1$5 = d$19;
        end
        if (j2$5 == idx$19) begin
            y2$5 = d$19;
        end
        if (j0$5 == idx$20) begin
            y0$5 = d$20;
        end
        if (j1$5 == idx$20) begin
            y1$5 = d$20;
        end
        if (j2$5 == idx$20) begin
            y2$5 = d$20;
        end
        if (j0$5 == idx$21) begin
            y0$5 = d$21;
        end
        if (j1$5 == idx$21) begin
            y1$5 = d$21;
        end
        if (j2$5 == idx$21) begin
            y2$5 = d$21;
        end
        if (j0$5 == idx$22) begin
            y0$5 = d$22;
        end
        if (j1$5 == idx$22) begin
            y1$5 = d$22;
        end
        if (j2$5 == idx$22) begin
            y2$5 = d$22;
        end
        if (j0$5 == idx$23) begin
            y0$5 = d$23;
        end
        if (j1$5 == idx$23) begin
            y1$5 = d$23;
        end
        if (j2$5 == idx$23) begin
            y2$5 = d$23;
        end
        y0$6 = 32'h0;
        y1$6 = 32'h0;
        y2$6 = 32'h0;
        if (j0$6 == idx$0) begin
            y0$6 = d$0;
        end
        if (j1$6 == idx$0) begin
            y1$6 = d$0;
        end
        if (j2$6 == idx$0) begin
            y2$6 = d$0;
        end
        if (j0$6 == idx$1) begin
            y0$6 = d$1;
        end
        if (j1$6 == idx$1) begin
            y1$6 = d$1;
        end
        if (j2$6 == idx$1) begin
            y2$6 = d$1;
        end
        if (j0$6 == idx$2) begin
            y0$6 = d$2;
        end
        if (j1$6 == idx$2) begin
            y1$6 = d$2;
        end
        if (j2$6 == idx$2) begin
            y2$6 = d$2;
        end
        if (j0$6 == idx$3) begin
            y0$6 = d$3;
        end
        if (j1$6 == idx$3) begin
            y1$6 = d$3;
        end
        if (j2$6 == idx$3) begin
            y2$6 = d$3;
        end
        if (j0$6 == idx$4) begin
            y0$6 = d$4;
        end
        if (j1$6 == idx$4) begin
            y1$6 = d$4;
        end
        if (j2$6 == idx$4) begin
            y2$6 = d$4;
        end
        if (j0$6 == idx$5) begin
            y0$6 = d$5;
        end
        if (j1$6 == idx$5) begin
            y1$6 = d$5;
        end
        if (j2$6 == idx$5) begin
            y2$6 = d$5;
        end
        if (j0$6 == idx$6) begin
            y0$6 = d$6;
        end
        if (j1$6 == idx$6) begin
            y1$6 = d$6;
        end
        if (j2$6 == idx$6) begin
            y2$6 = d$6;
        end
        if (j0$6 == idx$7) begin
            y0$6 = d$7;
        end
        if (j1$6 == idx$7) begin
            y1$6 = d$7;
        end
        if (j2$6 == idx$7) begin
            y2$6 = d$7;
        end
        if (j0$6 == idx$8) begin
            y0$6 = d$8;
        end
        if (j1$6 == idx$8) begin
            y1$6 = d$8;
        end
        if (j2$6 == idx$8) begin
            y2$6 = d$8;
        end
        if (j0$6 == idx$9) begin
            y0$6 = d$9;
        end
        if (j1$6 == idx$9) begin
            y1$6 = d$9;
        end
        if (j2$6 == idx$9) begin
            y2$6 = d$9;
        end
        if (j0$6 == idx$10) begin
            y0$6 = d$10;
        end
        if (j1$6 == idx$10) begin
            y1$6 = d$10;
        end
        if (j2$6 == idx$10) begin
            y2$6 = d$10;
        end
        if (j0$6 == idx$11) begin
            y0$6 = d$11;
        end
        if (j1$6 == idx$11) begin
            y1$6 = d$11;
        end
        if (j2$6 == idx$11) begin
            y2$6 = d$11;
        end
        if (j0$6 == idx$12) begin
            y0$6 = d$12;
        end
        if (j1$6 == idx$12) begin
            y1$6 = d$12;
        end
        if (j2$6 == idx$12) begin
            y2$6 = d$12;
        end
        if (j0$6 == idx$13) begin
            y0$6 = d$13;
        end
        if (j1$6 == idx$13) begin
            y1$6 = d$13;
        end
        if (j2$6 == idx$13) begin
            y2$6 = d$13;
        end
        if (j0$6 == idx$14) begin
            y0$6 = d$14;
        end
        if (j1$6 == idx$14) begin
            y1$6 = d$14;
        end
        if (j2$6 == idx$14) begin
            y2$6 = d$14;
        end
        if (j0$6 == idx$15) begin
            y0$6 = d$15;
        end
        if (j1$6 == idx$15) begin
            y1$6 = d$15;
        end
        if (j2$6 == idx$15) begin
            y2$6 = d$15;
        end
        if (j0$6 == idx$16) begin
            y0$6 = d$16;
        end
        if (j1$6 == idx$16) begin
            y1$6 = d$16;
        end
        if (j2$6 == idx$16) begin
            y2$6 = d$16;
        end
        if (j0$6 == idx$17) begin
            y0$6 = d$17;
        end
        if (j1$6 == idx$17) begin
            y1$6 = d$17;
        end
        if (j2$6 == idx$17) begin
            y2$6 = d$17;
        end
        if (j0$6 == idx$18) begin
            y0$6 = d$18;
        end
        if (j1$6 == idx$18) begin
            y1$6 = d$18;
        end
        if (j2$6 == idx$18) begin
            y2$6 = d$18;
        end
        if (j0$6 == idx$19) begin
            y0$6 = d$19;
        end
        if (j1$6 == idx$19) begin
            y1$6 = d$19;
        end
        if (j2$6 == idx$19) begin
            y2$6 = d$19;
        end
        if (j0$6 == idx$20) begin
            y0$6 = d$20;
        end
        if (j1$6 == idx$20) begin
            y1$6 = d$20;
        end
        if (j2$6 == idx$20) begin
            y2$6 = d$20;
        end
        if (j0$6 == idx$21) begin
            y0$6 = d$21;
        end
        if (j1$6 == idx$21) begin
            y1$6 = d$21;
        end
        if (j2$6 == idx$21) begin
            y2$6 = d$21;
        end
        if (j0$6 == idx$22) begin
            y0$6 = d$22;
        end
        if (j1$6 == idx$22) begin
            y1$6 = d$22;
        end
        if (j2$6 == idx$22) begin
            y2$6 = d$22;
        end
        if (j0$6 == idx$23) begin
            y0$6 = d$23;
        end
        if (j1$6 == idx$23) begin
            y1$6 = d$23;
        end
        if (j2$6 == idx$23) begin
            y2$6 = d$23;
        end
        y0$7 = 32'h0;
        y1$7 = 32'h0;
        y2$7 = 32'h0;
        if (j0$7 == idx$0) begin
            y0$7 = d$0;
        end
        if (j1$7 == idx$0) begin
            y1$7 = d$0;
        end
        if (j2$7 == idx$0) begin
            y2$7 = d$0;
        end
        if (j0$7 == idx$1) begin
            y0$7 = d$1;
        end
        if (j1$7 == idx$1) begin
            y1$7 = d$1;
        end
        if (j2$7 == idx$1) begin
            y2$7 = d$1;
        end
        if (j0$7 == idx$2) begin
            y0$7 = d$2;
        end
        if (j1$7 == idx$2) begin
            y1$7 = d$2;
        end
        if (j2$7 == idx$2) begin
            y2$7 = d$2;
        end
        if (j0$7 == idx$3) begin
            y0$7 = d$3;
        end
        if (j1$7 == idx$3) begin
            y1$7 = d$3;
        end
        if (j2$7 == idx$3) begin
            y2$7 = d$3;
        end
        if (j0$7 == idx$4) begin
            y0$7 = d$4;
        end
        if (j1$7 == idx$4) begin
            y1$7 = d$4;
        end
        if (j2$7 == idx$4) begin
            y2$7 = d$4;
        end
        if (j0$7 == idx$5) begin
            y0$7 = d$5;
        end
        if (j1$7 == idx$5) begin
            y1$7 = d$5;
        end
        if (j2$7 == idx$5) begin
            y2$7 = d$5;
        end
        if (j0$7 == idx$6) begin
            y0$7 = d$6;
        end
        if (j1$7 == idx$6) begin
            y1$7 = d$6;
        end
        if (j2$7 == idx$6) begin
            y2$7 = d$6;
        end
        if (j0$7 == idx$7) begin
            y0$7 = d$7;
        end
        if (j1$7 == idx$7) begin
            y1$7 = d$7;
        end
        if (j2$7 == idx$7) begin
            y2$7 = d$7;
        end
        if (j0$7 == idx$8) begin
            y0$7 = d$8;
        end
        if (j1$7 == idx$8) begin
            y1$7 = d$8;
        end
        if (j2$7 == idx$8) begin
            y2$7 = d$8;
        end
        if (j0$7 == idx$9) begin
            y0$7 = d$9;
        end
        if (j1$7 == idx$9) begin
            y1$7 = d$9;
        end
        if (j2$7 == idx$9) begin
            y2$7 = d$9;
        end
        if (j0$7 == idx$10) begin
            y0$7 = d$10;
        end
        if (j1$7 == idx$10) begin
            y1$7 = d$10;
        end
        if (j2$7 == idx$10) begin
            y2$7 = d$10;
        end
        if (j0$7 == idx$11) begin
            y0$7 = d$11;
        end
        if (j1$7 == idx$11) begin
            y1$7 = d$11;
        end
        if (j2$7 == idx$11) begin
            y2$7 = d$11;
        end
        if (j0$7 == idx$12) begin
            y0$7 = d$12;
        end
        if (j1$7 == idx$12) begin
            y1$7 = d$12;
        end
        if (j2$7 == idx$12) begin
            y2$7 = d$12;
        end
        if (j0$7 == idx$13) begin
            y0$7 = d$13;
        end
        if (j1$7 == idx$13) begin
            y1$7 = d$13;
        end
        if (j2$7 == idx$13) begin
            y2$7 = d$13;
        end
        if (j0$7 == idx$14) begin
            y0$7 = d$14;
        end
        if (j1$7 == idx$14) begin
            y1$7 = d$14;
        end
        if (j2$7 == idx$14) begin
            y2$7 = d$14;
        end
        if (j0$7 == idx$15) begin
            y0$7 = d$15;
        end
        if (j1$7 == idx$15) begin
            y1$7 = d$15;
        end
        if (j2$7 == idx$15) begin
            y2$7 = d$15;
        end
        if (j0$7 == idx$16) begin
            y0$7 = d$16;
        end
        if (j1$7 == idx$16) begin
            y1$7 = d$16;
        end
        if (j2$7 == idx$16) begin
            y2$7 = d$16;
        end
        if (j0$7 == idx$17) begin
            y0$7 = d$17;
        end
        if (j1$7 == idx$17) begin
            y1$7 = d$17;
        end
        if (j2$7 == idx$17) begin
            y2$7 = d$17;
        end
        if (j0$7 == idx$18) begin
            y0$7 = d$18;
        end
        if (j1$7 == idx$18) begin
            y1$7 = d$18;
        end
        if (j2$7 == idx$18) begin
            y2$7 = d$18;
        end
        if (j0$7 == idx$19) begin
            y0$7 = d$19;
        end
        if (j1$7 == idx$19) begin
            y1$7 = d$19;
        end
        if (j2$7 == idx$19) begin
            y2$7 = d$19;
        end
        if (j0$7 == idx$20) begin
            y0$7 = d$20;
        end
        if (j1$7 == idx$20) begin
            y1$7 = d$20;
        end
        if (j2$7 == idx$20) begin
            y2$7 = d$20;
        end
        if (j0$7 == idx$21) begin
            y0$7 = d$21;
        end
        if (j1$7 == idx$21) begin
            y1$7 = d$21;
        end
        if (j2$7 == idx$21) begin
            y2$7 = d$21;
        end
        if (j0$7 == idx$22) begin
            y0$7 = d$22;
        end
        if (j1$7 == idx$22) begin
            y1$7 = d$22;
        end
        if (j2$7 == idx$22) begin
            y2$7 = d$22;
        end
        if (j0$7 == idx$23) begin
            y0$7 = d$23;
        end
        if (j1$7 == idx$23) begin
            y1$7 = d$23;
        end
        if (j2$7 == idx$23) begin
            y2$7 = d$23;
        end
        y0$8 = 32'h0;
        y1$8 = 32'h0;
        y2$8 = 32'h0;
        if (j0$8 == idx$0) begin
            y0$8 = d$0;
        end
        if (j1$8 == idx$0) begin
            y1$8 = d$0;
        end
        if (j2$8 == idx$0) begin
            y2$8 = d$0;
        end
        if (j0$8 == idx$1) begin
            y0$8 = d$1;
        end
        if (j1$8 == idx$1) begin
            y1$8 = d$1;
        end
        if (j2$8 == idx$1) begin
            y2$8 = d$1;
        end
        if (j0$8 == idx$2) begin
            y0$8 = d$2;
        end
        if (j1$8 == idx$2) begin
            y1$8 = d$2;
        end
        if (j2$8 == idx$2) begin
            y2$8 = d$2;
        end
        if (j0$8 == idx$3) begin
            y0$8 = d$3;
        end
        if (j1$8 == idx$3) begin
            y1$8 = d$3;
        end
        if (j2$8 == idx$3) begin
            y2$8 = d$3;
        end
        if (j0$8 == idx$4) begin
            y0$8 = d$4;
        end
        if (j1$8 == idx$4) begin
            y1$8 = d$4;
        end
        if (j2$8 == idx$4) begin
            y2$8 = d$4;
        end
        if (j0$8 == idx$5) begin
            y0$8 = d$5;
        end
        if (j1$8 == idx$5) begin
            y1$8 = d$5;
        end
        if (j2$8 == idx$5) begin
            y2$8 = d$5;
        end
        if (j0$8 == idx$6) begin
            y0$8 = d$6;
        end
        if (j1$8 == idx$6) begin
            y1$8 = d$6;
        end
        if (j2$8 == idx$6) begin
            y2$8 = d$6;
        end
        if (j0$8 == idx$7) begin
            y0$8 = d$7;
        end
        if (j1$8 == idx$7) begin
            y1$8 = d$7;
        end
        if (j2$8 == idx$7) begin
            y2$8 = d$7;
        end
        if (j0$8 == idx$8) begin
            y0$8 = d$8;
        end
        if (j1$8 == idx$8) begin
            y1$8 = d$8;
        end
        if (j2$8 == idx$8) begin
            y2$8 = d$8;
        end
        if (j0$8 == idx$9) begin
            y0$8 = d$9;
        end
        if (j1$8 == idx$9) begin
            y1$8 = d$9;
        end
        if (j2$8 == idx$9) begin
            y2$8 = d$9;
        end
        if (j0$8 == idx$10) begin
            y0$8 = d$10;
        end
        if (j1$8 == idx$10) begin
            y1$8 = d$10;
        end
        if (j2$8 == idx$10) begin
            y2$8 = d$10;
        end
        if (j0$8 == idx$11) begin
            y0$8 = d$11;
        end
        if (j1$8 == idx$11) begin
            y1$8 = d$11;
        end
        if (j2$8 == idx$11) begin
            y2$8 = d$11;
        end
        if (j0$8 == idx$12) begin
            y0$8 = d$12;
        end
        if (j1$8 == idx$12) begin
            y1$8 = d$12;
        end
        if (j2$8 == idx$12) begin
            y2$8 = d$12;
        end
        if (j0$8 == idx$13) begin
            y0$8 = d$13;
        end
        if (j1$8 == idx$13) begin
            y1$8 = d$13;
        end
        if (j2$8 == idx$13) begin
            y2$8 = d$13;
        end
        if (j0$8 == idx$14) begin
            y0$8 = d$14;
        end
        if (j1$8 == idx$14) begin
            y1$8 = d$14;
        end
        if (j2$8 == idx$14) begin
            y2$8 = d$14;
        end
        if (j0$8 == idx$15) begin
            y0$8 = d$15;
        end
        if (j1$8 == idx$15) begin
            y1$8 = d$15;
        end
        if (j2$8 == idx$15) begin
            y2$8 = d$15;
        end
        if (j0$8 == idx$16) begin
            y0$8 = d$16;
        end
        if (j1$8 == idx$16) begin
            y1$8 = d$16;
        end
        if (j2$8 == idx$16) begin
            y2$8 = d$16;
        end
        if (j0$8 == idx$17) begin
            y0$8 = d$17;
        end
        if (j1$8 == idx$17) begin
            y1$8 = d$17;
        end
        if (j2$8 == idx$17) begin
            y2$8 = d$17;
        end
        if (j0$8 == idx$18) begin
            y0$8 = d$18;
        end
        if (j1$8 == idx$18) begin
            y1$8 = d$18;
        end
        if (j2$8 == idx$18) begin
            y2$8 = d$18;
        end
        if (j0$8 == idx$19) begin
            y0$8 = d$19;
        end
        if (j1$8 == idx$19) begin
            y1$8 = d$19;
        end
        if (j2$8 == idx$19) begin
            y2$8 = d$19;
        end
        if (j0$8 == idx$20) begin
            y0$8 = d$20;
        end
        if (j1$8 == idx$20) begin
            y1$8 = d$20;
        end
        if (j2$8 == idx$20) begin
            y2$8 = d$20;
        end
        if (j0$8 == idx$21) begin
            y0$8 = d$21;
        end
        if (j1$8 == idx$21) begin
            y1$8 = d$21;
        end
        if (j2$8 == idx$21) begin
            y2$8 = d$21;
        end
        if (j0$8 == idx$22) begin
            y0$8 = d$22;
        end
        if (j1$8 == idx$22) begin
            y1$8 = d$22;
        end
        if (j2$8 == idx$22) begin
            y2$8 = d$22;
        end
        if (j0$8 == idx$23) begin
            y0$8 = d$23;
        end
        if (j1$8 == idx$23) begin
            y1$8 = d$23;
        end
        if (j2$8 == idx$23) begin
            y2$8 = d$23;
        end
        y0$9 = 32'h0;
        y1$9 = 32'h0;
        y2$9 = 32'h0;
        if (j0$9 == idx$0) begin
            y0$9 = d$0;
        end
        if (j1$9 == idx$0) begin
            y1$9 = d$0;
        end
        if (j2$9 == idx$0) begin
            y2$9 = d$0;
        end
        if (j0$9 == idx$1) begin
            y0$9 = d$1;
        end
        if (j1$9 == idx$1) begin
            y1$9 = d$1;
        end
        if (j2$9 == idx$1) begin
            y2$9 = d$1;
        end
        if (j0$9 == idx$2) begin
            y0$9 = d$2;
        end
        if (j1$9 == idx$2) begin
            y1$9 = d$2;
        end
        if (j2$9 == idx$2) begin
            y2$9 = d$2;
        end
        if (j0$9 == idx$3) begin
            y0$9 = d$3;
        end
        if (j1$9 == idx$3) begin
            y1$9 = d$3;
        end
        if (j2$9 == idx$3) begin
            y2$9 = d$3;
        end
        if (j0$9 == idx$4) begin
            y0$9 = d$4;
        end
        if (j1$9 == idx$4) begin
            y1$9 = d$4;
        end
        if (j2$9 == idx$4) begin
            y2$9 = d$4;
        end
        if (j0$9 == idx$5) begin
            y0$9 = d$5;
        end
        if (j1$9 == idx$5) begin
            y1$9 = d$5;
        end
        if (j2$9 == idx$5) begin
            y2$9 = d$5;
        end
        if (j0$9 == idx$6) begin
            y0$9 = d$6;
        end
        if (j1$9 == idx$6) begin
            y1$9 = d$6;
        end
        if (j2$9 == idx$6) begin
            y2$9 = d$6;
        end
        if (j0$9 == idx$7) begin
            y0$9 = d$7;
        end
        if (j1$9 == idx$7) begin
            y1$9 = d$7;
        end
        if (j2$9 == idx$7) begin
            y2$9 = d$7;
        end
        if (j0$9 == idx$8) begin
            y0$9 = d$8;
        end
        if (j1$9 == idx$8) begin
            y1$9 = d$8;
        end
        if (j2$9 == idx$8) begin
            y2$9 = d$8;
        end
        if (j0$9 == idx$9) begin
            y0$9 = d$9;
        end
        if (j1$9 == idx$9) begin
            y1$9 = d$9;
        end
        if (j2$9 == idx$9) begin
            y2$9 = d$9;
        end
        if (j0$9 == idx$10) begin
            y0$9 = d$10;
        end
        if (j1$9 == idx$10) begin
            y1$9 = d$10;
        end
        if (j2$9 == idx$10) begin
            y2$9 = d$10;
        end
        if (j0$9 == idx$11) begin
            y0$9 = d$11;
        end
        if (j1$9 == idx$11) begin
            y1$9 = d$11;
        end
        if (j2$9 == idx$11) begin
            y2$9 = d$11;
        end
        if (j0$9 == idx$12) begin
            y0$9 = d$12;
        end
        if (j1$9 == idx$12) begin
            y1$9 = d$12;
        end
        if (j2$9 == idx$12) begin
            y2$9 = d$12;
        end
        if (j0$9 == idx$13) begin
            y0$9 = d$13;
        end
        if (j1$9 == idx$13) begin
            y1$9 = d$13;
        end
        if (j2$9 == idx$13) begin
            y2$9 = d$13;
        end
        if (j0$9 == idx$14) begin
            y0$9 = d$14;
        end
        if (j1$9 == idx$14) begin
            y1$9 = d$14;
        end
        if (j2$9 == idx$14) begin
            y2$9 = d$14;
        end
        if (j0$9 == idx$15) begin
            y0$9 = d$15;
        end
        if (j1$9 == idx$15) begin
            y1$9 = d$15;
        end
        if (j2$9 == idx$15) begin
            y2$9 = d$15;
        end
        if (j0$9 == idx$16) begin
            y0$9 = d$16;
        end
        if (j1$9 == idx$16) begin
            y1$9 = d$16;
        end
        if (j2$9 == idx$16) begin
            y2$9 = d$16;
        end
        if (j0$9 == idx$17) begin
            y0$9 = d$17;
        end
        if (j1$9 == idx$17) begin
            y1$9 = d$17;
        end
        if (j2$9 == idx$17) begin
            y2$9 = d$17;
        end
        if (j0$9 == idx$18) begin
            y0$9 = d$18;
        end
        if (j1$9 == idx$18) begin
            y1$9 = d$18;
        end
        if (j2$9 == idx$18) begin
            y2$9 = d$18;
        end
        if (j0$9 == idx$19) begin
            y0$9 = d$19;
        end
        if (j1$9 == idx$19) begin
            y1$9 = d$19;
        end
        if (j2$9 == idx$19) begin
            y2$9 = d$19;
        end
        if (j0$9 == idx$20) begin
            y0$9 = d$20;
        end
        if (j1$9 == idx$20) begin
            y1$9 = d$20;
        end
        if (j2$9 == idx$20) begin
            y2$9 = d$20;
        end
        if (j0$9 == idx$21) begin
            y0$9 = d$21;
        end
        if (j1$9 == idx$21) begin
            y1$9 = d$21;
        end
        if (j2$9 == idx$21) begin
            y2$9 = d$21;
        end
        if (j0$9 == idx$22) begin
            y0$9 = d$22;
        end
        if (j1$9 == idx$22) begin
            y1$9 = d$22;
        end
        if (j2$9 == idx$22) begin
            y2$9 = d$22;
        end
        if (j0$9 == idx$23) begin
            y0$9 = d$23;
        end
        if (j1$9 == idx$23) begin
            y1$9 = d$23;
        end
        if (j2$9 == idx$23) begin
            y2$9 = d$23;
        end
        y0$10 = 32'h0;
        y1$10 = 32'h0;
        y2$10 = 32'h0;
        if (j0$10 == idx$0) begin
            y0$10 = d$0;
        end
        if (j1$10 == idx$0) begin
            y1$10 = d$0;
        end
        if (j2$10 == idx$0) begin
            y2$10 = d$0;
        end
        if (j0$10 == idx$1) begin
            y0$10 = d$1;
        end
        if (j1$10 == idx$1) begin
            y1$10 = d$1;
        end
        if (j2$10 == idx$1) begin
            y2$10 = d$1;
        end
        if (j0$10 == idx$2) begin
            y0$10 = d$2;
        end
        if (j1$10 == idx$2) begin
            y1$10 = d$2;
        end
        if (j2$10 == idx$2) begin
            y2$10 = d$2;
        end
        if (j0$10 == idx$3) begin
            y0$10 = d$3;
        end
        if (j1$10 == idx$3) begin
            y1$10 = d$3;
        end
        if (j2$10 == idx$3) begin
            y2$10 = d$3;
        end
        if (j0$10 == idx$4) begin
            y0$10 = d$4;
        end
        if (j1$10 == idx$4) begin
            y1$10 = d$4;
        end
        if (j2$10 == idx$4) begin
            y2$10 = d$4;
        end
        if (j0$10 == idx$5) begin
            y0$10 = d$5;
        end
        if (j1$10 == idx$5) begin
            y1$10 = d$5;
        end
        if (j2$10 == idx$5) begin
            y2$10 = d$5;
        end
        if (j0$10 == idx$6) begin
            y0$10 = d$6;
        end
        if (j1$10 == idx$6) begin
            y1$10 = d$6;
        end
        if (j2$10 == idx$6) begin
            y2$10 = d$6;
        end
        if (j0$10 == idx$7) begin
            y0$10 = d$7;
        end
        if (j1$10 == idx$7) begin
            y1$10 = d$7;
        end
        if (j2$10 == idx$7) begin
            y2$10 = d$7;
        end
        if (j0$10 == idx$8) begin
            y0$10 = d$8;
        end
        if (j1$10 == idx$8) begin
            y1$10 = d$8;
        end
        if (j2$10 == idx$8) begin
            y2$10 = d$8;
        end
        if (j0$10 == idx$9) begin
            y0$10 = d$9;
        end
        if (j1$10 == idx$9) begin
            y1$10 = d$9;
        end
        if (j2$10 == idx$9) begin
            y2$10 = d$9;
        end
        if (j0$10 == idx$10) begin
            y0$10 = d$10;
        end
        if (j1$10 == idx$10) begin
            y1$10 = d$10;
        end
        if (j2$10 == idx$10) begin
            y2$10 = d$10;
        end
        if (j0$10 == idx$11) begin
            y0$10 = d$11;
        end
        if (j1$10 == idx$11) begin
            y1$10 = d$11;
        end
        if (j2$10 == idx$11) begin
            y2$10 = d$11;
        end
        if (j0$10 == idx$12) begin
            y0$10 = d$12;
        end
        if (j1$10 == idx$12) begin
            y1$10 = d$12;
        end
        if (j2$10 == idx$12) begin
            y2$10 = d$12;
        end
        if (j0$10 == idx$13) begin
            y0$10 = d$13;
        end
        if (j1$10 == idx$13) begin
            y1$10 = d$13;
        end
        if (j2$10 == idx$13) begin
            y2$10 = d$13;
        end
        if (j0$10 == idx$14) begin
            y0$10 = d$14;
        end
        if (j1$10 == idx$14) begin
            y1$10 = d$14;
        end
        if (j2$10 == idx$14) begin
            y2$10 = d$14;
        end
        if (j0$10 == idx$15) begin
            y0$10 = d$15;
        end
        if (j1$10 == idx$15) begin
            y1$10 = d$15;
        end
        if (j2$10 == idx$15) begin
            y2$10 = d$15;
        end
        if (j0$10 == idx$16) begin
            y0$10 = d$16;
        end
        if (j1$10 == idx$16) begin
            y1$10 = d$16;
        end
        if (j2$10 == idx$16) begin
            y2$10 = d$16;
        end
        if (j0$10 == idx$17) begin
            y0$10 = d$17;
        end
        if (j1$10 == idx$17) begin
            y1$10 = d$17;
        end
        if (j2$10 == idx$17) begin
            y2$10 = d$17;
        end
        if (j0$10 == idx$18) begin
            y0$10 = d$18;
        end
        if (j1$10 == idx$18) begin
            y1$10 = d$18;
        end
        if (j2$10 == idx$18) begin
            y2$10 = d$18;
        end
        if (j0$10 == idx$19) begin
            y0$10 = d$19;
        end
        if (j1$10 == idx$19) begin
            y1$10 = d$19;
        end
        if (j2$10 == idx$19) begin
            y2$10 = d$19;
        end
        if (j0$10 == idx$20) begin
            y0$10 = d$20;
        end
        if (j1$10 == idx$20) begin
            y1$10 = d$20;
        end
        if (j2$10 == idx$20) begin
            y2$10 = d$20;
        end
        if (j0$10 == idx$21) begin
            y0$10 = d$21;
        end
        if (j1$10 == idx$21) begin
            y1$10 = d$21;
        end
        if (j2$10 == idx$21) begin
            y2$10 = d$21;
        end
        if (j0$10 == idx$22) begin
            y0$10 = d$22;
        end
        if (j1$10 == idx$22) begin
            y1$10 = d$22;
        end
        if (j2$10 == idx$22) begin
            y2$10 = d$22;
        end
        if (j0$10 == idx$23) begin
            y0$10 = d$23;
        end
        if (j1$10 == idx$23) begin
            y1$10 = d$23;
        end
        if (j2$10 == idx$23) begin
            y2$10 = d$23;
        end
        y0$11 = 32'h0;
        y1$11 = 32'h0;
        y2$11 = 32'h0;
        if (j0$11 == idx$0) begin
            y0$11 = d$0;
        end
        if (j1$11 == idx$0) begin
            y1$11 = d$0;
        end
        if (j2$11 == idx$0) begin
            y2$11 = d$0;
        end
        if (j0$11 == idx$1) begin
            y0$11 = d$1;
        end
        if (j1$11 == idx$1) begin
            y1$11 = d$1;
        end
        if (j2$11 == idx$1) begin
            y2$11 = d$1;
        end
        if (j0$11 == idx$2) begin
            y0$11 = d$2;
        end
        if (j1$11 == idx$2) begin
            y1$11 = d$2;
        end
        if (j2$11 == idx$2) begin
            y2$11 = d$2;
        end
        if (j0$11 == idx$3) begin
            y0$11 = d$3;
        end
        if (j1$11 == idx$3) begin
            y1$11 = d$3;
        end
        if (j2$11 == idx$3) begin
            y2$11 = d$3;
        end
        if (j0$11 == idx$4) begin
            y0$11 = d$4;
        end
        if (j1$11 == idx$4) begin
            y1$11 = d$4;
        end
        if (j2$11 == idx$4) begin
            y2$11 = d$4;
        end
        if (j0$11 == idx$5) begin
            y0$11 = d$5;
        end
        if (j1$11 == idx$5) begin
            y1$11 = d$5;
        end
        if (j2$11 == idx$5) begin
            y2$11 = d$5;
        end
        if (j0$11 == idx$6) begin
            y0$11 = d$6;
        end
        if (j1$11 == idx$6) begin
            y1$11 = d$6;
        end
        if (j2$11 == idx$6) begin
            y2$11 = d$6;
        end
        if (j0$11 == idx$7) begin
            y0$11 = d$7;
        end
        if (j1$11 == idx$7) begin
            y1$11 = d$7;
        end
        if (j2$11 == idx$7) begin
            y2$11 = d$7;
        end
        if (j0$11 == idx$8) begin
            y0$11 = d$8;
        end
        if (j1$11 == idx$8) begin
            y1$11 = d$8;
        end
        if (j2$11 == idx$8) begin
            y2$11 = d$8;
        end
        if (j0$11 == idx$9) begin
            y0$11 = d$9;
        end
        if (j1$11 == idx$9) begin
            y1$11 = d$9;
        end
        if (j2$11 == idx$9) begin
            y2$11 = d$9;
        end
        if (j0$11 == idx$10) begin
            y0$11 = d$10;
        end
        if (j1$11 == idx$10) begin
            y1$11 = d$10;
        end
        if (j2$11 == idx$10) begin
            y2$11 = d$10;
        end
        if (j0$11 == idx$11) begin
            y0$11 = d$11;
        end
        if (j1$11 == idx$11) begin
            y1$11 = d$11;
        end
        if (j2$11 == idx$11) begin
            y2$11 = d$11;
        end
        if (j0$11 == idx$12) begin
            y0$11 = d$12;
        end
        if (j1$11 == idx$12) begin
            y1$11 = d$12;
        end
        if (j2$11 == idx$12) begin
            y2$11 = d$12;
        end
        if (j0$11 == idx$13) begin
            y0$11 = d$13;
        end
        if (j1$11 == idx$13) begin
            y1$11 = d$13;
        end
        if (j2$11 == idx$13) begin
            y2$11 = d$13;
        end
        if (j0$11 == idx$14) begin
            y0$11 = d$14;
        end
        if (j1$11 == idx$14) begin
            y1$11 = d$14;
        end
        if (j2$11 == idx$14) begin
            y2$11 = d$14;
        end
        if (j0$11 == idx$15) begin
            y0$11 = d$15;
        end
        if (j1$11 == idx$15) begin
            y1$11 = d$15;
        end
        if (j2$11 == idx$15) begin
            y2$11 = d$15;
        end
        if (j0$11 == idx$16) begin
            y0$11 = d$16;
        end
        if (j1$11 == idx$16) begin
            y1$11 = d$16;
        end
        if (j2$11 == idx$16) begin
            y2$11 = d$16;
        end
        if (j0$11 == idx$17) begin
            y0$11 = d$17;
        end
        if (j1$11 == idx$17) begin
            y1$11 = d$17;
        end
        if (j2$11 == idx$17) begin
            y2$11 = d$17;
        end
        if (j0$11 == idx$18) begin
            y0$11 = d$18;
        end
        if (j1$11 == idx$18) begin
            y1$11 = d$18;
        end
        if (j2$11 == idx$18) begin
            y2$11 = d$18;
        end
        if (j0$11 == idx$19) begin
            y0$11 = d$19;
        end
        if (j1$11 == idx$19) begin
            y1$11 = d$19;
        end
        if (j2$11 == idx$19) begin
            y2$11 = d$19;
        end
        if (j0$11 == idx$20) begin
            y0$11 = d$20;
        end
        if (j1$11 == idx$20) begin
            y1$11 = d$20;
        end
        if (j2$11 == idx$20) begin
            y2$11 = d$20;
        end
        if (j0$11 == idx$21) begin
            y0$11 = d$21;
        end
        if (j1$11 == idx$21) begin
            y1$11 = d$21;
        end
        if (j2$11 == idx$21) begin
            y2$11 = d$21;
        end
        if (j0$11 == idx$22) begin
            y0$11 = d$22;
        end
        if (j1$11 == idx$22) begin
            y1$11 = d$22;
        end
        if (j2$11 == idx$22) begin
            y2$11 = d$22;
        end
        if (j0$11 == idx$23) begin
            y0$11 = d$23;
        end
        if (j1$11 == idx$23) begin
            y1$11 = d$23;
        end
        if (j2$11 == idx$23) begin
            y2$11 = d$23;
        end
        y0$12 = 32'h0;
        y1$12 = 32'h0;
        y2$12 = 32'h0;
        if (j0$12 == idx$0) begin
            y0$12 = d$0;
        end
        if (j1$12 == idx$0) begin
            y1$12 = d$0;
        end
        if (j2$12 == idx$0) begin
            y2$12 = d$0;
        end
        if (j0$12 == idx$1) begin
            y0$12 = d$1;
        end
        if (j1$12 == idx$1) begin
            y1$12 = d$1;
        end
        if (j2$12 == idx$1) begin
            y2$12 = d$1;
        end
        if (j0$12 == idx$2) begin
            y0$12 = d$2;
        end
        if (j1$12 == idx$2) begin
            y1$12 = d$2;
        end
        if (j2$12 == idx$2) begin
            y2$12 = d$2;
        end
        if (j0$12 == idx$3) begin
            y0$12 = d$3;
        end
        if (j1$12 == idx$3) begin
            y1$12 = d$3;
        end
        if (j2$12 == idx$3) begin
            y2$12 = d$3;
        end
        if (j0$12 == idx$4) begin
            y0$12 = d$4;
        end
        if (j1$12 == idx$4) begin
            y1$12 = d$4;
        end
        if (j2$12 == idx$4) begin
            y2$12 = d$4;
        end
        if (j0$12 == idx$5) begin
            y0$12 = d$5;
        end
        if (j1$12 == idx$5) begin
            y1$12 = d$5;
        end
        if (j2$12 == idx$5) begin
            y2$12 = d$5;
        end
        if (j0$12 == idx$6) begin
            y0$12 = d$6;
        end
        if (j1$12 == idx$6) begin
            y1$12 = d$6;
        end
        if (j2$12 == idx$6) begin
            y2$12 = d$6;
        end
        if (j0$12 == idx$7) begin
            y0$12 = d$7;
        end
        if (j1$12 == idx$7) begin
            y1$12 = d$7;
        end
        if (j2$12 == idx$7) begin
            y2$12 = d$7;
        end
        if (j0$12 == idx$8) begin
            y0$12 = d$8;
        end
        if (j1$12 == idx$8) begin
            y1$12 = d$8;
        end
        if (j2$12 == idx$8) begin
            y2$12 = d$8;
        end
        if (j0$12 == idx$9) begin
            y0$12 = d$9;
        end
        if (j1$12 == idx$9) begin
            y1$12 = d$9;
        end
        if (j2$12 == idx$9) begin
            y2$12 = d$9;
        end
        if (j0$12 == idx$10) begin
            y0$12 = d$10;
        end
        if (j1$12 == idx$10) begin
            y1$12 = d$10;
        end
        if (j2$12 == idx$10) begin
            y2$12 = d$10;
        end
        if (j0$12 == idx$11) begin
            y0$12 = d$11;
        end
        if (j1$12 == idx$11) begin
            y1$12 = d$11;
        end
        if (j2$12 == idx$11) begin
            y2$12 = d$11;
        end
        if (j0$12 == idx$12) begin
            y0$12 = d$12;
        end
        if (j1$12 == idx$12) begin
            y1$12 = d$12;
        end
        if (j2$12 == idx$12) begin
            y2$12 = d$12;
        end
        if (j0$12 == idx$13) begin
            y0$12 = d$13;
        end
        if (j1$12 == idx$13) begin
            y1$12 = d$13;
        end
        if (j2$12 == idx$13) begin
            y2$12 = d$13;
        end
        if (j0$12 == idx$14) begin
            y0$12 = d$14;
        end
        if (j1$12 == idx$14) begin
            y1$12 = d$14;
        end
        if (j2$12 == idx$14) begin
            y2$12 = d$14;
        end
        if (j0$12 == idx$15) begin
            y0$12 = d$15;
        end
        if (j1$12 == idx$15) begin
            y1$12 = d$15;
        end
        if (j2$12 == idx$15) begin
            y2$12 = d$15;
        end
        if (j0$12 == idx$16) begin
            y0$12 = d$16;
        end
        if (j1$12 == idx$16) begin
            y1$12 = d$16;
        end
        if (j2$12 == idx$16) begin
            y2$12 = d$16;
        end
        if (j0$12 == idx$17) begin
            y0$12 = d$17;
        end
        if (j1$12 == idx$17) begin
            y1$12 = d$17;
        end
        if (j2$12 == idx$17) begin
            y2$12 = d$17;
        end
        if (j0$12 == idx$18) begin
            y0$12 = d$18;
        end
        if (j1$12 == idx$18) begin
            y1$12 = d$18;
        end
        if (j2$12 == idx$18) begin
            y2$12 = d$18;
        end
        if (j0$12 == idx$19) begin
            y0$12 = d$19;
        end
        if (j1$12 == idx$19) begin
            y1$12 = d$19;
        end
        if (j2$12 == idx$19) begin
            y2$12 = d$19;
        end
        if (j0$12 == idx$20) begin
            y0$12 = d$20;
        end
        if (j1$12 == idx$20) begin
            y1$12 = d$20;
        end
        if (j2$12 == idx$20) begin
            y2$12 = d$20;
        end
        if (j0$12 == idx$21) begin
            y0$12 = d$21;
        end
        if (j1$12 == idx$21) begin
            y1$12 = d$21;
        end
        if (j2$12 == idx$21) begin
            y2$12 = d$21;
        end
        if (j0$12 == idx$22) begin
            y0$12 = d$22;
        end
        if (j1$12 == idx$22) begin
            y1$12 = d$22;
        end
        if (j2$12 == idx$22) begin
            y2$12 = d$22;
        end
        if (j0$12 == idx$23) begin
            y0$12 = d$23;
        end
        if (j1$12 == idx$23) begin
            y1$12 = d$23;
        end
        if (j2$12 == idx$23) begin
            y2$12 = d$23;
        end
        y0$13 = 32'h0;
        y1$13 = 32'h0;
        y2$13 = 32'h0;
        if (j0$13 == idx$0) begin
            y0$13 = d$0;
        end
        if (j1$13 == idx$0) begin
            y1$13 = d$0;
        end
        if (j2$13 == idx$0) begin
            y2$13 = d$0;
        end
        if (j0$13 == idx$1) begin
            y0$13 = d$1;
        end
        if (j1$13 == idx$1) begin
            y1$13 = d$1;
        end
        if (j2$13 == idx$1) begin
            y2$13 = d$1;
        end
        if (j0$13 == idx$2) begin
            y0$13 = d$2;
        end
        if (j1$13 == idx$2) begin
            y1$13 = d$2;
        end
        if (j2$13 == idx$2) begin
            y2$13 = d$2;
        end
        if (j0$13 == idx$3) begin
            y0$13 = d$3;
        end
        if (j1$13 == idx$3) begin
            y1$13 = d$3;
        end
        if (j2$13 == idx$3) begin
            y2$13 = d$3;
        end
        if (j0$13 == idx$4) begin
            y0$13 = d$4;
        end
        if (j1$13 == idx$4) begin
            y1$13 = d$4;
        end
        if (j2$13 == idx$4) begin
            y2$13 = d$4;
        end
        if (j0$13 == idx$5) begin
            y0$13 = d$5;
        end
        if (j1$13 == idx$5) begin
            y1$13 = d$5;
        end
        if (j2$13 == idx$5) begin
            y2$13 = d$5;
        end
        if (j0$13 == idx$6) begin
            y0$13 = d$6;
        end
        if (j1$13 == idx$6) begin
            y1$13 = d$6;
        end
        if (j2$13 == idx$6) begin
            y2$13 = d$6;
        end
        if (j0$13 == idx$7) begin
            y0$13 = d$7;
        end
        if (j1$13 == idx$7) begin
            y1$13 = d$7;
        end
        if (j2$13 == idx$7) begin
            y2$13 = d$7;
        end
        if (j0$13 == idx$8) begin
            y0$13 = d$8;
        end
        if (j1$13 == idx$8) begin
            y1$13 = d$8;
        end
        if (j2$13 == idx$8) begin
            y2$13 = d$8;
        end
        if (j0$13 == idx$9) begin
            y0$13 = d$9;
        end
        if (j1$13 == idx$9) begin
            y1$13 = d$9;
        end
        if (j2$13 == idx$9) begin
            y2$13 = d$9;
        end
        if (j0$13 == idx$10) begin
            y0$13 = d$10;
        end
        if (j1$13 == idx$10) begin
            y1$13 = d$10;
        end
        if (j2$13 == idx$10) begin
            y2$13 = d$10;
        end
        if (j0$13 == idx$11) begin
            y0$13 = d$11;
        end
        if (j1$13 == idx$11) begin
            y1$13 = d$11;
        end
        if (j2$13 == idx$11) begin
            y2$13 = d$11;
        end
        if (j0$13 == idx$12) begin
            y0$13 = d$12;
        end
        if (j1$13 == idx$12) begin
            y1$13 = d$12;
        end
        if (j2$13 == idx$12) begin
            y2$13 = d$12;
        end
        if (j0$13 == idx$13) begin
            y0$13 = d$13;
        end
        if (j1$13 == idx$13) begin
            y1$13 = d$13;
        end
        if (j2$13 == idx$13) begin
            y2$13 = d$13;
        end
        if (j0$13 == idx$14) begin
            y0$13 = d$14;
        end
        if (j1$13 == idx$14) begin
            y1$13 = d$14;
        end
        if (j2$13 == idx$14) begin
            y2$13 = d$14;
        end
        if (j0$13 == idx$15) begin
            y0$13 = d$15;
        end
        if (j1$13 == idx$15) begin
            y1$13 = d$15;
        end
        if (j2$13 == idx$15) begin
            y2$13 = d$15;
        end
        if (j0$13 == idx$16) begin
            y0$13 = d$16;
        end
        if (j1$13 == idx$16) begin
            y1$13 = d$16;
        end
        if (j2$13 == idx$16) begin
            y2$13 = d$16;
        end
        if (j0$13 == idx$17) begin
            y0$13 = d$17;
        end
        if (j1$13 == idx$17) begin
            y1$13 = d$17;
        end
        if (j2$13 == idx$17) begin
            y2$13 = d$17;
        end
        if (j0$13 == idx$18) begin
            y0$13 = d$18;
        end
        if (j1$13 == idx$18) begin
            y1$13 = d$18;
        end
        if (j2$13 == idx$18) begin
            y2$13 = d$18;
        end
        if (j0$13 == idx$19) begin
            y0$13 = d$19;
        end
        if (j1$13 == idx$19) begin
            y1$13 = d$19;
        end
        if (j2$13 == idx$19) begin
            y2$13 = d$19;
        end
        if (j0$13 == idx$20) begin
            y0$13 = d$20;
        end
        if (j1$13 == idx$20) begin
            y1$13 = d$20;
        end
        if (j2$13 == idx$20) begin
            y2$13 = d$20;
        end
        if (j0$13 == idx$21) begin
            y0$13 = d$21;
        end
        if (j1$13 == idx$21) begin
            y1$13 = d$21;
        end
        if (j2$13 == idx$21) begin
            y2$13 = d$21;
        end
        if (j0$13 == idx$22) begin
            y0$13 = d$22;
        end
        if (j1$13 == idx$22) begin
            y1$13 = d$22;
        end
        if (j2$13 == idx$22) begin
            y2$13 = d$22;
        end
        if (j0$13 == idx$23) begin
            y0$13 = d$23;
        end
        if (j1$13 == idx$23) begin
            y1$13 = d$23;
        end
        if (j2$13 == idx$23) begin
            y2$13 = d$23;
        end
        y0$14 = 32'h0;
        y1$14 = 32'h0;
        y2$14 = 32'h0;
        if (j0$14 == idx$0) begin
            y0$14 = d$0;
        end
        if (j1$14 == idx$0) begin
            y1$14 = d$0;
        end
        if (j2$14 == idx$0) begin
            y2$14 = d$0;
        end
        if (j0$14 == idx$1) begin
            y0$14 = d$1;
        end
        if (j1$14 == idx$1) begin
            y1$14 = d$1;
        end
        if (j2$14 == idx$1) begin
            y2$14 = d$1;
        end
        if (j0$14 == idx$2) begin
            y0$14 = d$2;
        end
        if (j1$14 == idx$2) begin
            y1$14 = d$2;
        end
        if (j2$14 == idx$2) begin
            y2$14 = d$2;
        end
        if (j0$14 == idx$3) begin
            y0$14 = d$3;
        end
        if (j1$14 == idx$3) begin
            y1$14 = d$3;
        end
        if (j2$14 == idx$3) begin
            y2$14 = d$3;
        end
        if (j0$14 == idx$4) begin
            y0$14 = d$4;
        end
        if (j1$14 == idx$4) begin
            y1$14 = d$4;
        end
        if (j2$14 == idx$4) begin
            y2$14 = d$4;
        end
        if (j0$14 == idx$5) begin
            y0$14 = d$5;
        end
        if (j1$14 == idx$5) begin
            y1$14 = d$5;
        end
        if (j2$14 == idx$5) begin
            y2$14 = d$5;
        end
        if (j0$14 == idx$6) begin
            y0$14 = d$6;
        end
        if (j1$14 == idx$6) begin
            y1$14 = d$6;
        end
        if (j2$14 == idx$6) begin
            y2$14 = d$6;
        end
        if (j0$14 == idx$7) begin
            y0$14 = d$7;
        end
        if (j1$14 == idx$7) begin
            y1$14 = d$7;
        end
        if (j2$14 == idx$7) begin
            y2$14 = d$7;
        end
        if (j0$14 == idx$8) begin
            y0$14 = d$8;
        end
        if (j1$14 == idx$8) begin
            y1$14 = d$8;
        end
        if (j2$14 == idx$8) begin
            y2$14 = d$8;
        end
        if (j0$14 == idx$9) begin
            y0$14 = d$9;
        end
        if (j1$14 == idx$9) begin
            y1$14 = d$9;
        end
        if (j2$14 == idx$9) begin
            y2$14 = d$9;
        end
        if (j0$14 == idx$10) begin
            y0$14 = d$10;
        end
        if (j1$14 == idx$10) begin
            y1$14 = d$10;
        end
        if (j2$14 == idx$10) begin
            y2$14 = d$10;
        end
        if (j0$14 == idx$11) begin
            y0$14 = d$11;
        end
        if (j1$14 == idx$11) begin
            y1$14 = d$11;
        end
        if (j2$14 == idx$11) begin
            y2$14 = d$11;
        end
        if (j0$14 == idx$12) begin
            y0$14 = d$12;
        end
        if (j1$14 == idx$12) begin
            y1$14 = d$12;
        end
        if (j2$14 == idx$12) begin
            y2$14 = d$12;
        end
        if (j0$14 == idx$13) begin
            y0$14 = d$13;
        end
        if (j1$14 == idx$13) begin
            y1$14 = d$13;
        end
        if (j2$14 == idx$13) begin
            y2$14 = d$13;
        end
        if (j0$14 == idx$14) begin
            y0$14 = d$14;
        end
        if (j1$14 == idx$14) begin
            y1$14 = d$14;
        end
        if (j2$14 == idx$14) begin
            y2$14 = d$14;
        end
        if (j0$14 == idx$15) begin
            y0$14 = d$15;
        end
        if (j1$14 == idx$15) begin
            y1$14 = d$15;
        end
        if (j2$14 == idx$15) begin
            y2$14 = d$15;
        end
        if (j0$14 == idx$16) begin
            y0$14 = d$16;
        end
        if (j1$14 == idx$16) begin
            y1$14 = d$16;
        end
        if (j2$14 == idx$16) begin
            y2$14 = d$16;
        end
        if (j0$14 == idx$17) begin
            y0$14 = d$17;
        end
        if (j1$14 == idx$17) begin
            y1$14 = d$17;
        end
        if (j2$14 == idx$17) begin
            y2$14 = d$17;
        end
        if (j0$14 == idx$18) begin
            y0$14 = d$18;
        end
        if (j1$14 == idx$18) begin
            y1$14 = d$18;
        end
        if (j2$14 == idx$18) begin
            y2$14 = d$18;
        end
        if (j0$14 == idx$19) begin
            y0$14 = d$19;
        end
        if (j1$14 == idx$19) begin
            y1$14 = d$19;
        end
        if (j2$14 == idx$19) begin
            y2$14 = d$19;
        end
        if (j0$14 == idx$20) begin
            y0$14 = d$20;
        end
        if (j1$14 == idx$20) begin
            y1$14 = d$20;
        end
        if (j2$14 == idx$20) begin
            y2$14 = d$20;
        end
        if (j0$14 == idx$21) begin
            y0$14 = d$21;
        end
        if (j1$14 == idx$21) begin
            y1$14 = d$21;
        end
        if (j2$14 == idx$21) begin
            y2$14 = d$21;
        end
        if (j0$14 == idx$22) begin
            y0$14 = d$22;
        end
        if (j1$14 == idx$22) begin
            y1$14 = d$22;
        end
        if (j2$14 == idx$22) begin
            y2$14 = d$22;
        end
        if (j0$14 == idx$23) begin
            y0$14 = d$23;
        end
        if (j1$14 == idx$23) begin
            y1$14 = d$23;
        end
        if (j2$14 == idx$23) begin
            y2$14 = d$23;
        end
        y0$15 = 32'h0;
        y1$15 = 32'h0;
        y2$15 = 32'h0;
        if (j0$15 == idx$0) begin
            y0$15 = d$0;
        end
        if (j1$15 == idx$0) begin
            y1$15 = d$0;
        end
        if (j2$15 == idx$0) begin
            y2$15 = d$0;
        end
        if (j0$15 == idx$1) begin
            y0$15 = d$1;
        end
        if (j1$15 == idx$1) begin
            y1$15 = d$1;
        end
        if (j2$15 == idx$1) begin
            y2$15 = d$1;
        end
        if (j0$15 == idx$2) begin
            y0$15 = d$2;
        end
        if (j1$15 == idx$2) begin
            y1$15 = d$2;
        end
        if (j2$15 == idx$2) begin
            y2$15 = d$2;
        end
        if (j0$15 == idx$3) begin
            y0$15 = d$3;
        end
        if (j1$15 == idx$3) begin
            y1$15 = d$3;
        end
        if (j2$15 == idx$3) begin
            y2$15 = d$3;
        end
        if (j0$15 == idx$4) begin
            y0$15 = d$4;
        end
        if (j1$15 == idx$4) begin
            y1$15 = d$4;
        end
        if (j2$15 == idx$4) begin
            y2$15 = d$4;
        end
        if (j0$15 == idx$5) begin
            y0$15 = d$5;
        end
        if (j1$15 == idx$5) begin
            y1$15 = d$5;
        end
        if (j2$15 == idx$5) begin
            y2$15 = d$5;
        end
        if (j0$15 == idx$6) begin
            y0$15 = d$6;
        end
        if (j1$15 == idx$6) begin
            y1$15 = d$6;
        end
        if (j2$15 == idx$6) begin
            y2$15 = d$6;
        end
        if (j0$15 == idx$7) begin
            y0$15 = d$7;
        end
        if (j1$15 == idx$7) begin
            y1$15 = d$7;
        end
        if (j2$15 == idx$7) begin
            y2$15 = d$7;
        end
        if (j0$15 == idx$8) begin
            y0$15 = d$8;
        end
        if (j1$15 == idx$8) begin
            y1$15 = d$8;
        end
        if (j2$15 == idx$8) begin
            y2$15 = d$8;
        end
        if (j0$15 == idx$9) begin
            y0$15 = d$9;
        end
        if (j1$15 == idx$9) begin
            y1$15 = d$9;
        end
        if (j2$15 == idx$9) begin
            y2$15 = d$9;
        end
        if (j0$15 == idx$10) begin
            y0$15 = d$10;
        end
        if (j1$15 == idx$10) begin
            y1$15 = d$10;
        end
        if (j2$15 == idx$10) begin
            y2$15 = d$10;
        end
        if (j0$15 == idx$11) begin
            y0$15 = d$11;
        end
        if (j1$15 == idx$11) begin
            y1$15 = d$11;
        end
        if (j2$15 == idx$11) begin
            y2$15 = d$11;
        end
        if (j0$15 == idx$12) begin
            y0$15 = d$12;
        end
        if (j1$15 == idx$12) begin
            y1$15 = d$12;
        end
        if (j2$15 == idx$12) begin
            y2$15 = d$12;
        end
        if (j0$15 == idx$13) begin
            y0$15 = d$13;
        end
        if (j1$15 == idx$13) begin
            y1$15 = d$13;
        end
        if (j2$15 == idx$13) begin
            y2$15 = d$13;
        end
        if (j0$15 == idx$14) begin
            y0$15 = d$14;
        end
        if (j1$15 == idx$14) begin
            y1$15 = d$14;
        end
        if (j2$15 == idx$14) begin
            y2$15 = d$14;
        end
        if (j0$15 == idx$15) begin
            y0$15 = d$15;
        end
        if (j1$15 == idx$15) begin
            y1$15 = d$15;
        end
        if (j2$15 == idx$15) begin
            y2$15 = d$15;
        end
        if (j0$15 == idx$16) begin
            y0$15 = d$16;
        end
        if (j1$15 == idx$16) begin
            y1$15 = d$16;
        end
        if (j2$15 == idx$16) begin
            y2$15 = d$16;
        end
        if (j0$15 == idx$17) begin
            y0$15 = d$17;
        end
        if (j1$15 == idx$17) begin
            y1$15 = d$17;
        end
        if (j2$15 == idx$17) begin
            y2$15 = d$17;
        end
        if (j0$15 == idx$18) begin
            y0$15 = d$18;
        end
        if (j1$15 == idx$18) begin
            y1$15 = d$18;
        end
        if (j2$15 == idx$18) begin
            y2$15 = d$18;
        end
        if (j0$15 == idx$19) begin
            y0$15 = d$19;
        end
        if (j1$15 == idx$19) begin
            y1$15 = d$19;
        end
        if (j2$15 == idx$19) begin
            y2$15 = d$19;
        end
        if (j0$15 == idx$20) begin
            y0$15 = d$20;
        end
        if (j1$15 == idx$20) begin
            y1$15 = d$20;
        end
        if (j2$15 == idx$20) begin
            y2$15 = d$20;
        end
        if (j0$15 == idx$21) begin
            y0$15 = d$21;
        end
        if (j1$15 == idx$21) begin
            y1$15 = d$21;
        end
        if (j2$15 == idx$21) begin
            y2$15 = d$21;
        end
        if (j0$15 == idx$22) begin
            y0$15 = d$22;
        end
        if (j1$15 == idx$22) begin
            y1$15 = d$22;
        end
        if (j2$15 == idx$22) begin
            y2$15 = d$22;
        end
        if (j0$15 == idx$23) begin
            y0$15 = d$23;
        end
        if (j1$15 == idx$23) begin
            y1$15 = d$23;
        end
        if (j2$15 == idx$23) begin
            y2$15 = d$23;
        end
        y0$16 = 32'h0;
        y1$16 = 32'h0;
        y2$16 = 32'h0;
        if (j0$16 == idx$0) begin
            y0$16 = d$0;
        end
        if (j1$16 == idx$0) begin
            y1$16 = d$0;
        end
        if (j2$16 == idx$0) begin
            y2$16 = d$0;
        end
        if (j0$16 == idx$1) begin
            y0$16 = d$1;
        end
        if (j1$16 == idx$1) begin
            y1$16 = d$1;
        end
        if (j2$16 == idx$1) begin
            y2$16 = d$1;
        end
        if (j0$16 == idx$2) begin
            y0$16 = d$2;
        end
        if (j1$16 == idx$2) begin
            y1$16 = d$2;
        end
        if (j2$16 == idx$2) begin
            y2$16 = d$2;
        end
        if (j0$16 == idx$3) begin
            y0$16 = d$3;
        end
        if (j1$16 == idx$3) begin
            y1$16 = d$3;
        end
        if (j2$16 == idx$3) begin
            y2$16 = d$3;
        end
        if (j0$16 == idx$4) begin
            y0$16 = d$4;
        end
        if (j1$16 == idx$4) begin
            y1$16 = d$4;
        end
        if (j2$16 == idx$4) begin
            y2$16 = d$4;
        end
        if (j0$16 == idx$5) begin
            y0$16 = d$5;
        end
        if (j1$16 == idx$5) begin
            y1$16 = d$5;
        end
        if (j2$16 == idx$5) begin
            y2$16 = d$5;
        end
        if (j0$16 == idx$6) begin
            y0$16 = d$6;
        end
        if (j1$16 == idx$6) begin
            y1$16 = d$6;
        end
        if (j2$16 == idx$6) begin
            y2$16 = d$6;
        end
        if (j0$16 == idx$7) begin
            y0$16 = d$7;
        end
        if (j1$16 == idx$7) begin
            y1$16 = d$7;
        end
        if (j2$16 == idx$7) begin
            y2$16 = d$7;
        end
        if (j0$16 == idx$8) begin
            y0$16 = d$8;
        end
        if (j1$16 == idx$8) begin
            y1$16 = d$8;
        end
        if (j2$16 == idx$8) begin
            y2$16 = d$8;
        end
        if (j0$16 == idx$9) begin
            y0$16 = d$9;
        end
        if (j1$16 == idx$9) begin
            y1$16 = d$9;
        end
        if (j2$16 == idx$9) begin
            y2$16 = d$9;
        end
        if (j0$16 == idx$10) begin
            y0$16 = d$10;
        end
        if (j1$16 == idx$10) begin
            y1$16 = d$10;
        end
        if (j2$16 == idx$10) begin
            y2$16 = d$10;
        end
        if (j0$16 == idx$11) begin
            y0$16 = d$11;
        end
        if (j1$16 == idx$11) begin
            y1$16 = d$11;
        end
        if (j2$16 == idx$11) begin
            y2$16 = d$11;
        end
        if (j0$16 == idx$12) begin
            y0$16 = d$12;
        end
        if (j1$16 == idx$12) begin
            y1$16 = d$12;
        end
        if (j2$16 == idx$12) begin
            y2$16 = d$12;
        end
        if (j0$16 == idx$13) begin
            y0$16 = d$13;
        end
        if (j1$16 == idx$13) begin
            y1$16 = d$13;
        end
        if (j2$16 == idx$13) begin
            y2$16 = d$13;
        end
        if (j0$16 == idx$14) begin
            y0$16 = d$14;
        end
        if (j1$16 == idx$14) begin
            y1$16 = d$14;
        end
        if (j2$16 == idx$14) begin
            y2$16 = d$14;
        end
        if (j0$16 == idx$15) begin
            y0$16 = d$15;
        end
        if (j1$16 == idx$15) begin
            y1$16 = d$15;
        end
        if (j2$16 == idx$15) begin
            y2$16 = d$15;
        end
        if (j0$16 == idx$16) begin
            y0$16 = d$16;
        end
        if (j1$16 == idx$16) begin
            y1$16 = d$16;
        end
        if (j2$16 == idx$16) begin
            y2$16 = d$16;
        end
        if (j0$16 == idx$17) begin
            y0$16 = d$17;
        end
        if (j1$16 == idx$17) begin
            y1$16 = d$17;
        end
        if (j2$16 == idx$17) begin
            y2$16 = d$17;
        end
        if (j0$16 == idx$18) begin
            y0$16 = d$18;
        end
        if (j1$16 == idx$18) begin
            y1$16 = d$18;
        end
        if (j2$16 == idx$18) begin
            y2$16 = d$18;
        end
        if (j0$16 == idx$19) begin
            y0$16 = d$19;
        end
        if (j1$16 == idx$19) begin
            y1$16 = d$19;
        end
        if (j2$16 == idx$19) begin
            y2$16 = d$19;
        end
        if (j0$16 == idx$20) begin
            y0$16 = d$20;
        end
        if (j1$16 == idx$20) begin
            y1$16 = d$20;
        end
        if (j2$16 == idx$20) begin
            y2$16 = d$20;
        end
        if (j0$16 == idx$21) begin
            y0$16 = d$21;
        end
        if (j1$16 == idx$21) begin
            y1$16 = d$21;
        end
        if (j2$16 == idx$21) begin
            y2$16 = d$21;
        end
        if (j0$16 == idx$22) begin
            y0$16 = d$22;
        end
        if (j1$16 == idx$22) begin
            y1$16 = d$22;
        end
        if (j2$16 == idx$22) begin
            y2$16 = d$22;
        end
        if (j0$16 == idx$23) begin
            y0$16 = d$23;
        end
        if (j1$16 == idx$23) begin
            y1$16 = d$23;
        end
        if (j2$16 == idx$23) begin
            y2$16 = d$23;
        end
        y0$17 = 32'h0;
        y1$17 = 32'h0;
        y2$17 = 32'h0;
        if (j0$17 == idx$0) begin
            y0$17 = d$0;
        end
        if (j1$17 == idx$0) begin
            y1$17 = d$0;
        end
        if (j2$17 == idx$0) begin
            y2$17 = d$0;
        end
        if (j0$17 == idx$1) begin
            y0$17 = d$1;
        end
        if (j1$17 == idx$1) begin
            y1$17 = d$1;
        end
        if (j2$17 == idx$1) begin
            y2$17 = d$1;
        end
        if (j0$17 == idx$2) begin
            y0$17 = d$2;
        end
        if (j1$17 == idx$2) begin
            y1$17 = d$2;
        end
        if (j2$17 == idx$2) begin
            y2$17 = d$2;
        end
        if (j0$17 == idx$3) begin
            y0$17 = d$3;
        end
        if (j1$17 == idx$3) begin
            y1$17 = d$3;
        end
        if (j2$17 == idx$3) begin
            y2$17 = d$3;
        end
        if (j0$17 == idx$4) begin
            y0$17 = d$4;
        end
        if (j1$17 == idx$4) begin
            y1$17 = d$4;
        end
        if (j2$17 == idx$4) begin
            y2$17 = d$4;
        end
        if (j0$17 == idx$5) begin
            y0$17 = d$5;
        end
        if (j1$17 == idx$5) begin
            y1$17 = d$5;
        end
        if (j2$17 == idx$5) begin
            y2$17 = d$5;
        end
        if (j0$17 == idx$6) begin
            y0$17 = d$6;
        end
        if (j1$17 == idx$6) begin
            y1$17 = d$6;
        end
        if (j2$17 == idx$6) begin
            y2$17 = d$6;
        end
        if (j0$17 == idx$7) begin
            y0$17 = d$7;
        end
        if (j1$17 == idx$7) begin
            y1$17 = d$7;
        end
        if (j2$17 == idx$7) begin
            y2$17 = d$7;
        end
        if (j0$17 == idx$8) begin
            y0$17 = d$8;
        end
        if (j1$17 == idx$8) begin
            y1$17 = d$8;
        end
        if (j2$17 == idx$8) begin
            y2$17 = d$8;
        end
        if (j0$17 == idx$9) begin
            y0$17 = d$9;
        end
        if (j1$17 == idx$9) begin
            y1$17 = d$9;
        end
        if (j2$17 == idx$9) begin
            y2$17 = d$9;
        end
        if (j0$17 == idx$10) begin
            y0$17 = d$10;
        end
        if (j1$17 == idx$10) begin
            y1$17 = d$10;
        end
        if (j2$17 == idx$10) begin
            y2$17 = d$10;
        end
        if (j0$17 == idx$11) begin
            y0$17 = d$11;
        end
        if (j1$17 == idx$11) begin
            y1$17 = d$11;
        end
        if (j2$17 == idx$11) begin
            y2$17 = d$11;
        end
        if (j0$17 == idx$12) begin
            y0$17 = d$12;
        end
        if (j1$17 == idx$12) begin
            y1$17 = d$12;
        end
        if (j2$17 == idx$12) begin
            y2$17 = d$12;
        end
        if (j0$17 == idx$13) begin
            y0$17 = d$13;
        end
        if (j1$17 == idx$13) begin
            y1$17 = d$13;
        end
        if (j2$17 == idx$13) begin
            y2$17 = d$13;
        end
        if (j0$17 == idx$14) begin
            y0$17 = d$14;
        end
        if (j1$17 == idx$14) begin
            y1$17 = d$14;
        end
        if (j2$17 == idx$14) begin
            y2$17 = d$14;
        end
        if (j0$17 == idx$15) begin
            y0$17 = d$15;
        end
        if (j1$17 == idx$15) begin
            y1$17 = d$15;
        end
        if (j2$17 == idx$15) begin
            y2$17 = d$15;
        end
        if (j0$17 == idx$16) begin
            y0$17 = d$16;
        end
        if (j1$17 == idx$16) begin
            y1$17 = d$16;
        end
        if (j2$17 == idx$16) begin
            y2$17 = d$16;
        end
        if (j0$17 == idx$17) begin
            y0$17 = d$17;
        end
        if (j1$17 == idx$17) begin
            y1$17 = d$17;
        end
        if (j2$17 == idx$17) begin
            y2$17 = d$17;
        end
        if (j0$17 == idx$18) begin
            y0$17 = d$18;
        end
        if (j1$17 == idx$18) begin
            y1$17 = d$18;
        end
        if (j2$17 == idx$18) begin
            y2$17 = d$18;
        end
        if (j0$17 == idx$19) begin
            y0$17 = d$19;
        end
        if (j1$17 == idx$19) begin
            y1$17 = d$19;
        end
        if (j2$17 == idx$19) begin
            y2$17 = d$19;
        end
        if (j0$17 == idx$20) begin
            y0$17 = d$20;
        end
        if (j1$17 == idx$20) begin
            y1$17 = d$20;
        end
        if (j2$17 == idx$20) begin
            y2$17 = d$20;
        end
        if (j0$17 == idx$21) begin
            y0$17 = d$21;
        end
        if (j1$17 == idx$21) begin
            y1$17 = d$21;
        end
        if (j2$17 == idx$21) begin
            y2$17 = d$21;
        end
        if (j0$17 == idx$22) begin
            y0$17 = d$22;
        end
        if (j1$17 == idx$22) begin
            y1$17 = d$22;
        end
        if (j2$17 == idx$22) begin
            y2$17 = d$22;
        end
        if (j0$17 == idx$23) begin
            y0$17 = d$23;
        end
        if (j1$17 == idx$23) begin
            y1$17 = d$23;
        end
        if (j2$17 == idx$23) begin
            y2$17 = d$23;
        end
        y0$18 = 32'h0;
        y1$18 = 32'h0;
        y2$18 = 32'h0;
        if (j0$18 == idx$0) begin
            y0$18 = d$0;
        end
        if (j1$18 == idx$0) begin
            y1$18 = d$0;
        end
        if (j2$18 == idx$0) begin
            y2$18 = d$0;
        end
        if (j0$18 == idx$1) begin
            y0$18 = d$1;
        end
        if (j1$18 == idx$1) begin
            y1$18 = d$1;
        end
        if (j2$18 == idx$1) begin
            y2$18 = d$1;
        end
        if (j0$18 == idx$2) begin
            y0$18 = d$2;
        end
        if (j1$18 == idx$2) begin
            y1$18 = d$2;
        end
        if (j2$18 == idx$2) begin
            y2$18 = d$2;
        end
        if (j0$18 == idx$3) begin
            y0$18 = d$3;
        end
        if (j1$18 == idx$3) begin
            y1$18 = d$3;
        end
        if (j2$18 == idx$3) begin
            y2$18 = d$3;
        end
        if (j0$18 == idx$4) begin
            y0$18 = d$4;
        end
        if (j1$18 == idx$4) begin
            y1$18 = d$4;
        end
        if (j2$18 == idx$4) begin
            y2$18 = d$4;
        end
        if (j0$18 == idx$5) begin
            y0$18 = d$5;
        end
        if (j1$18 == idx$5) begin
            y1$18 = d$5;
        end
        if (j2$18 == idx$5) begin
            y2$18 = d$5;
        end
        if (j0$18 == idx$6) begin
            y0$18 = d$6;
        end
        if (j1$18 == idx$6) begin
            y1$18 = d$6;
        end
        if (j2$18 == idx$6) begin
            y2$18 = d$6;
        end
        if (j0$18 == idx$7) begin
            y0$18 = d$7;
        end
        if (j1$18 == idx$7) begin
            y1$18 = d$7;
        end
        if (j2$18 == idx$7) begin
            y2$18 = d$7;
        end
        if (j0$18 == idx$8) begin
            y0$18 = d$8;
        end
        if (j1$18 == idx$8) begin
            y1$18 = d$8;
        end
        if (j2$18 == idx$8) begin
            y2$18 = d$8;
        end
        if (j0$18 == idx$9) begin
            y0$18 = d$9;
        end
        if (j1$18 == idx$9) begin
            y1$18 = d$9;
        end
        if (j2$18 == idx$9) begin
            y2$18 = d$9;
        end
        if (j0$18 == idx$10) begin
            y0$18 = d$10;
        end
        if (j1$18 == idx$10) begin
            y1$18 = d$10;
        end
        if (j2$18 == idx$10) begin
            y2$18 = d$10;
        end
        if (j0$18 == idx$11) begin
            y0$18 = d$11;
        end
        if (j1$18 == idx$11) begin
            y1$18 = d$11;
        end
        if (j2$18 == idx$11) begin
            y2$18 = d$11;
        end
        if (j0$18 == idx$12) begin
            y0$18 = d$12;
        end
        if (j1$18 == idx$12) begin
            y1$18 = d$12;
        end
        if (j2$18 == idx$12) begin
            y2$18 = d$12;
        end
        if (j0$18 == idx$13) begin
            y0$18 = d$13;
        end
        if (j1$18 == idx$13) begin
            y1$18 = d$13;
        end
        if (j2$18 == idx$13) begin
            y2$18 = d$13;
        end
        if (j0$18 == idx$14) begin
            y0$18 = d$14;
        end
        if (j1$18 == idx$14) begin
            y1$18 = d$14;
        end
        if (j2$18 == idx$14) begin
            y2$18 = d$14;
        end
        if (j0$18 == idx$15) begin
            y0$18 = d$15;
        end
        if (j1$18 == idx$15) begin
            y1$18 = d$15;
        end
        if (j2$18 == idx$15) begin
            y2$18 = d$15;
        end
        if (j0$18 == idx$16) begin
            y0$18 = d$16;
        end
        if (j1$18 == idx$16) begin
            y1$18 = d$16;
        end
        if (j2$18 == idx$16) begin
            y2$18 = d$16;
        end
        if (j0$18 == idx$17) begin
            y0$18 = d$17;
        end
        if (j1$18 == idx$17) begin
            y1$18 = d$17;
        end
        if (j2$18 == idx$17) begin
            y2$18 = d$17;
        end
        if (j0$18 == idx$18) begin
            y0$18 = d$18;
        end
        if (j1$18 == idx$18) begin
            y1$18 = d$18;
        end
        if (j2$18 == idx$18) begin
            y2$18 = d$18;
        end
        if (j0$18 == idx$19) begin
            y0$18 = d$19;
        end
        if (j1$18 == idx$19) begin
            y1$18 = d$19;
        end
        if (j2$18 == idx$19) begin
            y2$18 = d$19;
        end
        if (j0$18 == idx$20) begin
            y0$18 = d$20;
        end
        if (j1$18 == idx$20) begin
            y1$18 = d$20;
        end
        if (j2$18 == idx$20) begin
            y2$18 = d$20;
        end
        if (j0$18 == idx$21) begin
            y0$18 = d$21;
        end
        if (j1$18 == idx$21) begin
            y1$18 = d$21;
        end
        if (j2$18 == idx$21) begin
            y2$18 = d$21;
        end
        if (j0$18 == idx$22) begin
            y0$18 = d$22;
        end
        if (j1$18 == idx$22) begin
            y1$18 = d$22;
        end
        if (j2$18 == idx$22) begin
            y2$18 = d$22;
        end
        if (j0$18 == idx$23) begin
            y0$18 = d$23;
        end
        if (j1$18 == idx$23) begin
            y1$18 = d$23;
        end
        if (j2$18 == idx$23) begin
            y2$18 = d$23;
        end
        y0$19 = 32'h0;
        y1$19 = 32'h0;
        y2$19 = 32'h0;
        if (j0$19 == idx$0) begin
            y0$19 = d$0;
        end
        if (j1$19 == idx$0) begin
            y1$19 = d$0;
        end
        if (j2$19 == idx$0) begin
            y2$19 = d$0;
        end
        if (j0$19 == idx$1) begin
            y0$19 = d$1;
        end
        if (j1$19 == idx$1) begin
            y1$19 = d$1;
        end
        if (j2$19 == idx$1) begin
            y2$19 = d$1;
        end
        if (j0$19 == idx$2) begin
            y0$19 = d$2;
        end
        if (j1$19 == idx$2) begin
            y1$19 = d$2;
        end
        if (j2$19 == idx$2) begin
            y2$19 = d$2;
        end
        if (j0$19 == idx$3) begin
            y0$19 = d$3;
        end
        if (j1$19 == idx$3) begin
            y1$19 = d$3;
        end
        if (j2$19 == idx$3) begin
            y2$19 = d$3;
        end
        if (j0$19 == idx$4) begin
            y0$19 = d$4;
        end
        if (j1$19 == idx$4) begin
            y1$19 = d$4;
        end
        if (j2$19 == idx$4) begin
            y2$19 = d$4;
        end
        if (j0$19 == idx$5) begin
            y0$19 = d$5;
        end
        if (j1$19 == idx$5) begin
            y1$19 = d$5;
        end
        if (j2$19 == idx$5) begin
            y2$19 = d$5;
        end
        if (j0$19 == idx$6) begin
            y0$19 = d$6;
        end
        if (j1$19 == idx$6) begin
            y1$19 = d$6;
        end
        if (j2$19 == idx$6) begin
            y2$19 = d$6;
        end
        if (j0$19 == idx$7) begin
            y0$19 = d$7;
        end
        if (j1$19 == idx$7) begin
            y1$19 = d$7;
        end
        if (j2$19 == idx$7) begin
            y2$19 = d$7;
        end
        if (j0$19 == idx$8) begin
            y0$19 = d$8;
        end
        if (j1$19 == idx$8) begin
            y1$19 = d$8;
        end
        if (j2$19 == idx$8) begin
            y2$19 = d$8;
        end
        if (j0$19 == idx$9) begin
            y0$19 = d$9;
        end
        if (j1$19 == idx$9) begin
            y1$19 = d$9;
        end
        if (j2$19 == idx$9) begin
            y2$19 = d$9;
        end
        if (j0$19 == idx$10) begin
            y0$19 = d$10;
        end
        if (j1$19 == idx$10) begin
            y1$19 = d$10;
        end
        if (j2$19 == idx$10) begin
            y2$19 = d$10;
        end
        if (j0$19 == idx$11) begin
            y0$19 = d$11;
        end
        if (j1$19 == idx$11) begin
            y1$19 = d$11;
        end
        if (j2$19 == idx$11) begin
            y2$19 = d$11;
        end
        if (j0$19 == idx$12) begin
            y0$19 = d$12;
        end
        if (j1$19 == idx$12) begin
            y1$19 = d$12;
        end
        if (j2$19 == idx$12) begin
            y2$19 = d$12;
        end
        if (j0$19 == idx$13) begin
            y0$19 = d$13;
        end
        if (j1$19 == idx$13) begin
            y1$19 = d$13;
        end
        if (j2$19 == idx$13) begin
            y2$19 = d$13;
        end
        if (j0$19 == idx$14) begin
            y0$19 = d$14;
        end
        if (j1$19 == idx$14) begin
            y1$19 = d$14;
        end
        if (j2$19 == idx$14) begin
            y2$19 = d$14;
        end
        if (j0$19 == idx$15) begin
            y0$19 = d$15;
        end
        if (j1$19 == idx$15) begin
            y1$19 = d$15;
        end
        if (j2$19 == idx$15) begin
            y2$19 = d$15;
        end
        if (j0$19 == idx$16) begin
            y0$19 = d$16;
        end
        if (j1$19 == idx$16) begin
            y1$19 = d$16;
        end
        if (j2$19 == idx$16) begin
            y2$19 = d$16;
        end
        if (j0$19 == idx$17) begin
            y0$19 = d$17;
        end
        if (j1$19 == idx$17) begin
            y1$19 = d$17;
        end
        if (j2$19 == idx$17) begin
            y2$19 = d$17;
        end
        if (j0$19 == idx$18) begin
            y0$19 = d$18;
        end
        if (j1$19 == idx$18) begin
            y1$19 = d$18;
        end
        if (j2$19 == idx$18) begin
            y2$19 = d$18;
        end
        if (j0$19 == idx$19) begin
            y0$19 = d$19;
        end
        if (j1$19 == idx$19) begin
            y1$19 = d$19;
        end
        if (j2$19 == idx$19) begin
            y2$19 = d$19;
        end
        if (j0$19 == idx$20) begin
            y0$19 = d$20;
        end
        if (j1$19 == idx$20) begin
            y1$19 = d$20;
        end
        if (j2$19 == idx$20) begin
            y2$19 = d$20;
        end
        if (j0$19 == idx$21) begin
            y0$19 = d$21;
        end
        if (j1$19 == idx$21) begin
            y1$19 = d$21;
        end
        if (j2$19 == idx$21) begin
            y2$19 = d$21;
        end
        if (j0$19 == idx$22) begin
            y0$19 = d$22;
        end
        if (j1$19 == idx$22) begin
            y1$19 = d$22;
        end
        if (j2$19 == idx$22) begin
            y2$19 = d$22;
        end
        if (j0$19 == idx$23) begin
            y0$19 = d$23;
        end
        if (j1$19 == idx$23) begin
            y1$19 = d$23;
        end
        if (j2$19 == idx$23) begin
            y2$19 = d$23;
        end
        y0$20 = 32'h0;
        y1$20 = 32'h0;
        y2$20 = 32'h0;
        if (j0$20 == idx$0) begin
            y0$20 = d$0;
        end
        if (j1$20 == idx$0) begin
            y1$20 = d$0;
        end
        if (j2$20 == idx$0) begin
            y2$20 = d$0;
        end
        if (j0$20 == idx$1) begin
            y0$20 = d$1;
        end
        if (j1$20 == idx$1) begin
            y1$20 = d$1;
        end
        if (j2$20 == idx$1) begin
            y2$20 = d$1;
        end
        if (j0$20 == idx$2) begin
            y0$20 = d$2;
        end
        if (j1$20 == idx$2) begin
            y1$20 = d$2;
        end
        if (j2$20 == idx$2) begin
            y2$20 = d$2;
        end
        if (j0$20 == idx$3) begin
            y0$20 = d$3;
        end
        if (j1$20 == idx$3) begin
            y1$20 = d$3;
        end
        if (j2$20 == idx$3) begin
            y2$20 = d$3;
        end
        if (j0$20 == idx$4) begin
            y0$20 = d$4;
        end
        if (j1$20 == idx$4) begin
            y1$20 = d$4;
        end
        if (j2$20 == idx$4) begin
            y2$20 = d$4;
        end
        if (j0$20 == idx$5) begin
            y0$20 = d$5;
        end
        if (j1$20 == idx$5) begin
            y1$20 = d$5;
        end
        if (j2$20 == idx$5) begin
            y2$20 = d$5;
        end
        if (j0$20 == idx$6) begin
            y0$20 = d$6;
        end
        if (j1$20 == idx$6) begin
            y1$20 = d$6;
        end
        if (j2$20 == idx$6) begin
            y2$20 = d$6;
        end
        if (j0$20 == idx$7) begin
            y0$20 = d$7;
        end
        if (j1$20 == idx$7) begin
            y1$20 = d$7;
        end
        if (j2$20 == idx$7) begin
            y2$20 = d$7;
        end
        if (j0$20 == idx$8) begin
            y0$20 = d$8;
        end
        if (j1$20 == idx$8) begin
            y1$20 = d$8;
        end
        if (j2$20 == idx$8) begin
            y2$20 = d$8;
        end
        if (j0$20 == idx$9) begin
            y0$20 = d$9;
        end
        if (j1$20 == idx$9) begin
            y1$20 = d$9;
        end
        if (j2$20 == idx$9) begin
            y2$20 = d$9;
        end
        if (j0$20 == idx$10) begin
            y0$20 = d$10;
        end
        if (j1$20 == idx$10) begin
            y1$20 = d$10;
        end
        if (j2$20 == idx$10) begin
            y2$20 = d$10;
        end
        if (j0$20 == idx$11) begin
            y0$20 = d$11;
        end
        if (j1$20 == idx$11) begin
            y1$20 = d$11;
        end
        if (j2$20 == idx$11) begin
            y2$20 = d$11;
        end
        if (j0$20 == idx$12) begin
            y0$20 = d$12;
        end
        if (j1$20 == idx$12) begin
            y1$20 = d$12;
        end
        if (j2$20 == idx$12) begin
            y2$20 = d$12;
        end
        if (j0$20 == idx$13) begin
            y0$20 = d$13;
        end
        if (j1$20 == idx$13) begin
            y1$20 = d$13;
        end
        if (j2$20 == idx$13) begin
            y2$20 = d$13;
        end
        if (j0$20 == idx$14) begin
            y0$20 = d$14;
        end
        if (j1$20 == idx$14) begin
            y1$20 = d$14;
        end
        if (j2$20 == idx$14) begin
            y2$20 = d$14;
        end
        if (j0$20 == idx$15) begin
            y0$20 = d$15;
        end
        if (j1$20 == idx$15) begin
            y1$20 = d$15;
        end
        if (j2$20 == idx$15) begin
            y2$20 = d$15;
        end
        if (j0$20 == idx$16) begin
            y0$20 = d$16;
        end
        if (j1$20 == idx$16) begin
            y1$20 = d$16;
        end
        if (j2$20 == idx$16) begin
            y2$20 = d$16;
        end
        if (j0$20 == idx$17) begin
            y0$20 = d$17;
        end
        if (j1$20 == idx$17) begin
            y1$20 = d$17;
        end
        if (j2$20 == idx$17) begin
            y2$20 = d$17;
        end
        if (j0$20 == idx$18) begin
            y0$20 = d$18;
        end
        if (j1$20 == idx$18) begin
            y1$20 = d$18;
        end
        if (j2$20 == idx$18) begin
            y2$20 = d$18;
        end
        if (j0$20 == idx$19) begin
            y0$20 = d$19;
        end
        if (j1$20 == idx$19) begin
            y1$20 = d$19;
        end
        if (j2$20 == idx$19) begin
            y2$20 = d$19;
        end
        if (j0$20 == idx$20) begin
            y0$20 = d$20;
        end
        if (j1$20 == idx$20) begin
            y1$20 = d$20;
        end
        if (j2$20 == idx$20) begin
            y2$20 = d$20;
        end
        if (j0$20 == idx$21) begin
            y0$20 = d$21;
        end
        if (j1$20 == idx$21) begin
            y1$20 = d$21;
        end
        if (j2$20 == idx$21) begin
            y2$20 = d$21;
        end
        if (j0$20 == idx$22) begin
            y0$20 = d$22;
        end
        if (j1$20 == idx$22) begin
            y1$20 = d$22;
        end
        if (j2$20 == idx$22) begin
            y2$20 = d$22;
        end
        if (j0$20 == idx$23) begin
            y0$20 = d$23;
        end
        if (j1$20 == idx$23) begin
            y1$20 = d$23;
        end
        if (j2$20 == idx$23) begin
            y2$20 = d$23;
        end
        y0$21 = 32'h0;
        y1$21 = 32'h0;
        y2$21 = 32'h0;
        if (j0$21 == idx$0) begin
            y0$21 = d$0;
        end
        if (j1$21 == idx$0) begin
            y1$21 = d$0;
        end
        if (j2$21 == idx$0) begin
            y2$21 = d$0;
        end
        if (j0$21 == idx$1) begin
            y0$21 = d$1;
        end
        if (j1$21 == idx$1) begin
            y1$21 = d$1;
        end
        if (j2$21 == idx$1) begin
            y2$21 = d$1;
        end
        if (j0$21 == idx$2) begin
            y0$21 = d$2;
        end
        if (j1$21 == idx$2) begin
            y1$21 = d$2;
        end
        if (j2$21 == idx$2) begin
            y2$21 = d$2;
        end
        if (j0$21 == idx$3) begin
            y0$21 = d$3;
        end
        if (j1$21 == idx$3) begin
            y1$21 = d$3;
        end
        if (j2$21 == idx$3) begin
            y2$21 = d$3;
        end
        if (j0$21 == idx$4) begin
            y0$21 = d$4;
        end
        if (j1$21 == idx$4) begin
            y1$21 = d$4;
        end
        if (j2$21 == idx$4) begin
            y2$21 = d$4;
        end
        if (j0$21 == idx$5) begin
            y0$21 = d$5;
        end
        if (j1$21 == idx$5) begin
            y1$21 = d$5;
        end
        if (j2$21 == idx$5) begin
            y2$21 = d$5;
        end
        if (j0$21 == idx$6) begin
            y0$21 = d$6;
        end
        if (j1$21 == idx$6) begin
            y1$21 = d$6;
        end
        if (j2$21 == idx$6) begin
            y2$21 = d$6;
        end
        if (j0$21 == idx$7) begin
            y0$21 = d$7;
        end
        if (j1$21 == idx$7) begin
            y1$21 = d$7;
        end
        if (j2$21 == idx$7) begin
            y2$21 = d$7;
        end
        if (j0$21 == idx$8) begin
            y0$21 = d$8;
        end
        if (j1$21 == idx$8) begin
            y1$21 = d$8;
        end
        if (j2$21 == idx$8) begin
            y2$21 = d$8;
        end
        if (j0$21 == idx$9) begin
            y0$21 = d$9;
        end
        if (j1$21 == idx$9) begin
            y1$21 = d$9;
        end
        if (j2$21 == idx$9) begin
            y2$21 = d$9;
        end
        if (j0$21 == idx$10) begin
            y0$21 = d$10;
        end
        if (j1$21 == idx$10) begin
            y1$21 = d$10;
        end
        if (j2$21 == idx$10) begin
            y2$21 = d$10;
        end
        if (j0$21 == idx$11) begin
            y0$21 = d$11;
        end
        if (j1$21 == idx$11) begin
            y1$21 = d$11;
        end
        if (j2$21 == idx$11) begin
            y2$21 = d$11;
        end
        if (j0$21 == idx$12) begin
            y0$21 = d$12;
        end
        if (j1$21 == idx$12) begin
            y1$21 = d$12;
        end
        if (j2$21 == idx$12) begin
            y2$21 = d$12;
        end
        if (j0$21 == idx$13) begin
            y0$21 = d$13;
        end
        if (j1$21 == idx$13) begin
            y1$21 = d$13;
        end
        if (j2$21 == idx$13) begin
            y2$21 = d$13;
        end
        if (j0$21 == idx$14) begin
            y0$21 = d$14;
        end
        if (j1$21 == idx$14) begin
            y1$21 = d$14;
        end
        if (j2$21 == idx$14) begin
            y2$21 = d$14;
        end
        if (j0$21 == idx$15) begin
            y0$21 = d$15;
        end
        if (j1$21 == idx$15) begin
            y1$21 = d$15;
        end
        if (j2$21 == idx$15) begin
            y2$21 = d$15;
        end
        if (j0$21 == idx$16) begin
            y0$21 = d$16;
        end
        if (j1$21 == idx$16) begin
            y1$21 = d$16;
        end
        if (j2$21 == idx$16) begin
            y2$21 = d$16;
        end
        if (j0$21 == idx$17) begin
            y0$21 = d$17;
        end
        if (j1$21 == idx$17) begin
            y1$21 = d$17;
        end
        if (j2$21 == idx$17) begin
            y2$21 = d$17;
        end
        if (j0$21 == idx$18) begin
            y0$21 = d$18;
        end
        if (j1$21 == idx$18) begin
            y1$21 = d$18;
        end
        if (j2$21 == idx$18) begin
            y2$21 = d$18;
        end
        if (j0$21 == idx$19) begin
            y0$21 = d$19;
        end
        if (j1$21 == idx$19) begin
            y1$21 = d$19;
        end
        if (j2$21 == idx$19) begin
            y2$21 = d$19;
        end
        if (j0$21 == idx$20) begin
            y0$21 = d$20;
        end
        if (j1$21 == idx$20) begin
            y1$21 = d$20;
        end
        if (j2$21 == idx$20) begin
            y2$21 = d$20;
        end
        if (j0$21 == idx$21) begin
            y0$21 = d$21;
        end
        if (j1$21 == idx$21) begin
            y1$21 = d$21;
        end
        if (j2$21 == idx$21) begin
            y2$21 = d$21;
        end
        if (j0$21 == idx$22) begin
            y0$21 = d$22;
        end
        if (j1$21 == idx$22) begin
            y1$21 = d$22;
        end
        if (j2$21 == idx$22) begin
            y2$21 = d$22;
        end
        if (j0$21 == idx$23) begin
            y0$21 = d$23;
        end
        if (j1$21 == idx$23) begin
            y1$21 = d$23;
        end
        if (j2$21 == idx$23) begin
            y2$21 = d$23;
        end
        y0$22 = 32'h0;
        y1$22 = 32'h0;
        y2$22 = 32'h0;
        if (j0$22 == idx$0) begin
            y0$22 = d$0;
        end
        if (j1$22 == idx$0) begin
            y1$22 = d$0;
        end
        if (j2$22 == idx$0) begin
            y2$22 = d$0;
        end
        if (j0$22 == idx$1) begin
            y0$22 = d$1;
        end
        if (j1$22 == idx$1) begin
            y1$22 = d$1;
        end
        if (j2$22 == idx$1) begin
            y2$22 = d$1;
        end
        if (j0$22 == idx$2) begin
            y0$22 = d$2;
        end
        if (j1$22 == idx$2) begin
            y1$22 = d$2;
        end
        if (j2$22 == idx$2) begin
            y2$22 = d$2;
        end
        if (j0$22 == idx$3) begin
            y0$22 = d$3;
        end
        if (j1$22 == idx$3) begin
            y1$22 = d$3;
        end
        if (j2$22 == idx$3) begin
            y2$22 = d$3;
        end
        if (j0$22 == idx$4) begin
            y0$22 = d$4;
        end
        if (j1$22 == idx$4) begin
            y1$22 = d$4;
        end
        if (j2$22 == idx$4) begin
            y2$22 = d$4;
        end
        if (j0$22 == idx$5) begin
            y0$22 = d$5;
        end
        if (j1$22 == idx$5) begin
            y1$22 = d$5;
        end
        if (j2$22 == idx$5) begin
            y2$22 = d$5;
        end
        if (j0$22 == idx$6) begin
            y0$22 = d$6;
        end
        if (j1$22 == idx$6) begin
            y1$22 = d$6;
        end
        if (j2$22 == idx$6) begin
            y2$22 = d$6;
        end
        if (j0$22 == idx$7) begin
            y0$22 = d$7;
        end
        if (j1$22 == idx$7) begin
            y1$22 = d$7;
        end
        if (j2$22 == idx$7) begin
            y2$22 = d$7;
        end
        if (j0$22 == idx$8) begin
            y0$22 = d$8;
        end
        if (j1$22 == idx$8) begin
            y1$22 = d$8;
        end
        if (j2$22 == idx$8) begin
            y2$22 = d$8;
        end
        if (j0$22 == idx$9) begin
            y0$22 = d$9;
        end
        if (j1$22 == idx$9) begin
            y1$22 = d$9;
        end
        if (j2$22 == idx$9) begin
            y2$22 = d$9;
        end
        if (j0$22 == idx$10) begin
            y0$22 = d$10;
        end
        if (j1$22 == idx$10) begin
            y1$22 = d$10;
        end
        if (j2$22 == idx$10) begin
            y2$22 = d$10;
        end
        if (j0$22 == idx$11) begin
            y0$22 = d$11;
        end
        if (j1$22 == idx$11) begin
            y1$22 = d$11;
        end
        if (j2$22 == idx$11) begin
            y2$22 = d$11;
        end
        if (j0$22 == idx$12) begin
            y0$22 = d$12;
        end
        if (j1$22 == idx$12) begin
            y1$22 = d$12;
        end
        if (j2$22 == idx$12) begin
            y2$22 = d$12;
        end
        if (j0$22 == idx$13) begin
            y0$22 = d$13;
        end
        if (j1$22 == idx$13) begin
            y1$22 = d$13;
        end
        if (j2$22 == idx$13) begin
            y2$22 = d$13;
        end
        if (j0$22 == idx$14) begin
            y0$22 = d$14;
        end
        if (j1$22 == idx$14) begin
            y1$22 = d$14;
        end
        if (j2$22 == idx$14) begin
            y2$22 = d$14;
        end
        if (j0$22 == idx$15) begin
            y0$22 = d$15;
        end
        if (j1$22 == idx$15) begin
            y1$22 = d$15;
        end
        if (j2$22 == idx$15) begin
            y2$22 = d$15;
        end
        if (j0$22 == idx$16) begin
            y0$22 = d$16;
        end
        if (j1$22 == idx$16) begin
            y1$22 = d$16;
        end
        if (j2$22 == idx$16) begin
            y2$22 = d$16;
        end
        if (j0$22 == idx$17) begin
            y0$22 = d$17;
        end
        if (j1$22 == idx$17) begin
            y1$22 = d$17;
        end
        if (j2$22 == idx$17) begin
            y2$22 = d$17;
        end
        if (j0$22 == idx$18) begin
            y0$22 = d$18;
        end
        if (j1$22 == idx$18) begin
            y1$22 = d$18;
        end
        if (j2$22 == idx$18) begin
            y2$22 = d$18;
        end
        if (j0$22 == idx$19) begin
            y0$22 = d$19;
        end
        if (j1$22 == idx$19) begin
            y1$22 = d$19;
        end
        if (j2$22 == idx$19) begin
            y2$22 = d$19;
        end
        if (j0$22 == idx$20) begin
            y0$22 = d$20;
        end
        if (j1$22 == idx$20) begin
            y1$22 = d$20;
        end
        if (j2$22 == idx$20) begin
            y2$22 = d$20;
        end
        if (j0$22 == idx$21) begin
            y0$22 = d$21;
        end
        if (j1$22 == idx$21) begin
            y1$22 = d$21;
        end
        if (j2$22 == idx$21) begin
            y2$22 = d$21;
        end
        if (j0$22 == idx$22) begin
            y0$22 = d$22;
        end
        if (j1$22 == idx$22) begin
            y1$22 = d$22;
        end
        if (j2$22 == idx$22) begin
            y2$22 = d$22;
        end
        if (j0$22 == idx$23) begin
            y0$22 = d$23;
        end
        if (j1$22 == idx$23) begin
            y1$22 = d$23;
        end
        if (j2$22 == idx$23) begin
            y2$22 = d$23;
        end
        y0$23 = 32'h0;
        y1$23 = 32'h0;
        y2$23 = 32'h0;
        if (j0$23 == idx$0) begin
            y0$23 = d$0;
        end
        if (j1$23 == idx$0) begin
            y1$23 = d$0;
        end
        if (j2$23 == idx$0) begin
            y2$23 = d$0;
        end
        if (j0$23 == idx$1) begin
            y0$23 = d$1;
        end
        if (j1$23 == idx$1) begin
            y1$23 = d$1;
        end
        if (j2$23 == idx$1) begin
            y2$23 = d$1;
        end
        if (j0$23 == idx$2) begin
            y0$23 = d$2;
        end
        if (j1$23 == idx$2) begin
            y1$23 = d$2;
        end
        if (j2$23 == idx$2) begin
            y2$23 = d$2;
        end
        if (j0$23 == idx$3) begin
            y0$23 = d$3;
        end
        if (j1$23 == idx$3) begin
            y1$23 = d$3;
        end
        if (j2$23 == idx$3) begin
            y2$23 = d$3;
        end
        if (j0$23 == idx$4) begin
            y0$23 = d$4;
        end
        if (j1$23 == idx$4) begin
            y1$23 = d$4;
        end
        if (j2$23 == idx$4) begin
            y2$23 = d$4;
        end
        if (j0$23 == idx$5) begin
            y0$23 = d$5;
        end
        if (j1$23 == idx$5) begin
            y1$23 = d$5;
        end
        if (j2$23 == idx$5) begin
            y2$23 = d$5;
        end
        if (j0$23 == idx$6) begin
            y0$23 = d$6;
        end
        if (j1$23 == idx$6) begin
            y1$23 = d$6;
        end
        if (j2$23 == idx$6) begin
            y2$23 = d$6;
        end
        if (j0$23 == idx$7) begin
            y0$23 = d$7;
        end
        if (j1$23 == idx$7) begin
            y1$23 = d$7;
        end
        if (j2$23 == idx$7) begin
            y2$23 = d$7;
        end
        if (j0$23 == idx$8) begin
            y0$23 = d$8;
        end
        if (j1$23 == idx$8) begin
            y1$23 = d$8;
        end
        if (j2$23 == idx$8) begin
            y2$23 = d$8;
        end
        if (j0$23 == idx$9) begin
            y0$23 = d$9;
        end
        if (j1$23 == idx$9) begin
            y1$23 = d$9;
        end
        if (j2$23 == idx$9) begin
            y2$23 = d$9;
        end
        if (j0$23 == idx$10) begin
            y0$23 = d$10;
        end
        if (j1$23 == idx$10) begin
            y1$23 = d$10;
        end
        if (j2$23 == idx$10) begin
            y2$23 = d$10;
        end
        if (j0$23 == idx$11) begin
            y0$23 = d$11;
        end
        if (j1$23 == idx$11) begin
            y1$23 = d$11;
        end
        if (j2$23 == idx$11) begin
            y2$23 = d$11;
        end
        if (j0$23 == idx$12) begin
            y0$23 = d$12;
        end
        if (j1$23 == idx$12) begin
            y1$23 = d$12;
        end
        if (j2$23 == idx$12) begin
            y2$23 = d$12;
        end
        if (j0$23 == idx$13) begin
            y0$23 = d$13;
        end
        if (j1$23 == idx$13) begin
            y1$23 = d$13;
        end
        if (j2$23 == idx$13) begin
            y2$23 = d$13;
        end
        if (j0$23 == idx$14) begin
            y0$23 = d$14;
        end
        if (j1$23 == idx$14) begin
            y1$23 = d$14;
        end
        if (j2$23 == idx$14) begin
            y2$23 = d$14;
        end
        if (j0$23 == idx$15) begin
            y0$23 = d$15;
        end
        if (j1$23 == idx$15) begin
            y1$23 = d$15;
        end
        if (j2$23 == idx$15) begin
            y2$23 = d$15;
        end
        if (j0$23 == idx$16) begin
            y0$23 = d$16;
        end
        if (j1$23 == idx$16) begin
            y1$23 = d$16;
        end
        if (j2$23 == idx$16) begin
            y2$23 = d$16;
        end
        if (j0$23 == idx$17) begin
            y0$23 = d$17;
        end
        if (j1$23 == idx$17) begin
            y1$23 = d$17;
        end
        if (j2$23 == idx$17) begin
            y2$23 = d$17;
        end
        if (j0$23 == idx$18) begin
            y0$23 = d$18;
        end
        if (j1$23 == idx$18) begin
            y1$23 = d$18;
        end
        if (j2$23 == idx$18) begin
            y2$23 = d$18;
        end
        if (j0$23 == idx$19) begin
            y0$23 = d$19;
        end
        if (j1$23 == idx$19) begin
            y1$23 = d$19;
        end
        if (j2$23 == idx$19) begin
            y2$23 = d$19;
        end
        if (j0$23 == idx$20) begin
            y0$23 = d$20;
        end
        if (j1$23 == idx$20) begin
            y1$23 = d$20;
        end
        if (j2$23 == idx$20) begin
            y2$23 = d$20;
        end
        if (j0$23 == idx$21) begin
            y0$23 = d$21;
        end
        if (j1$23 == idx$21) begin
            y1$23 = d$21;
        end
        if (j2$23 == idx$21) begin
            y2$23 = d$21;
        end
        if (j0$23 == idx$22) begin
            y0$23 = d$22;
        end
        if (j1$23 == idx$22) begin
            y1$23 = d$22;
        end
        if (j2$23 == idx$22) begin
            y2$23 = d$22;
        end
        if (j0$23 == idx$23) begin
            y0$23 = d$23;
        end
        if (j1$23 == idx$23) begin
            y1$23 = d$23;
        end
        if (j2$23 == idx$23) begin
            y2$23 = d$23;
        end
    end
    
endmodule // top$klmsel


module top$setup(clock,load_en,load_addr,load_data,c0$0,c0$1,c0$2,c0$3,c0$4,c0$5,c0$6,c0$7,c0$8,c0$9,c0$10,c0$11,c0$12,c0$13,c0$14,c0$15,c0$16,c0$17,c0$18,c0$19,c0$20,c0$21,c0$22,c0$23,c1$0,c1$1,c1$2,c1$3,c1$4,c1$5,c1$6,c1$7,c1$8,c1$9,c1$10,c1$11,c1$12,c1$13,c1$14,c1$15,c1$16,c1$17,c1$18,c1$19,c1$20,c1$21,c1$22,c1$23,c2$0,c2$1,c2$2,c2$3,c2$4,c2$5,c2$6,c2$7,c2$8,c2$9,c2$10,c2$11,c2$12,c2$13,c2$14,c2$15,c2$16,c2$17,c2$18,c2$19,c2$20,c2$21,c2$22,c2$23,c$0,c$1,c$2,c$3,c$4,c$5,c$6,c$7,c$8,c$9,c$10,c$11,c$12,c$13,c$14,c$15,c$16,c$17,c$18,c$19,c$20,c$21,c$22,c$23,j0$0,j0$1,j0$2,j0$3,j0$4,j0$5,j0$6,j0$7,j0$8,j0$9,j0$10,j0$11,j0$12,j0$13,j0$14,j0$15,j0$16,j0$17,j0$18,j0$19,j0$20,j0$21,j0$22,j0$23,j1$0,j1$1,j1$2,j1$3,j1$4,j1$5,j1$6,j1$7,j1$8,j1$9,j1$10,j1$11,j1$12,j1$13,j1$14,j1$15,j1$16,j1$17,j1$18,j1$19,j1$20,j1$21,j1$22,j1$23,j2$0,j2$1,j2$2,j2$3,j2$4,j2$5,j2$6,j2$7,j2$8,j2$9,j2$10,j2$11,j2$12,j2$13,j2$14,j2$15,j2$16,j2$17,j2$18,j2$19,j2$20,j2$21,j2$22,j2$23,round_up$0,round_up$1,round_up$2,round_up$3,round_up$4,round_up$5,round_up$6,round_up$7,round_up$8,round_up$9,round_up$10,round_up$11,round_up$12,round_up$13,round_up$14,round_up$15,round_up$16,round_up$17,round_up$18,round_up$19,round_up$20,round_up$21,round_up$22,round_up$23);
    
    // Module arguments
    input wire  clock;
    input wire  load_en;
    input wire  [7:0] load_addr;
    input wire  [31:0] load_data;
    output reg  [31:0] c0$0;
    output reg  [31:0] c0$1;
    output reg  [31:0] c0$2;
    output reg  [31:0] c0$3;
    output reg  [31:0] c0$4;
    output reg  [31:0] c0$5;
    output reg  [31:0] c0$6;
    output reg  [31:0] c0$7;
    output reg  [31:0] c0$8;
    output reg  [31:0] c0$9;
    output reg  [31:0] c0$10;
    output reg  [31:0] c0$11;
    output reg  [31:0] c0$12;
    output reg  [31:0] c0$13;
    output reg  [31:0] c0$14;
    output reg  [31:0] c0$15;
    output reg  [31:0] c0$16;
    output reg  [31:0] c0$17;
    output reg  [31:0] c0$18;
    output reg  [31:0] c0$19;
    output reg  [31:0] c0$20;
    output reg  [31:0] c0$21;
    output reg  [31:0] c0$22;
    output reg  [31:0] c0$23;
    output reg  [31:0] c1$0;
    output reg  [31:0] c1$1;
    output reg  [31:0] c1$2;
    output reg  [31:0] c1$3;
    output reg  [31:0] c1$4;
    output reg  [31:0] c1$5;
    output reg  [31:0] c1$6;
    output reg  [31:0] c1$7;
    output reg  [31:0] c1$8;
    output reg  [31:0] c1$9;
    output reg  [31:0] c1$10;
    output reg  [31:0] c1$11;
    output reg  [31:0] c1$12;
    output reg  [31:0] c1$13;
    output reg  [31:0] c1$14;
    output reg  [31:0] c1$15;
    output reg  [31:0] c1$16;
    output reg  [31:0] c1$17;
    output reg  [31:0] c1$18;
    output reg  [31:0] c1$19;
    output reg  [31:0] c1$20;
    output reg  [31:0] c1$21;
    output reg  [31:0] c1$22;
    output reg  [31:0] c1$23;
    output reg  [31:0] c2$0;
    output reg  [31:0] c2$1;
    output reg  [31:0] c2$2;
    output reg  [31:0] c2$3;
    output reg  [31:0] c2$4;
    output reg  [31:0] c2$5;
    output reg  [31:0] c2$6;
    output reg  [31:0] c2$7;
    output reg  [31:0] c2$8;
    output reg  [31:0] c2$9;
    output reg  [31:0] c2$10;
    output reg  [31:0] c2$11;
    output reg  [31:0] c2$12;
    output reg  [31:0] c2$13;
    output reg  [31:0] c2$14;
    output reg  [31:0] c2$15;
    output reg  [31:0] c2$16;
    output reg  [31:0] c2$17;
    output reg  [31:0] c2$18;
    output reg  [31:0] c2$19;
    output reg  [31:0] c2$20;
    output reg  [31:0] c2$21;
    output reg  [31:0] c2$22;
    output reg  [31:0] c2$23;
    output reg  [31:0] c$0;
    output reg  [31:0] c$1;
    output reg  [31:0] c$2;
    output reg  [31:0] c$3;
    output reg  [31:0] c$4;
    output reg  [31:0] c$5;
    output reg  [31:0] c$6;
    output reg  [31:0] c$7;
    output reg  [31:0] c$8;
    output reg  [31:0] c$9;
    output reg  [31:0] c$10;
    output reg  [31:0] c$11;
    output reg  [31:0] c$12;
    output reg  [31:0] c$13;
    output reg  [31:0] c$14;
    output reg  [31:0] c$15;
    output reg  [31:0] c$16;
    output reg  [31:0] c$17;
    output reg  [31:0] c$18;
    output reg  [31:0] c$19;
    output reg  [31:0] c$20;
    output reg  [31:0] c$21;
    output reg  [31:0] c$22;
    output reg  [31:0] c$23;
    output reg  [4:0] j0$0;
    output reg  [4:0] j0$1;
    output reg  [4:0] j0$2;
    output reg  [4:0] j0$3;
    output reg  [4:0] j0$4;
    output reg  [4:0] j0$5;
    output reg  [4:0] j0$6;
    output reg  [4:0] j0$7;
    output reg  [4:0] j0$8;
    output reg  [4:0] j0$9;
    output reg  [4:0] j0$10;
    output reg  [4:0] j0$11;
    output reg  [4:0] j0$12;
    output reg  [4:0] j0$13;
    output reg  [4:0] j0$14;
    output reg  [4:0] j0$15;
    output reg  [4:0] j0$16;
    output reg  [4:0] j0$17;
    output reg  [4:0] j0$18;
    output reg  [4:0] j0$19;
    output reg  [4:0] j0$20;
    output reg  [4:0] j0$21;
    output reg  [4:0] j0$22;
    output reg  [4:0] j0$23;
    output reg  [4:0] j1$0;
    output reg  [4:0] j1$1;
    output reg  [4:0] j1$2;
    output reg  [4:0] j1$3;
    output reg  [4:0] j1$4;
    output reg  [4:0] j1$5;
    output reg  [4:0] j1$6;
    output reg  [4:0] j1$7;
    output reg  [4:0] j1$8;
    output reg  [4:0] j1$9;
    output reg  [4:0] j1$10;
    output reg  [4:0] j1$11;
    output reg  [4:0] j1$12;
    output reg  [4:0] j1$13;
    output reg  [4:0] j1$14;
    output reg  [4:0] j1$15;
    output reg  [4:0] j1$16;
    output reg  [4:0] j1$17;
    output reg  [4:0] j1$18;
    output reg  [4:0] j1$19;
    output reg  [4:0] j1$20;
    output reg  [4:0] j1$21;
    output reg  [4:0] j1$22;
    output reg  [4:0] j1$23;
    output reg  [4:0] j2$0;
    output reg  [4:0] j2$1;
    output reg  [4:0] j2$2;
    output reg  [4:0] j2$3;
    output reg  [4:0] j2$4;
    output reg  [4:0] j2$5;
    output reg  [4:0] j2$6;
    output reg  [4:0] j2$7;
    output reg  [4:0] j2$8;
    output reg  [4:0] j2$9;
    output reg  [4:0] j2$10;
    output reg  [4:0] j2$11;
    output reg  [4:0] j2$12;
    output reg  [4:0] j2$13;
    output reg  [4:0] j2$14;
    output reg  [4:0] j2$15;
    output reg  [4:0] j2$16;
    output reg  [4:0] j2$17;
    output reg  [4:0] j2$18;
    output reg  [4:0] j2$19;
    output reg  [4:0] j2$20;
    output reg  [4:0] j2$21;
    output reg  [4:0] j2$22;
    output reg  [4:0] j2$23;
    output reg  round_up$0;
    output reg  round_up$1;
    output reg  round_up$2;
    output reg  round_up$3;
    output reg  round_up$4;
    output reg  round_up$5;
    output reg  round_up$6;
    output reg  round_up$7;
    output reg  round_up$8;
    output reg  round_up$9;
    output reg  round_up$10;
    output reg  round_up$11;
    output reg  round_up$12;
    output reg  round_up$13;
    output reg  round_up$14;
    output reg  round_up$15;
    output reg  round_up$16;
    output reg  round_up$17;
    output reg  round_up$18;
    output reg  round_up$19;
    output reg  round_up$20;
    output reg  round_up$21;
    output reg  round_up$22;
    output reg  round_up$23;
    
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
    
    // Stub signals
    reg  [31:0] cmat_0$0$d;
    wire  [31:0] cmat_0$0$q;
    reg  cmat_0$0$clock;
    reg  [31:0] cmat_0$1$d;
    wire  [31:0] cmat_0$1$q;
    reg  cmat_0$1$clock;
    reg  [31:0] cmat_0$2$d;
    wire  [31:0] cmat_0$2$q;
    reg  cmat_0$2$clock;
    reg  [31:0] cmat_0$3$d;
    wire  [31:0] cmat_0$3$q;
    reg  cmat_0$3$clock;
    reg  [31:0] cmat_0$4$d;
    wire  [31:0] cmat_0$4$q;
    reg  cmat_0$4$clock;
    reg  [31:0] cmat_0$5$d;
    wire  [31:0] cmat_0$5$q;
    reg  cmat_0$5$clock;
    reg  [31:0] cmat_0$6$d;
    wire  [31:0] cmat_0$6$q;
    reg  cmat_0$6$clock;
    reg  [31:0] cmat_0$7$d;
    wire  [31:0] cmat_0$7$q;
    reg  cmat_0$7$clock;
    reg  [31:0] cmat_0$8$d;
    wire  [31:0] cmat_0$8$q;
    reg  cmat_0$8$clock;
    reg  [31:0] cmat_0$9$d;
    wire  [31:0] cmat_0$9$q;
    reg  cmat_0$9$clock;
    reg  [31:0] cmat_0$10$d;
    wire  [31:0] cmat_0$10$q;
    reg  cmat_0$10$clock;
    reg  [31:0] cmat_0$11$d;
    wire  [31:0] cmat_0$11$q;
    reg  cmat_0$11$clock;
    reg  [31:0] cmat_0$12$d;
    wire  [31:0] cmat_0$12$q;
    reg  cmat_0$12$clock;
    reg  [31:0] cmat_0$13$d;
    wire  [31:0] cmat_0$13$q;
    reg  cmat_0$13$clock;
    reg  [31:0] cmat_0$14$d;
    wire  [31:0] cmat_0$14$q;
    reg  cmat_0$14$clock;
    reg  [31:0] cmat_0$15$d;
    wire  [31:0] cmat_0$15$q;
    reg  cmat_0$15$clock;
    reg  [31:0] cmat_0$16$d;
    wire  [31:0] cmat_0$16$q;
    reg  cmat_0$16$clock;
    reg  [31:0] cmat_0$17$d;
    wire  [31:0] cmat_0$17$q;
    reg  cmat_0$17$clock;
    reg  [31:0] cmat_0$18$d;
    wire  [31:0] cmat_0$18$q;
    reg  cmat_0$18$clock;
    reg  [31:0] cmat_0$19$d;
    wire  [31:0] cmat_0$19$q;
    reg  cmat_0$19$clock;
    reg  [31:0] cmat_0$20$d;
    wire  [31:0] cmat_0$20$q;
    reg  cmat_0$20$clock;
    reg  [31:0] cmat_0$21$d;
    wire  [31:0] cmat_0$21$q;
    reg  cmat_0$21$clock;
    reg  [31:0] cmat_0$22$d;
    wire  [31:0] cmat_0$22$q;
    reg  cmat_0$22$clock;
    reg  [31:0] cmat_0$23$d;
    wire  [31:0] cmat_0$23$q;
    reg  cmat_0$23$clock;
    reg  [31:0] cmat_1$0$d;
    wire  [31:0] cmat_1$0$q;
    reg  cmat_1$0$clock;
    reg  [31:0] cmat_1$1$d;
    wire  [31:0] cmat_1$1$q;
    reg  cmat_1$1$clock;
    reg  [31:0] cmat_1$2$d;
    wire  [31:0] cmat_1$2$q;
    reg  cmat_1$2$clock;
    reg  [31:0] cmat_1$3$d;
    wire  [31:0] cmat_1$3$q;
    reg  cmat_1$3$clock;
    reg  [31:0] cmat_1$4$d;
    wire  [31:0] cmat_1$4$q;
    reg  cmat_1$4$clock;
    reg  [31:0] cmat_1$5$d;
    wire  [31:0] cmat_1$5$q;
    reg  cmat_1$5$clock;
    reg  [31:0] cmat_1$6$d;
    wire  [31:0] cmat_1$6$q;
    reg  cmat_1$6$clock;
    reg  [31:0] cmat_1$7$d;
    wire  [31:0] cmat_1$7$q;
    reg  cmat_1$7$clock;
    reg  [31:0] cmat_1$8$d;
    wire  [31:0] cmat_1$8$q;
    reg  cmat_1$8$clock;
    reg  [31:0] cmat_1$9$d;
    wire  [31:0] cmat_1$9$q;
    reg  cmat_1$9$clock;
    reg  [31:0] cmat_1$10$d;
    wire  [31:0] cmat_1$10$q;
    reg  cmat_1$10$clock;
    reg  [31:0] cmat_1$11$d;
    wire  [31:0] cmat_1$11$q;
    reg  cmat_1$11$clock;
    reg  [31:0] cmat_1$12$d;
    wire  [31:0] cmat_1$12$q;
    reg  cmat_1$12$clock;
    reg  [31:0] cmat_1$13$d;
    wire  [31:0] cmat_1$13$q;
    reg  cmat_1$13$clock;
    reg  [31:0] cmat_1$14$d;
    wire  [31:0] cmat_1$14$q;
    reg  cmat_1$14$clock;
    reg  [31:0] cmat_1$15$d;
    wire  [31:0] cmat_1$15$q;
    reg  cmat_1$15$clock;
    reg  [31:0] cmat_1$16$d;
    wire  [31:0] cmat_1$16$q;
    reg  cmat_1$16$clock;
    reg  [31:0] cmat_1$17$d;
    wire  [31:0] cmat_1$17$q;
    reg  cmat_1$17$clock;
    reg  [31:0] cmat_1$18$d;
    wire  [31:0] cmat_1$18$q;
    reg  cmat_1$18$clock;
    reg  [31:0] cmat_1$19$d;
    wire  [31:0] cmat_1$19$q;
    reg  cmat_1$19$clock;
    reg  [31:0] cmat_1$20$d;
    wire  [31:0] cmat_1$20$q;
    reg  cmat_1$20$clock;
    reg  [31:0] cmat_1$21$d;
    wire  [31:0] cmat_1$21$q;
    reg  cmat_1$21$clock;
    reg  [31:0] cmat_1$22$d;
    wire  [31:0] cmat_1$22$q;
    reg  cmat_1$22$clock;
    reg  [31:0] cmat_1$23$d;
    wire  [31:0] cmat_1$23$q;
    reg  cmat_1$23$clock;
    reg  [31:0] cmat_2$0$d;
    wire  [31:0] cmat_2$0$q;
    reg  cmat_2$0$clock;
    reg  [31:0] cmat_2$1$d;
    wire  [31:0] cmat_2$1$q;
    reg  cmat_2$1$clock;
    reg  [31:0] cmat_2$2$d;
    wire  [31:0] cmat_2$2$q;
    reg  cmat_2$2$clock;
    reg  [31:0] cmat_2$3$d;
    wire  [31:0] cmat_2$3$q;
    reg  cmat_2$3$clock;
    reg  [31:0] cmat_2$4$d;
    wire  [31:0] cmat_2$4$q;
    reg  cmat_2$4$clock;
    reg  [31:0] cmat_2$5$d;
    wire  [31:0] cmat_2$5$q;
    reg  cmat_2$5$clock;
    reg  [31:0] cmat_2$6$d;
    wire  [31:0] cmat_2$6$q;
    reg  cmat_2$6$clock;
    reg  [31:0] cmat_2$7$d;
    wire  [31:0] cmat_2$7$q;
    reg  cmat_2$7$clock;
    reg  [31:0] cmat_2$8$d;
    wire  [31:0] cmat_2$8$q;
    reg  cmat_2$8$clock;
    reg  [31:0] cmat_2$9$d;
    wire  [31:0] cmat_2$9$q;
    reg  cmat_2$9$clock;
    reg  [31:0] cmat_2$10$d;
    wire  [31:0] cmat_2$10$q;
    reg  cmat_2$10$clock;
    reg  [31:0] cmat_2$11$d;
    wire  [31:0] cmat_2$11$q;
    reg  cmat_2$11$clock;
    reg  [31:0] cmat_2$12$d;
    wire  [31:0] cmat_2$12$q;
    reg  cmat_2$12$clock;
    reg  [31:0] cmat_2$13$d;
    wire  [31:0] cmat_2$13$q;
    reg  cmat_2$13$clock;
    reg  [31:0] cmat_2$14$d;
    wire  [31:0] cmat_2$14$q;
    reg  cmat_2$14$clock;
    reg  [31:0] cmat_2$15$d;
    wire  [31:0] cmat_2$15$q;
    reg  cmat_2$15$clock;
    reg  [31:0] cmat_2$16$d;
    wire  [31:0] cmat_2$16$q;
    reg  cmat_2$16$clock;
    reg  [31:0] cmat_2$17$d;
    wire  [31:0] cmat_2$17$q;
    reg  cmat_2$17$clock;
    reg  [31:0] cmat_2$18$d;
    wire  [31:0] cmat_2$18$q;
    reg  cmat_2$18$clock;
    reg  [31:0] cmat_2$19$d;
    wire  [31:0] cmat_2$19$q;
    reg  cmat_2$19$clock;
    reg  [31:0] cmat_2$20$d;
    wire  [31:0] cmat_2$20$q;
    reg  cmat_2$20$clock;
    reg  [31:0] cmat_2$21$d;
    wire  [31:0] cmat_2$21$q;
    reg  cmat_2$21$clock;
    reg  [31:0] cmat_2$22$d;
    wire  [31:0] cmat_2$22$q;
    reg  cmat_2$22$clock;
    reg  [31:0] cmat_2$23$d;
    wire  [31:0] cmat_2$23$q;
    reg  cmat_2$23$clock;
    reg  [31:0] cvec$0$d;
    wire  [31:0] cvec$0$q;
    reg  cvec$0$clock;
    reg  [31:0] cvec$1$d;
    wire  [31:0] cvec$1$q;
    reg  cvec$1$clock;
    reg  [31:0] cvec$2$d;
    wire  [31:0] cvec$2$q;
    reg  cvec$2$clock;
    reg  [31:0] cvec$3$d;
    wire  [31:0] cvec$3$q;
    reg  cvec$3$clock;
    reg  [31:0] cvec$4$d;
    wire  [31:0] cvec$4$q;
    reg  cvec$4$clock;
    reg  [31:0] cvec$5$d;
    wire  [31:0] cvec$5$q;
    reg  cvec$5$clock;
    reg  [31:0] cvec$6$d;
    wire  [31:0] cvec$6$q;
    reg  cvec$6$clock;
    reg  [31:0] cvec$7$d;
    wire  [31:0] cvec$7$q;
    reg  cvec$7$clock;
    reg  [31:0] cvec$8$d;
    wire  [31:0] cvec$8$q;
    reg  cvec$8$clock;
    reg  [31:0] cvec$9$d;
    wire  [31:0] cvec$9$q;
    reg  cvec$9$clock;
    reg  [31:0] cvec$10$d;
    wire  [31:0] cvec$10$q;
    reg  cvec$10$clock;
    reg  [31:0] cvec$11$d;
    wire  [31:0] cvec$11$q;
    reg  cvec$11$clock;
    reg  [31:0] cvec$12$d;
    wire  [31:0] cvec$12$q;
    reg  cvec$12$clock;
    reg  [31:0] cvec$13$d;
    wire  [31:0] cvec$13$q;
    reg  cvec$13$clock;
    reg  [31:0] cvec$14$d;
    wire  [31:0] cvec$14$q;
    reg  cvec$14$clock;
    reg  [31:0] cvec$15$d;
    wire  [31:0] cvec$15$q;
    reg  cvec$15$clock;
    reg  [31:0] cvec$16$d;
    wire  [31:0] cvec$16$q;
    reg  cvec$16$clock;
    reg  [31:0] cvec$17$d;
    wire  [31:0] cvec$17$q;
    reg  cvec$17$clock;
    reg  [31:0] cvec$18$d;
    wire  [31:0] cvec$18$q;
    reg  cvec$18$clock;
    reg  [31:0] cvec$19$d;
    wire  [31:0] cvec$19$q;
    reg  cvec$19$clock;
    reg  [31:0] cvec$20$d;
    wire  [31:0] cvec$20$q;
    reg  cvec$20$clock;
    reg  [31:0] cvec$21$d;
    wire  [31:0] cvec$21$q;
    reg  cvec$21$clock;
    reg  [31:0] cvec$22$d;
    wire  [31:0] cvec$22$q;
    reg  cvec$22$clock;
    reg  [31:0] cvec$23$d;
    wire  [31:0] cvec$23$q;
    reg  cvec$23$clock;
    reg  [4:0] jsel_0$0$d;
    wire  [4:0] jsel_0$0$q;
    reg  jsel_0$0$clock;
    reg  [4:0] jsel_0$1$d;
    wire  [4:0] jsel_0$1$q;
    reg  jsel_0$1$clock;
    reg  [4:0] jsel_0$2$d;
    wire  [4:0] jsel_0$2$q;
    reg  jsel_0$2$clock;
    reg  [4:0] jsel_0$3$d;
    wire  [4:0] jsel_0$3$q;
    reg  jsel_0$3$clock;
    reg  [4:0] jsel_0$4$d;
    wire  [4:0] jsel_0$4$q;
    reg  jsel_0$4$clock;
    reg  [4:0] jsel_0$5$d;
    wire  [4:0] jsel_0$5$q;
    reg  jsel_0$5$clock;
    reg  [4:0] jsel_0$6$d;
    wire  [4:0] jsel_0$6$q;
    reg  jsel_0$6$clock;
    reg  [4:0] jsel_0$7$d;
    wire  [4:0] jsel_0$7$q;
    reg  jsel_0$7$clock;
    reg  [4:0] jsel_0$8$d;
    wire  [4:0] jsel_0$8$q;
    reg  jsel_0$8$clock;
    reg  [4:0] jsel_0$9$d;
    wire  [4:0] jsel_0$9$q;
    reg  jsel_0$9$clock;
    reg  [4:0] jsel_0$10$d;
    wire  [4:0] jsel_0$10$q;
    reg  jsel_0$10$clock;
    reg  [4:0] jsel_0$11$d;
    wire  [4:0] jsel_0$11$q;
    reg  jsel_0$11$clock;
    reg  [4:0] jsel_0$12$d;
    wire  [4:0] jsel_0$12$q;
    reg  jsel_0$12$clock;
    reg  [4:0] jsel_0$13$d;
    wire  [4:0] jsel_0$13$q;
    reg  jsel_0$13$clock;
    reg  [4:0] jsel_0$14$d;
    wire  [4:0] jsel_0$14$q;
    reg  jsel_0$14$clock;
    reg  [4:0] jsel_0$15$d;
    wire  [4:0] jsel_0$15$q;
    reg  jsel_0$15$clock;
    reg  [4:0] jsel_0$16$d;
    wire  [4:0] jsel_0$16$q;
    reg  jsel_0$16$clock;
    reg  [4:0] jsel_0$17$d;
    wire  [4:0] jsel_0$17$q;
    reg  jsel_0$17$clock;
    reg  [4:0] jsel_0$18$d;
    wire  [4:0] jsel_0$18$q;
    reg  jsel_0$18$clock;
    reg  [4:0] jsel_0$19$d;
    wire  [4:0] jsel_0$19$q;
    reg  jsel_0$19$clock;
    reg  [4:0] jsel_0$20$d;
    wire  [4:0] jsel_0$20$q;
    reg  jsel_0$20$clock;
    reg  [4:0] jsel_0$21$d;
    wire  [4:0] jsel_0$21$q;
    reg  jsel_0$21$clock;
    reg  [4:0] jsel_0$22$d;
    wire  [4:0] jsel_0$22$q;
    reg  jsel_0$22$clock;
    reg  [4:0] jsel_0$23$d;
    wire  [4:0] jsel_0$23$q;
    reg  jsel_0$23$clock;
    reg  [4:0] jsel_1$0$d;
    wire  [4:0] jsel_1$0$q;
    reg  jsel_1$0$clock;
    reg  [4:0] jsel_1$1$d;
    wire  [4:0] jsel_1$1$q;
    reg  jsel_1$1$clock;
    reg  [4:0] jsel_1$2$d;
    wire  [4:0] jsel_1$2$q;
    reg  jsel_1$2$clock;
    reg  [4:0] jsel_1$3$d;
    wire  [4:0] jsel_1$3$q;
    reg  jsel_1$3$clock;
    reg  [4:0] jsel_1$4$d;
    wire  [4:0] jsel_1$4$q;
    reg  jsel_1$4$clock;
    reg  [4:0] jsel_1$5$d;
    wire  [4:0] jsel_1$5$q;
    reg  jsel_1$5$clock;
    reg  [4:0] jsel_1$6$d;
    wire  [4:0] jsel_1$6$q;
    reg  jsel_1$6$clock;
    reg  [4:0] jsel_1$7$d;
    wire  [4:0] jsel_1$7$q;
    reg  jsel_1$7$clock;
    reg  [4:0] jsel_1$8$d;
    wire  [4:0] jsel_1$8$q;
    reg  jsel_1$8$clock;
    reg  [4:0] jsel_1$9$d;
    wire  [4:0] jsel_1$9$q;
    reg  jsel_1$9$clock;
    reg  [4:0] jsel_1$10$d;
    wire  [4:0] jsel_1$10$q;
    reg  jsel_1$10$clock;
    reg  [4:0] jsel_1$11$d;
    wire  [4:0] jsel_1$11$q;
    reg  jsel_1$11$clock;
    reg  [4:0] jsel_1$12$d;
    wire  [4:0] jsel_1$12$q;
    reg  jsel_1$12$clock;
    reg  [4:0] jsel_1$13$d;
    wire  [4:0] jsel_1$13$q;
    reg  jsel_1$13$clock;
    reg  [4:0] jsel_1$14$d;
    wire  [4:0] jsel_1$14$q;
    reg  jsel_1$14$clock;
    reg  [4:0] jsel_1$15$d;
    wire  [4:0] jsel_1$15$q;
    reg  jsel_1$15$clock;
    reg  [4:0] jsel_1$16$d;
    wire  [4:0] jsel_1$16$q;
    reg  jsel_1$16$clock;
    reg  [4:0] jsel_1$17$d;
    wire  [4:0] jsel_1$17$q;
    reg  jsel_1$17$clock;
    reg  [4:0] jsel_1$18$d;
    wire  [4:0] jsel_1$18$q;
    reg  jsel_1$18$clock;
    reg  [4:0] jsel_1$19$d;
    wire  [4:0] jsel_1$19$q;
    reg  jsel_1$19$clock;
    reg  [4:0] jsel_1$20$d;
    wire  [4:0] jsel_1$20$q;
    reg  jsel_1$20$clock;
    reg  [4:0] jsel_1$21$d;
    wire  [4:0] jsel_1$21$q;
    reg  jsel_1$21$clock;
    reg  [4:0] jsel_1$22$d;
    wire  [4:0] jsel_1$22$q;
    reg  jsel_1$22$clock;
    reg  [4:0] jsel_1$23$d;
    wire  [4:0] jsel_1$23$q;
    reg  jsel_1$23$clock;
    reg  [4:0] jsel_2$0$d;
    wire  [4:0] jsel_2$0$q;
    reg  jsel_2$0$clock;
    reg  [4:0] jsel_2$1$d;
    wire  [4:0] jsel_2$1$q;
    reg  jsel_2$1$clock;
    reg  [4:0] jsel_2$2$d;
    wire  [4:0] jsel_2$2$q;
    reg  jsel_2$2$clock;
    reg  [4:0] jsel_2$3$d;
    wire  [4:0] jsel_2$3$q;
    reg  jsel_2$3$clock;
    reg  [4:0] jsel_2$4$d;
    wire  [4:0] jsel_2$4$q;
    reg  jsel_2$4$clock;
    reg  [4:0] jsel_2$5$d;
    wire  [4:0] jsel_2$5$q;
    reg  jsel_2$5$clock;
    reg  [4:0] jsel_2$6$d;
    wire  [4:0] jsel_2$6$q;
    reg  jsel_2$6$clock;
    reg  [4:0] jsel_2$7$d;
    wire  [4:0] jsel_2$7$q;
    reg  jsel_2$7$clock;
    reg  [4:0] jsel_2$8$d;
    wire  [4:0] jsel_2$8$q;
    reg  jsel_2$8$clock;
    reg  [4:0] jsel_2$9$d;
    wire  [4:0] jsel_2$9$q;
    reg  jsel_2$9$clock;
    reg  [4:0] jsel_2$10$d;
    wire  [4:0] jsel_2$10$q;
    reg  jsel_2$10$clock;
    reg  [4:0] jsel_2$11$d;
    wire  [4:0] jsel_2$11$q;
    reg  jsel_2$11$clock;
    reg  [4:0] jsel_2$12$d;
    wire  [4:0] jsel_2$12$q;
    reg  jsel_2$12$clock;
    reg  [4:0] jsel_2$13$d;
    wire  [4:0] jsel_2$13$q;
    reg  jsel_2$13$clock;
    reg  [4:0] jsel_2$14$d;
    wire  [4:0] jsel_2$14$q;
    reg  jsel_2$14$clock;
    reg  [4:0] jsel_2$15$d;
    wire  [4:0] jsel_2$15$q;
    reg  jsel_2$15$clock;
    reg  [4:0] jsel_2$16$d;
    wire  [4:0] jsel_2$16$q;
    reg  jsel_2$16$clock;
    reg  [4:0] jsel_2$17$d;
    wire  [4:0] jsel_2$17$q;
    reg  jsel_2$17$clock;
    reg  [4:0] jsel_2$18$d;
    wire  [4:0] jsel_2$18$q;
    reg  jsel_2$18$clock;
    reg  [4:0] jsel_2$19$d;
    wire  [4:0] jsel_2$19$q;
    reg  jsel_2$19$clock;
    reg  [4:0] jsel_2$20$d;
    wire  [4:0] jsel_2$20$q;
    reg  jsel_2$20$clock;
    reg  [4:0] jsel_2$21$d;
    wire  [4:0] jsel_2$21$q;
    reg  jsel_2$21$clock;
    reg  [4:0] jsel_2$22$d;
    wire  [4:0] jsel_2$22$q;
    reg  jsel_2$22$clock;
    reg  [4:0] jsel_2$23$d;
    wire  [4:0] jsel_2$23$q;
    reg  jsel_2$23$clock;
    reg  rnd$0$d;
    wire  rnd$0$q;
    reg  rnd$0$clock;
    reg  rnd$1$d;
    wire  rnd$1$q;
    reg  rnd$1$clock;
    reg  rnd$2$d;
    wire  rnd$2$q;
    reg  rnd$2$clock;
    reg  rnd$3$d;
    wire  rnd$3$q;
    reg  rnd$3$clock;
    reg  rnd$4$d;
    wire  rnd$4$q;
    reg  rnd$4$clock;
    reg  rnd$5$d;
    wire  rnd$5$q;
    reg  rnd$5$clock;
    reg  rnd$6$d;
    wire  rnd$6$q;
    reg  rnd$6$clock;
    reg  rnd$7$d;
    wire  rnd$7$q;
    reg  rnd$7$clock;
    reg  rnd$8$d;
    wire  rnd$8$q;
    reg  rnd$8$clock;
    reg  rnd$9$d;
    wire  rnd$9$q;
    reg  rnd$9$clock;
    reg  rnd$10$d;
    wire  rnd$10$q;
    reg  rnd$10$clock;
    reg  rnd$11$d;
    wire  rnd$11$q;
    reg  rnd$11$clock;
    reg  rnd$12$d;
    wire  rnd$12$q;
    reg  rnd$12$clock;
    reg  rnd$13$d;
    wire  rnd$13$q;
    reg  rnd$13$clock;
    reg  rnd$14$d;
    wire  rnd$14$q;
    reg  rnd$14$clock;
    reg  rnd$15$d;
    wire  rnd$15$q;
    reg  rnd$15$clock;
    reg  rnd$16$d;
    wire  rnd$16$q;
    reg  rnd$16$clock;
    reg  rnd$17$d;
    wire  rnd$17$q;
    reg  rnd$17$clock;
    reg  rnd$18$d;
    wire  rnd$18$q;
    reg  rnd$18$clock;
    reg  rnd$19$d;
    wire  rnd$19$q;
    reg  rnd$19$clock;
    reg  rnd$20$d;
    wire  rnd$20$q;
    reg  rnd$20$clock;
    reg  rnd$21$d;
    wire  rnd$21$q;
    reg  rnd$21$clock;
    reg  rnd$22$d;
    wire  rnd$22$q;
    reg  rnd$22$clock;
    reg  rnd$23$d;
    wire  rnd$23$q;
    reg  rnd$23$clock;
    
    // Local signals
    reg  [4:0] c_lane;
    reg  [2:0] c_field;
    
    // Sub module instances
    top$doptrf$0$add_0$s3_y cmat_0$0(
        .d(cmat_0$0$d),
        .q(cmat_0$0$q),
        .clock(cmat_0$0$clock)
    );
    top$doptrf$0$add_0$s3_y cmat_0$1(
        .d(cmat_0$1$d),
        .q(cmat_0$1$q),
        .clock(cmat_0$1$clock)
    );
    top$doptrf$0$add_0$s3_y cmat_0$2(
        .d(cmat_0$2$d),
        .q(cmat_0$2$q),
        .clock(cmat_0$2$clock)
    );
    top$doptrf$0$add_0$s3_y cmat_0$3(
        .d(cmat_0$3$d),
        .q(cmat_0$3$q),
        .clock(cmat_0$3$clock)
    );
    top$doptrf$0$add_0$s3_y cmat_0$4(
        .d(cmat_0$4$d),
        .q(cmat_0$4$q),
        .clock(cmat_0$4$clock)
    );
    top$doptrf$0$add_0$s3_y cmat_0$5(
        .d(cmat_0$5$d),
        .q(cmat_0$5$q),
        .clock(cmat_0$5$clock)
    );
    top$doptrf$0$add_0$s3_y cmat_0$6(
        .d(cmat_0$6$d),
        .q(cmat_0$6$q),
        .clock(cmat_0$6$clock)
    );
    top$doptrf$0$add_0$s3_y cmat_0$7(
        .d(cmat_0$7$d),
        .q(cmat_0$7$q),
        .clock(cmat_0$7$clock)
    );
    top$doptrf$0$add_0$s3_y cmat_0$8(
        .d(cmat_0$8$d),
        .q(cmat_0$8$q),
        .clock(cmat_0$8$clock)
    );
    top$doptrf$0$add_0$s3_y cmat_0$9(
        .d(cmat_0$9$d),
        .q(cmat_0$9$q),
        .clock(cmat_0$9$clock)
    );
    top$doptrf$0$add_0$s3_y cmat_0$10(
        .d(cmat_0$10$d),
        .q(cmat_0$10$q),
        .clock(cmat_0$10$clock)
    );
    top$doptrf$0$add_0$s3_y cmat_0$11(
        .d(cmat_0$11$d),
        .q(cmat_0$11$q),
        .clock(cmat_0$11$clock)
    );
    top$doptrf$0$add_0$s3_y cmat_0$12(
        .d(cmat_0$12$d),
        .q(cmat_0$12$q),
        .clock(cmat_0$12$clock)
    );
    top$doptrf$0$add_0$s3_y cmat_0$13(
        .d(cmat_0$13$d),
        .q(cmat_0$13$q),
        .clock(cmat_0$13$clock)
    );
    top$doptrf$0$add_0$s3_y cmat_0$14(
        .d(cmat_0$14$d),
        .q(cmat_0$14$q),
        .clock(cmat_0$14$clock)
    );
    top$doptrf$0$add_0$s3_y cmat_0$15(
        .d(cmat_0$15$d),
        .q(cmat_0$15$q),
        .clock(cmat_0$15$clock)
    );
    top$doptrf$0$add_0$s3_y cmat_0$16(
        .d(cmat_0$16$d),
        .q(cmat_0$16$q),
        .clock(cmat_0$16$clock)
    );
    top$doptrf$0$add_0$s3_y cmat_0$17(
        .d(cmat_0$17$d),
        .q(cmat_0$17$q),
        .clock(cmat_0$17$clock)
    );
    top$doptrf$0$add_0$s3_y cmat_0$18(
        .d(cmat_0$18$d),
        .q(cmat_0$18$q),
        .clock(cmat_0$18$clock)
    );
    top$doptrf$0$add_0$s3_y cmat_0$19(
        .d(cmat_0$19$d),
        .q(cmat_0$19$q),
        .clock(cmat_0$19$clock)
    );
    top$doptrf$0$add_0$s3_y cmat_0$20(
        .d(cmat_0$20$d),
        .q(cmat_0$20$q),
        .clock(cmat_0$20$clock)
    );
    top$doptrf$0$add_0$s3_y cmat_0$21(
        .d(cmat_0$21$d),
        .q(cmat_0$21$q),
        .clock(cmat_0$21$clock)
    );
    top$doptrf$0$add_0$s3_y cmat_0$22(
        .d(cmat_0$22$d),
        .q(cmat_0$22$q),
        .clock(cmat_0$22$clock)
    );
    top$doptrf$0$add_0$s3_y cmat_0$23(
        .d(cmat_0$23$d),
        .q(cmat_0$23$q),
        .clock(cmat_0$23$clock)
    );
    top$doptrf$0$add_0$s3_y cmat_1$0(
        .d(cmat_1$0$d),
        .q(cmat_1$0$q),
        .clock(cmat_1$0$clock)
    );
    top$doptrf$0$add_0$s3_y cmat_1$1(
        .d(cmat_1$1$d),
        .q(cmat_1$1$q),
        .clock(cmat_1$1$clock)
    );
    top$doptrf$0$add_0$s3_y cmat_1$2(
        .d(cmat_1$2$d),
        .q(cmat_1$2$q),
        .clock(cmat_1$2$clock)
    );
    top$doptrf$0$add_0$s3_y cmat_1$3(
        .d(cmat_1$3$d),
        .q(cmat_1$3$q),
        .clock(cmat_1$3$clock)
    );
    top$doptrf$0$add_0$s3_y cmat_1$4(
        .d(cmat_1$4$d),
        .q(cmat_1$4$q),
        .clock(cmat_1$4$clock)
    );
    top$doptrf$0$add_0$s3_y cmat_1$5(
        .d(cmat_1$5$d),
        .q(cmat_1$5$q),
        .clock(cmat_1$5$clock)
    );
    top$doptrf$0$add_0$s3_y cmat_1$6(
        .d(cmat_1$6$d),
        .q(cmat_1$6$q),
        .clock(cmat_1$6$clock)
    );
    top$doptrf$0$add_0$s3_y cmat_1$7(
        .d(cmat_1$7$d),
        .q(cmat_1$7$q),
        .clock(cmat_1$7$clock)
    );
    top$doptrf$0$add_0$s3_y cmat_1$8(
        .d(cmat_1$8$d),
        .q(cmat_1$8$q),
        .clock(cmat_1$8$clock)
    );
    top$doptrf$0$add_0$s3_y cmat_1$9(
        .d(cmat_1$9$d),
        .q(cmat_1$9$q),
        .clock(cmat_1$9$clock)
    );
    top$doptrf$0$add_0$s3_y cmat_1$10(
        .d(cmat_1$10$d),
        .q(cmat_1$10$q),
        .clock(cmat_1$10$clock)
    );
    top$doptrf$0$add_0$s3_y cmat_1$11(
        .d(cmat_1$11$d),
        .q(cmat_1$11$q),
        .clock(cmat_1$11$clock)
    );
    top$doptrf$0$add_0$s3_y cmat_1$12(
        .d(cmat_1$12$d),
        .q(cmat_1$12$q),
        .clock(cmat_1$12$clock)
    );
    top$doptrf$0$add_0$s3_y cmat_1$13(
        .d(cmat_1$13$d),
        .q(cmat_1$13$q),
        .clock(cmat_1$13$clock)
    );
    top$doptrf$0$add_0$s3_y cmat_1$14(
        .d(cmat_1$14$d),
        .q(cmat_1$14$q),
        .clock(cmat_1$14$clock)
    );
    top$doptrf$0$add_0$s3_y cmat_1$15(
        .d(cmat_1$15$d),
        .q(cmat_1$15$q),
        .clock(cmat_1$15$clock)
    );
    top$doptrf$0$add_0$s3_y cmat_1$16(
        .d(cmat_1$16$d),
        .q(cmat_1$16$q),
        .clock(cmat_1$16$clock)
    );
    top$doptrf$0$add_0$s3_y cmat_1$17(
        .d(cmat_1$17$d),
        .q(cmat_1$17$q),
        .clock(cmat_1$17$clock)
    );
    top$doptrf$0$add_0$s3_y cmat_1$18(
        .d(cmat_1$18$d),
        .q(cmat_1$18$q),
        .clock(cmat_1$18$clock)
    );
    top$doptrf$0$add_0$s3_y cmat_1$19(
        .d(cmat_1$19$d),
        .q(cmat_1$19$q),
        .clock(cmat_1$19$clock)
    );
    top$doptrf$0$add_0$s3_y cmat_1$20(
        .d(cmat_1$20$d),
        .q(cmat_1$20$q),
        .clock(cmat_1$20$clock)
    );
    top$doptrf$0$add_0$s3_y cmat_1$21(
        .d(cmat_1$21$d),
        .q(cmat_1$21$q),
        .clock(cmat_1$21$clock)
    );
    top$doptrf$0$add_0$s3_y cmat_1$22(
        .d(cmat_1$22$d),
        .q(cmat_1$22$q),
        .clock(cmat_1$22$clock)
    );
    top$doptrf$0$add_0$s3_y cmat_1$23(
        .d(cmat_1$23$d),
        .q(cmat_1$23$q),
        .clock(cmat_1$23$clock)
    );
    top$doptrf$0$add_0$s3_y cmat_2$0(
        .d(cmat_2$0$d),
        .q(cmat_2$0$q),
        .clock(cmat_2$0$clock)
    );
    top$doptrf$0$add_0$s3_y cmat_2$1(
        .d(cmat_2$1$d),
        .q(cmat_2$1$q),
        .clock(cmat_2$1$clock)
    );
    top$doptrf$0$add_0$s3_y cmat_2$2(
        .d(cmat_2$2$d),
        .q(cmat_2$2$q),
        .clock(cmat_2$2$clock)
    );
    top$doptrf$0$add_0$s3_y cmat_2$3(
        .d(cmat_2$3$d),
        .q(cmat_2$3$q),
        .clock(cmat_2$3$clock)
    );
    top$doptrf$0$add_0$s3_y cmat_2$4(
        .d(cmat_2$4$d),
        .q(cmat_2$4$q),
        .clock(cmat_2$4$clock)
    );
    top$doptrf$0$add_0$s3_y cmat_2$5(
        .d(cmat_2$5$d),
        .q(cmat_2$5$q),
        .clock(cmat_2$5$clock)
    );
    top$doptrf$0$add_0$s3_y cmat_2$6(
        .d(cmat_2$6$d),
        .q(cmat_2$6$q),
        .clock(cmat_2$6$clock)
    );
    top$doptrf$0$add_0$s3_y cmat_2$7(
        .d(cmat_2$7$d),
        .q(cmat_2$7$q),
        .clock(cmat_2$7$clock)
    );
    top$doptrf$0$add_0$s3_y cmat_2$8(
        .d(cmat_2$8$d),
        .q(cmat_2$8$q),
        .clock(cmat_2$8$clock)
    );
    top$doptrf$0$add_0$s3_y cmat_2$9(
        .d(cmat_2$9$d),
        .q(cmat_2$9$q),
        .clock(cmat_2$9$clock)
    );
    top$doptrf$0$add_0$s3_y cmat_2$10(
        .d(cmat_2$10$d),
        .q(cmat_2$10$q),
        .clock(cmat_2$10$clock)
    );
    top$doptrf$0$add_0$s3_y cmat_2$11(
        .d(cmat_2$11$d),
        .q(cmat_2$11$q),
        .clock(cmat_2$11$clock)
    );
    top$doptrf$0$add_0$s3_y cmat_2$12(
        .d(cmat_2$12$d),
        .q(cmat_2$12$q),
        .clock(cmat_2$12$clock)
    );
    top$doptrf$0$add_0$s3_y cmat_2$13(
        .d(cmat_2$13$d),
        .q(cmat_2$13$q),
        .clock(cmat_2$13$clock)
    );
    top$doptrf$0$add_0$s3_y cmat_2$14(
        .d(cmat_2$14$d),
        .q(cmat_2$14$q),
        .clock(cmat_2$14$clock)
    );
    top$doptrf$0$add_0$s3_y cmat_2$15(
        .d(cmat_2$15$d),
        .q(cmat_2$15$q),
        .clock(cmat_2$15$clock)
    );
    top$doptrf$0$add_0$s3_y cmat_2$16(
        .d(cmat_2$16$d),
        .q(cmat_2$16$q),
        .clock(cmat_2$16$clock)
    );
    top$doptrf$0$add_0$s3_y cmat_2$17(
        .d(cmat_2$17$d),
        .q(cmat_2$17$q),
        .clock(cmat_2$17$clock)
    );
    top$doptrf$0$add_0$s3_y cmat_2$18(
        .d(cmat_2$18$d),
        .q(cmat_2$18$q),
        .clock(cmat_2$18$clock)
    );
    top$doptrf$0$add_0$s3_y cmat_2$19(
        .d(cmat_2$19$d),
        .q(cmat_2$19$q),
        .clock(cmat_2$19$clock)
    );
    top$doptrf$0$add_0$s3_y cmat_2$20(
        .d(cmat_2$20$d),
        .q(cmat_2$20$q),
        .clock(cmat_2$20$clock)
    );
    top$doptrf$0$add_0$s3_y cmat_2$21(
        .d(cmat_2$21$d),
        .q(cmat_2$21$q),
        .clock(cmat_2$21$clock)
    );
    top$doptrf$0$add_0$s3_y cmat_2$22(
        .d(cmat_2$22$d),
        .q(cmat_2$22$q),
        .clock(cmat_2$22$clock)
    );
    top$doptrf$0$add_0$s3_y cmat_2$23(
        .d(cmat_2$23$d),
        .q(cmat_2$23$q),
        .clock(cmat_2$23$clock)
    );
    top$doptrf$0$add_0$s3_y cvec$0(
        .d(cvec$0$d),
        .q(cvec$0$q),
        .clock(cvec$0$clock)
    );
    top$doptrf$0$add_0$s3_y cvec$1(
        .d(cvec$1$d),
        .q(cvec$1$q),
        .clock(cvec$1$clock)
    );
    top$doptrf$0$add_0$s3_y cvec$2(
        .d(cvec$2$d),
        .q(cvec$2$q),
        .clock(cvec$2$clock)
    );
    top$doptrf$0$add_0$s3_y cvec$3(
        .d(cvec$3$d),
        .q(cvec$3$q),
        .clock(cvec$3$clock)
    );
    top$doptrf$0$add_0$s3_y cvec$4(
        .d(cvec$4$d),
        .q(cvec$4$q),
        .clock(cvec$4$clock)
    );
    top$doptrf$0$add_0$s3_y cvec$5(
        .d(cvec$5$d),
        .q(cvec$5$q),
        .clock(cvec$5$clock)
    );
    top$doptrf$0$add_0$s3_y cvec$6(
        .d(cvec$6$d),
        .q(cvec$6$q),
        .clock(cvec$6$clock)
    );
    top$doptrf$0$add_0$s3_y cvec$7(
        .d(cvec$7$d),
        .q(cvec$7$q),
        .clock(cvec$7$clock)
    );
    top$doptrf$0$add_0$s3_y cvec$8(
        .d(cvec$8$d),
        .q(cvec$8$q),
        .clock(cvec$8$clock)
    );
    top$doptrf$0$add_0$s3_y cvec$9(
        .d(cvec$9$d),
        .q(cvec$9$q),
        .clock(cvec$9$clock)
    );
    top$doptrf$0$add_0$s3_y cvec$10(
        .d(cvec$10$d),
        .q(cvec$10$q),
        .clock(cvec$10$clock)
    );
    top$doptrf$0$add_0$s3_y cvec$11(
        .d(cvec$11$d),
        .q(cvec$11$q),
        .clock(cvec$11$clock)
    );
    top$doptrf$0$add_0$s3_y cvec$12(
        .d(cvec$12$d),
        .q(cvec$12$q),
        .clock(cvec$12$clock)
    );
    top$doptrf$0$add_0$s3_y cvec$13(
        .d(cvec$13$d),
        .q(cvec$13$q),
        .clock(cvec$13$clock)
    );
    top$doptrf$0$add_0$s3_y cvec$14(
        .d(cvec$14$d),
        .q(cvec$14$q),
        .clock(cvec$14$clock)
    );
    top$doptrf$0$add_0$s3_y cvec$15(
        .d(cvec$15$d),
        .q(cvec$15$q),
        .clock(cvec$15$clock)
    );
    top$doptrf$0$add_0$s3_y cvec$16(
        .d(cvec$16$d),
        .q(cvec$16$q),
        .clock(cvec$16$clock)
    );
    top$doptrf$0$add_0$s3_y cvec$17(
        .d(cvec$17$d),
        .q(cvec$17$q),
        .clock(cvec$17$clock)
    );
    top$doptrf$0$add_0$s3_y cvec$18(
        .d(cvec$18$d),
        .q(cvec$18$q),
        .clock(cvec$18$clock)
    );
    top$doptrf$0$add_0$s3_y cvec$19(
        .d(cvec$19$d),
        .q(cvec$19$q),
        .clock(cvec$19$clock)
    );
    top$doptrf$0$add_0$s3_y cvec$20(
        .d(cvec$20$d),
        .q(cvec$20$q),
        .clock(cvec$20$clock)
    );
    top$doptrf$0$add_0$s3_y cvec$21(
        .d(cvec$21$d),
        .q(cvec$21$q),
        .clock(cvec$21$clock)
    );
    top$doptrf$0$add_0$s3_y cvec$22(
        .d(cvec$22$d),
        .q(cvec$22$q),
        .clock(cvec$22$clock)
    );
    top$doptrf$0$add_0$s3_y cvec$23(
        .d(cvec$23$d),
        .q(cvec$23$q),
        .clock(cvec$23$clock)
    );
    top$setup$jsel_0$0 jsel_0$0(
        .d(jsel_0$0$d),
        .q(jsel_0$0$q),
        .clock(jsel_0$0$clock)
    );
    top$setup$jsel_0$0 jsel_0$1(
        .d(jsel_0$1$d),
        .q(jsel_0$1$q),
        .clock(jsel_0$1$clock)
    );
    top$setup$jsel_0$0 jsel_0$2(
        .d(jsel_0$2$d),
        .q(jsel_0$2$q),
        .clock(jsel_0$2$clock)
    );
    top$setup$jsel_0$0 jsel_0$3(
        .d(jsel_0$3$d),
        .q(jsel_0$3$q),
        .clock(jsel_0$3$clock)
    );
    top$setup$jsel_0$0 jsel_0$4(
        .d(jsel_0$4$d),
        .q(jsel_0$4$q),
        .clock(jsel_0$4$clock)
    );
    top$setup$jsel_0$0 jsel_0$5(
        .d(jsel_0$5$d),
        .q(jsel_0$5$q),
        .clock(jsel_0$5$clock)
    );
    top$setup$jsel_0$0 jsel_0$6(
        .d(jsel_0$6$d),
        .q(jsel_0$6$q),
        .clock(jsel_0$6$clock)
    );
    top$setup$jsel_0$0 jsel_0$7(
        .d(jsel_0$7$d),
        .q(jsel_0$7$q),
        .clock(jsel_0$7$clock)
    );
    top$setup$jsel_0$0 jsel_0$8(
        .d(jsel_0$8$d),
        .q(jsel_0$8$q),
        .clock(jsel_0$8$clock)
    );
    top$setup$jsel_0$0 jsel_0$9(
        .d(jsel_0$9$d),
        .q(jsel_0$9$q),
        .clock(jsel_0$9$clock)
    );
    top$setup$jsel_0$0 jsel_0$10(
        .d(jsel_0$10$d),
        .q(jsel_0$10$q),
        .clock(jsel_0$10$clock)
    );
    top$setup$jsel_0$0 jsel_0$11(
        .d(jsel_0$11$d),
        .q(jsel_0$11$q),
        .clock(jsel_0$11$clock)
    );
    top$setup$jsel_0$0 jsel_0$12(
        .d(jsel_0$12$d),
        .q(jsel_0$12$q),
        .clock(jsel_0$12$clock)
    );
    top$setup$jsel_0$0 jsel_0$13(
        .d(jsel_0$13$d),
        .q(jsel_0$13$q),
        .clock(jsel_0$13$clock)
    );
    top$setup$jsel_0$0 jsel_0$14(
        .d(jsel_0$14$d),
        .q(jsel_0$14$q),
        .clock(jsel_0$14$clock)
    );
    top$setup$jsel_0$0 jsel_0$15(
        .d(jsel_0$15$d),
        .q(jsel_0$15$q),
        .clock(jsel_0$15$clock)
    );
    top$setup$jsel_0$0 jsel_0$16(
        .d(jsel_0$16$d),
        .q(jsel_0$16$q),
        .clock(jsel_0$16$clock)
    );
    top$setup$jsel_0$0 jsel_0$17(
        .d(jsel_0$17$d),
        .q(jsel_0$17$q),
        .clock(jsel_0$17$clock)
    );
    top$setup$jsel_0$0 jsel_0$18(
        .d(jsel_0$18$d),
        .q(jsel_0$18$q),
        .clock(jsel_0$18$clock)
    );
    top$setup$jsel_0$0 jsel_0$19(
        .d(jsel_0$19$d),
        .q(jsel_0$19$q),
        .clock(jsel_0$19$clock)
    );
    top$setup$jsel_0$0 jsel_0$20(
        .d(jsel_0$20$d),
        .q(jsel_0$20$q),
        .clock(jsel_0$20$clock)
    );
    top$setup$jsel_0$0 jsel_0$21(
        .d(jsel_0$21$d),
        .q(jsel_0$21$q),
        .clock(jsel_0$21$clock)
    );
    top$setup$jsel_0$0 jsel_0$22(
        .d(jsel_0$22$d),
        .q(jsel_0$22$q),
        .clock(jsel_0$22$clock)
    );
    top$setup$jsel_0$0 jsel_0$23(
        .d(jsel_0$23$d),
        .q(jsel_0$23$q),
        .clock(jsel_0$23$clock)
    );
    top$setup$jsel_0$0 jsel_1$0(
        .d(jsel_1$0$d),
        .q(jsel_1$0$q),
        .clock(jsel_1$0$clock)
    );
    top$setup$jsel_0$0 jsel_1$1(
        .d(jsel_1$1$d),
        .q(jsel_1$1$q),
        .clock(jsel_1$1$clock)
    );
    top$setup$jsel_0$0 jsel_1$2(
        .d(jsel_1$2$d),
        .q(jsel_1$2$q),
        .clock(jsel_1$2$clock)
    );
    top$setup$jsel_0$0 jsel_1$3(
        .d(jsel_1$3$d),
        .q(jsel_1$3$q),
        .clock(jsel_1$3$clock)
    );
    top$setup$jsel_0$0 jsel_1$4(
        .d(jsel_1$4$d),
        .q(jsel_1$4$q),
        .clock(jsel_1$4$clock)
    );
    top$setup$jsel_0$0 jsel_1$5(
        .d(jsel_1$5$d),
        .q(jsel_1$5$q),
        .clock(jsel_1$5$clock)
    );
    top$setup$jsel_0$0 jsel_1$6(
        .d(jsel_1$6$d),
        .q(jsel_1$6$q),
        .clock(jsel_1$6$clock)
    );
    top$setup$jsel_0$0 jsel_1$7(
        .d(jsel_1$7$d),
        .q(jsel_1$7$q),
        .clock(jsel_1$7$clock)
    );
    top$setup$jsel_0$0 jsel_1$8(
        .d(jsel_1$8$d),
        .q(jsel_1$8$q),
        .clock(jsel_1$8$clock)
    );
    top$setup$jsel_0$0 jsel_1$9(
        .d(jsel_1$9$d),
        .q(jsel_1$9$q),
        .clock(jsel_1$9$clock)
    );
    top$setup$jsel_0$0 jsel_1$10(
        .d(jsel_1$10$d),
        .q(jsel_1$10$q),
        .clock(jsel_1$10$clock)
    );
    top$setup$jsel_0$0 jsel_1$11(
        .d(jsel_1$11$d),
        .q(jsel_1$11$q),
        .clock(jsel_1$11$clock)
    );
    top$setup$jsel_0$0 jsel_1$12(
        .d(jsel_1$12$d),
        .q(jsel_1$12$q),
        .clock(jsel_1$12$clock)
    );
    top$setup$jsel_0$0 jsel_1$13(
        .d(jsel_1$13$d),
        .q(jsel_1$13$q),
        .clock(jsel_1$13$clock)
    );
    top$setup$jsel_0$0 jsel_1$14(
        .d(jsel_1$14$d),
        .q(jsel_1$14$q),
        .clock(jsel_1$14$clock)
    );
    top$setup$jsel_0$0 jsel_1$15(
        .d(jsel_1$15$d),
        .q(jsel_1$15$q),
        .clock(jsel_1$15$clock)
    );
    top$setup$jsel_0$0 jsel_1$16(
        .d(jsel_1$16$d),
        .q(jsel_1$16$q),
        .clock(jsel_1$16$clock)
    );
    top$setup$jsel_0$0 jsel_1$17(
        .d(jsel_1$17$d),
        .q(jsel_1$17$q),
        .clock(jsel_1$17$clock)
    );
    top$setup$jsel_0$0 jsel_1$18(
        .d(jsel_1$18$d),
        .q(jsel_1$18$q),
        .clock(jsel_1$18$clock)
    );
    top$setup$jsel_0$0 jsel_1$19(
        .d(jsel_1$19$d),
        .q(jsel_1$19$q),
        .clock(jsel_1$19$clock)
    );
    top$setup$jsel_0$0 jsel_1$20(
        .d(jsel_1$20$d),
        .q(jsel_1$20$q),
        .clock(jsel_1$20$clock)
    );
    top$setup$jsel_0$0 jsel_1$21(
        .d(jsel_1$21$d),
        .q(jsel_1$21$q),
        .clock(jsel_1$21$clock)
    );
    top$setup$jsel_0$0 jsel_1$22(
        .d(jsel_1$22$d),
        .q(jsel_1$22$q),
        .clock(jsel_1$22$clock)
    );
    top$setup$jsel_0$0 jsel_1$23(
        .d(jsel_1$23$d),
        .q(jsel_1$23$q),
        .clock(jsel_1$23$clock)
    );
    top$setup$jsel_0$0 jsel_2$0(
        .d(jsel_2$0$d),
        .q(jsel_2$0$q),
        .clock(jsel_2$0$clock)
    );
    top$setup$jsel_0$0 jsel_2$1(
        .d(jsel_2$1$d),
        .q(jsel_2$1$q),
        .clock(jsel_2$1$clock)
    );
    top$setup$jsel_0$0 jsel_2$2(
        .d(jsel_2$2$d),
        .q(jsel_2$2$q),
        .clock(jsel_2$2$clock)
    );
    top$setup$jsel_0$0 jsel_2$3(
        .d(jsel_2$3$d),
        .q(jsel_2$3$q),
        .clock(jsel_2$3$clock)
    );
    top$setup$jsel_0$0 jsel_2$4(
        .d(jsel_2$4$d),
        .q(jsel_2$4$q),
        .clock(jsel_2$4$clock)
    );
    top$setup$jsel_0$0 jsel_2$5(
        .d(jsel_2$5$d),
        .q(jsel_2$5$q),
        .clock(jsel_2$5$clock)
    );
    top$setup$jsel_0$0 jsel_2$6(
        .d(jsel_2$6$d),
        .q(jsel_2$6$q),
        .clock(jsel_2$6$clock)
    );
    top$setup$jsel_0$0 jsel_2$7(
        .d(jsel_2$7$d),
        .q(jsel_2$7$q),
        .clock(jsel_2$7$clock)
    );
    top$setup$jsel_0$0 jsel_2$8(
        .d(jsel_2$8$d),
        .q(jsel_2$8$q),
        .clock(jsel_2$8$clock)
    );
    top$setup$jsel_0$0 jsel_2$9(
        .d(jsel_2$9$d),
        .q(jsel_2$9$q),
        .clock(jsel_2$9$clock)
    );
    top$setup$jsel_0$0 jsel_2$10(
        .d(jsel_2$10$d),
        .q(jsel_2$10$q),
        .clock(jsel_2$10$clock)
    );
    top$setup$jsel_0$0 jsel_2$11(
        .d(jsel_2$11$d),
        .q(jsel_2$11$q),
        .clock(jsel_2$11$clock)
    );
    top$setup$jsel_0$0 jsel_2$12(
        .d(jsel_2$12$d),
        .q(jsel_2$12$q),
        .clock(jsel_2$12$clock)
    );
    top$setup$jsel_0$0 jsel_2$13(
        .d(jsel_2$13$d),
        .q(jsel_2$13$q),
        .clock(jsel_2$13$clock)
    );
    top$setup$jsel_0$0 jsel_2$14(
        .d(jsel_2$14$d),
        .q(jsel_2$14$q),
        .clock(jsel_2$14$clock)
    );
    top$setup$jsel_0$0 jsel_2$15(
        .d(jsel_2$15$d),
        .q(jsel_2$15$q),
        .clock(jsel_2$15$clock)
    );
    top$setup$jsel_0$0 jsel_2$16(
        .d(jsel_2$16$d),
        .q(jsel_2$16$q),
        .clock(jsel_2$16$clock)
    );
    top$setup$jsel_0$0 jsel_2$17(
        .d(jsel_2$17$d),
        .q(jsel_2$17$q),
        .clock(jsel_2$17$clock)
    );
    top$setup$jsel_0$0 jsel_2$18(
        .d(jsel_2$18$d),
        .q(jsel_2$18$q),
        .clock(jsel_2$18$clock)
    );
    top$setup$jsel_0$0 jsel_2$19(
        .d(jsel_2$19$d),
        .q(jsel_2$19$q),
        .clock(jsel_2$19$clock)
    );
    top$setup$jsel_0$0 jsel_2$20(
        .d(jsel_2$20$d),
        .q(jsel_2$20$q),
        .clock(jsel_2$20$clock)
    );
    top$setup$jsel_0$0 jsel_2$21(
        .d(jsel_2$21$d),
        .q(jsel_2$21$q),
        .clock(jsel_2$21$clock)
    );
    top$setup$jsel_0$0 jsel_2$22(
        .d(jsel_2$22$d),
        .q(jsel_2$22$q),
        .clock(jsel_2$22$clock)
    );
    top$setup$jsel_0$0 jsel_2$23(
        .d(jsel_2$23$d),
        .q(jsel_2$23$q),
        .clock(jsel_2$23$clock)
    );
    top$doptrf$0$add_0$s1_eff_sub rnd$0(
        .d(rnd$0$d),
        .q(rnd$0$q),
        .clock(rnd$0$clock)
    );
    top$doptrf$0$add_0$s1_eff_sub rnd$1(
        .d(rnd$1$d),
        .q(rnd$1$q),
        .clock(rnd$1$clock)
    );
    top$doptrf$0$add_0$s1_eff_sub rnd$2(
        .d(rnd$2$d),
        .q(rnd$2$q),
        .clock(rnd$2$clock)
    );
    top$doptrf$0$add_0$s1_eff_sub rnd$3(
        .d(rnd$3$d),
        .q(rnd$3$q),
        .clock(rnd$3$clock)
    );
    top$doptrf$0$add_0$s1_eff_sub rnd$4(
        .d(rnd$4$d),
        .q(rnd$4$q),
        .clock(rnd$4$clock)
    );
    top$doptrf$0$add_0$s1_eff_sub rnd$5(
        .d(rnd$5$d),
        .q(rnd$5$q),
        .clock(rnd$5$clock)
    );
    top$doptrf$0$add_0$s1_eff_sub rnd$6(
        .d(rnd$6$d),
        .q(rnd$6$q),
        .clock(rnd$6$clock)
    );
    top$doptrf$0$add_0$s1_eff_sub rnd$7(
        .d(rnd$7$d),
        .q(rnd$7$q),
        .clock(rnd$7$clock)
    );
    top$doptrf$0$add_0$s1_eff_sub rnd$8(
        .d(rnd$8$d),
        .q(rnd$8$q),
        .clock(rnd$8$clock)
    );
    top$doptrf$0$add_0$s1_eff_sub rnd$9(
        .d(rnd$9$d),
        .q(rnd$9$q),
        .clock(rnd$9$clock)
    );
    top$doptrf$0$add_0$s1_eff_sub rnd$10(
        .d(rnd$10$d),
        .q(rnd$10$q),
        .clock(rnd$10$clock)
    );
    top$doptrf$0$add_0$s1_eff_sub rnd$11(
        .d(rnd$11$d),
        .q(rnd$11$q),
        .clock(rnd$11$clock)
    );
    top$doptrf$0$add_0$s1_eff_sub rnd$12(
        .d(rnd$12$d),
        .q(rnd$12$q),
        .clock(rnd$12$clock)
    );
    top$doptrf$0$add_0$s1_eff_sub rnd$13(
        .d(rnd$13$d),
        .q(rnd$13$q),
        .clock(rnd$13$clock)
    );
    top$doptrf$0$add_0$s1_eff_sub rnd$14(
        .d(rnd$14$d),
        .q(rnd$14$q),
        .clock(rnd$14$clock)
    );
    top$doptrf$0$add_0$s1_eff_sub rnd$15(
        .d(rnd$15$d),
        .q(rnd$15$q),
        .clock(rnd$15$clock)
    );
    top$doptrf$0$add_0$s1_eff_sub rnd$16(
        .d(rnd$16$d),
        .q(rnd$16$q),
        .clock(rnd$16$clock)
    );
    top$doptrf$0$add_0$s1_eff_sub rnd$17(
        .d(rnd$17$d),
        .q(rnd$17$q),
        .clock(rnd$17$clock)
    );
    top$doptrf$0$add_0$s1_eff_sub rnd$18(
        .d(rnd$18$d),
        .q(rnd$18$q),
        .clock(rnd$18$clock)
    );
    top$doptrf$0$add_0$s1_eff_sub rnd$19(
        .d(rnd$19$d),
        .q(rnd$19$q),
        .clock(rnd$19$clock)
    );
    top$doptrf$0$add_0$s1_eff_sub rnd$20(
        .d(rnd$20$d),
        .q(rnd$20$q),
        .clock(rnd$20$clock)
    );
    top$doptrf$0$add_0$s1_eff_sub rnd$21(
        .d(rnd$21$d),
        .q(rnd$21$q),
        .clock(rnd$21$clock)
    );
    top$doptrf$0$add_0$s1_eff_sub rnd$22(
        .d(rnd$22$d),
        .q(rnd$22$q),
        .clock(rnd$22$clock)
    );
    top$doptrf$0$add_0$s1_eff_sub rnd$23(
        .d(rnd$23$d),
        .q(rnd$23$q),
        .clock(rnd$23$clock)
    );
    
    // Update code
    always @(*) begin
        c_lane = load_addr[(32'h3)+:(5)];
        c_field = load_addr[(32'h0)+:(3)];
        cmat_0$0$clock = clock;
        cmat_1$0$clock = clock;
        cmat_2$0$clock = clock;
        cvec$0$clock = clock;
        jsel_0$0$clock = clock;
        jsel_1$0$clock = clock;
        jsel_2$0$clock = clock;
        rnd$0$clock = clock;
        cmat_0$0$d = cmat_0$0$q;
        cmat_1$0$d = cmat_1$0$q;
        cmat_2$0$d = cmat_2$0$q;
        cvec$0$d = cvec$0$q;
        jsel_0$0$d = jsel_0$0$q;
        jsel_1$0$d = jsel_1$0$q;
        jsel_2$0$d = jsel_2$0$q;
        rnd$0$d = rnd$0$q;
        if (load_en & (c_lane == idx$0)) begin
            if (c_field == 32'h0) begin
                cmat_0$0$d = load_data;
            end
            if (c_field == 32'h1) begin
                cmat_1$0$d = load_data;
            end
            if (c_field == 32'h2) begin
                cmat_2$0$d = load_data;
            end
            if (c_field == 32'h3) begin
                cvec$0$d = load_data;
            end
            if (c_field == 32'h4) begin
                jsel_0$0$d = load_data[(32'h0)+:(5)];
                jsel_1$0$d = load_data[(32'h5)+:(5)];
                jsel_2$0$d = load_data[(32'ha)+:(5)];
                rnd$0$d = load_data[32'hf];
            end
        end
        c0$0 = cmat_0$0$q;
        c1$0 = cmat_1$0$q;
        c2$0 = cmat_2$0$q;
        c$0 = cvec$0$q;
        j0$0 = jsel_0$0$q;
        j1$0 = jsel_1$0$q;
        j2$0 = jsel_2$0$q;
        round_up$0 = rnd$0$q;
        cmat_0$1$clock = clock;
        cmat_1$1$clock = clock;
        cmat_2$1$clock = clock;
        cvec$1$clock = clock;
        jsel_0$1$clock = clock;
        jsel_1$1$clock = clock;
        jsel_2$1$clock = clock;
        rnd$1$clock = clock;
        cmat_0$1$d = cmat_0$1$q;
        cmat_1$1$d = cmat_1$1$q;
        cmat_2$1$d = cmat_2$1$q;
        cvec$1$d = cvec$1$q;
        jsel_0$1$d = jsel_0$1$q;
        jsel_1$1$d = jsel_1$1$q;
        jsel_2$1$d = jsel_2$1$q;
        rnd$1$d = rnd$1$q;
        if (load_en & (c_lane == idx$1)) begin
            if (c_field == 32'h0) begin
                cmat_0$1$d = load_data;
            end
            if (c_field == 32'h1) begin
                cmat_1$1$d = load_data;
            end
            if (c_field == 32'h2) begin
                cmat_2$1$d = load_data;
            end
            if (c_field == 32'h3) begin
                cvec$1$d = load_data;
            end
            if (c_field == 32'h4) begin
                jsel_0$1$d = load_data[(32'h0)+:(5)];
                jsel_1$1$d = load_data[(32'h5)+:(5)];
                jsel_2$1$d = load_data[(32'ha)+:(5)];
                rnd$1$d = load_data[32'hf];
            end
        end
        c0$1 = cmat_0$1$q;
        c1$1 = cmat_1$1$q;
        c2$1 = cmat_2$1$q;
        c$1 = cvec$1$q;
        j0$1 = jsel_0$1$q;
        j1$1 = jsel_1$1$q;
        j2$1 = jsel_2$1$q;
        round_up$1 = rnd$1$q;
        cmat_0$2$clock = clock;
        cmat_1$2$clock = clock;
        cmat_2$2$clock = clock;
        cvec$2$clock = clock;
        jsel_0$2$clock = clock;
        jsel_1$2$clock = clock;
        jsel_2$2$clock = clock;
        rnd$2$clock = clock;
        cmat_0$2$d = cmat_0$2$q;
        cmat_1$2$d = cmat_1$2$q;
        cmat_2$2$d = cmat_2$2$q;
        cvec$2$d = cvec$2$q;
        jsel_0$2$d = jsel_0$2$q;
        jsel_1$2$d = jsel_1$2$q;
        jsel_2$2$d = jsel_2$2$q;
        rnd$2$d = rnd$2$q;
        if (load_en & (c_lane == idx$2)) begin
            if (c_field == 32'h0) begin
                cmat_0$2$d = load_data;
            end
            if (c_field == 32'h1) begin
                cmat_1$2$d = load_data;
            end
            if (c_field == 32'h2) begin
                cmat_2$2$d = load_data;
            end
            if (c_field == 32'h3) begin
                cvec$2$d = load_data;
            end
            if (c_field == 32'h4) begin
                jsel_0$2$d = load_data[(32'h0)+:(5)];
                jsel_1$2$d = load_data[(32'h5)+:(5)];
                jsel_2$2$d = load_data[(32'ha)+:(5)];
                rnd$2$d = load_data[32'hf];
            end
        end
        c0$2 = cmat_0$2$q;
        c1$2 = cmat_1$2$q;
        c2$2 = cmat_2$2$q;
        c$2 = cvec$2$q;
        j0$2 = jsel_0$2$q;
        j1$2 = jsel_1$2$q;
        j2$2 = jsel_2$2$q;
        round_up$2 = rnd$2$q;
        cmat_0$3$clock = clock;
        cmat_1$3$clock = clock;
        cmat_2$3$clock = clock;
        cvec$3$clock = clock;
        jsel_0$3$clock = clock;
        jsel_1$3$clock = clock;
        jsel_2$3$clock = clock;
        rnd$3$clock = clock;
        cmat_0$3$d = cmat_0$3$q;
        cmat_1$3$d = cmat_1$3$q;
        cmat_2$3$d = cmat_2$3$q;
        cvec$3$d = cvec$3$q;
        jsel_0$3$d = jsel_0$3$q;
        jsel_1$3$d = jsel_1$3$q;
        jsel_2$3$d = jsel_2$3$q;
        rnd$3$d = rnd$3$q;
        if (load_en & (c_lane == idx$3)) begin
            if (c_field == 32'h0) begin
                cmat_0$3$d = load_data;
            end
            if (c_field == 32'h1) begin
                cmat_1$3$d = load_data;
            end
            if (c_field == 32'h2) begin
                cmat_2$3$d = load_data;
            end
            if (c_field == 32'h3) begin
                cvec$3$d = load_data;
            end
            if (c_field == 32'h4) begin
                jsel_0$3$d = load_data[(32'h0)+:(5)];
                jsel_1$3$d = load_data[(32'h5)+:(5)];
                jsel_2$3$d = load_data[(32'ha)+:(5)];
                rnd$3$d = load_data[32'hf];
            end
        end
        c0$3 = cmat_0$3$q;
        c1$3 = cmat_1$3$q;
        c2$3 = cmat_2$3$q;
        c$3 = cvec$3$q;
        j0$3 = jsel_0$3$q;
        j1$3 = jsel_1$3$q;
        j2$3 = jsel_2$3$q;
        round_up$3 = rnd$3$q;
        cmat_0$4$clock = clock;
        cmat_1$4$clock = clock;
        cmat_2$4$clock = clock;
        cvec$4$clock = clock;
        jsel_0$4$clock = clock;
        jsel_1$4$clock = clock;
        jsel_2$4$clock = clock;
        rnd$4$clock = clock;
        cmat_0$4$d = cmat_0$4$q;
        cmat_1$4$d = cmat_1$4$q;
        cmat_2$4$d = cmat_2$4$q;
        cvec$4$d = cvec$4$q;
        jsel_0$4$d = jsel_0$4$q;
        jsel_1$4$d = jsel_1$4$q;
        jsel_2$4$d = jsel_2$4$q;
        rnd$4$d = rnd$4$q;
        if (load_en & (c_lane == idx$4)) begin
            if (c_field == 32'h0) begin
                cmat_0$4$d = load_data;
            end
            if (c_field == 32'h1) begin
                cmat_1$4$d = load_data;
            end
            if (c_field == 32'h2) begin
                cmat_2$4$d = load_data;
            end
            if (c_field == 32'h3) begin
                cvec$4$d = load_data;
            end
            if (c_field == 32'h4) begin
                jsel_0$4$d = load_data[(32'h0)+:(5)];
                jsel_1$4$d = load_data[(32'h5)+:(5)];
                jsel_2$4$d = load_data[(32'ha)+:(5)];
                rnd$4$d = load_data[32'hf];
            end
        end
        c0$4 = cmat_0$4$q;
        c1$4 = cmat_1$4$q;
        c2$4 = cmat_2$4$q;
        c$4 = cvec$4$q;
        j0$4 = jsel_0$4$q;
        j1$4 = jsel_1$4$q;
        j2$4 = jsel_2$4$q;
        round_up$4 = rnd$4$q;
        cmat_0$5$clock = clock;
        cmat_1$5$clock = clock;
        cmat_2$5$clock = clock;
        cvec$5$clock = clock;
        jsel_0$5$clock = clock;
        jsel_1$5$clock = clock;
        jsel_2$5$clock = clock;
        rnd$5$clock = clock;
        cmat_0$5$d = cmat_0$5$q;
        cmat_1$5$d = cmat_1$5$q;
        cmat_2$5$d = cmat_2$5$q;
        cvec$5$d = cvec$5$q;
        jsel_0$5$d = jsel_0$5$q;
        jsel_1$5$d = jsel_1$5$q;
        jsel_2$5$d = jsel_2$5$q;
        rnd$5$d = rnd$5$q;
        if (load_en & (c_lane == idx$5)) begin
            if (c_field == 32'h0) begin
                cmat_0$5$d = load_data;
            end
            if (c_field == 32'h1) begin
                cmat_1$5$d = load_data;
            end
            if (c_field == 32'h2) begin
                cmat_2$5$d = load_data;
            end
            if (c_field == 32'h3) begin
                cvec$5$d = load_data;
            end
            if (c_field == 32'h4) begin
                jsel_0$5$d = load_data[(32'h0)+:(5)];
                jsel_1$5$d = load_data[(32'h5)+:(5)];
                jsel_2$5$d = load_data[(32'ha)+:(5)];
                rnd$5$d = load_data[32'hf];
            end
        end
        c0$5 = cmat_0$5$q;
        c1$5 = cmat_1$5$q;
        c2$5 = cmat_2$5$q;
        c$5 = cvec$5$q;
        j0$5 = jsel_0$5$q;
        j1$5 = jsel_1$5$q;
        j2$5 = jsel_2$5$q;
        round_up$5 = rnd$5$q;
        cmat_0$6$clock = clock;
        cmat_1$6$clock = clock;
        cmat_2$6$clock = clock;
        cvec$6$clock = clock;
        jsel_0$6$clock = clock;
        jsel_1$6$clock = clock;
        jsel_2$6$clock = clock;
        rnd$6$clock = clock;
        cmat_0$6$d = cmat_0$6$q;
        cmat_1$6$d = cmat_1$6$q;
        cmat_2$6$d = cmat_2$6$q;
        cvec$6$d = cvec$6$q;
        jsel_0$6$d = jsel_0$6$q;
        jsel_1$6$d = jsel_1$6$q;
        jsel_2$6$d = jsel_2$6$q;
        rnd$6$d = rnd$6$q;
        if (load_en & (c_lane == idx$6)) begin
            if (c_field == 32'h0) begin
                cmat_0$6$d = load_data;
            end
            if (c_field == 32'h1) begin
                cmat_1$6$d = load_data;
            end
            if (c_field == 32'h2) begin
                cmat_2$6$d = load_data;
            end
            if (c_field == 32'h3) begin
                cvec$6$d = load_data;
            end
            if (c_field == 32'h4) begin
                jsel_0$6$d = load_data[(32'h0)+:(5)];
                jsel_1$6$d = load_data[(32'h5)+:(5)];
                jsel_2$6$d = load_data[(32'ha)+:(5)];
                rnd$6$d = load_data[32'hf];
            end
        end
        c0$6 = cmat_0$6$q;
        c1$6 = cmat_1$6$q;
        c2$6 = cmat_2$6$q;
        c$6 = cvec$6$q;
        j0$6 = jsel_0$6$q;
        j1$6 = jsel_1$6$q;
        j2$6 = jsel_2$6$q;
        round_up$6 = rnd$6$q;
        cmat_0$7$clock = clock;
        cmat_1$7$clock = clock;
        cmat_2$7$clock = clock;
        cvec$7$clock = clock;
        jsel_0$7$clock = clock;
        jsel_1$7$clock = clock;
        jsel_2$7$clock = clock;
        rnd$7$clock = clock;
        cmat_0$7$d = cmat_0$7$q;
        cmat_1$7$d = cmat_1$7$q;
        cmat_2$7$d = cmat_2$7$q;
        cvec$7$d = cvec$7$q;
        jsel_0$7$d = jsel_0$7$q;
        jsel_1$7$d = jsel_1$7$q;
        jsel_2$7$d = jsel_2$7$q;
        rnd$7$d = rnd$7$q;
        if (load_en & (c_lane == idx$7)) begin
            if (c_field == 32'h0) begin
                cmat_0$7$d = load_data;
            end
            if (c_field == 32'h1) begin
                cmat_1$7$d = load_data;
            end
            if (c_field == 32'h2) begin
                cmat_2$7$d = load_data;
            end
            if (c_field == 32'h3) begin
                cvec$7$d = load_data;
            end
            if (c_field == 32'h4) begin
                jsel_0$7$d = load_data[(32'h0)+:(5)];
                jsel_1$7$d = load_data[(32'h5)+:(5)];
                jsel_2$7$d = load_data[(32'ha)+:(5)];
                rnd$7$d = load_data[32'hf];
            end
        end
        c0$7 = cmat_0$7$q;
        c1$7 = cmat_1$7$q;
        c2$7 = cmat_2$7$q;
        c$7 = cvec$7$q;
        j0$7 = jsel_0$7$q;
        j1$7 = jsel_1$7$q;
        j2$7 = jsel_2$7$q;
        round_up$7 = rnd$7$q;
        cmat_0$8$clock = clock;
        cmat_1$8$clock = clock;
        cmat_2$8$clock = clock;
        cvec$8$clock = clock;
        jsel_0$8$clock = clock;
        jsel_1$8$clock = clock;
        jsel_2$8$clock = clock;
        rnd$8$clock = clock;
        cmat_0$8$d = cmat_0$8$q;
        cmat_1$8$d = cmat_1$8$q;
        cmat_2$8$d = cmat_2$8$q;
        cvec$8$d = cvec$8$q;
        jsel_0$8$d = jsel_0$8$q;
        jsel_1$8$d = jsel_1$8$q;
        jsel_2$8$d = jsel_2$8$q;
        rnd$8$d = rnd$8$q;
        if (load_en & (c_lane == idx$8)) begin
            if (c_field == 32'h0) begin
                cmat_0$8$d = load_data;
            end
            if (c_field == 32'h1) begin
                cmat_1$8$d = load_data;
            end
            if (c_field == 32'h2) begin
                cmat_2$8$d = load_data;
            end
            if (c_field == 32'h3) begin
                cvec$8$d = load_data;
            end
            if (c_field == 32'h4) begin
                jsel_0$8$d = load_data[(32'h0)+:(5)];
                jsel_1$8$d = load_data[(32'h5)+:(5)];
                jsel_2$8$d = load_data[(32'ha)+:(5)];
                rnd$8$d = load_data[32'hf];
            end
        end
        c0$8 = cmat_0$8$q;
        c1$8 = cmat_1$8$q;
        c2$8 = cmat_2$8$q;
        c$8 = cvec$8$q;
        j0$8 = jsel_0$8$q;
        j1$8 = jsel_1$8$q;
        j2$8 = jsel_2$8$q;
        round_up$8 = rnd$8$q;
        cmat_0$9$clock = clock;
        cmat_1$9$clock = clock;
        cmat_2$9$clock = clock;
        cvec$9$clock = clock;
        jsel_0$9$clock = clock;
        jsel_1$9$clock = clock;
        jsel_2$9$clock = clock;
        rnd$9$clock = clock;
        cmat_0$9$d = cmat_0$9$q;
        cmat_1$9$d = cmat_1$9$q;
        cmat_2$9$d = cmat_2$9$q;
        cvec$9$d = cvec$9$q;
        jsel_0$9$d = jsel_0$9$q;
        jsel_1$9$d = jsel_1$9$q;
        jsel_2$9$d = jsel_2$9$q;
        rnd$9$d = rnd$9$q;
        if (load_en & (c_lane == idx$9)) begin
            if (c_field == 32'h0) begin
                cmat_0$9$d = load_data;
            end
            if (c_field == 32'h1) begin
                cmat_1$9$d = load_data;
            end
            if (c_field == 32'h2) begin
                cmat_2$9$d = load_data;
            end
            if (c_field == 32'h3) begin
                cvec$9$d = load_data;
            end
            if (c_field == 32'h4) begin
                jsel_0$9$d = load_data[(32'h0)+:(5)];
                jsel_1$9$d = load_data[(32'h5)+:(5)];
                jsel_2$9$d = load_data[(32'ha)+:(5)];
                rnd$9$d = load_data[32'hf];
            end
        end
        c0$9 = cmat_0$9$q;
        c1$9 = cmat_1$9$q;
        c2$9 = cmat_2$9$q;
        c$9 = cvec$9$q;
        j0$9 = jsel_0$9$q;
        j1$9 = jsel_1$9$q;
        j2$9 = jsel_2$9$q;
        round_up$9 = rnd$9$q;
        cmat_0$10$clock = clock;
        cmat_1$10$clock = clock;
        cmat_2$10$clock = clock;
        cvec$10$clock = clock;
        jsel_0$10$clock = clock;
        jsel_1$10$clock = clock;
        jsel_2$10$clock = clock;
        rnd$10$clock = clock;
        cmat_0$10$d = cmat_0$10$q;
        cmat_1$10$d = cmat_1$10$q;
        cmat_2$10$d = cmat_2$10$q;
        cvec$10$d = cvec$10$q;
        jsel_0$10$d = jsel_0$10$q;
        jsel_1$10$d = jsel_1$10$q;
        jsel_2$10$d = jsel_2$10$q;
        rnd$10$d = rnd$10$q;
        if (load_en & (c_lane == idx$10)) begin
            if (c_field == 32'h0) begin
                cmat_0$10$d = load_data;
            end
            if (c_field == 32'h1) begin
                cmat_1$10$d = load_data;
            end
            if (c_field == 32'h2) begin
                cmat_2$10$d = load_data;
            end
            if (c_field == 32'h3) begin
                cvec$10$d = load_data;
            end
            if (c_field == 32'h4) begin
                jsel_0$10$d = load_data[(32'h0)+:(5)];
                jsel_1$10$d = load_data[(32'h5)+:(5)];
                jsel_2$10$d = load_data[(32'ha)+:(5)];
                rnd$10$d = load_data[32'hf];
            end
        end
        c0$10 = cmat_0$10$q;
        c1$10 = cmat_1$10$q;
        c2$10 = cmat_2$10$q;
        c$10 = cvec$10$q;
        j0$10 = jsel_0$10$q;
        j1$10 = jsel_1$10$q;
        j2$10 = jsel_2$10$q;
        round_up$10 = rnd$10$q;
        cmat_0$11$clock = clock;
        cmat_1$11$clock = clock;
        cmat_2$11$clock = clock;
        cvec$11$clock = clock;
        jsel_0$11$clock = clock;
        jsel_1$11$clock = clock;
        jsel_2$11$clock = clock;
        rnd$11$clock = clock;
        cmat_0$11$d = cmat_0$11$q;
        cmat_1$11$d = cmat_1$11$q;
        cmat_2$11$d = cmat_2$11$q;
        cvec$11$d = cvec$11$q;
        jsel_0$11$d = jsel_0$11$q;
        jsel_1$11$d = jsel_1$11$q;
        jsel_2$11$d = jsel_2$11$q;
        rnd$11$d = rnd$11$q;
        if (load_en & (c_lane == idx$11)) begin
            if (c_field == 32'h0) begin
                cmat_0$11$d = load_data;
            end
            if (c_field == 32'h1) begin
                cmat_1$11$d = load_data;
            end
            if (c_field == 32'h2) begin
                cmat_2$11$d = load_data;
            end
            if (c_field == 32'h3) begin
                cvec$11$d = load_data;
            end
            if (c_field == 32'h4) begin
                jsel_0$11$d = load_data[(32'h0)+:(5)];
                jsel_1$11$d = load_data[(32'h5)+:(5)];
                jsel_2$11$d = load_data[(32'ha)+:(5)];
                rnd$11$d = load_data[32'hf];
            end
        end
        c0$11 = cmat_0$11$q;
        c1$11 = cmat_1$11$q;
        c2$11 = cmat_2$11$q;
        c$11 = cvec$11$q;
        j0$11 = jsel_0$11$q;
        j1$11 = jsel_1$11$q;
        j2$11 = jsel_2$11$q;
        round_up$11 = rnd$11$q;
        cmat_0$12$clock = clock;
        cmat_1$12$clock = clock;
        cmat_2$12$clock = clock;
        cvec$12$clock = clock;
        jsel_0$12$clock = clock;
        jsel_1$12$clock = clock;
        jsel_2$12$clock = clock;
        rnd$12$clock = clock;
        cmat_0$12$d = cmat_0$12$q;
        cmat_1$12$d = cmat_1$12$q;
        cmat_2$12$d = cmat_2$12$q;
        cvec$12$d = cvec$12$q;
        jsel_0$12$d = jsel_0$12$q;
        jsel_1$12$d = jsel_1$12$q;
        jsel_2$12$d = jsel_2$12$q;
        rnd$12$d = rnd$12$q;
        if (load_en & (c_lane == idx$12)) begin
            if (c_field == 32'h0) begin
                cmat_0$12$d = load_data;
            end
            if (c_field == 32'h1) begin
                cmat_1$12$d = load_data;
            end
            if (c_field == 32'h2) begin
                cmat_2$12$d = load_data;
            end
            if (c_field == 32'h3) begin
                cvec$12$d = load_data;
            end
            if (c_field == 32'h4) begin
                jsel_0$12$d = load_data[(32'h0)+:(5)];
                jsel_1$12$d = load_data[(32'h5)+:(5)];
                jsel_2$12$d = load_data[(32'ha)+:(5)];
                rnd$12$d = load_data[32'hf];
            end
        end
        c0$12 = cmat_0$12$q;
        c1$12 = cmat_1$12$q;
        c2$12 = cmat_2$12$q;
        c$12 = cvec$12$q;
        j0$12 = jsel_0$12$q;
        j1$12 = jsel_1$12$q;
        j2$12 = jsel_2$12$q;
        round_up$12 = rnd$12$q;
        cmat_0$13$clock = clock;
        cmat_1$13$clock = clock;
        cmat_2$13$clock = clock;
        cvec$13$clock = clock;
        jsel_0$13$clock = clock;
        jsel_1$13$clock = clock;
        jsel_2$13$clock = clock;
        rnd$13$clock = clock;
        cmat_0$13$d = cmat_0$13$q;
        cmat_1$13$d = cmat_1$13$q;
        cmat_2$13$d = cmat_2$13$q;
        cvec$13$d = cvec$13$q;
        jsel_0$13$d = jsel_0$13$q;
        jsel_1$13$d = jsel_1$13$q;
        jsel_2$13$d = jsel_2$13$q;
        rnd$13$d = rnd$13$q;
        if (load_en & (c_lane == idx$13)) begin
            if (c_field == 32'h0) begin
                cmat_0$13$d = load_data;
            end
            if (c_field == 32'h1) begin
                cmat_1$13$d = load_data;
            end
            if (c_field == 32'h2) begin
                cmat_2$13$d = load_data;
            end
            if (c_field == 32'h3) begin
                cvec$13$d = load_data;
            end
            if (c_field == 32'h4) begin
                jsel_0$13$d = load_data[(32'h0)+:(5)];
                jsel_1$13$d = load_data[(32'h5)+:(5)];
                jsel_2$13$d = load_data[(32'ha)+:(5)];
                rnd$13$d = load_data[32'hf];
            end
        end
        c0$13 = cmat_0$13$q;
        c1$13 = cmat_1$13$q;
        c2$13 = cmat_2$13$q;
        c$13 = cvec$13$q;
        j0$13 = jsel_0$13$q;
        j1$13 = jsel_1$13$q;
        j2$13 = jsel_2$13$q;
        round_up$13 = rnd$13$q;
        cmat_0$14$clock = clock;
        cmat_1$14$clock = clock;
        cmat_2$14$clock = clock;
        cvec$14$clock = clock;
        jsel_0$14$clock = clock;
        jsel_1$14$clock = clock;
        jsel_2$14$clock = clock;
        rnd$14$clock = clock;
        cmat_0$14$d = cmat_0$14$q;
        cmat_1$14$d = cmat_1$14$q;
        cmat_2$14$d = cmat_2$14$q;
        cvec$14$d = cvec$14$q;
        jsel_0$14$d = jsel_0$14$q;
        jsel_1$14$d = jsel_1$14$q;
        jsel_2$14$d = jsel_2$14$q;
        rnd$14$d = rnd$14$q;
        if (load_en & (c_lane == idx$14)) begin
            if (c_field == 32'h0) begin
                cmat_0$14$d = load_data;
            end
            if (c_field == 32'h1) begin
                cmat_1$14$d = load_data;
            end
            if (c_field == 32'h2) begin
                cmat_2$14$d = load_data;
            end
            if (c_field == 32'h3) begin
                cvec$14$d = load_data;
            end
            if (c_field == 32'h4) begin
                jsel_0$14$d = load_data[(32'h0)+:(5)];
                jsel_1$14$d = load_data[(32'h5)+:(5)];
                jsel_2$14$d = load_data[(32'ha)+:(5)];
                rnd$14$d = load_data[32'hf];
            end
        end
        c0$14 = cmat_0$14$q;
        c1$14 = cmat_1$14$q;
        c2$14 = cmat_2$14$q;
        c$14 = cvec$14$q;
        j0$14 = jsel_0$14$q;
        j1$14 = jsel_1$14$q;
        j2$14 = jsel_2$14$q;
        round_up$14 = rnd$14$q;
        cmat_0$15$clock = clock;
        cmat_1$15$clock = clock;
        cmat_2$15$clock = clock;
        cvec$15$clock = clock;
        jsel_0$15$clock = clock;
        jsel_1$15$clock = clock;
        jsel_2$15$clock = clock;
        rnd$15$clock = clock;
        cmat_0$15$d = cmat_0$15$q;
        cmat_1$15$d = cmat_1$15$q;
        cmat_2$15$d = cmat_2$15$q;
        cvec$15$d = cvec$15$q;
        jsel_0$15$d = jsel_0$15$q;
        jsel_1$15$d = jsel_1$15$q;
        jsel_2$15$d = jsel_2$15$q;
        rnd$15$d = rnd$15$q;
        if (load_en & (c_lane == idx$15)) begin
            if (c_field == 32'h0) begin
                cmat_0$15$d = load_data;
            end
            if (c_field == 32'h1) begin
                cmat_1$15$d = load_data;
            end
            if (c_field == 32'h2) begin
                cmat_2$15$d = load_data;
            end
            if (c_field == 32'h3) begin
                cvec$15$d = load_data;
            end
            if (c_field == 32'h4) begin
                jsel_0$15$d = load_data[(32'h0)+:(5)];
                jsel_1$15$d = load_data[(32'h5)+:(5)];
                jsel_2$15$d = load_data[(32'ha)+:(5)];
                rnd$15$d = load_data[32'hf];
            end
        end
        c0$15 = cmat_0$15$q;
        c1$15 = cmat_1$15$q;
        c2$15 = cmat_2$15$q;
        c$15 = cvec$15$q;
        j0$15 = jsel_0$15$q;
        j1$15 = jsel_1$15$q;
        j2$15 = jsel_2$15$q;
        round_up$15 = rnd$15$q;
        cmat_0$16$clock = clock;
        cmat_1$16$clock = clock;
        cmat_2$16$clock = clock;
        cvec$16$clock = clock;
        jsel_0$16$clock = clock;
        jsel_1$16$clock = clock;
        jsel_2$16$clock = clock;
        rnd$16$clock = clock;
        cmat_0$16$d = cmat_0$16$q;
        cmat_1$16$d = cmat_1$16$q;
        cmat_2$16$d = cmat_2$16$q;
        cvec$16$d = cvec$16$q;
        jsel_0$16$d = jsel_0$16$q;
        jsel_1$16$d = jsel_1$16$q;
        jsel_2$16$d = jsel_2$16$q;
        rnd$16$d = rnd$16$q;
        if (load_en & (c_lane == idx$16)) begin
            if (c_field == 32'h0) begin
                cmat_0$16$d = load_data;
            end
            if (c_field == 32'h1) begin
                cmat_1$16$d = load_data;
            end
            if (c_field == 32'h2) begin
                cmat_2$16$d = load_data;
            end
            if (c_field == 32'h3) begin
                cvec$16$d = load_data;
            end
            if (c_field == 32'h4) begin
                jsel_0$16$d = load_data[(32'h0)+:(5)];
                jsel_1$16$d = load_data[(32'h5)+:(5)];
                jsel_2$16$d = load_data[(32'ha)+:(5)];
                rnd$16$d = load_data[32'hf];
            end
        end
        c0$16 = cmat_0$16$q;
        c1$16 = cmat_1$16$q;
        c2$16 = cmat_2$16$q;
        c$16 = cvec$16$q;
        j0$16 = jsel_0$16$q;
        j1$16 = jsel_1$16$q;
        j2$16 = jsel_2$16$q;
        round_up$16 = rnd$16$q;
        cmat_0$17$clock = clock;
        cmat_1$17$clock = clock;
        cmat_2$17$clock = clock;
        cvec$17$clock = clock;
        jsel_0$17$clock = clock;
        jsel_1$17$clock = clock;
        jsel_2$17$clock = clock;
        rnd$17$clock = clock;
        cmat_0$17$d = cmat_0$17$q;
        cmat_1$17$d = cmat_1$17$q;
        cmat_2$17$d = cmat_2$17$q;
        cvec$17$d = cvec$17$q;
        jsel_0$17$d = jsel_0$17$q;
        jsel_1$17$d = jsel_1$17$q;
        jsel_2$17$d = jsel_2$17$q;
        rnd$17$d = rnd$17$q;
        if (load_en & (c_lane == idx$17)) begin
            if (c_field == 32'h0) begin
                cmat_0$17$d = load_data;
            end
            if (c_field == 32'h1) begin
                cmat_1$17$d = load_data;
            end
            if (c_field == 32'h2) begin
                cmat_2$17$d = load_data;
            end
            if (c_field == 32'h3) begin
                cvec$17$d = load_data;
            end
            if (c_field == 32'h4) begin
                jsel_0$17$d = load_data[(32'h0)+:(5)];
                jsel_1$17$d = load_data[(32'h5)+:(5)];
                jsel_2$17$d = load_data[(32'ha)+:(5)];
                rnd$17$d = load_data[32'hf];
            end
        end
        c0$17 = cmat_0$17$q;
        c1$17 = cmat_1$17$q;
        c2$17 = cmat_2$17$q;
        c$17 = cvec$17$q;
        j0$17 = jsel_0$17$q;
        j1$17 = jsel_1$17$q;
        j2$17 = jsel_2$17$q;
        round_up$17 = rnd$17$q;
        cmat_0$18$clock = clock;
        cmat_1$18$clock = clock;
        cmat_2$18$clock = clock;
        cvec$18$clock = clock;
        jsel_0$18$clock = clock;
        jsel_1$18$clock = clock;
        jsel_2$18$clock = clock;
        rnd$18$clock = clock;
        cmat_0$18$d = cmat_0$18$q;
        cmat_1$18$d = cmat_1$18$q;
        cmat_2$18$d = cmat_2$18$q;
        cvec$18$d = cvec$18$q;
        jsel_0$18$d = jsel_0$18$q;
        jsel_1$18$d = jsel_1$18$q;
        jsel_2$18$d = jsel_2$18$q;
        rnd$18$d = rnd$18$q;
        if (load_en & (c_lane == idx$18)) begin
            if (c_field == 32'h0) begin
                cmat_0$18$d = load_data;
            end
            if (c_field == 32'h1) begin
                cmat_1$18$d = load_data;
            end
            if (c_field == 32'h2) begin
                cmat_2$18$d = load_data;
            end
            if (c_field == 32'h3) begin
                cvec$18$d = load_data;
            end
            if (c_field == 32'h4) begin
                jsel_0$18$d = load_data[(32'h0)+:(5)];
                jsel_1$18$d = load_data[(32'h5)+:(5)];
                jsel_2$18$d = load_data[(32'ha)+:(5)];
                rnd$18$d = load_data[32'hf];
            end
        end
        c0$18 = cmat_0$18$q;
        c1$18 = cmat_1$18$q;
        c2$18 = cmat_2$18$q;
        c$18 = cvec$18$q;
        j0$18 = jsel_0$18$q;
        j1$18 = jsel_1$18$q;
        j2$18 = jsel_2$18$q;
        round_up$18 = rnd$18$q;
        cmat_0$19$clock = clock;
        cmat_1$19$clock = clock;
        cmat_2$19$clock = clock;
        cvec$19$clock = clock;
        jsel_0$19$clock = clock;
        jsel_1$19$clock = clock;
        jsel_2$19$clock = clock;
        rnd$19$clock = clock;
        cmat_0$19$d = cmat_0$19$q;
        cmat_1$19$d = cmat_1$19$q;
        cmat_2$19$d = cmat_2$19$q;
        cvec$19$d = cvec$19$q;
        jsel_0$19$d = jsel_0$19$q;
        jsel_1$19$d = jsel_1$19$q;
        jsel_2$19$d = jsel_2$19$q;
        rnd$19$d = rnd$19$q;
        if (load_en & (c_lane == idx$19)) begin
            if (c_field == 32'h0) begin
                cmat_0$19$d = load_data;
            end
            if (c_field == 32'h1) begin
                cmat_1$19$d = load_data;
            end
            if (c_field == 32'h2) begin
                cmat_2$19$d = load_data;
            end
            if (c_field == 32'h3) begin
                cvec$19$d = load_data;
            end
            if (c_field == 32'h4) begin
                jsel_0$19$d = load_data[(32'h0)+:(5)];
                jsel_1$19$d = load_data[(32'h5)+:(5)];
                jsel_2$19$d = load_data[(32'ha)+:(5)];
                rnd$19$d = load_data[32'hf];
            end
        end
        c0$19 = cmat_0$19$q;
        c1$19 = cmat_1$19$q;
        c2$19 = cmat_2$19$q;
        c$19 = cvec$19$q;
        j0$19 = jsel_0$19$q;
        j1$19 = jsel_1$19$q;
        j2$19 = jsel_2$19$q;
        round_up$19 = rnd$19$q;
        cmat_0$20$clock = clock;
        cmat_1$20$clock = clock;
        cmat_2$20$clock = clock;
        cvec$20$clock = clock;
        jsel_0$20$clock = clock;
        jsel_1$20$clock = clock;
        jsel_2$20$clock = clock;
        rnd$20$clock = clock;
        cmat_0$20$d = cmat_0$20$q;
        cmat_1$20$d = cmat_1$20$q;
        cmat_2$20$d = cmat_2$20$q;
        cvec$20$d = cvec$20$q;
        jsel_0$20$d = jsel_0$20$q;
        jsel_1$20$d = jsel_1$20$q;
        jsel_2$20$d = jsel_2$20$q;
        rnd$20$d = rnd$20$q;
        if (load_en & (c_lane == idx$20)) begin
            if (c_field == 32'h0) begin
                cmat_0$20$d = load_data;
            end
            if (c_field == 32'h1) begin
                cmat_1$20$d = load_data;
            end
            if (c_field == 32'h2) begin
                cmat_2$20$d = load_data;
            end
            if (c_field == 32'h3) begin
                cvec$20$d = load_data;
            end
            if (c_field == 32'h4) begin
                jsel_0$20$d = load_data[(32'h0)+:(5)];
                jsel_1$20$d = load_data[(32'h5)+:(5)];
                jsel_2$20$d = load_data[(32'ha)+:(5)];
                rnd$20$d = load_data[32'hf];
            end
        end
        c0$20 = cmat_0$20$q;
        c1$20 = cmat_1$20$q;
        c2$20 = cmat_2$20$q;
        c$20 = cvec$20$q;
        j0$20 = jsel_0$20$q;
        j1$20 = jsel_1$20$q;
        j2$20 = jsel_2$20$q;
        round_up$20 = rnd$20$q;
        cmat_0$21$clock = clock;
        cmat_1$21$clock = clock;
        cmat_2$21$clock = clock;
        cvec$21$clock = clock;
        jsel_0$21$clock = clock;
        jsel_1$21$clock = clock;
        jsel_2$21$clock = clock;
        rnd$21$clock = clock;
        cmat_0$21$d = cmat_0$21$q;
        cmat_1$21$d = cmat_1$21$q;
        cmat_2$21$d = cmat_2$21$q;
        cvec$21$d = cvec$21$q;
        jsel_0$21$d = jsel_0$21$q;
        jsel_1$21$d = jsel_1$21$q;
        jsel_2$21$d = jsel_2$21$q;
        rnd$21$d = rnd$21$q;
        if (load_en & (c_lane == idx$21)) begin
            if (c_field == 32'h0) begin
                cmat_0$21$d = load_data;
            end
            if (c_field == 32'h1) begin
                cmat_1$21$d = load_data;
            end
            if (c_field == 32'h2) begin
                cmat_2$21$d = load_data;
            end
            if (c_field == 32'h3) begin
                cvec$21$d = load_data;
            end
            if (c_field == 32'h4) begin
                jsel_0$21$d = load_data[(32'h0)+:(5)];
                jsel_1$21$d = load_data[(32'h5)+:(5)];
                jsel_2$21$d = load_data[(32'ha)+:(5)];
                rnd$21$d = load_data[32'hf];
            end
        end
        c0$21 = cmat_0$21$q;
        c1$21 = cmat_1$21$q;
        c2$21 = cmat_2$21$q;
        c$21 = cvec$21$q;
        j0$21 = jsel_0$21$q;
        j1$21 = jsel_1$21$q;
        j2$21 = jsel_2$21$q;
        round_up$21 = rnd$21$q;
        cmat_0$22$clock = clock;
        cmat_1$22$clock = clock;
        cmat_2$22$clock = clock;
        cvec$22$clock = clock;
        jsel_0$22$clock = clock;
        jsel_1$22$clock = clock;
        jsel_2$22$clock = clock;
        rnd$22$clock = clock;
        cmat_0$22$d = cmat_0$22$q;
        cmat_1$22$d = cmat_1$22$q;
        cmat_2$22$d = cmat_2$22$q;
        cvec$22$d = cvec$22$q;
        jsel_0$22$d = jsel_0$22$q;
        jsel_1$22$d = jsel_1$22$q;
        jsel_2$22$d = jsel_2$22$q;
        rnd$22$d = rnd$22$q;
        if (load_en & (c_lane == idx$22)) begin
            if (c_field == 32'h0) begin
                cmat_0$22$d = load_data;
            end
            if (c_field == 32'h1) begin
                cmat_1$22$d = load_data;
            end
            if (c_field == 32'h2) begin
                cmat_2$22$d = load_data;
            end
            if (c_field == 32'h3) begin
                cvec$22$d = load_data;
            end
            if (c_field == 32'h4) begin
                jsel_0$22$d = load_data[(32'h0)+:(5)];
                jsel_1$22$d = load_data[(32'h5)+:(5)];
                jsel_2$22$d = load_data[(32'ha)+:(5)];
                rnd$22$d = load_data[32'hf];
            end
        end
        c0$22 = cmat_0$22$q;
        c1$22 = cmat_1$22$q;
        c2$22 = cmat_2$22$q;
        c$22 = cvec$22$q;
        j0$22 = jsel_0$22$q;
        j1$22 = jsel_1$22$q;
        j2$22 = jsel_2$22$q;
        round_up$22 = rnd$22$q;
        cmat_0$23$clock = clock;
        cmat_1$23$clock = clock;
        cmat_2$23$clock = clock;
        cvec$23$clock = clock;
        jsel_0$23$clock = clock;
        jsel_1$23$clock = clock;
        jsel_2$23$clock = clock;
        rnd$23$clock = clock;
        cmat_0$23$d = cmat_0$23$q;
        cmat_1$23$d = cmat_1$23$q;
        cmat_2$23$d = cmat_2$23$q;
        cvec$23$d = cvec$23$q;
        jsel_0$23$d = jsel_0$23$q;
        jsel_1$23$d = jsel_1$23$q;
        jsel_2$23$d = jsel_2$23$q;
        rnd$23$d = rnd$23$q;
        if (load_en & (c_lane == idx$23)) begin
            if (c_field == 32'h0) begin
                cmat_0$23$d = load_data;
            end
            if (c_field == 32'h1) begin
                cmat_1$23$d = load_data;
            end
            if (c_field == 32'h2) begin
                cmat_2$23$d = load_data;
            end
            if (c_field == 32'h3) begin
                cvec$23$d = load_data;
            end
            if (c_field == 32'h4) begin
                jsel_0$23$d = load_data[(32'h0)+:(5)];
                jsel_1$23$d = load_data[(32'h5)+:(5)];
                jsel_2$23$d = load_data[(32'ha)+:(5)];
                rnd$23$d = load_data[32'hf];
            end
        end
        c0$23 = cmat_0$23$q;
        c1$23 = cmat_1$23$q;
        c2$23 = cmat_2$23$q;
        c$23 = cvec$23$q;
        j0$23 = jsel_0$23$q;
        j1$23 = jsel_1$23$q;
        j2$23 = jsel_2$23$q;
        round_up$23 = rnd$23$q;
    end
    
endmodule // top$setup


module top$setup$jsel_0$0(d,q,clock);
    
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
          
endmodule // top$setup$jsel_0$0


module top$tag_1(d,q,clock);
    
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
          
endmodule // top$tag_1
