// Testbench of an exported collision chip (rtl/chip_*.v, module `top`; parameter MW its
// memory word bits: 554 for chip_e8m15_k6, 2048 for chip_b32_k24): the host and the memory
// of src/harness/chip_io/mod.rs, clock for clock. It writes the registers from
// +host=<file> (one `{addr[10], data[32]}` per line), pulses `start`, serves memory
// requests from +mem=<file> ($readmemh, one MW-bit word per line) with the memory model
// (+word_bits=W the bits a word moves on the bus, default MW: the layout's word, which a
// port of records also carries in the `words` layout; +latency=L: a request accepted at
// edge t is answered in the cycle ending with edge t+L+B-1, B = ceil(W / +bus_bits)
// clocks on the bus, 1 without +bus_bits; +interval=I:
// the next request is accepted max(I, B) edges later at the earliest; or, with +ddr,
// the DDR SDRAM model of cycle::memory in the chip's clocks (chip::memory::DdrClocks):
// +banks +page_bytes +bus_bits +burst (beats a burst) +burst_clocks (clocks a burst holds
// the bus) +hit +miss, a request accepted in any cycle; docs/explanation/architecture.md), reads results
// with res_ready high in the cycles that are multiples of +reader=P (default 1: every
// cycle; cycle::drive::Reader), and prints the trace of cycle::drive::ChipTrace::text:
//   result <cycle> <A's triangle> <B's triangle> <uncertain>
//   done <cycles> overflow <0|1> max_depth <n> dop_tests <n> tri_tests <n> node_fetches <n> tri_fetches <n>
// Cycle 1 is the one after the edge that took `start`. +max_cycles=N (default 100000)
// bounds the query (`timeout` is printed instead of `done`). +ports also prints the output
// ports (and the memory handshake) of every cycle whose values differ from the last line's:
//   ports <cycle> busy done overflow max_depth req_valid req_ready req_addr resp_valid
//         res_valid res_uncertain res_a res_b dop_tests tri_tests node_fetches tri_fetches
// (src/harness/verilator.rs compares them with the cycle model's, clock by clock).
// +requests also prints each memory request the testbench accepts:
//   request <cycle> <word address>
// (scripts/run-chip.sh compares them with the cycle model's). It runs under both Icarus
// and Verilator.
// The same driver in Rust: src/cycle/drive.rs (run_query).
`timescale 1ns / 1ps
module tb;
  parameter MW = 578;
  localparam DEPTH = 1 << 16;
`ifdef VERILATOR
  reg clock = 1;  // falls at time 1, below
`else
  reg clock = 0;
`endif
  reg host_we = 0;
  reg [9:0] host_addr = 0;
  reg [31:0] host_data = 0;
  reg start = 0;
  wire busy, done, overflow;
  wire [10:0] max_depth;
  wire [31:0] dop_tests, tri_tests, node_fetches, tri_fetches;
  wire mem_req_valid;
  wire [23:0] mem_req_addr;
  reg mem_req_ready = 0;
  reg mem_resp_valid = 0;
  reg [MW-1:0] mem_resp_data = 0;
  wire res_valid, res_uncertain;
  wire [31:0] res_tag;
  reg res_ready = 1;

  top dut(.clock(clock), .host_we(host_we), .host_addr(host_addr), .host_data(host_data), .start(start),
          .busy(busy), .done(done), .overflow(overflow), .max_depth(max_depth), .dop_tests(dop_tests),
          .tri_tests(tri_tests), .node_fetches(node_fetches), .tri_fetches(tri_fetches),
          .mem_req_valid(mem_req_valid), .mem_req_addr(mem_req_addr), .mem_req_ready(mem_req_ready),
          .mem_resp_valid(mem_resp_valid), .mem_resp_data(mem_resp_data),
          .res_valid(res_valid), .res_tag(res_tag), .res_uncertain(res_uncertain), .res_ready(res_ready));

  reg [MW-1:0] mem [0:DEPTH-1];
  reg [41:0] host [0:1023];
  // requests accepted and not yet answered: due cycle and address, in order
  integer due [0:15];
  integer qaddr [0:15];
  integer qh, qt, next_accept, cyc, i, latency, interval, reader, max_cycles;
  // DDR SDRAM: per bank the open row (-1: none) and the cycle it is free; the data bus
  integer wbits, wb;  // bits and bytes per word: word address a starts at byte a * wb
  integer ddr, banks, page_bytes, bus_bits, burst, burst_clocks, hit, miss, cost, bursts, page, bank, row, t0, t1, bus_free, beats;
  integer open_row [0:63];  // cycle::memory::Ddr::MAX_BANKS
  integer bank_ready [0:63];  // the bank's next read of its open row
  integer bank_idle [0:63];   // the end of the bank's last transfer
  reg [1023:0] mem_file, host_file;
  reg ports, printed, requests;
  reg [202:0] port_line, last_line;

  task edge_;  // one rising edge, inputs set before it, outputs settled after it
    begin
      #5 clock = 1;
      #5 clock = 0;
    end
  endtask

  initial begin
