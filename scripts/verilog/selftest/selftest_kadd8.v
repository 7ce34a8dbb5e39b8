// Self-test unit for the preload phase of the Verilog flows (scripts/selftest.sh); written by
// hand in the style of rust-hdl 0.46's generate_verilog (see selftest_add8.v), with the shapes of
// the DOP unit's ports: an array input/output flattened to `$`-numbered ports (`a$0`, `a$1`,
// `y$0`, `y$1`), sub-blocks `top$k$0` .. (instances `k$0` ..), and a per-query register file
// written through a load port before the cases stream in.
// Function: a register file k[0..3] (8 bits each) written on the rising edge while load_en is
// high: k[load_addr] <= load_data for load_addr 0..3, other addresses ignored. Then
//   y$0 = a$0 + k[sel], y$1 = a$1 + k[sel ^ 1]   (mod 256), 2-cycle latency, valid in/out.
//   cycle c: a$0, a$1, sel, in_valid sampled into stage 1 (s1_*)
//   cycle c+1: the sums registered into stage 2 (s2_*), which drives y$0, y$1, out_valid
// so a case presented at cycle c is at the outputs at cycle c + 2 (k is read in cycle c+1).


module top(clock,load_en,load_addr,load_data,a$0,a$1,sel,in_valid,y$0,y$1,out_valid);
    
    // Module arguments
    input wire  clock;
    input wire  load_en;
    input wire  [7:0] load_addr;
    input wire  [7:0] load_data;
    input wire  [7:0] a$0;
    input wire  [7:0] a$1;
    input wire  [1:0] sel;
    input wire  in_valid;
    output reg  [7:0] y$0;
    output reg  [7:0] y$1;
    output reg  out_valid;
    
    // Stub signals
    reg  [7:0] k$0$d;
    wire  [7:0] k$0$q;
    reg  k$0$clock;
    reg  [7:0] k$1$d;
    wire  [7:0] k$1$q;
    reg  k$1$clock;
    reg  [7:0] k$2$d;
    wire  [7:0] k$2$q;
    reg  k$2$clock;
    reg  [7:0] k$3$d;
    wire  [7:0] k$3$q;
    reg  k$3$clock;
    reg  [7:0] s1_a0$d;
    wire  [7:0] s1_a0$q;
    reg  s1_a0$clock;
    reg  [7:0] s1_a1$d;
    wire  [7:0] s1_a1$q;
    reg  s1_a1$clock;
    reg  [1:0] s1_sel$d;
    wire  [1:0] s1_sel$q;
    reg  s1_sel$clock;
    reg  s1_v$d;
    wire  s1_v$q;
    reg  s1_v$clock;
    reg  [7:0] s2_y0$d;
    wire  [7:0] s2_y0$q;
    reg  s2_y0$clock;
    reg  [7:0] s2_y1$d;
    wire  [7:0] s2_y1$q;
    reg  s2_y1$clock;
    reg  s2_v$d;
    wire  s2_v$q;
    reg  s2_v$clock;
    
    // Local signals
    reg  [7:0] k_sel;
    reg  [7:0] k_alt;
    
    // Sub module instances
    top$k$0 k$0(
        .d(k$0$d),
        .q(k$0$q),
        .clock(k$0$clock)
    );
    top$k$1 k$1(
        .d(k$1$d),
        .q(k$1$q),
        .clock(k$1$clock)
    );
    top$k$2 k$2(
        .d(k$2$d),
        .q(k$2$q),
        .clock(k$2$clock)
    );
    top$k$3 k$3(
        .d(k$3$d),
        .q(k$3$q),
        .clock(k$3$clock)
    );
    top$s1_a0 s1_a0(
        .d(s1_a0$d),
        .q(s1_a0$q),
        .clock(s1_a0$clock)
    );
    top$s1_a1 s1_a1(
        .d(s1_a1$d),
        .q(s1_a1$q),
        .clock(s1_a1$clock)
    );
    top$s1_sel s1_sel(
        .d(s1_sel$d),
        .q(s1_sel$q),
        .clock(s1_sel$clock)
    );
    top$s1_v s1_v(
        .d(s1_v$d),
        .q(s1_v$q),
        .clock(s1_v$clock)
    );
    top$s2_y0 s2_y0(
        .d(s2_y0$d),
        .q(s2_y0$q),
        .clock(s2_y0$clock)
    );
    top$s2_y1 s2_y1(
        .d(s2_y1$d),
        .q(s2_y1$q),
        .clock(s2_y1$clock)
    );
    top$s2_v s2_v(
        .d(s2_v$d),
        .q(s2_v$q),
        .clock(s2_v$clock)
    );
    
    // Update code
    always @(*) begin
        k$0$clock = clock;
        k$1$clock = clock;
        k$2$clock = clock;
        k$3$clock = clock;
        s1_a0$clock = clock;
        s1_a1$clock = clock;
        s1_sel$clock = clock;
        s1_v$clock = clock;
        s2_y0$clock = clock;
        s2_y1$clock = clock;
        s2_v$clock = clock;
        k$0$d = k$0$q;
        k$1$d = k$1$q;
        k$2$d = k$2$q;
        k$3$d = k$3$q;
        s1_a0$d = s1_a0$q;
        s1_a1$d = s1_a1$q;
        s1_sel$d = s1_sel$q;
        s1_v$d = s1_v$q;
        s2_y0$d = s2_y0$q;
        s2_y1$d = s2_y1$q;
        s2_v$d = s2_v$q;
        if (load_en & (load_addr == 8'h0)) begin
            k$0$d = load_data;
        end
        if (load_en & (load_addr == 8'h1)) begin
            k$1$d = load_data;
        end
        if (load_en & (load_addr == 8'h2)) begin
            k$2$d = load_data;
        end
        if (load_en & (load_addr == 8'h3)) begin
            k$3$d = load_data;
        end
        s1_a0$d = a$0;
        s1_a1$d = a$1;
        s1_sel$d = sel;
        s1_v$d = in_valid;
        case (s1_sel$q)
            2'h0: begin k_sel = k$0$q; k_alt = k$1$q; end
            2'h1: begin k_sel = k$1$q; k_alt = k$0$q; end
            2'h2: begin k_sel = k$2$q; k_alt = k$3$q; end
            default: begin k_sel = k$3$q; k_alt = k$2$q; end
        endcase
        s2_y0$d = s1_a0$q + k_sel;
        s2_y1$d = s1_a1$q + k_alt;
        s2_v$d = s1_v$q;
        y$0 = s2_y0$q;
        y$1 = s2_y1$q;
        out_valid = s2_v$q;
    end
    
endmodule // top


module top$k$0(d,q,clock);
    
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
          
endmodule // top$k$0


module top$k$1(d,q,clock);
    
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
          
endmodule // top$k$1


module top$k$2(d,q,clock);
    
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
          
endmodule // top$k$2


module top$k$3(d,q,clock);
    
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
          
endmodule // top$k$3


module top$s1_a0(d,q,clock);
    
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
          
endmodule // top$s1_a0


module top$s1_a1(d,q,clock);
    
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
          
endmodule // top$s1_a1


module top$s1_sel(d,q,clock);
    
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
          
endmodule // top$s1_sel


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


module top$s2_y0(d,q,clock);
    
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
          
endmodule // top$s2_y0


module top$s2_y1(d,q,clock);
    
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
          
endmodule // top$s2_y1


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
