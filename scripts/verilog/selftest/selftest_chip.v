// A stand-in chip for scripts/selftest.sh: the exported chips' ports (module `top`, a 32-bit
// memory word), hand-written. After `start` it asks for memory word 5 (cycle 1), takes the
// word, offers one result (A's triangle 1, B's triangle 2, sure) until the host reads it and
// is done the cycle after, having counted one DOP test and one node fetch:
//   request 1 5
//   result 3 1 2 0
//   done 3 overflow 0 max_depth 1 dop_tests 1 tri_tests 0 node_fetches 1 tri_fetches 0
// under chip_tb.v with +latency=1 +interval=1 +reader=1. Its flaw on purpose: `overflow` is
// read from a register file the host writes only at address 0, so entry 3 is never
// written: zero in a two-state simulator that zeroes everything (Verilator by default),
// x under Icarus, random under Verilator with +verilator+rand+reset+2.
module top(clock,host_we,host_addr,host_data,start,busy,done,overflow,max_depth,dop_tests,tri_tests,node_fetches,tri_fetches,mem_req_valid,mem_req_addr,mem_req_ready,mem_resp_valid,mem_resp_data,res_valid,res_tag,res_uncertain,res_ready);
    input wire  clock;
    input wire  host_we;
    input wire  [9:0] host_addr;
    input wire  [31:0] host_data;
    input wire  start;
    output wire  busy;
    output wire  done;
    output wire  overflow;
    output wire  [10:0] max_depth;
    output wire  [31:0] dop_tests;
    output wire  [31:0] tri_tests;
    output wire  [31:0] node_fetches;
    output wire  [31:0] tri_fetches;
    output wire  mem_req_valid;
    output wire  [23:0] mem_req_addr;
    input wire  mem_req_ready;
    input wire  mem_resp_valid;
    input wire  [31:0] mem_resp_data;
    output wire  res_valid;
    output wire  [31:0] res_tag;
    output wire  res_uncertain;
    input wire  res_ready;

    localparam IDLE = 3'd0, ASK = 3'd1, WAIT = 3'd2, GIVE = 3'd3, DONE = 3'd4;
    reg [2:0] state = IDLE;
    reg [31:0] fetched = 32'h0;
    reg [31:0] regs [0:3];
    always @(posedge clock) begin
        if (host_we) regs[host_addr[1:0]] <= host_data;
        case (state)
            IDLE: if (start) state <= ASK;
            ASK: if (mem_req_ready) state <= WAIT;
            WAIT: if (mem_resp_valid) begin state <= GIVE; fetched <= 32'h1; end
            GIVE: if (res_ready) state <= DONE;
            default: state <= state;
        endcase
    end
    assign busy = state != IDLE && state != DONE;
    assign done = state == DONE;
    assign overflow = |regs[3];
    assign max_depth = 11'd1;
    assign dop_tests = fetched;
    assign tri_tests = 32'h0;
    assign node_fetches = fetched;
    assign tri_fetches = 32'h0;
    assign mem_req_valid = state == ASK;
    assign mem_req_addr = 24'd5;
    assign res_valid = state == GIVE;
    assign res_tag = {16'd2, 16'd1};
    assign res_uncertain = 1'b0;
endmodule
