

module top(clock,a,sel,y);
    
    // Module arguments
    input wire  clock;
    input wire  [18:0] a;
    input wire  sel;
    output reg  [18:0] y;
    
    // Constant declarations
    localparam  c_k0 = 10'b11111000;
    localparam  c_k1 = 10'b11111000;
    localparam  c_sh0 = 8'h9;
    localparam  c_sh1 = 8'h0;
    localparam  c_t0 = 8'h1;
    localparam  c_t1 = 8'h0;
    localparam  c_en0 = 1'b1;
    localparam  c_en1 = 1'b0;
    localparam  c_j = 8'hc;
    localparam  c_j1 = 8'hd;
    localparam  c_f = 8'ha;
    localparam  c_ofs = 10'b100000000;
    localparam  c_norm_min = 10'b100000001;
    localparam  c_min = 19'b10000000000;
    localparam  c_inf = 19'b111111110000000000;
    localparam  c_nan = 19'b111111111000000000;
    
    // Stub signals
    reg  out$clock;
    reg  [18:0] out$d;
    wire  [18:0] out$q;
    
    // Local signals
    reg  [7:0] field;
    reg  [9:0] frac;
    reg  [23:0] m;
    reg  [7:0] lo_sh;
    reg  [7:0] t_sh;
    reg  t_en;
    reg  [9:0] kk;
    reg  [23:0] third;
    reg  [23:0] sum;
    reg  top;
    reg  [7:0] sh;
    reg  [23:0] hi;
    reg  lost;
    reg  [23:0] rnd;
    reg  [9:0] eb;
    reg  [9:0] e10;
    reg  [18:0] res;
    
    // Sub module instances
    top$out out(
        .clock(out$clock),
        .d(out$d),
        .q(out$q)
    );
    
    // Update code
    always @(*) begin
        out$clock = clock;
        field = a[(32'ha)+:(8)];
        frac = a[(32'h0)+:(10)];
        m = (((frac) & 24'hffffff) & ~(1 << (32'ha)) | ((1'b1) << (32'ha)));
        lo_sh = c_sh0;
        t_sh = c_t0;
        t_en = c_en0;
        kk = c_k0;
        if (sel) begin
            lo_sh = c_sh1;
            t_sh = c_t1;
            t_en = c_en1;
            kk = c_k1;
        end
        third = 32'h0;
        if (t_en) begin
            third = m << t_sh;
        end
        sum = (m << c_j) + (m << lo_sh) + third;
        eb = ((field) & 10'h3ff) + kk;
        top = sum[32'h18 - 32'h1];
        sh = c_j;
        if (top) begin
            sh = c_j1;
        end
        hi = sum >> sh;
        lost = (hi << sh) != sum;
        rnd = hi + lost;
        e10 = eb + top + rnd[32'ha + 32'h1];
        res = (((e10 - c_ofs) & 19'h7ffff) << c_f) | ((((rnd) & 10'h3ff)) & 19'h7ffff);
        if ((field == 32'h0) | (e10 < c_norm_min)) begin
            res = c_min;
        end
        if ((field == 32'h0) & (frac == 32'h0)) begin
            res = 32'h0;
        end
        if (&field) begin
            res = c_inf;
            if (frac != 32'h0) begin
                res = c_nan;
            end
        end
        out$d = res;
        y = out$q;
    end
    
endmodule // top


module top$out(clock,d,q);
    
    // Module arguments
    input wire  clock;
    input wire  [18:0] d;
    output reg  [18:0] q;
    
    // Stub signals
    reg  [18:0] line$0$d;
    wire  [18:0] line$0$q;
    reg  line$0$clock;
    reg  [18:0] line$1$d;
    wire  [18:0] line$1$q;
    reg  line$1$clock;
    reg  [18:0] line$2$d;
    wire  [18:0] line$2$q;
    reg  line$2$clock;
    reg  [18:0] line$3$d;
    wire  [18:0] line$3$q;
    reg  line$3$clock;
    
    // Sub module instances
    top$out$line$0 line$0(
        .d(line$0$d),
        .q(line$0$q),
        .clock(line$0$clock)
    );
    top$out$line$0 line$1(
        .d(line$1$d),
        .q(line$1$q),
        .clock(line$1$clock)
    );
    top$out$line$0 line$2(
        .d(line$2$d),
        .q(line$2$q),
        .clock(line$2$clock)
    );
    top$out$line$0 line$3(
        .d(line$3$d),
        .q(line$3$q),
        .clock(line$3$clock)
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
        line$0$d = line$1$q;
        line$1$d = line$2$q;
        line$2$d = line$3$q;
        q = line$0$q;
    end
    
endmodule // top$out


module top$out$line$0(d,q,clock);
    
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
          
endmodule // top$out$line$0
