

module top(clock,clear,lifo,push,push_data,pop,empty,full,count,max_count,overflow,top_data);
    
    // Module arguments
    input wire  clock;
    input wire  clear;
    input wire  lifo;
    input wire  push;
    input wire  [66:0] push_data;
    input wire  pop;
    output reg  empty;
    output reg  full;
    output reg  [4:0] count;
    output reg  [4:0] max_count;
    output reg  overflow;
    output reg  [66:0] top_data;
    
    // Constant declarations
    localparam  c_cap = 5'b10000;
    
    // Stub signals
    reg  [4:0] cnt$d;
    wire  [4:0] cnt$q;
    reg  cnt$clock;
    reg  [66:0] top_r$d;
    wire  [66:0] top_r$q;
    reg  top_r$clock;
    reg  [3:0] rd_ptr$d;
    wire  [3:0] rd_ptr$q;
    reg  rd_ptr$clock;
    reg  [3:0] wr_ptr$d;
    wire  [3:0] wr_ptr$q;
    reg  wr_ptr$clock;
    reg  byp$d;
    wire  byp$q;
    reg  byp$clock;
    reg  [66:0] byp_data$d;
    wire  [66:0] byp_data$q;
    reg  byp_data$clock;
    reg  order_lifo$d;
    wire  order_lifo$q;
    reg  order_lifo$clock;
    reg  [4:0] max_r$d;
    wire  [4:0] max_r$q;
    reg  max_r$clock;
    reg  ovf_r$d;
    wire  ovf_r$q;
    reg  ovf_r$clock;
    reg  [3:0] ram$read_address;
    reg  ram$read_clock;
    wire  [66:0] ram$read_data;
    reg  [3:0] ram$write_address;
    reg  ram$write_clock;
    reg  [66:0] ram$write_data;
    reg  ram$write_enable;
    
    // Local signals
    reg  nonempty;
    reg  many;
    reg  is_full;
    reg  do_pop;
    reg  do_push;
    reg  [66:0] next_entry;
    reg  [4:0] cnt_n;
    reg  [3:0] rd_n;
    reg  [3:0] wr_n;
    reg  [3:0] raddr;
    reg  we;
    reg  [66:0] wdata;
    
    // Sub module instances
    top$cnt cnt(
        .d(cnt$d),
        .q(cnt$q),
        .clock(cnt$clock)
    );
    top$byp_data top_r(
        .d(top_r$d),
        .q(top_r$q),
        .clock(top_r$clock)
    );
    top$rd_ptr rd_ptr(
        .d(rd_ptr$d),
        .q(rd_ptr$q),
        .clock(rd_ptr$clock)
    );
    top$rd_ptr wr_ptr(
        .d(wr_ptr$d),
        .q(wr_ptr$q),
        .clock(wr_ptr$clock)
    );
    top$byp byp(
        .d(byp$d),
        .q(byp$q),
        .clock(byp$clock)
    );
    top$byp_data byp_data(
        .d(byp_data$d),
        .q(byp_data$q),
        .clock(byp_data$clock)
    );
    top$byp order_lifo(
        .d(order_lifo$d),
        .q(order_lifo$q),
        .clock(order_lifo$clock)
    );
    top$cnt max_r(
        .d(max_r$d),
        .q(max_r$q),
        .clock(max_r$clock)
    );
    top$byp ovf_r(
        .d(ovf_r$d),
        .q(ovf_r$q),
        .clock(ovf_r$clock)
    );
    top$ram ram(
        .read_address(ram$read_address),
        .read_clock(ram$read_clock),
        .read_data(ram$read_data),
        .write_address(ram$write_address),
        .write_clock(ram$write_clock),
        .write_data(ram$write_data),
        .write_enable(ram$write_enable)
    );
    
    // Update code
    always @(*) begin
        cnt$clock = clock;
        top_r$clock = clock;
        rd_ptr$clock = clock;
        wr_ptr$clock = clock;
        byp$clock = clock;
        byp_data$clock = clock;
        order_lifo$clock = clock;
        max_r$clock = clock;
        ovf_r$clock = clock;
        cnt$d = cnt$q;
        top_r$d = top_r$q;
        rd_ptr$d = rd_ptr$q;
        wr_ptr$d = wr_ptr$q;
        byp$d = byp$q;
        byp_data$d = byp_data$q;
        order_lifo$d = order_lifo$q;
        max_r$d = max_r$q;
        ovf_r$d = ovf_r$q;
        ram$read_clock = clock;
        ram$write_clock = clock;
        empty = cnt$q == 32'h0;
        full = cnt$q == c_cap;
        count = cnt$q;
        max_count = max_r$q;
        overflow = ovf_r$q;
        top_data = top_r$q;
        nonempty = cnt$q != 32'h0;
        many = cnt$q > 32'h1;
        is_full = cnt$q == c_cap;
        do_pop = pop & nonempty;
        do_push = push & (~is_full | do_pop);
        next_entry = ram$read_data;
        if (byp$q) begin
            next_entry = byp_data$q;
        end
        cnt_n = cnt$q;
        if (do_push & ~do_pop) begin
            cnt_n = cnt$q + 32'h1;
        end
        if (do_pop & ~do_push) begin
            cnt_n = cnt$q - 32'h1;
        end
        rd_n = rd_ptr$q;
        wr_n = wr_ptr$q;
        we = 1'b0;
        wdata = push_data;
        if (order_lifo$q) begin
            if (do_pop & ~do_push) begin
                top_r$d = 32'h0;
                if (many) begin
                    top_r$d = next_entry;
                    wr_n = wr_ptr$q - 32'h1;
                end
            end
            if (do_push) begin
                top_r$d = push_data;
                if (nonempty & ~do_pop) begin
                    we = 1'b1;
                    wdata = top_r$q;
                    wr_n = wr_ptr$q + 32'h1;
                end
            end
        end
        else begin
            if (do_pop) begin
                top_r$d = 32'h0;
                if (many) begin
                    top_r$d = next_entry;
                    rd_n = rd_ptr$q + 32'h1;
                end
            end
            if (do_push) begin
                if (many | (nonempty & ~do_pop)) begin
                    we = 1'b1;
                    wr_n = wr_ptr$q + 32'h1;
                end
                else begin
                    top_r$d = push_data;
                end
            end
        end
        cnt$d = cnt_n;
        if (cnt_n > max_r$q) begin
            max_r$d = cnt_n;
        end
        if (push & is_full & ~do_pop) begin
            ovf_r$d = 1'b1;
        end
        if (clear) begin
            cnt$d = 32'h0;
            top_r$d = 32'h0;
            rd_n = 32'h0;
            wr_n = 32'h0;
            we = 1'b0;
            order_lifo$d = lifo;
            max_r$d = 32'h0;
            ovf_r$d = 1'b0;
        end
        rd_ptr$d = rd_n;
        wr_ptr$d = wr_n;
        raddr = rd_n;
        if (order_lifo$d) begin
            raddr = wr_n - 32'h1;
        end
        ram$write_enable = we;
        ram$write_address = wr_ptr$q;
        ram$write_data = wdata;
        ram$read_address = raddr;
        byp$d = we & (raddr == wr_ptr$q);
        byp_data$d = wdata;
    end
    
endmodule // top


module top$byp(d,q,clock);
    
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
          
endmodule // top$byp


module top$byp_data(d,q,clock);
    
    // Module arguments
    input wire  [66:0] d;
    output reg  [66:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 67'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$byp_data


module top$cnt(d,q,clock);
    
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
          
endmodule // top$cnt


module top$ram(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [3:0] read_address;
    input wire  read_clock;
    output reg  [66:0] read_data;
    input wire  [3:0] write_address;
    input wire  write_clock;
    input wire  [66:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    reg[66:0] mem[15:0];
    
    
    
    always @(posedge read_clock) begin
       read_data <= mem[read_address];
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address] <= write_data;
       end
    end
                
endmodule // top$ram


module top$rd_ptr(d,q,clock);
    
    // Module arguments
    input wire  [3:0] d;
    output reg  [3:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 4'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$rd_ptr
