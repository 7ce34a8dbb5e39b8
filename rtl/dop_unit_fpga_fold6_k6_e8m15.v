

module top(clock,load_en,load_addr,load_data,d$0,d$1,d$2,d$3,d$4,d$5,e$0,e$1,e$2,e$3,e$4,e$5,tag,valid_in,overlap,tag_out,valid_out,in_ready);
    
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
    output reg  in_ready;
    
    // Constant declarations
    localparam  idx$0 = 5'b0;
    localparam  idx$1 = 5'b1;
    localparam  idx$2 = 5'b10;
    localparam  idx$3 = 5'b11;
    localparam  idx$4 = 5'b100;
    localparam  idx$5 = 5'b101;
    localparam  last_pass = 5'b101;
    localparam  first_out = 5'b10;
    localparam  last_out = 5'b1;
    
    // Stub signals
    reg  run$d;
    wire  run$q;
    reg  run$clock;
    reg  [4:0] counter$d;
    wire  [4:0] counter$q;
    reg  counter$clock;
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
    reg  [23:0] held_d$0$d;
    wire  [23:0] held_d$0$q;
    reg  held_d$0$clock;
    reg  [23:0] held_d$1$d;
    wire  [23:0] held_d$1$q;
    reg  held_d$1$clock;
    reg  [23:0] held_d$2$d;
    wire  [23:0] held_d$2$q;
    reg  held_d$2$clock;
    reg  [23:0] held_d$3$d;
    wire  [23:0] held_d$3$q;
    reg  held_d$3$clock;
    reg  [23:0] held_d$4$d;
    wire  [23:0] held_d$4$q;
    reg  held_d$4$clock;
    reg  [23:0] held_d$5$d;
    wire  [23:0] held_d$5$q;
    reg  held_d$5$clock;
    reg  [23:0] held_e$0$d;
    wire  [23:0] held_e$0$q;
    reg  held_e$0$clock;
    reg  [23:0] held_e$1$d;
    wire  [23:0] held_e$1$q;
    reg  held_e$1$clock;
    reg  [23:0] held_e$2$d;
    wire  [23:0] held_e$2$q;
    reg  held_e$2$clock;
    reg  [23:0] held_e$3$d;
    wire  [23:0] held_e$3$q;
    reg  held_e$3$clock;
    reg  [23:0] held_e$4$d;
    wire  [23:0] held_e$4$q;
    reg  held_e$4$clock;
    reg  [23:0] held_e$5$d;
    wire  [23:0] held_e$5$q;
    reg  held_e$5$clock;
    reg  [15:0] held_tag$d;
    wire  [15:0] held_tag$q;
    reg  held_tag$clock;
    reg  held_valid$d;
    wire  held_valid$q;
    reg  held_valid$clock;
    reg  [23:0] klmsel$d$0;
    reg  [23:0] klmsel$d$1;
    reg  [23:0] klmsel$d$2;
    reg  [23:0] klmsel$d$3;
    reg  [23:0] klmsel$d$4;
    reg  [23:0] klmsel$d$5;
    reg  [4:0] klmsel$j0$0;
    reg  [4:0] klmsel$j1$0;
    reg  [4:0] klmsel$j2$0;
    wire  [23:0] klmsel$y0$0;
    wire  [23:0] klmsel$y1$0;
    wire  [23:0] klmsel$y2$0;
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
    reg  tag_line$clock;
    reg  [15:0] tag_line$d;
    wire  [15:0] tag_line$q;
    reg  acc$d;
    wire  acc$q;
    reg  acc$clock;
    
    // Local signals
    reg  c_zero;
    reg  c_take;
    reg  [4:0] c_j0$0;
    reg  [4:0] c_j1$0;
    reg  [4:0] c_j2$0;
    reg  c_any;
    reg  c_first;
    
    // Sub module instances
    top$acc run(
        .d(run$d),
        .q(run$q),
        .clock(run$clock)
    );
    top$counter counter(
        .d(counter$d),
        .q(counter$q),
        .clock(counter$clock)
    );
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
    top$doptrf$0$add_0$s6_y held_d$0(
        .d(held_d$0$d),
        .q(held_d$0$q),
        .clock(held_d$0$clock)
    );
    top$doptrf$0$add_0$s6_y held_d$1(
        .d(held_d$1$d),
        .q(held_d$1$q),
        .clock(held_d$1$clock)
    );
    top$doptrf$0$add_0$s6_y held_d$2(
        .d(held_d$2$d),
        .q(held_d$2$q),
        .clock(held_d$2$clock)
    );
    top$doptrf$0$add_0$s6_y held_d$3(
        .d(held_d$3$d),
        .q(held_d$3$q),
        .clock(held_d$3$clock)
    );
    top$doptrf$0$add_0$s6_y held_d$4(
        .d(held_d$4$d),
        .q(held_d$4$q),
        .clock(held_d$4$clock)
    );
    top$doptrf$0$add_0$s6_y held_d$5(
        .d(held_d$5$d),
        .q(held_d$5$q),
        .clock(held_d$5$clock)
    );
    top$doptrf$0$add_0$s6_y held_e$0(
        .d(held_e$0$d),
        .q(held_e$0$q),
        .clock(held_e$0$clock)
    );
    top$doptrf$0$add_0$s6_y held_e$1(
        .d(held_e$1$d),
        .q(held_e$1$q),
        .clock(held_e$1$clock)
    );
    top$doptrf$0$add_0$s6_y held_e$2(
        .d(held_e$2$d),
        .q(held_e$2$q),
        .clock(held_e$2$clock)
    );
    top$doptrf$0$add_0$s6_y held_e$3(
        .d(held_e$3$d),
        .q(held_e$3$q),
        .clock(held_e$3$clock)
    );
    top$doptrf$0$add_0$s6_y held_e$4(
        .d(held_e$4$d),
        .q(held_e$4$q),
        .clock(held_e$4$clock)
    );
    top$doptrf$0$add_0$s6_y held_e$5(
        .d(held_e$5$d),
        .q(held_e$5$q),
        .clock(held_e$5$clock)
    );
    top$doptrf$0$add_0$s1_big held_tag(
        .d(held_tag$d),
        .q(held_tag$q),
        .clock(held_tag$clock)
    );
    top$acc held_valid(
        .d(held_valid$d),
        .q(held_valid$q),
        .clock(held_valid$clock)
    );
    top$klmsel klmsel(
        .d$0(klmsel$d$0),
        .d$1(klmsel$d$1),
        .d$2(klmsel$d$2),
        .d$3(klmsel$d$3),
        .d$4(klmsel$d$4),
        .d$5(klmsel$d$5),
        .j0$0(klmsel$j0$0),
        .j1$0(klmsel$j1$0),
        .j2$0(klmsel$j2$0),
        .y0$0(klmsel$y0$0),
        .y1$0(klmsel$y1$0),
        .y2$0(klmsel$y2$0)
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
    top$tag_line tag_line(
        .clock(tag_line$clock),
        .d(tag_line$d),
        .q(tag_line$q)
    );
    top$acc acc(
        .d(acc$d),
        .q(acc$q),
        .clock(acc$clock)
    );
    
    // Update code
    always @(*) begin
        run$clock = clock;
        counter$clock = clock;
        held_tag$clock = clock;
        held_valid$clock = clock;
        acc$clock = clock;
        run$d = run$q;
        counter$d = counter$q;
        held_tag$d = held_tag$q;
        held_valid$d = held_valid$q;
        acc$d = acc$q;
        c_zero = counter$q == 32'h0;
        c_take = valid_in & c_zero;
        in_ready = c_zero;
        run$d = run$q | c_take;
        counter$d = 32'h0;
        if ((run$q | c_take) & (counter$q != last_pass)) begin
            counter$d = counter$q + 32'h1;
        end
        setup$clock = clock;
        setup$load_en = load_en;
        setup$load_addr = load_addr;
        setup$load_data = load_data;
        tag_line$d = held_tag$q;
        if (c_zero) begin
            held_tag$d = tag;
            held_valid$d = c_take;
            tag_line$d = tag;
        end
        tag_line$clock = clock;
        held_d$0$clock = clock;
        held_e$0$clock = clock;
        held_d$0$d = held_d$0$q;
        held_e$0$d = held_e$0$q;
        if (c_zero) begin
            held_d$0$d = d$0;
            held_e$0$d = e$0;
            klmsel$d$0 = d$0;
        end
        else begin
            klmsel$d$0 = held_d$0$q;
        end
        held_d$1$clock = clock;
        held_e$1$clock = clock;
        held_d$1$d = held_d$1$q;
        held_e$1$d = held_e$1$q;
        if (c_zero) begin
            held_d$1$d = d$1;
            held_e$1$d = e$1;
            klmsel$d$1 = d$1;
        end
        else begin
            klmsel$d$1 = held_d$1$q;
        end
        held_d$2$clock = clock;
        held_e$2$clock = clock;
        held_d$2$d = held_d$2$q;
        held_e$2$d = held_e$2$q;
        if (c_zero) begin
            held_d$2$d = d$2;
            held_e$2$d = e$2;
            klmsel$d$2 = d$2;
        end
        else begin
            klmsel$d$2 = held_d$2$q;
        end
        held_d$3$clock = clock;
        held_e$3$clock = clock;
        held_d$3$d = held_d$3$q;
        held_e$3$d = held_e$3$q;
        if (c_zero) begin
            held_d$3$d = d$3;
            held_e$3$d = e$3;
            klmsel$d$3 = d$3;
        end
        else begin
            klmsel$d$3 = held_d$3$q;
        end
        held_d$4$clock = clock;
        held_e$4$clock = clock;
        held_d$4$d = held_d$4$q;
        held_e$4$d = held_e$4$q;
        if (c_zero) begin
            held_d$4$d = d$4;
            held_e$4$d = e$4;
            klmsel$d$4 = d$4;
        end
        else begin
            klmsel$d$4 = held_d$4$q;
        end
        held_d$5$clock = clock;
        held_e$5$clock = clock;
        held_d$5$d = held_d$5$q;
        held_e$5$d = held_e$5$q;
        if (c_zero) begin
            held_d$5$d = d$5;
            held_e$5$d = e$5;
            klmsel$d$5 = d$5;
        end
        else begin
            klmsel$d$5 = held_d$5$q;
        end
        doptrf$0$clock = clock;
        doptrf$0$round_up = setup$round_up$0;
        doptrf$0$valid_in = held_valid$q;
        if (c_zero) begin
            doptrf$0$valid_in = c_take;
        end
        c_j0$0 = setup$j0$0;
        c_j1$0 = setup$j1$0;
        c_j2$0 = setup$j2$0;
        doptrf$0$c0 = setup$c0$0;
        doptrf$0$c1 = setup$c1$0;
        doptrf$0$c2 = setup$c2$0;
        doptrf$0$c = setup$c$0;
        doptrf$0$e = e$3;
        if (counter$q == idx$1) begin
            c_j0$0 = setup$j0$1;
            c_j1$0 = setup$j1$1;
            c_j2$0 = setup$j2$1;
            doptrf$0$c0 = setup$c0$1;
            doptrf$0$c1 = setup$c1$1;
            doptrf$0$c2 = setup$c2$1;
            doptrf$0$c = setup$c$1;
            doptrf$0$e = held_e$4$q;
        end
        if (counter$q == idx$2) begin
            c_j0$0 = setup$j0$2;
            c_j1$0 = setup$j1$2;
            c_j2$0 = setup$j2$2;
            doptrf$0$c0 = setup$c0$2;
            doptrf$0$c1 = setup$c1$2;
            doptrf$0$c2 = setup$c2$2;
            doptrf$0$c = setup$c$2;
            doptrf$0$e = held_e$5$q;
        end
        if (counter$q == idx$3) begin
            c_j0$0 = setup$j0$3;
            c_j1$0 = setup$j1$3;
            c_j2$0 = setup$j2$3;
            doptrf$0$c0 = setup$c0$3;
            doptrf$0$c1 = setup$c1$3;
            doptrf$0$c2 = setup$c2$3;
            doptrf$0$c = setup$c$3;
            doptrf$0$e = held_e$0$q;
        end
        if (counter$q == idx$4) begin
            c_j0$0 = setup$j0$4;
            c_j1$0 = setup$j1$4;
            c_j2$0 = setup$j2$4;
            doptrf$0$c0 = setup$c0$4;
            doptrf$0$c1 = setup$c1$4;
            doptrf$0$c2 = setup$c2$4;
            doptrf$0$c = setup$c$4;
            doptrf$0$e = held_e$1$q;
        end
        if (counter$q == idx$5) begin
            c_j0$0 = setup$j0$5;
            c_j1$0 = setup$j1$5;
            c_j2$0 = setup$j2$5;
            doptrf$0$c0 = setup$c0$5;
            doptrf$0$c1 = setup$c1$5;
            doptrf$0$c2 = setup$c2$5;
            doptrf$0$c = setup$c$5;
            doptrf$0$e = held_e$2$q;
        end
        klmsel$j0$0 = c_j0$0;
        klmsel$j1$0 = c_j1$0;
        klmsel$j2$0 = c_j2$0;
        doptrf$0$d0 = klmsel$y0$0;
        doptrf$0$d1 = klmsel$y1$0;
        doptrf$0$d2 = klmsel$y2$0;
        c_any = 1'b0;
        if (doptrf$0$flag) begin
            c_any = 1'b1;
        end
        c_first = counter$q == first_out;
        acc$d = acc$q | c_any;
        if (c_first) begin
            acc$d = c_any;
        end
        overlap = ~(c_any | (acc$q & ~c_first));
        tag_out = tag_line$q;
        valid_out = doptrf$0$valid_out & (counter$q == last_out);
    end
    
endmodule // top


module top$acc(d,q,clock);
    
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
          
endmodule // top$acc


module top$counter(d,q,clock);
    
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
          
endmodule // top$counter


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
    reg  [23:0] c_6$d;
    wire  [23:0] c_6$q;
    reg  c_6$clock;
    reg  [23:0] c_7$d;
    wire  [23:0] c_7$q;
    reg  c_7$clock;
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
    reg  [23:0] e_12$d;
    wire  [23:0] e_12$q;
    reg  e_12$clock;
    reg  [23:0] e_13$d;
    wire  [23:0] e_13$q;
    reg  e_13$clock;
    reg  [23:0] e_14$d;
    wire  [23:0] e_14$q;
    reg  e_14$clock;
    reg  [23:0] e_15$d;
    wire  [23:0] e_15$q;
    reg  e_15$clock;
    reg  [23:0] e_16$d;
    wire  [23:0] e_16$q;
    reg  e_16$clock;
    reg  [23:0] e_17$d;
    wire  [23:0] e_17$q;
    reg  e_17$clock;
    reg  [23:0] e_18$d;
    wire  [23:0] e_18$q;
    reg  e_18$clock;
    reg  [23:0] e_19$d;
    wire  [23:0] e_19$q;
    reg  e_19$clock;
    reg  s26_valid$d;
    wire  s26_valid$q;
    reg  s26_valid$clock;
    reg  [23:0] s26_s$d;
    wire  [23:0] s26_s$q;
    reg  s26_s$clock;
    reg  s26_flag$d;
    wire  s26_flag$q;
    reg  s26_flag$clock;
    
    // Local signals
    reg  [7:0] c15_exp;
    reg  [14:0] c15_frac;
    reg  [22:0] c15_mag;
    reg  c15_nan;
    
    // Sub module instances
    top$acc s1_valid(
        .d(s1_valid$d),
        .q(s1_valid$q),
        .clock(s1_valid$clock)
    );
    top$doptrf$0$add_0$s6_y s1_d0(
        .d(s1_d0$d),
        .q(s1_d0$q),
        .clock(s1_d0$clock)
    );
    top$doptrf$0$add_0$s6_y s1_d1(
        .d(s1_d1$d),
        .q(s1_d1$q),
        .clock(s1_d1$clock)
    );
    top$doptrf$0$add_0$s6_y s1_d2(
        .d(s1_d2$d),
        .q(s1_d2$q),
        .clock(s1_d2$clock)
    );
    top$doptrf$0$add_0$s6_y s1_c0(
        .d(s1_c0$d),
        .q(s1_c0$q),
        .clock(s1_c0$clock)
    );
    top$doptrf$0$add_0$s6_y s1_c1(
        .d(s1_c1$d),
        .q(s1_c1$q),
        .clock(s1_c1$clock)
    );
    top$doptrf$0$add_0$s6_y s1_c2(
        .d(s1_c2$d),
        .q(s1_c2$q),
        .clock(s1_c2$clock)
    );
    top$doptrf$0$add_0$s6_y s1_c(
        .d(s1_c$d),
        .q(s1_c$q),
        .clock(s1_c$clock)
    );
    top$doptrf$0$add_0$s6_y s1_e(
        .d(s1_e$d),
        .q(s1_e$q),
        .clock(s1_e$clock)
    );
    top$acc s1_round(
        .d(s1_round$d),
        .q(s1_round$q),
        .clock(s1_round$clock)
    );
    top$doptrf$0$r_mul r_mul(
        .clock(r_mul$clock),
        .d(r_mul$d),
        .q(r_mul$q)
    );
    top$doptrf$0$r_s r_sum(
        .clock(r_sum$clock),
        .d(r_sum$d),
        .q(r_sum$q)
    );
    top$doptrf$0$r_s r_u(
        .clock(r_u$clock),
        .d(r_u$d),
        .q(r_u$q)
    );
    top$doptrf$0$r_s r_s(
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
    top$doptrf$0$add_0$s6_y c_2(
        .d(c_2$d),
        .q(c_2$q),
        .clock(c_2$clock)
    );
    top$doptrf$0$add_0$s6_y c_3(
        .d(c_3$d),
        .q(c_3$q),
        .clock(c_3$clock)
    );
    top$doptrf$0$add_0$s6_y c_4(
        .d(c_4$d),
        .q(c_4$q),
        .clock(c_4$clock)
    );
    top$doptrf$0$add_0$s6_y c_5(
        .d(c_5$d),
        .q(c_5$q),
        .clock(c_5$clock)
    );
    top$doptrf$0$add_0$s6_y c_6(
        .d(c_6$d),
        .q(c_6$q),
        .clock(c_6$clock)
    );
    top$doptrf$0$add_0$s6_y c_7(
        .d(c_7$d),
        .q(c_7$q),
        .clock(c_7$clock)
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
    top$doptrf$0$add_0$s6_y e_2(
        .d(e_2$d),
        .q(e_2$q),
        .clock(e_2$clock)
    );
    top$doptrf$0$add_0$s6_y e_3(
        .d(e_3$d),
        .q(e_3$q),
        .clock(e_3$clock)
    );
    top$doptrf$0$add_0$s6_y e_4(
        .d(e_4$d),
        .q(e_4$q),
        .clock(e_4$clock)
    );
    top$doptrf$0$add_0$s6_y e_5(
        .d(e_5$d),
        .q(e_5$q),
        .clock(e_5$clock)
    );
    top$doptrf$0$add_0$s6_y e_6(
        .d(e_6$d),
        .q(e_6$q),
        .clock(e_6$clock)
    );
    top$doptrf$0$add_0$s6_y e_7(
        .d(e_7$d),
        .q(e_7$q),
        .clock(e_7$clock)
    );
    top$doptrf$0$add_0$s6_y e_8(
        .d(e_8$d),
        .q(e_8$q),
        .clock(e_8$clock)
    );
    top$doptrf$0$add_0$s6_y e_9(
        .d(e_9$d),
        .q(e_9$q),
        .clock(e_9$clock)
    );
    top$doptrf$0$add_0$s6_y e_10(
        .d(e_10$d),
        .q(e_10$q),
        .clock(e_10$clock)
    );
    top$doptrf$0$add_0$s6_y e_11(
        .d(e_11$d),
        .q(e_11$q),
        .clock(e_11$clock)
    );
    top$doptrf$0$add_0$s6_y e_12(
        .d(e_12$d),
        .q(e_12$q),
        .clock(e_12$clock)
    );
    top$doptrf$0$add_0$s6_y e_13(
        .d(e_13$d),
        .q(e_13$q),
        .clock(e_13$clock)
    );
    top$doptrf$0$add_0$s6_y e_14(
        .d(e_14$d),
        .q(e_14$q),
        .clock(e_14$clock)
    );
    top$doptrf$0$add_0$s6_y e_15(
        .d(e_15$d),
        .q(e_15$q),
        .clock(e_15$clock)
    );
    top$doptrf$0$add_0$s6_y e_16(
        .d(e_16$d),
        .q(e_16$q),
        .clock(e_16$clock)
    );
    top$doptrf$0$add_0$s6_y e_17(
        .d(e_17$d),
        .q(e_17$q),
        .clock(e_17$clock)
    );
    top$doptrf$0$add_0$s6_y e_18(
        .d(e_18$d),
        .q(e_18$q),
        .clock(e_18$clock)
    );
    top$doptrf$0$add_0$s6_y e_19(
        .d(e_19$d),
        .q(e_19$q),
        .clock(e_19$clock)
    );
    top$acc s26_valid(
        .d(s26_valid$d),
        .q(s26_valid$q),
        .clock(s26_valid$clock)
    );
    top$doptrf$0$add_0$s6_y s26_s(
        .d(s26_s$d),
        .q(s26_s$q),
        .clock(s26_s$clock)
    );
    top$acc s26_flag(
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
        c15_exp = add_3$y[(32'hf)+:(8)];
        c15_frac = add_3$y[(32'h0)+:(15)];
        c15_mag = add_3$y[(32'h0)+:(23)];
        c15_nan = &c15_exp & (c15_frac != 32'h0);
        s26_valid$d = add_3$valid_out;
        s26_s$d = add_3$y;
        s26_flag$d = add_3$y[32'h17] & (c15_mag != 32'h0) & ~c15_nan;
        s = s26_s$q;
        flag = s26_flag$q;
        valid_out = s26_valid$q;
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
    top$acc s1_valid(
        .d(s1_valid$d),
        .q(s1_valid$q),
        .clock(s1_valid$clock)
    );
    top$acc s1_nan(
        .d(s1_nan$d),
        .q(s1_nan$q),
        .clock(s1_nan$clock)
    );
    top$acc s1_inf(
        .d(s1_inf$d),
        .q(s1_inf$q),
        .clock(s1_inf$clock)
    );
    top$acc s1_inf_sign(
        .d(s1_inf_sign$d),
        .q(s1_inf_sign$q),
        .clock(s1_inf_sign$clock)
    );
    top$acc s1_zero_sign(
        .d(s1_zero_sign$d),
        .q(s1_zero_sign$q),
        .clock(s1_zero_sign$clock)
    );
    top$acc s1_sign(
        .d(s1_sign$d),
        .q(s1_sign$q),
        .clock(s1_sign$clock)
    );
    top$acc s1_eff_sub(
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
    top$doptrf$0$add_0$s1_exp s1_shift(
        .d(s1_shift$d),
        .q(s1_shift$q),
        .clock(s1_shift$clock)
    );
    top$acc s2_valid(
        .d(s2_valid$d),
        .q(s2_valid$q),
        .clock(s2_valid$clock)
    );
    top$acc s2_nan(
        .d(s2_nan$d),
        .q(s2_nan$q),
        .clock(s2_nan$clock)
    );
    top$acc s2_inf(
        .d(s2_inf$d),
        .q(s2_inf$q),
        .clock(s2_inf$clock)
    );
    top$acc s2_inf_sign(
        .d(s2_inf_sign$d),
        .q(s2_inf_sign$q),
        .clock(s2_inf_sign$clock)
    );
    top$acc s2_zero_sign(
        .d(s2_zero_sign$d),
        .q(s2_zero_sign$q),
        .clock(s2_zero_sign$clock)
    );
    top$acc s2_sign(
        .d(s2_sign$d),
        .q(s2_sign$q),
        .clock(s2_sign$clock)
    );
    top$acc s2_eff_sub(
        .d(s2_eff_sub$d),
        .q(s2_eff_sub$q),
        .clock(s2_eff_sub$clock)
    );
    top$doptrf$0$add_0$s1_exp s2_exp(
        .d(s2_exp$d),
        .q(s2_exp$q),
        .clock(s2_exp$clock)
    );
    top$doptrf$0$add_0$s2_big s2_big(
        .d(s2_big$d),
        .q(s2_big$q),
        .clock(s2_big$clock)
    );
    top$doptrf$0$add_0$s2_big s2_small(
        .d(s2_small$d),
        .q(s2_small$q),
        .clock(s2_small$clock)
    );
    top$acc s3_valid(
        .d(s3_valid$d),
        .q(s3_valid$q),
        .clock(s3_valid$clock)
    );
    top$acc s3_nan(
        .d(s3_nan$d),
        .q(s3_nan$q),
        .clock(s3_nan$clock)
    );
    top$acc s3_inf(
        .d(s3_inf$d),
        .q(s3_inf$q),
        .clock(s3_inf$clock)
    );
    top$acc s3_inf_sign(
        .d(s3_inf_sign$d),
        .q(s3_inf_sign$q),
        .clock(s3_inf_sign$clock)
    );
    top$acc s3_zero_sign(
        .d(s3_zero_sign$d),
        .q(s3_zero_sign$q),
        .clock(s3_zero_sign$clock)
    );
    top$acc s3_sign(
        .d(s3_sign$d),
        .q(s3_sign$q),
        .clock(s3_sign$clock)
    );
    top$doptrf$0$add_0$s1_exp s3_exp(
        .d(s3_exp$d),
        .q(s3_exp$q),
        .clock(s3_exp$clock)
    );
    top$doptrf$0$add_0$s3_sum s3_sum(
        .d(s3_sum$d),
        .q(s3_sum$q),
        .clock(s3_sum$clock)
    );
    top$doptrf$0$add_0$s2_big s3_marker(
        .d(s3_marker$d),
        .q(s3_marker$q),
        .clock(s3_marker$clock)
    );
    top$doptrf$0$add_0$lzc lzc(
        .x(lzc$x),
        .lz(lzc$lz)
    );
    top$acc s4_valid(
        .d(s4_valid$d),
        .q(s4_valid$q),
        .clock(s4_valid$clock)
    );
    top$acc s4_sign(
        .d(s4_sign$d),
        .q(s4_sign$q),
        .clock(s4_sign$clock)
    );
    top$acc s4_nan(
        .d(s4_nan$d),
        .q(s4_nan$q),
        .clock(s4_nan$clock)
    );
    top$acc s4_inf(
        .d(s4_inf$d),
        .q(s4_inf$q),
        .clock(s4_inf$clock)
    );
    top$acc s4_zero(
        .d(s4_zero$d),
        .q(s4_zero$q),
        .clock(s4_zero$clock)
    );
    top$doptrf$0$add_0$s1_exp s4_exp(
        .d(s4_exp$d),
        .q(s4_exp$q),
        .clock(s4_exp$clock)
    );
    top$doptrf$0$add_0$s1_exp s4_shift(
        .d(s4_shift$d),
        .q(s4_shift$q),
        .clock(s4_shift$clock)
    );
    top$doptrf$0$add_0$s3_sum s4_sum(
        .d(s4_sum$d),
        .q(s4_sum$q),
        .clock(s4_sum$clock)
    );
    top$acc s5_valid(
        .d(s5_valid$d),
        .q(s5_valid$q),
        .clock(s5_valid$clock)
    );
    top$acc s5_sign(
        .d(s5_sign$d),
        .q(s5_sign$q),
        .clock(s5_sign$clock)
    );
    top$acc s5_nan(
        .d(s5_nan$d),
        .q(s5_nan$q),
        .clock(s5_nan$clock)
    );
    top$acc s5_inf(
        .d(s5_inf$d),
        .q(s5_inf$q),
        .clock(s5_inf$clock)
    );
    top$acc s5_zero(
        .d(s5_zero$d),
        .q(s5_zero$q),
        .clock(s5_zero$clock)
    );
    top$acc s5_ovf(
        .d(s5_ovf$d),
        .q(s5_ovf$q),
        .clock(s5_ovf$clock)
    );
    top$doptrf$0$add_0$s1_exp s5_efield(
        .d(s5_efield$d),
        .q(s5_efield$q),
        .clock(s5_efield$clock)
    );
    top$doptrf$0$add_0$s5_nm s5_nm(
        .d(s5_nm$d),
        .q(s5_nm$q),
        .clock(s5_nm$clock)
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
    top$acc s6_valid(
        .d(s6_valid$d),
        .q(s6_valid$q),
        .clock(s6_valid$clock)
    );
    top$doptrf$0$add_0$s6_y s6_y(
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
    
endmodule // top$doptrf$0$add_0


module top$doptrf$0$add_0$lzc(x,lz);
    
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
    
endmodule // top$doptrf$0$add_0$lzc


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
          
endmodule // top$doptrf$0$add_0$s1_big


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


module top$doptrf$0$add_0$s2_big(d,q,clock);
    
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
          
endmodule // top$doptrf$0$add_0$s2_big


module top$doptrf$0$add_0$s3_sum(d,q,clock);
    
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
          
endmodule // top$doptrf$0$add_0$s3_sum


module top$doptrf$0$add_0$s5_nm(d,q,clock);
    
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
          
endmodule // top$doptrf$0$add_0$s5_nm


module top$doptrf$0$add_0$s6_y(d,q,clock);
    
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
          
endmodule // top$doptrf$0$add_0$s6_y


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
    top$doptrf$0$mul_0$lzc_a lzc_a(
        .x(lzc_a$x),
        .lz(lzc_a$lz)
    );
    top$doptrf$0$mul_0$lzc_a lzc_b(
        .x(lzc_b$x),
        .lz(lzc_b$lz)
    );
    top$acc s1_valid(
        .d(s1_valid$d),
        .q(s1_valid$q),
        .clock(s1_valid$clock)
    );
    top$acc s1_sign(
        .d(s1_sign$d),
        .q(s1_sign$q),
        .clock(s1_sign$clock)
    );
    top$acc s1_nan(
        .d(s1_nan$d),
        .q(s1_nan$q),
        .clock(s1_nan$clock)
    );
    top$acc s1_inf(
        .d(s1_inf$d),
        .q(s1_inf$q),
        .clock(s1_inf$clock)
    );
    top$acc s1_zero(
        .d(s1_zero$d),
        .q(s1_zero$q),
        .clock(s1_zero$clock)
    );
    top$doptrf$0$add_0$s1_exp s1_exp_a(
        .d(s1_exp_a$d),
        .q(s1_exp_a$q),
        .clock(s1_exp_a$clock)
    );
    top$doptrf$0$add_0$s1_exp s1_exp_b(
        .d(s1_exp_b$d),
        .q(s1_exp_b$q),
        .clock(s1_exp_b$clock)
    );
    top$doptrf$0$add_0$s1_big s1_sig_a(
        .d(s1_sig_a$d),
        .q(s1_sig_a$q),
        .clock(s1_sig_a$clock)
    );
    top$doptrf$0$add_0$s1_big s1_sig_b(
        .d(s1_sig_b$d),
        .q(s1_sig_b$q),
        .clock(s1_sig_b$clock)
    );
    top$counter s1_lz_a(
        .d(s1_lz_a$d),
        .q(s1_lz_a$q),
        .clock(s1_lz_a$clock)
    );
    top$counter s1_lz_b(
        .d(s1_lz_b$d),
        .q(s1_lz_b$q),
        .clock(s1_lz_b$clock)
    );
    top$acc s2_valid(
        .d(s2_valid$d),
        .q(s2_valid$q),
        .clock(s2_valid$clock)
    );
    top$acc s2_sign(
        .d(s2_sign$d),
        .q(s2_sign$q),
        .clock(s2_sign$clock)
    );
    top$acc s2_nan(
        .d(s2_nan$d),
        .q(s2_nan$q),
        .clock(s2_nan$clock)
    );
    top$acc s2_inf(
        .d(s2_inf$d),
        .q(s2_inf$q),
        .clock(s2_inf$clock)
    );
    top$acc s2_zero(
        .d(s2_zero$d),
        .q(s2_zero$q),
        .clock(s2_zero$clock)
    );
    top$doptrf$0$mul_0$s2_exp s2_exp(
        .d(s2_exp$d),
        .q(s2_exp$q),
        .clock(s2_exp$clock)
    );
    top$doptrf$0$add_0$s1_big s2_sig_a(
        .d(s2_sig_a$d),
        .q(s2_sig_a$q),
        .clock(s2_sig_a$clock)
    );
    top$doptrf$0$add_0$s1_big s2_sig_b(
        .d(s2_sig_b$d),
        .q(s2_sig_b$q),
        .clock(s2_sig_b$clock)
    );
    top$acc s3_valid(
        .d(s3_valid$d),
        .q(s3_valid$q),
        .clock(s3_valid$clock)
    );
    top$acc s3_sign(
        .d(s3_sign$d),
        .q(s3_sign$q),
        .clock(s3_sign$clock)
    );
    top$acc s3_nan(
        .d(s3_nan$d),
        .q(s3_nan$q),
        .clock(s3_nan$clock)
    );
    top$acc s3_inf(
        .d(s3_inf$d),
        .q(s3_inf$q),
        .clock(s3_inf$clock)
    );
    top$acc s3_zero(
        .d(s3_zero$d),
        .q(s3_zero$q),
        .clock(s3_zero$clock)
    );
    top$doptrf$0$mul_0$s3_hh s3_ll(
        .d(s3_ll$d),
        .q(s3_ll$q),
        .clock(s3_ll$clock)
    );
    top$doptrf$0$mul_0$s3_hh s3_lh(
        .d(s3_lh$d),
        .q(s3_lh$q),
        .clock(s3_lh$clock)
    );
    top$doptrf$0$mul_0$s3_hh s3_hl(
        .d(s3_hl$d),
        .q(s3_hl$q),
        .clock(s3_hl$clock)
    );
    top$doptrf$0$mul_0$s3_hh s3_hh(
        .d(s3_hh$d),
        .q(s3_hh$q),
        .clock(s3_hh$clock)
    );
    top$acc s3_lt0(
        .d(s3_lt0$d),
        .q(s3_lt0$q),
        .clock(s3_lt0$clock)
    );
    top$acc s3_lt1(
        .d(s3_lt1$d),
        .q(s3_lt1$q),
        .clock(s3_lt1$clock)
    );
    top$doptrf$0$mul_0$s2_exp s3_u0(
        .d(s3_u0$d),
        .q(s3_u0$q),
        .clock(s3_u0$clock)
    );
    top$doptrf$0$mul_0$s2_exp s3_u1(
        .d(s3_u1$d),
        .q(s3_u1$q),
        .clock(s3_u1$clock)
    );
    top$acc s3_ovf0(
        .d(s3_ovf0$d),
        .q(s3_ovf0$q),
        .clock(s3_ovf0$clock)
    );
    top$acc s3_ovf1(
        .d(s3_ovf1$d),
        .q(s3_ovf1$q),
        .clock(s3_ovf1$clock)
    );
    top$doptrf$0$add_0$s1_exp s3_efield0(
        .d(s3_efield0$d),
        .q(s3_efield0$q),
        .clock(s3_efield0$clock)
    );
    top$doptrf$0$add_0$s1_exp s3_efield1(
        .d(s3_efield1$d),
        .q(s3_efield1$q),
        .clock(s3_efield1$clock)
    );
    top$acc s4_valid(
        .d(s4_valid$d),
        .q(s4_valid$q),
        .clock(s4_valid$clock)
    );
    top$acc s4_sign(
        .d(s4_sign$d),
        .q(s4_sign$q),
        .clock(s4_sign$clock)
    );
    top$acc s4_nan(
        .d(s4_nan$d),
        .q(s4_nan$q),
        .clock(s4_nan$clock)
    );
    top$acc s4_inf(
        .d(s4_inf$d),
        .q(s4_inf$q),
        .clock(s4_inf$clock)
    );
    top$acc s4_zero(
        .d(s4_zero$d),
        .q(s4_zero$q),
        .clock(s4_zero$clock)
    );
    top$doptrf$0$add_0$s5_nm s4_nm(
        .d(s4_nm$d),
        .q(s4_nm$q),
        .clock(s4_nm$clock)
    );
    top$doptrf$0$mul_0$s2_exp s4_cap(
        .d(s4_cap$d),
        .q(s4_cap$q),
        .clock(s4_cap$clock)
    );
    top$acc s4_ovf(
        .d(s4_ovf$d),
        .q(s4_ovf$q),
        .clock(s4_ovf$clock)
    );
    top$doptrf$0$add_0$s1_exp s4_efield(
        .d(s4_efield$d),
        .q(s4_efield$q),
        .clock(s4_efield$clock)
    );
    top$acc s5_valid(
        .d(s5_valid$d),
        .q(s5_valid$q),
        .clock(s5_valid$clock)
    );
    top$acc s5_sign(
        .d(s5_sign$d),
        .q(s5_sign$q),
        .clock(s5_sign$clock)
    );
    top$acc s5_nan(
        .d(s5_nan$d),
        .q(s5_nan$q),
        .clock(s5_nan$clock)
    );
    top$acc s5_inf(
        .d(s5_inf$d),
        .q(s5_inf$q),
        .clock(s5_inf$clock)
    );
    top$acc s5_zero(
        .d(s5_zero$d),
        .q(s5_zero$q),
        .clock(s5_zero$clock)
    );
    top$acc s5_ovf(
        .d(s5_ovf$d),
        .q(s5_ovf$q),
        .clock(s5_ovf$clock)
    );
    top$doptrf$0$add_0$s1_exp s5_efield(
        .d(s5_efield$d),
        .q(s5_efield$q),
        .clock(s5_efield$clock)
    );
    top$doptrf$0$add_0$s5_nm s5_nm(
        .d(s5_nm$d),
        .q(s5_nm$q),
        .clock(s5_nm$clock)
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
    top$acc s6_valid(
        .d(s6_valid$d),
        .q(s6_valid$q),
        .clock(s6_valid$clock)
    );
    top$doptrf$0$add_0$s6_y s6_y(
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
    
endmodule // top$doptrf$0$mul_0


module top$doptrf$0$mul_0$lzc_a(x,lz);
    
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
    
endmodule // top$doptrf$0$mul_0$lzc_a


module top$doptrf$0$mul_0$s2_exp(d,q,clock);
    
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
          
endmodule // top$doptrf$0$mul_0$s2_exp


module top$doptrf$0$mul_0$s3_hh(d,q,clock);
    
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
          
endmodule // top$doptrf$0$mul_0$s3_hh


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
    reg  line$3$d;
    wire  line$3$q;
    reg  line$3$clock;
    reg  line$4$d;
    wire  line$4$q;
    reg  line$4$clock;
    
    // Sub module instances
    top$acc line$0(
        .d(line$0$d),
        .q(line$0$q),
        .clock(line$0$clock)
    );
    top$acc line$1(
        .d(line$1$d),
        .q(line$1$q),
        .clock(line$1$clock)
    );
    top$acc line$2(
        .d(line$2$d),
        .q(line$2$q),
        .clock(line$2$clock)
    );
    top$acc line$3(
        .d(line$3$d),
        .q(line$3$q),
        .clock(line$3$clock)
    );
    top$acc line$4(
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
    
endmodule // top$doptrf$0$r_mul


module top$doptrf$0$r_s(clock,d,q);
    
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
    top$acc line$0(
        .d(line$0$d),
        .q(line$0$q),
        .clock(line$0$clock)
    );
    top$acc line$1(
        .d(line$1$d),
        .q(line$1$q),
        .clock(line$1$clock)
    );
    top$acc line$2(
        .d(line$2$d),
        .q(line$2$q),
        .clock(line$2$clock)
    );
    top$acc line$3(
        .d(line$3$d),
        .q(line$3$q),
        .clock(line$3$clock)
    );
    top$acc line$4(
        .d(line$4$d),
        .q(line$4$q),
        .clock(line$4$clock)
    );
    top$acc line$5(
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
    
endmodule // top$doptrf$0$r_s


module top$klmsel(d$0,d$1,d$2,d$3,d$4,d$5,j0$0,j1$0,j2$0,y0$0,y1$0,y2$0);
    
    // Module arguments
    input wire  [23:0] d$0;
    input wire  [23:0] d$1;
    input wire  [23:0] d$2;
    input wire  [23:0] d$3;
    input wire  [23:0] d$4;
    input wire  [23:0] d$5;
    input wire  [4:0] j0$0;
    input wire  [4:0] j1$0;
    input wire  [4:0] j2$0;
    output reg  [23:0] y0$0;
    output reg  [23:0] y1$0;
    output reg  [23:0] y2$0;
    
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
    top$doptrf$0$add_0$s6_y cmat_0$0(
        .d(cmat_0$0$d),
        .q(cmat_0$0$q),
        .clock(cmat_0$0$clock)
    );
    top$doptrf$0$add_0$s6_y cmat_0$1(
        .d(cmat_0$1$d),
        .q(cmat_0$1$q),
        .clock(cmat_0$1$clock)
    );
    top$doptrf$0$add_0$s6_y cmat_0$2(
        .d(cmat_0$2$d),
        .q(cmat_0$2$q),
        .clock(cmat_0$2$clock)
    );
    top$doptrf$0$add_0$s6_y cmat_0$3(
        .d(cmat_0$3$d),
        .q(cmat_0$3$q),
        .clock(cmat_0$3$clock)
    );
    top$doptrf$0$add_0$s6_y cmat_0$4(
        .d(cmat_0$4$d),
        .q(cmat_0$4$q),
        .clock(cmat_0$4$clock)
    );
    top$doptrf$0$add_0$s6_y cmat_0$5(
        .d(cmat_0$5$d),
        .q(cmat_0$5$q),
        .clock(cmat_0$5$clock)
    );
    top$doptrf$0$add_0$s6_y cmat_1$0(
        .d(cmat_1$0$d),
        .q(cmat_1$0$q),
        .clock(cmat_1$0$clock)
    );
    top$doptrf$0$add_0$s6_y cmat_1$1(
        .d(cmat_1$1$d),
        .q(cmat_1$1$q),
        .clock(cmat_1$1$clock)
    );
    top$doptrf$0$add_0$s6_y cmat_1$2(
        .d(cmat_1$2$d),
        .q(cmat_1$2$q),
        .clock(cmat_1$2$clock)
    );
    top$doptrf$0$add_0$s6_y cmat_1$3(
        .d(cmat_1$3$d),
        .q(cmat_1$3$q),
        .clock(cmat_1$3$clock)
    );
    top$doptrf$0$add_0$s6_y cmat_1$4(
        .d(cmat_1$4$d),
        .q(cmat_1$4$q),
        .clock(cmat_1$4$clock)
    );
    top$doptrf$0$add_0$s6_y cmat_1$5(
        .d(cmat_1$5$d),
        .q(cmat_1$5$q),
        .clock(cmat_1$5$clock)
    );
    top$doptrf$0$add_0$s6_y cmat_2$0(
        .d(cmat_2$0$d),
        .q(cmat_2$0$q),
        .clock(cmat_2$0$clock)
    );
    top$doptrf$0$add_0$s6_y cmat_2$1(
        .d(cmat_2$1$d),
        .q(cmat_2$1$q),
        .clock(cmat_2$1$clock)
    );
    top$doptrf$0$add_0$s6_y cmat_2$2(
        .d(cmat_2$2$d),
        .q(cmat_2$2$q),
        .clock(cmat_2$2$clock)
    );
    top$doptrf$0$add_0$s6_y cmat_2$3(
        .d(cmat_2$3$d),
        .q(cmat_2$3$q),
        .clock(cmat_2$3$clock)
    );
    top$doptrf$0$add_0$s6_y cmat_2$4(
        .d(cmat_2$4$d),
        .q(cmat_2$4$q),
        .clock(cmat_2$4$clock)
    );
    top$doptrf$0$add_0$s6_y cmat_2$5(
        .d(cmat_2$5$d),
        .q(cmat_2$5$q),
        .clock(cmat_2$5$clock)
    );
    top$doptrf$0$add_0$s6_y cvec$0(
        .d(cvec$0$d),
        .q(cvec$0$q),
        .clock(cvec$0$clock)
    );
    top$doptrf$0$add_0$s6_y cvec$1(
        .d(cvec$1$d),
        .q(cvec$1$q),
        .clock(cvec$1$clock)
    );
    top$doptrf$0$add_0$s6_y cvec$2(
        .d(cvec$2$d),
        .q(cvec$2$q),
        .clock(cvec$2$clock)
    );
    top$doptrf$0$add_0$s6_y cvec$3(
        .d(cvec$3$d),
        .q(cvec$3$q),
        .clock(cvec$3$clock)
    );
    top$doptrf$0$add_0$s6_y cvec$4(
        .d(cvec$4$d),
        .q(cvec$4$q),
        .clock(cvec$4$clock)
    );
    top$doptrf$0$add_0$s6_y cvec$5(
        .d(cvec$5$d),
        .q(cvec$5$q),
        .clock(cvec$5$clock)
    );
    top$counter jsel_0$0(
        .d(jsel_0$0$d),
        .q(jsel_0$0$q),
        .clock(jsel_0$0$clock)
    );
    top$counter jsel_0$1(
        .d(jsel_0$1$d),
        .q(jsel_0$1$q),
        .clock(jsel_0$1$clock)
    );
    top$counter jsel_0$2(
        .d(jsel_0$2$d),
        .q(jsel_0$2$q),
        .clock(jsel_0$2$clock)
    );
    top$counter jsel_0$3(
        .d(jsel_0$3$d),
        .q(jsel_0$3$q),
        .clock(jsel_0$3$clock)
    );
    top$counter jsel_0$4(
        .d(jsel_0$4$d),
        .q(jsel_0$4$q),
        .clock(jsel_0$4$clock)
    );
    top$counter jsel_0$5(
        .d(jsel_0$5$d),
        .q(jsel_0$5$q),
        .clock(jsel_0$5$clock)
    );
    top$counter jsel_1$0(
        .d(jsel_1$0$d),
        .q(jsel_1$0$q),
        .clock(jsel_1$0$clock)
    );
    top$counter jsel_1$1(
        .d(jsel_1$1$d),
        .q(jsel_1$1$q),
        .clock(jsel_1$1$clock)
    );
    top$counter jsel_1$2(
        .d(jsel_1$2$d),
        .q(jsel_1$2$q),
        .clock(jsel_1$2$clock)
    );
    top$counter jsel_1$3(
        .d(jsel_1$3$d),
        .q(jsel_1$3$q),
        .clock(jsel_1$3$clock)
    );
    top$counter jsel_1$4(
        .d(jsel_1$4$d),
        .q(jsel_1$4$q),
        .clock(jsel_1$4$clock)
    );
    top$counter jsel_1$5(
        .d(jsel_1$5$d),
        .q(jsel_1$5$q),
        .clock(jsel_1$5$clock)
    );
    top$counter jsel_2$0(
        .d(jsel_2$0$d),
        .q(jsel_2$0$q),
        .clock(jsel_2$0$clock)
    );
    top$counter jsel_2$1(
        .d(jsel_2$1$d),
        .q(jsel_2$1$q),
        .clock(jsel_2$1$clock)
    );
    top$counter jsel_2$2(
        .d(jsel_2$2$d),
        .q(jsel_2$2$q),
        .clock(jsel_2$2$clock)
    );
    top$counter jsel_2$3(
        .d(jsel_2$3$d),
        .q(jsel_2$3$q),
        .clock(jsel_2$3$clock)
    );
    top$counter jsel_2$4(
        .d(jsel_2$4$d),
        .q(jsel_2$4$q),
        .clock(jsel_2$4$clock)
    );
    top$counter jsel_2$5(
        .d(jsel_2$5$d),
        .q(jsel_2$5$q),
        .clock(jsel_2$5$clock)
    );
    top$acc rnd$0(
        .d(rnd$0$d),
        .q(rnd$0$q),
        .clock(rnd$0$clock)
    );
    top$acc rnd$1(
        .d(rnd$1$d),
        .q(rnd$1$q),
        .clock(rnd$1$clock)
    );
    top$acc rnd$2(
        .d(rnd$2$d),
        .q(rnd$2$q),
        .clock(rnd$2$clock)
    );
    top$acc rnd$3(
        .d(rnd$3$d),
        .q(rnd$3$q),
        .clock(rnd$3$clock)
    );
    top$acc rnd$4(
        .d(rnd$4$d),
        .q(rnd$4$q),
        .clock(rnd$4$clock)
    );
    top$acc rnd$5(
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


module top$tag_line(clock,d,q);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] d;
    output reg  [15:0] q;
    
    // Stub signals
    reg  [15:0] line$0$d;
    wire  [15:0] line$0$q;
    reg  line$0$clock;
    reg  [15:0] line$1$d;
    wire  [15:0] line$1$q;
    reg  line$1$clock;
    reg  [15:0] line$2$d;
    wire  [15:0] line$2$q;
    reg  line$2$clock;
    reg  [15:0] line$3$d;
    wire  [15:0] line$3$q;
    reg  line$3$clock;
    reg  [15:0] line$4$d;
    wire  [15:0] line$4$q;
    reg  line$4$clock;
    reg  [15:0] line$5$d;
    wire  [15:0] line$5$q;
    reg  line$5$clock;
    reg  [15:0] line$6$d;
    wire  [15:0] line$6$q;
    reg  line$6$clock;
    reg  [15:0] line$7$d;
    wire  [15:0] line$7$q;
    reg  line$7$clock;
    reg  [15:0] line$8$d;
    wire  [15:0] line$8$q;
    reg  line$8$clock;
    reg  [15:0] line$9$d;
    wire  [15:0] line$9$q;
    reg  line$9$clock;
    reg  [15:0] line$10$d;
    wire  [15:0] line$10$q;
    reg  line$10$clock;
    reg  [15:0] line$11$d;
    wire  [15:0] line$11$q;
    reg  line$11$clock;
    reg  [15:0] line$12$d;
    wire  [15:0] line$12$q;
    reg  line$12$clock;
    reg  [15:0] line$13$d;
    wire  [15:0] line$13$q;
    reg  line$13$clock;
    reg  [15:0] line$14$d;
    wire  [15:0] line$14$q;
    reg  line$14$clock;
    reg  [15:0] line$15$d;
    wire  [15:0] line$15$q;
    reg  line$15$clock;
    reg  [15:0] line$16$d;
    wire  [15:0] line$16$q;
    reg  line$16$clock;
    reg  [15:0] line$17$d;
    wire  [15:0] line$17$q;
    reg  line$17$clock;
    reg  [15:0] line$18$d;
    wire  [15:0] line$18$q;
    reg  line$18$clock;
    reg  [15:0] line$19$d;
    wire  [15:0] line$19$q;
    reg  line$19$clock;
    reg  [15:0] line$20$d;
    wire  [15:0] line$20$q;
    reg  line$20$clock;
    reg  [15:0] line$21$d;
    wire  [15:0] line$21$q;
    reg  line$21$clock;
    reg  [15:0] line$22$d;
    wire  [15:0] line$22$q;
    reg  line$22$clock;
    reg  [15:0] line$23$d;
    wire  [15:0] line$23$q;
    reg  line$23$clock;
    reg  [15:0] line$24$d;
    wire  [15:0] line$24$q;
    reg  line$24$clock;
    reg  [15:0] line$25$d;
    wire  [15:0] line$25$q;
    reg  line$25$clock;
    
    // Sub module instances
    top$doptrf$0$add_0$s1_big line$0(
        .d(line$0$d),
        .q(line$0$q),
        .clock(line$0$clock)
    );
    top$doptrf$0$add_0$s1_big line$1(
        .d(line$1$d),
        .q(line$1$q),
        .clock(line$1$clock)
    );
    top$doptrf$0$add_0$s1_big line$2(
        .d(line$2$d),
        .q(line$2$q),
        .clock(line$2$clock)
    );
    top$doptrf$0$add_0$s1_big line$3(
        .d(line$3$d),
        .q(line$3$q),
        .clock(line$3$clock)
    );
    top$doptrf$0$add_0$s1_big line$4(
        .d(line$4$d),
        .q(line$4$q),
        .clock(line$4$clock)
    );
    top$doptrf$0$add_0$s1_big line$5(
        .d(line$5$d),
        .q(line$5$q),
        .clock(line$5$clock)
    );
    top$doptrf$0$add_0$s1_big line$6(
        .d(line$6$d),
        .q(line$6$q),
        .clock(line$6$clock)
    );
    top$doptrf$0$add_0$s1_big line$7(
        .d(line$7$d),
        .q(line$7$q),
        .clock(line$7$clock)
    );
    top$doptrf$0$add_0$s1_big line$8(
        .d(line$8$d),
        .q(line$8$q),
        .clock(line$8$clock)
    );
    top$doptrf$0$add_0$s1_big line$9(
        .d(line$9$d),
        .q(line$9$q),
        .clock(line$9$clock)
    );
    top$doptrf$0$add_0$s1_big line$10(
        .d(line$10$d),
        .q(line$10$q),
        .clock(line$10$clock)
    );
    top$doptrf$0$add_0$s1_big line$11(
        .d(line$11$d),
        .q(line$11$q),
        .clock(line$11$clock)
    );
    top$doptrf$0$add_0$s1_big line$12(
        .d(line$12$d),
        .q(line$12$q),
        .clock(line$12$clock)
    );
    top$doptrf$0$add_0$s1_big line$13(
        .d(line$13$d),
        .q(line$13$q),
        .clock(line$13$clock)
    );
    top$doptrf$0$add_0$s1_big line$14(
        .d(line$14$d),
        .q(line$14$q),
        .clock(line$14$clock)
    );
    top$doptrf$0$add_0$s1_big line$15(
        .d(line$15$d),
        .q(line$15$q),
        .clock(line$15$clock)
    );
    top$doptrf$0$add_0$s1_big line$16(
        .d(line$16$d),
        .q(line$16$q),
        .clock(line$16$clock)
    );
    top$doptrf$0$add_0$s1_big line$17(
        .d(line$17$d),
        .q(line$17$q),
        .clock(line$17$clock)
    );
    top$doptrf$0$add_0$s1_big line$18(
        .d(line$18$d),
        .q(line$18$q),
        .clock(line$18$clock)
    );
    top$doptrf$0$add_0$s1_big line$19(
        .d(line$19$d),
        .q(line$19$q),
        .clock(line$19$clock)
    );
    top$doptrf$0$add_0$s1_big line$20(
        .d(line$20$d),
        .q(line$20$q),
        .clock(line$20$clock)
    );
    top$doptrf$0$add_0$s1_big line$21(
        .d(line$21$d),
        .q(line$21$q),
        .clock(line$21$clock)
    );
    top$doptrf$0$add_0$s1_big line$22(
        .d(line$22$d),
        .q(line$22$q),
        .clock(line$22$clock)
    );
    top$doptrf$0$add_0$s1_big line$23(
        .d(line$23$d),
        .q(line$23$q),
        .clock(line$23$clock)
    );
    top$doptrf$0$add_0$s1_big line$24(
        .d(line$24$d),
        .q(line$24$q),
        .clock(line$24$clock)
    );
    top$doptrf$0$add_0$s1_big line$25(
        .d(line$25$d),
        .q(line$25$q),
        .clock(line$25$clock)
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
        line$12$clock = clock;
        line$12$d = d;
        line$13$clock = clock;
        line$13$d = d;
        line$14$clock = clock;
        line$14$d = d;
        line$15$clock = clock;
        line$15$d = d;
        line$16$clock = clock;
        line$16$d = d;
        line$17$clock = clock;
        line$17$d = d;
        line$18$clock = clock;
        line$18$d = d;
        line$19$clock = clock;
        line$19$d = d;
        line$20$clock = clock;
        line$20$d = d;
        line$21$clock = clock;
        line$21$d = d;
        line$22$clock = clock;
        line$22$d = d;
        line$23$clock = clock;
        line$23$d = d;
        line$24$clock = clock;
        line$24$d = d;
        line$25$clock = clock;
        line$25$d = d;
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
        line$11$d = line$12$q;
        line$12$d = line$13$q;
        line$13$d = line$14$q;
        line$14$d = line$15$q;
        line$15$d = line$16$q;
        line$16$d = line$17$q;
        line$17$d = line$18$q;
        line$18$d = line$19$q;
        line$19$d = line$20$q;
        line$20$d = line$21$q;
        line$21$d = line$22$q;
        line$22$d = line$23$q;
        line$23$d = line$24$q;
        line$24$d = line$25$q;
        q = line$0$q;
    end
    
endmodule // top$tag_line
