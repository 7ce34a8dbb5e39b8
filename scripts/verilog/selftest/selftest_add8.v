// Self-test unit for the Verilog flows (scripts/selftest.sh); written by hand in the style of
// rust-hdl 0.46's generate_verilog: top module `top`, non-ANSI ports with `input wire` /
// `output reg`, sub-blocks as modules `top$<field>` with `$`-joined stub signals, DFFs with an
// `initial` value and one combinational `always @(*)` block.
// Function: y = a + b (mod 256), carry = carry out, 2-cycle latency, valid in/out.
//   cycle c: a, b, in_valid sampled into stage 1 (s1_*)
//   cycle c+1: sum registered into stage 2 (s2_*), which drives y, carry, out_valid
// so a case presented at cycle c is at the outputs at cycle c + 2.


module top(clock,a,b,in_valid,y,carry,out_valid);
    
    // Module arguments
    input wire  clock;
    input wire  [7:0] a;
    input wire  [7:0] b;
    input wire  in_valid;
    output reg  [7:0] y;
    output reg  carry;
    output reg  out_valid;
    
    // Stub signals
    reg  [7:0] s1_a$d;
    wire  [7:0] s1_a$q;
    reg  s1_a$clock;
    reg  [7:0] s1_b$d;
    wire  [7:0] s1_b$q;
    reg  s1_b$clock;
    reg  s1_v$d;
    wire  s1_v$q;
    reg  s1_v$clock;
    reg  [8:0] s2_s$d;
    wire  [8:0] s2_s$q;
    reg  s2_s$clock;
    reg  s2_v$d;
    wire  s2_v$q;
    reg  s2_v$clock;
    
    // Local signals
    reg  [8:0] wide_a;
    reg  [8:0] wide_b;
    
    // Sub module instances
    top$s1_a s1_a(
        .d(s1_a$d),
        .q(s1_a$q),
        .clock(s1_a$clock)
    );
    top$s1_b s1_b(
        .d(s1_b$d),
        .q(s1_b$q),
        .clock(s1_b$clock)
    );
    top$s1_v s1_v(
        .d(s1_v$d),
        .q(s1_v$q),
        .clock(s1_v$clock)
    );
    top$s2_s s2_s(
        .d(s2_s$d),
        .q(s2_s$q),
        .clock(s2_s$clock)
    );
    top$s2_v s2_v(
        .d(s2_v$d),
        .q(s2_v$q),
        .clock(s2_v$clock)
    );
    
    // Update code
    always @(*) begin
        s1_a$clock = clock;
        s1_b$clock = clock;
        s1_v$clock = clock;
        s2_s$clock = clock;
        s2_v$clock = clock;
        s1_a$d = s1_a$q;
        s1_b$d = s1_b$q;
        s1_v$d = s1_v$q;
        s2_s$d = s2_s$q;
        s2_v$d = s2_v$q;
        s1_a$d = a;
        s1_b$d = b;
        s1_v$d = in_valid;
        wide_a = s1_a$q;
        wide_b = s1_b$q;
        s2_s$d = wide_a + wide_b;
        s2_v$d = s1_v$q;
        y = s2_s$q[7:0];
        carry = s2_s$q[8];
        out_valid = s2_v$q;
    end
    
endmodule // top


module top$s1_a(d,q,clock);
    
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
          
endmodule // top$s1_a


module top$s1_b(d,q,clock);
    
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
          
endmodule // top$s1_b


module top$s1_v(d,q,clock);
    
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
          
endmodule // top$s1_v


module top$s2_s(d,q,clock);
    
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
          
endmodule // top$s2_s


module top$s2_v(d,q,clock);
    
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
          
endmodule // top$s2_v
