

module top(clock,x,valid_in,y,valid_out);
    
    // Module arguments
    input wire  clock;
    input wire  [23:0] x;
    input wire  valid_in;
    output reg  [23:0] y;
    output reg  valid_out;
    
    // Constant declarations
    localparam  c_shift = 8'h10;
    localparam  c_min_normal = 24'h8000;
    localparam  c_inf = 24'h7f8000;
    
    // Stub signals
    reg  s1_valid$d;
    wire  s1_valid$q;
    reg  s1_valid$clock;
    reg  [23:0] s1_y$d;
    wire  [23:0] s1_y$q;
    reg  s1_y$clock;
    
    // Local signals
    reg  [7:0] c1_ef;
    reg  c1_frac_zero;
    reg  [23:0] c1_y;
    
    // Sub module instances
    top$s1_valid s1_valid(
        .d(s1_valid$d),
        .q(s1_valid$q),
        .clock(s1_valid$clock)
    );
    top$s1_y s1_y(
        .d(s1_y$d),
        .q(s1_y$q),
        .clock(s1_y$clock)
    );
    
    // Update code
    always @(*) begin
        s1_valid$clock = clock;
        s1_y$clock = clock;
        s1_valid$d = s1_valid$q;
        s1_y$d = s1_y$q;
        c1_ef = x[(32'hf)+:(8)];
        c1_frac_zero = x[(32'h0)+:(15)] == 32'h0;
        c1_y = c_min_normal;
        if (c1_ef > c_shift) begin
            c1_y = ((c1_ef - c_shift) & 24'hffffff) << 32'hf;
        end
        if (&c1_ef) begin
            c1_y = c_min_normal;
            if (c1_frac_zero) begin
                c1_y = c_inf;
            end
        end
        s1_valid$d = valid_in;
        s1_y$d = c1_y;
        y = s1_y$q;
        valid_out = s1_valid$q;
    end
    
endmodule // top


module top$s1_valid(d,q,clock);
    
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
          
endmodule // top$s1_valid


module top$s1_y(d,q,clock);
    
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
          
endmodule // top$s1_y
