

module top(clock,a,b,valid_in,flag,valid_out);
    
    // Module arguments
    input wire  clock;
    input wire  [23:0] a;
    input wire  [23:0] b;
    input wire  valid_in;
    output reg  flag;
    output reg  valid_out;
    
    // Constant declarations
    localparam  c_inf = 23'h7f8000;
    
    // Stub signals
    reg  s1_flag$d;
    wire  s1_flag$q;
    reg  s1_flag$clock;
    reg  s1_valid$d;
    wire  s1_valid$q;
    reg  s1_valid$clock;
    
    // Local signals
    reg  [22:0] mag_a;
    reg  [22:0] mag_b;
    
    // Sub module instances
    top$s1_flag s1_flag(
        .d(s1_flag$d),
        .q(s1_flag$q),
        .clock(s1_flag$clock)
    );
    top$s1_flag s1_valid(
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
        mag_a = a[(32'h0)+:(23)];
        mag_b = b[(32'h0)+:(23)];
        s1_flag$d = 1'b0;
        if ((mag_a <= c_inf) & (mag_b <= c_inf)) begin
            if (a[32'h17] & b[32'h17]) begin
                s1_flag$d = |mag_a | |mag_b;
            end
            if (a[32'h17] & ~b[32'h17]) begin
                s1_flag$d = mag_a > mag_b;
            end
            if (~a[32'h17] & b[32'h17]) begin
                s1_flag$d = mag_b > mag_a;
            end
        end
        s1_valid$d = valid_in;
        flag = s1_flag$q;
        valid_out = s1_valid$q;
    end
    
endmodule // top


module top$s1_flag(d,q,clock);
    
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
          
endmodule // top$s1_flag