`ifdef VERILATOR
    // A falling edge before the first rising one: Verilator 5.006 applies a hierarchical
    // block's initial values when it first evaluates the block, which the edge makes it do;
    // without it, with +verilator+rand+reset+2 the blocks' outputs are random at the first
    // rising edge and the chip takes them in.
    #1 clock = 0;
`endif
    if (!$value$plusargs("mem=%s", mem_file) || !$value$plusargs("host=%s", host_file)) begin
      $display("chip_tb: need +mem=<file> +host=<file>");
      $finish;
    end
    if (!$value$plusargs("latency=%d", latency)) latency = 1;
    if (!$value$plusargs("interval=%d", interval)) interval = 1;
    if (!$value$plusargs("reader=%d", reader)) reader = 1;
    if (!$value$plusargs("word_bits=%d", wbits)) wbits = MW;
    wb = (wbits + 7) / 8;
    ddr = $test$plusargs("ddr");
    if (ddr) begin
      if (!$value$plusargs("banks=%d", banks) || !$value$plusargs("page_bytes=%d", page_bytes)
          || !$value$plusargs("bus_bits=%d", bus_bits) || !$value$plusargs("burst=%d", burst)
          || !$value$plusargs("burst_clocks=%d", burst_clocks)
          || !$value$plusargs("hit=%d", hit) || !$value$plusargs("miss=%d", miss) || banks > 64) begin
        $display("chip_tb: +ddr needs +banks (at most 64) +page_bytes +bus_bits +burst +burst_clocks +hit +miss");
        $finish;
      end
      bursts = (wbits + bus_bits * burst - 1) / (bus_bits * burst);
      for (i = 0; i < 64; i = i + 1) begin
        open_row[i] = -1;
        bank_ready[i] = 0;
        bank_idle[i] = 0;
      end
      bus_free = 0;
      beats = 1;
    end else begin
      // ideal: a word moves in ceil(W / bus_bits) clocks on a +bus_bits bus, else in one
      if (!$value$plusargs("bus_bits=%d", bus_bits)) bus_bits = 0;
      beats = bus_bits > 0 ? (wbits + bus_bits - 1) / bus_bits : 1;
    end
    if (!$value$plusargs("max_cycles=%d", max_cycles)) max_cycles = 100000;
    ports = $test$plusargs("ports");
    requests = $test$plusargs("requests");
    printed = 0;
    for (i = 0; i < 1024; i = i + 1) host[i] = {42{1'b1}};
    $readmemh(mem_file, mem);
    $readmemh(host_file, host);
    for (i = 0; host[i][41:32] != 10'h3ff; i = i + 1) begin
      host_we = 1;
      host_addr = host[i][41:32];
      host_data = host[i][31:0];
      edge_;
    end
    host_we = 0;
    start = 1;
    edge_;
    start = 0;
    qh = 0;
    qt = 0;
    next_accept = 0;
    for (cyc = 1; cyc <= max_cycles && !done; cyc = cyc + 1) begin
      mem_req_ready = cyc >= next_accept;
      mem_resp_valid = 0;
      if (qh != qt && due[qh % 16] <= cyc) begin
        mem_resp_valid = 1;
        mem_resp_data = mem[qaddr[qh % 16]];
        qh = qh + 1;
      end
      // the chip's request and result outputs depend on its registers only
      if (mem_req_valid && mem_req_ready) begin
        if (ddr) begin
          page = mem_req_addr * wb / page_bytes;
          bank = page % banks;
          row = page / banks;
          cost = open_row[bank] == row ? hit : miss;
          t0 = open_row[bank] == row ? bank_ready[bank] : bank_idle[bank];
          if (cyc > t0) t0 = cyc;
          t1 = t0 + cost + (bursts - 1) * burst_clocks;
          if (bus_free + bursts * burst_clocks > t1) t1 = bus_free + bursts * burst_clocks;
          open_row[bank] = row;
          bank_ready[bank] = t0 + cost - hit + bursts * burst_clocks;
          bank_idle[bank] = t1;
          bus_free = t1;
          due[qt % 16] = t1;
          next_accept = cyc + 1;
        end else begin
          due[qt % 16] = cyc + latency + beats - 1;
          next_accept = cyc + (interval > beats ? interval : beats);
        end
        qaddr[qt % 16] = mem_req_addr;
        qt = qt + 1;
        if (requests) $display("request %0d %0d", cyc, mem_req_addr);
      end
      res_ready = cyc % reader == 0;
      port_line = {busy, done, overflow, max_depth, mem_req_valid, mem_req_ready, mem_req_addr, mem_resp_valid,
                   res_valid, res_uncertain, res_tag, dop_tests, tri_tests, node_fetches, tri_fetches};
      if (ports && (!printed || port_line != last_line))
        $display("ports %0d %0d %0d %0d %0d %0d %0d %0d %0d %0d %0d %0d %0d %0d %0d %0d %0d", cyc, busy, done, overflow,
                 max_depth, mem_req_valid, mem_req_ready, mem_req_addr, mem_resp_valid, res_valid, res_uncertain,
                 res_tag[15:0], res_tag[31:16], dop_tests, tri_tests, node_fetches, tri_fetches);
      printed = 1;
      last_line = port_line;
      if (res_valid && res_ready) $display("result %0d %0d %0d %0d", cyc, res_tag[15:0], res_tag[31:16], res_uncertain);
      edge_;
    end
    if (done)
      $display("done %0d overflow %0d max_depth %0d dop_tests %0d tri_tests %0d node_fetches %0d tri_fetches %0d",
               cyc - 1, overflow, max_depth, dop_tests, tri_tests, node_fetches, tri_fetches);
    else
      $display("timeout after %0d cycles", max_cycles);
    $finish;
  end
endmodule
