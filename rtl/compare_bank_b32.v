

module top(clock,valid_in,first,lanes,e,dl,dr,overlap_l,overlap_r,valid_out);
    
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
    top$cmp_l0 cmp_l0(
        .clock(cmp_l0$clock),
        .a(cmp_l0$a),
        .b(cmp_l0$b),
        .valid_in(cmp_l0$valid_in),
        .flag(cmp_l0$flag),
        .valid_out(cmp_l0$valid_out)
    );
    top$cmp_l0 cmp_r0(
        .clock(cmp_r0$clock),
        .a(cmp_r0$a),
        .b(cmp_r0$b),
        .valid_in(cmp_r0$valid_in),
        .flag(cmp_r0$flag),
        .valid_out(cmp_r0$valid_out)
    );
    top$cmp_l0 cmp_l1(
        .clock(cmp_l1$clock),
        .a(cmp_l1$a),
        .b(cmp_l1$b),
        .valid_in(cmp_l1$valid_in),
        .flag(cmp_l1$flag),
        .valid_out(cmp_l1$valid_out)
    );
    top$cmp_l0 cmp_r1(
        .clock(cmp_r1$clock),
        .a(cmp_r1$a),
        .b(cmp_r1$b),
        .valid_in(cmp_r1$valid_in),
        .flag(cmp_r1$flag),
        .valid_out(cmp_r1$valid_out)
    );
    top$cmp_l0 cmp_l2(
        .clock(cmp_l2$clock),
        .a(cmp_l2$a),
        .b(cmp_l2$b),
        .valid_in(cmp_l2$valid_in),
        .flag(cmp_l2$flag),
        .valid_out(cmp_l2$valid_out)
    );
    top$cmp_l0 cmp_r2(
        .clock(cmp_r2$clock),
        .a(cmp_r2$a),
        .b(cmp_r2$b),
        .valid_in(cmp_r2$valid_in),
        .flag(cmp_r2$flag),
        .valid_out(cmp_r2$valid_out)
    );
    top$cmp_l0 cmp_l3(
        .clock(cmp_l3$clock),
        .a(cmp_l3$a),
        .b(cmp_l3$b),
        .valid_in(cmp_l3$valid_in),
        .flag(cmp_l3$flag),
        .valid_out(cmp_l3$valid_out)
    );
    top$cmp_l0 cmp_r3(
        .clock(cmp_r3$clock),
        .a(cmp_r3$a),
        .b(cmp_r3$b),
        .valid_in(cmp_r3$valid_in),
        .flag(cmp_r3$flag),
        .valid_out(cmp_r3$valid_out)
    );
    top$cmp_l0 cmp_l4(
        .clock(cmp_l4$clock),
        .a(cmp_l4$a),
        .b(cmp_l4$b),
        .valid_in(cmp_l4$valid_in),
        .flag(cmp_l4$flag),
        .valid_out(cmp_l4$valid_out)
    );
    top$cmp_l0 cmp_r4(
        .clock(cmp_r4$clock),
        .a(cmp_r4$a),
        .b(cmp_r4$b),
        .valid_in(cmp_r4$valid_in),
        .flag(cmp_r4$flag),
        .valid_out(cmp_r4$valid_out)
    );
    top$cmp_l0 cmp_l5(
        .clock(cmp_l5$clock),
        .a(cmp_l5$a),
        .b(cmp_l5$b),
        .valid_in(cmp_l5$valid_in),
        .flag(cmp_l5$flag),
        .valid_out(cmp_l5$valid_out)
    );
    top$cmp_l0 cmp_r5(
        .clock(cmp_r5$clock),
        .a(cmp_r5$a),
        .b(cmp_r5$b),
        .valid_in(cmp_r5$valid_in),
        .flag(cmp_r5$flag),
        .valid_out(cmp_r5$valid_out)
    );
    top$cmp_l0 cmp_l6(
        .clock(cmp_l6$clock),
        .a(cmp_l6$a),
        .b(cmp_l6$b),
        .valid_in(cmp_l6$valid_in),
        .flag(cmp_l6$flag),
        .valid_out(cmp_l6$valid_out)
    );
    top$cmp_l0 cmp_r6(
        .clock(cmp_r6$clock),
        .a(cmp_r6$a),
        .b(cmp_r6$b),
        .valid_in(cmp_r6$valid_in),
        .flag(cmp_r6$flag),
        .valid_out(cmp_r6$valid_out)
    );
    top$cmp_l0 cmp_l7(
        .clock(cmp_l7$clock),
        .a(cmp_l7$a),
        .b(cmp_l7$b),
        .valid_in(cmp_l7$valid_in),
        .flag(cmp_l7$flag),
        .valid_out(cmp_l7$valid_out)
    );
    top$cmp_l0 cmp_r7(
        .clock(cmp_r7$clock),
        .a(cmp_r7$a),
        .b(cmp_r7$b),
        .valid_in(cmp_r7$valid_in),
        .flag(cmp_r7$flag),
        .valid_out(cmp_r7$valid_out)
    );
    top$cmp_l0$s1_flag s1_first(
        .d(s1_first$d),
        .q(s1_first$q),
        .clock(s1_first$clock)
    );
    top$s1_lanes s1_lanes(
        .d(s1_lanes$d),
        .q(s1_lanes$q),
        .clock(s1_lanes$clock)
    );
    top$cmp_l0$s1_flag s2_sep_l(
        .d(s2_sep_l$d),
        .q(s2_sep_l$q),
        .clock(s2_sep_l$clock)
    );
    top$cmp_l0$s1_flag s2_sep_r(
        .d(s2_sep_r$d),
        .q(s2_sep_r$q),
        .clock(s2_sep_r$clock)
    );
    top$cmp_l0$s1_flag s2_valid(
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
    
endmodule // top


module top$cmp_l0(clock,a,b,valid_in,flag,valid_out);
    
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
    top$cmp_l0$s1_flag s1_flag(
        .d(s1_flag$d),
        .q(s1_flag$q),
        .clock(s1_flag$clock)
    );
    top$cmp_l0$s1_flag s1_valid(
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
    
endmodule // top$cmp_l0


module top$cmp_l0$s1_flag(d,q,clock);
    
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
          
endmodule // top$cmp_l0$s1_flag


module top$s1_lanes(d,q,clock);
    
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
          
endmodule // top$s1_lanes
