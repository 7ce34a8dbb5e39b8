

module top(clock,wr_valid,wr_set,wr_lane,wr_l,wr_r,rd_set,rd_entry,dl,dr);
    
    // Module arguments
    input wire  clock;
    input wire  wr_valid;
    input wire  wr_set;
    input wire  [4:0] wr_lane;
    input wire  [31:0] wr_l;
    input wire  [31:0] wr_r;
    input wire  rd_set;
    input wire  [1:0] rd_entry;
    output reg  [255:0] dl;
    output reg  [255:0] dr;
    
    // Constant declarations
    localparam  c_half = 5'b1100;
    
    // Stub signals
    reg  [2:0] ram_l0$read_address;
    reg  ram_l0$read_clock;
    wire  [31:0] ram_l0$read_data;
    reg  [2:0] ram_l0$write_address;
    reg  ram_l0$write_clock;
    reg  [31:0] ram_l0$write_data;
    reg  ram_l0$write_enable;
    reg  [2:0] ram_r0$read_address;
    reg  ram_r0$read_clock;
    wire  [31:0] ram_r0$read_data;
    reg  [2:0] ram_r0$write_address;
    reg  ram_r0$write_clock;
    reg  [31:0] ram_r0$write_data;
    reg  ram_r0$write_enable;
    reg  [2:0] ram_l1$read_address;
    reg  ram_l1$read_clock;
    wire  [31:0] ram_l1$read_data;
    reg  [2:0] ram_l1$write_address;
    reg  ram_l1$write_clock;
    reg  [31:0] ram_l1$write_data;
    reg  ram_l1$write_enable;
    reg  [2:0] ram_r1$read_address;
    reg  ram_r1$read_clock;
    wire  [31:0] ram_r1$read_data;
    reg  [2:0] ram_r1$write_address;
    reg  ram_r1$write_clock;
    reg  [31:0] ram_r1$write_data;
    reg  ram_r1$write_enable;
    reg  [2:0] ram_l2$read_address;
    reg  ram_l2$read_clock;
    wire  [31:0] ram_l2$read_data;
    reg  [2:0] ram_l2$write_address;
    reg  ram_l2$write_clock;
    reg  [31:0] ram_l2$write_data;
    reg  ram_l2$write_enable;
    reg  [2:0] ram_r2$read_address;
    reg  ram_r2$read_clock;
    wire  [31:0] ram_r2$read_data;
    reg  [2:0] ram_r2$write_address;
    reg  ram_r2$write_clock;
    reg  [31:0] ram_r2$write_data;
    reg  ram_r2$write_enable;
    reg  [2:0] ram_l3$read_address;
    reg  ram_l3$read_clock;
    wire  [31:0] ram_l3$read_data;
    reg  [2:0] ram_l3$write_address;
    reg  ram_l3$write_clock;
    reg  [31:0] ram_l3$write_data;
    reg  ram_l3$write_enable;
    reg  [2:0] ram_r3$read_address;
    reg  ram_r3$read_clock;
    wire  [31:0] ram_r3$read_data;
    reg  [2:0] ram_r3$write_address;
    reg  ram_r3$write_clock;
    reg  [31:0] ram_r3$write_data;
    reg  ram_r3$write_enable;
    reg  [2:0] ram_l4$read_address;
    reg  ram_l4$read_clock;
    wire  [31:0] ram_l4$read_data;
    reg  [2:0] ram_l4$write_address;
    reg  ram_l4$write_clock;
    reg  [31:0] ram_l4$write_data;
    reg  ram_l4$write_enable;
    reg  [2:0] ram_r4$read_address;
    reg  ram_r4$read_clock;
    wire  [31:0] ram_r4$read_data;
    reg  [2:0] ram_r4$write_address;
    reg  ram_r4$write_clock;
    reg  [31:0] ram_r4$write_data;
    reg  ram_r4$write_enable;
    reg  [2:0] ram_l5$read_address;
    reg  ram_l5$read_clock;
    wire  [31:0] ram_l5$read_data;
    reg  [2:0] ram_l5$write_address;
    reg  ram_l5$write_clock;
    reg  [31:0] ram_l5$write_data;
    reg  ram_l5$write_enable;
    reg  [2:0] ram_r5$read_address;
    reg  ram_r5$read_clock;
    wire  [31:0] ram_r5$read_data;
    reg  [2:0] ram_r5$write_address;
    reg  ram_r5$write_clock;
    reg  [31:0] ram_r5$write_data;
    reg  ram_r5$write_enable;
    reg  [2:0] ram_l6$read_address;
    reg  ram_l6$read_clock;
    wire  [31:0] ram_l6$read_data;
    reg  [2:0] ram_l6$write_address;
    reg  ram_l6$write_clock;
    reg  [31:0] ram_l6$write_data;
    reg  ram_l6$write_enable;
    reg  [2:0] ram_r6$read_address;
    reg  ram_r6$read_clock;
    wire  [31:0] ram_r6$read_data;
    reg  [2:0] ram_r6$write_address;
    reg  ram_r6$write_clock;
    reg  [31:0] ram_r6$write_data;
    reg  ram_r6$write_enable;
    reg  [2:0] ram_l7$read_address;
    reg  ram_l7$read_clock;
    wire  [31:0] ram_l7$read_data;
    reg  [2:0] ram_l7$write_address;
    reg  ram_l7$write_clock;
    reg  [31:0] ram_l7$write_data;
    reg  ram_l7$write_enable;
    reg  [2:0] ram_r7$read_address;
    reg  ram_r7$read_clock;
    wire  [31:0] ram_r7$read_data;
    reg  [2:0] ram_r7$write_address;
    reg  ram_r7$write_clock;
    reg  [31:0] ram_r7$write_data;
    reg  ram_r7$write_enable;
    
    // Local signals
    reg  [4:0] pos;
    reg  [2:0] wr_addr;
    reg  [2:0] rd_addr;
    
    // Sub module instances
    top$ram_l0 ram_l0(
        .read_address(ram_l0$read_address),
        .read_clock(ram_l0$read_clock),
        .read_data(ram_l0$read_data),
        .write_address(ram_l0$write_address),
        .write_clock(ram_l0$write_clock),
        .write_data(ram_l0$write_data),
        .write_enable(ram_l0$write_enable)
    );
    top$ram_l0 ram_r0(
        .read_address(ram_r0$read_address),
        .read_clock(ram_r0$read_clock),
        .read_data(ram_r0$read_data),
        .write_address(ram_r0$write_address),
        .write_clock(ram_r0$write_clock),
        .write_data(ram_r0$write_data),
        .write_enable(ram_r0$write_enable)
    );
    top$ram_l0 ram_l1(
        .read_address(ram_l1$read_address),
        .read_clock(ram_l1$read_clock),
        .read_data(ram_l1$read_data),
        .write_address(ram_l1$write_address),
        .write_clock(ram_l1$write_clock),
        .write_data(ram_l1$write_data),
        .write_enable(ram_l1$write_enable)
    );
    top$ram_l0 ram_r1(
        .read_address(ram_r1$read_address),
        .read_clock(ram_r1$read_clock),
        .read_data(ram_r1$read_data),
        .write_address(ram_r1$write_address),
        .write_clock(ram_r1$write_clock),
        .write_data(ram_r1$write_data),
        .write_enable(ram_r1$write_enable)
    );
    top$ram_l0 ram_l2(
        .read_address(ram_l2$read_address),
        .read_clock(ram_l2$read_clock),
        .read_data(ram_l2$read_data),
        .write_address(ram_l2$write_address),
        .write_clock(ram_l2$write_clock),
        .write_data(ram_l2$write_data),
        .write_enable(ram_l2$write_enable)
    );
    top$ram_l0 ram_r2(
        .read_address(ram_r2$read_address),
        .read_clock(ram_r2$read_clock),
        .read_data(ram_r2$read_data),
        .write_address(ram_r2$write_address),
        .write_clock(ram_r2$write_clock),
        .write_data(ram_r2$write_data),
        .write_enable(ram_r2$write_enable)
    );
    top$ram_l0 ram_l3(
        .read_address(ram_l3$read_address),
        .read_clock(ram_l3$read_clock),
        .read_data(ram_l3$read_data),
        .write_address(ram_l3$write_address),
        .write_clock(ram_l3$write_clock),
        .write_data(ram_l3$write_data),
        .write_enable(ram_l3$write_enable)
    );
    top$ram_l0 ram_r3(
        .read_address(ram_r3$read_address),
        .read_clock(ram_r3$read_clock),
        .read_data(ram_r3$read_data),
        .write_address(ram_r3$write_address),
        .write_clock(ram_r3$write_clock),
        .write_data(ram_r3$write_data),
        .write_enable(ram_r3$write_enable)
    );
    top$ram_l0 ram_l4(
        .read_address(ram_l4$read_address),
        .read_clock(ram_l4$read_clock),
        .read_data(ram_l4$read_data),
        .write_address(ram_l4$write_address),
        .write_clock(ram_l4$write_clock),
        .write_data(ram_l4$write_data),
        .write_enable(ram_l4$write_enable)
    );
    top$ram_l0 ram_r4(
        .read_address(ram_r4$read_address),
        .read_clock(ram_r4$read_clock),
        .read_data(ram_r4$read_data),
        .write_address(ram_r4$write_address),
        .write_clock(ram_r4$write_clock),
        .write_data(ram_r4$write_data),
        .write_enable(ram_r4$write_enable)
    );
    top$ram_l0 ram_l5(
        .read_address(ram_l5$read_address),
        .read_clock(ram_l5$read_clock),
        .read_data(ram_l5$read_data),
        .write_address(ram_l5$write_address),
        .write_clock(ram_l5$write_clock),
        .write_data(ram_l5$write_data),
        .write_enable(ram_l5$write_enable)
    );
    top$ram_l0 ram_r5(
        .read_address(ram_r5$read_address),
        .read_clock(ram_r5$read_clock),
        .read_data(ram_r5$read_data),
        .write_address(ram_r5$write_address),
        .write_clock(ram_r5$write_clock),
        .write_data(ram_r5$write_data),
        .write_enable(ram_r5$write_enable)
    );
    top$ram_l0 ram_l6(
        .read_address(ram_l6$read_address),
        .read_clock(ram_l6$read_clock),
        .read_data(ram_l6$read_data),
        .write_address(ram_l6$write_address),
        .write_clock(ram_l6$write_clock),
        .write_data(ram_l6$write_data),
        .write_enable(ram_l6$write_enable)
    );
    top$ram_l0 ram_r6(
        .read_address(ram_r6$read_address),
        .read_clock(ram_r6$read_clock),
        .read_data(ram_r6$read_data),
        .write_address(ram_r6$write_address),
        .write_clock(ram_r6$write_clock),
        .write_data(ram_r6$write_data),
        .write_enable(ram_r6$write_enable)
    );
    top$ram_l0 ram_l7(
        .read_address(ram_l7$read_address),
        .read_clock(ram_l7$read_clock),
        .read_data(ram_l7$read_data),
        .write_address(ram_l7$write_address),
        .write_clock(ram_l7$write_clock),
        .write_data(ram_l7$write_data),
        .write_enable(ram_l7$write_enable)
    );
    top$ram_l0 ram_r7(
        .read_address(ram_r7$read_address),
        .read_clock(ram_r7$read_clock),
        .read_data(ram_r7$read_data),
        .write_address(ram_r7$write_address),
        .write_clock(ram_r7$write_clock),
        .write_data(ram_r7$write_data),
        .write_enable(ram_r7$write_enable)
    );
    
    // Update code
    always @(*) begin
        pos = wr_lane - c_half;
        if (wr_lane < c_half) begin
            pos = wr_lane + c_half;
        end
        wr_addr = ((pos[(32'h3)+:(2)]) & 3'h7) | (((wr_set) & 3'h7) << 32'h2);
        rd_addr = ((rd_entry) & 3'h7) | (((rd_set) & 3'h7) << 32'h2);
        ram_l0$read_clock = clock;
        ram_l0$write_clock = clock;
        ram_l0$read_address = rd_addr;
        ram_l0$write_address = wr_addr;
        ram_l0$write_data = wr_l;
        ram_l0$write_enable = wr_valid & (pos[(32'h0)+:(3)] == 32'h0);
        ram_r0$read_clock = clock;
        ram_r0$write_clock = clock;
        ram_r0$read_address = rd_addr;
        ram_r0$write_address = wr_addr;
        ram_r0$write_data = wr_r;
        ram_r0$write_enable = wr_valid & (pos[(32'h0)+:(3)] == 32'h0);
        ram_l1$read_clock = clock;
        ram_l1$write_clock = clock;
        ram_l1$read_address = rd_addr;
        ram_l1$write_address = wr_addr;
        ram_l1$write_data = wr_l;
        ram_l1$write_enable = wr_valid & (pos[(32'h0)+:(3)] == 32'h1);
        ram_r1$read_clock = clock;
        ram_r1$write_clock = clock;
        ram_r1$read_address = rd_addr;
        ram_r1$write_address = wr_addr;
        ram_r1$write_data = wr_r;
        ram_r1$write_enable = wr_valid & (pos[(32'h0)+:(3)] == 32'h1);
        ram_l2$read_clock = clock;
        ram_l2$write_clock = clock;
        ram_l2$read_address = rd_addr;
        ram_l2$write_address = wr_addr;
        ram_l2$write_data = wr_l;
        ram_l2$write_enable = wr_valid & (pos[(32'h0)+:(3)] == 32'h2);
        ram_r2$read_clock = clock;
        ram_r2$write_clock = clock;
        ram_r2$read_address = rd_addr;
        ram_r2$write_address = wr_addr;
        ram_r2$write_data = wr_r;
        ram_r2$write_enable = wr_valid & (pos[(32'h0)+:(3)] == 32'h2);
        ram_l3$read_clock = clock;
        ram_l3$write_clock = clock;
        ram_l3$read_address = rd_addr;
        ram_l3$write_address = wr_addr;
        ram_l3$write_data = wr_l;
        ram_l3$write_enable = wr_valid & (pos[(32'h0)+:(3)] == 32'h3);
        ram_r3$read_clock = clock;
        ram_r3$write_clock = clock;
        ram_r3$read_address = rd_addr;
        ram_r3$write_address = wr_addr;
        ram_r3$write_data = wr_r;
        ram_r3$write_enable = wr_valid & (pos[(32'h0)+:(3)] == 32'h3);
        ram_l4$read_clock = clock;
        ram_l4$write_clock = clock;
        ram_l4$read_address = rd_addr;
        ram_l4$write_address = wr_addr;
        ram_l4$write_data = wr_l;
        ram_l4$write_enable = wr_valid & (pos[(32'h0)+:(3)] == 32'h4);
        ram_r4$read_clock = clock;
        ram_r4$write_clock = clock;
        ram_r4$read_address = rd_addr;
        ram_r4$write_address = wr_addr;
        ram_r4$write_data = wr_r;
        ram_r4$write_enable = wr_valid & (pos[(32'h0)+:(3)] == 32'h4);
        ram_l5$read_clock = clock;
        ram_l5$write_clock = clock;
        ram_l5$read_address = rd_addr;
        ram_l5$write_address = wr_addr;
        ram_l5$write_data = wr_l;
        ram_l5$write_enable = wr_valid & (pos[(32'h0)+:(3)] == 32'h5);
        ram_r5$read_clock = clock;
        ram_r5$write_clock = clock;
        ram_r5$read_address = rd_addr;
        ram_r5$write_address = wr_addr;
        ram_r5$write_data = wr_r;
        ram_r5$write_enable = wr_valid & (pos[(32'h0)+:(3)] == 32'h5);
        ram_l6$read_clock = clock;
        ram_l6$write_clock = clock;
        ram_l6$read_address = rd_addr;
        ram_l6$write_address = wr_addr;
        ram_l6$write_data = wr_l;
        ram_l6$write_enable = wr_valid & (pos[(32'h0)+:(3)] == 32'h6);
        ram_r6$read_clock = clock;
        ram_r6$write_clock = clock;
        ram_r6$read_address = rd_addr;
        ram_r6$write_address = wr_addr;
        ram_r6$write_data = wr_r;
        ram_r6$write_enable = wr_valid & (pos[(32'h0)+:(3)] == 32'h6);
        ram_l7$read_clock = clock;
        ram_l7$write_clock = clock;
        ram_l7$read_address = rd_addr;
        ram_l7$write_address = wr_addr;
        ram_l7$write_data = wr_l;
        ram_l7$write_enable = wr_valid & (pos[(32'h0)+:(3)] == 32'h7);
        ram_r7$read_clock = clock;
        ram_r7$write_clock = clock;
        ram_r7$read_address = rd_addr;
        ram_r7$write_address = wr_addr;
        ram_r7$write_data = wr_r;
        ram_r7$write_enable = wr_valid & (pos[(32'h0)+:(3)] == 32'h7);
        dl = (((ram_l0$read_data) & 256'hffffffffffffffffffffffffffffffffffffffffffffffffffffffffffffffff) << 32'h0) | (((ram_l1$read_data) & 256'hffffffffffffffffffffffffffffffffffffffffffffffffffffffffffffffff) << 32'h20) | (((ram_l2$read_data) & 256'hffffffffffffffffffffffffffffffffffffffffffffffffffffffffffffffff) << 32'h40) | (((ram_l3$read_data) & 256'hffffffffffffffffffffffffffffffffffffffffffffffffffffffffffffffff) << 32'h60) | (((ram_l4$read_data) & 256'hffffffffffffffffffffffffffffffffffffffffffffffffffffffffffffffff) << 32'h80) | (((ram_l5$read_data) & 256'hffffffffffffffffffffffffffffffffffffffffffffffffffffffffffffffff) << 32'ha0) | (((ram_l6$read_data) & 256'hffffffffffffffffffffffffffffffffffffffffffffffffffffffffffffffff) << 32'hc0) | (((ram_l7$read_data) & 256'hffffffffffffffffffffffffffffffffffffffffffffffffffffffffffffffff) << 32'he0);
        dr = (((ram_r0$read_data) & 256'hffffffffffffffffffffffffffffffffffffffffffffffffffffffffffffffff) << 32'h0) | (((ram_r1$read_data) & 256'hffffffffffffffffffffffffffffffffffffffffffffffffffffffffffffffff) << 32'h20) | (((ram_r2$read_data) & 256'hffffffffffffffffffffffffffffffffffffffffffffffffffffffffffffffff) << 32'h40) | (((ram_r3$read_data) & 256'hffffffffffffffffffffffffffffffffffffffffffffffffffffffffffffffff) << 32'h60) | (((ram_r4$read_data) & 256'hffffffffffffffffffffffffffffffffffffffffffffffffffffffffffffffff) << 32'h80) | (((ram_r5$read_data) & 256'hffffffffffffffffffffffffffffffffffffffffffffffffffffffffffffffff) << 32'ha0) | (((ram_r6$read_data) & 256'hffffffffffffffffffffffffffffffffffffffffffffffffffffffffffffffff) << 32'hc0) | (((ram_r7$read_data) & 256'hffffffffffffffffffffffffffffffffffffffffffffffffffffffffffffffff) << 32'he0);
    end
    
endmodule // top


module top$ram_l0(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [2:0] read_address;
    input wire  read_clock;
    output reg  [31:0] read_data;
    input wire  [2:0] write_address;
    input wire  write_clock;
    input wire  [31:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    reg[31:0] mem[7:0];
    
    
    
    always @(posedge read_clock) begin
       read_data <= mem[read_address];
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address] <= write_data;
       end
    end
                
endmodule // top$ram_l0
