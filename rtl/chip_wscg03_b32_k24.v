

module top(clock,host_we,host_addr,host_data,start,busy,done,overflow,max_depth,dop_tests,tri_tests,node_fetches,tri_fetches,mem_req_valid,mem_req_addr,mem_req_ready,mem_resp_valid,mem_resp_data,res_valid,res_tag,res_uncertain,res_ready);
    
    // Module arguments
    input wire  clock;
    input wire  host_we;
    input wire  [9:0] host_addr;
    input wire  [31:0] host_data;
    input wire  start;
    output reg  busy;
    output reg  done;
    output reg  overflow;
    output reg  [4:0] max_depth;
    output reg  [31:0] dop_tests;
    output reg  [31:0] tri_tests;
    output reg  [31:0] node_fetches;
    output reg  [31:0] tri_fetches;
    output reg  mem_req_valid;
    output reg  [23:0] mem_req_addr;
    input wire  mem_req_ready;
    input wire  mem_resp_valid;
    input wire  [2047:0] mem_resp_data;
    output reg  res_valid;
    output reg  [31:0] res_tag;
    output reg  res_uncertain;
    input wire  res_ready;
    
    // Stub signals
    reg  core$clock;
    reg  core$host_we;
    reg  [9:0] core$host_addr;
    reg  [31:0] core$host_data;
    reg  core$start;
    reg  core$mem_req_ready;
    reg  core$mem_resp_valid;
    reg  [2047:0] core$mem_resp_data;
    reg  core$tri_ready;
    reg  core$tri_sure;
    reg  core$tri_idle;
    wire  core$busy;
    wire  core$done;
    wire  core$overflow;
    wire  [4:0] core$max_depth;
    wire  [31:0] core$dop_tests;
    wire  [31:0] core$tri_tests;
    wire  [31:0] core$node_fetches;
    wire  [31:0] core$tri_fetches;
    wire  core$mem_req_valid;
    wire  [23:0] core$mem_req_addr;
    wire  core$pair_valid;
    wire  [31:0] core$pair_tag;
    wire  [737:0] core$a_word;
    wire  [737:0] core$b_word;
    reg  tri_unit$clock;
    reg  tri_unit$load_en;
    reg  [4:0] tri_unit$load_addr;
    reg  [31:0] tri_unit$load_data;
    reg  [31:0] tri_unit$a_m_0$0;
    reg  [31:0] tri_unit$a_m_0$1;
    reg  [31:0] tri_unit$a_m_0$2;
    reg  [31:0] tri_unit$a_m_0$3;
    reg  [31:0] tri_unit$a_m_1$0;
    reg  [31:0] tri_unit$a_m_1$1;
    reg  [31:0] tri_unit$a_m_1$2;
    reg  [31:0] tri_unit$a_m_1$3;
    reg  [31:0] tri_unit$a_m_2$0;
    reg  [31:0] tri_unit$a_m_2$1;
    reg  [31:0] tri_unit$a_m_2$2;
    reg  [31:0] tri_unit$a_m_2$3;
    reg  [31:0] tri_unit$a_alpha_m;
    reg  [31:0] tri_unit$a_alpha_f;
    reg  [31:0] tri_unit$a_v_x$0;
    reg  [31:0] tri_unit$a_v_x$1;
    reg  [31:0] tri_unit$a_v_x$2;
    reg  [31:0] tri_unit$a_v_y$0;
    reg  [31:0] tri_unit$a_v_y$1;
    reg  [31:0] tri_unit$a_v_y$2;
    reg  [31:0] tri_unit$a_v_z$0;
    reg  [31:0] tri_unit$a_v_z$1;
    reg  [31:0] tri_unit$a_v_z$2;
    reg  tri_unit$a_v_exact;
    reg  tri_unit$a_degenerate;
    reg  [31:0] tri_unit$b_m_0$0;
    reg  [31:0] tri_unit$b_m_0$1;
    reg  [31:0] tri_unit$b_m_0$2;
    reg  [31:0] tri_unit$b_m_0$3;
    reg  [31:0] tri_unit$b_m_1$0;
    reg  [31:0] tri_unit$b_m_1$1;
    reg  [31:0] tri_unit$b_m_1$2;
    reg  [31:0] tri_unit$b_m_1$3;
    reg  [31:0] tri_unit$b_m_2$0;
    reg  [31:0] tri_unit$b_m_2$1;
    reg  [31:0] tri_unit$b_m_2$2;
    reg  [31:0] tri_unit$b_m_2$3;
    reg  [31:0] tri_unit$b_alpha_m;
    reg  [31:0] tri_unit$b_alpha_f;
    reg  [31:0] tri_unit$b_v_x$0;
    reg  [31:0] tri_unit$b_v_x$1;
    reg  [31:0] tri_unit$b_v_x$2;
    reg  [31:0] tri_unit$b_v_y$0;
    reg  [31:0] tri_unit$b_v_y$1;
    reg  [31:0] tri_unit$b_v_y$2;
    reg  [31:0] tri_unit$b_v_z$0;
    reg  [31:0] tri_unit$b_v_z$1;
    reg  [31:0] tri_unit$b_v_z$2;
    reg  tri_unit$b_v_exact;
    reg  tri_unit$b_degenerate;
    reg  [31:0] tri_unit$tag;
    reg  tri_unit$in_valid;
    wire  tri_unit$in_ready;
    wire  [31:0] tri_unit$out_tag;
    wire  tri_unit$out_hit;
    wire  tri_unit$out_uncertain;
    wire  tri_unit$out_valid;
    reg  tri_unit$out_ready;
    reg  result$clock;
    reg  result$take;
    reg  result$out_valid;
    reg  result$out_hit;
    reg  result$out_uncertain;
    reg  [31:0] result$out_tag;
    reg  result$res_ready;
    wire  result$out_ready;
    wire  result$res_valid;
    wire  [31:0] result$res_tag;
    wire  result$res_uncertain;
    wire  result$give;
    wire  result$sure_hit;
    wire  [8:0] result$open;
    
    // Sub module instances
    top$core core(
        .clock(core$clock),
        .host_we(core$host_we),
        .host_addr(core$host_addr),
        .host_data(core$host_data),
        .start(core$start),
        .mem_req_ready(core$mem_req_ready),
        .mem_resp_valid(core$mem_resp_valid),
        .mem_resp_data(core$mem_resp_data),
        .tri_ready(core$tri_ready),
        .tri_sure(core$tri_sure),
        .tri_idle(core$tri_idle),
        .busy(core$busy),
        .done(core$done),
        .overflow(core$overflow),
        .max_depth(core$max_depth),
        .dop_tests(core$dop_tests),
        .tri_tests(core$tri_tests),
        .node_fetches(core$node_fetches),
        .tri_fetches(core$tri_fetches),
        .mem_req_valid(core$mem_req_valid),
        .mem_req_addr(core$mem_req_addr),
        .pair_valid(core$pair_valid),
        .pair_tag(core$pair_tag),
        .a_word(core$a_word),
        .b_word(core$b_word)
    );
    top$tri_unit tri_unit(
        .clock(tri_unit$clock),
        .load_en(tri_unit$load_en),
        .load_addr(tri_unit$load_addr),
        .load_data(tri_unit$load_data),
        .a_m_0$0(tri_unit$a_m_0$0),
        .a_m_0$1(tri_unit$a_m_0$1),
        .a_m_0$2(tri_unit$a_m_0$2),
        .a_m_0$3(tri_unit$a_m_0$3),
        .a_m_1$0(tri_unit$a_m_1$0),
        .a_m_1$1(tri_unit$a_m_1$1),
        .a_m_1$2(tri_unit$a_m_1$2),
        .a_m_1$3(tri_unit$a_m_1$3),
        .a_m_2$0(tri_unit$a_m_2$0),
        .a_m_2$1(tri_unit$a_m_2$1),
        .a_m_2$2(tri_unit$a_m_2$2),
        .a_m_2$3(tri_unit$a_m_2$3),
        .a_alpha_m(tri_unit$a_alpha_m),
        .a_alpha_f(tri_unit$a_alpha_f),
        .a_v_x$0(tri_unit$a_v_x$0),
        .a_v_x$1(tri_unit$a_v_x$1),
        .a_v_x$2(tri_unit$a_v_x$2),
        .a_v_y$0(tri_unit$a_v_y$0),
        .a_v_y$1(tri_unit$a_v_y$1),
        .a_v_y$2(tri_unit$a_v_y$2),
        .a_v_z$0(tri_unit$a_v_z$0),
        .a_v_z$1(tri_unit$a_v_z$1),
        .a_v_z$2(tri_unit$a_v_z$2),
        .a_v_exact(tri_unit$a_v_exact),
        .a_degenerate(tri_unit$a_degenerate),
        .b_m_0$0(tri_unit$b_m_0$0),
        .b_m_0$1(tri_unit$b_m_0$1),
        .b_m_0$2(tri_unit$b_m_0$2),
        .b_m_0$3(tri_unit$b_m_0$3),
        .b_m_1$0(tri_unit$b_m_1$0),
        .b_m_1$1(tri_unit$b_m_1$1),
        .b_m_1$2(tri_unit$b_m_1$2),
        .b_m_1$3(tri_unit$b_m_1$3),
        .b_m_2$0(tri_unit$b_m_2$0),
        .b_m_2$1(tri_unit$b_m_2$1),
        .b_m_2$2(tri_unit$b_m_2$2),
        .b_m_2$3(tri_unit$b_m_2$3),
        .b_alpha_m(tri_unit$b_alpha_m),
        .b_alpha_f(tri_unit$b_alpha_f),
        .b_v_x$0(tri_unit$b_v_x$0),
        .b_v_x$1(tri_unit$b_v_x$1),
        .b_v_x$2(tri_unit$b_v_x$2),
        .b_v_y$0(tri_unit$b_v_y$0),
        .b_v_y$1(tri_unit$b_v_y$1),
        .b_v_y$2(tri_unit$b_v_y$2),
        .b_v_z$0(tri_unit$b_v_z$0),
        .b_v_z$1(tri_unit$b_v_z$1),
        .b_v_z$2(tri_unit$b_v_z$2),
        .b_v_exact(tri_unit$b_v_exact),
        .b_degenerate(tri_unit$b_degenerate),
        .tag(tri_unit$tag),
        .in_valid(tri_unit$in_valid),
        .in_ready(tri_unit$in_ready),
        .out_tag(tri_unit$out_tag),
        .out_hit(tri_unit$out_hit),
        .out_uncertain(tri_unit$out_uncertain),
        .out_valid(tri_unit$out_valid),
        .out_ready(tri_unit$out_ready)
    );
    top$result result(
        .clock(result$clock),
        .take(result$take),
        .out_valid(result$out_valid),
        .out_hit(result$out_hit),
        .out_uncertain(result$out_uncertain),
        .out_tag(result$out_tag),
        .res_ready(result$res_ready),
        .out_ready(result$out_ready),
        .res_valid(result$res_valid),
        .res_tag(result$res_tag),
        .res_uncertain(result$res_uncertain),
        .give(result$give),
        .sure_hit(result$sure_hit),
        .open(result$open)
    );
    
    // Update code
    always @(*) begin
        core$clock = clock;
        tri_unit$clock = clock;
        result$clock = clock;
        core$host_we = host_we;
        core$host_addr = host_addr;
        core$host_data = host_data;
        core$start = start;
        core$mem_req_ready = mem_req_ready;
        core$mem_resp_valid = mem_resp_valid;
        core$mem_resp_data = mem_resp_data;
        core$tri_ready = tri_unit$in_ready;
        core$tri_sure = result$sure_hit;
        core$tri_idle = result$open == 32'h0;
        tri_unit$load_en = host_we & (host_addr[(32'h5)+:(5)] == 32'h8);
        tri_unit$load_addr = host_addr[(32'h0)+:(5)];
        tri_unit$load_data = host_data;
        result$take = core$pair_valid & tri_unit$in_ready;
        result$out_valid = tri_unit$out_valid;
        result$out_hit = tri_unit$out_hit;
        result$out_uncertain = tri_unit$out_uncertain;
        result$out_tag = tri_unit$out_tag;
        result$res_ready = res_ready;
        tri_unit$out_ready = result$out_ready;
        busy = core$busy;
        done = core$done;
        overflow = core$overflow;
        max_depth = core$max_depth;
        dop_tests = core$dop_tests;
        tri_tests = core$tri_tests;
        node_fetches = core$node_fetches;
        tri_fetches = core$tri_fetches;
        mem_req_valid = core$mem_req_valid;
        mem_req_addr = core$mem_req_addr;
        res_valid = result$res_valid;
        res_tag = result$res_tag;
        res_uncertain = result$res_uncertain;
        tri_unit$a_v_x$0 = core$a_word[(32'h3 * 0 * 32'h20)+:(32)];
        tri_unit$a_v_y$0 = core$a_word[((32'h3 * 0 + 32'h1) * 32'h20)+:(32)];
        tri_unit$a_v_z$0 = core$a_word[((32'h3 * 0 + 32'h2) * 32'h20)+:(32)];
        tri_unit$b_v_x$0 = core$b_word[(32'h3 * 0 * 32'h20)+:(32)];
        tri_unit$b_v_y$0 = core$b_word[((32'h3 * 0 + 32'h1) * 32'h20)+:(32)];
        tri_unit$b_v_z$0 = core$b_word[((32'h3 * 0 + 32'h2) * 32'h20)+:(32)];
        tri_unit$a_v_x$1 = core$a_word[(32'h3 * 1 * 32'h20)+:(32)];
        tri_unit$a_v_y$1 = core$a_word[((32'h3 * 1 + 32'h1) * 32'h20)+:(32)];
        tri_unit$a_v_z$1 = core$a_word[((32'h3 * 1 + 32'h2) * 32'h20)+:(32)];
        tri_unit$b_v_x$1 = core$b_word[(32'h3 * 1 * 32'h20)+:(32)];
        tri_unit$b_v_y$1 = core$b_word[((32'h3 * 1 + 32'h1) * 32'h20)+:(32)];
        tri_unit$b_v_z$1 = core$b_word[((32'h3 * 1 + 32'h2) * 32'h20)+:(32)];
        tri_unit$a_v_x$2 = core$a_word[(32'h3 * 2 * 32'h20)+:(32)];
        tri_unit$a_v_y$2 = core$a_word[((32'h3 * 2 + 32'h1) * 32'h20)+:(32)];
        tri_unit$a_v_z$2 = core$a_word[((32'h3 * 2 + 32'h2) * 32'h20)+:(32)];
        tri_unit$b_v_x$2 = core$b_word[(32'h3 * 2 * 32'h20)+:(32)];
        tri_unit$b_v_y$2 = core$b_word[((32'h3 * 2 + 32'h1) * 32'h20)+:(32)];
        tri_unit$b_v_z$2 = core$b_word[((32'h3 * 2 + 32'h2) * 32'h20)+:(32)];
        tri_unit$a_m_0$0 = core$a_word[((32'h9 + 0) * 32'h20)+:(32)];
        tri_unit$a_m_1$0 = core$a_word[((32'hd + 0) * 32'h20)+:(32)];
        tri_unit$a_m_2$0 = core$a_word[((32'h11 + 0) * 32'h20)+:(32)];
        tri_unit$b_m_0$0 = core$b_word[((32'h9 + 0) * 32'h20)+:(32)];
        tri_unit$b_m_1$0 = core$b_word[((32'hd + 0) * 32'h20)+:(32)];
        tri_unit$b_m_2$0 = core$b_word[((32'h11 + 0) * 32'h20)+:(32)];
        tri_unit$a_m_0$1 = core$a_word[((32'h9 + 1) * 32'h20)+:(32)];
        tri_unit$a_m_1$1 = core$a_word[((32'hd + 1) * 32'h20)+:(32)];
        tri_unit$a_m_2$1 = core$a_word[((32'h11 + 1) * 32'h20)+:(32)];
        tri_unit$b_m_0$1 = core$b_word[((32'h9 + 1) * 32'h20)+:(32)];
        tri_unit$b_m_1$1 = core$b_word[((32'hd + 1) * 32'h20)+:(32)];
        tri_unit$b_m_2$1 = core$b_word[((32'h11 + 1) * 32'h20)+:(32)];
        tri_unit$a_m_0$2 = core$a_word[((32'h9 + 2) * 32'h20)+:(32)];
        tri_unit$a_m_1$2 = core$a_word[((32'hd + 2) * 32'h20)+:(32)];
        tri_unit$a_m_2$2 = core$a_word[((32'h11 + 2) * 32'h20)+:(32)];
        tri_unit$b_m_0$2 = core$b_word[((32'h9 + 2) * 32'h20)+:(32)];
        tri_unit$b_m_1$2 = core$b_word[((32'hd + 2) * 32'h20)+:(32)];
        tri_unit$b_m_2$2 = core$b_word[((32'h11 + 2) * 32'h20)+:(32)];
        tri_unit$a_m_0$3 = core$a_word[((32'h9 + 3) * 32'h20)+:(32)];
        tri_unit$a_m_1$3 = core$a_word[((32'hd + 3) * 32'h20)+:(32)];
        tri_unit$a_m_2$3 = core$a_word[((32'h11 + 3) * 32'h20)+:(32)];
        tri_unit$b_m_0$3 = core$b_word[((32'h9 + 3) * 32'h20)+:(32)];
        tri_unit$b_m_1$3 = core$b_word[((32'hd + 3) * 32'h20)+:(32)];
        tri_unit$b_m_2$3 = core$b_word[((32'h11 + 3) * 32'h20)+:(32)];
        tri_unit$a_alpha_m = core$a_word[(32'h15 * 32'h20)+:(32)];
        tri_unit$a_alpha_f = core$a_word[(32'h16 * 32'h20)+:(32)];
        tri_unit$a_v_exact = core$a_word[32'h17 * 32'h20];
        tri_unit$a_degenerate = core$a_word[32'h17 * 32'h20 + 32'h1];
        tri_unit$b_alpha_m = core$b_word[(32'h15 * 32'h20)+:(32)];
        tri_unit$b_alpha_f = core$b_word[(32'h16 * 32'h20)+:(32)];
        tri_unit$b_v_exact = core$b_word[32'h17 * 32'h20];
        tri_unit$b_degenerate = core$b_word[32'h17 * 32'h20 + 32'h1];
        tri_unit$tag = core$pair_tag;
        tri_unit$in_valid = core$pair_valid;
    end
    
endmodule // top


module top$core(clock,host_we,host_addr,host_data,start,mem_req_ready,mem_resp_valid,mem_resp_data,tri_ready,tri_sure,tri_idle,busy,done,overflow,max_depth,dop_tests,tri_tests,node_fetches,tri_fetches,mem_req_valid,mem_req_addr,pair_valid,pair_tag,a_word,b_word);
    
    // Module arguments
    input wire  clock;
    input wire  host_we;
    input wire  [9:0] host_addr;
    input wire  [31:0] host_data;
    input wire  start;
    input wire  mem_req_ready;
    input wire  mem_resp_valid;
    input wire  [2047:0] mem_resp_data;
    input wire  tri_ready;
    input wire  tri_sure;
    input wire  tri_idle;
    output reg  busy;
    output reg  done;
    output reg  overflow;
    output reg  [4:0] max_depth;
    output reg  [31:0] dop_tests;
    output reg  [31:0] tri_tests;
    output reg  [31:0] node_fetches;
    output reg  [31:0] tri_fetches;
    output reg  mem_req_valid;
    output reg  [23:0] mem_req_addr;
    output reg  pair_valid;
    output reg  [31:0] pair_tag;
    output reg  [737:0] a_word;
    output reg  [737:0] b_word;
    
    // Constant declarations
    localparam  r_mode = 10'b100100000;
    localparam  r_base_na = 10'b100100010;
    localparam  r_base_nb = 10'b100100011;
    localparam  r_base_ta = 10'b100100100;
    localparam  r_base_tb = 10'b100100101;
    localparam  r_port = 10'b100100110;
    localparam  r_tri_cache = 10'b100100111;
    
    // Stub signals
    reg  lists$clock;
    reg  lists$clear;
    reg  lists$append;
    reg  lists$wr_side;
    reg  [15:0] lists$wr_ptr;
    reg  lists$read;
    reg  lists$next_list;
    wire  [4:0] lists$level;
    wire  lists$branch;
    wire  [15:0] lists$remaining;
    wire  lists$busy;
    wire  lists$done;
    wire  lists$rd_valid;
    wire  [15:0] lists$rd_ptr;
    wire  lists$overflow;
    reg  seq$clock;
    reg  seq$clear;
    reg  seq$halt;
    reg  [4:0] seq$level;
    reg  seq$branch;
    reg  [15:0] seq$remaining;
    reg  seq$ls_busy;
    reg  seq$ls_done;
    reg  seq$rd_valid;
    reg  [15:0] seq$rd_ptr;
    reg  seq$flags_valid;
    reg  [1:0] seq$overlap;
    reg  [3:0] seq$room;
    reg  seq$a_valid;
    reg  seq$al_valid;
    reg  [15:0] seq$al_id;
    reg  seq$al_leaf;
    reg  [31:0] seq$al_f0;
    reg  [31:0] seq$al_f1;
    reg  seq$ld_valid;
    reg  seq$ld_set;
    reg  seq$ld_pair;
    reg  [15:0] seq$ld_id;
    reg  seq$ld_leaf0;
    reg  seq$ld_leaf1;
    reg  [31:0] seq$ld_f00;
    reg  [31:0] seq$ld_f01;
    reg  [31:0] seq$ld_f10;
    reg  [31:0] seq$ld_f11;
    reg  seq$leaf_ready;
    wire  seq$append;
    wire  seq$wr_side;
    wire  [15:0] seq$wr_ptr;
    wire  seq$read;
    wire  seq$next_list;
    wire  seq$push;
    wire  seq$push_load;
    wire  seq$push_set;
    wire  seq$push_pair;
    wire  [15:0] seq$push_id;
    wire  seq$leaf_valid;
    wire  [15:0] seq$leaf_ida;
    wire  [15:0] seq$leaf_idb;
    wire  [31:0] seq$leaf_tag;
    wire  seq$leaf_side;
    wire  seq$idle;
    wire  [31:0] seq$lists;
    wire  [31:0] seq$dop_tests;
    reg  mc$clock;
    reg  mc$clear;
    reg  mc$halt;
    reg  mc$push;
    reg  mc$push_load;
    reg  mc$push_set;
    reg  mc$push_pair;
    reg  [15:0] mc$push_id;
    reg  mc$need_a;
    reg  mc$need_b;
    reg  [15:0] mc$ta_id;
    reg  [15:0] mc$tb_id;
    reg  [23:0] mc$base_na;
    reg  [23:0] mc$base_nb;
    reg  [23:0] mc$base_ta;
    reg  [23:0] mc$base_tb;
    reg  [3:0] mc$port_out;
    reg  mc$mem_req_ready;
    reg  mc$mem_resp_valid;
    reg  [2047:0] mc$mem_resp_data;
    reg  [1:0] mc$busy;
    wire  [3:0] mc$room;
    wire  mc$pending;
    wire  mc$mem_req_valid;
    wire  [23:0] mc$mem_req_addr;
    wire  mc$req_tri;
    wire  mc$fill_a;
    wire  mc$fill_b;
    wire  [15:0] mc$fill_id;
    wire  [737:0] mc$fill_word;
    wire  mc$t_valid;
    wire  mc$t_set;
    wire  mc$t_side;
    wire  [1:0] mc$t_entry;
    wire  mc$t_last;
    wire  [255:0] mc$t_data;
    wire  mc$a_valid;
    wire  mc$a_first;
    wire  mc$a_set;
    wire  [1:0] mc$a_entry;
    wire  [255:0] mc$e;
    wire  mc$al_valid;
    wire  [15:0] mc$al_id;
    wire  mc$al_leaf;
    wire  [31:0] mc$al_f0;
    wire  [31:0] mc$al_f1;
    wire  mc$ld_valid;
    wire  mc$ld_set;
    wire  mc$ld_pair;
    wire  [15:0] mc$ld_id;
    wire  mc$ld_leaf0;
    wire  mc$ld_leaf1;
    wire  [31:0] mc$ld_f00;
    wire  [31:0] mc$ld_f01;
    wire  [31:0] mc$ld_f10;
    wire  [31:0] mc$ld_f11;
    reg  dop$clock;
    reg  dop$load_en;
    reg  [7:0] dop$load_addr;
    reg  [31:0] dop$load_data;
    reg  dop$t_valid;
    reg  dop$t_set;
    reg  dop$t_side;
    reg  [1:0] dop$t_entry;
    reg  dop$t_last;
    reg  [255:0] dop$t_data;
    reg  dop$a_valid;
    reg  dop$a_first;
    reg  [7:0] dop$a_lanes;
    reg  dop$a_set;
    reg  [1:0] dop$a_entry;
    reg  [255:0] dop$e;
    wire  [1:0] dop$busy;
    wire  dop$overlap_l;
    wire  dop$overlap_r;
    wire  dop$flags_valid;
    reg  tin$clock;
    reg  tin$clear;
    reg  [6:0] tin$mask;
    reg  tin$halt;
    reg  tin$leaf_in;
    reg  [31:0] tin$leaf_ids;
    reg  [31:0] tin$leaf_tag;
    reg  tin$leaf_side;
    reg  tin$fill_a;
    reg  tin$fill_b;
    reg  [15:0] tin$fill_id;
    reg  [737:0] tin$fill_word;
    reg  tin$tri_ready;
    wire  tin$leaf_ready;
    wire  tin$need_a;
    wire  tin$need_b;
    wire  [15:0] tin$ta_id;
    wire  [15:0] tin$tb_id;
    wire  tin$pair_valid;
    wire  [31:0] tin$pair_tag;
    wire  [737:0] tin$a_word;
    wire  [737:0] tin$b_word;
    wire  tin$busy;
    reg  first$d;
    wire  first$q;
    reg  first$clock;
    reg  [23:0] base_na$d;
    wire  [23:0] base_na$q;
    reg  base_na$clock;
    reg  [23:0] base_nb$d;
    wire  [23:0] base_nb$q;
    reg  base_nb$clock;
    reg  [23:0] base_ta$d;
    wire  [23:0] base_ta$q;
    reg  base_ta$clock;
    reg  [23:0] base_tb$d;
    wire  [23:0] base_tb$q;
    reg  base_tb$clock;
    reg  [3:0] port_out$d;
    wire  [3:0] port_out$q;
    reg  port_out$clock;
    reg  [6:0] mask$d;
    wire  [6:0] mask$q;
    reg  mask$clock;
    reg  run$d;
    wire  run$q;
    reg  run$clock;
    reg  done_r$d;
    wire  done_r$q;
    reg  done_r$clock;
    reg  halted$d;
    wire  halted$q;
    reg  halted$clock;
    reg  [4:0] max_lvl$d;
    wire  [4:0] max_lvl$q;
    reg  max_lvl$clock;
    reg  [31:0] cnt_tri$d;
    wire  [31:0] cnt_tri$q;
    reg  cnt_tri$clock;
    reg  [31:0] cnt_nf$d;
    wire  [31:0] cnt_nf$q;
    reg  cnt_nf$clock;
    reg  [31:0] cnt_tf$d;
    wire  [31:0] cnt_tf$q;
    reg  cnt_tf$clock;
    
    // Local signals
    reg  c_clear;
    reg  c_halt;
    reg  c_finished;
    
    // Sub module instances
    top$core$lists lists(
        .clock(lists$clock),
        .clear(lists$clear),
        .append(lists$append),
        .wr_side(lists$wr_side),
        .wr_ptr(lists$wr_ptr),
        .read(lists$read),
        .next_list(lists$next_list),
        .level(lists$level),
        .branch(lists$branch),
        .remaining(lists$remaining),
        .busy(lists$busy),
        .done(lists$done),
        .rd_valid(lists$rd_valid),
        .rd_ptr(lists$rd_ptr),
        .overflow(lists$overflow)
    );
    top$core$seq seq(
        .clock(seq$clock),
        .clear(seq$clear),
        .halt(seq$halt),
        .level(seq$level),
        .branch(seq$branch),
        .remaining(seq$remaining),
        .ls_busy(seq$ls_busy),
        .ls_done(seq$ls_done),
        .rd_valid(seq$rd_valid),
        .rd_ptr(seq$rd_ptr),
        .flags_valid(seq$flags_valid),
        .overlap(seq$overlap),
        .room(seq$room),
        .a_valid(seq$a_valid),
        .al_valid(seq$al_valid),
        .al_id(seq$al_id),
        .al_leaf(seq$al_leaf),
        .al_f0(seq$al_f0),
        .al_f1(seq$al_f1),
        .ld_valid(seq$ld_valid),
        .ld_set(seq$ld_set),
        .ld_pair(seq$ld_pair),
        .ld_id(seq$ld_id),
        .ld_leaf0(seq$ld_leaf0),
        .ld_leaf1(seq$ld_leaf1),
        .ld_f00(seq$ld_f00),
        .ld_f01(seq$ld_f01),
        .ld_f10(seq$ld_f10),
        .ld_f11(seq$ld_f11),
        .leaf_ready(seq$leaf_ready),
        .append(seq$append),
        .wr_side(seq$wr_side),
        .wr_ptr(seq$wr_ptr),
        .read(seq$read),
        .next_list(seq$next_list),
        .push(seq$push),
        .push_load(seq$push_load),
        .push_set(seq$push_set),
        .push_pair(seq$push_pair),
        .push_id(seq$push_id),
        .leaf_valid(seq$leaf_valid),
        .leaf_ida(seq$leaf_ida),
        .leaf_idb(seq$leaf_idb),
        .leaf_tag(seq$leaf_tag),
        .leaf_side(seq$leaf_side),
        .idle(seq$idle),
        .lists(seq$lists),
        .dop_tests(seq$dop_tests)
    );
    top$core$mc mc(
        .clock(mc$clock),
        .clear(mc$clear),
        .halt(mc$halt),
        .push(mc$push),
        .push_load(mc$push_load),
        .push_set(mc$push_set),
        .push_pair(mc$push_pair),
        .push_id(mc$push_id),
        .need_a(mc$need_a),
        .need_b(mc$need_b),
        .ta_id(mc$ta_id),
        .tb_id(mc$tb_id),
        .base_na(mc$base_na),
        .base_nb(mc$base_nb),
        .base_ta(mc$base_ta),
        .base_tb(mc$base_tb),
        .port_out(mc$port_out),
        .mem_req_ready(mc$mem_req_ready),
        .mem_resp_valid(mc$mem_resp_valid),
        .mem_resp_data(mc$mem_resp_data),
        .busy(mc$busy),
        .room(mc$room),
        .pending(mc$pending),
        .mem_req_valid(mc$mem_req_valid),
        .mem_req_addr(mc$mem_req_addr),
        .req_tri(mc$req_tri),
        .fill_a(mc$fill_a),
        .fill_b(mc$fill_b),
        .fill_id(mc$fill_id),
        .fill_word(mc$fill_word),
        .t_valid(mc$t_valid),
        .t_set(mc$t_set),
        .t_side(mc$t_side),
        .t_entry(mc$t_entry),
        .t_last(mc$t_last),
        .t_data(mc$t_data),
        .a_valid(mc$a_valid),
        .a_first(mc$a_first),
        .a_set(mc$a_set),
        .a_entry(mc$a_entry),
        .e(mc$e),
        .al_valid(mc$al_valid),
        .al_id(mc$al_id),
        .al_leaf(mc$al_leaf),
        .al_f0(mc$al_f0),
        .al_f1(mc$al_f1),
        .ld_valid(mc$ld_valid),
        .ld_set(mc$ld_set),
        .ld_pair(mc$ld_pair),
        .ld_id(mc$ld_id),
        .ld_leaf0(mc$ld_leaf0),
        .ld_leaf1(mc$ld_leaf1),
        .ld_f00(mc$ld_f00),
        .ld_f01(mc$ld_f01),
        .ld_f10(mc$ld_f10),
        .ld_f11(mc$ld_f11)
    );
    top$core$dop dop(
        .clock(dop$clock),
        .load_en(dop$load_en),
        .load_addr(dop$load_addr),
        .load_data(dop$load_data),
        .t_valid(dop$t_valid),
        .t_set(dop$t_set),
        .t_side(dop$t_side),
        .t_entry(dop$t_entry),
        .t_last(dop$t_last),
        .t_data(dop$t_data),
        .a_valid(dop$a_valid),
        .a_first(dop$a_first),
        .a_lanes(dop$a_lanes),
        .a_set(dop$a_set),
        .a_entry(dop$a_entry),
        .e(dop$e),
        .busy(dop$busy),
        .overlap_l(dop$overlap_l),
        .overlap_r(dop$overlap_r),
        .flags_valid(dop$flags_valid)
    );
    top$core$tin tin(
        .clock(tin$clock),
        .clear(tin$clear),
        .mask(tin$mask),
        .halt(tin$halt),
        .leaf_in(tin$leaf_in),
        .leaf_ids(tin$leaf_ids),
        .leaf_tag(tin$leaf_tag),
        .leaf_side(tin$leaf_side),
        .fill_a(tin$fill_a),
        .fill_b(tin$fill_b),
        .fill_id(tin$fill_id),
        .fill_word(tin$fill_word),
        .tri_ready(tin$tri_ready),
        .leaf_ready(tin$leaf_ready),
        .need_a(tin$need_a),
        .need_b(tin$need_b),
        .ta_id(tin$ta_id),
        .tb_id(tin$tb_id),
        .pair_valid(tin$pair_valid),
        .pair_tag(tin$pair_tag),
        .a_word(tin$a_word),
        .b_word(tin$b_word),
        .busy(tin$busy)
    );
    top$core$done_r first(
        .d(first$d),
        .q(first$q),
        .clock(first$clock)
    );
    top$core$base_na base_na(
        .d(base_na$d),
        .q(base_na$q),
        .clock(base_na$clock)
    );
    top$core$base_na base_nb(
        .d(base_nb$d),
        .q(base_nb$q),
        .clock(base_nb$clock)
    );
    top$core$base_na base_ta(
        .d(base_ta$d),
        .q(base_ta$q),
        .clock(base_ta$clock)
    );
    top$core$base_na base_tb(
        .d(base_tb$d),
        .q(base_tb$q),
        .clock(base_tb$clock)
    );
    top$core$mc$ask_n port_out(
        .d(port_out$d),
        .q(port_out$q),
        .clock(port_out$clock)
    );
    top$core$dop$wr_tag$line$0 mask(
        .d(mask$d),
        .q(mask$q),
        .clock(mask$clock)
    );
    top$core$done_r run(
        .d(run$d),
        .q(run$q),
        .clock(run$clock)
    );
    top$core$done_r done_r(
        .d(done_r$d),
        .q(done_r$q),
        .clock(done_r$clock)
    );
    top$core$done_r halted(
        .d(halted$d),
        .q(halted$q),
        .clock(halted$clock)
    );
    top$core$dop$gen_cnt max_lvl(
        .d(max_lvl$d),
        .q(max_lvl$q),
        .clock(max_lvl$clock)
    );
    top$core$cnt_nf cnt_tri(
        .d(cnt_tri$d),
        .q(cnt_tri$q),
        .clock(cnt_tri$clock)
    );
    top$core$cnt_nf cnt_nf(
        .d(cnt_nf$d),
        .q(cnt_nf$q),
        .clock(cnt_nf$clock)
    );
    top$core$cnt_nf cnt_tf(
        .d(cnt_tf$d),
        .q(cnt_tf$q),
        .clock(cnt_tf$clock)
    );
    
    // Update code
    always @(*) begin
        first$clock = clock;
        base_na$clock = clock;
        base_nb$clock = clock;
        base_ta$clock = clock;
        base_tb$clock = clock;
        port_out$clock = clock;
        mask$clock = clock;
        first$d = first$q;
        base_na$d = base_na$q;
        base_nb$d = base_nb$q;
        base_ta$d = base_ta$q;
        base_tb$d = base_tb$q;
        port_out$d = port_out$q;
        mask$d = mask$q;
        run$clock = clock;
        done_r$clock = clock;
        halted$clock = clock;
        max_lvl$clock = clock;
        cnt_tri$clock = clock;
        cnt_nf$clock = clock;
        cnt_tf$clock = clock;
        run$d = run$q;
        done_r$d = done_r$q;
        halted$d = halted$q;
        max_lvl$d = max_lvl$q;
        cnt_tri$d = cnt_tri$q;
        cnt_nf$d = cnt_nf$q;
        cnt_tf$d = cnt_tf$q;
        lists$clock = clock;
        seq$clock = clock;
        mc$clock = clock;
        dop$clock = clock;
        tin$clock = clock;
        if (host_we) begin
            if (host_addr == r_mode) begin
                first$d = host_data[32'h1];
            end
            if (host_addr == r_base_na) begin
                base_na$d = host_data[(32'h0)+:(24)];
            end
            if (host_addr == r_base_nb) begin
                base_nb$d = host_data[(32'h0)+:(24)];
            end
            if (host_addr == r_base_ta) begin
                base_ta$d = host_data[(32'h0)+:(24)];
            end
            if (host_addr == r_base_tb) begin
                base_tb$d = host_data[(32'h0)+:(24)];
            end
            if (host_addr == r_port) begin
                port_out$d = host_data[(32'h4)+:(4)];
            end
            if (host_addr == r_tri_cache) begin
                mask$d = host_data[(32'h0)+:(7)];
            end
        end
        dop$load_en = host_we & (host_addr[(32'h8)+:(2)] == 32'h0);
        dop$load_addr = host_addr[(32'h0)+:(8)];
        dop$load_data = host_data;
        c_clear = start & ~run$q;
        c_halt = halted$q | (first$q & tri_sure);
        c_finished = ~tin$busy & tri_idle & ~mc$pending & (halted$q | (lists$done & seq$idle & (mc$room == 32'h8)));
        if (run$q) begin
            halted$d = c_halt;
        end
        if (run$q & c_finished) begin
            run$d = 1'b0;
            done_r$d = 1'b1;
        end
        if (c_clear) begin
            run$d = 1'b1;
            done_r$d = 1'b0;
            halted$d = 1'b0;
        end
        busy = run$q & ~c_finished;
        done = done_r$q | (run$q & c_finished);
        lists$clear = c_clear;
        lists$append = seq$append;
        lists$wr_side = seq$wr_side;
        lists$wr_ptr = seq$wr_ptr;
        lists$read = seq$read;
        lists$next_list = seq$next_list;
        seq$clear = c_clear;
        seq$halt = c_halt;
        seq$level = lists$level;
        seq$branch = lists$branch;
        seq$remaining = lists$remaining;
        seq$ls_busy = lists$busy;
        seq$ls_done = lists$done;
        seq$rd_valid = lists$rd_valid;
        seq$rd_ptr = lists$rd_ptr;
        seq$flags_valid = dop$flags_valid;
        seq$overlap = ((dop$overlap_l) & 2'h3) | (((dop$overlap_r) & 2'h3) << 32'h1);
        seq$room = mc$room;
        seq$a_valid = mc$a_valid;
        seq$al_valid = mc$al_valid;
        seq$al_id = mc$al_id;
        seq$al_leaf = mc$al_leaf;
        seq$al_f0 = mc$al_f0;
        seq$al_f1 = mc$al_f1;
        seq$ld_valid = mc$ld_valid;
        seq$ld_set = mc$ld_set;
        seq$ld_pair = mc$ld_pair;
        seq$ld_id = mc$ld_id;
        seq$ld_leaf0 = mc$ld_leaf0;
        seq$ld_leaf1 = mc$ld_leaf1;
        seq$ld_f00 = mc$ld_f00;
        seq$ld_f01 = mc$ld_f01;
        seq$ld_f10 = mc$ld_f10;
        seq$ld_f11 = mc$ld_f11;
        seq$leaf_ready = tin$leaf_ready;
        mc$clear = c_clear;
        mc$halt = c_halt;
        mc$push = seq$push;
        mc$push_load = seq$push_load;
        mc$push_set = seq$push_set;
        mc$push_pair = seq$push_pair;
        mc$push_id = seq$push_id;
        mc$need_a = tin$need_a;
        mc$need_b = tin$need_b;
        mc$ta_id = tin$ta_id;
        mc$tb_id = tin$tb_id;
        mc$base_na = base_na$q;
        mc$base_nb = base_nb$q;
        mc$base_ta = base_ta$q;
        mc$base_tb = base_tb$q;
        mc$port_out = port_out$q;
        mc$mem_req_ready = mem_req_ready;
        mc$mem_resp_valid = mem_resp_valid;
        mc$mem_resp_data = mem_resp_data;
        mc$busy = dop$busy;
        dop$t_valid = mc$t_valid;
        dop$t_set = ((mc$t_set) & 1'h1);
        dop$t_side = mc$t_side;
        dop$t_entry = mc$t_entry;
        dop$t_last = mc$t_last;
        dop$t_data = mc$t_data;
        dop$a_valid = mc$a_valid;
        dop$a_first = mc$a_first;
        dop$a_lanes = 32'hff;
        dop$a_set = ((mc$a_set) & 1'h1);
        dop$a_entry = mc$a_entry;
        dop$e = mc$e;
        tin$clear = c_clear;
        tin$mask = mask$q;
        tin$halt = c_halt;
        tin$leaf_in = seq$leaf_valid;
        tin$leaf_ids = ((seq$leaf_ida) & 32'hffffffff) | (((seq$leaf_idb) & 32'hffffffff) << 32'h10);
        tin$leaf_tag = seq$leaf_tag;
        tin$leaf_side = seq$leaf_side;
        tin$fill_a = mc$fill_a;
        tin$fill_b = mc$fill_b;
        tin$fill_id = mc$fill_id;
        tin$fill_word = mc$fill_word;
        tin$tri_ready = tri_ready;
        if (lists$level > max_lvl$q) begin
            max_lvl$d = lists$level;
        end
        if (tin$pair_valid & tri_ready) begin
            cnt_tri$d = cnt_tri$q + 32'h1;
        end
        if (mc$mem_req_valid & mem_req_ready & mc$req_tri) begin
            cnt_tf$d = cnt_tf$q + 32'h1;
        end
        if (mc$mem_req_valid & mem_req_ready & ~mc$req_tri) begin
            cnt_nf$d = cnt_nf$q + 32'h1;
        end
        if (c_clear) begin
            max_lvl$d = 32'h0;
            cnt_tri$d = 32'h0;
            cnt_nf$d = 32'h0;
            cnt_tf$d = 32'h0;
        end
        overflow = lists$overflow;
        max_depth = max_lvl$q;
        if (lists$level > max_lvl$q) begin
            max_depth = lists$level;
        end
        dop_tests = seq$dop_tests;
        tri_tests = cnt_tri$q;
        node_fetches = cnt_nf$q;
        tri_fetches = cnt_tf$q;
        mem_req_valid = mc$mem_req_valid & run$q;
        mem_req_addr = mc$mem_req_addr;
        pair_valid = tin$pair_valid;
        pair_tag = tin$pair_tag;
        a_word = tin$a_word;
        b_word = tin$b_word;
    end
    
endmodule // top$core


module top$core$base_na(d,q,clock);
    
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
          
endmodule // top$core$base_na


module top$core$cnt_nf(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$core$cnt_nf


module top$core$done_r(d,q,clock);
    
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
          
endmodule // top$core$done_r


module top$core$dop(clock,load_en,load_addr,load_data,t_valid,t_set,t_side,t_entry,t_last,t_data,a_valid,a_first,a_lanes,a_set,a_entry,e,busy,overlap_l,overlap_r,flags_valid);
    
    // Module arguments
    input wire  clock;
    input wire  load_en;
    input wire  [7:0] load_addr;
    input wire  [31:0] load_data;
    input wire  t_valid;
    input wire  t_set;
    input wire  t_side;
    input wire  [1:0] t_entry;
    input wire  t_last;
    input wire  [255:0] t_data;
    input wire  a_valid;
    input wire  a_first;
    input wire  [7:0] a_lanes;
    input wire  a_set;
    input wire  [1:0] a_entry;
    input wire  [255:0] e;
    output reg  [1:0] busy;
    output reg  overlap_l;
    output reg  overlap_r;
    output reg  flags_valid;
    
    // Constant declarations
    localparam  mmm_field$0 = 3'b0;
    localparam  mmm_field$1 = 3'b1;
    localparam  mmm_field$2 = 3'b10;
    localparam  mmm_field$3 = 3'b11;
    localparam  mmm_field$4 = 3'b100;
    localparam  entry_of$0 = 2'b0;
    localparam  entry_of$1 = 2'b0;
    localparam  entry_of$2 = 2'b0;
    localparam  entry_of$3 = 2'b0;
    localparam  entry_of$4 = 2'b0;
    localparam  entry_of$5 = 2'b0;
    localparam  entry_of$6 = 2'b0;
    localparam  entry_of$7 = 2'b0;
    localparam  entry_of$8 = 2'b1;
    localparam  entry_of$9 = 2'b1;
    localparam  entry_of$10 = 2'b1;
    localparam  entry_of$11 = 2'b1;
    localparam  entry_of$12 = 2'b1;
    localparam  entry_of$13 = 2'b1;
    localparam  entry_of$14 = 2'b1;
    localparam  entry_of$15 = 2'b1;
    localparam  entry_of$16 = 2'b10;
    localparam  entry_of$17 = 2'b10;
    localparam  entry_of$18 = 2'b10;
    localparam  entry_of$19 = 2'b10;
    localparam  entry_of$20 = 2'b10;
    localparam  entry_of$21 = 2'b10;
    localparam  entry_of$22 = 2'b10;
    localparam  entry_of$23 = 2'b10;
    localparam  last_row = 5'b10111;
    
    // Stub signals
    reg  [4:0] mmm$0$read_address;
    reg  mmm$0$read_clock;
    wire  [31:0] mmm$0$read_data;
    reg  [4:0] mmm$0$write_address;
    reg  mmm$0$write_clock;
    reg  [31:0] mmm$0$write_data;
    reg  mmm$0$write_enable;
    reg  [4:0] mmm$1$read_address;
    reg  mmm$1$read_clock;
    wire  [31:0] mmm$1$read_data;
    reg  [4:0] mmm$1$write_address;
    reg  mmm$1$write_clock;
    reg  [31:0] mmm$1$write_data;
    reg  mmm$1$write_enable;
    reg  [4:0] mmm$2$read_address;
    reg  mmm$2$read_clock;
    wire  [31:0] mmm$2$read_data;
    reg  [4:0] mmm$2$write_address;
    reg  mmm$2$write_clock;
    reg  [31:0] mmm$2$write_data;
    reg  mmm$2$write_enable;
    reg  [4:0] mmm$3$read_address;
    reg  mmm$3$read_clock;
    wire  [31:0] mmm$3$read_data;
    reg  [4:0] mmm$3$write_address;
    reg  mmm$3$write_clock;
    reg  [31:0] mmm$3$write_data;
    reg  mmm$3$write_enable;
    reg  [4:0] mmm$4$read_address;
    reg  mmm$4$read_clock;
    wire  [31:0] mmm$4$read_data;
    reg  [4:0] mmm$4$write_address;
    reg  mmm$4$write_clock;
    reg  [31:0] mmm$4$write_data;
    reg  mmm$4$write_enable;
    reg  [31:0] tin_l0$0$d;
    wire  [31:0] tin_l0$0$q;
    reg  tin_l0$0$clock;
    reg  [31:0] tin_l0$1$d;
    wire  [31:0] tin_l0$1$q;
    reg  tin_l0$1$clock;
    reg  [31:0] tin_l0$2$d;
    wire  [31:0] tin_l0$2$q;
    reg  tin_l0$2$clock;
    reg  [31:0] tin_l0$3$d;
    wire  [31:0] tin_l0$3$q;
    reg  tin_l0$3$clock;
    reg  [31:0] tin_l0$4$d;
    wire  [31:0] tin_l0$4$q;
    reg  tin_l0$4$clock;
    reg  [31:0] tin_l0$5$d;
    wire  [31:0] tin_l0$5$q;
    reg  tin_l0$5$clock;
    reg  [31:0] tin_l0$6$d;
    wire  [31:0] tin_l0$6$q;
    reg  tin_l0$6$clock;
    reg  [31:0] tin_l0$7$d;
    wire  [31:0] tin_l0$7$q;
    reg  tin_l0$7$clock;
    reg  [31:0] tin_l0$8$d;
    wire  [31:0] tin_l0$8$q;
    reg  tin_l0$8$clock;
    reg  [31:0] tin_l0$9$d;
    wire  [31:0] tin_l0$9$q;
    reg  tin_l0$9$clock;
    reg  [31:0] tin_l0$10$d;
    wire  [31:0] tin_l0$10$q;
    reg  tin_l0$10$clock;
    reg  [31:0] tin_l0$11$d;
    wire  [31:0] tin_l0$11$q;
    reg  tin_l0$11$clock;
    reg  [31:0] tin_l0$12$d;
    wire  [31:0] tin_l0$12$q;
    reg  tin_l0$12$clock;
    reg  [31:0] tin_l0$13$d;
    wire  [31:0] tin_l0$13$q;
    reg  tin_l0$13$clock;
    reg  [31:0] tin_l0$14$d;
    wire  [31:0] tin_l0$14$q;
    reg  tin_l0$14$clock;
    reg  [31:0] tin_l0$15$d;
    wire  [31:0] tin_l0$15$q;
    reg  tin_l0$15$clock;
    reg  [31:0] tin_l0$16$d;
    wire  [31:0] tin_l0$16$q;
    reg  tin_l0$16$clock;
    reg  [31:0] tin_l0$17$d;
    wire  [31:0] tin_l0$17$q;
    reg  tin_l0$17$clock;
    reg  [31:0] tin_l0$18$d;
    wire  [31:0] tin_l0$18$q;
    reg  tin_l0$18$clock;
    reg  [31:0] tin_l0$19$d;
    wire  [31:0] tin_l0$19$q;
    reg  tin_l0$19$clock;
    reg  [31:0] tin_l0$20$d;
    wire  [31:0] tin_l0$20$q;
    reg  tin_l0$20$clock;
    reg  [31:0] tin_l0$21$d;
    wire  [31:0] tin_l0$21$q;
    reg  tin_l0$21$clock;
    reg  [31:0] tin_l0$22$d;
    wire  [31:0] tin_l0$22$q;
    reg  tin_l0$22$clock;
    reg  [31:0] tin_l0$23$d;
    wire  [31:0] tin_l0$23$q;
    reg  tin_l0$23$clock;
    reg  [31:0] tin_r0$0$d;
    wire  [31:0] tin_r0$0$q;
    reg  tin_r0$0$clock;
    reg  [31:0] tin_r0$1$d;
    wire  [31:0] tin_r0$1$q;
    reg  tin_r0$1$clock;
    reg  [31:0] tin_r0$2$d;
    wire  [31:0] tin_r0$2$q;
    reg  tin_r0$2$clock;
    reg  [31:0] tin_r0$3$d;
    wire  [31:0] tin_r0$3$q;
    reg  tin_r0$3$clock;
    reg  [31:0] tin_r0$4$d;
    wire  [31:0] tin_r0$4$q;
    reg  tin_r0$4$clock;
    reg  [31:0] tin_r0$5$d;
    wire  [31:0] tin_r0$5$q;
    reg  tin_r0$5$clock;
    reg  [31:0] tin_r0$6$d;
    wire  [31:0] tin_r0$6$q;
    reg  tin_r0$6$clock;
    reg  [31:0] tin_r0$7$d;
    wire  [31:0] tin_r0$7$q;
    reg  tin_r0$7$clock;
    reg  [31:0] tin_r0$8$d;
    wire  [31:0] tin_r0$8$q;
    reg  tin_r0$8$clock;
    reg  [31:0] tin_r0$9$d;
    wire  [31:0] tin_r0$9$q;
    reg  tin_r0$9$clock;
    reg  [31:0] tin_r0$10$d;
    wire  [31:0] tin_r0$10$q;
    reg  tin_r0$10$clock;
    reg  [31:0] tin_r0$11$d;
    wire  [31:0] tin_r0$11$q;
    reg  tin_r0$11$clock;
    reg  [31:0] tin_r0$12$d;
    wire  [31:0] tin_r0$12$q;
    reg  tin_r0$12$clock;
    reg  [31:0] tin_r0$13$d;
    wire  [31:0] tin_r0$13$q;
    reg  tin_r0$13$clock;
    reg  [31:0] tin_r0$14$d;
    wire  [31:0] tin_r0$14$q;
    reg  tin_r0$14$clock;
    reg  [31:0] tin_r0$15$d;
    wire  [31:0] tin_r0$15$q;
    reg  tin_r0$15$clock;
    reg  [31:0] tin_r0$16$d;
    wire  [31:0] tin_r0$16$q;
    reg  tin_r0$16$clock;
    reg  [31:0] tin_r0$17$d;
    wire  [31:0] tin_r0$17$q;
    reg  tin_r0$17$clock;
    reg  [31:0] tin_r0$18$d;
    wire  [31:0] tin_r0$18$q;
    reg  tin_r0$18$clock;
    reg  [31:0] tin_r0$19$d;
    wire  [31:0] tin_r0$19$q;
    reg  tin_r0$19$clock;
    reg  [31:0] tin_r0$20$d;
    wire  [31:0] tin_r0$20$q;
    reg  tin_r0$20$clock;
    reg  [31:0] tin_r0$21$d;
    wire  [31:0] tin_r0$21$q;
    reg  tin_r0$21$clock;
    reg  [31:0] tin_r0$22$d;
    wire  [31:0] tin_r0$22$q;
    reg  tin_r0$22$clock;
    reg  [31:0] tin_r0$23$d;
    wire  [31:0] tin_r0$23$q;
    reg  tin_r0$23$clock;
    reg  [31:0] tin_l1$0$d;
    wire  [31:0] tin_l1$0$q;
    reg  tin_l1$0$clock;
    reg  [31:0] tin_l1$1$d;
    wire  [31:0] tin_l1$1$q;
    reg  tin_l1$1$clock;
    reg  [31:0] tin_l1$2$d;
    wire  [31:0] tin_l1$2$q;
    reg  tin_l1$2$clock;
    reg  [31:0] tin_l1$3$d;
    wire  [31:0] tin_l1$3$q;
    reg  tin_l1$3$clock;
    reg  [31:0] tin_l1$4$d;
    wire  [31:0] tin_l1$4$q;
    reg  tin_l1$4$clock;
    reg  [31:0] tin_l1$5$d;
    wire  [31:0] tin_l1$5$q;
    reg  tin_l1$5$clock;
    reg  [31:0] tin_l1$6$d;
    wire  [31:0] tin_l1$6$q;
    reg  tin_l1$6$clock;
    reg  [31:0] tin_l1$7$d;
    wire  [31:0] tin_l1$7$q;
    reg  tin_l1$7$clock;
    reg  [31:0] tin_l1$8$d;
    wire  [31:0] tin_l1$8$q;
    reg  tin_l1$8$clock;
    reg  [31:0] tin_l1$9$d;
    wire  [31:0] tin_l1$9$q;
    reg  tin_l1$9$clock;
    reg  [31:0] tin_l1$10$d;
    wire  [31:0] tin_l1$10$q;
    reg  tin_l1$10$clock;
    reg  [31:0] tin_l1$11$d;
    wire  [31:0] tin_l1$11$q;
    reg  tin_l1$11$clock;
    reg  [31:0] tin_l1$12$d;
    wire  [31:0] tin_l1$12$q;
    reg  tin_l1$12$clock;
    reg  [31:0] tin_l1$13$d;
    wire  [31:0] tin_l1$13$q;
    reg  tin_l1$13$clock;
    reg  [31:0] tin_l1$14$d;
    wire  [31:0] tin_l1$14$q;
    reg  tin_l1$14$clock;
    reg  [31:0] tin_l1$15$d;
    wire  [31:0] tin_l1$15$q;
    reg  tin_l1$15$clock;
    reg  [31:0] tin_l1$16$d;
    wire  [31:0] tin_l1$16$q;
    reg  tin_l1$16$clock;
    reg  [31:0] tin_l1$17$d;
    wire  [31:0] tin_l1$17$q;
    reg  tin_l1$17$clock;
    reg  [31:0] tin_l1$18$d;
    wire  [31:0] tin_l1$18$q;
    reg  tin_l1$18$clock;
    reg  [31:0] tin_l1$19$d;
    wire  [31:0] tin_l1$19$q;
    reg  tin_l1$19$clock;
    reg  [31:0] tin_l1$20$d;
    wire  [31:0] tin_l1$20$q;
    reg  tin_l1$20$clock;
    reg  [31:0] tin_l1$21$d;
    wire  [31:0] tin_l1$21$q;
    reg  tin_l1$21$clock;
    reg  [31:0] tin_l1$22$d;
    wire  [31:0] tin_l1$22$q;
    reg  tin_l1$22$clock;
    reg  [31:0] tin_l1$23$d;
    wire  [31:0] tin_l1$23$q;
    reg  tin_l1$23$clock;
    reg  [31:0] tin_r1$0$d;
    wire  [31:0] tin_r1$0$q;
    reg  tin_r1$0$clock;
    reg  [31:0] tin_r1$1$d;
    wire  [31:0] tin_r1$1$q;
    reg  tin_r1$1$clock;
    reg  [31:0] tin_r1$2$d;
    wire  [31:0] tin_r1$2$q;
    reg  tin_r1$2$clock;
    reg  [31:0] tin_r1$3$d;
    wire  [31:0] tin_r1$3$q;
    reg  tin_r1$3$clock;
    reg  [31:0] tin_r1$4$d;
    wire  [31:0] tin_r1$4$q;
    reg  tin_r1$4$clock;
    reg  [31:0] tin_r1$5$d;
    wire  [31:0] tin_r1$5$q;
    reg  tin_r1$5$clock;
    reg  [31:0] tin_r1$6$d;
    wire  [31:0] tin_r1$6$q;
    reg  tin_r1$6$clock;
    reg  [31:0] tin_r1$7$d;
    wire  [31:0] tin_r1$7$q;
    reg  tin_r1$7$clock;
    reg  [31:0] tin_r1$8$d;
    wire  [31:0] tin_r1$8$q;
    reg  tin_r1$8$clock;
    reg  [31:0] tin_r1$9$d;
    wire  [31:0] tin_r1$9$q;
    reg  tin_r1$9$clock;
    reg  [31:0] tin_r1$10$d;
    wire  [31:0] tin_r1$10$q;
    reg  tin_r1$10$clock;
    reg  [31:0] tin_r1$11$d;
    wire  [31:0] tin_r1$11$q;
    reg  tin_r1$11$clock;
    reg  [31:0] tin_r1$12$d;
    wire  [31:0] tin_r1$12$q;
    reg  tin_r1$12$clock;
    reg  [31:0] tin_r1$13$d;
    wire  [31:0] tin_r1$13$q;
    reg  tin_r1$13$clock;
    reg  [31:0] tin_r1$14$d;
    wire  [31:0] tin_r1$14$q;
    reg  tin_r1$14$clock;
    reg  [31:0] tin_r1$15$d;
    wire  [31:0] tin_r1$15$q;
    reg  tin_r1$15$clock;
    reg  [31:0] tin_r1$16$d;
    wire  [31:0] tin_r1$16$q;
    reg  tin_r1$16$clock;
    reg  [31:0] tin_r1$17$d;
    wire  [31:0] tin_r1$17$q;
    reg  tin_r1$17$clock;
    reg  [31:0] tin_r1$18$d;
    wire  [31:0] tin_r1$18$q;
    reg  tin_r1$18$clock;
    reg  [31:0] tin_r1$19$d;
    wire  [31:0] tin_r1$19$q;
    reg  tin_r1$19$clock;
    reg  [31:0] tin_r1$20$d;
    wire  [31:0] tin_r1$20$q;
    reg  tin_r1$20$clock;
    reg  [31:0] tin_r1$21$d;
    wire  [31:0] tin_r1$21$q;
    reg  tin_r1$21$clock;
    reg  [31:0] tin_r1$22$d;
    wire  [31:0] tin_r1$22$q;
    reg  tin_r1$22$clock;
    reg  [31:0] tin_r1$23$d;
    wire  [31:0] tin_r1$23$q;
    reg  tin_r1$23$clock;
    reg  gen_run$d;
    wire  gen_run$q;
    reg  gen_run$clock;
    reg  [4:0] gen_cnt$d;
    wire  [4:0] gen_cnt$q;
    reg  gen_cnt$clock;
    reg  gen_set$d;
    wire  gen_set$q;
    reg  gen_set$clock;
    reg  [1:0] pend$d;
    wire  [1:0] pend$q;
    reg  pend$clock;
    reg  [1:0] busy_r$d;
    wire  [1:0] busy_r$q;
    reg  busy_r$clock;
    reg  s1_valid$d;
    wire  s1_valid$q;
    reg  s1_valid$clock;
    reg  s1_set$d;
    wire  s1_set$q;
    reg  s1_set$clock;
    reg  [4:0] s1_lane$d;
    wire  [4:0] s1_lane$q;
    reg  s1_lane$clock;
    reg  s1_last$d;
    wire  s1_last$q;
    reg  s1_last$clock;
    reg  [31:0] klm_l$d$0;
    reg  [31:0] klm_l$d$1;
    reg  [31:0] klm_l$d$2;
    reg  [31:0] klm_l$d$3;
    reg  [31:0] klm_l$d$4;
    reg  [31:0] klm_l$d$5;
    reg  [31:0] klm_l$d$6;
    reg  [31:0] klm_l$d$7;
    reg  [31:0] klm_l$d$8;
    reg  [31:0] klm_l$d$9;
    reg  [31:0] klm_l$d$10;
    reg  [31:0] klm_l$d$11;
    reg  [31:0] klm_l$d$12;
    reg  [31:0] klm_l$d$13;
    reg  [31:0] klm_l$d$14;
    reg  [31:0] klm_l$d$15;
    reg  [31:0] klm_l$d$16;
    reg  [31:0] klm_l$d$17;
    reg  [31:0] klm_l$d$18;
    reg  [31:0] klm_l$d$19;
    reg  [31:0] klm_l$d$20;
    reg  [31:0] klm_l$d$21;
    reg  [31:0] klm_l$d$22;
    reg  [31:0] klm_l$d$23;
    reg  [4:0] klm_l$j0$0;
    reg  [4:0] klm_l$j1$0;
    reg  [4:0] klm_l$j2$0;
    wire  [31:0] klm_l$y0$0;
    wire  [31:0] klm_l$y1$0;
    wire  [31:0] klm_l$y2$0;
    reg  [31:0] klm_r$d$0;
    reg  [31:0] klm_r$d$1;
    reg  [31:0] klm_r$d$2;
    reg  [31:0] klm_r$d$3;
    reg  [31:0] klm_r$d$4;
    reg  [31:0] klm_r$d$5;
    reg  [31:0] klm_r$d$6;
    reg  [31:0] klm_r$d$7;
    reg  [31:0] klm_r$d$8;
    reg  [31:0] klm_r$d$9;
    reg  [31:0] klm_r$d$10;
    reg  [31:0] klm_r$d$11;
    reg  [31:0] klm_r$d$12;
    reg  [31:0] klm_r$d$13;
    reg  [31:0] klm_r$d$14;
    reg  [31:0] klm_r$d$15;
    reg  [31:0] klm_r$d$16;
    reg  [31:0] klm_r$d$17;
    reg  [31:0] klm_r$d$18;
    reg  [31:0] klm_r$d$19;
    reg  [31:0] klm_r$d$20;
    reg  [31:0] klm_r$d$21;
    reg  [31:0] klm_r$d$22;
    reg  [31:0] klm_r$d$23;
    reg  [4:0] klm_r$j0$0;
    reg  [4:0] klm_r$j1$0;
    reg  [4:0] klm_r$j2$0;
    wire  [31:0] klm_r$y0$0;
    wire  [31:0] klm_r$y1$0;
    wire  [31:0] klm_r$y2$0;
    reg  dot_l$clock;
    reg  [31:0] dot_l$d0;
    reg  [31:0] dot_l$d1;
    reg  [31:0] dot_l$d2;
    reg  [31:0] dot_l$c0;
    reg  [31:0] dot_l$c1;
    reg  [31:0] dot_l$c2;
    reg  [31:0] dot_l$c;
    reg  dot_l$valid_in;
    reg  dot_l$round_up;
    wire  [31:0] dot_l$u;
    wire  dot_l$valid_out;
    reg  dot_r$clock;
    reg  [31:0] dot_r$d0;
    reg  [31:0] dot_r$d1;
    reg  [31:0] dot_r$d2;
    reg  [31:0] dot_r$c0;
    reg  [31:0] dot_r$c1;
    reg  [31:0] dot_r$c2;
    reg  [31:0] dot_r$c;
    reg  dot_r$valid_in;
    reg  dot_r$round_up;
    wire  [31:0] dot_r$u;
    wire  dot_r$valid_out;
    reg  wr_tag$clock;
    reg  [6:0] wr_tag$d;
    wire  [6:0] wr_tag$q;
    reg  dprime$clock;
    reg  dprime$wr_valid;
    reg  dprime$wr_set;
    reg  [4:0] dprime$wr_lane;
    reg  [31:0] dprime$wr_l;
    reg  [31:0] dprime$wr_r;
    reg  dprime$rd_set;
    reg  [1:0] dprime$rd_entry;
    wire  [255:0] dprime$dl;
    wire  [255:0] dprime$dr;
    reg  sa_valid$d;
    wire  sa_valid$q;
    reg  sa_valid$clock;
    reg  sa_first$d;
    wire  sa_first$q;
    reg  sa_first$clock;
    reg  [7:0] sa_lanes$d;
    wire  [7:0] sa_lanes$q;
    reg  sa_lanes$clock;
    reg  [255:0] sa_e$d;
    wire  [255:0] sa_e$q;
    reg  sa_e$clock;
    reg  bank$clock;
    reg  bank$valid_in;
    reg  bank$first;
    reg  [7:0] bank$lanes;
    reg  [255:0] bank$e;
    reg  [255:0] bank$dl;
    reg  [255:0] bank$dr;
    wire  bank$overlap_l;
    wire  bank$overlap_r;
    wire  bank$valid_out;
    
    // Local signals
    reg  [4:0] c_row;
    reg  [2:0] c_field;
    reg  [31:0] c_slot$0;
    reg  [31:0] c_slot$1;
    reg  [31:0] c_slot$2;
    reg  [31:0] c_slot$3;
    reg  [31:0] c_slot$4;
    reg  [31:0] c_slot$5;
    reg  [31:0] c_slot$6;
    reg  [31:0] c_slot$7;
    reg  c_row_last;
    reg  c_go;
    reg  c_go_set;
    reg  [1:0] c_t_set;
    reg  [1:0] c_go_mask;
    reg  [1:0] c_pend_set;
    reg  [1:0] c_busy_set;
    reg  [1:0] c_busy_clr;
    reg  [31:0] c_ctl;
    reg  c_wr_set;
    
    // Sub module instances
    top$core$dop$mmm$0 mmm$0(
        .read_address(mmm$0$read_address),
        .read_clock(mmm$0$read_clock),
        .read_data(mmm$0$read_data),
        .write_address(mmm$0$write_address),
        .write_clock(mmm$0$write_clock),
        .write_data(mmm$0$write_data),
        .write_enable(mmm$0$write_enable)
    );
    top$core$dop$mmm$0 mmm$1(
        .read_address(mmm$1$read_address),
        .read_clock(mmm$1$read_clock),
        .read_data(mmm$1$read_data),
        .write_address(mmm$1$write_address),
        .write_clock(mmm$1$write_clock),
        .write_data(mmm$1$write_data),
        .write_enable(mmm$1$write_enable)
    );
    top$core$dop$mmm$0 mmm$2(
        .read_address(mmm$2$read_address),
        .read_clock(mmm$2$read_clock),
        .read_data(mmm$2$read_data),
        .write_address(mmm$2$write_address),
        .write_clock(mmm$2$write_clock),
        .write_data(mmm$2$write_data),
        .write_enable(mmm$2$write_enable)
    );
    top$core$dop$mmm$0 mmm$3(
        .read_address(mmm$3$read_address),
        .read_clock(mmm$3$read_clock),
        .read_data(mmm$3$read_data),
        .write_address(mmm$3$write_address),
        .write_clock(mmm$3$write_clock),
        .write_data(mmm$3$write_data),
        .write_enable(mmm$3$write_enable)
    );
    top$core$dop$mmm$0 mmm$4(
        .read_address(mmm$4$read_address),
        .read_clock(mmm$4$read_clock),
        .read_data(mmm$4$read_data),
        .write_address(mmm$4$write_address),
        .write_clock(mmm$4$write_clock),
        .write_data(mmm$4$write_data),
        .write_enable(mmm$4$write_enable)
    );
    top$core$cnt_nf tin_l0$0(
        .d(tin_l0$0$d),
        .q(tin_l0$0$q),
        .clock(tin_l0$0$clock)
    );
    top$core$cnt_nf tin_l0$1(
        .d(tin_l0$1$d),
        .q(tin_l0$1$q),
        .clock(tin_l0$1$clock)
    );
    top$core$cnt_nf tin_l0$2(
        .d(tin_l0$2$d),
        .q(tin_l0$2$q),
        .clock(tin_l0$2$clock)
    );
    top$core$cnt_nf tin_l0$3(
        .d(tin_l0$3$d),
        .q(tin_l0$3$q),
        .clock(tin_l0$3$clock)
    );
    top$core$cnt_nf tin_l0$4(
        .d(tin_l0$4$d),
        .q(tin_l0$4$q),
        .clock(tin_l0$4$clock)
    );
    top$core$cnt_nf tin_l0$5(
        .d(tin_l0$5$d),
        .q(tin_l0$5$q),
        .clock(tin_l0$5$clock)
    );
    top$core$cnt_nf tin_l0$6(
        .d(tin_l0$6$d),
        .q(tin_l0$6$q),
        .clock(tin_l0$6$clock)
    );
    top$core$cnt_nf tin_l0$7(
        .d(tin_l0$7$d),
        .q(tin_l0$7$q),
        .clock(tin_l0$7$clock)
    );
    top$core$cnt_nf tin_l0$8(
        .d(tin_l0$8$d),
        .q(tin_l0$8$q),
        .clock(tin_l0$8$clock)
    );
    top$core$cnt_nf tin_l0$9(
        .d(tin_l0$9$d),
        .q(tin_l0$9$q),
        .clock(tin_l0$9$clock)
    );
    top$core$cnt_nf tin_l0$10(
        .d(tin_l0$10$d),
        .q(tin_l0$10$q),
        .clock(tin_l0$10$clock)
    );
    top$core$cnt_nf tin_l0$11(
        .d(tin_l0$11$d),
        .q(tin_l0$11$q),
        .clock(tin_l0$11$clock)
    );
    top$core$cnt_nf tin_l0$12(
        .d(tin_l0$12$d),
        .q(tin_l0$12$q),
        .clock(tin_l0$12$clock)
    );
    top$core$cnt_nf tin_l0$13(
        .d(tin_l0$13$d),
        .q(tin_l0$13$q),
        .clock(tin_l0$13$clock)
    );
    top$core$cnt_nf tin_l0$14(
        .d(tin_l0$14$d),
        .q(tin_l0$14$q),
        .clock(tin_l0$14$clock)
    );
    top$core$cnt_nf tin_l0$15(
        .d(tin_l0$15$d),
        .q(tin_l0$15$q),
        .clock(tin_l0$15$clock)
    );
    top$core$cnt_nf tin_l0$16(
        .d(tin_l0$16$d),
        .q(tin_l0$16$q),
        .clock(tin_l0$16$clock)
    );
    top$core$cnt_nf tin_l0$17(
        .d(tin_l0$17$d),
        .q(tin_l0$17$q),
        .clock(tin_l0$17$clock)
    );
    top$core$cnt_nf tin_l0$18(
        .d(tin_l0$18$d),
        .q(tin_l0$18$q),
        .clock(tin_l0$18$clock)
    );
    top$core$cnt_nf tin_l0$19(
        .d(tin_l0$19$d),
        .q(tin_l0$19$q),
        .clock(tin_l0$19$clock)
    );
    top$core$cnt_nf tin_l0$20(
        .d(tin_l0$20$d),
        .q(tin_l0$20$q),
        .clock(tin_l0$20$clock)
    );
    top$core$cnt_nf tin_l0$21(
        .d(tin_l0$21$d),
        .q(tin_l0$21$q),
        .clock(tin_l0$21$clock)
    );
    top$core$cnt_nf tin_l0$22(
        .d(tin_l0$22$d),
        .q(tin_l0$22$q),
        .clock(tin_l0$22$clock)
    );
    top$core$cnt_nf tin_l0$23(
        .d(tin_l0$23$d),
        .q(tin_l0$23$q),
        .clock(tin_l0$23$clock)
    );
    top$core$cnt_nf tin_r0$0(
        .d(tin_r0$0$d),
        .q(tin_r0$0$q),
        .clock(tin_r0$0$clock)
    );
    top$core$cnt_nf tin_r0$1(
        .d(tin_r0$1$d),
        .q(tin_r0$1$q),
        .clock(tin_r0$1$clock)
    );
    top$core$cnt_nf tin_r0$2(
        .d(tin_r0$2$d),
        .q(tin_r0$2$q),
        .clock(tin_r0$2$clock)
    );
    top$core$cnt_nf tin_r0$3(
        .d(tin_r0$3$d),
        .q(tin_r0$3$q),
        .clock(tin_r0$3$clock)
    );
    top$core$cnt_nf tin_r0$4(
        .d(tin_r0$4$d),
        .q(tin_r0$4$q),
        .clock(tin_r0$4$clock)
    );
    top$core$cnt_nf tin_r0$5(
        .d(tin_r0$5$d),
        .q(tin_r0$5$q),
        .clock(tin_r0$5$clock)
    );
    top$core$cnt_nf tin_r0$6(
        .d(tin_r0$6$d),
        .q(tin_r0$6$q),
        .clock(tin_r0$6$clock)
    );
    top$core$cnt_nf tin_r0$7(
        .d(tin_r0$7$d),
        .q(tin_r0$7$q),
        .clock(tin_r0$7$clock)
    );
    top$core$cnt_nf tin_r0$8(
        .d(tin_r0$8$d),
        .q(tin_r0$8$q),
        .clock(tin_r0$8$clock)
    );
    top$core$cnt_nf tin_r0$9(
        .d(tin_r0$9$d),
        .q(tin_r0$9$q),
        .clock(tin_r0$9$clock)
    );
    top$core$cnt_nf tin_r0$10(
        .d(tin_r0$10$d),
        .q(tin_r0$10$q),
        .clock(tin_r0$10$clock)
    );
    top$core$cnt_nf tin_r0$11(
        .d(tin_r0$11$d),
        .q(tin_r0$11$q),
        .clock(tin_r0$11$clock)
    );
    top$core$cnt_nf tin_r0$12(
        .d(tin_r0$12$d),
        .q(tin_r0$12$q),
        .clock(tin_r0$12$clock)
    );
    top$core$cnt_nf tin_r0$13(
        .d(tin_r0$13$d),
        .q(tin_r0$13$q),
        .clock(tin_r0$13$clock)
    );
    top$core$cnt_nf tin_r0$14(
        .d(tin_r0$14$d),
        .q(tin_r0$14$q),
        .clock(tin_r0$14$clock)
    );
    top$core$cnt_nf tin_r0$15(
        .d(tin_r0$15$d),
        .q(tin_r0$15$q),
        .clock(tin_r0$15$clock)
    );
    top$core$cnt_nf tin_r0$16(
        .d(tin_r0$16$d),
        .q(tin_r0$16$q),
        .clock(tin_r0$16$clock)
    );
    top$core$cnt_nf tin_r0$17(
        .d(tin_r0$17$d),
        .q(tin_r0$17$q),
        .clock(tin_r0$17$clock)
    );
    top$core$cnt_nf tin_r0$18(
        .d(tin_r0$18$d),
        .q(tin_r0$18$q),
        .clock(tin_r0$18$clock)
    );
    top$core$cnt_nf tin_r0$19(
        .d(tin_r0$19$d),
        .q(tin_r0$19$q),
        .clock(tin_r0$19$clock)
    );
    top$core$cnt_nf tin_r0$20(
        .d(tin_r0$20$d),
        .q(tin_r0$20$q),
        .clock(tin_r0$20$clock)
    );
    top$core$cnt_nf tin_r0$21(
        .d(tin_r0$21$d),
        .q(tin_r0$21$q),
        .clock(tin_r0$21$clock)
    );
    top$core$cnt_nf tin_r0$22(
        .d(tin_r0$22$d),
        .q(tin_r0$22$q),
        .clock(tin_r0$22$clock)
    );
    top$core$cnt_nf tin_r0$23(
        .d(tin_r0$23$d),
        .q(tin_r0$23$q),
        .clock(tin_r0$23$clock)
    );
    top$core$cnt_nf tin_l1$0(
        .d(tin_l1$0$d),
        .q(tin_l1$0$q),
        .clock(tin_l1$0$clock)
    );
    top$core$cnt_nf tin_l1$1(
        .d(tin_l1$1$d),
        .q(tin_l1$1$q),
        .clock(tin_l1$1$clock)
    );
    top$core$cnt_nf tin_l1$2(
        .d(tin_l1$2$d),
        .q(tin_l1$2$q),
        .clock(tin_l1$2$clock)
    );
    top$core$cnt_nf tin_l1$3(
        .d(tin_l1$3$d),
        .q(tin_l1$3$q),
        .clock(tin_l1$3$clock)
    );
    top$core$cnt_nf tin_l1$4(
        .d(tin_l1$4$d),
        .q(tin_l1$4$q),
        .clock(tin_l1$4$clock)
    );
    top$core$cnt_nf tin_l1$5(
        .d(tin_l1$5$d),
        .q(tin_l1$5$q),
        .clock(tin_l1$5$clock)
    );
    top$core$cnt_nf tin_l1$6(
        .d(tin_l1$6$d),
        .q(tin_l1$6$q),
        .clock(tin_l1$6$clock)
    );
    top$core$cnt_nf tin_l1$7(
        .d(tin_l1$7$d),
        .q(tin_l1$7$q),
        .clock(tin_l1$7$clock)
    );
    top$core$cnt_nf tin_l1$8(
        .d(tin_l1$8$d),
        .q(tin_l1$8$q),
        .clock(tin_l1$8$clock)
    );
    top$core$cnt_nf tin_l1$9(
        .d(tin_l1$9$d),
        .q(tin_l1$9$q),
        .clock(tin_l1$9$clock)
    );
    top$core$cnt_nf tin_l1$10(
        .d(tin_l1$10$d),
        .q(tin_l1$10$q),
        .clock(tin_l1$10$clock)
    );
    top$core$cnt_nf tin_l1$11(
        .d(tin_l1$11$d),
        .q(tin_l1$11$q),
        .clock(tin_l1$11$clock)
    );
    top$core$cnt_nf tin_l1$12(
        .d(tin_l1$12$d),
        .q(tin_l1$12$q),
        .clock(tin_l1$12$clock)
    );
    top$core$cnt_nf tin_l1$13(
        .d(tin_l1$13$d),
        .q(tin_l1$13$q),
        .clock(tin_l1$13$clock)
    );
    top$core$cnt_nf tin_l1$14(
        .d(tin_l1$14$d),
        .q(tin_l1$14$q),
        .clock(tin_l1$14$clock)
    );
    top$core$cnt_nf tin_l1$15(
        .d(tin_l1$15$d),
        .q(tin_l1$15$q),
        .clock(tin_l1$15$clock)
    );
    top$core$cnt_nf tin_l1$16(
        .d(tin_l1$16$d),
        .q(tin_l1$16$q),
        .clock(tin_l1$16$clock)
    );
    top$core$cnt_nf tin_l1$17(
        .d(tin_l1$17$d),
        .q(tin_l1$17$q),
        .clock(tin_l1$17$clock)
    );
    top$core$cnt_nf tin_l1$18(
        .d(tin_l1$18$d),
        .q(tin_l1$18$q),
        .clock(tin_l1$18$clock)
    );
    top$core$cnt_nf tin_l1$19(
        .d(tin_l1$19$d),
        .q(tin_l1$19$q),
        .clock(tin_l1$19$clock)
    );
    top$core$cnt_nf tin_l1$20(
        .d(tin_l1$20$d),
        .q(tin_l1$20$q),
        .clock(tin_l1$20$clock)
    );
    top$core$cnt_nf tin_l1$21(
        .d(tin_l1$21$d),
        .q(tin_l1$21$q),
        .clock(tin_l1$21$clock)
    );
    top$core$cnt_nf tin_l1$22(
        .d(tin_l1$22$d),
        .q(tin_l1$22$q),
        .clock(tin_l1$22$clock)
    );
    top$core$cnt_nf tin_l1$23(
        .d(tin_l1$23$d),
        .q(tin_l1$23$q),
        .clock(tin_l1$23$clock)
    );
    top$core$cnt_nf tin_r1$0(
        .d(tin_r1$0$d),
        .q(tin_r1$0$q),
        .clock(tin_r1$0$clock)
    );
    top$core$cnt_nf tin_r1$1(
        .d(tin_r1$1$d),
        .q(tin_r1$1$q),
        .clock(tin_r1$1$clock)
    );
    top$core$cnt_nf tin_r1$2(
        .d(tin_r1$2$d),
        .q(tin_r1$2$q),
        .clock(tin_r1$2$clock)
    );
    top$core$cnt_nf tin_r1$3(
        .d(tin_r1$3$d),
        .q(tin_r1$3$q),
        .clock(tin_r1$3$clock)
    );
    top$core$cnt_nf tin_r1$4(
        .d(tin_r1$4$d),
        .q(tin_r1$4$q),
        .clock(tin_r1$4$clock)
    );
    top$core$cnt_nf tin_r1$5(
        .d(tin_r1$5$d),
        .q(tin_r1$5$q),
        .clock(tin_r1$5$clock)
    );
    top$core$cnt_nf tin_r1$6(
        .d(tin_r1$6$d),
        .q(tin_r1$6$q),
        .clock(tin_r1$6$clock)
    );
    top$core$cnt_nf tin_r1$7(
        .d(tin_r1$7$d),
        .q(tin_r1$7$q),
        .clock(tin_r1$7$clock)
    );
    top$core$cnt_nf tin_r1$8(
        .d(tin_r1$8$d),
        .q(tin_r1$8$q),
        .clock(tin_r1$8$clock)
    );
    top$core$cnt_nf tin_r1$9(
        .d(tin_r1$9$d),
        .q(tin_r1$9$q),
        .clock(tin_r1$9$clock)
    );
    top$core$cnt_nf tin_r1$10(
        .d(tin_r1$10$d),
        .q(tin_r1$10$q),
        .clock(tin_r1$10$clock)
    );
    top$core$cnt_nf tin_r1$11(
        .d(tin_r1$11$d),
        .q(tin_r1$11$q),
        .clock(tin_r1$11$clock)
    );
    top$core$cnt_nf tin_r1$12(
        .d(tin_r1$12$d),
        .q(tin_r1$12$q),
        .clock(tin_r1$12$clock)
    );
    top$core$cnt_nf tin_r1$13(
        .d(tin_r1$13$d),
        .q(tin_r1$13$q),
        .clock(tin_r1$13$clock)
    );
    top$core$cnt_nf tin_r1$14(
        .d(tin_r1$14$d),
        .q(tin_r1$14$q),
        .clock(tin_r1$14$clock)
    );
    top$core$cnt_nf tin_r1$15(
        .d(tin_r1$15$d),
        .q(tin_r1$15$q),
        .clock(tin_r1$15$clock)
    );
    top$core$cnt_nf tin_r1$16(
        .d(tin_r1$16$d),
        .q(tin_r1$16$q),
        .clock(tin_r1$16$clock)
    );
    top$core$cnt_nf tin_r1$17(
        .d(tin_r1$17$d),
        .q(tin_r1$17$q),
        .clock(tin_r1$17$clock)
    );
    top$core$cnt_nf tin_r1$18(
        .d(tin_r1$18$d),
        .q(tin_r1$18$q),
        .clock(tin_r1$18$clock)
    );
    top$core$cnt_nf tin_r1$19(
        .d(tin_r1$19$d),
        .q(tin_r1$19$q),
        .clock(tin_r1$19$clock)
    );
    top$core$cnt_nf tin_r1$20(
        .d(tin_r1$20$d),
        .q(tin_r1$20$q),
        .clock(tin_r1$20$clock)
    );
    top$core$cnt_nf tin_r1$21(
        .d(tin_r1$21$d),
        .q(tin_r1$21$q),
        .clock(tin_r1$21$clock)
    );
    top$core$cnt_nf tin_r1$22(
        .d(tin_r1$22$d),
        .q(tin_r1$22$q),
        .clock(tin_r1$22$clock)
    );
    top$core$cnt_nf tin_r1$23(
        .d(tin_r1$23$d),
        .q(tin_r1$23$q),
        .clock(tin_r1$23$clock)
    );
    top$core$done_r gen_run(
        .d(gen_run$d),
        .q(gen_run$q),
        .clock(gen_run$clock)
    );
    top$core$dop$gen_cnt gen_cnt(
        .d(gen_cnt$d),
        .q(gen_cnt$q),
        .clock(gen_cnt$clock)
    );
    top$core$done_r gen_set(
        .d(gen_set$d),
        .q(gen_set$q),
        .clock(gen_set$clock)
    );
    top$core$dop$busy_r pend(
        .d(pend$d),
        .q(pend$q),
        .clock(pend$clock)
    );
    top$core$dop$busy_r busy_r(
        .d(busy_r$d),
        .q(busy_r$q),
        .clock(busy_r$clock)
    );
    top$core$done_r s1_valid(
        .d(s1_valid$d),
        .q(s1_valid$q),
        .clock(s1_valid$clock)
    );
    top$core$done_r s1_set(
        .d(s1_set$d),
        .q(s1_set$q),
        .clock(s1_set$clock)
    );
    top$core$dop$gen_cnt s1_lane(
        .d(s1_lane$d),
        .q(s1_lane$q),
        .clock(s1_lane$clock)
    );
    top$core$done_r s1_last(
        .d(s1_last$d),
        .q(s1_last$q),
        .clock(s1_last$clock)
    );
    top$core$dop$klm_l klm_l(
        .d$0(klm_l$d$0),
        .d$1(klm_l$d$1),
        .d$2(klm_l$d$2),
        .d$3(klm_l$d$3),
        .d$4(klm_l$d$4),
        .d$5(klm_l$d$5),
        .d$6(klm_l$d$6),
        .d$7(klm_l$d$7),
        .d$8(klm_l$d$8),
        .d$9(klm_l$d$9),
        .d$10(klm_l$d$10),
        .d$11(klm_l$d$11),
        .d$12(klm_l$d$12),
        .d$13(klm_l$d$13),
        .d$14(klm_l$d$14),
        .d$15(klm_l$d$15),
        .d$16(klm_l$d$16),
        .d$17(klm_l$d$17),
        .d$18(klm_l$d$18),
        .d$19(klm_l$d$19),
        .d$20(klm_l$d$20),
        .d$21(klm_l$d$21),
        .d$22(klm_l$d$22),
        .d$23(klm_l$d$23),
        .j0$0(klm_l$j0$0),
        .j1$0(klm_l$j1$0),
        .j2$0(klm_l$j2$0),
        .y0$0(klm_l$y0$0),
        .y1$0(klm_l$y1$0),
        .y2$0(klm_l$y2$0)
    );
    top$core$dop$klm_l klm_r(
        .d$0(klm_r$d$0),
        .d$1(klm_r$d$1),
        .d$2(klm_r$d$2),
        .d$3(klm_r$d$3),
        .d$4(klm_r$d$4),
        .d$5(klm_r$d$5),
        .d$6(klm_r$d$6),
        .d$7(klm_r$d$7),
        .d$8(klm_r$d$8),
        .d$9(klm_r$d$9),
        .d$10(klm_r$d$10),
        .d$11(klm_r$d$11),
        .d$12(klm_r$d$12),
        .d$13(klm_r$d$13),
        .d$14(klm_r$d$14),
        .d$15(klm_r$d$15),
        .d$16(klm_r$d$16),
        .d$17(klm_r$d$17),
        .d$18(klm_r$d$18),
        .d$19(klm_r$d$19),
        .d$20(klm_r$d$20),
        .d$21(klm_r$d$21),
        .d$22(klm_r$d$22),
        .d$23(klm_r$d$23),
        .j0$0(klm_r$j0$0),
        .j1$0(klm_r$j1$0),
        .j2$0(klm_r$j2$0),
        .y0$0(klm_r$y0$0),
        .y1$0(klm_r$y1$0),
        .y2$0(klm_r$y2$0)
    );
    top$core$dop$dot_l dot_l(
        .clock(dot_l$clock),
        .d0(dot_l$d0),
        .d1(dot_l$d1),
        .d2(dot_l$d2),
        .c0(dot_l$c0),
        .c1(dot_l$c1),
        .c2(dot_l$c2),
        .c(dot_l$c),
        .valid_in(dot_l$valid_in),
        .round_up(dot_l$round_up),
        .u(dot_l$u),
        .valid_out(dot_l$valid_out)
    );
    top$core$dop$dot_l dot_r(
        .clock(dot_r$clock),
        .d0(dot_r$d0),
        .d1(dot_r$d1),
        .d2(dot_r$d2),
        .c0(dot_r$c0),
        .c1(dot_r$c1),
        .c2(dot_r$c2),
        .c(dot_r$c),
        .valid_in(dot_r$valid_in),
        .round_up(dot_r$round_up),
        .u(dot_r$u),
        .valid_out(dot_r$valid_out)
    );
    top$core$dop$wr_tag wr_tag(
        .clock(wr_tag$clock),
        .d(wr_tag$d),
        .q(wr_tag$q)
    );
    top$core$dop$dprime dprime(
        .clock(dprime$clock),
        .wr_valid(dprime$wr_valid),
        .wr_set(dprime$wr_set),
        .wr_lane(dprime$wr_lane),
        .wr_l(dprime$wr_l),
        .wr_r(dprime$wr_r),
        .rd_set(dprime$rd_set),
        .rd_entry(dprime$rd_entry),
        .dl(dprime$dl),
        .dr(dprime$dr)
    );
    top$core$done_r sa_valid(
        .d(sa_valid$d),
        .q(sa_valid$q),
        .clock(sa_valid$clock)
    );
    top$core$done_r sa_first(
        .d(sa_first$d),
        .q(sa_first$q),
        .clock(sa_first$clock)
    );
    top$core$dop$bank$s1_lanes sa_lanes(
        .d(sa_lanes$d),
        .q(sa_lanes$q),
        .clock(sa_lanes$clock)
    );
    top$core$dop$sa_e sa_e(
        .d(sa_e$d),
        .q(sa_e$q),
        .clock(sa_e$clock)
    );
    top$core$dop$bank bank(
        .clock(bank$clock),
        .valid_in(bank$valid_in),
        .first(bank$first),
        .lanes(bank$lanes),
        .e(bank$e),
        .dl(bank$dl),
        .dr(bank$dr),
        .overlap_l(bank$overlap_l),
        .overlap_r(bank$overlap_r),
        .valid_out(bank$valid_out)
    );
    
    // Update code
    always @(*) begin
        c_row = load_addr[(32'h3)+:(5)];
        c_field = load_addr[(32'h0)+:(3)];
        mmm$0$read_clock = clock;
        mmm$0$write_clock = clock;
        mmm$0$read_address = gen_cnt$q;
        mmm$0$write_address = c_row;
        mmm$0$write_data = load_data;
        mmm$0$write_enable = load_en & (c_field == mmm_field$0);
        mmm$1$read_clock = clock;
        mmm$1$write_clock = clock;
        mmm$1$read_address = gen_cnt$q;
        mmm$1$write_address = c_row;
        mmm$1$write_data = load_data;
        mmm$1$write_enable = load_en & (c_field == mmm_field$1);
        mmm$2$read_clock = clock;
        mmm$2$write_clock = clock;
        mmm$2$read_address = gen_cnt$q;
        mmm$2$write_address = c_row;
        mmm$2$write_data = load_data;
        mmm$2$write_enable = load_en & (c_field == mmm_field$2);
        mmm$3$read_clock = clock;
        mmm$3$write_clock = clock;
        mmm$3$read_address = gen_cnt$q;
        mmm$3$write_address = c_row;
        mmm$3$write_data = load_data;
        mmm$3$write_enable = load_en & (c_field == mmm_field$3);
        mmm$4$read_clock = clock;
        mmm$4$write_clock = clock;
        mmm$4$read_address = gen_cnt$q;
        mmm$4$write_address = c_row;
        mmm$4$write_data = load_data;
        mmm$4$write_enable = load_en & (c_field == mmm_field$4);
        c_slot$0 = t_data[(32'h0)+:(32)];
        c_slot$1 = t_data[(32'h20)+:(32)];
        c_slot$2 = t_data[(32'h40)+:(32)];
        c_slot$3 = t_data[(32'h60)+:(32)];
        c_slot$4 = t_data[(32'h80)+:(32)];
        c_slot$5 = t_data[(32'ha0)+:(32)];
        c_slot$6 = t_data[(32'hc0)+:(32)];
        c_slot$7 = t_data[(32'he0)+:(32)];
        tin_l0$0$clock = clock;
        tin_r0$0$clock = clock;
        tin_l1$0$clock = clock;
        tin_r1$0$clock = clock;
        tin_l0$0$d = tin_l0$0$q;
        tin_r0$0$d = tin_r0$0$q;
        tin_l1$0$d = tin_l1$0$q;
        tin_r1$0$d = tin_r1$0$q;
        if (t_valid & (t_entry == entry_of$0)) begin
            if (t_set == 32'h1) begin
                if (t_side) begin
                    tin_r1$0$d = c_slot$0;
                end
                else begin
                    tin_l1$0$d = c_slot$0;
                end
            end
            else if (t_side) begin
                tin_r0$0$d = c_slot$0;
            end
            else begin
                tin_l0$0$d = c_slot$0;
            end
        end
        tin_l0$1$clock = clock;
        tin_r0$1$clock = clock;
        tin_l1$1$clock = clock;
        tin_r1$1$clock = clock;
        tin_l0$1$d = tin_l0$1$q;
        tin_r0$1$d = tin_r0$1$q;
        tin_l1$1$d = tin_l1$1$q;
        tin_r1$1$d = tin_r1$1$q;
        if (t_valid & (t_entry == entry_of$1)) begin
            if (t_set == 32'h1) begin
                if (t_side) begin
                    tin_r1$1$d = c_slot$1;
                end
                else begin
                    tin_l1$1$d = c_slot$1;
                end
            end
            else if (t_side) begin
                tin_r0$1$d = c_slot$1;
            end
            else begin
                tin_l0$1$d = c_slot$1;
            end
        end
        tin_l0$2$clock = clock;
        tin_r0$2$clock = clock;
        tin_l1$2$clock = clock;
        tin_r1$2$clock = clock;
        tin_l0$2$d = tin_l0$2$q;
        tin_r0$2$d = tin_r0$2$q;
        tin_l1$2$d = tin_l1$2$q;
        tin_r1$2$d = tin_r1$2$q;
        if (t_valid & (t_entry == entry_of$2)) begin
            if (t_set == 32'h1) begin
                if (t_side) begin
                    tin_r1$2$d = c_slot$2;
                end
                else begin
                    tin_l1$2$d = c_slot$2;
                end
            end
            else if (t_side) begin
                tin_r0$2$d = c_slot$2;
            end
            else begin
                tin_l0$2$d = c_slot$2;
            end
        end
        tin_l0$3$clock = clock;
        tin_r0$3$clock = clock;
        tin_l1$3$clock = clock;
        tin_r1$3$clock = clock;
        tin_l0$3$d = tin_l0$3$q;
        tin_r0$3$d = tin_r0$3$q;
        tin_l1$3$d = tin_l1$3$q;
        tin_r1$3$d = tin_r1$3$q;
        if (t_valid & (t_entry == entry_of$3)) begin
            if (t_set == 32'h1) begin
                if (t_side) begin
                    tin_r1$3$d = c_slot$3;
                end
                else begin
                    tin_l1$3$d = c_slot$3;
                end
            end
            else if (t_side) begin
                tin_r0$3$d = c_slot$3;
            end
            else begin
                tin_l0$3$d = c_slot$3;
            end
        end
        tin_l0$4$clock = clock;
        tin_r0$4$clock = clock;
        tin_l1$4$clock = clock;
        tin_r1$4$clock = clock;
        tin_l0$4$d = tin_l0$4$q;
        tin_r0$4$d = tin_r0$4$q;
        tin_l1$4$d = tin_l1$4$q;
        tin_r1$4$d = tin_r1$4$q;
        if (t_valid & (t_entry == entry_of$4)) begin
            if (t_set == 32'h1) begin
                if (t_side) begin
                    tin_r1$4$d = c_slot$4;
                end
                else begin
                    tin_l1$4$d = c_slot$4;
                end
            end
            else if (t_side) begin
                tin_r0$4$d = c_slot$4;
            end
            else begin
                tin_l0$4$d = c_slot$4;
            end
        end
        tin_l0$5$clock = clock;
        tin_r0$5$clock = clock;
        tin_l1$5$clock = clock;
        tin_r1$5$clock = clock;
        tin_l0$5$d = tin_l0$5$q;
        tin_r0$5$d = tin_r0$5$q;
        tin_l1$5$d = tin_l1$5$q;
        tin_r1$5$d = tin_r1$5$q;
        if (t_valid & (t_entry == entry_of$5)) begin
            if (t_set == 32'h1) begin
                if (t_side) begin
                    tin_r1$5$d = c_slot$5;
                end
                else begin
                    tin_l1$5$d = c_slot$5;
                end
            end
            else if (t_side) begin
                tin_r0$5$d = c_slot$5;
            end
            else begin
                tin_l0$5$d = c_slot$5;
            end
        end
        tin_l0$6$clock = clock;
        tin_r0$6$clock = clock;
        tin_l1$6$clock = clock;
        tin_r1$6$clock = clock;
        tin_l0$6$d = tin_l0$6$q;
        tin_r0$6$d = tin_r0$6$q;
        tin_l1$6$d = tin_l1$6$q;
        tin_r1$6$d = tin_r1$6$q;
        if (t_valid & (t_entry == entry_of$6)) begin
            if (t_set == 32'h1) begin
                if (t_side) begin
                    tin_r1$6$d = c_slot$6;
                end
                else begin
                    tin_l1$6$d = c_slot$6;
                end
            end
            else if (t_side) begin
                tin_r0$6$d = c_slot$6;
            end
            else begin
                tin_l0$6$d = c_slot$6;
            end
        end
        tin_l0$7$clock = clock;
        tin_r0$7$clock = clock;
        tin_l1$7$clock = clock;
        tin_r1$7$clock = clock;
        tin_l0$7$d = tin_l0$7$q;
        tin_r0$7$d = tin_r0$7$q;
        tin_l1$7$d = tin_l1$7$q;
        tin_r1$7$d = tin_r1$7$q;
        if (t_valid & (t_entry == entry_of$7)) begin
            if (t_set == 32'h1) begin
                if (t_side) begin
                    tin_r1$7$d = c_slot$7;
                end
                else begin
                    tin_l1$7$d = c_slot$7;
                end
            end
            else if (t_side) begin
                tin_r0$7$d = c_slot$7;
            end
            else begin
                tin_l0$7$d = c_slot$7;
            end
        end
        tin_l0$8$clock = clock;
        tin_r0$8$clock = clock;
        tin_l1$8$clock = clock;
        tin_r1$8$clock = clock;
        tin_l0$8$d = tin_l0$8$q;
        tin_r0$8$d = tin_r0$8$q;
        tin_l1$8$d = tin_l1$8$q;
        tin_r1$8$d = tin_r1$8$q;
        if (t_valid & (t_entry == entry_of$8)) begin
            if (t_set == 32'h1) begin
                if (t_side) begin
                    tin_r1$8$d = c_slot$0;
                end
                else begin
                    tin_l1$8$d = c_slot$0;
                end
            end
            else if (t_side) begin
                tin_r0$8$d = c_slot$0;
            end
            else begin
                tin_l0$8$d = c_slot$0;
            end
        end
        tin_l0$9$clock = clock;
        tin_r0$9$clock = clock;
        tin_l1$9$clock = clock;
        tin_r1$9$clock = clock;
        tin_l0$9$d = tin_l0$9$q;
        tin_r0$9$d = tin_r0$9$q;
        tin_l1$9$d = tin_l1$9$q;
        tin_r1$9$d = tin_r1$9$q;
        if (t_valid & (t_entry == entry_of$9)) begin
            if (t_set == 32'h1) begin
                if (t_side) begin
                    tin_r1$9$d = c_slot$1;
                end
                else begin
                    tin_l1$9$d = c_slot$1;
                end
            end
            else if (t_side) begin
                tin_r0$9$d = c_slot$1;
            end
            else begin
                tin_l0$9$d = c_slot$1;
            end
        end
        tin_l0$10$clock = clock;
        tin_r0$10$clock = clock;
        tin_l1$10$clock = clock;
        tin_r1$10$clock = clock;
        tin_l0$10$d = tin_l0$10$q;
        tin_r0$10$d = tin_r0$10$q;
        tin_l1$10$d = tin_l1$10$q;
        tin_r1$10$d = tin_r1$10$q;
        if (t_valid & (t_entry == entry_of$10)) begin
            if (t_set == 32'h1) begin
                if (t_side) begin
                    tin_r1$10$d = c_slot$2;
                end
                else begin
                    tin_l1$10$d = c_slot$2;
                end
            end
            else if (t_side) begin
                tin_r0$10$d = c_slot$2;
            end
            else begin
                tin_l0$10$d = c_slot$2;
            end
        end
        tin_l0$11$clock = clock;
        tin_r0$11$clock = clock;
        tin_l1$11$clock = clock;
        tin_r1$11$clock = clock;
        tin_l0$11$d = tin_l0$11$q;
        tin_r0$11$d = tin_r0$11$q;
        tin_l1$11$d = tin_l1$11$q;
        tin_r1$11$d = tin_r1$11$q;
        if (t_valid & (t_entry == entry_of$11)) begin
            if (t_set == 32'h1) begin
                if (t_side) begin
                    tin_r1$11$d = c_slot$3;
                end
                else begin
                    tin_l1$11$d = c_slot$3;
                end
            end
            else if (t_side) begin
                tin_r0$11$d = c_slot$3;
            end
            else begin
                tin_l0$11$d = c_slot$3;
            end
        end
        tin_l0$12$clock = clock;
        tin_r0$12$clock = clock;
        tin_l1$12$clock = clock;
        tin_r1$12$clock = clock;
        tin_l0$12$d = tin_l0$12$q;
        tin_r0$12$d = tin_r0$12$q;
        tin_l1$12$d = tin_l1$12$q;
        tin_r1$12$d = tin_r1$12$q;
        if (t_valid & (t_entry == entry_of$12)) begin
            if (t_set == 32'h1) begin
                if (t_side) begin
                    tin_r1$12$d = c_slot$4;
                end
                else begin
                    tin_l1$12$d = c_slot$4;
                end
            end
            else if (t_side) begin
                tin_r0$12$d = c_slot$4;
            end
            else begin
                tin_l0$12$d = c_slot$4;
            end
        end
        tin_l0$13$clock = clock;
        tin_r0$13$clock = clock;
        tin_l1$13$clock = clock;
        tin_r1$13$clock = clock;
        tin_l0$13$d = tin_l0$13$q;
        tin_r0$13$d = tin_r0$13$q;
        tin_l1$13$d = tin_l1$13$q;
        tin_r1$13$d = tin_r1$13$q;
        if (t_valid & (t_entry == entry_of$13)) begin
            if (t_set == 32'h1) begin
                if (t_side) begin
                    tin_r1$13$d = c_slot$5;
                end
                else begin
                    tin_l1$13$d = c_slot$5;
                end
            end
            else if (t_side) begin
                tin_r0$13$d = c_slot$5;
            end
            else begin
                tin_l0$13$d = c_slot$5;
            end
        end
        tin_l0$14$clock = clock;
        tin_r0$14$clock = clock;
        tin_l1$14$clock = clock;
        tin_r1$14$clock = clock;
        tin_l0$14$d = tin_l0$14$q;
        tin_r0$14$d = tin_r0$14$q;
        tin_l1$14$d = tin_l1$14$q;
        tin_r1$14$d = tin_r1$14$q;
        if (t_valid & (t_entry == entry_of$14)) begin
            if (t_set == 32'h1) begin
                if (t_side) begin
                    tin_r1$14$d = c_slot$6;
                end
                else begin
                    tin_l1$14$d = c_slot$6;
                end
            end
            else if (t_side) begin
                tin_r0$14$d = c_slot$6;
            end
            else begin
                tin_l0$14$d = c_slot$6;
            end
        end
        tin_l0$15$clock = clock;
        tin_r0$15$clock = clock;
        tin_l1$15$clock = clock;
        tin_r1$15$clock = clock;
        tin_l0$15$d = tin_l0$15$q;
        tin_r0$15$d = tin_r0$15$q;
        tin_l1$15$d = tin_l1$15$q;
        tin_r1$15$d = tin_r1$15$q;
        if (t_valid & (t_entry == entry_of$15)) begin
            if (t_set == 32'h1) begin
                if (t_side) begin
                    tin_r1$15$d = c_slot$7;
                end
                else begin
                    tin_l1$15$d = c_slot$7;
                end
            end
            else if (t_side) begin
                tin_r0$15$d = c_slot$7;
            end
            else begin
                tin_l0$15$d = c_slot$7;
            end
        end
        tin_l0$16$clock = clock;
        tin_r0$16$clock = clock;
        tin_l1$16$clock = clock;
        tin_r1$16$clock = clock;
        tin_l0$16$d = tin_l0$16$q;
        tin_r0$16$d = tin_r0$16$q;
        tin_l1$16$d = tin_l1$16$q;
        tin_r1$16$d = tin_r1$16$q;
        if (t_valid & (t_entry == entry_of$16)) begin
            if (t_set == 32'h1) begin
                if (t_side) begin
                    tin_r1$16$d = c_slot$0;
                end
                else begin
                    tin_l1$16$d = c_slot$0;
                end
            end
            else if (t_side) begin
                tin_r0$16$d = c_slot$0;
            end
            else begin
                tin_l0$16$d = c_slot$0;
            end
        end
        tin_l0$17$clock = clock;
        tin_r0$17$clock = clock;
        tin_l1$17$clock = clock;
        tin_r1$17$clock = clock;
        tin_l0$17$d = tin_l0$17$q;
        tin_r0$17$d = tin_r0$17$q;
        tin_l1$17$d = tin_l1$17$q;
        tin_r1$17$d = tin_r1$17$q;
        if (t_valid & (t_entry == entry_of$17)) begin
            if (t_set == 32'h1) begin
                if (t_side) begin
                    tin_r1$17$d = c_slot$1;
                end
                else begin
                    tin_l1$17$d = c_slot$1;
                end
            end
            else if (t_side) begin
                tin_r0$17$d = c_slot$1;
            end
            else begin
                tin_l0$17$d = c_slot$1;
            end
        end
        tin_l0$18$clock = clock;
        tin_r0$18$clock = clock;
        tin_l1$18$clock = clock;
        tin_r1$18$clock = clock;
        tin_l0$18$d = tin_l0$18$q;
        tin_r0$18$d = tin_r0$18$q;
        tin_l1$18$d = tin_l1$18$q;
        tin_r1$18$d = tin_r1$18$q;
        if (t_valid & (t_entry == entry_of$18)) begin
            if (t_set == 32'h1) begin
                if (t_side) begin
                    tin_r1$18$d = c_slot$2;
                end
                else begin
                    tin_l1$18$d = c_slot$2;
                end
            end
            else if (t_side) begin
                tin_r0$18$d = c_slot$2;
            end
            else begin
                tin_l0$18$d = c_slot$2;
            end
        end
        tin_l0$19$clock = clock;
        tin_r0$19$clock = clock;
        tin_l1$19$clock = clock;
        tin_r1$19$clock = clock;
        tin_l0$19$d = tin_l0$19$q;
        tin_r0$19$d = tin_r0$19$q;
        tin_l1$19$d = tin_l1$19$q;
        tin_r1$19$d = tin_r1$19$q;
        if (t_valid & (t_entry == entry_of$19)) begin
            if (t_set == 32'h1) begin
                if (t_side) begin
                    tin_r1$19$d = c_slot$3;
                end
                else begin
                    tin_l1$19$d = c_slot$3;
                end
            end
            else if (t_side) begin
                tin_r0$19$d = c_slot$3;
            end
            else begin
                tin_l0$19$d = c_slot$3;
            end
        end
        tin_l0$20$clock = clock;
        tin_r0$20$clock = clock;
        tin_l1$20$clock = clock;
        tin_r1$20$clock = clock;
        tin_l0$20$d = tin_l0$20$q;
        tin_r0$20$d = tin_r0$20$q;
        tin_l1$20$d = tin_l1$20$q;
        tin_r1$20$d = tin_r1$20$q;
        if (t_valid & (t_entry == entry_of$20)) begin
            if (t_set == 32'h1) begin
                if (t_side) begin
                    tin_r1$20$d = c_slot$4;
                end
                else begin
                    tin_l1$20$d = c_slot$4;
                end
            end
            else if (t_side) begin
                tin_r0$20$d = c_slot$4;
            end
            else begin
                tin_l0$20$d = c_slot$4;
            end
        end
        tin_l0$21$clock = clock;
        tin_r0$21$clock = clock;
        tin_l1$21$clock = clock;
        tin_r1$21$clock = clock;
        tin_l0$21$d = tin_l0$21$q;
        tin_r0$21$d = tin_r0$21$q;
        tin_l1$21$d = tin_l1$21$q;
        tin_r1$21$d = tin_r1$21$q;
        if (t_valid & (t_entry == entry_of$21)) begin
            if (t_set == 32'h1) begin
                if (t_side) begin
                    tin_r1$21$d = c_slot$5;
                end
                else begin
                    tin_l1$21$d = c_slot$5;
                end
            end
            else if (t_side) begin
                tin_r0$21$d = c_slot$5;
            end
            else begin
                tin_l0$21$d = c_slot$5;
            end
        end
        tin_l0$22$clock = clock;
        tin_r0$22$clock = clock;
        tin_l1$22$clock = clock;
        tin_r1$22$clock = clock;
        tin_l0$22$d = tin_l0$22$q;
        tin_r0$22$d = tin_r0$22$q;
        tin_l1$22$d = tin_l1$22$q;
        tin_r1$22$d = tin_r1$22$q;
        if (t_valid & (t_entry == entry_of$22)) begin
            if (t_set == 32'h1) begin
                if (t_side) begin
                    tin_r1$22$d = c_slot$6;
                end
                else begin
                    tin_l1$22$d = c_slot$6;
                end
            end
            else if (t_side) begin
                tin_r0$22$d = c_slot$6;
            end
            else begin
                tin_l0$22$d = c_slot$6;
            end
        end
        tin_l0$23$clock = clock;
        tin_r0$23$clock = clock;
        tin_l1$23$clock = clock;
        tin_r1$23$clock = clock;
        tin_l0$23$d = tin_l0$23$q;
        tin_r0$23$d = tin_r0$23$q;
        tin_l1$23$d = tin_l1$23$q;
        tin_r1$23$d = tin_r1$23$q;
        if (t_valid & (t_entry == entry_of$23)) begin
            if (t_set == 32'h1) begin
                if (t_side) begin
                    tin_r1$23$d = c_slot$7;
                end
                else begin
                    tin_l1$23$d = c_slot$7;
                end
            end
            else if (t_side) begin
                tin_r0$23$d = c_slot$7;
            end
            else begin
                tin_l0$23$d = c_slot$7;
            end
        end
        gen_run$clock = clock;
        gen_cnt$clock = clock;
        gen_set$clock = clock;
        pend$clock = clock;
        s1_valid$clock = clock;
        s1_set$clock = clock;
        s1_lane$clock = clock;
        s1_last$clock = clock;
        gen_run$d = gen_run$q;
        gen_cnt$d = gen_cnt$q;
        gen_set$d = gen_set$q;
        pend$d = pend$q;
        s1_valid$d = s1_valid$q;
        s1_set$d = s1_set$q;
        s1_lane$d = s1_lane$q;
        s1_last$d = s1_last$q;
        c_row_last = gen_run$q & (gen_cnt$q == last_row);
        c_go = (~gen_run$q | c_row_last) & ((pend$q != 32'h0) | (t_valid & t_last));
        c_go_set = t_set;
        if (pend$q[32'h1]) begin
            c_go_set = 32'h1;
        end
        if (pend$q[32'h0]) begin
            c_go_set = 32'h0;
        end
        c_t_set = 32'h1;
        if (t_set == 32'h1) begin
            c_t_set = 32'h2;
        end
        c_go_mask = 32'h0;
        if (c_go) begin
            c_go_mask = 32'h1;
            if (c_go_set == 32'h1) begin
                c_go_mask = 32'h2;
            end
        end
        c_pend_set = 32'h0;
        c_busy_set = 32'h0;
        if (t_valid) begin
            c_busy_set = c_t_set;
            if (t_last) begin
                c_pend_set = c_t_set;
            end
        end
        pend$d = (pend$q | c_pend_set) & ~c_go_mask;
        gen_run$d = gen_run$q & ~c_row_last;
        gen_cnt$d = 32'h0;
        if (gen_run$q & ~c_row_last) begin
            gen_cnt$d = gen_cnt$q + 32'h1;
        end
        gen_set$d = gen_set$q;
        if (c_go) begin
            gen_run$d = 1'b1;
            gen_set$d = c_go_set;
        end
        s1_valid$d = gen_run$q;
        s1_set$d = gen_set$q;
        s1_lane$d = gen_cnt$q;
        s1_last$d = 32'h0;
        if (c_row_last) begin
            s1_last$d = 32'h1;
        end
        c_ctl = mmm$4$read_data;
        if (s1_set$q == 32'h1) begin
            klm_l$d$0 = tin_l1$0$q;
            klm_r$d$0 = tin_r1$0$q;
        end
        else begin
            klm_l$d$0 = tin_l0$0$q;
            klm_r$d$0 = tin_r0$0$q;
        end
        if (s1_set$q == 32'h1) begin
            klm_l$d$1 = tin_l1$1$q;
            klm_r$d$1 = tin_r1$1$q;
        end
        else begin
            klm_l$d$1 = tin_l0$1$q;
            klm_r$d$1 = tin_r0$1$q;
        end
        if (s1_set$q == 32'h1) begin
            klm_l$d$2 = tin_l1$2$q;
            klm_r$d$2 = tin_r1$2$q;
        end
        else begin
            klm_l$d$2 = tin_l0$2$q;
            klm_r$d$2 = tin_r0$2$q;
        end
        if (s1_set$q == 32'h1) begin
            klm_l$d$3 = tin_l1$3$q;
            klm_r$d$3 = tin_r1$3$q;
        end
        else begin
            klm_l$d$3 = tin_l0$3$q;
            klm_r$d$3 = tin_r0$3$q;
        end
        if (s1_set$q == 32'h1) begin
            klm_l$d$4 = tin_l1$4$q;
            klm_r$d$4 = tin_r1$4$q;
        end
        else begin
            klm_l$d$4 = tin_l0$4$q;
            klm_r$d$4 = tin_r0$4$q;
        end
        if (s1_set$q == 32'h1) begin
            klm_l$d$5 = tin_l1$5$q;
            klm_r$d$5 = tin_r1$5$q;
        end
        else begin
            klm_l$d$5 = tin_l0$5$q;
            klm_r$d$5 = tin_r0$5$q;
        end
        if (s1_set$q == 32'h1) begin
            klm_l$d$6 = tin_l1$6$q;
            klm_r$d$6 = tin_r1$6$q;
        end
        else begin
            klm_l$d$6 = tin_l0$6$q;
            klm_r$d$6 = tin_r0$6$q;
        end
        if (s1_set$q == 32'h1) begin
            klm_l$d$7 = tin_l1$7$q;
            klm_r$d$7 = tin_r1$7$q;
        end
        else begin
            klm_l$d$7 = tin_l0$7$q;
            klm_r$d$7 = tin_r0$7$q;
        end
        if (s1_set$q == 32'h1) begin
            klm_l$d$8 = tin_l1$8$q;
            klm_r$d$8 = tin_r1$8$q;
        end
        else begin
            klm_l$d$8 = tin_l0$8$q;
            klm_r$d$8 = tin_r0$8$q;
        end
        if (s1_set$q == 32'h1) begin
            klm_l$d$9 = tin_l1$9$q;
            klm_r$d$9 = tin_r1$9$q;
        end
        else begin
            klm_l$d$9 = tin_l0$9$q;
            klm_r$d$9 = tin_r0$9$q;
        end
        if (s1_set$q == 32'h1) begin
            klm_l$d$10 = tin_l1$10$q;
            klm_r$d$10 = tin_r1$10$q;
        end
        else begin
            klm_l$d$10 = tin_l0$10$q;
            klm_r$d$10 = tin_r0$10$q;
        end
        if (s1_set$q == 32'h1) begin
            klm_l$d$11 = tin_l1$11$q;
            klm_r$d$11 = tin_r1$11$q;
        end
        else begin
            klm_l$d$11 = tin_l0$11$q;
            klm_r$d$11 = tin_r0$11$q;
        end
        if (s1_set$q == 32'h1) begin
            klm_l$d$12 = tin_l1$12$q;
            klm_r$d$12 = tin_r1$12$q;
        end
        else begin
            klm_l$d$12 = tin_l0$12$q;
            klm_r$d$12 = tin_r0$12$q;
        end
        if (s1_set$q == 32'h1) begin
            klm_l$d$13 = tin_l1$13$q;
            klm_r$d$13 = tin_r1$13$q;
        end
        else begin
            klm_l$d$13 = tin_l0$13$q;
            klm_r$d$13 = tin_r0$13$q;
        end
        if (s1_set$q == 32'h1) begin
            klm_l$d$14 = tin_l1$14$q;
            klm_r$d$14 = tin_r1$14$q;
        end
        else begin
            klm_l$d$14 = tin_l0$14$q;
            klm_r$d$14 = tin_r0$14$q;
        end
        if (s1_set$q == 32'h1) begin
            klm_l$d$15 = tin_l1$15$q;
            klm_r$d$15 = tin_r1$15$q;
        end
        else begin
            klm_l$d$15 = tin_l0$15$q;
            klm_r$d$15 = tin_r0$15$q;
        end
        if (s1_set$q == 32'h1) begin
            klm_l$d$16 = tin_l1$16$q;
            klm_r$d$16 = tin_r1$16$q;
        end
        else begin
            klm_l$d$16 = tin_l0$16$q;
            klm_r$d$16 = tin_r0$16$q;
        end
        if (s1_set$q == 32'h1) begin
            klm_l$d$17 = tin_l1$17$q;
            klm_r$d$17 = tin_r1$17$q;
        end
        else begin
            klm_l$d$17 = tin_l0$17$q;
            klm_r$d$17 = tin_r0$17$q;
        end
        if (s1_set$q == 32'h1) begin
            klm_l$d$18 = tin_l1$18$q;
            klm_r$d$18 = tin_r1$18$q;
        end
        else begin
            klm_l$d$18 = tin_l0$18$q;
            klm_r$d$18 = tin_r0$18$q;
        end
        if (s1_set$q == 32'h1) begin
            klm_l$d$19 = tin_l1$19$q;
            klm_r$d$19 = tin_r1$19$q;
        end
        else begin
            klm_l$d$19 = tin_l0$19$q;
            klm_r$d$19 = tin_r0$19$q;
        end
        if (s1_set$q == 32'h1) begin
            klm_l$d$20 = tin_l1$20$q;
            klm_r$d$20 = tin_r1$20$q;
        end
        else begin
            klm_l$d$20 = tin_l0$20$q;
            klm_r$d$20 = tin_r0$20$q;
        end
        if (s1_set$q == 32'h1) begin
            klm_l$d$21 = tin_l1$21$q;
            klm_r$d$21 = tin_r1$21$q;
        end
        else begin
            klm_l$d$21 = tin_l0$21$q;
            klm_r$d$21 = tin_r0$21$q;
        end
        if (s1_set$q == 32'h1) begin
            klm_l$d$22 = tin_l1$22$q;
            klm_r$d$22 = tin_r1$22$q;
        end
        else begin
            klm_l$d$22 = tin_l0$22$q;
            klm_r$d$22 = tin_r0$22$q;
        end
        if (s1_set$q == 32'h1) begin
            klm_l$d$23 = tin_l1$23$q;
            klm_r$d$23 = tin_r1$23$q;
        end
        else begin
            klm_l$d$23 = tin_l0$23$q;
            klm_r$d$23 = tin_r0$23$q;
        end
        klm_l$j0$0 = c_ctl[(32'h0)+:(5)];
        klm_l$j1$0 = c_ctl[(32'h5)+:(5)];
        klm_l$j2$0 = c_ctl[(32'ha)+:(5)];
        klm_r$j0$0 = c_ctl[(32'h0)+:(5)];
        klm_r$j1$0 = c_ctl[(32'h5)+:(5)];
        klm_r$j2$0 = c_ctl[(32'ha)+:(5)];
        dot_l$clock = clock;
        dot_l$valid_in = s1_valid$q;
        dot_l$round_up = c_ctl[32'hf];
        dot_l$c0 = mmm$0$read_data;
        dot_l$c1 = mmm$1$read_data;
        dot_l$c2 = mmm$2$read_data;
        dot_l$c = mmm$3$read_data;
        dot_l$d0 = klm_l$y0$0;
        dot_l$d1 = klm_l$y1$0;
        dot_l$d2 = klm_l$y2$0;
        dot_r$clock = clock;
        dot_r$valid_in = s1_valid$q;
        dot_r$round_up = c_ctl[32'hf];
        dot_r$c0 = mmm$0$read_data;
        dot_r$c1 = mmm$1$read_data;
        dot_r$c2 = mmm$2$read_data;
        dot_r$c = mmm$3$read_data;
        dot_r$d0 = klm_r$y0$0;
        dot_r$d1 = klm_r$y1$0;
        dot_r$d2 = klm_r$y2$0;
        busy_r$clock = clock;
        sa_valid$clock = clock;
        sa_first$clock = clock;
        sa_lanes$clock = clock;
        sa_e$clock = clock;
        busy_r$d = busy_r$q;
        sa_valid$d = sa_valid$q;
        sa_first$d = sa_first$q;
        sa_lanes$d = sa_lanes$q;
        sa_e$d = sa_e$q;
        wr_tag$clock = clock;
        wr_tag$d = ((s1_lane$q) & 7'h7f) | (((s1_set$q) & 7'h7f) << 32'h5) | (((s1_last$q) & 7'h7f) << 32'h6);
        c_wr_set = wr_tag$q[(32'h5)+:(1)];
        dprime$clock = clock;
        dprime$wr_valid = dot_l$valid_out;
        dprime$wr_set = c_wr_set;
        dprime$wr_lane = wr_tag$q[(32'h0)+:(5)];
        dprime$wr_l = dot_l$u;
        dprime$wr_r = dot_r$u;
        c_busy_clr = 32'h0;
        if (dot_l$valid_out & wr_tag$q[32'h6]) begin
            c_busy_clr = 32'h1;
            if (c_wr_set == 32'h1) begin
                c_busy_clr = 32'h2;
            end
        end
        busy_r$d = (busy_r$q & ~c_busy_clr) | c_busy_set;
        busy = busy_r$q;
        dprime$rd_set = a_set;
        dprime$rd_entry = a_entry;
        sa_valid$d = a_valid;
        sa_first$d = a_first;
        sa_lanes$d = a_lanes;
        sa_e$d = e;
        bank$clock = clock;
        bank$valid_in = sa_valid$q;
        bank$first = sa_first$q;
        bank$lanes = sa_lanes$q;
        bank$e = sa_e$q;
        bank$dl = dprime$dl;
        bank$dr = dprime$dr;
        overlap_l = bank$overlap_l;
        overlap_r = bank$overlap_r;
        flags_valid = bank$valid_out;
    end
    
endmodule // top$core$dop


module top$core$dop$bank(clock,valid_in,first,lanes,e,dl,dr,overlap_l,overlap_r,valid_out);
    
    // Module arguments
    input wire  clock;
    input wire  valid_in;
    input wire  first;
    input wire  [7:0] lanes;
    input wire  [255:0] e;
    input wire  [255:0] dl;
    input wire  [255:0] dr;
    output reg  overlap_l;
    output reg  overlap_r;
    output reg  valid_out;
    
    // Stub signals
    reg  cmp_l0$clock;
    reg  [31:0] cmp_l0$a;
    reg  [31:0] cmp_l0$b;
    reg  cmp_l0$valid_in;
    wire  cmp_l0$flag;
    wire  cmp_l0$valid_out;
    reg  cmp_r0$clock;
    reg  [31:0] cmp_r0$a;
    reg  [31:0] cmp_r0$b;
    reg  cmp_r0$valid_in;
    wire  cmp_r0$flag;
    wire  cmp_r0$valid_out;
    reg  cmp_l1$clock;
    reg  [31:0] cmp_l1$a;
    reg  [31:0] cmp_l1$b;
    reg  cmp_l1$valid_in;
    wire  cmp_l1$flag;
    wire  cmp_l1$valid_out;
    reg  cmp_r1$clock;
    reg  [31:0] cmp_r1$a;
    reg  [31:0] cmp_r1$b;
    reg  cmp_r1$valid_in;
    wire  cmp_r1$flag;
    wire  cmp_r1$valid_out;
    reg  cmp_l2$clock;
    reg  [31:0] cmp_l2$a;
    reg  [31:0] cmp_l2$b;
    reg  cmp_l2$valid_in;
    wire  cmp_l2$flag;
    wire  cmp_l2$valid_out;
    reg  cmp_r2$clock;
    reg  [31:0] cmp_r2$a;
    reg  [31:0] cmp_r2$b;
    reg  cmp_r2$valid_in;
    wire  cmp_r2$flag;
    wire  cmp_r2$valid_out;
    reg  cmp_l3$clock;
    reg  [31:0] cmp_l3$a;
    reg  [31:0] cmp_l3$b;
    reg  cmp_l3$valid_in;
    wire  cmp_l3$flag;
    wire  cmp_l3$valid_out;
    reg  cmp_r3$clock;
    reg  [31:0] cmp_r3$a;
    reg  [31:0] cmp_r3$b;
    reg  cmp_r3$valid_in;
    wire  cmp_r3$flag;
    wire  cmp_r3$valid_out;
    reg  cmp_l4$clock;
    reg  [31:0] cmp_l4$a;
    reg  [31:0] cmp_l4$b;
    reg  cmp_l4$valid_in;
    wire  cmp_l4$flag;
    wire  cmp_l4$valid_out;
    reg  cmp_r4$clock;
    reg  [31:0] cmp_r4$a;
    reg  [31:0] cmp_r4$b;
    reg  cmp_r4$valid_in;
    wire  cmp_r4$flag;
    wire  cmp_r4$valid_out;
    reg  cmp_l5$clock;
    reg  [31:0] cmp_l5$a;
    reg  [31:0] cmp_l5$b;
    reg  cmp_l5$valid_in;
    wire  cmp_l5$flag;
    wire  cmp_l5$valid_out;
    reg  cmp_r5$clock;
    reg  [31:0] cmp_r5$a;
    reg  [31:0] cmp_r5$b;
    reg  cmp_r5$valid_in;
    wire  cmp_r5$flag;
    wire  cmp_r5$valid_out;
    reg  cmp_l6$clock;
    reg  [31:0] cmp_l6$a;
    reg  [31:0] cmp_l6$b;
    reg  cmp_l6$valid_in;
    wire  cmp_l6$flag;
    wire  cmp_l6$valid_out;
    reg  cmp_r6$clock;
    reg  [31:0] cmp_r6$a;
    reg  [31:0] cmp_r6$b;
    reg  cmp_r6$valid_in;
    wire  cmp_r6$flag;
    wire  cmp_r6$valid_out;
    reg  cmp_l7$clock;
    reg  [31:0] cmp_l7$a;
    reg  [31:0] cmp_l7$b;
    reg  cmp_l7$valid_in;
    wire  cmp_l7$flag;
    wire  cmp_l7$valid_out;
    reg  cmp_r7$clock;
    reg  [31:0] cmp_r7$a;
    reg  [31:0] cmp_r7$b;
    reg  cmp_r7$valid_in;
    wire  cmp_r7$flag;
    wire  cmp_r7$valid_out;
    reg  s1_first$d;
    wire  s1_first$q;
    reg  s1_first$clock;
    reg  [7:0] s1_lanes$d;
    wire  [7:0] s1_lanes$q;
    reg  s1_lanes$clock;
    reg  s2_sep_l$d;
    wire  s2_sep_l$q;
    reg  s2_sep_l$clock;
    reg  s2_sep_r$d;
    wire  s2_sep_r$q;
    reg  s2_sep_r$clock;
    reg  s2_valid$d;
    wire  s2_valid$q;
    reg  s2_valid$clock;
    
    // Local signals
    reg  c2_any_l;
    reg  c2_any_r;
    
    // Sub module instances
    top$core$dop$bank$cmp_l0 cmp_l0(
        .clock(cmp_l0$clock),
        .a(cmp_l0$a),
        .b(cmp_l0$b),
        .valid_in(cmp_l0$valid_in),
        .flag(cmp_l0$flag),
        .valid_out(cmp_l0$valid_out)
    );
    top$core$dop$bank$cmp_l0 cmp_r0(
        .clock(cmp_r0$clock),
        .a(cmp_r0$a),
        .b(cmp_r0$b),
        .valid_in(cmp_r0$valid_in),
        .flag(cmp_r0$flag),
        .valid_out(cmp_r0$valid_out)
    );
    top$core$dop$bank$cmp_l0 cmp_l1(
        .clock(cmp_l1$clock),
        .a(cmp_l1$a),
        .b(cmp_l1$b),
        .valid_in(cmp_l1$valid_in),
        .flag(cmp_l1$flag),
        .valid_out(cmp_l1$valid_out)
    );
    top$core$dop$bank$cmp_l0 cmp_r1(
        .clock(cmp_r1$clock),
        .a(cmp_r1$a),
        .b(cmp_r1$b),
        .valid_in(cmp_r1$valid_in),
        .flag(cmp_r1$flag),
        .valid_out(cmp_r1$valid_out)
    );
    top$core$dop$bank$cmp_l0 cmp_l2(
        .clock(cmp_l2$clock),
        .a(cmp_l2$a),
        .b(cmp_l2$b),
        .valid_in(cmp_l2$valid_in),
        .flag(cmp_l2$flag),
        .valid_out(cmp_l2$valid_out)
    );
    top$core$dop$bank$cmp_l0 cmp_r2(
        .clock(cmp_r2$clock),
        .a(cmp_r2$a),
        .b(cmp_r2$b),
        .valid_in(cmp_r2$valid_in),
        .flag(cmp_r2$flag),
        .valid_out(cmp_r2$valid_out)
    );
    top$core$dop$bank$cmp_l0 cmp_l3(
        .clock(cmp_l3$clock),
        .a(cmp_l3$a),
        .b(cmp_l3$b),
        .valid_in(cmp_l3$valid_in),
        .flag(cmp_l3$flag),
        .valid_out(cmp_l3$valid_out)
    );
    top$core$dop$bank$cmp_l0 cmp_r3(
        .clock(cmp_r3$clock),
        .a(cmp_r3$a),
        .b(cmp_r3$b),
        .valid_in(cmp_r3$valid_in),
        .flag(cmp_r3$flag),
        .valid_out(cmp_r3$valid_out)
    );
    top$core$dop$bank$cmp_l0 cmp_l4(
        .clock(cmp_l4$clock),
        .a(cmp_l4$a),
        .b(cmp_l4$b),
        .valid_in(cmp_l4$valid_in),
        .flag(cmp_l4$flag),
        .valid_out(cmp_l4$valid_out)
    );
    top$core$dop$bank$cmp_l0 cmp_r4(
        .clock(cmp_r4$clock),
        .a(cmp_r4$a),
        .b(cmp_r4$b),
        .valid_in(cmp_r4$valid_in),
        .flag(cmp_r4$flag),
        .valid_out(cmp_r4$valid_out)
    );
    top$core$dop$bank$cmp_l0 cmp_l5(
        .clock(cmp_l5$clock),
        .a(cmp_l5$a),
        .b(cmp_l5$b),
        .valid_in(cmp_l5$valid_in),
        .flag(cmp_l5$flag),
        .valid_out(cmp_l5$valid_out)
    );
    top$core$dop$bank$cmp_l0 cmp_r5(
        .clock(cmp_r5$clock),
        .a(cmp_r5$a),
        .b(cmp_r5$b),
        .valid_in(cmp_r5$valid_in),
        .flag(cmp_r5$flag),
        .valid_out(cmp_r5$valid_out)
    );
    top$core$dop$bank$cmp_l0 cmp_l6(
        .clock(cmp_l6$clock),
        .a(cmp_l6$a),
        .b(cmp_l6$b),
        .valid_in(cmp_l6$valid_in),
        .flag(cmp_l6$flag),
        .valid_out(cmp_l6$valid_out)
    );
    top$core$dop$bank$cmp_l0 cmp_r6(
        .clock(cmp_r6$clock),
        .a(cmp_r6$a),
        .b(cmp_r6$b),
        .valid_in(cmp_r6$valid_in),
        .flag(cmp_r6$flag),
        .valid_out(cmp_r6$valid_out)
    );
    top$core$dop$bank$cmp_l0 cmp_l7(
        .clock(cmp_l7$clock),
        .a(cmp_l7$a),
        .b(cmp_l7$b),
        .valid_in(cmp_l7$valid_in),
        .flag(cmp_l7$flag),
        .valid_out(cmp_l7$valid_out)
    );
    top$core$dop$bank$cmp_l0 cmp_r7(
        .clock(cmp_r7$clock),
        .a(cmp_r7$a),
        .b(cmp_r7$b),
        .valid_in(cmp_r7$valid_in),
        .flag(cmp_r7$flag),
        .valid_out(cmp_r7$valid_out)
    );
    top$core$done_r s1_first(
        .d(s1_first$d),
        .q(s1_first$q),
        .clock(s1_first$clock)
    );
    top$core$dop$bank$s1_lanes s1_lanes(
        .d(s1_lanes$d),
        .q(s1_lanes$q),
        .clock(s1_lanes$clock)
    );
    top$core$done_r s2_sep_l(
        .d(s2_sep_l$d),
        .q(s2_sep_l$q),
        .clock(s2_sep_l$clock)
    );
    top$core$done_r s2_sep_r(
        .d(s2_sep_r$d),
        .q(s2_sep_r$q),
        .clock(s2_sep_r$clock)
    );
    top$core$done_r s2_valid(
        .d(s2_valid$d),
        .q(s2_valid$q),
        .clock(s2_valid$clock)
    );
    
    // Update code
    always @(*) begin
        s1_first$clock = clock;
        s1_lanes$clock = clock;
        s2_sep_l$clock = clock;
        s2_sep_r$clock = clock;
        s2_valid$clock = clock;
        s1_first$d = s1_first$q;
        s1_lanes$d = s1_lanes$q;
        s2_sep_l$d = s2_sep_l$q;
        s2_sep_r$d = s2_sep_r$q;
        s2_valid$d = s2_valid$q;
        cmp_l0$clock = clock;
        cmp_l0$a = dl[(32'h0)+:(32)];
        cmp_l0$b = e[(32'h0)+:(32)];
        cmp_l0$valid_in = valid_in;
        cmp_r0$clock = clock;
        cmp_r0$a = dr[(32'h0)+:(32)];
        cmp_r0$b = e[(32'h0)+:(32)];
        cmp_r0$valid_in = valid_in;
        cmp_l1$clock = clock;
        cmp_l1$a = dl[(32'h20)+:(32)];
        cmp_l1$b = e[(32'h20)+:(32)];
        cmp_l1$valid_in = valid_in;
        cmp_r1$clock = clock;
        cmp_r1$a = dr[(32'h20)+:(32)];
        cmp_r1$b = e[(32'h20)+:(32)];
        cmp_r1$valid_in = valid_in;
        cmp_l2$clock = clock;
        cmp_l2$a = dl[(32'h40)+:(32)];
        cmp_l2$b = e[(32'h40)+:(32)];
        cmp_l2$valid_in = valid_in;
        cmp_r2$clock = clock;
        cmp_r2$a = dr[(32'h40)+:(32)];
        cmp_r2$b = e[(32'h40)+:(32)];
        cmp_r2$valid_in = valid_in;
        cmp_l3$clock = clock;
        cmp_l3$a = dl[(32'h60)+:(32)];
        cmp_l3$b = e[(32'h60)+:(32)];
        cmp_l3$valid_in = valid_in;
        cmp_r3$clock = clock;
        cmp_r3$a = dr[(32'h60)+:(32)];
        cmp_r3$b = e[(32'h60)+:(32)];
        cmp_r3$valid_in = valid_in;
        cmp_l4$clock = clock;
        cmp_l4$a = dl[(32'h80)+:(32)];
        cmp_l4$b = e[(32'h80)+:(32)];
        cmp_l4$valid_in = valid_in;
        cmp_r4$clock = clock;
        cmp_r4$a = dr[(32'h80)+:(32)];
        cmp_r4$b = e[(32'h80)+:(32)];
        cmp_r4$valid_in = valid_in;
        cmp_l5$clock = clock;
        cmp_l5$a = dl[(32'ha0)+:(32)];
        cmp_l5$b = e[(32'ha0)+:(32)];
        cmp_l5$valid_in = valid_in;
        cmp_r5$clock = clock;
        cmp_r5$a = dr[(32'ha0)+:(32)];
        cmp_r5$b = e[(32'ha0)+:(32)];
        cmp_r5$valid_in = valid_in;
        cmp_l6$clock = clock;
        cmp_l6$a = dl[(32'hc0)+:(32)];
        cmp_l6$b = e[(32'hc0)+:(32)];
        cmp_l6$valid_in = valid_in;
        cmp_r6$clock = clock;
        cmp_r6$a = dr[(32'hc0)+:(32)];
        cmp_r6$b = e[(32'hc0)+:(32)];
        cmp_r6$valid_in = valid_in;
        cmp_l7$clock = clock;
        cmp_l7$a = dl[(32'he0)+:(32)];
        cmp_l7$b = e[(32'he0)+:(32)];
        cmp_l7$valid_in = valid_in;
        cmp_r7$clock = clock;
        cmp_r7$a = dr[(32'he0)+:(32)];
        cmp_r7$b = e[(32'he0)+:(32)];
        cmp_r7$valid_in = valid_in;
        s1_first$d = first;
        s1_lanes$d = lanes;
        c2_any_l = 1'b0;
        c2_any_r = 1'b0;
        if (cmp_l0$flag & s1_lanes$q[32'h0]) begin
            c2_any_l = 1'b1;
        end
        if (cmp_r0$flag & s1_lanes$q[32'h0]) begin
            c2_any_r = 1'b1;
        end
        if (cmp_l1$flag & s1_lanes$q[32'h1]) begin
            c2_any_l = 1'b1;
        end
        if (cmp_r1$flag & s1_lanes$q[32'h1]) begin
            c2_any_r = 1'b1;
        end
        if (cmp_l2$flag & s1_lanes$q[32'h2]) begin
            c2_any_l = 1'b1;
        end
        if (cmp_r2$flag & s1_lanes$q[32'h2]) begin
            c2_any_r = 1'b1;
        end
        if (cmp_l3$flag & s1_lanes$q[32'h3]) begin
            c2_any_l = 1'b1;
        end
        if (cmp_r3$flag & s1_lanes$q[32'h3]) begin
            c2_any_r = 1'b1;
        end
        if (cmp_l4$flag & s1_lanes$q[32'h4]) begin
            c2_any_l = 1'b1;
        end
        if (cmp_r4$flag & s1_lanes$q[32'h4]) begin
            c2_any_r = 1'b1;
        end
        if (cmp_l5$flag & s1_lanes$q[32'h5]) begin
            c2_any_l = 1'b1;
        end
        if (cmp_r5$flag & s1_lanes$q[32'h5]) begin
            c2_any_r = 1'b1;
        end
        if (cmp_l6$flag & s1_lanes$q[32'h6]) begin
            c2_any_l = 1'b1;
        end
        if (cmp_r6$flag & s1_lanes$q[32'h6]) begin
            c2_any_r = 1'b1;
        end
        if (cmp_l7$flag & s1_lanes$q[32'h7]) begin
            c2_any_l = 1'b1;
        end
        if (cmp_r7$flag & s1_lanes$q[32'h7]) begin
            c2_any_r = 1'b1;
        end
        s2_valid$d = cmp_l0$valid_out;
        if (cmp_l0$valid_out) begin
            s2_sep_l$d = c2_any_l | (s2_sep_l$q & ~s1_first$q);
            s2_sep_r$d = c2_any_r | (s2_sep_r$q & ~s1_first$q);
        end
        overlap_l = ~s2_sep_l$q;
        overlap_r = ~s2_sep_r$q;
        valid_out = s2_valid$q;
    end
    
endmodule // top$core$dop$bank


module top$core$dop$bank$cmp_l0(clock,a,b,valid_in,flag,valid_out);
    
    // Module arguments
    input wire  clock;
    input wire  [31:0] a;
    input wire  [31:0] b;
    input wire  valid_in;
    output reg  flag;
    output reg  valid_out;
    
    // Constant declarations
    localparam  c_inf = 31'h7f800000;
    
    // Stub signals
    reg  s1_flag$d;
    wire  s1_flag$q;
    reg  s1_flag$clock;
    reg  s1_valid$d;
    wire  s1_valid$q;
    reg  s1_valid$clock;
    
    // Local signals
    reg  [30:0] mag_a;
    reg  [30:0] mag_b;
    
    // Sub module instances
    top$core$done_r s1_flag(
        .d(s1_flag$d),
        .q(s1_flag$q),
        .clock(s1_flag$clock)
    );
    top$core$done_r s1_valid(
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
        mag_a = a[(32'h0)+:(31)];
        mag_b = b[(32'h0)+:(31)];
        s1_flag$d = 1'b0;
        if ((mag_a <= c_inf) & (mag_b <= c_inf)) begin
            if (a[32'h1f] & b[32'h1f]) begin
                s1_flag$d = |mag_a | |mag_b;
            end
            if (a[32'h1f] & ~b[32'h1f]) begin
                s1_flag$d = mag_a > mag_b;
            end
            if (~a[32'h1f] & b[32'h1f]) begin
                s1_flag$d = mag_b > mag_a;
            end
        end
        s1_valid$d = valid_in;
        flag = s1_flag$q;
        valid_out = s1_valid$q;
    end
    
endmodule // top$core$dop$bank$cmp_l0


module top$core$dop$bank$s1_lanes(d,q,clock);
    
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
          
endmodule // top$core$dop$bank$s1_lanes


module top$core$dop$busy_r(d,q,clock);
    
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
          
endmodule // top$core$dop$busy_r


module top$core$dop$dot_l(clock,d0,d1,d2,c0,c1,c2,c,valid_in,round_up,u,valid_out);
    
    // Module arguments
    input wire  clock;
    input wire  [31:0] d0;
    input wire  [31:0] d1;
    input wire  [31:0] d2;
    input wire  [31:0] c0;
    input wire  [31:0] c1;
    input wire  [31:0] c2;
    input wire  [31:0] c;
    input wire  valid_in;
    input wire  round_up;
    output reg  [31:0] u;
    output reg  valid_out;
    
    // Stub signals
    reg  s1_valid$d;
    wire  s1_valid$q;
    reg  s1_valid$clock;
    reg  [31:0] s1_d0$d;
    wire  [31:0] s1_d0$q;
    reg  s1_d0$clock;
    reg  [31:0] s1_d1$d;
    wire  [31:0] s1_d1$q;
    reg  s1_d1$clock;
    reg  [31:0] s1_d2$d;
    wire  [31:0] s1_d2$q;
    reg  s1_d2$clock;
    reg  [31:0] s1_c0$d;
    wire  [31:0] s1_c0$q;
    reg  s1_c0$clock;
    reg  [31:0] s1_c1$d;
    wire  [31:0] s1_c1$q;
    reg  s1_c1$clock;
    reg  [31:0] s1_c2$d;
    wire  [31:0] s1_c2$q;
    reg  s1_c2$clock;
    reg  [31:0] s1_c$d;
    wire  [31:0] s1_c$q;
    reg  s1_c$clock;
    reg  s1_round$d;
    wire  s1_round$q;
    reg  s1_round$clock;
    reg  r_mul$clock;
    reg  r_mul$d;
    wire  r_mul$q;
    reg  r_sum$clock;
    reg  r_sum$d;
    wire  r_sum$q;
    reg  r_u$clock;
    reg  r_u$d;
    wire  r_u$q;
    reg  mul_0$clock;
    reg  [31:0] mul_0$a;
    reg  [31:0] mul_0$b;
    reg  mul_0$valid_in;
    wire  [31:0] mul_0$y;
    wire  mul_0$valid_out;
    reg  mul_0$round_up;
    reg  mul_1$clock;
    reg  [31:0] mul_1$a;
    reg  [31:0] mul_1$b;
    reg  mul_1$valid_in;
    wire  [31:0] mul_1$y;
    wire  mul_1$valid_out;
    reg  mul_1$round_up;
    reg  mul_2$clock;
    reg  [31:0] mul_2$a;
    reg  [31:0] mul_2$b;
    reg  mul_2$valid_in;
    wire  [31:0] mul_2$y;
    wire  mul_2$valid_out;
    reg  mul_2$round_up;
    reg  [31:0] c_2$d;
    wire  [31:0] c_2$q;
    reg  c_2$clock;
    reg  [31:0] c_3$d;
    wire  [31:0] c_3$q;
    reg  c_3$clock;
    reg  [31:0] c_4$d;
    wire  [31:0] c_4$q;
    reg  c_4$clock;
    reg  [31:0] c_5$d;
    wire  [31:0] c_5$q;
    reg  c_5$clock;
    reg  add_0$clock;
    reg  [31:0] add_0$a;
    reg  [31:0] add_0$b;
    reg  add_0$sub;
    reg  add_0$valid_in;
    wire  [31:0] add_0$y;
    wire  add_0$valid_out;
    reg  add_0$round_up;
    reg  add_1$clock;
    reg  [31:0] add_1$a;
    reg  [31:0] add_1$b;
    reg  add_1$sub;
    reg  add_1$valid_in;
    wire  [31:0] add_1$y;
    wire  add_1$valid_out;
    reg  add_1$round_up;
    reg  add_2$clock;
    reg  [31:0] add_2$a;
    reg  [31:0] add_2$b;
    reg  add_2$sub;
    reg  add_2$valid_in;
    wire  [31:0] add_2$y;
    wire  add_2$valid_out;
    reg  add_2$round_up;
    reg  s12_valid$d;
    wire  s12_valid$q;
    reg  s12_valid$clock;
    reg  [31:0] s12_u$d;
    wire  [31:0] s12_u$q;
    reg  s12_u$clock;
    
    // Sub module instances
    top$core$done_r s1_valid(
        .d(s1_valid$d),
        .q(s1_valid$q),
        .clock(s1_valid$clock)
    );
    top$core$cnt_nf s1_d0(
        .d(s1_d0$d),
        .q(s1_d0$q),
        .clock(s1_d0$clock)
    );
    top$core$cnt_nf s1_d1(
        .d(s1_d1$d),
        .q(s1_d1$q),
        .clock(s1_d1$clock)
    );
    top$core$cnt_nf s1_d2(
        .d(s1_d2$d),
        .q(s1_d2$q),
        .clock(s1_d2$clock)
    );
    top$core$cnt_nf s1_c0(
        .d(s1_c0$d),
        .q(s1_c0$q),
        .clock(s1_c0$clock)
    );
    top$core$cnt_nf s1_c1(
        .d(s1_c1$d),
        .q(s1_c1$q),
        .clock(s1_c1$clock)
    );
    top$core$cnt_nf s1_c2(
        .d(s1_c2$d),
        .q(s1_c2$q),
        .clock(s1_c2$clock)
    );
    top$core$cnt_nf s1_c(
        .d(s1_c$d),
        .q(s1_c$q),
        .clock(s1_c$clock)
    );
    top$core$done_r s1_round(
        .d(s1_round$d),
        .q(s1_round$q),
        .clock(s1_round$clock)
    );
    top$core$dop$dot_l$r_mul r_mul(
        .clock(r_mul$clock),
        .d(r_mul$d),
        .q(r_mul$q)
    );
    top$core$dop$dot_l$r_mul r_sum(
        .clock(r_sum$clock),
        .d(r_sum$d),
        .q(r_sum$q)
    );
    top$core$dop$dot_l$r_mul r_u(
        .clock(r_u$clock),
        .d(r_u$d),
        .q(r_u$q)
    );
    top$core$dop$dot_l$mul_0 mul_0(
        .clock(mul_0$clock),
        .a(mul_0$a),
        .b(mul_0$b),
        .valid_in(mul_0$valid_in),
        .y(mul_0$y),
        .valid_out(mul_0$valid_out),
        .round_up(mul_0$round_up)
    );
    top$core$dop$dot_l$mul_0 mul_1(
        .clock(mul_1$clock),
        .a(mul_1$a),
        .b(mul_1$b),
        .valid_in(mul_1$valid_in),
        .y(mul_1$y),
        .valid_out(mul_1$valid_out),
        .round_up(mul_1$round_up)
    );
    top$core$dop$dot_l$mul_0 mul_2(
        .clock(mul_2$clock),
        .a(mul_2$a),
        .b(mul_2$b),
        .valid_in(mul_2$valid_in),
        .y(mul_2$y),
        .valid_out(mul_2$valid_out),
        .round_up(mul_2$round_up)
    );
    top$core$cnt_nf c_2(
        .d(c_2$d),
        .q(c_2$q),
        .clock(c_2$clock)
    );
    top$core$cnt_nf c_3(
        .d(c_3$d),
        .q(c_3$q),
        .clock(c_3$clock)
    );
    top$core$cnt_nf c_4(
        .d(c_4$d),
        .q(c_4$q),
        .clock(c_4$clock)
    );
    top$core$cnt_nf c_5(
        .d(c_5$d),
        .q(c_5$q),
        .clock(c_5$clock)
    );
    top$core$dop$dot_l$add_0 add_0(
        .clock(add_0$clock),
        .a(add_0$a),
        .b(add_0$b),
        .sub(add_0$sub),
        .valid_in(add_0$valid_in),
        .y(add_0$y),
        .valid_out(add_0$valid_out),
        .round_up(add_0$round_up)
    );
    top$core$dop$dot_l$add_0 add_1(
        .clock(add_1$clock),
        .a(add_1$a),
        .b(add_1$b),
        .sub(add_1$sub),
        .valid_in(add_1$valid_in),
        .y(add_1$y),
        .valid_out(add_1$valid_out),
        .round_up(add_1$round_up)
    );
    top$core$dop$dot_l$add_0 add_2(
        .clock(add_2$clock),
        .a(add_2$a),
        .b(add_2$b),
        .sub(add_2$sub),
        .valid_in(add_2$valid_in),
        .y(add_2$y),
        .valid_out(add_2$valid_out),
        .round_up(add_2$round_up)
    );
    top$core$done_r s12_valid(
        .d(s12_valid$d),
        .q(s12_valid$q),
        .clock(s12_valid$clock)
    );
    top$core$cnt_nf s12_u(
        .d(s12_u$d),
        .q(s12_u$q),
        .clock(s12_u$clock)
    );
    
    // Update code
    always @(*) begin
        s1_valid$clock = clock;
        s1_d0$clock = clock;
        s1_d1$clock = clock;
        s1_d2$clock = clock;
        s1_c0$clock = clock;
        s1_c1$clock = clock;
        s1_c2$clock = clock;
        s1_c$clock = clock;
        s1_round$clock = clock;
        s1_valid$d = s1_valid$q;
        s1_d0$d = s1_d0$q;
        s1_d1$d = s1_d1$q;
        s1_d2$d = s1_d2$q;
        s1_c0$d = s1_c0$q;
        s1_c1$d = s1_c1$q;
        s1_c2$d = s1_c2$q;
        s1_c$d = s1_c$q;
        s1_round$d = s1_round$q;
        r_mul$clock = clock;
        r_sum$clock = clock;
        r_u$clock = clock;
        c_2$clock = clock;
        c_3$clock = clock;
        c_4$clock = clock;
        c_5$clock = clock;
        c_2$d = c_2$q;
        c_3$d = c_3$q;
        c_4$d = c_4$q;
        c_5$d = c_5$q;
        s12_valid$clock = clock;
        s12_u$clock = clock;
        s12_valid$d = s12_valid$q;
        s12_u$d = s12_u$q;
        mul_0$clock = clock;
        mul_1$clock = clock;
        mul_2$clock = clock;
        add_0$clock = clock;
        add_1$clock = clock;
        add_2$clock = clock;
        mul_0$round_up = r_mul$q;
        mul_1$round_up = r_mul$q;
        mul_2$round_up = r_mul$q;
        add_0$round_up = r_sum$q;
        add_1$round_up = r_sum$q;
        add_2$round_up = r_u$q;
        s1_valid$d = valid_in;
        s1_d0$d = d0;
        s1_d1$d = d1;
        s1_d2$d = d2;
        s1_c0$d = c0;
        s1_c1$d = c1;
        s1_c2$d = c2;
        s1_c$d = c;
        s1_round$d = round_up;
        r_mul$d = s1_round$q;
        r_sum$d = r_mul$q;
        r_u$d = r_sum$q;
        mul_0$a = s1_d0$q;
        mul_0$b = s1_c0$q;
        mul_0$valid_in = s1_valid$q;
        mul_1$a = s1_d1$q;
        mul_1$b = s1_c1$q;
        mul_1$valid_in = s1_valid$q;
        mul_2$a = s1_d2$q;
        mul_2$b = s1_c2$q;
        mul_2$valid_in = s1_valid$q;
        c_2$d = s1_c$q;
        c_3$d = c_2$q;
        c_4$d = c_3$q;
        c_5$d = c_4$q;
        add_0$a = mul_0$y;
        add_0$b = mul_1$y;
        add_0$sub = 1'b0;
        add_0$valid_in = mul_0$valid_out;
        add_1$a = mul_2$y;
        add_1$b = c_5$q;
        add_1$sub = 1'b0;
        add_1$valid_in = mul_0$valid_out;
        add_2$a = add_0$y;
        add_2$b = add_1$y;
        add_2$sub = 1'b0;
        add_2$valid_in = add_0$valid_out;
        s12_valid$d = add_2$valid_out;
        s12_u$d = add_2$y;
        u = s12_u$q;
        valid_out = s12_valid$q;
    end
    
endmodule // top$core$dop$dot_l


module top$core$dop$dot_l$add_0(clock,a,b,sub,valid_in,y,valid_out,round_up);
    
    // Module arguments
    input wire  clock;
    input wire  [31:0] a;
    input wire  [31:0] b;
    input wire  sub;
    input wire  valid_in;
    output reg  [31:0] y;
    output reg  valid_out;
    input wire  round_up;
    
    // Constant declarations
    localparam  c_align_cap = 8'h1b;
    localparam  c_exp_ones = 10'b11111111;
    
    // Stub signals
    reg  [31:0] unpack_a$x;
    wire  unpack_a$sign;
    wire  [7:0] unpack_a$exp;
    wire  [23:0] unpack_a$sig;
    wire  unpack_a$is_zero;
    wire  unpack_a$is_inf;
    wire  unpack_a$is_nan;
    reg  [31:0] unpack_b$x;
    wire  unpack_b$sign;
    wire  [7:0] unpack_b$exp;
    wire  [23:0] unpack_b$sig;
    wire  unpack_b$is_zero;
    wire  unpack_b$is_inf;
    wire  unpack_b$is_nan;
    reg  s1_valid$d;
    wire  s1_valid$q;
    reg  s1_valid$clock;
    reg  s1_nan$d;
    wire  s1_nan$q;
    reg  s1_nan$clock;
    reg  s1_inf$d;
    wire  s1_inf$q;
    reg  s1_inf$clock;
    reg  s1_inf_sign$d;
    wire  s1_inf_sign$q;
    reg  s1_inf_sign$clock;
    reg  s1_zero_sign$d;
    wire  s1_zero_sign$q;
    reg  s1_zero_sign$clock;
    reg  s1_sign$d;
    wire  s1_sign$q;
    reg  s1_sign$clock;
    reg  s1_eff_sub$d;
    wire  s1_eff_sub$q;
    reg  s1_eff_sub$clock;
    reg  [7:0] s1_exp$d;
    wire  [7:0] s1_exp$q;
    reg  s1_exp$clock;
    reg  [26:0] s1_big$d;
    wire  [26:0] s1_big$q;
    reg  s1_big$clock;
    reg  [26:0] s1_small$d;
    wire  [26:0] s1_small$q;
    reg  s1_small$clock;
    reg  [26:0] norm$x;
    wire  [26:0] norm$y;
    wire  [4:0] norm$lz;
    reg  s2_valid$d;
    wire  s2_valid$q;
    reg  s2_valid$clock;
    reg  s2_sign$d;
    wire  s2_sign$q;
    reg  s2_sign$clock;
    reg  s2_nan$d;
    wire  s2_nan$q;
    reg  s2_nan$clock;
    reg  s2_inf$d;
    wire  s2_inf$q;
    reg  s2_inf$clock;
    reg  s2_zero$d;
    wire  s2_zero$q;
    reg  s2_zero$clock;
    reg  s2_ovf$d;
    wire  s2_ovf$q;
    reg  s2_ovf$clock;
    reg  [7:0] s2_efield$d;
    wire  [7:0] s2_efield$q;
    reg  s2_efield$clock;
    reg  [25:0] s2_nm$d;
    wire  [25:0] s2_nm$q;
    reg  s2_nm$clock;
    reg  round$round_up;
    reg  round$sign;
    reg  round$nan;
    reg  round$inf;
    reg  round$zero;
    reg  round$ovf;
    reg  [7:0] round$efield;
    reg  [25:0] round$nm;
    wire  [31:0] round$y;
    reg  s3_valid$d;
    wire  s3_valid$q;
    reg  s3_valid$clock;
    reg  [31:0] s3_y$d;
    wire  [31:0] s3_y$q;
    reg  s3_y$clock;
    
    // Local signals
    reg  c1_b_sign;
    reg  c1_swap;
    reg  c1_big_sign;
    reg  [7:0] c1_big_exp;
    reg  [23:0] c1_big_sig;
    reg  c1_small_sign;
    reg  [7:0] c1_small_exp;
    reg  [23:0] c1_small_sig;
    reg  [7:0] c1_diff;
    reg  [7:0] c1_shift;
    reg  [26:0] c1_small_ext;
    reg  [26:0] c1_aligned;
    reg  [26:0] c1_back;
    reg  c1_lost;
    reg  c1_inf_sign;
    reg  [27:0] c2_sum;
    reg  c2_carry;
    reg  c2_zero;
    reg  [7:0] c2_limit;
    reg  [7:0] c2_lz;
    reg  [7:0] c2_shift;
    reg  [26:0] c2_shifted;
    reg  [9:0] c2_exp;
    reg  [25:0] c2_nm;
    reg  c2_sign;
    
    // Sub module instances
    top$core$dop$dot_l$add_0$unpack_a unpack_a(
        .x(unpack_a$x),
        .sign(unpack_a$sign),
        .exp(unpack_a$exp),
        .sig(unpack_a$sig),
        .is_zero(unpack_a$is_zero),
        .is_inf(unpack_a$is_inf),
        .is_nan(unpack_a$is_nan)
    );
    top$core$dop$dot_l$add_0$unpack_a unpack_b(
        .x(unpack_b$x),
        .sign(unpack_b$sign),
        .exp(unpack_b$exp),
        .sig(unpack_b$sig),
        .is_zero(unpack_b$is_zero),
        .is_inf(unpack_b$is_inf),
        .is_nan(unpack_b$is_nan)
    );
    top$core$done_r s1_valid(
        .d(s1_valid$d),
        .q(s1_valid$q),
        .clock(s1_valid$clock)
    );
    top$core$done_r s1_nan(
        .d(s1_nan$d),
        .q(s1_nan$q),
        .clock(s1_nan$clock)
    );
    top$core$done_r s1_inf(
        .d(s1_inf$d),
        .q(s1_inf$q),
        .clock(s1_inf$clock)
    );
    top$core$done_r s1_inf_sign(
        .d(s1_inf_sign$d),
        .q(s1_inf_sign$q),
        .clock(s1_inf_sign$clock)
    );
    top$core$done_r s1_zero_sign(
        .d(s1_zero_sign$d),
        .q(s1_zero_sign$q),
        .clock(s1_zero_sign$clock)
    );
    top$core$done_r s1_sign(
        .d(s1_sign$d),
        .q(s1_sign$q),
        .clock(s1_sign$clock)
    );
    top$core$done_r s1_eff_sub(
        .d(s1_eff_sub$d),
        .q(s1_eff_sub$q),
        .clock(s1_eff_sub$clock)
    );
    top$core$dop$bank$s1_lanes s1_exp(
        .d(s1_exp$d),
        .q(s1_exp$q),
        .clock(s1_exp$clock)
    );
    top$core$dop$dot_l$add_0$s1_big s1_big(
        .d(s1_big$d),
        .q(s1_big$q),
        .clock(s1_big$clock)
    );
    top$core$dop$dot_l$add_0$s1_big s1_small(
        .d(s1_small$d),
        .q(s1_small$q),
        .clock(s1_small$clock)
    );
    top$core$dop$dot_l$add_0$norm norm(
        .x(norm$x),
        .y(norm$y),
        .lz(norm$lz)
    );
    top$core$done_r s2_valid(
        .d(s2_valid$d),
        .q(s2_valid$q),
        .clock(s2_valid$clock)
    );
    top$core$done_r s2_sign(
        .d(s2_sign$d),
        .q(s2_sign$q),
        .clock(s2_sign$clock)
    );
    top$core$done_r s2_nan(
        .d(s2_nan$d),
        .q(s2_nan$q),
        .clock(s2_nan$clock)
    );
    top$core$done_r s2_inf(
        .d(s2_inf$d),
        .q(s2_inf$q),
        .clock(s2_inf$clock)
    );
    top$core$done_r s2_zero(
        .d(s2_zero$d),
        .q(s2_zero$q),
        .clock(s2_zero$clock)
    );
    top$core$done_r s2_ovf(
        .d(s2_ovf$d),
        .q(s2_ovf$q),
        .clock(s2_ovf$clock)
    );
    top$core$dop$bank$s1_lanes s2_efield(
        .d(s2_efield$d),
        .q(s2_efield$q),
        .clock(s2_efield$clock)
    );
    top$core$dop$dot_l$add_0$s2_nm s2_nm(
        .d(s2_nm$d),
        .q(s2_nm$q),
        .clock(s2_nm$clock)
    );
    top$core$dop$dot_l$add_0$round round(
        .round_up(round$round_up),
        .sign(round$sign),
        .nan(round$nan),
        .inf(round$inf),
        .zero(round$zero),
        .ovf(round$ovf),
        .efield(round$efield),
        .nm(round$nm),
        .y(round$y)
    );
    top$core$done_r s3_valid(
        .d(s3_valid$d),
        .q(s3_valid$q),
        .clock(s3_valid$clock)
    );
    top$core$cnt_nf s3_y(
        .d(s3_y$d),
        .q(s3_y$q),
        .clock(s3_y$clock)
    );
    
    // Update code
    always @(*) begin
        s1_valid$clock = clock;
        s1_nan$clock = clock;
        s1_inf$clock = clock;
        s1_inf_sign$clock = clock;
        s1_zero_sign$clock = clock;
        s1_sign$clock = clock;
        s1_eff_sub$clock = clock;
        s1_exp$clock = clock;
        s1_big$clock = clock;
        s1_small$clock = clock;
        s1_valid$d = s1_valid$q;
        s1_nan$d = s1_nan$q;
        s1_inf$d = s1_inf$q;
        s1_inf_sign$d = s1_inf_sign$q;
        s1_zero_sign$d = s1_zero_sign$q;
        s1_sign$d = s1_sign$q;
        s1_eff_sub$d = s1_eff_sub$q;
        s1_exp$d = s1_exp$q;
        s1_big$d = s1_big$q;
        s1_small$d = s1_small$q;
        s2_valid$clock = clock;
        s2_sign$clock = clock;
        s2_nan$clock = clock;
        s2_inf$clock = clock;
        s2_zero$clock = clock;
        s2_ovf$clock = clock;
        s2_efield$clock = clock;
        s2_nm$clock = clock;
        s2_valid$d = s2_valid$q;
        s2_sign$d = s2_sign$q;
        s2_nan$d = s2_nan$q;
        s2_inf$d = s2_inf$q;
        s2_zero$d = s2_zero$q;
        s2_ovf$d = s2_ovf$q;
        s2_efield$d = s2_efield$q;
        s2_nm$d = s2_nm$q;
        s3_valid$clock = clock;
        s3_y$clock = clock;
        s3_valid$d = s3_valid$q;
        s3_y$d = s3_y$q;
        unpack_a$x = a;
        unpack_b$x = b;
        c1_b_sign = unpack_b$sign ^ sub;
        c1_swap = a[(32'h0)+:(31)] < b[(32'h0)+:(31)];
        c1_big_sign = unpack_a$sign;
        c1_big_exp = unpack_a$exp;
        c1_big_sig = unpack_a$sig;
        c1_small_sign = c1_b_sign;
        c1_small_exp = unpack_b$exp;
        c1_small_sig = unpack_b$sig;
        if (c1_swap) begin
            c1_big_sign = c1_b_sign;
            c1_big_exp = unpack_b$exp;
            c1_big_sig = unpack_b$sig;
            c1_small_sign = unpack_a$sign;
            c1_small_exp = unpack_a$exp;
            c1_small_sig = unpack_a$sig;
        end
        c1_diff = c1_big_exp - c1_small_exp;
        c1_shift = c1_diff;
        if (c1_diff > c_align_cap) begin
            c1_shift = c_align_cap;
        end
        c1_small_ext = ((c1_small_sig) & 27'h7ffffff) << 32'h3;
        c1_aligned = c1_small_ext >> c1_shift;
        c1_back = c1_aligned << c1_shift;
        c1_lost = c1_back != c1_small_ext;
        c1_inf_sign = c1_b_sign;
        if (unpack_a$is_inf) begin
            c1_inf_sign = unpack_a$sign;
        end
        s1_valid$d = valid_in;
        s1_nan$d = unpack_a$is_nan | unpack_b$is_nan | (unpack_a$is_inf & unpack_b$is_inf & (unpack_a$sign ^ c1_b_sign));
        s1_inf$d = unpack_a$is_inf | unpack_b$is_inf;
        s1_inf_sign$d = c1_inf_sign;
        s1_zero_sign$d = unpack_a$sign & c1_b_sign;
        s1_sign$d = c1_big_sign;
        s1_eff_sub$d = c1_big_sign ^ c1_small_sign;
        s1_exp$d = c1_big_exp;
        s1_big$d = ((c1_big_sig) & 27'h7ffffff) << 32'h3;
        s1_small$d = (c1_aligned & ~(1 << (32'h0)) | ((c1_aligned[32'h0] | c1_lost) << (32'h0)));
        c2_sum = ((s1_big$q) & 28'hfffffff) + ((s1_small$q) & 28'hfffffff);
        if (s1_eff_sub$q) begin
            c2_sum = ((s1_big$q) & 28'hfffffff) - ((s1_small$q) & 28'hfffffff);
        end
        c2_carry = c2_sum[32'h1b];
        c2_zero = c2_sum == 32'h0;
        norm$x = c2_sum[(32'h0)+:(27)];
        c2_limit = s1_exp$q - 32'h1;
        c2_lz = ((norm$lz) & 8'hff);
        c2_shift = c2_lz;
        if (c2_lz > c2_limit) begin
            c2_shift = c2_limit;
        end
        c2_shifted = c2_sum[(32'h0)+:(27)] << c2_shift;
        c2_exp = ((s1_exp$q) & 10'h3ff) - ((c2_shift) & 10'h3ff);
        c2_nm = (((c2_shifted >> 32'h1) & 26'h3ffffff) & ~(1 << (32'h0)) | ((c2_shifted[32'h1] | c2_shifted[32'h0]) << (32'h0)));
        if (c2_carry) begin
            c2_exp = ((s1_exp$q) & 10'h3ff) + 32'h1;
            c2_nm = (((c2_sum >> 32'h2) & 26'h3ffffff) & ~(1 << (32'h0)) | ((c2_sum[32'h2] | c2_sum[32'h1] | c2_sum[32'h0]) << (32'h0)));
        end
        c2_sign = s1_sign$q;
        if (c2_zero) begin
            c2_sign = s1_zero_sign$q;
        end
        if (s1_inf$q) begin
            c2_sign = s1_inf_sign$q;
        end
        s2_valid$d = s1_valid$q;
        s2_sign$d = c2_sign;
        s2_nan$d = s1_nan$q;
        s2_inf$d = s1_inf$q;
        s2_zero$d = c2_zero;
        s2_ovf$d = c2_exp >= c_exp_ones;
        s2_efield$d = 32'h0;
        if (c2_nm[32'h18 + 32'h1]) begin
            s2_efield$d = ((c2_exp) & 8'hff);
        end
        s2_nm$d = c2_nm;
        round$round_up = round_up;
        round$sign = s2_sign$q;
        round$nan = s2_nan$q;
        round$inf = s2_inf$q;
        round$zero = s2_zero$q;
        round$ovf = s2_ovf$q;
        round$efield = s2_efield$q;
        round$nm = s2_nm$q;
        s3_valid$d = s2_valid$q;
        s3_y$d = round$y;
        y = s3_y$q;
        valid_out = s3_valid$q;
    end
    
endmodule // top$core$dop$dot_l$add_0


module top$core$dop$dot_l$add_0$norm(x,y,lz);
    
    // Module arguments
    input wire  [26:0] x;
    output reg  [26:0] y;
    output reg  [4:0] lz;
    
    // Local signals
    reg  z16;
    reg  z8;
    reg  z4;
    reg  z2;
    reg  z1;
    reg  [26:0] x16;
    reg  [26:0] x8;
    reg  [26:0] x4;
    reg  [26:0] x2;
    
    // Update code
    always @(*) begin
        z16 = x[(32'hb)+:(16)] == 32'h0;
        x16 = x;
        if (z16) begin
            x16 = x << 32'h10;
        end
        z8 = x16[(32'h13)+:(8)] == 32'h0;
        x8 = x16;
        if (z8) begin
            x8 = x16 << 32'h8;
        end
        z4 = x8[(32'h17)+:(4)] == 32'h0;
        x4 = x8;
        if (z4) begin
            x4 = x8 << 32'h4;
        end
        z2 = x4[(32'h19)+:(2)] == 32'h0;
        x2 = x4;
        if (z2) begin
            x2 = x4 << 32'h2;
        end
        z1 = ~x2[32'h1a];
        y = x2;
        if (z1) begin
            y = x2 << 32'h1;
        end
        lz = (((((((32'h0) & 5'h1f) & ~(1 << (32'h4)) | ((z16) << (32'h4))) & ~(1 << (32'h3)) | ((z8) << (32'h3))) & ~(1 << (32'h2)) | ((z4) << (32'h2))) & ~(1 << (32'h1)) | ((z2) << (32'h1))) & ~(1 << (32'h0)) | ((z1) << (32'h0)));
    end
    
endmodule // top$core$dop$dot_l$add_0$norm


module top$core$dop$dot_l$add_0$round(round_up,sign,nan,inf,zero,ovf,efield,nm,y);
    
    // Module arguments
    input wire  round_up;
    input wire  sign;
    input wire  nan;
    input wire  inf;
    input wire  zero;
    input wire  ovf;
    input wire  [7:0] efield;
    input wire  [25:0] nm;
    output reg  [31:0] y;
    
    // Constant declarations
    localparam  c_nan = 32'h7fc00000;
    localparam  c_sign = 32'h80000000;
    localparam  c_inf = 31'h7f800000;
    localparam  c_max_finite = 31'h7f7fffff;
    
    // Local signals
    reg  lsb;
    reg  guard;
    reg  sticky;
    reg  inc;
    reg  [30:0] pack_word;
    reg  [30:0] rounded;
    reg  rexp_ones;
    reg  [30:0] mag;
    
    // Update code
    always @(*) begin
        lsb = nm[32'h2];
        guard = nm[32'h1];
        sticky = nm[32'h0];
        inc = guard & (sticky | lsb);
        if (round_up) begin
            inc = ~sign & (guard | sticky);
        end
        pack_word = (((efield) & 31'h7fffffff) << 32'h17) | ((nm[(32'h2)+:(23)]) & 31'h7fffffff);
        rounded = pack_word + inc;
        rexp_ones = &rounded[(32'h17)+:(8)];
        mag = rounded;
        if (ovf | rexp_ones) begin
            mag = c_inf;
            if (round_up & sign) begin
                mag = c_max_finite;
            end
        end
        if (zero) begin
            mag = 32'h0;
        end
        if (inf) begin
            mag = c_inf;
        end
        y = ((mag) & 32'hffffffff);
        if (sign) begin
            y = ((mag) & 32'hffffffff) | c_sign;
        end
        if (nan) begin
            y = c_nan;
        end
    end
    
endmodule // top$core$dop$dot_l$add_0$round


module top$core$dop$dot_l$add_0$s1_big(d,q,clock);
    
    // Module arguments
    input wire  [26:0] d;
    output reg  [26:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 27'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$core$dop$dot_l$add_0$s1_big


module top$core$dop$dot_l$add_0$s2_nm(d,q,clock);
    
    // Module arguments
    input wire  [25:0] d;
    output reg  [25:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 26'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$core$dop$dot_l$add_0$s2_nm


module top$core$dop$dot_l$add_0$unpack_a(x,sign,exp,sig,is_zero,is_inf,is_nan);
    
    // Module arguments
    input wire  [31:0] x;
    output reg  sign;
    output reg  [7:0] exp;
    output reg  [23:0] sig;
    output reg  is_zero;
    output reg  is_inf;
    output reg  is_nan;
    
    // Local signals
    reg  [7:0] field;
    reg  [22:0] frac;
    reg  exp_zero;
    reg  exp_ones;
    reg  frac_zero;
    
    // Update code
    always @(*) begin
        field = x[(32'h17)+:(8)];
        frac = x[(32'h0)+:(23)];
        sign = x[32'h1f];
        exp_zero = field == 32'h0;
        exp_ones = &field;
        frac_zero = frac == 32'h0;
        is_zero = exp_zero & frac_zero;
        is_inf = exp_ones & frac_zero;
        is_nan = exp_ones & ~frac_zero;
        exp = field;
        sig = (((frac) & 24'hffffff) & ~(1 << (32'h17)) | ((1'b1) << (32'h17)));
        if (exp_zero) begin
            exp = 32'h1;
            sig = ((frac) & 24'hffffff);
        end
    end
    
endmodule // top$core$dop$dot_l$add_0$unpack_a


module top$core$dop$dot_l$mul_0(clock,a,b,valid_in,y,valid_out,round_up);
    
    // Module arguments
    input wire  clock;
    input wire  [31:0] a;
    input wire  [31:0] b;
    input wire  valid_in;
    output reg  [31:0] y;
    output reg  valid_out;
    input wire  round_up;
    
    // Constant declarations
    localparam  c_exp_adj = 10'b10000001;
    localparam  c_exp_ofs = 10'b100000000;
    localparam  c_exp_norm_min = 10'b100000001;
    localparam  c_exp_ovf = 10'b111111111;
    localparam  c_shift_cap = 10'b11010;
    
    // Stub signals
    reg  [31:0] unpack_a$x;
    wire  unpack_a$sign;
    wire  [7:0] unpack_a$exp;
    wire  [23:0] unpack_a$sig;
    wire  unpack_a$is_zero;
    wire  unpack_a$is_inf;
    wire  unpack_a$is_nan;
    reg  [31:0] unpack_b$x;
    wire  unpack_b$sign;
    wire  [7:0] unpack_b$exp;
    wire  [23:0] unpack_b$sig;
    wire  unpack_b$is_zero;
    wire  unpack_b$is_inf;
    wire  unpack_b$is_nan;
    reg  [23:0] norm_a$x;
    wire  [23:0] norm_a$y;
    wire  [4:0] norm_a$lz;
    reg  [23:0] norm_b$x;
    wire  [23:0] norm_b$y;
    wire  [4:0] norm_b$lz;
    reg  s1_valid$d;
    wire  s1_valid$q;
    reg  s1_valid$clock;
    reg  s1_sign$d;
    wire  s1_sign$q;
    reg  s1_sign$clock;
    reg  s1_nan$d;
    wire  s1_nan$q;
    reg  s1_nan$clock;
    reg  s1_inf$d;
    wire  s1_inf$q;
    reg  s1_inf$clock;
    reg  s1_zero$d;
    wire  s1_zero$q;
    reg  s1_zero$clock;
    reg  [9:0] s1_exp$d;
    wire  [9:0] s1_exp$q;
    reg  s1_exp$clock;
    reg  [23:0] s1_sig_a$d;
    wire  [23:0] s1_sig_a$q;
    reg  s1_sig_a$clock;
    reg  [23:0] s1_sig_b$d;
    wire  [23:0] s1_sig_b$q;
    reg  s1_sig_b$clock;
    reg  [23:0] sig_mul$a;
    reg  [23:0] sig_mul$b;
    wire  [25:0] sig_mul$hi;
    wire  sig_mul$sticky;
    reg  s2_valid$d;
    wire  s2_valid$q;
    reg  s2_valid$clock;
    reg  s2_sign$d;
    wire  s2_sign$q;
    reg  s2_sign$clock;
    reg  s2_nan$d;
    wire  s2_nan$q;
    reg  s2_nan$clock;
    reg  s2_inf$d;
    wire  s2_inf$q;
    reg  s2_inf$clock;
    reg  s2_zero$d;
    wire  s2_zero$q;
    reg  s2_zero$clock;
    reg  [9:0] s2_exp$d;
    wire  [9:0] s2_exp$q;
    reg  s2_exp$clock;
    reg  [25:0] s2_hi$d;
    wire  [25:0] s2_hi$q;
    reg  s2_hi$clock;
    reg  s2_sticky$d;
    wire  s2_sticky$q;
    reg  s2_sticky$clock;
    reg  s3_valid$d;
    wire  s3_valid$q;
    reg  s3_valid$clock;
    reg  s3_sign$d;
    wire  s3_sign$q;
    reg  s3_sign$clock;
    reg  s3_nan$d;
    wire  s3_nan$q;
    reg  s3_nan$clock;
    reg  s3_inf$d;
    wire  s3_inf$q;
    reg  s3_inf$clock;
    reg  s3_zero$d;
    wire  s3_zero$q;
    reg  s3_zero$clock;
    reg  s3_ovf$d;
    wire  s3_ovf$q;
    reg  s3_ovf$clock;
    reg  [7:0] s3_efield$d;
    wire  [7:0] s3_efield$q;
    reg  s3_efield$clock;
    reg  [25:0] s3_nm$d;
    wire  [25:0] s3_nm$q;
    reg  s3_nm$clock;
    reg  round$round_up;
    reg  round$sign;
    reg  round$nan;
    reg  round$inf;
    reg  round$zero;
    reg  round$ovf;
    reg  [7:0] round$efield;
    reg  [25:0] round$nm;
    wire  [31:0] round$y;
    reg  s4_valid$d;
    wire  s4_valid$q;
    reg  s4_valid$clock;
    reg  [31:0] s4_y$d;
    wire  [31:0] s4_y$q;
    reg  s4_y$clock;
    
    // Local signals
    reg  [9:0] c1_exp;
    reg  c3_top;
    reg  [25:0] c3_nm;
    reg  [9:0] c3_exp;
    reg  [9:0] c3_shift;
    reg  [9:0] c3_shift_cap;
    reg  [25:0] c3_shifted;
    reg  [25:0] c3_back;
    reg  c3_lost;
    reg  [7:0] c3_efield;
    
    // Sub module instances
    top$core$dop$dot_l$add_0$unpack_a unpack_a(
        .x(unpack_a$x),
        .sign(unpack_a$sign),
        .exp(unpack_a$exp),
        .sig(unpack_a$sig),
        .is_zero(unpack_a$is_zero),
        .is_inf(unpack_a$is_inf),
        .is_nan(unpack_a$is_nan)
    );
    top$core$dop$dot_l$add_0$unpack_a unpack_b(
        .x(unpack_b$x),
        .sign(unpack_b$sign),
        .exp(unpack_b$exp),
        .sig(unpack_b$sig),
        .is_zero(unpack_b$is_zero),
        .is_inf(unpack_b$is_inf),
        .is_nan(unpack_b$is_nan)
    );
    top$core$dop$dot_l$mul_0$norm_a norm_a(
        .x(norm_a$x),
        .y(norm_a$y),
        .lz(norm_a$lz)
    );
    top$core$dop$dot_l$mul_0$norm_a norm_b(
        .x(norm_b$x),
        .y(norm_b$y),
        .lz(norm_b$lz)
    );
    top$core$done_r s1_valid(
        .d(s1_valid$d),
        .q(s1_valid$q),
        .clock(s1_valid$clock)
    );
    top$core$done_r s1_sign(
        .d(s1_sign$d),
        .q(s1_sign$q),
        .clock(s1_sign$clock)
    );
    top$core$done_r s1_nan(
        .d(s1_nan$d),
        .q(s1_nan$q),
        .clock(s1_nan$clock)
    );
    top$core$done_r s1_inf(
        .d(s1_inf$d),
        .q(s1_inf$q),
        .clock(s1_inf$clock)
    );
    top$core$done_r s1_zero(
        .d(s1_zero$d),
        .q(s1_zero$q),
        .clock(s1_zero$clock)
    );
    top$core$dop$dot_l$mul_0$s1_exp s1_exp(
        .d(s1_exp$d),
        .q(s1_exp$q),
        .clock(s1_exp$clock)
    );
    top$core$base_na s1_sig_a(
        .d(s1_sig_a$d),
        .q(s1_sig_a$q),
        .clock(s1_sig_a$clock)
    );
    top$core$base_na s1_sig_b(
        .d(s1_sig_b$d),
        .q(s1_sig_b$q),
        .clock(s1_sig_b$clock)
    );
    top$core$dop$dot_l$mul_0$sig_mul sig_mul(
        .a(sig_mul$a),
        .b(sig_mul$b),
        .hi(sig_mul$hi),
        .sticky(sig_mul$sticky)
    );
    top$core$done_r s2_valid(
        .d(s2_valid$d),
        .q(s2_valid$q),
        .clock(s2_valid$clock)
    );
    top$core$done_r s2_sign(
        .d(s2_sign$d),
        .q(s2_sign$q),
        .clock(s2_sign$clock)
    );
    top$core$done_r s2_nan(
        .d(s2_nan$d),
        .q(s2_nan$q),
        .clock(s2_nan$clock)
    );
    top$core$done_r s2_inf(
        .d(s2_inf$d),
        .q(s2_inf$q),
        .clock(s2_inf$clock)
    );
    top$core$done_r s2_zero(
        .d(s2_zero$d),
        .q(s2_zero$q),
        .clock(s2_zero$clock)
    );
    top$core$dop$dot_l$mul_0$s1_exp s2_exp(
        .d(s2_exp$d),
        .q(s2_exp$q),
        .clock(s2_exp$clock)
    );
    top$core$dop$dot_l$add_0$s2_nm s2_hi(
        .d(s2_hi$d),
        .q(s2_hi$q),
        .clock(s2_hi$clock)
    );
    top$core$done_r s2_sticky(
        .d(s2_sticky$d),
        .q(s2_sticky$q),
        .clock(s2_sticky$clock)
    );
    top$core$done_r s3_valid(
        .d(s3_valid$d),
        .q(s3_valid$q),
        .clock(s3_valid$clock)
    );
    top$core$done_r s3_sign(
        .d(s3_sign$d),
        .q(s3_sign$q),
        .clock(s3_sign$clock)
    );
    top$core$done_r s3_nan(
        .d(s3_nan$d),
        .q(s3_nan$q),
        .clock(s3_nan$clock)
    );
    top$core$done_r s3_inf(
        .d(s3_inf$d),
        .q(s3_inf$q),
        .clock(s3_inf$clock)
    );
    top$core$done_r s3_zero(
        .d(s3_zero$d),
        .q(s3_zero$q),
        .clock(s3_zero$clock)
    );
    top$core$done_r s3_ovf(
        .d(s3_ovf$d),
        .q(s3_ovf$q),
        .clock(s3_ovf$clock)
    );
    top$core$dop$bank$s1_lanes s3_efield(
        .d(s3_efield$d),
        .q(s3_efield$q),
        .clock(s3_efield$clock)
    );
    top$core$dop$dot_l$add_0$s2_nm s3_nm(
        .d(s3_nm$d),
        .q(s3_nm$q),
        .clock(s3_nm$clock)
    );
    top$core$dop$dot_l$add_0$round round(
        .round_up(round$round_up),
        .sign(round$sign),
        .nan(round$nan),
        .inf(round$inf),
        .zero(round$zero),
        .ovf(round$ovf),
        .efield(round$efield),
        .nm(round$nm),
        .y(round$y)
    );
    top$core$done_r s4_valid(
        .d(s4_valid$d),
        .q(s4_valid$q),
        .clock(s4_valid$clock)
    );
    top$core$cnt_nf s4_y(
        .d(s4_y$d),
        .q(s4_y$q),
        .clock(s4_y$clock)
    );
    
    // Update code
    always @(*) begin
        s1_valid$clock = clock;
        s1_sign$clock = clock;
        s1_nan$clock = clock;
        s1_inf$clock = clock;
        s1_zero$clock = clock;
        s1_exp$clock = clock;
        s1_sig_a$clock = clock;
        s1_sig_b$clock = clock;
        s1_valid$d = s1_valid$q;
        s1_sign$d = s1_sign$q;
        s1_nan$d = s1_nan$q;
        s1_inf$d = s1_inf$q;
        s1_zero$d = s1_zero$q;
        s1_exp$d = s1_exp$q;
        s1_sig_a$d = s1_sig_a$q;
        s1_sig_b$d = s1_sig_b$q;
        s2_valid$clock = clock;
        s2_sign$clock = clock;
        s2_nan$clock = clock;
        s2_inf$clock = clock;
        s2_zero$clock = clock;
        s2_exp$clock = clock;
        s2_hi$clock = clock;
        s2_sticky$clock = clock;
        s2_valid$d = s2_valid$q;
        s2_sign$d = s2_sign$q;
        s2_nan$d = s2_nan$q;
        s2_inf$d = s2_inf$q;
        s2_zero$d = s2_zero$q;
        s2_exp$d = s2_exp$q;
        s2_hi$d = s2_hi$q;
        s2_sticky$d = s2_sticky$q;
        s3_valid$clock = clock;
        s3_sign$clock = clock;
        s3_nan$clock = clock;
        s3_inf$clock = clock;
        s3_zero$clock = clock;
        s3_ovf$clock = clock;
        s3_efield$clock = clock;
        s3_nm$clock = clock;
        s3_valid$d = s3_valid$q;
        s3_sign$d = s3_sign$q;
        s3_nan$d = s3_nan$q;
        s3_inf$d = s3_inf$q;
        s3_zero$d = s3_zero$q;
        s3_ovf$d = s3_ovf$q;
        s3_efield$d = s3_efield$q;
        s3_nm$d = s3_nm$q;
        s4_valid$clock = clock;
        s4_y$clock = clock;
        s4_valid$d = s4_valid$q;
        s4_y$d = s4_y$q;
        unpack_a$x = a;
        unpack_b$x = b;
        norm_a$x = unpack_a$sig;
        norm_b$x = unpack_b$sig;
        c1_exp = ((unpack_a$exp) & 10'h3ff) + ((unpack_b$exp) & 10'h3ff) - ((norm_a$lz) & 10'h3ff) - ((norm_b$lz) & 10'h3ff) + c_exp_adj;
        s1_valid$d = valid_in;
        s1_sign$d = unpack_a$sign ^ unpack_b$sign;
        s1_nan$d = unpack_a$is_nan | unpack_b$is_nan | (unpack_a$is_inf & unpack_b$is_zero) | (unpack_a$is_zero & unpack_b$is_inf);
        s1_inf$d = unpack_a$is_inf | unpack_b$is_inf;
        s1_zero$d = unpack_a$is_zero | unpack_b$is_zero;
        s1_exp$d = c1_exp;
        s1_sig_a$d = norm_a$y;
        s1_sig_b$d = norm_b$y;
        sig_mul$a = s1_sig_a$q;
        sig_mul$b = s1_sig_b$q;
        s2_valid$d = s1_valid$q;
        s2_sign$d = s1_sign$q;
        s2_nan$d = s1_nan$q;
        s2_inf$d = s1_inf$q;
        s2_zero$d = s1_zero$q;
        s2_exp$d = s1_exp$q;
        s2_hi$d = sig_mul$hi;
        s2_sticky$d = sig_mul$sticky;
        c3_top = s2_hi$q[32'h18 + 32'h1];
        c3_nm = ((s2_hi$q << 32'h1) & ~(1 << (32'h0)) | ((s2_sticky$q) << (32'h0)));
        if (c3_top) begin
            c3_nm = (s2_hi$q & ~(1 << (32'h0)) | ((s2_hi$q[32'h0] | s2_sticky$q) << (32'h0)));
        end
        c3_exp = s2_exp$q + c3_top;
        c3_shift = 32'h0;
        if (c3_exp < c_exp_norm_min) begin
            c3_shift = c_exp_norm_min - c3_exp;
        end
        c3_shift_cap = c3_shift;
        if (c3_shift > c_shift_cap) begin
            c3_shift_cap = c_shift_cap;
        end
        c3_shifted = c3_nm >> c3_shift_cap;
        c3_back = c3_shifted << c3_shift_cap;
        c3_lost = c3_back != c3_nm;
        c3_efield = 32'h0;
        if (c3_shift == 32'h0) begin
            c3_efield = ((c3_exp - c_exp_ofs) & 8'hff);
        end
        s3_valid$d = s2_valid$q;
        s3_sign$d = s2_sign$q;
        s3_nan$d = s2_nan$q;
        s3_inf$d = s2_inf$q;
        s3_zero$d = s2_zero$q;
        s3_ovf$d = c3_exp >= c_exp_ovf;
        s3_efield$d = c3_efield;
        s3_nm$d = (c3_shifted & ~(1 << (32'h0)) | ((c3_shifted[32'h0] | c3_lost) << (32'h0)));
        round$round_up = round_up;
        round$sign = s3_sign$q;
        round$nan = s3_nan$q;
        round$inf = s3_inf$q;
        round$zero = s3_zero$q;
        round$ovf = s3_ovf$q;
        round$efield = s3_efield$q;
        round$nm = s3_nm$q;
        s4_valid$d = s3_valid$q;
        s4_y$d = round$y;
        y = s4_y$q;
        valid_out = s4_valid$q;
    end
    
endmodule // top$core$dop$dot_l$mul_0


module top$core$dop$dot_l$mul_0$norm_a(x,y,lz);
    
    // Module arguments
    input wire  [23:0] x;
    output reg  [23:0] y;
    output reg  [4:0] lz;
    
    // Local signals
    reg  z16;
    reg  z8;
    reg  z4;
    reg  z2;
    reg  z1;
    reg  [23:0] x16;
    reg  [23:0] x8;
    reg  [23:0] x4;
    reg  [23:0] x2;
    
    // Update code
    always @(*) begin
        z16 = x[(32'h8)+:(16)] == 32'h0;
        x16 = x;
        if (z16) begin
            x16 = x << 32'h10;
        end
        z8 = x16[(32'h10)+:(8)] == 32'h0;
        x8 = x16;
        if (z8) begin
            x8 = x16 << 32'h8;
        end
        z4 = x8[(32'h14)+:(4)] == 32'h0;
        x4 = x8;
        if (z4) begin
            x4 = x8 << 32'h4;
        end
        z2 = x4[(32'h16)+:(2)] == 32'h0;
        x2 = x4;
        if (z2) begin
            x2 = x4 << 32'h2;
        end
        z1 = ~x2[32'h17];
        y = x2;
        if (z1) begin
            y = x2 << 32'h1;
        end
        lz = (((((((32'h0) & 5'h1f) & ~(1 << (32'h4)) | ((z16) << (32'h4))) & ~(1 << (32'h3)) | ((z8) << (32'h3))) & ~(1 << (32'h2)) | ((z4) << (32'h2))) & ~(1 << (32'h1)) | ((z2) << (32'h1))) & ~(1 << (32'h0)) | ((z1) << (32'h0)));
    end
    
endmodule // top$core$dop$dot_l$mul_0$norm_a


module top$core$dop$dot_l$mul_0$s1_exp(d,q,clock);
    
    // Module arguments
    input wire  [9:0] d;
    output reg  [9:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 10'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$core$dop$dot_l$mul_0$s1_exp


module top$core$dop$dot_l$mul_0$sig_mul(a,b,hi,sticky);
    
    // Module arguments
    input wire  [23:0] a;
    input wire  [23:0] b;
    output reg  [25:0] hi;
    output reg  sticky;
    
    // Update code (custom)
    wire [47:0] prod;
    assign prod = a * b;
    always @(*) begin
        hi = prod[47:22];
        sticky = |prod[21:0];
    end
endmodule // top$core$dop$dot_l$mul_0$sig_mul


module top$core$dop$dot_l$r_mul(clock,d,q);
    
    // Module arguments
    input wire  clock;
    input wire  d;
    output reg  q;
    
    // Stub signals
    reg  line$0$d;
    wire  line$0$q;
    reg  line$0$clock;
    reg  line$1$d;
    wire  line$1$q;
    reg  line$1$clock;
    reg  line$2$d;
    wire  line$2$q;
    reg  line$2$clock;
    
    // Sub module instances
    top$core$done_r line$0(
        .d(line$0$d),
        .q(line$0$q),
        .clock(line$0$clock)
    );
    top$core$done_r line$1(
        .d(line$1$d),
        .q(line$1$q),
        .clock(line$1$clock)
    );
    top$core$done_r line$2(
        .d(line$2$d),
        .q(line$2$q),
        .clock(line$2$clock)
    );
    
    // Update code
    always @(*) begin
        line$0$clock = clock;
        line$0$d = d;
        line$1$clock = clock;
        line$1$d = d;
        line$2$clock = clock;
        line$2$d = d;
        line$0$d = line$1$q;
        line$1$d = line$2$q;
        q = line$0$q;
    end
    
endmodule // top$core$dop$dot_l$r_mul


module top$core$dop$dprime(clock,wr_valid,wr_set,wr_lane,wr_l,wr_r,rd_set,rd_entry,dl,dr);
    
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
    top$core$dop$dprime$ram_l0 ram_l0(
        .read_address(ram_l0$read_address),
        .read_clock(ram_l0$read_clock),
        .read_data(ram_l0$read_data),
        .write_address(ram_l0$write_address),
        .write_clock(ram_l0$write_clock),
        .write_data(ram_l0$write_data),
        .write_enable(ram_l0$write_enable)
    );
    top$core$dop$dprime$ram_l0 ram_r0(
        .read_address(ram_r0$read_address),
        .read_clock(ram_r0$read_clock),
        .read_data(ram_r0$read_data),
        .write_address(ram_r0$write_address),
        .write_clock(ram_r0$write_clock),
        .write_data(ram_r0$write_data),
        .write_enable(ram_r0$write_enable)
    );
    top$core$dop$dprime$ram_l0 ram_l1(
        .read_address(ram_l1$read_address),
        .read_clock(ram_l1$read_clock),
        .read_data(ram_l1$read_data),
        .write_address(ram_l1$write_address),
        .write_clock(ram_l1$write_clock),
        .write_data(ram_l1$write_data),
        .write_enable(ram_l1$write_enable)
    );
    top$core$dop$dprime$ram_l0 ram_r1(
        .read_address(ram_r1$read_address),
        .read_clock(ram_r1$read_clock),
        .read_data(ram_r1$read_data),
        .write_address(ram_r1$write_address),
        .write_clock(ram_r1$write_clock),
        .write_data(ram_r1$write_data),
        .write_enable(ram_r1$write_enable)
    );
    top$core$dop$dprime$ram_l0 ram_l2(
        .read_address(ram_l2$read_address),
        .read_clock(ram_l2$read_clock),
        .read_data(ram_l2$read_data),
        .write_address(ram_l2$write_address),
        .write_clock(ram_l2$write_clock),
        .write_data(ram_l2$write_data),
        .write_enable(ram_l2$write_enable)
    );
    top$core$dop$dprime$ram_l0 ram_r2(
        .read_address(ram_r2$read_address),
        .read_clock(ram_r2$read_clock),
        .read_data(ram_r2$read_data),
        .write_address(ram_r2$write_address),
        .write_clock(ram_r2$write_clock),
        .write_data(ram_r2$write_data),
        .write_enable(ram_r2$write_enable)
    );
    top$core$dop$dprime$ram_l0 ram_l3(
        .read_address(ram_l3$read_address),
        .read_clock(ram_l3$read_clock),
        .read_data(ram_l3$read_data),
        .write_address(ram_l3$write_address),
        .write_clock(ram_l3$write_clock),
        .write_data(ram_l3$write_data),
        .write_enable(ram_l3$write_enable)
    );
    top$core$dop$dprime$ram_l0 ram_r3(
        .read_address(ram_r3$read_address),
        .read_clock(ram_r3$read_clock),
        .read_data(ram_r3$read_data),
        .write_address(ram_r3$write_address),
        .write_clock(ram_r3$write_clock),
        .write_data(ram_r3$write_data),
        .write_enable(ram_r3$write_enable)
    );
    top$core$dop$dprime$ram_l0 ram_l4(
        .read_address(ram_l4$read_address),
        .read_clock(ram_l4$read_clock),
        .read_data(ram_l4$read_data),
        .write_address(ram_l4$write_address),
        .write_clock(ram_l4$write_clock),
        .write_data(ram_l4$write_data),
        .write_enable(ram_l4$write_enable)
    );
    top$core$dop$dprime$ram_l0 ram_r4(
        .read_address(ram_r4$read_address),
        .read_clock(ram_r4$read_clock),
        .read_data(ram_r4$read_data),
        .write_address(ram_r4$write_address),
        .write_clock(ram_r4$write_clock),
        .write_data(ram_r4$write_data),
        .write_enable(ram_r4$write_enable)
    );
    top$core$dop$dprime$ram_l0 ram_l5(
        .read_address(ram_l5$read_address),
        .read_clock(ram_l5$read_clock),
        .read_data(ram_l5$read_data),
        .write_address(ram_l5$write_address),
        .write_clock(ram_l5$write_clock),
        .write_data(ram_l5$write_data),
        .write_enable(ram_l5$write_enable)
    );
    top$core$dop$dprime$ram_l0 ram_r5(
        .read_address(ram_r5$read_address),
        .read_clock(ram_r5$read_clock),
        .read_data(ram_r5$read_data),
        .write_address(ram_r5$write_address),
        .write_clock(ram_r5$write_clock),
        .write_data(ram_r5$write_data),
        .write_enable(ram_r5$write_enable)
    );
    top$core$dop$dprime$ram_l0 ram_l6(
        .read_address(ram_l6$read_address),
        .read_clock(ram_l6$read_clock),
        .read_data(ram_l6$read_data),
        .write_address(ram_l6$write_address),
        .write_clock(ram_l6$write_clock),
        .write_data(ram_l6$write_data),
        .write_enable(ram_l6$write_enable)
    );
    top$core$dop$dprime$ram_l0 ram_r6(
        .read_address(ram_r6$read_address),
        .read_clock(ram_r6$read_clock),
        .read_data(ram_r6$read_data),
        .write_address(ram_r6$write_address),
        .write_clock(ram_r6$write_clock),
        .write_data(ram_r6$write_data),
        .write_enable(ram_r6$write_enable)
    );
    top$core$dop$dprime$ram_l0 ram_l7(
        .read_address(ram_l7$read_address),
        .read_clock(ram_l7$read_clock),
        .read_data(ram_l7$read_data),
        .write_address(ram_l7$write_address),
        .write_clock(ram_l7$write_clock),
        .write_data(ram_l7$write_data),
        .write_enable(ram_l7$write_enable)
    );
    top$core$dop$dprime$ram_l0 ram_r7(
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
    
endmodule // top$core$dop$dprime


module top$core$dop$dprime$ram_l0(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
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
                
endmodule // top$core$dop$dprime$ram_l0


module top$core$dop$gen_cnt(d,q,clock);
    
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
          
endmodule // top$core$dop$gen_cnt


module top$core$dop$klm_l(d$0,d$1,d$2,d$3,d$4,d$5,d$6,d$7,d$8,d$9,d$10,d$11,d$12,d$13,d$14,d$15,d$16,d$17,d$18,d$19,d$20,d$21,d$22,d$23,j0$0,j1$0,j2$0,y0$0,y1$0,y2$0);
    
    // Module arguments
    input wire  [31:0] d$0;
    input wire  [31:0] d$1;
    input wire  [31:0] d$2;
    input wire  [31:0] d$3;
    input wire  [31:0] d$4;
    input wire  [31:0] d$5;
    input wire  [31:0] d$6;
    input wire  [31:0] d$7;
    input wire  [31:0] d$8;
    input wire  [31:0] d$9;
    input wire  [31:0] d$10;
    input wire  [31:0] d$11;
    input wire  [31:0] d$12;
    input wire  [31:0] d$13;
    input wire  [31:0] d$14;
    input wire  [31:0] d$15;
    input wire  [31:0] d$16;
    input wire  [31:0] d$17;
    input wire  [31:0] d$18;
    input wire  [31:0] d$19;
    input wire  [31:0] d$20;
    input wire  [31:0] d$21;
    input wire  [31:0] d$22;
    input wire  [31:0] d$23;
    input wire  [4:0] j0$0;
    input wire  [4:0] j1$0;
    input wire  [4:0] j2$0;
    output reg  [31:0] y0$0;
    output reg  [31:0] y1$0;
    output reg  [31:0] y2$0;
    
    // Constant declarations
    localparam  idx$0 = 5'b0;
    localparam  idx$1 = 5'b1;
    localparam  idx$2 = 5'b10;
    localparam  idx$3 = 5'b11;
    localparam  idx$4 = 5'b100;
    localparam  idx$5 = 5'b101;
    localparam  idx$6 = 5'b110;
    localparam  idx$7 = 5'b111;
    localparam  idx$8 = 5'b1000;
    localparam  idx$9 = 5'b1001;
    localparam  idx$10 = 5'b1010;
    localparam  idx$11 = 5'b1011;
    localparam  idx$12 = 5'b1100;
    localparam  idx$13 = 5'b1101;
    localparam  idx$14 = 5'b1110;
    localparam  idx$15 = 5'b1111;
    localparam  idx$16 = 5'b10000;
    localparam  idx$17 = 5'b10001;
    localparam  idx$18 = 5'b10010;
    localparam  idx$19 = 5'b10011;
    localparam  idx$20 = 5'b10100;
    localparam  idx$21 = 5'b10101;
    localparam  idx$22 = 5'b10110;
    localparam  idx$23 = 5'b10111;
    
    // Update code
    always @(*) begin
        y0$0 = 32'h0;
        y1$0 = 32'h0;
        y2$0 = 32'h0;
        if (j0$0 == idx$0) begin
            y0$0 = d$0;
        end
        if (j1$0 == idx$0) begin
            y1$0 = d$0;
        end
        if (j2$0 == idx$0) begin
            y2$0 = d$0;
        end
        if (j0$0 == idx$1) begin
            y0$0 = d$1;
        end
        if (j1$0 == idx$1) begin
            y1$0 = d$1;
        end
        if (j2$0 == idx$1) begin
            y2$0 = d$1;
        end
        if (j0$0 == idx$2) begin
            y0$0 = d$2;
        end
        if (j1$0 == idx$2) begin
            y1$0 = d$2;
        end
        if (j2$0 == idx$2) begin
            y2$0 = d$2;
        end
        if (j0$0 == idx$3) begin
            y0$0 = d$3;
        end
        if (j1$0 == idx$3) begin
            y1$0 = d$3;
        end
        if (j2$0 == idx$3) begin
            y2$0 = d$3;
        end
        if (j0$0 == idx$4) begin
            y0$0 = d$4;
        end
        if (j1$0 == idx$4) begin
            y1$0 = d$4;
        end
        if (j2$0 == idx$4) begin
            y2$0 = d$4;
        end
        if (j0$0 == idx$5) begin
            y0$0 = d$5;
        end
        if (j1$0 == idx$5) begin
            y1$0 = d$5;
        end
        if (j2$0 == idx$5) begin
            y2$0 = d$5;
        end
        if (j0$0 == idx$6) begin
            y0$0 = d$6;
        end
        if (j1$0 == idx$6) begin
            y1$0 = d$6;
        end
        if (j2$0 == idx$6) begin
            y2$0 = d$6;
        end
        if (j0$0 == idx$7) begin
            y0$0 = d$7;
        end
        if (j1$0 == idx$7) begin
            y1$0 = d$7;
        end
        if (j2$0 == idx$7) begin
            y2$0 = d$7;
        end
        if (j0$0 == idx$8) begin
            y0$0 = d$8;
        end
        if (j1$0 == idx$8) begin
            y1$0 = d$8;
        end
        if (j2$0 == idx$8) begin
            y2$0 = d$8;
        end
        if (j0$0 == idx$9) begin
            y0$0 = d$9;
        end
        if (j1$0 == idx$9) begin
            y1$0 = d$9;
        end
        if (j2$0 == idx$9) begin
            y2$0 = d$9;
        end
        if (j0$0 == idx$10) begin
            y0$0 = d$10;
        end
        if (j1$0 == idx$10) begin
            y1$0 = d$10;
        end
        if (j2$0 == idx$10) begin
            y2$0 = d$10;
        end
        if (j0$0 == idx$11) begin
            y0$0 = d$11;
        end
        if (j1$0 == idx$11) begin
            y1$0 = d$11;
        end
        if (j2$0 == idx$11) begin
            y2$0 = d$11;
        end
        if (j0$0 == idx$12) begin
            y0$0 = d$12;
        end
        if (j1$0 == idx$12) begin
            y1$0 = d$12;
        end
        if (j2$0 == idx$12) begin
            y2$0 = d$12;
        end
        if (j0$0 == idx$13) begin
            y0$0 = d$13;
        end
        if (j1$0 == idx$13) begin
            y1$0 = d$13;
        end
        if (j2$0 == idx$13) begin
            y2$0 = d$13;
        end
        if (j0$0 == idx$14) begin
            y0$0 = d$14;
        end
        if (j1$0 == idx$14) begin
            y1$0 = d$14;
        end
        if (j2$0 == idx$14) begin
            y2$0 = d$14;
        end
        if (j0$0 == idx$15) begin
            y0$0 = d$15;
        end
        if (j1$0 == idx$15) begin
            y1$0 = d$15;
        end
        if (j2$0 == idx$15) begin
            y2$0 = d$15;
        end
        if (j0$0 == idx$16) begin
            y0$0 = d$16;
        end
        if (j1$0 == idx$16) begin
            y1$0 = d$16;
        end
        if (j2$0 == idx$16) begin
            y2$0 = d$16;
        end
        if (j0$0 == idx$17) begin
            y0$0 = d$17;
        end
        if (j1$0 == idx$17) begin
            y1$0 = d$17;
        end
        if (j2$0 == idx$17) begin
            y2$0 = d$17;
        end
        if (j0$0 == idx$18) begin
            y0$0 = d$18;
        end
        if (j1$0 == idx$18) begin
            y1$0 = d$18;
        end
        if (j2$0 == idx$18) begin
            y2$0 = d$18;
        end
        if (j0$0 == idx$19) begin
            y0$0 = d$19;
        end
        if (j1$0 == idx$19) begin
            y1$0 = d$19;
        end
        if (j2$0 == idx$19) begin
            y2$0 = d$19;
        end
        if (j0$0 == idx$20) begin
            y0$0 = d$20;
        end
        if (j1$0 == idx$20) begin
            y1$0 = d$20;
        end
        if (j2$0 == idx$20) begin
            y2$0 = d$20;
        end
        if (j0$0 == idx$21) begin
            y0$0 = d$21;
        end
        if (j1$0 == idx$21) begin
            y1$0 = d$21;
        end
        if (j2$0 == idx$21) begin
            y2$0 = d$21;
        end
        if (j0$0 == idx$22) begin
            y0$0 = d$22;
        end
        if (j1$0 == idx$22) begin
            y1$0 = d$22;
        end
        if (j2$0 == idx$22) begin
            y2$0 = d$22;
        end
        if (j0$0 == idx$23) begin
            y0$0 = d$23;
        end
        if (j1$0 == idx$23) begin
            y1$0 = d$23;
        end
        if (j2$0 == idx$23) begin
            y2$0 = d$23;
        end
    end
    
endmodule // top$core$dop$klm_l


module top$core$dop$mmm$0(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [4:0] read_address;
    input wire  read_clock;
    output reg  [31:0] read_data;
    input wire  [4:0] write_address;
    input wire  write_clock;
    input wire  [31:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    reg[31:0] mem[31:0];
    
    
    
    always @(posedge read_clock) begin
       read_data <= mem[read_address];
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address] <= write_data;
       end
    end
                
endmodule // top$core$dop$mmm$0


module top$core$dop$sa_e(d,q,clock);
    
    // Module arguments
    input wire  [255:0] d;
    output reg  [255:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 256'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$core$dop$sa_e


module top$core$dop$wr_tag(clock,d,q);
    
    // Module arguments
    input wire  clock;
    input wire  [6:0] d;
    output reg  [6:0] q;
    
    // Stub signals
    reg  [6:0] line$0$d;
    wire  [6:0] line$0$q;
    reg  line$0$clock;
    reg  [6:0] line$1$d;
    wire  [6:0] line$1$q;
    reg  line$1$clock;
    reg  [6:0] line$2$d;
    wire  [6:0] line$2$q;
    reg  line$2$clock;
    reg  [6:0] line$3$d;
    wire  [6:0] line$3$q;
    reg  line$3$clock;
    reg  [6:0] line$4$d;
    wire  [6:0] line$4$q;
    reg  line$4$clock;
    reg  [6:0] line$5$d;
    wire  [6:0] line$5$q;
    reg  line$5$clock;
    reg  [6:0] line$6$d;
    wire  [6:0] line$6$q;
    reg  line$6$clock;
    reg  [6:0] line$7$d;
    wire  [6:0] line$7$q;
    reg  line$7$clock;
    reg  [6:0] line$8$d;
    wire  [6:0] line$8$q;
    reg  line$8$clock;
    reg  [6:0] line$9$d;
    wire  [6:0] line$9$q;
    reg  line$9$clock;
    reg  [6:0] line$10$d;
    wire  [6:0] line$10$q;
    reg  line$10$clock;
    reg  [6:0] line$11$d;
    wire  [6:0] line$11$q;
    reg  line$11$clock;
    
    // Sub module instances
    top$core$dop$wr_tag$line$0 line$0(
        .d(line$0$d),
        .q(line$0$q),
        .clock(line$0$clock)
    );
    top$core$dop$wr_tag$line$0 line$1(
        .d(line$1$d),
        .q(line$1$q),
        .clock(line$1$clock)
    );
    top$core$dop$wr_tag$line$0 line$2(
        .d(line$2$d),
        .q(line$2$q),
        .clock(line$2$clock)
    );
    top$core$dop$wr_tag$line$0 line$3(
        .d(line$3$d),
        .q(line$3$q),
        .clock(line$3$clock)
    );
    top$core$dop$wr_tag$line$0 line$4(
        .d(line$4$d),
        .q(line$4$q),
        .clock(line$4$clock)
    );
    top$core$dop$wr_tag$line$0 line$5(
        .d(line$5$d),
        .q(line$5$q),
        .clock(line$5$clock)
    );
    top$core$dop$wr_tag$line$0 line$6(
        .d(line$6$d),
        .q(line$6$q),
        .clock(line$6$clock)
    );
    top$core$dop$wr_tag$line$0 line$7(
        .d(line$7$d),
        .q(line$7$q),
        .clock(line$7$clock)
    );
    top$core$dop$wr_tag$line$0 line$8(
        .d(line$8$d),
        .q(line$8$q),
        .clock(line$8$clock)
    );
    top$core$dop$wr_tag$line$0 line$9(
        .d(line$9$d),
        .q(line$9$q),
        .clock(line$9$clock)
    );
    top$core$dop$wr_tag$line$0 line$10(
        .d(line$10$d),
        .q(line$10$q),
        .clock(line$10$clock)
    );
    top$core$dop$wr_tag$line$0 line$11(
        .d(line$11$d),
        .q(line$11$q),
        .clock(line$11$clock)
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
        line$4$clock = clock;
        line$4$d = d;
        line$5$clock = clock;
        line$5$d = d;
        line$6$clock = clock;
        line$6$d = d;
        line$7$clock = clock;
        line$7$d = d;
        line$8$clock = clock;
        line$8$d = d;
        line$9$clock = clock;
        line$9$d = d;
        line$10$clock = clock;
        line$10$d = d;
        line$11$clock = clock;
        line$11$d = d;
        line$0$d = line$1$q;
        line$1$d = line$2$q;
        line$2$d = line$3$q;
        line$3$d = line$4$q;
        line$4$d = line$5$q;
        line$5$d = line$6$q;
        line$6$d = line$7$q;
        line$7$d = line$8$q;
        line$8$d = line$9$q;
        line$9$d = line$10$q;
        line$10$d = line$11$q;
        q = line$0$q;
    end
    
endmodule // top$core$dop$wr_tag


module top$core$dop$wr_tag$line$0(d,q,clock);
    
    // Module arguments
    input wire  [6:0] d;
    output reg  [6:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 7'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$core$dop$wr_tag$line$0


module top$core$lists(clock,clear,append,wr_side,wr_ptr,read,next_list,level,branch,remaining,busy,done,rd_valid,rd_ptr,overflow);
    
    // Module arguments
    input wire  clock;
    input wire  clear;
    input wire  append;
    input wire  wr_side;
    input wire  [15:0] wr_ptr;
    input wire  read;
    input wire  next_list;
    output reg  [4:0] level;
    output reg  branch;
    output reg  [15:0] remaining;
    output reg  busy;
    output reg  done;
    output reg  rd_valid;
    output reg  [15:0] rd_ptr;
    output reg  overflow;
    
    // Constant declarations
    localparam  idx$0 = 5'b0;
    localparam  idx$1 = 5'b1;
    localparam  idx$2 = 5'b10;
    localparam  idx$3 = 5'b11;
    localparam  idx$4 = 5'b100;
    localparam  idx$5 = 5'b101;
    localparam  idx$6 = 5'b110;
    localparam  idx$7 = 5'b111;
    localparam  idx$8 = 5'b1000;
    localparam  idx$9 = 5'b1001;
    localparam  idx$10 = 5'b1010;
    localparam  idx$11 = 5'b1011;
    localparam  idx$12 = 5'b1100;
    localparam  idx$13 = 5'b1101;
    localparam  idx$14 = 5'b1110;
    localparam  idx$15 = 5'b1111;
    localparam  idx$16 = 5'b10000;
    localparam  idx$17 = 5'b10001;
    localparam  idx$18 = 5'b10010;
    localparam  idx$19 = 5'b10011;
    localparam  idx$20 = 5'b10100;
    localparam  idx$21 = 5'b10101;
    localparam  idx$22 = 5'b10110;
    localparam  idx$23 = 5'b10111;
    localparam  idx$24 = 5'b11000;
    localparam  idx$25 = 5'b11001;
    localparam  idx$26 = 5'b11010;
    localparam  idx$27 = 5'b11011;
    localparam  idx$28 = 5'b11100;
    localparam  idx$29 = 5'b11101;
    localparam  idx$30 = 5'b11110;
    localparam  idx$31 = 5'b11111;
    localparam  cap = 16'h1000;
    
    // Stub signals
    reg  [11:0] sram_l$read_address;
    reg  sram_l$read_clock;
    wire  [15:0] sram_l$read_data;
    reg  [11:0] sram_l$write_address;
    reg  sram_l$write_clock;
    reg  [15:0] sram_l$write_data;
    reg  sram_l$write_enable;
    reg  [11:0] sram_r$read_address;
    reg  sram_r$read_clock;
    wire  [15:0] sram_r$read_data;
    reg  [11:0] sram_r$write_address;
    reg  sram_r$write_clock;
    reg  [15:0] sram_r$write_data;
    reg  sram_r$write_enable;
    reg  [4:0] lvl$d;
    wire  [4:0] lvl$q;
    reg  lvl$clock;
    reg  [15:0] pos$d;
    wire  [15:0] pos$q;
    reg  pos$clock;
    reg  [15:0] rem$d;
    wire  [15:0] rem$q;
    reg  rem$clock;
    reg  cur_b$d;
    wire  cur_b$q;
    reg  cur_b$clock;
    reg  [15:0] wa_l$d;
    wire  [15:0] wa_l$q;
    reg  wa_l$clock;
    reg  [15:0] wa_r$d;
    wire  [15:0] wa_r$q;
    reg  wa_r$clock;
    reg  up$d;
    wire  up$q;
    reg  up$clock;
    reg  done_r$d;
    wire  done_r$q;
    reg  done_r$clock;
    reg  ovf$d;
    wire  ovf$q;
    reg  ovf$clock;
    reg  rd_v$d;
    wire  rd_v$q;
    reg  rd_v$clock;
    reg  rd_side$d;
    wire  rd_side$q;
    reg  rd_side$clock;
    reg  br$0$d;
    wire  br$0$q;
    reg  br$0$clock;
    reg  br$1$d;
    wire  br$1$q;
    reg  br$1$clock;
    reg  br$2$d;
    wire  br$2$q;
    reg  br$2$clock;
    reg  br$3$d;
    wire  br$3$q;
    reg  br$3$clock;
    reg  br$4$d;
    wire  br$4$q;
    reg  br$4$clock;
    reg  br$5$d;
    wire  br$5$q;
    reg  br$5$clock;
    reg  br$6$d;
    wire  br$6$q;
    reg  br$6$clock;
    reg  br$7$d;
    wire  br$7$q;
    reg  br$7$clock;
    reg  br$8$d;
    wire  br$8$q;
    reg  br$8$clock;
    reg  br$9$d;
    wire  br$9$q;
    reg  br$9$clock;
    reg  br$10$d;
    wire  br$10$q;
    reg  br$10$clock;
    reg  br$11$d;
    wire  br$11$q;
    reg  br$11$clock;
    reg  br$12$d;
    wire  br$12$q;
    reg  br$12$clock;
    reg  br$13$d;
    wire  br$13$q;
    reg  br$13$clock;
    reg  br$14$d;
    wire  br$14$q;
    reg  br$14$clock;
    reg  br$15$d;
    wire  br$15$q;
    reg  br$15$clock;
    reg  br$16$d;
    wire  br$16$q;
    reg  br$16$clock;
    reg  br$17$d;
    wire  br$17$q;
    reg  br$17$clock;
    reg  br$18$d;
    wire  br$18$q;
    reg  br$18$clock;
    reg  br$19$d;
    wire  br$19$q;
    reg  br$19$clock;
    reg  br$20$d;
    wire  br$20$q;
    reg  br$20$clock;
    reg  br$21$d;
    wire  br$21$q;
    reg  br$21$clock;
    reg  br$22$d;
    wire  br$22$q;
    reg  br$22$clock;
    reg  br$23$d;
    wire  br$23$q;
    reg  br$23$clock;
    reg  br$24$d;
    wire  br$24$q;
    reg  br$24$clock;
    reg  br$25$d;
    wire  br$25$q;
    reg  br$25$clock;
    reg  br$26$d;
    wire  br$26$q;
    reg  br$26$clock;
    reg  br$27$d;
    wire  br$27$q;
    reg  br$27$clock;
    reg  br$28$d;
    wire  br$28$q;
    reg  br$28$clock;
    reg  br$29$d;
    wire  br$29$q;
    reg  br$29$clock;
    reg  br$30$d;
    wire  br$30$q;
    reg  br$30$clock;
    reg  br$31$d;
    wire  br$31$q;
    reg  br$31$clock;
    reg  [15:0] start_l$0$d;
    wire  [15:0] start_l$0$q;
    reg  start_l$0$clock;
    reg  [15:0] start_l$1$d;
    wire  [15:0] start_l$1$q;
    reg  start_l$1$clock;
    reg  [15:0] start_l$2$d;
    wire  [15:0] start_l$2$q;
    reg  start_l$2$clock;
    reg  [15:0] start_l$3$d;
    wire  [15:0] start_l$3$q;
    reg  start_l$3$clock;
    reg  [15:0] start_l$4$d;
    wire  [15:0] start_l$4$q;
    reg  start_l$4$clock;
    reg  [15:0] start_l$5$d;
    wire  [15:0] start_l$5$q;
    reg  start_l$5$clock;
    reg  [15:0] start_l$6$d;
    wire  [15:0] start_l$6$q;
    reg  start_l$6$clock;
    reg  [15:0] start_l$7$d;
    wire  [15:0] start_l$7$q;
    reg  start_l$7$clock;
    reg  [15:0] start_l$8$d;
    wire  [15:0] start_l$8$q;
    reg  start_l$8$clock;
    reg  [15:0] start_l$9$d;
    wire  [15:0] start_l$9$q;
    reg  start_l$9$clock;
    reg  [15:0] start_l$10$d;
    wire  [15:0] start_l$10$q;
    reg  start_l$10$clock;
    reg  [15:0] start_l$11$d;
    wire  [15:0] start_l$11$q;
    reg  start_l$11$clock;
    reg  [15:0] start_l$12$d;
    wire  [15:0] start_l$12$q;
    reg  start_l$12$clock;
    reg  [15:0] start_l$13$d;
    wire  [15:0] start_l$13$q;
    reg  start_l$13$clock;
    reg  [15:0] start_l$14$d;
    wire  [15:0] start_l$14$q;
    reg  start_l$14$clock;
    reg  [15:0] start_l$15$d;
    wire  [15:0] start_l$15$q;
    reg  start_l$15$clock;
    reg  [15:0] start_l$16$d;
    wire  [15:0] start_l$16$q;
    reg  start_l$16$clock;
    reg  [15:0] start_l$17$d;
    wire  [15:0] start_l$17$q;
    reg  start_l$17$clock;
    reg  [15:0] start_l$18$d;
    wire  [15:0] start_l$18$q;
    reg  start_l$18$clock;
    reg  [15:0] start_l$19$d;
    wire  [15:0] start_l$19$q;
    reg  start_l$19$clock;
    reg  [15:0] start_l$20$d;
    wire  [15:0] start_l$20$q;
    reg  start_l$20$clock;
    reg  [15:0] start_l$21$d;
    wire  [15:0] start_l$21$q;
    reg  start_l$21$clock;
    reg  [15:0] start_l$22$d;
    wire  [15:0] start_l$22$q;
    reg  start_l$22$clock;
    reg  [15:0] start_l$23$d;
    wire  [15:0] start_l$23$q;
    reg  start_l$23$clock;
    reg  [15:0] start_l$24$d;
    wire  [15:0] start_l$24$q;
    reg  start_l$24$clock;
    reg  [15:0] start_l$25$d;
    wire  [15:0] start_l$25$q;
    reg  start_l$25$clock;
    reg  [15:0] start_l$26$d;
    wire  [15:0] start_l$26$q;
    reg  start_l$26$clock;
    reg  [15:0] start_l$27$d;
    wire  [15:0] start_l$27$q;
    reg  start_l$27$clock;
    reg  [15:0] start_l$28$d;
    wire  [15:0] start_l$28$q;
    reg  start_l$28$clock;
    reg  [15:0] start_l$29$d;
    wire  [15:0] start_l$29$q;
    reg  start_l$29$clock;
    reg  [15:0] start_l$30$d;
    wire  [15:0] start_l$30$q;
    reg  start_l$30$clock;
    reg  [15:0] start_l$31$d;
    wire  [15:0] start_l$31$q;
    reg  start_l$31$clock;
    reg  [15:0] start_r$0$d;
    wire  [15:0] start_r$0$q;
    reg  start_r$0$clock;
    reg  [15:0] start_r$1$d;
    wire  [15:0] start_r$1$q;
    reg  start_r$1$clock;
    reg  [15:0] start_r$2$d;
    wire  [15:0] start_r$2$q;
    reg  start_r$2$clock;
    reg  [15:0] start_r$3$d;
    wire  [15:0] start_r$3$q;
    reg  start_r$3$clock;
    reg  [15:0] start_r$4$d;
    wire  [15:0] start_r$4$q;
    reg  start_r$4$clock;
    reg  [15:0] start_r$5$d;
    wire  [15:0] start_r$5$q;
    reg  start_r$5$clock;
    reg  [15:0] start_r$6$d;
    wire  [15:0] start_r$6$q;
    reg  start_r$6$clock;
    reg  [15:0] start_r$7$d;
    wire  [15:0] start_r$7$q;
    reg  start_r$7$clock;
    reg  [15:0] start_r$8$d;
    wire  [15:0] start_r$8$q;
    reg  start_r$8$clock;
    reg  [15:0] start_r$9$d;
    wire  [15:0] start_r$9$q;
    reg  start_r$9$clock;
    reg  [15:0] start_r$10$d;
    wire  [15:0] start_r$10$q;
    reg  start_r$10$clock;
    reg  [15:0] start_r$11$d;
    wire  [15:0] start_r$11$q;
    reg  start_r$11$clock;
    reg  [15:0] start_r$12$d;
    wire  [15:0] start_r$12$q;
    reg  start_r$12$clock;
    reg  [15:0] start_r$13$d;
    wire  [15:0] start_r$13$q;
    reg  start_r$13$clock;
    reg  [15:0] start_r$14$d;
    wire  [15:0] start_r$14$q;
    reg  start_r$14$clock;
    reg  [15:0] start_r$15$d;
    wire  [15:0] start_r$15$q;
    reg  start_r$15$clock;
    reg  [15:0] start_r$16$d;
    wire  [15:0] start_r$16$q;
    reg  start_r$16$clock;
    reg  [15:0] start_r$17$d;
    wire  [15:0] start_r$17$q;
    reg  start_r$17$clock;
    reg  [15:0] start_r$18$d;
    wire  [15:0] start_r$18$q;
    reg  start_r$18$clock;
    reg  [15:0] start_r$19$d;
    wire  [15:0] start_r$19$q;
    reg  start_r$19$clock;
    reg  [15:0] start_r$20$d;
    wire  [15:0] start_r$20$q;
    reg  start_r$20$clock;
    reg  [15:0] start_r$21$d;
    wire  [15:0] start_r$21$q;
    reg  start_r$21$clock;
    reg  [15:0] start_r$22$d;
    wire  [15:0] start_r$22$q;
    reg  start_r$22$clock;
    reg  [15:0] start_r$23$d;
    wire  [15:0] start_r$23$q;
    reg  start_r$23$clock;
    reg  [15:0] start_r$24$d;
    wire  [15:0] start_r$24$q;
    reg  start_r$24$clock;
    reg  [15:0] start_r$25$d;
    wire  [15:0] start_r$25$q;
    reg  start_r$25$clock;
    reg  [15:0] start_r$26$d;
    wire  [15:0] start_r$26$q;
    reg  start_r$26$clock;
    reg  [15:0] start_r$27$d;
    wire  [15:0] start_r$27$q;
    reg  start_r$27$clock;
    reg  [15:0] start_r$28$d;
    wire  [15:0] start_r$28$q;
    reg  start_r$28$clock;
    reg  [15:0] start_r$29$d;
    wire  [15:0] start_r$29$q;
    reg  start_r$29$clock;
    reg  [15:0] start_r$30$d;
    wire  [15:0] start_r$30$q;
    reg  start_r$30$clock;
    reg  [15:0] start_r$31$d;
    wire  [15:0] start_r$31$q;
    reg  start_r$31$clock;
    reg  [15:0] len_l$0$d;
    wire  [15:0] len_l$0$q;
    reg  len_l$0$clock;
    reg  [15:0] len_l$1$d;
    wire  [15:0] len_l$1$q;
    reg  len_l$1$clock;
    reg  [15:0] len_l$2$d;
    wire  [15:0] len_l$2$q;
    reg  len_l$2$clock;
    reg  [15:0] len_l$3$d;
    wire  [15:0] len_l$3$q;
    reg  len_l$3$clock;
    reg  [15:0] len_l$4$d;
    wire  [15:0] len_l$4$q;
    reg  len_l$4$clock;
    reg  [15:0] len_l$5$d;
    wire  [15:0] len_l$5$q;
    reg  len_l$5$clock;
    reg  [15:0] len_l$6$d;
    wire  [15:0] len_l$6$q;
    reg  len_l$6$clock;
    reg  [15:0] len_l$7$d;
    wire  [15:0] len_l$7$q;
    reg  len_l$7$clock;
    reg  [15:0] len_l$8$d;
    wire  [15:0] len_l$8$q;
    reg  len_l$8$clock;
    reg  [15:0] len_l$9$d;
    wire  [15:0] len_l$9$q;
    reg  len_l$9$clock;
    reg  [15:0] len_l$10$d;
    wire  [15:0] len_l$10$q;
    reg  len_l$10$clock;
    reg  [15:0] len_l$11$d;
    wire  [15:0] len_l$11$q;
    reg  len_l$11$clock;
    reg  [15:0] len_l$12$d;
    wire  [15:0] len_l$12$q;
    reg  len_l$12$clock;
    reg  [15:0] len_l$13$d;
    wire  [15:0] len_l$13$q;
    reg  len_l$13$clock;
    reg  [15:0] len_l$14$d;
    wire  [15:0] len_l$14$q;
    reg  len_l$14$clock;
    reg  [15:0] len_l$15$d;
    wire  [15:0] len_l$15$q;
    reg  len_l$15$clock;
    reg  [15:0] len_l$16$d;
    wire  [15:0] len_l$16$q;
    reg  len_l$16$clock;
    reg  [15:0] len_l$17$d;
    wire  [15:0] len_l$17$q;
    reg  len_l$17$clock;
    reg  [15:0] len_l$18$d;
    wire  [15:0] len_l$18$q;
    reg  len_l$18$clock;
    reg  [15:0] len_l$19$d;
    wire  [15:0] len_l$19$q;
    reg  len_l$19$clock;
    reg  [15:0] len_l$20$d;
    wire  [15:0] len_l$20$q;
    reg  len_l$20$clock;
    reg  [15:0] len_l$21$d;
    wire  [15:0] len_l$21$q;
    reg  len_l$21$clock;
    reg  [15:0] len_l$22$d;
    wire  [15:0] len_l$22$q;
    reg  len_l$22$clock;
    reg  [15:0] len_l$23$d;
    wire  [15:0] len_l$23$q;
    reg  len_l$23$clock;
    reg  [15:0] len_l$24$d;
    wire  [15:0] len_l$24$q;
    reg  len_l$24$clock;
    reg  [15:0] len_l$25$d;
    wire  [15:0] len_l$25$q;
    reg  len_l$25$clock;
    reg  [15:0] len_l$26$d;
    wire  [15:0] len_l$26$q;
    reg  len_l$26$clock;
    reg  [15:0] len_l$27$d;
    wire  [15:0] len_l$27$q;
    reg  len_l$27$clock;
    reg  [15:0] len_l$28$d;
    wire  [15:0] len_l$28$q;
    reg  len_l$28$clock;
    reg  [15:0] len_l$29$d;
    wire  [15:0] len_l$29$q;
    reg  len_l$29$clock;
    reg  [15:0] len_l$30$d;
    wire  [15:0] len_l$30$q;
    reg  len_l$30$clock;
    reg  [15:0] len_l$31$d;
    wire  [15:0] len_l$31$q;
    reg  len_l$31$clock;
    reg  [15:0] len_r$0$d;
    wire  [15:0] len_r$0$q;
    reg  len_r$0$clock;
    reg  [15:0] len_r$1$d;
    wire  [15:0] len_r$1$q;
    reg  len_r$1$clock;
    reg  [15:0] len_r$2$d;
    wire  [15:0] len_r$2$q;
    reg  len_r$2$clock;
    reg  [15:0] len_r$3$d;
    wire  [15:0] len_r$3$q;
    reg  len_r$3$clock;
    reg  [15:0] len_r$4$d;
    wire  [15:0] len_r$4$q;
    reg  len_r$4$clock;
    reg  [15:0] len_r$5$d;
    wire  [15:0] len_r$5$q;
    reg  len_r$5$clock;
    reg  [15:0] len_r$6$d;
    wire  [15:0] len_r$6$q;
    reg  len_r$6$clock;
    reg  [15:0] len_r$7$d;
    wire  [15:0] len_r$7$q;
    reg  len_r$7$clock;
    reg  [15:0] len_r$8$d;
    wire  [15:0] len_r$8$q;
    reg  len_r$8$clock;
    reg  [15:0] len_r$9$d;
    wire  [15:0] len_r$9$q;
    reg  len_r$9$clock;
    reg  [15:0] len_r$10$d;
    wire  [15:0] len_r$10$q;
    reg  len_r$10$clock;
    reg  [15:0] len_r$11$d;
    wire  [15:0] len_r$11$q;
    reg  len_r$11$clock;
    reg  [15:0] len_r$12$d;
    wire  [15:0] len_r$12$q;
    reg  len_r$12$clock;
    reg  [15:0] len_r$13$d;
    wire  [15:0] len_r$13$q;
    reg  len_r$13$clock;
    reg  [15:0] len_r$14$d;
    wire  [15:0] len_r$14$q;
    reg  len_r$14$clock;
    reg  [15:0] len_r$15$d;
    wire  [15:0] len_r$15$q;
    reg  len_r$15$clock;
    reg  [15:0] len_r$16$d;
    wire  [15:0] len_r$16$q;
    reg  len_r$16$clock;
    reg  [15:0] len_r$17$d;
    wire  [15:0] len_r$17$q;
    reg  len_r$17$clock;
    reg  [15:0] len_r$18$d;
    wire  [15:0] len_r$18$q;
    reg  len_r$18$clock;
    reg  [15:0] len_r$19$d;
    wire  [15:0] len_r$19$q;
    reg  len_r$19$clock;
    reg  [15:0] len_r$20$d;
    wire  [15:0] len_r$20$q;
    reg  len_r$20$clock;
    reg  [15:0] len_r$21$d;
    wire  [15:0] len_r$21$q;
    reg  len_r$21$clock;
    reg  [15:0] len_r$22$d;
    wire  [15:0] len_r$22$q;
    reg  len_r$22$clock;
    reg  [15:0] len_r$23$d;
    wire  [15:0] len_r$23$q;
    reg  len_r$23$clock;
    reg  [15:0] len_r$24$d;
    wire  [15:0] len_r$24$q;
    reg  len_r$24$clock;
    reg  [15:0] len_r$25$d;
    wire  [15:0] len_r$25$q;
    reg  len_r$25$clock;
    reg  [15:0] len_r$26$d;
    wire  [15:0] len_r$26$q;
    reg  len_r$26$clock;
    reg  [15:0] len_r$27$d;
    wire  [15:0] len_r$27$q;
    reg  len_r$27$clock;
    reg  [15:0] len_r$28$d;
    wire  [15:0] len_r$28$q;
    reg  len_r$28$clock;
    reg  [15:0] len_r$29$d;
    wire  [15:0] len_r$29$q;
    reg  len_r$29$clock;
    reg  [15:0] len_r$30$d;
    wire  [15:0] len_r$30$q;
    reg  len_r$30$clock;
    reg  [15:0] len_r$31$d;
    wire  [15:0] len_r$31$q;
    reg  len_r$31$clock;
    
    // Local signals
    reg  c_b_up;
    reg  [15:0] c_cs_l;
    reg  [15:0] c_cs_r;
    reg  [15:0] c_cl_l;
    reg  [15:0] c_cl_r;
    reg  [15:0] c_ns_l;
    reg  [15:0] c_ns_r;
    reg  [15:0] c_nl_l;
    reg  [15:0] c_nl_r;
    reg  [4:0] c_l1;
    reg  [15:0] c_cur_start;
    reg  [15:0] c_raddr;
    reg  c_idle;
    reg  c_read;
    reg  [15:0] c_waddr;
    reg  c_wok;
    reg  c_next;
    reg  c_desc;
    reg  c_desc_b;
    reg  c_u_right;
    reg  c_u_zero;
    reg  c_open;
    reg  [4:0] c_open_lvl;
    reg  [15:0] c_open_l;
    reg  [15:0] c_open_r;
    
    // Sub module instances
    top$core$lists$sram_l sram_l(
        .read_address(sram_l$read_address),
        .read_clock(sram_l$read_clock),
        .read_data(sram_l$read_data),
        .write_address(sram_l$write_address),
        .write_clock(sram_l$write_clock),
        .write_data(sram_l$write_data),
        .write_enable(sram_l$write_enable)
    );
    top$core$lists$sram_l sram_r(
        .read_address(sram_r$read_address),
        .read_clock(sram_r$read_clock),
        .read_data(sram_r$read_data),
        .write_address(sram_r$write_address),
        .write_clock(sram_r$write_clock),
        .write_data(sram_r$write_data),
        .write_enable(sram_r$write_enable)
    );
    top$core$dop$gen_cnt lvl(
        .d(lvl$d),
        .q(lvl$q),
        .clock(lvl$clock)
    );
    top$core$lists$len_l$0 pos(
        .d(pos$d),
        .q(pos$q),
        .clock(pos$clock)
    );
    top$core$lists$len_l$0 rem(
        .d(rem$d),
        .q(rem$q),
        .clock(rem$clock)
    );
    top$core$done_r cur_b(
        .d(cur_b$d),
        .q(cur_b$q),
        .clock(cur_b$clock)
    );
    top$core$lists$len_l$0 wa_l(
        .d(wa_l$d),
        .q(wa_l$q),
        .clock(wa_l$clock)
    );
    top$core$lists$len_l$0 wa_r(
        .d(wa_r$d),
        .q(wa_r$q),
        .clock(wa_r$clock)
    );
    top$core$done_r up(
        .d(up$d),
        .q(up$q),
        .clock(up$clock)
    );
    top$core$done_r done_r(
        .d(done_r$d),
        .q(done_r$q),
        .clock(done_r$clock)
    );
    top$core$done_r ovf(
        .d(ovf$d),
        .q(ovf$q),
        .clock(ovf$clock)
    );
    top$core$done_r rd_v(
        .d(rd_v$d),
        .q(rd_v$q),
        .clock(rd_v$clock)
    );
    top$core$done_r rd_side(
        .d(rd_side$d),
        .q(rd_side$q),
        .clock(rd_side$clock)
    );
    top$core$done_r br$0(
        .d(br$0$d),
        .q(br$0$q),
        .clock(br$0$clock)
    );
    top$core$done_r br$1(
        .d(br$1$d),
        .q(br$1$q),
        .clock(br$1$clock)
    );
    top$core$done_r br$2(
        .d(br$2$d),
        .q(br$2$q),
        .clock(br$2$clock)
    );
    top$core$done_r br$3(
        .d(br$3$d),
        .q(br$3$q),
        .clock(br$3$clock)
    );
    top$core$done_r br$4(
        .d(br$4$d),
        .q(br$4$q),
        .clock(br$4$clock)
    );
    top$core$done_r br$5(
        .d(br$5$d),
        .q(br$5$q),
        .clock(br$5$clock)
    );
    top$core$done_r br$6(
        .d(br$6$d),
        .q(br$6$q),
        .clock(br$6$clock)
    );
    top$core$done_r br$7(
        .d(br$7$d),
        .q(br$7$q),
        .clock(br$7$clock)
    );
    top$core$done_r br$8(
        .d(br$8$d),
        .q(br$8$q),
        .clock(br$8$clock)
    );
    top$core$done_r br$9(
        .d(br$9$d),
        .q(br$9$q),
        .clock(br$9$clock)
    );
    top$core$done_r br$10(
        .d(br$10$d),
        .q(br$10$q),
        .clock(br$10$clock)
    );
    top$core$done_r br$11(
        .d(br$11$d),
        .q(br$11$q),
        .clock(br$11$clock)
    );
    top$core$done_r br$12(
        .d(br$12$d),
        .q(br$12$q),
        .clock(br$12$clock)
    );
    top$core$done_r br$13(
        .d(br$13$d),
        .q(br$13$q),
        .clock(br$13$clock)
    );
    top$core$done_r br$14(
        .d(br$14$d),
        .q(br$14$q),
        .clock(br$14$clock)
    );
    top$core$done_r br$15(
        .d(br$15$d),
        .q(br$15$q),
        .clock(br$15$clock)
    );
    top$core$done_r br$16(
        .d(br$16$d),
        .q(br$16$q),
        .clock(br$16$clock)
    );
    top$core$done_r br$17(
        .d(br$17$d),
        .q(br$17$q),
        .clock(br$17$clock)
    );
    top$core$done_r br$18(
        .d(br$18$d),
        .q(br$18$q),
        .clock(br$18$clock)
    );
    top$core$done_r br$19(
        .d(br$19$d),
        .q(br$19$q),
        .clock(br$19$clock)
    );
    top$core$done_r br$20(
        .d(br$20$d),
        .q(br$20$q),
        .clock(br$20$clock)
    );
    top$core$done_r br$21(
        .d(br$21$d),
        .q(br$21$q),
        .clock(br$21$clock)
    );
    top$core$done_r br$22(
        .d(br$22$d),
        .q(br$22$q),
        .clock(br$22$clock)
    );
    top$core$done_r br$23(
        .d(br$23$d),
        .q(br$23$q),
        .clock(br$23$clock)
    );
    top$core$done_r br$24(
        .d(br$24$d),
        .q(br$24$q),
        .clock(br$24$clock)
    );
    top$core$done_r br$25(
        .d(br$25$d),
        .q(br$25$q),
        .clock(br$25$clock)
    );
    top$core$done_r br$26(
        .d(br$26$d),
        .q(br$26$q),
        .clock(br$26$clock)
    );
    top$core$done_r br$27(
        .d(br$27$d),
        .q(br$27$q),
        .clock(br$27$clock)
    );
    top$core$done_r br$28(
        .d(br$28$d),
        .q(br$28$q),
        .clock(br$28$clock)
    );
    top$core$done_r br$29(
        .d(br$29$d),
        .q(br$29$q),
        .clock(br$29$clock)
    );
    top$core$done_r br$30(
        .d(br$30$d),
        .q(br$30$q),
        .clock(br$30$clock)
    );
    top$core$done_r br$31(
        .d(br$31$d),
        .q(br$31$q),
        .clock(br$31$clock)
    );
    top$core$lists$len_l$0 start_l$0(
        .d(start_l$0$d),
        .q(start_l$0$q),
        .clock(start_l$0$clock)
    );
    top$core$lists$len_l$0 start_l$1(
        .d(start_l$1$d),
        .q(start_l$1$q),
        .clock(start_l$1$clock)
    );
    top$core$lists$len_l$0 start_l$2(
        .d(start_l$2$d),
        .q(start_l$2$q),
        .clock(start_l$2$clock)
    );
    top$core$lists$len_l$0 start_l$3(
        .d(start_l$3$d),
        .q(start_l$3$q),
        .clock(start_l$3$clock)
    );
    top$core$lists$len_l$0 start_l$4(
        .d(start_l$4$d),
        .q(start_l$4$q),
        .clock(start_l$4$clock)
    );
    top$core$lists$len_l$0 start_l$5(
        .d(start_l$5$d),
        .q(start_l$5$q),
        .clock(start_l$5$clock)
    );
    top$core$lists$len_l$0 start_l$6(
        .d(start_l$6$d),
        .q(start_l$6$q),
        .clock(start_l$6$clock)
    );
    top$core$lists$len_l$0 start_l$7(
        .d(start_l$7$d),
        .q(start_l$7$q),
        .clock(start_l$7$clock)
    );
    top$core$lists$len_l$0 start_l$8(
        .d(start_l$8$d),
        .q(start_l$8$q),
        .clock(start_l$8$clock)
    );
    top$core$lists$len_l$0 start_l$9(
        .d(start_l$9$d),
        .q(start_l$9$q),
        .clock(start_l$9$clock)
    );
    top$core$lists$len_l$0 start_l$10(
        .d(start_l$10$d),
        .q(start_l$10$q),
        .clock(start_l$10$clock)
    );
    top$core$lists$len_l$0 start_l$11(
        .d(start_l$11$d),
        .q(start_l$11$q),
        .clock(start_l$11$clock)
    );
    top$core$lists$len_l$0 start_l$12(
        .d(start_l$12$d),
        .q(start_l$12$q),
        .clock(start_l$12$clock)
    );
    top$core$lists$len_l$0 start_l$13(
        .d(start_l$13$d),
        .q(start_l$13$q),
        .clock(start_l$13$clock)
    );
    top$core$lists$len_l$0 start_l$14(
        .d(start_l$14$d),
        .q(start_l$14$q),
        .clock(start_l$14$clock)
    );
    top$core$lists$len_l$0 start_l$15(
        .d(start_l$15$d),
        .q(start_l$15$q),
        .clock(start_l$15$clock)
    );
    top$core$lists$len_l$0 start_l$16(
        .d(start_l$16$d),
        .q(start_l$16$q),
        .clock(start_l$16$clock)
    );
    top$core$lists$len_l$0 start_l$17(
        .d(start_l$17$d),
        .q(start_l$17$q),
        .clock(start_l$17$clock)
    );
    top$core$lists$len_l$0 start_l$18(
        .d(start_l$18$d),
        .q(start_l$18$q),
        .clock(start_l$18$clock)
    );
    top$core$lists$len_l$0 start_l$19(
        .d(start_l$19$d),
        .q(start_l$19$q),
        .clock(start_l$19$clock)
    );
    top$core$lists$len_l$0 start_l$20(
        .d(start_l$20$d),
        .q(start_l$20$q),
        .clock(start_l$20$clock)
    );
    top$core$lists$len_l$0 start_l$21(
        .d(start_l$21$d),
        .q(start_l$21$q),
        .clock(start_l$21$clock)
    );
    top$core$lists$len_l$0 start_l$22(
        .d(start_l$22$d),
        .q(start_l$22$q),
        .clock(start_l$22$clock)
    );
    top$core$lists$len_l$0 start_l$23(
        .d(start_l$23$d),
        .q(start_l$23$q),
        .clock(start_l$23$clock)
    );
    top$core$lists$len_l$0 start_l$24(
        .d(start_l$24$d),
        .q(start_l$24$q),
        .clock(start_l$24$clock)
    );
    top$core$lists$len_l$0 start_l$25(
        .d(start_l$25$d),
        .q(start_l$25$q),
        .clock(start_l$25$clock)
    );
    top$core$lists$len_l$0 start_l$26(
        .d(start_l$26$d),
        .q(start_l$26$q),
        .clock(start_l$26$clock)
    );
    top$core$lists$len_l$0 start_l$27(
        .d(start_l$27$d),
        .q(start_l$27$q),
        .clock(start_l$27$clock)
    );
    top$core$lists$len_l$0 start_l$28(
        .d(start_l$28$d),
        .q(start_l$28$q),
        .clock(start_l$28$clock)
    );
    top$core$lists$len_l$0 start_l$29(
        .d(start_l$29$d),
        .q(start_l$29$q),
        .clock(start_l$29$clock)
    );
    top$core$lists$len_l$0 start_l$30(
        .d(start_l$30$d),
        .q(start_l$30$q),
        .clock(start_l$30$clock)
    );
    top$core$lists$len_l$0 start_l$31(
        .d(start_l$31$d),
        .q(start_l$31$q),
        .clock(start_l$31$clock)
    );
    top$core$lists$len_l$0 start_r$0(
        .d(start_r$0$d),
        .q(start_r$0$q),
        .clock(start_r$0$clock)
    );
    top$core$lists$len_l$0 start_r$1(
        .d(start_r$1$d),
        .q(start_r$1$q),
        .clock(start_r$1$clock)
    );
    top$core$lists$len_l$0 start_r$2(
        .d(start_r$2$d),
        .q(start_r$2$q),
        .clock(start_r$2$clock)
    );
    top$core$lists$len_l$0 start_r$3(
        .d(start_r$3$d),
        .q(start_r$3$q),
        .clock(start_r$3$clock)
    );
    top$core$lists$len_l$0 start_r$4(
        .d(start_r$4$d),
        .q(start_r$4$q),
        .clock(start_r$4$clock)
    );
    top$core$lists$len_l$0 start_r$5(
        .d(start_r$5$d),
        .q(start_r$5$q),
        .clock(start_r$5$clock)
    );
    top$core$lists$len_l$0 start_r$6(
        .d(start_r$6$d),
        .q(start_r$6$q),
        .clock(start_r$6$clock)
    );
    top$core$lists$len_l$0 start_r$7(
        .d(start_r$7$d),
        .q(start_r$7$q),
        .clock(start_r$7$clock)
    );
    top$core$lists$len_l$0 start_r$8(
        .d(start_r$8$d),
        .q(start_r$8$q),
        .clock(start_r$8$clock)
    );
    top$core$lists$len_l$0 start_r$9(
        .d(start_r$9$d),
        .q(start_r$9$q),
        .clock(start_r$9$clock)
    );
    top$core$lists$len_l$0 start_r$10(
        .d(start_r$10$d),
        .q(start_r$10$q),
        .clock(start_r$10$clock)
    );
    top$core$lists$len_l$0 start_r$11(
        .d(start_r$11$d),
        .q(start_r$11$q),
        .clock(start_r$11$clock)
    );
    top$core$lists$len_l$0 start_r$12(
        .d(start_r$12$d),
        .q(start_r$12$q),
        .clock(start_r$12$clock)
    );
    top$core$lists$len_l$0 start_r$13(
        .d(start_r$13$d),
        .q(start_r$13$q),
        .clock(start_r$13$clock)
    );
    top$core$lists$len_l$0 start_r$14(
        .d(start_r$14$d),
        .q(start_r$14$q),
        .clock(start_r$14$clock)
    );
    top$core$lists$len_l$0 start_r$15(
        .d(start_r$15$d),
        .q(start_r$15$q),
        .clock(start_r$15$clock)
    );
    top$core$lists$len_l$0 start_r$16(
        .d(start_r$16$d),
        .q(start_r$16$q),
        .clock(start_r$16$clock)
    );
    top$core$lists$len_l$0 start_r$17(
        .d(start_r$17$d),
        .q(start_r$17$q),
        .clock(start_r$17$clock)
    );
    top$core$lists$len_l$0 start_r$18(
        .d(start_r$18$d),
        .q(start_r$18$q),
        .clock(start_r$18$clock)
    );
    top$core$lists$len_l$0 start_r$19(
        .d(start_r$19$d),
        .q(start_r$19$q),
        .clock(start_r$19$clock)
    );
    top$core$lists$len_l$0 start_r$20(
        .d(start_r$20$d),
        .q(start_r$20$q),
        .clock(start_r$20$clock)
    );
    top$core$lists$len_l$0 start_r$21(
        .d(start_r$21$d),
        .q(start_r$21$q),
        .clock(start_r$21$clock)
    );
    top$core$lists$len_l$0 start_r$22(
        .d(start_r$22$d),
        .q(start_r$22$q),
        .clock(start_r$22$clock)
    );
    top$core$lists$len_l$0 start_r$23(
        .d(start_r$23$d),
        .q(start_r$23$q),
        .clock(start_r$23$clock)
    );
    top$core$lists$len_l$0 start_r$24(
        .d(start_r$24$d),
        .q(start_r$24$q),
        .clock(start_r$24$clock)
    );
    top$core$lists$len_l$0 start_r$25(
        .d(start_r$25$d),
        .q(start_r$25$q),
        .clock(start_r$25$clock)
    );
    top$core$lists$len_l$0 start_r$26(
        .d(start_r$26$d),
        .q(start_r$26$q),
        .clock(start_r$26$clock)
    );
    top$core$lists$len_l$0 start_r$27(
        .d(start_r$27$d),
        .q(start_r$27$q),
        .clock(start_r$27$clock)
    );
    top$core$lists$len_l$0 start_r$28(
        .d(start_r$28$d),
        .q(start_r$28$q),
        .clock(start_r$28$clock)
    );
    top$core$lists$len_l$0 start_r$29(
        .d(start_r$29$d),
        .q(start_r$29$q),
        .clock(start_r$29$clock)
    );
    top$core$lists$len_l$0 start_r$30(
        .d(start_r$30$d),
        .q(start_r$30$q),
        .clock(start_r$30$clock)
    );
    top$core$lists$len_l$0 start_r$31(
        .d(start_r$31$d),
        .q(start_r$31$q),
        .clock(start_r$31$clock)
    );
    top$core$lists$len_l$0 len_l$0(
        .d(len_l$0$d),
        .q(len_l$0$q),
        .clock(len_l$0$clock)
    );
    top$core$lists$len_l$0 len_l$1(
        .d(len_l$1$d),
        .q(len_l$1$q),
        .clock(len_l$1$clock)
    );
    top$core$lists$len_l$0 len_l$2(
        .d(len_l$2$d),
        .q(len_l$2$q),
        .clock(len_l$2$clock)
    );
    top$core$lists$len_l$0 len_l$3(
        .d(len_l$3$d),
        .q(len_l$3$q),
        .clock(len_l$3$clock)
    );
    top$core$lists$len_l$0 len_l$4(
        .d(len_l$4$d),
        .q(len_l$4$q),
        .clock(len_l$4$clock)
    );
    top$core$lists$len_l$0 len_l$5(
        .d(len_l$5$d),
        .q(len_l$5$q),
        .clock(len_l$5$clock)
    );
    top$core$lists$len_l$0 len_l$6(
        .d(len_l$6$d),
        .q(len_l$6$q),
        .clock(len_l$6$clock)
    );
    top$core$lists$len_l$0 len_l$7(
        .d(len_l$7$d),
        .q(len_l$7$q),
        .clock(len_l$7$clock)
    );
    top$core$lists$len_l$0 len_l$8(
        .d(len_l$8$d),
        .q(len_l$8$q),
        .clock(len_l$8$clock)
    );
    top$core$lists$len_l$0 len_l$9(
        .d(len_l$9$d),
        .q(len_l$9$q),
        .clock(len_l$9$clock)
    );
    top$core$lists$len_l$0 len_l$10(
        .d(len_l$10$d),
        .q(len_l$10$q),
        .clock(len_l$10$clock)
    );
    top$core$lists$len_l$0 len_l$11(
        .d(len_l$11$d),
        .q(len_l$11$q),
        .clock(len_l$11$clock)
    );
    top$core$lists$len_l$0 len_l$12(
        .d(len_l$12$d),
        .q(len_l$12$q),
        .clock(len_l$12$clock)
    );
    top$core$lists$len_l$0 len_l$13(
        .d(len_l$13$d),
        .q(len_l$13$q),
        .clock(len_l$13$clock)
    );
    top$core$lists$len_l$0 len_l$14(
        .d(len_l$14$d),
        .q(len_l$14$q),
        .clock(len_l$14$clock)
    );
    top$core$lists$len_l$0 len_l$15(
        .d(len_l$15$d),
        .q(len_l$15$q),
        .clock(len_l$15$clock)
    );
    top$core$lists$len_l$0 len_l$16(
        .d(len_l$16$d),
        .q(len_l$16$q),
        .clock(len_l$16$clock)
    );
    top$core$lists$len_l$0 len_l$17(
        .d(len_l$17$d),
        .q(len_l$17$q),
        .clock(len_l$17$clock)
    );
    top$core$lists$len_l$0 len_l$18(
        .d(len_l$18$d),
        .q(len_l$18$q),
        .clock(len_l$18$clock)
    );
    top$core$lists$len_l$0 len_l$19(
        .d(len_l$19$d),
        .q(len_l$19$q),
        .clock(len_l$19$clock)
    );
    top$core$lists$len_l$0 len_l$20(
        .d(len_l$20$d),
        .q(len_l$20$q),
        .clock(len_l$20$clock)
    );
    top$core$lists$len_l$0 len_l$21(
        .d(len_l$21$d),
        .q(len_l$21$q),
        .clock(len_l$21$clock)
    );
    top$core$lists$len_l$0 len_l$22(
        .d(len_l$22$d),
        .q(len_l$22$q),
        .clock(len_l$22$clock)
    );
    top$core$lists$len_l$0 len_l$23(
        .d(len_l$23$d),
        .q(len_l$23$q),
        .clock(len_l$23$clock)
    );
    top$core$lists$len_l$0 len_l$24(
        .d(len_l$24$d),
        .q(len_l$24$q),
        .clock(len_l$24$clock)
    );
    top$core$lists$len_l$0 len_l$25(
        .d(len_l$25$d),
        .q(len_l$25$q),
        .clock(len_l$25$clock)
    );
    top$core$lists$len_l$0 len_l$26(
        .d(len_l$26$d),
        .q(len_l$26$q),
        .clock(len_l$26$clock)
    );
    top$core$lists$len_l$0 len_l$27(
        .d(len_l$27$d),
        .q(len_l$27$q),
        .clock(len_l$27$clock)
    );
    top$core$lists$len_l$0 len_l$28(
        .d(len_l$28$d),
        .q(len_l$28$q),
        .clock(len_l$28$clock)
    );
    top$core$lists$len_l$0 len_l$29(
        .d(len_l$29$d),
        .q(len_l$29$q),
        .clock(len_l$29$clock)
    );
    top$core$lists$len_l$0 len_l$30(
        .d(len_l$30$d),
        .q(len_l$30$q),
        .clock(len_l$30$clock)
    );
    top$core$lists$len_l$0 len_l$31(
        .d(len_l$31$d),
        .q(len_l$31$q),
        .clock(len_l$31$clock)
    );
    top$core$lists$len_l$0 len_r$0(
        .d(len_r$0$d),
        .q(len_r$0$q),
        .clock(len_r$0$clock)
    );
    top$core$lists$len_l$0 len_r$1(
        .d(len_r$1$d),
        .q(len_r$1$q),
        .clock(len_r$1$clock)
    );
    top$core$lists$len_l$0 len_r$2(
        .d(len_r$2$d),
        .q(len_r$2$q),
        .clock(len_r$2$clock)
    );
    top$core$lists$len_l$0 len_r$3(
        .d(len_r$3$d),
        .q(len_r$3$q),
        .clock(len_r$3$clock)
    );
    top$core$lists$len_l$0 len_r$4(
        .d(len_r$4$d),
        .q(len_r$4$q),
        .clock(len_r$4$clock)
    );
    top$core$lists$len_l$0 len_r$5(
        .d(len_r$5$d),
        .q(len_r$5$q),
        .clock(len_r$5$clock)
    );
    top$core$lists$len_l$0 len_r$6(
        .d(len_r$6$d),
        .q(len_r$6$q),
        .clock(len_r$6$clock)
    );
    top$core$lists$len_l$0 len_r$7(
        .d(len_r$7$d),
        .q(len_r$7$q),
        .clock(len_r$7$clock)
    );
    top$core$lists$len_l$0 len_r$8(
        .d(len_r$8$d),
        .q(len_r$8$q),
        .clock(len_r$8$clock)
    );
    top$core$lists$len_l$0 len_r$9(
        .d(len_r$9$d),
        .q(len_r$9$q),
        .clock(len_r$9$clock)
    );
    top$core$lists$len_l$0 len_r$10(
        .d(len_r$10$d),
        .q(len_r$10$q),
        .clock(len_r$10$clock)
    );
    top$core$lists$len_l$0 len_r$11(
        .d(len_r$11$d),
        .q(len_r$11$q),
        .clock(len_r$11$clock)
    );
    top$core$lists$len_l$0 len_r$12(
        .d(len_r$12$d),
        .q(len_r$12$q),
        .clock(len_r$12$clock)
    );
    top$core$lists$len_l$0 len_r$13(
        .d(len_r$13$d),
        .q(len_r$13$q),
        .clock(len_r$13$clock)
    );
    top$core$lists$len_l$0 len_r$14(
        .d(len_r$14$d),
        .q(len_r$14$q),
        .clock(len_r$14$clock)
    );
    top$core$lists$len_l$0 len_r$15(
        .d(len_r$15$d),
        .q(len_r$15$q),
        .clock(len_r$15$clock)
    );
    top$core$lists$len_l$0 len_r$16(
        .d(len_r$16$d),
        .q(len_r$16$q),
        .clock(len_r$16$clock)
    );
    top$core$lists$len_l$0 len_r$17(
        .d(len_r$17$d),
        .q(len_r$17$q),
        .clock(len_r$17$clock)
    );
    top$core$lists$len_l$0 len_r$18(
        .d(len_r$18$d),
        .q(len_r$18$q),
        .clock(len_r$18$clock)
    );
    top$core$lists$len_l$0 len_r$19(
        .d(len_r$19$d),
        .q(len_r$19$q),
        .clock(len_r$19$clock)
    );
    top$core$lists$len_l$0 len_r$20(
        .d(len_r$20$d),
        .q(len_r$20$q),
        .clock(len_r$20$clock)
    );
    top$core$lists$len_l$0 len_r$21(
        .d(len_r$21$d),
        .q(len_r$21$q),
        .clock(len_r$21$clock)
    );
    top$core$lists$len_l$0 len_r$22(
        .d(len_r$22$d),
        .q(len_r$22$q),
        .clock(len_r$22$clock)
    );
    top$core$lists$len_l$0 len_r$23(
        .d(len_r$23$d),
        .q(len_r$23$q),
        .clock(len_r$23$clock)
    );
    top$core$lists$len_l$0 len_r$24(
        .d(len_r$24$d),
        .q(len_r$24$q),
        .clock(len_r$24$clock)
    );
    top$core$lists$len_l$0 len_r$25(
        .d(len_r$25$d),
        .q(len_r$25$q),
        .clock(len_r$25$clock)
    );
    top$core$lists$len_l$0 len_r$26(
        .d(len_r$26$d),
        .q(len_r$26$q),
        .clock(len_r$26$clock)
    );
    top$core$lists$len_l$0 len_r$27(
        .d(len_r$27$d),
        .q(len_r$27$q),
        .clock(len_r$27$clock)
    );
    top$core$lists$len_l$0 len_r$28(
        .d(len_r$28$d),
        .q(len_r$28$q),
        .clock(len_r$28$clock)
    );
    top$core$lists$len_l$0 len_r$29(
        .d(len_r$29$d),
        .q(len_r$29$q),
        .clock(len_r$29$clock)
    );
    top$core$lists$len_l$0 len_r$30(
        .d(len_r$30$d),
        .q(len_r$30$q),
        .clock(len_r$30$clock)
    );
    top$core$lists$len_l$0 len_r$31(
        .d(len_r$31$d),
        .q(len_r$31$q),
        .clock(len_r$31$clock)
    );
    
    // Update code
    always @(*) begin
        ovf$clock = clock;
        rd_v$clock = clock;
        rd_side$clock = clock;
        ovf$d = ovf$q;
        rd_v$d = rd_v$q;
        rd_side$d = rd_side$q;
        c_l1 = lvl$q + 32'h1;
        c_b_up = 1'b0;
        c_cs_l = 32'h0;
        c_cs_r = 32'h0;
        c_cl_l = 32'h0;
        c_cl_r = 32'h0;
        c_ns_l = 32'h0;
        c_ns_r = 32'h0;
        c_nl_l = 32'h0;
        c_nl_r = 32'h0;
        if (lvl$q == idx$0) begin
            c_cs_l = start_l$0$q;
            c_cs_r = start_r$0$q;
            c_cl_l = len_l$0$q;
            c_cl_r = len_r$0$q;
        end
        if (lvl$q == idx$0 + 32'h1) begin
            c_b_up = br$0$q;
        end
        if ((c_l1 == idx$0) & (lvl$q != 32'h1f)) begin
            c_ns_l = start_l$0$q;
            c_ns_r = start_r$0$q;
            c_nl_l = len_l$0$q;
            c_nl_r = len_r$0$q;
        end
        if (lvl$q == idx$1) begin
            c_cs_l = start_l$1$q;
            c_cs_r = start_r$1$q;
            c_cl_l = len_l$1$q;
            c_cl_r = len_r$1$q;
        end
        if (lvl$q == idx$1 + 32'h1) begin
            c_b_up = br$1$q;
        end
        if ((c_l1 == idx$1) & (lvl$q != 32'h1f)) begin
            c_ns_l = start_l$1$q;
            c_ns_r = start_r$1$q;
            c_nl_l = len_l$1$q;
            c_nl_r = len_r$1$q;
        end
        if (lvl$q == idx$2) begin
            c_cs_l = start_l$2$q;
            c_cs_r = start_r$2$q;
            c_cl_l = len_l$2$q;
            c_cl_r = len_r$2$q;
        end
        if (lvl$q == idx$2 + 32'h1) begin
            c_b_up = br$2$q;
        end
        if ((c_l1 == idx$2) & (lvl$q != 32'h1f)) begin
            c_ns_l = start_l$2$q;
            c_ns_r = start_r$2$q;
            c_nl_l = len_l$2$q;
            c_nl_r = len_r$2$q;
        end
        if (lvl$q == idx$3) begin
            c_cs_l = start_l$3$q;
            c_cs_r = start_r$3$q;
            c_cl_l = len_l$3$q;
            c_cl_r = len_r$3$q;
        end
        if (lvl$q == idx$3 + 32'h1) begin
            c_b_up = br$3$q;
        end
        if ((c_l1 == idx$3) & (lvl$q != 32'h1f)) begin
            c_ns_l = start_l$3$q;
            c_ns_r = start_r$3$q;
            c_nl_l = len_l$3$q;
            c_nl_r = len_r$3$q;
        end
        if (lvl$q == idx$4) begin
            c_cs_l = start_l$4$q;
            c_cs_r = start_r$4$q;
            c_cl_l = len_l$4$q;
            c_cl_r = len_r$4$q;
        end
        if (lvl$q == idx$4 + 32'h1) begin
            c_b_up = br$4$q;
        end
        if ((c_l1 == idx$4) & (lvl$q != 32'h1f)) begin
            c_ns_l = start_l$4$q;
            c_ns_r = start_r$4$q;
            c_nl_l = len_l$4$q;
            c_nl_r = len_r$4$q;
        end
        if (lvl$q == idx$5) begin
            c_cs_l = start_l$5$q;
            c_cs_r = start_r$5$q;
            c_cl_l = len_l$5$q;
            c_cl_r = len_r$5$q;
        end
        if (lvl$q == idx$5 + 32'h1) begin
            c_b_up = br$5$q;
        end
        if ((c_l1 == idx$5) & (lvl$q != 32'h1f)) begin
            c_ns_l = start_l$5$q;
            c_ns_r = start_r$5$q;
            c_nl_l = len_l$5$q;
            c_nl_r = len_r$5$q;
        end
        if (lvl$q == idx$6) begin
            c_cs_l = start_l$6$q;
            c_cs_r = start_r$6$q;
            c_cl_l = len_l$6$q;
            c_cl_r = len_r$6$q;
        end
        if (lvl$q == idx$6 + 32'h1) begin
            c_b_up = br$6$q;
        end
        if ((c_l1 == idx$6) & (lvl$q != 32'h1f)) begin
            c_ns_l = start_l$6$q;
            c_ns_r = start_r$6$q;
            c_nl_l = len_l$6$q;
            c_nl_r = len_r$6$q;
        end
        if (lvl$q == idx$7) begin
            c_cs_l = start_l$7$q;
            c_cs_r = start_r$7$q;
            c_cl_l = len_l$7$q;
            c_cl_r = len_r$7$q;
        end
        if (lvl$q == idx$7 + 32'h1) begin
            c_b_up = br$7$q;
        end
        if ((c_l1 == idx$7) & (lvl$q != 32'h1f)) begin
            c_ns_l = start_l$7$q;
            c_ns_r = start_r$7$q;
            c_nl_l = len_l$7$q;
            c_nl_r = len_r$7$q;
        end
        if (lvl$q == idx$8) begin
            c_cs_l = start_l$8$q;
            c_cs_r = start_r$8$q;
            c_cl_l = len_l$8$q;
            c_cl_r = len_r$8$q;
        end
        if (lvl$q == idx$8 + 32'h1) begin
            c_b_up = br$8$q;
        end
        if ((c_l1 == idx$8) & (lvl$q != 32'h1f)) begin
            c_ns_l = start_l$8$q;
            c_ns_r = start_r$8$q;
            c_nl_l = len_l$8$q;
            c_nl_r = len_r$8$q;
        end
        if (lvl$q == idx$9) begin
            c_cs_l = start_l$9$q;
            c_cs_r = start_r$9$q;
            c_cl_l = len_l$9$q;
            c_cl_r = len_r$9$q;
        end
        if (lvl$q == idx$9 + 32'h1) begin
            c_b_up = br$9$q;
        end
        if ((c_l1 == idx$9) & (lvl$q != 32'h1f)) begin
            c_ns_l = start_l$9$q;
            c_ns_r = start_r$9$q;
            c_nl_l = len_l$9$q;
            c_nl_r = len_r$9$q;
        end
        if (lvl$q == idx$10) begin
            c_cs_l = start_l$10$q;
            c_cs_r = start_r$10$q;
            c_cl_l = len_l$10$q;
            c_cl_r = len_r$10$q;
        end
        if (lvl$q == idx$10 + 32'h1) begin
            c_b_up = br$10$q;
        end
        if ((c_l1 == idx$10) & (lvl$q != 32'h1f)) begin
            c_ns_l = start_l$10$q;
            c_ns_r = start_r$10$q;
            c_nl_l = len_l$10$q;
            c_nl_r = len_r$10$q;
        end
        if (lvl$q == idx$11) begin
            c_cs_l = start_l$11$q;
            c_cs_r = start_r$11$q;
            c_cl_l = len_l$11$q;
            c_cl_r = len_r$11$q;
        end
        if (lvl$q == idx$11 + 32'h1) begin
            c_b_up = br$11$q;
        end
        if ((c_l1 == idx$11) & (lvl$q != 32'h1f)) begin
            c_ns_l = start_l$11$q;
            c_ns_r = start_r$11$q;
            c_nl_l = len_l$11$q;
            c_nl_r = len_r$11$q;
        end
        if (lvl$q == idx$12) begin
            c_cs_l = start_l$12$q;
            c_cs_r = start_r$12$q;
            c_cl_l = len_l$12$q;
            c_cl_r = len_r$12$q;
        end
        if (lvl$q == idx$12 + 32'h1) begin
            c_b_up = br$12$q;
        end
        if ((c_l1 == idx$12) & (lvl$q != 32'h1f)) begin
            c_ns_l = start_l$12$q;
            c_ns_r = start_r$12$q;
            c_nl_l = len_l$12$q;
            c_nl_r = len_r$12$q;
        end
        if (lvl$q == idx$13) begin
            c_cs_l = start_l$13$q;
            c_cs_r = start_r$13$q;
            c_cl_l = len_l$13$q;
            c_cl_r = len_r$13$q;
        end
        if (lvl$q == idx$13 + 32'h1) begin
            c_b_up = br$13$q;
        end
        if ((c_l1 == idx$13) & (lvl$q != 32'h1f)) begin
            c_ns_l = start_l$13$q;
            c_ns_r = start_r$13$q;
            c_nl_l = len_l$13$q;
            c_nl_r = len_r$13$q;
        end
        if (lvl$q == idx$14) begin
            c_cs_l = start_l$14$q;
            c_cs_r = start_r$14$q;
            c_cl_l = len_l$14$q;
            c_cl_r = len_r$14$q;
        end
        if (lvl$q == idx$14 + 32'h1) begin
            c_b_up = br$14$q;
        end
        if ((c_l1 == idx$14) & (lvl$q != 32'h1f)) begin
            c_ns_l = start_l$14$q;
            c_ns_r = start_r$14$q;
            c_nl_l = len_l$14$q;
            c_nl_r = len_r$14$q;
        end
        if (lvl$q == idx$15) begin
            c_cs_l = start_l$15$q;
            c_cs_r = start_r$15$q;
            c_cl_l = len_l$15$q;
            c_cl_r = len_r$15$q;
        end
        if (lvl$q == idx$15 + 32'h1) begin
            c_b_up = br$15$q;
        end
        if ((c_l1 == idx$15) & (lvl$q != 32'h1f)) begin
            c_ns_l = start_l$15$q;
            c_ns_r = start_r$15$q;
            c_nl_l = len_l$15$q;
            c_nl_r = len_r$15$q;
        end
        if (lvl$q == idx$16) begin
            c_cs_l = start_l$16$q;
            c_cs_r = start_r$16$q;
            c_cl_l = len_l$16$q;
            c_cl_r = len_r$16$q;
        end
        if (lvl$q == idx$16 + 32'h1) begin
            c_b_up = br$16$q;
        end
        if ((c_l1 == idx$16) & (lvl$q != 32'h1f)) begin
            c_ns_l = start_l$16$q;
            c_ns_r = start_r$16$q;
            c_nl_l = len_l$16$q;
            c_nl_r = len_r$16$q;
        end
        if (lvl$q == idx$17) begin
            c_cs_l = start_l$17$q;
            c_cs_r = start_r$17$q;
            c_cl_l = len_l$17$q;
            c_cl_r = len_r$17$q;
        end
        if (lvl$q == idx$17 + 32'h1) begin
            c_b_up = br$17$q;
        end
        if ((c_l1 == idx$17) & (lvl$q != 32'h1f)) begin
            c_ns_l = start_l$17$q;
            c_ns_r = start_r$17$q;
            c_nl_l = len_l$17$q;
            c_nl_r = len_r$17$q;
        end
        if (lvl$q == idx$18) begin
            c_cs_l = start_l$18$q;
            c_cs_r = start_r$18$q;
            c_cl_l = len_l$18$q;
            c_cl_r = len_r$18$q;
        end
        if (lvl$q == idx$18 + 32'h1) begin
            c_b_up = br$18$q;
        end
        if ((c_l1 == idx$18) & (lvl$q != 32'h1f)) begin
            c_ns_l = start_l$18$q;
            c_ns_r = start_r$18$q;
            c_nl_l = len_l$18$q;
            c_nl_r = len_r$18$q;
        end
        if (lvl$q == idx$19) begin
            c_cs_l = start_l$19$q;
            c_cs_r = start_r$19$q;
            c_cl_l = len_l$19$q;
            c_cl_r = len_r$19$q;
        end
        if (lvl$q == idx$19 + 32'h1) begin
            c_b_up = br$19$q;
        end
        if ((c_l1 == idx$19) & (lvl$q != 32'h1f)) begin
            c_ns_l = start_l$19$q;
            c_ns_r = start_r$19$q;
            c_nl_l = len_l$19$q;
            c_nl_r = len_r$19$q;
        end
        if (lvl$q == idx$20) begin
            c_cs_l = start_l$20$q;
            c_cs_r = start_r$20$q;
            c_cl_l = len_l$20$q;
            c_cl_r = len_r$20$q;
        end
        if (lvl$q == idx$20 + 32'h1) begin
            c_b_up = br$20$q;
        end
        if ((c_l1 == idx$20) & (lvl$q != 32'h1f)) begin
            c_ns_l = start_l$20$q;
            c_ns_r = start_r$20$q;
            c_nl_l = len_l$20$q;
            c_nl_r = len_r$20$q;
        end
        if (lvl$q == idx$21) begin
            c_cs_l = start_l$21$q;
            c_cs_r = start_r$21$q;
            c_cl_l = len_l$21$q;
            c_cl_r = len_r$21$q;
        end
        if (lvl$q == idx$21 + 32'h1) begin
            c_b_up = br$21$q;
        end
        if ((c_l1 == idx$21) & (lvl$q != 32'h1f)) begin
            c_ns_l = start_l$21$q;
            c_ns_r = start_r$21$q;
            c_nl_l = len_l$21$q;
            c_nl_r = len_r$21$q;
        end
        if (lvl$q == idx$22) begin
            c_cs_l = start_l$22$q;
            c_cs_r = start_r$22$q;
            c_cl_l = len_l$22$q;
            c_cl_r = len_r$22$q;
        end
        if (lvl$q == idx$22 + 32'h1) begin
            c_b_up = br$22$q;
        end
        if ((c_l1 == idx$22) & (lvl$q != 32'h1f)) begin
            c_ns_l = start_l$22$q;
            c_ns_r = start_r$22$q;
            c_nl_l = len_l$22$q;
            c_nl_r = len_r$22$q;
        end
        if (lvl$q == idx$23) begin
            c_cs_l = start_l$23$q;
            c_cs_r = start_r$23$q;
            c_cl_l = len_l$23$q;
            c_cl_r = len_r$23$q;
        end
        if (lvl$q == idx$23 + 32'h1) begin
            c_b_up = br$23$q;
        end
        if ((c_l1 == idx$23) & (lvl$q != 32'h1f)) begin
            c_ns_l = start_l$23$q;
            c_ns_r = start_r$23$q;
            c_nl_l = len_l$23$q;
            c_nl_r = len_r$23$q;
        end
        if (lvl$q == idx$24) begin
            c_cs_l = start_l$24$q;
            c_cs_r = start_r$24$q;
            c_cl_l = len_l$24$q;
            c_cl_r = len_r$24$q;
        end
        if (lvl$q == idx$24 + 32'h1) begin
            c_b_up = br$24$q;
        end
        if ((c_l1 == idx$24) & (lvl$q != 32'h1f)) begin
            c_ns_l = start_l$24$q;
            c_ns_r = start_r$24$q;
            c_nl_l = len_l$24$q;
            c_nl_r = len_r$24$q;
        end
        if (lvl$q == idx$25) begin
            c_cs_l = start_l$25$q;
            c_cs_r = start_r$25$q;
            c_cl_l = len_l$25$q;
            c_cl_r = len_r$25$q;
        end
        if (lvl$q == idx$25 + 32'h1) begin
            c_b_up = br$25$q;
        end
        if ((c_l1 == idx$25) & (lvl$q != 32'h1f)) begin
            c_ns_l = start_l$25$q;
            c_ns_r = start_r$25$q;
            c_nl_l = len_l$25$q;
            c_nl_r = len_r$25$q;
        end
        if (lvl$q == idx$26) begin
            c_cs_l = start_l$26$q;
            c_cs_r = start_r$26$q;
            c_cl_l = len_l$26$q;
            c_cl_r = len_r$26$q;
        end
        if (lvl$q == idx$26 + 32'h1) begin
            c_b_up = br$26$q;
        end
        if ((c_l1 == idx$26) & (lvl$q != 32'h1f)) begin
            c_ns_l = start_l$26$q;
            c_ns_r = start_r$26$q;
            c_nl_l = len_l$26$q;
            c_nl_r = len_r$26$q;
        end
        if (lvl$q == idx$27) begin
            c_cs_l = start_l$27$q;
            c_cs_r = start_r$27$q;
            c_cl_l = len_l$27$q;
            c_cl_r = len_r$27$q;
        end
        if (lvl$q == idx$27 + 32'h1) begin
            c_b_up = br$27$q;
        end
        if ((c_l1 == idx$27) & (lvl$q != 32'h1f)) begin
            c_ns_l = start_l$27$q;
            c_ns_r = start_r$27$q;
            c_nl_l = len_l$27$q;
            c_nl_r = len_r$27$q;
        end
        if (lvl$q == idx$28) begin
            c_cs_l = start_l$28$q;
            c_cs_r = start_r$28$q;
            c_cl_l = len_l$28$q;
            c_cl_r = len_r$28$q;
        end
        if (lvl$q == idx$28 + 32'h1) begin
            c_b_up = br$28$q;
        end
        if ((c_l1 == idx$28) & (lvl$q != 32'h1f)) begin
            c_ns_l = start_l$28$q;
            c_ns_r = start_r$28$q;
            c_nl_l = len_l$28$q;
            c_nl_r = len_r$28$q;
        end
        if (lvl$q == idx$29) begin
            c_cs_l = start_l$29$q;
            c_cs_r = start_r$29$q;
            c_cl_l = len_l$29$q;
            c_cl_r = len_r$29$q;
        end
        if (lvl$q == idx$29 + 32'h1) begin
            c_b_up = br$29$q;
        end
        if ((c_l1 == idx$29) & (lvl$q != 32'h1f)) begin
            c_ns_l = start_l$29$q;
            c_ns_r = start_r$29$q;
            c_nl_l = len_l$29$q;
            c_nl_r = len_r$29$q;
        end
        if (lvl$q == idx$30) begin
            c_cs_l = start_l$30$q;
            c_cs_r = start_r$30$q;
            c_cl_l = len_l$30$q;
            c_cl_r = len_r$30$q;
        end
        if (lvl$q == idx$30 + 32'h1) begin
            c_b_up = br$30$q;
        end
        if ((c_l1 == idx$30) & (lvl$q != 32'h1f)) begin
            c_ns_l = start_l$30$q;
            c_ns_r = start_r$30$q;
            c_nl_l = len_l$30$q;
            c_nl_r = len_r$30$q;
        end
        if (lvl$q == idx$31) begin
            c_cs_l = start_l$31$q;
            c_cs_r = start_r$31$q;
            c_cl_l = len_l$31$q;
            c_cl_r = len_r$31$q;
        end
        if (lvl$q == idx$31 + 32'h1) begin
            c_b_up = br$31$q;
        end
        if ((c_l1 == idx$31) & (lvl$q != 32'h1f)) begin
            c_ns_l = start_l$31$q;
            c_ns_r = start_r$31$q;
            c_nl_l = len_l$31$q;
            c_nl_r = len_r$31$q;
        end
        c_idle = ~up$q & ~done_r$q;
        c_cur_start = c_cs_l;
        if (cur_b$q) begin
            c_cur_start = c_cs_r;
        end
        c_read = read & c_idle & (rem$q != 32'h0);
        c_waddr = wa_l$q;
        if (wr_side) begin
            c_waddr = wa_r$q;
        end
        c_wok = append & c_idle & (lvl$q != 32'h1f) & (c_waddr < cap);
        ovf$d = ovf$q | (append & c_idle & ~c_wok);
        sram_l$read_clock = clock;
        sram_r$read_clock = clock;
        sram_l$write_clock = clock;
        sram_r$write_clock = clock;
        c_raddr = c_cur_start + pos$q;
        sram_l$read_address = c_raddr[(32'h0)+:(12)];
        sram_r$read_address = c_raddr[(32'h0)+:(12)];
        sram_l$write_address = c_waddr[(32'h0)+:(12)];
        sram_r$write_address = c_waddr[(32'h0)+:(12)];
        sram_l$write_data = wr_ptr;
        sram_r$write_data = wr_ptr;
        sram_l$write_enable = c_wok & ~wr_side;
        sram_r$write_enable = c_wok & wr_side;
        rd_v$d = c_read;
        rd_side$d = cur_b$q;
        rd_ptr = 32'h0;
        if (rd_v$q) begin
            rd_ptr = sram_l$read_data;
            if (rd_side$q) begin
                rd_ptr = sram_r$read_data;
            end
        end
        lvl$clock = clock;
        pos$clock = clock;
        rem$clock = clock;
        cur_b$clock = clock;
        wa_l$clock = clock;
        wa_r$clock = clock;
        up$clock = clock;
        done_r$clock = clock;
        lvl$d = lvl$q;
        pos$d = pos$q;
        rem$d = rem$q;
        cur_b$d = cur_b$q;
        wa_l$d = wa_l$q;
        wa_r$d = wa_r$q;
        up$d = up$q;
        done_r$d = done_r$q;
        c_next = next_list & c_idle & ~append;
        c_desc = c_next & (lvl$q != 32'h1f) & ((c_nl_l != 32'h0) | (c_nl_r != 32'h0));
        c_desc_b = c_nl_l == 32'h0;
        c_u_right = up$q & ~cur_b$q & (c_cl_r != 32'h0);
        c_u_zero = lvl$q == 32'h0;
        c_open = (c_desc & (lvl$q < 32'h1e)) | (c_u_right & (lvl$q != 32'h1f));
        c_open_lvl = lvl$q + 32'h1;
        c_open_l = c_cs_l + c_cl_l;
        c_open_r = c_cs_r + c_cl_r;
        if (c_desc) begin
            c_open_lvl = lvl$q + 32'h2;
            c_open_l = wa_l$q;
            c_open_r = wa_r$q;
        end
        if (c_wok & ~wr_side) begin
            wa_l$d = wa_l$q + 32'h1;
        end
        if (c_wok & wr_side) begin
            wa_r$d = wa_r$q + 32'h1;
        end
        if (c_desc | c_u_right | (up$q & ~c_u_zero)) begin
            wa_l$d = c_open_l;
            wa_r$d = c_open_r;
        end
        if (c_read) begin
            pos$d = pos$q + 32'h1;
            rem$d = rem$q - 32'h1;
        end
        if (c_desc | c_u_right) begin
            pos$d = 32'h0;
        end
        if (c_desc) begin
            rem$d = c_nl_l;
            if (c_desc_b) begin
                rem$d = c_nl_r;
            end
        end
        if (c_u_right) begin
            rem$d = c_cl_r;
        end
        if (c_desc) begin
            lvl$d = c_l1;
            cur_b$d = c_desc_b;
        end
        if (c_u_right) begin
            cur_b$d = 1'b1;
        end
        if (up$q & ~c_u_right & ~c_u_zero) begin
            lvl$d = lvl$q - 32'h1;
            cur_b$d = c_b_up;
        end
        if (c_next & ~c_desc) begin
            up$d = 1'b1;
            pos$d = 32'h0;
        end
        if (up$q & (c_u_right | c_u_zero)) begin
            up$d = 1'b0;
            done_r$d = ~c_u_right;
        end
        br$0$clock = clock;
        start_l$0$clock = clock;
        start_r$0$clock = clock;
        len_l$0$clock = clock;
        len_r$0$clock = clock;
        br$0$d = br$0$q;
        start_l$0$d = start_l$0$q;
        start_r$0$d = start_r$0$q;
        len_l$0$d = len_l$0$q;
        len_r$0$d = len_r$0$q;
        if (c_l1 == idx$0) begin
            if (c_desc) begin
                br$0$d = c_desc_b;
            end
            if (c_wok & ~wr_side) begin
                len_l$0$d = len_l$0$q + 32'h1;
            end
            if (c_wok & wr_side) begin
                len_r$0$d = len_r$0$q + 32'h1;
            end
        end
        if (c_u_right & (lvl$q == idx$0)) begin
            br$0$d = 1'b1;
        end
        if (c_open & (c_open_lvl == idx$0)) begin
            start_l$0$d = c_open_l;
            start_r$0$d = c_open_r;
            len_l$0$d = 32'h0;
            len_r$0$d = 32'h0;
        end
        if (clear) begin
            br$0$d = 1'b0;
            start_l$0$d = 32'h0;
            start_r$0$d = 32'h0;
            len_l$0$d = 32'h0;
            len_r$0$d = 32'h0;
        end
        br$1$clock = clock;
        start_l$1$clock = clock;
        start_r$1$clock = clock;
        len_l$1$clock = clock;
        len_r$1$clock = clock;
        br$1$d = br$1$q;
        start_l$1$d = start_l$1$q;
        start_r$1$d = start_r$1$q;
        len_l$1$d = len_l$1$q;
        len_r$1$d = len_r$1$q;
        if (c_l1 == idx$1) begin
            if (c_desc) begin
                br$1$d = c_desc_b;
            end
            if (c_wok & ~wr_side) begin
                len_l$1$d = len_l$1$q + 32'h1;
            end
            if (c_wok & wr_side) begin
                len_r$1$d = len_r$1$q + 32'h1;
            end
        end
        if (c_u_right & (lvl$q == idx$1)) begin
            br$1$d = 1'b1;
        end
        if (c_open & (c_open_lvl == idx$1)) begin
            start_l$1$d = c_open_l;
            start_r$1$d = c_open_r;
            len_l$1$d = 32'h0;
            len_r$1$d = 32'h0;
        end
        if (clear) begin
            br$1$d = 1'b0;
            start_l$1$d = 32'h0;
            start_r$1$d = 32'h0;
            len_l$1$d = 32'h0;
            len_r$1$d = 32'h0;
        end
        br$2$clock = clock;
        start_l$2$clock = clock;
        start_r$2$clock = clock;
        len_l$2$clock = clock;
        len_r$2$clock = clock;
        br$2$d = br$2$q;
        start_l$2$d = start_l$2$q;
        start_r$2$d = start_r$2$q;
        len_l$2$d = len_l$2$q;
        len_r$2$d = len_r$2$q;
        if (c_l1 == idx$2) begin
            if (c_desc) begin
                br$2$d = c_desc_b;
            end
            if (c_wok & ~wr_side) begin
                len_l$2$d = len_l$2$q + 32'h1;
            end
            if (c_wok & wr_side) begin
                len_r$2$d = len_r$2$q + 32'h1;
            end
        end
        if (c_u_right & (lvl$q == idx$2)) begin
            br$2$d = 1'b1;
        end
        if (c_open & (c_open_lvl == idx$2)) begin
            start_l$2$d = c_open_l;
            start_r$2$d = c_open_r;
            len_l$2$d = 32'h0;
            len_r$2$d = 32'h0;
        end
        if (clear) begin
            br$2$d = 1'b0;
            start_l$2$d = 32'h0;
            start_r$2$d = 32'h0;
            len_l$2$d = 32'h0;
            len_r$2$d = 32'h0;
        end
        br$3$clock = clock;
        start_l$3$clock = clock;
        start_r$3$clock = clock;
        len_l$3$clock = clock;
        len_r$3$clock = clock;
        br$3$d = br$3$q;
        start_l$3$d = start_l$3$q;
        start_r$3$d = start_r$3$q;
        len_l$3$d = len_l$3$q;
        len_r$3$d = len_r$3$q;
        if (c_l1 == idx$3) begin
            if (c_desc) begin
                br$3$d = c_desc_b;
            end
            if (c_wok & ~wr_side) begin
                len_l$3$d = len_l$3$q + 32'h1;
            end
            if (c_wok & wr_side) begin
                len_r$3$d = len_r$3$q + 32'h1;
            end
        end
        if (c_u_right & (lvl$q == idx$3)) begin
            br$3$d = 1'b1;
        end
        if (c_open & (c_open_lvl == idx$3)) begin
            start_l$3$d = c_open_l;
            start_r$3$d = c_open_r;
            len_l$3$d = 32'h0;
            len_r$3$d = 32'h0;
        end
        if (clear) begin
            br$3$d = 1'b0;
            start_l$3$d = 32'h0;
            start_r$3$d = 32'h0;
            len_l$3$d = 32'h0;
            len_r$3$d = 32'h0;
        end
        br$4$clock = clock;
        start_l$4$clock = clock;
        start_r$4$clock = clock;
        len_l$4$clock = clock;
        len_r$4$clock = clock;
        br$4$d = br$4$q;
        start_l$4$d = start_l$4$q;
        start_r$4$d = start_r$4$q;
        len_l$4$d = len_l$4$q;
        len_r$4$d = len_r$4$q;
        if (c_l1 == idx$4) begin
            if (c_desc) begin
                br$4$d = c_desc_b;
            end
            if (c_wok & ~wr_side) begin
                len_l$4$d = len_l$4$q + 32'h1;
            end
            if (c_wok & wr_side) begin
                len_r$4$d = len_r$4$q + 32'h1;
            end
        end
        if (c_u_right & (lvl$q == idx$4)) begin
            br$4$d = 1'b1;
        end
        if (c_open & (c_open_lvl == idx$4)) begin
            start_l$4$d = c_open_l;
            start_r$4$d = c_open_r;
            len_l$4$d = 32'h0;
            len_r$4$d = 32'h0;
        end
        if (clear) begin
            br$4$d = 1'b0;
            start_l$4$d = 32'h0;
            start_r$4$d = 32'h0;
            len_l$4$d = 32'h0;
            len_r$4$d = 32'h0;
        end
        br$5$clock = clock;
        start_l$5$clock = clock;
        start_r$5$clock = clock;
        len_l$5$clock = clock;
        len_r$5$clock = clock;
        br$5$d = br$5$q;
        start_l$5$d = start_l$5$q;
        start_r$5$d = start_r$5$q;
        len_l$5$d = len_l$5$q;
        len_r$5$d = len_r$5$q;
        if (c_l1 == idx$5) begin
            if (c_desc) begin
                br$5$d = c_desc_b;
            end
            if (c_wok & ~wr_side) begin
                len_l$5$d = len_l$5$q + 32'h1;
            end
            if (c_wok & wr_side) begin
                len_r$5$d = len_r$5$q + 32'h1;
            end
        end
        if (c_u_right & (lvl$q == idx$5)) begin
            br$5$d = 1'b1;
        end
        if (c_open & (c_open_lvl == idx$5)) begin
            start_l$5$d = c_open_l;
            start_r$5$d = c_open_r;
            len_l$5$d = 32'h0;
            len_r$5$d = 32'h0;
        end
        if (clear) begin
            br$5$d = 1'b0;
            start_l$5$d = 32'h0;
            start_r$5$d = 32'h0;
            len_l$5$d = 32'h0;
            len_r$5$d = 32'h0;
        end
        br$6$clock = clock;
        start_l$6$clock = clock;
        start_r$6$clock = clock;
        len_l$6$clock = clock;
        len_r$6$clock = clock;
        br$6$d = br$6$q;
        start_l$6$d = start_l$6$q;
        start_r$6$d = start_r$6$q;
        len_l$6$d = len_l$6$q;
        len_r$6$d = len_r$6$q;
        if (c_l1 == idx$6) begin
            if (c_desc) begin
                br$6$d = c_desc_b;
            end
            if (c_wok & ~wr_side) begin
                len_l$6$d = len_l$6$q + 32'h1;
            end
            if (c_wok & wr_side) begin
                len_r$6$d = len_r$6$q + 32'h1;
            end
        end
        if (c_u_right & (lvl$q == idx$6)) begin
            br$6$d = 1'b1;
        end
        if (c_open & (c_open_lvl == idx$6)) begin
            start_l$6$d = c_open_l;
            start_r$6$d = c_open_r;
            len_l$6$d = 32'h0;
            len_r$6$d = 32'h0;
        end
        if (clear) begin
            br$6$d = 1'b0;
            start_l$6$d = 32'h0;
            start_r$6$d = 32'h0;
            len_l$6$d = 32'h0;
            len_r$6$d = 32'h0;
        end
        br$7$clock = clock;
        start_l$7$clock = clock;
        start_r$7$clock = clock;
        len_l$7$clock = clock;
        len_r$7$clock = clock;
        br$7$d = br$7$q;
        start_l$7$d = start_l$7$q;
        start_r$7$d = start_r$7$q;
        len_l$7$d = len_l$7$q;
        len_r$7$d = len_r$7$q;
        if (c_l1 == idx$7) begin
            if (c_desc) begin
                br$7$d = c_desc_b;
            end
            if (c_wok & ~wr_side) begin
                len_l$7$d = len_l$7$q + 32'h1;
            end
            if (c_wok & wr_side) begin
                len_r$7$d = len_r$7$q + 32'h1;
            end
        end
        if (c_u_right & (lvl$q == idx$7)) begin
            br$7$d = 1'b1;
        end
        if (c_open & (c_open_lvl == idx$7)) begin
            start_l$7$d = c_open_l;
            start_r$7$d = c_open_r;
            len_l$7$d = 32'h0;
            len_r$7$d = 32'h0;
        end
        if (clear) begin
            br$7$d = 1'b0;
            start_l$7$d = 32'h0;
            start_r$7$d = 32'h0;
            len_l$7$d = 32'h0;
            len_r$7$d = 32'h0;
        end
        br$8$clock = clock;
        start_l$8$clock = clock;
        start_r$8$clock = clock;
        len_l$8$clock = clock;
        len_r$8$clock = clock;
        br$8$d = br$8$q;
        start_l$8$d = start_l$8$q;
        start_r$8$d = start_r$8$q;
        len_l$8$d = len_l$8$q;
        len_r$8$d = len_r$8$q;
        if (c_l1 == idx$8) begin
            if (c_desc) begin
                br$8$d = c_desc_b;
            end
            if (c_wok & ~wr_side) begin
                len_l$8$d = len_l$8$q + 32'h1;
            end
            if (c_wok & wr_side) begin
                len_r$8$d = len_r$8$q + 32'h1;
            end
        end
        if (c_u_right & (lvl$q == idx$8)) begin
            br$8$d = 1'b1;
        end
        if (c_open & (c_open_lvl == idx$8)) begin
            start_l$8$d = c_open_l;
            start_r$8$d = c_open_r;
            len_l$8$d = 32'h0;
            len_r$8$d = 32'h0;
        end
        if (clear) begin
            br$8$d = 1'b0;
            start_l$8$d = 32'h0;
            start_r$8$d = 32'h0;
            len_l$8$d = 32'h0;
            len_r$8$d = 32'h0;
        end
        br$9$clock = clock;
        start_l$9$clock = clock;
        start_r$9$clock = clock;
        len_l$9$clock = clock;
        len_r$9$clock = clock;
        br$9$d = br$9$q;
        start_l$9$d = start_l$9$q;
        start_r$9$d = start_r$9$q;
        len_l$9$d = len_l$9$q;
        len_r$9$d = len_r$9$q;
        if (c_l1 == idx$9) begin
            if (c_desc) begin
                br$9$d = c_desc_b;
            end
            if (c_wok & ~wr_side) begin
                len_l$9$d = len_l$9$q + 32'h1;
            end
            if (c_wok & wr_side) begin
                len_r$9$d = len_r$9$q + 32'h1;
            end
        end
        if (c_u_right & (lvl$q == idx$9)) begin
            br$9$d = 1'b1;
        end
        if (c_open & (c_open_lvl == idx$9)) begin
            start_l$9$d = c_open_l;
            start_r$9$d = c_open_r;
            len_l$9$d = 32'h0;
            len_r$9$d = 32'h0;
        end
        if (clear) begin
            br$9$d = 1'b0;
            start_l$9$d = 32'h0;
            start_r$9$d = 32'h0;
            len_l$9$d = 32'h0;
            len_r$9$d = 32'h0;
        end
        br$10$clock = clock;
        start_l$10$clock = clock;
        start_r$10$clock = clock;
        len_l$10$clock = clock;
        len_r$10$clock = clock;
        br$10$d = br$10$q;
        start_l$10$d = start_l$10$q;
        start_r$10$d = start_r$10$q;
        len_l$10$d = len_l$10$q;
        len_r$10$d = len_r$10$q;
        if (c_l1 == idx$10) begin
            if (c_desc) begin
                br$10$d = c_desc_b;
            end
            if (c_wok & ~wr_side) begin
                len_l$10$d = len_l$10$q + 32'h1;
            end
            if (c_wok & wr_side) begin
                len_r$10$d = len_r$10$q + 32'h1;
            end
        end
        if (c_u_right & (lvl$q == idx$10)) begin
            br$10$d = 1'b1;
        end
        if (c_open & (c_open_lvl == idx$10)) begin
            start_l$10$d = c_open_l;
            start_r$10$d = c_open_r;
            len_l$10$d = 32'h0;
            len_r$10$d = 32'h0;
        end
        if (clear) begin
            br$10$d = 1'b0;
            start_l$10$d = 32'h0;
            start_r$10$d = 32'h0;
            len_l$10$d = 32'h0;
            len_r$10$d = 32'h0;
        end
        br$11$clock = clock;
        start_l$11$clock = clock;
        start_r$11$clock = clock;
        len_l$11$clock = clock;
        len_r$11$clock = clock;
        br$11$d = br$11$q;
        start_l$11$d = start_l$11$q;
        start_r$11$d = start_r$11$q;
        len_l$11$d = len_l$11$q;
        len_r$11$d = len_r$11$q;
        if (c_l1 == idx$11) begin
            if (c_desc) begin
                br$11$d = c_desc_b;
            end
            if (c_wok & ~wr_side) begin
                len_l$11$d = len_l$11$q + 32'h1;
            end
            if (c_wok & wr_side) begin
                len_r$11$d = len_r$11$q + 32'h1;
            end
        end
        if (c_u_right & (lvl$q == idx$11)) begin
            br$11$d = 1'b1;
        end
        if (c_open & (c_open_lvl == idx$11)) begin
            start_l$11$d = c_open_l;
            start_r$11$d = c_open_r;
            len_l$11$d = 32'h0;
            len_r$11$d = 32'h0;
        end
        if (clear) begin
            br$11$d = 1'b0;
            start_l$11$d = 32'h0;
            start_r$11$d = 32'h0;
            len_l$11$d = 32'h0;
            len_r$11$d = 32'h0;
        end
        br$12$clock = clock;
        start_l$12$clock = clock;
        start_r$12$clock = clock;
        len_l$12$clock = clock;
        len_r$12$clock = clock;
        br$12$d = br$12$q;
        start_l$12$d = start_l$12$q;
        start_r$12$d = start_r$12$q;
        len_l$12$d = len_l$12$q;
        len_r$12$d = len_r$12$q;
        if (c_l1 == idx$12) begin
            if (c_desc) begin
                br$12$d = c_desc_b;
            end
            if (c_wok & ~wr_side) begin
                len_l$12$d = len_l$12$q + 32'h1;
            end
            if (c_wok & wr_side) begin
                len_r$12$d = len_r$12$q + 32'h1;
            end
        end
        if (c_u_right & (lvl$q == idx$12)) begin
            br$12$d = 1'b1;
        end
        if (c_open & (c_open_lvl == idx$12)) begin
            start_l$12$d = c_open_l;
            start_r$12$d = c_open_r;
            len_l$12$d = 32'h0;
            len_r$12$d = 32'h0;
        end
        if (clear) begin
            br$12$d = 1'b0;
            start_l$12$d = 32'h0;
            start_r$12$d = 32'h0;
            len_l$12$d = 32'h0;
            len_r$12$d = 32'h0;
        end
        br$13$clock = clock;
        start_l$13$clock = clock;
        start_r$13$clock = clock;
        len_l$13$clock = clock;
        len_r$13$clock = clock;
        br$13$d = br$13$q;
        start_l$13$d = start_l$13$q;
        start_r$13$d = start_r$13$q;
        len_l$13$d = len_l$13$q;
        len_r$13$d = len_r$13$q;
        if (c_l1 == idx$13) begin
            if (c_desc) begin
                br$13$d = c_desc_b;
            end
            if (c_wok & ~wr_side) begin
                len_l$13$d = len_l$13$q + 32'h1;
            end
            if (c_wok & wr_side) begin
                len_r$13$d = len_r$13$q + 32'h1;
            end
        end
        if (c_u_right & (lvl$q == idx$13)) begin
            br$13$d = 1'b1;
        end
        if (c_open & (c_open_lvl == idx$13)) begin
            start_l$13$d = c_open_l;
            start_r$13$d = c_open_r;
            len_l$13$d = 32'h0;
            len_r$13$d = 32'h0;
        end
        if (clear) begin
            br$13$d = 1'b0;
            start_l$13$d = 32'h0;
            start_r$13$d = 32'h0;
            len_l$13$d = 32'h0;
            len_r$13$d = 32'h0;
        end
        br$14$clock = clock;
        start_l$14$clock = clock;
        start_r$14$clock = clock;
        len_l$14$clock = clock;
        len_r$14$clock = clock;
        br$14$d = br$14$q;
        start_l$14$d = start_l$14$q;
        start_r$14$d = start_r$14$q;
        len_l$14$d = len_l$14$q;
        len_r$14$d = len_r$14$q;
        if (c_l1 == idx$14) begin
            if (c_desc) begin
                br$14$d = c_desc_b;
            end
            if (c_wok & ~wr_side) begin
                len_l$14$d = len_l$14$q + 32'h1;
            end
            if (c_wok & wr_side) begin
                len_r$14$d = len_r$14$q + 32'h1;
            end
        end
        if (c_u_right & (lvl$q == idx$14)) begin
            br$14$d = 1'b1;
        end
        if (c_open & (c_open_lvl == idx$14)) begin
            start_l$14$d = c_open_l;
            start_r$14$d = c_open_r;
            len_l$14$d = 32'h0;
            len_r$14$d = 32'h0;
        end
        if (clear) begin
            br$14$d = 1'b0;
            start_l$14$d = 32'h0;
            start_r$14$d = 32'h0;
            len_l$14$d = 32'h0;
            len_r$14$d = 32'h0;
        end
        br$15$clock = clock;
        start_l$15$clock = clock;
        start_r$15$clock = clock;
        len_l$15$clock = clock;
        len_r$15$clock = clock;
        br$15$d = br$15$q;
        start_l$15$d = start_l$15$q;
        start_r$15$d = start_r$15$q;
        len_l$15$d = len_l$15$q;
        len_r$15$d = len_r$15$q;
        if (c_l1 == idx$15) begin
            if (c_desc) begin
                br$15$d = c_desc_b;
            end
            if (c_wok & ~wr_side) begin
                len_l$15$d = len_l$15$q + 32'h1;
            end
            if (c_wok & wr_side) begin
                len_r$15$d = len_r$15$q + 32'h1;
            end
        end
        if (c_u_right & (lvl$q == idx$15)) begin
            br$15$d = 1'b1;
        end
        if (c_open & (c_open_lvl == idx$15)) begin
            start_l$15$d = c_open_l;
            start_r$15$d = c_open_r;
            len_l$15$d = 32'h0;
            len_r$15$d = 32'h0;
        end
        if (clear) begin
            br$15$d = 1'b0;
            start_l$15$d = 32'h0;
            start_r$15$d = 32'h0;
            len_l$15$d = 32'h0;
            len_r$15$d = 32'h0;
        end
        br$16$clock = clock;
        start_l$16$clock = clock;
        start_r$16$clock = clock;
        len_l$16$clock = clock;
        len_r$16$clock = clock;
        br$16$d = br$16$q;
        start_l$16$d = start_l$16$q;
        start_r$16$d = start_r$16$q;
        len_l$16$d = len_l$16$q;
        len_r$16$d = len_r$16$q;
        if (c_l1 == idx$16) begin
            if (c_desc) begin
                br$16$d = c_desc_b;
            end
            if (c_wok & ~wr_side) begin
                len_l$16$d = len_l$16$q + 32'h1;
            end
            if (c_wok & wr_side) begin
                len_r$16$d = len_r$16$q + 32'h1;
            end
        end
        if (c_u_right & (lvl$q == idx$16)) begin
            br$16$d = 1'b1;
        end
        if (c_open & (c_open_lvl == idx$16)) begin
            start_l$16$d = c_open_l;
            start_r$16$d = c_open_r;
            len_l$16$d = 32'h0;
            len_r$16$d = 32'h0;
        end
        if (clear) begin
            br$16$d = 1'b0;
            start_l$16$d = 32'h0;
            start_r$16$d = 32'h0;
            len_l$16$d = 32'h0;
            len_r$16$d = 32'h0;
        end
        br$17$clock = clock;
        start_l$17$clock = clock;
        start_r$17$clock = clock;
        len_l$17$clock = clock;
        len_r$17$clock = clock;
        br$17$d = br$17$q;
        start_l$17$d = start_l$17$q;
        start_r$17$d = start_r$17$q;
        len_l$17$d = len_l$17$q;
        len_r$17$d = len_r$17$q;
        if (c_l1 == idx$17) begin
            if (c_desc) begin
                br$17$d = c_desc_b;
            end
            if (c_wok & ~wr_side) begin
                len_l$17$d = len_l$17$q + 32'h1;
            end
            if (c_wok & wr_side) begin
                len_r$17$d = len_r$17$q + 32'h1;
            end
        end
        if (c_u_right & (lvl$q == idx$17)) begin
            br$17$d = 1'b1;
        end
        if (c_open & (c_open_lvl == idx$17)) begin
            start_l$17$d = c_open_l;
            start_r$17$d = c_open_r;
            len_l$17$d = 32'h0;
            len_r$17$d = 32'h0;
        end
        if (clear) begin
            br$17$d = 1'b0;
            start_l$17$d = 32'h0;
            start_r$17$d = 32'h0;
            len_l$17$d = 32'h0;
            len_r$17$d = 32'h0;
        end
        br$18$clock = clock;
        start_l$18$clock = clock;
        start_r$18$clock = clock;
        len_l$18$clock = clock;
        len_r$18$clock = clock;
        br$18$d = br$18$q;
        start_l$18$d = start_l$18$q;
        start_r$18$d = start_r$18$q;
        len_l$18$d = len_l$18$q;
        len_r$18$d = len_r$18$q;
        if (c_l1 == idx$18) begin
            if (c_desc) begin
                br$18$d = c_desc_b;
            end
            if (c_wok & ~wr_side) begin
                len_l$18$d = len_l$18$q + 32'h1;
            end
            if (c_wok & wr_side) begin
                len_r$18$d = len_r$18$q + 32'h1;
            end
        end
        if (c_u_right & (lvl$q == idx$18)) begin
            br$18$d = 1'b1;
        end
        if (c_open & (c_open_lvl == idx$18)) begin
            start_l$18$d = c_open_l;
            start_r$18$d = c_open_r;
            len_l$18$d = 32'h0;
            len_r$18$d = 32'h0;
        end
        if (clear) begin
            br$18$d = 1'b0;
            start_l$18$d = 32'h0;
            start_r$18$d = 32'h0;
            len_l$18$d = 32'h0;
            len_r$18$d = 32'h0;
        end
        br$19$clock = clock;
        start_l$19$clock = clock;
        start_r$19$clock = clock;
        len_l$19$clock = clock;
        len_r$19$clock = clock;
        br$19$d = br$19$q;
        start_l$19$d = start_l$19$q;
        start_r$19$d = start_r$19$q;
        len_l$19$d = len_l$19$q;
        len_r$19$d = len_r$19$q;
        if (c_l1 == idx$19) begin
            if (c_desc) begin
                br$19$d = c_desc_b;
            end
            if (c_wok & ~wr_side) begin
                len_l$19$d = len_l$19$q + 32'h1;
            end
            if (c_wok & wr_side) begin
                len_r$19$d = len_r$19$q + 32'h1;
            end
        end
        if (c_u_right & (lvl$q == idx$19)) begin
            br$19$d = 1'b1;
        end
        if (c_open & (c_open_lvl == idx$19)) begin
            start_l$19$d = c_open_l;
            start_r$19$d = c_open_r;
            len_l$19$d = 32'h0;
            len_r$19$d = 32'h0;
        end
        if (clear) begin
            br$19$d = 1'b0;
            start_l$19$d = 32'h0;
            start_r$19$d = 32'h0;
            len_l$19$d = 32'h0;
            len_r$19$d = 32'h0;
        end
        br$20$clock = clock;
        start_l$20$clock = clock;
        start_r$20$clock = clock;
        len_l$20$clock = clock;
        len_r$20$clock = clock;
        br$20$d = br$20$q;
        start_l$20$d = start_l$20$q;
        start_r$20$d = start_r$20$q;
        len_l$20$d = len_l$20$q;
        len_r$20$d = len_r$20$q;
        if (c_l1 == idx$20) begin
            if (c_desc) begin
                br$20$d = c_desc_b;
            end
            if (c_wok & ~wr_side) begin
                len_l$20$d = len_l$20$q + 32'h1;
            end
            if (c_wok & wr_side) begin
                len_r$20$d = len_r$20$q + 32'h1;
            end
        end
        if (c_u_right & (lvl$q == idx$20)) begin
            br$20$d = 1'b1;
        end
        if (c_open & (c_open_lvl == idx$20)) begin
            start_l$20$d = c_open_l;
            start_r$20$d = c_open_r;
            len_l$20$d = 32'h0;
            len_r$20$d = 32'h0;
        end
        if (clear) begin
            br$20$d = 1'b0;
            start_l$20$d = 32'h0;
            start_r$20$d = 32'h0;
            len_l$20$d = 32'h0;
            len_r$20$d = 32'h0;
        end
        br$21$clock = clock;
        start_l$21$clock = clock;
        start_r$21$clock = clock;
        len_l$21$clock = clock;
        len_r$21$clock = clock;
        br$21$d = br$21$q;
        start_l$21$d = start_l$21$q;
        start_r$21$d = start_r$21$q;
        len_l$21$d = len_l$21$q;
        len_r$21$d = len_r$21$q;
        if (c_l1 == idx$21) begin
            if (c_desc) begin
                br$21$d = c_desc_b;
            end
            if (c_wok & ~wr_side) begin
                len_l$21$d = len_l$21$q + 32'h1;
            end
            if (c_wok & wr_side) begin
                len_r$21$d = len_r$21$q + 32'h1;
            end
        end
        if (c_u_right & (lvl$q == idx$21)) begin
            br$21$d = 1'b1;
        end
        if (c_open & (c_open_lvl == idx$21)) begin
            start_l$21$d = c_open_l;
            start_r$21$d = c_open_r;
            len_l$21$d = 32'h0;
            len_r$21$d = 32'h0;
        end
        if (clear) begin
            br$21$d = 1'b0;
            start_l$21$d = 32'h0;
            start_r$21$d = 32'h0;
            len_l$21$d = 32'h0;
            len_r$21$d = 32'h0;
        end
        br$22$clock = clock;
        start_l$22$clock = clock;
        start_r$22$clock = clock;
        len_l$22$clock = clock;
        len_r$22$clock = clock;
        br$22$d = br$22$q;
        start_l$22$d = start_l$22$q;
        start_r$22$d = start_r$22$q;
        len_l$22$d = len_l$22$q;
        len_r$22$d = len_r$22$q;
        if (c_l1 == idx$22) begin
            if (c_desc) begin
                br$22$d = c_desc_b;
            end
            if (c_wok & ~wr_side) begin
                len_l$22$d = len_l$22$q + 32'h1;
            end
            if (c_wok & wr_side) begin
                len_r$22$d = len_r$22$q + 32'h1;
            end
        end
        if (c_u_right & (lvl$q == idx$22)) begin
            br$22$d = 1'b1;
        end
        if (c_open & (c_open_lvl == idx$22)) begin
            start_l$22$d = c_open_l;
            start_r$22$d = c_open_r;
            len_l$22$d = 32'h0;
            len_r$22$d = 32'h0;
        end
        if (clear) begin
            br$22$d = 1'b0;
            start_l$22$d = 32'h0;
            start_r$22$d = 32'h0;
            len_l$22$d = 32'h0;
            len_r$22$d = 32'h0;
        end
        br$23$clock = clock;
        start_l$23$clock = clock;
        start_r$23$clock = clock;
        len_l$23$clock = clock;
        len_r$23$clock = clock;
        br$23$d = br$23$q;
        start_l$23$d = start_l$23$q;
        start_r$23$d = start_r$23$q;
        len_l$23$d = len_l$23$q;
        len_r$23$d = len_r$23$q;
        if (c_l1 == idx$23) begin
            if (c_desc) begin
                br$23$d = c_desc_b;
            end
            if (c_wok & ~wr_side) begin
                len_l$23$d = len_l$23$q + 32'h1;
            end
            if (c_wok & wr_side) begin
                len_r$23$d = len_r$23$q + 32'h1;
            end
        end
        if (c_u_right & (lvl$q == idx$23)) begin
            br$23$d = 1'b1;
        end
        if (c_open & (c_open_lvl == idx$23)) begin
            start_l$23$d = c_open_l;
            start_r$23$d = c_open_r;
            len_l$23$d = 32'h0;
            len_r$23$d = 32'h0;
        end
        if (clear) begin
            br$23$d = 1'b0;
            start_l$23$d = 32'h0;
            start_r$23$d = 32'h0;
            len_l$23$d = 32'h0;
            len_r$23$d = 32'h0;
        end
        br$24$clock = clock;
        start_l$24$clock = clock;
        start_r$24$clock = clock;
        len_l$24$clock = clock;
        len_r$24$clock = clock;
        br$24$d = br$24$q;
        start_l$24$d = start_l$24$q;
        start_r$24$d = start_r$24$q;
        len_l$24$d = len_l$24$q;
        len_r$24$d = len_r$24$q;
        if (c_l1 == idx$24) begin
            if (c_desc) begin
                br$24$d = c_desc_b;
            end
            if (c_wok & ~wr_side) begin
                len_l$24$d = len_l$24$q + 32'h1;
            end
            if (c_wok & wr_side) begin
                len_r$24$d = len_r$24$q + 32'h1;
            end
        end
        if (c_u_right & (lvl$q == idx$24)) begin
            br$24$d = 1'b1;
        end
        if (c_open & (c_open_lvl == idx$24)) begin
            start_l$24$d = c_open_l;
            start_r$24$d = c_open_r;
            len_l$24$d = 32'h0;
            len_r$24$d = 32'h0;
        end
        if (clear) begin
            br$24$d = 1'b0;
            start_l$24$d = 32'h0;
            start_r$24$d = 32'h0;
            len_l$24$d = 32'h0;
            len_r$24$d = 32'h0;
        end
        br$25$clock = clock;
        start_l$25$clock = clock;
        start_r$25$clock = clock;
        len_l$25$clock = clock;
        len_r$25$clock = clock;
        br$25$d = br$25$q;
        start_l$25$d = start_l$25$q;
        start_r$25$d = start_r$25$q;
        len_l$25$d = len_l$25$q;
        len_r$25$d = len_r$25$q;
        if (c_l1 == idx$25) begin
            if (c_desc) begin
                br$25$d = c_desc_b;
            end
            if (c_wok & ~wr_side) begin
                len_l$25$d = len_l$25$q + 32'h1;
            end
            if (c_wok & wr_side) begin
                len_r$25$d = len_r$25$q + 32'h1;
            end
        end
        if (c_u_right & (lvl$q == idx$25)) begin
            br$25$d = 1'b1;
        end
        if (c_open & (c_open_lvl == idx$25)) begin
            start_l$25$d = c_open_l;
            start_r$25$d = c_open_r;
            len_l$25$d = 32'h0;
            len_r$25$d = 32'h0;
        end
        if (clear) begin
            br$25$d = 1'b0;
            start_l$25$d = 32'h0;
            start_r$25$d = 32'h0;
            len_l$25$d = 32'h0;
            len_r$25$d = 32'h0;
        end
        br$26$clock = clock;
        start_l$26$clock = clock;
        start_r$26$clock = clock;
        len_l$26$clock = clock;
        len_r$26$clock = clock;
        br$26$d = br$26$q;
        start_l$26$d = start_l$26$q;
        start_r$26$d = start_r$26$q;
        len_l$26$d = len_l$26$q;
        len_r$26$d = len_r$26$q;
        if (c_l1 == idx$26) begin
            if (c_desc) begin
                br$26$d = c_desc_b;
            end
            if (c_wok & ~wr_side) begin
                len_l$26$d = len_l$26$q + 32'h1;
            end
            if (c_wok & wr_side) begin
                len_r$26$d = len_r$26$q + 32'h1;
            end
        end
        if (c_u_right & (lvl$q == idx$26)) begin
            br$26$d = 1'b1;
        end
        if (c_open & (c_open_lvl == idx$26)) begin
            start_l$26$d = c_open_l;
            start_r$26$d = c_open_r;
            len_l$26$d = 32'h0;
            len_r$26$d = 32'h0;
        end
        if (clear) begin
            br$26$d = 1'b0;
            start_l$26$d = 32'h0;
            start_r$26$d = 32'h0;
            len_l$26$d = 32'h0;
            len_r$26$d = 32'h0;
        end
        br$27$clock = clock;
        start_l$27$clock = clock;
        start_r$27$clock = clock;
        len_l$27$clock = clock;
        len_r$27$clock = clock;
        br$27$d = br$27$q;
        start_l$27$d = start_l$27$q;
        start_r$27$d = start_r$27$q;
        len_l$27$d = len_l$27$q;
        len_r$27$d = len_r$27$q;
        if (c_l1 == idx$27) begin
            if (c_desc) begin
                br$27$d = c_desc_b;
            end
            if (c_wok & ~wr_side) begin
                len_l$27$d = len_l$27$q + 32'h1;
            end
            if (c_wok & wr_side) begin
                len_r$27$d = len_r$27$q + 32'h1;
            end
        end
        if (c_u_right & (lvl$q == idx$27)) begin
            br$27$d = 1'b1;
        end
        if (c_open & (c_open_lvl == idx$27)) begin
            start_l$27$d = c_open_l;
            start_r$27$d = c_open_r;
            len_l$27$d = 32'h0;
            len_r$27$d = 32'h0;
        end
        if (clear) begin
            br$27$d = 1'b0;
            start_l$27$d = 32'h0;
            start_r$27$d = 32'h0;
            len_l$27$d = 32'h0;
            len_r$27$d = 32'h0;
        end
        br$28$clock = clock;
        start_l$28$clock = clock;
        start_r$28$clock = clock;
        len_l$28$clock = clock;
        len_r$28$clock = clock;
        br$28$d = br$28$q;
        start_l$28$d = start_l$28$q;
        start_r$28$d = start_r$28$q;
        len_l$28$d = len_l$28$q;
        len_r$28$d = len_r$28$q;
        if (c_l1 == idx$28) begin
            if (c_desc) begin
                br$28$d = c_desc_b;
            end
            if (c_wok & ~wr_side) begin
                len_l$28$d = len_l$28$q + 32'h1;
            end
            if (c_wok & wr_side) begin
                len_r$28$d = len_r$28$q + 32'h1;
            end
        end
        if (c_u_right & (lvl$q == idx$28)) begin
            br$28$d = 1'b1;
        end
        if (c_open & (c_open_lvl == idx$28)) begin
            start_l$28$d = c_open_l;
            start_r$28$d = c_open_r;
            len_l$28$d = 32'h0;
            len_r$28$d = 32'h0;
        end
        if (clear) begin
            br$28$d = 1'b0;
            start_l$28$d = 32'h0;
            start_r$28$d = 32'h0;
            len_l$28$d = 32'h0;
            len_r$28$d = 32'h0;
        end
        br$29$clock = clock;
        start_l$29$clock = clock;
        start_r$29$clock = clock;
        len_l$29$clock = clock;
        len_r$29$clock = clock;
        br$29$d = br$29$q;
        start_l$29$d = start_l$29$q;
        start_r$29$d = start_r$29$q;
        len_l$29$d = len_l$29$q;
        len_r$29$d = len_r$29$q;
        if (c_l1 == idx$29) begin
            if (c_desc) begin
                br$29$d = c_desc_b;
            end
            if (c_wok & ~wr_side) begin
                len_l$29$d = len_l$29$q + 32'h1;
            end
            if (c_wok & wr_side) begin
                len_r$29$d = len_r$29$q + 32'h1;
            end
        end
        if (c_u_right & (lvl$q == idx$29)) begin
            br$29$d = 1'b1;
        end
        if (c_open & (c_open_lvl == idx$29)) begin
            start_l$29$d = c_open_l;
            start_r$29$d = c_open_r;
            len_l$29$d = 32'h0;
            len_r$29$d = 32'h0;
        end
        if (clear) begin
            br$29$d = 1'b0;
            start_l$29$d = 32'h0;
            start_r$29$d = 32'h0;
            len_l$29$d = 32'h0;
            len_r$29$d = 32'h0;
        end
        br$30$clock = clock;
        start_l$30$clock = clock;
        start_r$30$clock = clock;
        len_l$30$clock = clock;
        len_r$30$clock = clock;
        br$30$d = br$30$q;
        start_l$30$d = start_l$30$q;
        start_r$30$d = start_r$30$q;
        len_l$30$d = len_l$30$q;
        len_r$30$d = len_r$30$q;
        if (c_l1 == idx$30) begin
            if (c_desc) begin
                br$30$d = c_desc_b;
            end
            if (c_wok & ~wr_side) begin
                len_l$30$d = len_l$30$q + 32'h1;
            end
            if (c_wok & wr_side) begin
                len_r$30$d = len_r$30$q + 32'h1;
            end
        end
        if (c_u_right & (lvl$q == idx$30)) begin
            br$30$d = 1'b1;
        end
        if (c_open & (c_open_lvl == idx$30)) begin
            start_l$30$d = c_open_l;
            start_r$30$d = c_open_r;
            len_l$30$d = 32'h0;
            len_r$30$d = 32'h0;
        end
        if (clear) begin
            br$30$d = 1'b0;
            start_l$30$d = 32'h0;
            start_r$30$d = 32'h0;
            len_l$30$d = 32'h0;
            len_r$30$d = 32'h0;
        end
        br$31$clock = clock;
        start_l$31$clock = clock;
        start_r$31$clock = clock;
        len_l$31$clock = clock;
        len_r$31$clock = clock;
        br$31$d = br$31$q;
        start_l$31$d = start_l$31$q;
        start_r$31$d = start_r$31$q;
        len_l$31$d = len_l$31$q;
        len_r$31$d = len_r$31$q;
        if (c_l1 == idx$31) begin
            if (c_desc) begin
                br$31$d = c_desc_b;
            end
            if (c_wok & ~wr_side) begin
                len_l$31$d = len_l$31$q + 32'h1;
            end
            if (c_wok & wr_side) begin
                len_r$31$d = len_r$31$q + 32'h1;
            end
        end
        if (c_u_right & (lvl$q == idx$31)) begin
            br$31$d = 1'b1;
        end
        if (c_open & (c_open_lvl == idx$31)) begin
            start_l$31$d = c_open_l;
            start_r$31$d = c_open_r;
            len_l$31$d = 32'h0;
            len_r$31$d = 32'h0;
        end
        if (clear) begin
            br$31$d = 1'b0;
            start_l$31$d = 32'h0;
            start_r$31$d = 32'h0;
            len_l$31$d = 32'h0;
            len_r$31$d = 32'h0;
        end
        if (clear) begin
            lvl$d = 32'h0;
            pos$d = 32'h0;
            rem$d = 32'h0;
            cur_b$d = 1'b0;
            wa_l$d = 32'h0;
            wa_r$d = 32'h0;
            up$d = 1'b0;
            done_r$d = 1'b0;
            ovf$d = 1'b0;
            rd_v$d = 1'b0;
        end
        level = lvl$q;
        branch = cur_b$q;
        remaining = 32'h0;
        if (c_idle) begin
            remaining = rem$q;
        end
        busy = up$q;
        done = done_r$q;
        rd_valid = rd_v$q;
        overflow = ovf$q;
    end
    
endmodule // top$core$lists


module top$core$lists$len_l$0(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$core$lists$len_l$0


module top$core$lists$sram_l(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [11:0] read_address;
    input wire  read_clock;
    output reg  [15:0] read_data;
    input wire  [11:0] write_address;
    input wire  write_clock;
    input wire  [15:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    reg[15:0] mem[4095:0];
    
    
    
    always @(posedge read_clock) begin
       read_data <= mem[read_address];
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address] <= write_data;
       end
    end
                
endmodule // top$core$lists$sram_l


module top$core$mc(clock,clear,halt,push,push_load,push_set,push_pair,push_id,need_a,need_b,ta_id,tb_id,base_na,base_nb,base_ta,base_tb,port_out,mem_req_ready,mem_resp_valid,mem_resp_data,busy,room,pending,mem_req_valid,mem_req_addr,req_tri,fill_a,fill_b,fill_id,fill_word,t_valid,t_set,t_side,t_entry,t_last,t_data,a_valid,a_first,a_set,a_entry,e,al_valid,al_id,al_leaf,al_f0,al_f1,ld_valid,ld_set,ld_pair,ld_id,ld_leaf0,ld_leaf1,ld_f00,ld_f01,ld_f10,ld_f11);
    
    // Module arguments
    input wire  clock;
    input wire  clear;
    input wire  halt;
    input wire  push;
    input wire  push_load;
    input wire  push_set;
    input wire  push_pair;
    input wire  [15:0] push_id;
    input wire  need_a;
    input wire  need_b;
    input wire  [15:0] ta_id;
    input wire  [15:0] tb_id;
    input wire  [23:0] base_na;
    input wire  [23:0] base_nb;
    input wire  [23:0] base_ta;
    input wire  [23:0] base_tb;
    input wire  [3:0] port_out;
    input wire  mem_req_ready;
    input wire  mem_resp_valid;
    input wire  [2047:0] mem_resp_data;
    input wire  [1:0] busy;
    output reg  [3:0] room;
    output reg  pending;
    output reg  mem_req_valid;
    output reg  [23:0] mem_req_addr;
    output reg  req_tri;
    output reg  fill_a;
    output reg  fill_b;
    output reg  [15:0] fill_id;
    output reg  [737:0] fill_word;
    output reg  t_valid;
    output reg  t_set;
    output reg  t_side;
    output reg  [1:0] t_entry;
    output reg  t_last;
    output reg  [255:0] t_data;
    output reg  a_valid;
    output reg  a_first;
    output reg  a_set;
    output reg  [1:0] a_entry;
    output reg  [255:0] e;
    output reg  al_valid;
    output reg  [15:0] al_id;
    output reg  al_leaf;
    output reg  [31:0] al_f0;
    output reg  [31:0] al_f1;
    output reg  ld_valid;
    output reg  ld_set;
    output reg  ld_pair;
    output reg  [15:0] ld_id;
    output reg  ld_leaf0;
    output reg  ld_leaf1;
    output reg  [31:0] ld_f00;
    output reg  [31:0] ld_f01;
    output reg  [31:0] ld_f10;
    output reg  [31:0] ld_f11;
    
    // Constant declarations
    localparam  idx8$0 = 4'h0;
    localparam  idx8$1 = 4'h1;
    localparam  idx8$2 = 4'h2;
    localparam  idx8$3 = 4'h3;
    localparam  idx8$4 = 4'h4;
    localparam  idx8$5 = 4'h5;
    localparam  idx8$6 = 4'h6;
    localparam  idx8$7 = 4'h7;
    localparam  asks = 4'h8;
    localparam  idx16$0 = 4'h0;
    localparam  idx16$1 = 4'h1;
    localparam  idx16$2 = 4'h2;
    localparam  idx16$3 = 4'h3;
    localparam  idx16$4 = 4'h4;
    localparam  idx16$5 = 4'h5;
    localparam  idx16$6 = 4'h6;
    localparam  idx16$7 = 4'h7;
    localparam  idx16$8 = 4'h8;
    localparam  idx16$9 = 4'h9;
    localparam  idx16$10 = 4'ha;
    localparam  idx16$11 = 4'hb;
    localparam  idx16$12 = 4'hc;
    localparam  idx16$13 = 4'hd;
    localparam  idx16$14 = 4'he;
    localparam  idx16$15 = 4'hf;
    
    // Stub signals
    reg  [19:0] ask_e$0$d;
    wire  [19:0] ask_e$0$q;
    reg  ask_e$0$clock;
    reg  [19:0] ask_e$1$d;
    wire  [19:0] ask_e$1$q;
    reg  ask_e$1$clock;
    reg  [19:0] ask_e$2$d;
    wire  [19:0] ask_e$2$q;
    reg  ask_e$2$clock;
    reg  [19:0] ask_e$3$d;
    wire  [19:0] ask_e$3$q;
    reg  ask_e$3$clock;
    reg  [19:0] ask_e$4$d;
    wire  [19:0] ask_e$4$q;
    reg  ask_e$4$clock;
    reg  [19:0] ask_e$5$d;
    wire  [19:0] ask_e$5$q;
    reg  ask_e$5$clock;
    reg  [19:0] ask_e$6$d;
    wire  [19:0] ask_e$6$q;
    reg  ask_e$6$clock;
    reg  [19:0] ask_e$7$d;
    wire  [19:0] ask_e$7$q;
    reg  ask_e$7$clock;
    reg  ask_req$0$d;
    wire  ask_req$0$q;
    reg  ask_req$0$clock;
    reg  ask_req$1$d;
    wire  ask_req$1$q;
    reg  ask_req$1$clock;
    reg  ask_req$2$d;
    wire  ask_req$2$q;
    reg  ask_req$2$clock;
    reg  ask_req$3$d;
    wire  ask_req$3$q;
    reg  ask_req$3$clock;
    reg  ask_req$4$d;
    wire  ask_req$4$q;
    reg  ask_req$4$clock;
    reg  ask_req$5$d;
    wire  ask_req$5$q;
    reg  ask_req$5$clock;
    reg  ask_req$6$d;
    wire  ask_req$6$q;
    reg  ask_req$6$clock;
    reg  ask_req$7$d;
    wire  ask_req$7$q;
    reg  ask_req$7$clock;
    reg  [3:0] ask_n$d;
    wire  [3:0] ask_n$q;
    reg  ask_n$clock;
    reg  [15:0] last_al$d;
    wire  [15:0] last_al$q;
    reg  last_al$clock;
    reg  last_al_v$d;
    wire  last_al_v$q;
    reg  last_al_v$clock;
    reg  [1:0] tag_d$0$d;
    wire  [1:0] tag_d$0$q;
    reg  tag_d$0$clock;
    reg  [1:0] tag_d$1$d;
    wire  [1:0] tag_d$1$q;
    reg  tag_d$1$clock;
    reg  [1:0] tag_d$2$d;
    wire  [1:0] tag_d$2$q;
    reg  tag_d$2$clock;
    reg  [1:0] tag_d$3$d;
    wire  [1:0] tag_d$3$q;
    reg  tag_d$3$clock;
    reg  [1:0] tag_d$4$d;
    wire  [1:0] tag_d$4$q;
    reg  tag_d$4$clock;
    reg  [1:0] tag_d$5$d;
    wire  [1:0] tag_d$5$q;
    reg  tag_d$5$clock;
    reg  [1:0] tag_d$6$d;
    wire  [1:0] tag_d$6$q;
    reg  tag_d$6$clock;
    reg  [1:0] tag_d$7$d;
    wire  [1:0] tag_d$7$q;
    reg  tag_d$7$clock;
    reg  [1:0] tag_d$8$d;
    wire  [1:0] tag_d$8$q;
    reg  tag_d$8$clock;
    reg  [1:0] tag_d$9$d;
    wire  [1:0] tag_d$9$q;
    reg  tag_d$9$clock;
    reg  [1:0] tag_d$10$d;
    wire  [1:0] tag_d$10$q;
    reg  tag_d$10$clock;
    reg  [1:0] tag_d$11$d;
    wire  [1:0] tag_d$11$q;
    reg  tag_d$11$clock;
    reg  [1:0] tag_d$12$d;
    wire  [1:0] tag_d$12$q;
    reg  tag_d$12$clock;
    reg  [1:0] tag_d$13$d;
    wire  [1:0] tag_d$13$q;
    reg  tag_d$13$clock;
    reg  [1:0] tag_d$14$d;
    wire  [1:0] tag_d$14$q;
    reg  tag_d$14$clock;
    reg  [1:0] tag_d$15$d;
    wire  [1:0] tag_d$15$q;
    reg  tag_d$15$clock;
    reg  [15:0] tag_r$0$d;
    wire  [15:0] tag_r$0$q;
    reg  tag_r$0$clock;
    reg  [15:0] tag_r$1$d;
    wire  [15:0] tag_r$1$q;
    reg  tag_r$1$clock;
    reg  [15:0] tag_r$2$d;
    wire  [15:0] tag_r$2$q;
    reg  tag_r$2$clock;
    reg  [15:0] tag_r$3$d;
    wire  [15:0] tag_r$3$q;
    reg  tag_r$3$clock;
    reg  [15:0] tag_r$4$d;
    wire  [15:0] tag_r$4$q;
    reg  tag_r$4$clock;
    reg  [15:0] tag_r$5$d;
    wire  [15:0] tag_r$5$q;
    reg  tag_r$5$clock;
    reg  [15:0] tag_r$6$d;
    wire  [15:0] tag_r$6$q;
    reg  tag_r$6$clock;
    reg  [15:0] tag_r$7$d;
    wire  [15:0] tag_r$7$q;
    reg  tag_r$7$clock;
    reg  [15:0] tag_r$8$d;
    wire  [15:0] tag_r$8$q;
    reg  tag_r$8$clock;
    reg  [15:0] tag_r$9$d;
    wire  [15:0] tag_r$9$q;
    reg  tag_r$9$clock;
    reg  [15:0] tag_r$10$d;
    wire  [15:0] tag_r$10$q;
    reg  tag_r$10$clock;
    reg  [15:0] tag_r$11$d;
    wire  [15:0] tag_r$11$q;
    reg  tag_r$11$clock;
    reg  [15:0] tag_r$12$d;
    wire  [15:0] tag_r$12$q;
    reg  tag_r$12$clock;
    reg  [15:0] tag_r$13$d;
    wire  [15:0] tag_r$13$q;
    reg  tag_r$13$clock;
    reg  [15:0] tag_r$14$d;
    wire  [15:0] tag_r$14$q;
    reg  tag_r$14$clock;
    reg  [15:0] tag_r$15$d;
    wire  [15:0] tag_r$15$q;
    reg  tag_r$15$clock;
    reg  [3:0] tag_head$d;
    wire  [3:0] tag_head$q;
    reg  tag_head$clock;
    reg  [4:0] tag_n$d;
    wire  [4:0] tag_n$q;
    reg  tag_n$clock;
    reg  ta_out$d;
    wire  ta_out$q;
    reg  ta_out$clock;
    reg  tb_out$d;
    wire  tb_out$q;
    reg  tb_out$clock;
    reg  [1:0] node_inf$d;
    wire  [1:0] node_inf$q;
    reg  node_inf$clock;
    reg  [2047:0] held0$d;
    wire  [2047:0] held0$q;
    reg  held0$clock;
    reg  [2047:0] held1$d;
    wire  [2047:0] held1$q;
    reg  held1$clock;
    reg  [1:0] held_n$d;
    wire  [1:0] held_n$q;
    reg  held_n$clock;
    reg  [2047:0] cur$d;
    wire  [2047:0] cur$q;
    reg  cur$clock;
    reg  [2:0] beat$d;
    wire  [2:0] beat$q;
    reg  beat$clock;
    
    // Local signals
    reg  [19:0] c_e0;
    reg  c_load;
    reg  c_set;
    reg  c_pair;
    reg  c_fetch;
    reg  [15:0] c_id;
    reg  c_first;
    reg  [2047:0] c_rec;
    reg  c_ok;
    reg  c_side;
    reg  [2:0] c_entry;
    reg  c_slot;
    reg  [832:0] c_word;
    reg  [832:0] c_w0;
    reg  [832:0] c_w1;
    reg  [255:0] c_bundle;
    reg  c_last;
    reg  c_pop;
    reg  c_take;
    reg  c_rq_found;
    reg  [3:0] c_rq_idx;
    reg  [19:0] c_rq_e;
    reg  [23:0] c_rq_base;
    reg  c_tag_ok;
    reg  c_req_ta;
    reg  c_req_tb;
    reg  c_req_node;
    reg  c_accept;
    reg  [1:0] c_acc_d;
    reg  [15:0] c_acc_r;
    reg  [1:0] c_hd_d;
    reg  [15:0] c_hd_r;
    reg  c_resp_node;
    reg  [15:0] c_push_rec;
    reg  c_push_fetch;
    reg  [3:0] c_push_at;
    reg  [3:0] c_tag_at;
    
    // Sub module instances
    top$core$mc$ask_e$0 ask_e$0(
        .d(ask_e$0$d),
        .q(ask_e$0$q),
        .clock(ask_e$0$clock)
    );
    top$core$mc$ask_e$0 ask_e$1(
        .d(ask_e$1$d),
        .q(ask_e$1$q),
        .clock(ask_e$1$clock)
    );
    top$core$mc$ask_e$0 ask_e$2(
        .d(ask_e$2$d),
        .q(ask_e$2$q),
        .clock(ask_e$2$clock)
    );
    top$core$mc$ask_e$0 ask_e$3(
        .d(ask_e$3$d),
        .q(ask_e$3$q),
        .clock(ask_e$3$clock)
    );
    top$core$mc$ask_e$0 ask_e$4(
        .d(ask_e$4$d),
        .q(ask_e$4$q),
        .clock(ask_e$4$clock)
    );
    top$core$mc$ask_e$0 ask_e$5(
        .d(ask_e$5$d),
        .q(ask_e$5$q),
        .clock(ask_e$5$clock)
    );
    top$core$mc$ask_e$0 ask_e$6(
        .d(ask_e$6$d),
        .q(ask_e$6$q),
        .clock(ask_e$6$clock)
    );
    top$core$mc$ask_e$0 ask_e$7(
        .d(ask_e$7$d),
        .q(ask_e$7$q),
        .clock(ask_e$7$clock)
    );
    top$core$done_r ask_req$0(
        .d(ask_req$0$d),
        .q(ask_req$0$q),
        .clock(ask_req$0$clock)
    );
    top$core$done_r ask_req$1(
        .d(ask_req$1$d),
        .q(ask_req$1$q),
        .clock(ask_req$1$clock)
    );
    top$core$done_r ask_req$2(
        .d(ask_req$2$d),
        .q(ask_req$2$q),
        .clock(ask_req$2$clock)
    );
    top$core$done_r ask_req$3(
        .d(ask_req$3$d),
        .q(ask_req$3$q),
        .clock(ask_req$3$clock)
    );
    top$core$done_r ask_req$4(
        .d(ask_req$4$d),
        .q(ask_req$4$q),
        .clock(ask_req$4$clock)
    );
    top$core$done_r ask_req$5(
        .d(ask_req$5$d),
        .q(ask_req$5$q),
        .clock(ask_req$5$clock)
    );
    top$core$done_r ask_req$6(
        .d(ask_req$6$d),
        .q(ask_req$6$q),
        .clock(ask_req$6$clock)
    );
    top$core$done_r ask_req$7(
        .d(ask_req$7$d),
        .q(ask_req$7$q),
        .clock(ask_req$7$clock)
    );
    top$core$mc$ask_n ask_n(
        .d(ask_n$d),
        .q(ask_n$q),
        .clock(ask_n$clock)
    );
    top$core$lists$len_l$0 last_al(
        .d(last_al$d),
        .q(last_al$q),
        .clock(last_al$clock)
    );
    top$core$done_r last_al_v(
        .d(last_al_v$d),
        .q(last_al_v$q),
        .clock(last_al_v$clock)
    );
    top$core$dop$busy_r tag_d$0(
        .d(tag_d$0$d),
        .q(tag_d$0$q),
        .clock(tag_d$0$clock)
    );
    top$core$dop$busy_r tag_d$1(
        .d(tag_d$1$d),
        .q(tag_d$1$q),
        .clock(tag_d$1$clock)
    );
    top$core$dop$busy_r tag_d$2(
        .d(tag_d$2$d),
        .q(tag_d$2$q),
        .clock(tag_d$2$clock)
    );
    top$core$dop$busy_r tag_d$3(
        .d(tag_d$3$d),
        .q(tag_d$3$q),
        .clock(tag_d$3$clock)
    );
    top$core$dop$busy_r tag_d$4(
        .d(tag_d$4$d),
        .q(tag_d$4$q),
        .clock(tag_d$4$clock)
    );
    top$core$dop$busy_r tag_d$5(
        .d(tag_d$5$d),
        .q(tag_d$5$q),
        .clock(tag_d$5$clock)
    );
    top$core$dop$busy_r tag_d$6(
        .d(tag_d$6$d),
        .q(tag_d$6$q),
        .clock(tag_d$6$clock)
    );
    top$core$dop$busy_r tag_d$7(
        .d(tag_d$7$d),
        .q(tag_d$7$q),
        .clock(tag_d$7$clock)
    );
    top$core$dop$busy_r tag_d$8(
        .d(tag_d$8$d),
        .q(tag_d$8$q),
        .clock(tag_d$8$clock)
    );
    top$core$dop$busy_r tag_d$9(
        .d(tag_d$9$d),
        .q(tag_d$9$q),
        .clock(tag_d$9$clock)
    );
    top$core$dop$busy_r tag_d$10(
        .d(tag_d$10$d),
        .q(tag_d$10$q),
        .clock(tag_d$10$clock)
    );
    top$core$dop$busy_r tag_d$11(
        .d(tag_d$11$d),
        .q(tag_d$11$q),
        .clock(tag_d$11$clock)
    );
    top$core$dop$busy_r tag_d$12(
        .d(tag_d$12$d),
        .q(tag_d$12$q),
        .clock(tag_d$12$clock)
    );
    top$core$dop$busy_r tag_d$13(
        .d(tag_d$13$d),
        .q(tag_d$13$q),
        .clock(tag_d$13$clock)
    );
    top$core$dop$busy_r tag_d$14(
        .d(tag_d$14$d),
        .q(tag_d$14$q),
        .clock(tag_d$14$clock)
    );
    top$core$dop$busy_r tag_d$15(
        .d(tag_d$15$d),
        .q(tag_d$15$q),
        .clock(tag_d$15$clock)
    );
    top$core$lists$len_l$0 tag_r$0(
        .d(tag_r$0$d),
        .q(tag_r$0$q),
        .clock(tag_r$0$clock)
    );
    top$core$lists$len_l$0 tag_r$1(
        .d(tag_r$1$d),
        .q(tag_r$1$q),
        .clock(tag_r$1$clock)
    );
    top$core$lists$len_l$0 tag_r$2(
        .d(tag_r$2$d),
        .q(tag_r$2$q),
        .clock(tag_r$2$clock)
    );
    top$core$lists$len_l$0 tag_r$3(
        .d(tag_r$3$d),
        .q(tag_r$3$q),
        .clock(tag_r$3$clock)
    );
    top$core$lists$len_l$0 tag_r$4(
        .d(tag_r$4$d),
        .q(tag_r$4$q),
        .clock(tag_r$4$clock)
    );
    top$core$lists$len_l$0 tag_r$5(
        .d(tag_r$5$d),
        .q(tag_r$5$q),
        .clock(tag_r$5$clock)
    );
    top$core$lists$len_l$0 tag_r$6(
        .d(tag_r$6$d),
        .q(tag_r$6$q),
        .clock(tag_r$6$clock)
    );
    top$core$lists$len_l$0 tag_r$7(
        .d(tag_r$7$d),
        .q(tag_r$7$q),
        .clock(tag_r$7$clock)
    );
    top$core$lists$len_l$0 tag_r$8(
        .d(tag_r$8$d),
        .q(tag_r$8$q),
        .clock(tag_r$8$clock)
    );
    top$core$lists$len_l$0 tag_r$9(
        .d(tag_r$9$d),
        .q(tag_r$9$q),
        .clock(tag_r$9$clock)
    );
    top$core$lists$len_l$0 tag_r$10(
        .d(tag_r$10$d),
        .q(tag_r$10$q),
        .clock(tag_r$10$clock)
    );
    top$core$lists$len_l$0 tag_r$11(
        .d(tag_r$11$d),
        .q(tag_r$11$q),
        .clock(tag_r$11$clock)
    );
    top$core$lists$len_l$0 tag_r$12(
        .d(tag_r$12$d),
        .q(tag_r$12$q),
        .clock(tag_r$12$clock)
    );
    top$core$lists$len_l$0 tag_r$13(
        .d(tag_r$13$d),
        .q(tag_r$13$q),
        .clock(tag_r$13$clock)
    );
    top$core$lists$len_l$0 tag_r$14(
        .d(tag_r$14$d),
        .q(tag_r$14$q),
        .clock(tag_r$14$clock)
    );
    top$core$lists$len_l$0 tag_r$15(
        .d(tag_r$15$d),
        .q(tag_r$15$q),
        .clock(tag_r$15$clock)
    );
    top$core$mc$ask_n tag_head(
        .d(tag_head$d),
        .q(tag_head$q),
        .clock(tag_head$clock)
    );
    top$core$dop$gen_cnt tag_n(
        .d(tag_n$d),
        .q(tag_n$q),
        .clock(tag_n$clock)
    );
    top$core$done_r ta_out(
        .d(ta_out$d),
        .q(ta_out$q),
        .clock(ta_out$clock)
    );
    top$core$done_r tb_out(
        .d(tb_out$d),
        .q(tb_out$q),
        .clock(tb_out$clock)
    );
    top$core$dop$busy_r node_inf(
        .d(node_inf$d),
        .q(node_inf$q),
        .clock(node_inf$clock)
    );
    top$core$mc$cur held0(
        .d(held0$d),
        .q(held0$q),
        .clock(held0$clock)
    );
    top$core$mc$cur held1(
        .d(held1$d),
        .q(held1$q),
        .clock(held1$clock)
    );
    top$core$dop$busy_r held_n(
        .d(held_n$d),
        .q(held_n$q),
        .clock(held_n$clock)
    );
    top$core$mc$cur cur(
        .d(cur$d),
        .q(cur$q),
        .clock(cur$clock)
    );
    top$core$mc$beat beat(
        .d(beat$d),
        .q(beat$q),
        .clock(beat$clock)
    );
    
    // Update code
    always @(*) begin
        c_e0 = ask_e$0$q;
        c_load = c_e0[32'h0];
        c_set = c_e0[32'h1];
        c_pair = c_e0[32'h2];
        c_fetch = c_e0[32'h3];
        c_id = c_e0[(32'h4)+:(16)];
        c_first = beat$q == 32'h0;
        if (c_first & c_fetch) begin
            c_rec = held0$q;
        end
        else begin
            c_rec = cur$q;
        end
        c_ok = (ask_n$q != 32'h0) & ~halt & ~(c_first & c_fetch & (held_n$q == 32'h0)) & ~(c_first & (busy[32'h0] & ~c_set)) & ~(c_first & (busy[32'h1] & c_set));
        c_side = c_load & (beat$q > 32'h2);
        if (c_side) begin
            c_entry = beat$q - 32'h3;
        end
        else begin
            c_entry = beat$q;
        end
        if (c_load & c_pair) begin
            c_slot = c_side;
        end
        else begin
            c_slot = c_id[32'h0];
        end
        c_w0 = c_rec[(32'h0)+:(833)];
        c_w1 = c_rec[(32'h341)+:(833)];
        if (c_slot) begin
            c_word = c_w1;
        end
        else begin
            c_word = c_w0;
        end
        if (c_entry == 32'h0) begin
            c_bundle = c_word[(32'h1)+:(256)];
        end
        else if (c_entry == 32'h1) begin
            c_bundle = c_word[(32'h101)+:(256)];
        end
        else begin
            c_bundle = c_word[(32'h201)+:(256)];
        end
        if (c_load & c_pair) begin
            c_last = beat$q == 32'h5;
        end
        else begin
            c_last = beat$q == 32'h2;
        end
        c_pop = c_ok & c_last;
        c_take = c_ok & c_first & c_fetch;
        c_rq_found = 1'b0;
        c_rq_idx = 32'h0;
        c_rq_e = 32'h0;
        if ((idx8$7 < ask_n$q) & ~ask_req$7$q) begin
            c_rq_found = 1'b1;
            c_rq_idx = idx8$7;
            c_rq_e = ask_e$7$q;
        end
        if ((idx8$6 < ask_n$q) & ~ask_req$6$q) begin
            c_rq_found = 1'b1;
            c_rq_idx = idx8$6;
            c_rq_e = ask_e$6$q;
        end
        if ((idx8$5 < ask_n$q) & ~ask_req$5$q) begin
            c_rq_found = 1'b1;
            c_rq_idx = idx8$5;
            c_rq_e = ask_e$5$q;
        end
        if ((idx8$4 < ask_n$q) & ~ask_req$4$q) begin
            c_rq_found = 1'b1;
            c_rq_idx = idx8$4;
            c_rq_e = ask_e$4$q;
        end
        if ((idx8$3 < ask_n$q) & ~ask_req$3$q) begin
            c_rq_found = 1'b1;
            c_rq_idx = idx8$3;
            c_rq_e = ask_e$3$q;
        end
        if ((idx8$2 < ask_n$q) & ~ask_req$2$q) begin
            c_rq_found = 1'b1;
            c_rq_idx = idx8$2;
            c_rq_e = ask_e$2$q;
        end
        if ((idx8$1 < ask_n$q) & ~ask_req$1$q) begin
            c_rq_found = 1'b1;
            c_rq_idx = idx8$1;
            c_rq_e = ask_e$1$q;
        end
        if ((idx8$0 < ask_n$q) & ~ask_req$0$q) begin
            c_rq_found = 1'b1;
            c_rq_idx = idx8$0;
            c_rq_e = ask_e$0$q;
        end
        c_rq_base = base_na;
        if (c_rq_e[32'h0]) begin
            c_rq_base = base_nb;
        end
        c_tag_ok = tag_n$q <= ((port_out) & 5'h1f);
        c_req_ta = c_tag_ok & need_a & ~ta_out$q;
        c_req_tb = c_tag_ok & need_b & ~tb_out$q & ~c_req_ta;
        c_req_node = c_tag_ok & ~c_req_ta & ~c_req_tb & c_rq_found & (((held_n$q) & 3'h7) + ((node_inf$q) & 3'h7) < 32'h2);
        mem_req_valid = c_req_ta | c_req_tb | c_req_node;
        req_tri = c_req_ta | c_req_tb;
        c_accept = mem_req_valid & mem_req_ready;
        if (c_req_ta) begin
            mem_req_addr = base_ta + ((ta_id) & 24'hffffff);
            c_acc_d = 32'h2;
            c_acc_r = ta_id;
        end
        else if (c_req_tb) begin
            mem_req_addr = base_tb + ((tb_id) & 24'hffffff);
            c_acc_d = 32'h3;
            c_acc_r = tb_id;
        end
        else if (c_req_node) begin
            mem_req_addr = c_rq_base + ((c_rq_e[(32'h4)+:(16)] >> 32'h1) & 24'hffffff);
            c_acc_d = ((c_rq_e[(32'h0)+:(1)]) & 2'h3);
            c_acc_r = c_rq_e[(32'h4)+:(16)] >> 32'h1;
        end
        else begin
            mem_req_addr = 32'h0;
            c_acc_d = 32'h0;
            c_acc_r = 32'h0;
        end
        c_hd_d = 32'h0;
        c_hd_r = 32'h0;
        if (tag_head$q == idx16$0) begin
            c_hd_d = tag_d$0$q;
            c_hd_r = tag_r$0$q;
        end
        if (tag_head$q == idx16$1) begin
            c_hd_d = tag_d$1$q;
            c_hd_r = tag_r$1$q;
        end
        if (tag_head$q == idx16$2) begin
            c_hd_d = tag_d$2$q;
            c_hd_r = tag_r$2$q;
        end
        if (tag_head$q == idx16$3) begin
            c_hd_d = tag_d$3$q;
            c_hd_r = tag_r$3$q;
        end
        if (tag_head$q == idx16$4) begin
            c_hd_d = tag_d$4$q;
            c_hd_r = tag_r$4$q;
        end
        if (tag_head$q == idx16$5) begin
            c_hd_d = tag_d$5$q;
            c_hd_r = tag_r$5$q;
        end
        if (tag_head$q == idx16$6) begin
            c_hd_d = tag_d$6$q;
            c_hd_r = tag_r$6$q;
        end
        if (tag_head$q == idx16$7) begin
            c_hd_d = tag_d$7$q;
            c_hd_r = tag_r$7$q;
        end
        if (tag_head$q == idx16$8) begin
            c_hd_d = tag_d$8$q;
            c_hd_r = tag_r$8$q;
        end
        if (tag_head$q == idx16$9) begin
            c_hd_d = tag_d$9$q;
            c_hd_r = tag_r$9$q;
        end
        if (tag_head$q == idx16$10) begin
            c_hd_d = tag_d$10$q;
            c_hd_r = tag_r$10$q;
        end
        if (tag_head$q == idx16$11) begin
            c_hd_d = tag_d$11$q;
            c_hd_r = tag_r$11$q;
        end
        if (tag_head$q == idx16$12) begin
            c_hd_d = tag_d$12$q;
            c_hd_r = tag_r$12$q;
        end
        if (tag_head$q == idx16$13) begin
            c_hd_d = tag_d$13$q;
            c_hd_r = tag_r$13$q;
        end
        if (tag_head$q == idx16$14) begin
            c_hd_d = tag_d$14$q;
            c_hd_r = tag_r$14$q;
        end
        if (tag_head$q == idx16$15) begin
            c_hd_d = tag_d$15$q;
            c_hd_r = tag_r$15$q;
        end
        c_resp_node = mem_resp_valid & ~c_hd_d[32'h1];
        fill_a = mem_resp_valid & (c_hd_d == 32'h2);
        fill_b = mem_resp_valid & (c_hd_d == 32'h3);
        fill_id = 32'h0;
        fill_word = 32'h0;
        if (fill_a | fill_b) begin
            fill_id = c_hd_r;
            fill_word = mem_resp_data[(32'h0)+:(738)];
        end
        ask_n$clock = clock;
        last_al$clock = clock;
        last_al_v$clock = clock;
        tag_head$clock = clock;
        tag_n$clock = clock;
        ta_out$clock = clock;
        tb_out$clock = clock;
        ask_n$d = ask_n$q;
        last_al$d = last_al$q;
        last_al_v$d = last_al_v$q;
        tag_head$d = tag_head$q;
        tag_n$d = tag_n$q;
        ta_out$d = ta_out$q;
        tb_out$d = tb_out$q;
        node_inf$clock = clock;
        held0$clock = clock;
        held1$clock = clock;
        held_n$clock = clock;
        cur$clock = clock;
        beat$clock = clock;
        node_inf$d = node_inf$q;
        held0$d = held0$q;
        held1$d = held1$q;
        held_n$d = held_n$q;
        cur$d = cur$q;
        beat$d = beat$q;
        t_valid = c_ok & c_load;
        a_valid = c_ok & ~c_load;
        al_valid = a_valid & c_last;
        ld_valid = t_valid & c_first;
        t_set = t_valid & c_set;
        t_side = t_valid & c_side;
        t_last = t_valid & c_last;
        a_first = a_valid & c_first;
        a_set = a_valid & c_set;
        t_entry = 32'h0;
        t_data = 32'h0;
        a_entry = 32'h0;
        e = 32'h0;
        if (t_valid) begin
            t_entry = c_entry[(32'h0)+:(2)];
            t_data = c_bundle;
        end
        if (a_valid) begin
            a_entry = c_entry[(32'h0)+:(2)];
            e = c_bundle;
        end
        al_id = 32'h0;
        al_leaf = 1'b0;
        al_f0 = 32'h0;
        al_f1 = 32'h0;
        if (al_valid) begin
            al_id = c_id;
            al_leaf = c_word[32'h0];
            al_f0 = c_word[(32'h301)+:(32)];
            al_f1 = c_word[(32'h301 + 32'h20)+:(32)];
        end
        ld_set = ld_valid & c_set;
        ld_pair = ld_valid & c_pair;
        ld_id = 32'h0;
        ld_leaf0 = 1'b0;
        ld_leaf1 = 1'b0;
        ld_f00 = 32'h0;
        ld_f01 = 32'h0;
        ld_f10 = 32'h0;
        ld_f11 = 32'h0;
        if (ld_valid) begin
            ld_id = c_id;
            ld_leaf0 = c_word[32'h0];
            ld_f00 = c_word[(32'h301)+:(32)];
            ld_f01 = c_word[(32'h301 + 32'h20)+:(32)];
        end
        if (ld_pair) begin
            ld_leaf1 = c_w1[32'h0];
            ld_f10 = c_w1[(32'h301)+:(32)];
            ld_f11 = c_w1[(32'h301 + 32'h20)+:(32)];
        end
        room = asks - ask_n$q;
        pending = tag_n$q != 32'h0;
        if (c_ok) begin
            beat$d = beat$q + 32'h1;
        end
        if (c_pop) begin
            beat$d = 32'h0;
        end
        if (c_take) begin
            cur$d = held0$q;
            held0$d = held1$q;
        end
        if (c_resp_node) begin
            if ((held_n$q == 32'h0) | ((held_n$q == 32'h1) & c_take)) begin
                held0$d = mem_resp_data;
            end
            else begin
                held1$d = mem_resp_data;
            end
        end
        held_n$d = held_n$q + ((c_resp_node) & 2'h3) - ((c_take) & 2'h3);
        node_inf$d = node_inf$q + (((c_accept & c_req_node)) & 2'h3) - ((c_resp_node) & 2'h3);
        c_push_rec = push_id >> 32'h1;
        c_push_fetch = push_load | ~last_al_v$q | (last_al$q != c_push_rec);
        if (push & ~push_load) begin
            last_al_v$d = 1'b1;
            last_al$d = c_push_rec;
        end
        if (push & push_load) begin
            last_al_v$d = 1'b0;
        end
        c_push_at = ask_n$q - ((c_pop) & 4'hf);
        ask_n$d = c_push_at + ((push) & 4'hf);
        ask_e$0$clock = clock;
        ask_req$0$clock = clock;
        ask_e$0$d = ask_e$0$q;
        ask_req$0$d = ask_req$0$q | (c_accept & c_req_node & (c_rq_idx == idx8$0));
        ask_e$1$clock = clock;
        ask_req$1$clock = clock;
        ask_e$1$d = ask_e$1$q;
        ask_req$1$d = ask_req$1$q | (c_accept & c_req_node & (c_rq_idx == idx8$1));
        ask_e$2$clock = clock;
        ask_req$2$clock = clock;
        ask_e$2$d = ask_e$2$q;
        ask_req$2$d = ask_req$2$q | (c_accept & c_req_node & (c_rq_idx == idx8$2));
        ask_e$3$clock = clock;
        ask_req$3$clock = clock;
        ask_e$3$d = ask_e$3$q;
        ask_req$3$d = ask_req$3$q | (c_accept & c_req_node & (c_rq_idx == idx8$3));
        ask_e$4$clock = clock;
        ask_req$4$clock = clock;
        ask_e$4$d = ask_e$4$q;
        ask_req$4$d = ask_req$4$q | (c_accept & c_req_node & (c_rq_idx == idx8$4));
        ask_e$5$clock = clock;
        ask_req$5$clock = clock;
        ask_e$5$d = ask_e$5$q;
        ask_req$5$d = ask_req$5$q | (c_accept & c_req_node & (c_rq_idx == idx8$5));
        ask_e$6$clock = clock;
        ask_req$6$clock = clock;
        ask_e$6$d = ask_e$6$q;
        ask_req$6$d = ask_req$6$q | (c_accept & c_req_node & (c_rq_idx == idx8$6));
        ask_e$7$clock = clock;
        ask_req$7$clock = clock;
        ask_e$7$d = ask_e$7$q;
        ask_req$7$d = ask_req$7$q | (c_accept & c_req_node & (c_rq_idx == idx8$7));
        if (c_pop) begin
            ask_e$0$d = ask_e$1$q;
            ask_req$0$d = ask_req$1$q | (c_accept & c_req_node & (c_rq_idx == idx8$1));
        end
        if (c_pop) begin
            ask_e$1$d = ask_e$2$q;
            ask_req$1$d = ask_req$2$q | (c_accept & c_req_node & (c_rq_idx == idx8$2));
        end
        if (c_pop) begin
            ask_e$2$d = ask_e$3$q;
            ask_req$2$d = ask_req$3$q | (c_accept & c_req_node & (c_rq_idx == idx8$3));
        end
        if (c_pop) begin
            ask_e$3$d = ask_e$4$q;
            ask_req$3$d = ask_req$4$q | (c_accept & c_req_node & (c_rq_idx == idx8$4));
        end
        if (c_pop) begin
            ask_e$4$d = ask_e$5$q;
            ask_req$4$d = ask_req$5$q | (c_accept & c_req_node & (c_rq_idx == idx8$5));
        end
        if (c_pop) begin
            ask_e$5$d = ask_e$6$q;
            ask_req$5$d = ask_req$6$q | (c_accept & c_req_node & (c_rq_idx == idx8$6));
        end
        if (c_pop) begin
            ask_e$6$d = ask_e$7$q;
            ask_req$6$d = ask_req$7$q | (c_accept & c_req_node & (c_rq_idx == idx8$7));
        end
        if (push & (c_push_at == idx8$0)) begin
            ask_e$0$d = ((push_load) & 20'hfffff) | (((push_set) & 20'hfffff) << 32'h1) | (((push_pair) & 20'hfffff) << 32'h2) | (((c_push_fetch) & 20'hfffff) << 32'h3) | (((push_id) & 20'hfffff) << 32'h4);
            ask_req$0$d = ~c_push_fetch;
        end
        if (push & (c_push_at == idx8$1)) begin
            ask_e$1$d = ((push_load) & 20'hfffff) | (((push_set) & 20'hfffff) << 32'h1) | (((push_pair) & 20'hfffff) << 32'h2) | (((c_push_fetch) & 20'hfffff) << 32'h3) | (((push_id) & 20'hfffff) << 32'h4);
            ask_req$1$d = ~c_push_fetch;
        end
        if (push & (c_push_at == idx8$2)) begin
            ask_e$2$d = ((push_load) & 20'hfffff) | (((push_set) & 20'hfffff) << 32'h1) | (((push_pair) & 20'hfffff) << 32'h2) | (((c_push_fetch) & 20'hfffff) << 32'h3) | (((push_id) & 20'hfffff) << 32'h4);
            ask_req$2$d = ~c_push_fetch;
        end
        if (push & (c_push_at == idx8$3)) begin
            ask_e$3$d = ((push_load) & 20'hfffff) | (((push_set) & 20'hfffff) << 32'h1) | (((push_pair) & 20'hfffff) << 32'h2) | (((c_push_fetch) & 20'hfffff) << 32'h3) | (((push_id) & 20'hfffff) << 32'h4);
            ask_req$3$d = ~c_push_fetch;
        end
        if (push & (c_push_at == idx8$4)) begin
            ask_e$4$d = ((push_load) & 20'hfffff) | (((push_set) & 20'hfffff) << 32'h1) | (((push_pair) & 20'hfffff) << 32'h2) | (((c_push_fetch) & 20'hfffff) << 32'h3) | (((push_id) & 20'hfffff) << 32'h4);
            ask_req$4$d = ~c_push_fetch;
        end
        if (push & (c_push_at == idx8$5)) begin
            ask_e$5$d = ((push_load) & 20'hfffff) | (((push_set) & 20'hfffff) << 32'h1) | (((push_pair) & 20'hfffff) << 32'h2) | (((c_push_fetch) & 20'hfffff) << 32'h3) | (((push_id) & 20'hfffff) << 32'h4);
            ask_req$5$d = ~c_push_fetch;
        end
        if (push & (c_push_at == idx8$6)) begin
            ask_e$6$d = ((push_load) & 20'hfffff) | (((push_set) & 20'hfffff) << 32'h1) | (((push_pair) & 20'hfffff) << 32'h2) | (((c_push_fetch) & 20'hfffff) << 32'h3) | (((push_id) & 20'hfffff) << 32'h4);
            ask_req$6$d = ~c_push_fetch;
        end
        if (push & (c_push_at == idx8$7)) begin
            ask_e$7$d = ((push_load) & 20'hfffff) | (((push_set) & 20'hfffff) << 32'h1) | (((push_pair) & 20'hfffff) << 32'h2) | (((c_push_fetch) & 20'hfffff) << 32'h3) | (((push_id) & 20'hfffff) << 32'h4);
            ask_req$7$d = ~c_push_fetch;
        end
        c_tag_at = (tag_head$q + tag_n$q[(32'h0)+:(4)]);
        tag_d$0$clock = clock;
        tag_r$0$clock = clock;
        tag_d$0$d = tag_d$0$q;
        tag_r$0$d = tag_r$0$q;
        if (c_accept & (c_tag_at == idx16$0)) begin
            tag_d$0$d = c_acc_d;
            tag_r$0$d = c_acc_r;
        end
        tag_d$1$clock = clock;
        tag_r$1$clock = clock;
        tag_d$1$d = tag_d$1$q;
        tag_r$1$d = tag_r$1$q;
        if (c_accept & (c_tag_at == idx16$1)) begin
            tag_d$1$d = c_acc_d;
            tag_r$1$d = c_acc_r;
        end
        tag_d$2$clock = clock;
        tag_r$2$clock = clock;
        tag_d$2$d = tag_d$2$q;
        tag_r$2$d = tag_r$2$q;
        if (c_accept & (c_tag_at == idx16$2)) begin
            tag_d$2$d = c_acc_d;
            tag_r$2$d = c_acc_r;
        end
        tag_d$3$clock = clock;
        tag_r$3$clock = clock;
        tag_d$3$d = tag_d$3$q;
        tag_r$3$d = tag_r$3$q;
        if (c_accept & (c_tag_at == idx16$3)) begin
            tag_d$3$d = c_acc_d;
            tag_r$3$d = c_acc_r;
        end
        tag_d$4$clock = clock;
        tag_r$4$clock = clock;
        tag_d$4$d = tag_d$4$q;
        tag_r$4$d = tag_r$4$q;
        if (c_accept & (c_tag_at == idx16$4)) begin
            tag_d$4$d = c_acc_d;
            tag_r$4$d = c_acc_r;
        end
        tag_d$5$clock = clock;
        tag_r$5$clock = clock;
        tag_d$5$d = tag_d$5$q;
        tag_r$5$d = tag_r$5$q;
        if (c_accept & (c_tag_at == idx16$5)) begin
            tag_d$5$d = c_acc_d;
            tag_r$5$d = c_acc_r;
        end
        tag_d$6$clock = clock;
        tag_r$6$clock = clock;
        tag_d$6$d = tag_d$6$q;
        tag_r$6$d = tag_r$6$q;
        if (c_accept & (c_tag_at == idx16$6)) begin
            tag_d$6$d = c_acc_d;
            tag_r$6$d = c_acc_r;
        end
        tag_d$7$clock = clock;
        tag_r$7$clock = clock;
        tag_d$7$d = tag_d$7$q;
        tag_r$7$d = tag_r$7$q;
        if (c_accept & (c_tag_at == idx16$7)) begin
            tag_d$7$d = c_acc_d;
            tag_r$7$d = c_acc_r;
        end
        tag_d$8$clock = clock;
        tag_r$8$clock = clock;
        tag_d$8$d = tag_d$8$q;
        tag_r$8$d = tag_r$8$q;
        if (c_accept & (c_tag_at == idx16$8)) begin
            tag_d$8$d = c_acc_d;
            tag_r$8$d = c_acc_r;
        end
        tag_d$9$clock = clock;
        tag_r$9$clock = clock;
        tag_d$9$d = tag_d$9$q;
        tag_r$9$d = tag_r$9$q;
        if (c_accept & (c_tag_at == idx16$9)) begin
            tag_d$9$d = c_acc_d;
            tag_r$9$d = c_acc_r;
        end
        tag_d$10$clock = clock;
        tag_r$10$clock = clock;
        tag_d$10$d = tag_d$10$q;
        tag_r$10$d = tag_r$10$q;
        if (c_accept & (c_tag_at == idx16$10)) begin
            tag_d$10$d = c_acc_d;
            tag_r$10$d = c_acc_r;
        end
        tag_d$11$clock = clock;
        tag_r$11$clock = clock;
        tag_d$11$d = tag_d$11$q;
        tag_r$11$d = tag_r$11$q;
        if (c_accept & (c_tag_at == idx16$11)) begin
            tag_d$11$d = c_acc_d;
            tag_r$11$d = c_acc_r;
        end
        tag_d$12$clock = clock;
        tag_r$12$clock = clock;
        tag_d$12$d = tag_d$12$q;
        tag_r$12$d = tag_r$12$q;
        if (c_accept & (c_tag_at == idx16$12)) begin
            tag_d$12$d = c_acc_d;
            tag_r$12$d = c_acc_r;
        end
        tag_d$13$clock = clock;
        tag_r$13$clock = clock;
        tag_d$13$d = tag_d$13$q;
        tag_r$13$d = tag_r$13$q;
        if (c_accept & (c_tag_at == idx16$13)) begin
            tag_d$13$d = c_acc_d;
            tag_r$13$d = c_acc_r;
        end
        tag_d$14$clock = clock;
        tag_r$14$clock = clock;
        tag_d$14$d = tag_d$14$q;
        tag_r$14$d = tag_r$14$q;
        if (c_accept & (c_tag_at == idx16$14)) begin
            tag_d$14$d = c_acc_d;
            tag_r$14$d = c_acc_r;
        end
        tag_d$15$clock = clock;
        tag_r$15$clock = clock;
        tag_d$15$d = tag_d$15$q;
        tag_r$15$d = tag_r$15$q;
        if (c_accept & (c_tag_at == idx16$15)) begin
            tag_d$15$d = c_acc_d;
            tag_r$15$d = c_acc_r;
        end
        tag_n$d = tag_n$q + ((c_accept) & 5'h1f) - ((mem_resp_valid) & 5'h1f);
        if (mem_resp_valid) begin
            tag_head$d = tag_head$q + 32'h1;
        end
        if (c_accept & c_req_ta) begin
            ta_out$d = 1'b1;
        end
        if (fill_a) begin
            ta_out$d = 1'b0;
        end
        if (c_accept & c_req_tb) begin
            tb_out$d = 1'b1;
        end
        if (fill_b) begin
            tb_out$d = 1'b0;
        end
        if (clear) begin
            ask_n$d = 32'h0;
            held_n$d = 32'h0;
            beat$d = 32'h0;
            last_al_v$d = 1'b0;
        end
    end
    
endmodule // top$core$mc


module top$core$mc$ask_e$0(d,q,clock);
    
    // Module arguments
    input wire  [19:0] d;
    output reg  [19:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 20'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$core$mc$ask_e$0


module top$core$mc$ask_n(d,q,clock);
    
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
          
endmodule // top$core$mc$ask_n


module top$core$mc$beat(d,q,clock);
    
    // Module arguments
    input wire  [2:0] d;
    output reg  [2:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 3'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$core$mc$beat


module top$core$mc$cur(d,q,clock);
    
    // Module arguments
    input wire  [2047:0] d;
    output reg  [2047:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 2048'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$core$mc$cur


module top$core$seq(clock,clear,halt,level,branch,remaining,ls_busy,ls_done,rd_valid,rd_ptr,flags_valid,overlap,room,a_valid,al_valid,al_id,al_leaf,al_f0,al_f1,ld_valid,ld_set,ld_pair,ld_id,ld_leaf0,ld_leaf1,ld_f00,ld_f01,ld_f10,ld_f11,leaf_ready,append,wr_side,wr_ptr,read,next_list,push,push_load,push_set,push_pair,push_id,leaf_valid,leaf_ida,leaf_idb,leaf_tag,leaf_side,idle,lists,dop_tests);
    
    // Module arguments
    input wire  clock;
    input wire  clear;
    input wire  halt;
    input wire  [4:0] level;
    input wire  branch;
    input wire  [15:0] remaining;
    input wire  ls_busy;
    input wire  ls_done;
    input wire  rd_valid;
    input wire  [15:0] rd_ptr;
    input wire  flags_valid;
    input wire  [1:0] overlap;
    input wire  [3:0] room;
    input wire  a_valid;
    input wire  al_valid;
    input wire  [15:0] al_id;
    input wire  al_leaf;
    input wire  [31:0] al_f0;
    input wire  [31:0] al_f1;
    input wire  ld_valid;
    input wire  ld_set;
    input wire  ld_pair;
    input wire  [15:0] ld_id;
    input wire  ld_leaf0;
    input wire  ld_leaf1;
    input wire  [31:0] ld_f00;
    input wire  [31:0] ld_f01;
    input wire  [31:0] ld_f10;
    input wire  [31:0] ld_f11;
    input wire  leaf_ready;
    output reg  append;
    output reg  wr_side;
    output reg  [15:0] wr_ptr;
    output reg  read;
    output reg  next_list;
    output reg  push;
    output reg  push_load;
    output reg  push_set;
    output reg  push_pair;
    output reg  [15:0] push_id;
    output reg  leaf_valid;
    output reg  [15:0] leaf_ida;
    output reg  [15:0] leaf_idb;
    output reg  [31:0] leaf_tag;
    output reg  leaf_side;
    output reg  idle;
    output reg  [31:0] lists;
    output reg  [31:0] dop_tests;
    
    // Constant declarations
    localparam  idx_act$0 = 6'b0;
    localparam  idx_act$1 = 6'b1;
    localparam  idx_act$2 = 6'b10;
    localparam  idx_act$3 = 6'b11;
    localparam  idx_act$4 = 6'b100;
    localparam  idx_act$5 = 6'b101;
    localparam  idx_act$6 = 6'b110;
    localparam  idx_act$7 = 6'b111;
    localparam  idx_act$8 = 6'b1000;
    localparam  idx_act$9 = 6'b1001;
    localparam  idx_act$10 = 6'b1010;
    localparam  idx_act$11 = 6'b1011;
    localparam  idx_act$12 = 6'b1100;
    localparam  idx_act$13 = 6'b1101;
    localparam  idx_act$14 = 6'b1110;
    localparam  idx_act$15 = 6'b1111;
    localparam  idx_act$16 = 6'b10000;
    localparam  idx_act$17 = 6'b10001;
    localparam  idx_act$18 = 6'b10010;
    localparam  idx_act$19 = 6'b10011;
    localparam  idx_act$20 = 6'b10100;
    localparam  idx_act$21 = 6'b10101;
    localparam  idx_act$22 = 6'b10110;
    localparam  idx_act$23 = 6'b10111;
    localparam  idx_act$24 = 6'b11000;
    localparam  idx_act$25 = 6'b11001;
    localparam  idx_act$26 = 6'b11010;
    localparam  idx_act$27 = 6'b11011;
    localparam  idx_act$28 = 6'b11100;
    localparam  idx_act$29 = 6'b11101;
    localparam  idx_act$30 = 6'b11110;
    localparam  idx_act$31 = 6'b11111;
    localparam  idx_act$32 = 6'b100000;
    localparam  idx_act$33 = 6'b100001;
    localparam  idx_act$34 = 6'b100010;
    localparam  idx_lvl$0 = 5'b0;
    localparam  idx_lvl$1 = 5'b1;
    localparam  idx_lvl$2 = 5'b10;
    localparam  idx_lvl$3 = 5'b11;
    localparam  idx_lvl$4 = 5'b100;
    localparam  idx_lvl$5 = 5'b101;
    localparam  idx_lvl$6 = 5'b110;
    localparam  idx_lvl$7 = 5'b111;
    localparam  idx_lvl$8 = 5'b1000;
    localparam  idx_lvl$9 = 5'b1001;
    localparam  idx_lvl$10 = 5'b1010;
    localparam  idx_lvl$11 = 5'b1011;
    localparam  idx_lvl$12 = 5'b1100;
    localparam  idx_lvl$13 = 5'b1101;
    localparam  idx_lvl$14 = 5'b1110;
    localparam  idx_lvl$15 = 5'b1111;
    localparam  idx_lvl$16 = 5'b10000;
    localparam  idx_lvl$17 = 5'b10001;
    localparam  idx_lvl$18 = 5'b10010;
    localparam  idx_lvl$19 = 5'b10011;
    localparam  idx_lvl$20 = 5'b10100;
    localparam  idx_lvl$21 = 5'b10101;
    localparam  idx_lvl$22 = 5'b10110;
    localparam  idx_lvl$23 = 5'b10111;
    localparam  idx_lvl$24 = 5'b11000;
    localparam  idx_lvl$25 = 5'b11001;
    localparam  idx_lvl$26 = 5'b11010;
    localparam  idx_lvl$27 = 5'b11011;
    localparam  idx_lvl$28 = 5'b11100;
    localparam  idx_lvl$29 = 5'b11101;
    localparam  idx_lvl$30 = 5'b11110;
    localparam  idx_lvl$31 = 5'b11111;
    localparam  idx_cmp$0 = 2'b0;
    localparam  idx_cmp$1 = 2'b1;
    localparam  idx_cmp$2 = 2'b10;
    
    // Stub signals
    reg  [65:0] act_e$0$d;
    wire  [65:0] act_e$0$q;
    reg  act_e$0$clock;
    reg  [65:0] act_e$1$d;
    wire  [65:0] act_e$1$q;
    reg  act_e$1$clock;
    reg  [65:0] act_e$2$d;
    wire  [65:0] act_e$2$q;
    reg  act_e$2$clock;
    reg  [65:0] act_e$3$d;
    wire  [65:0] act_e$3$q;
    reg  act_e$3$clock;
    reg  [65:0] act_e$4$d;
    wire  [65:0] act_e$4$q;
    reg  act_e$4$clock;
    reg  [65:0] act_e$5$d;
    wire  [65:0] act_e$5$q;
    reg  act_e$5$clock;
    reg  [65:0] act_e$6$d;
    wire  [65:0] act_e$6$q;
    reg  act_e$6$clock;
    reg  [65:0] act_e$7$d;
    wire  [65:0] act_e$7$q;
    reg  act_e$7$clock;
    reg  [65:0] act_e$8$d;
    wire  [65:0] act_e$8$q;
    reg  act_e$8$clock;
    reg  [65:0] act_e$9$d;
    wire  [65:0] act_e$9$q;
    reg  act_e$9$clock;
    reg  [65:0] act_e$10$d;
    wire  [65:0] act_e$10$q;
    reg  act_e$10$clock;
    reg  [65:0] act_e$11$d;
    wire  [65:0] act_e$11$q;
    reg  act_e$11$clock;
    reg  [65:0] act_e$12$d;
    wire  [65:0] act_e$12$q;
    reg  act_e$12$clock;
    reg  [65:0] act_e$13$d;
    wire  [65:0] act_e$13$q;
    reg  act_e$13$clock;
    reg  [65:0] act_e$14$d;
    wire  [65:0] act_e$14$q;
    reg  act_e$14$clock;
    reg  [65:0] act_e$15$d;
    wire  [65:0] act_e$15$q;
    reg  act_e$15$clock;
    reg  [65:0] act_e$16$d;
    wire  [65:0] act_e$16$q;
    reg  act_e$16$clock;
    reg  [65:0] act_e$17$d;
    wire  [65:0] act_e$17$q;
    reg  act_e$17$clock;
    reg  [65:0] act_e$18$d;
    wire  [65:0] act_e$18$q;
    reg  act_e$18$clock;
    reg  [65:0] act_e$19$d;
    wire  [65:0] act_e$19$q;
    reg  act_e$19$clock;
    reg  [65:0] act_e$20$d;
    wire  [65:0] act_e$20$q;
    reg  act_e$20$clock;
    reg  [65:0] act_e$21$d;
    wire  [65:0] act_e$21$q;
    reg  act_e$21$clock;
    reg  [65:0] act_e$22$d;
    wire  [65:0] act_e$22$q;
    reg  act_e$22$clock;
    reg  [65:0] act_e$23$d;
    wire  [65:0] act_e$23$q;
    reg  act_e$23$clock;
    reg  [65:0] act_e$24$d;
    wire  [65:0] act_e$24$q;
    reg  act_e$24$clock;
    reg  [65:0] act_e$25$d;
    wire  [65:0] act_e$25$q;
    reg  act_e$25$clock;
    reg  [65:0] act_e$26$d;
    wire  [65:0] act_e$26$q;
    reg  act_e$26$clock;
    reg  [65:0] act_e$27$d;
    wire  [65:0] act_e$27$q;
    reg  act_e$27$clock;
    reg  [65:0] act_e$28$d;
    wire  [65:0] act_e$28$q;
    reg  act_e$28$clock;
    reg  [65:0] act_e$29$d;
    wire  [65:0] act_e$29$q;
    reg  act_e$29$clock;
    reg  [65:0] act_e$30$d;
    wire  [65:0] act_e$30$q;
    reg  act_e$30$clock;
    reg  [65:0] act_e$31$d;
    wire  [65:0] act_e$31$q;
    reg  act_e$31$clock;
    reg  [65:0] act_e$32$d;
    wire  [65:0] act_e$32$q;
    reg  act_e$32$clock;
    reg  [65:0] act_e$33$d;
    wire  [65:0] act_e$33$q;
    reg  act_e$33$clock;
    reg  [65:0] act_e$34$d;
    wire  [65:0] act_e$34$q;
    reg  act_e$34$clock;
    reg  [5:0] act_n$d;
    wire  [5:0] act_n$q;
    reg  act_n$clock;
    reg  [33:0] grp$0$d;
    wire  [33:0] grp$0$q;
    reg  grp$0$clock;
    reg  [33:0] grp$1$d;
    wire  [33:0] grp$1$q;
    reg  grp$1$clock;
    reg  [33:0] grp$2$d;
    wire  [33:0] grp$2$q;
    reg  grp$2$clock;
    reg  [33:0] grp$3$d;
    wire  [33:0] grp$3$q;
    reg  grp$3$clock;
    reg  [33:0] grp$4$d;
    wire  [33:0] grp$4$q;
    reg  grp$4$clock;
    reg  [33:0] grp$5$d;
    wire  [33:0] grp$5$q;
    reg  grp$5$clock;
    reg  [33:0] grp$6$d;
    wire  [33:0] grp$6$q;
    reg  grp$6$clock;
    reg  [33:0] grp$7$d;
    wire  [33:0] grp$7$q;
    reg  grp$7$clock;
    reg  [33:0] grp$8$d;
    wire  [33:0] grp$8$q;
    reg  grp$8$clock;
    reg  [33:0] grp$9$d;
    wire  [33:0] grp$9$q;
    reg  grp$9$clock;
    reg  [33:0] grp$10$d;
    wire  [33:0] grp$10$q;
    reg  grp$10$clock;
    reg  [33:0] grp$11$d;
    wire  [33:0] grp$11$q;
    reg  grp$11$clock;
    reg  [33:0] grp$12$d;
    wire  [33:0] grp$12$q;
    reg  grp$12$clock;
    reg  [33:0] grp$13$d;
    wire  [33:0] grp$13$q;
    reg  grp$13$clock;
    reg  [33:0] grp$14$d;
    wire  [33:0] grp$14$q;
    reg  grp$14$clock;
    reg  [33:0] grp$15$d;
    wire  [33:0] grp$15$q;
    reg  grp$15$clock;
    reg  [33:0] grp$16$d;
    wire  [33:0] grp$16$q;
    reg  grp$16$clock;
    reg  [33:0] grp$17$d;
    wire  [33:0] grp$17$q;
    reg  grp$17$clock;
    reg  [33:0] grp$18$d;
    wire  [33:0] grp$18$q;
    reg  grp$18$clock;
    reg  [33:0] grp$19$d;
    wire  [33:0] grp$19$q;
    reg  grp$19$clock;
    reg  [33:0] grp$20$d;
    wire  [33:0] grp$20$q;
    reg  grp$20$clock;
    reg  [33:0] grp$21$d;
    wire  [33:0] grp$21$q;
    reg  grp$21$clock;
    reg  [33:0] grp$22$d;
    wire  [33:0] grp$22$q;
    reg  grp$22$clock;
    reg  [33:0] grp$23$d;
    wire  [33:0] grp$23$q;
    reg  grp$23$clock;
    reg  [33:0] grp$24$d;
    wire  [33:0] grp$24$q;
    reg  grp$24$clock;
    reg  [33:0] grp$25$d;
    wire  [33:0] grp$25$q;
    reg  grp$25$clock;
    reg  [33:0] grp$26$d;
    wire  [33:0] grp$26$q;
    reg  grp$26$clock;
    reg  [33:0] grp$27$d;
    wire  [33:0] grp$27$q;
    reg  grp$27$clock;
    reg  [33:0] grp$28$d;
    wire  [33:0] grp$28$q;
    reg  grp$28$clock;
    reg  [33:0] grp$29$d;
    wire  [33:0] grp$29$q;
    reg  grp$29$clock;
    reg  [33:0] grp$30$d;
    wire  [33:0] grp$30$q;
    reg  grp$30$clock;
    reg  [33:0] grp$31$d;
    wire  [33:0] grp$31$q;
    reg  grp$31$clock;
    reg  entered$d;
    wire  entered$q;
    reg  entered$clock;
    reg  spec$d;
    wire  spec$q;
    reg  spec$clock;
    reg  cur$d;
    wire  cur$q;
    reg  cur$clock;
    reg  [17:0] hold$0$d;
    wire  [17:0] hold$0$q;
    reg  hold$0$clock;
    reg  [17:0] hold$1$d;
    wire  [17:0] hold$1$q;
    reg  hold$1$clock;
    reg  [147:0] ldd$0$d;
    wire  [147:0] ldd$0$q;
    reg  ldd$0$clock;
    reg  [147:0] ldd$1$d;
    wire  [147:0] ldd$1$q;
    reg  ldd$1$clock;
    reg  [3:0] inflight$d;
    wire  [3:0] inflight$q;
    reg  inflight$clock;
    reg  [81:0] cmp_e$0$d;
    wire  [81:0] cmp_e$0$q;
    reg  cmp_e$0$clock;
    reg  [81:0] cmp_e$1$d;
    wire  [81:0] cmp_e$1$q;
    reg  cmp_e$1$clock;
    reg  [81:0] cmp_e$2$d;
    wire  [81:0] cmp_e$2$q;
    reg  cmp_e$2$clock;
    reg  [1:0] cmp_n$d;
    wire  [1:0] cmp_n$q;
    reg  cmp_n$clock;
    reg  [31:0] n_lists$d;
    wire  [31:0] n_lists$q;
    reg  n_lists$clock;
    reg  [31:0] n_tests$d;
    wire  [31:0] n_tests$q;
    reg  n_tests$clock;
    
    // Local signals
    reg  c_idle;
    reg  [65:0] c_front;
    reg  c_has;
    reg  c_taken;
    reg  [33:0] c_grp;
    reg  [16:0] c_gm;
    reg  [15:0] c_g_id;
    reg  c_g_pair;
    reg  c_h0;
    reg  c_h1;
    reg  [17:0] c_hc;
    reg  [17:0] c_ho;
    reg  [147:0] c_lc;
    reg  c_loaded;
    reg  c_ho_children;
    reg  [16:0] c_gw0;
    reg  [16:0] c_gw1;
    reg  [33:0] c_gw;
    reg  [17:0] c_hold_w;
    reg  [147:0] c_ldd_w;
    reg  c_enter;
    reg  c_enter_set;
    reg  c_spec_done;
    reg  c_flag;
    reg  [81:0] c_n;
    reg  c_nleaf;
    reg  c_v0;
    reg  c_v1;
    reg  [65:0] c_e0;
    reg  [65:0] c_e1;
    reg  [65:0] c_e2;
    reg  [65:0] c_e3;
    reg  c_nv1;
    reg  c_nv3;
    reg  [5:0] c_p0;
    reg  [5:0] c_p2;
    reg  [1:0] c_pm;
    
    // Sub module instances
    top$core$seq$act_e$0 act_e$0(
        .d(act_e$0$d),
        .q(act_e$0$q),
        .clock(act_e$0$clock)
    );
    top$core$seq$act_e$0 act_e$1(
        .d(act_e$1$d),
        .q(act_e$1$q),
        .clock(act_e$1$clock)
    );
    top$core$seq$act_e$0 act_e$2(
        .d(act_e$2$d),
        .q(act_e$2$q),
        .clock(act_e$2$clock)
    );
    top$core$seq$act_e$0 act_e$3(
        .d(act_e$3$d),
        .q(act_e$3$q),
        .clock(act_e$3$clock)
    );
    top$core$seq$act_e$0 act_e$4(
        .d(act_e$4$d),
        .q(act_e$4$q),
        .clock(act_e$4$clock)
    );
    top$core$seq$act_e$0 act_e$5(
        .d(act_e$5$d),
        .q(act_e$5$q),
        .clock(act_e$5$clock)
    );
    top$core$seq$act_e$0 act_e$6(
        .d(act_e$6$d),
        .q(act_e$6$q),
        .clock(act_e$6$clock)
    );
    top$core$seq$act_e$0 act_e$7(
        .d(act_e$7$d),
        .q(act_e$7$q),
        .clock(act_e$7$clock)
    );
    top$core$seq$act_e$0 act_e$8(
        .d(act_e$8$d),
        .q(act_e$8$q),
        .clock(act_e$8$clock)
    );
    top$core$seq$act_e$0 act_e$9(
        .d(act_e$9$d),
        .q(act_e$9$q),
        .clock(act_e$9$clock)
    );
    top$core$seq$act_e$0 act_e$10(
        .d(act_e$10$d),
        .q(act_e$10$q),
        .clock(act_e$10$clock)
    );
    top$core$seq$act_e$0 act_e$11(
        .d(act_e$11$d),
        .q(act_e$11$q),
        .clock(act_e$11$clock)
    );
    top$core$seq$act_e$0 act_e$12(
        .d(act_e$12$d),
        .q(act_e$12$q),
        .clock(act_e$12$clock)
    );
    top$core$seq$act_e$0 act_e$13(
        .d(act_e$13$d),
        .q(act_e$13$q),
        .clock(act_e$13$clock)
    );
    top$core$seq$act_e$0 act_e$14(
        .d(act_e$14$d),
        .q(act_e$14$q),
        .clock(act_e$14$clock)
    );
    top$core$seq$act_e$0 act_e$15(
        .d(act_e$15$d),
        .q(act_e$15$q),
        .clock(act_e$15$clock)
    );
    top$core$seq$act_e$0 act_e$16(
        .d(act_e$16$d),
        .q(act_e$16$q),
        .clock(act_e$16$clock)
    );
    top$core$seq$act_e$0 act_e$17(
        .d(act_e$17$d),
        .q(act_e$17$q),
        .clock(act_e$17$clock)
    );
    top$core$seq$act_e$0 act_e$18(
        .d(act_e$18$d),
        .q(act_e$18$q),
        .clock(act_e$18$clock)
    );
    top$core$seq$act_e$0 act_e$19(
        .d(act_e$19$d),
        .q(act_e$19$q),
        .clock(act_e$19$clock)
    );
    top$core$seq$act_e$0 act_e$20(
        .d(act_e$20$d),
        .q(act_e$20$q),
        .clock(act_e$20$clock)
    );
    top$core$seq$act_e$0 act_e$21(
        .d(act_e$21$d),
        .q(act_e$21$q),
        .clock(act_e$21$clock)
    );
    top$core$seq$act_e$0 act_e$22(
        .d(act_e$22$d),
        .q(act_e$22$q),
        .clock(act_e$22$clock)
    );
    top$core$seq$act_e$0 act_e$23(
        .d(act_e$23$d),
        .q(act_e$23$q),
        .clock(act_e$23$clock)
    );
    top$core$seq$act_e$0 act_e$24(
        .d(act_e$24$d),
        .q(act_e$24$q),
        .clock(act_e$24$clock)
    );
    top$core$seq$act_e$0 act_e$25(
        .d(act_e$25$d),
        .q(act_e$25$q),
        .clock(act_e$25$clock)
    );
    top$core$seq$act_e$0 act_e$26(
        .d(act_e$26$d),
        .q(act_e$26$q),
        .clock(act_e$26$clock)
    );
    top$core$seq$act_e$0 act_e$27(
        .d(act_e$27$d),
        .q(act_e$27$q),
        .clock(act_e$27$clock)
    );
    top$core$seq$act_e$0 act_e$28(
        .d(act_e$28$d),
        .q(act_e$28$q),
        .clock(act_e$28$clock)
    );
    top$core$seq$act_e$0 act_e$29(
        .d(act_e$29$d),
        .q(act_e$29$q),
        .clock(act_e$29$clock)
    );
    top$core$seq$act_e$0 act_e$30(
        .d(act_e$30$d),
        .q(act_e$30$q),
        .clock(act_e$30$clock)
    );
    top$core$seq$act_e$0 act_e$31(
        .d(act_e$31$d),
        .q(act_e$31$q),
        .clock(act_e$31$clock)
    );
    top$core$seq$act_e$0 act_e$32(
        .d(act_e$32$d),
        .q(act_e$32$q),
        .clock(act_e$32$clock)
    );
    top$core$seq$act_e$0 act_e$33(
        .d(act_e$33$d),
        .q(act_e$33$q),
        .clock(act_e$33$clock)
    );
    top$core$seq$act_e$0 act_e$34(
        .d(act_e$34$d),
        .q(act_e$34$q),
        .clock(act_e$34$clock)
    );
    top$core$seq$act_n act_n(
        .d(act_n$d),
        .q(act_n$q),
        .clock(act_n$clock)
    );
    top$core$seq$grp$0 grp$0(
        .d(grp$0$d),
        .q(grp$0$q),
        .clock(grp$0$clock)
    );
    top$core$seq$grp$0 grp$1(
        .d(grp$1$d),
        .q(grp$1$q),
        .clock(grp$1$clock)
    );
    top$core$seq$grp$0 grp$2(
        .d(grp$2$d),
        .q(grp$2$q),
        .clock(grp$2$clock)
    );
    top$core$seq$grp$0 grp$3(
        .d(grp$3$d),
        .q(grp$3$q),
        .clock(grp$3$clock)
    );
    top$core$seq$grp$0 grp$4(
        .d(grp$4$d),
        .q(grp$4$q),
        .clock(grp$4$clock)
    );
    top$core$seq$grp$0 grp$5(
        .d(grp$5$d),
        .q(grp$5$q),
        .clock(grp$5$clock)
    );
    top$core$seq$grp$0 grp$6(
        .d(grp$6$d),
        .q(grp$6$q),
        .clock(grp$6$clock)
    );
    top$core$seq$grp$0 grp$7(
        .d(grp$7$d),
        .q(grp$7$q),
        .clock(grp$7$clock)
    );
    top$core$seq$grp$0 grp$8(
        .d(grp$8$d),
        .q(grp$8$q),
        .clock(grp$8$clock)
    );
    top$core$seq$grp$0 grp$9(
        .d(grp$9$d),
        .q(grp$9$q),
        .clock(grp$9$clock)
    );
    top$core$seq$grp$0 grp$10(
        .d(grp$10$d),
        .q(grp$10$q),
        .clock(grp$10$clock)
    );
    top$core$seq$grp$0 grp$11(
        .d(grp$11$d),
        .q(grp$11$q),
        .clock(grp$11$clock)
    );
    top$core$seq$grp$0 grp$12(
        .d(grp$12$d),
        .q(grp$12$q),
        .clock(grp$12$clock)
    );
    top$core$seq$grp$0 grp$13(
        .d(grp$13$d),
        .q(grp$13$q),
        .clock(grp$13$clock)
    );
    top$core$seq$grp$0 grp$14(
        .d(grp$14$d),
        .q(grp$14$q),
        .clock(grp$14$clock)
    );
    top$core$seq$grp$0 grp$15(
        .d(grp$15$d),
        .q(grp$15$q),
        .clock(grp$15$clock)
    );
    top$core$seq$grp$0 grp$16(
        .d(grp$16$d),
        .q(grp$16$q),
        .clock(grp$16$clock)
    );
    top$core$seq$grp$0 grp$17(
        .d(grp$17$d),
        .q(grp$17$q),
        .clock(grp$17$clock)
    );
    top$core$seq$grp$0 grp$18(
        .d(grp$18$d),
        .q(grp$18$q),
        .clock(grp$18$clock)
    );
    top$core$seq$grp$0 grp$19(
        .d(grp$19$d),
        .q(grp$19$q),
        .clock(grp$19$clock)
    );
    top$core$seq$grp$0 grp$20(
        .d(grp$20$d),
        .q(grp$20$q),
        .clock(grp$20$clock)
    );
    top$core$seq$grp$0 grp$21(
        .d(grp$21$d),
        .q(grp$21$q),
        .clock(grp$21$clock)
    );
    top$core$seq$grp$0 grp$22(
        .d(grp$22$d),
        .q(grp$22$q),
        .clock(grp$22$clock)
    );
    top$core$seq$grp$0 grp$23(
        .d(grp$23$d),
        .q(grp$23$q),
        .clock(grp$23$clock)
    );
    top$core$seq$grp$0 grp$24(
        .d(grp$24$d),
        .q(grp$24$q),
        .clock(grp$24$clock)
    );
    top$core$seq$grp$0 grp$25(
        .d(grp$25$d),
        .q(grp$25$q),
        .clock(grp$25$clock)
    );
    top$core$seq$grp$0 grp$26(
        .d(grp$26$d),
        .q(grp$26$q),
        .clock(grp$26$clock)
    );
    top$core$seq$grp$0 grp$27(
        .d(grp$27$d),
        .q(grp$27$q),
        .clock(grp$27$clock)
    );
    top$core$seq$grp$0 grp$28(
        .d(grp$28$d),
        .q(grp$28$q),
        .clock(grp$28$clock)
    );
    top$core$seq$grp$0 grp$29(
        .d(grp$29$d),
        .q(grp$29$q),
        .clock(grp$29$clock)
    );
    top$core$seq$grp$0 grp$30(
        .d(grp$30$d),
        .q(grp$30$q),
        .clock(grp$30$clock)
    );
    top$core$seq$grp$0 grp$31(
        .d(grp$31$d),
        .q(grp$31$q),
        .clock(grp$31$clock)
    );
    top$core$done_r entered(
        .d(entered$d),
        .q(entered$q),
        .clock(entered$clock)
    );
    top$core$done_r spec(
        .d(spec$d),
        .q(spec$q),
        .clock(spec$clock)
    );
    top$core$done_r cur(
        .d(cur$d),
        .q(cur$q),
        .clock(cur$clock)
    );
    top$core$seq$hold$0 hold$0(
        .d(hold$0$d),
        .q(hold$0$q),
        .clock(hold$0$clock)
    );
    top$core$seq$hold$0 hold$1(
        .d(hold$1$d),
        .q(hold$1$q),
        .clock(hold$1$clock)
    );
    top$core$seq$ldd$0 ldd$0(
        .d(ldd$0$d),
        .q(ldd$0$q),
        .clock(ldd$0$clock)
    );
    top$core$seq$ldd$0 ldd$1(
        .d(ldd$1$d),
        .q(ldd$1$q),
        .clock(ldd$1$clock)
    );
    top$core$mc$ask_n inflight(
        .d(inflight$d),
        .q(inflight$q),
        .clock(inflight$clock)
    );
    top$core$seq$cmp_e$0 cmp_e$0(
        .d(cmp_e$0$d),
        .q(cmp_e$0$q),
        .clock(cmp_e$0$clock)
    );
    top$core$seq$cmp_e$0 cmp_e$1(
        .d(cmp_e$1$d),
        .q(cmp_e$1$q),
        .clock(cmp_e$1$clock)
    );
    top$core$seq$cmp_e$0 cmp_e$2(
        .d(cmp_e$2$d),
        .q(cmp_e$2$q),
        .clock(cmp_e$2$clock)
    );
    top$core$dop$busy_r cmp_n(
        .d(cmp_n$d),
        .q(cmp_n$q),
        .clock(cmp_n$clock)
    );
    top$core$cnt_nf n_lists(
        .d(n_lists$d),
        .q(n_lists$q),
        .clock(n_lists$clock)
    );
    top$core$cnt_nf n_tests(
        .d(n_tests$d),
        .q(n_tests$q),
        .clock(n_tests$clock)
    );
    
    // Update code
    always @(*) begin
        c_idle = ~ls_busy & ~ls_done & ~halt;
        c_front = act_e$0$q;
        c_has = act_n$q != 32'h0;
        append = c_has & ~c_front[32'h0] & c_idle;
        leaf_valid = c_has & c_front[32'h0] & ~halt;
        c_taken = append | (leaf_valid & leaf_ready);
        wr_side = 1'b0;
        wr_ptr = 32'h0;
        if (append) begin
            wr_side = c_front[32'h1];
            wr_ptr = c_front[(32'h2)+:(16)];
        end
        leaf_side = 1'b0;
        leaf_ida = 32'h0;
        leaf_idb = 32'h0;
        leaf_tag = 32'h0;
        if (leaf_valid) begin
            leaf_side = c_front[32'h1];
            leaf_ida = c_front[(32'h2)+:(16)];
            leaf_idb = c_front[(32'h12)+:(16)];
            leaf_tag = c_front[(32'h22)+:(32)];
        end
        c_grp = 32'h0;
        if (level == idx_lvl$0 + 32'h1) begin
            c_grp = grp$0$q;
        end
        if (level == idx_lvl$1 + 32'h1) begin
            c_grp = grp$1$q;
        end
        if (level == idx_lvl$2 + 32'h1) begin
            c_grp = grp$2$q;
        end
        if (level == idx_lvl$3 + 32'h1) begin
            c_grp = grp$3$q;
        end
        if (level == idx_lvl$4 + 32'h1) begin
            c_grp = grp$4$q;
        end
        if (level == idx_lvl$5 + 32'h1) begin
            c_grp = grp$5$q;
        end
        if (level == idx_lvl$6 + 32'h1) begin
            c_grp = grp$6$q;
        end
        if (level == idx_lvl$7 + 32'h1) begin
            c_grp = grp$7$q;
        end
        if (level == idx_lvl$8 + 32'h1) begin
            c_grp = grp$8$q;
        end
        if (level == idx_lvl$9 + 32'h1) begin
            c_grp = grp$9$q;
        end
        if (level == idx_lvl$10 + 32'h1) begin
            c_grp = grp$10$q;
        end
        if (level == idx_lvl$11 + 32'h1) begin
            c_grp = grp$11$q;
        end
        if (level == idx_lvl$12 + 32'h1) begin
            c_grp = grp$12$q;
        end
        if (level == idx_lvl$13 + 32'h1) begin
            c_grp = grp$13$q;
        end
        if (level == idx_lvl$14 + 32'h1) begin
            c_grp = grp$14$q;
        end
        if (level == idx_lvl$15 + 32'h1) begin
            c_grp = grp$15$q;
        end
        if (level == idx_lvl$16 + 32'h1) begin
            c_grp = grp$16$q;
        end
        if (level == idx_lvl$17 + 32'h1) begin
            c_grp = grp$17$q;
        end
        if (level == idx_lvl$18 + 32'h1) begin
            c_grp = grp$18$q;
        end
        if (level == idx_lvl$19 + 32'h1) begin
            c_grp = grp$19$q;
        end
        if (level == idx_lvl$20 + 32'h1) begin
            c_grp = grp$20$q;
        end
        if (level == idx_lvl$21 + 32'h1) begin
            c_grp = grp$21$q;
        end
        if (level == idx_lvl$22 + 32'h1) begin
            c_grp = grp$22$q;
        end
        if (level == idx_lvl$23 + 32'h1) begin
            c_grp = grp$23$q;
        end
        if (level == idx_lvl$24 + 32'h1) begin
            c_grp = grp$24$q;
        end
        if (level == idx_lvl$25 + 32'h1) begin
            c_grp = grp$25$q;
        end
        if (level == idx_lvl$26 + 32'h1) begin
            c_grp = grp$26$q;
        end
        if (level == idx_lvl$27 + 32'h1) begin
            c_grp = grp$27$q;
        end
        if (level == idx_lvl$28 + 32'h1) begin
            c_grp = grp$28$q;
        end
        if (level == idx_lvl$29 + 32'h1) begin
            c_grp = grp$29$q;
        end
        if (level == idx_lvl$30 + 32'h1) begin
            c_grp = grp$30$q;
        end
        if (level == idx_lvl$31 + 32'h1) begin
            c_grp = grp$31$q;
        end
        if (branch) begin
            c_gm = c_grp[(32'h11)+:(17)];
        end
        else begin
            c_gm = c_grp[(32'h0)+:(17)];
        end
        c_g_id = 32'h0;
        c_g_pair = 1'b0;
        if (level != 32'h1) begin
            c_g_id = c_gm[(32'h1)+:(16)];
            c_g_pair = ~c_gm[32'h0];
        end
        c_h0 = hold$0$q[32'h0] & (hold$0$q[32'h1] == c_g_pair) & (hold$0$q[(32'h2)+:(16)] == c_g_id);
        c_h1 = hold$1$q[32'h0] & (hold$1$q[32'h1] == c_g_pair) & (hold$1$q[(32'h2)+:(16)] == c_g_id);
        if (cur$q) begin
            c_hc = hold$1$q;
            c_ho = hold$0$q;
            c_lc = ldd$1$q;
        end
        else begin
            c_hc = hold$0$q;
            c_ho = hold$1$q;
            c_lc = ldd$0$q;
        end
        c_loaded = c_lc[(32'h0)+:(18)] == c_hc;
        c_ho_children = c_ho[32'h0] & c_ho[32'h1] & (((c_ho[(32'h2)+:(16)]) & 32'hffffffff) == c_lc[(32'h14)+:(32)]);
        c_enter = 1'b0;
        c_enter_set = 1'b0;
        c_spec_done = 1'b0;
        push = 1'b0;
        push_load = 1'b0;
        push_set = 1'b0;
        push_pair = 1'b0;
        push_id = 32'h0;
        if (rd_valid) begin
            push = 1'b1;
            push_set = cur$q;
            push_id = rd_ptr;
        end
        else if (c_idle & (room != 32'h0) & ~entered$q & (level != 32'h0)) begin
            c_enter = 1'b1;
            if (c_h0) begin
                c_enter_set = 1'b0;
            end
            else if (c_h1) begin
                c_enter_set = 1'b1;
            end
            else begin
                c_enter_set = ~cur$q;
                push = 1'b1;
                push_load = 1'b1;
                push_set = ~cur$q;
                push_pair = c_g_pair;
                push_id = c_g_id;
            end
        end
        else if (c_idle & (room != 32'h0) & entered$q & spec$q & c_loaded & c_lc[32'h0]) begin
            c_spec_done = 1'b1;
            if (~c_lc[32'h12] & ~c_ho_children) begin
                push = 1'b1;
                push_load = 1'b1;
                push_set = ~cur$q;
                push_pair = 1'b1;
                push_id = c_lc[(32'h14)+:(16)];
            end
        end
        read = c_idle & entered$q & (remaining != 32'h0) & (room > 32'h2) & (inflight$q < 32'h8) & (act_n$q < 32'h4) & (level != 32'h0);
        next_list = c_idle & entered$q & (remaining == 32'h0) & (inflight$q == 32'h0) & ~c_has;
        idle = ~c_has;
        lists = n_lists$q;
        dop_tests = n_tests$q;
        c_n = cmp_e$0$q;
        c_flag = flags_valid & c_n[32'h0];
        c_nleaf = c_n[32'h11];
        c_v0 = c_flag & overlap[32'h0] & c_lc[32'h0];
        c_v1 = c_flag & overlap[32'h1] & c_lc[32'h0] & c_lc[32'h1];
        c_nv1 = c_v0 & ~c_nleaf;
        c_nv3 = c_v1 & ~c_nleaf;
        if (c_nleaf & c_lc[32'h12]) begin
            c_e0 = 32'h1 | (((c_n[(32'h32)+:(16)]) & 66'h3ffffffffffffffff) << 32'h2) | (((c_lc[(32'h34)+:(16)]) & 66'h3ffffffffffffffff) << 32'h12) | (((c_n[(32'h12)+:(32)] | (c_lc[(32'h14)+:(32)] << 32'h10)) & 66'h3ffffffffffffffff) << 32'h22);
        end
        else if (c_nleaf) begin
            c_e0 = ((c_n[(32'h1)+:(16)]) & 66'h3ffffffffffffffff) << 32'h2;
        end
        else begin
            c_e0 = ((c_n[(32'h12)+:(16)]) & 66'h3ffffffffffffffff) << 32'h2;
        end
        if (c_nleaf & c_lc[32'h13]) begin
            c_e2 = 32'h3 | (((c_n[(32'h32)+:(16)]) & 66'h3ffffffffffffffff) << 32'h2) | (((c_lc[(32'h74)+:(16)]) & 66'h3ffffffffffffffff) << 32'h12) | (((c_n[(32'h12)+:(32)] | (c_lc[(32'h54)+:(32)] << 32'h10)) & 66'h3ffffffffffffffff) << 32'h22);
        end
        else if (c_nleaf) begin
            c_e2 = 32'h2 | (((c_n[(32'h1)+:(16)]) & 66'h3ffffffffffffffff) << 32'h2);
        end
        else begin
            c_e2 = 32'h2 | (((c_n[(32'h12)+:(16)]) & 66'h3ffffffffffffffff) << 32'h2);
        end
        c_e1 = ((c_n[(32'h32)+:(16)]) & 66'h3ffffffffffffffff) << 32'h2;
        c_e3 = 32'h2 | (((c_n[(32'h32)+:(16)]) & 66'h3ffffffffffffffff) << 32'h2);
        c_p0 = act_n$q - ((c_taken) & 6'h3f);
        c_p2 = c_p0;
        if (c_v0) begin
            c_p2 = c_p0 + 32'h1 + ((c_nv1) & 6'h3f);
        end
        c_pm = cmp_n$q - ((flags_valid) & 2'h3);
        c_hold_w = 32'h1 | (((push_pair) & 18'h3ffff) << 32'h1) | (((push_id) & 18'h3ffff) << 32'h2);
        c_ldd_w = 32'h1 | (((ld_pair) & 148'hfffffffffffffffffffffffffffffffffffff) << 32'h1) | (((ld_id) & 148'hfffffffffffffffffffffffffffffffffffff) << 32'h2) | (((ld_leaf0) & 148'hfffffffffffffffffffffffffffffffffffff) << 32'h12) | (((ld_leaf1) & 148'hfffffffffffffffffffffffffffffffffffff) << 32'h13) | (((ld_f00) & 148'hfffffffffffffffffffffffffffffffffffff) << 32'h14) | (((ld_f01) & 148'hfffffffffffffffffffffffffffffffffffff) << 32'h34) | (((ld_f10) & 148'hfffffffffffffffffffffffffffffffffffff) << 32'h54) | (((ld_f11) & 148'hfffffffffffffffffffffffffffffffffffff) << 32'h74);
        if (c_lc[32'h12]) begin
            c_gw0 = 32'h1 | (((c_lc[(32'h2)+:(16)]) & 17'h1ffff) << 32'h1);
        end
        else begin
            c_gw0 = ((c_lc[(32'h14)+:(16)]) & 17'h1ffff) << 32'h1;
        end
        if (c_lc[32'h13]) begin
            c_gw1 = 32'h1 | (((c_lc[(32'h2)+:(16)] + 32'h1) & 17'h1ffff) << 32'h1);
        end
        else begin
            c_gw1 = ((c_lc[(32'h54)+:(16)]) & 17'h1ffff) << 32'h1;
        end
        c_gw = ((c_gw0) & 34'h3ffffffff) | (((c_gw1) & 34'h3ffffffff) << 32'h11);
        act_n$clock = clock;
        entered$clock = clock;
        spec$clock = clock;
        cur$clock = clock;
        inflight$clock = clock;
        cmp_n$clock = clock;
        n_lists$clock = clock;
        n_tests$clock = clock;
        act_n$d = act_n$q;
        entered$d = entered$q;
        spec$d = spec$q;
        cur$d = cur$q;
        inflight$d = inflight$q;
        cmp_n$d = cmp_n$q;
        n_lists$d = n_lists$q;
        n_tests$d = n_tests$q;
        act_n$d = c_p2 + ((c_v1) & 6'h3f) + ((c_nv3) & 6'h3f);
        act_e$0$clock = clock;
        act_e$0$d = act_e$0$q;
        act_e$1$clock = clock;
        act_e$1$d = act_e$1$q;
        act_e$2$clock = clock;
        act_e$2$d = act_e$2$q;
        act_e$3$clock = clock;
        act_e$3$d = act_e$3$q;
        act_e$4$clock = clock;
        act_e$4$d = act_e$4$q;
        act_e$5$clock = clock;
        act_e$5$d = act_e$5$q;
        act_e$6$clock = clock;
        act_e$6$d = act_e$6$q;
        act_e$7$clock = clock;
        act_e$7$d = act_e$7$q;
        act_e$8$clock = clock;
        act_e$8$d = act_e$8$q;
        act_e$9$clock = clock;
        act_e$9$d = act_e$9$q;
        act_e$10$clock = clock;
        act_e$10$d = act_e$10$q;
        act_e$11$clock = clock;
        act_e$11$d = act_e$11$q;
        act_e$12$clock = clock;
        act_e$12$d = act_e$12$q;
        act_e$13$clock = clock;
        act_e$13$d = act_e$13$q;
        act_e$14$clock = clock;
        act_e$14$d = act_e$14$q;
        act_e$15$clock = clock;
        act_e$15$d = act_e$15$q;
        act_e$16$clock = clock;
        act_e$16$d = act_e$16$q;
        act_e$17$clock = clock;
        act_e$17$d = act_e$17$q;
        act_e$18$clock = clock;
        act_e$18$d = act_e$18$q;
        act_e$19$clock = clock;
        act_e$19$d = act_e$19$q;
        act_e$20$clock = clock;
        act_e$20$d = act_e$20$q;
        act_e$21$clock = clock;
        act_e$21$d = act_e$21$q;
        act_e$22$clock = clock;
        act_e$22$d = act_e$22$q;
        act_e$23$clock = clock;
        act_e$23$d = act_e$23$q;
        act_e$24$clock = clock;
        act_e$24$d = act_e$24$q;
        act_e$25$clock = clock;
        act_e$25$d = act_e$25$q;
        act_e$26$clock = clock;
        act_e$26$d = act_e$26$q;
        act_e$27$clock = clock;
        act_e$27$d = act_e$27$q;
        act_e$28$clock = clock;
        act_e$28$d = act_e$28$q;
        act_e$29$clock = clock;
        act_e$29$d = act_e$29$q;
        act_e$30$clock = clock;
        act_e$30$d = act_e$30$q;
        act_e$31$clock = clock;
        act_e$31$d = act_e$31$q;
        act_e$32$clock = clock;
        act_e$32$d = act_e$32$q;
        act_e$33$clock = clock;
        act_e$33$d = act_e$33$q;
        act_e$34$clock = clock;
        act_e$34$d = act_e$34$q;
        if (c_taken) begin
            act_e$0$d = act_e$1$q;
        end
        if (c_taken) begin
            act_e$1$d = act_e$2$q;
        end
        if (c_taken) begin
            act_e$2$d = act_e$3$q;
        end
        if (c_taken) begin
            act_e$3$d = act_e$4$q;
        end
        if (c_taken) begin
            act_e$4$d = act_e$5$q;
        end
        if (c_taken) begin
            act_e$5$d = act_e$6$q;
        end
        if (c_taken) begin
            act_e$6$d = act_e$7$q;
        end
        if (c_taken) begin
            act_e$7$d = act_e$8$q;
        end
        if (c_taken) begin
            act_e$8$d = act_e$9$q;
        end
        if (c_taken) begin
            act_e$9$d = act_e$10$q;
        end
        if (c_taken) begin
            act_e$10$d = act_e$11$q;
        end
        if (c_taken) begin
            act_e$11$d = act_e$12$q;
        end
        if (c_taken) begin
            act_e$12$d = act_e$13$q;
        end
        if (c_taken) begin
            act_e$13$d = act_e$14$q;
        end
        if (c_taken) begin
            act_e$14$d = act_e$15$q;
        end
        if (c_taken) begin
            act_e$15$d = act_e$16$q;
        end
        if (c_taken) begin
            act_e$16$d = act_e$17$q;
        end
        if (c_taken) begin
            act_e$17$d = act_e$18$q;
        end
        if (c_taken) begin
            act_e$18$d = act_e$19$q;
        end
        if (c_taken) begin
            act_e$19$d = act_e$20$q;
        end
        if (c_taken) begin
            act_e$20$d = act_e$21$q;
        end
        if (c_taken) begin
            act_e$21$d = act_e$22$q;
        end
        if (c_taken) begin
            act_e$22$d = act_e$23$q;
        end
        if (c_taken) begin
            act_e$23$d = act_e$24$q;
        end
        if (c_taken) begin
            act_e$24$d = act_e$25$q;
        end
        if (c_taken) begin
            act_e$25$d = act_e$26$q;
        end
        if (c_taken) begin
            act_e$26$d = act_e$27$q;
        end
        if (c_taken) begin
            act_e$27$d = act_e$28$q;
        end
        if (c_taken) begin
            act_e$28$d = act_e$29$q;
        end
        if (c_taken) begin
            act_e$29$d = act_e$30$q;
        end
        if (c_taken) begin
            act_e$30$d = act_e$31$q;
        end
        if (c_taken) begin
            act_e$31$d = act_e$32$q;
        end
        if (c_taken) begin
            act_e$32$d = act_e$33$q;
        end
        if (c_taken) begin
            act_e$33$d = act_e$34$q;
        end
        if (c_v0 & (c_p0 == idx_act$0)) begin
            act_e$0$d = c_e0;
        end
        if (c_nv1 & (c_p0 + 32'h1 == idx_act$0)) begin
            act_e$0$d = c_e1;
        end
        if (c_v1 & (c_p2 == idx_act$0)) begin
            act_e$0$d = c_e2;
        end
        if (c_nv3 & (c_p2 + 32'h1 == idx_act$0)) begin
            act_e$0$d = c_e3;
        end
        if (c_v0 & (c_p0 == idx_act$1)) begin
            act_e$1$d = c_e0;
        end
        if (c_nv1 & (c_p0 + 32'h1 == idx_act$1)) begin
            act_e$1$d = c_e1;
        end
        if (c_v1 & (c_p2 == idx_act$1)) begin
            act_e$1$d = c_e2;
        end
        if (c_nv3 & (c_p2 + 32'h1 == idx_act$1)) begin
            act_e$1$d = c_e3;
        end
        if (c_v0 & (c_p0 == idx_act$2)) begin
            act_e$2$d = c_e0;
        end
        if (c_nv1 & (c_p0 + 32'h1 == idx_act$2)) begin
            act_e$2$d = c_e1;
        end
        if (c_v1 & (c_p2 == idx_act$2)) begin
            act_e$2$d = c_e2;
        end
        if (c_nv3 & (c_p2 + 32'h1 == idx_act$2)) begin
            act_e$2$d = c_e3;
        end
        if (c_v0 & (c_p0 == idx_act$3)) begin
            act_e$3$d = c_e0;
        end
        if (c_nv1 & (c_p0 + 32'h1 == idx_act$3)) begin
            act_e$3$d = c_e1;
        end
        if (c_v1 & (c_p2 == idx_act$3)) begin
            act_e$3$d = c_e2;
        end
        if (c_nv3 & (c_p2 + 32'h1 == idx_act$3)) begin
            act_e$3$d = c_e3;
        end
        if (c_v0 & (c_p0 == idx_act$4)) begin
            act_e$4$d = c_e0;
        end
        if (c_nv1 & (c_p0 + 32'h1 == idx_act$4)) begin
            act_e$4$d = c_e1;
        end
        if (c_v1 & (c_p2 == idx_act$4)) begin
            act_e$4$d = c_e2;
        end
        if (c_nv3 & (c_p2 + 32'h1 == idx_act$4)) begin
            act_e$4$d = c_e3;
        end
        if (c_v0 & (c_p0 == idx_act$5)) begin
            act_e$5$d = c_e0;
        end
        if (c_nv1 & (c_p0 + 32'h1 == idx_act$5)) begin
            act_e$5$d = c_e1;
        end
        if (c_v1 & (c_p2 == idx_act$5)) begin
            act_e$5$d = c_e2;
        end
        if (c_nv3 & (c_p2 + 32'h1 == idx_act$5)) begin
            act_e$5$d = c_e3;
        end
        if (c_v0 & (c_p0 == idx_act$6)) begin
            act_e$6$d = c_e0;
        end
        if (c_nv1 & (c_p0 + 32'h1 == idx_act$6)) begin
            act_e$6$d = c_e1;
        end
        if (c_v1 & (c_p2 == idx_act$6)) begin
            act_e$6$d = c_e2;
        end
        if (c_nv3 & (c_p2 + 32'h1 == idx_act$6)) begin
            act_e$6$d = c_e3;
        end
        if (c_v0 & (c_p0 == idx_act$7)) begin
            act_e$7$d = c_e0;
        end
        if (c_nv1 & (c_p0 + 32'h1 == idx_act$7)) begin
            act_e$7$d = c_e1;
        end
        if (c_v1 & (c_p2 == idx_act$7)) begin
            act_e$7$d = c_e2;
        end
        if (c_nv3 & (c_p2 + 32'h1 == idx_act$7)) begin
            act_e$7$d = c_e3;
        end
        if (c_v0 & (c_p0 == idx_act$8)) begin
            act_e$8$d = c_e0;
        end
        if (c_nv1 & (c_p0 + 32'h1 == idx_act$8)) begin
            act_e$8$d = c_e1;
        end
        if (c_v1 & (c_p2 == idx_act$8)) begin
            act_e$8$d = c_e2;
        end
        if (c_nv3 & (c_p2 + 32'h1 == idx_act$8)) begin
            act_e$8$d = c_e3;
        end
        if (c_v0 & (c_p0 == idx_act$9)) begin
            act_e$9$d = c_e0;
        end
        if (c_nv1 & (c_p0 + 32'h1 == idx_act$9)) begin
            act_e$9$d = c_e1;
        end
        if (c_v1 & (c_p2 == idx_act$9)) begin
            act_e$9$d = c_e2;
        end
        if (c_nv3 & (c_p2 + 32'h1 == idx_act$9)) begin
            act_e$9$d = c_e3;
        end
        if (c_v0 & (c_p0 == idx_act$10)) begin
            act_e$10$d = c_e0;
        end
        if (c_nv1 & (c_p0 + 32'h1 == idx_act$10)) begin
            act_e$10$d = c_e1;
        end
        if (c_v1 & (c_p2 == idx_act$10)) begin
            act_e$10$d = c_e2;
        end
        if (c_nv3 & (c_p2 + 32'h1 == idx_act$10)) begin
            act_e$10$d = c_e3;
        end
        if (c_v0 & (c_p0 == idx_act$11)) begin
            act_e$11$d = c_e0;
        end
        if (c_nv1 & (c_p0 + 32'h1 == idx_act$11)) begin
            act_e$11$d = c_e1;
        end
        if (c_v1 & (c_p2 == idx_act$11)) begin
            act_e$11$d = c_e2;
        end
        if (c_nv3 & (c_p2 + 32'h1 == idx_act$11)) begin
            act_e$11$d = c_e3;
        end
        if (c_v0 & (c_p0 == idx_act$12)) begin
            act_e$12$d = c_e0;
        end
        if (c_nv1 & (c_p0 + 32'h1 == idx_act$12)) begin
            act_e$12$d = c_e1;
        end
        if (c_v1 & (c_p2 == idx_act$12)) begin
            act_e$12$d = c_e2;
        end
        if (c_nv3 & (c_p2 + 32'h1 == idx_act$12)) begin
            act_e$12$d = c_e3;
        end
        if (c_v0 & (c_p0 == idx_act$13)) begin
            act_e$13$d = c_e0;
        end
        if (c_nv1 & (c_p0 + 32'h1 == idx_act$13)) begin
            act_e$13$d = c_e1;
        end
        if (c_v1 & (c_p2 == idx_act$13)) begin
            act_e$13$d = c_e2;
        end
        if (c_nv3 & (c_p2 + 32'h1 == idx_act$13)) begin
            act_e$13$d = c_e3;
        end
        if (c_v0 & (c_p0 == idx_act$14)) begin
            act_e$14$d = c_e0;
        end
        if (c_nv1 & (c_p0 + 32'h1 == idx_act$14)) begin
            act_e$14$d = c_e1;
        end
        if (c_v1 & (c_p2 == idx_act$14)) begin
            act_e$14$d = c_e2;
        end
        if (c_nv3 & (c_p2 + 32'h1 == idx_act$14)) begin
            act_e$14$d = c_e3;
        end
        if (c_v0 & (c_p0 == idx_act$15)) begin
            act_e$15$d = c_e0;
        end
        if (c_nv1 & (c_p0 + 32'h1 == idx_act$15)) begin
            act_e$15$d = c_e1;
        end
        if (c_v1 & (c_p2 == idx_act$15)) begin
            act_e$15$d = c_e2;
        end
        if (c_nv3 & (c_p2 + 32'h1 == idx_act$15)) begin
            act_e$15$d = c_e3;
        end
        if (c_v0 & (c_p0 == idx_act$16)) begin
            act_e$16$d = c_e0;
        end
        if (c_nv1 & (c_p0 + 32'h1 == idx_act$16)) begin
            act_e$16$d = c_e1;
        end
        if (c_v1 & (c_p2 == idx_act$16)) begin
            act_e$16$d = c_e2;
        end
        if (c_nv3 & (c_p2 + 32'h1 == idx_act$16)) begin
            act_e$16$d = c_e3;
        end
        if (c_v0 & (c_p0 == idx_act$17)) begin
            act_e$17$d = c_e0;
        end
        if (c_nv1 & (c_p0 + 32'h1 == idx_act$17)) begin
            act_e$17$d = c_e1;
        end
        if (c_v1 & (c_p2 == idx_act$17)) begin
            act_e$17$d = c_e2;
        end
        if (c_nv3 & (c_p2 + 32'h1 == idx_act$17)) begin
            act_e$17$d = c_e3;
        end
        if (c_v0 & (c_p0 == idx_act$18)) begin
            act_e$18$d = c_e0;
        end
        if (c_nv1 & (c_p0 + 32'h1 == idx_act$18)) begin
            act_e$18$d = c_e1;
        end
        if (c_v1 & (c_p2 == idx_act$18)) begin
            act_e$18$d = c_e2;
        end
        if (c_nv3 & (c_p2 + 32'h1 == idx_act$18)) begin
            act_e$18$d = c_e3;
        end
        if (c_v0 & (c_p0 == idx_act$19)) begin
            act_e$19$d = c_e0;
        end
        if (c_nv1 & (c_p0 + 32'h1 == idx_act$19)) begin
            act_e$19$d = c_e1;
        end
        if (c_v1 & (c_p2 == idx_act$19)) begin
            act_e$19$d = c_e2;
        end
        if (c_nv3 & (c_p2 + 32'h1 == idx_act$19)) begin
            act_e$19$d = c_e3;
        end
        if (c_v0 & (c_p0 == idx_act$20)) begin
            act_e$20$d = c_e0;
        end
        if (c_nv1 & (c_p0 + 32'h1 == idx_act$20)) begin
            act_e$20$d = c_e1;
        end
        if (c_v1 & (c_p2 == idx_act$20)) begin
            act_e$20$d = c_e2;
        end
        if (c_nv3 & (c_p2 + 32'h1 == idx_act$20)) begin
            act_e$20$d = c_e3;
        end
        if (c_v0 & (c_p0 == idx_act$21)) begin
            act_e$21$d = c_e0;
        end
        if (c_nv1 & (c_p0 + 32'h1 == idx_act$21)) begin
            act_e$21$d = c_e1;
        end
        if (c_v1 & (c_p2 == idx_act$21)) begin
            act_e$21$d = c_e2;
        end
        if (c_nv3 & (c_p2 + 32'h1 == idx_act$21)) begin
            act_e$21$d = c_e3;
        end
        if (c_v0 & (c_p0 == idx_act$22)) begin
            act_e$22$d = c_e0;
        end
        if (c_nv1 & (c_p0 + 32'h1 == idx_act$22)) begin
            act_e$22$d = c_e1;
        end
        if (c_v1 & (c_p2 == idx_act$22)) begin
            act_e$22$d = c_e2;
        end
        if (c_nv3 & (c_p2 + 32'h1 == idx_act$22)) begin
            act_e$22$d = c_e3;
        end
        if (c_v0 & (c_p0 == idx_act$23)) begin
            act_e$23$d = c_e0;
        end
        if (c_nv1 & (c_p0 + 32'h1 == idx_act$23)) begin
            act_e$23$d = c_e1;
        end
        if (c_v1 & (c_p2 == idx_act$23)) begin
            act_e$23$d = c_e2;
        end
        if (c_nv3 & (c_p2 + 32'h1 == idx_act$23)) begin
            act_e$23$d = c_e3;
        end
        if (c_v0 & (c_p0 == idx_act$24)) begin
            act_e$24$d = c_e0;
        end
        if (c_nv1 & (c_p0 + 32'h1 == idx_act$24)) begin
            act_e$24$d = c_e1;
        end
        if (c_v1 & (c_p2 == idx_act$24)) begin
            act_e$24$d = c_e2;
        end
        if (c_nv3 & (c_p2 + 32'h1 == idx_act$24)) begin
            act_e$24$d = c_e3;
        end
        if (c_v0 & (c_p0 == idx_act$25)) begin
            act_e$25$d = c_e0;
        end
        if (c_nv1 & (c_p0 + 32'h1 == idx_act$25)) begin
            act_e$25$d = c_e1;
        end
        if (c_v1 & (c_p2 == idx_act$25)) begin
            act_e$25$d = c_e2;
        end
        if (c_nv3 & (c_p2 + 32'h1 == idx_act$25)) begin
            act_e$25$d = c_e3;
        end
        if (c_v0 & (c_p0 == idx_act$26)) begin
            act_e$26$d = c_e0;
        end
        if (c_nv1 & (c_p0 + 32'h1 == idx_act$26)) begin
            act_e$26$d = c_e1;
        end
        if (c_v1 & (c_p2 == idx_act$26)) begin
            act_e$26$d = c_e2;
        end
        if (c_nv3 & (c_p2 + 32'h1 == idx_act$26)) begin
            act_e$26$d = c_e3;
        end
        if (c_v0 & (c_p0 == idx_act$27)) begin
            act_e$27$d = c_e0;
        end
        if (c_nv1 & (c_p0 + 32'h1 == idx_act$27)) begin
            act_e$27$d = c_e1;
        end
        if (c_v1 & (c_p2 == idx_act$27)) begin
            act_e$27$d = c_e2;
        end
        if (c_nv3 & (c_p2 + 32'h1 == idx_act$27)) begin
            act_e$27$d = c_e3;
        end
        if (c_v0 & (c_p0 == idx_act$28)) begin
            act_e$28$d = c_e0;
        end
        if (c_nv1 & (c_p0 + 32'h1 == idx_act$28)) begin
            act_e$28$d = c_e1;
        end
        if (c_v1 & (c_p2 == idx_act$28)) begin
            act_e$28$d = c_e2;
        end
        if (c_nv3 & (c_p2 + 32'h1 == idx_act$28)) begin
            act_e$28$d = c_e3;
        end
        if (c_v0 & (c_p0 == idx_act$29)) begin
            act_e$29$d = c_e0;
        end
        if (c_nv1 & (c_p0 + 32'h1 == idx_act$29)) begin
            act_e$29$d = c_e1;
        end
        if (c_v1 & (c_p2 == idx_act$29)) begin
            act_e$29$d = c_e2;
        end
        if (c_nv3 & (c_p2 + 32'h1 == idx_act$29)) begin
            act_e$29$d = c_e3;
        end
        if (c_v0 & (c_p0 == idx_act$30)) begin
            act_e$30$d = c_e0;
        end
        if (c_nv1 & (c_p0 + 32'h1 == idx_act$30)) begin
            act_e$30$d = c_e1;
        end
        if (c_v1 & (c_p2 == idx_act$30)) begin
            act_e$30$d = c_e2;
        end
        if (c_nv3 & (c_p2 + 32'h1 == idx_act$30)) begin
            act_e$30$d = c_e3;
        end
        if (c_v0 & (c_p0 == idx_act$31)) begin
            act_e$31$d = c_e0;
        end
        if (c_nv1 & (c_p0 + 32'h1 == idx_act$31)) begin
            act_e$31$d = c_e1;
        end
        if (c_v1 & (c_p2 == idx_act$31)) begin
            act_e$31$d = c_e2;
        end
        if (c_nv3 & (c_p2 + 32'h1 == idx_act$31)) begin
            act_e$31$d = c_e3;
        end
        if (c_v0 & (c_p0 == idx_act$32)) begin
            act_e$32$d = c_e0;
        end
        if (c_nv1 & (c_p0 + 32'h1 == idx_act$32)) begin
            act_e$32$d = c_e1;
        end
        if (c_v1 & (c_p2 == idx_act$32)) begin
            act_e$32$d = c_e2;
        end
        if (c_nv3 & (c_p2 + 32'h1 == idx_act$32)) begin
            act_e$32$d = c_e3;
        end
        if (c_v0 & (c_p0 == idx_act$33)) begin
            act_e$33$d = c_e0;
        end
        if (c_nv1 & (c_p0 + 32'h1 == idx_act$33)) begin
            act_e$33$d = c_e1;
        end
        if (c_v1 & (c_p2 == idx_act$33)) begin
            act_e$33$d = c_e2;
        end
        if (c_nv3 & (c_p2 + 32'h1 == idx_act$33)) begin
            act_e$33$d = c_e3;
        end
        if (c_v0 & (c_p0 == idx_act$34)) begin
            act_e$34$d = c_e0;
        end
        if (c_nv1 & (c_p0 + 32'h1 == idx_act$34)) begin
            act_e$34$d = c_e1;
        end
        if (c_v1 & (c_p2 == idx_act$34)) begin
            act_e$34$d = c_e2;
        end
        if (c_nv3 & (c_p2 + 32'h1 == idx_act$34)) begin
            act_e$34$d = c_e3;
        end
        grp$0$clock = clock;
        grp$0$d = grp$0$q;
        if (c_flag & (level == idx_lvl$0)) begin
            grp$0$d = c_gw;
        end
        grp$1$clock = clock;
        grp$1$d = grp$1$q;
        if (c_flag & (level == idx_lvl$1)) begin
            grp$1$d = c_gw;
        end
        grp$2$clock = clock;
        grp$2$d = grp$2$q;
        if (c_flag & (level == idx_lvl$2)) begin
            grp$2$d = c_gw;
        end
        grp$3$clock = clock;
        grp$3$d = grp$3$q;
        if (c_flag & (level == idx_lvl$3)) begin
            grp$3$d = c_gw;
        end
        grp$4$clock = clock;
        grp$4$d = grp$4$q;
        if (c_flag & (level == idx_lvl$4)) begin
            grp$4$d = c_gw;
        end
        grp$5$clock = clock;
        grp$5$d = grp$5$q;
        if (c_flag & (level == idx_lvl$5)) begin
            grp$5$d = c_gw;
        end
        grp$6$clock = clock;
        grp$6$d = grp$6$q;
        if (c_flag & (level == idx_lvl$6)) begin
            grp$6$d = c_gw;
        end
        grp$7$clock = clock;
        grp$7$d = grp$7$q;
        if (c_flag & (level == idx_lvl$7)) begin
            grp$7$d = c_gw;
        end
        grp$8$clock = clock;
        grp$8$d = grp$8$q;
        if (c_flag & (level == idx_lvl$8)) begin
            grp$8$d = c_gw;
        end
        grp$9$clock = clock;
        grp$9$d = grp$9$q;
        if (c_flag & (level == idx_lvl$9)) begin
            grp$9$d = c_gw;
        end
        grp$10$clock = clock;
        grp$10$d = grp$10$q;
        if (c_flag & (level == idx_lvl$10)) begin
            grp$10$d = c_gw;
        end
        grp$11$clock = clock;
        grp$11$d = grp$11$q;
        if (c_flag & (level == idx_lvl$11)) begin
            grp$11$d = c_gw;
        end
        grp$12$clock = clock;
        grp$12$d = grp$12$q;
        if (c_flag & (level == idx_lvl$12)) begin
            grp$12$d = c_gw;
        end
        grp$13$clock = clock;
        grp$13$d = grp$13$q;
        if (c_flag & (level == idx_lvl$13)) begin
            grp$13$d = c_gw;
        end
        grp$14$clock = clock;
        grp$14$d = grp$14$q;
        if (c_flag & (level == idx_lvl$14)) begin
            grp$14$d = c_gw;
        end
        grp$15$clock = clock;
        grp$15$d = grp$15$q;
        if (c_flag & (level == idx_lvl$15)) begin
            grp$15$d = c_gw;
        end
        grp$16$clock = clock;
        grp$16$d = grp$16$q;
        if (c_flag & (level == idx_lvl$16)) begin
            grp$16$d = c_gw;
        end
        grp$17$clock = clock;
        grp$17$d = grp$17$q;
        if (c_flag & (level == idx_lvl$17)) begin
            grp$17$d = c_gw;
        end
        grp$18$clock = clock;
        grp$18$d = grp$18$q;
        if (c_flag & (level == idx_lvl$18)) begin
            grp$18$d = c_gw;
        end
        grp$19$clock = clock;
        grp$19$d = grp$19$q;
        if (c_flag & (level == idx_lvl$19)) begin
            grp$19$d = c_gw;
        end
        grp$20$clock = clock;
        grp$20$d = grp$20$q;
        if (c_flag & (level == idx_lvl$20)) begin
            grp$20$d = c_gw;
        end
        grp$21$clock = clock;
        grp$21$d = grp$21$q;
        if (c_flag & (level == idx_lvl$21)) begin
            grp$21$d = c_gw;
        end
        grp$22$clock = clock;
        grp$22$d = grp$22$q;
        if (c_flag & (level == idx_lvl$22)) begin
            grp$22$d = c_gw;
        end
        grp$23$clock = clock;
        grp$23$d = grp$23$q;
        if (c_flag & (level == idx_lvl$23)) begin
            grp$23$d = c_gw;
        end
        grp$24$clock = clock;
        grp$24$d = grp$24$q;
        if (c_flag & (level == idx_lvl$24)) begin
            grp$24$d = c_gw;
        end
        grp$25$clock = clock;
        grp$25$d = grp$25$q;
        if (c_flag & (level == idx_lvl$25)) begin
            grp$25$d = c_gw;
        end
        grp$26$clock = clock;
        grp$26$d = grp$26$q;
        if (c_flag & (level == idx_lvl$26)) begin
            grp$26$d = c_gw;
        end
        grp$27$clock = clock;
        grp$27$d = grp$27$q;
        if (c_flag & (level == idx_lvl$27)) begin
            grp$27$d = c_gw;
        end
        grp$28$clock = clock;
        grp$28$d = grp$28$q;
        if (c_flag & (level == idx_lvl$28)) begin
            grp$28$d = c_gw;
        end
        grp$29$clock = clock;
        grp$29$d = grp$29$q;
        if (c_flag & (level == idx_lvl$29)) begin
            grp$29$d = c_gw;
        end
        grp$30$clock = clock;
        grp$30$d = grp$30$q;
        if (c_flag & (level == idx_lvl$30)) begin
            grp$30$d = c_gw;
        end
        grp$31$clock = clock;
        grp$31$d = grp$31$q;
        if (c_flag & (level == idx_lvl$31)) begin
            grp$31$d = c_gw;
        end
        if (c_flag) begin
            n_tests$d = n_tests$q + ((c_lc[(32'h0)+:(1)]) & 32'hffffffff) + ((c_lc[(32'h1)+:(1)]) & 32'hffffffff);
        end
        inflight$d = inflight$q + ((read) & 4'hf) - ((c_flag) & 4'hf);
        cmp_n$d = c_pm + ((a_valid) & 2'h3);
        cmp_e$0$clock = clock;
        cmp_e$0$d = cmp_e$0$q;
        cmp_e$1$clock = clock;
        cmp_e$1$d = cmp_e$1$q;
        cmp_e$2$clock = clock;
        cmp_e$2$d = cmp_e$2$q;
        if (flags_valid) begin
            cmp_e$0$d = cmp_e$1$q;
        end
        if (flags_valid) begin
            cmp_e$1$d = cmp_e$2$q;
        end
        if (a_valid & (c_pm == idx_cmp$0)) begin
            cmp_e$0$d = ((al_valid) & 82'h3ffffffffffffffffffff) | (((al_id) & 82'h3ffffffffffffffffffff) << 32'h1) | (((al_leaf) & 82'h3ffffffffffffffffffff) << 32'h11) | (((al_f0) & 82'h3ffffffffffffffffffff) << 32'h12) | (((al_f1) & 82'h3ffffffffffffffffffff) << 32'h32);
        end
        if (a_valid & (c_pm == idx_cmp$1)) begin
            cmp_e$1$d = ((al_valid) & 82'h3ffffffffffffffffffff) | (((al_id) & 82'h3ffffffffffffffffffff) << 32'h1) | (((al_leaf) & 82'h3ffffffffffffffffffff) << 32'h11) | (((al_f0) & 82'h3ffffffffffffffffffff) << 32'h12) | (((al_f1) & 82'h3ffffffffffffffffffff) << 32'h32);
        end
        if (a_valid & (c_pm == idx_cmp$2)) begin
            cmp_e$2$d = ((al_valid) & 82'h3ffffffffffffffffffff) | (((al_id) & 82'h3ffffffffffffffffffff) << 32'h1) | (((al_leaf) & 82'h3ffffffffffffffffffff) << 32'h11) | (((al_f0) & 82'h3ffffffffffffffffffff) << 32'h12) | (((al_f1) & 82'h3ffffffffffffffffffff) << 32'h32);
        end
        hold$0$clock = clock;
        ldd$0$clock = clock;
        hold$0$d = hold$0$q;
        ldd$0$d = ldd$0$q;
        hold$1$clock = clock;
        ldd$1$clock = clock;
        hold$1$d = hold$1$q;
        ldd$1$d = ldd$1$q;
        if (push_load & ~push_set) begin
            hold$0$d = c_hold_w;
        end
        if (push_load & push_set) begin
            hold$1$d = c_hold_w;
        end
        if (ld_valid & ~ld_set) begin
            ldd$0$d = c_ldd_w;
        end
        if (ld_valid & ld_set) begin
            ldd$1$d = c_ldd_w;
        end
        if (c_enter) begin
            entered$d = 1'b1;
            spec$d = 1'b1;
            cur$d = c_enter_set;
            n_lists$d = n_lists$q + 32'h1;
        end
        if (c_spec_done) begin
            spec$d = 1'b0;
        end
        if (next_list) begin
            entered$d = 1'b0;
        end
        if (clear) begin
            act_n$d = 32'h1;
            act_e$0$d = 32'h0;
            entered$d = 1'b1;
            spec$d = 1'b0;
            cur$d = 1'b0;
            hold$0$d = 32'h0;
            hold$1$d = 32'h0;
            ldd$0$d = 32'h0;
            ldd$1$d = 32'h0;
            inflight$d = 32'h0;
            cmp_n$d = 32'h0;
            n_lists$d = 32'h0;
            n_tests$d = 32'h0;
        end
    end
    
endmodule // top$core$seq


module top$core$seq$act_e$0(d,q,clock);
    
    // Module arguments
    input wire  [65:0] d;
    output reg  [65:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 66'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$core$seq$act_e$0


module top$core$seq$act_n(d,q,clock);
    
    // Module arguments
    input wire  [5:0] d;
    output reg  [5:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 6'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$core$seq$act_n


module top$core$seq$cmp_e$0(d,q,clock);
    
    // Module arguments
    input wire  [81:0] d;
    output reg  [81:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 82'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$core$seq$cmp_e$0


module top$core$seq$grp$0(d,q,clock);
    
    // Module arguments
    input wire  [33:0] d;
    output reg  [33:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 34'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$core$seq$grp$0


module top$core$seq$hold$0(d,q,clock);
    
    // Module arguments
    input wire  [17:0] d;
    output reg  [17:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 18'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$core$seq$hold$0


module top$core$seq$ldd$0(d,q,clock);
    
    // Module arguments
    input wire  [147:0] d;
    output reg  [147:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 148'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$core$seq$ldd$0


module top$core$tin(clock,clear,mask,halt,leaf_in,leaf_ids,leaf_tag,leaf_side,fill_a,fill_b,fill_id,fill_word,tri_ready,leaf_ready,need_a,need_b,ta_id,tb_id,pair_valid,pair_tag,a_word,b_word,busy);
    
    // Module arguments
    input wire  clock;
    input wire  clear;
    input wire  [6:0] mask;
    input wire  halt;
    input wire  leaf_in;
    input wire  [31:0] leaf_ids;
    input wire  [31:0] leaf_tag;
    input wire  leaf_side;
    input wire  fill_a;
    input wire  fill_b;
    input wire  [15:0] fill_id;
    input wire  [737:0] fill_word;
    input wire  tri_ready;
    output reg  leaf_ready;
    output reg  need_a;
    output reg  need_b;
    output reg  [15:0] ta_id;
    output reg  [15:0] tb_id;
    output reg  pair_valid;
    output reg  [31:0] pair_tag;
    output reg  [737:0] a_word;
    output reg  [737:0] b_word;
    output reg  busy;
    
    // Stub signals
    reg  cache$clock;
    reg  cache$clear;
    reg  [6:0] cache$mask;
    reg  cache$fill;
    reg  [15:0] cache$fill_id;
    reg  [737:0] cache$fill_word;
    reg  [15:0] cache$id;
    reg  [15:0] cache$next_id;
    wire  cache$hit;
    wire  [737:0] cache$word;
    reg  leaf_v$d;
    wire  leaf_v$q;
    reg  leaf_v$clock;
    reg  [31:0] leaf_id$d;
    wire  [31:0] leaf_id$q;
    reg  leaf_id$clock;
    reg  [31:0] leaf_t$d;
    wire  [31:0] leaf_t$q;
    reg  leaf_t$clock;
    reg  side$d;
    wire  side$q;
    reg  side$clock;
    reg  b_ok0$d;
    wire  b_ok0$q;
    reg  b_ok0$clock;
    reg  b_ok1$d;
    wire  b_ok1$q;
    reg  b_ok1$clock;
    reg  [15:0] b_id0$d;
    wire  [15:0] b_id0$q;
    reg  b_id0$clock;
    reg  [15:0] b_id1$d;
    wire  [15:0] b_id1$q;
    reg  b_id1$clock;
    reg  [737:0] b_word0$d;
    wire  [737:0] b_word0$q;
    reg  b_word0$clock;
    reg  [737:0] b_word1$d;
    wire  [737:0] b_word1$q;
    reg  b_word1$clock;
    reg  pair_v$d;
    wire  pair_v$q;
    reg  pair_v$clock;
    reg  [31:0] pair_t$d;
    wire  [31:0] pair_t$q;
    reg  pair_t$clock;
    reg  [737:0] pair_a$d;
    wire  [737:0] pair_a$q;
    reg  pair_a$clock;
    reg  [737:0] pair_b$d;
    wire  [737:0] pair_b$q;
    reg  pair_b$clock;
    
    // Local signals
    reg  live;
    reg  hit_b0;
    reg  hit_b1;
    reg  go;
    reg  load;
    
    // Sub module instances
    top$core$tin$cache cache(
        .clock(cache$clock),
        .clear(cache$clear),
        .mask(cache$mask),
        .fill(cache$fill),
        .fill_id(cache$fill_id),
        .fill_word(cache$fill_word),
        .id(cache$id),
        .next_id(cache$next_id),
        .hit(cache$hit),
        .word(cache$word)
    );
    top$core$done_r leaf_v(
        .d(leaf_v$d),
        .q(leaf_v$q),
        .clock(leaf_v$clock)
    );
    top$core$cnt_nf leaf_id(
        .d(leaf_id$d),
        .q(leaf_id$q),
        .clock(leaf_id$clock)
    );
    top$core$cnt_nf leaf_t(
        .d(leaf_t$d),
        .q(leaf_t$q),
        .clock(leaf_t$clock)
    );
    top$core$done_r side(
        .d(side$d),
        .q(side$q),
        .clock(side$clock)
    );
    top$core$done_r b_ok0(
        .d(b_ok0$d),
        .q(b_ok0$q),
        .clock(b_ok0$clock)
    );
    top$core$done_r b_ok1(
        .d(b_ok1$d),
        .q(b_ok1$q),
        .clock(b_ok1$clock)
    );
    top$core$lists$len_l$0 b_id0(
        .d(b_id0$d),
        .q(b_id0$q),
        .clock(b_id0$clock)
    );
    top$core$lists$len_l$0 b_id1(
        .d(b_id1$d),
        .q(b_id1$q),
        .clock(b_id1$clock)
    );
    top$core$tin$b_word0 b_word0(
        .d(b_word0$d),
        .q(b_word0$q),
        .clock(b_word0$clock)
    );
    top$core$tin$b_word0 b_word1(
        .d(b_word1$d),
        .q(b_word1$q),
        .clock(b_word1$clock)
    );
    top$core$done_r pair_v(
        .d(pair_v$d),
        .q(pair_v$q),
        .clock(pair_v$clock)
    );
    top$core$cnt_nf pair_t(
        .d(pair_t$d),
        .q(pair_t$q),
        .clock(pair_t$clock)
    );
    top$core$tin$b_word0 pair_a(
        .d(pair_a$d),
        .q(pair_a$q),
        .clock(pair_a$clock)
    );
    top$core$tin$b_word0 pair_b(
        .d(pair_b$d),
        .q(pair_b$q),
        .clock(pair_b$clock)
    );
    
    // Update code
    always @(*) begin
        leaf_v$clock = clock;
        leaf_id$clock = clock;
        leaf_t$clock = clock;
        side$clock = clock;
        b_ok0$clock = clock;
        b_ok1$clock = clock;
        b_id0$clock = clock;
        b_id1$clock = clock;
        leaf_v$d = leaf_v$q;
        leaf_id$d = leaf_id$q;
        leaf_t$d = leaf_t$q;
        side$d = side$q;
        b_ok0$d = b_ok0$q;
        b_ok1$d = b_ok1$q;
        b_id0$d = b_id0$q;
        b_id1$d = b_id1$q;
        b_word0$clock = clock;
        b_word1$clock = clock;
        pair_v$clock = clock;
        pair_t$clock = clock;
        pair_a$clock = clock;
        pair_b$clock = clock;
        b_word0$d = b_word0$q;
        b_word1$d = b_word1$q;
        pair_v$d = pair_v$q;
        pair_t$d = pair_t$q;
        pair_a$d = pair_a$q;
        pair_b$d = pair_b$q;
        cache$clock = clock;
        live = leaf_v$q & ~halt;
        cache$clear = clear;
        cache$mask = mask;
        cache$id = leaf_id$q[(32'h0)+:(16)];
        hit_b0 = b_ok0$q & (b_id0$q == leaf_id$q[(32'h10)+:(16)]);
        hit_b1 = b_ok1$q & (b_id1$q == leaf_id$q[(32'h10)+:(16)]);
        need_a = live & ~cache$hit;
        need_b = live & ~(hit_b0 | hit_b1);
        go = live & cache$hit & (hit_b0 | hit_b1) & (~pair_v$q | tri_ready);
        leaf_ready = ~halt & (~leaf_v$q | go);
        load = leaf_in & leaf_ready;
        if (load) begin
            cache$next_id = leaf_ids[(32'h0)+:(16)];
        end
        else begin
            cache$next_id = leaf_id$q[(32'h0)+:(16)];
        end
        cache$fill = fill_a;
        cache$fill_id = fill_id;
        cache$fill_word = fill_word;
        if (fill_b & ~side$q) begin
            b_ok0$d = 1'b1;
            b_id0$d = fill_id;
            b_word0$d = fill_word;
        end
        if (fill_b & side$q) begin
            b_ok1$d = 1'b1;
            b_id1$d = fill_id;
            b_word1$d = fill_word;
        end
        if (pair_v$q & tri_ready) begin
            pair_v$d = 1'b0;
        end
        if (go) begin
            leaf_v$d = 1'b0;
            pair_v$d = 1'b1;
            pair_t$d = leaf_t$q;
            pair_a$d = cache$word;
            pair_b$d = b_word1$q;
            if (hit_b0) begin
                pair_b$d = b_word0$q;
            end
        end
        if (load) begin
            leaf_v$d = 1'b1;
            leaf_id$d = leaf_ids;
            leaf_t$d = leaf_tag;
            side$d = leaf_side;
        end
        if (halt | clear) begin
            leaf_v$d = 1'b0;
            pair_v$d = 1'b0;
        end
        if (clear) begin
            b_ok0$d = 1'b0;
            b_ok1$d = 1'b0;
        end
        ta_id = leaf_id$q[(32'h0)+:(16)];
        tb_id = leaf_id$q[(32'h10)+:(16)];
        pair_valid = pair_v$q & ~halt;
        pair_tag = pair_t$q;
        a_word = pair_a$q;
        b_word = pair_b$q;
        busy = leaf_v$q | pair_v$q;
    end
    
endmodule // top$core$tin


module top$core$tin$b_word0(d,q,clock);
    
    // Module arguments
    input wire  [737:0] d;
    output reg  [737:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 738'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$core$tin$b_word0


module top$core$tin$cache(clock,clear,mask,fill,fill_id,fill_word,id,next_id,hit,word);
    
    // Module arguments
    input wire  clock;
    input wire  clear;
    input wire  [6:0] mask;
    input wire  fill;
    input wire  [15:0] fill_id;
    input wire  [737:0] fill_word;
    input wire  [15:0] id;
    input wire  [15:0] next_id;
    output reg  hit;
    output reg  [737:0] word;
    
    // Constant declarations
    localparam  c_one128 = 128'h1;
    
    // Stub signals
    reg  [127:0] valid$d;
    wire  [127:0] valid$q;
    reg  valid$clock;
    reg  [6:0] ids$read_address;
    reg  ids$read_clock;
    wire  [15:0] ids$read_data;
    reg  [6:0] ids$write_address;
    reg  ids$write_clock;
    reg  [15:0] ids$write_data;
    reg  ids$write_enable;
    reg  [6:0] words$read_address;
    reg  words$read_clock;
    wire  [737:0] words$read_data;
    reg  [6:0] words$write_address;
    reg  words$write_clock;
    reg  [737:0] words$write_data;
    reg  words$write_enable;
    reg  byp$d;
    wire  byp$q;
    reg  byp$clock;
    reg  [15:0] last_id$d;
    wire  [15:0] last_id$q;
    reg  last_id$clock;
    reg  [737:0] last_word$d;
    wire  [737:0] last_word$q;
    reg  last_word$clock;
    
    // Local signals
    reg  [6:0] line;
    reg  [6:0] fill_line;
    reg  [6:0] next_line;
    reg  [15:0] held_id;
    
    // Sub module instances
    top$core$tin$cache$valid valid(
        .d(valid$d),
        .q(valid$q),
        .clock(valid$clock)
    );
    top$core$tin$cache$ids ids(
        .read_address(ids$read_address),
        .read_clock(ids$read_clock),
        .read_data(ids$read_data),
        .write_address(ids$write_address),
        .write_clock(ids$write_clock),
        .write_data(ids$write_data),
        .write_enable(ids$write_enable)
    );
    top$core$tin$cache$words words(
        .read_address(words$read_address),
        .read_clock(words$read_clock),
        .read_data(words$read_data),
        .write_address(words$write_address),
        .write_clock(words$write_clock),
        .write_data(words$write_data),
        .write_enable(words$write_enable)
    );
    top$core$done_r byp(
        .d(byp$d),
        .q(byp$q),
        .clock(byp$clock)
    );
    top$core$lists$len_l$0 last_id(
        .d(last_id$d),
        .q(last_id$q),
        .clock(last_id$clock)
    );
    top$core$tin$b_word0 last_word(
        .d(last_word$d),
        .q(last_word$q),
        .clock(last_word$clock)
    );
    
    // Update code
    always @(*) begin
        valid$clock = clock;
        byp$clock = clock;
        last_id$clock = clock;
        last_word$clock = clock;
        valid$d = valid$q;
        byp$d = byp$q;
        last_id$d = last_id$q;
        last_word$d = last_word$q;
        ids$read_clock = clock;
        ids$write_clock = clock;
        words$read_clock = clock;
        words$write_clock = clock;
        line = id[(32'h0)+:(7)] & mask;
        fill_line = fill_id[(32'h0)+:(7)] & mask;
        next_line = next_id[(32'h0)+:(7)] & mask;
        held_id = ids$read_data;
        word = words$read_data;
        if (byp$q) begin
            held_id = last_id$q;
            word = last_word$q;
        end
        hit = ((valid$q & (c_one128 << line)) != 32'h0) & (held_id == id);
        ids$write_enable = fill;
        ids$write_address = fill_line;
        ids$write_data = fill_id;
        words$write_enable = fill;
        words$write_address = fill_line;
        words$write_data = fill_word;
        ids$read_address = next_line;
        words$read_address = next_line;
        byp$d = fill & (fill_line == next_line);
        if (fill) begin
            valid$d = valid$q | (c_one128 << fill_line);
            last_id$d = fill_id;
            last_word$d = fill_word;
        end
        if (clear) begin
            valid$d = 32'h0;
        end
    end
    
endmodule // top$core$tin$cache


module top$core$tin$cache$ids(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [6:0] read_address;
    input wire  read_clock;
    output reg  [15:0] read_data;
    input wire  [6:0] write_address;
    input wire  write_clock;
    input wire  [15:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    reg[15:0] mem[127:0];
    
    
    
    always @(posedge read_clock) begin
       read_data <= mem[read_address];
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address] <= write_data;
       end
    end
                
endmodule // top$core$tin$cache$ids


module top$core$tin$cache$valid(d,q,clock);
    
    // Module arguments
    input wire  [127:0] d;
    output reg  [127:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 128'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$core$tin$cache$valid


module top$core$tin$cache$words(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [6:0] read_address;
    input wire  read_clock;
    output reg  [737:0] read_data;
    input wire  [6:0] write_address;
    input wire  write_clock;
    input wire  [737:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    reg[737:0] mem[127:0];
    
    
    
    always @(posedge read_clock) begin
       read_data <= mem[read_address];
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address] <= write_data;
       end
    end
                
endmodule // top$core$tin$cache$words


module top$result(clock,take,out_valid,out_hit,out_uncertain,out_tag,res_ready,out_ready,res_valid,res_tag,res_uncertain,give,sure_hit,open);
    
    // Module arguments
    input wire  clock;
    input wire  take;
    input wire  out_valid;
    input wire  out_hit;
    input wire  out_uncertain;
    input wire  [31:0] out_tag;
    input wire  res_ready;
    output reg  out_ready;
    output reg  res_valid;
    output reg  [31:0] res_tag;
    output reg  res_uncertain;
    output reg  give;
    output reg  sure_hit;
    output reg  [8:0] open;
    
    // Stub signals
    reg  [8:0] open_r$d;
    wire  [8:0] open_r$q;
    reg  open_r$clock;
    
    // Local signals
    reg  keep;
    
    // Sub module instances
    top$result$open_r open_r(
        .d(open_r$d),
        .q(open_r$q),
        .clock(open_r$clock)
    );
    
    // Update code
    always @(*) begin
        open_r$clock = clock;
        open_r$d = open_r$q;
        keep = out_hit | out_uncertain;
        res_valid = out_valid & keep;
        res_tag = out_tag;
        res_uncertain = out_uncertain;
        out_ready = res_ready | ~keep;
        give = out_valid & (res_ready | ~keep);
        if (take & ~give) begin
            open_r$d = open_r$q + 32'h1;
        end
        if (give & ~take) begin
            open_r$d = open_r$q - 32'h1;
        end
        sure_hit = out_valid & out_hit & ~out_uncertain;
        open = open_r$q;
    end
    
endmodule // top$result


module top$result$open_r(d,q,clock);
    
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
          
endmodule // top$result$open_r


module top$tri_unit(clock,load_en,load_addr,load_data,a_m_0$0,a_m_0$1,a_m_0$2,a_m_0$3,a_m_1$0,a_m_1$1,a_m_1$2,a_m_1$3,a_m_2$0,a_m_2$1,a_m_2$2,a_m_2$3,a_alpha_m,a_alpha_f,a_v_x$0,a_v_x$1,a_v_x$2,a_v_y$0,a_v_y$1,a_v_y$2,a_v_z$0,a_v_z$1,a_v_z$2,a_v_exact,a_degenerate,b_m_0$0,b_m_0$1,b_m_0$2,b_m_0$3,b_m_1$0,b_m_1$1,b_m_1$2,b_m_1$3,b_m_2$0,b_m_2$1,b_m_2$2,b_m_2$3,b_alpha_m,b_alpha_f,b_v_x$0,b_v_x$1,b_v_x$2,b_v_y$0,b_v_y$1,b_v_y$2,b_v_z$0,b_v_z$1,b_v_z$2,b_v_exact,b_degenerate,tag,in_valid,in_ready,out_tag,out_hit,out_uncertain,out_valid,out_ready);
    
    // Module arguments
    input wire  clock;
    input wire  load_en;
    input wire  [4:0] load_addr;
    input wire  [31:0] load_data;
    input wire  [31:0] a_m_0$0;
    input wire  [31:0] a_m_0$1;
    input wire  [31:0] a_m_0$2;
    input wire  [31:0] a_m_0$3;
    input wire  [31:0] a_m_1$0;
    input wire  [31:0] a_m_1$1;
    input wire  [31:0] a_m_1$2;
    input wire  [31:0] a_m_1$3;
    input wire  [31:0] a_m_2$0;
    input wire  [31:0] a_m_2$1;
    input wire  [31:0] a_m_2$2;
    input wire  [31:0] a_m_2$3;
    input wire  [31:0] a_alpha_m;
    input wire  [31:0] a_alpha_f;
    input wire  [31:0] a_v_x$0;
    input wire  [31:0] a_v_x$1;
    input wire  [31:0] a_v_x$2;
    input wire  [31:0] a_v_y$0;
    input wire  [31:0] a_v_y$1;
    input wire  [31:0] a_v_y$2;
    input wire  [31:0] a_v_z$0;
    input wire  [31:0] a_v_z$1;
    input wire  [31:0] a_v_z$2;
    input wire  a_v_exact;
    input wire  a_degenerate;
    input wire  [31:0] b_m_0$0;
    input wire  [31:0] b_m_0$1;
    input wire  [31:0] b_m_0$2;
    input wire  [31:0] b_m_0$3;
    input wire  [31:0] b_m_1$0;
    input wire  [31:0] b_m_1$1;
    input wire  [31:0] b_m_1$2;
    input wire  [31:0] b_m_1$3;
    input wire  [31:0] b_m_2$0;
    input wire  [31:0] b_m_2$1;
    input wire  [31:0] b_m_2$2;
    input wire  [31:0] b_m_2$3;
    input wire  [31:0] b_alpha_m;
    input wire  [31:0] b_alpha_f;
    input wire  [31:0] b_v_x$0;
    input wire  [31:0] b_v_x$1;
    input wire  [31:0] b_v_x$2;
    input wire  [31:0] b_v_y$0;
    input wire  [31:0] b_v_y$1;
    input wire  [31:0] b_v_y$2;
    input wire  [31:0] b_v_z$0;
    input wire  [31:0] b_v_z$1;
    input wire  [31:0] b_v_z$2;
    input wire  b_v_exact;
    input wire  b_degenerate;
    input wire  [31:0] tag;
    input wire  in_valid;
    output reg  in_ready;
    output reg  [31:0] out_tag;
    output reg  out_hit;
    output reg  out_uncertain;
    output reg  out_valid;
    input wire  out_ready;
    
    // Constant declarations
    localparam  addr_0$0 = 5'b0;
    localparam  addr_0$1 = 5'b1;
    localparam  addr_0$2 = 5'b10;
    localparam  addr_0$3 = 5'b11;
    localparam  addr_1$0 = 5'b100;
    localparam  addr_1$1 = 5'b101;
    localparam  addr_1$2 = 5'b110;
    localparam  addr_1$3 = 5'b111;
    localparam  addr_2$0 = 5'b1000;
    localparam  addr_2$1 = 5'b1001;
    localparam  addr_2$2 = 5'b1010;
    localparam  addr_2$3 = 5'b1011;
    localparam  c_hit = 34'h2;
    localparam  c_uncertain = 34'h1;
    localparam  c_full = 9'b100000000;
    
    // Stub signals
    reg  [31:0] ab_0$0$d;
    wire  [31:0] ab_0$0$q;
    reg  ab_0$0$clock;
    reg  [31:0] ab_0$1$d;
    wire  [31:0] ab_0$1$q;
    reg  ab_0$1$clock;
    reg  [31:0] ab_0$2$d;
    wire  [31:0] ab_0$2$q;
    reg  ab_0$2$clock;
    reg  [31:0] ab_0$3$d;
    wire  [31:0] ab_0$3$q;
    reg  ab_0$3$clock;
    reg  [31:0] ab_1$0$d;
    wire  [31:0] ab_1$0$q;
    reg  ab_1$0$clock;
    reg  [31:0] ab_1$1$d;
    wire  [31:0] ab_1$1$q;
    reg  ab_1$1$clock;
    reg  [31:0] ab_1$2$d;
    wire  [31:0] ab_1$2$q;
    reg  ab_1$2$clock;
    reg  [31:0] ab_1$3$d;
    wire  [31:0] ab_1$3$q;
    reg  ab_1$3$clock;
    reg  [31:0] ab_2$0$d;
    wire  [31:0] ab_2$0$q;
    reg  ab_2$0$clock;
    reg  [31:0] ab_2$1$d;
    wire  [31:0] ab_2$1$q;
    reg  ab_2$1$clock;
    reg  [31:0] ab_2$2$d;
    wire  [31:0] ab_2$2$q;
    reg  ab_2$2$clock;
    reg  [31:0] ab_2$3$d;
    wire  [31:0] ab_2$3$q;
    reg  ab_2$3$clock;
    reg  [31:0] ab_bm$d;
    wire  [31:0] ab_bm$q;
    reg  ab_bm$clock;
    reg  [31:0] ab_bf$d;
    wire  [31:0] ab_bf$q;
    reg  ab_bf$clock;
    reg  [31:0] ab_s$d;
    wire  [31:0] ab_s$q;
    reg  ab_s$clock;
    reg  [31:0] ba_0$0$d;
    wire  [31:0] ba_0$0$q;
    reg  ba_0$0$clock;
    reg  [31:0] ba_0$1$d;
    wire  [31:0] ba_0$1$q;
    reg  ba_0$1$clock;
    reg  [31:0] ba_0$2$d;
    wire  [31:0] ba_0$2$q;
    reg  ba_0$2$clock;
    reg  [31:0] ba_0$3$d;
    wire  [31:0] ba_0$3$q;
    reg  ba_0$3$clock;
    reg  [31:0] ba_1$0$d;
    wire  [31:0] ba_1$0$q;
    reg  ba_1$0$clock;
    reg  [31:0] ba_1$1$d;
    wire  [31:0] ba_1$1$q;
    reg  ba_1$1$clock;
    reg  [31:0] ba_1$2$d;
    wire  [31:0] ba_1$2$q;
    reg  ba_1$2$clock;
    reg  [31:0] ba_1$3$d;
    wire  [31:0] ba_1$3$q;
    reg  ba_1$3$clock;
    reg  [31:0] ba_2$0$d;
    wire  [31:0] ba_2$0$q;
    reg  ba_2$0$clock;
    reg  [31:0] ba_2$1$d;
    wire  [31:0] ba_2$1$q;
    reg  ba_2$1$clock;
    reg  [31:0] ba_2$2$d;
    wire  [31:0] ba_2$2$q;
    reg  ba_2$2$clock;
    reg  [31:0] ba_2$3$d;
    wire  [31:0] ba_2$3$q;
    reg  ba_2$3$clock;
    reg  [31:0] ba_bm$d;
    wire  [31:0] ba_bm$q;
    reg  ba_bm$clock;
    reg  [31:0] ba_bf$d;
    wire  [31:0] ba_bf$q;
    reg  ba_bf$clock;
    reg  [31:0] ba_s$d;
    wire  [31:0] ba_s$q;
    reg  ba_s$clock;
    reg  tc_ab$clock;
    reg  [31:0] tc_ab$m_0$0;
    reg  [31:0] tc_ab$m_0$1;
    reg  [31:0] tc_ab$m_0$2;
    reg  [31:0] tc_ab$m_0$3;
    reg  [31:0] tc_ab$m_1$0;
    reg  [31:0] tc_ab$m_1$1;
    reg  [31:0] tc_ab$m_1$2;
    reg  [31:0] tc_ab$m_1$3;
    reg  [31:0] tc_ab$m_2$0;
    reg  [31:0] tc_ab$m_2$1;
    reg  [31:0] tc_ab$m_2$2;
    reg  [31:0] tc_ab$m_2$3;
    reg  [31:0] tc_ab$alpha_m;
    reg  [31:0] tc_ab$alpha_f;
    reg  [31:0] tc_ab$f_0$0;
    reg  [31:0] tc_ab$f_0$1;
    reg  [31:0] tc_ab$f_0$2;
    reg  [31:0] tc_ab$f_0$3;
    reg  [31:0] tc_ab$f_1$0;
    reg  [31:0] tc_ab$f_1$1;
    reg  [31:0] tc_ab$f_1$2;
    reg  [31:0] tc_ab$f_1$3;
    reg  [31:0] tc_ab$f_2$0;
    reg  [31:0] tc_ab$f_2$1;
    reg  [31:0] tc_ab$f_2$2;
    reg  [31:0] tc_ab$f_2$3;
    reg  [31:0] tc_ab$beta_m;
    reg  [31:0] tc_ab$beta_f;
    reg  [31:0] tc_ab$scale;
    reg  [31:0] tc_ab$v_x$0;
    reg  [31:0] tc_ab$v_x$1;
    reg  [31:0] tc_ab$v_x$2;
    reg  [31:0] tc_ab$v_y$0;
    reg  [31:0] tc_ab$v_y$1;
    reg  [31:0] tc_ab$v_y$2;
    reg  [31:0] tc_ab$v_z$0;
    reg  [31:0] tc_ab$v_z$1;
    reg  [31:0] tc_ab$v_z$2;
    reg  tc_ab$v_exact;
    reg  [31:0] tc_ab$tag;
    reg  tc_ab$valid_in;
    wire  [31:0] tc_ab$s_x$0;
    wire  [31:0] tc_ab$s_x$1;
    wire  [31:0] tc_ab$s_x$2;
    wire  [31:0] tc_ab$s_b$0;
    wire  [31:0] tc_ab$s_b$1;
    wire  [31:0] tc_ab$s_b$2;
    wire  tc_ab$cross_t$0;
    wire  tc_ab$cross_t$1;
    wire  tc_ab$cross_t$2;
    wire  tc_ab$cross_f$0;
    wire  tc_ab$cross_f$1;
    wire  tc_ab$cross_f$2;
    wire  tc_ab$hit;
    wire  tc_ab$miss;
    wire  [31:0] tc_ab$tag_out;
    wire  tc_ab$valid_out;
    reg  tc_ba$clock;
    reg  [31:0] tc_ba$m_0$0;
    reg  [31:0] tc_ba$m_0$1;
    reg  [31:0] tc_ba$m_0$2;
    reg  [31:0] tc_ba$m_0$3;
    reg  [31:0] tc_ba$m_1$0;
    reg  [31:0] tc_ba$m_1$1;
    reg  [31:0] tc_ba$m_1$2;
    reg  [31:0] tc_ba$m_1$3;
    reg  [31:0] tc_ba$m_2$0;
    reg  [31:0] tc_ba$m_2$1;
    reg  [31:0] tc_ba$m_2$2;
    reg  [31:0] tc_ba$m_2$3;
    reg  [31:0] tc_ba$alpha_m;
    reg  [31:0] tc_ba$alpha_f;
    reg  [31:0] tc_ba$f_0$0;
    reg  [31:0] tc_ba$f_0$1;
    reg  [31:0] tc_ba$f_0$2;
    reg  [31:0] tc_ba$f_0$3;
    reg  [31:0] tc_ba$f_1$0;
    reg  [31:0] tc_ba$f_1$1;
    reg  [31:0] tc_ba$f_1$2;
    reg  [31:0] tc_ba$f_1$3;
    reg  [31:0] tc_ba$f_2$0;
    reg  [31:0] tc_ba$f_2$1;
    reg  [31:0] tc_ba$f_2$2;
    reg  [31:0] tc_ba$f_2$3;
    reg  [31:0] tc_ba$beta_m;
    reg  [31:0] tc_ba$beta_f;
    reg  [31:0] tc_ba$scale;
    reg  [31:0] tc_ba$v_x$0;
    reg  [31:0] tc_ba$v_x$1;
    reg  [31:0] tc_ba$v_x$2;
    reg  [31:0] tc_ba$v_y$0;
    reg  [31:0] tc_ba$v_y$1;
    reg  [31:0] tc_ba$v_y$2;
    reg  [31:0] tc_ba$v_z$0;
    reg  [31:0] tc_ba$v_z$1;
    reg  [31:0] tc_ba$v_z$2;
    reg  tc_ba$v_exact;
    reg  [31:0] tc_ba$tag;
    reg  tc_ba$valid_in;
    wire  [31:0] tc_ba$s_x$0;
    wire  [31:0] tc_ba$s_x$1;
    wire  [31:0] tc_ba$s_x$2;
    wire  [31:0] tc_ba$s_b$0;
    wire  [31:0] tc_ba$s_b$1;
    wire  [31:0] tc_ba$s_b$2;
    wire  tc_ba$cross_t$0;
    wire  tc_ba$cross_t$1;
    wire  tc_ba$cross_t$2;
    wire  tc_ba$cross_f$0;
    wire  tc_ba$cross_f$1;
    wire  tc_ba$cross_f$2;
    wire  tc_ba$hit;
    wire  tc_ba$miss;
    wire  [31:0] tc_ba$tag_out;
    wire  tc_ba$valid_out;
    reg  degenerate_wait$clock;
    reg  [1:0] degenerate_wait$d;
    wire  [1:0] degenerate_wait$q;
    reg  fifo$clock;
    reg  fifo$read;
    wire  [33:0] fifo$data_out;
    wire  fifo$empty;
    wire  fifo$almost_empty;
    wire  fifo$underflow;
    reg  fifo$write;
    reg  [33:0] fifo$data_in;
    wire  fifo$full;
    wire  fifo$almost_full;
    wire  fifo$overflow;
    reg  [8:0] count$d;
    wire  [8:0] count$q;
    reg  count$clock;
    
    // Local signals
    reg  d1_t;
    reg  d1_f;
    reg  d2_t;
    reg  d2_f;
    reg  [33:0] result;
    reg  take;
    reg  give;
    
    // Sub module instances
    top$core$cnt_nf ab_0$0(
        .d(ab_0$0$d),
        .q(ab_0$0$q),
        .clock(ab_0$0$clock)
    );
    top$core$cnt_nf ab_0$1(
        .d(ab_0$1$d),
        .q(ab_0$1$q),
        .clock(ab_0$1$clock)
    );
    top$core$cnt_nf ab_0$2(
        .d(ab_0$2$d),
        .q(ab_0$2$q),
        .clock(ab_0$2$clock)
    );
    top$core$cnt_nf ab_0$3(
        .d(ab_0$3$d),
        .q(ab_0$3$q),
        .clock(ab_0$3$clock)
    );
    top$core$cnt_nf ab_1$0(
        .d(ab_1$0$d),
        .q(ab_1$0$q),
        .clock(ab_1$0$clock)
    );
    top$core$cnt_nf ab_1$1(
        .d(ab_1$1$d),
        .q(ab_1$1$q),
        .clock(ab_1$1$clock)
    );
    top$core$cnt_nf ab_1$2(
        .d(ab_1$2$d),
        .q(ab_1$2$q),
        .clock(ab_1$2$clock)
    );
    top$core$cnt_nf ab_1$3(
        .d(ab_1$3$d),
        .q(ab_1$3$q),
        .clock(ab_1$3$clock)
    );
    top$core$cnt_nf ab_2$0(
        .d(ab_2$0$d),
        .q(ab_2$0$q),
        .clock(ab_2$0$clock)
    );
    top$core$cnt_nf ab_2$1(
        .d(ab_2$1$d),
        .q(ab_2$1$q),
        .clock(ab_2$1$clock)
    );
    top$core$cnt_nf ab_2$2(
        .d(ab_2$2$d),
        .q(ab_2$2$q),
        .clock(ab_2$2$clock)
    );
    top$core$cnt_nf ab_2$3(
        .d(ab_2$3$d),
        .q(ab_2$3$q),
        .clock(ab_2$3$clock)
    );
    top$core$cnt_nf ab_bm(
        .d(ab_bm$d),
        .q(ab_bm$q),
        .clock(ab_bm$clock)
    );
    top$core$cnt_nf ab_bf(
        .d(ab_bf$d),
        .q(ab_bf$q),
        .clock(ab_bf$clock)
    );
    top$core$cnt_nf ab_s(
        .d(ab_s$d),
        .q(ab_s$q),
        .clock(ab_s$clock)
    );
    top$core$cnt_nf ba_0$0(
        .d(ba_0$0$d),
        .q(ba_0$0$q),
        .clock(ba_0$0$clock)
    );
    top$core$cnt_nf ba_0$1(
        .d(ba_0$1$d),
        .q(ba_0$1$q),
        .clock(ba_0$1$clock)
    );
    top$core$cnt_nf ba_0$2(
        .d(ba_0$2$d),
        .q(ba_0$2$q),
        .clock(ba_0$2$clock)
    );
    top$core$cnt_nf ba_0$3(
        .d(ba_0$3$d),
        .q(ba_0$3$q),
        .clock(ba_0$3$clock)
    );
    top$core$cnt_nf ba_1$0(
        .d(ba_1$0$d),
        .q(ba_1$0$q),
        .clock(ba_1$0$clock)
    );
    top$core$cnt_nf ba_1$1(
        .d(ba_1$1$d),
        .q(ba_1$1$q),
        .clock(ba_1$1$clock)
    );
    top$core$cnt_nf ba_1$2(
        .d(ba_1$2$d),
        .q(ba_1$2$q),
        .clock(ba_1$2$clock)
    );
    top$core$cnt_nf ba_1$3(
        .d(ba_1$3$d),
        .q(ba_1$3$q),
        .clock(ba_1$3$clock)
    );
    top$core$cnt_nf ba_2$0(
        .d(ba_2$0$d),
        .q(ba_2$0$q),
        .clock(ba_2$0$clock)
    );
    top$core$cnt_nf ba_2$1(
        .d(ba_2$1$d),
        .q(ba_2$1$q),
        .clock(ba_2$1$clock)
    );
    top$core$cnt_nf ba_2$2(
        .d(ba_2$2$d),
        .q(ba_2$2$q),
        .clock(ba_2$2$clock)
    );
    top$core$cnt_nf ba_2$3(
        .d(ba_2$3$d),
        .q(ba_2$3$q),
        .clock(ba_2$3$clock)
    );
    top$core$cnt_nf ba_bm(
        .d(ba_bm$d),
        .q(ba_bm$q),
        .clock(ba_bm$clock)
    );
    top$core$cnt_nf ba_bf(
        .d(ba_bf$d),
        .q(ba_bf$q),
        .clock(ba_bf$clock)
    );
    top$core$cnt_nf ba_s(
        .d(ba_s$d),
        .q(ba_s$q),
        .clock(ba_s$clock)
    );
    top$tri_unit$tc_ab tc_ab(
        .clock(tc_ab$clock),
        .m_0$0(tc_ab$m_0$0),
        .m_0$1(tc_ab$m_0$1),
        .m_0$2(tc_ab$m_0$2),
        .m_0$3(tc_ab$m_0$3),
        .m_1$0(tc_ab$m_1$0),
        .m_1$1(tc_ab$m_1$1),
        .m_1$2(tc_ab$m_1$2),
        .m_1$3(tc_ab$m_1$3),
        .m_2$0(tc_ab$m_2$0),
        .m_2$1(tc_ab$m_2$1),
        .m_2$2(tc_ab$m_2$2),
        .m_2$3(tc_ab$m_2$3),
        .alpha_m(tc_ab$alpha_m),
        .alpha_f(tc_ab$alpha_f),
        .f_0$0(tc_ab$f_0$0),
        .f_0$1(tc_ab$f_0$1),
        .f_0$2(tc_ab$f_0$2),
        .f_0$3(tc_ab$f_0$3),
        .f_1$0(tc_ab$f_1$0),
        .f_1$1(tc_ab$f_1$1),
        .f_1$2(tc_ab$f_1$2),
        .f_1$3(tc_ab$f_1$3),
        .f_2$0(tc_ab$f_2$0),
        .f_2$1(tc_ab$f_2$1),
        .f_2$2(tc_ab$f_2$2),
        .f_2$3(tc_ab$f_2$3),
        .beta_m(tc_ab$beta_m),
        .beta_f(tc_ab$beta_f),
        .scale(tc_ab$scale),
        .v_x$0(tc_ab$v_x$0),
        .v_x$1(tc_ab$v_x$1),
        .v_x$2(tc_ab$v_x$2),
        .v_y$0(tc_ab$v_y$0),
        .v_y$1(tc_ab$v_y$1),
        .v_y$2(tc_ab$v_y$2),
        .v_z$0(tc_ab$v_z$0),
        .v_z$1(tc_ab$v_z$1),
        .v_z$2(tc_ab$v_z$2),
        .v_exact(tc_ab$v_exact),
        .tag(tc_ab$tag),
        .valid_in(tc_ab$valid_in),
        .s_x$0(tc_ab$s_x$0),
        .s_x$1(tc_ab$s_x$1),
        .s_x$2(tc_ab$s_x$2),
        .s_b$0(tc_ab$s_b$0),
        .s_b$1(tc_ab$s_b$1),
        .s_b$2(tc_ab$s_b$2),
        .cross_t$0(tc_ab$cross_t$0),
        .cross_t$1(tc_ab$cross_t$1),
        .cross_t$2(tc_ab$cross_t$2),
        .cross_f$0(tc_ab$cross_f$0),
        .cross_f$1(tc_ab$cross_f$1),
        .cross_f$2(tc_ab$cross_f$2),
        .hit(tc_ab$hit),
        .miss(tc_ab$miss),
        .tag_out(tc_ab$tag_out),
        .valid_out(tc_ab$valid_out)
    );
    top$tri_unit$tc_ab tc_ba(
        .clock(tc_ba$clock),
        .m_0$0(tc_ba$m_0$0),
        .m_0$1(tc_ba$m_0$1),
        .m_0$2(tc_ba$m_0$2),
        .m_0$3(tc_ba$m_0$3),
        .m_1$0(tc_ba$m_1$0),
        .m_1$1(tc_ba$m_1$1),
        .m_1$2(tc_ba$m_1$2),
        .m_1$3(tc_ba$m_1$3),
        .m_2$0(tc_ba$m_2$0),
        .m_2$1(tc_ba$m_2$1),
        .m_2$2(tc_ba$m_2$2),
        .m_2$3(tc_ba$m_2$3),
        .alpha_m(tc_ba$alpha_m),
        .alpha_f(tc_ba$alpha_f),
        .f_0$0(tc_ba$f_0$0),
        .f_0$1(tc_ba$f_0$1),
        .f_0$2(tc_ba$f_0$2),
        .f_0$3(tc_ba$f_0$3),
        .f_1$0(tc_ba$f_1$0),
        .f_1$1(tc_ba$f_1$1),
        .f_1$2(tc_ba$f_1$2),
        .f_1$3(tc_ba$f_1$3),
        .f_2$0(tc_ba$f_2$0),
        .f_2$1(tc_ba$f_2$1),
        .f_2$2(tc_ba$f_2$2),
        .f_2$3(tc_ba$f_2$3),
        .beta_m(tc_ba$beta_m),
        .beta_f(tc_ba$beta_f),
        .scale(tc_ba$scale),
        .v_x$0(tc_ba$v_x$0),
        .v_x$1(tc_ba$v_x$1),
        .v_x$2(tc_ba$v_x$2),
        .v_y$0(tc_ba$v_y$0),
        .v_y$1(tc_ba$v_y$1),
        .v_y$2(tc_ba$v_y$2),
        .v_z$0(tc_ba$v_z$0),
        .v_z$1(tc_ba$v_z$1),
        .v_z$2(tc_ba$v_z$2),
        .v_exact(tc_ba$v_exact),
        .tag(tc_ba$tag),
        .valid_in(tc_ba$valid_in),
        .s_x$0(tc_ba$s_x$0),
        .s_x$1(tc_ba$s_x$1),
        .s_x$2(tc_ba$s_x$2),
        .s_b$0(tc_ba$s_b$0),
        .s_b$1(tc_ba$s_b$1),
        .s_b$2(tc_ba$s_b$2),
        .cross_t$0(tc_ba$cross_t$0),
        .cross_t$1(tc_ba$cross_t$1),
        .cross_t$2(tc_ba$cross_t$2),
        .cross_f$0(tc_ba$cross_f$0),
        .cross_f$1(tc_ba$cross_f$1),
        .cross_f$2(tc_ba$cross_f$2),
        .hit(tc_ba$hit),
        .miss(tc_ba$miss),
        .tag_out(tc_ba$tag_out),
        .valid_out(tc_ba$valid_out)
    );
    top$tri_unit$degenerate_wait degenerate_wait(
        .clock(degenerate_wait$clock),
        .d(degenerate_wait$d),
        .q(degenerate_wait$q)
    );
    top$tri_unit$fifo fifo(
        .clock(fifo$clock),
        .read(fifo$read),
        .data_out(fifo$data_out),
        .empty(fifo$empty),
        .almost_empty(fifo$almost_empty),
        .underflow(fifo$underflow),
        .write(fifo$write),
        .data_in(fifo$data_in),
        .full(fifo$full),
        .almost_full(fifo$almost_full),
        .overflow(fifo$overflow)
    );
    top$result$open_r count(
        .d(count$d),
        .q(count$q),
        .clock(count$clock)
    );
    
    // Update code
    always @(*) begin
        ab_bm$clock = clock;
        ab_bf$clock = clock;
        ab_s$clock = clock;
        ba_bm$clock = clock;
        ba_bf$clock = clock;
        ba_s$clock = clock;
        count$clock = clock;
        ab_bm$d = ab_bm$q;
        ab_bf$d = ab_bf$q;
        ab_s$d = ab_s$q;
        ba_bm$d = ba_bm$q;
        ba_bf$d = ba_bf$q;
        ba_s$d = ba_s$q;
        count$d = count$q;
        tc_ab$clock = clock;
        tc_ba$clock = clock;
        degenerate_wait$clock = clock;
        fifo$clock = clock;
        ab_bm$d = ab_bm$q;
        ab_bf$d = ab_bf$q;
        ab_s$d = ab_s$q;
        ba_bm$d = ba_bm$q;
        ba_bf$d = ba_bf$q;
        ba_s$d = ba_s$q;
        if (load_en) begin
            if (load_addr == 32'hc) begin
                ab_bm$d = load_data;
            end
            if (load_addr == 32'hd) begin
                ab_bf$d = load_data;
            end
            if (load_addr == 32'he) begin
                ab_s$d = load_data;
            end
            if (load_addr == 32'h1c) begin
                ba_bm$d = load_data;
            end
            if (load_addr == 32'h1d) begin
                ba_bf$d = load_data;
            end
            if (load_addr == 32'h1e) begin
                ba_s$d = load_data;
            end
        end
        ab_0$0$clock = clock;
        ab_1$0$clock = clock;
        ab_2$0$clock = clock;
        ba_0$0$clock = clock;
        ba_1$0$clock = clock;
        ba_2$0$clock = clock;
        ab_0$0$d = ab_0$0$q;
        ab_1$0$d = ab_1$0$q;
        ab_2$0$d = ab_2$0$q;
        ba_0$0$d = ba_0$0$q;
        ba_1$0$d = ba_1$0$q;
        ba_2$0$d = ba_2$0$q;
        if (load_en & (load_addr == addr_0$0)) begin
            ab_0$0$d = load_data;
        end
        if (load_en & (load_addr == addr_1$0)) begin
            ab_1$0$d = load_data;
        end
        if (load_en & (load_addr == addr_2$0)) begin
            ab_2$0$d = load_data;
        end
        if (load_en & (load_addr == (addr_0$0 | 32'h10))) begin
            ba_0$0$d = load_data;
        end
        if (load_en & (load_addr == (addr_1$0 | 32'h10))) begin
            ba_1$0$d = load_data;
        end
        if (load_en & (load_addr == (addr_2$0 | 32'h10))) begin
            ba_2$0$d = load_data;
        end
        tc_ab$m_0$0 = b_m_0$0;
        tc_ab$m_1$0 = b_m_1$0;
        tc_ab$m_2$0 = b_m_2$0;
        tc_ab$f_0$0 = ab_0$0$q;
        tc_ab$f_1$0 = ab_1$0$q;
        tc_ab$f_2$0 = ab_2$0$q;
        tc_ba$m_0$0 = a_m_0$0;
        tc_ba$m_1$0 = a_m_1$0;
        tc_ba$m_2$0 = a_m_2$0;
        tc_ba$f_0$0 = ba_0$0$q;
        tc_ba$f_1$0 = ba_1$0$q;
        tc_ba$f_2$0 = ba_2$0$q;
        ab_0$1$clock = clock;
        ab_1$1$clock = clock;
        ab_2$1$clock = clock;
        ba_0$1$clock = clock;
        ba_1$1$clock = clock;
        ba_2$1$clock = clock;
        ab_0$1$d = ab_0$1$q;
        ab_1$1$d = ab_1$1$q;
        ab_2$1$d = ab_2$1$q;
        ba_0$1$d = ba_0$1$q;
        ba_1$1$d = ba_1$1$q;
        ba_2$1$d = ba_2$1$q;
        if (load_en & (load_addr == addr_0$1)) begin
            ab_0$1$d = load_data;
        end
        if (load_en & (load_addr == addr_1$1)) begin
            ab_1$1$d = load_data;
        end
        if (load_en & (load_addr == addr_2$1)) begin
            ab_2$1$d = load_data;
        end
        if (load_en & (load_addr == (addr_0$1 | 32'h10))) begin
            ba_0$1$d = load_data;
        end
        if (load_en & (load_addr == (addr_1$1 | 32'h10))) begin
            ba_1$1$d = load_data;
        end
        if (load_en & (load_addr == (addr_2$1 | 32'h10))) begin
            ba_2$1$d = load_data;
        end
        tc_ab$m_0$1 = b_m_0$1;
        tc_ab$m_1$1 = b_m_1$1;
        tc_ab$m_2$1 = b_m_2$1;
        tc_ab$f_0$1 = ab_0$1$q;
        tc_ab$f_1$1 = ab_1$1$q;
        tc_ab$f_2$1 = ab_2$1$q;
        tc_ba$m_0$1 = a_m_0$1;
        tc_ba$m_1$1 = a_m_1$1;
        tc_ba$m_2$1 = a_m_2$1;
        tc_ba$f_0$1 = ba_0$1$q;
        tc_ba$f_1$1 = ba_1$1$q;
        tc_ba$f_2$1 = ba_2$1$q;
        ab_0$2$clock = clock;
        ab_1$2$clock = clock;
        ab_2$2$clock = clock;
        ba_0$2$clock = clock;
        ba_1$2$clock = clock;
        ba_2$2$clock = clock;
        ab_0$2$d = ab_0$2$q;
        ab_1$2$d = ab_1$2$q;
        ab_2$2$d = ab_2$2$q;
        ba_0$2$d = ba_0$2$q;
        ba_1$2$d = ba_1$2$q;
        ba_2$2$d = ba_2$2$q;
        if (load_en & (load_addr == addr_0$2)) begin
            ab_0$2$d = load_data;
        end
        if (load_en & (load_addr == addr_1$2)) begin
            ab_1$2$d = load_data;
        end
        if (load_en & (load_addr == addr_2$2)) begin
            ab_2$2$d = load_data;
        end
        if (load_en & (load_addr == (addr_0$2 | 32'h10))) begin
            ba_0$2$d = load_data;
        end
        if (load_en & (load_addr == (addr_1$2 | 32'h10))) begin
            ba_1$2$d = load_data;
        end
        if (load_en & (load_addr == (addr_2$2 | 32'h10))) begin
            ba_2$2$d = load_data;
        end
        tc_ab$m_0$2 = b_m_0$2;
        tc_ab$m_1$2 = b_m_1$2;
        tc_ab$m_2$2 = b_m_2$2;
        tc_ab$f_0$2 = ab_0$2$q;
        tc_ab$f_1$2 = ab_1$2$q;
        tc_ab$f_2$2 = ab_2$2$q;
        tc_ba$m_0$2 = a_m_0$2;
        tc_ba$m_1$2 = a_m_1$2;
        tc_ba$m_2$2 = a_m_2$2;
        tc_ba$f_0$2 = ba_0$2$q;
        tc_ba$f_1$2 = ba_1$2$q;
        tc_ba$f_2$2 = ba_2$2$q;
        ab_0$3$clock = clock;
        ab_1$3$clock = clock;
        ab_2$3$clock = clock;
        ba_0$3$clock = clock;
        ba_1$3$clock = clock;
        ba_2$3$clock = clock;
        ab_0$3$d = ab_0$3$q;
        ab_1$3$d = ab_1$3$q;
        ab_2$3$d = ab_2$3$q;
        ba_0$3$d = ba_0$3$q;
        ba_1$3$d = ba_1$3$q;
        ba_2$3$d = ba_2$3$q;
        if (load_en & (load_addr == addr_0$3)) begin
            ab_0$3$d = load_data;
        end
        if (load_en & (load_addr == addr_1$3)) begin
            ab_1$3$d = load_data;
        end
        if (load_en & (load_addr == addr_2$3)) begin
            ab_2$3$d = load_data;
        end
        if (load_en & (load_addr == (addr_0$3 | 32'h10))) begin
            ba_0$3$d = load_data;
        end
        if (load_en & (load_addr == (addr_1$3 | 32'h10))) begin
            ba_1$3$d = load_data;
        end
        if (load_en & (load_addr == (addr_2$3 | 32'h10))) begin
            ba_2$3$d = load_data;
        end
        tc_ab$m_0$3 = b_m_0$3;
        tc_ab$m_1$3 = b_m_1$3;
        tc_ab$m_2$3 = b_m_2$3;
        tc_ab$f_0$3 = ab_0$3$q;
        tc_ab$f_1$3 = ab_1$3$q;
        tc_ab$f_2$3 = ab_2$3$q;
        tc_ba$m_0$3 = a_m_0$3;
        tc_ba$m_1$3 = a_m_1$3;
        tc_ba$m_2$3 = a_m_2$3;
        tc_ba$f_0$3 = ba_0$3$q;
        tc_ba$f_1$3 = ba_1$3$q;
        tc_ba$f_2$3 = ba_2$3$q;
        tc_ab$v_x$0 = a_v_x$0;
        tc_ab$v_y$0 = a_v_y$0;
        tc_ab$v_z$0 = a_v_z$0;
        tc_ba$v_x$0 = b_v_x$0;
        tc_ba$v_y$0 = b_v_y$0;
        tc_ba$v_z$0 = b_v_z$0;
        tc_ab$v_x$1 = a_v_x$1;
        tc_ab$v_y$1 = a_v_y$1;
        tc_ab$v_z$1 = a_v_z$1;
        tc_ba$v_x$1 = b_v_x$1;
        tc_ba$v_y$1 = b_v_y$1;
        tc_ba$v_z$1 = b_v_z$1;
        tc_ab$v_x$2 = a_v_x$2;
        tc_ab$v_y$2 = a_v_y$2;
        tc_ab$v_z$2 = a_v_z$2;
        tc_ba$v_x$2 = b_v_x$2;
        tc_ba$v_y$2 = b_v_y$2;
        tc_ba$v_z$2 = b_v_z$2;
        tc_ab$alpha_m = b_alpha_m;
        tc_ab$alpha_f = b_alpha_f;
        tc_ab$beta_m = ab_bm$q;
        tc_ab$beta_f = ab_bf$q;
        tc_ab$scale = ab_s$q;
        tc_ab$v_exact = a_v_exact;
        tc_ab$tag = tag;
        tc_ba$alpha_m = a_alpha_m;
        tc_ba$alpha_f = a_alpha_f;
        tc_ba$beta_m = ba_bm$q;
        tc_ba$beta_f = ba_bf$q;
        tc_ba$scale = ba_s$q;
        tc_ba$v_exact = b_v_exact;
        tc_ba$tag = tag;
        in_ready = count$q != c_full;
        take = in_valid & (count$q != c_full);
        give = out_ready & ~fifo$empty;
        count$d = count$q;
        if (take & ~give) begin
            count$d = count$q + 32'h1;
        end
        if (give & ~take) begin
            count$d = count$q - 32'h1;
        end
        tc_ab$valid_in = take;
        tc_ba$valid_in = take;
        degenerate_wait$d = 32'h0;
        if (a_degenerate) begin
            degenerate_wait$d = 32'h1;
        end
        if (b_degenerate) begin
            degenerate_wait$d = 32'h2;
            if (a_degenerate) begin
                degenerate_wait$d = 32'h3;
            end
        end
        d1_t = tc_ab$hit & ~degenerate_wait$q[32'h1];
        d1_f = tc_ab$miss & ~degenerate_wait$q[32'h1];
        d2_t = tc_ba$hit & ~degenerate_wait$q[32'h0];
        d2_f = tc_ba$miss & ~degenerate_wait$q[32'h0];
        result = ((tc_ab$tag_out) & 34'h3ffffffff) << 32'h2;
        if (d1_t | d2_t) begin
            result = (((tc_ab$tag_out) & 34'h3ffffffff) << 32'h2) | c_hit;
        end
        if (~(d1_t | d2_t) & ~(d1_f & d2_f)) begin
            result = (((tc_ab$tag_out) & 34'h3ffffffff) << 32'h2) | c_uncertain;
        end
        fifo$write = tc_ab$valid_out;
        fifo$data_in = result;
        fifo$read = give;
        out_valid = ~fifo$empty;
        out_tag = fifo$data_out[(32'h2)+:(32)];
        out_hit = fifo$data_out[32'h1];
        out_uncertain = fifo$data_out[32'h0];
    end
    
endmodule // top$tri_unit


module top$tri_unit$degenerate_wait(clock,d,q);
    
    // Module arguments
    input wire  clock;
    input wire  [1:0] d;
    output reg  [1:0] q;
    
    // Stub signals
    reg  [1:0] line$0$d;
    wire  [1:0] line$0$q;
    reg  line$0$clock;
    reg  [1:0] line$1$d;
    wire  [1:0] line$1$q;
    reg  line$1$clock;
    reg  [1:0] line$2$d;
    wire  [1:0] line$2$q;
    reg  line$2$clock;
    reg  [1:0] line$3$d;
    wire  [1:0] line$3$q;
    reg  line$3$clock;
    reg  [1:0] line$4$d;
    wire  [1:0] line$4$q;
    reg  line$4$clock;
    reg  [1:0] line$5$d;
    wire  [1:0] line$5$q;
    reg  line$5$clock;
    reg  [1:0] line$6$d;
    wire  [1:0] line$6$q;
    reg  line$6$clock;
    reg  [1:0] line$7$d;
    wire  [1:0] line$7$q;
    reg  line$7$clock;
    reg  [1:0] line$8$d;
    wire  [1:0] line$8$q;
    reg  line$8$clock;
    reg  [1:0] line$9$d;
    wire  [1:0] line$9$q;
    reg  line$9$clock;
    reg  [1:0] line$10$d;
    wire  [1:0] line$10$q;
    reg  line$10$clock;
    reg  [1:0] line$11$d;
    wire  [1:0] line$11$q;
    reg  line$11$clock;
    reg  [1:0] line$12$d;
    wire  [1:0] line$12$q;
    reg  line$12$clock;
    reg  [1:0] line$13$d;
    wire  [1:0] line$13$q;
    reg  line$13$clock;
    reg  [1:0] line$14$d;
    wire  [1:0] line$14$q;
    reg  line$14$clock;
    reg  [1:0] line$15$d;
    wire  [1:0] line$15$q;
    reg  line$15$clock;
    reg  [1:0] line$16$d;
    wire  [1:0] line$16$q;
    reg  line$16$clock;
    reg  [1:0] line$17$d;
    wire  [1:0] line$17$q;
    reg  line$17$clock;
    reg  [1:0] line$18$d;
    wire  [1:0] line$18$q;
    reg  line$18$clock;
    reg  [1:0] line$19$d;
    wire  [1:0] line$19$q;
    reg  line$19$clock;
    reg  [1:0] line$20$d;
    wire  [1:0] line$20$q;
    reg  line$20$clock;
    reg  [1:0] line$21$d;
    wire  [1:0] line$21$q;
    reg  line$21$clock;
    reg  [1:0] line$22$d;
    wire  [1:0] line$22$q;
    reg  line$22$clock;
    reg  [1:0] line$23$d;
    wire  [1:0] line$23$q;
    reg  line$23$clock;
    reg  [1:0] line$24$d;
    wire  [1:0] line$24$q;
    reg  line$24$clock;
    reg  [1:0] line$25$d;
    wire  [1:0] line$25$q;
    reg  line$25$clock;
    reg  [1:0] line$26$d;
    wire  [1:0] line$26$q;
    reg  line$26$clock;
    reg  [1:0] line$27$d;
    wire  [1:0] line$27$q;
    reg  line$27$clock;
    reg  [1:0] line$28$d;
    wire  [1:0] line$28$q;
    reg  line$28$clock;
    reg  [1:0] line$29$d;
    wire  [1:0] line$29$q;
    reg  line$29$clock;
    reg  [1:0] line$30$d;
    wire  [1:0] line$30$q;
    reg  line$30$clock;
    reg  [1:0] line$31$d;
    wire  [1:0] line$31$q;
    reg  line$31$clock;
    reg  [1:0] line$32$d;
    wire  [1:0] line$32$q;
    reg  line$32$clock;
    reg  [1:0] line$33$d;
    wire  [1:0] line$33$q;
    reg  line$33$clock;
    reg  [1:0] line$34$d;
    wire  [1:0] line$34$q;
    reg  line$34$clock;
    reg  [1:0] line$35$d;
    wire  [1:0] line$35$q;
    reg  line$35$clock;
    reg  [1:0] line$36$d;
    wire  [1:0] line$36$q;
    reg  line$36$clock;
    reg  [1:0] line$37$d;
    wire  [1:0] line$37$q;
    reg  line$37$clock;
    reg  [1:0] line$38$d;
    wire  [1:0] line$38$q;
    reg  line$38$clock;
    reg  [1:0] line$39$d;
    wire  [1:0] line$39$q;
    reg  line$39$clock;
    reg  [1:0] line$40$d;
    wire  [1:0] line$40$q;
    reg  line$40$clock;
    reg  [1:0] line$41$d;
    wire  [1:0] line$41$q;
    reg  line$41$clock;
    reg  [1:0] line$42$d;
    wire  [1:0] line$42$q;
    reg  line$42$clock;
    reg  [1:0] line$43$d;
    wire  [1:0] line$43$q;
    reg  line$43$clock;
    reg  [1:0] line$44$d;
    wire  [1:0] line$44$q;
    reg  line$44$clock;
    reg  [1:0] line$45$d;
    wire  [1:0] line$45$q;
    reg  line$45$clock;
    reg  [1:0] line$46$d;
    wire  [1:0] line$46$q;
    reg  line$46$clock;
    reg  [1:0] line$47$d;
    wire  [1:0] line$47$q;
    reg  line$47$clock;
    reg  [1:0] line$48$d;
    wire  [1:0] line$48$q;
    reg  line$48$clock;
    reg  [1:0] line$49$d;
    wire  [1:0] line$49$q;
    reg  line$49$clock;
    reg  [1:0] line$50$d;
    wire  [1:0] line$50$q;
    reg  line$50$clock;
    reg  [1:0] line$51$d;
    wire  [1:0] line$51$q;
    reg  line$51$clock;
    
    // Sub module instances
    top$core$dop$busy_r line$0(
        .d(line$0$d),
        .q(line$0$q),
        .clock(line$0$clock)
    );
    top$core$dop$busy_r line$1(
        .d(line$1$d),
        .q(line$1$q),
        .clock(line$1$clock)
    );
    top$core$dop$busy_r line$2(
        .d(line$2$d),
        .q(line$2$q),
        .clock(line$2$clock)
    );
    top$core$dop$busy_r line$3(
        .d(line$3$d),
        .q(line$3$q),
        .clock(line$3$clock)
    );
    top$core$dop$busy_r line$4(
        .d(line$4$d),
        .q(line$4$q),
        .clock(line$4$clock)
    );
    top$core$dop$busy_r line$5(
        .d(line$5$d),
        .q(line$5$q),
        .clock(line$5$clock)
    );
    top$core$dop$busy_r line$6(
        .d(line$6$d),
        .q(line$6$q),
        .clock(line$6$clock)
    );
    top$core$dop$busy_r line$7(
        .d(line$7$d),
        .q(line$7$q),
        .clock(line$7$clock)
    );
    top$core$dop$busy_r line$8(
        .d(line$8$d),
        .q(line$8$q),
        .clock(line$8$clock)
    );
    top$core$dop$busy_r line$9(
        .d(line$9$d),
        .q(line$9$q),
        .clock(line$9$clock)
    );
    top$core$dop$busy_r line$10(
        .d(line$10$d),
        .q(line$10$q),
        .clock(line$10$clock)
    );
    top$core$dop$busy_r line$11(
        .d(line$11$d),
        .q(line$11$q),
        .clock(line$11$clock)
    );
    top$core$dop$busy_r line$12(
        .d(line$12$d),
        .q(line$12$q),
        .clock(line$12$clock)
    );
    top$core$dop$busy_r line$13(
        .d(line$13$d),
        .q(line$13$q),
        .clock(line$13$clock)
    );
    top$core$dop$busy_r line$14(
        .d(line$14$d),
        .q(line$14$q),
        .clock(line$14$clock)
    );
    top$core$dop$busy_r line$15(
        .d(line$15$d),
        .q(line$15$q),
        .clock(line$15$clock)
    );
    top$core$dop$busy_r line$16(
        .d(line$16$d),
        .q(line$16$q),
        .clock(line$16$clock)
    );
    top$core$dop$busy_r line$17(
        .d(line$17$d),
        .q(line$17$q),
        .clock(line$17$clock)
    );
    top$core$dop$busy_r line$18(
        .d(line$18$d),
        .q(line$18$q),
        .clock(line$18$clock)
    );
    top$core$dop$busy_r line$19(
        .d(line$19$d),
        .q(line$19$q),
        .clock(line$19$clock)
    );
    top$core$dop$busy_r line$20(
        .d(line$20$d),
        .q(line$20$q),
        .clock(line$20$clock)
    );
    top$core$dop$busy_r line$21(
        .d(line$21$d),
        .q(line$21$q),
        .clock(line$21$clock)
    );
    top$core$dop$busy_r line$22(
        .d(line$22$d),
        .q(line$22$q),
        .clock(line$22$clock)
    );
    top$core$dop$busy_r line$23(
        .d(line$23$d),
        .q(line$23$q),
        .clock(line$23$clock)
    );
    top$core$dop$busy_r line$24(
        .d(line$24$d),
        .q(line$24$q),
        .clock(line$24$clock)
    );
    top$core$dop$busy_r line$25(
        .d(line$25$d),
        .q(line$25$q),
        .clock(line$25$clock)
    );
    top$core$dop$busy_r line$26(
        .d(line$26$d),
        .q(line$26$q),
        .clock(line$26$clock)
    );
    top$core$dop$busy_r line$27(
        .d(line$27$d),
        .q(line$27$q),
        .clock(line$27$clock)
    );
    top$core$dop$busy_r line$28(
        .d(line$28$d),
        .q(line$28$q),
        .clock(line$28$clock)
    );
    top$core$dop$busy_r line$29(
        .d(line$29$d),
        .q(line$29$q),
        .clock(line$29$clock)
    );
    top$core$dop$busy_r line$30(
        .d(line$30$d),
        .q(line$30$q),
        .clock(line$30$clock)
    );
    top$core$dop$busy_r line$31(
        .d(line$31$d),
        .q(line$31$q),
        .clock(line$31$clock)
    );
    top$core$dop$busy_r line$32(
        .d(line$32$d),
        .q(line$32$q),
        .clock(line$32$clock)
    );
    top$core$dop$busy_r line$33(
        .d(line$33$d),
        .q(line$33$q),
        .clock(line$33$clock)
    );
    top$core$dop$busy_r line$34(
        .d(line$34$d),
        .q(line$34$q),
        .clock(line$34$clock)
    );
    top$core$dop$busy_r line$35(
        .d(line$35$d),
        .q(line$35$q),
        .clock(line$35$clock)
    );
    top$core$dop$busy_r line$36(
        .d(line$36$d),
        .q(line$36$q),
        .clock(line$36$clock)
    );
    top$core$dop$busy_r line$37(
        .d(line$37$d),
        .q(line$37$q),
        .clock(line$37$clock)
    );
    top$core$dop$busy_r line$38(
        .d(line$38$d),
        .q(line$38$q),
        .clock(line$38$clock)
    );
    top$core$dop$busy_r line$39(
        .d(line$39$d),
        .q(line$39$q),
        .clock(line$39$clock)
    );
    top$core$dop$busy_r line$40(
        .d(line$40$d),
        .q(line$40$q),
        .clock(line$40$clock)
    );
    top$core$dop$busy_r line$41(
        .d(line$41$d),
        .q(line$41$q),
        .clock(line$41$clock)
    );
    top$core$dop$busy_r line$42(
        .d(line$42$d),
        .q(line$42$q),
        .clock(line$42$clock)
    );
    top$core$dop$busy_r line$43(
        .d(line$43$d),
        .q(line$43$q),
        .clock(line$43$clock)
    );
    top$core$dop$busy_r line$44(
        .d(line$44$d),
        .q(line$44$q),
        .clock(line$44$clock)
    );
    top$core$dop$busy_r line$45(
        .d(line$45$d),
        .q(line$45$q),
        .clock(line$45$clock)
    );
    top$core$dop$busy_r line$46(
        .d(line$46$d),
        .q(line$46$q),
        .clock(line$46$clock)
    );
    top$core$dop$busy_r line$47(
        .d(line$47$d),
        .q(line$47$q),
        .clock(line$47$clock)
    );
    top$core$dop$busy_r line$48(
        .d(line$48$d),
        .q(line$48$q),
        .clock(line$48$clock)
    );
    top$core$dop$busy_r line$49(
        .d(line$49$d),
        .q(line$49$q),
        .clock(line$49$clock)
    );
    top$core$dop$busy_r line$50(
        .d(line$50$d),
        .q(line$50$q),
        .clock(line$50$clock)
    );
    top$core$dop$busy_r line$51(
        .d(line$51$d),
        .q(line$51$q),
        .clock(line$51$clock)
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
        line$4$clock = clock;
        line$4$d = d;
        line$5$clock = clock;
        line$5$d = d;
        line$6$clock = clock;
        line$6$d = d;
        line$7$clock = clock;
        line$7$d = d;
        line$8$clock = clock;
        line$8$d = d;
        line$9$clock = clock;
        line$9$d = d;
        line$10$clock = clock;
        line$10$d = d;
        line$11$clock = clock;
        line$11$d = d;
        line$12$clock = clock;
        line$12$d = d;
        line$13$clock = clock;
        line$13$d = d;
        line$14$clock = clock;
        line$14$d = d;
        line$15$clock = clock;
        line$15$d = d;
        line$16$clock = clock;
        line$16$d = d;
        line$17$clock = clock;
        line$17$d = d;
        line$18$clock = clock;
        line$18$d = d;
        line$19$clock = clock;
        line$19$d = d;
        line$20$clock = clock;
        line$20$d = d;
        line$21$clock = clock;
        line$21$d = d;
        line$22$clock = clock;
        line$22$d = d;
        line$23$clock = clock;
        line$23$d = d;
        line$24$clock = clock;
        line$24$d = d;
        line$25$clock = clock;
        line$25$d = d;
        line$26$clock = clock;
        line$26$d = d;
        line$27$clock = clock;
        line$27$d = d;
        line$28$clock = clock;
        line$28$d = d;
        line$29$clock = clock;
        line$29$d = d;
        line$30$clock = clock;
        line$30$d = d;
        line$31$clock = clock;
        line$31$d = d;
        line$32$clock = clock;
        line$32$d = d;
        line$33$clock = clock;
        line$33$d = d;
        line$34$clock = clock;
        line$34$d = d;
        line$35$clock = clock;
        line$35$d = d;
        line$36$clock = clock;
        line$36$d = d;
        line$37$clock = clock;
        line$37$d = d;
        line$38$clock = clock;
        line$38$d = d;
        line$39$clock = clock;
        line$39$d = d;
        line$40$clock = clock;
        line$40$d = d;
        line$41$clock = clock;
        line$41$d = d;
        line$42$clock = clock;
        line$42$d = d;
        line$43$clock = clock;
        line$43$d = d;
        line$44$clock = clock;
        line$44$d = d;
        line$45$clock = clock;
        line$45$d = d;
        line$46$clock = clock;
        line$46$d = d;
        line$47$clock = clock;
        line$47$d = d;
        line$48$clock = clock;
        line$48$d = d;
        line$49$clock = clock;
        line$49$d = d;
        line$50$clock = clock;
        line$50$d = d;
        line$51$clock = clock;
        line$51$d = d;
        line$0$d = line$1$q;
        line$1$d = line$2$q;
        line$2$d = line$3$q;
        line$3$d = line$4$q;
        line$4$d = line$5$q;
        line$5$d = line$6$q;
        line$6$d = line$7$q;
        line$7$d = line$8$q;
        line$8$d = line$9$q;
        line$9$d = line$10$q;
        line$10$d = line$11$q;
        line$11$d = line$12$q;
        line$12$d = line$13$q;
        line$13$d = line$14$q;
        line$14$d = line$15$q;
        line$15$d = line$16$q;
        line$16$d = line$17$q;
        line$17$d = line$18$q;
        line$18$d = line$19$q;
        line$19$d = line$20$q;
        line$20$d = line$21$q;
        line$21$d = line$22$q;
        line$22$d = line$23$q;
        line$23$d = line$24$q;
        line$24$d = line$25$q;
        line$25$d = line$26$q;
        line$26$d = line$27$q;
        line$27$d = line$28$q;
        line$28$d = line$29$q;
        line$29$d = line$30$q;
        line$30$d = line$31$q;
        line$31$d = line$32$q;
        line$32$d = line$33$q;
        line$33$d = line$34$q;
        line$34$d = line$35$q;
        line$35$d = line$36$q;
        line$36$d = line$37$q;
        line$37$d = line$38$q;
        line$38$d = line$39$q;
        line$39$d = line$40$q;
        line$40$d = line$41$q;
        line$41$d = line$42$q;
        line$42$d = line$43$q;
        line$43$d = line$44$q;
        line$44$d = line$45$q;
        line$45$d = line$46$q;
        line$46$d = line$47$q;
        line$47$d = line$48$q;
        line$48$d = line$49$q;
        line$49$d = line$50$q;
        line$50$d = line$51$q;
        q = line$0$q;
    end
    
endmodule // top$tri_unit$degenerate_wait


module top$tri_unit$fifo(clock,read,data_out,empty,almost_empty,underflow,write,data_in,full,almost_full,overflow);
    
    // Module arguments
    input wire  clock;
    input wire  read;
    output reg  [33:0] data_out;
    output reg  empty;
    output reg  almost_empty;
    output reg  underflow;
    input wire  write;
    input wire  [33:0] data_in;
    output reg  full;
    output reg  almost_full;
    output reg  overflow;
    
    // Stub signals
    reg  [7:0] ram$read_address;
    reg  ram$read_clock;
    wire  [33:0] ram$read_data;
    reg  [7:0] ram$write_address;
    reg  ram$write_clock;
    reg  [33:0] ram$write_data;
    reg  ram$write_enable;
    reg  read_logic$clock;
    reg  read_logic$read;
    wire  [33:0] read_logic$data_out;
    wire  read_logic$empty;
    wire  read_logic$almost_empty;
    wire  read_logic$underflow;
    reg  [8:0] read_logic$write_address_delayed;
    wire  [7:0] read_logic$ram_read_address;
    reg  [33:0] read_logic$ram_read_data;
    wire  read_logic$ram_read_clock;
    wire  [8:0] read_logic$read_address_out;
    wire  [8:0] read_logic$fill_level;
    reg  write_logic$write;
    reg  [33:0] write_logic$data_in;
    wire  write_logic$full;
    wire  write_logic$almost_full;
    wire  write_logic$overflow;
    reg  write_logic$clock;
    wire  [7:0] write_logic$ram_write_address;
    wire  write_logic$ram_write_clock;
    wire  [33:0] write_logic$ram_write_data;
    wire  write_logic$ram_write_enable;
    reg  [8:0] write_logic$read_address;
    wire  [8:0] write_logic$write_address_delayed;
    wire  [8:0] write_logic$fill_level;
    
    // Sub module instances
    top$tri_unit$fifo$ram ram(
        .read_address(ram$read_address),
        .read_clock(ram$read_clock),
        .read_data(ram$read_data),
        .write_address(ram$write_address),
        .write_clock(ram$write_clock),
        .write_data(ram$write_data),
        .write_enable(ram$write_enable)
    );
    top$tri_unit$fifo$read_logic read_logic(
        .clock(read_logic$clock),
        .read(read_logic$read),
        .data_out(read_logic$data_out),
        .empty(read_logic$empty),
        .almost_empty(read_logic$almost_empty),
        .underflow(read_logic$underflow),
        .write_address_delayed(read_logic$write_address_delayed),
        .ram_read_address(read_logic$ram_read_address),
        .ram_read_data(read_logic$ram_read_data),
        .ram_read_clock(read_logic$ram_read_clock),
        .read_address_out(read_logic$read_address_out),
        .fill_level(read_logic$fill_level)
    );
    top$tri_unit$fifo$write_logic write_logic(
        .write(write_logic$write),
        .data_in(write_logic$data_in),
        .full(write_logic$full),
        .almost_full(write_logic$almost_full),
        .overflow(write_logic$overflow),
        .clock(write_logic$clock),
        .ram_write_address(write_logic$ram_write_address),
        .ram_write_clock(write_logic$ram_write_clock),
        .ram_write_data(write_logic$ram_write_data),
        .ram_write_enable(write_logic$ram_write_enable),
        .read_address(write_logic$read_address),
        .write_address_delayed(write_logic$write_address_delayed),
        .fill_level(write_logic$fill_level)
    );
    
    // Update code
    always @(*) begin
        read_logic$clock = clock;
        write_logic$clock = clock;
        read_logic$read = read;
        empty = read_logic$empty;
        almost_empty = read_logic$almost_empty;
        data_out = read_logic$data_out;
        underflow = read_logic$underflow;
        overflow = write_logic$overflow;
        almost_full = write_logic$almost_full;
        full = write_logic$full;
        write_logic$write = write;
        write_logic$data_in = data_in;
        ram$write_clock = clock;
        ram$write_enable = write_logic$ram_write_enable;
        ram$write_address = write_logic$ram_write_address;
        ram$write_data = write_logic$ram_write_data;
        ram$read_clock = clock;
        ram$read_address = read_logic$ram_read_address;
        read_logic$ram_read_data = ram$read_data;
        read_logic$write_address_delayed = write_logic$write_address_delayed;
        write_logic$read_address = read_logic$read_address_out;
    end
    
endmodule // top$tri_unit$fifo


module top$tri_unit$fifo$ram(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [7:0] read_address;
    input wire  read_clock;
    output reg  [33:0] read_data;
    input wire  [7:0] write_address;
    input wire  write_clock;
    input wire  [33:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    reg[33:0] mem[255:0];
    
    
    
    always @(posedge read_clock) begin
       read_data <= mem[read_address];
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address] <= write_data;
       end
    end
                
endmodule // top$tri_unit$fifo$ram


module top$tri_unit$fifo$read_logic(clock,read,data_out,empty,almost_empty,underflow,write_address_delayed,ram_read_address,ram_read_data,ram_read_clock,read_address_out,fill_level);
    
    // Module arguments
    input wire  clock;
    input wire  read;
    output reg  [33:0] data_out;
    output reg  empty;
    output reg  almost_empty;
    output reg  underflow;
    input wire  [8:0] write_address_delayed;
    output reg  [7:0] ram_read_address;
    input wire  [33:0] ram_read_data;
    output reg  ram_read_clock;
    output reg  [8:0] read_address_out;
    output reg  [8:0] fill_level;
    
    // Constant declarations
    localparam  fifo_address_mask = 9'b11111111;
    localparam  fifo_size = 9'b100000000;
    localparam  block_size = 9'b1;
    
    // Stub signals
    reg  [8:0] read_address$d;
    wire  [8:0] read_address$q;
    reg  read_address$clock;
    reg  dff_underflow$d;
    wire  dff_underflow$q;
    reg  dff_underflow$clock;
    
    // Local signals
    reg  is_empty;
    reg  is_full;
    
    // Sub module instances
    top$result$open_r read_address(
        .d(read_address$d),
        .q(read_address$q),
        .clock(read_address$clock)
    );
    top$core$done_r dff_underflow(
        .d(dff_underflow$d),
        .q(dff_underflow$q),
        .clock(dff_underflow$clock)
    );
    
    // Update code
    always @(*) begin
        read_address$clock = clock;
        dff_underflow$clock = clock;
        read_address$d = read_address$q;
        dff_underflow$d = dff_underflow$q;
        ram_read_clock = clock;
        is_empty = (read_address$q == write_address_delayed);
        is_full = ~is_empty & ((read_address$q & fifo_address_mask) == (write_address_delayed & fifo_address_mask));
        fill_level = ((write_address_delayed & fifo_address_mask) + fifo_size - (read_address$q & fifo_address_mask)) & fifo_address_mask;
        if (is_full) begin
            fill_level = fifo_size;
        end
        almost_empty = (fill_level < block_size);
        empty = is_empty;
        ram_read_address = ((read_address$q & fifo_address_mask) & 8'hff);
        data_out = ram_read_data;
        if (read & ~is_empty) begin
            read_address$d = read_address$q + 32'h1;
            ram_read_address = (((read_address$q + 32'h1) & fifo_address_mask) & 8'hff);
        end
        else begin
            read_address$d = read_address$q;
        end
        dff_underflow$d = dff_underflow$q | (is_empty & read);
        underflow = dff_underflow$q;
        read_address_out = read_address$q;
    end
    
endmodule // top$tri_unit$fifo$read_logic


module top$tri_unit$fifo$write_logic(write,data_in,full,almost_full,overflow,clock,ram_write_address,ram_write_clock,ram_write_data,ram_write_enable,read_address,write_address_delayed,fill_level);
    
    // Module arguments
    input wire  write;
    input wire  [33:0] data_in;
    output reg  full;
    output reg  almost_full;
    output reg  overflow;
    input wire  clock;
    output reg  [7:0] ram_write_address;
    output reg  ram_write_clock;
    output reg  [33:0] ram_write_data;
    output reg  ram_write_enable;
    input wire  [8:0] read_address;
    output reg  [8:0] write_address_delayed;
    output reg  [8:0] fill_level;
    
    // Constant declarations
    localparam  fifo_address_mask = 9'b11111111;
    localparam  fifo_size = 9'b100000000;
    localparam  almost_full_level = 9'b11111111;
    
    // Stub signals
    reg  [8:0] write_address$d;
    wire  [8:0] write_address$q;
    reg  write_address$clock;
    reg  [8:0] dff_write_address_delay$d;
    wire  [8:0] dff_write_address_delay$q;
    reg  dff_write_address_delay$clock;
    reg  dff_overflow$d;
    wire  dff_overflow$q;
    reg  dff_overflow$clock;
    
    // Local signals
    reg  is_empty;
    reg  is_full;
    
    // Sub module instances
    top$result$open_r write_address(
        .d(write_address$d),
        .q(write_address$q),
        .clock(write_address$clock)
    );
    top$result$open_r dff_write_address_delay(
        .d(dff_write_address_delay$d),
        .q(dff_write_address_delay$q),
        .clock(dff_write_address_delay$clock)
    );
    top$core$done_r dff_overflow(
        .d(dff_overflow$d),
        .q(dff_overflow$q),
        .clock(dff_overflow$clock)
    );
    
    // Update code
    always @(*) begin
        dff_overflow$clock = clock;
        write_address$clock = clock;
        dff_write_address_delay$clock = clock;
        dff_overflow$d = dff_overflow$q;
        write_address$d = write_address$q;
        dff_write_address_delay$d = dff_write_address_delay$q;
        ram_write_clock = clock;
        dff_write_address_delay$d = write_address$q;
        write_address_delayed = dff_write_address_delay$q;
        ram_write_enable = 1'b0;
        is_empty = (read_address == dff_write_address_delay$q);
        is_full = ~is_empty & ((read_address & fifo_address_mask) == (write_address$q & fifo_address_mask));
        fill_level = ((dff_write_address_delay$q & fifo_address_mask) + fifo_size - (read_address & fifo_address_mask)) & fifo_address_mask;
        if (is_full) begin
            fill_level = fifo_size;
        end
        almost_full = (fill_level >= almost_full_level);
        full = is_full;
        ram_write_address = ((write_address$q & fifo_address_mask) & 8'hff);
        ram_write_data = data_in;
        if (write & ~is_full) begin
            write_address$d = write_address$q + 32'h1;
            ram_write_enable = 1'b1;
        end
        else begin
            write_address$d = write_address$q;
            ram_write_enable = 1'b0;
        end
        dff_overflow$d = dff_overflow$q | (is_full & write);
        overflow = dff_overflow$q;
    end
    
endmodule // top$tri_unit$fifo$write_logic


module top$tri_unit$tc_ab(clock,m_0$0,m_0$1,m_0$2,m_0$3,m_1$0,m_1$1,m_1$2,m_1$3,m_2$0,m_2$1,m_2$2,m_2$3,alpha_m,alpha_f,f_0$0,f_0$1,f_0$2,f_0$3,f_1$0,f_1$1,f_1$2,f_1$3,f_2$0,f_2$1,f_2$2,f_2$3,beta_m,beta_f,scale,v_x$0,v_x$1,v_x$2,v_y$0,v_y$1,v_y$2,v_z$0,v_z$1,v_z$2,v_exact,tag,valid_in,s_x$0,s_x$1,s_x$2,s_b$0,s_b$1,s_b$2,cross_t$0,cross_t$1,cross_t$2,cross_f$0,cross_f$1,cross_f$2,hit,miss,tag_out,valid_out);
    
    // Module arguments
    input wire  clock;
    input wire  [31:0] m_0$0;
    input wire  [31:0] m_0$1;
    input wire  [31:0] m_0$2;
    input wire  [31:0] m_0$3;
    input wire  [31:0] m_1$0;
    input wire  [31:0] m_1$1;
    input wire  [31:0] m_1$2;
    input wire  [31:0] m_1$3;
    input wire  [31:0] m_2$0;
    input wire  [31:0] m_2$1;
    input wire  [31:0] m_2$2;
    input wire  [31:0] m_2$3;
    input wire  [31:0] alpha_m;
    input wire  [31:0] alpha_f;
    input wire  [31:0] f_0$0;
    input wire  [31:0] f_0$1;
    input wire  [31:0] f_0$2;
    input wire  [31:0] f_0$3;
    input wire  [31:0] f_1$0;
    input wire  [31:0] f_1$1;
    input wire  [31:0] f_1$2;
    input wire  [31:0] f_1$3;
    input wire  [31:0] f_2$0;
    input wire  [31:0] f_2$1;
    input wire  [31:0] f_2$2;
    input wire  [31:0] f_2$3;
    input wire  [31:0] beta_m;
    input wire  [31:0] beta_f;
    input wire  [31:0] scale;
    input wire  [31:0] v_x$0;
    input wire  [31:0] v_x$1;
    input wire  [31:0] v_x$2;
    input wire  [31:0] v_y$0;
    input wire  [31:0] v_y$1;
    input wire  [31:0] v_y$2;
    input wire  [31:0] v_z$0;
    input wire  [31:0] v_z$1;
    input wire  [31:0] v_z$2;
    input wire  v_exact;
    input wire  [31:0] tag;
    input wire  valid_in;
    output reg  [31:0] s_x$0;
    output reg  [31:0] s_x$1;
    output reg  [31:0] s_x$2;
    output reg  [31:0] s_b$0;
    output reg  [31:0] s_b$1;
    output reg  [31:0] s_b$2;
    output reg  cross_t$0;
    output reg  cross_t$1;
    output reg  cross_t$2;
    output reg  cross_f$0;
    output reg  cross_f$1;
    output reg  cross_f$2;
    output reg  hit;
    output reg  miss;
    output reg  [31:0] tag_out;
    output reg  valid_out;
    
    // Constant declarations
    localparam  mask = 32'h7fffffff;
    
    // Stub signals
    reg  [31:0] in_m_0$0$d;
    wire  [31:0] in_m_0$0$q;
    reg  in_m_0$0$clock;
    reg  [31:0] in_m_0$1$d;
    wire  [31:0] in_m_0$1$q;
    reg  in_m_0$1$clock;
    reg  [31:0] in_m_0$2$d;
    wire  [31:0] in_m_0$2$q;
    reg  in_m_0$2$clock;
    reg  [31:0] in_m_0$3$d;
    wire  [31:0] in_m_0$3$q;
    reg  in_m_0$3$clock;
    reg  [31:0] in_m_1$0$d;
    wire  [31:0] in_m_1$0$q;
    reg  in_m_1$0$clock;
    reg  [31:0] in_m_1$1$d;
    wire  [31:0] in_m_1$1$q;
    reg  in_m_1$1$clock;
    reg  [31:0] in_m_1$2$d;
    wire  [31:0] in_m_1$2$q;
    reg  in_m_1$2$clock;
    reg  [31:0] in_m_1$3$d;
    wire  [31:0] in_m_1$3$q;
    reg  in_m_1$3$clock;
    reg  [31:0] in_m_2$0$d;
    wire  [31:0] in_m_2$0$q;
    reg  in_m_2$0$clock;
    reg  [31:0] in_m_2$1$d;
    wire  [31:0] in_m_2$1$q;
    reg  in_m_2$1$clock;
    reg  [31:0] in_m_2$2$d;
    wire  [31:0] in_m_2$2$q;
    reg  in_m_2$2$clock;
    reg  [31:0] in_m_2$3$d;
    wire  [31:0] in_m_2$3$q;
    reg  in_m_2$3$clock;
    reg  [31:0] in_alpha_m$d;
    wire  [31:0] in_alpha_m$q;
    reg  in_alpha_m$clock;
    reg  [31:0] in_alpha_f$d;
    wire  [31:0] in_alpha_f$q;
    reg  in_alpha_f$clock;
    reg  [31:0] in_f_0$0$d;
    wire  [31:0] in_f_0$0$q;
    reg  in_f_0$0$clock;
    reg  [31:0] in_f_0$1$d;
    wire  [31:0] in_f_0$1$q;
    reg  in_f_0$1$clock;
    reg  [31:0] in_f_0$2$d;
    wire  [31:0] in_f_0$2$q;
    reg  in_f_0$2$clock;
    reg  [31:0] in_f_0$3$d;
    wire  [31:0] in_f_0$3$q;
    reg  in_f_0$3$clock;
    reg  [31:0] in_f_1$0$d;
    wire  [31:0] in_f_1$0$q;
    reg  in_f_1$0$clock;
    reg  [31:0] in_f_1$1$d;
    wire  [31:0] in_f_1$1$q;
    reg  in_f_1$1$clock;
    reg  [31:0] in_f_1$2$d;
    wire  [31:0] in_f_1$2$q;
    reg  in_f_1$2$clock;
    reg  [31:0] in_f_1$3$d;
    wire  [31:0] in_f_1$3$q;
    reg  in_f_1$3$clock;
    reg  [31:0] in_f_2$0$d;
    wire  [31:0] in_f_2$0$q;
    reg  in_f_2$0$clock;
    reg  [31:0] in_f_2$1$d;
    wire  [31:0] in_f_2$1$q;
    reg  in_f_2$1$clock;
    reg  [31:0] in_f_2$2$d;
    wire  [31:0] in_f_2$2$q;
    reg  in_f_2$2$clock;
    reg  [31:0] in_f_2$3$d;
    wire  [31:0] in_f_2$3$q;
    reg  in_f_2$3$clock;
    reg  [31:0] in_beta_m$d;
    wire  [31:0] in_beta_m$q;
    reg  in_beta_m$clock;
    reg  [31:0] in_beta_f$d;
    wire  [31:0] in_beta_f$q;
    reg  in_beta_f$clock;
    reg  [31:0] in_scale$d;
    wire  [31:0] in_scale$q;
    reg  in_scale$clock;
    reg  [31:0] in_v_x$0$d;
    wire  [31:0] in_v_x$0$q;
    reg  in_v_x$0$clock;
    reg  [31:0] in_v_x$1$d;
    wire  [31:0] in_v_x$1$q;
    reg  in_v_x$1$clock;
    reg  [31:0] in_v_x$2$d;
    wire  [31:0] in_v_x$2$q;
    reg  in_v_x$2$clock;
    reg  [31:0] in_v_y$0$d;
    wire  [31:0] in_v_y$0$q;
    reg  in_v_y$0$clock;
    reg  [31:0] in_v_y$1$d;
    wire  [31:0] in_v_y$1$q;
    reg  in_v_y$1$clock;
    reg  [31:0] in_v_y$2$d;
    wire  [31:0] in_v_y$2$q;
    reg  in_v_y$2$clock;
    reg  [31:0] in_v_z$0$d;
    wire  [31:0] in_v_z$0$q;
    reg  in_v_z$0$clock;
    reg  [31:0] in_v_z$1$d;
    wire  [31:0] in_v_z$1$q;
    reg  in_v_z$1$clock;
    reg  [31:0] in_v_z$2$d;
    wire  [31:0] in_v_z$2$q;
    reg  in_v_z$2$clock;
    reg  in_v_exact$d;
    wire  in_v_exact$q;
    reg  in_v_exact$clock;
    reg  [31:0] in_tag$d;
    wire  [31:0] in_tag$q;
    reg  in_tag$clock;
    reg  in_valid$d;
    wire  in_valid$q;
    reg  in_valid$clock;
    reg  mb_0$0$clock;
    reg  [31:0] mb_0$0$a0;
    reg  [31:0] mb_0$0$a1;
    reg  [31:0] mb_0$0$a2;
    reg  [31:0] mb_0$0$b0;
    reg  [31:0] mb_0$0$b1;
    reg  [31:0] mb_0$0$b2;
    reg  [31:0] mb_0$0$c;
    wire  [31:0] mb_0$0$y;
    reg  mb_0$1$clock;
    reg  [31:0] mb_0$1$a0;
    reg  [31:0] mb_0$1$a1;
    reg  [31:0] mb_0$1$a2;
    reg  [31:0] mb_0$1$b0;
    reg  [31:0] mb_0$1$b1;
    reg  [31:0] mb_0$1$b2;
    reg  [31:0] mb_0$1$c;
    wire  [31:0] mb_0$1$y;
    reg  mb_0$2$clock;
    reg  [31:0] mb_0$2$a0;
    reg  [31:0] mb_0$2$a1;
    reg  [31:0] mb_0$2$a2;
    reg  [31:0] mb_0$2$b0;
    reg  [31:0] mb_0$2$b1;
    reg  [31:0] mb_0$2$b2;
    reg  [31:0] mb_0$2$c;
    wire  [31:0] mb_0$2$y;
    reg  mb_0$3$clock;
    reg  [31:0] mb_0$3$a0;
    reg  [31:0] mb_0$3$a1;
    reg  [31:0] mb_0$3$a2;
    reg  [31:0] mb_0$3$b0;
    reg  [31:0] mb_0$3$b1;
    reg  [31:0] mb_0$3$b2;
    reg  [31:0] mb_0$3$c;
    wire  [31:0] mb_0$3$y;
    reg  mb_1$0$clock;
    reg  [31:0] mb_1$0$a0;
    reg  [31:0] mb_1$0$a1;
    reg  [31:0] mb_1$0$a2;
    reg  [31:0] mb_1$0$b0;
    reg  [31:0] mb_1$0$b1;
    reg  [31:0] mb_1$0$b2;
    reg  [31:0] mb_1$0$c;
    wire  [31:0] mb_1$0$y;
    reg  mb_1$1$clock;
    reg  [31:0] mb_1$1$a0;
    reg  [31:0] mb_1$1$a1;
    reg  [31:0] mb_1$1$a2;
    reg  [31:0] mb_1$1$b0;
    reg  [31:0] mb_1$1$b1;
    reg  [31:0] mb_1$1$b2;
    reg  [31:0] mb_1$1$c;
    wire  [31:0] mb_1$1$y;
    reg  mb_1$2$clock;
    reg  [31:0] mb_1$2$a0;
    reg  [31:0] mb_1$2$a1;
    reg  [31:0] mb_1$2$a2;
    reg  [31:0] mb_1$2$b0;
    reg  [31:0] mb_1$2$b1;
    reg  [31:0] mb_1$2$b2;
    reg  [31:0] mb_1$2$c;
    wire  [31:0] mb_1$2$y;
    reg  mb_1$3$clock;
    reg  [31:0] mb_1$3$a0;
    reg  [31:0] mb_1$3$a1;
    reg  [31:0] mb_1$3$a2;
    reg  [31:0] mb_1$3$b0;
    reg  [31:0] mb_1$3$b1;
    reg  [31:0] mb_1$3$b2;
    reg  [31:0] mb_1$3$c;
    wire  [31:0] mb_1$3$y;
    reg  mb_2$0$clock;
    reg  [31:0] mb_2$0$a0;
    reg  [31:0] mb_2$0$a1;
    reg  [31:0] mb_2$0$a2;
    reg  [31:0] mb_2$0$b0;
    reg  [31:0] mb_2$0$b1;
    reg  [31:0] mb_2$0$b2;
    reg  [31:0] mb_2$0$c;
    wire  [31:0] mb_2$0$y;
    reg  mb_2$1$clock;
    reg  [31:0] mb_2$1$a0;
    reg  [31:0] mb_2$1$a1;
    reg  [31:0] mb_2$1$a2;
    reg  [31:0] mb_2$1$b0;
    reg  [31:0] mb_2$1$b1;
    reg  [31:0] mb_2$1$b2;
    reg  [31:0] mb_2$1$c;
    wire  [31:0] mb_2$1$y;
    reg  mb_2$2$clock;
    reg  [31:0] mb_2$2$a0;
    reg  [31:0] mb_2$2$a1;
    reg  [31:0] mb_2$2$a2;
    reg  [31:0] mb_2$2$b0;
    reg  [31:0] mb_2$2$b1;
    reg  [31:0] mb_2$2$b2;
    reg  [31:0] mb_2$2$c;
    wire  [31:0] mb_2$2$y;
    reg  mb_2$3$clock;
    reg  [31:0] mb_2$3$a0;
    reg  [31:0] mb_2$3$a1;
    reg  [31:0] mb_2$3$a2;
    reg  [31:0] mb_2$3$b0;
    reg  [31:0] mb_2$3$b1;
    reg  [31:0] mb_2$3$b2;
    reg  [31:0] mb_2$3$c;
    wire  [31:0] mb_2$3$y;
    reg  mg_0$0$clock;
    reg  [31:0] mg_0$0$a0;
    reg  [31:0] mg_0$0$a1;
    reg  [31:0] mg_0$0$a2;
    reg  [31:0] mg_0$0$b0;
    reg  [31:0] mg_0$0$b1;
    reg  [31:0] mg_0$0$b2;
    reg  [31:0] mg_0$0$c;
    wire  [31:0] mg_0$0$y;
    reg  mg_0$1$clock;
    reg  [31:0] mg_0$1$a0;
    reg  [31:0] mg_0$1$a1;
    reg  [31:0] mg_0$1$a2;
    reg  [31:0] mg_0$1$b0;
    reg  [31:0] mg_0$1$b1;
    reg  [31:0] mg_0$1$b2;
    reg  [31:0] mg_0$1$c;
    wire  [31:0] mg_0$1$y;
    reg  mg_0$2$clock;
    reg  [31:0] mg_0$2$a0;
    reg  [31:0] mg_0$2$a1;
    reg  [31:0] mg_0$2$a2;
    reg  [31:0] mg_0$2$b0;
    reg  [31:0] mg_0$2$b1;
    reg  [31:0] mg_0$2$b2;
    reg  [31:0] mg_0$2$c;
    wire  [31:0] mg_0$2$y;
    reg  mg_0$3$clock;
    reg  [31:0] mg_0$3$a0;
    reg  [31:0] mg_0$3$a1;
    reg  [31:0] mg_0$3$a2;
    reg  [31:0] mg_0$3$b0;
    reg  [31:0] mg_0$3$b1;
    reg  [31:0] mg_0$3$b2;
    reg  [31:0] mg_0$3$c;
    wire  [31:0] mg_0$3$y;
    reg  mg_1$0$clock;
    reg  [31:0] mg_1$0$a0;
    reg  [31:0] mg_1$0$a1;
    reg  [31:0] mg_1$0$a2;
    reg  [31:0] mg_1$0$b0;
    reg  [31:0] mg_1$0$b1;
    reg  [31:0] mg_1$0$b2;
    reg  [31:0] mg_1$0$c;
    wire  [31:0] mg_1$0$y;
    reg  mg_1$1$clock;
    reg  [31:0] mg_1$1$a0;
    reg  [31:0] mg_1$1$a1;
    reg  [31:0] mg_1$1$a2;
    reg  [31:0] mg_1$1$b0;
    reg  [31:0] mg_1$1$b1;
    reg  [31:0] mg_1$1$b2;
    reg  [31:0] mg_1$1$c;
    wire  [31:0] mg_1$1$y;
    reg  mg_1$2$clock;
    reg  [31:0] mg_1$2$a0;
    reg  [31:0] mg_1$2$a1;
    reg  [31:0] mg_1$2$a2;
    reg  [31:0] mg_1$2$b0;
    reg  [31:0] mg_1$2$b1;
    reg  [31:0] mg_1$2$b2;
    reg  [31:0] mg_1$2$c;
    wire  [31:0] mg_1$2$y;
    reg  mg_1$3$clock;
    reg  [31:0] mg_1$3$a0;
    reg  [31:0] mg_1$3$a1;
    reg  [31:0] mg_1$3$a2;
    reg  [31:0] mg_1$3$b0;
    reg  [31:0] mg_1$3$b1;
    reg  [31:0] mg_1$3$b2;
    reg  [31:0] mg_1$3$c;
    wire  [31:0] mg_1$3$y;
    reg  mg_2$0$clock;
    reg  [31:0] mg_2$0$a0;
    reg  [31:0] mg_2$0$a1;
    reg  [31:0] mg_2$0$a2;
    reg  [31:0] mg_2$0$b0;
    reg  [31:0] mg_2$0$b1;
    reg  [31:0] mg_2$0$b2;
    reg  [31:0] mg_2$0$c;
    wire  [31:0] mg_2$0$y;
    reg  mg_2$1$clock;
    reg  [31:0] mg_2$1$a0;
    reg  [31:0] mg_2$1$a1;
    reg  [31:0] mg_2$1$a2;
    reg  [31:0] mg_2$1$b0;
    reg  [31:0] mg_2$1$b1;
    reg  [31:0] mg_2$1$b2;
    reg  [31:0] mg_2$1$c;
    wire  [31:0] mg_2$1$y;
    reg  mg_2$2$clock;
    reg  [31:0] mg_2$2$a0;
    reg  [31:0] mg_2$2$a1;
    reg  [31:0] mg_2$2$a2;
    reg  [31:0] mg_2$2$b0;
    reg  [31:0] mg_2$2$b1;
    reg  [31:0] mg_2$2$b2;
    reg  [31:0] mg_2$2$c;
    wire  [31:0] mg_2$2$y;
    reg  mg_2$3$clock;
    reg  [31:0] mg_2$3$a0;
    reg  [31:0] mg_2$3$a1;
    reg  [31:0] mg_2$3$a2;
    reg  [31:0] mg_2$3$b0;
    reg  [31:0] mg_2$3$b1;
    reg  [31:0] mg_2$3$b2;
    reg  [31:0] mg_2$3$c;
    wire  [31:0] mg_2$3$y;
    reg  c3_0$clock;
    reg  [31:0] c3_0$d;
    wire  [31:0] c3_0$q;
    reg  c3_1$clock;
    reg  [31:0] c3_1$d;
    wire  [31:0] c3_1$q;
    reg  c3_2$clock;
    reg  [31:0] c3_2$d;
    wire  [31:0] c3_2$q;
    reg  am$clock;
    reg  [31:0] am$a;
    reg  [31:0] am$b;
    reg  am$valid_in;
    wire  [31:0] am$y;
    wire  am$valid_out;
    reg  af$clock;
    reg  [31:0] af$a;
    reg  [31:0] af$b;
    reg  af$valid_in;
    wire  [31:0] af$y;
    wire  af$valid_out;
    reg  aerr$clock;
    reg  [31:0] aerr$a;
    reg  [31:0] aerr$b;
    reg  aerr$sub;
    reg  aerr$valid_in;
    wire  [31:0] aerr$y;
    wire  aerr$valid_out;
    reg  aerr_wait$clock;
    reg  [31:0] aerr_wait$d;
    wire  [31:0] aerr_wait$q;
    reg  la$0$clock;
    reg  [31:0] la$0$a;
    reg  [31:0] la$0$b;
    reg  la$0$sub;
    reg  la$0$valid_in;
    wire  [31:0] la$0$y;
    wire  la$0$valid_out;
    reg  la$1$clock;
    reg  [31:0] la$1$a;
    reg  [31:0] la$1$b;
    reg  la$1$sub;
    reg  la$1$valid_in;
    wire  [31:0] la$1$y;
    wire  la$1$valid_out;
    reg  la$2$clock;
    reg  [31:0] la$2$a;
    reg  [31:0] la$2$b;
    reg  la$2$sub;
    reg  la$2$valid_in;
    wire  [31:0] la$2$y;
    wire  la$2$valid_out;
    reg  lb$0$clock;
    reg  [31:0] lb$0$a;
    reg  [31:0] lb$0$b;
    reg  lb$0$sub;
    reg  lb$0$valid_in;
    wire  [31:0] lb$0$y;
    wire  lb$0$valid_out;
    reg  lb$1$clock;
    reg  [31:0] lb$1$a;
    reg  [31:0] lb$1$b;
    reg  lb$1$sub;
    reg  lb$1$valid_in;
    wire  [31:0] lb$1$y;
    wire  lb$1$valid_out;
    reg  lb$2$clock;
    reg  [31:0] lb$2$a;
    reg  [31:0] lb$2$b;
    reg  lb$2$sub;
    reg  lb$2$valid_in;
    wire  [31:0] lb$2$y;
    wire  lb$2$valid_out;
    reg  l1$0$clock;
    reg  [31:0] l1$0$a;
    reg  [31:0] l1$0$b;
    reg  l1$0$sub;
    reg  l1$0$valid_in;
    wire  [31:0] l1$0$y;
    wire  l1$0$valid_out;
    reg  l1$1$clock;
    reg  [31:0] l1$1$a;
    reg  [31:0] l1$1$b;
    reg  l1$1$sub;
    reg  l1$1$valid_in;
    wire  [31:0] l1$1$y;
    wire  l1$1$valid_out;
    reg  l1$2$clock;
    reg  [31:0] l1$2$a;
    reg  [31:0] l1$2$b;
    reg  l1$2$sub;
    reg  l1$2$valid_in;
    wire  [31:0] l1$2$y;
    wire  l1$2$valid_out;
    reg  l1_wait$0$clock;
    reg  [31:0] l1_wait$0$d;
    wire  [31:0] l1_wait$0$q;
    reg  l1_wait$1$clock;
    reg  [31:0] l1_wait$1$d;
    wire  [31:0] l1_wait$1$q;
    reg  l1_wait$2$clock;
    reg  [31:0] l1_wait$2$d;
    wire  [31:0] l1_wait$2$q;
    reg  err$0$clock;
    reg  [31:0] err$0$a;
    reg  [31:0] err$0$b;
    reg  err$0$valid_in;
    wire  [31:0] err$0$y;
    wire  err$0$valid_out;
    reg  err$1$clock;
    reg  [31:0] err$1$a;
    reg  [31:0] err$1$b;
    reg  err$1$valid_in;
    wire  [31:0] err$1$y;
    wire  err$1$valid_out;
    reg  err$2$clock;
    reg  [31:0] err$2$a;
    reg  [31:0] err$2$b;
    reg  err$2$valid_in;
    wire  [31:0] err$2$y;
    wire  err$2$valid_out;
    reg  [31:0] mbr_0$0$d;
    wire  [31:0] mbr_0$0$q;
    reg  mbr_0$0$clock;
    reg  [31:0] mbr_0$1$d;
    wire  [31:0] mbr_0$1$q;
    reg  mbr_0$1$clock;
    reg  [31:0] mbr_0$2$d;
    wire  [31:0] mbr_0$2$q;
    reg  mbr_0$2$clock;
    reg  [31:0] mbr_0$3$d;
    wire  [31:0] mbr_0$3$q;
    reg  mbr_0$3$clock;
    reg  [31:0] mbr_1$0$d;
    wire  [31:0] mbr_1$0$q;
    reg  mbr_1$0$clock;
    reg  [31:0] mbr_1$1$d;
    wire  [31:0] mbr_1$1$q;
    reg  mbr_1$1$clock;
    reg  [31:0] mbr_1$2$d;
    wire  [31:0] mbr_1$2$q;
    reg  mbr_1$2$clock;
    reg  [31:0] mbr_1$3$d;
    wire  [31:0] mbr_1$3$q;
    reg  mbr_1$3$clock;
    reg  [31:0] mbr_2$0$d;
    wire  [31:0] mbr_2$0$q;
    reg  mbr_2$0$clock;
    reg  [31:0] mbr_2$1$d;
    wire  [31:0] mbr_2$1$q;
    reg  mbr_2$1$clock;
    reg  [31:0] mbr_2$2$d;
    wire  [31:0] mbr_2$2$q;
    reg  mbr_2$2$clock;
    reg  [31:0] mbr_2$3$d;
    wire  [31:0] mbr_2$3$q;
    reg  mbr_2$3$clock;
    reg  [31:0] mgr_0$0$d;
    wire  [31:0] mgr_0$0$q;
    reg  mgr_0$0$clock;
    reg  [31:0] mgr_0$1$d;
    wire  [31:0] mgr_0$1$q;
    reg  mgr_0$1$clock;
    reg  [31:0] mgr_0$2$d;
    wire  [31:0] mgr_0$2$q;
    reg  mgr_0$2$clock;
    reg  [31:0] mgr_0$3$d;
    wire  [31:0] mgr_0$3$q;
    reg  mgr_0$3$clock;
    reg  [31:0] mgr_1$0$d;
    wire  [31:0] mgr_1$0$q;
    reg  mgr_1$0$clock;
    reg  [31:0] mgr_1$1$d;
    wire  [31:0] mgr_1$1$q;
    reg  mgr_1$1$clock;
    reg  [31:0] mgr_1$2$d;
    wire  [31:0] mgr_1$2$q;
    reg  mgr_1$2$clock;
    reg  [31:0] mgr_1$3$d;
    wire  [31:0] mgr_1$3$q;
    reg  mgr_1$3$clock;
    reg  [31:0] mgr_2$0$d;
    wire  [31:0] mgr_2$0$q;
    reg  mgr_2$0$clock;
    reg  [31:0] mgr_2$1$d;
    wire  [31:0] mgr_2$1$q;
    reg  mgr_2$1$clock;
    reg  [31:0] mgr_2$2$d;
    wire  [31:0] mgr_2$2$q;
    reg  mgr_2$2$clock;
    reg  [31:0] mgr_2$3$d;
    wire  [31:0] mgr_2$3$q;
    reg  mgr_2$3$clock;
    reg  mg3_0$clock;
    reg  [31:0] mg3_0$d;
    wire  [31:0] mg3_0$q;
    reg  mg3_1$clock;
    reg  [31:0] mg3_1$d;
    wire  [31:0] mg3_1$q;
    reg  mg3_2$clock;
    reg  [31:0] mg3_2$d;
    wire  [31:0] mg3_2$q;
    reg  m3_0$0$clock;
    reg  [31:0] m3_0$0$a;
    reg  [31:0] m3_0$0$b;
    reg  m3_0$0$sub;
    reg  m3_0$0$valid_in;
    wire  [31:0] m3_0$0$y;
    wire  m3_0$0$valid_out;
    reg  m3_0$1$clock;
    reg  [31:0] m3_0$1$a;
    reg  [31:0] m3_0$1$b;
    reg  m3_0$1$sub;
    reg  m3_0$1$valid_in;
    wire  [31:0] m3_0$1$y;
    wire  m3_0$1$valid_out;
    reg  m3_0$2$clock;
    reg  [31:0] m3_0$2$a;
    reg  [31:0] m3_0$2$b;
    reg  m3_0$2$sub;
    reg  m3_0$2$valid_in;
    wire  [31:0] m3_0$2$y;
    wire  m3_0$2$valid_out;
    reg  m3_1$0$clock;
    reg  [31:0] m3_1$0$a;
    reg  [31:0] m3_1$0$b;
    reg  m3_1$0$sub;
    reg  m3_1$0$valid_in;
    wire  [31:0] m3_1$0$y;
    wire  m3_1$0$valid_out;
    reg  m3_1$1$clock;
    reg  [31:0] m3_1$1$a;
    reg  [31:0] m3_1$1$b;
    reg  m3_1$1$sub;
    reg  m3_1$1$valid_in;
    wire  [31:0] m3_1$1$y;
    wire  m3_1$1$valid_out;
    reg  m3_1$2$clock;
    reg  [31:0] m3_1$2$a;
    reg  [31:0] m3_1$2$b;
    reg  m3_1$2$sub;
    reg  m3_1$2$valid_in;
    wire  [31:0] m3_1$2$y;
    wire  m3_1$2$valid_out;
    reg  m3_2$0$clock;
    reg  [31:0] m3_2$0$a;
    reg  [31:0] m3_2$0$b;
    reg  m3_2$0$sub;
    reg  m3_2$0$valid_in;
    wire  [31:0] m3_2$0$y;
    wire  m3_2$0$valid_out;
    reg  m3_2$1$clock;
    reg  [31:0] m3_2$1$a;
    reg  [31:0] m3_2$1$b;
    reg  m3_2$1$sub;
    reg  m3_2$1$valid_in;
    wire  [31:0] m3_2$1$y;
    wire  m3_2$1$valid_out;
    reg  m3_2$2$clock;
    reg  [31:0] m3_2$2$a;
    reg  [31:0] m3_2$2$b;
    reg  m3_2$2$sub;
    reg  m3_2$2$valid_in;
    wire  [31:0] m3_2$2$y;
    wire  m3_2$2$valid_out;
    reg  vc_0$clock;
    reg  [31:0] vc_0$d;
    wire  [31:0] vc_0$q;
    reg  vc_1$clock;
    reg  [31:0] vc_1$d;
    wire  [31:0] vc_1$q;
    reg  vc_2$clock;
    reg  [31:0] vc_2$d;
    wire  [31:0] vc_2$q;
    reg  v_x_wait$0$clock;
    reg  [31:0] v_x_wait$0$d;
    wire  [31:0] v_x_wait$0$q;
    reg  v_x_wait$1$clock;
    reg  [31:0] v_x_wait$1$d;
    wire  [31:0] v_x_wait$1$q;
    reg  v_x_wait$2$clock;
    reg  [31:0] v_x_wait$2$d;
    wire  [31:0] v_x_wait$2$q;
    reg  v_y_wait$0$clock;
    reg  [31:0] v_y_wait$0$d;
    wire  [31:0] v_y_wait$0$q;
    reg  v_y_wait$1$clock;
    reg  [31:0] v_y_wait$1$d;
    wire  [31:0] v_y_wait$1$q;
    reg  v_y_wait$2$clock;
    reg  [31:0] v_y_wait$2$d;
    wire  [31:0] v_y_wait$2$q;
    reg  v_z_wait$0$clock;
    reg  [31:0] v_z_wait$0$d;
    wire  [31:0] v_z_wait$0$q;
    reg  v_z_wait$1$clock;
    reg  [31:0] v_z_wait$1$d;
    wire  [31:0] v_z_wait$1$q;
    reg  v_z_wait$2$clock;
    reg  [31:0] v_z_wait$2$d;
    wire  [31:0] v_z_wait$2$q;
    reg  vt_0$0$clock;
    reg  [31:0] vt_0$0$a0;
    reg  [31:0] vt_0$0$a1;
    reg  [31:0] vt_0$0$a2;
    reg  [31:0] vt_0$0$b0;
    reg  [31:0] vt_0$0$b1;
    reg  [31:0] vt_0$0$b2;
    reg  [31:0] vt_0$0$c;
    wire  [31:0] vt_0$0$y;
    reg  vt_0$1$clock;
    reg  [31:0] vt_0$1$a0;
    reg  [31:0] vt_0$1$a1;
    reg  [31:0] vt_0$1$a2;
    reg  [31:0] vt_0$1$b0;
    reg  [31:0] vt_0$1$b1;
    reg  [31:0] vt_0$1$b2;
    reg  [31:0] vt_0$1$c;
    wire  [31:0] vt_0$1$y;
    reg  vt_0$2$clock;
    reg  [31:0] vt_0$2$a0;
    reg  [31:0] vt_0$2$a1;
    reg  [31:0] vt_0$2$a2;
    reg  [31:0] vt_0$2$b0;
    reg  [31:0] vt_0$2$b1;
    reg  [31:0] vt_0$2$b2;
    reg  [31:0] vt_0$2$c;
    wire  [31:0] vt_0$2$y;
    reg  vt_1$0$clock;
    reg  [31:0] vt_1$0$a0;
    reg  [31:0] vt_1$0$a1;
    reg  [31:0] vt_1$0$a2;
    reg  [31:0] vt_1$0$b0;
    reg  [31:0] vt_1$0$b1;
    reg  [31:0] vt_1$0$b2;
    reg  [31:0] vt_1$0$c;
    wire  [31:0] vt_1$0$y;
    reg  vt_1$1$clock;
    reg  [31:0] vt_1$1$a0;
    reg  [31:0] vt_1$1$a1;
    reg  [31:0] vt_1$1$a2;
    reg  [31:0] vt_1$1$b0;
    reg  [31:0] vt_1$1$b1;
    reg  [31:0] vt_1$1$b2;
    reg  [31:0] vt_1$1$c;
    wire  [31:0] vt_1$1$y;
    reg  vt_1$2$clock;
    reg  [31:0] vt_1$2$a0;
    reg  [31:0] vt_1$2$a1;
    reg  [31:0] vt_1$2$a2;
    reg  [31:0] vt_1$2$b0;
    reg  [31:0] vt_1$2$b1;
    reg  [31:0] vt_1$2$b2;
    reg  [31:0] vt_1$2$c;
    wire  [31:0] vt_1$2$y;
    reg  vt_2$0$clock;
    reg  [31:0] vt_2$0$a0;
    reg  [31:0] vt_2$0$a1;
    reg  [31:0] vt_2$0$a2;
    reg  [31:0] vt_2$0$b0;
    reg  [31:0] vt_2$0$b1;
    reg  [31:0] vt_2$0$b2;
    reg  [31:0] vt_2$0$c;
    wire  [31:0] vt_2$0$y;
    reg  vt_2$1$clock;
    reg  [31:0] vt_2$1$a0;
    reg  [31:0] vt_2$1$a1;
    reg  [31:0] vt_2$1$a2;
    reg  [31:0] vt_2$1$b0;
    reg  [31:0] vt_2$1$b1;
    reg  [31:0] vt_2$1$b2;
    reg  [31:0] vt_2$1$c;
    wire  [31:0] vt_2$1$y;
    reg  vt_2$2$clock;
    reg  [31:0] vt_2$2$a0;
    reg  [31:0] vt_2$2$a1;
    reg  [31:0] vt_2$2$a2;
    reg  [31:0] vt_2$2$b0;
    reg  [31:0] vt_2$2$b1;
    reg  [31:0] vt_2$2$b2;
    reg  [31:0] vt_2$2$c;
    wire  [31:0] vt_2$2$y;
    reg  vm_0$0$clock;
    reg  [31:0] vm_0$0$a0;
    reg  [31:0] vm_0$0$a1;
    reg  [31:0] vm_0$0$a2;
    reg  [31:0] vm_0$0$b0;
    reg  [31:0] vm_0$0$b1;
    reg  [31:0] vm_0$0$b2;
    reg  [31:0] vm_0$0$c;
    wire  [31:0] vm_0$0$y;
    reg  vm_0$1$clock;
    reg  [31:0] vm_0$1$a0;
    reg  [31:0] vm_0$1$a1;
    reg  [31:0] vm_0$1$a2;
    reg  [31:0] vm_0$1$b0;
    reg  [31:0] vm_0$1$b1;
    reg  [31:0] vm_0$1$b2;
    reg  [31:0] vm_0$1$c;
    wire  [31:0] vm_0$1$y;
    reg  vm_0$2$clock;
    reg  [31:0] vm_0$2$a0;
    reg  [31:0] vm_0$2$a1;
    reg  [31:0] vm_0$2$a2;
    reg  [31:0] vm_0$2$b0;
    reg  [31:0] vm_0$2$b1;
    reg  [31:0] vm_0$2$b2;
    reg  [31:0] vm_0$2$c;
    wire  [31:0] vm_0$2$y;
    reg  vm_1$0$clock;
    reg  [31:0] vm_1$0$a0;
    reg  [31:0] vm_1$0$a1;
    reg  [31:0] vm_1$0$a2;
    reg  [31:0] vm_1$0$b0;
    reg  [31:0] vm_1$0$b1;
    reg  [31:0] vm_1$0$b2;
    reg  [31:0] vm_1$0$c;
    wire  [31:0] vm_1$0$y;
    reg  vm_1$1$clock;
    reg  [31:0] vm_1$1$a0;
    reg  [31:0] vm_1$1$a1;
    reg  [31:0] vm_1$1$a2;
    reg  [31:0] vm_1$1$b0;
    reg  [31:0] vm_1$1$b1;
    reg  [31:0] vm_1$1$b2;
    reg  [31:0] vm_1$1$c;
    wire  [31:0] vm_1$1$y;
    reg  vm_1$2$clock;
    reg  [31:0] vm_1$2$a0;
    reg  [31:0] vm_1$2$a1;
    reg  [31:0] vm_1$2$a2;
    reg  [31:0] vm_1$2$b0;
    reg  [31:0] vm_1$2$b1;
    reg  [31:0] vm_1$2$b2;
    reg  [31:0] vm_1$2$c;
    wire  [31:0] vm_1$2$y;
    reg  vm_2$0$clock;
    reg  [31:0] vm_2$0$a0;
    reg  [31:0] vm_2$0$a1;
    reg  [31:0] vm_2$0$a2;
    reg  [31:0] vm_2$0$b0;
    reg  [31:0] vm_2$0$b1;
    reg  [31:0] vm_2$0$b2;
    reg  [31:0] vm_2$0$c;
    wire  [31:0] vm_2$0$y;
    reg  vm_2$1$clock;
    reg  [31:0] vm_2$1$a0;
    reg  [31:0] vm_2$1$a1;
    reg  [31:0] vm_2$1$a2;
    reg  [31:0] vm_2$1$b0;
    reg  [31:0] vm_2$1$b1;
    reg  [31:0] vm_2$1$b2;
    reg  [31:0] vm_2$1$c;
    wire  [31:0] vm_2$1$y;
    reg  vm_2$2$clock;
    reg  [31:0] vm_2$2$a0;
    reg  [31:0] vm_2$2$a1;
    reg  [31:0] vm_2$2$a2;
    reg  [31:0] vm_2$2$b0;
    reg  [31:0] vm_2$2$b1;
    reg  [31:0] vm_2$2$b2;
    reg  [31:0] vm_2$2$c;
    wire  [31:0] vm_2$2$y;
    reg  [31:0] vtr_0$0$d;
    wire  [31:0] vtr_0$0$q;
    reg  vtr_0$0$clock;
    reg  [31:0] vtr_0$1$d;
    wire  [31:0] vtr_0$1$q;
    reg  vtr_0$1$clock;
    reg  [31:0] vtr_0$2$d;
    wire  [31:0] vtr_0$2$q;
    reg  vtr_0$2$clock;
    reg  [31:0] vtr_1$0$d;
    wire  [31:0] vtr_1$0$q;
    reg  vtr_1$0$clock;
    reg  [31:0] vtr_1$1$d;
    wire  [31:0] vtr_1$1$q;
    reg  vtr_1$1$clock;
    reg  [31:0] vtr_1$2$d;
    wire  [31:0] vtr_1$2$q;
    reg  vtr_1$2$clock;
    reg  [31:0] vtr_2$0$d;
    wire  [31:0] vtr_2$0$q;
    reg  vtr_2$0$clock;
    reg  [31:0] vtr_2$1$d;
    wire  [31:0] vtr_2$1$q;
    reg  vtr_2$1$clock;
    reg  [31:0] vtr_2$2$d;
    wire  [31:0] vtr_2$2$q;
    reg  vtr_2$2$clock;
    reg  [31:0] vmr_0$0$d;
    wire  [31:0] vmr_0$0$q;
    reg  vmr_0$0$clock;
    reg  [31:0] vmr_0$1$d;
    wire  [31:0] vmr_0$1$q;
    reg  vmr_0$1$clock;
    reg  [31:0] vmr_0$2$d;
    wire  [31:0] vmr_0$2$q;
    reg  vmr_0$2$clock;
    reg  [31:0] vmr_1$0$d;
    wire  [31:0] vmr_1$0$q;
    reg  vmr_1$0$clock;
    reg  [31:0] vmr_1$1$d;
    wire  [31:0] vmr_1$1$q;
    reg  vmr_1$1$clock;
    reg  [31:0] vmr_1$2$d;
    wire  [31:0] vmr_1$2$q;
    reg  vmr_1$2$clock;
    reg  [31:0] vmr_2$0$d;
    wire  [31:0] vmr_2$0$q;
    reg  vmr_2$0$clock;
    reg  [31:0] vmr_2$1$d;
    wire  [31:0] vmr_2$1$q;
    reg  vmr_2$1$clock;
    reg  [31:0] vmr_2$2$d;
    wire  [31:0] vmr_2$2$q;
    reg  vmr_2$2$clock;
    reg  exact_wait$clock;
    reg  exact_wait$d;
    wire  exact_wait$q;
    reg  verts$0$clock;
    reg  [31:0] verts$0$z;
    reg  [31:0] verts$0$m0;
    reg  [31:0] verts$0$m1;
    reg  [31:0] verts$0$m2;
    reg  verts$0$exact;
    wire  [31:0] verts$0$e;
    wire  [31:0] verts$0$g;
    wire  [31:0] verts$0$f0;
    wire  [31:0] verts$0$f1;
    wire  [31:0] verts$0$f2;
    wire  [31:0] verts$0$h;
    reg  verts$1$clock;
    reg  [31:0] verts$1$z;
    reg  [31:0] verts$1$m0;
    reg  [31:0] verts$1$m1;
    reg  [31:0] verts$1$m2;
    reg  verts$1$exact;
    wire  [31:0] verts$1$e;
    wire  [31:0] verts$1$g;
    wire  [31:0] verts$1$f0;
    wire  [31:0] verts$1$f1;
    wire  [31:0] verts$1$f2;
    wire  [31:0] verts$1$h;
    reg  verts$2$clock;
    reg  [31:0] verts$2$z;
    reg  [31:0] verts$2$m0;
    reg  [31:0] verts$2$m1;
    reg  [31:0] verts$2$m2;
    reg  verts$2$exact;
    wire  [31:0] verts$2$e;
    wire  [31:0] verts$2$g;
    wire  [31:0] verts$2$f0;
    wire  [31:0] verts$2$f1;
    wire  [31:0] verts$2$f2;
    wire  [31:0] verts$2$h;
    reg  edges$0$clock;
    reg  [31:0] edges$0$p0;
    reg  [31:0] edges$0$p1;
    reg  [31:0] edges$0$p2;
    reg  [31:0] edges$0$q0;
    reg  [31:0] edges$0$q1;
    reg  [31:0] edges$0$q2;
    reg  [31:0] edges$0$pe;
    reg  [31:0] edges$0$qe;
    reg  [31:0] edges$0$pg;
    reg  [31:0] edges$0$qg;
    reg  [31:0] edges$0$pf0;
    reg  [31:0] edges$0$pf1;
    reg  [31:0] edges$0$pf2;
    reg  [31:0] edges$0$qf0;
    reg  [31:0] edges$0$qf1;
    reg  [31:0] edges$0$qf2;
    reg  [31:0] edges$0$ph;
    reg  [31:0] edges$0$qh;
    wire  [31:0] edges$0$s_x;
    wire  [31:0] edges$0$s_b;
    wire  edges$0$cross_t;
    wire  edges$0$cross_f;
    reg  edges$1$clock;
    reg  [31:0] edges$1$p0;
    reg  [31:0] edges$1$p1;
    reg  [31:0] edges$1$p2;
    reg  [31:0] edges$1$q0;
    reg  [31:0] edges$1$q1;
    reg  [31:0] edges$1$q2;
    reg  [31:0] edges$1$pe;
    reg  [31:0] edges$1$qe;
    reg  [31:0] edges$1$pg;
    reg  [31:0] edges$1$qg;
    reg  [31:0] edges$1$pf0;
    reg  [31:0] edges$1$pf1;
    reg  [31:0] edges$1$pf2;
    reg  [31:0] edges$1$qf0;
    reg  [31:0] edges$1$qf1;
    reg  [31:0] edges$1$qf2;
    reg  [31:0] edges$1$ph;
    reg  [31:0] edges$1$qh;
    wire  [31:0] edges$1$s_x;
    wire  [31:0] edges$1$s_b;
    wire  edges$1$cross_t;
    wire  edges$1$cross_f;
    reg  edges$2$clock;
    reg  [31:0] edges$2$p0;
    reg  [31:0] edges$2$p1;
    reg  [31:0] edges$2$p2;
    reg  [31:0] edges$2$q0;
    reg  [31:0] edges$2$q1;
    reg  [31:0] edges$2$q2;
    reg  [31:0] edges$2$pe;
    reg  [31:0] edges$2$qe;
    reg  [31:0] edges$2$pg;
    reg  [31:0] edges$2$qg;
    reg  [31:0] edges$2$pf0;
    reg  [31:0] edges$2$pf1;
    reg  [31:0] edges$2$pf2;
    reg  [31:0] edges$2$qf0;
    reg  [31:0] edges$2$qf1;
    reg  [31:0] edges$2$qf2;
    reg  [31:0] edges$2$ph;
    reg  [31:0] edges$2$qh;
    wire  [31:0] edges$2$s_x;
    wire  [31:0] edges$2$s_b;
    wire  edges$2$cross_t;
    wire  edges$2$cross_f;
    reg  tag_wait$clock;
    reg  [31:0] tag_wait$d;
    wire  [31:0] tag_wait$q;
    reg  valid_wait$clock;
    reg  valid_wait$d;
    wire  valid_wait$q;
    reg  v_cross_t$0$d;
    wire  v_cross_t$0$q;
    reg  v_cross_t$0$clock;
    reg  v_cross_t$1$d;
    wire  v_cross_t$1$q;
    reg  v_cross_t$1$clock;
    reg  v_cross_t$2$d;
    wire  v_cross_t$2$q;
    reg  v_cross_t$2$clock;
    reg  v_cross_f$0$d;
    wire  v_cross_f$0$q;
    reg  v_cross_f$0$clock;
    reg  v_cross_f$1$d;
    wire  v_cross_f$1$q;
    reg  v_cross_f$1$clock;
    reg  v_cross_f$2$d;
    wire  v_cross_f$2$q;
    reg  v_cross_f$2$clock;
    reg  [31:0] v_s_x$0$d;
    wire  [31:0] v_s_x$0$q;
    reg  v_s_x$0$clock;
    reg  [31:0] v_s_x$1$d;
    wire  [31:0] v_s_x$1$q;
    reg  v_s_x$1$clock;
    reg  [31:0] v_s_x$2$d;
    wire  [31:0] v_s_x$2$q;
    reg  v_s_x$2$clock;
    reg  [31:0] v_s_b$0$d;
    wire  [31:0] v_s_b$0$q;
    reg  v_s_b$0$clock;
    reg  [31:0] v_s_b$1$d;
    wire  [31:0] v_s_b$1$q;
    reg  v_s_b$1$clock;
    reg  [31:0] v_s_b$2$d;
    wire  [31:0] v_s_b$2$q;
    reg  v_s_b$2$clock;
    reg  [31:0] out_s_x$0$d;
    wire  [31:0] out_s_x$0$q;
    reg  out_s_x$0$clock;
    reg  [31:0] out_s_x$1$d;
    wire  [31:0] out_s_x$1$q;
    reg  out_s_x$1$clock;
    reg  [31:0] out_s_x$2$d;
    wire  [31:0] out_s_x$2$q;
    reg  out_s_x$2$clock;
    reg  [31:0] out_s_b$0$d;
    wire  [31:0] out_s_b$0$q;
    reg  out_s_b$0$clock;
    reg  [31:0] out_s_b$1$d;
    wire  [31:0] out_s_b$1$q;
    reg  out_s_b$1$clock;
    reg  [31:0] out_s_b$2$d;
    wire  [31:0] out_s_b$2$q;
    reg  out_s_b$2$clock;
    reg  out_cross_t$0$d;
    wire  out_cross_t$0$q;
    reg  out_cross_t$0$clock;
    reg  out_cross_t$1$d;
    wire  out_cross_t$1$q;
    reg  out_cross_t$1$clock;
    reg  out_cross_t$2$d;
    wire  out_cross_t$2$q;
    reg  out_cross_t$2$clock;
    reg  out_cross_f$0$d;
    wire  out_cross_f$0$q;
    reg  out_cross_f$0$clock;
    reg  out_cross_f$1$d;
    wire  out_cross_f$1$q;
    reg  out_cross_f$1$clock;
    reg  out_cross_f$2$d;
    wire  out_cross_f$2$q;
    reg  out_cross_f$2$clock;
    reg  out_hit$d;
    wire  out_hit$q;
    reg  out_hit$clock;
    reg  out_miss$d;
    wire  out_miss$q;
    reg  out_miss$clock;
    reg  [31:0] out_tag$d;
    wire  [31:0] out_tag$q;
    reg  out_tag$clock;
    reg  out_valid$d;
    wire  out_valid$q;
    reg  out_valid$clock;
    
    // Local signals
    reg  hit_any;
    reg  miss_all;
    
    // Sub module instances
    top$core$cnt_nf in_m_0$0(
        .d(in_m_0$0$d),
        .q(in_m_0$0$q),
        .clock(in_m_0$0$clock)
    );
    top$core$cnt_nf in_m_0$1(
        .d(in_m_0$1$d),
        .q(in_m_0$1$q),
        .clock(in_m_0$1$clock)
    );
    top$core$cnt_nf in_m_0$2(
        .d(in_m_0$2$d),
        .q(in_m_0$2$q),
        .clock(in_m_0$2$clock)
    );
    top$core$cnt_nf in_m_0$3(
        .d(in_m_0$3$d),
        .q(in_m_0$3$q),
        .clock(in_m_0$3$clock)
    );
    top$core$cnt_nf in_m_1$0(
        .d(in_m_1$0$d),
        .q(in_m_1$0$q),
        .clock(in_m_1$0$clock)
    );
    top$core$cnt_nf in_m_1$1(
        .d(in_m_1$1$d),
        .q(in_m_1$1$q),
        .clock(in_m_1$1$clock)
    );
    top$core$cnt_nf in_m_1$2(
        .d(in_m_1$2$d),
        .q(in_m_1$2$q),
        .clock(in_m_1$2$clock)
    );
    top$core$cnt_nf in_m_1$3(
        .d(in_m_1$3$d),
        .q(in_m_1$3$q),
        .clock(in_m_1$3$clock)
    );
    top$core$cnt_nf in_m_2$0(
        .d(in_m_2$0$d),
        .q(in_m_2$0$q),
        .clock(in_m_2$0$clock)
    );
    top$core$cnt_nf in_m_2$1(
        .d(in_m_2$1$d),
        .q(in_m_2$1$q),
        .clock(in_m_2$1$clock)
    );
    top$core$cnt_nf in_m_2$2(
        .d(in_m_2$2$d),
        .q(in_m_2$2$q),
        .clock(in_m_2$2$clock)
    );
    top$core$cnt_nf in_m_2$3(
        .d(in_m_2$3$d),
        .q(in_m_2$3$q),
        .clock(in_m_2$3$clock)
    );
    top$core$cnt_nf in_alpha_m(
        .d(in_alpha_m$d),
        .q(in_alpha_m$q),
        .clock(in_alpha_m$clock)
    );
    top$core$cnt_nf in_alpha_f(
        .d(in_alpha_f$d),
        .q(in_alpha_f$q),
        .clock(in_alpha_f$clock)
    );
    top$core$cnt_nf in_f_0$0(
        .d(in_f_0$0$d),
        .q(in_f_0$0$q),
        .clock(in_f_0$0$clock)
    );
    top$core$cnt_nf in_f_0$1(
        .d(in_f_0$1$d),
        .q(in_f_0$1$q),
        .clock(in_f_0$1$clock)
    );
    top$core$cnt_nf in_f_0$2(
        .d(in_f_0$2$d),
        .q(in_f_0$2$q),
        .clock(in_f_0$2$clock)
    );
    top$core$cnt_nf in_f_0$3(
        .d(in_f_0$3$d),
        .q(in_f_0$3$q),
        .clock(in_f_0$3$clock)
    );
    top$core$cnt_nf in_f_1$0(
        .d(in_f_1$0$d),
        .q(in_f_1$0$q),
        .clock(in_f_1$0$clock)
    );
    top$core$cnt_nf in_f_1$1(
        .d(in_f_1$1$d),
        .q(in_f_1$1$q),
        .clock(in_f_1$1$clock)
    );
    top$core$cnt_nf in_f_1$2(
        .d(in_f_1$2$d),
        .q(in_f_1$2$q),
        .clock(in_f_1$2$clock)
    );
    top$core$cnt_nf in_f_1$3(
        .d(in_f_1$3$d),
        .q(in_f_1$3$q),
        .clock(in_f_1$3$clock)
    );
    top$core$cnt_nf in_f_2$0(
        .d(in_f_2$0$d),
        .q(in_f_2$0$q),
        .clock(in_f_2$0$clock)
    );
    top$core$cnt_nf in_f_2$1(
        .d(in_f_2$1$d),
        .q(in_f_2$1$q),
        .clock(in_f_2$1$clock)
    );
    top$core$cnt_nf in_f_2$2(
        .d(in_f_2$2$d),
        .q(in_f_2$2$q),
        .clock(in_f_2$2$clock)
    );
    top$core$cnt_nf in_f_2$3(
        .d(in_f_2$3$d),
        .q(in_f_2$3$q),
        .clock(in_f_2$3$clock)
    );
    top$core$cnt_nf in_beta_m(
        .d(in_beta_m$d),
        .q(in_beta_m$q),
        .clock(in_beta_m$clock)
    );
    top$core$cnt_nf in_beta_f(
        .d(in_beta_f$d),
        .q(in_beta_f$q),
        .clock(in_beta_f$clock)
    );
    top$core$cnt_nf in_scale(
        .d(in_scale$d),
        .q(in_scale$q),
        .clock(in_scale$clock)
    );
    top$core$cnt_nf in_v_x$0(
        .d(in_v_x$0$d),
        .q(in_v_x$0$q),
        .clock(in_v_x$0$clock)
    );
    top$core$cnt_nf in_v_x$1(
        .d(in_v_x$1$d),
        .q(in_v_x$1$q),
        .clock(in_v_x$1$clock)
    );
    top$core$cnt_nf in_v_x$2(
        .d(in_v_x$2$d),
        .q(in_v_x$2$q),
        .clock(in_v_x$2$clock)
    );
    top$core$cnt_nf in_v_y$0(
        .d(in_v_y$0$d),
        .q(in_v_y$0$q),
        .clock(in_v_y$0$clock)
    );
    top$core$cnt_nf in_v_y$1(
        .d(in_v_y$1$d),
        .q(in_v_y$1$q),
        .clock(in_v_y$1$clock)
    );
    top$core$cnt_nf in_v_y$2(
        .d(in_v_y$2$d),
        .q(in_v_y$2$q),
        .clock(in_v_y$2$clock)
    );
    top$core$cnt_nf in_v_z$0(
        .d(in_v_z$0$d),
        .q(in_v_z$0$q),
        .clock(in_v_z$0$clock)
    );
    top$core$cnt_nf in_v_z$1(
        .d(in_v_z$1$d),
        .q(in_v_z$1$q),
        .clock(in_v_z$1$clock)
    );
    top$core$cnt_nf in_v_z$2(
        .d(in_v_z$2$d),
        .q(in_v_z$2$q),
        .clock(in_v_z$2$clock)
    );
    top$core$done_r in_v_exact(
        .d(in_v_exact$d),
        .q(in_v_exact$q),
        .clock(in_v_exact$clock)
    );
    top$core$cnt_nf in_tag(
        .d(in_tag$d),
        .q(in_tag$q),
        .clock(in_tag$clock)
    );
    top$core$done_r in_valid(
        .d(in_valid$d),
        .q(in_valid$q),
        .clock(in_valid$clock)
    );
    top$tri_unit$tc_ab$mb_0$0 mb_0$0(
        .clock(mb_0$0$clock),
        .a0(mb_0$0$a0),
        .a1(mb_0$0$a1),
        .a2(mb_0$0$a2),
        .b0(mb_0$0$b0),
        .b1(mb_0$0$b1),
        .b2(mb_0$0$b2),
        .c(mb_0$0$c),
        .y(mb_0$0$y)
    );
    top$tri_unit$tc_ab$mb_0$0 mb_0$1(
        .clock(mb_0$1$clock),
        .a0(mb_0$1$a0),
        .a1(mb_0$1$a1),
        .a2(mb_0$1$a2),
        .b0(mb_0$1$b0),
        .b1(mb_0$1$b1),
        .b2(mb_0$1$b2),
        .c(mb_0$1$c),
        .y(mb_0$1$y)
    );
    top$tri_unit$tc_ab$mb_0$0 mb_0$2(
        .clock(mb_0$2$clock),
        .a0(mb_0$2$a0),
        .a1(mb_0$2$a1),
        .a2(mb_0$2$a2),
        .b0(mb_0$2$b0),
        .b1(mb_0$2$b1),
        .b2(mb_0$2$b2),
        .c(mb_0$2$c),
        .y(mb_0$2$y)
    );
    top$tri_unit$tc_ab$mb_0$3 mb_0$3(
        .clock(mb_0$3$clock),
        .a0(mb_0$3$a0),
        .a1(mb_0$3$a1),
        .a2(mb_0$3$a2),
        .b0(mb_0$3$b0),
        .b1(mb_0$3$b1),
        .b2(mb_0$3$b2),
        .c(mb_0$3$c),
        .y(mb_0$3$y)
    );
    top$tri_unit$tc_ab$mb_0$0 mb_1$0(
        .clock(mb_1$0$clock),
        .a0(mb_1$0$a0),
        .a1(mb_1$0$a1),
        .a2(mb_1$0$a2),
        .b0(mb_1$0$b0),
        .b1(mb_1$0$b1),
        .b2(mb_1$0$b2),
        .c(mb_1$0$c),
        .y(mb_1$0$y)
    );
    top$tri_unit$tc_ab$mb_0$0 mb_1$1(
        .clock(mb_1$1$clock),
        .a0(mb_1$1$a0),
        .a1(mb_1$1$a1),
        .a2(mb_1$1$a2),
        .b0(mb_1$1$b0),
        .b1(mb_1$1$b1),
        .b2(mb_1$1$b2),
        .c(mb_1$1$c),
        .y(mb_1$1$y)
    );
    top$tri_unit$tc_ab$mb_0$0 mb_1$2(
        .clock(mb_1$2$clock),
        .a0(mb_1$2$a0),
        .a1(mb_1$2$a1),
        .a2(mb_1$2$a2),
        .b0(mb_1$2$b0),
        .b1(mb_1$2$b1),
        .b2(mb_1$2$b2),
        .c(mb_1$2$c),
        .y(mb_1$2$y)
    );
    top$tri_unit$tc_ab$mb_0$3 mb_1$3(
        .clock(mb_1$3$clock),
        .a0(mb_1$3$a0),
        .a1(mb_1$3$a1),
        .a2(mb_1$3$a2),
        .b0(mb_1$3$b0),
        .b1(mb_1$3$b1),
        .b2(mb_1$3$b2),
        .c(mb_1$3$c),
        .y(mb_1$3$y)
    );
    top$tri_unit$tc_ab$mb_0$0 mb_2$0(
        .clock(mb_2$0$clock),
        .a0(mb_2$0$a0),
        .a1(mb_2$0$a1),
        .a2(mb_2$0$a2),
        .b0(mb_2$0$b0),
        .b1(mb_2$0$b1),
        .b2(mb_2$0$b2),
        .c(mb_2$0$c),
        .y(mb_2$0$y)
    );
    top$tri_unit$tc_ab$mb_0$0 mb_2$1(
        .clock(mb_2$1$clock),
        .a0(mb_2$1$a0),
        .a1(mb_2$1$a1),
        .a2(mb_2$1$a2),
        .b0(mb_2$1$b0),
        .b1(mb_2$1$b1),
        .b2(mb_2$1$b2),
        .c(mb_2$1$c),
        .y(mb_2$1$y)
    );
    top$tri_unit$tc_ab$mb_0$0 mb_2$2(
        .clock(mb_2$2$clock),
        .a0(mb_2$2$a0),
        .a1(mb_2$2$a1),
        .a2(mb_2$2$a2),
        .b0(mb_2$2$b0),
        .b1(mb_2$2$b1),
        .b2(mb_2$2$b2),
        .c(mb_2$2$c),
        .y(mb_2$2$y)
    );
    top$tri_unit$tc_ab$mb_0$3 mb_2$3(
        .clock(mb_2$3$clock),
        .a0(mb_2$3$a0),
        .a1(mb_2$3$a1),
        .a2(mb_2$3$a2),
        .b0(mb_2$3$b0),
        .b1(mb_2$3$b1),
        .b2(mb_2$3$b2),
        .c(mb_2$3$c),
        .y(mb_2$3$y)
    );
    top$tri_unit$tc_ab$mg_0$0 mg_0$0(
        .clock(mg_0$0$clock),
        .a0(mg_0$0$a0),
        .a1(mg_0$0$a1),
        .a2(mg_0$0$a2),
        .b0(mg_0$0$b0),
        .b1(mg_0$0$b1),
        .b2(mg_0$0$b2),
        .c(mg_0$0$c),
        .y(mg_0$0$y)
    );
    top$tri_unit$tc_ab$mg_0$0 mg_0$1(
        .clock(mg_0$1$clock),
        .a0(mg_0$1$a0),
        .a1(mg_0$1$a1),
        .a2(mg_0$1$a2),
        .b0(mg_0$1$b0),
        .b1(mg_0$1$b1),
        .b2(mg_0$1$b2),
        .c(mg_0$1$c),
        .y(mg_0$1$y)
    );
    top$tri_unit$tc_ab$mg_0$0 mg_0$2(
        .clock(mg_0$2$clock),
        .a0(mg_0$2$a0),
        .a1(mg_0$2$a1),
        .a2(mg_0$2$a2),
        .b0(mg_0$2$b0),
        .b1(mg_0$2$b1),
        .b2(mg_0$2$b2),
        .c(mg_0$2$c),
        .y(mg_0$2$y)
    );
    top$tri_unit$tc_ab$mg_0$3 mg_0$3(
        .clock(mg_0$3$clock),
        .a0(mg_0$3$a0),
        .a1(mg_0$3$a1),
        .a2(mg_0$3$a2),
        .b0(mg_0$3$b0),
        .b1(mg_0$3$b1),
        .b2(mg_0$3$b2),
        .c(mg_0$3$c),
        .y(mg_0$3$y)
    );
    top$tri_unit$tc_ab$mg_0$0 mg_1$0(
        .clock(mg_1$0$clock),
        .a0(mg_1$0$a0),
        .a1(mg_1$0$a1),
        .a2(mg_1$0$a2),
        .b0(mg_1$0$b0),
        .b1(mg_1$0$b1),
        .b2(mg_1$0$b2),
        .c(mg_1$0$c),
        .y(mg_1$0$y)
    );
    top$tri_unit$tc_ab$mg_0$0 mg_1$1(
        .clock(mg_1$1$clock),
        .a0(mg_1$1$a0),
        .a1(mg_1$1$a1),
        .a2(mg_1$1$a2),
        .b0(mg_1$1$b0),
        .b1(mg_1$1$b1),
        .b2(mg_1$1$b2),
        .c(mg_1$1$c),
        .y(mg_1$1$y)
    );
    top$tri_unit$tc_ab$mg_0$0 mg_1$2(
        .clock(mg_1$2$clock),
        .a0(mg_1$2$a0),
        .a1(mg_1$2$a1),
        .a2(mg_1$2$a2),
        .b0(mg_1$2$b0),
        .b1(mg_1$2$b1),
        .b2(mg_1$2$b2),
        .c(mg_1$2$c),
        .y(mg_1$2$y)
    );
    top$tri_unit$tc_ab$mg_0$3 mg_1$3(
        .clock(mg_1$3$clock),
        .a0(mg_1$3$a0),
        .a1(mg_1$3$a1),
        .a2(mg_1$3$a2),
        .b0(mg_1$3$b0),
        .b1(mg_1$3$b1),
        .b2(mg_1$3$b2),
        .c(mg_1$3$c),
        .y(mg_1$3$y)
    );
    top$tri_unit$tc_ab$mg_0$0 mg_2$0(
        .clock(mg_2$0$clock),
        .a0(mg_2$0$a0),
        .a1(mg_2$0$a1),
        .a2(mg_2$0$a2),
        .b0(mg_2$0$b0),
        .b1(mg_2$0$b1),
        .b2(mg_2$0$b2),
        .c(mg_2$0$c),
        .y(mg_2$0$y)
    );
    top$tri_unit$tc_ab$mg_0$0 mg_2$1(
        .clock(mg_2$1$clock),
        .a0(mg_2$1$a0),
        .a1(mg_2$1$a1),
        .a2(mg_2$1$a2),
        .b0(mg_2$1$b0),
        .b1(mg_2$1$b1),
        .b2(mg_2$1$b2),
        .c(mg_2$1$c),
        .y(mg_2$1$y)
    );
    top$tri_unit$tc_ab$mg_0$0 mg_2$2(
        .clock(mg_2$2$clock),
        .a0(mg_2$2$a0),
        .a1(mg_2$2$a1),
        .a2(mg_2$2$a2),
        .b0(mg_2$2$b0),
        .b1(mg_2$2$b1),
        .b2(mg_2$2$b2),
        .c(mg_2$2$c),
        .y(mg_2$2$y)
    );
    top$tri_unit$tc_ab$mg_0$3 mg_2$3(
        .clock(mg_2$3$clock),
        .a0(mg_2$3$a0),
        .a1(mg_2$3$a1),
        .a2(mg_2$3$a2),
        .b0(mg_2$3$b0),
        .b1(mg_2$3$b1),
        .b2(mg_2$3$b2),
        .c(mg_2$3$c),
        .y(mg_2$3$y)
    );
    top$tri_unit$tc_ab$c3_0 c3_0(
        .clock(c3_0$clock),
        .d(c3_0$d),
        .q(c3_0$q)
    );
    top$tri_unit$tc_ab$c3_0 c3_1(
        .clock(c3_1$clock),
        .d(c3_1$d),
        .q(c3_1$q)
    );
    top$tri_unit$tc_ab$c3_0 c3_2(
        .clock(c3_2$clock),
        .d(c3_2$d),
        .q(c3_2$q)
    );
    top$tri_unit$tc_ab$af am(
        .clock(am$clock),
        .a(am$a),
        .b(am$b),
        .valid_in(am$valid_in),
        .y(am$y),
        .valid_out(am$valid_out)
    );
    top$tri_unit$tc_ab$af af(
        .clock(af$clock),
        .a(af$a),
        .b(af$b),
        .valid_in(af$valid_in),
        .y(af$y),
        .valid_out(af$valid_out)
    );
    top$tri_unit$tc_ab$aerr aerr(
        .clock(aerr$clock),
        .a(aerr$a),
        .b(aerr$b),
        .sub(aerr$sub),
        .valid_in(aerr$valid_in),
        .y(aerr$y),
        .valid_out(aerr$valid_out)
    );
    top$tri_unit$tc_ab$aerr_wait aerr_wait(
        .clock(aerr_wait$clock),
        .d(aerr_wait$d),
        .q(aerr_wait$q)
    );
    top$tri_unit$tc_ab$aerr la$0(
        .clock(la$0$clock),
        .a(la$0$a),
        .b(la$0$b),
        .sub(la$0$sub),
        .valid_in(la$0$valid_in),
        .y(la$0$y),
        .valid_out(la$0$valid_out)
    );
    top$tri_unit$tc_ab$aerr la$1(
        .clock(la$1$clock),
        .a(la$1$a),
        .b(la$1$b),
        .sub(la$1$sub),
        .valid_in(la$1$valid_in),
        .y(la$1$y),
        .valid_out(la$1$valid_out)
    );
    top$tri_unit$tc_ab$aerr la$2(
        .clock(la$2$clock),
        .a(la$2$a),
        .b(la$2$b),
        .sub(la$2$sub),
        .valid_in(la$2$valid_in),
        .y(la$2$y),
        .valid_out(la$2$valid_out)
    );
    top$tri_unit$tc_ab$aerr lb$0(
        .clock(lb$0$clock),
        .a(lb$0$a),
        .b(lb$0$b),
        .sub(lb$0$sub),
        .valid_in(lb$0$valid_in),
        .y(lb$0$y),
        .valid_out(lb$0$valid_out)
    );
    top$tri_unit$tc_ab$aerr lb$1(
        .clock(lb$1$clock),
        .a(lb$1$a),
        .b(lb$1$b),
        .sub(lb$1$sub),
        .valid_in(lb$1$valid_in),
        .y(lb$1$y),
        .valid_out(lb$1$valid_out)
    );
    top$tri_unit$tc_ab$aerr lb$2(
        .clock(lb$2$clock),
        .a(lb$2$a),
        .b(lb$2$b),
        .sub(lb$2$sub),
        .valid_in(lb$2$valid_in),
        .y(lb$2$y),
        .valid_out(lb$2$valid_out)
    );
    top$tri_unit$tc_ab$aerr l1$0(
        .clock(l1$0$clock),
        .a(l1$0$a),
        .b(l1$0$b),
        .sub(l1$0$sub),
        .valid_in(l1$0$valid_in),
        .y(l1$0$y),
        .valid_out(l1$0$valid_out)
    );
    top$tri_unit$tc_ab$aerr l1$1(
        .clock(l1$1$clock),
        .a(l1$1$a),
        .b(l1$1$b),
        .sub(l1$1$sub),
        .valid_in(l1$1$valid_in),
        .y(l1$1$y),
        .valid_out(l1$1$valid_out)
    );
    top$tri_unit$tc_ab$aerr l1$2(
        .clock(l1$2$clock),
        .a(l1$2$a),
        .b(l1$2$b),
        .sub(l1$2$sub),
        .valid_in(l1$2$valid_in),
        .y(l1$2$y),
        .valid_out(l1$2$valid_out)
    );
    top$tri_unit$tc_ab$l1_wait$0 l1_wait$0(
        .clock(l1_wait$0$clock),
        .d(l1_wait$0$d),
        .q(l1_wait$0$q)
    );
    top$tri_unit$tc_ab$l1_wait$0 l1_wait$1(
        .clock(l1_wait$1$clock),
        .d(l1_wait$1$d),
        .q(l1_wait$1$q)
    );
    top$tri_unit$tc_ab$l1_wait$0 l1_wait$2(
        .clock(l1_wait$2$clock),
        .d(l1_wait$2$d),
        .q(l1_wait$2$q)
    );
    top$tri_unit$tc_ab$af err$0(
        .clock(err$0$clock),
        .a(err$0$a),
        .b(err$0$b),
        .valid_in(err$0$valid_in),
        .y(err$0$y),
        .valid_out(err$0$valid_out)
    );
    top$tri_unit$tc_ab$af err$1(
        .clock(err$1$clock),
        .a(err$1$a),
        .b(err$1$b),
        .valid_in(err$1$valid_in),
        .y(err$1$y),
        .valid_out(err$1$valid_out)
    );
    top$tri_unit$tc_ab$af err$2(
        .clock(err$2$clock),
        .a(err$2$a),
        .b(err$2$b),
        .valid_in(err$2$valid_in),
        .y(err$2$y),
        .valid_out(err$2$valid_out)
    );
    top$core$cnt_nf mbr_0$0(
        .d(mbr_0$0$d),
        .q(mbr_0$0$q),
        .clock(mbr_0$0$clock)
    );
    top$core$cnt_nf mbr_0$1(
        .d(mbr_0$1$d),
        .q(mbr_0$1$q),
        .clock(mbr_0$1$clock)
    );
    top$core$cnt_nf mbr_0$2(
        .d(mbr_0$2$d),
        .q(mbr_0$2$q),
        .clock(mbr_0$2$clock)
    );
    top$core$cnt_nf mbr_0$3(
        .d(mbr_0$3$d),
        .q(mbr_0$3$q),
        .clock(mbr_0$3$clock)
    );
    top$core$cnt_nf mbr_1$0(
        .d(mbr_1$0$d),
        .q(mbr_1$0$q),
        .clock(mbr_1$0$clock)
    );
    top$core$cnt_nf mbr_1$1(
        .d(mbr_1$1$d),
        .q(mbr_1$1$q),
        .clock(mbr_1$1$clock)
    );
    top$core$cnt_nf mbr_1$2(
        .d(mbr_1$2$d),
        .q(mbr_1$2$q),
        .clock(mbr_1$2$clock)
    );
    top$core$cnt_nf mbr_1$3(
        .d(mbr_1$3$d),
        .q(mbr_1$3$q),
        .clock(mbr_1$3$clock)
    );
    top$core$cnt_nf mbr_2$0(
        .d(mbr_2$0$d),
        .q(mbr_2$0$q),
        .clock(mbr_2$0$clock)
    );
    top$core$cnt_nf mbr_2$1(
        .d(mbr_2$1$d),
        .q(mbr_2$1$q),
        .clock(mbr_2$1$clock)
    );
    top$core$cnt_nf mbr_2$2(
        .d(mbr_2$2$d),
        .q(mbr_2$2$q),
        .clock(mbr_2$2$clock)
    );
    top$core$cnt_nf mbr_2$3(
        .d(mbr_2$3$d),
        .q(mbr_2$3$q),
        .clock(mbr_2$3$clock)
    );
    top$core$cnt_nf mgr_0$0(
        .d(mgr_0$0$d),
        .q(mgr_0$0$q),
        .clock(mgr_0$0$clock)
    );
    top$core$cnt_nf mgr_0$1(
        .d(mgr_0$1$d),
        .q(mgr_0$1$q),
        .clock(mgr_0$1$clock)
    );
    top$core$cnt_nf mgr_0$2(
        .d(mgr_0$2$d),
        .q(mgr_0$2$q),
        .clock(mgr_0$2$clock)
    );
    top$core$cnt_nf mgr_0$3(
        .d(mgr_0$3$d),
        .q(mgr_0$3$q),
        .clock(mgr_0$3$clock)
    );
    top$core$cnt_nf mgr_1$0(
        .d(mgr_1$0$d),
        .q(mgr_1$0$q),
        .clock(mgr_1$0$clock)
    );
    top$core$cnt_nf mgr_1$1(
        .d(mgr_1$1$d),
        .q(mgr_1$1$q),
        .clock(mgr_1$1$clock)
    );
    top$core$cnt_nf mgr_1$2(
        .d(mgr_1$2$d),
        .q(mgr_1$2$q),
        .clock(mgr_1$2$clock)
    );
    top$core$cnt_nf mgr_1$3(
        .d(mgr_1$3$d),
        .q(mgr_1$3$q),
        .clock(mgr_1$3$clock)
    );
    top$core$cnt_nf mgr_2$0(
        .d(mgr_2$0$d),
        .q(mgr_2$0$q),
        .clock(mgr_2$0$clock)
    );
    top$core$cnt_nf mgr_2$1(
        .d(mgr_2$1$d),
        .q(mgr_2$1$q),
        .clock(mgr_2$1$clock)
    );
    top$core$cnt_nf mgr_2$2(
        .d(mgr_2$2$d),
        .q(mgr_2$2$q),
        .clock(mgr_2$2$clock)
    );
    top$core$cnt_nf mgr_2$3(
        .d(mgr_2$3$d),
        .q(mgr_2$3$q),
        .clock(mgr_2$3$clock)
    );
    top$tri_unit$tc_ab$aerr_wait mg3_0(
        .clock(mg3_0$clock),
        .d(mg3_0$d),
        .q(mg3_0$q)
    );
    top$tri_unit$tc_ab$aerr_wait mg3_1(
        .clock(mg3_1$clock),
        .d(mg3_1$d),
        .q(mg3_1$q)
    );
    top$tri_unit$tc_ab$aerr_wait mg3_2(
        .clock(mg3_2$clock),
        .d(mg3_2$d),
        .q(mg3_2$q)
    );
    top$tri_unit$tc_ab$aerr m3_0$0(
        .clock(m3_0$0$clock),
        .a(m3_0$0$a),
        .b(m3_0$0$b),
        .sub(m3_0$0$sub),
        .valid_in(m3_0$0$valid_in),
        .y(m3_0$0$y),
        .valid_out(m3_0$0$valid_out)
    );
    top$tri_unit$tc_ab$aerr m3_0$1(
        .clock(m3_0$1$clock),
        .a(m3_0$1$a),
        .b(m3_0$1$b),
        .sub(m3_0$1$sub),
        .valid_in(m3_0$1$valid_in),
        .y(m3_0$1$y),
        .valid_out(m3_0$1$valid_out)
    );
    top$tri_unit$tc_ab$aerr m3_0$2(
        .clock(m3_0$2$clock),
        .a(m3_0$2$a),
        .b(m3_0$2$b),
        .sub(m3_0$2$sub),
        .valid_in(m3_0$2$valid_in),
        .y(m3_0$2$y),
        .valid_out(m3_0$2$valid_out)
    );
    top$tri_unit$tc_ab$aerr m3_1$0(
        .clock(m3_1$0$clock),
        .a(m3_1$0$a),
        .b(m3_1$0$b),
        .sub(m3_1$0$sub),
        .valid_in(m3_1$0$valid_in),
        .y(m3_1$0$y),
        .valid_out(m3_1$0$valid_out)
    );
    top$tri_unit$tc_ab$aerr m3_1$1(
        .clock(m3_1$1$clock),
        .a(m3_1$1$a),
        .b(m3_1$1$b),
        .sub(m3_1$1$sub),
        .valid_in(m3_1$1$valid_in),
        .y(m3_1$1$y),
        .valid_out(m3_1$1$valid_out)
    );
    top$tri_unit$tc_ab$aerr m3_1$2(
        .clock(m3_1$2$clock),
        .a(m3_1$2$a),
        .b(m3_1$2$b),
        .sub(m3_1$2$sub),
        .valid_in(m3_1$2$valid_in),
        .y(m3_1$2$y),
        .valid_out(m3_1$2$valid_out)
    );
    top$tri_unit$tc_ab$aerr m3_2$0(
        .clock(m3_2$0$clock),
        .a(m3_2$0$a),
        .b(m3_2$0$b),
        .sub(m3_2$0$sub),
        .valid_in(m3_2$0$valid_in),
        .y(m3_2$0$y),
        .valid_out(m3_2$0$valid_out)
    );
    top$tri_unit$tc_ab$aerr m3_2$1(
        .clock(m3_2$1$clock),
        .a(m3_2$1$a),
        .b(m3_2$1$b),
        .sub(m3_2$1$sub),
        .valid_in(m3_2$1$valid_in),
        .y(m3_2$1$y),
        .valid_out(m3_2$1$valid_out)
    );
    top$tri_unit$tc_ab$aerr m3_2$2(
        .clock(m3_2$2$clock),
        .a(m3_2$2$a),
        .b(m3_2$2$b),
        .sub(m3_2$2$sub),
        .valid_in(m3_2$2$valid_in),
        .y(m3_2$2$y),
        .valid_out(m3_2$2$valid_out)
    );
    top$tri_unit$tc_ab$c3_0 vc_0(
        .clock(vc_0$clock),
        .d(vc_0$d),
        .q(vc_0$q)
    );
    top$tri_unit$tc_ab$c3_0 vc_1(
        .clock(vc_1$clock),
        .d(vc_1$d),
        .q(vc_1$q)
    );
    top$tri_unit$tc_ab$c3_0 vc_2(
        .clock(vc_2$clock),
        .d(vc_2$d),
        .q(vc_2$q)
    );
    top$tri_unit$tc_ab$v_x_wait$0 v_x_wait$0(
        .clock(v_x_wait$0$clock),
        .d(v_x_wait$0$d),
        .q(v_x_wait$0$q)
    );
    top$tri_unit$tc_ab$v_x_wait$0 v_x_wait$1(
        .clock(v_x_wait$1$clock),
        .d(v_x_wait$1$d),
        .q(v_x_wait$1$q)
    );
    top$tri_unit$tc_ab$v_x_wait$0 v_x_wait$2(
        .clock(v_x_wait$2$clock),
        .d(v_x_wait$2$d),
        .q(v_x_wait$2$q)
    );
    top$tri_unit$tc_ab$v_x_wait$0 v_y_wait$0(
        .clock(v_y_wait$0$clock),
        .d(v_y_wait$0$d),
        .q(v_y_wait$0$q)
    );
    top$tri_unit$tc_ab$v_x_wait$0 v_y_wait$1(
        .clock(v_y_wait$1$clock),
        .d(v_y_wait$1$d),
        .q(v_y_wait$1$q)
    );
    top$tri_unit$tc_ab$v_x_wait$0 v_y_wait$2(
        .clock(v_y_wait$2$clock),
        .d(v_y_wait$2$d),
        .q(v_y_wait$2$q)
    );
    top$tri_unit$tc_ab$v_x_wait$0 v_z_wait$0(
        .clock(v_z_wait$0$clock),
        .d(v_z_wait$0$d),
        .q(v_z_wait$0$q)
    );
    top$tri_unit$tc_ab$v_x_wait$0 v_z_wait$1(
        .clock(v_z_wait$1$clock),
        .d(v_z_wait$1$d),
        .q(v_z_wait$1$q)
    );
    top$tri_unit$tc_ab$v_x_wait$0 v_z_wait$2(
        .clock(v_z_wait$2$clock),
        .d(v_z_wait$2$d),
        .q(v_z_wait$2$q)
    );
    top$tri_unit$tc_ab$mb_0$3 vt_0$0(
        .clock(vt_0$0$clock),
        .a0(vt_0$0$a0),
        .a1(vt_0$0$a1),
        .a2(vt_0$0$a2),
        .b0(vt_0$0$b0),
        .b1(vt_0$0$b1),
        .b2(vt_0$0$b2),
        .c(vt_0$0$c),
        .y(vt_0$0$y)
    );
    top$tri_unit$tc_ab$mb_0$3 vt_0$1(
        .clock(vt_0$1$clock),
        .a0(vt_0$1$a0),
        .a1(vt_0$1$a1),
        .a2(vt_0$1$a2),
        .b0(vt_0$1$b0),
        .b1(vt_0$1$b1),
        .b2(vt_0$1$b2),
        .c(vt_0$1$c),
        .y(vt_0$1$y)
    );
    top$tri_unit$tc_ab$mb_0$3 vt_0$2(
        .clock(vt_0$2$clock),
        .a0(vt_0$2$a0),
        .a1(vt_0$2$a1),
        .a2(vt_0$2$a2),
        .b0(vt_0$2$b0),
        .b1(vt_0$2$b1),
        .b2(vt_0$2$b2),
        .c(vt_0$2$c),
        .y(vt_0$2$y)
    );
    top$tri_unit$tc_ab$mb_0$3 vt_1$0(
        .clock(vt_1$0$clock),
        .a0(vt_1$0$a0),
        .a1(vt_1$0$a1),
        .a2(vt_1$0$a2),
        .b0(vt_1$0$b0),
        .b1(vt_1$0$b1),
        .b2(vt_1$0$b2),
        .c(vt_1$0$c),
        .y(vt_1$0$y)
    );
    top$tri_unit$tc_ab$mb_0$3 vt_1$1(
        .clock(vt_1$1$clock),
        .a0(vt_1$1$a0),
        .a1(vt_1$1$a1),
        .a2(vt_1$1$a2),
        .b0(vt_1$1$b0),
        .b1(vt_1$1$b1),
        .b2(vt_1$1$b2),
        .c(vt_1$1$c),
        .y(vt_1$1$y)
    );
    top$tri_unit$tc_ab$mb_0$3 vt_1$2(
        .clock(vt_1$2$clock),
        .a0(vt_1$2$a0),
        .a1(vt_1$2$a1),
        .a2(vt_1$2$a2),
        .b0(vt_1$2$b0),
        .b1(vt_1$2$b1),
        .b2(vt_1$2$b2),
        .c(vt_1$2$c),
        .y(vt_1$2$y)
    );
    top$tri_unit$tc_ab$mb_0$3 vt_2$0(
        .clock(vt_2$0$clock),
        .a0(vt_2$0$a0),
        .a1(vt_2$0$a1),
        .a2(vt_2$0$a2),
        .b0(vt_2$0$b0),
        .b1(vt_2$0$b1),
        .b2(vt_2$0$b2),
        .c(vt_2$0$c),
        .y(vt_2$0$y)
    );
    top$tri_unit$tc_ab$mb_0$3 vt_2$1(
        .clock(vt_2$1$clock),
        .a0(vt_2$1$a0),
        .a1(vt_2$1$a1),
        .a2(vt_2$1$a2),
        .b0(vt_2$1$b0),
        .b1(vt_2$1$b1),
        .b2(vt_2$1$b2),
        .c(vt_2$1$c),
        .y(vt_2$1$y)
    );
    top$tri_unit$tc_ab$mb_0$3 vt_2$2(
        .clock(vt_2$2$clock),
        .a0(vt_2$2$a0),
        .a1(vt_2$2$a1),
        .a2(vt_2$2$a2),
        .b0(vt_2$2$b0),
        .b1(vt_2$2$b1),
        .b2(vt_2$2$b2),
        .c(vt_2$2$c),
        .y(vt_2$2$y)
    );
    top$tri_unit$tc_ab$mg_0$3 vm_0$0(
        .clock(vm_0$0$clock),
        .a0(vm_0$0$a0),
        .a1(vm_0$0$a1),
        .a2(vm_0$0$a2),
        .b0(vm_0$0$b0),
        .b1(vm_0$0$b1),
        .b2(vm_0$0$b2),
        .c(vm_0$0$c),
        .y(vm_0$0$y)
    );
    top$tri_unit$tc_ab$mg_0$3 vm_0$1(
        .clock(vm_0$1$clock),
        .a0(vm_0$1$a0),
        .a1(vm_0$1$a1),
        .a2(vm_0$1$a2),
        .b0(vm_0$1$b0),
        .b1(vm_0$1$b1),
        .b2(vm_0$1$b2),
        .c(vm_0$1$c),
        .y(vm_0$1$y)
    );
    top$tri_unit$tc_ab$mg_0$3 vm_0$2(
        .clock(vm_0$2$clock),
        .a0(vm_0$2$a0),
        .a1(vm_0$2$a1),
        .a2(vm_0$2$a2),
        .b0(vm_0$2$b0),
        .b1(vm_0$2$b1),
        .b2(vm_0$2$b2),
        .c(vm_0$2$c),
        .y(vm_0$2$y)
    );
    top$tri_unit$tc_ab$mg_0$3 vm_1$0(
        .clock(vm_1$0$clock),
        .a0(vm_1$0$a0),
        .a1(vm_1$0$a1),
        .a2(vm_1$0$a2),
        .b0(vm_1$0$b0),
        .b1(vm_1$0$b1),
        .b2(vm_1$0$b2),
        .c(vm_1$0$c),
        .y(vm_1$0$y)
    );
    top$tri_unit$tc_ab$mg_0$3 vm_1$1(
        .clock(vm_1$1$clock),
        .a0(vm_1$1$a0),
        .a1(vm_1$1$a1),
        .a2(vm_1$1$a2),
        .b0(vm_1$1$b0),
        .b1(vm_1$1$b1),
        .b2(vm_1$1$b2),
        .c(vm_1$1$c),
        .y(vm_1$1$y)
    );
    top$tri_unit$tc_ab$mg_0$3 vm_1$2(
        .clock(vm_1$2$clock),
        .a0(vm_1$2$a0),
        .a1(vm_1$2$a1),
        .a2(vm_1$2$a2),
        .b0(vm_1$2$b0),
        .b1(vm_1$2$b1),
        .b2(vm_1$2$b2),
        .c(vm_1$2$c),
        .y(vm_1$2$y)
    );
    top$tri_unit$tc_ab$mg_0$3 vm_2$0(
        .clock(vm_2$0$clock),
        .a0(vm_2$0$a0),
        .a1(vm_2$0$a1),
        .a2(vm_2$0$a2),
        .b0(vm_2$0$b0),
        .b1(vm_2$0$b1),
        .b2(vm_2$0$b2),
        .c(vm_2$0$c),
        .y(vm_2$0$y)
    );
    top$tri_unit$tc_ab$mg_0$3 vm_2$1(
        .clock(vm_2$1$clock),
        .a0(vm_2$1$a0),
        .a1(vm_2$1$a1),
        .a2(vm_2$1$a2),
        .b0(vm_2$1$b0),
        .b1(vm_2$1$b1),
        .b2(vm_2$1$b2),
        .c(vm_2$1$c),
        .y(vm_2$1$y)
    );
    top$tri_unit$tc_ab$mg_0$3 vm_2$2(
        .clock(vm_2$2$clock),
        .a0(vm_2$2$a0),
        .a1(vm_2$2$a1),
        .a2(vm_2$2$a2),
        .b0(vm_2$2$b0),
        .b1(vm_2$2$b1),
        .b2(vm_2$2$b2),
        .c(vm_2$2$c),
        .y(vm_2$2$y)
    );
    top$core$cnt_nf vtr_0$0(
        .d(vtr_0$0$d),
        .q(vtr_0$0$q),
        .clock(vtr_0$0$clock)
    );
    top$core$cnt_nf vtr_0$1(
        .d(vtr_0$1$d),
        .q(vtr_0$1$q),
        .clock(vtr_0$1$clock)
    );
    top$core$cnt_nf vtr_0$2(
        .d(vtr_0$2$d),
        .q(vtr_0$2$q),
        .clock(vtr_0$2$clock)
    );
    top$core$cnt_nf vtr_1$0(
        .d(vtr_1$0$d),
        .q(vtr_1$0$q),
        .clock(vtr_1$0$clock)
    );
    top$core$cnt_nf vtr_1$1(
        .d(vtr_1$1$d),
        .q(vtr_1$1$q),
        .clock(vtr_1$1$clock)
    );
    top$core$cnt_nf vtr_1$2(
        .d(vtr_1$2$d),
        .q(vtr_1$2$q),
        .clock(vtr_1$2$clock)
    );
    top$core$cnt_nf vtr_2$0(
        .d(vtr_2$0$d),
        .q(vtr_2$0$q),
        .clock(vtr_2$0$clock)
    );
    top$core$cnt_nf vtr_2$1(
        .d(vtr_2$1$d),
        .q(vtr_2$1$q),
        .clock(vtr_2$1$clock)
    );
    top$core$cnt_nf vtr_2$2(
        .d(vtr_2$2$d),
        .q(vtr_2$2$q),
        .clock(vtr_2$2$clock)
    );
    top$core$cnt_nf vmr_0$0(
        .d(vmr_0$0$d),
        .q(vmr_0$0$q),
        .clock(vmr_0$0$clock)
    );
    top$core$cnt_nf vmr_0$1(
        .d(vmr_0$1$d),
        .q(vmr_0$1$q),
        .clock(vmr_0$1$clock)
    );
    top$core$cnt_nf vmr_0$2(
        .d(vmr_0$2$d),
        .q(vmr_0$2$q),
        .clock(vmr_0$2$clock)
    );
    top$core$cnt_nf vmr_1$0(
        .d(vmr_1$0$d),
        .q(vmr_1$0$q),
        .clock(vmr_1$0$clock)
    );
    top$core$cnt_nf vmr_1$1(
        .d(vmr_1$1$d),
        .q(vmr_1$1$q),
        .clock(vmr_1$1$clock)
    );
    top$core$cnt_nf vmr_1$2(
        .d(vmr_1$2$d),
        .q(vmr_1$2$q),
        .clock(vmr_1$2$clock)
    );
    top$core$cnt_nf vmr_2$0(
        .d(vmr_2$0$d),
        .q(vmr_2$0$q),
        .clock(vmr_2$0$clock)
    );
    top$core$cnt_nf vmr_2$1(
        .d(vmr_2$1$d),
        .q(vmr_2$1$q),
        .clock(vmr_2$1$clock)
    );
    top$core$cnt_nf vmr_2$2(
        .d(vmr_2$2$d),
        .q(vmr_2$2$q),
        .clock(vmr_2$2$clock)
    );
    top$tri_unit$tc_ab$exact_wait exact_wait(
        .clock(exact_wait$clock),
        .d(exact_wait$d),
        .q(exact_wait$q)
    );
    top$tri_unit$tc_ab$verts$0 verts$0(
        .clock(verts$0$clock),
        .z(verts$0$z),
        .m0(verts$0$m0),
        .m1(verts$0$m1),
        .m2(verts$0$m2),
        .exact(verts$0$exact),
        .e(verts$0$e),
        .g(verts$0$g),
        .f0(verts$0$f0),
        .f1(verts$0$f1),
        .f2(verts$0$f2),
        .h(verts$0$h)
    );
    top$tri_unit$tc_ab$verts$0 verts$1(
        .clock(verts$1$clock),
        .z(verts$1$z),
        .m0(verts$1$m0),
        .m1(verts$1$m1),
        .m2(verts$1$m2),
        .exact(verts$1$exact),
        .e(verts$1$e),
        .g(verts$1$g),
        .f0(verts$1$f0),
        .f1(verts$1$f1),
        .f2(verts$1$f2),
        .h(verts$1$h)
    );
    top$tri_unit$tc_ab$verts$0 verts$2(
        .clock(verts$2$clock),
        .z(verts$2$z),
        .m0(verts$2$m0),
        .m1(verts$2$m1),
        .m2(verts$2$m2),
        .exact(verts$2$exact),
        .e(verts$2$e),
        .g(verts$2$g),
        .f0(verts$2$f0),
        .f1(verts$2$f1),
        .f2(verts$2$f2),
        .h(verts$2$h)
    );
    top$tri_unit$tc_ab$edges$0 edges$0(
        .clock(edges$0$clock),
        .p0(edges$0$p0),
        .p1(edges$0$p1),
        .p2(edges$0$p2),
        .q0(edges$0$q0),
        .q1(edges$0$q1),
        .q2(edges$0$q2),
        .pe(edges$0$pe),
        .qe(edges$0$qe),
        .pg(edges$0$pg),
        .qg(edges$0$qg),
        .pf0(edges$0$pf0),
        .pf1(edges$0$pf1),
        .pf2(edges$0$pf2),
        .qf0(edges$0$qf0),
        .qf1(edges$0$qf1),
        .qf2(edges$0$qf2),
        .ph(edges$0$ph),
        .qh(edges$0$qh),
        .s_x(edges$0$s_x),
        .s_b(edges$0$s_b),
        .cross_t(edges$0$cross_t),
        .cross_f(edges$0$cross_f)
    );
    top$tri_unit$tc_ab$edges$0 edges$1(
        .clock(edges$1$clock),
        .p0(edges$1$p0),
        .p1(edges$1$p1),
        .p2(edges$1$p2),
        .q0(edges$1$q0),
        .q1(edges$1$q1),
        .q2(edges$1$q2),
        .pe(edges$1$pe),
        .qe(edges$1$qe),
        .pg(edges$1$pg),
        .qg(edges$1$qg),
        .pf0(edges$1$pf0),
        .pf1(edges$1$pf1),
        .pf2(edges$1$pf2),
        .qf0(edges$1$qf0),
        .qf1(edges$1$qf1),
        .qf2(edges$1$qf2),
        .ph(edges$1$ph),
        .qh(edges$1$qh),
        .s_x(edges$1$s_x),
        .s_b(edges$1$s_b),
        .cross_t(edges$1$cross_t),
        .cross_f(edges$1$cross_f)
    );
    top$tri_unit$tc_ab$edges$0 edges$2(
        .clock(edges$2$clock),
        .p0(edges$2$p0),
        .p1(edges$2$p1),
        .p2(edges$2$p2),
        .q0(edges$2$q0),
        .q1(edges$2$q1),
        .q2(edges$2$q2),
        .pe(edges$2$pe),
        .qe(edges$2$qe),
        .pg(edges$2$pg),
        .qg(edges$2$qg),
        .pf0(edges$2$pf0),
        .pf1(edges$2$pf1),
        .pf2(edges$2$pf2),
        .qf0(edges$2$qf0),
        .qf1(edges$2$qf1),
        .qf2(edges$2$qf2),
        .ph(edges$2$ph),
        .qh(edges$2$qh),
        .s_x(edges$2$s_x),
        .s_b(edges$2$s_b),
        .cross_t(edges$2$cross_t),
        .cross_f(edges$2$cross_f)
    );
    top$tri_unit$tc_ab$tag_wait tag_wait(
        .clock(tag_wait$clock),
        .d(tag_wait$d),
        .q(tag_wait$q)
    );
    top$tri_unit$tc_ab$valid_wait valid_wait(
        .clock(valid_wait$clock),
        .d(valid_wait$d),
        .q(valid_wait$q)
    );
    top$core$done_r v_cross_t$0(
        .d(v_cross_t$0$d),
        .q(v_cross_t$0$q),
        .clock(v_cross_t$0$clock)
    );
    top$core$done_r v_cross_t$1(
        .d(v_cross_t$1$d),
        .q(v_cross_t$1$q),
        .clock(v_cross_t$1$clock)
    );
    top$core$done_r v_cross_t$2(
        .d(v_cross_t$2$d),
        .q(v_cross_t$2$q),
        .clock(v_cross_t$2$clock)
    );
    top$core$done_r v_cross_f$0(
        .d(v_cross_f$0$d),
        .q(v_cross_f$0$q),
        .clock(v_cross_f$0$clock)
    );
    top$core$done_r v_cross_f$1(
        .d(v_cross_f$1$d),
        .q(v_cross_f$1$q),
        .clock(v_cross_f$1$clock)
    );
    top$core$done_r v_cross_f$2(
        .d(v_cross_f$2$d),
        .q(v_cross_f$2$q),
        .clock(v_cross_f$2$clock)
    );
    top$core$cnt_nf v_s_x$0(
        .d(v_s_x$0$d),
        .q(v_s_x$0$q),
        .clock(v_s_x$0$clock)
    );
    top$core$cnt_nf v_s_x$1(
        .d(v_s_x$1$d),
        .q(v_s_x$1$q),
        .clock(v_s_x$1$clock)
    );
    top$core$cnt_nf v_s_x$2(
        .d(v_s_x$2$d),
        .q(v_s_x$2$q),
        .clock(v_s_x$2$clock)
    );
    top$core$cnt_nf v_s_b$0(
        .d(v_s_b$0$d),
        .q(v_s_b$0$q),
        .clock(v_s_b$0$clock)
    );
    top$core$cnt_nf v_s_b$1(
        .d(v_s_b$1$d),
        .q(v_s_b$1$q),
        .clock(v_s_b$1$clock)
    );
    top$core$cnt_nf v_s_b$2(
        .d(v_s_b$2$d),
        .q(v_s_b$2$q),
        .clock(v_s_b$2$clock)
    );
    top$core$cnt_nf out_s_x$0(
        .d(out_s_x$0$d),
        .q(out_s_x$0$q),
        .clock(out_s_x$0$clock)
    );
    top$core$cnt_nf out_s_x$1(
        .d(out_s_x$1$d),
        .q(out_s_x$1$q),
        .clock(out_s_x$1$clock)
    );
    top$core$cnt_nf out_s_x$2(
        .d(out_s_x$2$d),
        .q(out_s_x$2$q),
        .clock(out_s_x$2$clock)
    );
    top$core$cnt_nf out_s_b$0(
        .d(out_s_b$0$d),
        .q(out_s_b$0$q),
        .clock(out_s_b$0$clock)
    );
    top$core$cnt_nf out_s_b$1(
        .d(out_s_b$1$d),
        .q(out_s_b$1$q),
        .clock(out_s_b$1$clock)
    );
    top$core$cnt_nf out_s_b$2(
        .d(out_s_b$2$d),
        .q(out_s_b$2$q),
        .clock(out_s_b$2$clock)
    );
    top$core$done_r out_cross_t$0(
        .d(out_cross_t$0$d),
        .q(out_cross_t$0$q),
        .clock(out_cross_t$0$clock)
    );
    top$core$done_r out_cross_t$1(
        .d(out_cross_t$1$d),
        .q(out_cross_t$1$q),
        .clock(out_cross_t$1$clock)
    );
    top$core$done_r out_cross_t$2(
        .d(out_cross_t$2$d),
        .q(out_cross_t$2$q),
        .clock(out_cross_t$2$clock)
    );
    top$core$done_r out_cross_f$0(
        .d(out_cross_f$0$d),
        .q(out_cross_f$0$q),
        .clock(out_cross_f$0$clock)
    );
    top$core$done_r out_cross_f$1(
        .d(out_cross_f$1$d),
        .q(out_cross_f$1$q),
        .clock(out_cross_f$1$clock)
    );
    top$core$done_r out_cross_f$2(
        .d(out_cross_f$2$d),
        .q(out_cross_f$2$q),
        .clock(out_cross_f$2$clock)
    );
    top$core$done_r out_hit(
        .d(out_hit$d),
        .q(out_hit$q),
        .clock(out_hit$clock)
    );
    top$core$done_r out_miss(
        .d(out_miss$d),
        .q(out_miss$q),
        .clock(out_miss$clock)
    );
    top$core$cnt_nf out_tag(
        .d(out_tag$d),
        .q(out_tag$q),
        .clock(out_tag$clock)
    );
    top$core$done_r out_valid(
        .d(out_valid$d),
        .q(out_valid$q),
        .clock(out_valid$clock)
    );
    
    // Update code
    always @(*) begin
        in_alpha_m$clock = clock;
        in_alpha_f$clock = clock;
        in_beta_m$clock = clock;
        in_beta_f$clock = clock;
        in_scale$clock = clock;
        in_v_exact$clock = clock;
        in_tag$clock = clock;
        in_valid$clock = clock;
        in_alpha_m$d = in_alpha_m$q;
        in_alpha_f$d = in_alpha_f$q;
        in_beta_m$d = in_beta_m$q;
        in_beta_f$d = in_beta_f$q;
        in_scale$d = in_scale$q;
        in_v_exact$d = in_v_exact$q;
        in_tag$d = in_tag$q;
        in_valid$d = in_valid$q;
        out_hit$clock = clock;
        out_miss$clock = clock;
        out_tag$clock = clock;
        out_valid$clock = clock;
        out_hit$d = out_hit$q;
        out_miss$d = out_miss$q;
        out_tag$d = out_tag$q;
        out_valid$d = out_valid$q;
        c3_0$clock = clock;
        c3_1$clock = clock;
        c3_2$clock = clock;
        am$clock = clock;
        af$clock = clock;
        aerr$clock = clock;
        aerr_wait$clock = clock;
        mg3_0$clock = clock;
        mg3_1$clock = clock;
        mg3_2$clock = clock;
        vc_0$clock = clock;
        vc_1$clock = clock;
        vc_2$clock = clock;
        exact_wait$clock = clock;
        tag_wait$clock = clock;
        valid_wait$clock = clock;
        in_m_0$0$clock = clock;
        in_m_1$0$clock = clock;
        in_m_2$0$clock = clock;
        in_f_0$0$clock = clock;
        in_f_1$0$clock = clock;
        in_f_2$0$clock = clock;
        in_m_0$0$d = m_0$0;
        in_m_1$0$d = m_1$0;
        in_m_2$0$d = m_2$0;
        in_f_0$0$d = f_0$0;
        in_f_1$0$d = f_1$0;
        in_f_2$0$d = f_2$0;
        in_m_0$1$clock = clock;
        in_m_1$1$clock = clock;
        in_m_2$1$clock = clock;
        in_f_0$1$clock = clock;
        in_f_1$1$clock = clock;
        in_f_2$1$clock = clock;
        in_m_0$1$d = m_0$1;
        in_m_1$1$d = m_1$1;
        in_m_2$1$d = m_2$1;
        in_f_0$1$d = f_0$1;
        in_f_1$1$d = f_1$1;
        in_f_2$1$d = f_2$1;
        in_m_0$2$clock = clock;
        in_m_1$2$clock = clock;
        in_m_2$2$clock = clock;
        in_f_0$2$clock = clock;
        in_f_1$2$clock = clock;
        in_f_2$2$clock = clock;
        in_m_0$2$d = m_0$2;
        in_m_1$2$d = m_1$2;
        in_m_2$2$d = m_2$2;
        in_f_0$2$d = f_0$2;
        in_f_1$2$d = f_1$2;
        in_f_2$2$d = f_2$2;
        in_m_0$3$clock = clock;
        in_m_1$3$clock = clock;
        in_m_2$3$clock = clock;
        in_f_0$3$clock = clock;
        in_f_1$3$clock = clock;
        in_f_2$3$clock = clock;
        in_m_0$3$d = m_0$3;
        in_m_1$3$d = m_1$3;
        in_m_2$3$d = m_2$3;
        in_f_0$3$d = f_0$3;
        in_f_1$3$d = f_1$3;
        in_f_2$3$d = f_2$3;
        in_alpha_m$d = alpha_m;
        in_alpha_f$d = alpha_f;
        in_beta_m$d = beta_m;
        in_beta_f$d = beta_f;
        in_scale$d = scale;
        in_v_exact$d = v_exact;
        in_tag$d = tag;
        in_valid$d = valid_in;
        in_v_x$0$clock = clock;
        in_v_y$0$clock = clock;
        in_v_z$0$clock = clock;
        in_v_x$0$d = v_x$0;
        in_v_y$0$d = v_y$0;
        in_v_z$0$d = v_z$0;
        in_v_x$1$clock = clock;
        in_v_y$1$clock = clock;
        in_v_z$1$clock = clock;
        in_v_x$1$d = v_x$1;
        in_v_y$1$d = v_y$1;
        in_v_z$1$d = v_z$1;
        in_v_x$2$clock = clock;
        in_v_y$2$clock = clock;
        in_v_z$2$clock = clock;
        in_v_x$2$d = v_x$2;
        in_v_y$2$d = v_y$2;
        in_v_z$2$d = v_z$2;
        c3_0$d = in_m_0$3$q;
        mb_0$0$clock = clock;
        mg_0$0$clock = clock;
        mb_0$0$a0 = in_m_0$0$q;
        mb_0$0$a1 = in_m_0$1$q;
        mb_0$0$a2 = in_m_0$2$q;
        mb_0$0$b0 = in_f_0$0$q;
        mb_0$0$b1 = in_f_1$0$q;
        mb_0$0$b2 = in_f_2$0$q;
        mb_0$0$c = c3_0$q;
        mg_0$0$a0 = in_m_0$0$q;
        mg_0$0$a1 = in_m_0$1$q;
        mg_0$0$a2 = in_m_0$2$q;
        mg_0$0$b0 = in_f_0$0$q;
        mg_0$0$b1 = in_f_1$0$q;
        mg_0$0$b2 = in_f_2$0$q;
        mg_0$0$c = c3_0$q;
        mbr_0$0$clock = clock;
        mgr_0$0$clock = clock;
        mbr_0$0$d = mb_0$0$y;
        mgr_0$0$d = mg_0$0$y;
        mb_0$1$clock = clock;
        mg_0$1$clock = clock;
        mb_0$1$a0 = in_m_0$0$q;
        mb_0$1$a1 = in_m_0$1$q;
        mb_0$1$a2 = in_m_0$2$q;
        mb_0$1$b0 = in_f_0$1$q;
        mb_0$1$b1 = in_f_1$1$q;
        mb_0$1$b2 = in_f_2$1$q;
        mb_0$1$c = c3_0$q;
        mg_0$1$a0 = in_m_0$0$q;
        mg_0$1$a1 = in_m_0$1$q;
        mg_0$1$a2 = in_m_0$2$q;
        mg_0$1$b0 = in_f_0$1$q;
        mg_0$1$b1 = in_f_1$1$q;
        mg_0$1$b2 = in_f_2$1$q;
        mg_0$1$c = c3_0$q;
        mbr_0$1$clock = clock;
        mgr_0$1$clock = clock;
        mbr_0$1$d = mb_0$1$y;
        mgr_0$1$d = mg_0$1$y;
        mb_0$2$clock = clock;
        mg_0$2$clock = clock;
        mb_0$2$a0 = in_m_0$0$q;
        mb_0$2$a1 = in_m_0$1$q;
        mb_0$2$a2 = in_m_0$2$q;
        mb_0$2$b0 = in_f_0$2$q;
        mb_0$2$b1 = in_f_1$2$q;
        mb_0$2$b2 = in_f_2$2$q;
        mb_0$2$c = c3_0$q;
        mg_0$2$a0 = in_m_0$0$q;
        mg_0$2$a1 = in_m_0$1$q;
        mg_0$2$a2 = in_m_0$2$q;
        mg_0$2$b0 = in_f_0$2$q;
        mg_0$2$b1 = in_f_1$2$q;
        mg_0$2$b2 = in_f_2$2$q;
        mg_0$2$c = c3_0$q;
        mbr_0$2$clock = clock;
        mgr_0$2$clock = clock;
        mbr_0$2$d = mb_0$2$y;
        mgr_0$2$d = mg_0$2$y;
        mb_0$3$clock = clock;
        mg_0$3$clock = clock;
        mb_0$3$a0 = in_m_0$0$q;
        mb_0$3$a1 = in_m_0$1$q;
        mb_0$3$a2 = in_m_0$2$q;
        mb_0$3$b0 = in_f_0$3$q;
        mb_0$3$b1 = in_f_1$3$q;
        mb_0$3$b2 = in_f_2$3$q;
        mb_0$3$c = c3_0$q;
        mg_0$3$a0 = in_m_0$0$q;
        mg_0$3$a1 = in_m_0$1$q;
        mg_0$3$a2 = in_m_0$2$q;
        mg_0$3$b0 = in_f_0$3$q;
        mg_0$3$b1 = in_f_1$3$q;
        mg_0$3$b2 = in_f_2$3$q;
        mg_0$3$c = c3_0$q;
        mbr_0$3$clock = clock;
        mgr_0$3$clock = clock;
        mbr_0$3$d = mb_0$3$y;
        mgr_0$3$d = mg_0$3$y;
        c3_1$d = in_m_1$3$q;
        mb_1$0$clock = clock;
        mg_1$0$clock = clock;
        mb_1$0$a0 = in_m_1$0$q;
        mb_1$0$a1 = in_m_1$1$q;
        mb_1$0$a2 = in_m_1$2$q;
        mb_1$0$b0 = in_f_0$0$q;
        mb_1$0$b1 = in_f_1$0$q;
        mb_1$0$b2 = in_f_2$0$q;
        mb_1$0$c = c3_1$q;
        mg_1$0$a0 = in_m_1$0$q;
        mg_1$0$a1 = in_m_1$1$q;
        mg_1$0$a2 = in_m_1$2$q;
        mg_1$0$b0 = in_f_0$0$q;
        mg_1$0$b1 = in_f_1$0$q;
        mg_1$0$b2 = in_f_2$0$q;
        mg_1$0$c = c3_1$q;
        mbr_1$0$clock = clock;
        mgr_1$0$clock = clock;
        mbr_1$0$d = mb_1$0$y;
        mgr_1$0$d = mg_1$0$y;
        mb_1$1$clock = clock;
        mg_1$1$clock = clock;
        mb_1$1$a0 = in_m_1$0$q;
        mb_1$1$a1 = in_m_1$1$q;
        mb_1$1$a2 = in_m_1$2$q;
        mb_1$1$b0 = in_f_0$1$q;
        mb_1$1$b1 = in_f_1$1$q;
        mb_1$1$b2 = in_f_2$1$q;
        mb_1$1$c = c3_1$q;
        mg_1$1$a0 = in_m_1$0$q;
        mg_1$1$a1 = in_m_1$1$q;
        mg_1$1$a2 = in_m_1$2$q;
        mg_1$1$b0 = in_f_0$1$q;
        mg_1$1$b1 = in_f_1$1$q;
        mg_1$1$b2 = in_f_2$1$q;
        mg_1$1$c = c3_1$q;
        mbr_1$1$clock = clock;
        mgr_1$1$clock = clock;
        mbr_1$1$d = mb_1$1$y;
        mgr_1$1$d = mg_1$1$y;
        mb_1$2$clock = clock;
        mg_1$2$clock = clock;
        mb_1$2$a0 = in_m_1$0$q;
        mb_1$2$a1 = in_m_1$1$q;
        mb_1$2$a2 = in_m_1$2$q;
        mb_1$2$b0 = in_f_0$2$q;
        mb_1$2$b1 = in_f_1$2$q;
        mb_1$2$b2 = in_f_2$2$q;
        mb_1$2$c = c3_1$q;
        mg_1$2$a0 = in_m_1$0$q;
        mg_1$2$a1 = in_m_1$1$q;
        mg_1$2$a2 = in_m_1$2$q;
        mg_1$2$b0 = in_f_0$2$q;
        mg_1$2$b1 = in_f_1$2$q;
        mg_1$2$b2 = in_f_2$2$q;
        mg_1$2$c = c3_1$q;
        mbr_1$2$clock = clock;
        mgr_1$2$clock = clock;
        mbr_1$2$d = mb_1$2$y;
        mgr_1$2$d = mg_1$2$y;
        mb_1$3$clock = clock;
        mg_1$3$clock = clock;
        mb_1$3$a0 = in_m_1$0$q;
        mb_1$3$a1 = in_m_1$1$q;
        mb_1$3$a2 = in_m_1$2$q;
        mb_1$3$b0 = in_f_0$3$q;
        mb_1$3$b1 = in_f_1$3$q;
        mb_1$3$b2 = in_f_2$3$q;
        mb_1$3$c = c3_1$q;
        mg_1$3$a0 = in_m_1$0$q;
        mg_1$3$a1 = in_m_1$1$q;
        mg_1$3$a2 = in_m_1$2$q;
        mg_1$3$b0 = in_f_0$3$q;
        mg_1$3$b1 = in_f_1$3$q;
        mg_1$3$b2 = in_f_2$3$q;
        mg_1$3$c = c3_1$q;
        mbr_1$3$clock = clock;
        mgr_1$3$clock = clock;
        mbr_1$3$d = mb_1$3$y;
        mgr_1$3$d = mg_1$3$y;
        c3_2$d = in_m_2$3$q;
        mb_2$0$clock = clock;
        mg_2$0$clock = clock;
        mb_2$0$a0 = in_m_2$0$q;
        mb_2$0$a1 = in_m_2$1$q;
        mb_2$0$a2 = in_m_2$2$q;
        mb_2$0$b0 = in_f_0$0$q;
        mb_2$0$b1 = in_f_1$0$q;
        mb_2$0$b2 = in_f_2$0$q;
        mb_2$0$c = c3_2$q;
        mg_2$0$a0 = in_m_2$0$q;
        mg_2$0$a1 = in_m_2$1$q;
        mg_2$0$a2 = in_m_2$2$q;
        mg_2$0$b0 = in_f_0$0$q;
        mg_2$0$b1 = in_f_1$0$q;
        mg_2$0$b2 = in_f_2$0$q;
        mg_2$0$c = c3_2$q;
        mbr_2$0$clock = clock;
        mgr_2$0$clock = clock;
        mbr_2$0$d = mb_2$0$y;
        mgr_2$0$d = mg_2$0$y;
        mb_2$1$clock = clock;
        mg_2$1$clock = clock;
        mb_2$1$a0 = in_m_2$0$q;
        mb_2$1$a1 = in_m_2$1$q;
        mb_2$1$a2 = in_m_2$2$q;
        mb_2$1$b0 = in_f_0$1$q;
        mb_2$1$b1 = in_f_1$1$q;
        mb_2$1$b2 = in_f_2$1$q;
        mb_2$1$c = c3_2$q;
        mg_2$1$a0 = in_m_2$0$q;
        mg_2$1$a1 = in_m_2$1$q;
        mg_2$1$a2 = in_m_2$2$q;
        mg_2$1$b0 = in_f_0$1$q;
        mg_2$1$b1 = in_f_1$1$q;
        mg_2$1$b2 = in_f_2$1$q;
        mg_2$1$c = c3_2$q;
        mbr_2$1$clock = clock;
        mgr_2$1$clock = clock;
        mbr_2$1$d = mb_2$1$y;
        mgr_2$1$d = mg_2$1$y;
        mb_2$2$clock = clock;
        mg_2$2$clock = clock;
        mb_2$2$a0 = in_m_2$0$q;
        mb_2$2$a1 = in_m_2$1$q;
        mb_2$2$a2 = in_m_2$2$q;
        mb_2$2$b0 = in_f_0$2$q;
        mb_2$2$b1 = in_f_1$2$q;
        mb_2$2$b2 = in_f_2$2$q;
        mb_2$2$c = c3_2$q;
        mg_2$2$a0 = in_m_2$0$q;
        mg_2$2$a1 = in_m_2$1$q;
        mg_2$2$a2 = in_m_2$2$q;
        mg_2$2$b0 = in_f_0$2$q;
        mg_2$2$b1 = in_f_1$2$q;
        mg_2$2$b2 = in_f_2$2$q;
        mg_2$2$c = c3_2$q;
        mbr_2$2$clock = clock;
        mgr_2$2$clock = clock;
        mbr_2$2$d = mb_2$2$y;
        mgr_2$2$d = mg_2$2$y;
        mb_2$3$clock = clock;
        mg_2$3$clock = clock;
        mb_2$3$a0 = in_m_2$0$q;
        mb_2$3$a1 = in_m_2$1$q;
        mb_2$3$a2 = in_m_2$2$q;
        mb_2$3$b0 = in_f_0$3$q;
        mb_2$3$b1 = in_f_1$3$q;
        mb_2$3$b2 = in_f_2$3$q;
        mb_2$3$c = c3_2$q;
        mg_2$3$a0 = in_m_2$0$q;
        mg_2$3$a1 = in_m_2$1$q;
        mg_2$3$a2 = in_m_2$2$q;
        mg_2$3$b0 = in_f_0$3$q;
        mg_2$3$b1 = in_f_1$3$q;
        mg_2$3$b2 = in_f_2$3$q;
        mg_2$3$c = c3_2$q;
        mbr_2$3$clock = clock;
        mgr_2$3$clock = clock;
        mbr_2$3$d = mb_2$3$y;
        mgr_2$3$d = mg_2$3$y;
        am$a = in_alpha_m$q;
        am$b = in_beta_m$q;
        am$valid_in = 1'b0;
        af$a = in_alpha_f$q;
        af$b = in_beta_f$q;
        af$valid_in = 1'b0;
        aerr$a = am$y;
        aerr$b = af$y;
        aerr$sub = 1'b0;
        aerr$valid_in = 1'b0;
        aerr_wait$d = aerr$y;
        la$0$clock = clock;
        lb$0$clock = clock;
        l1$0$clock = clock;
        l1_wait$0$clock = clock;
        err$0$clock = clock;
        la$0$a = in_v_x$0$q & mask;
        la$0$b = in_v_y$0$q & mask;
        lb$0$a = in_v_z$0$q & mask;
        lb$0$b = in_scale$q;
        l1$0$a = la$0$y;
        l1$0$b = lb$0$y;
        la$0$sub = 1'b0;
        lb$0$sub = 1'b0;
        l1$0$sub = 1'b0;
        la$0$valid_in = 1'b0;
        lb$0$valid_in = 1'b0;
        l1$0$valid_in = 1'b0;
        l1_wait$0$d = l1$0$y;
        err$0$a = aerr_wait$q;
        err$0$b = l1_wait$0$q;
        err$0$valid_in = 1'b0;
        v_x_wait$0$clock = clock;
        v_y_wait$0$clock = clock;
        v_z_wait$0$clock = clock;
        v_x_wait$0$d = in_v_x$0$q;
        v_y_wait$0$d = in_v_y$0$q;
        v_z_wait$0$d = in_v_z$0$q;
        la$1$clock = clock;
        lb$1$clock = clock;
        l1$1$clock = clock;
        l1_wait$1$clock = clock;
        err$1$clock = clock;
        la$1$a = in_v_x$1$q & mask;
        la$1$b = in_v_y$1$q & mask;
        lb$1$a = in_v_z$1$q & mask;
        lb$1$b = in_scale$q;
        l1$1$a = la$1$y;
        l1$1$b = lb$1$y;
        la$1$sub = 1'b0;
        lb$1$sub = 1'b0;
        l1$1$sub = 1'b0;
        la$1$valid_in = 1'b0;
        lb$1$valid_in = 1'b0;
        l1$1$valid_in = 1'b0;
        l1_wait$1$d = l1$1$y;
        err$1$a = aerr_wait$q;
        err$1$b = l1_wait$1$q;
        err$1$valid_in = 1'b0;
        v_x_wait$1$clock = clock;
        v_y_wait$1$clock = clock;
        v_z_wait$1$clock = clock;
        v_x_wait$1$d = in_v_x$1$q;
        v_y_wait$1$d = in_v_y$1$q;
        v_z_wait$1$d = in_v_z$1$q;
        la$2$clock = clock;
        lb$2$clock = clock;
        l1$2$clock = clock;
        l1_wait$2$clock = clock;
        err$2$clock = clock;
        la$2$a = in_v_x$2$q & mask;
        la$2$b = in_v_y$2$q & mask;
        lb$2$a = in_v_z$2$q & mask;
        lb$2$b = in_scale$q;
        l1$2$a = la$2$y;
        l1$2$b = lb$2$y;
        la$2$sub = 1'b0;
        lb$2$sub = 1'b0;
        l1$2$sub = 1'b0;
        la$2$valid_in = 1'b0;
        lb$2$valid_in = 1'b0;
        l1$2$valid_in = 1'b0;
        l1_wait$2$d = l1$2$y;
        err$2$a = aerr_wait$q;
        err$2$b = l1_wait$2$q;
        err$2$valid_in = 1'b0;
        v_x_wait$2$clock = clock;
        v_y_wait$2$clock = clock;
        v_z_wait$2$clock = clock;
        v_x_wait$2$d = in_v_x$2$q;
        v_y_wait$2$d = in_v_y$2$q;
        v_z_wait$2$d = in_v_z$2$q;
        mg3_0$d = mgr_0$3$q;
        vc_0$d = mbr_0$3$q;
        m3_0$0$clock = clock;
        m3_0$0$a = mg3_0$q;
        m3_0$0$b = err$0$y;
        m3_0$0$sub = 1'b0;
        m3_0$0$valid_in = 1'b0;
        vt_0$0$clock = clock;
        vm_0$0$clock = clock;
        vt_0$0$a0 = mbr_0$0$q;
        vt_0$0$a1 = mbr_0$1$q;
        vt_0$0$a2 = mbr_0$2$q;
        vt_0$0$b0 = v_x_wait$0$q;
        vt_0$0$b1 = v_y_wait$0$q;
        vt_0$0$b2 = v_z_wait$0$q;
        vt_0$0$c = vc_0$q;
        vm_0$0$a0 = mgr_0$0$q;
        vm_0$0$a1 = mgr_0$1$q;
        vm_0$0$a2 = mgr_0$2$q;
        vm_0$0$b0 = v_x_wait$0$q;
        vm_0$0$b1 = v_y_wait$0$q;
        vm_0$0$b2 = v_z_wait$0$q;
        vm_0$0$c = m3_0$0$y;
        vtr_0$0$clock = clock;
        vmr_0$0$clock = clock;
        vtr_0$0$d = vt_0$0$y;
        vmr_0$0$d = vm_0$0$y;
        m3_0$1$clock = clock;
        m3_0$1$a = mg3_0$q;
        m3_0$1$b = err$1$y;
        m3_0$1$sub = 1'b0;
        m3_0$1$valid_in = 1'b0;
        vt_0$1$clock = clock;
        vm_0$1$clock = clock;
        vt_0$1$a0 = mbr_0$0$q;
        vt_0$1$a1 = mbr_0$1$q;
        vt_0$1$a2 = mbr_0$2$q;
        vt_0$1$b0 = v_x_wait$1$q;
        vt_0$1$b1 = v_y_wait$1$q;
        vt_0$1$b2 = v_z_wait$1$q;
        vt_0$1$c = vc_0$q;
        vm_0$1$a0 = mgr_0$0$q;
        vm_0$1$a1 = mgr_0$1$q;
        vm_0$1$a2 = mgr_0$2$q;
        vm_0$1$b0 = v_x_wait$1$q;
        vm_0$1$b1 = v_y_wait$1$q;
        vm_0$1$b2 = v_z_wait$1$q;
        vm_0$1$c = m3_0$1$y;
        vtr_0$1$clock = clock;
        vmr_0$1$clock = clock;
        vtr_0$1$d = vt_0$1$y;
        vmr_0$1$d = vm_0$1$y;
        m3_0$2$clock = clock;
        m3_0$2$a = mg3_0$q;
        m3_0$2$b = err$2$y;
        m3_0$2$sub = 1'b0;
        m3_0$2$valid_in = 1'b0;
        vt_0$2$clock = clock;
        vm_0$2$clock = clock;
        vt_0$2$a0 = mbr_0$0$q;
        vt_0$2$a1 = mbr_0$1$q;
        vt_0$2$a2 = mbr_0$2$q;
        vt_0$2$b0 = v_x_wait$2$q;
        vt_0$2$b1 = v_y_wait$2$q;
        vt_0$2$b2 = v_z_wait$2$q;
        vt_0$2$c = vc_0$q;
        vm_0$2$a0 = mgr_0$0$q;
        vm_0$2$a1 = mgr_0$1$q;
        vm_0$2$a2 = mgr_0$2$q;
        vm_0$2$b0 = v_x_wait$2$q;
        vm_0$2$b1 = v_y_wait$2$q;
        vm_0$2$b2 = v_z_wait$2$q;
        vm_0$2$c = m3_0$2$y;
        vtr_0$2$clock = clock;
        vmr_0$2$clock = clock;
        vtr_0$2$d = vt_0$2$y;
        vmr_0$2$d = vm_0$2$y;
        mg3_1$d = mgr_1$3$q;
        vc_1$d = mbr_1$3$q;
        m3_1$0$clock = clock;
        m3_1$0$a = mg3_1$q;
        m3_1$0$b = err$0$y;
        m3_1$0$sub = 1'b0;
        m3_1$0$valid_in = 1'b0;
        vt_1$0$clock = clock;
        vm_1$0$clock = clock;
        vt_1$0$a0 = mbr_1$0$q;
        vt_1$0$a1 = mbr_1$1$q;
        vt_1$0$a2 = mbr_1$2$q;
        vt_1$0$b0 = v_x_wait$0$q;
        vt_1$0$b1 = v_y_wait$0$q;
        vt_1$0$b2 = v_z_wait$0$q;
        vt_1$0$c = vc_1$q;
        vm_1$0$a0 = mgr_1$0$q;
        vm_1$0$a1 = mgr_1$1$q;
        vm_1$0$a2 = mgr_1$2$q;
        vm_1$0$b0 = v_x_wait$0$q;
        vm_1$0$b1 = v_y_wait$0$q;
        vm_1$0$b2 = v_z_wait$0$q;
        vm_1$0$c = m3_1$0$y;
        vtr_1$0$clock = clock;
        vmr_1$0$clock = clock;
        vtr_1$0$d = vt_1$0$y;
        vmr_1$0$d = vm_1$0$y;
        m3_1$1$clock = clock;
        m3_1$1$a = mg3_1$q;
        m3_1$1$b = err$1$y;
        m3_1$1$sub = 1'b0;
        m3_1$1$valid_in = 1'b0;
        vt_1$1$clock = clock;
        vm_1$1$clock = clock;
        vt_1$1$a0 = mbr_1$0$q;
        vt_1$1$a1 = mbr_1$1$q;
        vt_1$1$a2 = mbr_1$2$q;
        vt_1$1$b0 = v_x_wait$1$q;
        vt_1$1$b1 = v_y_wait$1$q;
        vt_1$1$b2 = v_z_wait$1$q;
        vt_1$1$c = vc_1$q;
        vm_1$1$a0 = mgr_1$0$q;
        vm_1$1$a1 = mgr_1$1$q;
        vm_1$1$a2 = mgr_1$2$q;
        vm_1$1$b0 = v_x_wait$1$q;
        vm_1$1$b1 = v_y_wait$1$q;
        vm_1$1$b2 = v_z_wait$1$q;
        vm_1$1$c = m3_1$1$y;
        vtr_1$1$clock = clock;
        vmr_1$1$clock = clock;
        vtr_1$1$d = vt_1$1$y;
        vmr_1$1$d = vm_1$1$y;
        m3_1$2$clock = clock;
        m3_1$2$a = mg3_1$q;
        m3_1$2$b = err$2$y;
        m3_1$2$sub = 1'b0;
        m3_1$2$valid_in = 1'b0;
        vt_1$2$clock = clock;
        vm_1$2$clock = clock;
        vt_1$2$a0 = mbr_1$0$q;
        vt_1$2$a1 = mbr_1$1$q;
        vt_1$2$a2 = mbr_1$2$q;
        vt_1$2$b0 = v_x_wait$2$q;
        vt_1$2$b1 = v_y_wait$2$q;
        vt_1$2$b2 = v_z_wait$2$q;
        vt_1$2$c = vc_1$q;
        vm_1$2$a0 = mgr_1$0$q;
        vm_1$2$a1 = mgr_1$1$q;
        vm_1$2$a2 = mgr_1$2$q;
        vm_1$2$b0 = v_x_wait$2$q;
        vm_1$2$b1 = v_y_wait$2$q;
        vm_1$2$b2 = v_z_wait$2$q;
        vm_1$2$c = m3_1$2$y;
        vtr_1$2$clock = clock;
        vmr_1$2$clock = clock;
        vtr_1$2$d = vt_1$2$y;
        vmr_1$2$d = vm_1$2$y;
        mg3_2$d = mgr_2$3$q;
        vc_2$d = mbr_2$3$q;
        m3_2$0$clock = clock;
        m3_2$0$a = mg3_2$q;
        m3_2$0$b = err$0$y;
        m3_2$0$sub = 1'b0;
        m3_2$0$valid_in = 1'b0;
        vt_2$0$clock = clock;
        vm_2$0$clock = clock;
        vt_2$0$a0 = mbr_2$0$q;
        vt_2$0$a1 = mbr_2$1$q;
        vt_2$0$a2 = mbr_2$2$q;
        vt_2$0$b0 = v_x_wait$0$q;
        vt_2$0$b1 = v_y_wait$0$q;
        vt_2$0$b2 = v_z_wait$0$q;
        vt_2$0$c = vc_2$q;
        vm_2$0$a0 = mgr_2$0$q;
        vm_2$0$a1 = mgr_2$1$q;
        vm_2$0$a2 = mgr_2$2$q;
        vm_2$0$b0 = v_x_wait$0$q;
        vm_2$0$b1 = v_y_wait$0$q;
        vm_2$0$b2 = v_z_wait$0$q;
        vm_2$0$c = m3_2$0$y;
        vtr_2$0$clock = clock;
        vmr_2$0$clock = clock;
        vtr_2$0$d = vt_2$0$y;
        vmr_2$0$d = vm_2$0$y;
        m3_2$1$clock = clock;
        m3_2$1$a = mg3_2$q;
        m3_2$1$b = err$1$y;
        m3_2$1$sub = 1'b0;
        m3_2$1$valid_in = 1'b0;
        vt_2$1$clock = clock;
        vm_2$1$clock = clock;
        vt_2$1$a0 = mbr_2$0$q;
        vt_2$1$a1 = mbr_2$1$q;
        vt_2$1$a2 = mbr_2$2$q;
        vt_2$1$b0 = v_x_wait$1$q;
        vt_2$1$b1 = v_y_wait$1$q;
        vt_2$1$b2 = v_z_wait$1$q;
        vt_2$1$c = vc_2$q;
        vm_2$1$a0 = mgr_2$0$q;
        vm_2$1$a1 = mgr_2$1$q;
        vm_2$1$a2 = mgr_2$2$q;
        vm_2$1$b0 = v_x_wait$1$q;
        vm_2$1$b1 = v_y_wait$1$q;
        vm_2$1$b2 = v_z_wait$1$q;
        vm_2$1$c = m3_2$1$y;
        vtr_2$1$clock = clock;
        vmr_2$1$clock = clock;
        vtr_2$1$d = vt_2$1$y;
        vmr_2$1$d = vm_2$1$y;
        m3_2$2$clock = clock;
        m3_2$2$a = mg3_2$q;
        m3_2$2$b = err$2$y;
        m3_2$2$sub = 1'b0;
        m3_2$2$valid_in = 1'b0;
        vt_2$2$clock = clock;
        vm_2$2$clock = clock;
        vt_2$2$a0 = mbr_2$0$q;
        vt_2$2$a1 = mbr_2$1$q;
        vt_2$2$a2 = mbr_2$2$q;
        vt_2$2$b0 = v_x_wait$2$q;
        vt_2$2$b1 = v_y_wait$2$q;
        vt_2$2$b2 = v_z_wait$2$q;
        vt_2$2$c = vc_2$q;
        vm_2$2$a0 = mgr_2$0$q;
        vm_2$2$a1 = mgr_2$1$q;
        vm_2$2$a2 = mgr_2$2$q;
        vm_2$2$b0 = v_x_wait$2$q;
        vm_2$2$b1 = v_y_wait$2$q;
        vm_2$2$b2 = v_z_wait$2$q;
        vm_2$2$c = m3_2$2$y;
        vtr_2$2$clock = clock;
        vmr_2$2$clock = clock;
        vtr_2$2$d = vt_2$2$y;
        vmr_2$2$d = vm_2$2$y;
        exact_wait$d = in_v_exact$q;
        verts$0$clock = clock;
        verts$0$exact = exact_wait$q;
        verts$0$z = vtr_2$0$q;
        verts$0$m0 = vmr_0$0$q;
        verts$0$m1 = vmr_1$0$q;
        verts$0$m2 = vmr_2$0$q;
        verts$1$clock = clock;
        verts$1$exact = exact_wait$q;
        verts$1$z = vtr_2$1$q;
        verts$1$m0 = vmr_0$1$q;
        verts$1$m1 = vmr_1$1$q;
        verts$1$m2 = vmr_2$1$q;
        verts$2$clock = clock;
        verts$2$exact = exact_wait$q;
        verts$2$z = vtr_2$2$q;
        verts$2$m0 = vmr_0$2$q;
        verts$2$m1 = vmr_1$2$q;
        verts$2$m2 = vmr_2$2$q;
        edges$0$p0 = vtr_0$0$q;
        edges$0$p1 = vtr_1$0$q;
        edges$0$p2 = vtr_2$0$q;
        edges$0$q0 = vtr_0$1$q;
        edges$0$q1 = vtr_1$1$q;
        edges$0$q2 = vtr_2$1$q;
        edges$0$pe = verts$0$e;
        edges$0$qe = verts$1$e;
        edges$0$pg = verts$0$g;
        edges$0$qg = verts$1$g;
        edges$0$pf0 = verts$0$f0;
        edges$0$pf1 = verts$0$f1;
        edges$0$pf2 = verts$0$f2;
        edges$0$qf0 = verts$1$f0;
        edges$0$qf1 = verts$1$f1;
        edges$0$qf2 = verts$1$f2;
        edges$0$ph = verts$0$h;
        edges$0$qh = verts$1$h;
        edges$1$p0 = vtr_0$1$q;
        edges$1$p1 = vtr_1$1$q;
        edges$1$p2 = vtr_2$1$q;
        edges$1$q0 = vtr_0$2$q;
        edges$1$q1 = vtr_1$2$q;
        edges$1$q2 = vtr_2$2$q;
        edges$1$pe = verts$1$e;
        edges$1$qe = verts$2$e;
        edges$1$pg = verts$1$g;
        edges$1$qg = verts$2$g;
        edges$1$pf0 = verts$1$f0;
        edges$1$pf1 = verts$1$f1;
        edges$1$pf2 = verts$1$f2;
        edges$1$qf0 = verts$2$f0;
        edges$1$qf1 = verts$2$f1;
        edges$1$qf2 = verts$2$f2;
        edges$1$ph = verts$1$h;
        edges$1$qh = verts$2$h;
        edges$2$p0 = vtr_0$2$q;
        edges$2$p1 = vtr_1$2$q;
        edges$2$p2 = vtr_2$2$q;
        edges$2$q0 = vtr_0$0$q;
        edges$2$q1 = vtr_1$0$q;
        edges$2$q2 = vtr_2$0$q;
        edges$2$pe = verts$2$e;
        edges$2$qe = verts$0$e;
        edges$2$pg = verts$2$g;
        edges$2$qg = verts$0$g;
        edges$2$pf0 = verts$2$f0;
        edges$2$pf1 = verts$2$f1;
        edges$2$pf2 = verts$2$f2;
        edges$2$qf0 = verts$0$f0;
        edges$2$qf1 = verts$0$f1;
        edges$2$qf2 = verts$0$f2;
        edges$2$ph = verts$2$h;
        edges$2$qh = verts$0$h;
        tag_wait$d = in_tag$q;
        valid_wait$d = in_valid$q;
        hit_any = 1'b0;
        miss_all = 1'b1;
        edges$0$clock = clock;
        v_cross_t$0$clock = clock;
        v_cross_f$0$clock = clock;
        v_s_x$0$clock = clock;
        v_s_b$0$clock = clock;
        out_s_x$0$clock = clock;
        out_s_b$0$clock = clock;
        out_cross_t$0$clock = clock;
        out_cross_f$0$clock = clock;
        v_cross_t$0$d = edges$0$cross_t;
        v_cross_f$0$d = edges$0$cross_f;
        v_s_x$0$d = edges$0$s_x;
        v_s_b$0$d = edges$0$s_b;
        out_s_x$0$d = v_s_x$0$q;
        out_s_b$0$d = v_s_b$0$q;
        out_cross_t$0$d = v_cross_t$0$q;
        out_cross_f$0$d = v_cross_f$0$q;
        if (v_cross_t$0$q) begin
            hit_any = 1'b1;
        end
        if (~v_cross_f$0$q) begin
            miss_all = 1'b0;
        end
        s_x$0 = out_s_x$0$q;
        s_b$0 = out_s_b$0$q;
        cross_t$0 = out_cross_t$0$q;
        cross_f$0 = out_cross_f$0$q;
        edges$1$clock = clock;
        v_cross_t$1$clock = clock;
        v_cross_f$1$clock = clock;
        v_s_x$1$clock = clock;
        v_s_b$1$clock = clock;
        out_s_x$1$clock = clock;
        out_s_b$1$clock = clock;
        out_cross_t$1$clock = clock;
        out_cross_f$1$clock = clock;
        v_cross_t$1$d = edges$1$cross_t;
        v_cross_f$1$d = edges$1$cross_f;
        v_s_x$1$d = edges$1$s_x;
        v_s_b$1$d = edges$1$s_b;
        out_s_x$1$d = v_s_x$1$q;
        out_s_b$1$d = v_s_b$1$q;
        out_cross_t$1$d = v_cross_t$1$q;
        out_cross_f$1$d = v_cross_f$1$q;
        if (v_cross_t$1$q) begin
            hit_any = 1'b1;
        end
        if (~v_cross_f$1$q) begin
            miss_all = 1'b0;
        end
        s_x$1 = out_s_x$1$q;
        s_b$1 = out_s_b$1$q;
        cross_t$1 = out_cross_t$1$q;
        cross_f$1 = out_cross_f$1$q;
        edges$2$clock = clock;
        v_cross_t$2$clock = clock;
        v_cross_f$2$clock = clock;
        v_s_x$2$clock = clock;
        v_s_b$2$clock = clock;
        out_s_x$2$clock = clock;
        out_s_b$2$clock = clock;
        out_cross_t$2$clock = clock;
        out_cross_f$2$clock = clock;
        v_cross_t$2$d = edges$2$cross_t;
        v_cross_f$2$d = edges$2$cross_f;
        v_s_x$2$d = edges$2$s_x;
        v_s_b$2$d = edges$2$s_b;
        out_s_x$2$d = v_s_x$2$q;
        out_s_b$2$d = v_s_b$2$q;
        out_cross_t$2$d = v_cross_t$2$q;
        out_cross_f$2$d = v_cross_f$2$q;
        if (v_cross_t$2$q) begin
            hit_any = 1'b1;
        end
        if (~v_cross_f$2$q) begin
            miss_all = 1'b0;
        end
        s_x$2 = out_s_x$2$q;
        s_b$2 = out_s_b$2$q;
        cross_t$2 = out_cross_t$2$q;
        cross_f$2 = out_cross_f$2$q;
        out_hit$d = hit_any;
        out_miss$d = miss_all;
        out_tag$d = tag_wait$q;
        out_valid$d = valid_wait$q;
        hit = out_hit$q;
        miss = out_miss$q;
        tag_out = out_tag$q;
        valid_out = out_valid$q;
    end
    
endmodule // top$tri_unit$tc_ab


module top$tri_unit$tc_ab$aerr(clock,a,b,sub,valid_in,y,valid_out);
    
    // Module arguments
    input wire  clock;
    input wire  [31:0] a;
    input wire  [31:0] b;
    input wire  sub;
    input wire  valid_in;
    output reg  [31:0] y;
    output reg  valid_out;
    
    // Constant declarations
    localparam  round_up = 1'b1;
    localparam  c_align_cap = 8'h1b;
    localparam  c_exp_ones = 10'b11111111;
    
    // Stub signals
    reg  [31:0] unpack_a$x;
    wire  unpack_a$sign;
    wire  [7:0] unpack_a$exp;
    wire  [23:0] unpack_a$sig;
    wire  unpack_a$is_zero;
    wire  unpack_a$is_inf;
    wire  unpack_a$is_nan;
    reg  [31:0] unpack_b$x;
    wire  unpack_b$sign;
    wire  [7:0] unpack_b$exp;
    wire  [23:0] unpack_b$sig;
    wire  unpack_b$is_zero;
    wire  unpack_b$is_inf;
    wire  unpack_b$is_nan;
    reg  s1_valid$d;
    wire  s1_valid$q;
    reg  s1_valid$clock;
    reg  s1_nan$d;
    wire  s1_nan$q;
    reg  s1_nan$clock;
    reg  s1_inf$d;
    wire  s1_inf$q;
    reg  s1_inf$clock;
    reg  s1_inf_sign$d;
    wire  s1_inf_sign$q;
    reg  s1_inf_sign$clock;
    reg  s1_zero_sign$d;
    wire  s1_zero_sign$q;
    reg  s1_zero_sign$clock;
    reg  s1_sign$d;
    wire  s1_sign$q;
    reg  s1_sign$clock;
    reg  s1_eff_sub$d;
    wire  s1_eff_sub$q;
    reg  s1_eff_sub$clock;
    reg  [7:0] s1_exp$d;
    wire  [7:0] s1_exp$q;
    reg  s1_exp$clock;
    reg  [26:0] s1_big$d;
    wire  [26:0] s1_big$q;
    reg  s1_big$clock;
    reg  [26:0] s1_small$d;
    wire  [26:0] s1_small$q;
    reg  s1_small$clock;
    reg  [26:0] norm$x;
    wire  [26:0] norm$y;
    wire  [4:0] norm$lz;
    reg  s2_valid$d;
    wire  s2_valid$q;
    reg  s2_valid$clock;
    reg  s2_sign$d;
    wire  s2_sign$q;
    reg  s2_sign$clock;
    reg  s2_nan$d;
    wire  s2_nan$q;
    reg  s2_nan$clock;
    reg  s2_inf$d;
    wire  s2_inf$q;
    reg  s2_inf$clock;
    reg  s2_zero$d;
    wire  s2_zero$q;
    reg  s2_zero$clock;
    reg  s2_ovf$d;
    wire  s2_ovf$q;
    reg  s2_ovf$clock;
    reg  [7:0] s2_efield$d;
    wire  [7:0] s2_efield$q;
    reg  s2_efield$clock;
    reg  [25:0] s2_nm$d;
    wire  [25:0] s2_nm$q;
    reg  s2_nm$clock;
    reg  round$round_up;
    reg  round$sign;
    reg  round$nan;
    reg  round$inf;
    reg  round$zero;
    reg  round$ovf;
    reg  [7:0] round$efield;
    reg  [25:0] round$nm;
    wire  [31:0] round$y;
    reg  s3_valid$d;
    wire  s3_valid$q;
    reg  s3_valid$clock;
    reg  [31:0] s3_y$d;
    wire  [31:0] s3_y$q;
    reg  s3_y$clock;
    
    // Local signals
    reg  c1_b_sign;
    reg  c1_swap;
    reg  c1_big_sign;
    reg  [7:0] c1_big_exp;
    reg  [23:0] c1_big_sig;
    reg  c1_small_sign;
    reg  [7:0] c1_small_exp;
    reg  [23:0] c1_small_sig;
    reg  [7:0] c1_diff;
    reg  [7:0] c1_shift;
    reg  [26:0] c1_small_ext;
    reg  [26:0] c1_aligned;
    reg  [26:0] c1_back;
    reg  c1_lost;
    reg  c1_inf_sign;
    reg  [27:0] c2_sum;
    reg  c2_carry;
    reg  c2_zero;
    reg  [7:0] c2_limit;
    reg  [7:0] c2_lz;
    reg  [7:0] c2_shift;
    reg  [26:0] c2_shifted;
    reg  [9:0] c2_exp;
    reg  [25:0] c2_nm;
    reg  c2_sign;
    
    // Sub module instances
    top$core$dop$dot_l$add_0$unpack_a unpack_a(
        .x(unpack_a$x),
        .sign(unpack_a$sign),
        .exp(unpack_a$exp),
        .sig(unpack_a$sig),
        .is_zero(unpack_a$is_zero),
        .is_inf(unpack_a$is_inf),
        .is_nan(unpack_a$is_nan)
    );
    top$core$dop$dot_l$add_0$unpack_a unpack_b(
        .x(unpack_b$x),
        .sign(unpack_b$sign),
        .exp(unpack_b$exp),
        .sig(unpack_b$sig),
        .is_zero(unpack_b$is_zero),
        .is_inf(unpack_b$is_inf),
        .is_nan(unpack_b$is_nan)
    );
    top$core$done_r s1_valid(
        .d(s1_valid$d),
        .q(s1_valid$q),
        .clock(s1_valid$clock)
    );
    top$core$done_r s1_nan(
        .d(s1_nan$d),
        .q(s1_nan$q),
        .clock(s1_nan$clock)
    );
    top$core$done_r s1_inf(
        .d(s1_inf$d),
        .q(s1_inf$q),
        .clock(s1_inf$clock)
    );
    top$core$done_r s1_inf_sign(
        .d(s1_inf_sign$d),
        .q(s1_inf_sign$q),
        .clock(s1_inf_sign$clock)
    );
    top$core$done_r s1_zero_sign(
        .d(s1_zero_sign$d),
        .q(s1_zero_sign$q),
        .clock(s1_zero_sign$clock)
    );
    top$core$done_r s1_sign(
        .d(s1_sign$d),
        .q(s1_sign$q),
        .clock(s1_sign$clock)
    );
    top$core$done_r s1_eff_sub(
        .d(s1_eff_sub$d),
        .q(s1_eff_sub$q),
        .clock(s1_eff_sub$clock)
    );
    top$core$dop$bank$s1_lanes s1_exp(
        .d(s1_exp$d),
        .q(s1_exp$q),
        .clock(s1_exp$clock)
    );
    top$core$dop$dot_l$add_0$s1_big s1_big(
        .d(s1_big$d),
        .q(s1_big$q),
        .clock(s1_big$clock)
    );
    top$core$dop$dot_l$add_0$s1_big s1_small(
        .d(s1_small$d),
        .q(s1_small$q),
        .clock(s1_small$clock)
    );
    top$core$dop$dot_l$add_0$norm norm(
        .x(norm$x),
        .y(norm$y),
        .lz(norm$lz)
    );
    top$core$done_r s2_valid(
        .d(s2_valid$d),
        .q(s2_valid$q),
        .clock(s2_valid$clock)
    );
    top$core$done_r s2_sign(
        .d(s2_sign$d),
        .q(s2_sign$q),
        .clock(s2_sign$clock)
    );
    top$core$done_r s2_nan(
        .d(s2_nan$d),
        .q(s2_nan$q),
        .clock(s2_nan$clock)
    );
    top$core$done_r s2_inf(
        .d(s2_inf$d),
        .q(s2_inf$q),
        .clock(s2_inf$clock)
    );
    top$core$done_r s2_zero(
        .d(s2_zero$d),
        .q(s2_zero$q),
        .clock(s2_zero$clock)
    );
    top$core$done_r s2_ovf(
        .d(s2_ovf$d),
        .q(s2_ovf$q),
        .clock(s2_ovf$clock)
    );
    top$core$dop$bank$s1_lanes s2_efield(
        .d(s2_efield$d),
        .q(s2_efield$q),
        .clock(s2_efield$clock)
    );
    top$core$dop$dot_l$add_0$s2_nm s2_nm(
        .d(s2_nm$d),
        .q(s2_nm$q),
        .clock(s2_nm$clock)
    );
    top$core$dop$dot_l$add_0$round round(
        .round_up(round$round_up),
        .sign(round$sign),
        .nan(round$nan),
        .inf(round$inf),
        .zero(round$zero),
        .ovf(round$ovf),
        .efield(round$efield),
        .nm(round$nm),
        .y(round$y)
    );
    top$core$done_r s3_valid(
        .d(s3_valid$d),
        .q(s3_valid$q),
        .clock(s3_valid$clock)
    );
    top$core$cnt_nf s3_y(
        .d(s3_y$d),
        .q(s3_y$q),
        .clock(s3_y$clock)
    );
    
    // Update code
    always @(*) begin
        s1_valid$clock = clock;
        s1_nan$clock = clock;
        s1_inf$clock = clock;
        s1_inf_sign$clock = clock;
        s1_zero_sign$clock = clock;
        s1_sign$clock = clock;
        s1_eff_sub$clock = clock;
        s1_exp$clock = clock;
        s1_big$clock = clock;
        s1_small$clock = clock;
        s1_valid$d = s1_valid$q;
        s1_nan$d = s1_nan$q;
        s1_inf$d = s1_inf$q;
        s1_inf_sign$d = s1_inf_sign$q;
        s1_zero_sign$d = s1_zero_sign$q;
        s1_sign$d = s1_sign$q;
        s1_eff_sub$d = s1_eff_sub$q;
        s1_exp$d = s1_exp$q;
        s1_big$d = s1_big$q;
        s1_small$d = s1_small$q;
        s2_valid$clock = clock;
        s2_sign$clock = clock;
        s2_nan$clock = clock;
        s2_inf$clock = clock;
        s2_zero$clock = clock;
        s2_ovf$clock = clock;
        s2_efield$clock = clock;
        s2_nm$clock = clock;
        s2_valid$d = s2_valid$q;
        s2_sign$d = s2_sign$q;
        s2_nan$d = s2_nan$q;
        s2_inf$d = s2_inf$q;
        s2_zero$d = s2_zero$q;
        s2_ovf$d = s2_ovf$q;
        s2_efield$d = s2_efield$q;
        s2_nm$d = s2_nm$q;
        s3_valid$clock = clock;
        s3_y$clock = clock;
        s3_valid$d = s3_valid$q;
        s3_y$d = s3_y$q;
        unpack_a$x = a;
        unpack_b$x = b;
        c1_b_sign = unpack_b$sign ^ sub;
        c1_swap = a[(32'h0)+:(31)] < b[(32'h0)+:(31)];
        c1_big_sign = unpack_a$sign;
        c1_big_exp = unpack_a$exp;
        c1_big_sig = unpack_a$sig;
        c1_small_sign = c1_b_sign;
        c1_small_exp = unpack_b$exp;
        c1_small_sig = unpack_b$sig;
        if (c1_swap) begin
            c1_big_sign = c1_b_sign;
            c1_big_exp = unpack_b$exp;
            c1_big_sig = unpack_b$sig;
            c1_small_sign = unpack_a$sign;
            c1_small_exp = unpack_a$exp;
            c1_small_sig = unpack_a$sig;
        end
        c1_diff = c1_big_exp - c1_small_exp;
        c1_shift = c1_diff;
        if (c1_diff > c_align_cap) begin
            c1_shift = c_align_cap;
        end
        c1_small_ext = ((c1_small_sig) & 27'h7ffffff) << 32'h3;
        c1_aligned = c1_small_ext >> c1_shift;
        c1_back = c1_aligned << c1_shift;
        c1_lost = c1_back != c1_small_ext;
        c1_inf_sign = c1_b_sign;
        if (unpack_a$is_inf) begin
            c1_inf_sign = unpack_a$sign;
        end
        s1_valid$d = valid_in;
        s1_nan$d = unpack_a$is_nan | unpack_b$is_nan | (unpack_a$is_inf & unpack_b$is_inf & (unpack_a$sign ^ c1_b_sign));
        s1_inf$d = unpack_a$is_inf | unpack_b$is_inf;
        s1_inf_sign$d = c1_inf_sign;
        s1_zero_sign$d = unpack_a$sign & c1_b_sign;
        s1_sign$d = c1_big_sign;
        s1_eff_sub$d = c1_big_sign ^ c1_small_sign;
        s1_exp$d = c1_big_exp;
        s1_big$d = ((c1_big_sig) & 27'h7ffffff) << 32'h3;
        s1_small$d = (c1_aligned & ~(1 << (32'h0)) | ((c1_aligned[32'h0] | c1_lost) << (32'h0)));
        c2_sum = ((s1_big$q) & 28'hfffffff) + ((s1_small$q) & 28'hfffffff);
        if (s1_eff_sub$q) begin
            c2_sum = ((s1_big$q) & 28'hfffffff) - ((s1_small$q) & 28'hfffffff);
        end
        c2_carry = c2_sum[32'h1b];
        c2_zero = c2_sum == 32'h0;
        norm$x = c2_sum[(32'h0)+:(27)];
        c2_limit = s1_exp$q - 32'h1;
        c2_lz = ((norm$lz) & 8'hff);
        c2_shift = c2_lz;
        if (c2_lz > c2_limit) begin
            c2_shift = c2_limit;
        end
        c2_shifted = c2_sum[(32'h0)+:(27)] << c2_shift;
        c2_exp = ((s1_exp$q) & 10'h3ff) - ((c2_shift) & 10'h3ff);
        c2_nm = (((c2_shifted >> 32'h1) & 26'h3ffffff) & ~(1 << (32'h0)) | ((c2_shifted[32'h1] | c2_shifted[32'h0]) << (32'h0)));
        if (c2_carry) begin
            c2_exp = ((s1_exp$q) & 10'h3ff) + 32'h1;
            c2_nm = (((c2_sum >> 32'h2) & 26'h3ffffff) & ~(1 << (32'h0)) | ((c2_sum[32'h2] | c2_sum[32'h1] | c2_sum[32'h0]) << (32'h0)));
        end
        c2_sign = s1_sign$q;
        if (c2_zero) begin
            c2_sign = s1_zero_sign$q;
        end
        if (s1_inf$q) begin
            c2_sign = s1_inf_sign$q;
        end
        s2_valid$d = s1_valid$q;
        s2_sign$d = c2_sign;
        s2_nan$d = s1_nan$q;
        s2_inf$d = s1_inf$q;
        s2_zero$d = c2_zero;
        s2_ovf$d = c2_exp >= c_exp_ones;
        s2_efield$d = 32'h0;
        if (c2_nm[32'h18 + 32'h1]) begin
            s2_efield$d = ((c2_exp) & 8'hff);
        end
        s2_nm$d = c2_nm;
        round$round_up = round_up;
        round$sign = s2_sign$q;
        round$nan = s2_nan$q;
        round$inf = s2_inf$q;
        round$zero = s2_zero$q;
        round$ovf = s2_ovf$q;
        round$efield = s2_efield$q;
        round$nm = s2_nm$q;
        s3_valid$d = s2_valid$q;
        s3_y$d = round$y;
        y = s3_y$q;
        valid_out = s3_valid$q;
    end
    
endmodule // top$tri_unit$tc_ab$aerr


module top$tri_unit$tc_ab$aerr_wait(clock,d,q);
    
    // Module arguments
    input wire  clock;
    input wire  [31:0] d;
    output reg  [31:0] q;
    
    // Stub signals
    reg  [31:0] line$0$d;
    wire  [31:0] line$0$q;
    reg  line$0$clock;
    
    // Sub module instances
    top$core$cnt_nf line$0(
        .d(line$0$d),
        .q(line$0$q),
        .clock(line$0$clock)
    );
    
    // Update code
    always @(*) begin
        line$0$clock = clock;
        line$0$d = d;
        q = line$0$q;
    end
    
endmodule // top$tri_unit$tc_ab$aerr_wait


module top$tri_unit$tc_ab$af(clock,a,b,valid_in,y,valid_out);
    
    // Module arguments
    input wire  clock;
    input wire  [31:0] a;
    input wire  [31:0] b;
    input wire  valid_in;
    output reg  [31:0] y;
    output reg  valid_out;
    
    // Constant declarations
    localparam  round_up = 1'b1;
    localparam  c_exp_adj = 10'b10000001;
    localparam  c_exp_ofs = 10'b100000000;
    localparam  c_exp_norm_min = 10'b100000001;
    localparam  c_exp_ovf = 10'b111111111;
    localparam  c_shift_cap = 10'b11010;
    
    // Stub signals
    reg  [31:0] unpack_a$x;
    wire  unpack_a$sign;
    wire  [7:0] unpack_a$exp;
    wire  [23:0] unpack_a$sig;
    wire  unpack_a$is_zero;
    wire  unpack_a$is_inf;
    wire  unpack_a$is_nan;
    reg  [31:0] unpack_b$x;
    wire  unpack_b$sign;
    wire  [7:0] unpack_b$exp;
    wire  [23:0] unpack_b$sig;
    wire  unpack_b$is_zero;
    wire  unpack_b$is_inf;
    wire  unpack_b$is_nan;
    reg  [23:0] norm_a$x;
    wire  [23:0] norm_a$y;
    wire  [4:0] norm_a$lz;
    reg  [23:0] norm_b$x;
    wire  [23:0] norm_b$y;
    wire  [4:0] norm_b$lz;
    reg  s1_valid$d;
    wire  s1_valid$q;
    reg  s1_valid$clock;
    reg  s1_sign$d;
    wire  s1_sign$q;
    reg  s1_sign$clock;
    reg  s1_nan$d;
    wire  s1_nan$q;
    reg  s1_nan$clock;
    reg  s1_inf$d;
    wire  s1_inf$q;
    reg  s1_inf$clock;
    reg  s1_zero$d;
    wire  s1_zero$q;
    reg  s1_zero$clock;
    reg  [9:0] s1_exp$d;
    wire  [9:0] s1_exp$q;
    reg  s1_exp$clock;
    reg  [23:0] s1_sig_a$d;
    wire  [23:0] s1_sig_a$q;
    reg  s1_sig_a$clock;
    reg  [23:0] s1_sig_b$d;
    wire  [23:0] s1_sig_b$q;
    reg  s1_sig_b$clock;
    reg  [23:0] sig_mul$a;
    reg  [23:0] sig_mul$b;
    wire  [25:0] sig_mul$hi;
    wire  sig_mul$sticky;
    reg  s2_valid$d;
    wire  s2_valid$q;
    reg  s2_valid$clock;
    reg  s2_sign$d;
    wire  s2_sign$q;
    reg  s2_sign$clock;
    reg  s2_nan$d;
    wire  s2_nan$q;
    reg  s2_nan$clock;
    reg  s2_inf$d;
    wire  s2_inf$q;
    reg  s2_inf$clock;
    reg  s2_zero$d;
    wire  s2_zero$q;
    reg  s2_zero$clock;
    reg  [9:0] s2_exp$d;
    wire  [9:0] s2_exp$q;
    reg  s2_exp$clock;
    reg  [25:0] s2_hi$d;
    wire  [25:0] s2_hi$q;
    reg  s2_hi$clock;
    reg  s2_sticky$d;
    wire  s2_sticky$q;
    reg  s2_sticky$clock;
    reg  s3_valid$d;
    wire  s3_valid$q;
    reg  s3_valid$clock;
    reg  s3_sign$d;
    wire  s3_sign$q;
    reg  s3_sign$clock;
    reg  s3_nan$d;
    wire  s3_nan$q;
    reg  s3_nan$clock;
    reg  s3_inf$d;
    wire  s3_inf$q;
    reg  s3_inf$clock;
    reg  s3_zero$d;
    wire  s3_zero$q;
    reg  s3_zero$clock;
    reg  s3_ovf$d;
    wire  s3_ovf$q;
    reg  s3_ovf$clock;
    reg  [7:0] s3_efield$d;
    wire  [7:0] s3_efield$q;
    reg  s3_efield$clock;
    reg  [25:0] s3_nm$d;
    wire  [25:0] s3_nm$q;
    reg  s3_nm$clock;
    reg  round$round_up;
    reg  round$sign;
    reg  round$nan;
    reg  round$inf;
    reg  round$zero;
    reg  round$ovf;
    reg  [7:0] round$efield;
    reg  [25:0] round$nm;
    wire  [31:0] round$y;
    reg  s4_valid$d;
    wire  s4_valid$q;
    reg  s4_valid$clock;
    reg  [31:0] s4_y$d;
    wire  [31:0] s4_y$q;
    reg  s4_y$clock;
    
    // Local signals
    reg  [9:0] c1_exp;
    reg  c3_top;
    reg  [25:0] c3_nm;
    reg  [9:0] c3_exp;
    reg  [9:0] c3_shift;
    reg  [9:0] c3_shift_cap;
    reg  [25:0] c3_shifted;
    reg  [25:0] c3_back;
    reg  c3_lost;
    reg  [7:0] c3_efield;
    
    // Sub module instances
    top$core$dop$dot_l$add_0$unpack_a unpack_a(
        .x(unpack_a$x),
        .sign(unpack_a$sign),
        .exp(unpack_a$exp),
        .sig(unpack_a$sig),
        .is_zero(unpack_a$is_zero),
        .is_inf(unpack_a$is_inf),
        .is_nan(unpack_a$is_nan)
    );
    top$core$dop$dot_l$add_0$unpack_a unpack_b(
        .x(unpack_b$x),
        .sign(unpack_b$sign),
        .exp(unpack_b$exp),
        .sig(unpack_b$sig),
        .is_zero(unpack_b$is_zero),
        .is_inf(unpack_b$is_inf),
        .is_nan(unpack_b$is_nan)
    );
    top$core$dop$dot_l$mul_0$norm_a norm_a(
        .x(norm_a$x),
        .y(norm_a$y),
        .lz(norm_a$lz)
    );
    top$core$dop$dot_l$mul_0$norm_a norm_b(
        .x(norm_b$x),
        .y(norm_b$y),
        .lz(norm_b$lz)
    );
    top$core$done_r s1_valid(
        .d(s1_valid$d),
        .q(s1_valid$q),
        .clock(s1_valid$clock)
    );
    top$core$done_r s1_sign(
        .d(s1_sign$d),
        .q(s1_sign$q),
        .clock(s1_sign$clock)
    );
    top$core$done_r s1_nan(
        .d(s1_nan$d),
        .q(s1_nan$q),
        .clock(s1_nan$clock)
    );
    top$core$done_r s1_inf(
        .d(s1_inf$d),
        .q(s1_inf$q),
        .clock(s1_inf$clock)
    );
    top$core$done_r s1_zero(
        .d(s1_zero$d),
        .q(s1_zero$q),
        .clock(s1_zero$clock)
    );
    top$core$dop$dot_l$mul_0$s1_exp s1_exp(
        .d(s1_exp$d),
        .q(s1_exp$q),
        .clock(s1_exp$clock)
    );
    top$core$base_na s1_sig_a(
        .d(s1_sig_a$d),
        .q(s1_sig_a$q),
        .clock(s1_sig_a$clock)
    );
    top$core$base_na s1_sig_b(
        .d(s1_sig_b$d),
        .q(s1_sig_b$q),
        .clock(s1_sig_b$clock)
    );
    top$core$dop$dot_l$mul_0$sig_mul sig_mul(
        .a(sig_mul$a),
        .b(sig_mul$b),
        .hi(sig_mul$hi),
        .sticky(sig_mul$sticky)
    );
    top$core$done_r s2_valid(
        .d(s2_valid$d),
        .q(s2_valid$q),
        .clock(s2_valid$clock)
    );
    top$core$done_r s2_sign(
        .d(s2_sign$d),
        .q(s2_sign$q),
        .clock(s2_sign$clock)
    );
    top$core$done_r s2_nan(
        .d(s2_nan$d),
        .q(s2_nan$q),
        .clock(s2_nan$clock)
    );
    top$core$done_r s2_inf(
        .d(s2_inf$d),
        .q(s2_inf$q),
        .clock(s2_inf$clock)
    );
    top$core$done_r s2_zero(
        .d(s2_zero$d),
        .q(s2_zero$q),
        .clock(s2_zero$clock)
    );
    top$core$dop$dot_l$mul_0$s1_exp s2_exp(
        .d(s2_exp$d),
        .q(s2_exp$q),
        .clock(s2_exp$clock)
    );
    top$core$dop$dot_l$add_0$s2_nm s2_hi(
        .d(s2_hi$d),
        .q(s2_hi$q),
        .clock(s2_hi$clock)
    );
    top$core$done_r s2_sticky(
        .d(s2_sticky$d),
        .q(s2_sticky$q),
        .clock(s2_sticky$clock)
    );
    top$core$done_r s3_valid(
        .d(s3_valid$d),
        .q(s3_valid$q),
        .clock(s3_valid$clock)
    );
    top$core$done_r s3_sign(
        .d(s3_sign$d),
        .q(s3_sign$q),
        .clock(s3_sign$clock)
    );
    top$core$done_r s3_nan(
        .d(s3_nan$d),
        .q(s3_nan$q),
        .clock(s3_nan$clock)
    );
    top$core$done_r s3_inf(
        .d(s3_inf$d),
        .q(s3_inf$q),
        .clock(s3_inf$clock)
    );
    top$core$done_r s3_zero(
        .d(s3_zero$d),
        .q(s3_zero$q),
        .clock(s3_zero$clock)
    );
    top$core$done_r s3_ovf(
        .d(s3_ovf$d),
        .q(s3_ovf$q),
        .clock(s3_ovf$clock)
    );
    top$core$dop$bank$s1_lanes s3_efield(
        .d(s3_efield$d),
        .q(s3_efield$q),
        .clock(s3_efield$clock)
    );
    top$core$dop$dot_l$add_0$s2_nm s3_nm(
        .d(s3_nm$d),
        .q(s3_nm$q),
        .clock(s3_nm$clock)
    );
    top$core$dop$dot_l$add_0$round round(
        .round_up(round$round_up),
        .sign(round$sign),
        .nan(round$nan),
        .inf(round$inf),
        .zero(round$zero),
        .ovf(round$ovf),
        .efield(round$efield),
        .nm(round$nm),
        .y(round$y)
    );
    top$core$done_r s4_valid(
        .d(s4_valid$d),
        .q(s4_valid$q),
        .clock(s4_valid$clock)
    );
    top$core$cnt_nf s4_y(
        .d(s4_y$d),
        .q(s4_y$q),
        .clock(s4_y$clock)
    );
    
    // Update code
    always @(*) begin
        s1_valid$clock = clock;
        s1_sign$clock = clock;
        s1_nan$clock = clock;
        s1_inf$clock = clock;
        s1_zero$clock = clock;
        s1_exp$clock = clock;
        s1_sig_a$clock = clock;
        s1_sig_b$clock = clock;
        s1_valid$d = s1_valid$q;
        s1_sign$d = s1_sign$q;
        s1_nan$d = s1_nan$q;
        s1_inf$d = s1_inf$q;
        s1_zero$d = s1_zero$q;
        s1_exp$d = s1_exp$q;
        s1_sig_a$d = s1_sig_a$q;
        s1_sig_b$d = s1_sig_b$q;
        s2_valid$clock = clock;
        s2_sign$clock = clock;
        s2_nan$clock = clock;
        s2_inf$clock = clock;
        s2_zero$clock = clock;
        s2_exp$clock = clock;
        s2_hi$clock = clock;
        s2_sticky$clock = clock;
        s2_valid$d = s2_valid$q;
        s2_sign$d = s2_sign$q;
        s2_nan$d = s2_nan$q;
        s2_inf$d = s2_inf$q;
        s2_zero$d = s2_zero$q;
        s2_exp$d = s2_exp$q;
        s2_hi$d = s2_hi$q;
        s2_sticky$d = s2_sticky$q;
        s3_valid$clock = clock;
        s3_sign$clock = clock;
        s3_nan$clock = clock;
        s3_inf$clock = clock;
        s3_zero$clock = clock;
        s3_ovf$clock = clock;
        s3_efield$clock = clock;
        s3_nm$clock = clock;
        s3_valid$d = s3_valid$q;
        s3_sign$d = s3_sign$q;
        s3_nan$d = s3_nan$q;
        s3_inf$d = s3_inf$q;
        s3_zero$d = s3_zero$q;
        s3_ovf$d = s3_ovf$q;
        s3_efield$d = s3_efield$q;
        s3_nm$d = s3_nm$q;
        s4_valid$clock = clock;
        s4_y$clock = clock;
        s4_valid$d = s4_valid$q;
        s4_y$d = s4_y$q;
        unpack_a$x = a;
        unpack_b$x = b;
        norm_a$x = unpack_a$sig;
        norm_b$x = unpack_b$sig;
        c1_exp = ((unpack_a$exp) & 10'h3ff) + ((unpack_b$exp) & 10'h3ff) - ((norm_a$lz) & 10'h3ff) - ((norm_b$lz) & 10'h3ff) + c_exp_adj;
        s1_valid$d = valid_in;
        s1_sign$d = unpack_a$sign ^ unpack_b$sign;
        s1_nan$d = unpack_a$is_nan | unpack_b$is_nan | (unpack_a$is_inf & unpack_b$is_zero) | (unpack_a$is_zero & unpack_b$is_inf);
        s1_inf$d = unpack_a$is_inf | unpack_b$is_inf;
        s1_zero$d = unpack_a$is_zero | unpack_b$is_zero;
        s1_exp$d = c1_exp;
        s1_sig_a$d = norm_a$y;
        s1_sig_b$d = norm_b$y;
        sig_mul$a = s1_sig_a$q;
        sig_mul$b = s1_sig_b$q;
        s2_valid$d = s1_valid$q;
        s2_sign$d = s1_sign$q;
        s2_nan$d = s1_nan$q;
        s2_inf$d = s1_inf$q;
        s2_zero$d = s1_zero$q;
        s2_exp$d = s1_exp$q;
        s2_hi$d = sig_mul$hi;
        s2_sticky$d = sig_mul$sticky;
        c3_top = s2_hi$q[32'h18 + 32'h1];
        c3_nm = ((s2_hi$q << 32'h1) & ~(1 << (32'h0)) | ((s2_sticky$q) << (32'h0)));
        if (c3_top) begin
            c3_nm = (s2_hi$q & ~(1 << (32'h0)) | ((s2_hi$q[32'h0] | s2_sticky$q) << (32'h0)));
        end
        c3_exp = s2_exp$q + c3_top;
        c3_shift = 32'h0;
        if (c3_exp < c_exp_norm_min) begin
            c3_shift = c_exp_norm_min - c3_exp;
        end
        c3_shift_cap = c3_shift;
        if (c3_shift > c_shift_cap) begin
            c3_shift_cap = c_shift_cap;
        end
        c3_shifted = c3_nm >> c3_shift_cap;
        c3_back = c3_shifted << c3_shift_cap;
        c3_lost = c3_back != c3_nm;
        c3_efield = 32'h0;
        if (c3_shift == 32'h0) begin
            c3_efield = ((c3_exp - c_exp_ofs) & 8'hff);
        end
        s3_valid$d = s2_valid$q;
        s3_sign$d = s2_sign$q;
        s3_nan$d = s2_nan$q;
        s3_inf$d = s2_inf$q;
        s3_zero$d = s2_zero$q;
        s3_ovf$d = c3_exp >= c_exp_ovf;
        s3_efield$d = c3_efield;
        s3_nm$d = (c3_shifted & ~(1 << (32'h0)) | ((c3_shifted[32'h0] | c3_lost) << (32'h0)));
        round$round_up = round_up;
        round$sign = s3_sign$q;
        round$nan = s3_nan$q;
        round$inf = s3_inf$q;
        round$zero = s3_zero$q;
        round$ovf = s3_ovf$q;
        round$efield = s3_efield$q;
        round$nm = s3_nm$q;
        s4_valid$d = s3_valid$q;
        s4_y$d = round$y;
        y = s4_y$q;
        valid_out = s4_valid$q;
    end
    
endmodule // top$tri_unit$tc_ab$af


module top$tri_unit$tc_ab$c3_0(clock,d,q);
    
    // Module arguments
    input wire  clock;
    input wire  [31:0] d;
    output reg  [31:0] q;
    
    // Stub signals
    reg  [31:0] line$0$d;
    wire  [31:0] line$0$q;
    reg  line$0$clock;
    reg  [31:0] line$1$d;
    wire  [31:0] line$1$q;
    reg  line$1$clock;
    reg  [31:0] line$2$d;
    wire  [31:0] line$2$q;
    reg  line$2$clock;
    reg  [31:0] line$3$d;
    wire  [31:0] line$3$q;
    reg  line$3$clock;
    
    // Sub module instances
    top$core$cnt_nf line$0(
        .d(line$0$d),
        .q(line$0$q),
        .clock(line$0$clock)
    );
    top$core$cnt_nf line$1(
        .d(line$1$d),
        .q(line$1$q),
        .clock(line$1$clock)
    );
    top$core$cnt_nf line$2(
        .d(line$2$d),
        .q(line$2$q),
        .clock(line$2$clock)
    );
    top$core$cnt_nf line$3(
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
    
endmodule // top$tri_unit$tc_ab$c3_0


module top$tri_unit$tc_ab$edges$0(clock,p0,p1,p2,q0,q1,q2,pe,qe,pg,qg,pf0,pf1,pf2,qf0,qf1,qf2,ph,qh,s_x,s_b,cross_t,cross_f);
    
    // Module arguments
    input wire  clock;
    input wire  [31:0] p0;
    input wire  [31:0] p1;
    input wire  [31:0] p2;
    input wire  [31:0] q0;
    input wire  [31:0] q1;
    input wire  [31:0] q2;
    input wire  [31:0] pe;
    input wire  [31:0] qe;
    input wire  [31:0] pg;
    input wire  [31:0] qg;
    input wire  [31:0] pf0;
    input wire  [31:0] pf1;
    input wire  [31:0] pf2;
    input wire  [31:0] qf0;
    input wire  [31:0] qf1;
    input wire  [31:0] qf2;
    input wire  [31:0] ph;
    input wire  [31:0] qh;
    output reg  [31:0] s_x;
    output reg  [31:0] s_b;
    output reg  cross_t;
    output reg  cross_f;
    
    // Constant declarations
    localparam  mask = 32'h7fffffff;
    
    // Stub signals
    reg  px_qz$clock;
    reg  [31:0] px_qz$a;
    reg  [31:0] px_qz$b;
    reg  px_qz$valid_in;
    wire  [31:0] px_qz$y;
    wire  px_qz$valid_out;
    reg  qx_pz$clock;
    reg  [31:0] qx_pz$a;
    reg  [31:0] qx_pz$b;
    reg  qx_pz$valid_in;
    wire  [31:0] qx_pz$y;
    wire  qx_pz$valid_out;
    reg  py_qz$clock;
    reg  [31:0] py_qz$a;
    reg  [31:0] py_qz$b;
    reg  py_qz$valid_in;
    wire  [31:0] py_qz$y;
    wire  py_qz$valid_out;
    reg  qy_pz$clock;
    reg  [31:0] qy_pz$a;
    reg  [31:0] qy_pz$b;
    reg  qy_pz$valid_in;
    wire  [31:0] qy_pz$y;
    wire  qy_pz$valid_out;
    reg  a$clock;
    reg  [31:0] a$a;
    reg  [31:0] a$b;
    reg  a$sub;
    reg  a$valid_in;
    wire  [31:0] a$y;
    wire  a$valid_out;
    reg  b$clock;
    reg  [31:0] b$a;
    reg  [31:0] b$b;
    reg  b$sub;
    reg  b$valid_in;
    wire  [31:0] b$y;
    wire  b$valid_out;
    reg  rz$clock;
    reg  [31:0] rz$a;
    reg  [31:0] rz$b;
    reg  rz$sub;
    reg  rz$valid_in;
    wire  [31:0] rz$y;
    wire  rz$valid_out;
    reg  rz_wait$clock;
    reg  [31:0] rz_wait$d;
    wire  [31:0] rz_wait$q;
    reg  ab$clock;
    reg  [31:0] ab$a;
    reg  [31:0] ab$b;
    reg  ab$sub;
    reg  ab$valid_in;
    wire  [31:0] ab$y;
    wire  ab$valid_out;
    reg  s$clock;
    reg  [31:0] s$a;
    reg  [31:0] s$b;
    reg  s$sub;
    reg  s$valid_in;
    wire  [31:0] s$y;
    wire  s$valid_out;
    reg  pf0_wait$clock;
    reg  [31:0] pf0_wait$d;
    wire  [31:0] pf0_wait$q;
    reg  qf0_wait$clock;
    reg  [31:0] qf0_wait$d;
    wire  [31:0] qf0_wait$q;
    reg  pf1_wait$clock;
    reg  [31:0] pf1_wait$d;
    wire  [31:0] pf1_wait$q;
    reg  qf1_wait$clock;
    reg  [31:0] qf1_wait$d;
    wire  [31:0] qf1_wait$q;
    reg  p0_wait$clock;
    reg  [31:0] p0_wait$d;
    wire  [31:0] p0_wait$q;
    reg  q0_wait$clock;
    reg  [31:0] q0_wait$d;
    wire  [31:0] q0_wait$q;
    reg  p1_wait$clock;
    reg  [31:0] p1_wait$d;
    wire  [31:0] p1_wait$q;
    reg  q1_wait$clock;
    reg  [31:0] q1_wait$d;
    wire  [31:0] q1_wait$q;
    reg  ta$0$clock;
    reg  [31:0] ta$0$a;
    reg  [31:0] ta$0$b;
    reg  ta$0$valid_in;
    wire  [31:0] ta$0$y;
    wire  ta$0$valid_out;
    reg  ta$1$clock;
    reg  [31:0] ta$1$a;
    reg  [31:0] ta$1$b;
    reg  ta$1$valid_in;
    wire  [31:0] ta$1$y;
    wire  ta$1$valid_out;
    reg  ta$2$clock;
    reg  [31:0] ta$2$a;
    reg  [31:0] ta$2$b;
    reg  ta$2$valid_in;
    wire  [31:0] ta$2$y;
    wire  ta$2$valid_out;
    reg  ta$3$clock;
    reg  [31:0] ta$3$a;
    reg  [31:0] ta$3$b;
    reg  ta$3$valid_in;
    wire  [31:0] ta$3$y;
    wire  ta$3$valid_out;
    reg  tb$0$clock;
    reg  [31:0] tb$0$a;
    reg  [31:0] tb$0$b;
    reg  tb$0$valid_in;
    wire  [31:0] tb$0$y;
    wire  tb$0$valid_out;
    reg  tb$1$clock;
    reg  [31:0] tb$1$a;
    reg  [31:0] tb$1$b;
    reg  tb$1$valid_in;
    wire  [31:0] tb$1$y;
    wire  tb$1$valid_out;
    reg  tb$2$clock;
    reg  [31:0] tb$2$a;
    reg  [31:0] tb$2$b;
    reg  tb$2$valid_in;
    wire  [31:0] tb$2$y;
    wire  tb$2$valid_out;
    reg  tb$3$clock;
    reg  [31:0] tb$3$a;
    reg  [31:0] tb$3$b;
    reg  tb$3$valid_in;
    wire  [31:0] tb$3$y;
    wire  tb$3$valid_out;
    reg  ta_wait$0$clock;
    reg  [31:0] ta_wait$0$d;
    wire  [31:0] ta_wait$0$q;
    reg  ta_wait$1$clock;
    reg  [31:0] ta_wait$1$d;
    wire  [31:0] ta_wait$1$q;
    reg  tb_wait$0$clock;
    reg  [31:0] tb_wait$0$d;
    wire  [31:0] tb_wait$0$q;
    reg  tb_wait$1$clock;
    reg  [31:0] tb_wait$1$d;
    wire  [31:0] tb_wait$1$q;
    reg  sa$0$clock;
    reg  [31:0] sa$0$a;
    reg  [31:0] sa$0$b;
    reg  sa$0$sub;
    reg  sa$0$valid_in;
    wire  [31:0] sa$0$y;
    wire  sa$0$valid_out;
    reg  sa$1$clock;
    reg  [31:0] sa$1$a;
    reg  [31:0] sa$1$b;
    reg  sa$1$sub;
    reg  sa$1$valid_in;
    wire  [31:0] sa$1$y;
    wire  sa$1$valid_out;
    reg  sb$0$clock;
    reg  [31:0] sb$0$a;
    reg  [31:0] sb$0$b;
    reg  sb$0$sub;
    reg  sb$0$valid_in;
    wire  [31:0] sb$0$y;
    wire  sb$0$valid_out;
    reg  sb$1$clock;
    reg  [31:0] sb$1$a;
    reg  [31:0] sb$1$b;
    reg  sb$1$sub;
    reg  sb$1$valid_in;
    wire  [31:0] sb$1$y;
    wire  sb$1$valid_out;
    reg  ba$clock;
    reg  [31:0] ba$a;
    reg  [31:0] ba$b;
    reg  ba$sub;
    reg  ba$valid_in;
    wire  [31:0] ba$y;
    wire  ba$valid_out;
    reg  bb$clock;
    reg  [31:0] bb$a;
    reg  [31:0] bb$b;
    reg  bb$sub;
    reg  bb$valid_in;
    wire  [31:0] bb$y;
    wire  bb$valid_out;
    reg  brz$clock;
    reg  [31:0] brz$a;
    reg  [31:0] brz$b;
    reg  brz$sub;
    reg  brz$valid_in;
    wire  [31:0] brz$y;
    wire  brz$valid_out;
    reg  brz_wait$clock;
    reg  [31:0] brz_wait$d;
    wire  [31:0] brz_wait$q;
    reg  rab$clock;
    reg  [31:0] rab$a;
    reg  [31:0] rab$b;
    reg  rab$sub;
    reg  rab$valid_in;
    wire  [31:0] rab$y;
    wire  rab$valid_out;
    reg  rabz$clock;
    reg  [31:0] rabz$a;
    reg  [31:0] rabz$b;
    reg  rabz$sub;
    reg  rabz$valid_in;
    wire  [31:0] rabz$y;
    wire  rabz$valid_out;
    reg  rs$clock;
    reg  [31:0] rs$a;
    reg  rs$sel;
    wire  [31:0] rs$y;
    reg  brs$clock;
    reg  [31:0] brs$a;
    reg  [31:0] brs$b;
    reg  brs$sub;
    reg  brs$valid_in;
    wire  [31:0] brs$y;
    wire  brs$valid_out;
    reg  brs_wait$clock;
    reg  [31:0] brs_wait$d;
    wire  [31:0] brs_wait$q;
    reg  bab$clock;
    reg  [31:0] bab$a;
    reg  [31:0] bab$b;
    reg  bab$sub;
    reg  bab$valid_in;
    wire  [31:0] bab$y;
    wire  bab$valid_out;
    reg  bs$clock;
    reg  [31:0] bs$a;
    reg  [31:0] bs$b;
    reg  bs$sub;
    reg  bs$valid_in;
    wire  [31:0] bs$y;
    wire  bs$valid_out;
    reg  pz_wait$clock;
    reg  [31:0] pz_wait$d;
    wire  [31:0] pz_wait$q;
    reg  qz_wait$clock;
    reg  [31:0] qz_wait$d;
    wire  [31:0] qz_wait$q;
    reg  a_wait$clock;
    reg  [31:0] a_wait$d;
    wire  [31:0] a_wait$q;
    reg  b_wait$clock;
    reg  [31:0] b_wait$d;
    wire  [31:0] b_wait$q;
    reg  s_wait$clock;
    reg  [31:0] s_wait$d;
    wire  [31:0] s_wait$q;
    reg  [31:0] sign_pz$x;
    reg  [31:0] sign_pz$e;
    wire  [1:0] sign_pz$sgn;
    reg  [31:0] sign_qz$x;
    reg  [31:0] sign_qz$e;
    wire  [1:0] sign_qz$sgn;
    reg  [31:0] sign_rz$x;
    reg  [31:0] sign_rz$e;
    wire  [1:0] sign_rz$sgn;
    reg  [31:0] sign_a$x;
    reg  [31:0] sign_a$e;
    wire  [1:0] sign_a$sgn;
    reg  [31:0] sign_b$x;
    reg  [31:0] sign_b$e;
    wire  [1:0] sign_b$sgn;
    reg  [31:0] sign_s$x;
    reg  [31:0] sign_s$e;
    wire  [1:0] sign_s$sgn;
    reg  pz_sgn_wait$clock;
    reg  [1:0] pz_sgn_wait$d;
    wire  [1:0] pz_sgn_wait$q;
    reg  qz_sgn_wait$clock;
    reg  [1:0] qz_sgn_wait$d;
    wire  [1:0] qz_sgn_wait$q;
    reg  rz_sgn_wait$clock;
    reg  [1:0] rz_sgn_wait$d;
    wire  [1:0] rz_sgn_wait$q;
    reg  a_sgn_wait$clock;
    reg  [1:0] a_sgn_wait$d;
    wire  [1:0] a_sgn_wait$q;
    reg  b_sgn_wait$clock;
    reg  [1:0] b_sgn_wait$d;
    wire  [1:0] b_sgn_wait$q;
    reg  [1:0] r_pz$d;
    wire  [1:0] r_pz$q;
    reg  r_pz$clock;
    reg  [1:0] r_qz$d;
    wire  [1:0] r_qz$q;
    reg  r_qz$clock;
    reg  [1:0] r_rz$d;
    wire  [1:0] r_rz$q;
    reg  r_rz$clock;
    reg  [1:0] r_a$d;
    wire  [1:0] r_a$q;
    reg  r_a$clock;
    reg  [1:0] r_b$d;
    wire  [1:0] r_b$q;
    reg  r_b$clock;
    reg  [1:0] r_s$d;
    wire  [1:0] r_s$q;
    reg  r_s$clock;
    reg  [31:0] r_s_x$d;
    wire  [31:0] r_s_x$q;
    reg  r_s_x$clock;
    reg  [31:0] r_s_b$d;
    wire  [31:0] r_s_b$q;
    reg  r_s_b$clock;
    
    // Local signals
    reg  pz_p;
    reg  pz_n;
    reg  qz_p;
    reg  qz_n;
    reg  rz_p;
    reg  rz_n;
    reg  a_p;
    reg  a_n;
    reg  b_p;
    reg  b_n;
    reg  s_p;
    reg  s_n;
    
    // Sub module instances
    top$tri_unit$tc_ab$edges$0$px_qz px_qz(
        .clock(px_qz$clock),
        .a(px_qz$a),
        .b(px_qz$b),
        .valid_in(px_qz$valid_in),
        .y(px_qz$y),
        .valid_out(px_qz$valid_out)
    );
    top$tri_unit$tc_ab$edges$0$px_qz qx_pz(
        .clock(qx_pz$clock),
        .a(qx_pz$a),
        .b(qx_pz$b),
        .valid_in(qx_pz$valid_in),
        .y(qx_pz$y),
        .valid_out(qx_pz$valid_out)
    );
    top$tri_unit$tc_ab$edges$0$px_qz py_qz(
        .clock(py_qz$clock),
        .a(py_qz$a),
        .b(py_qz$b),
        .valid_in(py_qz$valid_in),
        .y(py_qz$y),
        .valid_out(py_qz$valid_out)
    );
    top$tri_unit$tc_ab$edges$0$px_qz qy_pz(
        .clock(qy_pz$clock),
        .a(qy_pz$a),
        .b(qy_pz$b),
        .valid_in(qy_pz$valid_in),
        .y(qy_pz$y),
        .valid_out(qy_pz$valid_out)
    );
    top$tri_unit$tc_ab$edges$0$a a(
        .clock(a$clock),
        .a(a$a),
        .b(a$b),
        .sub(a$sub),
        .valid_in(a$valid_in),
        .y(a$y),
        .valid_out(a$valid_out)
    );
    top$tri_unit$tc_ab$edges$0$a b(
        .clock(b$clock),
        .a(b$a),
        .b(b$b),
        .sub(b$sub),
        .valid_in(b$valid_in),
        .y(b$y),
        .valid_out(b$valid_out)
    );
    top$tri_unit$tc_ab$edges$0$a rz(
        .clock(rz$clock),
        .a(rz$a),
        .b(rz$b),
        .sub(rz$sub),
        .valid_in(rz$valid_in),
        .y(rz$y),
        .valid_out(rz$valid_out)
    );
    top$tri_unit$tc_ab$edges$0$brz_wait rz_wait(
        .clock(rz_wait$clock),
        .d(rz_wait$d),
        .q(rz_wait$q)
    );
    top$tri_unit$tc_ab$edges$0$a ab(
        .clock(ab$clock),
        .a(ab$a),
        .b(ab$b),
        .sub(ab$sub),
        .valid_in(ab$valid_in),
        .y(ab$y),
        .valid_out(ab$valid_out)
    );
    top$tri_unit$tc_ab$edges$0$a s(
        .clock(s$clock),
        .a(s$a),
        .b(s$b),
        .sub(s$sub),
        .valid_in(s$valid_in),
        .y(s$y),
        .valid_out(s$valid_out)
    );
    top$tri_unit$tc_ab$edges$0$brs_wait pf0_wait(
        .clock(pf0_wait$clock),
        .d(pf0_wait$d),
        .q(pf0_wait$q)
    );
    top$tri_unit$tc_ab$edges$0$brs_wait qf0_wait(
        .clock(qf0_wait$clock),
        .d(qf0_wait$d),
        .q(qf0_wait$q)
    );
    top$tri_unit$tc_ab$edges$0$brs_wait pf1_wait(
        .clock(pf1_wait$clock),
        .d(pf1_wait$d),
        .q(pf1_wait$q)
    );
    top$tri_unit$tc_ab$edges$0$brs_wait qf1_wait(
        .clock(qf1_wait$clock),
        .d(qf1_wait$d),
        .q(qf1_wait$q)
    );
    top$tri_unit$tc_ab$edges$0$brz_wait p0_wait(
        .clock(p0_wait$clock),
        .d(p0_wait$d),
        .q(p0_wait$q)
    );
    top$tri_unit$tc_ab$edges$0$brz_wait q0_wait(
        .clock(q0_wait$clock),
        .d(q0_wait$d),
        .q(q0_wait$q)
    );
    top$tri_unit$tc_ab$edges$0$brz_wait p1_wait(
        .clock(p1_wait$clock),
        .d(p1_wait$d),
        .q(p1_wait$q)
    );
    top$tri_unit$tc_ab$edges$0$brz_wait q1_wait(
        .clock(q1_wait$clock),
        .d(q1_wait$d),
        .q(q1_wait$q)
    );
    top$tri_unit$tc_ab$af ta$0(
        .clock(ta$0$clock),
        .a(ta$0$a),
        .b(ta$0$b),
        .valid_in(ta$0$valid_in),
        .y(ta$0$y),
        .valid_out(ta$0$valid_out)
    );
    top$tri_unit$tc_ab$af ta$1(
        .clock(ta$1$clock),
        .a(ta$1$a),
        .b(ta$1$b),
        .valid_in(ta$1$valid_in),
        .y(ta$1$y),
        .valid_out(ta$1$valid_out)
    );
    top$tri_unit$tc_ab$af ta$2(
        .clock(ta$2$clock),
        .a(ta$2$a),
        .b(ta$2$b),
        .valid_in(ta$2$valid_in),
        .y(ta$2$y),
        .valid_out(ta$2$valid_out)
    );
    top$tri_unit$tc_ab$af ta$3(
        .clock(ta$3$clock),
        .a(ta$3$a),
        .b(ta$3$b),
        .valid_in(ta$3$valid_in),
        .y(ta$3$y),
        .valid_out(ta$3$valid_out)
    );
    top$tri_unit$tc_ab$af tb$0(
        .clock(tb$0$clock),
        .a(tb$0$a),
        .b(tb$0$b),
        .valid_in(tb$0$valid_in),
        .y(tb$0$y),
        .valid_out(tb$0$valid_out)
    );
    top$tri_unit$tc_ab$af tb$1(
        .clock(tb$1$clock),
        .a(tb$1$a),
        .b(tb$1$b),
        .valid_in(tb$1$valid_in),
        .y(tb$1$y),
        .valid_out(tb$1$valid_out)
    );
    top$tri_unit$tc_ab$af tb$2(
        .clock(tb$2$clock),
        .a(tb$2$a),
        .b(tb$2$b),
        .valid_in(tb$2$valid_in),
        .y(tb$2$y),
        .valid_out(tb$2$valid_out)
    );
    top$tri_unit$tc_ab$af tb$3(
        .clock(tb$3$clock),
        .a(tb$3$a),
        .b(tb$3$b),
        .valid_in(tb$3$valid_in),
        .y(tb$3$y),
        .valid_out(tb$3$valid_out)
    );
    top$tri_unit$tc_ab$edges$0$brs_wait ta_wait$0(
        .clock(ta_wait$0$clock),
        .d(ta_wait$0$d),
        .q(ta_wait$0$q)
    );
    top$tri_unit$tc_ab$edges$0$brs_wait ta_wait$1(
        .clock(ta_wait$1$clock),
        .d(ta_wait$1$d),
        .q(ta_wait$1$q)
    );
    top$tri_unit$tc_ab$edges$0$brs_wait tb_wait$0(
        .clock(tb_wait$0$clock),
        .d(tb_wait$0$d),
        .q(tb_wait$0$q)
    );
    top$tri_unit$tc_ab$edges$0$brs_wait tb_wait$1(
        .clock(tb_wait$1$clock),
        .d(tb_wait$1$d),
        .q(tb_wait$1$q)
    );
    top$tri_unit$tc_ab$aerr sa$0(
        .clock(sa$0$clock),
        .a(sa$0$a),
        .b(sa$0$b),
        .sub(sa$0$sub),
        .valid_in(sa$0$valid_in),
        .y(sa$0$y),
        .valid_out(sa$0$valid_out)
    );
    top$tri_unit$tc_ab$aerr sa$1(
        .clock(sa$1$clock),
        .a(sa$1$a),
        .b(sa$1$b),
        .sub(sa$1$sub),
        .valid_in(sa$1$valid_in),
        .y(sa$1$y),
        .valid_out(sa$1$valid_out)
    );
    top$tri_unit$tc_ab$aerr sb$0(
        .clock(sb$0$clock),
        .a(sb$0$a),
        .b(sb$0$b),
        .sub(sb$0$sub),
        .valid_in(sb$0$valid_in),
        .y(sb$0$y),
        .valid_out(sb$0$valid_out)
    );
    top$tri_unit$tc_ab$aerr sb$1(
        .clock(sb$1$clock),
        .a(sb$1$a),
        .b(sb$1$b),
        .sub(sb$1$sub),
        .valid_in(sb$1$valid_in),
        .y(sb$1$y),
        .valid_out(sb$1$valid_out)
    );
    top$tri_unit$tc_ab$aerr ba(
        .clock(ba$clock),
        .a(ba$a),
        .b(ba$b),
        .sub(ba$sub),
        .valid_in(ba$valid_in),
        .y(ba$y),
        .valid_out(ba$valid_out)
    );
    top$tri_unit$tc_ab$aerr bb(
        .clock(bb$clock),
        .a(bb$a),
        .b(bb$b),
        .sub(bb$sub),
        .valid_in(bb$valid_in),
        .y(bb$y),
        .valid_out(bb$valid_out)
    );
    top$tri_unit$tc_ab$aerr brz(
        .clock(brz$clock),
        .a(brz$a),
        .b(brz$b),
        .sub(brz$sub),
        .valid_in(brz$valid_in),
        .y(brz$y),
        .valid_out(brz$valid_out)
    );
    top$tri_unit$tc_ab$edges$0$brz_wait brz_wait(
        .clock(brz_wait$clock),
        .d(brz_wait$d),
        .q(brz_wait$q)
    );
    top$tri_unit$tc_ab$aerr rab(
        .clock(rab$clock),
        .a(rab$a),
        .b(rab$b),
        .sub(rab$sub),
        .valid_in(rab$valid_in),
        .y(rab$y),
        .valid_out(rab$valid_out)
    );
    top$tri_unit$tc_ab$aerr rabz(
        .clock(rabz$clock),
        .a(rabz$a),
        .b(rabz$b),
        .sub(rabz$sub),
        .valid_in(rabz$valid_in),
        .y(rabz$y),
        .valid_out(rabz$valid_out)
    );
    top$tri_unit$tc_ab$edges$0$rs rs(
        .clock(rs$clock),
        .a(rs$a),
        .sel(rs$sel),
        .y(rs$y)
    );
    top$tri_unit$tc_ab$aerr brs(
        .clock(brs$clock),
        .a(brs$a),
        .b(brs$b),
        .sub(brs$sub),
        .valid_in(brs$valid_in),
        .y(brs$y),
        .valid_out(brs$valid_out)
    );
    top$tri_unit$tc_ab$edges$0$brs_wait brs_wait(
        .clock(brs_wait$clock),
        .d(brs_wait$d),
        .q(brs_wait$q)
    );
    top$tri_unit$tc_ab$aerr bab(
        .clock(bab$clock),
        .a(bab$a),
        .b(bab$b),
        .sub(bab$sub),
        .valid_in(bab$valid_in),
        .y(bab$y),
        .valid_out(bab$valid_out)
    );
    top$tri_unit$tc_ab$aerr bs(
        .clock(bs$clock),
        .a(bs$a),
        .b(bs$b),
        .sub(bs$sub),
        .valid_in(bs$valid_in),
        .y(bs$y),
        .valid_out(bs$valid_out)
    );
    top$tri_unit$tc_ab$c3_0 pz_wait(
        .clock(pz_wait$clock),
        .d(pz_wait$d),
        .q(pz_wait$q)
    );
    top$tri_unit$tc_ab$c3_0 qz_wait(
        .clock(qz_wait$clock),
        .d(qz_wait$d),
        .q(qz_wait$q)
    );
    top$tri_unit$tc_ab$edges$0$a_wait a_wait(
        .clock(a_wait$clock),
        .d(a_wait$d),
        .q(a_wait$q)
    );
    top$tri_unit$tc_ab$edges$0$a_wait b_wait(
        .clock(b_wait$clock),
        .d(b_wait$d),
        .q(b_wait$q)
    );
    top$tri_unit$tc_ab$edges$0$a_wait s_wait(
        .clock(s_wait$clock),
        .d(s_wait$d),
        .q(s_wait$q)
    );
    top$tri_unit$tc_ab$edges$0$sign_a sign_pz(
        .x(sign_pz$x),
        .e(sign_pz$e),
        .sgn(sign_pz$sgn)
    );
    top$tri_unit$tc_ab$edges$0$sign_a sign_qz(
        .x(sign_qz$x),
        .e(sign_qz$e),
        .sgn(sign_qz$sgn)
    );
    top$tri_unit$tc_ab$edges$0$sign_a sign_rz(
        .x(sign_rz$x),
        .e(sign_rz$e),
        .sgn(sign_rz$sgn)
    );
    top$tri_unit$tc_ab$edges$0$sign_a sign_a(
        .x(sign_a$x),
        .e(sign_a$e),
        .sgn(sign_a$sgn)
    );
    top$tri_unit$tc_ab$edges$0$sign_a sign_b(
        .x(sign_b$x),
        .e(sign_b$e),
        .sgn(sign_b$sgn)
    );
    top$tri_unit$tc_ab$edges$0$sign_a sign_s(
        .x(sign_s$x),
        .e(sign_s$e),
        .sgn(sign_s$sgn)
    );
    top$tri_unit$tc_ab$edges$0$pz_sgn_wait pz_sgn_wait(
        .clock(pz_sgn_wait$clock),
        .d(pz_sgn_wait$d),
        .q(pz_sgn_wait$q)
    );
    top$tri_unit$tc_ab$edges$0$pz_sgn_wait qz_sgn_wait(
        .clock(qz_sgn_wait$clock),
        .d(qz_sgn_wait$d),
        .q(qz_sgn_wait$q)
    );
    top$tri_unit$tc_ab$edges$0$rz_sgn_wait rz_sgn_wait(
        .clock(rz_sgn_wait$clock),
        .d(rz_sgn_wait$d),
        .q(rz_sgn_wait$q)
    );
    top$tri_unit$tc_ab$edges$0$a_sgn_wait a_sgn_wait(
        .clock(a_sgn_wait$clock),
        .d(a_sgn_wait$d),
        .q(a_sgn_wait$q)
    );
    top$tri_unit$tc_ab$edges$0$a_sgn_wait b_sgn_wait(
        .clock(b_sgn_wait$clock),
        .d(b_sgn_wait$d),
        .q(b_sgn_wait$q)
    );
    top$core$dop$busy_r r_pz(
        .d(r_pz$d),
        .q(r_pz$q),
        .clock(r_pz$clock)
    );
    top$core$dop$busy_r r_qz(
        .d(r_qz$d),
        .q(r_qz$q),
        .clock(r_qz$clock)
    );
    top$core$dop$busy_r r_rz(
        .d(r_rz$d),
        .q(r_rz$q),
        .clock(r_rz$clock)
    );
    top$core$dop$busy_r r_a(
        .d(r_a$d),
        .q(r_a$q),
        .clock(r_a$clock)
    );
    top$core$dop$busy_r r_b(
        .d(r_b$d),
        .q(r_b$q),
        .clock(r_b$clock)
    );
    top$core$dop$busy_r r_s(
        .d(r_s$d),
        .q(r_s$q),
        .clock(r_s$clock)
    );
    top$core$cnt_nf r_s_x(
        .d(r_s_x$d),
        .q(r_s_x$q),
        .clock(r_s_x$clock)
    );
    top$core$cnt_nf r_s_b(
        .d(r_s_b$d),
        .q(r_s_b$q),
        .clock(r_s_b$clock)
    );
    
    // Update code
    always @(*) begin
        px_qz$clock = clock;
        qx_pz$clock = clock;
        py_qz$clock = clock;
        qy_pz$clock = clock;
        a$clock = clock;
        b$clock = clock;
        rz$clock = clock;
        rz_wait$clock = clock;
        ab$clock = clock;
        s$clock = clock;
        pf0_wait$clock = clock;
        qf0_wait$clock = clock;
        pf1_wait$clock = clock;
        qf1_wait$clock = clock;
        p0_wait$clock = clock;
        q0_wait$clock = clock;
        p1_wait$clock = clock;
        q1_wait$clock = clock;
        ba$clock = clock;
        bb$clock = clock;
        brz$clock = clock;
        brz_wait$clock = clock;
        rab$clock = clock;
        rabz$clock = clock;
        rs$clock = clock;
        brs$clock = clock;
        brs_wait$clock = clock;
        bab$clock = clock;
        bs$clock = clock;
        pz_wait$clock = clock;
        qz_wait$clock = clock;
        a_wait$clock = clock;
        b_wait$clock = clock;
        s_wait$clock = clock;
        pz_sgn_wait$clock = clock;
        qz_sgn_wait$clock = clock;
        rz_sgn_wait$clock = clock;
        a_sgn_wait$clock = clock;
        b_sgn_wait$clock = clock;
        r_pz$clock = clock;
        r_qz$clock = clock;
        r_rz$clock = clock;
        r_a$clock = clock;
        r_b$clock = clock;
        r_s$clock = clock;
        r_s_x$clock = clock;
        r_s_b$clock = clock;
        r_pz$d = r_pz$q;
        r_qz$d = r_qz$q;
        r_rz$d = r_rz$q;
        r_a$d = r_a$q;
        r_b$d = r_b$q;
        r_s$d = r_s$q;
        r_s_x$d = r_s_x$q;
        r_s_b$d = r_s_b$q;
        px_qz$a = p0;
        px_qz$b = q2;
        qx_pz$a = q0;
        qx_pz$b = p2;
        py_qz$a = p1;
        py_qz$b = q2;
        qy_pz$a = q1;
        qy_pz$b = p2;
        px_qz$valid_in = 1'b0;
        qx_pz$valid_in = 1'b0;
        py_qz$valid_in = 1'b0;
        qy_pz$valid_in = 1'b0;
        a$a = px_qz$y;
        a$b = qx_pz$y;
        a$sub = 1'b1;
        a$valid_in = 1'b0;
        b$a = py_qz$y;
        b$b = qy_pz$y;
        b$sub = 1'b1;
        b$valid_in = 1'b0;
        rz$a = q2;
        rz$b = p2;
        rz$sub = 1'b1;
        rz$valid_in = 1'b0;
        rz_wait$d = rz$y;
        ab$a = a$y;
        ab$b = b$y;
        ab$sub = 1'b0;
        ab$valid_in = 1'b0;
        s$a = ab$y;
        s$b = rz_wait$q;
        s$sub = 1'b1;
        s$valid_in = 1'b0;
        pf0_wait$d = pf0;
        qf0_wait$d = qf0;
        pf1_wait$d = pf1;
        qf1_wait$d = qf1;
        p0_wait$d = p0 & mask;
        q0_wait$d = q0 & mask;
        p1_wait$d = p1 & mask;
        q1_wait$d = q1 & mask;
        ta$0$clock = clock;
        tb$0$clock = clock;
        ta$0$valid_in = 1'b0;
        tb$0$valid_in = 1'b0;
        ta$1$clock = clock;
        tb$1$clock = clock;
        ta$1$valid_in = 1'b0;
        tb$1$valid_in = 1'b0;
        ta$2$clock = clock;
        tb$2$clock = clock;
        ta$2$valid_in = 1'b0;
        tb$2$valid_in = 1'b0;
        ta$3$clock = clock;
        tb$3$clock = clock;
        ta$3$valid_in = 1'b0;
        tb$3$valid_in = 1'b0;
        ta$0$a = pf0_wait$q;
        ta$0$b = qh;
        ta$1$a = p0_wait$q;
        ta$1$b = qg;
        ta$2$a = qf0_wait$q;
        ta$2$b = ph;
        ta$3$a = q0_wait$q;
        ta$3$b = pg;
        tb$0$a = pf1_wait$q;
        tb$0$b = qh;
        tb$1$a = p1_wait$q;
        tb$1$b = qg;
        tb$2$a = qf1_wait$q;
        tb$2$b = ph;
        tb$3$a = q1_wait$q;
        tb$3$b = pg;
        ta_wait$0$clock = clock;
        tb_wait$0$clock = clock;
        sa$0$clock = clock;
        sb$0$clock = clock;
        sa$0$sub = 1'b0;
        sb$0$sub = 1'b0;
        sa$0$valid_in = 1'b0;
        sb$0$valid_in = 1'b0;
        ta_wait$1$clock = clock;
        tb_wait$1$clock = clock;
        sa$1$clock = clock;
        sb$1$clock = clock;
        sa$1$sub = 1'b0;
        sb$1$sub = 1'b0;
        sa$1$valid_in = 1'b0;
        sb$1$valid_in = 1'b0;
        ta_wait$0$d = ta$1$y;
        ta_wait$1$d = ta$3$y;
        tb_wait$0$d = tb$1$y;
        tb_wait$1$d = tb$3$y;
        sa$0$a = ta$0$y;
        sa$0$b = ta_wait$0$q;
        sa$1$a = ta$2$y;
        sa$1$b = ta_wait$1$q;
        sb$0$a = tb$0$y;
        sb$0$b = tb_wait$0$q;
        sb$1$a = tb$2$y;
        sb$1$b = tb_wait$1$q;
        ba$a = sa$0$y;
        ba$b = sa$1$y;
        ba$sub = 1'b0;
        ba$valid_in = 1'b0;
        bb$a = sb$0$y;
        bb$b = sb$1$y;
        bb$sub = 1'b0;
        bb$valid_in = 1'b0;
        brz$a = qf2;
        brz$b = pf2;
        brz$sub = 1'b0;
        brz$valid_in = 1'b0;
        brz_wait$d = brz$y;
        rab$a = a$y & mask;
        rab$b = b$y & mask;
        rab$sub = 1'b0;
        rab$valid_in = 1'b0;
        rabz$a = rab$y;
        rabz$b = rz_wait$q & mask;
        rabz$sub = 1'b0;
        rabz$valid_in = 1'b0;
        rs$a = rabz$y;
        rs$sel = 1'b0;
        brs$a = brz_wait$q;
        brs$b = rs$y;
        brs$sub = 1'b0;
        brs$valid_in = 1'b0;
        brs_wait$d = brs$y;
        bab$a = ba$y;
        bab$b = bb$y;
        bab$sub = 1'b0;
        bab$valid_in = 1'b0;
        bs$a = bab$y;
        bs$b = brs_wait$q;
        bs$sub = 1'b0;
        bs$valid_in = 1'b0;
        pz_wait$d = p2;
        qz_wait$d = q2;
        sign_pz$x = pz_wait$q;
        sign_pz$e = pe;
        sign_qz$x = qz_wait$q;
        sign_qz$e = qe;
        sign_rz$x = rz_wait$q;
        sign_rz$e = brz$y;
        a_wait$d = a$y;
        b_wait$d = b$y;
        s_wait$d = s$y;
        sign_a$x = a_wait$q;
        sign_a$e = ba$y;
        sign_b$x = b_wait$q;
        sign_b$e = bb$y;
        sign_s$x = s_wait$q;
        sign_s$e = bs$y;
        pz_sgn_wait$d = sign_pz$sgn;
        qz_sgn_wait$d = sign_qz$sgn;
        rz_sgn_wait$d = sign_rz$sgn;
        a_sgn_wait$d = sign_a$sgn;
        b_sgn_wait$d = sign_b$sgn;
        r_pz$d = pz_sgn_wait$q;
        r_qz$d = qz_sgn_wait$q;
        r_rz$d = rz_sgn_wait$q;
        r_a$d = a_sgn_wait$q;
        r_b$d = b_sgn_wait$q;
        r_s$d = sign_s$sgn;
        r_s_x$d = s_wait$q;
        r_s_b$d = bs$y;
        pz_p = r_pz$q[32'h0];
        pz_n = r_pz$q[32'h1];
        qz_p = r_qz$q[32'h0];
        qz_n = r_qz$q[32'h1];
        rz_p = r_rz$q[32'h0];
        rz_n = r_rz$q[32'h1];
        a_p = r_a$q[32'h0];
        a_n = r_a$q[32'h1];
        b_p = r_b$q[32'h0];
        b_n = r_b$q[32'h1];
        s_p = r_s$q[32'h0];
        s_n = r_s$q[32'h1];
        cross_t = (pz_n & qz_p & rz_p & a_p & b_p & s_n) | (pz_p & qz_n & rz_n & a_n & b_n & s_p);
        cross_f = (pz_p | qz_n | rz_n | a_n | b_n | s_p) & (pz_n | qz_p | rz_p | a_p | b_p | s_n);
        s_x = r_s_x$q;
        s_b = r_s_b$q;
    end
    
endmodule // top$tri_unit$tc_ab$edges$0


module top$tri_unit$tc_ab$edges$0$a(clock,a,b,sub,valid_in,y,valid_out);
    
    // Module arguments
    input wire  clock;
    input wire  [31:0] a;
    input wire  [31:0] b;
    input wire  sub;
    input wire  valid_in;
    output reg  [31:0] y;
    output reg  valid_out;
    
    // Constant declarations
    localparam  round_up = 1'b0;
    localparam  c_align_cap = 8'h1b;
    localparam  c_exp_ones = 10'b11111111;
    
    // Stub signals
    reg  [31:0] unpack_a$x;
    wire  unpack_a$sign;
    wire  [7:0] unpack_a$exp;
    wire  [23:0] unpack_a$sig;
    wire  unpack_a$is_zero;
    wire  unpack_a$is_inf;
    wire  unpack_a$is_nan;
    reg  [31:0] unpack_b$x;
    wire  unpack_b$sign;
    wire  [7:0] unpack_b$exp;
    wire  [23:0] unpack_b$sig;
    wire  unpack_b$is_zero;
    wire  unpack_b$is_inf;
    wire  unpack_b$is_nan;
    reg  s1_valid$d;
    wire  s1_valid$q;
    reg  s1_valid$clock;
    reg  s1_nan$d;
    wire  s1_nan$q;
    reg  s1_nan$clock;
    reg  s1_inf$d;
    wire  s1_inf$q;
    reg  s1_inf$clock;
    reg  s1_inf_sign$d;
    wire  s1_inf_sign$q;
    reg  s1_inf_sign$clock;
    reg  s1_zero_sign$d;
    wire  s1_zero_sign$q;
    reg  s1_zero_sign$clock;
    reg  s1_sign$d;
    wire  s1_sign$q;
    reg  s1_sign$clock;
    reg  s1_eff_sub$d;
    wire  s1_eff_sub$q;
    reg  s1_eff_sub$clock;
    reg  [7:0] s1_exp$d;
    wire  [7:0] s1_exp$q;
    reg  s1_exp$clock;
    reg  [26:0] s1_big$d;
    wire  [26:0] s1_big$q;
    reg  s1_big$clock;
    reg  [26:0] s1_small$d;
    wire  [26:0] s1_small$q;
    reg  s1_small$clock;
    reg  [26:0] norm$x;
    wire  [26:0] norm$y;
    wire  [4:0] norm$lz;
    reg  s2_valid$d;
    wire  s2_valid$q;
    reg  s2_valid$clock;
    reg  s2_sign$d;
    wire  s2_sign$q;
    reg  s2_sign$clock;
    reg  s2_nan$d;
    wire  s2_nan$q;
    reg  s2_nan$clock;
    reg  s2_inf$d;
    wire  s2_inf$q;
    reg  s2_inf$clock;
    reg  s2_zero$d;
    wire  s2_zero$q;
    reg  s2_zero$clock;
    reg  s2_ovf$d;
    wire  s2_ovf$q;
    reg  s2_ovf$clock;
    reg  [7:0] s2_efield$d;
    wire  [7:0] s2_efield$q;
    reg  s2_efield$clock;
    reg  [25:0] s2_nm$d;
    wire  [25:0] s2_nm$q;
    reg  s2_nm$clock;
    reg  round$round_up;
    reg  round$sign;
    reg  round$nan;
    reg  round$inf;
    reg  round$zero;
    reg  round$ovf;
    reg  [7:0] round$efield;
    reg  [25:0] round$nm;
    wire  [31:0] round$y;
    reg  s3_valid$d;
    wire  s3_valid$q;
    reg  s3_valid$clock;
    reg  [31:0] s3_y$d;
    wire  [31:0] s3_y$q;
    reg  s3_y$clock;
    
    // Local signals
    reg  c1_b_sign;
    reg  c1_swap;
    reg  c1_big_sign;
    reg  [7:0] c1_big_exp;
    reg  [23:0] c1_big_sig;
    reg  c1_small_sign;
    reg  [7:0] c1_small_exp;
    reg  [23:0] c1_small_sig;
    reg  [7:0] c1_diff;
    reg  [7:0] c1_shift;
    reg  [26:0] c1_small_ext;
    reg  [26:0] c1_aligned;
    reg  [26:0] c1_back;
    reg  c1_lost;
    reg  c1_inf_sign;
    reg  [27:0] c2_sum;
    reg  c2_carry;
    reg  c2_zero;
    reg  [7:0] c2_limit;
    reg  [7:0] c2_lz;
    reg  [7:0] c2_shift;
    reg  [26:0] c2_shifted;
    reg  [9:0] c2_exp;
    reg  [25:0] c2_nm;
    reg  c2_sign;
    
    // Sub module instances
    top$core$dop$dot_l$add_0$unpack_a unpack_a(
        .x(unpack_a$x),
        .sign(unpack_a$sign),
        .exp(unpack_a$exp),
        .sig(unpack_a$sig),
        .is_zero(unpack_a$is_zero),
        .is_inf(unpack_a$is_inf),
        .is_nan(unpack_a$is_nan)
    );
    top$core$dop$dot_l$add_0$unpack_a unpack_b(
        .x(unpack_b$x),
        .sign(unpack_b$sign),
        .exp(unpack_b$exp),
        .sig(unpack_b$sig),
        .is_zero(unpack_b$is_zero),
        .is_inf(unpack_b$is_inf),
        .is_nan(unpack_b$is_nan)
    );
    top$core$done_r s1_valid(
        .d(s1_valid$d),
        .q(s1_valid$q),
        .clock(s1_valid$clock)
    );
    top$core$done_r s1_nan(
        .d(s1_nan$d),
        .q(s1_nan$q),
        .clock(s1_nan$clock)
    );
    top$core$done_r s1_inf(
        .d(s1_inf$d),
        .q(s1_inf$q),
        .clock(s1_inf$clock)
    );
    top$core$done_r s1_inf_sign(
        .d(s1_inf_sign$d),
        .q(s1_inf_sign$q),
        .clock(s1_inf_sign$clock)
    );
    top$core$done_r s1_zero_sign(
        .d(s1_zero_sign$d),
        .q(s1_zero_sign$q),
        .clock(s1_zero_sign$clock)
    );
    top$core$done_r s1_sign(
        .d(s1_sign$d),
        .q(s1_sign$q),
        .clock(s1_sign$clock)
    );
    top$core$done_r s1_eff_sub(
        .d(s1_eff_sub$d),
        .q(s1_eff_sub$q),
        .clock(s1_eff_sub$clock)
    );
    top$core$dop$bank$s1_lanes s1_exp(
        .d(s1_exp$d),
        .q(s1_exp$q),
        .clock(s1_exp$clock)
    );
    top$core$dop$dot_l$add_0$s1_big s1_big(
        .d(s1_big$d),
        .q(s1_big$q),
        .clock(s1_big$clock)
    );
    top$core$dop$dot_l$add_0$s1_big s1_small(
        .d(s1_small$d),
        .q(s1_small$q),
        .clock(s1_small$clock)
    );
    top$core$dop$dot_l$add_0$norm norm(
        .x(norm$x),
        .y(norm$y),
        .lz(norm$lz)
    );
    top$core$done_r s2_valid(
        .d(s2_valid$d),
        .q(s2_valid$q),
        .clock(s2_valid$clock)
    );
    top$core$done_r s2_sign(
        .d(s2_sign$d),
        .q(s2_sign$q),
        .clock(s2_sign$clock)
    );
    top$core$done_r s2_nan(
        .d(s2_nan$d),
        .q(s2_nan$q),
        .clock(s2_nan$clock)
    );
    top$core$done_r s2_inf(
        .d(s2_inf$d),
        .q(s2_inf$q),
        .clock(s2_inf$clock)
    );
    top$core$done_r s2_zero(
        .d(s2_zero$d),
        .q(s2_zero$q),
        .clock(s2_zero$clock)
    );
    top$core$done_r s2_ovf(
        .d(s2_ovf$d),
        .q(s2_ovf$q),
        .clock(s2_ovf$clock)
    );
    top$core$dop$bank$s1_lanes s2_efield(
        .d(s2_efield$d),
        .q(s2_efield$q),
        .clock(s2_efield$clock)
    );
    top$core$dop$dot_l$add_0$s2_nm s2_nm(
        .d(s2_nm$d),
        .q(s2_nm$q),
        .clock(s2_nm$clock)
    );
    top$core$dop$dot_l$add_0$round round(
        .round_up(round$round_up),
        .sign(round$sign),
        .nan(round$nan),
        .inf(round$inf),
        .zero(round$zero),
        .ovf(round$ovf),
        .efield(round$efield),
        .nm(round$nm),
        .y(round$y)
    );
    top$core$done_r s3_valid(
        .d(s3_valid$d),
        .q(s3_valid$q),
        .clock(s3_valid$clock)
    );
    top$core$cnt_nf s3_y(
        .d(s3_y$d),
        .q(s3_y$q),
        .clock(s3_y$clock)
    );
    
    // Update code
    always @(*) begin
        s1_valid$clock = clock;
        s1_nan$clock = clock;
        s1_inf$clock = clock;
        s1_inf_sign$clock = clock;
        s1_zero_sign$clock = clock;
        s1_sign$clock = clock;
        s1_eff_sub$clock = clock;
        s1_exp$clock = clock;
        s1_big$clock = clock;
        s1_small$clock = clock;
        s1_valid$d = s1_valid$q;
        s1_nan$d = s1_nan$q;
        s1_inf$d = s1_inf$q;
        s1_inf_sign$d = s1_inf_sign$q;
        s1_zero_sign$d = s1_zero_sign$q;
        s1_sign$d = s1_sign$q;
        s1_eff_sub$d = s1_eff_sub$q;
        s1_exp$d = s1_exp$q;
        s1_big$d = s1_big$q;
        s1_small$d = s1_small$q;
        s2_valid$clock = clock;
        s2_sign$clock = clock;
        s2_nan$clock = clock;
        s2_inf$clock = clock;
        s2_zero$clock = clock;
        s2_ovf$clock = clock;
        s2_efield$clock = clock;
        s2_nm$clock = clock;
        s2_valid$d = s2_valid$q;
        s2_sign$d = s2_sign$q;
        s2_nan$d = s2_nan$q;
        s2_inf$d = s2_inf$q;
        s2_zero$d = s2_zero$q;
        s2_ovf$d = s2_ovf$q;
        s2_efield$d = s2_efield$q;
        s2_nm$d = s2_nm$q;
        s3_valid$clock = clock;
        s3_y$clock = clock;
        s3_valid$d = s3_valid$q;
        s3_y$d = s3_y$q;
        unpack_a$x = a;
        unpack_b$x = b;
        c1_b_sign = unpack_b$sign ^ sub;
        c1_swap = a[(32'h0)+:(31)] < b[(32'h0)+:(31)];
        c1_big_sign = unpack_a$sign;
        c1_big_exp = unpack_a$exp;
        c1_big_sig = unpack_a$sig;
        c1_small_sign = c1_b_sign;
        c1_small_exp = unpack_b$exp;
        c1_small_sig = unpack_b$sig;
        if (c1_swap) begin
            c1_big_sign = c1_b_sign;
            c1_big_exp = unpack_b$exp;
            c1_big_sig = unpack_b$sig;
            c1_small_sign = unpack_a$sign;
            c1_small_exp = unpack_a$exp;
            c1_small_sig = unpack_a$sig;
        end
        c1_diff = c1_big_exp - c1_small_exp;
        c1_shift = c1_diff;
        if (c1_diff > c_align_cap) begin
            c1_shift = c_align_cap;
        end
        c1_small_ext = ((c1_small_sig) & 27'h7ffffff) << 32'h3;
        c1_aligned = c1_small_ext >> c1_shift;
        c1_back = c1_aligned << c1_shift;
        c1_lost = c1_back != c1_small_ext;
        c1_inf_sign = c1_b_sign;
        if (unpack_a$is_inf) begin
            c1_inf_sign = unpack_a$sign;
        end
        s1_valid$d = valid_in;
        s1_nan$d = unpack_a$is_nan | unpack_b$is_nan | (unpack_a$is_inf & unpack_b$is_inf & (unpack_a$sign ^ c1_b_sign));
        s1_inf$d = unpack_a$is_inf | unpack_b$is_inf;
        s1_inf_sign$d = c1_inf_sign;
        s1_zero_sign$d = unpack_a$sign & c1_b_sign;
        s1_sign$d = c1_big_sign;
        s1_eff_sub$d = c1_big_sign ^ c1_small_sign;
        s1_exp$d = c1_big_exp;
        s1_big$d = ((c1_big_sig) & 27'h7ffffff) << 32'h3;
        s1_small$d = (c1_aligned & ~(1 << (32'h0)) | ((c1_aligned[32'h0] | c1_lost) << (32'h0)));
        c2_sum = ((s1_big$q) & 28'hfffffff) + ((s1_small$q) & 28'hfffffff);
        if (s1_eff_sub$q) begin
            c2_sum = ((s1_big$q) & 28'hfffffff) - ((s1_small$q) & 28'hfffffff);
        end
        c2_carry = c2_sum[32'h1b];
        c2_zero = c2_sum == 32'h0;
        norm$x = c2_sum[(32'h0)+:(27)];
        c2_limit = s1_exp$q - 32'h1;
        c2_lz = ((norm$lz) & 8'hff);
        c2_shift = c2_lz;
        if (c2_lz > c2_limit) begin
            c2_shift = c2_limit;
        end
        c2_shifted = c2_sum[(32'h0)+:(27)] << c2_shift;
        c2_exp = ((s1_exp$q) & 10'h3ff) - ((c2_shift) & 10'h3ff);
        c2_nm = (((c2_shifted >> 32'h1) & 26'h3ffffff) & ~(1 << (32'h0)) | ((c2_shifted[32'h1] | c2_shifted[32'h0]) << (32'h0)));
        if (c2_carry) begin
            c2_exp = ((s1_exp$q) & 10'h3ff) + 32'h1;
            c2_nm = (((c2_sum >> 32'h2) & 26'h3ffffff) & ~(1 << (32'h0)) | ((c2_sum[32'h2] | c2_sum[32'h1] | c2_sum[32'h0]) << (32'h0)));
        end
        c2_sign = s1_sign$q;
        if (c2_zero) begin
            c2_sign = s1_zero_sign$q;
        end
        if (s1_inf$q) begin
            c2_sign = s1_inf_sign$q;
        end
        s2_valid$d = s1_valid$q;
        s2_sign$d = c2_sign;
        s2_nan$d = s1_nan$q;
        s2_inf$d = s1_inf$q;
        s2_zero$d = c2_zero;
        s2_ovf$d = c2_exp >= c_exp_ones;
        s2_efield$d = 32'h0;
        if (c2_nm[32'h18 + 32'h1]) begin
            s2_efield$d = ((c2_exp) & 8'hff);
        end
        s2_nm$d = c2_nm;
        round$round_up = round_up;
        round$sign = s2_sign$q;
        round$nan = s2_nan$q;
        round$inf = s2_inf$q;
        round$zero = s2_zero$q;
        round$ovf = s2_ovf$q;
        round$efield = s2_efield$q;
        round$nm = s2_nm$q;
        s3_valid$d = s2_valid$q;
        s3_y$d = round$y;
        y = s3_y$q;
        valid_out = s3_valid$q;
    end
    
endmodule // top$tri_unit$tc_ab$edges$0$a


module top$tri_unit$tc_ab$edges$0$a_sgn_wait(clock,d,q);
    
    // Module arguments
    input wire  clock;
    input wire  [1:0] d;
    output reg  [1:0] q;
    
    // Stub signals
    reg  [1:0] line$0$d;
    wire  [1:0] line$0$q;
    reg  line$0$clock;
    reg  [1:0] line$1$d;
    wire  [1:0] line$1$q;
    reg  line$1$clock;
    reg  [1:0] line$2$d;
    wire  [1:0] line$2$q;
    reg  line$2$clock;
    reg  [1:0] line$3$d;
    wire  [1:0] line$3$q;
    reg  line$3$clock;
    reg  [1:0] line$4$d;
    wire  [1:0] line$4$q;
    reg  line$4$clock;
    reg  [1:0] line$5$d;
    wire  [1:0] line$5$q;
    reg  line$5$clock;
    
    // Sub module instances
    top$core$dop$busy_r line$0(
        .d(line$0$d),
        .q(line$0$q),
        .clock(line$0$clock)
    );
    top$core$dop$busy_r line$1(
        .d(line$1$d),
        .q(line$1$q),
        .clock(line$1$clock)
    );
    top$core$dop$busy_r line$2(
        .d(line$2$d),
        .q(line$2$q),
        .clock(line$2$clock)
    );
    top$core$dop$busy_r line$3(
        .d(line$3$d),
        .q(line$3$q),
        .clock(line$3$clock)
    );
    top$core$dop$busy_r line$4(
        .d(line$4$d),
        .q(line$4$q),
        .clock(line$4$clock)
    );
    top$core$dop$busy_r line$5(
        .d(line$5$d),
        .q(line$5$q),
        .clock(line$5$clock)
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
        line$4$clock = clock;
        line$4$d = d;
        line$5$clock = clock;
        line$5$d = d;
        line$0$d = line$1$q;
        line$1$d = line$2$q;
        line$2$d = line$3$q;
        line$3$d = line$4$q;
        line$4$d = line$5$q;
        q = line$0$q;
    end
    
endmodule // top$tri_unit$tc_ab$edges$0$a_sgn_wait


module top$tri_unit$tc_ab$edges$0$a_wait(clock,d,q);
    
    // Module arguments
    input wire  clock;
    input wire  [31:0] d;
    output reg  [31:0] q;
    
    // Stub signals
    reg  [31:0] line$0$d;
    wire  [31:0] line$0$q;
    reg  line$0$clock;
    reg  [31:0] line$1$d;
    wire  [31:0] line$1$q;
    reg  line$1$clock;
    reg  [31:0] line$2$d;
    wire  [31:0] line$2$q;
    reg  line$2$clock;
    reg  [31:0] line$3$d;
    wire  [31:0] line$3$q;
    reg  line$3$clock;
    reg  [31:0] line$4$d;
    wire  [31:0] line$4$q;
    reg  line$4$clock;
    reg  [31:0] line$5$d;
    wire  [31:0] line$5$q;
    reg  line$5$clock;
    reg  [31:0] line$6$d;
    wire  [31:0] line$6$q;
    reg  line$6$clock;
    reg  [31:0] line$7$d;
    wire  [31:0] line$7$q;
    reg  line$7$clock;
    reg  [31:0] line$8$d;
    wire  [31:0] line$8$q;
    reg  line$8$clock;
    reg  [31:0] line$9$d;
    wire  [31:0] line$9$q;
    reg  line$9$clock;
    reg  [31:0] line$10$d;
    wire  [31:0] line$10$q;
    reg  line$10$clock;
    reg  [31:0] line$11$d;
    wire  [31:0] line$11$q;
    reg  line$11$clock;
    reg  [31:0] line$12$d;
    wire  [31:0] line$12$q;
    reg  line$12$clock;
    
    // Sub module instances
    top$core$cnt_nf line$0(
        .d(line$0$d),
        .q(line$0$q),
        .clock(line$0$clock)
    );
    top$core$cnt_nf line$1(
        .d(line$1$d),
        .q(line$1$q),
        .clock(line$1$clock)
    );
    top$core$cnt_nf line$2(
        .d(line$2$d),
        .q(line$2$q),
        .clock(line$2$clock)
    );
    top$core$cnt_nf line$3(
        .d(line$3$d),
        .q(line$3$q),
        .clock(line$3$clock)
    );
    top$core$cnt_nf line$4(
        .d(line$4$d),
        .q(line$4$q),
        .clock(line$4$clock)
    );
    top$core$cnt_nf line$5(
        .d(line$5$d),
        .q(line$5$q),
        .clock(line$5$clock)
    );
    top$core$cnt_nf line$6(
        .d(line$6$d),
        .q(line$6$q),
        .clock(line$6$clock)
    );
    top$core$cnt_nf line$7(
        .d(line$7$d),
        .q(line$7$q),
        .clock(line$7$clock)
    );
    top$core$cnt_nf line$8(
        .d(line$8$d),
        .q(line$8$q),
        .clock(line$8$clock)
    );
    top$core$cnt_nf line$9(
        .d(line$9$d),
        .q(line$9$q),
        .clock(line$9$clock)
    );
    top$core$cnt_nf line$10(
        .d(line$10$d),
        .q(line$10$q),
        .clock(line$10$clock)
    );
    top$core$cnt_nf line$11(
        .d(line$11$d),
        .q(line$11$q),
        .clock(line$11$clock)
    );
    top$core$cnt_nf line$12(
        .d(line$12$d),
        .q(line$12$q),
        .clock(line$12$clock)
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
        line$4$clock = clock;
        line$4$d = d;
        line$5$clock = clock;
        line$5$d = d;
        line$6$clock = clock;
        line$6$d = d;
        line$7$clock = clock;
        line$7$d = d;
        line$8$clock = clock;
        line$8$d = d;
        line$9$clock = clock;
        line$9$d = d;
        line$10$clock = clock;
        line$10$d = d;
        line$11$clock = clock;
        line$11$d = d;
        line$12$clock = clock;
        line$12$d = d;
        line$0$d = line$1$q;
        line$1$d = line$2$q;
        line$2$d = line$3$q;
        line$3$d = line$4$q;
        line$4$d = line$5$q;
        line$5$d = line$6$q;
        line$6$d = line$7$q;
        line$7$d = line$8$q;
        line$8$d = line$9$q;
        line$9$d = line$10$q;
        line$10$d = line$11$q;
        line$11$d = line$12$q;
        q = line$0$q;
    end
    
endmodule // top$tri_unit$tc_ab$edges$0$a_wait


module top$tri_unit$tc_ab$edges$0$brs_wait(clock,d,q);
    
    // Module arguments
    input wire  clock;
    input wire  [31:0] d;
    output reg  [31:0] q;
    
    // Stub signals
    reg  [31:0] line$0$d;
    wire  [31:0] line$0$q;
    reg  line$0$clock;
    reg  [31:0] line$1$d;
    wire  [31:0] line$1$q;
    reg  line$1$clock;
    reg  [31:0] line$2$d;
    wire  [31:0] line$2$q;
    reg  line$2$clock;
    
    // Sub module instances
    top$core$cnt_nf line$0(
        .d(line$0$d),
        .q(line$0$q),
        .clock(line$0$clock)
    );
    top$core$cnt_nf line$1(
        .d(line$1$d),
        .q(line$1$q),
        .clock(line$1$clock)
    );
    top$core$cnt_nf line$2(
        .d(line$2$d),
        .q(line$2$q),
        .clock(line$2$clock)
    );
    
    // Update code
    always @(*) begin
        line$0$clock = clock;
        line$0$d = d;
        line$1$clock = clock;
        line$1$d = d;
        line$2$clock = clock;
        line$2$d = d;
        line$0$d = line$1$q;
        line$1$d = line$2$q;
        q = line$0$q;
    end
    
endmodule // top$tri_unit$tc_ab$edges$0$brs_wait


module top$tri_unit$tc_ab$edges$0$brz_wait(clock,d,q);
    
    // Module arguments
    input wire  clock;
    input wire  [31:0] d;
    output reg  [31:0] q;
    
    // Stub signals
    reg  [31:0] line$0$d;
    wire  [31:0] line$0$q;
    reg  line$0$clock;
    reg  [31:0] line$1$d;
    wire  [31:0] line$1$q;
    reg  line$1$clock;
    reg  [31:0] line$2$d;
    wire  [31:0] line$2$q;
    reg  line$2$clock;
    reg  [31:0] line$3$d;
    wire  [31:0] line$3$q;
    reg  line$3$clock;
    reg  [31:0] line$4$d;
    wire  [31:0] line$4$q;
    reg  line$4$clock;
    reg  [31:0] line$5$d;
    wire  [31:0] line$5$q;
    reg  line$5$clock;
    reg  [31:0] line$6$d;
    wire  [31:0] line$6$q;
    reg  line$6$clock;
    
    // Sub module instances
    top$core$cnt_nf line$0(
        .d(line$0$d),
        .q(line$0$q),
        .clock(line$0$clock)
    );
    top$core$cnt_nf line$1(
        .d(line$1$d),
        .q(line$1$q),
        .clock(line$1$clock)
    );
    top$core$cnt_nf line$2(
        .d(line$2$d),
        .q(line$2$q),
        .clock(line$2$clock)
    );
    top$core$cnt_nf line$3(
        .d(line$3$d),
        .q(line$3$q),
        .clock(line$3$clock)
    );
    top$core$cnt_nf line$4(
        .d(line$4$d),
        .q(line$4$q),
        .clock(line$4$clock)
    );
    top$core$cnt_nf line$5(
        .d(line$5$d),
        .q(line$5$q),
        .clock(line$5$clock)
    );
    top$core$cnt_nf line$6(
        .d(line$6$d),
        .q(line$6$q),
        .clock(line$6$clock)
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
        line$4$clock = clock;
        line$4$d = d;
        line$5$clock = clock;
        line$5$d = d;
        line$6$clock = clock;
        line$6$d = d;
        line$0$d = line$1$q;
        line$1$d = line$2$q;
        line$2$d = line$3$q;
        line$3$d = line$4$q;
        line$4$d = line$5$q;
        line$5$d = line$6$q;
        q = line$0$q;
    end
    
endmodule // top$tri_unit$tc_ab$edges$0$brz_wait


module top$tri_unit$tc_ab$edges$0$px_qz(clock,a,b,valid_in,y,valid_out);
    
    // Module arguments
    input wire  clock;
    input wire  [31:0] a;
    input wire  [31:0] b;
    input wire  valid_in;
    output reg  [31:0] y;
    output reg  valid_out;
    
    // Constant declarations
    localparam  round_up = 1'b0;
    localparam  c_exp_adj = 10'b10000001;
    localparam  c_exp_ofs = 10'b100000000;
    localparam  c_exp_norm_min = 10'b100000001;
    localparam  c_exp_ovf = 10'b111111111;
    localparam  c_shift_cap = 10'b11010;
    
    // Stub signals
    reg  [31:0] unpack_a$x;
    wire  unpack_a$sign;
    wire  [7:0] unpack_a$exp;
    wire  [23:0] unpack_a$sig;
    wire  unpack_a$is_zero;
    wire  unpack_a$is_inf;
    wire  unpack_a$is_nan;
    reg  [31:0] unpack_b$x;
    wire  unpack_b$sign;
    wire  [7:0] unpack_b$exp;
    wire  [23:0] unpack_b$sig;
    wire  unpack_b$is_zero;
    wire  unpack_b$is_inf;
    wire  unpack_b$is_nan;
    reg  [23:0] norm_a$x;
    wire  [23:0] norm_a$y;
    wire  [4:0] norm_a$lz;
    reg  [23:0] norm_b$x;
    wire  [23:0] norm_b$y;
    wire  [4:0] norm_b$lz;
    reg  s1_valid$d;
    wire  s1_valid$q;
    reg  s1_valid$clock;
    reg  s1_sign$d;
    wire  s1_sign$q;
    reg  s1_sign$clock;
    reg  s1_nan$d;
    wire  s1_nan$q;
    reg  s1_nan$clock;
    reg  s1_inf$d;
    wire  s1_inf$q;
    reg  s1_inf$clock;
    reg  s1_zero$d;
    wire  s1_zero$q;
    reg  s1_zero$clock;
    reg  [9:0] s1_exp$d;
    wire  [9:0] s1_exp$q;
    reg  s1_exp$clock;
    reg  [23:0] s1_sig_a$d;
    wire  [23:0] s1_sig_a$q;
    reg  s1_sig_a$clock;
    reg  [23:0] s1_sig_b$d;
    wire  [23:0] s1_sig_b$q;
    reg  s1_sig_b$clock;
    reg  [23:0] sig_mul$a;
    reg  [23:0] sig_mul$b;
    wire  [25:0] sig_mul$hi;
    wire  sig_mul$sticky;
    reg  s2_valid$d;
    wire  s2_valid$q;
    reg  s2_valid$clock;
    reg  s2_sign$d;
    wire  s2_sign$q;
    reg  s2_sign$clock;
    reg  s2_nan$d;
    wire  s2_nan$q;
    reg  s2_nan$clock;
    reg  s2_inf$d;
    wire  s2_inf$q;
    reg  s2_inf$clock;
    reg  s2_zero$d;
    wire  s2_zero$q;
    reg  s2_zero$clock;
    reg  [9:0] s2_exp$d;
    wire  [9:0] s2_exp$q;
    reg  s2_exp$clock;
    reg  [25:0] s2_hi$d;
    wire  [25:0] s2_hi$q;
    reg  s2_hi$clock;
    reg  s2_sticky$d;
    wire  s2_sticky$q;
    reg  s2_sticky$clock;
    reg  s3_valid$d;
    wire  s3_valid$q;
    reg  s3_valid$clock;
    reg  s3_sign$d;
    wire  s3_sign$q;
    reg  s3_sign$clock;
    reg  s3_nan$d;
    wire  s3_nan$q;
    reg  s3_nan$clock;
    reg  s3_inf$d;
    wire  s3_inf$q;
    reg  s3_inf$clock;
    reg  s3_zero$d;
    wire  s3_zero$q;
    reg  s3_zero$clock;
    reg  s3_ovf$d;
    wire  s3_ovf$q;
    reg  s3_ovf$clock;
    reg  [7:0] s3_efield$d;
    wire  [7:0] s3_efield$q;
    reg  s3_efield$clock;
    reg  [25:0] s3_nm$d;
    wire  [25:0] s3_nm$q;
    reg  s3_nm$clock;
    reg  round$round_up;
    reg  round$sign;
    reg  round$nan;
    reg  round$inf;
    reg  round$zero;
    reg  round$ovf;
    reg  [7:0] round$efield;
    reg  [25:0] round$nm;
    wire  [31:0] round$y;
    reg  s4_valid$d;
    wire  s4_valid$q;
    reg  s4_valid$clock;
    reg  [31:0] s4_y$d;
    wire  [31:0] s4_y$q;
    reg  s4_y$clock;
    
    // Local signals
    reg  [9:0] c1_exp;
    reg  c3_top;
    reg  [25:0] c3_nm;
    reg  [9:0] c3_exp;
    reg  [9:0] c3_shift;
    reg  [9:0] c3_shift_cap;
    reg  [25:0] c3_shifted;
    reg  [25:0] c3_back;
    reg  c3_lost;
    reg  [7:0] c3_efield;
    
    // Sub module instances
    top$core$dop$dot_l$add_0$unpack_a unpack_a(
        .x(unpack_a$x),
        .sign(unpack_a$sign),
        .exp(unpack_a$exp),
        .sig(unpack_a$sig),
        .is_zero(unpack_a$is_zero),
        .is_inf(unpack_a$is_inf),
        .is_nan(unpack_a$is_nan)
    );
    top$core$dop$dot_l$add_0$unpack_a unpack_b(
        .x(unpack_b$x),
        .sign(unpack_b$sign),
        .exp(unpack_b$exp),
        .sig(unpack_b$sig),
        .is_zero(unpack_b$is_zero),
        .is_inf(unpack_b$is_inf),
        .is_nan(unpack_b$is_nan)
    );
    top$core$dop$dot_l$mul_0$norm_a norm_a(
        .x(norm_a$x),
        .y(norm_a$y),
        .lz(norm_a$lz)
    );
    top$core$dop$dot_l$mul_0$norm_a norm_b(
        .x(norm_b$x),
        .y(norm_b$y),
        .lz(norm_b$lz)
    );
    top$core$done_r s1_valid(
        .d(s1_valid$d),
        .q(s1_valid$q),
        .clock(s1_valid$clock)
    );
    top$core$done_r s1_sign(
        .d(s1_sign$d),
        .q(s1_sign$q),
        .clock(s1_sign$clock)
    );
    top$core$done_r s1_nan(
        .d(s1_nan$d),
        .q(s1_nan$q),
        .clock(s1_nan$clock)
    );
    top$core$done_r s1_inf(
        .d(s1_inf$d),
        .q(s1_inf$q),
        .clock(s1_inf$clock)
    );
    top$core$done_r s1_zero(
        .d(s1_zero$d),
        .q(s1_zero$q),
        .clock(s1_zero$clock)
    );
    top$core$dop$dot_l$mul_0$s1_exp s1_exp(
        .d(s1_exp$d),
        .q(s1_exp$q),
        .clock(s1_exp$clock)
    );
    top$core$base_na s1_sig_a(
        .d(s1_sig_a$d),
        .q(s1_sig_a$q),
        .clock(s1_sig_a$clock)
    );
    top$core$base_na s1_sig_b(
        .d(s1_sig_b$d),
        .q(s1_sig_b$q),
        .clock(s1_sig_b$clock)
    );
    top$core$dop$dot_l$mul_0$sig_mul sig_mul(
        .a(sig_mul$a),
        .b(sig_mul$b),
        .hi(sig_mul$hi),
        .sticky(sig_mul$sticky)
    );
    top$core$done_r s2_valid(
        .d(s2_valid$d),
        .q(s2_valid$q),
        .clock(s2_valid$clock)
    );
    top$core$done_r s2_sign(
        .d(s2_sign$d),
        .q(s2_sign$q),
        .clock(s2_sign$clock)
    );
    top$core$done_r s2_nan(
        .d(s2_nan$d),
        .q(s2_nan$q),
        .clock(s2_nan$clock)
    );
    top$core$done_r s2_inf(
        .d(s2_inf$d),
        .q(s2_inf$q),
        .clock(s2_inf$clock)
    );
    top$core$done_r s2_zero(
        .d(s2_zero$d),
        .q(s2_zero$q),
        .clock(s2_zero$clock)
    );
    top$core$dop$dot_l$mul_0$s1_exp s2_exp(
        .d(s2_exp$d),
        .q(s2_exp$q),
        .clock(s2_exp$clock)
    );
    top$core$dop$dot_l$add_0$s2_nm s2_hi(
        .d(s2_hi$d),
        .q(s2_hi$q),
        .clock(s2_hi$clock)
    );
    top$core$done_r s2_sticky(
        .d(s2_sticky$d),
        .q(s2_sticky$q),
        .clock(s2_sticky$clock)
    );
    top$core$done_r s3_valid(
        .d(s3_valid$d),
        .q(s3_valid$q),
        .clock(s3_valid$clock)
    );
    top$core$done_r s3_sign(
        .d(s3_sign$d),
        .q(s3_sign$q),
        .clock(s3_sign$clock)
    );
    top$core$done_r s3_nan(
        .d(s3_nan$d),
        .q(s3_nan$q),
        .clock(s3_nan$clock)
    );
    top$core$done_r s3_inf(
        .d(s3_inf$d),
        .q(s3_inf$q),
        .clock(s3_inf$clock)
    );
    top$core$done_r s3_zero(
        .d(s3_zero$d),
        .q(s3_zero$q),
        .clock(s3_zero$clock)
    );
    top$core$done_r s3_ovf(
        .d(s3_ovf$d),
        .q(s3_ovf$q),
        .clock(s3_ovf$clock)
    );
    top$core$dop$bank$s1_lanes s3_efield(
        .d(s3_efield$d),
        .q(s3_efield$q),
        .clock(s3_efield$clock)
    );
    top$core$dop$dot_l$add_0$s2_nm s3_nm(
        .d(s3_nm$d),
        .q(s3_nm$q),
        .clock(s3_nm$clock)
    );
    top$core$dop$dot_l$add_0$round round(
        .round_up(round$round_up),
        .sign(round$sign),
        .nan(round$nan),
        .inf(round$inf),
        .zero(round$zero),
        .ovf(round$ovf),
        .efield(round$efield),
        .nm(round$nm),
        .y(round$y)
    );
    top$core$done_r s4_valid(
        .d(s4_valid$d),
        .q(s4_valid$q),
        .clock(s4_valid$clock)
    );
    top$core$cnt_nf s4_y(
        .d(s4_y$d),
        .q(s4_y$q),
        .clock(s4_y$clock)
    );
    
    // Update code
    always @(*) begin
        s1_valid$clock = clock;
        s1_sign$clock = clock;
        s1_nan$clock = clock;
        s1_inf$clock = clock;
        s1_zero$clock = clock;
        s1_exp$clock = clock;
        s1_sig_a$clock = clock;
        s1_sig_b$clock = clock;
        s1_valid$d = s1_valid$q;
        s1_sign$d = s1_sign$q;
        s1_nan$d = s1_nan$q;
        s1_inf$d = s1_inf$q;
        s1_zero$d = s1_zero$q;
        s1_exp$d = s1_exp$q;
        s1_sig_a$d = s1_sig_a$q;
        s1_sig_b$d = s1_sig_b$q;
        s2_valid$clock = clock;
        s2_sign$clock = clock;
        s2_nan$clock = clock;
        s2_inf$clock = clock;
        s2_zero$clock = clock;
        s2_exp$clock = clock;
        s2_hi$clock = clock;
        s2_sticky$clock = clock;
        s2_valid$d = s2_valid$q;
        s2_sign$d = s2_sign$q;
        s2_nan$d = s2_nan$q;
        s2_inf$d = s2_inf$q;
        s2_zero$d = s2_zero$q;
        s2_exp$d = s2_exp$q;
        s2_hi$d = s2_hi$q;
        s2_sticky$d = s2_sticky$q;
        s3_valid$clock = clock;
        s3_sign$clock = clock;
        s3_nan$clock = clock;
        s3_inf$clock = clock;
        s3_zero$clock = clock;
        s3_ovf$clock = clock;
        s3_efield$clock = clock;
        s3_nm$clock = clock;
        s3_valid$d = s3_valid$q;
        s3_sign$d = s3_sign$q;
        s3_nan$d = s3_nan$q;
        s3_inf$d = s3_inf$q;
        s3_zero$d = s3_zero$q;
        s3_ovf$d = s3_ovf$q;
        s3_efield$d = s3_efield$q;
        s3_nm$d = s3_nm$q;
        s4_valid$clock = clock;
        s4_y$clock = clock;
        s4_valid$d = s4_valid$q;
        s4_y$d = s4_y$q;
        unpack_a$x = a;
        unpack_b$x = b;
        norm_a$x = unpack_a$sig;
        norm_b$x = unpack_b$sig;
        c1_exp = ((unpack_a$exp) & 10'h3ff) + ((unpack_b$exp) & 10'h3ff) - ((norm_a$lz) & 10'h3ff) - ((norm_b$lz) & 10'h3ff) + c_exp_adj;
        s1_valid$d = valid_in;
        s1_sign$d = unpack_a$sign ^ unpack_b$sign;
        s1_nan$d = unpack_a$is_nan | unpack_b$is_nan | (unpack_a$is_inf & unpack_b$is_zero) | (unpack_a$is_zero & unpack_b$is_inf);
        s1_inf$d = unpack_a$is_inf | unpack_b$is_inf;
        s1_zero$d = unpack_a$is_zero | unpack_b$is_zero;
        s1_exp$d = c1_exp;
        s1_sig_a$d = norm_a$y;
        s1_sig_b$d = norm_b$y;
        sig_mul$a = s1_sig_a$q;
        sig_mul$b = s1_sig_b$q;
        s2_valid$d = s1_valid$q;
        s2_sign$d = s1_sign$q;
        s2_nan$d = s1_nan$q;
        s2_inf$d = s1_inf$q;
        s2_zero$d = s1_zero$q;
        s2_exp$d = s1_exp$q;
        s2_hi$d = sig_mul$hi;
        s2_sticky$d = sig_mul$sticky;
        c3_top = s2_hi$q[32'h18 + 32'h1];
        c3_nm = ((s2_hi$q << 32'h1) & ~(1 << (32'h0)) | ((s2_sticky$q) << (32'h0)));
        if (c3_top) begin
            c3_nm = (s2_hi$q & ~(1 << (32'h0)) | ((s2_hi$q[32'h0] | s2_sticky$q) << (32'h0)));
        end
        c3_exp = s2_exp$q + c3_top;
        c3_shift = 32'h0;
        if (c3_exp < c_exp_norm_min) begin
            c3_shift = c_exp_norm_min - c3_exp;
        end
        c3_shift_cap = c3_shift;
        if (c3_shift > c_shift_cap) begin
            c3_shift_cap = c_shift_cap;
        end
        c3_shifted = c3_nm >> c3_shift_cap;
        c3_back = c3_shifted << c3_shift_cap;
        c3_lost = c3_back != c3_nm;
        c3_efield = 32'h0;
        if (c3_shift == 32'h0) begin
            c3_efield = ((c3_exp - c_exp_ofs) & 8'hff);
        end
        s3_valid$d = s2_valid$q;
        s3_sign$d = s2_sign$q;
        s3_nan$d = s2_nan$q;
        s3_inf$d = s2_inf$q;
        s3_zero$d = s2_zero$q;
        s3_ovf$d = c3_exp >= c_exp_ovf;
        s3_efield$d = c3_efield;
        s3_nm$d = (c3_shifted & ~(1 << (32'h0)) | ((c3_shifted[32'h0] | c3_lost) << (32'h0)));
        round$round_up = round_up;
        round$sign = s3_sign$q;
        round$nan = s3_nan$q;
        round$inf = s3_inf$q;
        round$zero = s3_zero$q;
        round$ovf = s3_ovf$q;
        round$efield = s3_efield$q;
        round$nm = s3_nm$q;
        s4_valid$d = s3_valid$q;
        s4_y$d = round$y;
        y = s4_y$q;
        valid_out = s4_valid$q;
    end
    
endmodule // top$tri_unit$tc_ab$edges$0$px_qz


module top$tri_unit$tc_ab$edges$0$pz_sgn_wait(clock,d,q);
    
    // Module arguments
    input wire  clock;
    input wire  [1:0] d;
    output reg  [1:0] q;
    
    // Stub signals
    reg  [1:0] line$0$d;
    wire  [1:0] line$0$q;
    reg  line$0$clock;
    reg  [1:0] line$1$d;
    wire  [1:0] line$1$q;
    reg  line$1$clock;
    reg  [1:0] line$2$d;
    wire  [1:0] line$2$q;
    reg  line$2$clock;
    reg  [1:0] line$3$d;
    wire  [1:0] line$3$q;
    reg  line$3$clock;
    reg  [1:0] line$4$d;
    wire  [1:0] line$4$q;
    reg  line$4$clock;
    reg  [1:0] line$5$d;
    wire  [1:0] line$5$q;
    reg  line$5$clock;
    reg  [1:0] line$6$d;
    wire  [1:0] line$6$q;
    reg  line$6$clock;
    reg  [1:0] line$7$d;
    wire  [1:0] line$7$q;
    reg  line$7$clock;
    reg  [1:0] line$8$d;
    wire  [1:0] line$8$q;
    reg  line$8$clock;
    reg  [1:0] line$9$d;
    wire  [1:0] line$9$q;
    reg  line$9$clock;
    reg  [1:0] line$10$d;
    wire  [1:0] line$10$q;
    reg  line$10$clock;
    reg  [1:0] line$11$d;
    wire  [1:0] line$11$q;
    reg  line$11$clock;
    reg  [1:0] line$12$d;
    wire  [1:0] line$12$q;
    reg  line$12$clock;
    reg  [1:0] line$13$d;
    wire  [1:0] line$13$q;
    reg  line$13$clock;
    reg  [1:0] line$14$d;
    wire  [1:0] line$14$q;
    reg  line$14$clock;
    reg  [1:0] line$15$d;
    wire  [1:0] line$15$q;
    reg  line$15$clock;
    reg  [1:0] line$16$d;
    wire  [1:0] line$16$q;
    reg  line$16$clock;
    reg  [1:0] line$17$d;
    wire  [1:0] line$17$q;
    reg  line$17$clock;
    reg  [1:0] line$18$d;
    wire  [1:0] line$18$q;
    reg  line$18$clock;
    reg  [1:0] line$19$d;
    wire  [1:0] line$19$q;
    reg  line$19$clock;
    reg  [1:0] line$20$d;
    wire  [1:0] line$20$q;
    reg  line$20$clock;
    reg  [1:0] line$21$d;
    wire  [1:0] line$21$q;
    reg  line$21$clock;
    
    // Sub module instances
    top$core$dop$busy_r line$0(
        .d(line$0$d),
        .q(line$0$q),
        .clock(line$0$clock)
    );
    top$core$dop$busy_r line$1(
        .d(line$1$d),
        .q(line$1$q),
        .clock(line$1$clock)
    );
    top$core$dop$busy_r line$2(
        .d(line$2$d),
        .q(line$2$q),
        .clock(line$2$clock)
    );
    top$core$dop$busy_r line$3(
        .d(line$3$d),
        .q(line$3$q),
        .clock(line$3$clock)
    );
    top$core$dop$busy_r line$4(
        .d(line$4$d),
        .q(line$4$q),
        .clock(line$4$clock)
    );
    top$core$dop$busy_r line$5(
        .d(line$5$d),
        .q(line$5$q),
        .clock(line$5$clock)
    );
    top$core$dop$busy_r line$6(
        .d(line$6$d),
        .q(line$6$q),
        .clock(line$6$clock)
    );
    top$core$dop$busy_r line$7(
        .d(line$7$d),
        .q(line$7$q),
        .clock(line$7$clock)
    );
    top$core$dop$busy_r line$8(
        .d(line$8$d),
        .q(line$8$q),
        .clock(line$8$clock)
    );
    top$core$dop$busy_r line$9(
        .d(line$9$d),
        .q(line$9$q),
        .clock(line$9$clock)
    );
    top$core$dop$busy_r line$10(
        .d(line$10$d),
        .q(line$10$q),
        .clock(line$10$clock)
    );
    top$core$dop$busy_r line$11(
        .d(line$11$d),
        .q(line$11$q),
        .clock(line$11$clock)
    );
    top$core$dop$busy_r line$12(
        .d(line$12$d),
        .q(line$12$q),
        .clock(line$12$clock)
    );
    top$core$dop$busy_r line$13(
        .d(line$13$d),
        .q(line$13$q),
        .clock(line$13$clock)
    );
    top$core$dop$busy_r line$14(
        .d(line$14$d),
        .q(line$14$q),
        .clock(line$14$clock)
    );
    top$core$dop$busy_r line$15(
        .d(line$15$d),
        .q(line$15$q),
        .clock(line$15$clock)
    );
    top$core$dop$busy_r line$16(
        .d(line$16$d),
        .q(line$16$q),
        .clock(line$16$clock)
    );
    top$core$dop$busy_r line$17(
        .d(line$17$d),
        .q(line$17$q),
        .clock(line$17$clock)
    );
    top$core$dop$busy_r line$18(
        .d(line$18$d),
        .q(line$18$q),
        .clock(line$18$clock)
    );
    top$core$dop$busy_r line$19(
        .d(line$19$d),
        .q(line$19$q),
        .clock(line$19$clock)
    );
    top$core$dop$busy_r line$20(
        .d(line$20$d),
        .q(line$20$q),
        .clock(line$20$clock)
    );
    top$core$dop$busy_r line$21(
        .d(line$21$d),
        .q(line$21$q),
        .clock(line$21$clock)
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
        line$4$clock = clock;
        line$4$d = d;
        line$5$clock = clock;
        line$5$d = d;
        line$6$clock = clock;
        line$6$d = d;
        line$7$clock = clock;
        line$7$d = d;
        line$8$clock = clock;
        line$8$d = d;
        line$9$clock = clock;
        line$9$d = d;
        line$10$clock = clock;
        line$10$d = d;
        line$11$clock = clock;
        line$11$d = d;
        line$12$clock = clock;
        line$12$d = d;
        line$13$clock = clock;
        line$13$d = d;
        line$14$clock = clock;
        line$14$d = d;
        line$15$clock = clock;
        line$15$d = d;
        line$16$clock = clock;
        line$16$d = d;
        line$17$clock = clock;
        line$17$d = d;
        line$18$clock = clock;
        line$18$d = d;
        line$19$clock = clock;
        line$19$d = d;
        line$20$clock = clock;
        line$20$d = d;
        line$21$clock = clock;
        line$21$d = d;
        line$0$d = line$1$q;
        line$1$d = line$2$q;
        line$2$d = line$3$q;
        line$3$d = line$4$q;
        line$4$d = line$5$q;
        line$5$d = line$6$q;
        line$6$d = line$7$q;
        line$7$d = line$8$q;
        line$8$d = line$9$q;
        line$9$d = line$10$q;
        line$10$d = line$11$q;
        line$11$d = line$12$q;
        line$12$d = line$13$q;
        line$13$d = line$14$q;
        line$14$d = line$15$q;
        line$15$d = line$16$q;
        line$16$d = line$17$q;
        line$17$d = line$18$q;
        line$18$d = line$19$q;
        line$19$d = line$20$q;
        line$20$d = line$21$q;
        q = line$0$q;
    end
    
endmodule // top$tri_unit$tc_ab$edges$0$pz_sgn_wait


module top$tri_unit$tc_ab$edges$0$rs(clock,a,sel,y);
    
    // Module arguments
    input wire  clock;
    input wire  [31:0] a;
    input wire  sel;
    output reg  [31:0] y;
    
    // Constant declarations
    localparam  c_k0 = 10'b11101001;
    localparam  c_k1 = 10'b11101001;
    localparam  c_sh0 = 8'h1;
    localparam  c_sh1 = 8'h1;
    localparam  c_t0 = 8'h1;
    localparam  c_t1 = 8'h1;
    localparam  c_en0 = 1'b0;
    localparam  c_en1 = 1'b0;
    localparam  c_j = 8'h19;
    localparam  c_j1 = 8'h1a;
    localparam  c_f = 8'h17;
    localparam  c_ofs = 10'b100000000;
    localparam  c_norm_min = 10'b100000001;
    localparam  c_min = 32'h800000;
    localparam  c_inf = 32'h7f800000;
    localparam  c_nan = 32'h7fc00000;
    
    // Stub signals
    reg  out$clock;
    reg  [31:0] out$d;
    wire  [31:0] out$q;
    
    // Local signals
    reg  [7:0] field;
    reg  [22:0] frac;
    reg  [49:0] m;
    reg  [7:0] lo_sh;
    reg  [7:0] t_sh;
    reg  t_en;
    reg  [9:0] kk;
    reg  [49:0] third;
    reg  [49:0] sum;
    reg  top;
    reg  [7:0] sh;
    reg  [49:0] hi;
    reg  lost;
    reg  [49:0] rnd;
    reg  [9:0] eb;
    reg  [9:0] e10;
    reg  [31:0] res;
    
    // Sub module instances
    top$tri_unit$tc_ab$c3_0 out(
        .clock(out$clock),
        .d(out$d),
        .q(out$q)
    );
    
    // Update code
    always @(*) begin
        out$clock = clock;
        field = a[(32'h17)+:(8)];
        frac = a[(32'h0)+:(23)];
        m = (((frac) & 50'h3ffffffffffff) & ~(1 << (32'h17)) | ((1'b1) << (32'h17)));
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
        top = sum[32'h32 - 32'h1];
        sh = c_j;
        if (top) begin
            sh = c_j1;
        end
        hi = sum >> sh;
        lost = (hi << sh) != sum;
        rnd = hi + lost;
        e10 = eb + top + rnd[32'h17 + 32'h1];
        res = (((e10 - c_ofs) & 32'hffffffff) << c_f) | ((((rnd) & 23'h7fffff)) & 32'hffffffff);
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
    
endmodule // top$tri_unit$tc_ab$edges$0$rs


module top$tri_unit$tc_ab$edges$0$rz_sgn_wait(clock,d,q);
    
    // Module arguments
    input wire  clock;
    input wire  [1:0] d;
    output reg  [1:0] q;
    
    // Stub signals
    reg  [1:0] line$0$d;
    wire  [1:0] line$0$q;
    reg  line$0$clock;
    reg  [1:0] line$1$d;
    wire  [1:0] line$1$q;
    reg  line$1$clock;
    reg  [1:0] line$2$d;
    wire  [1:0] line$2$q;
    reg  line$2$clock;
    reg  [1:0] line$3$d;
    wire  [1:0] line$3$q;
    reg  line$3$clock;
    reg  [1:0] line$4$d;
    wire  [1:0] line$4$q;
    reg  line$4$clock;
    reg  [1:0] line$5$d;
    wire  [1:0] line$5$q;
    reg  line$5$clock;
    reg  [1:0] line$6$d;
    wire  [1:0] line$6$q;
    reg  line$6$clock;
    reg  [1:0] line$7$d;
    wire  [1:0] line$7$q;
    reg  line$7$clock;
    reg  [1:0] line$8$d;
    wire  [1:0] line$8$q;
    reg  line$8$clock;
    reg  [1:0] line$9$d;
    wire  [1:0] line$9$q;
    reg  line$9$clock;
    reg  [1:0] line$10$d;
    wire  [1:0] line$10$q;
    reg  line$10$clock;
    reg  [1:0] line$11$d;
    wire  [1:0] line$11$q;
    reg  line$11$clock;
    reg  [1:0] line$12$d;
    wire  [1:0] line$12$q;
    reg  line$12$clock;
    reg  [1:0] line$13$d;
    wire  [1:0] line$13$q;
    reg  line$13$clock;
    reg  [1:0] line$14$d;
    wire  [1:0] line$14$q;
    reg  line$14$clock;
    reg  [1:0] line$15$d;
    wire  [1:0] line$15$q;
    reg  line$15$clock;
    
    // Sub module instances
    top$core$dop$busy_r line$0(
        .d(line$0$d),
        .q(line$0$q),
        .clock(line$0$clock)
    );
    top$core$dop$busy_r line$1(
        .d(line$1$d),
        .q(line$1$q),
        .clock(line$1$clock)
    );
    top$core$dop$busy_r line$2(
        .d(line$2$d),
        .q(line$2$q),
        .clock(line$2$clock)
    );
    top$core$dop$busy_r line$3(
        .d(line$3$d),
        .q(line$3$q),
        .clock(line$3$clock)
    );
    top$core$dop$busy_r line$4(
        .d(line$4$d),
        .q(line$4$q),
        .clock(line$4$clock)
    );
    top$core$dop$busy_r line$5(
        .d(line$5$d),
        .q(line$5$q),
        .clock(line$5$clock)
    );
    top$core$dop$busy_r line$6(
        .d(line$6$d),
        .q(line$6$q),
        .clock(line$6$clock)
    );
    top$core$dop$busy_r line$7(
        .d(line$7$d),
        .q(line$7$q),
        .clock(line$7$clock)
    );
    top$core$dop$busy_r line$8(
        .d(line$8$d),
        .q(line$8$q),
        .clock(line$8$clock)
    );
    top$core$dop$busy_r line$9(
        .d(line$9$d),
        .q(line$9$q),
        .clock(line$9$clock)
    );
    top$core$dop$busy_r line$10(
        .d(line$10$d),
        .q(line$10$q),
        .clock(line$10$clock)
    );
    top$core$dop$busy_r line$11(
        .d(line$11$d),
        .q(line$11$q),
        .clock(line$11$clock)
    );
    top$core$dop$busy_r line$12(
        .d(line$12$d),
        .q(line$12$q),
        .clock(line$12$clock)
    );
    top$core$dop$busy_r line$13(
        .d(line$13$d),
        .q(line$13$q),
        .clock(line$13$clock)
    );
    top$core$dop$busy_r line$14(
        .d(line$14$d),
        .q(line$14$q),
        .clock(line$14$clock)
    );
    top$core$dop$busy_r line$15(
        .d(line$15$d),
        .q(line$15$q),
        .clock(line$15$clock)
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
        line$4$clock = clock;
        line$4$d = d;
        line$5$clock = clock;
        line$5$d = d;
        line$6$clock = clock;
        line$6$d = d;
        line$7$clock = clock;
        line$7$d = d;
        line$8$clock = clock;
        line$8$d = d;
        line$9$clock = clock;
        line$9$d = d;
        line$10$clock = clock;
        line$10$d = d;
        line$11$clock = clock;
        line$11$d = d;
        line$12$clock = clock;
        line$12$d = d;
        line$13$clock = clock;
        line$13$d = d;
        line$14$clock = clock;
        line$14$d = d;
        line$15$clock = clock;
        line$15$d = d;
        line$0$d = line$1$q;
        line$1$d = line$2$q;
        line$2$d = line$3$q;
        line$3$d = line$4$q;
        line$4$d = line$5$q;
        line$5$d = line$6$q;
        line$6$d = line$7$q;
        line$7$d = line$8$q;
        line$8$d = line$9$q;
        line$9$d = line$10$q;
        line$10$d = line$11$q;
        line$11$d = line$12$q;
        line$12$d = line$13$q;
        line$13$d = line$14$q;
        line$14$d = line$15$q;
        q = line$0$q;
    end
    
endmodule // top$tri_unit$tc_ab$edges$0$rz_sgn_wait


module top$tri_unit$tc_ab$edges$0$sign_a(x,e,sgn);
    
    // Module arguments
    input wire  [31:0] x;
    input wire  [31:0] e;
    output reg  [1:0] sgn;
    
    // Constant declarations
    localparam  c_pos = 2'b1;
    localparam  c_neg = 2'b10;
    
    // Local signals
    reg  nan;
    reg  big;
    
    // Update code
    always @(*) begin
        nan = &x[(32'h17)+:(8)] & (x[(32'h0)+:(23)] != 32'h0);
        big = ((x[(32'h0)+:(31)]) & 32'hffffffff) > e;
        sgn = 32'h0;
        if (big & ~nan) begin
            sgn = c_pos;
            if (x[32'h1f]) begin
                sgn = c_neg;
            end
        end
    end
    
endmodule // top$tri_unit$tc_ab$edges$0$sign_a


module top$tri_unit$tc_ab$exact_wait(clock,d,q);
    
    // Module arguments
    input wire  clock;
    input wire  d;
    output reg  q;
    
    // Stub signals
    reg  line$0$d;
    wire  line$0$q;
    reg  line$0$clock;
    reg  line$1$d;
    wire  line$1$q;
    reg  line$1$clock;
    reg  line$2$d;
    wire  line$2$q;
    reg  line$2$clock;
    reg  line$3$d;
    wire  line$3$q;
    reg  line$3$clock;
    reg  line$4$d;
    wire  line$4$q;
    reg  line$4$clock;
    reg  line$5$d;
    wire  line$5$q;
    reg  line$5$clock;
    reg  line$6$d;
    wire  line$6$q;
    reg  line$6$clock;
    reg  line$7$d;
    wire  line$7$q;
    reg  line$7$clock;
    reg  line$8$d;
    wire  line$8$q;
    reg  line$8$clock;
    reg  line$9$d;
    wire  line$9$q;
    reg  line$9$clock;
    reg  line$10$d;
    wire  line$10$q;
    reg  line$10$clock;
    reg  line$11$d;
    wire  line$11$q;
    reg  line$11$clock;
    reg  line$12$d;
    wire  line$12$q;
    reg  line$12$clock;
    reg  line$13$d;
    wire  line$13$q;
    reg  line$13$clock;
    reg  line$14$d;
    wire  line$14$q;
    reg  line$14$clock;
    reg  line$15$d;
    wire  line$15$q;
    reg  line$15$clock;
    reg  line$16$d;
    wire  line$16$q;
    reg  line$16$clock;
    reg  line$17$d;
    wire  line$17$q;
    reg  line$17$clock;
    reg  line$18$d;
    wire  line$18$q;
    reg  line$18$clock;
    reg  line$19$d;
    wire  line$19$q;
    reg  line$19$clock;
    reg  line$20$d;
    wire  line$20$q;
    reg  line$20$clock;
    reg  line$21$d;
    wire  line$21$q;
    reg  line$21$clock;
    
    // Sub module instances
    top$core$done_r line$0(
        .d(line$0$d),
        .q(line$0$q),
        .clock(line$0$clock)
    );
    top$core$done_r line$1(
        .d(line$1$d),
        .q(line$1$q),
        .clock(line$1$clock)
    );
    top$core$done_r line$2(
        .d(line$2$d),
        .q(line$2$q),
        .clock(line$2$clock)
    );
    top$core$done_r line$3(
        .d(line$3$d),
        .q(line$3$q),
        .clock(line$3$clock)
    );
    top$core$done_r line$4(
        .d(line$4$d),
        .q(line$4$q),
        .clock(line$4$clock)
    );
    top$core$done_r line$5(
        .d(line$5$d),
        .q(line$5$q),
        .clock(line$5$clock)
    );
    top$core$done_r line$6(
        .d(line$6$d),
        .q(line$6$q),
        .clock(line$6$clock)
    );
    top$core$done_r line$7(
        .d(line$7$d),
        .q(line$7$q),
        .clock(line$7$clock)
    );
    top$core$done_r line$8(
        .d(line$8$d),
        .q(line$8$q),
        .clock(line$8$clock)
    );
    top$core$done_r line$9(
        .d(line$9$d),
        .q(line$9$q),
        .clock(line$9$clock)
    );
    top$core$done_r line$10(
        .d(line$10$d),
        .q(line$10$q),
        .clock(line$10$clock)
    );
    top$core$done_r line$11(
        .d(line$11$d),
        .q(line$11$q),
        .clock(line$11$clock)
    );
    top$core$done_r line$12(
        .d(line$12$d),
        .q(line$12$q),
        .clock(line$12$clock)
    );
    top$core$done_r line$13(
        .d(line$13$d),
        .q(line$13$q),
        .clock(line$13$clock)
    );
    top$core$done_r line$14(
        .d(line$14$d),
        .q(line$14$q),
        .clock(line$14$clock)
    );
    top$core$done_r line$15(
        .d(line$15$d),
        .q(line$15$q),
        .clock(line$15$clock)
    );
    top$core$done_r line$16(
        .d(line$16$d),
        .q(line$16$q),
        .clock(line$16$clock)
    );
    top$core$done_r line$17(
        .d(line$17$d),
        .q(line$17$q),
        .clock(line$17$clock)
    );
    top$core$done_r line$18(
        .d(line$18$d),
        .q(line$18$q),
        .clock(line$18$clock)
    );
    top$core$done_r line$19(
        .d(line$19$d),
        .q(line$19$q),
        .clock(line$19$clock)
    );
    top$core$done_r line$20(
        .d(line$20$d),
        .q(line$20$q),
        .clock(line$20$clock)
    );
    top$core$done_r line$21(
        .d(line$21$d),
        .q(line$21$q),
        .clock(line$21$clock)
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
        line$4$clock = clock;
        line$4$d = d;
        line$5$clock = clock;
        line$5$d = d;
        line$6$clock = clock;
        line$6$d = d;
        line$7$clock = clock;
        line$7$d = d;
        line$8$clock = clock;
        line$8$d = d;
        line$9$clock = clock;
        line$9$d = d;
        line$10$clock = clock;
        line$10$d = d;
        line$11$clock = clock;
        line$11$d = d;
        line$12$clock = clock;
        line$12$d = d;
        line$13$clock = clock;
        line$13$d = d;
        line$14$clock = clock;
        line$14$d = d;
        line$15$clock = clock;
        line$15$d = d;
        line$16$clock = clock;
        line$16$d = d;
        line$17$clock = clock;
        line$17$d = d;
        line$18$clock = clock;
        line$18$d = d;
        line$19$clock = clock;
        line$19$d = d;
        line$20$clock = clock;
        line$20$d = d;
        line$21$clock = clock;
        line$21$d = d;
        line$0$d = line$1$q;
        line$1$d = line$2$q;
        line$2$d = line$3$q;
        line$3$d = line$4$q;
        line$4$d = line$5$q;
        line$5$d = line$6$q;
        line$6$d = line$7$q;
        line$7$d = line$8$q;
        line$8$d = line$9$q;
        line$9$d = line$10$q;
        line$10$d = line$11$q;
        line$11$d = line$12$q;
        line$12$d = line$13$q;
        line$13$d = line$14$q;
        line$14$d = line$15$q;
        line$15$d = line$16$q;
        line$16$d = line$17$q;
        line$17$d = line$18$q;
        line$18$d = line$19$q;
        line$19$d = line$20$q;
        line$20$d = line$21$q;
        q = line$0$q;
    end
    
endmodule // top$tri_unit$tc_ab$exact_wait


module top$tri_unit$tc_ab$l1_wait$0(clock,d,q);
    
    // Module arguments
    input wire  clock;
    input wire  [31:0] d;
    output reg  [31:0] q;
    
    // Stub signals
    reg  [31:0] line$0$d;
    wire  [31:0] line$0$q;
    reg  line$0$clock;
    reg  [31:0] line$1$d;
    wire  [31:0] line$1$q;
    reg  line$1$clock;
    
    // Sub module instances
    top$core$cnt_nf line$0(
        .d(line$0$d),
        .q(line$0$q),
        .clock(line$0$clock)
    );
    top$core$cnt_nf line$1(
        .d(line$1$d),
        .q(line$1$q),
        .clock(line$1$clock)
    );
    
    // Update code
    always @(*) begin
        line$0$clock = clock;
        line$0$d = d;
        line$1$clock = clock;
        line$1$d = d;
        line$0$d = line$1$q;
        q = line$0$q;
    end
    
endmodule // top$tri_unit$tc_ab$l1_wait$0


module top$tri_unit$tc_ab$mb_0$0(clock,a0,a1,a2,b0,b1,b2,c,y);
    
    // Module arguments
    input wire  clock;
    input wire  [31:0] a0;
    input wire  [31:0] a1;
    input wire  [31:0] a2;
    input wire  [31:0] b0;
    input wire  [31:0] b1;
    input wire  [31:0] b2;
    input wire  [31:0] c;
    output reg  [31:0] y;
    
    // Constant declarations
    localparam  affine = 1'b0;
    localparam  mask = 32'hffffffff;
    
    // Stub signals
    reg  p$0$clock;
    reg  [31:0] p$0$a;
    reg  [31:0] p$0$b;
    reg  p$0$valid_in;
    wire  [31:0] p$0$y;
    wire  p$0$valid_out;
    reg  p$1$clock;
    reg  [31:0] p$1$a;
    reg  [31:0] p$1$b;
    reg  p$1$valid_in;
    wire  [31:0] p$1$y;
    wire  p$1$valid_out;
    reg  p$2$clock;
    reg  [31:0] p$2$a;
    reg  [31:0] p$2$b;
    reg  p$2$valid_in;
    wire  [31:0] p$2$y;
    wire  p$2$valid_out;
    reg  s01$clock;
    reg  [31:0] s01$a;
    reg  [31:0] s01$b;
    reg  s01$sub;
    reg  s01$valid_in;
    wire  [31:0] s01$y;
    wire  s01$valid_out;
    reg  s2c$clock;
    reg  [31:0] s2c$a;
    reg  [31:0] s2c$b;
    reg  s2c$sub;
    reg  s2c$valid_in;
    wire  [31:0] s2c$y;
    wire  s2c$valid_out;
    reg  s$clock;
    reg  [31:0] s$a;
    reg  [31:0] s$b;
    reg  s$sub;
    reg  s$valid_in;
    wire  [31:0] s$y;
    wire  s$valid_out;
    reg  p2_wait$clock;
    reg  [31:0] p2_wait$d;
    wire  [31:0] p2_wait$q;
    
    // Sub module instances
    top$tri_unit$tc_ab$edges$0$px_qz p$0(
        .clock(p$0$clock),
        .a(p$0$a),
        .b(p$0$b),
        .valid_in(p$0$valid_in),
        .y(p$0$y),
        .valid_out(p$0$valid_out)
    );
    top$tri_unit$tc_ab$edges$0$px_qz p$1(
        .clock(p$1$clock),
        .a(p$1$a),
        .b(p$1$b),
        .valid_in(p$1$valid_in),
        .y(p$1$y),
        .valid_out(p$1$valid_out)
    );
    top$tri_unit$tc_ab$edges$0$px_qz p$2(
        .clock(p$2$clock),
        .a(p$2$a),
        .b(p$2$b),
        .valid_in(p$2$valid_in),
        .y(p$2$y),
        .valid_out(p$2$valid_out)
    );
    top$tri_unit$tc_ab$edges$0$a s01(
        .clock(s01$clock),
        .a(s01$a),
        .b(s01$b),
        .sub(s01$sub),
        .valid_in(s01$valid_in),
        .y(s01$y),
        .valid_out(s01$valid_out)
    );
    top$tri_unit$tc_ab$edges$0$a s2c(
        .clock(s2c$clock),
        .a(s2c$a),
        .b(s2c$b),
        .sub(s2c$sub),
        .valid_in(s2c$valid_in),
        .y(s2c$y),
        .valid_out(s2c$valid_out)
    );
    top$tri_unit$tc_ab$edges$0$a s(
        .clock(s$clock),
        .a(s$a),
        .b(s$b),
        .sub(s$sub),
        .valid_in(s$valid_in),
        .y(s$y),
        .valid_out(s$valid_out)
    );
    top$tri_unit$tc_ab$edges$0$brs_wait p2_wait(
        .clock(p2_wait$clock),
        .d(p2_wait$d),
        .q(p2_wait$q)
    );
    
    // Update code
    always @(*) begin
        s01$clock = clock;
        s2c$clock = clock;
        s$clock = clock;
        p2_wait$clock = clock;
        p$0$clock = clock;
        p$0$valid_in = 1'b0;
        p$1$clock = clock;
        p$1$valid_in = 1'b0;
        p$2$clock = clock;
        p$2$valid_in = 1'b0;
        p$0$a = a0 & mask;
        p$0$b = b0 & mask;
        p$1$a = a1 & mask;
        p$1$b = b1 & mask;
        p$2$a = a2 & mask;
        p$2$b = b2 & mask;
        s01$a = p$0$y;
        s01$b = p$1$y;
        s01$sub = 1'b0;
        s01$valid_in = 1'b0;
        s2c$a = p$2$y;
        s2c$b = c & mask;
        s2c$sub = 1'b0;
        s2c$valid_in = 1'b0;
        p2_wait$d = p$2$y;
        s$a = s01$y;
        s$b = p2_wait$q;
        if (affine) begin
            s$b = s2c$y;
        end
        s$sub = 1'b0;
        s$valid_in = 1'b0;
        y = s$y;
    end
    
endmodule // top$tri_unit$tc_ab$mb_0$0


module top$tri_unit$tc_ab$mb_0$3(clock,a0,a1,a2,b0,b1,b2,c,y);
    
    // Module arguments
    input wire  clock;
    input wire  [31:0] a0;
    input wire  [31:0] a1;
    input wire  [31:0] a2;
    input wire  [31:0] b0;
    input wire  [31:0] b1;
    input wire  [31:0] b2;
    input wire  [31:0] c;
    output reg  [31:0] y;
    
    // Constant declarations
    localparam  affine = 1'b1;
    localparam  mask = 32'hffffffff;
    
    // Stub signals
    reg  p$0$clock;
    reg  [31:0] p$0$a;
    reg  [31:0] p$0$b;
    reg  p$0$valid_in;
    wire  [31:0] p$0$y;
    wire  p$0$valid_out;
    reg  p$1$clock;
    reg  [31:0] p$1$a;
    reg  [31:0] p$1$b;
    reg  p$1$valid_in;
    wire  [31:0] p$1$y;
    wire  p$1$valid_out;
    reg  p$2$clock;
    reg  [31:0] p$2$a;
    reg  [31:0] p$2$b;
    reg  p$2$valid_in;
    wire  [31:0] p$2$y;
    wire  p$2$valid_out;
    reg  s01$clock;
    reg  [31:0] s01$a;
    reg  [31:0] s01$b;
    reg  s01$sub;
    reg  s01$valid_in;
    wire  [31:0] s01$y;
    wire  s01$valid_out;
    reg  s2c$clock;
    reg  [31:0] s2c$a;
    reg  [31:0] s2c$b;
    reg  s2c$sub;
    reg  s2c$valid_in;
    wire  [31:0] s2c$y;
    wire  s2c$valid_out;
    reg  s$clock;
    reg  [31:0] s$a;
    reg  [31:0] s$b;
    reg  s$sub;
    reg  s$valid_in;
    wire  [31:0] s$y;
    wire  s$valid_out;
    reg  p2_wait$clock;
    reg  [31:0] p2_wait$d;
    wire  [31:0] p2_wait$q;
    
    // Sub module instances
    top$tri_unit$tc_ab$edges$0$px_qz p$0(
        .clock(p$0$clock),
        .a(p$0$a),
        .b(p$0$b),
        .valid_in(p$0$valid_in),
        .y(p$0$y),
        .valid_out(p$0$valid_out)
    );
    top$tri_unit$tc_ab$edges$0$px_qz p$1(
        .clock(p$1$clock),
        .a(p$1$a),
        .b(p$1$b),
        .valid_in(p$1$valid_in),
        .y(p$1$y),
        .valid_out(p$1$valid_out)
    );
    top$tri_unit$tc_ab$edges$0$px_qz p$2(
        .clock(p$2$clock),
        .a(p$2$a),
        .b(p$2$b),
        .valid_in(p$2$valid_in),
        .y(p$2$y),
        .valid_out(p$2$valid_out)
    );
    top$tri_unit$tc_ab$edges$0$a s01(
        .clock(s01$clock),
        .a(s01$a),
        .b(s01$b),
        .sub(s01$sub),
        .valid_in(s01$valid_in),
        .y(s01$y),
        .valid_out(s01$valid_out)
    );
    top$tri_unit$tc_ab$edges$0$a s2c(
        .clock(s2c$clock),
        .a(s2c$a),
        .b(s2c$b),
        .sub(s2c$sub),
        .valid_in(s2c$valid_in),
        .y(s2c$y),
        .valid_out(s2c$valid_out)
    );
    top$tri_unit$tc_ab$edges$0$a s(
        .clock(s$clock),
        .a(s$a),
        .b(s$b),
        .sub(s$sub),
        .valid_in(s$valid_in),
        .y(s$y),
        .valid_out(s$valid_out)
    );
    top$tri_unit$tc_ab$edges$0$brs_wait p2_wait(
        .clock(p2_wait$clock),
        .d(p2_wait$d),
        .q(p2_wait$q)
    );
    
    // Update code
    always @(*) begin
        s01$clock = clock;
        s2c$clock = clock;
        s$clock = clock;
        p2_wait$clock = clock;
        p$0$clock = clock;
        p$0$valid_in = 1'b0;
        p$1$clock = clock;
        p$1$valid_in = 1'b0;
        p$2$clock = clock;
        p$2$valid_in = 1'b0;
        p$0$a = a0 & mask;
        p$0$b = b0 & mask;
        p$1$a = a1 & mask;
        p$1$b = b1 & mask;
        p$2$a = a2 & mask;
        p$2$b = b2 & mask;
        s01$a = p$0$y;
        s01$b = p$1$y;
        s01$sub = 1'b0;
        s01$valid_in = 1'b0;
        s2c$a = p$2$y;
        s2c$b = c & mask;
        s2c$sub = 1'b0;
        s2c$valid_in = 1'b0;
        p2_wait$d = p$2$y;
        s$a = s01$y;
        s$b = p2_wait$q;
        if (affine) begin
            s$b = s2c$y;
        end
        s$sub = 1'b0;
        s$valid_in = 1'b0;
        y = s$y;
    end
    
endmodule // top$tri_unit$tc_ab$mb_0$3


module top$tri_unit$tc_ab$mg_0$0(clock,a0,a1,a2,b0,b1,b2,c,y);
    
    // Module arguments
    input wire  clock;
    input wire  [31:0] a0;
    input wire  [31:0] a1;
    input wire  [31:0] a2;
    input wire  [31:0] b0;
    input wire  [31:0] b1;
    input wire  [31:0] b2;
    input wire  [31:0] c;
    output reg  [31:0] y;
    
    // Constant declarations
    localparam  affine = 1'b0;
    localparam  mask = 32'h7fffffff;
    
    // Stub signals
    reg  p$0$clock;
    reg  [31:0] p$0$a;
    reg  [31:0] p$0$b;
    reg  p$0$valid_in;
    wire  [31:0] p$0$y;
    wire  p$0$valid_out;
    reg  p$1$clock;
    reg  [31:0] p$1$a;
    reg  [31:0] p$1$b;
    reg  p$1$valid_in;
    wire  [31:0] p$1$y;
    wire  p$1$valid_out;
    reg  p$2$clock;
    reg  [31:0] p$2$a;
    reg  [31:0] p$2$b;
    reg  p$2$valid_in;
    wire  [31:0] p$2$y;
    wire  p$2$valid_out;
    reg  s01$clock;
    reg  [31:0] s01$a;
    reg  [31:0] s01$b;
    reg  s01$sub;
    reg  s01$valid_in;
    wire  [31:0] s01$y;
    wire  s01$valid_out;
    reg  s2c$clock;
    reg  [31:0] s2c$a;
    reg  [31:0] s2c$b;
    reg  s2c$sub;
    reg  s2c$valid_in;
    wire  [31:0] s2c$y;
    wire  s2c$valid_out;
    reg  s$clock;
    reg  [31:0] s$a;
    reg  [31:0] s$b;
    reg  s$sub;
    reg  s$valid_in;
    wire  [31:0] s$y;
    wire  s$valid_out;
    reg  p2_wait$clock;
    reg  [31:0] p2_wait$d;
    wire  [31:0] p2_wait$q;
    
    // Sub module instances
    top$tri_unit$tc_ab$af p$0(
        .clock(p$0$clock),
        .a(p$0$a),
        .b(p$0$b),
        .valid_in(p$0$valid_in),
        .y(p$0$y),
        .valid_out(p$0$valid_out)
    );
    top$tri_unit$tc_ab$af p$1(
        .clock(p$1$clock),
        .a(p$1$a),
        .b(p$1$b),
        .valid_in(p$1$valid_in),
        .y(p$1$y),
        .valid_out(p$1$valid_out)
    );
    top$tri_unit$tc_ab$af p$2(
        .clock(p$2$clock),
        .a(p$2$a),
        .b(p$2$b),
        .valid_in(p$2$valid_in),
        .y(p$2$y),
        .valid_out(p$2$valid_out)
    );
    top$tri_unit$tc_ab$aerr s01(
        .clock(s01$clock),
        .a(s01$a),
        .b(s01$b),
        .sub(s01$sub),
        .valid_in(s01$valid_in),
        .y(s01$y),
        .valid_out(s01$valid_out)
    );
    top$tri_unit$tc_ab$aerr s2c(
        .clock(s2c$clock),
        .a(s2c$a),
        .b(s2c$b),
        .sub(s2c$sub),
        .valid_in(s2c$valid_in),
        .y(s2c$y),
        .valid_out(s2c$valid_out)
    );
    top$tri_unit$tc_ab$aerr s(
        .clock(s$clock),
        .a(s$a),
        .b(s$b),
        .sub(s$sub),
        .valid_in(s$valid_in),
        .y(s$y),
        .valid_out(s$valid_out)
    );
    top$tri_unit$tc_ab$edges$0$brs_wait p2_wait(
        .clock(p2_wait$clock),
        .d(p2_wait$d),
        .q(p2_wait$q)
    );
    
    // Update code
    always @(*) begin
        s01$clock = clock;
        s2c$clock = clock;
        s$clock = clock;
        p2_wait$clock = clock;
        p$0$clock = clock;
        p$0$valid_in = 1'b0;
        p$1$clock = clock;
        p$1$valid_in = 1'b0;
        p$2$clock = clock;
        p$2$valid_in = 1'b0;
        p$0$a = a0 & mask;
        p$0$b = b0 & mask;
        p$1$a = a1 & mask;
        p$1$b = b1 & mask;
        p$2$a = a2 & mask;
        p$2$b = b2 & mask;
        s01$a = p$0$y;
        s01$b = p$1$y;
        s01$sub = 1'b0;
        s01$valid_in = 1'b0;
        s2c$a = p$2$y;
        s2c$b = c & mask;
        s2c$sub = 1'b0;
        s2c$valid_in = 1'b0;
        p2_wait$d = p$2$y;
        s$a = s01$y;
        s$b = p2_wait$q;
        if (affine) begin
            s$b = s2c$y;
        end
        s$sub = 1'b0;
        s$valid_in = 1'b0;
        y = s$y;
    end
    
endmodule // top$tri_unit$tc_ab$mg_0$0


module top$tri_unit$tc_ab$mg_0$3(clock,a0,a1,a2,b0,b1,b2,c,y);
    
    // Module arguments
    input wire  clock;
    input wire  [31:0] a0;
    input wire  [31:0] a1;
    input wire  [31:0] a2;
    input wire  [31:0] b0;
    input wire  [31:0] b1;
    input wire  [31:0] b2;
    input wire  [31:0] c;
    output reg  [31:0] y;
    
    // Constant declarations
    localparam  affine = 1'b1;
    localparam  mask = 32'h7fffffff;
    
    // Stub signals
    reg  p$0$clock;
    reg  [31:0] p$0$a;
    reg  [31:0] p$0$b;
    reg  p$0$valid_in;
    wire  [31:0] p$0$y;
    wire  p$0$valid_out;
    reg  p$1$clock;
    reg  [31:0] p$1$a;
    reg  [31:0] p$1$b;
    reg  p$1$valid_in;
    wire  [31:0] p$1$y;
    wire  p$1$valid_out;
    reg  p$2$clock;
    reg  [31:0] p$2$a;
    reg  [31:0] p$2$b;
    reg  p$2$valid_in;
    wire  [31:0] p$2$y;
    wire  p$2$valid_out;
    reg  s01$clock;
    reg  [31:0] s01$a;
    reg  [31:0] s01$b;
    reg  s01$sub;
    reg  s01$valid_in;
    wire  [31:0] s01$y;
    wire  s01$valid_out;
    reg  s2c$clock;
    reg  [31:0] s2c$a;
    reg  [31:0] s2c$b;
    reg  s2c$sub;
    reg  s2c$valid_in;
    wire  [31:0] s2c$y;
    wire  s2c$valid_out;
    reg  s$clock;
    reg  [31:0] s$a;
    reg  [31:0] s$b;
    reg  s$sub;
    reg  s$valid_in;
    wire  [31:0] s$y;
    wire  s$valid_out;
    reg  p2_wait$clock;
    reg  [31:0] p2_wait$d;
    wire  [31:0] p2_wait$q;
    
    // Sub module instances
    top$tri_unit$tc_ab$af p$0(
        .clock(p$0$clock),
        .a(p$0$a),
        .b(p$0$b),
        .valid_in(p$0$valid_in),
        .y(p$0$y),
        .valid_out(p$0$valid_out)
    );
    top$tri_unit$tc_ab$af p$1(
        .clock(p$1$clock),
        .a(p$1$a),
        .b(p$1$b),
        .valid_in(p$1$valid_in),
        .y(p$1$y),
        .valid_out(p$1$valid_out)
    );
    top$tri_unit$tc_ab$af p$2(
        .clock(p$2$clock),
        .a(p$2$a),
        .b(p$2$b),
        .valid_in(p$2$valid_in),
        .y(p$2$y),
        .valid_out(p$2$valid_out)
    );
    top$tri_unit$tc_ab$aerr s01(
        .clock(s01$clock),
        .a(s01$a),
        .b(s01$b),
        .sub(s01$sub),
        .valid_in(s01$valid_in),
        .y(s01$y),
        .valid_out(s01$valid_out)
    );
    top$tri_unit$tc_ab$aerr s2c(
        .clock(s2c$clock),
        .a(s2c$a),
        .b(s2c$b),
        .sub(s2c$sub),
        .valid_in(s2c$valid_in),
        .y(s2c$y),
        .valid_out(s2c$valid_out)
    );
    top$tri_unit$tc_ab$aerr s(
        .clock(s$clock),
        .a(s$a),
        .b(s$b),
        .sub(s$sub),
        .valid_in(s$valid_in),
        .y(s$y),
        .valid_out(s$valid_out)
    );
    top$tri_unit$tc_ab$edges$0$brs_wait p2_wait(
        .clock(p2_wait$clock),
        .d(p2_wait$d),
        .q(p2_wait$q)
    );
    
    // Update code
    always @(*) begin
        s01$clock = clock;
        s2c$clock = clock;
        s$clock = clock;
        p2_wait$clock = clock;
        p$0$clock = clock;
        p$0$valid_in = 1'b0;
        p$1$clock = clock;
        p$1$valid_in = 1'b0;
        p$2$clock = clock;
        p$2$valid_in = 1'b0;
        p$0$a = a0 & mask;
        p$0$b = b0 & mask;
        p$1$a = a1 & mask;
        p$1$b = b1 & mask;
        p$2$a = a2 & mask;
        p$2$b = b2 & mask;
        s01$a = p$0$y;
        s01$b = p$1$y;
        s01$sub = 1'b0;
        s01$valid_in = 1'b0;
        s2c$a = p$2$y;
        s2c$b = c & mask;
        s2c$sub = 1'b0;
        s2c$valid_in = 1'b0;
        p2_wait$d = p$2$y;
        s$a = s01$y;
        s$b = p2_wait$q;
        if (affine) begin
            s$b = s2c$y;
        end
        s$sub = 1'b0;
        s$valid_in = 1'b0;
        y = s$y;
    end
    
endmodule // top$tri_unit$tc_ab$mg_0$3


module top$tri_unit$tc_ab$tag_wait(clock,d,q);
    
    // Module arguments
    input wire  clock;
    input wire  [31:0] d;
    output reg  [31:0] q;
    
    // Stub signals
    reg  [31:0] line$0$d;
    wire  [31:0] line$0$q;
    reg  line$0$clock;
    reg  [31:0] line$1$d;
    wire  [31:0] line$1$q;
    reg  line$1$clock;
    reg  [31:0] line$2$d;
    wire  [31:0] line$2$q;
    reg  line$2$clock;
    reg  [31:0] line$3$d;
    wire  [31:0] line$3$q;
    reg  line$3$clock;
    reg  [31:0] line$4$d;
    wire  [31:0] line$4$q;
    reg  line$4$clock;
    reg  [31:0] line$5$d;
    wire  [31:0] line$5$q;
    reg  line$5$clock;
    reg  [31:0] line$6$d;
    wire  [31:0] line$6$q;
    reg  line$6$clock;
    reg  [31:0] line$7$d;
    wire  [31:0] line$7$q;
    reg  line$7$clock;
    reg  [31:0] line$8$d;
    wire  [31:0] line$8$q;
    reg  line$8$clock;
    reg  [31:0] line$9$d;
    wire  [31:0] line$9$q;
    reg  line$9$clock;
    reg  [31:0] line$10$d;
    wire  [31:0] line$10$q;
    reg  line$10$clock;
    reg  [31:0] line$11$d;
    wire  [31:0] line$11$q;
    reg  line$11$clock;
    reg  [31:0] line$12$d;
    wire  [31:0] line$12$q;
    reg  line$12$clock;
    reg  [31:0] line$13$d;
    wire  [31:0] line$13$q;
    reg  line$13$clock;
    reg  [31:0] line$14$d;
    wire  [31:0] line$14$q;
    reg  line$14$clock;
    reg  [31:0] line$15$d;
    wire  [31:0] line$15$q;
    reg  line$15$clock;
    reg  [31:0] line$16$d;
    wire  [31:0] line$16$q;
    reg  line$16$clock;
    reg  [31:0] line$17$d;
    wire  [31:0] line$17$q;
    reg  line$17$clock;
    reg  [31:0] line$18$d;
    wire  [31:0] line$18$q;
    reg  line$18$clock;
    reg  [31:0] line$19$d;
    wire  [31:0] line$19$q;
    reg  line$19$clock;
    reg  [31:0] line$20$d;
    wire  [31:0] line$20$q;
    reg  line$20$clock;
    reg  [31:0] line$21$d;
    wire  [31:0] line$21$q;
    reg  line$21$clock;
    reg  [31:0] line$22$d;
    wire  [31:0] line$22$q;
    reg  line$22$clock;
    reg  [31:0] line$23$d;
    wire  [31:0] line$23$q;
    reg  line$23$clock;
    reg  [31:0] line$24$d;
    wire  [31:0] line$24$q;
    reg  line$24$clock;
    reg  [31:0] line$25$d;
    wire  [31:0] line$25$q;
    reg  line$25$clock;
    reg  [31:0] line$26$d;
    wire  [31:0] line$26$q;
    reg  line$26$clock;
    reg  [31:0] line$27$d;
    wire  [31:0] line$27$q;
    reg  line$27$clock;
    reg  [31:0] line$28$d;
    wire  [31:0] line$28$q;
    reg  line$28$clock;
    reg  [31:0] line$29$d;
    wire  [31:0] line$29$q;
    reg  line$29$clock;
    reg  [31:0] line$30$d;
    wire  [31:0] line$30$q;
    reg  line$30$clock;
    reg  [31:0] line$31$d;
    wire  [31:0] line$31$q;
    reg  line$31$clock;
    reg  [31:0] line$32$d;
    wire  [31:0] line$32$q;
    reg  line$32$clock;
    reg  [31:0] line$33$d;
    wire  [31:0] line$33$q;
    reg  line$33$clock;
    reg  [31:0] line$34$d;
    wire  [31:0] line$34$q;
    reg  line$34$clock;
    reg  [31:0] line$35$d;
    wire  [31:0] line$35$q;
    reg  line$35$clock;
    reg  [31:0] line$36$d;
    wire  [31:0] line$36$q;
    reg  line$36$clock;
    reg  [31:0] line$37$d;
    wire  [31:0] line$37$q;
    reg  line$37$clock;
    reg  [31:0] line$38$d;
    wire  [31:0] line$38$q;
    reg  line$38$clock;
    reg  [31:0] line$39$d;
    wire  [31:0] line$39$q;
    reg  line$39$clock;
    reg  [31:0] line$40$d;
    wire  [31:0] line$40$q;
    reg  line$40$clock;
    reg  [31:0] line$41$d;
    wire  [31:0] line$41$q;
    reg  line$41$clock;
    reg  [31:0] line$42$d;
    wire  [31:0] line$42$q;
    reg  line$42$clock;
    reg  [31:0] line$43$d;
    wire  [31:0] line$43$q;
    reg  line$43$clock;
    reg  [31:0] line$44$d;
    wire  [31:0] line$44$q;
    reg  line$44$clock;
    reg  [31:0] line$45$d;
    wire  [31:0] line$45$q;
    reg  line$45$clock;
    reg  [31:0] line$46$d;
    wire  [31:0] line$46$q;
    reg  line$46$clock;
    reg  [31:0] line$47$d;
    wire  [31:0] line$47$q;
    reg  line$47$clock;
    reg  [31:0] line$48$d;
    wire  [31:0] line$48$q;
    reg  line$48$clock;
    reg  [31:0] line$49$d;
    wire  [31:0] line$49$q;
    reg  line$49$clock;
    
    // Sub module instances
    top$core$cnt_nf line$0(
        .d(line$0$d),
        .q(line$0$q),
        .clock(line$0$clock)
    );
    top$core$cnt_nf line$1(
        .d(line$1$d),
        .q(line$1$q),
        .clock(line$1$clock)
    );
    top$core$cnt_nf line$2(
        .d(line$2$d),
        .q(line$2$q),
        .clock(line$2$clock)
    );
    top$core$cnt_nf line$3(
        .d(line$3$d),
        .q(line$3$q),
        .clock(line$3$clock)
    );
    top$core$cnt_nf line$4(
        .d(line$4$d),
        .q(line$4$q),
        .clock(line$4$clock)
    );
    top$core$cnt_nf line$5(
        .d(line$5$d),
        .q(line$5$q),
        .clock(line$5$clock)
    );
    top$core$cnt_nf line$6(
        .d(line$6$d),
        .q(line$6$q),
        .clock(line$6$clock)
    );
    top$core$cnt_nf line$7(
        .d(line$7$d),
        .q(line$7$q),
        .clock(line$7$clock)
    );
    top$core$cnt_nf line$8(
        .d(line$8$d),
        .q(line$8$q),
        .clock(line$8$clock)
    );
    top$core$cnt_nf line$9(
        .d(line$9$d),
        .q(line$9$q),
        .clock(line$9$clock)
    );
    top$core$cnt_nf line$10(
        .d(line$10$d),
        .q(line$10$q),
        .clock(line$10$clock)
    );
    top$core$cnt_nf line$11(
        .d(line$11$d),
        .q(line$11$q),
        .clock(line$11$clock)
    );
    top$core$cnt_nf line$12(
        .d(line$12$d),
        .q(line$12$q),
        .clock(line$12$clock)
    );
    top$core$cnt_nf line$13(
        .d(line$13$d),
        .q(line$13$q),
        .clock(line$13$clock)
    );
    top$core$cnt_nf line$14(
        .d(line$14$d),
        .q(line$14$q),
        .clock(line$14$clock)
    );
    top$core$cnt_nf line$15(
        .d(line$15$d),
        .q(line$15$q),
        .clock(line$15$clock)
    );
    top$core$cnt_nf line$16(
        .d(line$16$d),
        .q(line$16$q),
        .clock(line$16$clock)
    );
    top$core$cnt_nf line$17(
        .d(line$17$d),
        .q(line$17$q),
        .clock(line$17$clock)
    );
    top$core$cnt_nf line$18(
        .d(line$18$d),
        .q(line$18$q),
        .clock(line$18$clock)
    );
    top$core$cnt_nf line$19(
        .d(line$19$d),
        .q(line$19$q),
        .clock(line$19$clock)
    );
    top$core$cnt_nf line$20(
        .d(line$20$d),
        .q(line$20$q),
        .clock(line$20$clock)
    );
    top$core$cnt_nf line$21(
        .d(line$21$d),
        .q(line$21$q),
        .clock(line$21$clock)
    );
    top$core$cnt_nf line$22(
        .d(line$22$d),
        .q(line$22$q),
        .clock(line$22$clock)
    );
    top$core$cnt_nf line$23(
        .d(line$23$d),
        .q(line$23$q),
        .clock(line$23$clock)
    );
    top$core$cnt_nf line$24(
        .d(line$24$d),
        .q(line$24$q),
        .clock(line$24$clock)
    );
    top$core$cnt_nf line$25(
        .d(line$25$d),
        .q(line$25$q),
        .clock(line$25$clock)
    );
    top$core$cnt_nf line$26(
        .d(line$26$d),
        .q(line$26$q),
        .clock(line$26$clock)
    );
    top$core$cnt_nf line$27(
        .d(line$27$d),
        .q(line$27$q),
        .clock(line$27$clock)
    );
    top$core$cnt_nf line$28(
        .d(line$28$d),
        .q(line$28$q),
        .clock(line$28$clock)
    );
    top$core$cnt_nf line$29(
        .d(line$29$d),
        .q(line$29$q),
        .clock(line$29$clock)
    );
    top$core$cnt_nf line$30(
        .d(line$30$d),
        .q(line$30$q),
        .clock(line$30$clock)
    );
    top$core$cnt_nf line$31(
        .d(line$31$d),
        .q(line$31$q),
        .clock(line$31$clock)
    );
    top$core$cnt_nf line$32(
        .d(line$32$d),
        .q(line$32$q),
        .clock(line$32$clock)
    );
    top$core$cnt_nf line$33(
        .d(line$33$d),
        .q(line$33$q),
        .clock(line$33$clock)
    );
    top$core$cnt_nf line$34(
        .d(line$34$d),
        .q(line$34$q),
        .clock(line$34$clock)
    );
    top$core$cnt_nf line$35(
        .d(line$35$d),
        .q(line$35$q),
        .clock(line$35$clock)
    );
    top$core$cnt_nf line$36(
        .d(line$36$d),
        .q(line$36$q),
        .clock(line$36$clock)
    );
    top$core$cnt_nf line$37(
        .d(line$37$d),
        .q(line$37$q),
        .clock(line$37$clock)
    );
    top$core$cnt_nf line$38(
        .d(line$38$d),
        .q(line$38$q),
        .clock(line$38$clock)
    );
    top$core$cnt_nf line$39(
        .d(line$39$d),
        .q(line$39$q),
        .clock(line$39$clock)
    );
    top$core$cnt_nf line$40(
        .d(line$40$d),
        .q(line$40$q),
        .clock(line$40$clock)
    );
    top$core$cnt_nf line$41(
        .d(line$41$d),
        .q(line$41$q),
        .clock(line$41$clock)
    );
    top$core$cnt_nf line$42(
        .d(line$42$d),
        .q(line$42$q),
        .clock(line$42$clock)
    );
    top$core$cnt_nf line$43(
        .d(line$43$d),
        .q(line$43$q),
        .clock(line$43$clock)
    );
    top$core$cnt_nf line$44(
        .d(line$44$d),
        .q(line$44$q),
        .clock(line$44$clock)
    );
    top$core$cnt_nf line$45(
        .d(line$45$d),
        .q(line$45$q),
        .clock(line$45$clock)
    );
    top$core$cnt_nf line$46(
        .d(line$46$d),
        .q(line$46$q),
        .clock(line$46$clock)
    );
    top$core$cnt_nf line$47(
        .d(line$47$d),
        .q(line$47$q),
        .clock(line$47$clock)
    );
    top$core$cnt_nf line$48(
        .d(line$48$d),
        .q(line$48$q),
        .clock(line$48$clock)
    );
    top$core$cnt_nf line$49(
        .d(line$49$d),
        .q(line$49$q),
        .clock(line$49$clock)
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
        line$4$clock = clock;
        line$4$d = d;
        line$5$clock = clock;
        line$5$d = d;
        line$6$clock = clock;
        line$6$d = d;
        line$7$clock = clock;
        line$7$d = d;
        line$8$clock = clock;
        line$8$d = d;
        line$9$clock = clock;
        line$9$d = d;
        line$10$clock = clock;
        line$10$d = d;
        line$11$clock = clock;
        line$11$d = d;
        line$12$clock = clock;
        line$12$d = d;
        line$13$clock = clock;
        line$13$d = d;
        line$14$clock = clock;
        line$14$d = d;
        line$15$clock = clock;
        line$15$d = d;
        line$16$clock = clock;
        line$16$d = d;
        line$17$clock = clock;
        line$17$d = d;
        line$18$clock = clock;
        line$18$d = d;
        line$19$clock = clock;
        line$19$d = d;
        line$20$clock = clock;
        line$20$d = d;
        line$21$clock = clock;
        line$21$d = d;
        line$22$clock = clock;
        line$22$d = d;
        line$23$clock = clock;
        line$23$d = d;
        line$24$clock = clock;
        line$24$d = d;
        line$25$clock = clock;
        line$25$d = d;
        line$26$clock = clock;
        line$26$d = d;
        line$27$clock = clock;
        line$27$d = d;
        line$28$clock = clock;
        line$28$d = d;
        line$29$clock = clock;
        line$29$d = d;
        line$30$clock = clock;
        line$30$d = d;
        line$31$clock = clock;
        line$31$d = d;
        line$32$clock = clock;
        line$32$d = d;
        line$33$clock = clock;
        line$33$d = d;
        line$34$clock = clock;
        line$34$d = d;
        line$35$clock = clock;
        line$35$d = d;
        line$36$clock = clock;
        line$36$d = d;
        line$37$clock = clock;
        line$37$d = d;
        line$38$clock = clock;
        line$38$d = d;
        line$39$clock = clock;
        line$39$d = d;
        line$40$clock = clock;
        line$40$d = d;
        line$41$clock = clock;
        line$41$d = d;
        line$42$clock = clock;
        line$42$d = d;
        line$43$clock = clock;
        line$43$d = d;
        line$44$clock = clock;
        line$44$d = d;
        line$45$clock = clock;
        line$45$d = d;
        line$46$clock = clock;
        line$46$d = d;
        line$47$clock = clock;
        line$47$d = d;
        line$48$clock = clock;
        line$48$d = d;
        line$49$clock = clock;
        line$49$d = d;
        line$0$d = line$1$q;
        line$1$d = line$2$q;
        line$2$d = line$3$q;
        line$3$d = line$4$q;
        line$4$d = line$5$q;
        line$5$d = line$6$q;
        line$6$d = line$7$q;
        line$7$d = line$8$q;
        line$8$d = line$9$q;
        line$9$d = line$10$q;
        line$10$d = line$11$q;
        line$11$d = line$12$q;
        line$12$d = line$13$q;
        line$13$d = line$14$q;
        line$14$d = line$15$q;
        line$15$d = line$16$q;
        line$16$d = line$17$q;
        line$17$d = line$18$q;
        line$18$d = line$19$q;
        line$19$d = line$20$q;
        line$20$d = line$21$q;
        line$21$d = line$22$q;
        line$22$d = line$23$q;
        line$23$d = line$24$q;
        line$24$d = line$25$q;
        line$25$d = line$26$q;
        line$26$d = line$27$q;
        line$27$d = line$28$q;
        line$28$d = line$29$q;
        line$29$d = line$30$q;
        line$30$d = line$31$q;
        line$31$d = line$32$q;
        line$32$d = line$33$q;
        line$33$d = line$34$q;
        line$34$d = line$35$q;
        line$35$d = line$36$q;
        line$36$d = line$37$q;
        line$37$d = line$38$q;
        line$38$d = line$39$q;
        line$39$d = line$40$q;
        line$40$d = line$41$q;
        line$41$d = line$42$q;
        line$42$d = line$43$q;
        line$43$d = line$44$q;
        line$44$d = line$45$q;
        line$45$d = line$46$q;
        line$46$d = line$47$q;
        line$47$d = line$48$q;
        line$48$d = line$49$q;
        q = line$0$q;
    end
    
endmodule // top$tri_unit$tc_ab$tag_wait


module top$tri_unit$tc_ab$v_x_wait$0(clock,d,q);
    
    // Module arguments
    input wire  clock;
    input wire  [31:0] d;
    output reg  [31:0] q;
    
    // Stub signals
    reg  [31:0] line$0$d;
    wire  [31:0] line$0$q;
    reg  line$0$clock;
    reg  [31:0] line$1$d;
    wire  [31:0] line$1$q;
    reg  line$1$clock;
    reg  [31:0] line$2$d;
    wire  [31:0] line$2$q;
    reg  line$2$clock;
    reg  [31:0] line$3$d;
    wire  [31:0] line$3$q;
    reg  line$3$clock;
    reg  [31:0] line$4$d;
    wire  [31:0] line$4$q;
    reg  line$4$clock;
    reg  [31:0] line$5$d;
    wire  [31:0] line$5$q;
    reg  line$5$clock;
    reg  [31:0] line$6$d;
    wire  [31:0] line$6$q;
    reg  line$6$clock;
    reg  [31:0] line$7$d;
    wire  [31:0] line$7$q;
    reg  line$7$clock;
    reg  [31:0] line$8$d;
    wire  [31:0] line$8$q;
    reg  line$8$clock;
    reg  [31:0] line$9$d;
    wire  [31:0] line$9$q;
    reg  line$9$clock;
    reg  [31:0] line$10$d;
    wire  [31:0] line$10$q;
    reg  line$10$clock;
    
    // Sub module instances
    top$core$cnt_nf line$0(
        .d(line$0$d),
        .q(line$0$q),
        .clock(line$0$clock)
    );
    top$core$cnt_nf line$1(
        .d(line$1$d),
        .q(line$1$q),
        .clock(line$1$clock)
    );
    top$core$cnt_nf line$2(
        .d(line$2$d),
        .q(line$2$q),
        .clock(line$2$clock)
    );
    top$core$cnt_nf line$3(
        .d(line$3$d),
        .q(line$3$q),
        .clock(line$3$clock)
    );
    top$core$cnt_nf line$4(
        .d(line$4$d),
        .q(line$4$q),
        .clock(line$4$clock)
    );
    top$core$cnt_nf line$5(
        .d(line$5$d),
        .q(line$5$q),
        .clock(line$5$clock)
    );
    top$core$cnt_nf line$6(
        .d(line$6$d),
        .q(line$6$q),
        .clock(line$6$clock)
    );
    top$core$cnt_nf line$7(
        .d(line$7$d),
        .q(line$7$q),
        .clock(line$7$clock)
    );
    top$core$cnt_nf line$8(
        .d(line$8$d),
        .q(line$8$q),
        .clock(line$8$clock)
    );
    top$core$cnt_nf line$9(
        .d(line$9$d),
        .q(line$9$q),
        .clock(line$9$clock)
    );
    top$core$cnt_nf line$10(
        .d(line$10$d),
        .q(line$10$q),
        .clock(line$10$clock)
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
        line$4$clock = clock;
        line$4$d = d;
        line$5$clock = clock;
        line$5$d = d;
        line$6$clock = clock;
        line$6$d = d;
        line$7$clock = clock;
        line$7$d = d;
        line$8$clock = clock;
        line$8$d = d;
        line$9$clock = clock;
        line$9$d = d;
        line$10$clock = clock;
        line$10$d = d;
        line$0$d = line$1$q;
        line$1$d = line$2$q;
        line$2$d = line$3$q;
        line$3$d = line$4$q;
        line$4$d = line$5$q;
        line$5$d = line$6$q;
        line$6$d = line$7$q;
        line$7$d = line$8$q;
        line$8$d = line$9$q;
        line$9$d = line$10$q;
        q = line$0$q;
    end
    
endmodule // top$tri_unit$tc_ab$v_x_wait$0


module top$tri_unit$tc_ab$valid_wait(clock,d,q);
    
    // Module arguments
    input wire  clock;
    input wire  d;
    output reg  q;
    
    // Stub signals
    reg  line$0$d;
    wire  line$0$q;
    reg  line$0$clock;
    reg  line$1$d;
    wire  line$1$q;
    reg  line$1$clock;
    reg  line$2$d;
    wire  line$2$q;
    reg  line$2$clock;
    reg  line$3$d;
    wire  line$3$q;
    reg  line$3$clock;
    reg  line$4$d;
    wire  line$4$q;
    reg  line$4$clock;
    reg  line$5$d;
    wire  line$5$q;
    reg  line$5$clock;
    reg  line$6$d;
    wire  line$6$q;
    reg  line$6$clock;
    reg  line$7$d;
    wire  line$7$q;
    reg  line$7$clock;
    reg  line$8$d;
    wire  line$8$q;
    reg  line$8$clock;
    reg  line$9$d;
    wire  line$9$q;
    reg  line$9$clock;
    reg  line$10$d;
    wire  line$10$q;
    reg  line$10$clock;
    reg  line$11$d;
    wire  line$11$q;
    reg  line$11$clock;
    reg  line$12$d;
    wire  line$12$q;
    reg  line$12$clock;
    reg  line$13$d;
    wire  line$13$q;
    reg  line$13$clock;
    reg  line$14$d;
    wire  line$14$q;
    reg  line$14$clock;
    reg  line$15$d;
    wire  line$15$q;
    reg  line$15$clock;
    reg  line$16$d;
    wire  line$16$q;
    reg  line$16$clock;
    reg  line$17$d;
    wire  line$17$q;
    reg  line$17$clock;
    reg  line$18$d;
    wire  line$18$q;
    reg  line$18$clock;
    reg  line$19$d;
    wire  line$19$q;
    reg  line$19$clock;
    reg  line$20$d;
    wire  line$20$q;
    reg  line$20$clock;
    reg  line$21$d;
    wire  line$21$q;
    reg  line$21$clock;
    reg  line$22$d;
    wire  line$22$q;
    reg  line$22$clock;
    reg  line$23$d;
    wire  line$23$q;
    reg  line$23$clock;
    reg  line$24$d;
    wire  line$24$q;
    reg  line$24$clock;
    reg  line$25$d;
    wire  line$25$q;
    reg  line$25$clock;
    reg  line$26$d;
    wire  line$26$q;
    reg  line$26$clock;
    reg  line$27$d;
    wire  line$27$q;
    reg  line$27$clock;
    reg  line$28$d;
    wire  line$28$q;
    reg  line$28$clock;
    reg  line$29$d;
    wire  line$29$q;
    reg  line$29$clock;
    reg  line$30$d;
    wire  line$30$q;
    reg  line$30$clock;
    reg  line$31$d;
    wire  line$31$q;
    reg  line$31$clock;
    reg  line$32$d;
    wire  line$32$q;
    reg  line$32$clock;
    reg  line$33$d;
    wire  line$33$q;
    reg  line$33$clock;
    reg  line$34$d;
    wire  line$34$q;
    reg  line$34$clock;
    reg  line$35$d;
    wire  line$35$q;
    reg  line$35$clock;
    reg  line$36$d;
    wire  line$36$q;
    reg  line$36$clock;
    reg  line$37$d;
    wire  line$37$q;
    reg  line$37$clock;
    reg  line$38$d;
    wire  line$38$q;
    reg  line$38$clock;
    reg  line$39$d;
    wire  line$39$q;
    reg  line$39$clock;
    reg  line$40$d;
    wire  line$40$q;
    reg  line$40$clock;
    reg  line$41$d;
    wire  line$41$q;
    reg  line$41$clock;
    reg  line$42$d;
    wire  line$42$q;
    reg  line$42$clock;
    reg  line$43$d;
    wire  line$43$q;
    reg  line$43$clock;
    reg  line$44$d;
    wire  line$44$q;
    reg  line$44$clock;
    reg  line$45$d;
    wire  line$45$q;
    reg  line$45$clock;
    reg  line$46$d;
    wire  line$46$q;
    reg  line$46$clock;
    reg  line$47$d;
    wire  line$47$q;
    reg  line$47$clock;
    reg  line$48$d;
    wire  line$48$q;
    reg  line$48$clock;
    reg  line$49$d;
    wire  line$49$q;
    reg  line$49$clock;
    
    // Sub module instances
    top$core$done_r line$0(
        .d(line$0$d),
        .q(line$0$q),
        .clock(line$0$clock)
    );
    top$core$done_r line$1(
        .d(line$1$d),
        .q(line$1$q),
        .clock(line$1$clock)
    );
    top$core$done_r line$2(
        .d(line$2$d),
        .q(line$2$q),
        .clock(line$2$clock)
    );
    top$core$done_r line$3(
        .d(line$3$d),
        .q(line$3$q),
        .clock(line$3$clock)
    );
    top$core$done_r line$4(
        .d(line$4$d),
        .q(line$4$q),
        .clock(line$4$clock)
    );
    top$core$done_r line$5(
        .d(line$5$d),
        .q(line$5$q),
        .clock(line$5$clock)
    );
    top$core$done_r line$6(
        .d(line$6$d),
        .q(line$6$q),
        .clock(line$6$clock)
    );
    top$core$done_r line$7(
        .d(line$7$d),
        .q(line$7$q),
        .clock(line$7$clock)
    );
    top$core$done_r line$8(
        .d(line$8$d),
        .q(line$8$q),
        .clock(line$8$clock)
    );
    top$core$done_r line$9(
        .d(line$9$d),
        .q(line$9$q),
        .clock(line$9$clock)
    );
    top$core$done_r line$10(
        .d(line$10$d),
        .q(line$10$q),
        .clock(line$10$clock)
    );
    top$core$done_r line$11(
        .d(line$11$d),
        .q(line$11$q),
        .clock(line$11$clock)
    );
    top$core$done_r line$12(
        .d(line$12$d),
        .q(line$12$q),
        .clock(line$12$clock)
    );
    top$core$done_r line$13(
        .d(line$13$d),
        .q(line$13$q),
        .clock(line$13$clock)
    );
    top$core$done_r line$14(
        .d(line$14$d),
        .q(line$14$q),
        .clock(line$14$clock)
    );
    top$core$done_r line$15(
        .d(line$15$d),
        .q(line$15$q),
        .clock(line$15$clock)
    );
    top$core$done_r line$16(
        .d(line$16$d),
        .q(line$16$q),
        .clock(line$16$clock)
    );
    top$core$done_r line$17(
        .d(line$17$d),
        .q(line$17$q),
        .clock(line$17$clock)
    );
    top$core$done_r line$18(
        .d(line$18$d),
        .q(line$18$q),
        .clock(line$18$clock)
    );
    top$core$done_r line$19(
        .d(line$19$d),
        .q(line$19$q),
        .clock(line$19$clock)
    );
    top$core$done_r line$20(
        .d(line$20$d),
        .q(line$20$q),
        .clock(line$20$clock)
    );
    top$core$done_r line$21(
        .d(line$21$d),
        .q(line$21$q),
        .clock(line$21$clock)
    );
    top$core$done_r line$22(
        .d(line$22$d),
        .q(line$22$q),
        .clock(line$22$clock)
    );
    top$core$done_r line$23(
        .d(line$23$d),
        .q(line$23$q),
        .clock(line$23$clock)
    );
    top$core$done_r line$24(
        .d(line$24$d),
        .q(line$24$q),
        .clock(line$24$clock)
    );
    top$core$done_r line$25(
        .d(line$25$d),
        .q(line$25$q),
        .clock(line$25$clock)
    );
    top$core$done_r line$26(
        .d(line$26$d),
        .q(line$26$q),
        .clock(line$26$clock)
    );
    top$core$done_r line$27(
        .d(line$27$d),
        .q(line$27$q),
        .clock(line$27$clock)
    );
    top$core$done_r line$28(
        .d(line$28$d),
        .q(line$28$q),
        .clock(line$28$clock)
    );
    top$core$done_r line$29(
        .d(line$29$d),
        .q(line$29$q),
        .clock(line$29$clock)
    );
    top$core$done_r line$30(
        .d(line$30$d),
        .q(line$30$q),
        .clock(line$30$clock)
    );
    top$core$done_r line$31(
        .d(line$31$d),
        .q(line$31$q),
        .clock(line$31$clock)
    );
    top$core$done_r line$32(
        .d(line$32$d),
        .q(line$32$q),
        .clock(line$32$clock)
    );
    top$core$done_r line$33(
        .d(line$33$d),
        .q(line$33$q),
        .clock(line$33$clock)
    );
    top$core$done_r line$34(
        .d(line$34$d),
        .q(line$34$q),
        .clock(line$34$clock)
    );
    top$core$done_r line$35(
        .d(line$35$d),
        .q(line$35$q),
        .clock(line$35$clock)
    );
    top$core$done_r line$36(
        .d(line$36$d),
        .q(line$36$q),
        .clock(line$36$clock)
    );
    top$core$done_r line$37(
        .d(line$37$d),
        .q(line$37$q),
        .clock(line$37$clock)
    );
    top$core$done_r line$38(
        .d(line$38$d),
        .q(line$38$q),
        .clock(line$38$clock)
    );
    top$core$done_r line$39(
        .d(line$39$d),
        .q(line$39$q),
        .clock(line$39$clock)
    );
    top$core$done_r line$40(
        .d(line$40$d),
        .q(line$40$q),
        .clock(line$40$clock)
    );
    top$core$done_r line$41(
        .d(line$41$d),
        .q(line$41$q),
        .clock(line$41$clock)
    );
    top$core$done_r line$42(
        .d(line$42$d),
        .q(line$42$q),
        .clock(line$42$clock)
    );
    top$core$done_r line$43(
        .d(line$43$d),
        .q(line$43$q),
        .clock(line$43$clock)
    );
    top$core$done_r line$44(
        .d(line$44$d),
        .q(line$44$q),
        .clock(line$44$clock)
    );
    top$core$done_r line$45(
        .d(line$45$d),
        .q(line$45$q),
        .clock(line$45$clock)
    );
    top$core$done_r line$46(
        .d(line$46$d),
        .q(line$46$q),
        .clock(line$46$clock)
    );
    top$core$done_r line$47(
        .d(line$47$d),
        .q(line$47$q),
        .clock(line$47$clock)
    );
    top$core$done_r line$48(
        .d(line$48$d),
        .q(line$48$q),
        .clock(line$48$clock)
    );
    top$core$done_r line$49(
        .d(line$49$d),
        .q(line$49$q),
        .clock(line$49$clock)
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
        line$4$clock = clock;
        line$4$d = d;
        line$5$clock = clock;
        line$5$d = d;
        line$6$clock = clock;
        line$6$d = d;
        line$7$clock = clock;
        line$7$d = d;
        line$8$clock = clock;
        line$8$d = d;
        line$9$clock = clock;
        line$9$d = d;
        line$10$clock = clock;
        line$10$d = d;
        line$11$clock = clock;
        line$11$d = d;
        line$12$clock = clock;
        line$12$d = d;
        line$13$clock = clock;
        line$13$d = d;
        line$14$clock = clock;
        line$14$d = d;
        line$15$clock = clock;
        line$15$d = d;
        line$16$clock = clock;
        line$16$d = d;
        line$17$clock = clock;
        line$17$d = d;
        line$18$clock = clock;
        line$18$d = d;
        line$19$clock = clock;
        line$19$d = d;
        line$20$clock = clock;
        line$20$d = d;
        line$21$clock = clock;
        line$21$d = d;
        line$22$clock = clock;
        line$22$d = d;
        line$23$clock = clock;
        line$23$d = d;
        line$24$clock = clock;
        line$24$d = d;
        line$25$clock = clock;
        line$25$d = d;
        line$26$clock = clock;
        line$26$d = d;
        line$27$clock = clock;
        line$27$d = d;
        line$28$clock = clock;
        line$28$d = d;
        line$29$clock = clock;
        line$29$d = d;
        line$30$clock = clock;
        line$30$d = d;
        line$31$clock = clock;
        line$31$d = d;
        line$32$clock = clock;
        line$32$d = d;
        line$33$clock = clock;
        line$33$d = d;
        line$34$clock = clock;
        line$34$d = d;
        line$35$clock = clock;
        line$35$d = d;
        line$36$clock = clock;
        line$36$d = d;
        line$37$clock = clock;
        line$37$d = d;
        line$38$clock = clock;
        line$38$d = d;
        line$39$clock = clock;
        line$39$d = d;
        line$40$clock = clock;
        line$40$d = d;
        line$41$clock = clock;
        line$41$d = d;
        line$42$clock = clock;
        line$42$d = d;
        line$43$clock = clock;
        line$43$d = d;
        line$44$clock = clock;
        line$44$d = d;
        line$45$clock = clock;
        line$45$d = d;
        line$46$clock = clock;
        line$46$d = d;
        line$47$clock = clock;
        line$47$d = d;
        line$48$clock = clock;
        line$48$d = d;
        line$49$clock = clock;
        line$49$d = d;
        line$0$d = line$1$q;
        line$1$d = line$2$q;
        line$2$d = line$3$q;
        line$3$d = line$4$q;
        line$4$d = line$5$q;
        line$5$d = line$6$q;
        line$6$d = line$7$q;
        line$7$d = line$8$q;
        line$8$d = line$9$q;
        line$9$d = line$10$q;
        line$10$d = line$11$q;
        line$11$d = line$12$q;
        line$12$d = line$13$q;
        line$13$d = line$14$q;
        line$14$d = line$15$q;
        line$15$d = line$16$q;
        line$16$d = line$17$q;
        line$17$d = line$18$q;
        line$18$d = line$19$q;
        line$19$d = line$20$q;
        line$20$d = line$21$q;
        line$21$d = line$22$q;
        line$22$d = line$23$q;
        line$23$d = line$24$q;
        line$24$d = line$25$q;
        line$25$d = line$26$q;
        line$26$d = line$27$q;
        line$27$d = line$28$q;
        line$28$d = line$29$q;
        line$29$d = line$30$q;
        line$30$d = line$31$q;
        line$31$d = line$32$q;
        line$32$d = line$33$q;
        line$33$d = line$34$q;
        line$34$d = line$35$q;
        line$35$d = line$36$q;
        line$36$d = line$37$q;
        line$37$d = line$38$q;
        line$38$d = line$39$q;
        line$39$d = line$40$q;
        line$40$d = line$41$q;
        line$41$d = line$42$q;
        line$42$d = line$43$q;
        line$43$d = line$44$q;
        line$44$d = line$45$q;
        line$45$d = line$46$q;
        line$46$d = line$47$q;
        line$47$d = line$48$q;
        line$48$d = line$49$q;
        q = line$0$q;
    end
    
endmodule // top$tri_unit$tc_ab$valid_wait


module top$tri_unit$tc_ab$verts$0(clock,z,m0,m1,m2,exact,e,g,f0,f1,f2,h);
    
    // Module arguments
    input wire  clock;
    input wire  [31:0] z;
    input wire  [31:0] m0;
    input wire  [31:0] m1;
    input wire  [31:0] m2;
    input wire  exact;
    output reg  [31:0] e;
    output reg  [31:0] g;
    output reg  [31:0] f0;
    output reg  [31:0] f1;
    output reg  [31:0] f2;
    output reg  [31:0] h;
    
    // Constant declarations
    localparam  mask = 32'h7fffffff;
    localparam  c_one = 32'h800000;
    
    // Stub signals
    reg  ef$0$clock;
    reg  [31:0] ef$0$a;
    reg  ef$0$sel;
    wire  [31:0] ef$0$y;
    reg  ef$1$clock;
    reg  [31:0] ef$1$a;
    reg  ef$1$sel;
    wire  [31:0] ef$1$y;
    reg  ef$2$clock;
    reg  [31:0] ef$2$a;
    reg  ef$2$sel;
    wire  [31:0] ef$2$y;
    reg  ez$clock;
    reg  [31:0] ez$a;
    reg  ez$sel;
    wire  [31:0] ez$y;
    reg  cz$clock;
    reg  [31:0] cz$a;
    reg  cz$sel;
    wire  [31:0] cz$y;
    reg  gz$clock;
    reg  [31:0] gz$a;
    reg  [31:0] gz$b;
    reg  gz$sub;
    reg  gz$valid_in;
    wire  [31:0] gz$y;
    wire  gz$valid_out;
    reg  hz$clock;
    reg  [31:0] hz$a;
    reg  [31:0] hz$b;
    reg  hz$sub;
    reg  hz$valid_in;
    wire  [31:0] hz$y;
    wire  hz$valid_out;
    reg  f_wait$0$clock;
    reg  [31:0] f_wait$0$d;
    wire  [31:0] f_wait$0$q;
    reg  f_wait$1$clock;
    reg  [31:0] f_wait$1$d;
    wire  [31:0] f_wait$1$q;
    reg  f_wait$2$clock;
    reg  [31:0] f_wait$2$d;
    wire  [31:0] f_wait$2$q;
    reg  z_wait$clock;
    reg  [31:0] z_wait$d;
    wire  [31:0] z_wait$q;
    reg  h_wait$clock;
    reg  [31:0] h_wait$d;
    wire  [31:0] h_wait$q;
    
    // Local signals
    reg  [31:0] e2z;
    
    // Sub module instances
    top$tri_unit$tc_ab$verts$0$ef$0 ef$0(
        .clock(ef$0$clock),
        .a(ef$0$a),
        .sel(ef$0$sel),
        .y(ef$0$y)
    );
    top$tri_unit$tc_ab$verts$0$ef$0 ef$1(
        .clock(ef$1$clock),
        .a(ef$1$a),
        .sel(ef$1$sel),
        .y(ef$1$y)
    );
    top$tri_unit$tc_ab$verts$0$ef$2 ef$2(
        .clock(ef$2$clock),
        .a(ef$2$a),
        .sel(ef$2$sel),
        .y(ef$2$y)
    );
    top$tri_unit$tc_ab$verts$0$ef$0 ez(
        .clock(ez$clock),
        .a(ez$a),
        .sel(ez$sel),
        .y(ez$y)
    );
    top$tri_unit$tc_ab$edges$0$rs cz(
        .clock(cz$clock),
        .a(cz$a),
        .sel(cz$sel),
        .y(cz$y)
    );
    top$tri_unit$tc_ab$aerr gz(
        .clock(gz$clock),
        .a(gz$a),
        .b(gz$b),
        .sub(gz$sub),
        .valid_in(gz$valid_in),
        .y(gz$y),
        .valid_out(gz$valid_out)
    );
    top$tri_unit$tc_ab$aerr hz(
        .clock(hz$clock),
        .a(hz$a),
        .b(hz$b),
        .sub(hz$sub),
        .valid_in(hz$valid_in),
        .y(hz$y),
        .valid_out(hz$valid_out)
    );
    top$tri_unit$tc_ab$edges$0$brs_wait f_wait$0(
        .clock(f_wait$0$clock),
        .d(f_wait$0$d),
        .q(f_wait$0$q)
    );
    top$tri_unit$tc_ab$edges$0$brs_wait f_wait$1(
        .clock(f_wait$1$clock),
        .d(f_wait$1$d),
        .q(f_wait$1$q)
    );
    top$tri_unit$tc_ab$edges$0$brs_wait f_wait$2(
        .clock(f_wait$2$clock),
        .d(f_wait$2$d),
        .q(f_wait$2$q)
    );
    top$tri_unit$tc_ab$c3_0 z_wait(
        .clock(z_wait$clock),
        .d(z_wait$d),
        .q(z_wait$q)
    );
    top$tri_unit$tc_ab$edges$0$brs_wait h_wait(
        .clock(h_wait$clock),
        .d(h_wait$d),
        .q(h_wait$q)
    );
    
    // Update code
    always @(*) begin
        ez$clock = clock;
        cz$clock = clock;
        gz$clock = clock;
        hz$clock = clock;
        z_wait$clock = clock;
        h_wait$clock = clock;
        ef$0$clock = clock;
        ef$0$sel = exact;
        f_wait$0$clock = clock;
        f_wait$0$d = ef$0$y;
        ef$1$clock = clock;
        ef$1$sel = exact;
        f_wait$1$clock = clock;
        f_wait$1$d = ef$1$y;
        ef$2$clock = clock;
        ef$2$sel = exact;
        f_wait$2$clock = clock;
        f_wait$2$d = ef$2$y;
        ef$0$a = m0;
        ef$1$a = m1;
        ef$2$a = m2;
        ez$a = m2;
        ez$sel = exact;
        cz$a = z;
        cz$sel = 1'b0;
        gz$a = ez$y;
        gz$b = cz$y;
        gz$sub = 1'b0;
        gz$valid_in = 1'b0;
        e2z = ez$y;
        if ((ez$y[(32'h17)+:(8)] != 32'h0) & ~&ez$y[(32'h17)+:(8)]) begin
            e2z = ez$y + c_one;
        end
        z_wait$d = z & mask;
        hz$a = z_wait$q;
        hz$b = e2z;
        hz$sub = 1'b0;
        hz$valid_in = 1'b0;
        h_wait$d = hz$y;
        e = ez$y;
        g = gz$y;
        f0 = f_wait$0$q;
        f1 = f_wait$1$q;
        f2 = f_wait$2$q;
        h = h_wait$q;
    end
    
endmodule // top$tri_unit$tc_ab$verts$0


module top$tri_unit$tc_ab$verts$0$ef$0(clock,a,sel,y);
    
    // Module arguments
    input wire  clock;
    input wire  [31:0] a;
    input wire  sel;
    output reg  [31:0] y;
    
    // Constant declarations
    localparam  c_k0 = 10'b11101011;
    localparam  c_k1 = 10'b11101011;
    localparam  c_sh0 = 8'h16;
    localparam  c_sh1 = 8'h0;
    localparam  c_t0 = 8'h1;
    localparam  c_t1 = 8'h0;
    localparam  c_en0 = 1'b1;
    localparam  c_en1 = 1'b0;
    localparam  c_j = 8'h19;
    localparam  c_j1 = 8'h1a;
    localparam  c_f = 8'h17;
    localparam  c_ofs = 10'b100000000;
    localparam  c_norm_min = 10'b100000001;
    localparam  c_min = 32'h800000;
    localparam  c_inf = 32'h7f800000;
    localparam  c_nan = 32'h7fc00000;
    
    // Stub signals
    reg  out$clock;
    reg  [31:0] out$d;
    wire  [31:0] out$q;
    
    // Local signals
    reg  [7:0] field;
    reg  [22:0] frac;
    reg  [49:0] m;
    reg  [7:0] lo_sh;
    reg  [7:0] t_sh;
    reg  t_en;
    reg  [9:0] kk;
    reg  [49:0] third;
    reg  [49:0] sum;
    reg  top;
    reg  [7:0] sh;
    reg  [49:0] hi;
    reg  lost;
    reg  [49:0] rnd;
    reg  [9:0] eb;
    reg  [9:0] e10;
    reg  [31:0] res;
    
    // Sub module instances
    top$tri_unit$tc_ab$c3_0 out(
        .clock(out$clock),
        .d(out$d),
        .q(out$q)
    );
    
    // Update code
    always @(*) begin
        out$clock = clock;
        field = a[(32'h17)+:(8)];
        frac = a[(32'h0)+:(23)];
        m = (((frac) & 50'h3ffffffffffff) & ~(1 << (32'h17)) | ((1'b1) << (32'h17)));
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
        top = sum[32'h32 - 32'h1];
        sh = c_j;
        if (top) begin
            sh = c_j1;
        end
        hi = sum >> sh;
        lost = (hi << sh) != sum;
        rnd = hi + lost;
        e10 = eb + top + rnd[32'h17 + 32'h1];
        res = (((e10 - c_ofs) & 32'hffffffff) << c_f) | ((((rnd) & 23'h7fffff)) & 32'hffffffff);
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
    
endmodule // top$tri_unit$tc_ab$verts$0$ef$0


module top$tri_unit$tc_ab$verts$0$ef$2(clock,a,sel,y);
    
    // Module arguments
    input wire  clock;
    input wire  [31:0] a;
    input wire  sel;
    output reg  [31:0] y;
    
    // Constant declarations
    localparam  c_k0 = 10'b11101011;
    localparam  c_k1 = 10'b11101011;
    localparam  c_sh0 = 8'h17;
    localparam  c_sh1 = 8'h16;
    localparam  c_t0 = 8'h1;
    localparam  c_t1 = 8'h1;
    localparam  c_en0 = 1'b1;
    localparam  c_en1 = 1'b1;
    localparam  c_j = 8'h19;
    localparam  c_j1 = 8'h1a;
    localparam  c_f = 8'h17;
    localparam  c_ofs = 10'b100000000;
    localparam  c_norm_min = 10'b100000001;
    localparam  c_min = 32'h800000;
    localparam  c_inf = 32'h7f800000;
    localparam  c_nan = 32'h7fc00000;
    
    // Stub signals
    reg  out$clock;
    reg  [31:0] out$d;
    wire  [31:0] out$q;
    
    // Local signals
    reg  [7:0] field;
    reg  [22:0] frac;
    reg  [49:0] m;
    reg  [7:0] lo_sh;
    reg  [7:0] t_sh;
    reg  t_en;
    reg  [9:0] kk;
    reg  [49:0] third;
    reg  [49:0] sum;
    reg  top;
    reg  [7:0] sh;
    reg  [49:0] hi;
    reg  lost;
    reg  [49:0] rnd;
    reg  [9:0] eb;
    reg  [9:0] e10;
    reg  [31:0] res;
    
    // Sub module instances
    top$tri_unit$tc_ab$c3_0 out(
        .clock(out$clock),
        .d(out$d),
        .q(out$q)
    );
    
    // Update code
    always @(*) begin
        out$clock = clock;
        field = a[(32'h17)+:(8)];
        frac = a[(32'h0)+:(23)];
        m = (((frac) & 50'h3ffffffffffff) & ~(1 << (32'h17)) | ((1'b1) << (32'h17)));
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
        top = sum[32'h32 - 32'h1];
        sh = c_j;
        if (top) begin
            sh = c_j1;
        end
        hi = sum >> sh;
        lost = (hi << sh) != sum;
        rnd = hi + lost;
        e10 = eb + top + rnd[32'h17 + 32'h1];
        res = (((e10 - c_ofs) & 32'hffffffff) << c_f) | ((((rnd) & 23'h7fffff)) & 32'hffffffff);
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
    
endmodule // top$tri_unit$tc_ab$verts$0$ef$2
