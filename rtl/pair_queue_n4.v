

module top(clock,clear,lifo,push,push_data,push2,push2_data,pop,empty,full,count,max_count,overflow,top_data);
    
    // Module arguments
    input wire  clock;
    input wire  clear;
    input wire  lifo;
    input wire  push;
    input wire  [66:0] push_data;
    input wire  push2;
    input wire  [66:0] push2_data;
    input wire  pop;
    output reg  empty;
    output reg  full;
    output reg  [4:0] count;
    output reg  [4:0] max_count;
    output reg  overflow;
    output reg  [66:0] top_data;
    
    // Constant declarations
    localparam  c_cap = 5'b10000;
    localparam  c_last = 4'hf;
    localparam  c_one = 4'h1;
    localparam  c_m2 = 4'he;
    
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
    reg  rsel$d;
    wire  rsel$q;
    reg  rsel$clock;
    reg  order_lifo$d;
    wire  order_lifo$q;
    reg  order_lifo$clock;
    reg  [4:0] max_r$d;
    wire  [4:0] max_r$q;
    reg  max_r$clock;
    reg  ovf_r$d;
    wire  ovf_r$q;
    reg  ovf_r$clock;
    reg  [2:0] bank0$read_address;
    reg  bank0$read_clock;
    wire  [66:0] bank0$read_data;
    reg  [2:0] bank0$write_address;
    reg  bank0$write_clock;
    reg  [66:0] bank0$write_data;
    reg  bank0$write_enable;
    reg  [2:0] bank1$read_address;
    reg  bank1$read_clock;
    wire  [66:0] bank1$read_data;
    reg  [2:0] bank1$write_address;
    reg  bank1$write_clock;
    reg  [66:0] bank1$write_data;
    reg  bank1$write_enable;
    reg  nonempty$d;
    wire  nonempty$q;
    reg  nonempty$clock;
    reg  many_r$d;
    wire  many_r$q;
    reg  many_r$clock;
    reg  full_r$d;
    wire  full_r$q;
    reg  full_r$clock;
    reg  tight_r$d;
    wire  tight_r$q;
    reg  tight_r$clock;
    reg  [3:0] rd1_x$d;
    wire  [3:0] rd1_x$q;
    reg  rd1_x$clock;
    reg  [3:0] wr1_x$d;
    wire  [3:0] wr1_x$q;
    reg  wr1_x$clock;
    reg  [3:0] wr_m1_n$d;
    wire  [3:0] wr_m1_n$q;
    reg  wr_m1_n$clock;
    reg  [3:0] wr_m2_x$d;
    wire  [3:0] wr_m2_x$q;
    reg  wr_m2_x$clock;
    
    // Local signals
    reg  many;
    reg  do_pop;
    reg  nfull;
    reg  spare;
    reg  c0_zero;
    reg  [4:0] cnt_m1;
    reg  [4:0] cnt_p1;
    reg  [4:0] cnt_p2;
    reg  [66:0] e1;
    reg  any;
    reg  two;
    reg  s1;
    reg  s2;
    reg  [66:0] next_entry;
    reg  [4:0] cnt_n;
    reg  [3:0] rd_n;
    reg  [3:0] wr_n;
    reg  [3:0] wr1;
    reg  [3:0] wr_m1;
    reg  [3:0] wr_m2;
    reg  [3:0] rd1;
    reg  pick;
    reg  hit_a;
    reg  hit_b;
    reg  [3:0] raddr;
    reg  we_a;
    reg  we_b;
    reg  [66:0] wdata_a;
    reg  [66:0] wdata_b;
    
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
    top$rd1_x rd_ptr(
        .d(rd_ptr$d),
        .q(rd_ptr$q),
        .clock(rd_ptr$clock)
    );
    top$rd1_x wr_ptr(
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
    top$byp rsel(
        .d(rsel$d),
        .q(rsel$q),
        .clock(rsel$clock)
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
    top$bank0 bank0(
        .read_address(bank0$read_address),
        .read_clock(bank0$read_clock),
        .read_data(bank0$read_data),
        .write_address(bank0$write_address),
        .write_clock(bank0$write_clock),
        .write_data(bank0$write_data),
        .write_enable(bank0$write_enable)
    );
    top$bank0 bank1(
        .read_address(bank1$read_address),
        .read_clock(bank1$read_clock),
        .read_data(bank1$read_data),
        .write_address(bank1$write_address),
        .write_clock(bank1$write_clock),
        .write_data(bank1$write_data),
        .write_enable(bank1$write_enable)
    );
    top$byp nonempty(
        .d(nonempty$d),
        .q(nonempty$q),
        .clock(nonempty$clock)
    );
    top$byp many_r(
        .d(many_r$d),
        .q(many_r$q),
        .clock(many_r$clock)
    );
    top$byp full_r(
        .d(full_r$d),
        .q(full_r$q),
        .clock(full_r$clock)
    );
    top$byp tight_r(
        .d(tight_r$d),
        .q(tight_r$q),
        .clock(tight_r$clock)
    );
    top$rd1_x rd1_x(
        .d(rd1_x$d),
        .q(rd1_x$q),
        .clock(rd1_x$clock)
    );
    top$rd1_x wr1_x(
        .d(wr1_x$d),
        .q(wr1_x$q),
        .clock(wr1_x$clock)
    );
    top$rd1_x wr_m1_n(
        .d(wr_m1_n$d),
        .q(wr_m1_n$q),
        .clock(wr_m1_n$clock)
    );
    top$rd1_x wr_m2_x(
        .d(wr_m2_x$d),
        .q(wr_m2_x$q),
        .clock(wr_m2_x$clock)
    );
    
    // Update code
    always @(*) begin
        cnt$clock = clock;
        nonempty$clock = clock;
        top_r$clock = clock;
        rd_ptr$clock = clock;
        wr_ptr$clock = clock;
        byp$clock = clock;
        byp_data$clock = clock;
        rsel$clock = clock;
        order_lifo$clock = clock;
        max_r$clock = clock;
        ovf_r$clock = clock;
        cnt$d = cnt$q;
        nonempty$d = nonempty$q;
        top_r$d = top_r$q;
        rd_ptr$d = rd_ptr$q;
        wr_ptr$d = wr_ptr$q;
        byp$d = byp$q;
        byp_data$d = byp_data$q;
        rsel$d = rsel$q;
        order_lifo$d = order_lifo$q;
        max_r$d = max_r$q;
        ovf_r$d = ovf_r$q;
        many_r$clock = clock;
        full_r$clock = clock;
        tight_r$clock = clock;
        rd1_x$clock = clock;
        wr1_x$clock = clock;
        wr_m1_n$clock = clock;
        wr_m2_x$clock = clock;
        many_r$d = many_r$q;
        full_r$d = full_r$q;
        tight_r$d = tight_r$q;
        rd1_x$d = rd1_x$q;
        wr1_x$d = wr1_x$q;
        wr_m1_n$d = wr_m1_n$q;
        wr_m2_x$d = wr_m2_x$q;
        bank0$read_clock = clock;
        bank0$write_clock = clock;
        bank1$read_clock = clock;
        bank1$write_clock = clock;
        empty = ~nonempty$q;
        full = cnt$q == c_cap;
        count = cnt$q;
        max_count = max_r$q;
        overflow = ovf_r$q;
        top_data = top_r$q;
        many = many_r$q;
        do_pop = pop & nonempty$q;
        nfull = ~full_r$q;
        spare = ~tight_r$q;
        cnt_m1 = cnt$q - 32'h1;
        cnt_p1 = cnt$q + 32'h1;
        cnt_p2 = cnt$q + 32'h2;
        c0_zero = ~nonempty$q | (do_pop & ~many);
        e1 = push2_data;
        if (push) begin
            e1 = push_data;
        end
        any = push | push2;
        two = push & push2;
        s1 = any & (do_pop | nfull);
        s2 = two & ((do_pop & nfull) | spare);
        next_entry = bank0$read_data;
        if (rsel$q) begin
            next_entry = bank1$read_data;
        end
        if (byp$q) begin
            next_entry = byp_data$q;
        end
        cnt_n = cnt$q;
        if (do_pop) begin
            if (~s1) begin
                cnt_n = cnt_m1;
            end
            if (s2) begin
                cnt_n = cnt_p1;
            end
        end
        else begin
            if (s1) begin
                cnt_n = cnt_p1;
            end
            if (s2) begin
                cnt_n = cnt_p2;
            end
        end
        rd_n = rd_ptr$q;
        wr_n = wr_ptr$q;
        wr1 = wr1_x$q ^ c_one;
        we_a = 1'b0;
        we_b = 1'b0;
        wdata_a = e1;
        wdata_b = push2_data;
        if (order_lifo$q) begin
            wdata_b = e1;
            if (do_pop) begin
                if (~s1) begin
                    top_r$d = 32'h0;
                    if (many) begin
                        top_r$d = next_entry;
                        wr_n = wr_ptr$q - 32'h1;
                    end
                end
                if (s1) begin
                    top_r$d = e1;
                end
                if (s2) begin
                    we_a = 1'b1;
                    wr_n = wr_ptr$q + 32'h1;
                    top_r$d = push2_data;
                end
            end
            else begin
                if (s1) begin
                    top_r$d = e1;
                    if (nonempty$q) begin
                        we_a = 1'b1;
                        wdata_a = top_r$q;
                        wr_n = wr_ptr$q + 32'h1;
                    end
                end
                if (s2) begin
                    top_r$d = push2_data;
                    we_a = 1'b1;
                    wr_n = wr_ptr$q + 32'h1;
                    if (nonempty$q) begin
                        we_b = 1'b1;
                        wr_n = wr_ptr$q + 32'h2;
                    end
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
            if (c0_zero) begin
                if (s1) begin
                    top_r$d = e1;
                end
                if (s2) begin
                    we_a = 1'b1;
                    wdata_a = push2_data;
                    wr_n = wr_ptr$q + 32'h1;
                end
            end
            else begin
                if (s1) begin
                    we_a = 1'b1;
                    wr_n = wr_ptr$q + 32'h1;
                end
                if (s2) begin
                    we_b = 1'b1;
                    wr_n = wr_ptr$q + 32'h2;
                end
            end
        end
        if ((any & ~s1) | (two & ~s2)) begin
            ovf_r$d = 1'b1;
        end
        if (clear) begin
            cnt_n = 32'h0;
            top_r$d = 32'h0;
            rd_n = 32'h0;
            wr_n = 32'h0;
            we_a = 1'b0;
            we_b = 1'b0;
            order_lifo$d = lifo;
            max_r$d = 32'h0;
            ovf_r$d = 1'b0;
        end
        cnt$d = cnt_n;
        nonempty$d = cnt_n != 32'h0;
        if (cnt_n > max_r$q) begin
            max_r$d = cnt_n;
        end
        many_r$d = cnt_n > 32'h1;
        full_r$d = cnt_n == c_cap;
        tight_r$d = cnt_n >= c_cap - 32'h1;
        rd_ptr$d = rd_n;
        wr_ptr$d = wr_n;
        rd1_x$d = (rd_n + 32'h1) ^ c_one;
        wr1_x$d = (wr_n + 32'h1) ^ c_one;
        wr_m1_n$d = ~(wr_n - 32'h1);
        wr_m2_x$d = (wr_n - 32'h2) ^ c_m2;
        rd1 = rd1_x$q ^ c_one;
        wr_m1 = ~wr_m1_n$q;
        wr_m2 = wr_m2_x$q ^ c_m2;
        pick = do_pop & many;
        raddr = rd_ptr$q;
        if (pick) begin
            raddr = rd1;
        end
        if (order_lifo$q) begin
            raddr = wr_m1;
            if (do_pop) begin
                if (~s1 & many) begin
                    raddr = wr_m2;
                end
                if (s2) begin
                    raddr = wr_ptr$q;
                end
            end
            else begin
                if (s1 & nonempty$q) begin
                    raddr = wr_ptr$q;
                end
                if (s2) begin
                    raddr = wr_ptr$q;
                    if (nonempty$q) begin
                        raddr = wr1;
                    end
                end
            end
        end
        if (clear) begin
            raddr = 32'h0;
            if (lifo) begin
                raddr = c_last;
            end
        end
        bank0$write_enable = (we_a & ~wr_ptr$q[32'h0]) | (we_b & wr_ptr$q[32'h0]);
        bank1$write_enable = (we_a & wr_ptr$q[32'h0]) | (we_b & ~wr_ptr$q[32'h0]);
        bank0$write_address = wr_ptr$q[(32'h1)+:(3)];
        bank0$write_data = wdata_a;
        bank1$write_address = wr_ptr$q[(32'h1)+:(3)];
        bank1$write_data = wdata_a;
        if (wr_ptr$q[32'h0]) begin
            bank0$write_address = wr1[(32'h1)+:(3)];
            bank0$write_data = wdata_b;
        end
        else begin
            bank1$write_address = wr1[(32'h1)+:(3)];
            bank1$write_data = wdata_b;
        end
        bank0$read_address = raddr[(32'h1)+:(3)];
        bank1$read_address = raddr[(32'h1)+:(3)];
        rsel$d = raddr[32'h0];
        hit_a = rd_ptr$q == wr_ptr$q;
        hit_b = rd_ptr$q == wr1;
        if (pick) begin
            hit_a = rd1 == wr_ptr$q;
            hit_b = rd_ptr$q == wr_ptr$q;
        end
        if (order_lifo$q) begin
            hit_a = 1'b1;
            hit_b = 1'b1;
        end
        byp$d = (we_a & hit_a) | (we_b & hit_b);
        byp_data$d = wdata_a;
        if (we_b & hit_b) begin
            byp_data$d = wdata_b;
        end
    end
    
endmodule // top


module top$bank0(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [2:0] read_address;
    input wire  read_clock;
    output reg  [66:0] read_data;
    input wire  [2:0] write_address;
    input wire  write_clock;
    input wire  [66:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    reg[66:0] mem[7:0];
    
    
    
    always @(posedge read_clock) begin
       read_data <= mem[read_address];
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address] <= write_data;
       end
    end
                
endmodule // top$bank0


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


module top$rd1_x(d,q,clock);
    
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
          
endmodule // top$rd1_x
