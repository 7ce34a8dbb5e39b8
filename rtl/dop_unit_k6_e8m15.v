

module top(clock,load_en,load_addr,load_data,d$0,d$1,d$2,d$3,d$4,d$5,e$0,e$1,e$2,e$3,e$4,e$5,tag,valid_in,overlap,tag_out,valid_out);
    
    // Module arguments
    input wire  clock;
    input wire  load_en;
    input wire  [7:0] load_addr;
    input wire  [23:0] load_data;
    input wire  [23:0] d$0;
    input wire  [23:0] d$1;
    input wire  [23:0] d$2;
    input wire  [23:0] d$3;
    input wire  [23:0] d$4;
    input wire  [23:0] d$5;
    input wire  [23:0] e$0;
    input wire  [23:0] e$1;
    input wire  [23:0] e$2;
    input wire  [23:0] e$3;
    input wire  [23:0] e$4;
    input wire  [23:0] e$5;
    input wire  [15:0] tag;
    input wire  valid_in;
    output reg  overlap;
    output reg  [15:0] tag_out;
    output reg  valid_out;
    
    // Stub signals
    reg  setup$clock;
    reg  setup$load_en;
    reg  [7:0] setup$load_addr;
    reg  [23:0] setup$load_data;
    wire  [23:0] setup$c0$0;
    wire  [23:0] setup$c0$1;
    wire  [23:0] setup$c0$2;
    wire  [23:0] setup$c0$3;
    wire  [23:0] setup$c0$4;
    wire  [23:0] setup$c0$5;
    wire  [23:0] setup$c1$0;
    wire  [23:0] setup$c1$1;
    wire  [23:0] setup$c1$2;
    wire  [23:0] setup$c1$3;
    wire  [23:0] setup$c1$4;
    wire  [23:0] setup$c1$5;
    wire  [23:0] setup$c2$0;
    wire  [23:0] setup$c2$1;
    wire  [23:0] setup$c2$2;
    wire  [23:0] setup$c2$3;
    wire  [23:0] setup$c2$4;
    wire  [23:0] setup$c2$5;
    wire  [23:0] setup$c$0;
    wire  [23:0] setup$c$1;
    wire  [23:0] setup$c$2;
    wire  [23:0] setup$c$3;
    wire  [23:0] setup$c$4;
    wire  [23:0] setup$c$5;
    wire  [4:0] setup$j0$0;
    wire  [4:0] setup$j0$1;
    wire  [4:0] setup$j0$2;
    wire  [4:0] setup$j0$3;
    wire  [4:0] setup$j0$4;
    wire  [4:0] setup$j0$5;
    wire  [4:0] setup$j1$0;
    wire  [4:0] setup$j1$1;
    wire  [4:0] setup$j1$2;
    wire  [4:0] setup$j1$3;
    wire  [4:0] setup$j1$4;
    wire  [4:0] setup$j1$5;
    wire  [4:0] setup$j2$0;
    wire  [4:0] setup$j2$1;
    wire  [4:0] setup$j2$2;
    wire  [4:0] setup$j2$3;
    wire  [4:0] setup$j2$4;
    wire  [4:0] setup$j2$5;
    wire  setup$round_up$0;
    wire  setup$round_up$1;
    wire  setup$round_up$2;
    wire  setup$round_up$3;
    wire  setup$round_up$4;
    wire  setup$round_up$5;
    reg  [23:0] klmsel$d$0;
    reg  [23:0] klmsel$d$1;
    reg  [23:0] klmsel$d$2;
    reg  [23:0] klmsel$d$3;
    reg  [23:0] klmsel$d$4;
    reg  [23:0] klmsel$d$5;
    reg  [4:0] klmsel$j0$0;
    reg  [4:0] klmsel$j0$1;
    reg  [4:0] klmsel$j0$2;
    reg  [4:0] klmsel$j0$3;
    reg  [4:0] klmsel$j0$4;
    reg  [4:0] klmsel$j0$5;
    reg  [4:0] klmsel$j1$0;
    reg  [4:0] klmsel$j1$1;
    reg  [4:0] klmsel$j1$2;
    reg  [4:0] klmsel$j1$3;
    reg  [4:0] klmsel$j1$4;
    reg  [4:0] klmsel$j1$5;
    reg  [4:0] klmsel$j2$0;
    reg  [4:0] klmsel$j2$1;
    reg  [4:0] klmsel$j2$2;
    reg  [4:0] klmsel$j2$3;
    reg  [4:0] klmsel$j2$4;
    reg  [4:0] klmsel$j2$5;
    wire  [23:0] klmsel$y0$0;
    wire  [23:0] klmsel$y0$1;
    wire  [23:0] klmsel$y0$2;
    wire  [23:0] klmsel$y0$3;
    wire  [23:0] klmsel$y0$4;
    wire  [23:0] klmsel$y0$5;
    wire  [23:0] klmsel$y1$0;
    wire  [23:0] klmsel$y1$1;
    wire  [23:0] klmsel$y1$2;
    wire  [23:0] klmsel$y1$3;
    wire  [23:0] klmsel$y1$4;
    wire  [23:0] klmsel$y1$5;
    wire  [23:0] klmsel$y2$0;
    wire  [23:0] klmsel$y2$1;
    wire  [23:0] klmsel$y2$2;
    wire  [23:0] klmsel$y2$3;
    wire  [23:0] klmsel$y2$4;
    wire  [23:0] klmsel$y2$5;
    reg  doptrf$0$clock;
    reg  [23:0] doptrf$0$d0;
    reg  [23:0] doptrf$0$d1;
    reg  [23:0] doptrf$0$d2;
    reg  [23:0] doptrf$0$c0;
    reg  [23:0] doptrf$0$c1;
    reg  [23:0] doptrf$0$c2;
    reg  [23:0] doptrf$0$c;
    reg  [23:0] doptrf$0$e;
    reg  doptrf$0$valid_in;
    reg  doptrf$0$round_up;
    wire  [23:0] doptrf$0$s;
    wire  doptrf$0$flag;
    wire  doptrf$0$valid_out;
    reg  doptrf$1$clock;
    reg  [23:0] doptrf$1$d0;
    reg  [23:0] doptrf$1$d1;
    reg  [23:0] doptrf$1$d2;
    reg  [23:0] doptrf$1$c0;
    reg  [23:0] doptrf$1$c1;
    reg  [23:0] doptrf$1$c2;
    reg  [23:0] doptrf$1$c;
    reg  [23:0] doptrf$1$e;
    reg  doptrf$1$valid_in;
    reg  doptrf$1$round_up;
    wire  [23:0] doptrf$1$s;
    wire  doptrf$1$flag;
    wire  doptrf$1$valid_out;
    reg  doptrf$2$clock;
    reg  [23:0] doptrf$2$d0;
    reg  [23:0] doptrf$2$d1;
    reg  [23:0] doptrf$2$d2;
    reg  [23:0] doptrf$2$c0;
    reg  [23:0] doptrf$2$c1;
    reg  [23:0] doptrf$2$c2;
    reg  [23:0] doptrf$2$c;
    reg  [23:0] doptrf$2$e;
    reg  doptrf$2$valid_in;
    reg  doptrf$2$round_up;
    wire  [23:0] doptrf$2$s;
    wire  doptrf$2$flag;
    wire  doptrf$2$valid_out;
    reg  doptrf$3$clock;
    reg  [23:0] doptrf$3$d0;
    reg  [23:0] doptrf$3$d1;
    reg  [23:0] doptrf$3$d2;
    reg  [23:0] doptrf$3$c0;
    reg  [23:0] doptrf$3$c1;
    reg  [23:0] doptrf$3$c2;
    reg  [23:0] doptrf$3$c;
    reg  [23:0] doptrf$3$e;
    reg  doptrf$3$valid_in;
    reg  doptrf$3$round_up;
    wire  [23:0] doptrf$3$s;
    wire  doptrf$3$flag;
    wire  doptrf$3$valid_out;
    reg  doptrf$4$clock;
    reg  [23:0] doptrf$4$d0;
    reg  [23:0] doptrf$4$d1;
    reg  [23:0] doptrf$4$d2;
    reg  [23:0] doptrf$4$c0;
    reg  [23:0] doptrf$4$c1;
    reg  [23:0] doptrf$4$c2;
    reg  [23:0] doptrf$4$c;
    reg  [23:0] doptrf$4$e;
    reg  doptrf$4$valid_in;
    reg  doptrf$4$round_up;
    wire  [23:0] doptrf$4$s;
    wire  doptrf$4$flag;
    wire  doptrf$4$valid_out;
    reg  doptrf$5$clock;
    reg  [23:0] doptrf$5$d0;
    reg  [23:0] doptrf$5$d1;
    reg  [23:0] doptrf$5$d2;
    reg  [23:0] doptrf$5$c0;
    reg  [23:0] doptrf$5$c1;
    reg  [23:0] doptrf$5$c2;
    reg  [23:0] doptrf$5$c;
    reg  [23:0] doptrf$5$e;
    reg  doptrf$5$valid_in;
    reg  doptrf$5$round_up;
    wire  [23:0] doptrf$5$s;
    wire  doptrf$5$flag;
    wire  doptrf$5$valid_out;
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
        .c1$0(setup$c1$0),
        .c1$1(setup$c1$1),
        .c1$2(setup$c1$2),
        .c1$3(setup$c1$3),
        .c1$4(setup$c1$4),
        .c1$5(setup$c1$5),
        .c2$0(setup$c2$0),
        .c2$1(setup$c2$1),
        .c2$2(setup$c2$2),
        .c2$3(setup$c2$3),
        .c2$4(setup$c2$4),
        .c2$5(setup$c2$5),
        .c$0(setup$c$0),
        .c$1(setup$c$1),
        .c$2(setup$c$2),
        .c$3(setup$c$3),
        .c$4(setup$c$4),
        .c$5(setup$c$5),
        .j0$0(setup$j0$0),
        .j0$1(setup$j0$1),
        .j0$2(setup$j0$2),
        .j0$3(setup$j0$3),
        .j0$4(setup$j0$4),
        .j0$5(setup$j0$5),
        .j1$0(setup$j1$0),
        .j1$1(setup$j1$1),
        .j1$2(setup$j1$2),
        .j1$3(setup$j1$3),
        .j1$4(setup$j1$4),
        .j1$5(setup$j1$5),
        .j2$0(setup$j2$0),
        .j2$1(setup$j2$1),
        .j2$2(setup$j2$2),
        .j2$3(setup$j2$3),
        .j2$4(setup$j2$4),
        .j2$5(setup$j2$5),
        .round_up$0(setup$round_up$0),
        .round_up$1(setup$round_up$1),
        .round_up$2(setup$round_up$2),
        .round_up$3(setup$round_up$3),
        .round_up$4(setup$round_up$4),
        .round_up$5(setup$round_up$5)
    );
    top$klmsel klmsel(
        .d$0(klmsel$d$0),
        .d$1(klmsel$d$1),
        .d$2(klmsel$d$2),
        .d$3(klmsel$d$3),
        .d$4(klmsel$d$4),
        .d$5(klmsel$d$5),
        .j0$0(klmsel$j0$0),
        .j0$1(klmsel$j0$1),
        .j0$2(klmsel$j0$2),
        .j0$3(klmsel$j0$3),
        .j0$4(klmsel$j0$4),
        .j0$5(klmsel$j0$5),
        .j1$0(klmsel$j1$0),
        .j1$1(klmsel$j1$1),
        .j1$2(klmsel$j1$2),
        .j1$3(klmsel$j1$3),
        .j1$4(klmsel$j1$4),
        .j1$5(klmsel$j1$5),
        .j2$0(klmsel$j2$0),
        .j2$1(klmsel$j2$1),
        .j2$2(klmsel$j2$2),
        .j2$3(klmsel$j2$3),
        .j2$4(klmsel$j2$4),
        .j2$5(klmsel$j2$5),
        .y0$0(klmsel$y0$0),
        .y0$1(klmsel$y0$1),
        .y0$2(klmsel$y0$2),
        .y0$3(klmsel$y0$3),
        .y0$4(klmsel$y0$4),
        .y0$5(klmsel$y0$5),
        .y1$0(klmsel$y1$0),
        .y1$1(klmsel$y1$1),
        .y1$2(klmsel$y1$2),
        .y1$3(klmsel$y1$3),
        .y1$4(klmsel$y1$4),
        .y1$5(klmsel$y1$5),
        .y2$0(klmsel$y2$0),
        .y2$1(klmsel$y2$1),
        .y2$2(klmsel$y2$2),
        .y2$3(klmsel$y2$3),
        .y2$4(klmsel$y2$4),
        .y2$5(klmsel$y2$5)
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
    top$doptrf$0$mul_0$s1_sig_a tag_1(
        .d(tag_1$d),
        .q(tag_1$q),
        .clock(tag_1$clock)
    );
    top$doptrf$0$mul_0$s1_sig_a tag_2(
        .d(tag_2$d),
        .q(tag_2$q),
        .clock(tag_2$clock)
    );
    top$doptrf$0$mul_0$s1_sig_a tag_3(
        .d(tag_3$d),
        .q(tag_3$q),
        .clock(tag_3$clock)
    );
    top$doptrf$0$mul_0$s1_sig_a tag_4(
        .d(tag_4$d),
        .q(tag_4$q),
        .clock(tag_4$clock)
    );
    top$doptrf$0$mul_0$s1_sig_a tag_5(
        .d(tag_5$d),
        .q(tag_5$q),
        .clock(tag_5$clock)
    );
    top$doptrf$0$mul_0$s1_sig_a tag_6(
        .d(tag_6$d),
        .q(tag_6$q),
        .clock(tag_6$clock)
    );
    top$doptrf$0$mul_0$s1_sig_a tag_7(
        .d(tag_7$d),
        .q(tag_7$q),
        .clock(tag_7$clock)
    );
    top$doptrf$0$mul_0$s1_sig_a tag_8(
        .d(tag_8$d),
        .q(tag_8$q),
        .clock(tag_8$clock)
    );
    top$doptrf$0$mul_0$s1_sig_a tag_9(
        .d(tag_9$d),
        .q(tag_9$q),
        .clock(tag_9$clock)
    );
    top$doptrf$0$mul_0$s1_sig_a tag_10(
        .d(tag_10$d),
        .q(tag_10$q),
        .clock(tag_10$clock)
    );
    top$doptrf$0$mul_0$s1_sig_a tag_11(
        .d(tag_11$d),
        .q(tag_11$q),
        .clock(tag_11$clock)
    );
    top$doptrf$0$mul_0$s1_sig_a tag_12(
        .d(tag_12$d),
        .q(tag_12$q),
        .clock(tag_12$clock)
    );
    top$doptrf$0$mul_0$s1_sig_a tag_13(
        .d(tag_13$d),
        .q(tag_13$q),
        .clock(tag_13$clock)
    );
    top$doptrf$0$mul_0$s1_sig_a tag_14(
        .d(tag_14$d),
        .q(tag_14$q),
        .clock(tag_14$clock)
    );
    top$doptrf$0$mul_0$s1_sig_a tag_15(
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
        doptrf$0$e = e$3;
        doptrf$1$e = e$4;
        doptrf$2$e = e$5;
        doptrf$3$e = e$0;
        doptrf$4$e = e$1;
        doptrf$5$e = e$2;
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
        overlap = ~c_any;
        tag_out = tag_15$q;
        valid_out = doptrf$0$valid_out;
    end
    
endmodule // top


module top$doptrf$0(clock,d0,d1,d2,c0,c1,c2,c,e,valid_in,round_up,s,flag,valid_out);
    
    // Module arguments
    input wire  clock;
    input wire  [23:0] d0;
    input wire  [23:0] d1;
    input wire  [23:0] d2;
    input wire  [23:0] c0;
    input wire  [23:0] c1;
    input wire  [23:0] c2;
    input wire  [23:0] c;
    input wire  [23:0] e;
    input wire  valid_in;
    input wire  round_up;
    output reg  [23:0] s;
    output reg  flag;
    output reg  valid_out;
    
    // Stub signals
    reg  s1_valid$d;
    wire  s1_valid$q;
    reg  s1_valid$clock;
    reg  [23:0] s1_d0$d;
    wire  [23:0] s1_d0$q;
    reg  s1_d0$clock;
    reg  [23:0] s1_d1$d;
    wire  [23:0] s1_d1$q;
    reg  s1_d1$clock;
    reg  [23:0] s1_d2$d;
    wire  [23:0] s1_d2$q;
    reg  s1_d2$clock;
    reg  [23:0] s1_c0$d;
    wire  [23:0] s1_c0$q;
    reg  s1_c0$clock;
    reg  [23:0] s1_c1$d;
    wire  [23:0] s1_c1$q;
    reg  s1_c1$clock;
    reg  [23:0] s1_c2$d;
    wire  [23:0] s1_c2$q;
    reg  s1_c2$clock;
    reg  [23:0] s1_c$d;
    wire  [23:0] s1_c$q;
    reg  s1_c$clock;
    reg  [23:0] s1_e$d;
    wire  [23:0] s1_e$q;
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
    reg  [23:0] mul_0$a;
    reg  [23:0] mul_0$b;
    reg  mul_0$valid_in;
    wire  [23:0] mul_0$y;
    wire  mul_0$valid_out;
    reg  mul_0$round_up;
    reg  mul_1$clock;
    reg  [23:0] mul_1$a;
    reg  [23:0] mul_1$b;
    reg  mul_1$valid_in;
    wire  [23:0] mul_1$y;
    wire  mul_1$valid_out;
    reg  mul_1$round_up;
    reg  mul_2$clock;
    reg  [23:0] mul_2$a;
    reg  [23:0] mul_2$b;
    reg  mul_2$valid_in;
    wire  [23:0] mul_2$y;
    wire  mul_2$valid_out;
    reg  mul_2$round_up;
    reg  [23:0] c_2$d;
    wire  [23:0] c_2$q;
    reg  c_2$clock;
    reg  [23:0] c_3$d;
    wire  [23:0] c_3$q;
    reg  c_3$clock;
    reg  [23:0] c_4$d;
    wire  [23:0] c_4$q;
    reg  c_4$clock;
    reg  [23:0] c_5$d;
    wire  [23:0] c_5$q;
    reg  c_5$clock;
    reg  add_0$clock;
    reg  [23:0] add_0$a;
    reg  [23:0] add_0$b;
    reg  add_0$sub;
    reg  add_0$valid_in;
    wire  [23:0] add_0$y;
    wire  add_0$valid_out;
    reg  add_0$round_up;
    reg  add_1$clock;
    reg  [23:0] add_1$a;
    reg  [23:0] add_1$b;
    reg  add_1$sub;
    reg  add_1$valid_in;
    wire  [23:0] add_1$y;
    wire  add_1$valid_out;
    reg  add_1$round_up;
    reg  add_2$clock;
    reg  [23:0] add_2$a;
    reg  [23:0] add_2$b;
    reg  add_2$sub;
    reg  add_2$valid_in;
    wire  [23:0] add_2$y;
    wire  add_2$valid_out;
    reg  add_2$round_up;
    reg  add_3$clock;
    reg  [23:0] add_3$a;
    reg  [23:0] add_3$b;
    reg  add_3$sub;
    reg  add_3$valid_in;
    wire  [23:0] add_3$y;
    wire  add_3$valid_out;
    reg  add_3$round_up;
    reg  [23:0] e_2$d;
    wire  [23:0] e_2$q;
    reg  e_2$clock;
    reg  [23:0] e_3$d;
    wire  [23:0] e_3$q;
    reg  e_3$clock;
    reg  [23:0] e_4$d;
    wire  [23:0] e_4$q;
    reg  e_4$clock;
    reg  [23:0] e_5$d;
    wire  [23:0] e_5$q;
    reg  e_5$clock;
    reg  [23:0] e_6$d;
    wire  [23:0] e_6$q;
    reg  e_6$clock;
    reg  [23:0] e_7$d;
    wire  [23:0] e_7$q;
    reg  e_7$clock;
    reg  [23:0] e_8$d;
    wire  [23:0] e_8$q;
    reg  e_8$clock;
    reg  [23:0] e_9$d;
    wire  [23:0] e_9$q;
    reg  e_9$clock;
    reg  [23:0] e_10$d;
    wire  [23:0] e_10$q;
    reg  e_10$clock;
    reg  [23:0] e_11$d;
    wire  [23:0] e_11$q;
    reg  e_11$clock;
    reg  s15_valid$d;
    wire  s15_valid$q;
    reg  s15_valid$clock;
    reg  [23:0] s15_s$d;
    wire  [23:0] s15_s$q;
    reg  s15_s$clock;
    reg  s15_flag$d;
    wire  s15_flag$q;
    reg  s15_flag$clock;
    
    // Local signals
    reg  [7:0] c15_exp;
    reg  [14:0] c15_frac;
    reg  [22:0] c15_mag;
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
        c15_exp = add_3$y[(32'hf)+:(8)];
        c15_frac = add_3$y[(32'h0)+:(15)];
        c15_mag = add_3$y[(32'h0)+:(23)];
        c15_nan = &c15_exp & (c15_frac != 32'h0);
        s15_valid$d = add_3$valid_out;
        s15_s$d = add_3$y;
        s15_flag$d = add_3$y[32'h17] & (c15_mag != 32'h0) & ~c15_nan;
        s = s15_s$q;
        flag = s15_flag$q;
        valid_out = s15_valid$q;
    end
    
endmodule // top$doptrf$0


module top$doptrf$0$add_0(clock,a,b,sub,valid_in,y,valid_out,round_up);
    
    // Module arguments
    input wire  clock;
    input wire  [23:0] a;
    input wire  [23:0] b;
    input wire  sub;
    input wire  valid_in;
    output reg  [23:0] y;
    output reg  valid_out;
    input wire  round_up;
    
    // Constant declarations
    localparam  c_align_cap = 8'h13;
    localparam  c_exp_ones = 10'b11111111;
    
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
    reg  [18:0] s1_big$d;
    wire  [18:0] s1_big$q;
    reg  s1_big$clock;
    reg  [18:0] s1_small$d;
    wire  [18:0] s1_small$q;
    reg  s1_small$clock;
    reg  [18:0] norm$x;
    wire  [18:0] norm$y;
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
    reg  [17:0] s2_nm$d;
    wire  [17:0] s2_nm$q;
    reg  s2_nm$clock;
    reg  round$round_up;
    reg  round$sign;
    reg  round$nan;
    reg  round$inf;
    reg  round$zero;
    reg  round$ovf;
    reg  [7:0] round$efield;
    reg  [17:0] round$nm;
    wire  [23:0] round$y;
    reg  s3_valid$d;
    wire  s3_valid$q;
    reg  s3_valid$clock;
    reg  [23:0] s3_y$d;
    wire  [23:0] s3_y$q;
    reg  s3_y$clock;
    
    // Local signals
    reg  c1_b_sign;
    reg  c1_swap;
    reg  c1_big_sign;
    reg  [7:0] c1_big_exp;
    reg  [15:0] c1_big_sig;
    reg  c1_small_sign;
    reg  [7:0] c1_small_exp;
    reg  [15:0] c1_small_sig;
    reg  [7:0] c1_diff;
    reg  [7:0] c1_shift;
    reg  [18:0] c1_small_ext;
    reg  [18:0] c1_aligned;
    reg  [18:0] c1_back;
    reg  c1_lost;
    reg  c1_inf_sign;
    reg  [19:0] c2_sum;
    reg  c2_carry;
    reg  c2_zero;
    reg  [7:0] c2_limit;
    reg  [7:0] c2_lz;
    reg  [7:0] c2_shift;
    reg  [18:0] c2_shifted;
    reg  [9:0] c2_exp;
    reg  [17:0] c2_nm;
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
        c1_swap = a[(32'h0)+:(23)] < b[(32'h0)+:(23)];
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
        c1_small_ext = ((c1_small_sig) & 19'h7ffff) << 32'h3;
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
        s1_big$d = ((c1_big_sig) & 19'h7ffff) << 32'h3;
        s1_small$d = (c1_aligned & ~(1 << (32'h0)) | ((c1_aligned[32'h0] | c1_lost) << (32'h0)));
        c2_sum = ((s1_big$q) & 20'hfffff) + ((s1_small$q) & 20'hfffff);
        if (s1_eff_sub$q) begin
            c2_sum = ((s1_big$q) & 20'hfffff) - ((s1_small$q) & 20'hfffff);
        end
        c2_carry = c2_sum[32'h13];
        c2_zero = c2_sum == 32'h0;
        norm$x = c2_sum[(32'h0)+:(19)];
        c2_limit = s1_exp$q - 32'h1;
        c2_lz = ((norm$lz) & 8'hff);
        c2_shift = c2_lz;
        if (c2_lz > c2_limit) begin
            c2_shift = c2_limit;
        end
        c2_shifted = c2_sum[(32'h0)+:(19)] << c2_shift;
        c2_exp = ((s1_exp$q) & 10'h3ff) - ((c2_shift) & 10'h3ff);
        c2_nm = (((c2_shifted >> 32'h1) & 18'h3ffff) & ~(1 << (32'h0)) | ((c2_shifted[32'h1] | c2_shifted[32'h0]) << (32'h0)));
        if (c2_carry) begin
            c2_exp = ((s1_exp$q) & 10'h3ff) + 32'h1;
            c2_nm = (((c2_sum >> 32'h2) & 18'h3ffff) & ~(1 << (32'h0)) | ((c2_sum[32'h2] | c2_sum[32'h1] | c2_sum[32'h0]) << (32'h0)));
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
        if (c2_nm[32'h10 + 32'h1]) begin
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
    input wire  [18:0] x;
    output reg  [18:0] y;
    output reg  [4:0] lz;
    
    // Local signals
    reg  z16;
    reg  z8;
    reg  z4;
    reg  z2;
    reg  z1;
    reg  [18:0] x16;
    reg  [18:0] x8;
    reg  [18:0] x4;
    reg  [18:0] x2;
    
    // Update code
    always @(*) begin
        z16 = x[(32'h3)+:(16)] == 32'h0;
        x16 = x;
        if (z16) begin
            x16 = x << 32'h10;
        end
        z8 = x16[(32'hb)+:(8)] == 32'h0;
        x8 = x16;
        if (z8) begin
            x8 = x16 << 32'h8;
        end
        z4 = x8[(32'hf)+:(4)] == 32'h0;
        x4 = x8;
        if (z4) begin
            x4 = x8 << 32'h4;
        end
        z2 = x4[(32'h11)+:(2)] == 32'h0;
        x2 = x4;
        if (z2) begin
            x2 = x4 << 32'h2;
        end
        z1 = ~x2[32'h12];
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
    
endmodule // top$doptrf$0$add_0$round


module top$doptrf$0$add_0$s1_big(d,q,clock);
    
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
          
endmodule // top$doptrf$0$add_0$s2_nm


module top$doptrf$0$add_0$s3_y(d,q,clock);
    
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
          
endmodule // top$doptrf$0$add_0$s3_y


module top$doptrf$0$add_0$unpack_a(x,sign,exp,sig,is_zero,is_inf,is_nan);
    
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
    
endmodule // top$doptrf$0$add_0$unpack_a


module top$doptrf$0$mul_0(clock,a,b,valid_in,y,valid_out,round_up);
    
    // Module arguments
    input wire  clock;
    input wire  [23:0] a;
    input wire  [23:0] b;
    input wire  valid_in;
    output reg  [23:0] y;
    output reg  valid_out;
    input wire  round_up;
    
    // Constant declarations
    localparam  c_exp_adj = 10'b10000001;
    localparam  c_exp_ofs = 10'b100000000;
    localparam  c_exp_norm_min = 10'b100000001;
    localparam  c_exp_ovf = 10'b111111111;
    localparam  c_shift_cap = 10'b10010;
    
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
    reg  [15:0] norm_a$x;
    wire  [15:0] norm_a$y;
    wire  [4:0] norm_a$lz;
    reg  [15:0] norm_b$x;
    wire  [15:0] norm_b$y;
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
    reg  [15:0] s1_sig_a$d;
    wire  [15:0] s1_sig_a$q;
    reg  s1_sig_a$clock;
    reg  [15:0] s1_sig_b$d;
    wire  [15:0] s1_sig_b$q;
    reg  s1_sig_b$clock;
    reg  [15:0] sig_mul$a;
    reg  [15:0] sig_mul$b;
    wire  [17:0] sig_mul$hi;
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
    reg  [17:0] s2_hi$d;
    wire  [17:0] s2_hi$q;
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
    reg  [17:0] s3_nm$d;
    wire  [17:0] s3_nm$q;
    reg  s3_nm$clock;
    reg  round$round_up;
    reg  round$sign;
    reg  round$nan;
    reg  round$inf;
    reg  round$zero;
    reg  round$ovf;
    reg  [7:0] round$efield;
    reg  [17:0] round$nm;
    wire  [23:0] round$y;
    reg  s4_valid$d;
    wire  s4_valid$q;
    reg  s4_valid$clock;
    reg  [23:0] s4_y$d;
    wire  [23:0] s4_y$q;
    reg  s4_y$clock;
    
    // Local signals
    reg  [9:0] c1_exp;
    reg  c3_top;
    reg  [17:0] c3_nm;
    reg  [9:0] c3_exp;
    reg  [9:0] c3_shift;
    reg  [9:0] c3_shift_cap;
    reg  [17:0] c3_shifted;
    reg  [17:0] c3_back;
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
        c3_top = s2_hi$q[32'h10 + 32'h1];
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
    input wire  [15:0] x;
    output reg  [15:0] y;
    output reg  [4:0] lz;
    
    // Local signals
    reg  z16;
    reg  z8;
    reg  z4;
    reg  z2;
    reg  z1;
    reg  [15:0] x16;
    reg  [15:0] x8;
    reg  [15:0] x4;
    reg  [15:0] x2;
    
    // Update code
    always @(*) begin
        z16 = x[(32'h0)+:(16)] == 32'h0;
        x16 = x;
        if (z16) begin
            x16 = x << 32'h10;
        end
        z8 = x16[(32'h8)+:(8)] == 32'h0;
        x8 = x16;
        if (z8) begin
            x8 = x16 << 32'h8;
        end
        z4 = x8[(32'hc)+:(4)] == 32'h0;
        x4 = x8;
        if (z4) begin
            x4 = x8 << 32'h4;
        end
        z2 = x4[(32'he)+:(2)] == 32'h0;
        x2 = x4;
        if (z2) begin
            x2 = x4 << 32'h2;
        end
        z1 = ~x2[32'hf];
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
          
endmodule // top$doptrf$0$mul_0$s1_sig_a


module top$doptrf$0$mul_0$sig_mul(a,b,hi,sticky);
    
    // Module arguments
    input wire  [15:0] a;
    input wire  [15:0] b;
    output reg  [17:0] hi;
    output reg  sticky;
    
    // Update code (custom)
    wire [31:0] prod;
    assign prod = a * b;
    always @(*) begin
        hi = prod[31:14];
        sticky = |prod[13:0];
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


module top$klmsel(d$0,d$1,d$2,d$3,d$4,d$5,j0$0,j0$1,j0$2,j0$3,j0$4,j0$5,j1$0,j1$1,j1$2,j1$3,j1$4,j1$5,j2$0,j2$1,j2$2,j2$3,j2$4,j2$5,y0$0,y0$1,y0$2,y0$3,y0$4,y0$5,y1$0,y1$1,y1$2,y1$3,y1$4,y1$5,y2$0,y2$1,y2$2,y2$3,y2$4,y2$5);
    
    // Module arguments
    input wire  [23:0] d$0;
    input wire  [23:0] d$1;
    input wire  [23:0] d$2;
    input wire  [23:0] d$3;
    input wire  [23:0] d$4;
    input wire  [23:0] d$5;
    input wire  [4:0] j0$0;
    input wire  [4:0] j0$1;
    input wire  [4:0] j0$2;
    input wire  [4:0] j0$3;
    input wire  [4:0] j0$4;
    input wire  [4:0] j0$5;
    input wire  [4:0] j1$0;
    input wire  [4:0] j1$1;
    input wire  [4:0] j1$2;
    input wire  [4:0] j1$3;
    input wire  [4:0] j1$4;
    input wire  [4:0] j1$5;
    input wire  [4:0] j2$0;
    input wire  [4:0] j2$1;
    input wire  [4:0] j2$2;
    input wire  [4:0] j2$3;
    input wire  [4:0] j2$4;
    input wire  [4:0] j2$5;
    output reg  [23:0] y0$0;
    output reg  [23:0] y0$1;
    output reg  [23:0] y0$2;
    output reg  [23:0] y0$3;
    output reg  [23:0] y0$4;
    output reg  [23:0] y0$5;
    output reg  [23:0] y1$0;
    output reg  [23:0] y1$1;
    output reg  [23:0] y1$2;
    output reg  [23:0] y1$3;
    output reg  [23:0] y1$4;
    output reg  [23:0] y1$5;
    output reg  [23:0] y2$0;
    output reg  [23:0] y2$1;
    output reg  [23:0] y2$2;
    output reg  [23:0] y2$3;
    output reg  [23:0] y2$4;
    output reg  [23:0] y2$5;
    
    // Constant declarations
    localparam  idx$0 = 5'b0;
    localparam  idx$1 = 5'b1;
    localparam  idx$2 = 5'b10;
    localparam  idx$3 = 5'b11;
    localparam  idx$4 = 5'b100;
    localparam  idx$5 = 5'b101;
    
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
    end
    
endmodule // top$klmsel


module top$setup(clock,load_en,load_addr,load_data,c0$0,c0$1,c0$2,c0$3,c0$4,c0$5,c1$0,c1$1,c1$2,c1$3,c1$4,c1$5,c2$0,c2$1,c2$2,c2$3,c2$4,c2$5,c$0,c$1,c$2,c$3,c$4,c$5,j0$0,j0$1,j0$2,j0$3,j0$4,j0$5,j1$0,j1$1,j1$2,j1$3,j1$4,j1$5,j2$0,j2$1,j2$2,j2$3,j2$4,j2$5,round_up$0,round_up$1,round_up$2,round_up$3,round_up$4,round_up$5);
    
    // Module arguments
    input wire  clock;
    input wire  load_en;
    input wire  [7:0] load_addr;
    input wire  [23:0] load_data;
    output reg  [23:0] c0$0;
    output reg  [23:0] c0$1;
    output reg  [23:0] c0$2;
    output reg  [23:0] c0$3;
    output reg  [23:0] c0$4;
    output reg  [23:0] c0$5;
    output reg  [23:0] c1$0;
    output reg  [23:0] c1$1;
    output reg  [23:0] c1$2;
    output reg  [23:0] c1$3;
    output reg  [23:0] c1$4;
    output reg  [23:0] c1$5;
    output reg  [23:0] c2$0;
    output reg  [23:0] c2$1;
    output reg  [23:0] c2$2;
    output reg  [23:0] c2$3;
    output reg  [23:0] c2$4;
    output reg  [23:0] c2$5;
    output reg  [23:0] c$0;
    output reg  [23:0] c$1;
    output reg  [23:0] c$2;
    output reg  [23:0] c$3;
    output reg  [23:0] c$4;
    output reg  [23:0] c$5;
    output reg  [4:0] j0$0;
    output reg  [4:0] j0$1;
    output reg  [4:0] j0$2;
    output reg  [4:0] j0$3;
    output reg  [4:0] j0$4;
    output reg  [4:0] j0$5;
    output reg  [4:0] j1$0;
    output reg  [4:0] j1$1;
    output reg  [4:0] j1$2;
    output reg  [4:0] j1$3;
    output reg  [4:0] j1$4;
    output reg  [4:0] j1$5;
    output reg  [4:0] j2$0;
    output reg  [4:0] j2$1;
    output reg  [4:0] j2$2;
    output reg  [4:0] j2$3;
    output reg  [4:0] j2$4;
    output reg  [4:0] j2$5;
    output reg  round_up$0;
    output reg  round_up$1;
    output reg  round_up$2;
    output reg  round_up$3;
    output reg  round_up$4;
    output reg  round_up$5;
    
    // Constant declarations
    localparam  idx$0 = 5'b0;
    localparam  idx$1 = 5'b1;
    localparam  idx$2 = 5'b10;
    localparam  idx$3 = 5'b11;
    localparam  idx$4 = 5'b100;
    localparam  idx$5 = 5'b101;
    
    // Stub signals
    reg  [23:0] cmat_0$0$d;
    wire  [23:0] cmat_0$0$q;
    reg  cmat_0$0$clock;
    reg  [23:0] cmat_0$1$d;
    wire  [23:0] cmat_0$1$q;
    reg  cmat_0$1$clock;
    reg  [23:0] cmat_0$2$d;
    wire  [23:0] cmat_0$2$q;
    reg  cmat_0$2$clock;
    reg  [23:0] cmat_0$3$d;
    wire  [23:0] cmat_0$3$q;
    reg  cmat_0$3$clock;
    reg  [23:0] cmat_0$4$d;
    wire  [23:0] cmat_0$4$q;
    reg  cmat_0$4$clock;
    reg  [23:0] cmat_0$5$d;
    wire  [23:0] cmat_0$5$q;
    reg  cmat_0$5$clock;
    reg  [23:0] cmat_1$0$d;
    wire  [23:0] cmat_1$0$q;
    reg  cmat_1$0$clock;
    reg  [23:0] cmat_1$1$d;
    wire  [23:0] cmat_1$1$q;
    reg  cmat_1$1$clock;
    reg  [23:0] cmat_1$2$d;
    wire  [23:0] cmat_1$2$q;
    reg  cmat_1$2$clock;
    reg  [23:0] cmat_1$3$d;
    wire  [23:0] cmat_1$3$q;
    reg  cmat_1$3$clock;
    reg  [23:0] cmat_1$4$d;
    wire  [23:0] cmat_1$4$q;
    reg  cmat_1$4$clock;
    reg  [23:0] cmat_1$5$d;
    wire  [23:0] cmat_1$5$q;
    reg  cmat_1$5$clock;
    reg  [23:0] cmat_2$0$d;
    wire  [23:0] cmat_2$0$q;
    reg  cmat_2$0$clock;
    reg  [23:0] cmat_2$1$d;
    wire  [23:0] cmat_2$1$q;
    reg  cmat_2$1$clock;
    reg  [23:0] cmat_2$2$d;
    wire  [23:0] cmat_2$2$q;
    reg  cmat_2$2$clock;
    reg  [23:0] cmat_2$3$d;
    wire  [23:0] cmat_2$3$q;
    reg  cmat_2$3$clock;
    reg  [23:0] cmat_2$4$d;
    wire  [23:0] cmat_2$4$q;
    reg  cmat_2$4$clock;
    reg  [23:0] cmat_2$5$d;
    wire  [23:0] cmat_2$5$q;
    reg  cmat_2$5$clock;
    reg  [23:0] cvec$0$d;
    wire  [23:0] cvec$0$q;
    reg  cvec$0$clock;
    reg  [23:0] cvec$1$d;
    wire  [23:0] cvec$1$q;
    reg  cvec$1$clock;
    reg  [23:0] cvec$2$d;
    wire  [23:0] cvec$2$q;
    reg  cvec$2$clock;
    reg  [23:0] cvec$3$d;
    wire  [23:0] cvec$3$q;
    reg  cvec$3$clock;
    reg  [23:0] cvec$4$d;
    wire  [23:0] cvec$4$q;
    reg  cvec$4$clock;
    reg  [23:0] cvec$5$d;
    wire  [23:0] cvec$5$q;
    reg  cvec$5$clock;
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
