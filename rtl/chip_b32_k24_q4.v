

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
    output reg  [10:0] max_depth;
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
    
    // Constant declarations
    localparam  c_ones16 = 16'hffff;
    localparam  c_credit = 6'b10000;
    localparam  c_pf_max = 5'b1110;
    
    // Stub signals
    reg  mode_lifo$d;
    wire  mode_lifo$q;
    reg  mode_lifo$clock;
    reg  mode_first$d;
    wire  mode_first$q;
    reg  mode_first$clock;
    reg  mode_rec$d;
    wire  mode_rec$q;
    reg  mode_rec$clock;
    reg  [2:0] mode_slot$d;
    wire  [2:0] mode_slot$q;
    reg  mode_slot$clock;
    reg  [31:0] root$d;
    wire  [31:0] root$q;
    reg  root$clock;
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
    reg  [19:0] map$d;
    wire  [19:0] map$q;
    reg  map$clock;
    reg  run$d;
    wire  run$q;
    reg  run$clock;
    reg  done_r$d;
    wire  done_r$q;
    reg  done_r$clock;
    reg  push_root$d;
    wire  push_root$q;
    reg  push_root$clock;
    reg  stop$d;
    wire  stop$q;
    reg  stop$clock;
    reg  [3:0] port_pf$d;
    wire  [3:0] port_pf$q;
    reg  port_pf$clock;
    reg  [3:0] port_out$d;
    wire  [3:0] port_out$q;
    reg  port_out$clock;
    reg  port_one$d;
    wire  port_one$q;
    reg  port_one$clock;
    reg  [5:0] port_credit$d;
    wire  [5:0] port_credit$q;
    reg  port_credit$clock;
    reg  d_cntr$clock;
    reg  d_cntr$clear;
    reg  d_cntr$lifo;
    reg  d_cntr$push_root;
    reg  [31:0] d_cntr$root;
    reg  d_cntr$go;
    reg  [4:0] d_cntr$pf;
    reg  d_cntr$one;
    reg  [5:0] d_cntr$credit_lim;
    reg  [5:0] d_cntr$leaf_count;
    reg  [15:0] d_cntr$id_mask;
    reg  d_cntr$wa_empty;
    reg  d_cntr$wb_empty;
    reg  d_cntr$dop_valid;
    reg  d_cntr$dop_overlap;
    reg  [98:0] d_cntr$side;
    wire  d_cntr$empty;
    wire  [10:0] d_cntr$count;
    wire  [10:0] d_cntr$max_count;
    wire  d_cntr$overflow;
    wire  d_cntr$push;
    wire  d_cntr$pop;
    wire  [66:0] d_cntr$pop_entry;
    wire  [3:0] d_cntr$pop_fetch;
    wire  d_cntr$ent_valid;
    wire  [15:0] d_cntr$cur_a;
    wire  [15:0] d_cntr$cur_b;
    wire  d_cntr$cur_flip;
    wire  d_cntr$cur_fa;
    wire  d_cntr$cur_fb;
    wire  d_cntr$need_na;
    wire  d_cntr$need_nb;
    wire  d_cntr$issue;
    wire  [15:0] d_cntr$r_a;
    wire  [15:0] d_cntr$r_b;
    wire  d_cntr$r_a_leaf;
    wire  d_cntr$r_b_leaf;
    wire  d_cntr$leaf_in;
    wire  [63:0] d_cntr$leaf_pair;
    wire  [4:0] d_cntr$inflight;
    wire  d_cntr$pend;
    reg  mem_port$clock;
    reg  mem_port$clear;
    reg  mem_port$go;
    reg  mem_port$pf_on;
    reg  [2:0] mem_port$slot_bits;
    reg  [3:0] mem_port$port_out;
    reg  [23:0] mem_port$base_na;
    reg  [23:0] mem_port$base_nb;
    reg  [23:0] mem_port$base_ta;
    reg  [23:0] mem_port$base_tb;
    reg  [19:0] mem_port$map;
    reg  mem_port$pop;
    reg  [66:0] mem_port$pop_entry;
    reg  [3:0] mem_port$pop_fetch;
    reg  mem_port$issue;
    reg  mem_port$cur_fa;
    reg  mem_port$cur_fb;
    reg  [2:0] mem_port$cur_sa;
    reg  [2:0] mem_port$cur_sb;
    reg  mem_port$need_ta;
    reg  mem_port$need_tb;
    reg  [31:0] mem_port$leaf_tag;
    reg  mem_port$mem_req_ready;
    reg  mem_port$mem_resp_valid;
    reg  [2047:0] mem_port$mem_resp_data;
    wire  mem_port$mem_req_valid;
    wire  [23:0] mem_port$mem_req_addr;
    wire  [1:0] mem_port$req_dst;
    wire  mem_port$accept;
    wire  mem_port$resp;
    wire  [1:0] mem_port$resp_dst;
    wire  [15:0] mem_port$ta_req;
    wire  [15:0] mem_port$tb_req;
    wire  mem_port$outstanding;
    wire  [160:0] mem_port$na_in;
    wire  [160:0] mem_port$nb_in;
    wire  [983:0] mem_port$na_sh;
    wire  [983:0] mem_port$nb_sh;
    wire  mem_port$wa_empty;
    wire  mem_port$wb_empty;
    reg  dop$clock;
    reg  dop$load_en;
    reg  [7:0] dop$load_addr;
    reg  [31:0] dop$load_data;
    reg  [3:0] dop$d$0;
    reg  [3:0] dop$d$1;
    reg  [3:0] dop$d$2;
    reg  [3:0] dop$d$3;
    reg  [3:0] dop$d$4;
    reg  [3:0] dop$d$5;
    reg  [3:0] dop$d$6;
    reg  [3:0] dop$d$7;
    reg  [3:0] dop$d$8;
    reg  [3:0] dop$d$9;
    reg  [3:0] dop$d$10;
    reg  [3:0] dop$d$11;
    reg  [3:0] dop$d$12;
    reg  [3:0] dop$d$13;
    reg  [3:0] dop$d$14;
    reg  [3:0] dop$d$15;
    reg  [3:0] dop$d$16;
    reg  [3:0] dop$d$17;
    reg  [3:0] dop$d$18;
    reg  [3:0] dop$d$19;
    reg  [3:0] dop$d$20;
    reg  [3:0] dop$d$21;
    reg  [3:0] dop$d$22;
    reg  [3:0] dop$d$23;
    reg  [3:0] dop$e$0;
    reg  [3:0] dop$e$1;
    reg  [3:0] dop$e$2;
    reg  [3:0] dop$e$3;
    reg  [3:0] dop$e$4;
    reg  [3:0] dop$e$5;
    reg  [3:0] dop$e$6;
    reg  [3:0] dop$e$7;
    reg  [3:0] dop$e$8;
    reg  [3:0] dop$e$9;
    reg  [3:0] dop$e$10;
    reg  [3:0] dop$e$11;
    reg  [3:0] dop$e$12;
    reg  [3:0] dop$e$13;
    reg  [3:0] dop$e$14;
    reg  [3:0] dop$e$15;
    reg  [3:0] dop$e$16;
    reg  [3:0] dop$e$17;
    reg  [3:0] dop$e$18;
    reg  [3:0] dop$e$19;
    reg  [3:0] dop$e$20;
    reg  [3:0] dop$e$21;
    reg  [3:0] dop$e$22;
    reg  [3:0] dop$e$23;
    reg  [31:0] dop$rd$0;
    reg  [31:0] dop$rd$1;
    reg  [31:0] dop$rd$2;
    reg  [31:0] dop$rd$3;
    reg  [31:0] dop$rd$4;
    reg  [31:0] dop$rd$5;
    reg  [31:0] dop$rd$6;
    reg  [31:0] dop$rd$7;
    reg  [31:0] dop$rd$8;
    reg  [31:0] dop$rd$9;
    reg  [31:0] dop$rd$10;
    reg  [31:0] dop$rd$11;
    reg  [31:0] dop$rd$12;
    reg  [31:0] dop$rd$13;
    reg  [31:0] dop$rd$14;
    reg  [31:0] dop$rd$15;
    reg  [31:0] dop$rd$16;
    reg  [31:0] dop$rd$17;
    reg  [31:0] dop$rd$18;
    reg  [31:0] dop$rd$19;
    reg  [31:0] dop$rd$20;
    reg  [31:0] dop$rd$21;
    reg  [31:0] dop$rd$22;
    reg  [31:0] dop$rd$23;
    reg  [31:0] dop$re$0;
    reg  [31:0] dop$re$1;
    reg  [31:0] dop$re$2;
    reg  [31:0] dop$re$3;
    reg  [31:0] dop$re$4;
    reg  [31:0] dop$re$5;
    reg  [31:0] dop$re$6;
    reg  [31:0] dop$re$7;
    reg  [31:0] dop$re$8;
    reg  [31:0] dop$re$9;
    reg  [31:0] dop$re$10;
    reg  [31:0] dop$re$11;
    reg  [31:0] dop$re$12;
    reg  [31:0] dop$re$13;
    reg  [31:0] dop$re$14;
    reg  [31:0] dop$re$15;
    reg  [31:0] dop$re$16;
    reg  [31:0] dop$re$17;
    reg  [31:0] dop$re$18;
    reg  [31:0] dop$re$19;
    reg  [31:0] dop$re$20;
    reg  [31:0] dop$re$21;
    reg  [31:0] dop$re$22;
    reg  [31:0] dop$re$23;
    reg  [8:0] dop$efd$0;
    reg  [8:0] dop$efd$1;
    reg  [8:0] dop$efd$2;
    reg  [8:0] dop$efd$3;
    reg  [8:0] dop$efd$4;
    reg  [8:0] dop$efd$5;
    reg  [8:0] dop$efd$6;
    reg  [8:0] dop$efd$7;
    reg  [8:0] dop$efd$8;
    reg  [8:0] dop$efd$9;
    reg  [8:0] dop$efd$10;
    reg  [8:0] dop$efd$11;
    reg  [8:0] dop$efd$12;
    reg  [8:0] dop$efd$13;
    reg  [8:0] dop$efd$14;
    reg  [8:0] dop$efd$15;
    reg  [8:0] dop$efd$16;
    reg  [8:0] dop$efd$17;
    reg  [8:0] dop$efd$18;
    reg  [8:0] dop$efd$19;
    reg  [8:0] dop$efd$20;
    reg  [8:0] dop$efd$21;
    reg  [8:0] dop$efd$22;
    reg  [8:0] dop$efd$23;
    reg  [8:0] dop$efe$0;
    reg  [8:0] dop$efe$1;
    reg  [8:0] dop$efe$2;
    reg  [8:0] dop$efe$3;
    reg  [8:0] dop$efe$4;
    reg  [8:0] dop$efe$5;
    reg  [8:0] dop$efe$6;
    reg  [8:0] dop$efe$7;
    reg  [8:0] dop$efe$8;
    reg  [8:0] dop$efe$9;
    reg  [8:0] dop$efe$10;
    reg  [8:0] dop$efe$11;
    reg  [8:0] dop$efe$12;
    reg  [8:0] dop$efe$13;
    reg  [8:0] dop$efe$14;
    reg  [8:0] dop$efe$15;
    reg  [8:0] dop$efe$16;
    reg  [8:0] dop$efe$17;
    reg  [8:0] dop$efe$18;
    reg  [8:0] dop$efe$19;
    reg  [8:0] dop$efe$20;
    reg  [8:0] dop$efe$21;
    reg  [8:0] dop$efe$22;
    reg  [8:0] dop$efe$23;
    reg  [15:0] dop$tag;
    reg  dop$valid_in;
    wire  dop$overlap;
    wire  [15:0] dop$tag_out;
    wire  dop$valid_out;
    reg  side$clock;
    reg  [98:0] side$d;
    wire  [98:0] side$q;
    reg  leaf_fifo$clock;
    reg  leaf_fifo$read;
    wire  [63:0] leaf_fifo$data_out;
    wire  leaf_fifo$empty;
    wire  leaf_fifo$almost_empty;
    wire  leaf_fifo$underflow;
    reg  leaf_fifo$write;
    reg  [63:0] leaf_fifo$data_in;
    wire  leaf_fifo$full;
    wire  leaf_fifo$almost_full;
    wire  leaf_fifo$overflow;
    reg  [5:0] leaf_count$d;
    wire  [5:0] leaf_count$q;
    reg  leaf_count$clock;
    reg  leaf_valid$d;
    wire  leaf_valid$q;
    reg  leaf_valid$clock;
    reg  [63:0] leaf_tag$d;
    wire  [63:0] leaf_tag$q;
    reg  leaf_tag$clock;
    reg  [6:0] tc_mask$d;
    wire  [6:0] tc_mask$q;
    reg  tc_mask$clock;
    reg  tri_cache$clock;
    reg  tri_cache$clear;
    reg  [6:0] tri_cache$mask;
    reg  tri_cache$fill;
    reg  [15:0] tri_cache$fill_id;
    reg  [737:0] tri_cache$fill_word;
    reg  [15:0] tri_cache$id;
    reg  [15:0] tri_cache$next_id;
    wire  tri_cache$hit;
    wire  [737:0] tri_cache$word;
    reg  tb_ok$d;
    wire  tb_ok$q;
    reg  tb_ok$clock;
    reg  [15:0] tb_id$d;
    wire  [15:0] tb_id$q;
    reg  tb_id$clock;
    reg  [737:0] tb_word$d;
    wire  [737:0] tb_word$q;
    reg  tb_word$clock;
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
    reg  cnt_dop$clock;
    reg  cnt_dop$clear;
    reg  cnt_dop$inc;
    wire  [31:0] cnt_dop$count;
    reg  cnt_tri$clock;
    reg  cnt_tri$clear;
    reg  cnt_tri$inc;
    wire  [31:0] cnt_tri$count;
    reg  cnt_nf$clock;
    reg  cnt_nf$clear;
    reg  cnt_nf$inc;
    wire  [31:0] cnt_nf$count;
    reg  cnt_tf$clock;
    reg  cnt_tf$clear;
    reg  cnt_tf$inc;
    wire  [31:0] cnt_tf$count;
    
    // Local signals
    reg  [15:0] id_mask;
    reg  halt;
    reg  start_q;
    reg  [5:0] credit_lim;
    reg  [4:0] pf;
    reg  go;
    reg  leaf_out;
    reg  [31:0] tri_ids;
    reg  [31:0] next_tri_ids;
    reg  need_ta;
    reg  need_tb;
    reg  tri_in;
    reg  tri_take;
    reg  all_idle;
    reg  halt_idle;
    
    // Sub module instances
    top$cnt_dop$pending mode_lifo(
        .d(mode_lifo$d),
        .q(mode_lifo$q),
        .clock(mode_lifo$clock)
    );
    top$cnt_dop$pending mode_first(
        .d(mode_first$d),
        .q(mode_first$q),
        .clock(mode_first$clock)
    );
    top$cnt_dop$pending mode_rec(
        .d(mode_rec$d),
        .q(mode_rec$q),
        .clock(mode_rec$clock)
    );
    top$mode_slot mode_slot(
        .d(mode_slot$d),
        .q(mode_slot$q),
        .clock(mode_slot$clock)
    );
    top$cnt_dop$total root(
        .d(root$d),
        .q(root$q),
        .clock(root$clock)
    );
    top$base_na base_na(
        .d(base_na$d),
        .q(base_na$q),
        .clock(base_na$clock)
    );
    top$base_na base_nb(
        .d(base_nb$d),
        .q(base_nb$q),
        .clock(base_nb$clock)
    );
    top$base_na base_ta(
        .d(base_ta$d),
        .q(base_ta$q),
        .clock(base_ta$clock)
    );
    top$base_na base_tb(
        .d(base_tb$d),
        .q(base_tb$q),
        .clock(base_tb$clock)
    );
    top$map map(
        .d(map$d),
        .q(map$q),
        .clock(map$clock)
    );
    top$cnt_dop$pending run(
        .d(run$d),
        .q(run$q),
        .clock(run$clock)
    );
    top$cnt_dop$pending done_r(
        .d(done_r$d),
        .q(done_r$q),
        .clock(done_r$clock)
    );
    top$cnt_dop$pending push_root(
        .d(push_root$d),
        .q(push_root$q),
        .clock(push_root$clock)
    );
    top$cnt_dop$pending stop(
        .d(stop$d),
        .q(stop$q),
        .clock(stop$clock)
    );
    top$d_cntr$ahd_fetch$row$0 port_pf(
        .d(port_pf$d),
        .q(port_pf$q),
        .clock(port_pf$clock)
    );
    top$d_cntr$ahd_fetch$row$0 port_out(
        .d(port_out$d),
        .q(port_out$q),
        .clock(port_out$clock)
    );
    top$cnt_dop$pending port_one(
        .d(port_one$d),
        .q(port_one$q),
        .clock(port_one$clock)
    );
    top$leaf_count port_credit(
        .d(port_credit$d),
        .q(port_credit$q),
        .clock(port_credit$clock)
    );
    top$d_cntr d_cntr(
        .clock(d_cntr$clock),
        .clear(d_cntr$clear),
        .lifo(d_cntr$lifo),
        .push_root(d_cntr$push_root),
        .root(d_cntr$root),
        .go(d_cntr$go),
        .pf(d_cntr$pf),
        .one(d_cntr$one),
        .credit_lim(d_cntr$credit_lim),
        .leaf_count(d_cntr$leaf_count),
        .id_mask(d_cntr$id_mask),
        .wa_empty(d_cntr$wa_empty),
        .wb_empty(d_cntr$wb_empty),
        .dop_valid(d_cntr$dop_valid),
        .dop_overlap(d_cntr$dop_overlap),
        .side(d_cntr$side),
        .empty(d_cntr$empty),
        .count(d_cntr$count),
        .max_count(d_cntr$max_count),
        .overflow(d_cntr$overflow),
        .push(d_cntr$push),
        .pop(d_cntr$pop),
        .pop_entry(d_cntr$pop_entry),
        .pop_fetch(d_cntr$pop_fetch),
        .ent_valid(d_cntr$ent_valid),
        .cur_a(d_cntr$cur_a),
        .cur_b(d_cntr$cur_b),
        .cur_flip(d_cntr$cur_flip),
        .cur_fa(d_cntr$cur_fa),
        .cur_fb(d_cntr$cur_fb),
        .need_na(d_cntr$need_na),
        .need_nb(d_cntr$need_nb),
        .issue(d_cntr$issue),
        .r_a(d_cntr$r_a),
        .r_b(d_cntr$r_b),
        .r_a_leaf(d_cntr$r_a_leaf),
        .r_b_leaf(d_cntr$r_b_leaf),
        .leaf_in(d_cntr$leaf_in),
        .leaf_pair(d_cntr$leaf_pair),
        .inflight(d_cntr$inflight),
        .pend(d_cntr$pend)
    );
    top$mem_port mem_port(
        .clock(mem_port$clock),
        .clear(mem_port$clear),
        .go(mem_port$go),
        .pf_on(mem_port$pf_on),
        .slot_bits(mem_port$slot_bits),
        .port_out(mem_port$port_out),
        .base_na(mem_port$base_na),
        .base_nb(mem_port$base_nb),
        .base_ta(mem_port$base_ta),
        .base_tb(mem_port$base_tb),
        .map(mem_port$map),
        .pop(mem_port$pop),
        .pop_entry(mem_port$pop_entry),
        .pop_fetch(mem_port$pop_fetch),
        .issue(mem_port$issue),
        .cur_fa(mem_port$cur_fa),
        .cur_fb(mem_port$cur_fb),
        .cur_sa(mem_port$cur_sa),
        .cur_sb(mem_port$cur_sb),
        .need_ta(mem_port$need_ta),
        .need_tb(mem_port$need_tb),
        .leaf_tag(mem_port$leaf_tag),
        .mem_req_ready(mem_port$mem_req_ready),
        .mem_resp_valid(mem_port$mem_resp_valid),
        .mem_resp_data(mem_port$mem_resp_data),
        .mem_req_valid(mem_port$mem_req_valid),
        .mem_req_addr(mem_port$mem_req_addr),
        .req_dst(mem_port$req_dst),
        .accept(mem_port$accept),
        .resp(mem_port$resp),
        .resp_dst(mem_port$resp_dst),
        .ta_req(mem_port$ta_req),
        .tb_req(mem_port$tb_req),
        .outstanding(mem_port$outstanding),
        .na_in(mem_port$na_in),
        .nb_in(mem_port$nb_in),
        .na_sh(mem_port$na_sh),
        .nb_sh(mem_port$nb_sh),
        .wa_empty(mem_port$wa_empty),
        .wb_empty(mem_port$wb_empty)
    );
    top$dop dop(
        .clock(dop$clock),
        .load_en(dop$load_en),
        .load_addr(dop$load_addr),
        .load_data(dop$load_data),
        .d$0(dop$d$0),
        .d$1(dop$d$1),
        .d$2(dop$d$2),
        .d$3(dop$d$3),
        .d$4(dop$d$4),
        .d$5(dop$d$5),
        .d$6(dop$d$6),
        .d$7(dop$d$7),
        .d$8(dop$d$8),
        .d$9(dop$d$9),
        .d$10(dop$d$10),
        .d$11(dop$d$11),
        .d$12(dop$d$12),
        .d$13(dop$d$13),
        .d$14(dop$d$14),
        .d$15(dop$d$15),
        .d$16(dop$d$16),
        .d$17(dop$d$17),
        .d$18(dop$d$18),
        .d$19(dop$d$19),
        .d$20(dop$d$20),
        .d$21(dop$d$21),
        .d$22(dop$d$22),
        .d$23(dop$d$23),
        .e$0(dop$e$0),
        .e$1(dop$e$1),
        .e$2(dop$e$2),
        .e$3(dop$e$3),
        .e$4(dop$e$4),
        .e$5(dop$e$5),
        .e$6(dop$e$6),
        .e$7(dop$e$7),
        .e$8(dop$e$8),
        .e$9(dop$e$9),
        .e$10(dop$e$10),
        .e$11(dop$e$11),
        .e$12(dop$e$12),
        .e$13(dop$e$13),
        .e$14(dop$e$14),
        .e$15(dop$e$15),
        .e$16(dop$e$16),
        .e$17(dop$e$17),
        .e$18(dop$e$18),
        .e$19(dop$e$19),
        .e$20(dop$e$20),
        .e$21(dop$e$21),
        .e$22(dop$e$22),
        .e$23(dop$e$23),
        .rd$0(dop$rd$0),
        .rd$1(dop$rd$1),
        .rd$2(dop$rd$2),
        .rd$3(dop$rd$3),
        .rd$4(dop$rd$4),
        .rd$5(dop$rd$5),
        .rd$6(dop$rd$6),
        .rd$7(dop$rd$7),
        .rd$8(dop$rd$8),
        .rd$9(dop$rd$9),
        .rd$10(dop$rd$10),
        .rd$11(dop$rd$11),
        .rd$12(dop$rd$12),
        .rd$13(dop$rd$13),
        .rd$14(dop$rd$14),
        .rd$15(dop$rd$15),
        .rd$16(dop$rd$16),
        .rd$17(dop$rd$17),
        .rd$18(dop$rd$18),
        .rd$19(dop$rd$19),
        .rd$20(dop$rd$20),
        .rd$21(dop$rd$21),
        .rd$22(dop$rd$22),
        .rd$23(dop$rd$23),
        .re$0(dop$re$0),
        .re$1(dop$re$1),
        .re$2(dop$re$2),
        .re$3(dop$re$3),
        .re$4(dop$re$4),
        .re$5(dop$re$5),
        .re$6(dop$re$6),
        .re$7(dop$re$7),
        .re$8(dop$re$8),
        .re$9(dop$re$9),
        .re$10(dop$re$10),
        .re$11(dop$re$11),
        .re$12(dop$re$12),
        .re$13(dop$re$13),
        .re$14(dop$re$14),
        .re$15(dop$re$15),
        .re$16(dop$re$16),
        .re$17(dop$re$17),
        .re$18(dop$re$18),
        .re$19(dop$re$19),
        .re$20(dop$re$20),
        .re$21(dop$re$21),
        .re$22(dop$re$22),
        .re$23(dop$re$23),
        .efd$0(dop$efd$0),
        .efd$1(dop$efd$1),
        .efd$2(dop$efd$2),
        .efd$3(dop$efd$3),
        .efd$4(dop$efd$4),
        .efd$5(dop$efd$5),
        .efd$6(dop$efd$6),
        .efd$7(dop$efd$7),
        .efd$8(dop$efd$8),
        .efd$9(dop$efd$9),
        .efd$10(dop$efd$10),
        .efd$11(dop$efd$11),
        .efd$12(dop$efd$12),
        .efd$13(dop$efd$13),
        .efd$14(dop$efd$14),
        .efd$15(dop$efd$15),
        .efd$16(dop$efd$16),
        .efd$17(dop$efd$17),
        .efd$18(dop$efd$18),
        .efd$19(dop$efd$19),
        .efd$20(dop$efd$20),
        .efd$21(dop$efd$21),
        .efd$22(dop$efd$22),
        .efd$23(dop$efd$23),
        .efe$0(dop$efe$0),
        .efe$1(dop$efe$1),
        .efe$2(dop$efe$2),
        .efe$3(dop$efe$3),
        .efe$4(dop$efe$4),
        .efe$5(dop$efe$5),
        .efe$6(dop$efe$6),
        .efe$7(dop$efe$7),
        .efe$8(dop$efe$8),
        .efe$9(dop$efe$9),
        .efe$10(dop$efe$10),
        .efe$11(dop$efe$11),
        .efe$12(dop$efe$12),
        .efe$13(dop$efe$13),
        .efe$14(dop$efe$14),
        .efe$15(dop$efe$15),
        .efe$16(dop$efe$16),
        .efe$17(dop$efe$17),
        .efe$18(dop$efe$18),
        .efe$19(dop$efe$19),
        .efe$20(dop$efe$20),
        .efe$21(dop$efe$21),
        .efe$22(dop$efe$22),
        .efe$23(dop$efe$23),
        .tag(dop$tag),
        .valid_in(dop$valid_in),
        .overlap(dop$overlap),
        .tag_out(dop$tag_out),
        .valid_out(dop$valid_out)
    );
    top$side side(
        .clock(side$clock),
        .d(side$d),
        .q(side$q)
    );
    top$leaf_fifo leaf_fifo(
        .clock(leaf_fifo$clock),
        .read(leaf_fifo$read),
        .data_out(leaf_fifo$data_out),
        .empty(leaf_fifo$empty),
        .almost_empty(leaf_fifo$almost_empty),
        .underflow(leaf_fifo$underflow),
        .write(leaf_fifo$write),
        .data_in(leaf_fifo$data_in),
        .full(leaf_fifo$full),
        .almost_full(leaf_fifo$almost_full),
        .overflow(leaf_fifo$overflow)
    );
    top$leaf_count leaf_count(
        .d(leaf_count$d),
        .q(leaf_count$q),
        .clock(leaf_count$clock)
    );
    top$cnt_dop$pending leaf_valid(
        .d(leaf_valid$d),
        .q(leaf_valid$q),
        .clock(leaf_valid$clock)
    );
    top$leaf_tag leaf_tag(
        .d(leaf_tag$d),
        .q(leaf_tag$q),
        .clock(leaf_tag$clock)
    );
    top$leaf_fifo$read_logic$read_address tc_mask(
        .d(tc_mask$d),
        .q(tc_mask$q),
        .clock(tc_mask$clock)
    );
    top$tri_cache tri_cache(
        .clock(tri_cache$clock),
        .clear(tri_cache$clear),
        .mask(tri_cache$mask),
        .fill(tri_cache$fill),
        .fill_id(tri_cache$fill_id),
        .fill_word(tri_cache$fill_word),
        .id(tri_cache$id),
        .next_id(tri_cache$next_id),
        .hit(tri_cache$hit),
        .word(tri_cache$word)
    );
    top$cnt_dop$pending tb_ok(
        .d(tb_ok$d),
        .q(tb_ok$q),
        .clock(tb_ok$clock)
    );
    top$d_cntr$last_a tb_id(
        .d(tb_id$d),
        .q(tb_id$q),
        .clock(tb_id$clock)
    );
    top$tb_word tb_word(
        .d(tb_word$d),
        .q(tb_word$q),
        .clock(tb_word$clock)
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
    top$cnt_dop cnt_dop(
        .clock(cnt_dop$clock),
        .clear(cnt_dop$clear),
        .inc(cnt_dop$inc),
        .count(cnt_dop$count)
    );
    top$cnt_dop cnt_tri(
        .clock(cnt_tri$clock),
        .clear(cnt_tri$clear),
        .inc(cnt_tri$inc),
        .count(cnt_tri$count)
    );
    top$cnt_dop cnt_nf(
        .clock(cnt_nf$clock),
        .clear(cnt_nf$clear),
        .inc(cnt_nf$inc),
        .count(cnt_nf$count)
    );
    top$cnt_dop cnt_tf(
        .clock(cnt_tf$clock),
        .clear(cnt_tf$clear),
        .inc(cnt_tf$inc),
        .count(cnt_tf$count)
    );
    
    // Update code
    always @(*) begin
        mode_lifo$clock = clock;
        mode_first$clock = clock;
        mode_rec$clock = clock;
        mode_slot$clock = clock;
        root$clock = clock;
        base_na$clock = clock;
        base_nb$clock = clock;
        base_ta$clock = clock;
        base_tb$clock = clock;
        map$clock = clock;
        mode_lifo$d = mode_lifo$q;
        mode_first$d = mode_first$q;
        mode_rec$d = mode_rec$q;
        mode_slot$d = mode_slot$q;
        root$d = root$q;
        base_na$d = base_na$q;
        base_nb$d = base_nb$q;
        base_ta$d = base_ta$q;
        base_tb$d = base_tb$q;
        map$d = map$q;
        port_pf$clock = clock;
        port_out$clock = clock;
        port_one$clock = clock;
        port_credit$clock = clock;
        run$clock = clock;
        done_r$clock = clock;
        push_root$clock = clock;
        stop$clock = clock;
        port_pf$d = port_pf$q;
        port_out$d = port_out$q;
        port_one$d = port_one$q;
        port_credit$d = port_credit$q;
        run$d = run$q;
        done_r$d = done_r$q;
        push_root$d = push_root$q;
        stop$d = stop$q;
        leaf_count$clock = clock;
        leaf_valid$clock = clock;
        leaf_tag$clock = clock;
        leaf_count$d = leaf_count$q;
        leaf_valid$d = leaf_valid$q;
        leaf_tag$d = leaf_tag$q;
        tc_mask$clock = clock;
        tb_ok$clock = clock;
        tb_id$clock = clock;
        tb_word$clock = clock;
        tc_mask$d = tc_mask$q;
        tb_ok$d = tb_ok$q;
        tb_id$d = tb_id$q;
        tb_word$d = tb_word$q;
        d_cntr$clock = clock;
        mem_port$clock = clock;
        dop$clock = clock;
        side$clock = clock;
        leaf_fifo$clock = clock;
        tri_cache$clock = clock;
        tri_unit$clock = clock;
        result$clock = clock;
        cnt_dop$clock = clock;
        cnt_tri$clock = clock;
        cnt_nf$clock = clock;
        cnt_tf$clock = clock;
        dop$load_en = host_we & (host_addr[(32'h8)+:(2)] == 32'h0);
        dop$load_addr = host_addr[(32'h0)+:(8)];
        dop$load_data = host_data[(32'h0)+:(32)];
        tri_unit$load_en = host_we & (host_addr[(32'h5)+:(5)] == 32'h8);
        tri_unit$load_addr = host_addr[(32'h0)+:(5)];
        tri_unit$load_data = host_data[(32'h0)+:(32)];
        if (host_we) begin
            if (host_addr == 32'h120) begin
                mode_lifo$d = host_data[32'h0];
                mode_first$d = host_data[32'h1];
                mode_rec$d = host_data[32'h2];
                mode_slot$d = host_data[(32'h3)+:(3)];
            end
            if (host_addr == 32'h121) begin
                root$d = host_data;
            end
            if (host_addr == 32'h122) begin
                base_na$d = host_data[(32'h0)+:(24)];
            end
            if (host_addr == 32'h123) begin
                base_nb$d = host_data[(32'h0)+:(24)];
            end
            if (host_addr == 32'h124) begin
                base_ta$d = host_data[(32'h0)+:(24)];
            end
            if (host_addr == 32'h125) begin
                base_tb$d = host_data[(32'h0)+:(24)];
            end
            if (host_addr == 32'h126) begin
                port_pf$d = host_data[(32'h0)+:(4)];
                port_out$d = host_data[(32'h4)+:(4)];
                port_one$d = host_data[32'h8];
                port_credit$d = host_data[(32'h9)+:(6)];
            end
            if (host_addr == 32'h127) begin
                tc_mask$d = host_data[(32'h0)+:(7)];
            end
            if (host_addr == 32'h128) begin
                map$d = host_data[(32'h0)+:(20)];
            end
        end
        pf = ((port_pf$q) & 5'h1f);
        if (((port_pf$q) & 5'h1f) > c_pf_max) begin
            pf = c_pf_max;
        end
        credit_lim = port_credit$q;
        if (port_credit$q == 32'h0) begin
            credit_lim = c_credit;
        end
        halt = stop$q | d_cntr$overflow;
        go = run$q & ~halt;
        start_q = start & ~run$q;
        d_cntr$clear = start_q;
        d_cntr$lifo = mode_lifo$q;
        d_cntr$push_root = push_root$q;
        d_cntr$root = root$q;
        d_cntr$go = go;
        d_cntr$pf = pf;
        d_cntr$one = port_one$q;
        d_cntr$credit_lim = credit_lim;
        d_cntr$leaf_count = leaf_count$q;
        d_cntr$wa_empty = mem_port$wa_empty;
        d_cntr$wb_empty = mem_port$wb_empty;
        d_cntr$dop_valid = dop$valid_out;
        d_cntr$dop_overlap = dop$overlap;
        d_cntr$side = side$q;
        id_mask = c_ones16 << mode_slot$q;
        d_cntr$id_mask = id_mask;
        push_root$d = 1'b0;
        tri_ids = leaf_tag$q[(32'h0)+:(32)];
        if (mode_rec$q) begin
            tri_ids = leaf_tag$q[(32'h20)+:(32)];
        end
        tri_cache$clear = start_q;
        tri_cache$mask = tc_mask$q;
        tri_cache$id = tri_ids[(32'h0)+:(16)];
        need_ta = go & leaf_valid$q & ~tri_cache$hit;
        need_tb = go & leaf_valid$q & ~(tb_ok$q & (tb_id$q == tri_ids[(32'h10)+:(16)]));
        mem_port$clear = start_q;
        mem_port$go = go;
        mem_port$pf_on = pf != 32'h0;
        mem_port$port_out = port_out$q;
        mem_port$base_na = base_na$q;
        mem_port$base_nb = base_nb$q;
        mem_port$base_ta = base_ta$q;
        mem_port$base_tb = base_tb$q;
        mem_port$map = map$q;
        mem_port$pop = d_cntr$pop;
        mem_port$pop_entry = d_cntr$pop_entry;
        mem_port$pop_fetch = d_cntr$pop_fetch;
        mem_port$issue = d_cntr$issue;
        mem_port$cur_fa = d_cntr$cur_fa;
        mem_port$cur_fb = d_cntr$cur_fb;
        mem_port$need_ta = need_ta;
        mem_port$need_tb = need_tb;
        mem_port$leaf_tag = tri_ids;
        mem_port$slot_bits = mode_slot$q;
        mem_port$cur_sa = ((d_cntr$cur_a & ~id_mask) & 3'h7);
        mem_port$cur_sb = ((d_cntr$cur_b & ~id_mask) & 3'h7);
        mem_port$mem_req_ready = mem_req_ready;
        mem_port$mem_resp_valid = mem_resp_valid;
        mem_port$mem_resp_data = mem_resp_data;
        mem_req_valid = mem_port$mem_req_valid;
        mem_req_addr = mem_port$mem_req_addr;
        cnt_tf$inc = mem_port$accept & mem_port$req_dst[32'h1];
        cnt_nf$inc = mem_port$accept & ~mem_port$req_dst[32'h1];
        tri_cache$fill = mem_port$resp & (mem_port$resp_dst == 32'h2);
        tri_cache$fill_id = mem_port$ta_req;
        tri_cache$fill_word = mem_resp_data[(32'h0)+:(738)];
        if (mem_port$resp) begin
            if (mem_port$resp_dst == 32'h3) begin
                tb_ok$d = 1'b1;
                tb_id$d = mem_port$tb_req;
                tb_word$d = mem_resp_data[(32'h0)+:(738)];
            end
        end
        dop$d$0 = mem_port$nb_in[(32'h1 + 0 * 32'h4)+:(4)];
        dop$e$0 = mem_port$na_in[(32'h1 + 0 * 32'h4)+:(4)];
        dop$d$1 = mem_port$nb_in[(32'h1 + 1 * 32'h4)+:(4)];
        dop$e$1 = mem_port$na_in[(32'h1 + 1 * 32'h4)+:(4)];
        dop$d$2 = mem_port$nb_in[(32'h1 + 2 * 32'h4)+:(4)];
        dop$e$2 = mem_port$na_in[(32'h1 + 2 * 32'h4)+:(4)];
        dop$d$3 = mem_port$nb_in[(32'h1 + 3 * 32'h4)+:(4)];
        dop$e$3 = mem_port$na_in[(32'h1 + 3 * 32'h4)+:(4)];
        dop$d$4 = mem_port$nb_in[(32'h1 + 4 * 32'h4)+:(4)];
        dop$e$4 = mem_port$na_in[(32'h1 + 4 * 32'h4)+:(4)];
        dop$d$5 = mem_port$nb_in[(32'h1 + 5 * 32'h4)+:(4)];
        dop$e$5 = mem_port$na_in[(32'h1 + 5 * 32'h4)+:(4)];
        dop$d$6 = mem_port$nb_in[(32'h1 + 6 * 32'h4)+:(4)];
        dop$e$6 = mem_port$na_in[(32'h1 + 6 * 32'h4)+:(4)];
        dop$d$7 = mem_port$nb_in[(32'h1 + 7 * 32'h4)+:(4)];
        dop$e$7 = mem_port$na_in[(32'h1 + 7 * 32'h4)+:(4)];
        dop$d$8 = mem_port$nb_in[(32'h1 + 8 * 32'h4)+:(4)];
        dop$e$8 = mem_port$na_in[(32'h1 + 8 * 32'h4)+:(4)];
        dop$d$9 = mem_port$nb_in[(32'h1 + 9 * 32'h4)+:(4)];
        dop$e$9 = mem_port$na_in[(32'h1 + 9 * 32'h4)+:(4)];
        dop$d$10 = mem_port$nb_in[(32'h1 + 10 * 32'h4)+:(4)];
        dop$e$10 = mem_port$na_in[(32'h1 + 10 * 32'h4)+:(4)];
        dop$d$11 = mem_port$nb_in[(32'h1 + 11 * 32'h4)+:(4)];
        dop$e$11 = mem_port$na_in[(32'h1 + 11 * 32'h4)+:(4)];
        dop$d$12 = mem_port$nb_in[(32'h1 + 12 * 32'h4)+:(4)];
        dop$e$12 = mem_port$na_in[(32'h1 + 12 * 32'h4)+:(4)];
        dop$d$13 = mem_port$nb_in[(32'h1 + 13 * 32'h4)+:(4)];
        dop$e$13 = mem_port$na_in[(32'h1 + 13 * 32'h4)+:(4)];
        dop$d$14 = mem_port$nb_in[(32'h1 + 14 * 32'h4)+:(4)];
        dop$e$14 = mem_port$na_in[(32'h1 + 14 * 32'h4)+:(4)];
        dop$d$15 = mem_port$nb_in[(32'h1 + 15 * 32'h4)+:(4)];
        dop$e$15 = mem_port$na_in[(32'h1 + 15 * 32'h4)+:(4)];
        dop$d$16 = mem_port$nb_in[(32'h1 + 16 * 32'h4)+:(4)];
        dop$e$16 = mem_port$na_in[(32'h1 + 16 * 32'h4)+:(4)];
        dop$d$17 = mem_port$nb_in[(32'h1 + 17 * 32'h4)+:(4)];
        dop$e$17 = mem_port$na_in[(32'h1 + 17 * 32'h4)+:(4)];
        dop$d$18 = mem_port$nb_in[(32'h1 + 18 * 32'h4)+:(4)];
        dop$e$18 = mem_port$na_in[(32'h1 + 18 * 32'h4)+:(4)];
        dop$d$19 = mem_port$nb_in[(32'h1 + 19 * 32'h4)+:(4)];
        dop$e$19 = mem_port$na_in[(32'h1 + 19 * 32'h4)+:(4)];
        dop$d$20 = mem_port$nb_in[(32'h1 + 20 * 32'h4)+:(4)];
        dop$e$20 = mem_port$na_in[(32'h1 + 20 * 32'h4)+:(4)];
        dop$d$21 = mem_port$nb_in[(32'h1 + 21 * 32'h4)+:(4)];
        dop$e$21 = mem_port$na_in[(32'h1 + 21 * 32'h4)+:(4)];
        dop$d$22 = mem_port$nb_in[(32'h1 + 22 * 32'h4)+:(4)];
        dop$e$22 = mem_port$na_in[(32'h1 + 22 * 32'h4)+:(4)];
        dop$d$23 = mem_port$nb_in[(32'h1 + 23 * 32'h4)+:(4)];
        dop$e$23 = mem_port$na_in[(32'h1 + 23 * 32'h4)+:(4)];
        dop$rd$0 = mem_port$nb_sh[(0 * 32'h20)+:(32)];
        dop$re$0 = mem_port$na_sh[(0 * 32'h20)+:(32)];
        dop$efd$0 = mem_port$nb_sh[(32'h18 * 32'h20 + 0 * 32'h9)+:(9)];
        dop$efe$0 = mem_port$na_sh[(32'h18 * 32'h20 + 0 * 32'h9)+:(9)];
        dop$rd$1 = mem_port$nb_sh[(1 * 32'h20)+:(32)];
        dop$re$1 = mem_port$na_sh[(1 * 32'h20)+:(32)];
        dop$efd$1 = mem_port$nb_sh[(32'h18 * 32'h20 + 1 * 32'h9)+:(9)];
        dop$efe$1 = mem_port$na_sh[(32'h18 * 32'h20 + 1 * 32'h9)+:(9)];
        dop$rd$2 = mem_port$nb_sh[(2 * 32'h20)+:(32)];
        dop$re$2 = mem_port$na_sh[(2 * 32'h20)+:(32)];
        dop$efd$2 = mem_port$nb_sh[(32'h18 * 32'h20 + 2 * 32'h9)+:(9)];
        dop$efe$2 = mem_port$na_sh[(32'h18 * 32'h20 + 2 * 32'h9)+:(9)];
        dop$rd$3 = mem_port$nb_sh[(3 * 32'h20)+:(32)];
        dop$re$3 = mem_port$na_sh[(3 * 32'h20)+:(32)];
        dop$efd$3 = mem_port$nb_sh[(32'h18 * 32'h20 + 3 * 32'h9)+:(9)];
        dop$efe$3 = mem_port$na_sh[(32'h18 * 32'h20 + 3 * 32'h9)+:(9)];
        dop$rd$4 = mem_port$nb_sh[(4 * 32'h20)+:(32)];
        dop$re$4 = mem_port$na_sh[(4 * 32'h20)+:(32)];
        dop$efd$4 = mem_port$nb_sh[(32'h18 * 32'h20 + 4 * 32'h9)+:(9)];
        dop$efe$4 = mem_port$na_sh[(32'h18 * 32'h20 + 4 * 32'h9)+:(9)];
        dop$rd$5 = mem_port$nb_sh[(5 * 32'h20)+:(32)];
        dop$re$5 = mem_port$na_sh[(5 * 32'h20)+:(32)];
        dop$efd$5 = mem_port$nb_sh[(32'h18 * 32'h20 + 5 * 32'h9)+:(9)];
        dop$efe$5 = mem_port$na_sh[(32'h18 * 32'h20 + 5 * 32'h9)+:(9)];
        dop$rd$6 = mem_port$nb_sh[(6 * 32'h20)+:(32)];
        dop$re$6 = mem_port$na_sh[(6 * 32'h20)+:(32)];
        dop$efd$6 = mem_port$nb_sh[(32'h18 * 32'h20 + 6 * 32'h9)+:(9)];
        dop$efe$6 = mem_port$na_sh[(32'h18 * 32'h20 + 6 * 32'h9)+:(9)];
        dop$rd$7 = mem_port$nb_sh[(7 * 32'h20)+:(32)];
        dop$re$7 = mem_port$na_sh[(7 * 32'h20)+:(32)];
        dop$efd$7 = mem_port$nb_sh[(32'h18 * 32'h20 + 7 * 32'h9)+:(9)];
        dop$efe$7 = mem_port$na_sh[(32'h18 * 32'h20 + 7 * 32'h9)+:(9)];
        dop$rd$8 = mem_port$nb_sh[(8 * 32'h20)+:(32)];
        dop$re$8 = mem_port$na_sh[(8 * 32'h20)+:(32)];
        dop$efd$8 = mem_port$nb_sh[(32'h18 * 32'h20 + 8 * 32'h9)+:(9)];
        dop$efe$8 = mem_port$na_sh[(32'h18 * 32'h20 + 8 * 32'h9)+:(9)];
        dop$rd$9 = mem_port$nb_sh[(9 * 32'h20)+:(32)];
        dop$re$9 = mem_port$na_sh[(9 * 32'h20)+:(32)];
        dop$efd$9 = mem_port$nb_sh[(32'h18 * 32'h20 + 9 * 32'h9)+:(9)];
        dop$efe$9 = mem_port$na_sh[(32'h18 * 32'h20 + 9 * 32'h9)+:(9)];
        dop$rd$10 = mem_port$nb_sh[(10 * 32'h20)+:(32)];
        dop$re$10 = mem_port$na_sh[(10 * 32'h20)+:(32)];
        dop$efd$10 = mem_port$nb_sh[(32'h18 * 32'h20 + 10 * 32'h9)+:(9)];
        dop$efe$10 = mem_port$na_sh[(32'h18 * 32'h20 + 10 * 32'h9)+:(9)];
        dop$rd$11 = mem_port$nb_sh[(11 * 32'h20)+:(32)];
        dop$re$11 = mem_port$na_sh[(11 * 32'h20)+:(32)];
        dop$efd$11 = mem_port$nb_sh[(32'h18 * 32'h20 + 11 * 32'h9)+:(9)];
        dop$efe$11 = mem_port$na_sh[(32'h18 * 32'h20 + 11 * 32'h9)+:(9)];
        dop$rd$12 = mem_port$nb_sh[(12 * 32'h20)+:(32)];
        dop$re$12 = mem_port$na_sh[(12 * 32'h20)+:(32)];
        dop$efd$12 = mem_port$nb_sh[(32'h18 * 32'h20 + 12 * 32'h9)+:(9)];
        dop$efe$12 = mem_port$na_sh[(32'h18 * 32'h20 + 12 * 32'h9)+:(9)];
        dop$rd$13 = mem_port$nb_sh[(13 * 32'h20)+:(32)];
        dop$re$13 = mem_port$na_sh[(13 * 32'h20)+:(32)];
        dop$efd$13 = mem_port$nb_sh[(32'h18 * 32'h20 + 13 * 32'h9)+:(9)];
        dop$efe$13 = mem_port$na_sh[(32'h18 * 32'h20 + 13 * 32'h9)+:(9)];
        dop$rd$14 = mem_port$nb_sh[(14 * 32'h20)+:(32)];
        dop$re$14 = mem_port$na_sh[(14 * 32'h20)+:(32)];
        dop$efd$14 = mem_port$nb_sh[(32'h18 * 32'h20 + 14 * 32'h9)+:(9)];
        dop$efe$14 = mem_port$na_sh[(32'h18 * 32'h20 + 14 * 32'h9)+:(9)];
        dop$rd$15 = mem_port$nb_sh[(15 * 32'h20)+:(32)];
        dop$re$15 = mem_port$na_sh[(15 * 32'h20)+:(32)];
        dop$efd$15 = mem_port$nb_sh[(32'h18 * 32'h20 + 15 * 32'h9)+:(9)];
        dop$efe$15 = mem_port$na_sh[(32'h18 * 32'h20 + 15 * 32'h9)+:(9)];
        dop$rd$16 = mem_port$nb_sh[(16 * 32'h20)+:(32)];
        dop$re$16 = mem_port$na_sh[(16 * 32'h20)+:(32)];
        dop$efd$16 = mem_port$nb_sh[(32'h18 * 32'h20 + 16 * 32'h9)+:(9)];
        dop$efe$16 = mem_port$na_sh[(32'h18 * 32'h20 + 16 * 32'h9)+:(9)];
        dop$rd$17 = mem_port$nb_sh[(17 * 32'h20)+:(32)];
        dop$re$17 = mem_port$na_sh[(17 * 32'h20)+:(32)];
        dop$efd$17 = mem_port$nb_sh[(32'h18 * 32'h20 + 17 * 32'h9)+:(9)];
        dop$efe$17 = mem_port$na_sh[(32'h18 * 32'h20 + 17 * 32'h9)+:(9)];
        dop$rd$18 = mem_port$nb_sh[(18 * 32'h20)+:(32)];
        dop$re$18 = mem_port$na_sh[(18 * 32'h20)+:(32)];
        dop$efd$18 = mem_port$nb_sh[(32'h18 * 32'h20 + 18 * 32'h9)+:(9)];
        dop$efe$18 = mem_port$na_sh[(32'h18 * 32'h20 + 18 * 32'h9)+:(9)];
        dop$rd$19 = mem_port$nb_sh[(19 * 32'h20)+:(32)];
        dop$re$19 = mem_port$na_sh[(19 * 32'h20)+:(32)];
        dop$efd$19 = mem_port$nb_sh[(32'h18 * 32'h20 + 19 * 32'h9)+:(9)];
        dop$efe$19 = mem_port$na_sh[(32'h18 * 32'h20 + 19 * 32'h9)+:(9)];
        dop$rd$20 = mem_port$nb_sh[(20 * 32'h20)+:(32)];
        dop$re$20 = mem_port$na_sh[(20 * 32'h20)+:(32)];
        dop$efd$20 = mem_port$nb_sh[(32'h18 * 32'h20 + 20 * 32'h9)+:(9)];
        dop$efe$20 = mem_port$na_sh[(32'h18 * 32'h20 + 20 * 32'h9)+:(9)];
        dop$rd$21 = mem_port$nb_sh[(21 * 32'h20)+:(32)];
        dop$re$21 = mem_port$na_sh[(21 * 32'h20)+:(32)];
        dop$efd$21 = mem_port$nb_sh[(32'h18 * 32'h20 + 21 * 32'h9)+:(9)];
        dop$efe$21 = mem_port$na_sh[(32'h18 * 32'h20 + 21 * 32'h9)+:(9)];
        dop$rd$22 = mem_port$nb_sh[(22 * 32'h20)+:(32)];
        dop$re$22 = mem_port$na_sh[(22 * 32'h20)+:(32)];
        dop$efd$22 = mem_port$nb_sh[(32'h18 * 32'h20 + 22 * 32'h9)+:(9)];
        dop$efe$22 = mem_port$na_sh[(32'h18 * 32'h20 + 22 * 32'h9)+:(9)];
        dop$rd$23 = mem_port$nb_sh[(23 * 32'h20)+:(32)];
        dop$re$23 = mem_port$na_sh[(23 * 32'h20)+:(32)];
        dop$efd$23 = mem_port$nb_sh[(32'h18 * 32'h20 + 23 * 32'h9)+:(9)];
        dop$efe$23 = mem_port$na_sh[(32'h18 * 32'h20 + 23 * 32'h9)+:(9)];
        dop$tag = d_cntr$cur_a;
        dop$valid_in = d_cntr$issue;
        side$d = ((d_cntr$cur_a) & 99'h7ffffffffffffffffffffffff) | (((d_cntr$cur_b) & 99'h7ffffffffffffffffffffffff) << 32'h10) | (((d_cntr$cur_flip) & 99'h7ffffffffffffffffffffffff) << 32'h20) | (((mem_port$na_in[(32'h0)+:(1)]) & 99'h7ffffffffffffffffffffffff) << 32'h21) | (((mem_port$na_in[(32'h1 + 32'h18 * 32'h4)+:(16)]) & 99'h7ffffffffffffffffffffffff) << 32'h22) | (((mem_port$na_in[(32'h21 + 32'h18 * 32'h4)+:(16)]) & 99'h7ffffffffffffffffffffffff) << 32'h32) | (((mem_port$nb_in[(32'h0)+:(1)]) & 99'h7ffffffffffffffffffffffff) << 32'h42) | (((mem_port$nb_in[(32'h1 + 32'h18 * 32'h4)+:(16)]) & 99'h7ffffffffffffffffffffffff) << 32'h43) | (((mem_port$nb_in[(32'h21 + 32'h18 * 32'h4)+:(16)]) & 99'h7ffffffffffffffffffffffff) << 32'h53);
        cnt_dop$inc = d_cntr$issue;
        leaf_fifo$write = d_cntr$leaf_in;
        leaf_fifo$data_in = d_cntr$leaf_pair;
        tri_in = run$q & ~halt & leaf_valid$q & ~need_ta & ~need_tb;
        tri_take = tri_in & tri_unit$in_ready;
        cnt_tri$inc = tri_take;
        leaf_out = ~leaf_fifo$empty & (halt | (run$q & (~leaf_valid$q | tri_take)));
        leaf_fifo$read = leaf_out;
        if (tri_take) begin
            leaf_valid$d = 1'b0;
        end
        if (leaf_out & ~halt) begin
            leaf_valid$d = 1'b1;
            leaf_tag$d = leaf_fifo$data_out;
        end
        if (d_cntr$leaf_in & ~leaf_out) begin
            leaf_count$d = leaf_count$q + 32'h1;
        end
        if (leaf_out & ~d_cntr$leaf_in) begin
            leaf_count$d = leaf_count$q - 32'h1;
        end
        next_tri_ids = leaf_fifo$data_out[(32'h0)+:(32)];
        if (mode_rec$q) begin
            next_tri_ids = leaf_fifo$data_out[(32'h20)+:(32)];
        end
        tri_cache$next_id = tri_ids[(32'h0)+:(16)];
        if (leaf_out & ~halt) begin
            tri_cache$next_id = next_tri_ids[(32'h0)+:(16)];
        end
        tri_unit$a_v_x$0 = tri_cache$word[(32'h3 * 0 * 32'h20)+:(32)];
        tri_unit$a_v_y$0 = tri_cache$word[((32'h3 * 0 + 32'h1) * 32'h20)+:(32)];
        tri_unit$a_v_z$0 = tri_cache$word[((32'h3 * 0 + 32'h2) * 32'h20)+:(32)];
        tri_unit$b_v_x$0 = tb_word$q[(32'h3 * 0 * 32'h20)+:(32)];
        tri_unit$b_v_y$0 = tb_word$q[((32'h3 * 0 + 32'h1) * 32'h20)+:(32)];
        tri_unit$b_v_z$0 = tb_word$q[((32'h3 * 0 + 32'h2) * 32'h20)+:(32)];
        tri_unit$a_v_x$1 = tri_cache$word[(32'h3 * 1 * 32'h20)+:(32)];
        tri_unit$a_v_y$1 = tri_cache$word[((32'h3 * 1 + 32'h1) * 32'h20)+:(32)];
        tri_unit$a_v_z$1 = tri_cache$word[((32'h3 * 1 + 32'h2) * 32'h20)+:(32)];
        tri_unit$b_v_x$1 = tb_word$q[(32'h3 * 1 * 32'h20)+:(32)];
        tri_unit$b_v_y$1 = tb_word$q[((32'h3 * 1 + 32'h1) * 32'h20)+:(32)];
        tri_unit$b_v_z$1 = tb_word$q[((32'h3 * 1 + 32'h2) * 32'h20)+:(32)];
        tri_unit$a_v_x$2 = tri_cache$word[(32'h3 * 2 * 32'h20)+:(32)];
        tri_unit$a_v_y$2 = tri_cache$word[((32'h3 * 2 + 32'h1) * 32'h20)+:(32)];
        tri_unit$a_v_z$2 = tri_cache$word[((32'h3 * 2 + 32'h2) * 32'h20)+:(32)];
        tri_unit$b_v_x$2 = tb_word$q[(32'h3 * 2 * 32'h20)+:(32)];
        tri_unit$b_v_y$2 = tb_word$q[((32'h3 * 2 + 32'h1) * 32'h20)+:(32)];
        tri_unit$b_v_z$2 = tb_word$q[((32'h3 * 2 + 32'h2) * 32'h20)+:(32)];
        tri_unit$a_m_0$0 = tri_cache$word[((32'h9 + 0) * 32'h20)+:(32)];
        tri_unit$a_m_1$0 = tri_cache$word[((32'hd + 0) * 32'h20)+:(32)];
        tri_unit$a_m_2$0 = tri_cache$word[((32'h11 + 0) * 32'h20)+:(32)];
        tri_unit$b_m_0$0 = tb_word$q[((32'h9 + 0) * 32'h20)+:(32)];
        tri_unit$b_m_1$0 = tb_word$q[((32'hd + 0) * 32'h20)+:(32)];
        tri_unit$b_m_2$0 = tb_word$q[((32'h11 + 0) * 32'h20)+:(32)];
        tri_unit$a_m_0$1 = tri_cache$word[((32'h9 + 1) * 32'h20)+:(32)];
        tri_unit$a_m_1$1 = tri_cache$word[((32'hd + 1) * 32'h20)+:(32)];
        tri_unit$a_m_2$1 = tri_cache$word[((32'h11 + 1) * 32'h20)+:(32)];
        tri_unit$b_m_0$1 = tb_word$q[((32'h9 + 1) * 32'h20)+:(32)];
        tri_unit$b_m_1$1 = tb_word$q[((32'hd + 1) * 32'h20)+:(32)];
        tri_unit$b_m_2$1 = tb_word$q[((32'h11 + 1) * 32'h20)+:(32)];
        tri_unit$a_m_0$2 = tri_cache$word[((32'h9 + 2) * 32'h20)+:(32)];
        tri_unit$a_m_1$2 = tri_cache$word[((32'hd + 2) * 32'h20)+:(32)];
        tri_unit$a_m_2$2 = tri_cache$word[((32'h11 + 2) * 32'h20)+:(32)];
        tri_unit$b_m_0$2 = tb_word$q[((32'h9 + 2) * 32'h20)+:(32)];
        tri_unit$b_m_1$2 = tb_word$q[((32'hd + 2) * 32'h20)+:(32)];
        tri_unit$b_m_2$2 = tb_word$q[((32'h11 + 2) * 32'h20)+:(32)];
        tri_unit$a_m_0$3 = tri_cache$word[((32'h9 + 3) * 32'h20)+:(32)];
        tri_unit$a_m_1$3 = tri_cache$word[((32'hd + 3) * 32'h20)+:(32)];
        tri_unit$a_m_2$3 = tri_cache$word[((32'h11 + 3) * 32'h20)+:(32)];
        tri_unit$b_m_0$3 = tb_word$q[((32'h9 + 3) * 32'h20)+:(32)];
        tri_unit$b_m_1$3 = tb_word$q[((32'hd + 3) * 32'h20)+:(32)];
        tri_unit$b_m_2$3 = tb_word$q[((32'h11 + 3) * 32'h20)+:(32)];
        tri_unit$a_alpha_m = tri_cache$word[(32'h15 * 32'h20)+:(32)];
        tri_unit$a_alpha_f = tri_cache$word[(32'h16 * 32'h20)+:(32)];
        tri_unit$a_v_exact = tri_cache$word[32'h17 * 32'h20];
        tri_unit$a_degenerate = tri_cache$word[32'h17 * 32'h20 + 32'h1];
        tri_unit$b_alpha_m = tb_word$q[(32'h15 * 32'h20)+:(32)];
        tri_unit$b_alpha_f = tb_word$q[(32'h16 * 32'h20)+:(32)];
        tri_unit$b_v_exact = tb_word$q[32'h17 * 32'h20];
        tri_unit$b_degenerate = tb_word$q[32'h17 * 32'h20 + 32'h1];
        tri_unit$tag = leaf_tag$q[(32'h0)+:(32)];
        tri_unit$in_valid = tri_in;
        result$take = tri_take;
        result$out_valid = tri_unit$out_valid;
        result$out_hit = tri_unit$out_hit;
        result$out_uncertain = tri_unit$out_uncertain;
        result$out_tag = tri_unit$out_tag;
        result$res_ready = res_ready;
        tri_unit$out_ready = result$out_ready;
        res_valid = result$res_valid;
        res_tag = result$res_tag;
        res_uncertain = result$res_uncertain;
        if (run$q & mode_first$q & result$sure_hit) begin
            stop$d = 1'b1;
        end
        halt_idle = (d_cntr$inflight == 32'h0) & ~d_cntr$pend & ~mem_port$outstanding & (result$open == 32'h0) & ~push_root$q & (leaf_count$q == 32'h0);
        all_idle = halt_idle & d_cntr$empty & ~d_cntr$ent_valid & ~leaf_valid$q;
        if (run$q & (all_idle | (halt & halt_idle))) begin
            run$d = 1'b0;
            done_r$d = 1'b1;
        end
        if (start_q) begin
            run$d = 1'b1;
            done_r$d = 1'b0;
            push_root$d = 1'b1;
            stop$d = 1'b0;
            leaf_valid$d = 1'b0;
            tb_ok$d = 1'b0;
        end
        busy = run$q;
        done = done_r$q;
        overflow = d_cntr$overflow;
        max_depth = d_cntr$max_count;
        cnt_dop$clear = start_q;
        cnt_tri$clear = start_q;
        cnt_nf$clear = start_q;
        cnt_tf$clear = start_q;
        dop_tests = cnt_dop$count;
        tri_tests = cnt_tri$count;
        node_fetches = cnt_nf$count;
        tri_fetches = cnt_tf$count;
    end
    
endmodule // top


module top$base_na(d,q,clock);
    
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
          
endmodule // top$base_na


module top$cnt_dop(clock,clear,inc,count);
    
    // Module arguments
    input wire  clock;
    input wire  clear;
    input wire  inc;
    output reg  [31:0] count;
    
    // Stub signals
    reg  [31:0] total$d;
    wire  [31:0] total$q;
    reg  total$clock;
    reg  pending$d;
    wire  pending$q;
    reg  pending$clock;
    
    // Sub module instances
    top$cnt_dop$total total(
        .d(total$d),
        .q(total$q),
        .clock(total$clock)
    );
    top$cnt_dop$pending pending(
        .d(pending$d),
        .q(pending$q),
        .clock(pending$clock)
    );
    
    // Update code
    always @(*) begin
        total$clock = clock;
        total$d = total$q;
        pending$clock = clock;
        pending$d = inc;
        if (pending$q) begin
            total$d = total$q + 32'h1;
        end
        if (clear) begin
            total$d = 32'h0;
            pending$d = 1'b0;
        end
        count = total$q + ((pending$q) & 32'hffffffff);
    end
    
endmodule // top$cnt_dop


module top$cnt_dop$pending(d,q,clock);
    
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
          
endmodule // top$cnt_dop$pending


module top$cnt_dop$total(d,q,clock);
    
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
          
endmodule // top$cnt_dop$total


module top$d_cntr(clock,clear,lifo,push_root,root,go,pf,one,credit_lim,leaf_count,id_mask,wa_empty,wb_empty,dop_valid,dop_overlap,side,empty,count,max_count,overflow,push,pop,pop_entry,pop_fetch,ent_valid,cur_a,cur_b,cur_flip,cur_fa,cur_fb,need_na,need_nb,issue,r_a,r_b,r_a_leaf,r_b_leaf,leaf_in,leaf_pair,inflight,pend);
    
    // Module arguments
    input wire  clock;
    input wire  clear;
    input wire  lifo;
    input wire  push_root;
    input wire  [31:0] root;
    input wire  go;
    input wire  [4:0] pf;
    input wire  one;
    input wire  [5:0] credit_lim;
    input wire  [5:0] leaf_count;
    input wire  [15:0] id_mask;
    input wire  wa_empty;
    input wire  wb_empty;
    input wire  dop_valid;
    input wire  dop_overlap;
    input wire  [98:0] side;
    output reg  empty;
    output reg  [10:0] count;
    output reg  [10:0] max_count;
    output reg  overflow;
    output reg  push;
    output reg  pop;
    output reg  [66:0] pop_entry;
    output reg  [3:0] pop_fetch;
    output reg  ent_valid;
    output reg  [15:0] cur_a;
    output reg  [15:0] cur_b;
    output reg  cur_flip;
    output reg  cur_fa;
    output reg  cur_fb;
    output reg  need_na;
    output reg  need_nb;
    output reg  issue;
    output reg  [15:0] r_a;
    output reg  [15:0] r_b;
    output reg  r_a_leaf;
    output reg  r_b_leaf;
    output reg  leaf_in;
    output reg  [63:0] leaf_pair;
    output reg  [4:0] inflight;
    output reg  pend;
    
    // Constant declarations
    localparam  c_one16 = 16'h1;
    localparam  c_two = 67'h60000000000000000;
    
    // Stub signals
    reg  queue$clock;
    reg  queue$clear;
    reg  queue$lifo;
    reg  queue$push;
    reg  [66:0] queue$push_data;
    reg  queue$push2;
    reg  [66:0] queue$push2_data;
    reg  queue$pop;
    wire  queue$empty;
    wire  queue$full;
    wire  [10:0] queue$count;
    wire  [10:0] queue$max_count;
    wire  queue$overflow;
    wire  [66:0] queue$top_data;
    reg  ahd_ent$clock;
    reg  [15:0] ahd_ent$wsel;
    reg  [66:0] ahd_ent$wdata;
    reg  [15:0] ahd_ent$rsel;
    wire  [66:0] ahd_ent$rdata;
    reg  ahd_fetch$clock;
    reg  [15:0] ahd_fetch$wsel;
    reg  [3:0] ahd_fetch$wdata;
    reg  [15:0] ahd_fetch$rsel;
    wire  [3:0] ahd_fetch$rdata;
    reg  [3:0] ahd_head$d;
    wire  [3:0] ahd_head$q;
    reg  ahd_head$clock;
    reg  [3:0] ahd_tail$d;
    wire  [3:0] ahd_tail$q;
    reg  ahd_tail$clock;
    reg  [4:0] ahd_pairs$d;
    wire  [4:0] ahd_pairs$q;
    reg  ahd_pairs$clock;
    reg  ent_second$d;
    wire  ent_second$q;
    reg  ent_second$clock;
    reg  last_ok$d;
    wire  last_ok$q;
    reg  last_ok$clock;
    reg  [15:0] last_a$d;
    wire  [15:0] last_a$q;
    reg  last_a$clock;
    reg  [15:0] last_b$d;
    wire  [15:0] last_b$q;
    reg  last_b$clock;
    reg  last_issue$d;
    wire  last_issue$q;
    reg  last_issue$clock;
    reg  [4:0] inflight_r$d;
    wire  [4:0] inflight_r$q;
    reg  inflight_r$clock;
    reg  pend_r$d;
    wire  pend_r$q;
    reg  pend_r$clock;
    reg  [66:0] pend_data$d;
    wire  [66:0] pend_data$q;
    reg  pend_data$clock;
    
    // Local signals
    reg  [66:0] head_ent;
    reg  [3:0] head_fetch;
    reg  ent_last;
    reg  [5:0] credit;
    reg  room;
    reg  child_push;
    reg  [66:0] top;
    reg  top_two;
    reg  fetch_a0;
    reg  fetch_b0;
    reg  fetch_a1;
    reg  fetch_b1;
    reg  r_flip;
    reg  [15:0] r_a0;
    reg  [15:0] r_a1;
    reg  [15:0] r_b0;
    reg  [15:0] r_b1;
    reg  r_hit;
    reg  [15:0] xa;
    reg  [15:0] xb;
    reg  [15:0] ya;
    reg  [15:0] yb;
    reg  [15:0] p0a;
    reg  [15:0] p0b;
    reg  [15:0] p1a;
    reg  [15:0] p1b;
    reg  [66:0] e0;
    reg  [66:0] e1;
    
    // Sub module instances
    top$d_cntr$queue queue(
        .clock(queue$clock),
        .clear(queue$clear),
        .lifo(queue$lifo),
        .push(queue$push),
        .push_data(queue$push_data),
        .push2(queue$push2),
        .push2_data(queue$push2_data),
        .pop(queue$pop),
        .empty(queue$empty),
        .full(queue$full),
        .count(queue$count),
        .max_count(queue$max_count),
        .overflow(queue$overflow),
        .top_data(queue$top_data)
    );
    top$d_cntr$ahd_ent ahd_ent(
        .clock(ahd_ent$clock),
        .wsel(ahd_ent$wsel),
        .wdata(ahd_ent$wdata),
        .rsel(ahd_ent$rsel),
        .rdata(ahd_ent$rdata)
    );
    top$d_cntr$ahd_fetch ahd_fetch(
        .clock(ahd_fetch$clock),
        .wsel(ahd_fetch$wsel),
        .wdata(ahd_fetch$wdata),
        .rsel(ahd_fetch$rsel),
        .rdata(ahd_fetch$rdata)
    );
    top$d_cntr$ahd_fetch$row$0 ahd_head(
        .d(ahd_head$d),
        .q(ahd_head$q),
        .clock(ahd_head$clock)
    );
    top$d_cntr$ahd_fetch$row$0 ahd_tail(
        .d(ahd_tail$d),
        .q(ahd_tail$q),
        .clock(ahd_tail$clock)
    );
    top$d_cntr$ahd_pairs ahd_pairs(
        .d(ahd_pairs$d),
        .q(ahd_pairs$q),
        .clock(ahd_pairs$clock)
    );
    top$cnt_dop$pending ent_second(
        .d(ent_second$d),
        .q(ent_second$q),
        .clock(ent_second$clock)
    );
    top$cnt_dop$pending last_ok(
        .d(last_ok$d),
        .q(last_ok$q),
        .clock(last_ok$clock)
    );
    top$d_cntr$last_a last_a(
        .d(last_a$d),
        .q(last_a$q),
        .clock(last_a$clock)
    );
    top$d_cntr$last_a last_b(
        .d(last_b$d),
        .q(last_b$q),
        .clock(last_b$clock)
    );
    top$cnt_dop$pending last_issue(
        .d(last_issue$d),
        .q(last_issue$q),
        .clock(last_issue$clock)
    );
    top$d_cntr$ahd_pairs inflight_r(
        .d(inflight_r$d),
        .q(inflight_r$q),
        .clock(inflight_r$clock)
    );
    top$cnt_dop$pending pend_r(
        .d(pend_r$d),
        .q(pend_r$q),
        .clock(pend_r$clock)
    );
    top$d_cntr$ahd_ent$row$0 pend_data(
        .d(pend_data$d),
        .q(pend_data$q),
        .clock(pend_data$clock)
    );
    
    // Update code
    always @(*) begin
        ahd_head$clock = clock;
        ahd_tail$clock = clock;
        ahd_pairs$clock = clock;
        ent_second$clock = clock;
        last_ok$clock = clock;
        last_a$clock = clock;
        last_b$clock = clock;
        ahd_head$d = ahd_head$q;
        ahd_tail$d = ahd_tail$q;
        ahd_pairs$d = ahd_pairs$q;
        ent_second$d = ent_second$q;
        last_ok$d = last_ok$q;
        last_a$d = last_a$q;
        last_b$d = last_b$q;
        last_issue$clock = clock;
        inflight_r$clock = clock;
        pend_r$clock = clock;
        pend_data$clock = clock;
        last_issue$d = last_issue$q;
        inflight_r$d = inflight_r$q;
        pend_r$d = pend_r$q;
        pend_data$d = pend_data$q;
        queue$clock = clock;
        ahd_ent$clock = clock;
        ahd_fetch$clock = clock;
        ahd_ent$rsel = c_one16 << ahd_head$q;
        ahd_fetch$rsel = c_one16 << ahd_head$q;
        head_ent = ahd_ent$rdata;
        head_fetch = ahd_fetch$rdata;
        ent_valid = ahd_pairs$q != 32'h0;
        cur_a = head_ent[(32'h0)+:(16)];
        cur_b = head_ent[(32'h10)+:(16)];
        cur_flip = head_ent[(32'h20)+:(1)];
        cur_fa = head_fetch[32'h0];
        cur_fb = head_fetch[32'h1];
        if (ent_second$q) begin
            cur_a = head_ent[(32'h21)+:(16)];
            cur_b = head_ent[(32'h31)+:(16)];
            cur_flip = head_ent[(32'h41)+:(1)];
            cur_fa = head_fetch[32'h2];
            cur_fb = head_fetch[32'h3];
        end
        ent_last = ent_second$q | ~head_ent[32'h42];
        need_na = go & (ahd_pairs$q != 32'h0) & cur_fa & wa_empty;
        need_nb = go & (ahd_pairs$q != 32'h0) & cur_fb & wb_empty;
        credit = ((inflight_r$q) & 6'h3f) + leaf_count;
        issue = go & (ahd_pairs$q != 32'h0) & ~need_na & ~need_nb & ~(last_issue$q & ~one) & (credit < credit_lim);
        last_issue$d = issue;
        if (issue) begin
            ent_second$d = 1'b1;
            if (ent_last) begin
                ent_second$d = 1'b0;
                ahd_head$d = ahd_head$q + 32'h1;
            end
        end
        r_a = side[(32'h0)+:(16)];
        r_b = side[(32'h10)+:(16)];
        r_flip = side[32'h20];
        r_a_leaf = side[32'h21];
        r_a0 = side[(32'h22)+:(16)];
        r_a1 = side[(32'h32)+:(16)];
        r_b_leaf = side[32'h42];
        r_b0 = side[(32'h43)+:(16)];
        r_b1 = side[(32'h53)+:(16)];
        r_hit = dop_valid & dop_overlap;
        child_push = pend_r$q | (r_hit & ~(r_a_leaf & r_b_leaf));
        room = ahd_pairs$q <= pf;
        pop = go & ~queue$empty & room & ~(lifo & child_push);
        queue$pop = pop;
        top = queue$top_data;
        top_two = top[32'h42];
        fetch_a0 = ~(last_ok$q & ((last_a$q & id_mask) == (top[(32'h0)+:(16)] & id_mask)));
        fetch_b0 = ~(last_ok$q & ((last_b$q & id_mask) == (top[(32'h10)+:(16)] & id_mask)));
        fetch_a1 = top_two & ((top[(32'h21)+:(16)] & id_mask) != (top[(32'h0)+:(16)] & id_mask));
        fetch_b1 = top_two & ((top[(32'h31)+:(16)] & id_mask) != (top[(32'h10)+:(16)] & id_mask));
        pop_fetch = ((fetch_a0) & 4'hf) | (((fetch_b0) & 4'hf) << 32'h1) | (((fetch_a1) & 4'hf) << 32'h2) | (((fetch_b1) & 4'hf) << 32'h3);
        pop_entry = top;
        ahd_ent$wsel = 32'h0;
        ahd_fetch$wsel = 32'h0;
        if (pop) begin
            ahd_ent$wsel = c_one16 << ahd_tail$q;
            ahd_fetch$wsel = c_one16 << ahd_tail$q;
        end
        ahd_ent$wdata = top;
        ahd_fetch$wdata = pop_fetch;
        ahd_pairs$d = ahd_pairs$q - ((issue) & 5'h1f);
        if (pop) begin
            ahd_tail$d = ahd_tail$q + 32'h1;
            ahd_pairs$d = ahd_pairs$q - ((issue) & 5'h1f) + 32'h1 + ((top_two) & 5'h1f);
            last_ok$d = 1'b1;
            last_a$d = top[(32'h0)+:(16)];
            last_b$d = top[(32'h10)+:(16)];
            if (top_two) begin
                last_a$d = top[(32'h21)+:(16)];
                last_b$d = top[(32'h31)+:(16)];
            end
        end
        xa = r_a0;
        xb = r_a1;
        ya = r_b0;
        yb = r_b1;
        if (r_flip) begin
            xa = r_a1;
            xb = r_a0;
            ya = r_b1;
            yb = r_b0;
        end
        p0a = xa;
        p0b = r_b0;
        p1a = xa;
        p1b = r_b1;
        if (r_b_leaf) begin
            p0b = r_b;
            p1a = xb;
            p1b = r_b;
        end
        if (r_a_leaf) begin
            p0a = r_a;
            p0b = ya;
            p1a = r_a;
            p1b = yb;
        end
        e0 = c_two | ((p0a) & 67'h7ffffffffffffffff) | (((p0b) & 67'h7ffffffffffffffff) << 32'h10) | (((p1a) & 67'h7ffffffffffffffff) << 32'h21) | (((p1b) & 67'h7ffffffffffffffff) << 32'h31);
        e1 = c_two | ((xb) & 67'h7ffffffffffffffff) | (((r_b1) & 67'h7ffffffffffffffff) << 32'h10) | (((xb) & 67'h7ffffffffffffffff) << 32'h21) | (((r_b0) & 67'h7ffffffffffffffff) << 32'h31);
        queue$clear = clear;
        queue$lifo = lifo;
        queue$push = 1'b0;
        queue$push_data = e0;
        queue$push2 = 1'b0;
        queue$push2_data = e1;
        pend_r$d = 1'b0;
        if (pend_r$q) begin
            queue$push = 1'b1;
            queue$push_data = pend_data$q;
        end
        leaf_in = r_hit & r_a_leaf & r_b_leaf;
        leaf_pair = ((r_a0) & 64'hffffffffffffffff) | (((r_b0) & 64'hffffffffffffffff) << 32'h10) | (((r_a1) & 64'hffffffffffffffff) << 32'h20) | (((r_b1) & 64'hffffffffffffffff) << 32'h30);
        if (r_hit & ~(r_a_leaf & r_b_leaf)) begin
            queue$push = 1'b1;
            if (r_a_leaf | r_b_leaf) begin
                queue$push_data = e0;
            end
            else begin
                queue$push2 = one;
                pend_r$d = ~one;
                if (lifo) begin
                    queue$push_data = e1;
                    queue$push2_data = e0;
                    pend_data$d = e0;
                end
                else begin
                    queue$push_data = e0;
                    pend_data$d = e1;
                end
            end
        end
        if (push_root) begin
            queue$push = 1'b1;
            queue$push_data = ((root) & 67'h7ffffffffffffffff);
        end
        inflight_r$d = inflight_r$q;
        if (issue & ~dop_valid) begin
            inflight_r$d = inflight_r$q + 32'h1;
        end
        if (dop_valid & ~issue) begin
            inflight_r$d = inflight_r$q - 32'h1;
        end
        if (clear) begin
            ahd_head$d = 32'h0;
            ahd_tail$d = 32'h0;
            ahd_pairs$d = 32'h0;
            ent_second$d = 1'b0;
            last_ok$d = 1'b0;
        end
        push = queue$push;
        empty = queue$empty;
        count = queue$count;
        max_count = queue$max_count;
        overflow = queue$overflow;
        inflight = inflight_r$q;
        pend = pend_r$q;
    end
    
endmodule // top$d_cntr


module top$d_cntr$ahd_ent(clock,wsel,wdata,rsel,rdata);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] wsel;
    input wire  [66:0] wdata;
    input wire  [15:0] rsel;
    output reg  [66:0] rdata;
    
    // Stub signals
    reg  [66:0] row$0$d;
    wire  [66:0] row$0$q;
    reg  row$0$clock;
    reg  [66:0] row$1$d;
    wire  [66:0] row$1$q;
    reg  row$1$clock;
    reg  [66:0] row$2$d;
    wire  [66:0] row$2$q;
    reg  row$2$clock;
    reg  [66:0] row$3$d;
    wire  [66:0] row$3$q;
    reg  row$3$clock;
    reg  [66:0] row$4$d;
    wire  [66:0] row$4$q;
    reg  row$4$clock;
    reg  [66:0] row$5$d;
    wire  [66:0] row$5$q;
    reg  row$5$clock;
    reg  [66:0] row$6$d;
    wire  [66:0] row$6$q;
    reg  row$6$clock;
    reg  [66:0] row$7$d;
    wire  [66:0] row$7$q;
    reg  row$7$clock;
    reg  [66:0] row$8$d;
    wire  [66:0] row$8$q;
    reg  row$8$clock;
    reg  [66:0] row$9$d;
    wire  [66:0] row$9$q;
    reg  row$9$clock;
    reg  [66:0] row$10$d;
    wire  [66:0] row$10$q;
    reg  row$10$clock;
    reg  [66:0] row$11$d;
    wire  [66:0] row$11$q;
    reg  row$11$clock;
    reg  [66:0] row$12$d;
    wire  [66:0] row$12$q;
    reg  row$12$clock;
    reg  [66:0] row$13$d;
    wire  [66:0] row$13$q;
    reg  row$13$clock;
    reg  [66:0] row$14$d;
    wire  [66:0] row$14$q;
    reg  row$14$clock;
    reg  [66:0] row$15$d;
    wire  [66:0] row$15$q;
    reg  row$15$clock;
    
    // Local signals
    reg  [66:0] picked;
    
    // Sub module instances
    top$d_cntr$ahd_ent$row$0 row$0(
        .d(row$0$d),
        .q(row$0$q),
        .clock(row$0$clock)
    );
    top$d_cntr$ahd_ent$row$0 row$1(
        .d(row$1$d),
        .q(row$1$q),
        .clock(row$1$clock)
    );
    top$d_cntr$ahd_ent$row$0 row$2(
        .d(row$2$d),
        .q(row$2$q),
        .clock(row$2$clock)
    );
    top$d_cntr$ahd_ent$row$0 row$3(
        .d(row$3$d),
        .q(row$3$q),
        .clock(row$3$clock)
    );
    top$d_cntr$ahd_ent$row$0 row$4(
        .d(row$4$d),
        .q(row$4$q),
        .clock(row$4$clock)
    );
    top$d_cntr$ahd_ent$row$0 row$5(
        .d(row$5$d),
        .q(row$5$q),
        .clock(row$5$clock)
    );
    top$d_cntr$ahd_ent$row$0 row$6(
        .d(row$6$d),
        .q(row$6$q),
        .clock(row$6$clock)
    );
    top$d_cntr$ahd_ent$row$0 row$7(
        .d(row$7$d),
        .q(row$7$q),
        .clock(row$7$clock)
    );
    top$d_cntr$ahd_ent$row$0 row$8(
        .d(row$8$d),
        .q(row$8$q),
        .clock(row$8$clock)
    );
    top$d_cntr$ahd_ent$row$0 row$9(
        .d(row$9$d),
        .q(row$9$q),
        .clock(row$9$clock)
    );
    top$d_cntr$ahd_ent$row$0 row$10(
        .d(row$10$d),
        .q(row$10$q),
        .clock(row$10$clock)
    );
    top$d_cntr$ahd_ent$row$0 row$11(
        .d(row$11$d),
        .q(row$11$q),
        .clock(row$11$clock)
    );
    top$d_cntr$ahd_ent$row$0 row$12(
        .d(row$12$d),
        .q(row$12$q),
        .clock(row$12$clock)
    );
    top$d_cntr$ahd_ent$row$0 row$13(
        .d(row$13$d),
        .q(row$13$q),
        .clock(row$13$clock)
    );
    top$d_cntr$ahd_ent$row$0 row$14(
        .d(row$14$d),
        .q(row$14$q),
        .clock(row$14$clock)
    );
    top$d_cntr$ahd_ent$row$0 row$15(
        .d(row$15$d),
        .q(row$15$q),
        .clock(row$15$clock)
    );
    
    // Update code
    always @(*) begin
        picked = 32'h0;
        row$0$clock = clock;
        row$0$d = row$0$q;
        if (wsel[0]) begin
            row$0$d = wdata;
        end
        if (rsel[0]) begin
            picked = row$0$q;
        end
        row$1$clock = clock;
        row$1$d = row$1$q;
        if (wsel[1]) begin
            row$1$d = wdata;
        end
        if (rsel[1]) begin
            picked = row$1$q;
        end
        row$2$clock = clock;
        row$2$d = row$2$q;
        if (wsel[2]) begin
            row$2$d = wdata;
        end
        if (rsel[2]) begin
            picked = row$2$q;
        end
        row$3$clock = clock;
        row$3$d = row$3$q;
        if (wsel[3]) begin
            row$3$d = wdata;
        end
        if (rsel[3]) begin
            picked = row$3$q;
        end
        row$4$clock = clock;
        row$4$d = row$4$q;
        if (wsel[4]) begin
            row$4$d = wdata;
        end
        if (rsel[4]) begin
            picked = row$4$q;
        end
        row$5$clock = clock;
        row$5$d = row$5$q;
        if (wsel[5]) begin
            row$5$d = wdata;
        end
        if (rsel[5]) begin
            picked = row$5$q;
        end
        row$6$clock = clock;
        row$6$d = row$6$q;
        if (wsel[6]) begin
            row$6$d = wdata;
        end
        if (rsel[6]) begin
            picked = row$6$q;
        end
        row$7$clock = clock;
        row$7$d = row$7$q;
        if (wsel[7]) begin
            row$7$d = wdata;
        end
        if (rsel[7]) begin
            picked = row$7$q;
        end
        row$8$clock = clock;
        row$8$d = row$8$q;
        if (wsel[8]) begin
            row$8$d = wdata;
        end
        if (rsel[8]) begin
            picked = row$8$q;
        end
        row$9$clock = clock;
        row$9$d = row$9$q;
        if (wsel[9]) begin
            row$9$d = wdata;
        end
        if (rsel[9]) begin
            picked = row$9$q;
        end
        row$10$clock = clock;
        row$10$d = row$10$q;
        if (wsel[10]) begin
            row$10$d = wdata;
        end
        if (rsel[10]) begin
            picked = row$10$q;
        end
        row$11$clock = clock;
        row$11$d = row$11$q;
        if (wsel[11]) begin
            row$11$d = wdata;
        end
        if (rsel[11]) begin
            picked = row$11$q;
        end
        row$12$clock = clock;
        row$12$d = row$12$q;
        if (wsel[12]) begin
            row$12$d = wdata;
        end
        if (rsel[12]) begin
            picked = row$12$q;
        end
        row$13$clock = clock;
        row$13$d = row$13$q;
        if (wsel[13]) begin
            row$13$d = wdata;
        end
        if (rsel[13]) begin
            picked = row$13$q;
        end
        row$14$clock = clock;
        row$14$d = row$14$q;
        if (wsel[14]) begin
            row$14$d = wdata;
        end
        if (rsel[14]) begin
            picked = row$14$q;
        end
        row$15$clock = clock;
        row$15$d = row$15$q;
        if (wsel[15]) begin
            row$15$d = wdata;
        end
        if (rsel[15]) begin
            picked = row$15$q;
        end
        rdata = picked;
    end
    
endmodule // top$d_cntr$ahd_ent


module top$d_cntr$ahd_ent$row$0(d,q,clock);
    
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
          
endmodule // top$d_cntr$ahd_ent$row$0


module top$d_cntr$ahd_fetch(clock,wsel,wdata,rsel,rdata);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] wsel;
    input wire  [3:0] wdata;
    input wire  [15:0] rsel;
    output reg  [3:0] rdata;
    
    // Stub signals
    reg  [3:0] row$0$d;
    wire  [3:0] row$0$q;
    reg  row$0$clock;
    reg  [3:0] row$1$d;
    wire  [3:0] row$1$q;
    reg  row$1$clock;
    reg  [3:0] row$2$d;
    wire  [3:0] row$2$q;
    reg  row$2$clock;
    reg  [3:0] row$3$d;
    wire  [3:0] row$3$q;
    reg  row$3$clock;
    reg  [3:0] row$4$d;
    wire  [3:0] row$4$q;
    reg  row$4$clock;
    reg  [3:0] row$5$d;
    wire  [3:0] row$5$q;
    reg  row$5$clock;
    reg  [3:0] row$6$d;
    wire  [3:0] row$6$q;
    reg  row$6$clock;
    reg  [3:0] row$7$d;
    wire  [3:0] row$7$q;
    reg  row$7$clock;
    reg  [3:0] row$8$d;
    wire  [3:0] row$8$q;
    reg  row$8$clock;
    reg  [3:0] row$9$d;
    wire  [3:0] row$9$q;
    reg  row$9$clock;
    reg  [3:0] row$10$d;
    wire  [3:0] row$10$q;
    reg  row$10$clock;
    reg  [3:0] row$11$d;
    wire  [3:0] row$11$q;
    reg  row$11$clock;
    reg  [3:0] row$12$d;
    wire  [3:0] row$12$q;
    reg  row$12$clock;
    reg  [3:0] row$13$d;
    wire  [3:0] row$13$q;
    reg  row$13$clock;
    reg  [3:0] row$14$d;
    wire  [3:0] row$14$q;
    reg  row$14$clock;
    reg  [3:0] row$15$d;
    wire  [3:0] row$15$q;
    reg  row$15$clock;
    
    // Local signals
    reg  [3:0] picked;
    
    // Sub module instances
    top$d_cntr$ahd_fetch$row$0 row$0(
        .d(row$0$d),
        .q(row$0$q),
        .clock(row$0$clock)
    );
    top$d_cntr$ahd_fetch$row$0 row$1(
        .d(row$1$d),
        .q(row$1$q),
        .clock(row$1$clock)
    );
    top$d_cntr$ahd_fetch$row$0 row$2(
        .d(row$2$d),
        .q(row$2$q),
        .clock(row$2$clock)
    );
    top$d_cntr$ahd_fetch$row$0 row$3(
        .d(row$3$d),
        .q(row$3$q),
        .clock(row$3$clock)
    );
    top$d_cntr$ahd_fetch$row$0 row$4(
        .d(row$4$d),
        .q(row$4$q),
        .clock(row$4$clock)
    );
    top$d_cntr$ahd_fetch$row$0 row$5(
        .d(row$5$d),
        .q(row$5$q),
        .clock(row$5$clock)
    );
    top$d_cntr$ahd_fetch$row$0 row$6(
        .d(row$6$d),
        .q(row$6$q),
        .clock(row$6$clock)
    );
    top$d_cntr$ahd_fetch$row$0 row$7(
        .d(row$7$d),
        .q(row$7$q),
        .clock(row$7$clock)
    );
    top$d_cntr$ahd_fetch$row$0 row$8(
        .d(row$8$d),
        .q(row$8$q),
        .clock(row$8$clock)
    );
    top$d_cntr$ahd_fetch$row$0 row$9(
        .d(row$9$d),
        .q(row$9$q),
        .clock(row$9$clock)
    );
    top$d_cntr$ahd_fetch$row$0 row$10(
        .d(row$10$d),
        .q(row$10$q),
        .clock(row$10$clock)
    );
    top$d_cntr$ahd_fetch$row$0 row$11(
        .d(row$11$d),
        .q(row$11$q),
        .clock(row$11$clock)
    );
    top$d_cntr$ahd_fetch$row$0 row$12(
        .d(row$12$d),
        .q(row$12$q),
        .clock(row$12$clock)
    );
    top$d_cntr$ahd_fetch$row$0 row$13(
        .d(row$13$d),
        .q(row$13$q),
        .clock(row$13$clock)
    );
    top$d_cntr$ahd_fetch$row$0 row$14(
        .d(row$14$d),
        .q(row$14$q),
        .clock(row$14$clock)
    );
    top$d_cntr$ahd_fetch$row$0 row$15(
        .d(row$15$d),
        .q(row$15$q),
        .clock(row$15$clock)
    );
    
    // Update code
    always @(*) begin
        picked = 32'h0;
        row$0$clock = clock;
        row$0$d = row$0$q;
        if (wsel[0]) begin
            row$0$d = wdata;
        end
        if (rsel[0]) begin
            picked = row$0$q;
        end
        row$1$clock = clock;
        row$1$d = row$1$q;
        if (wsel[1]) begin
            row$1$d = wdata;
        end
        if (rsel[1]) begin
            picked = row$1$q;
        end
        row$2$clock = clock;
        row$2$d = row$2$q;
        if (wsel[2]) begin
            row$2$d = wdata;
        end
        if (rsel[2]) begin
            picked = row$2$q;
        end
        row$3$clock = clock;
        row$3$d = row$3$q;
        if (wsel[3]) begin
            row$3$d = wdata;
        end
        if (rsel[3]) begin
            picked = row$3$q;
        end
        row$4$clock = clock;
        row$4$d = row$4$q;
        if (wsel[4]) begin
            row$4$d = wdata;
        end
        if (rsel[4]) begin
            picked = row$4$q;
        end
        row$5$clock = clock;
        row$5$d = row$5$q;
        if (wsel[5]) begin
            row$5$d = wdata;
        end
        if (rsel[5]) begin
            picked = row$5$q;
        end
        row$6$clock = clock;
        row$6$d = row$6$q;
        if (wsel[6]) begin
            row$6$d = wdata;
        end
        if (rsel[6]) begin
            picked = row$6$q;
        end
        row$7$clock = clock;
        row$7$d = row$7$q;
        if (wsel[7]) begin
            row$7$d = wdata;
        end
        if (rsel[7]) begin
            picked = row$7$q;
        end
        row$8$clock = clock;
        row$8$d = row$8$q;
        if (wsel[8]) begin
            row$8$d = wdata;
        end
        if (rsel[8]) begin
            picked = row$8$q;
        end
        row$9$clock = clock;
        row$9$d = row$9$q;
        if (wsel[9]) begin
            row$9$d = wdata;
        end
        if (rsel[9]) begin
            picked = row$9$q;
        end
        row$10$clock = clock;
        row$10$d = row$10$q;
        if (wsel[10]) begin
            row$10$d = wdata;
        end
        if (rsel[10]) begin
            picked = row$10$q;
        end
        row$11$clock = clock;
        row$11$d = row$11$q;
        if (wsel[11]) begin
            row$11$d = wdata;
        end
        if (rsel[11]) begin
            picked = row$11$q;
        end
        row$12$clock = clock;
        row$12$d = row$12$q;
        if (wsel[12]) begin
            row$12$d = wdata;
        end
        if (rsel[12]) begin
            picked = row$12$q;
        end
        row$13$clock = clock;
        row$13$d = row$13$q;
        if (wsel[13]) begin
            row$13$d = wdata;
        end
        if (rsel[13]) begin
            picked = row$13$q;
        end
        row$14$clock = clock;
        row$14$d = row$14$q;
        if (wsel[14]) begin
            row$14$d = wdata;
        end
        if (rsel[14]) begin
            picked = row$14$q;
        end
        row$15$clock = clock;
        row$15$d = row$15$q;
        if (wsel[15]) begin
            row$15$d = wdata;
        end
        if (rsel[15]) begin
            picked = row$15$q;
        end
        rdata = picked;
    end
    
endmodule // top$d_cntr$ahd_fetch


module top$d_cntr$ahd_fetch$row$0(d,q,clock);
    
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
          
endmodule // top$d_cntr$ahd_fetch$row$0


module top$d_cntr$ahd_pairs(d,q,clock);
    
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
          
endmodule // top$d_cntr$ahd_pairs


module top$d_cntr$last_a(d,q,clock);
    
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
          
endmodule // top$d_cntr$last_a


module top$d_cntr$queue(clock,clear,lifo,push,push_data,push2,push2_data,pop,empty,full,count,max_count,overflow,top_data);
    
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
    output reg  [10:0] count;
    output reg  [10:0] max_count;
    output reg  overflow;
    output reg  [66:0] top_data;
    
    // Constant declarations
    localparam  c_cap = 11'b10000000000;
    localparam  c_last = 10'b1111111111;
    localparam  c_one = 10'b1;
    localparam  c_m2 = 10'b1111111110;
    
    // Stub signals
    reg  [10:0] cnt$d;
    wire  [10:0] cnt$q;
    reg  cnt$clock;
    reg  [66:0] top_r$d;
    wire  [66:0] top_r$q;
    reg  top_r$clock;
    reg  [9:0] rd_ptr$d;
    wire  [9:0] rd_ptr$q;
    reg  rd_ptr$clock;
    reg  [9:0] wr_ptr$d;
    wire  [9:0] wr_ptr$q;
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
    reg  [10:0] max_r$d;
    wire  [10:0] max_r$q;
    reg  max_r$clock;
    reg  ovf_r$d;
    wire  ovf_r$q;
    reg  ovf_r$clock;
    reg  [8:0] bank0$read_address;
    reg  bank0$read_clock;
    wire  [66:0] bank0$read_data;
    reg  [8:0] bank0$write_address;
    reg  bank0$write_clock;
    reg  [66:0] bank0$write_data;
    reg  bank0$write_enable;
    reg  [8:0] bank1$read_address;
    reg  bank1$read_clock;
    wire  [66:0] bank1$read_data;
    reg  [8:0] bank1$write_address;
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
    reg  [9:0] rd1_x$d;
    wire  [9:0] rd1_x$q;
    reg  rd1_x$clock;
    reg  [9:0] wr1_x$d;
    wire  [9:0] wr1_x$q;
    reg  wr1_x$clock;
    reg  [9:0] wr_m1_n$d;
    wire  [9:0] wr_m1_n$q;
    reg  wr_m1_n$clock;
    reg  [9:0] wr_m2_x$d;
    wire  [9:0] wr_m2_x$q;
    reg  wr_m2_x$clock;
    
    // Local signals
    reg  many;
    reg  do_pop;
    reg  nfull;
    reg  spare;
    reg  c0_zero;
    reg  [10:0] cnt_m1;
    reg  [10:0] cnt_p1;
    reg  [10:0] cnt_p2;
    reg  [66:0] e1;
    reg  any;
    reg  two;
    reg  s1;
    reg  s2;
    reg  [66:0] next_entry;
    reg  [10:0] cnt_n;
    reg  [9:0] rd_n;
    reg  [9:0] wr_n;
    reg  [9:0] wr1;
    reg  [9:0] wr_m1;
    reg  [9:0] wr_m2;
    reg  [9:0] rd1;
    reg  pick;
    reg  hit_a;
    reg  hit_b;
    reg  [9:0] raddr;
    reg  we_a;
    reg  we_b;
    reg  [66:0] wdata_a;
    reg  [66:0] wdata_b;
    
    // Sub module instances
    top$d_cntr$queue$cnt cnt(
        .d(cnt$d),
        .q(cnt$q),
        .clock(cnt$clock)
    );
    top$d_cntr$ahd_ent$row$0 top_r(
        .d(top_r$d),
        .q(top_r$q),
        .clock(top_r$clock)
    );
    top$d_cntr$queue$rd1_x rd_ptr(
        .d(rd_ptr$d),
        .q(rd_ptr$q),
        .clock(rd_ptr$clock)
    );
    top$d_cntr$queue$rd1_x wr_ptr(
        .d(wr_ptr$d),
        .q(wr_ptr$q),
        .clock(wr_ptr$clock)
    );
    top$cnt_dop$pending byp(
        .d(byp$d),
        .q(byp$q),
        .clock(byp$clock)
    );
    top$d_cntr$ahd_ent$row$0 byp_data(
        .d(byp_data$d),
        .q(byp_data$q),
        .clock(byp_data$clock)
    );
    top$cnt_dop$pending rsel(
        .d(rsel$d),
        .q(rsel$q),
        .clock(rsel$clock)
    );
    top$cnt_dop$pending order_lifo(
        .d(order_lifo$d),
        .q(order_lifo$q),
        .clock(order_lifo$clock)
    );
    top$d_cntr$queue$cnt max_r(
        .d(max_r$d),
        .q(max_r$q),
        .clock(max_r$clock)
    );
    top$cnt_dop$pending ovf_r(
        .d(ovf_r$d),
        .q(ovf_r$q),
        .clock(ovf_r$clock)
    );
    top$d_cntr$queue$bank0 bank0(
        .read_address(bank0$read_address),
        .read_clock(bank0$read_clock),
        .read_data(bank0$read_data),
        .write_address(bank0$write_address),
        .write_clock(bank0$write_clock),
        .write_data(bank0$write_data),
        .write_enable(bank0$write_enable)
    );
    top$d_cntr$queue$bank0 bank1(
        .read_address(bank1$read_address),
        .read_clock(bank1$read_clock),
        .read_data(bank1$read_data),
        .write_address(bank1$write_address),
        .write_clock(bank1$write_clock),
        .write_data(bank1$write_data),
        .write_enable(bank1$write_enable)
    );
    top$cnt_dop$pending nonempty(
        .d(nonempty$d),
        .q(nonempty$q),
        .clock(nonempty$clock)
    );
    top$cnt_dop$pending many_r(
        .d(many_r$d),
        .q(many_r$q),
        .clock(many_r$clock)
    );
    top$cnt_dop$pending full_r(
        .d(full_r$d),
        .q(full_r$q),
        .clock(full_r$clock)
    );
    top$cnt_dop$pending tight_r(
        .d(tight_r$d),
        .q(tight_r$q),
        .clock(tight_r$clock)
    );
    top$d_cntr$queue$rd1_x rd1_x(
        .d(rd1_x$d),
        .q(rd1_x$q),
        .clock(rd1_x$clock)
    );
    top$d_cntr$queue$rd1_x wr1_x(
        .d(wr1_x$d),
        .q(wr1_x$q),
        .clock(wr1_x$clock)
    );
    top$d_cntr$queue$rd1_x wr_m1_n(
        .d(wr_m1_n$d),
        .q(wr_m1_n$q),
        .clock(wr_m1_n$clock)
    );
    top$d_cntr$queue$rd1_x wr_m2_x(
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
        bank0$write_address = wr_ptr$q[(32'h1)+:(9)];
        bank0$write_data = wdata_a;
        bank1$write_address = wr_ptr$q[(32'h1)+:(9)];
        bank1$write_data = wdata_a;
        if (wr_ptr$q[32'h0]) begin
            bank0$write_address = wr1[(32'h1)+:(9)];
            bank0$write_data = wdata_b;
        end
        else begin
            bank1$write_address = wr1[(32'h1)+:(9)];
            bank1$write_data = wdata_b;
        end
        bank0$read_address = raddr[(32'h1)+:(9)];
        bank1$read_address = raddr[(32'h1)+:(9)];
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
    
endmodule // top$d_cntr$queue


module top$d_cntr$queue$bank0(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [8:0] read_address;
    input wire  read_clock;
    output reg  [66:0] read_data;
    input wire  [8:0] write_address;
    input wire  write_clock;
    input wire  [66:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    reg[66:0] mem[511:0];
    
    
    
    always @(posedge read_clock) begin
       read_data <= mem[read_address];
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address] <= write_data;
       end
    end
                
endmodule // top$d_cntr$queue$bank0


module top$d_cntr$queue$cnt(d,q,clock);
    
    // Module arguments
    input wire  [10:0] d;
    output reg  [10:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 11'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$d_cntr$queue$cnt


module top$d_cntr$queue$rd1_x(d,q,clock);
    
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
          
endmodule // top$d_cntr$queue$rd1_x


module top$dop(clock,load_en,load_addr,load_data,d$0,d$1,d$2,d$3,d$4,d$5,d$6,d$7,d$8,d$9,d$10,d$11,d$12,d$13,d$14,d$15,d$16,d$17,d$18,d$19,d$20,d$21,d$22,d$23,e$0,e$1,e$2,e$3,e$4,e$5,e$6,e$7,e$8,e$9,e$10,e$11,e$12,e$13,e$14,e$15,e$16,e$17,e$18,e$19,e$20,e$21,e$22,e$23,rd$0,rd$1,rd$2,rd$3,rd$4,rd$5,rd$6,rd$7,rd$8,rd$9,rd$10,rd$11,rd$12,rd$13,rd$14,rd$15,rd$16,rd$17,rd$18,rd$19,rd$20,rd$21,rd$22,rd$23,re$0,re$1,re$2,re$3,re$4,re$5,re$6,re$7,re$8,re$9,re$10,re$11,re$12,re$13,re$14,re$15,re$16,re$17,re$18,re$19,re$20,re$21,re$22,re$23,efd$0,efd$1,efd$2,efd$3,efd$4,efd$5,efd$6,efd$7,efd$8,efd$9,efd$10,efd$11,efd$12,efd$13,efd$14,efd$15,efd$16,efd$17,efd$18,efd$19,efd$20,efd$21,efd$22,efd$23,efe$0,efe$1,efe$2,efe$3,efe$4,efe$5,efe$6,efe$7,efe$8,efe$9,efe$10,efe$11,efe$12,efe$13,efe$14,efe$15,efe$16,efe$17,efe$18,efe$19,efe$20,efe$21,efe$22,efe$23,tag,valid_in,overlap,tag_out,valid_out);
    
    // Module arguments
    input wire  clock;
    input wire  load_en;
    input wire  [7:0] load_addr;
    input wire  [31:0] load_data;
    input wire  [3:0] d$0;
    input wire  [3:0] d$1;
    input wire  [3:0] d$2;
    input wire  [3:0] d$3;
    input wire  [3:0] d$4;
    input wire  [3:0] d$5;
    input wire  [3:0] d$6;
    input wire  [3:0] d$7;
    input wire  [3:0] d$8;
    input wire  [3:0] d$9;
    input wire  [3:0] d$10;
    input wire  [3:0] d$11;
    input wire  [3:0] d$12;
    input wire  [3:0] d$13;
    input wire  [3:0] d$14;
    input wire  [3:0] d$15;
    input wire  [3:0] d$16;
    input wire  [3:0] d$17;
    input wire  [3:0] d$18;
    input wire  [3:0] d$19;
    input wire  [3:0] d$20;
    input wire  [3:0] d$21;
    input wire  [3:0] d$22;
    input wire  [3:0] d$23;
    input wire  [3:0] e$0;
    input wire  [3:0] e$1;
    input wire  [3:0] e$2;
    input wire  [3:0] e$3;
    input wire  [3:0] e$4;
    input wire  [3:0] e$5;
    input wire  [3:0] e$6;
    input wire  [3:0] e$7;
    input wire  [3:0] e$8;
    input wire  [3:0] e$9;
    input wire  [3:0] e$10;
    input wire  [3:0] e$11;
    input wire  [3:0] e$12;
    input wire  [3:0] e$13;
    input wire  [3:0] e$14;
    input wire  [3:0] e$15;
    input wire  [3:0] e$16;
    input wire  [3:0] e$17;
    input wire  [3:0] e$18;
    input wire  [3:0] e$19;
    input wire  [3:0] e$20;
    input wire  [3:0] e$21;
    input wire  [3:0] e$22;
    input wire  [3:0] e$23;
    input wire  [31:0] rd$0;
    input wire  [31:0] rd$1;
    input wire  [31:0] rd$2;
    input wire  [31:0] rd$3;
    input wire  [31:0] rd$4;
    input wire  [31:0] rd$5;
    input wire  [31:0] rd$6;
    input wire  [31:0] rd$7;
    input wire  [31:0] rd$8;
    input wire  [31:0] rd$9;
    input wire  [31:0] rd$10;
    input wire  [31:0] rd$11;
    input wire  [31:0] rd$12;
    input wire  [31:0] rd$13;
    input wire  [31:0] rd$14;
    input wire  [31:0] rd$15;
    input wire  [31:0] rd$16;
    input wire  [31:0] rd$17;
    input wire  [31:0] rd$18;
    input wire  [31:0] rd$19;
    input wire  [31:0] rd$20;
    input wire  [31:0] rd$21;
    input wire  [31:0] rd$22;
    input wire  [31:0] rd$23;
    input wire  [31:0] re$0;
    input wire  [31:0] re$1;
    input wire  [31:0] re$2;
    input wire  [31:0] re$3;
    input wire  [31:0] re$4;
    input wire  [31:0] re$5;
    input wire  [31:0] re$6;
    input wire  [31:0] re$7;
    input wire  [31:0] re$8;
    input wire  [31:0] re$9;
    input wire  [31:0] re$10;
    input wire  [31:0] re$11;
    input wire  [31:0] re$12;
    input wire  [31:0] re$13;
    input wire  [31:0] re$14;
    input wire  [31:0] re$15;
    input wire  [31:0] re$16;
    input wire  [31:0] re$17;
    input wire  [31:0] re$18;
    input wire  [31:0] re$19;
    input wire  [31:0] re$20;
    input wire  [31:0] re$21;
    input wire  [31:0] re$22;
    input wire  [31:0] re$23;
    input wire  [8:0] efd$0;
    input wire  [8:0] efd$1;
    input wire  [8:0] efd$2;
    input wire  [8:0] efd$3;
    input wire  [8:0] efd$4;
    input wire  [8:0] efd$5;
    input wire  [8:0] efd$6;
    input wire  [8:0] efd$7;
    input wire  [8:0] efd$8;
    input wire  [8:0] efd$9;
    input wire  [8:0] efd$10;
    input wire  [8:0] efd$11;
    input wire  [8:0] efd$12;
    input wire  [8:0] efd$13;
    input wire  [8:0] efd$14;
    input wire  [8:0] efd$15;
    input wire  [8:0] efd$16;
    input wire  [8:0] efd$17;
    input wire  [8:0] efd$18;
    input wire  [8:0] efd$19;
    input wire  [8:0] efd$20;
    input wire  [8:0] efd$21;
    input wire  [8:0] efd$22;
    input wire  [8:0] efd$23;
    input wire  [8:0] efe$0;
    input wire  [8:0] efe$1;
    input wire  [8:0] efe$2;
    input wire  [8:0] efe$3;
    input wire  [8:0] efe$4;
    input wire  [8:0] efe$5;
    input wire  [8:0] efe$6;
    input wire  [8:0] efe$7;
    input wire  [8:0] efe$8;
    input wire  [8:0] efe$9;
    input wire  [8:0] efe$10;
    input wire  [8:0] efe$11;
    input wire  [8:0] efe$12;
    input wire  [8:0] efe$13;
    input wire  [8:0] efe$14;
    input wire  [8:0] efe$15;
    input wire  [8:0] efe$16;
    input wire  [8:0] efe$17;
    input wire  [8:0] efe$18;
    input wire  [8:0] efe$19;
    input wire  [8:0] efe$20;
    input wire  [8:0] efe$21;
    input wire  [8:0] efe$22;
    input wire  [8:0] efe$23;
    input wire  [15:0] tag;
    input wire  valid_in;
    output reg  overlap;
    output reg  [15:0] tag_out;
    output reg  valid_out;
    
    // Constant declarations
    localparam  at_rnd$0 = 8'h4;
    localparam  at_rnd$1 = 8'hc;
    localparam  at_rnd$2 = 8'h14;
    localparam  at_rnd$3 = 8'h1c;
    localparam  at_rnd$4 = 8'h24;
    localparam  at_rnd$5 = 8'h2c;
    localparam  at_rnd$6 = 8'h34;
    localparam  at_rnd$7 = 8'h3c;
    localparam  at_rnd$8 = 8'h44;
    localparam  at_rnd$9 = 8'h4c;
    localparam  at_rnd$10 = 8'h54;
    localparam  at_rnd$11 = 8'h5c;
    localparam  at_rnd$12 = 8'h64;
    localparam  at_rnd$13 = 8'h6c;
    localparam  at_rnd$14 = 8'h74;
    localparam  at_rnd$15 = 8'h7c;
    localparam  at_rnd$16 = 8'h84;
    localparam  at_rnd$17 = 8'h8c;
    localparam  at_rnd$18 = 8'h94;
    localparam  at_rnd$19 = 8'h9c;
    localparam  at_rnd$20 = 8'ha4;
    localparam  at_rnd$21 = 8'hac;
    localparam  at_rnd$22 = 8'hb4;
    localparam  at_rnd$23 = 8'hbc;
    
    // Stub signals
    reg  rnd$0$d;
    wire  rnd$0$q;
    reg  rnd$0$clock;
    reg  rnd$1$d;
    wire  rnd$1$q;
    reg  rnd$1$clock;
    reg  rnd$2$d;
    wire  rnd$2$q;
    reg  rnd$2$clock;
    reg  rnd$3$d;
    wire  rnd$3$q;
    reg  rnd$3$clock;
    reg  rnd$4$d;
    wire  rnd$4$q;
    reg  rnd$4$clock;
    reg  rnd$5$d;
    wire  rnd$5$q;
    reg  rnd$5$clock;
    reg  rnd$6$d;
    wire  rnd$6$q;
    reg  rnd$6$clock;
    reg  rnd$7$d;
    wire  rnd$7$q;
    reg  rnd$7$clock;
    reg  rnd$8$d;
    wire  rnd$8$q;
    reg  rnd$8$clock;
    reg  rnd$9$d;
    wire  rnd$9$q;
    reg  rnd$9$clock;
    reg  rnd$10$d;
    wire  rnd$10$q;
    reg  rnd$10$clock;
    reg  rnd$11$d;
    wire  rnd$11$q;
    reg  rnd$11$clock;
    reg  rnd$12$d;
    wire  rnd$12$q;
    reg  rnd$12$clock;
    reg  rnd$13$d;
    wire  rnd$13$q;
    reg  rnd$13$clock;
    reg  rnd$14$d;
    wire  rnd$14$q;
    reg  rnd$14$clock;
    reg  rnd$15$d;
    wire  rnd$15$q;
    reg  rnd$15$clock;
    reg  rnd$16$d;
    wire  rnd$16$q;
    reg  rnd$16$clock;
    reg  rnd$17$d;
    wire  rnd$17$q;
    reg  rnd$17$clock;
    reg  rnd$18$d;
    wire  rnd$18$q;
    reg  rnd$18$clock;
    reg  rnd$19$d;
    wire  rnd$19$q;
    reg  rnd$19$clock;
    reg  rnd$20$d;
    wire  rnd$20$q;
    reg  rnd$20$clock;
    reg  rnd$21$d;
    wire  rnd$21$q;
    reg  rnd$21$clock;
    reg  rnd$22$d;
    wire  rnd$22$q;
    reg  rnd$22$clock;
    reg  rnd$23$d;
    wire  rnd$23$q;
    reg  rnd$23$clock;
    reg  dec_d$0$clock;
    reg  [31:0] dec_d$0$r;
    reg  [3:0] dec_d$0$q;
    reg  [8:0] dec_d$0$ef;
    reg  dec_d$0$valid_in;
    reg  dec_d$0$round_up;
    wire  [31:0] dec_d$0$y;
    wire  dec_d$0$valid_out;
    reg  dec_d$1$clock;
    reg  [31:0] dec_d$1$r;
    reg  [3:0] dec_d$1$q;
    reg  [8:0] dec_d$1$ef;
    reg  dec_d$1$valid_in;
    reg  dec_d$1$round_up;
    wire  [31:0] dec_d$1$y;
    wire  dec_d$1$valid_out;
    reg  dec_d$2$clock;
    reg  [31:0] dec_d$2$r;
    reg  [3:0] dec_d$2$q;
    reg  [8:0] dec_d$2$ef;
    reg  dec_d$2$valid_in;
    reg  dec_d$2$round_up;
    wire  [31:0] dec_d$2$y;
    wire  dec_d$2$valid_out;
    reg  dec_d$3$clock;
    reg  [31:0] dec_d$3$r;
    reg  [3:0] dec_d$3$q;
    reg  [8:0] dec_d$3$ef;
    reg  dec_d$3$valid_in;
    reg  dec_d$3$round_up;
    wire  [31:0] dec_d$3$y;
    wire  dec_d$3$valid_out;
    reg  dec_d$4$clock;
    reg  [31:0] dec_d$4$r;
    reg  [3:0] dec_d$4$q;
    reg  [8:0] dec_d$4$ef;
    reg  dec_d$4$valid_in;
    reg  dec_d$4$round_up;
    wire  [31:0] dec_d$4$y;
    wire  dec_d$4$valid_out;
    reg  dec_d$5$clock;
    reg  [31:0] dec_d$5$r;
    reg  [3:0] dec_d$5$q;
    reg  [8:0] dec_d$5$ef;
    reg  dec_d$5$valid_in;
    reg  dec_d$5$round_up;
    wire  [31:0] dec_d$5$y;
    wire  dec_d$5$valid_out;
    reg  dec_d$6$clock;
    reg  [31:0] dec_d$6$r;
    reg  [3:0] dec_d$6$q;
    reg  [8:0] dec_d$6$ef;
    reg  dec_d$6$valid_in;
    reg  dec_d$6$round_up;
    wire  [31:0] dec_d$6$y;
    wire  dec_d$6$valid_out;
    reg  dec_d$7$clock;
    reg  [31:0] dec_d$7$r;
    reg  [3:0] dec_d$7$q;
    reg  [8:0] dec_d$7$ef;
    reg  dec_d$7$valid_in;
    reg  dec_d$7$round_up;
    wire  [31:0] dec_d$7$y;
    wire  dec_d$7$valid_out;
    reg  dec_d$8$clock;
    reg  [31:0] dec_d$8$r;
    reg  [3:0] dec_d$8$q;
    reg  [8:0] dec_d$8$ef;
    reg  dec_d$8$valid_in;
    reg  dec_d$8$round_up;
    wire  [31:0] dec_d$8$y;
    wire  dec_d$8$valid_out;
    reg  dec_d$9$clock;
    reg  [31:0] dec_d$9$r;
    reg  [3:0] dec_d$9$q;
    reg  [8:0] dec_d$9$ef;
    reg  dec_d$9$valid_in;
    reg  dec_d$9$round_up;
    wire  [31:0] dec_d$9$y;
    wire  dec_d$9$valid_out;
    reg  dec_d$10$clock;
    reg  [31:0] dec_d$10$r;
    reg  [3:0] dec_d$10$q;
    reg  [8:0] dec_d$10$ef;
    reg  dec_d$10$valid_in;
    reg  dec_d$10$round_up;
    wire  [31:0] dec_d$10$y;
    wire  dec_d$10$valid_out;
    reg  dec_d$11$clock;
    reg  [31:0] dec_d$11$r;
    reg  [3:0] dec_d$11$q;
    reg  [8:0] dec_d$11$ef;
    reg  dec_d$11$valid_in;
    reg  dec_d$11$round_up;
    wire  [31:0] dec_d$11$y;
    wire  dec_d$11$valid_out;
    reg  dec_d$12$clock;
    reg  [31:0] dec_d$12$r;
    reg  [3:0] dec_d$12$q;
    reg  [8:0] dec_d$12$ef;
    reg  dec_d$12$valid_in;
    reg  dec_d$12$round_up;
    wire  [31:0] dec_d$12$y;
    wire  dec_d$12$valid_out;
    reg  dec_d$13$clock;
    reg  [31:0] dec_d$13$r;
    reg  [3:0] dec_d$13$q;
    reg  [8:0] dec_d$13$ef;
    reg  dec_d$13$valid_in;
    reg  dec_d$13$round_up;
    wire  [31:0] dec_d$13$y;
    wire  dec_d$13$valid_out;
    reg  dec_d$14$clock;
    reg  [31:0] dec_d$14$r;
    reg  [3:0] dec_d$14$q;
    reg  [8:0] dec_d$14$ef;
    reg  dec_d$14$valid_in;
    reg  dec_d$14$round_up;
    wire  [31:0] dec_d$14$y;
    wire  dec_d$14$valid_out;
    reg  dec_d$15$clock;
    reg  [31:0] dec_d$15$r;
    reg  [3:0] dec_d$15$q;
    reg  [8:0] dec_d$15$ef;
    reg  dec_d$15$valid_in;
    reg  dec_d$15$round_up;
    wire  [31:0] dec_d$15$y;
    wire  dec_d$15$valid_out;
    reg  dec_d$16$clock;
    reg  [31:0] dec_d$16$r;
    reg  [3:0] dec_d$16$q;
    reg  [8:0] dec_d$16$ef;
    reg  dec_d$16$valid_in;
    reg  dec_d$16$round_up;
    wire  [31:0] dec_d$16$y;
    wire  dec_d$16$valid_out;
    reg  dec_d$17$clock;
    reg  [31:0] dec_d$17$r;
    reg  [3:0] dec_d$17$q;
    reg  [8:0] dec_d$17$ef;
    reg  dec_d$17$valid_in;
    reg  dec_d$17$round_up;
    wire  [31:0] dec_d$17$y;
    wire  dec_d$17$valid_out;
    reg  dec_d$18$clock;
    reg  [31:0] dec_d$18$r;
    reg  [3:0] dec_d$18$q;
    reg  [8:0] dec_d$18$ef;
    reg  dec_d$18$valid_in;
    reg  dec_d$18$round_up;
    wire  [31:0] dec_d$18$y;
    wire  dec_d$18$valid_out;
    reg  dec_d$19$clock;
    reg  [31:0] dec_d$19$r;
    reg  [3:0] dec_d$19$q;
    reg  [8:0] dec_d$19$ef;
    reg  dec_d$19$valid_in;
    reg  dec_d$19$round_up;
    wire  [31:0] dec_d$19$y;
    wire  dec_d$19$valid_out;
    reg  dec_d$20$clock;
    reg  [31:0] dec_d$20$r;
    reg  [3:0] dec_d$20$q;
    reg  [8:0] dec_d$20$ef;
    reg  dec_d$20$valid_in;
    reg  dec_d$20$round_up;
    wire  [31:0] dec_d$20$y;
    wire  dec_d$20$valid_out;
    reg  dec_d$21$clock;
    reg  [31:0] dec_d$21$r;
    reg  [3:0] dec_d$21$q;
    reg  [8:0] dec_d$21$ef;
    reg  dec_d$21$valid_in;
    reg  dec_d$21$round_up;
    wire  [31:0] dec_d$21$y;
    wire  dec_d$21$valid_out;
    reg  dec_d$22$clock;
    reg  [31:0] dec_d$22$r;
    reg  [3:0] dec_d$22$q;
    reg  [8:0] dec_d$22$ef;
    reg  dec_d$22$valid_in;
    reg  dec_d$22$round_up;
    wire  [31:0] dec_d$22$y;
    wire  dec_d$22$valid_out;
    reg  dec_d$23$clock;
    reg  [31:0] dec_d$23$r;
    reg  [3:0] dec_d$23$q;
    reg  [8:0] dec_d$23$ef;
    reg  dec_d$23$valid_in;
    reg  dec_d$23$round_up;
    wire  [31:0] dec_d$23$y;
    wire  dec_d$23$valid_out;
    reg  dec_e$0$clock;
    reg  [31:0] dec_e$0$r;
    reg  [3:0] dec_e$0$q;
    reg  [8:0] dec_e$0$ef;
    reg  dec_e$0$valid_in;
    reg  dec_e$0$round_up;
    wire  [31:0] dec_e$0$y;
    wire  dec_e$0$valid_out;
    reg  dec_e$1$clock;
    reg  [31:0] dec_e$1$r;
    reg  [3:0] dec_e$1$q;
    reg  [8:0] dec_e$1$ef;
    reg  dec_e$1$valid_in;
    reg  dec_e$1$round_up;
    wire  [31:0] dec_e$1$y;
    wire  dec_e$1$valid_out;
    reg  dec_e$2$clock;
    reg  [31:0] dec_e$2$r;
    reg  [3:0] dec_e$2$q;
    reg  [8:0] dec_e$2$ef;
    reg  dec_e$2$valid_in;
    reg  dec_e$2$round_up;
    wire  [31:0] dec_e$2$y;
    wire  dec_e$2$valid_out;
    reg  dec_e$3$clock;
    reg  [31:0] dec_e$3$r;
    reg  [3:0] dec_e$3$q;
    reg  [8:0] dec_e$3$ef;
    reg  dec_e$3$valid_in;
    reg  dec_e$3$round_up;
    wire  [31:0] dec_e$3$y;
    wire  dec_e$3$valid_out;
    reg  dec_e$4$clock;
    reg  [31:0] dec_e$4$r;
    reg  [3:0] dec_e$4$q;
    reg  [8:0] dec_e$4$ef;
    reg  dec_e$4$valid_in;
    reg  dec_e$4$round_up;
    wire  [31:0] dec_e$4$y;
    wire  dec_e$4$valid_out;
    reg  dec_e$5$clock;
    reg  [31:0] dec_e$5$r;
    reg  [3:0] dec_e$5$q;
    reg  [8:0] dec_e$5$ef;
    reg  dec_e$5$valid_in;
    reg  dec_e$5$round_up;
    wire  [31:0] dec_e$5$y;
    wire  dec_e$5$valid_out;
    reg  dec_e$6$clock;
    reg  [31:0] dec_e$6$r;
    reg  [3:0] dec_e$6$q;
    reg  [8:0] dec_e$6$ef;
    reg  dec_e$6$valid_in;
    reg  dec_e$6$round_up;
    wire  [31:0] dec_e$6$y;
    wire  dec_e$6$valid_out;
    reg  dec_e$7$clock;
    reg  [31:0] dec_e$7$r;
    reg  [3:0] dec_e$7$q;
    reg  [8:0] dec_e$7$ef;
    reg  dec_e$7$valid_in;
    reg  dec_e$7$round_up;
    wire  [31:0] dec_e$7$y;
    wire  dec_e$7$valid_out;
    reg  dec_e$8$clock;
    reg  [31:0] dec_e$8$r;
    reg  [3:0] dec_e$8$q;
    reg  [8:0] dec_e$8$ef;
    reg  dec_e$8$valid_in;
    reg  dec_e$8$round_up;
    wire  [31:0] dec_e$8$y;
    wire  dec_e$8$valid_out;
    reg  dec_e$9$clock;
    reg  [31:0] dec_e$9$r;
    reg  [3:0] dec_e$9$q;
    reg  [8:0] dec_e$9$ef;
    reg  dec_e$9$valid_in;
    reg  dec_e$9$round_up;
    wire  [31:0] dec_e$9$y;
    wire  dec_e$9$valid_out;
    reg  dec_e$10$clock;
    reg  [31:0] dec_e$10$r;
    reg  [3:0] dec_e$10$q;
    reg  [8:0] dec_e$10$ef;
    reg  dec_e$10$valid_in;
    reg  dec_e$10$round_up;
    wire  [31:0] dec_e$10$y;
    wire  dec_e$10$valid_out;
    reg  dec_e$11$clock;
    reg  [31:0] dec_e$11$r;
    reg  [3:0] dec_e$11$q;
    reg  [8:0] dec_e$11$ef;
    reg  dec_e$11$valid_in;
    reg  dec_e$11$round_up;
    wire  [31:0] dec_e$11$y;
    wire  dec_e$11$valid_out;
    reg  dec_e$12$clock;
    reg  [31:0] dec_e$12$r;
    reg  [3:0] dec_e$12$q;
    reg  [8:0] dec_e$12$ef;
    reg  dec_e$12$valid_in;
    reg  dec_e$12$round_up;
    wire  [31:0] dec_e$12$y;
    wire  dec_e$12$valid_out;
    reg  dec_e$13$clock;
    reg  [31:0] dec_e$13$r;
    reg  [3:0] dec_e$13$q;
    reg  [8:0] dec_e$13$ef;
    reg  dec_e$13$valid_in;
    reg  dec_e$13$round_up;
    wire  [31:0] dec_e$13$y;
    wire  dec_e$13$valid_out;
    reg  dec_e$14$clock;
    reg  [31:0] dec_e$14$r;
    reg  [3:0] dec_e$14$q;
    reg  [8:0] dec_e$14$ef;
    reg  dec_e$14$valid_in;
    reg  dec_e$14$round_up;
    wire  [31:0] dec_e$14$y;
    wire  dec_e$14$valid_out;
    reg  dec_e$15$clock;
    reg  [31:0] dec_e$15$r;
    reg  [3:0] dec_e$15$q;
    reg  [8:0] dec_e$15$ef;
    reg  dec_e$15$valid_in;
    reg  dec_e$15$round_up;
    wire  [31:0] dec_e$15$y;
    wire  dec_e$15$valid_out;
    reg  dec_e$16$clock;
    reg  [31:0] dec_e$16$r;
    reg  [3:0] dec_e$16$q;
    reg  [8:0] dec_e$16$ef;
    reg  dec_e$16$valid_in;
    reg  dec_e$16$round_up;
    wire  [31:0] dec_e$16$y;
    wire  dec_e$16$valid_out;
    reg  dec_e$17$clock;
    reg  [31:0] dec_e$17$r;
    reg  [3:0] dec_e$17$q;
    reg  [8:0] dec_e$17$ef;
    reg  dec_e$17$valid_in;
    reg  dec_e$17$round_up;
    wire  [31:0] dec_e$17$y;
    wire  dec_e$17$valid_out;
    reg  dec_e$18$clock;
    reg  [31:0] dec_e$18$r;
    reg  [3:0] dec_e$18$q;
    reg  [8:0] dec_e$18$ef;
    reg  dec_e$18$valid_in;
    reg  dec_e$18$round_up;
    wire  [31:0] dec_e$18$y;
    wire  dec_e$18$valid_out;
    reg  dec_e$19$clock;
    reg  [31:0] dec_e$19$r;
    reg  [3:0] dec_e$19$q;
    reg  [8:0] dec_e$19$ef;
    reg  dec_e$19$valid_in;
    reg  dec_e$19$round_up;
    wire  [31:0] dec_e$19$y;
    wire  dec_e$19$valid_out;
    reg  dec_e$20$clock;
    reg  [31:0] dec_e$20$r;
    reg  [3:0] dec_e$20$q;
    reg  [8:0] dec_e$20$ef;
    reg  dec_e$20$valid_in;
    reg  dec_e$20$round_up;
    wire  [31:0] dec_e$20$y;
    wire  dec_e$20$valid_out;
    reg  dec_e$21$clock;
    reg  [31:0] dec_e$21$r;
    reg  [3:0] dec_e$21$q;
    reg  [8:0] dec_e$21$ef;
    reg  dec_e$21$valid_in;
    reg  dec_e$21$round_up;
    wire  [31:0] dec_e$21$y;
    wire  dec_e$21$valid_out;
    reg  dec_e$22$clock;
    reg  [31:0] dec_e$22$r;
    reg  [3:0] dec_e$22$q;
    reg  [8:0] dec_e$22$ef;
    reg  dec_e$22$valid_in;
    reg  dec_e$22$round_up;
    wire  [31:0] dec_e$22$y;
    wire  dec_e$22$valid_out;
    reg  dec_e$23$clock;
    reg  [31:0] dec_e$23$r;
    reg  [3:0] dec_e$23$q;
    reg  [8:0] dec_e$23$ef;
    reg  dec_e$23$valid_in;
    reg  dec_e$23$round_up;
    wire  [31:0] dec_e$23$y;
    wire  dec_e$23$valid_out;
    reg  tag_dec$clock;
    reg  [15:0] tag_dec$d;
    wire  [15:0] tag_dec$q;
    reg  unit$clock;
    reg  unit$load_en;
    reg  [7:0] unit$load_addr;
    reg  [31:0] unit$load_data;
    reg  [31:0] unit$d$0;
    reg  [31:0] unit$d$1;
    reg  [31:0] unit$d$2;
    reg  [31:0] unit$d$3;
    reg  [31:0] unit$d$4;
    reg  [31:0] unit$d$5;
    reg  [31:0] unit$d$6;
    reg  [31:0] unit$d$7;
    reg  [31:0] unit$d$8;
    reg  [31:0] unit$d$9;
    reg  [31:0] unit$d$10;
    reg  [31:0] unit$d$11;
    reg  [31:0] unit$d$12;
    reg  [31:0] unit$d$13;
    reg  [31:0] unit$d$14;
    reg  [31:0] unit$d$15;
    reg  [31:0] unit$d$16;
    reg  [31:0] unit$d$17;
    reg  [31:0] unit$d$18;
    reg  [31:0] unit$d$19;
    reg  [31:0] unit$d$20;
    reg  [31:0] unit$d$21;
    reg  [31:0] unit$d$22;
    reg  [31:0] unit$d$23;
    reg  [31:0] unit$e$0;
    reg  [31:0] unit$e$1;
    reg  [31:0] unit$e$2;
    reg  [31:0] unit$e$3;
    reg  [31:0] unit$e$4;
    reg  [31:0] unit$e$5;
    reg  [31:0] unit$e$6;
    reg  [31:0] unit$e$7;
    reg  [31:0] unit$e$8;
    reg  [31:0] unit$e$9;
    reg  [31:0] unit$e$10;
    reg  [31:0] unit$e$11;
    reg  [31:0] unit$e$12;
    reg  [31:0] unit$e$13;
    reg  [31:0] unit$e$14;
    reg  [31:0] unit$e$15;
    reg  [31:0] unit$e$16;
    reg  [31:0] unit$e$17;
    reg  [31:0] unit$e$18;
    reg  [31:0] unit$e$19;
    reg  [31:0] unit$e$20;
    reg  [31:0] unit$e$21;
    reg  [31:0] unit$e$22;
    reg  [31:0] unit$e$23;
    reg  [15:0] unit$tag;
    reg  unit$valid_in;
    wire  unit$overlap;
    wire  [15:0] unit$tag_out;
    wire  unit$valid_out;
    
    // Sub module instances
    top$cnt_dop$pending rnd$0(
        .d(rnd$0$d),
        .q(rnd$0$q),
        .clock(rnd$0$clock)
    );
    top$cnt_dop$pending rnd$1(
        .d(rnd$1$d),
        .q(rnd$1$q),
        .clock(rnd$1$clock)
    );
    top$cnt_dop$pending rnd$2(
        .d(rnd$2$d),
        .q(rnd$2$q),
        .clock(rnd$2$clock)
    );
    top$cnt_dop$pending rnd$3(
        .d(rnd$3$d),
        .q(rnd$3$q),
        .clock(rnd$3$clock)
    );
    top$cnt_dop$pending rnd$4(
        .d(rnd$4$d),
        .q(rnd$4$q),
        .clock(rnd$4$clock)
    );
    top$cnt_dop$pending rnd$5(
        .d(rnd$5$d),
        .q(rnd$5$q),
        .clock(rnd$5$clock)
    );
    top$cnt_dop$pending rnd$6(
        .d(rnd$6$d),
        .q(rnd$6$q),
        .clock(rnd$6$clock)
    );
    top$cnt_dop$pending rnd$7(
        .d(rnd$7$d),
        .q(rnd$7$q),
        .clock(rnd$7$clock)
    );
    top$cnt_dop$pending rnd$8(
        .d(rnd$8$d),
        .q(rnd$8$q),
        .clock(rnd$8$clock)
    );
    top$cnt_dop$pending rnd$9(
        .d(rnd$9$d),
        .q(rnd$9$q),
        .clock(rnd$9$clock)
    );
    top$cnt_dop$pending rnd$10(
        .d(rnd$10$d),
        .q(rnd$10$q),
        .clock(rnd$10$clock)
    );
    top$cnt_dop$pending rnd$11(
        .d(rnd$11$d),
        .q(rnd$11$q),
        .clock(rnd$11$clock)
    );
    top$cnt_dop$pending rnd$12(
        .d(rnd$12$d),
        .q(rnd$12$q),
        .clock(rnd$12$clock)
    );
    top$cnt_dop$pending rnd$13(
        .d(rnd$13$d),
        .q(rnd$13$q),
        .clock(rnd$13$clock)
    );
    top$cnt_dop$pending rnd$14(
        .d(rnd$14$d),
        .q(rnd$14$q),
        .clock(rnd$14$clock)
    );
    top$cnt_dop$pending rnd$15(
        .d(rnd$15$d),
        .q(rnd$15$q),
        .clock(rnd$15$clock)
    );
    top$cnt_dop$pending rnd$16(
        .d(rnd$16$d),
        .q(rnd$16$q),
        .clock(rnd$16$clock)
    );
    top$cnt_dop$pending rnd$17(
        .d(rnd$17$d),
        .q(rnd$17$q),
        .clock(rnd$17$clock)
    );
    top$cnt_dop$pending rnd$18(
        .d(rnd$18$d),
        .q(rnd$18$q),
        .clock(rnd$18$clock)
    );
    top$cnt_dop$pending rnd$19(
        .d(rnd$19$d),
        .q(rnd$19$q),
        .clock(rnd$19$clock)
    );
    top$cnt_dop$pending rnd$20(
        .d(rnd$20$d),
        .q(rnd$20$q),
        .clock(rnd$20$clock)
    );
    top$cnt_dop$pending rnd$21(
        .d(rnd$21$d),
        .q(rnd$21$q),
        .clock(rnd$21$clock)
    );
    top$cnt_dop$pending rnd$22(
        .d(rnd$22$d),
        .q(rnd$22$q),
        .clock(rnd$22$clock)
    );
    top$cnt_dop$pending rnd$23(
        .d(rnd$23$d),
        .q(rnd$23$q),
        .clock(rnd$23$clock)
    );
    top$dop$dec_d$0 dec_d$0(
        .clock(dec_d$0$clock),
        .r(dec_d$0$r),
        .q(dec_d$0$q),
        .ef(dec_d$0$ef),
        .valid_in(dec_d$0$valid_in),
        .round_up(dec_d$0$round_up),
        .y(dec_d$0$y),
        .valid_out(dec_d$0$valid_out)
    );
    top$dop$dec_d$0 dec_d$1(
        .clock(dec_d$1$clock),
        .r(dec_d$1$r),
        .q(dec_d$1$q),
        .ef(dec_d$1$ef),
        .valid_in(dec_d$1$valid_in),
        .round_up(dec_d$1$round_up),
        .y(dec_d$1$y),
        .valid_out(dec_d$1$valid_out)
    );
    top$dop$dec_d$0 dec_d$2(
        .clock(dec_d$2$clock),
        .r(dec_d$2$r),
        .q(dec_d$2$q),
        .ef(dec_d$2$ef),
        .valid_in(dec_d$2$valid_in),
        .round_up(dec_d$2$round_up),
        .y(dec_d$2$y),
        .valid_out(dec_d$2$valid_out)
    );
    top$dop$dec_d$0 dec_d$3(
        .clock(dec_d$3$clock),
        .r(dec_d$3$r),
        .q(dec_d$3$q),
        .ef(dec_d$3$ef),
        .valid_in(dec_d$3$valid_in),
        .round_up(dec_d$3$round_up),
        .y(dec_d$3$y),
        .valid_out(dec_d$3$valid_out)
    );
    top$dop$dec_d$0 dec_d$4(
        .clock(dec_d$4$clock),
        .r(dec_d$4$r),
        .q(dec_d$4$q),
        .ef(dec_d$4$ef),
        .valid_in(dec_d$4$valid_in),
        .round_up(dec_d$4$round_up),
        .y(dec_d$4$y),
        .valid_out(dec_d$4$valid_out)
    );
    top$dop$dec_d$0 dec_d$5(
        .clock(dec_d$5$clock),
        .r(dec_d$5$r),
        .q(dec_d$5$q),
        .ef(dec_d$5$ef),
        .valid_in(dec_d$5$valid_in),
        .round_up(dec_d$5$round_up),
        .y(dec_d$5$y),
        .valid_out(dec_d$5$valid_out)
    );
    top$dop$dec_d$0 dec_d$6(
        .clock(dec_d$6$clock),
        .r(dec_d$6$r),
        .q(dec_d$6$q),
        .ef(dec_d$6$ef),
        .valid_in(dec_d$6$valid_in),
        .round_up(dec_d$6$round_up),
        .y(dec_d$6$y),
        .valid_out(dec_d$6$valid_out)
    );
    top$dop$dec_d$0 dec_d$7(
        .clock(dec_d$7$clock),
        .r(dec_d$7$r),
        .q(dec_d$7$q),
        .ef(dec_d$7$ef),
        .valid_in(dec_d$7$valid_in),
        .round_up(dec_d$7$round_up),
        .y(dec_d$7$y),
        .valid_out(dec_d$7$valid_out)
    );
    top$dop$dec_d$0 dec_d$8(
        .clock(dec_d$8$clock),
        .r(dec_d$8$r),
        .q(dec_d$8$q),
        .ef(dec_d$8$ef),
        .valid_in(dec_d$8$valid_in),
        .round_up(dec_d$8$round_up),
        .y(dec_d$8$y),
        .valid_out(dec_d$8$valid_out)
    );
    top$dop$dec_d$0 dec_d$9(
        .clock(dec_d$9$clock),
        .r(dec_d$9$r),
        .q(dec_d$9$q),
        .ef(dec_d$9$ef),
        .valid_in(dec_d$9$valid_in),
        .round_up(dec_d$9$round_up),
        .y(dec_d$9$y),
        .valid_out(dec_d$9$valid_out)
    );
    top$dop$dec_d$0 dec_d$10(
        .clock(dec_d$10$clock),
        .r(dec_d$10$r),
        .q(dec_d$10$q),
        .ef(dec_d$10$ef),
        .valid_in(dec_d$10$valid_in),
        .round_up(dec_d$10$round_up),
        .y(dec_d$10$y),
        .valid_out(dec_d$10$valid_out)
    );
    top$dop$dec_d$0 dec_d$11(
        .clock(dec_d$11$clock),
        .r(dec_d$11$r),
        .q(dec_d$11$q),
        .ef(dec_d$11$ef),
        .valid_in(dec_d$11$valid_in),
        .round_up(dec_d$11$round_up),
        .y(dec_d$11$y),
        .valid_out(dec_d$11$valid_out)
    );
    top$dop$dec_d$0 dec_d$12(
        .clock(dec_d$12$clock),
        .r(dec_d$12$r),
        .q(dec_d$12$q),
        .ef(dec_d$12$ef),
        .valid_in(dec_d$12$valid_in),
        .round_up(dec_d$12$round_up),
        .y(dec_d$12$y),
        .valid_out(dec_d$12$valid_out)
    );
    top$dop$dec_d$0 dec_d$13(
        .clock(dec_d$13$clock),
        .r(dec_d$13$r),
        .q(dec_d$13$q),
        .ef(dec_d$13$ef),
        .valid_in(dec_d$13$valid_in),
        .round_up(dec_d$13$round_up),
        .y(dec_d$13$y),
        .valid_out(dec_d$13$valid_out)
    );
    top$dop$dec_d$0 dec_d$14(
        .clock(dec_d$14$clock),
        .r(dec_d$14$r),
        .q(dec_d$14$q),
        .ef(dec_d$14$ef),
        .valid_in(dec_d$14$valid_in),
        .round_up(dec_d$14$round_up),
        .y(dec_d$14$y),
        .valid_out(dec_d$14$valid_out)
    );
    top$dop$dec_d$0 dec_d$15(
        .clock(dec_d$15$clock),
        .r(dec_d$15$r),
        .q(dec_d$15$q),
        .ef(dec_d$15$ef),
        .valid_in(dec_d$15$valid_in),
        .round_up(dec_d$15$round_up),
        .y(dec_d$15$y),
        .valid_out(dec_d$15$valid_out)
    );
    top$dop$dec_d$0 dec_d$16(
        .clock(dec_d$16$clock),
        .r(dec_d$16$r),
        .q(dec_d$16$q),
        .ef(dec_d$16$ef),
        .valid_in(dec_d$16$valid_in),
        .round_up(dec_d$16$round_up),
        .y(dec_d$16$y),
        .valid_out(dec_d$16$valid_out)
    );
    top$dop$dec_d$0 dec_d$17(
        .clock(dec_d$17$clock),
        .r(dec_d$17$r),
        .q(dec_d$17$q),
        .ef(dec_d$17$ef),
        .valid_in(dec_d$17$valid_in),
        .round_up(dec_d$17$round_up),
        .y(dec_d$17$y),
        .valid_out(dec_d$17$valid_out)
    );
    top$dop$dec_d$0 dec_d$18(
        .clock(dec_d$18$clock),
        .r(dec_d$18$r),
        .q(dec_d$18$q),
        .ef(dec_d$18$ef),
        .valid_in(dec_d$18$valid_in),
        .round_up(dec_d$18$round_up),
        .y(dec_d$18$y),
        .valid_out(dec_d$18$valid_out)
    );
    top$dop$dec_d$0 dec_d$19(
        .clock(dec_d$19$clock),
        .r(dec_d$19$r),
        .q(dec_d$19$q),
        .ef(dec_d$19$ef),
        .valid_in(dec_d$19$valid_in),
        .round_up(dec_d$19$round_up),
        .y(dec_d$19$y),
        .valid_out(dec_d$19$valid_out)
    );
    top$dop$dec_d$0 dec_d$20(
        .clock(dec_d$20$clock),
        .r(dec_d$20$r),
        .q(dec_d$20$q),
        .ef(dec_d$20$ef),
        .valid_in(dec_d$20$valid_in),
        .round_up(dec_d$20$round_up),
        .y(dec_d$20$y),
        .valid_out(dec_d$20$valid_out)
    );
    top$dop$dec_d$0 dec_d$21(
        .clock(dec_d$21$clock),
        .r(dec_d$21$r),
        .q(dec_d$21$q),
        .ef(dec_d$21$ef),
        .valid_in(dec_d$21$valid_in),
        .round_up(dec_d$21$round_up),
        .y(dec_d$21$y),
        .valid_out(dec_d$21$valid_out)
    );
    top$dop$dec_d$0 dec_d$22(
        .clock(dec_d$22$clock),
        .r(dec_d$22$r),
        .q(dec_d$22$q),
        .ef(dec_d$22$ef),
        .valid_in(dec_d$22$valid_in),
        .round_up(dec_d$22$round_up),
        .y(dec_d$22$y),
        .valid_out(dec_d$22$valid_out)
    );
    top$dop$dec_d$0 dec_d$23(
        .clock(dec_d$23$clock),
        .r(dec_d$23$r),
        .q(dec_d$23$q),
        .ef(dec_d$23$ef),
        .valid_in(dec_d$23$valid_in),
        .round_up(dec_d$23$round_up),
        .y(dec_d$23$y),
        .valid_out(dec_d$23$valid_out)
    );
    top$dop$dec_d$0 dec_e$0(
        .clock(dec_e$0$clock),
        .r(dec_e$0$r),
        .q(dec_e$0$q),
        .ef(dec_e$0$ef),
        .valid_in(dec_e$0$valid_in),
        .round_up(dec_e$0$round_up),
        .y(dec_e$0$y),
        .valid_out(dec_e$0$valid_out)
    );
    top$dop$dec_d$0 dec_e$1(
        .clock(dec_e$1$clock),
        .r(dec_e$1$r),
        .q(dec_e$1$q),
        .ef(dec_e$1$ef),
        .valid_in(dec_e$1$valid_in),
        .round_up(dec_e$1$round_up),
        .y(dec_e$1$y),
        .valid_out(dec_e$1$valid_out)
    );
    top$dop$dec_d$0 dec_e$2(
        .clock(dec_e$2$clock),
        .r(dec_e$2$r),
        .q(dec_e$2$q),
        .ef(dec_e$2$ef),
        .valid_in(dec_e$2$valid_in),
        .round_up(dec_e$2$round_up),
        .y(dec_e$2$y),
        .valid_out(dec_e$2$valid_out)
    );
    top$dop$dec_d$0 dec_e$3(
        .clock(dec_e$3$clock),
        .r(dec_e$3$r),
        .q(dec_e$3$q),
        .ef(dec_e$3$ef),
        .valid_in(dec_e$3$valid_in),
        .round_up(dec_e$3$round_up),
        .y(dec_e$3$y),
        .valid_out(dec_e$3$valid_out)
    );
    top$dop$dec_d$0 dec_e$4(
        .clock(dec_e$4$clock),
        .r(dec_e$4$r),
        .q(dec_e$4$q),
        .ef(dec_e$4$ef),
        .valid_in(dec_e$4$valid_in),
        .round_up(dec_e$4$round_up),
        .y(dec_e$4$y),
        .valid_out(dec_e$4$valid_out)
    );
    top$dop$dec_d$0 dec_e$5(
        .clock(dec_e$5$clock),
        .r(dec_e$5$r),
        .q(dec_e$5$q),
        .ef(dec_e$5$ef),
        .valid_in(dec_e$5$valid_in),
        .round_up(dec_e$5$round_up),
        .y(dec_e$5$y),
        .valid_out(dec_e$5$valid_out)
    );
    top$dop$dec_d$0 dec_e$6(
        .clock(dec_e$6$clock),
        .r(dec_e$6$r),
        .q(dec_e$6$q),
        .ef(dec_e$6$ef),
        .valid_in(dec_e$6$valid_in),
        .round_up(dec_e$6$round_up),
        .y(dec_e$6$y),
        .valid_out(dec_e$6$valid_out)
    );
    top$dop$dec_d$0 dec_e$7(
        .clock(dec_e$7$clock),
        .r(dec_e$7$r),
        .q(dec_e$7$q),
        .ef(dec_e$7$ef),
        .valid_in(dec_e$7$valid_in),
        .round_up(dec_e$7$round_up),
        .y(dec_e$7$y),
        .valid_out(dec_e$7$valid_out)
    );
    top$dop$dec_d$0 dec_e$8(
        .clock(dec_e$8$clock),
        .r(dec_e$8$r),
        .q(dec_e$8$q),
        .ef(dec_e$8$ef),
        .valid_in(dec_e$8$valid_in),
        .round_up(dec_e$8$round_up),
        .y(dec_e$8$y),
        .valid_out(dec_e$8$valid_out)
    );
    top$dop$dec_d$0 dec_e$9(
        .clock(dec_e$9$clock),
        .r(dec_e$9$r),
        .q(dec_e$9$q),
        .ef(dec_e$9$ef),
        .valid_in(dec_e$9$valid_in),
        .round_up(dec_e$9$round_up),
        .y(dec_e$9$y),
        .valid_out(dec_e$9$valid_out)
    );
    top$dop$dec_d$0 dec_e$10(
        .clock(dec_e$10$clock),
        .r(dec_e$10$r),
        .q(dec_e$10$q),
        .ef(dec_e$10$ef),
        .valid_in(dec_e$10$valid_in),
        .round_up(dec_e$10$round_up),
        .y(dec_e$10$y),
        .valid_out(dec_e$10$valid_out)
    );
    top$dop$dec_d$0 dec_e$11(
        .clock(dec_e$11$clock),
        .r(dec_e$11$r),
        .q(dec_e$11$q),
        .ef(dec_e$11$ef),
        .valid_in(dec_e$11$valid_in),
        .round_up(dec_e$11$round_up),
        .y(dec_e$11$y),
        .valid_out(dec_e$11$valid_out)
    );
    top$dop$dec_d$0 dec_e$12(
        .clock(dec_e$12$clock),
        .r(dec_e$12$r),
        .q(dec_e$12$q),
        .ef(dec_e$12$ef),
        .valid_in(dec_e$12$valid_in),
        .round_up(dec_e$12$round_up),
        .y(dec_e$12$y),
        .valid_out(dec_e$12$valid_out)
    );
    top$dop$dec_d$0 dec_e$13(
        .clock(dec_e$13$clock),
        .r(dec_e$13$r),
        .q(dec_e$13$q),
        .ef(dec_e$13$ef),
        .valid_in(dec_e$13$valid_in),
        .round_up(dec_e$13$round_up),
        .y(dec_e$13$y),
        .valid_out(dec_e$13$valid_out)
    );
    top$dop$dec_d$0 dec_e$14(
        .clock(dec_e$14$clock),
        .r(dec_e$14$r),
        .q(dec_e$14$q),
        .ef(dec_e$14$ef),
        .valid_in(dec_e$14$valid_in),
        .round_up(dec_e$14$round_up),
        .y(dec_e$14$y),
        .valid_out(dec_e$14$valid_out)
    );
    top$dop$dec_d$0 dec_e$15(
        .clock(dec_e$15$clock),
        .r(dec_e$15$r),
        .q(dec_e$15$q),
        .ef(dec_e$15$ef),
        .valid_in(dec_e$15$valid_in),
        .round_up(dec_e$15$round_up),
        .y(dec_e$15$y),
        .valid_out(dec_e$15$valid_out)
    );
    top$dop$dec_d$0 dec_e$16(
        .clock(dec_e$16$clock),
        .r(dec_e$16$r),
        .q(dec_e$16$q),
        .ef(dec_e$16$ef),
        .valid_in(dec_e$16$valid_in),
        .round_up(dec_e$16$round_up),
        .y(dec_e$16$y),
        .valid_out(dec_e$16$valid_out)
    );
    top$dop$dec_d$0 dec_e$17(
        .clock(dec_e$17$clock),
        .r(dec_e$17$r),
        .q(dec_e$17$q),
        .ef(dec_e$17$ef),
        .valid_in(dec_e$17$valid_in),
        .round_up(dec_e$17$round_up),
        .y(dec_e$17$y),
        .valid_out(dec_e$17$valid_out)
    );
    top$dop$dec_d$0 dec_e$18(
        .clock(dec_e$18$clock),
        .r(dec_e$18$r),
        .q(dec_e$18$q),
        .ef(dec_e$18$ef),
        .valid_in(dec_e$18$valid_in),
        .round_up(dec_e$18$round_up),
        .y(dec_e$18$y),
        .valid_out(dec_e$18$valid_out)
    );
    top$dop$dec_d$0 dec_e$19(
        .clock(dec_e$19$clock),
        .r(dec_e$19$r),
        .q(dec_e$19$q),
        .ef(dec_e$19$ef),
        .valid_in(dec_e$19$valid_in),
        .round_up(dec_e$19$round_up),
        .y(dec_e$19$y),
        .valid_out(dec_e$19$valid_out)
    );
    top$dop$dec_d$0 dec_e$20(
        .clock(dec_e$20$clock),
        .r(dec_e$20$r),
        .q(dec_e$20$q),
        .ef(dec_e$20$ef),
        .valid_in(dec_e$20$valid_in),
        .round_up(dec_e$20$round_up),
        .y(dec_e$20$y),
        .valid_out(dec_e$20$valid_out)
    );
    top$dop$dec_d$0 dec_e$21(
        .clock(dec_e$21$clock),
        .r(dec_e$21$r),
        .q(dec_e$21$q),
        .ef(dec_e$21$ef),
        .valid_in(dec_e$21$valid_in),
        .round_up(dec_e$21$round_up),
        .y(dec_e$21$y),
        .valid_out(dec_e$21$valid_out)
    );
    top$dop$dec_d$0 dec_e$22(
        .clock(dec_e$22$clock),
        .r(dec_e$22$r),
        .q(dec_e$22$q),
        .ef(dec_e$22$ef),
        .valid_in(dec_e$22$valid_in),
        .round_up(dec_e$22$round_up),
        .y(dec_e$22$y),
        .valid_out(dec_e$22$valid_out)
    );
    top$dop$dec_d$0 dec_e$23(
        .clock(dec_e$23$clock),
        .r(dec_e$23$r),
        .q(dec_e$23$q),
        .ef(dec_e$23$ef),
        .valid_in(dec_e$23$valid_in),
        .round_up(dec_e$23$round_up),
        .y(dec_e$23$y),
        .valid_out(dec_e$23$valid_out)
    );
    top$dop$tag_dec tag_dec(
        .clock(tag_dec$clock),
        .d(tag_dec$d),
        .q(tag_dec$q)
    );
    top$dop$unit unit(
        .clock(unit$clock),
        .load_en(unit$load_en),
        .load_addr(unit$load_addr),
        .load_data(unit$load_data),
        .d$0(unit$d$0),
        .d$1(unit$d$1),
        .d$2(unit$d$2),
        .d$3(unit$d$3),
        .d$4(unit$d$4),
        .d$5(unit$d$5),
        .d$6(unit$d$6),
        .d$7(unit$d$7),
        .d$8(unit$d$8),
        .d$9(unit$d$9),
        .d$10(unit$d$10),
        .d$11(unit$d$11),
        .d$12(unit$d$12),
        .d$13(unit$d$13),
        .d$14(unit$d$14),
        .d$15(unit$d$15),
        .d$16(unit$d$16),
        .d$17(unit$d$17),
        .d$18(unit$d$18),
        .d$19(unit$d$19),
        .d$20(unit$d$20),
        .d$21(unit$d$21),
        .d$22(unit$d$22),
        .d$23(unit$d$23),
        .e$0(unit$e$0),
        .e$1(unit$e$1),
        .e$2(unit$e$2),
        .e$3(unit$e$3),
        .e$4(unit$e$4),
        .e$5(unit$e$5),
        .e$6(unit$e$6),
        .e$7(unit$e$7),
        .e$8(unit$e$8),
        .e$9(unit$e$9),
        .e$10(unit$e$10),
        .e$11(unit$e$11),
        .e$12(unit$e$12),
        .e$13(unit$e$13),
        .e$14(unit$e$14),
        .e$15(unit$e$15),
        .e$16(unit$e$16),
        .e$17(unit$e$17),
        .e$18(unit$e$18),
        .e$19(unit$e$19),
        .e$20(unit$e$20),
        .e$21(unit$e$21),
        .e$22(unit$e$22),
        .e$23(unit$e$23),
        .tag(unit$tag),
        .valid_in(unit$valid_in),
        .overlap(unit$overlap),
        .tag_out(unit$tag_out),
        .valid_out(unit$valid_out)
    );
    
    // Update code
    always @(*) begin
        tag_dec$clock = clock;
        unit$clock = clock;
        rnd$0$clock = clock;
        rnd$0$d = rnd$0$q;
        if (load_en & (load_addr == at_rnd$0)) begin
            rnd$0$d = load_data[32'hf];
        end
        dec_d$0$round_up = rnd$0$q;
        dec_e$0$round_up = rnd$0$q;
        dec_d$0$clock = clock;
        dec_d$0$r = rd$0;
        dec_d$0$q = d$0;
        dec_d$0$ef = efd$0;
        dec_d$0$valid_in = valid_in;
        dec_e$0$clock = clock;
        dec_e$0$r = re$0;
        dec_e$0$q = e$0;
        dec_e$0$ef = efe$0;
        dec_e$0$valid_in = valid_in;
        unit$d$0 = dec_d$0$y;
        unit$e$0 = dec_e$0$y;
        rnd$1$clock = clock;
        rnd$1$d = rnd$1$q;
        if (load_en & (load_addr == at_rnd$1)) begin
            rnd$1$d = load_data[32'hf];
        end
        dec_d$1$round_up = rnd$1$q;
        dec_e$1$round_up = rnd$1$q;
        dec_d$1$clock = clock;
        dec_d$1$r = rd$1;
        dec_d$1$q = d$1;
        dec_d$1$ef = efd$1;
        dec_d$1$valid_in = valid_in;
        dec_e$1$clock = clock;
        dec_e$1$r = re$1;
        dec_e$1$q = e$1;
        dec_e$1$ef = efe$1;
        dec_e$1$valid_in = valid_in;
        unit$d$1 = dec_d$1$y;
        unit$e$1 = dec_e$1$y;
        rnd$2$clock = clock;
        rnd$2$d = rnd$2$q;
        if (load_en & (load_addr == at_rnd$2)) begin
            rnd$2$d = load_data[32'hf];
        end
        dec_d$2$round_up = rnd$2$q;
        dec_e$2$round_up = rnd$2$q;
        dec_d$2$clock = clock;
        dec_d$2$r = rd$2;
        dec_d$2$q = d$2;
        dec_d$2$ef = efd$2;
        dec_d$2$valid_in = valid_in;
        dec_e$2$clock = clock;
        dec_e$2$r = re$2;
        dec_e$2$q = e$2;
        dec_e$2$ef = efe$2;
        dec_e$2$valid_in = valid_in;
        unit$d$2 = dec_d$2$y;
        unit$e$2 = dec_e$2$y;
        rnd$3$clock = clock;
        rnd$3$d = rnd$3$q;
        if (load_en & (load_addr == at_rnd$3)) begin
            rnd$3$d = load_data[32'hf];
        end
        dec_d$3$round_up = rnd$3$q;
        dec_e$3$round_up = rnd$3$q;
        dec_d$3$clock = clock;
        dec_d$3$r = rd$3;
        dec_d$3$q = d$3;
        dec_d$3$ef = efd$3;
        dec_d$3$valid_in = valid_in;
        dec_e$3$clock = clock;
        dec_e$3$r = re$3;
        dec_e$3$q = e$3;
        dec_e$3$ef = efe$3;
        dec_e$3$valid_in = valid_in;
        unit$d$3 = dec_d$3$y;
        unit$e$3 = dec_e$3$y;
        rnd$4$clock = clock;
        rnd$4$d = rnd$4$q;
        if (load_en & (load_addr == at_rnd$4)) begin
            rnd$4$d = load_data[32'hf];
        end
        dec_d$4$round_up = rnd$4$q;
        dec_e$4$round_up = rnd$4$q;
        dec_d$4$clock = clock;
        dec_d$4$r = rd$4;
        dec_d$4$q = d$4;
        dec_d$4$ef = efd$4;
        dec_d$4$valid_in = valid_in;
        dec_e$4$clock = clock;
        dec_e$4$r = re$4;
        dec_e$4$q = e$4;
        dec_e$4$ef = efe$4;
        dec_e$4$valid_in = valid_in;
        unit$d$4 = dec_d$4$y;
        unit$e$4 = dec_e$4$y;
        rnd$5$clock = clock;
        rnd$5$d = rnd$5$q;
        if (load_en & (load_addr == at_rnd$5)) begin
            rnd$5$d = load_data[32'hf];
        end
        dec_d$5$round_up = rnd$5$q;
        dec_e$5$round_up = rnd$5$q;
        dec_d$5$clock = clock;
        dec_d$5$r = rd$5;
        dec_d$5$q = d$5;
        dec_d$5$ef = efd$5;
        dec_d$5$valid_in = valid_in;
        dec_e$5$clock = clock;
        dec_e$5$r = re$5;
        dec_e$5$q = e$5;
        dec_e$5$ef = efe$5;
        dec_e$5$valid_in = valid_in;
        unit$d$5 = dec_d$5$y;
        unit$e$5 = dec_e$5$y;
        rnd$6$clock = clock;
        rnd$6$d = rnd$6$q;
        if (load_en & (load_addr == at_rnd$6)) begin
            rnd$6$d = load_data[32'hf];
        end
        dec_d$6$round_up = rnd$6$q;
        dec_e$6$round_up = rnd$6$q;
        dec_d$6$clock = clock;
        dec_d$6$r = rd$6;
        dec_d$6$q = d$6;
        dec_d$6$ef = efd$6;
        dec_d$6$valid_in = valid_in;
        dec_e$6$clock = clock;
        dec_e$6$r = re$6;
        dec_e$6$q = e$6;
        dec_e$6$ef = efe$6;
        dec_e$6$valid_in = valid_in;
        unit$d$6 = dec_d$6$y;
        unit$e$6 = dec_e$6$y;
        rnd$7$clock = clock;
        rnd$7$d = rnd$7$q;
        if (load_en & (load_addr == at_rnd$7)) begin
            rnd$7$d = load_data[32'hf];
        end
        dec_d$7$round_up = rnd$7$q;
        dec_e$7$round_up = rnd$7$q;
        dec_d$7$clock = clock;
        dec_d$7$r = rd$7;
        dec_d$7$q = d$7;
        dec_d$7$ef = efd$7;
        dec_d$7$valid_in = valid_in;
        dec_e$7$clock = clock;
        dec_e$7$r = re$7;
        dec_e$7$q = e$7;
        dec_e$7$ef = efe$7;
        dec_e$7$valid_in = valid_in;
        unit$d$7 = dec_d$7$y;
        unit$e$7 = dec_e$7$y;
        rnd$8$clock = clock;
        rnd$8$d = rnd$8$q;
        if (load_en & (load_addr == at_rnd$8)) begin
            rnd$8$d = load_data[32'hf];
        end
        dec_d$8$round_up = rnd$8$q;
        dec_e$8$round_up = rnd$8$q;
        dec_d$8$clock = clock;
        dec_d$8$r = rd$8;
        dec_d$8$q = d$8;
        dec_d$8$ef = efd$8;
        dec_d$8$valid_in = valid_in;
        dec_e$8$clock = clock;
        dec_e$8$r = re$8;
        dec_e$8$q = e$8;
        dec_e$8$ef = efe$8;
        dec_e$8$valid_in = valid_in;
        unit$d$8 = dec_d$8$y;
        unit$e$8 = dec_e$8$y;
        rnd$9$clock = clock;
        rnd$9$d = rnd$9$q;
        if (load_en & (load_addr == at_rnd$9)) begin
            rnd$9$d = load_data[32'hf];
        end
        dec_d$9$round_up = rnd$9$q;
        dec_e$9$round_up = rnd$9$q;
        dec_d$9$clock = clock;
        dec_d$9$r = rd$9;
        dec_d$9$q = d$9;
        dec_d$9$ef = efd$9;
        dec_d$9$valid_in = valid_in;
        dec_e$9$clock = clock;
        dec_e$9$r = re$9;
        dec_e$9$q = e$9;
        dec_e$9$ef = efe$9;
        dec_e$9$valid_in = valid_in;
        unit$d$9 = dec_d$9$y;
        unit$e$9 = dec_e$9$y;
        rnd$10$clock = clock;
        rnd$10$d = rnd$10$q;
        if (load_en & (load_addr == at_rnd$10)) begin
            rnd$10$d = load_data[32'hf];
        end
        dec_d$10$round_up = rnd$10$q;
        dec_e$10$round_up = rnd$10$q;
        dec_d$10$clock = clock;
        dec_d$10$r = rd$10;
        dec_d$10$q = d$10;
        dec_d$10$ef = efd$10;
        dec_d$10$valid_in = valid_in;
        dec_e$10$clock = clock;
        dec_e$10$r = re$10;
        dec_e$10$q = e$10;
        dec_e$10$ef = efe$10;
        dec_e$10$valid_in = valid_in;
        unit$d$10 = dec_d$10$y;
        unit$e$10 = dec_e$10$y;
        rnd$11$clock = clock;
        rnd$11$d = rnd$11$q;
        if (load_en & (load_addr == at_rnd$11)) begin
            rnd$11$d = load_data[32'hf];
        end
        dec_d$11$round_up = rnd$11$q;
        dec_e$11$round_up = rnd$11$q;
        dec_d$11$clock = clock;
        dec_d$11$r = rd$11;
        dec_d$11$q = d$11;
        dec_d$11$ef = efd$11;
        dec_d$11$valid_in = valid_in;
        dec_e$11$clock = clock;
        dec_e$11$r = re$11;
        dec_e$11$q = e$11;
        dec_e$11$ef = efe$11;
        dec_e$11$valid_in = valid_in;
        unit$d$11 = dec_d$11$y;
        unit$e$11 = dec_e$11$y;
        rnd$12$clock = clock;
        rnd$12$d = rnd$12$q;
        if (load_en & (load_addr == at_rnd$12)) begin
            rnd$12$d = load_data[32'hf];
        end
        dec_d$12$round_up = rnd$12$q;
        dec_e$12$round_up = rnd$12$q;
        dec_d$12$clock = clock;
        dec_d$12$r = rd$12;
        dec_d$12$q = d$12;
        dec_d$12$ef = efd$12;
        dec_d$12$valid_in = valid_in;
        dec_e$12$clock = clock;
        dec_e$12$r = re$12;
        dec_e$12$q = e$12;
        dec_e$12$ef = efe$12;
        dec_e$12$valid_in = valid_in;
        unit$d$12 = dec_d$12$y;
        unit$e$12 = dec_e$12$y;
        rnd$13$clock = clock;
        rnd$13$d = rnd$13$q;
        if (load_en & (load_addr == at_rnd$13)) begin
            rnd$13$d = load_data[32'hf];
        end
        dec_d$13$round_up = rnd$13$q;
        dec_e$13$round_up = rnd$13$q;
        dec_d$13$clock = clock;
        dec_d$13$r = rd$13;
        dec_d$13$q = d$13;
        dec_d$13$ef = efd$13;
        dec_d$13$valid_in = valid_in;
        dec_e$13$clock = clock;
        dec_e$13$r = re$13;
        dec_e$13$q = e$13;
        dec_e$13$ef = efe$13;
        dec_e$13$valid_in = valid_in;
        unit$d$13 = dec_d$13$y;
        unit$e$13 = dec_e$13$y;
        rnd$14$clock = clock;
        rnd$14$d = rnd$14$q;
        if (load_en & (load_addr == at_rnd$14)) begin
            rnd$14$d = load_data[32'hf];
        end
        dec_d$14$round_up = rnd$14$q;
        dec_e$14$round_up = rnd$14$q;
        dec_d$14$clock = clock;
        dec_d$14$r = rd$14;
        dec_d$14$q = d$14;
        dec_d$14$ef = efd$14;
        dec_d$14$valid_in = valid_in;
        dec_e$14$clock = clock;
        dec_e$14$r = re$14;
        dec_e$14$q = e$14;
        dec_e$14$ef = efe$14;
        dec_e$14$valid_in = valid_in;
        unit$d$14 = dec_d$14$y;
        unit$e$14 = dec_e$14$y;
        rnd$15$clock = clock;
        rnd$15$d = rnd$15$q;
        if (load_en & (load_addr == at_rnd$15)) begin
            rnd$15$d = load_data[32'hf];
        end
        dec_d$15$round_up = rnd$15$q;
        dec_e$15$round_up = rnd$15$q;
        dec_d$15$clock = clock;
        dec_d$15$r = rd$15;
        dec_d$15$q = d$15;
        dec_d$15$ef = efd$15;
        dec_d$15$valid_in = valid_in;
        dec_e$15$clock = clock;
        dec_e$15$r = re$15;
        dec_e$15$q = e$15;
        dec_e$15$ef = efe$15;
        dec_e$15$valid_in = valid_in;
        unit$d$15 = dec_d$15$y;
        unit$e$15 = dec_e$15$y;
        rnd$16$clock = clock;
        rnd$16$d = rnd$16$q;
        if (load_en & (load_addr == at_rnd$16)) begin
            rnd$16$d = load_data[32'hf];
        end
        dec_d$16$round_up = rnd$16$q;
        dec_e$16$round_up = rnd$16$q;
        dec_d$16$clock = clock;
        dec_d$16$r = rd$16;
        dec_d$16$q = d$16;
        dec_d$16$ef = efd$16;
        dec_d$16$valid_in = valid_in;
        dec_e$16$clock = clock;
        dec_e$16$r = re$16;
        dec_e$16$q = e$16;
        dec_e$16$ef = efe$16;
        dec_e$16$valid_in = valid_in;
        unit$d$16 = dec_d$16$y;
        unit$e$16 = dec_e$16$y;
        rnd$17$clock = clock;
        rnd$17$d = rnd$17$q;
        if (load_en & (load_addr == at_rnd$17)) begin
            rnd$17$d = load_data[32'hf];
        end
        dec_d$17$round_up = rnd$17$q;
        dec_e$17$round_up = rnd$17$q;
        dec_d$17$clock = clock;
        dec_d$17$r = rd$17;
        dec_d$17$q = d$17;
        dec_d$17$ef = efd$17;
        dec_d$17$valid_in = valid_in;
        dec_e$17$clock = clock;
        dec_e$17$r = re$17;
        dec_e$17$q = e$17;
        dec_e$17$ef = efe$17;
        dec_e$17$valid_in = valid_in;
        unit$d$17 = dec_d$17$y;
        unit$e$17 = dec_e$17$y;
        rnd$18$clock = clock;
        rnd$18$d = rnd$18$q;
        if (load_en & (load_addr == at_rnd$18)) begin
            rnd$18$d = load_data[32'hf];
        end
        dec_d$18$round_up = rnd$18$q;
        dec_e$18$round_up = rnd$18$q;
        dec_d$18$clock = clock;
        dec_d$18$r = rd$18;
        dec_d$18$q = d$18;
        dec_d$18$ef = efd$18;
        dec_d$18$valid_in = valid_in;
        dec_e$18$clock = clock;
        dec_e$18$r = re$18;
        dec_e$18$q = e$18;
        dec_e$18$ef = efe$18;
        dec_e$18$valid_in = valid_in;
        unit$d$18 = dec_d$18$y;
        unit$e$18 = dec_e$18$y;
        rnd$19$clock = clock;
        rnd$19$d = rnd$19$q;
        if (load_en & (load_addr == at_rnd$19)) begin
            rnd$19$d = load_data[32'hf];
        end
        dec_d$19$round_up = rnd$19$q;
        dec_e$19$round_up = rnd$19$q;
        dec_d$19$clock = clock;
        dec_d$19$r = rd$19;
        dec_d$19$q = d$19;
        dec_d$19$ef = efd$19;
        dec_d$19$valid_in = valid_in;
        dec_e$19$clock = clock;
        dec_e$19$r = re$19;
        dec_e$19$q = e$19;
        dec_e$19$ef = efe$19;
        dec_e$19$valid_in = valid_in;
        unit$d$19 = dec_d$19$y;
        unit$e$19 = dec_e$19$y;
        rnd$20$clock = clock;
        rnd$20$d = rnd$20$q;
        if (load_en & (load_addr == at_rnd$20)) begin
            rnd$20$d = load_data[32'hf];
        end
        dec_d$20$round_up = rnd$20$q;
        dec_e$20$round_up = rnd$20$q;
        dec_d$20$clock = clock;
        dec_d$20$r = rd$20;
        dec_d$20$q = d$20;
        dec_d$20$ef = efd$20;
        dec_d$20$valid_in = valid_in;
        dec_e$20$clock = clock;
        dec_e$20$r = re$20;
        dec_e$20$q = e$20;
        dec_e$20$ef = efe$20;
        dec_e$20$valid_in = valid_in;
        unit$d$20 = dec_d$20$y;
        unit$e$20 = dec_e$20$y;
        rnd$21$clock = clock;
        rnd$21$d = rnd$21$q;
        if (load_en & (load_addr == at_rnd$21)) begin
            rnd$21$d = load_data[32'hf];
        end
        dec_d$21$round_up = rnd$21$q;
        dec_e$21$round_up = rnd$21$q;
        dec_d$21$clock = clock;
        dec_d$21$r = rd$21;
        dec_d$21$q = d$21;
        dec_d$21$ef = efd$21;
        dec_d$21$valid_in = valid_in;
        dec_e$21$clock = clock;
        dec_e$21$r = re$21;
        dec_e$21$q = e$21;
        dec_e$21$ef = efe$21;
        dec_e$21$valid_in = valid_in;
        unit$d$21 = dec_d$21$y;
        unit$e$21 = dec_e$21$y;
        rnd$22$clock = clock;
        rnd$22$d = rnd$22$q;
        if (load_en & (load_addr == at_rnd$22)) begin
            rnd$22$d = load_data[32'hf];
        end
        dec_d$22$round_up = rnd$22$q;
        dec_e$22$round_up = rnd$22$q;
        dec_d$22$clock = clock;
        dec_d$22$r = rd$22;
        dec_d$22$q = d$22;
        dec_d$22$ef = efd$22;
        dec_d$22$valid_in = valid_in;
        dec_e$22$clock = clock;
        dec_e$22$r = re$22;
        dec_e$22$q = e$22;
        dec_e$22$ef = efe$22;
        dec_e$22$valid_in = valid_in;
        unit$d$22 = dec_d$22$y;
        unit$e$22 = dec_e$22$y;
        rnd$23$clock = clock;
        rnd$23$d = rnd$23$q;
        if (load_en & (load_addr == at_rnd$23)) begin
            rnd$23$d = load_data[32'hf];
        end
        dec_d$23$round_up = rnd$23$q;
        dec_e$23$round_up = rnd$23$q;
        dec_d$23$clock = clock;
        dec_d$23$r = rd$23;
        dec_d$23$q = d$23;
        dec_d$23$ef = efd$23;
        dec_d$23$valid_in = valid_in;
        dec_e$23$clock = clock;
        dec_e$23$r = re$23;
        dec_e$23$q = e$23;
        dec_e$23$ef = efe$23;
        dec_e$23$valid_in = valid_in;
        unit$d$23 = dec_d$23$y;
        unit$e$23 = dec_e$23$y;
        tag_dec$d = tag;
        unit$load_en = load_en;
        unit$load_addr = load_addr;
        unit$load_data = load_data;
        unit$tag = tag_dec$q;
        unit$valid_in = dec_d$0$valid_out;
        overlap = unit$overlap;
        tag_out = unit$tag_out;
        valid_out = unit$valid_out;
    end
    
endmodule // top$dop


module top$dop$dec_d$0(clock,r,q,ef,valid_in,round_up,y,valid_out);
    
    // Module arguments
    input wire  clock;
    input wire  [31:0] r;
    input wire  [3:0] q;
    input wire  [8:0] ef;
    input wire  valid_in;
    input wire  round_up;
    output reg  [31:0] y;
    output reg  valid_out;
    
    // Constant declarations
    localparam  c_f = 16'h17;
    localparam  c_b = 16'h4;
    
    // Stub signals
    reg  [31:0] s0_r$d;
    wire  [31:0] s0_r$q;
    reg  s0_r$clock;
    reg  [3:0] s0_q$d;
    wire  [3:0] s0_q$q;
    reg  s0_q$clock;
    reg  [8:0] s0_ef$d;
    wire  [8:0] s0_ef$q;
    reg  s0_ef$clock;
    reg  s0_valid$d;
    wire  s0_valid$q;
    reg  s0_valid$clock;
    reg  s0_round$d;
    wire  s0_round$q;
    reg  s0_round$clock;
    reg  r_add$clock;
    reg  r_add$d;
    wire  r_add$q;
    reg  add$clock;
    reg  [31:0] add$a;
    reg  [31:0] add$b;
    reg  add$sub;
    reg  add$valid_in;
    wire  [31:0] add$y;
    wire  add$valid_out;
    reg  add$round_up;
    
    // Local signals
    reg  [3:0] norm$0;
    reg  [3:0] norm$1;
    reg  [3:0] norm$2;
    reg  [3:0] norm$3;
    reg  [15:0] lz$0;
    reg  [15:0] lz$1;
    reg  [15:0] lz$2;
    reg  [15:0] lz$3;
    reg  [15:0] expo;
    reg  [22:0] frac;
    reg  [31:0] step;
    
    // Sub module instances
    top$cnt_dop$total s0_r(
        .d(s0_r$d),
        .q(s0_r$q),
        .clock(s0_r$clock)
    );
    top$d_cntr$ahd_fetch$row$0 s0_q(
        .d(s0_q$d),
        .q(s0_q$q),
        .clock(s0_q$clock)
    );
    top$dop$dec_d$0$s0_ef s0_ef(
        .d(s0_ef$d),
        .q(s0_ef$q),
        .clock(s0_ef$clock)
    );
    top$cnt_dop$pending s0_valid(
        .d(s0_valid$d),
        .q(s0_valid$q),
        .clock(s0_valid$clock)
    );
    top$cnt_dop$pending s0_round(
        .d(s0_round$d),
        .q(s0_round$q),
        .clock(s0_round$clock)
    );
    top$dop$dec_d$0$r_add r_add(
        .clock(r_add$clock),
        .d(r_add$d),
        .q(r_add$q)
    );
    top$dop$dec_d$0$add add(
        .clock(add$clock),
        .a(add$a),
        .b(add$b),
        .sub(add$sub),
        .valid_in(add$valid_in),
        .y(add$y),
        .valid_out(add$valid_out),
        .round_up(add$round_up)
    );
    
    // Update code
    always @(*) begin
        add$clock = clock;
        r_add$clock = clock;
        s0_r$clock = clock;
        s0_q$clock = clock;
        s0_ef$clock = clock;
        s0_valid$clock = clock;
        s0_round$clock = clock;
        s0_r$d = s0_r$q;
        s0_q$d = s0_q$q;
        s0_ef$d = s0_ef$q;
        s0_valid$d = s0_valid$q;
        s0_round$d = s0_round$q;
        s0_round$d = round_up;
        r_add$d = s0_round$q;
        add$round_up = r_add$q;
        s0_r$d = r;
        s0_q$d = q;
        s0_ef$d = ef;
        s0_valid$d = valid_in;
        norm$0 = s0_q$q;
        lz$0 = 32'h0;
        norm$1 = norm$0;
        lz$1 = lz$0;
        if (~norm$0[32'h4 - 32'h1]) begin
            norm$1 = norm$0 << 32'h1;
            lz$1 = lz$0 + 32'h1;
        end
        norm$2 = norm$1;
        lz$2 = lz$1;
        if (~norm$1[32'h4 - 32'h1]) begin
            norm$2 = norm$1 << 32'h1;
            lz$2 = lz$1 + 32'h1;
        end
        norm$3 = norm$2;
        lz$3 = lz$2;
        if (~norm$2[32'h4 - 32'h1]) begin
            norm$3 = norm$2 << 32'h1;
            lz$3 = lz$2 + 32'h1;
        end
        expo = 32'h0;
        frac = ((s0_q$q) & 23'h7fffff) << s0_ef$q;
        if (((s0_ef$q) & 16'hffff) + c_b > c_f + lz$3) begin
            expo = ((s0_ef$q) & 16'hffff) + c_b - lz$3 - c_f;
            frac = ((norm$3) & 23'h7fffff) << (32'h17 + 32'h1 - 32'h4);
        end
        step = (((expo) & 32'hffffffff) << 32'h17) | ((frac) & 32'hffffffff);
        if (s0_q$q == 32'h0) begin
            step = 32'h0;
        end
        add$a = s0_r$q;
        add$b = step;
        add$sub = 1'b1;
        add$valid_in = s0_valid$q;
        y = add$y;
        valid_out = add$valid_out;
    end
    
endmodule // top$dop$dec_d$0


module top$dop$dec_d$0$add(clock,a,b,sub,valid_in,y,valid_out,round_up);
    
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
    top$dop$dec_d$0$add$unpack_a unpack_a(
        .x(unpack_a$x),
        .sign(unpack_a$sign),
        .exp(unpack_a$exp),
        .sig(unpack_a$sig),
        .is_zero(unpack_a$is_zero),
        .is_inf(unpack_a$is_inf),
        .is_nan(unpack_a$is_nan)
    );
    top$dop$dec_d$0$add$unpack_a unpack_b(
        .x(unpack_b$x),
        .sign(unpack_b$sign),
        .exp(unpack_b$exp),
        .sig(unpack_b$sig),
        .is_zero(unpack_b$is_zero),
        .is_inf(unpack_b$is_inf),
        .is_nan(unpack_b$is_nan)
    );
    top$cnt_dop$pending s1_valid(
        .d(s1_valid$d),
        .q(s1_valid$q),
        .clock(s1_valid$clock)
    );
    top$cnt_dop$pending s1_nan(
        .d(s1_nan$d),
        .q(s1_nan$q),
        .clock(s1_nan$clock)
    );
    top$cnt_dop$pending s1_inf(
        .d(s1_inf$d),
        .q(s1_inf$q),
        .clock(s1_inf$clock)
    );
    top$cnt_dop$pending s1_inf_sign(
        .d(s1_inf_sign$d),
        .q(s1_inf_sign$q),
        .clock(s1_inf_sign$clock)
    );
    top$cnt_dop$pending s1_zero_sign(
        .d(s1_zero_sign$d),
        .q(s1_zero_sign$q),
        .clock(s1_zero_sign$clock)
    );
    top$cnt_dop$pending s1_sign(
        .d(s1_sign$d),
        .q(s1_sign$q),
        .clock(s1_sign$clock)
    );
    top$cnt_dop$pending s1_eff_sub(
        .d(s1_eff_sub$d),
        .q(s1_eff_sub$q),
        .clock(s1_eff_sub$clock)
    );
    top$dop$dec_d$0$add$s1_exp s1_exp(
        .d(s1_exp$d),
        .q(s1_exp$q),
        .clock(s1_exp$clock)
    );
    top$dop$dec_d$0$add$s1_big s1_big(
        .d(s1_big$d),
        .q(s1_big$q),
        .clock(s1_big$clock)
    );
    top$dop$dec_d$0$add$s1_big s1_small(
        .d(s1_small$d),
        .q(s1_small$q),
        .clock(s1_small$clock)
    );
    top$dop$dec_d$0$add$norm norm(
        .x(norm$x),
        .y(norm$y),
        .lz(norm$lz)
    );
    top$cnt_dop$pending s2_valid(
        .d(s2_valid$d),
        .q(s2_valid$q),
        .clock(s2_valid$clock)
    );
    top$cnt_dop$pending s2_sign(
        .d(s2_sign$d),
        .q(s2_sign$q),
        .clock(s2_sign$clock)
    );
    top$cnt_dop$pending s2_nan(
        .d(s2_nan$d),
        .q(s2_nan$q),
        .clock(s2_nan$clock)
    );
    top$cnt_dop$pending s2_inf(
        .d(s2_inf$d),
        .q(s2_inf$q),
        .clock(s2_inf$clock)
    );
    top$cnt_dop$pending s2_zero(
        .d(s2_zero$d),
        .q(s2_zero$q),
        .clock(s2_zero$clock)
    );
    top$cnt_dop$pending s2_ovf(
        .d(s2_ovf$d),
        .q(s2_ovf$q),
        .clock(s2_ovf$clock)
    );
    top$dop$dec_d$0$add$s1_exp s2_efield(
        .d(s2_efield$d),
        .q(s2_efield$q),
        .clock(s2_efield$clock)
    );
    top$dop$dec_d$0$add$s2_nm s2_nm(
        .d(s2_nm$d),
        .q(s2_nm$q),
        .clock(s2_nm$clock)
    );
    top$dop$dec_d$0$add$round round(
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
    top$cnt_dop$pending s3_valid(
        .d(s3_valid$d),
        .q(s3_valid$q),
        .clock(s3_valid$clock)
    );
    top$cnt_dop$total s3_y(
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
    
endmodule // top$dop$dec_d$0$add


module top$dop$dec_d$0$add$norm(x,y,lz);
    
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
    
endmodule // top$dop$dec_d$0$add$norm


module top$dop$dec_d$0$add$round(round_up,sign,nan,inf,zero,ovf,efield,nm,y);
    
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
    
endmodule // top$dop$dec_d$0$add$round


module top$dop$dec_d$0$add$s1_big(d,q,clock);
    
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
          
endmodule // top$dop$dec_d$0$add$s1_big


module top$dop$dec_d$0$add$s1_exp(d,q,clock);
    
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
          
endmodule // top$dop$dec_d$0$add$s1_exp


module top$dop$dec_d$0$add$s2_nm(d,q,clock);
    
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
          
endmodule // top$dop$dec_d$0$add$s2_nm


module top$dop$dec_d$0$add$unpack_a(x,sign,exp,sig,is_zero,is_inf,is_nan);
    
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
    
endmodule // top$dop$dec_d$0$add$unpack_a


module top$dop$dec_d$0$r_add(clock,d,q);
    
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
    
    // Sub module instances
    top$cnt_dop$pending line$0(
        .d(line$0$d),
        .q(line$0$q),
        .clock(line$0$clock)
    );
    top$cnt_dop$pending line$1(
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
    
endmodule // top$dop$dec_d$0$r_add


module top$dop$dec_d$0$s0_ef(d,q,clock);
    
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
          
endmodule // top$dop$dec_d$0$s0_ef


module top$dop$tag_dec(clock,d,q);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] d;
    output reg  [15:0] q;
    
    // Stub signals
    reg  [15:0] line$0$d;
    wire  [15:0] line$0$q;
    reg  line$0$clock;
    reg  [15:0] line$1$d;
    wire  [15:0] line$1$q;
    reg  line$1$clock;
    reg  [15:0] line$2$d;
    wire  [15:0] line$2$q;
    reg  line$2$clock;
    reg  [15:0] line$3$d;
    wire  [15:0] line$3$q;
    reg  line$3$clock;
    
    // Sub module instances
    top$d_cntr$last_a line$0(
        .d(line$0$d),
        .q(line$0$q),
        .clock(line$0$clock)
    );
    top$d_cntr$last_a line$1(
        .d(line$1$d),
        .q(line$1$q),
        .clock(line$1$clock)
    );
    top$d_cntr$last_a line$2(
        .d(line$2$d),
        .q(line$2$q),
        .clock(line$2$clock)
    );
    top$d_cntr$last_a line$3(
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
    
endmodule // top$dop$tag_dec


module top$dop$unit(clock,load_en,load_addr,load_data,d$0,d$1,d$2,d$3,d$4,d$5,d$6,d$7,d$8,d$9,d$10,d$11,d$12,d$13,d$14,d$15,d$16,d$17,d$18,d$19,d$20,d$21,d$22,d$23,e$0,e$1,e$2,e$3,e$4,e$5,e$6,e$7,e$8,e$9,e$10,e$11,e$12,e$13,e$14,e$15,e$16,e$17,e$18,e$19,e$20,e$21,e$22,e$23,tag,valid_in,overlap,tag_out,valid_out);
    
    // Module arguments
    input wire  clock;
    input wire  load_en;
    input wire  [7:0] load_addr;
    input wire  [31:0] load_data;
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
    input wire  [31:0] e$0;
    input wire  [31:0] e$1;
    input wire  [31:0] e$2;
    input wire  [31:0] e$3;
    input wire  [31:0] e$4;
    input wire  [31:0] e$5;
    input wire  [31:0] e$6;
    input wire  [31:0] e$7;
    input wire  [31:0] e$8;
    input wire  [31:0] e$9;
    input wire  [31:0] e$10;
    input wire  [31:0] e$11;
    input wire  [31:0] e$12;
    input wire  [31:0] e$13;
    input wire  [31:0] e$14;
    input wire  [31:0] e$15;
    input wire  [31:0] e$16;
    input wire  [31:0] e$17;
    input wire  [31:0] e$18;
    input wire  [31:0] e$19;
    input wire  [31:0] e$20;
    input wire  [31:0] e$21;
    input wire  [31:0] e$22;
    input wire  [31:0] e$23;
    input wire  [15:0] tag;
    input wire  valid_in;
    output reg  overlap;
    output reg  [15:0] tag_out;
    output reg  valid_out;
    
    // Stub signals
    reg  setup$clock;
    reg  setup$load_en;
    reg  [7:0] setup$load_addr;
    reg  [31:0] setup$load_data;
    wire  [31:0] setup$c0$0;
    wire  [31:0] setup$c0$1;
    wire  [31:0] setup$c0$2;
    wire  [31:0] setup$c0$3;
    wire  [31:0] setup$c0$4;
    wire  [31:0] setup$c0$5;
    wire  [31:0] setup$c0$6;
    wire  [31:0] setup$c0$7;
    wire  [31:0] setup$c0$8;
    wire  [31:0] setup$c0$9;
    wire  [31:0] setup$c0$10;
    wire  [31:0] setup$c0$11;
    wire  [31:0] setup$c0$12;
    wire  [31:0] setup$c0$13;
    wire  [31:0] setup$c0$14;
    wire  [31:0] setup$c0$15;
    wire  [31:0] setup$c0$16;
    wire  [31:0] setup$c0$17;
    wire  [31:0] setup$c0$18;
    wire  [31:0] setup$c0$19;
    wire  [31:0] setup$c0$20;
    wire  [31:0] setup$c0$21;
    wire  [31:0] setup$c0$22;
    wire  [31:0] setup$c0$23;
    wire  [31:0] setup$c1$0;
    wire  [31:0] setup$c1$1;
    wire  [31:0] setup$c1$2;
    wire  [31:0] setup$c1$3;
    wire  [31:0] setup$c1$4;
    wire  [31:0] setup$c1$5;
    wire  [31:0] setup$c1$6;
    wire  [31:0] setup$c1$7;
    wire  [31:0] setup$c1$8;
    wire  [31:0] setup$c1$9;
    wire  [31:0] setup$c1$10;
    wire  [31:0] setup$c1$11;
    wire  [31:0] setup$c1$12;
    wire  [31:0] setup$c1$13;
    wire  [31:0] setup$c1$14;
    wire  [31:0] setup$c1$15;
    wire  [31:0] setup$c1$16;
    wire  [31:0] setup$c1$17;
    wire  [31:0] setup$c1$18;
    wire  [31:0] setup$c1$19;
    wire  [31:0] setup$c1$20;
    wire  [31:0] setup$c1$21;
    wire  [31:0] setup$c1$22;
    wire  [31:0] setup$c1$23;
    wire  [31:0] setup$c2$0;
    wire  [31:0] setup$c2$1;
    wire  [31:0] setup$c2$2;
    wire  [31:0] setup$c2$3;
    wire  [31:0] setup$c2$4;
    wire  [31:0] setup$c2$5;
    wire  [31:0] setup$c2$6;
    wire  [31:0] setup$c2$7;
    wire  [31:0] setup$c2$8;
    wire  [31:0] setup$c2$9;
    wire  [31:0] setup$c2$10;
    wire  [31:0] setup$c2$11;
    wire  [31:0] setup$c2$12;
    wire  [31:0] setup$c2$13;
    wire  [31:0] setup$c2$14;
    wire  [31:0] setup$c2$15;
    wire  [31:0] setup$c2$16;
    wire  [31:0] setup$c2$17;
    wire  [31:0] setup$c2$18;
    wire  [31:0] setup$c2$19;
    wire  [31:0] setup$c2$20;
    wire  [31:0] setup$c2$21;
    wire  [31:0] setup$c2$22;
    wire  [31:0] setup$c2$23;
    wire  [31:0] setup$c$0;
    wire  [31:0] setup$c$1;
    wire  [31:0] setup$c$2;
    wire  [31:0] setup$c$3;
    wire  [31:0] setup$c$4;
    wire  [31:0] setup$c$5;
    wire  [31:0] setup$c$6;
    wire  [31:0] setup$c$7;
    wire  [31:0] setup$c$8;
    wire  [31:0] setup$c$9;
    wire  [31:0] setup$c$10;
    wire  [31:0] setup$c$11;
    wire  [31:0] setup$c$12;
    wire  [31:0] setup$c$13;
    wire  [31:0] setup$c$14;
    wire  [31:0] setup$c$15;
    wire  [31:0] setup$c$16;
    wire  [31:0] setup$c$17;
    wire  [31:0] setup$c$18;
    wire  [31:0] setup$c$19;
    wire  [31:0] setup$c$20;
    wire  [31:0] setup$c$21;
    wire  [31:0] setup$c$22;
    wire  [31:0] setup$c$23;
    wire  [4:0] setup$j0$0;
    wire  [4:0] setup$j0$1;
    wire  [4:0] setup$j0$2;
    wire  [4:0] setup$j0$3;
    wire  [4:0] setup$j0$4;
    wire  [4:0] setup$j0$5;
    wire  [4:0] setup$j0$6;
    wire  [4:0] setup$j0$7;
    wire  [4:0] setup$j0$8;
    wire  [4:0] setup$j0$9;
    wire  [4:0] setup$j0$10;
    wire  [4:0] setup$j0$11;
    wire  [4:0] setup$j0$12;
    wire  [4:0] setup$j0$13;
    wire  [4:0] setup$j0$14;
    wire  [4:0] setup$j0$15;
    wire  [4:0] setup$j0$16;
    wire  [4:0] setup$j0$17;
    wire  [4:0] setup$j0$18;
    wire  [4:0] setup$j0$19;
    wire  [4:0] setup$j0$20;
    wire  [4:0] setup$j0$21;
    wire  [4:0] setup$j0$22;
    wire  [4:0] setup$j0$23;
    wire  [4:0] setup$j1$0;
    wire  [4:0] setup$j1$1;
    wire  [4:0] setup$j1$2;
    wire  [4:0] setup$j1$3;
    wire  [4:0] setup$j1$4;
    wire  [4:0] setup$j1$5;
    wire  [4:0] setup$j1$6;
    wire  [4:0] setup$j1$7;
    wire  [4:0] setup$j1$8;
    wire  [4:0] setup$j1$9;
    wire  [4:0] setup$j1$10;
    wire  [4:0] setup$j1$11;
    wire  [4:0] setup$j1$12;
    wire  [4:0] setup$j1$13;
    wire  [4:0] setup$j1$14;
    wire  [4:0] setup$j1$15;
    wire  [4:0] setup$j1$16;
    wire  [4:0] setup$j1$17;
    wire  [4:0] setup$j1$18;
    wire  [4:0] setup$j1$19;
    wire  [4:0] setup$j1$20;
    wire  [4:0] setup$j1$21;
    wire  [4:0] setup$j1$22;
    wire  [4:0] setup$j1$23;
    wire  [4:0] setup$j2$0;
    wire  [4:0] setup$j2$1;
    wire  [4:0] setup$j2$2;
    wire  [4:0] setup$j2$3;
    wire  [4:0] setup$j2$4;
    wire  [4:0] setup$j2$5;
    wire  [4:0] setup$j2$6;
    wire  [4:0] setup$j2$7;
    wire  [4:0] setup$j2$8;
    wire  [4:0] setup$j2$9;
    wire  [4:0] setup$j2$10;
    wire  [4:0] setup$j2$11;
    wire  [4:0] setup$j2$12;
    wire  [4:0] setup$j2$13;
    wire  [4:0] setup$j2$14;
    wire  [4:0] setup$j2$15;
    wire  [4:0] setup$j2$16;
    wire  [4:0] setup$j2$17;
    wire  [4:0] setup$j2$18;
    wire  [4:0] setup$j2$19;
    wire  [4:0] setup$j2$20;
    wire  [4:0] setup$j2$21;
    wire  [4:0] setup$j2$22;
    wire  [4:0] setup$j2$23;
    wire  setup$round_up$0;
    wire  setup$round_up$1;
    wire  setup$round_up$2;
    wire  setup$round_up$3;
    wire  setup$round_up$4;
    wire  setup$round_up$5;
    wire  setup$round_up$6;
    wire  setup$round_up$7;
    wire  setup$round_up$8;
    wire  setup$round_up$9;
    wire  setup$round_up$10;
    wire  setup$round_up$11;
    wire  setup$round_up$12;
    wire  setup$round_up$13;
    wire  setup$round_up$14;
    wire  setup$round_up$15;
    wire  setup$round_up$16;
    wire  setup$round_up$17;
    wire  setup$round_up$18;
    wire  setup$round_up$19;
    wire  setup$round_up$20;
    wire  setup$round_up$21;
    wire  setup$round_up$22;
    wire  setup$round_up$23;
    reg  [31:0] klmsel$d$0;
    reg  [31:0] klmsel$d$1;
    reg  [31:0] klmsel$d$2;
    reg  [31:0] klmsel$d$3;
    reg  [31:0] klmsel$d$4;
    reg  [31:0] klmsel$d$5;
    reg  [31:0] klmsel$d$6;
    reg  [31:0] klmsel$d$7;
    reg  [31:0] klmsel$d$8;
    reg  [31:0] klmsel$d$9;
    reg  [31:0] klmsel$d$10;
    reg  [31:0] klmsel$d$11;
    reg  [31:0] klmsel$d$12;
    reg  [31:0] klmsel$d$13;
    reg  [31:0] klmsel$d$14;
    reg  [31:0] klmsel$d$15;
    reg  [31:0] klmsel$d$16;
    reg  [31:0] klmsel$d$17;
    reg  [31:0] klmsel$d$18;
    reg  [31:0] klmsel$d$19;
    reg  [31:0] klmsel$d$20;
    reg  [31:0] klmsel$d$21;
    reg  [31:0] klmsel$d$22;
    reg  [31:0] klmsel$d$23;
    reg  [4:0] klmsel$j0$0;
    reg  [4:0] klmsel$j0$1;
    reg  [4:0] klmsel$j0$2;
    reg  [4:0] klmsel$j0$3;
    reg  [4:0] klmsel$j0$4;
    reg  [4:0] klmsel$j0$5;
    reg  [4:0] klmsel$j0$6;
    reg  [4:0] klmsel$j0$7;
    reg  [4:0] klmsel$j0$8;
    reg  [4:0] klmsel$j0$9;
    reg  [4:0] klmsel$j0$10;
    reg  [4:0] klmsel$j0$11;
    reg  [4:0] klmsel$j0$12;
    reg  [4:0] klmsel$j0$13;
    reg  [4:0] klmsel$j0$14;
    reg  [4:0] klmsel$j0$15;
    reg  [4:0] klmsel$j0$16;
    reg  [4:0] klmsel$j0$17;
    reg  [4:0] klmsel$j0$18;
    reg  [4:0] klmsel$j0$19;
    reg  [4:0] klmsel$j0$20;
    reg  [4:0] klmsel$j0$21;
    reg  [4:0] klmsel$j0$22;
    reg  [4:0] klmsel$j0$23;
    reg  [4:0] klmsel$j1$0;
    reg  [4:0] klmsel$j1$1;
    reg  [4:0] klmsel$j1$2;
    reg  [4:0] klmsel$j1$3;
    reg  [4:0] klmsel$j1$4;
    reg  [4:0] klmsel$j1$5;
    reg  [4:0] klmsel$j1$6;
    reg  [4:0] klmsel$j1$7;
    reg  [4:0] klmsel$j1$8;
    reg  [4:0] klmsel$j1$9;
    reg  [4:0] klmsel$j1$10;
    reg  [4:0] klmsel$j1$11;
    reg  [4:0] klmsel$j1$12;
    reg  [4:0] klmsel$j1$13;
    reg  [4:0] klmsel$j1$14;
    reg  [4:0] klmsel$j1$15;
    reg  [4:0] klmsel$j1$16;
    reg  [4:0] klmsel$j1$17;
    reg  [4:0] klmsel$j1$18;
    reg  [4:0] klmsel$j1$19;
    reg  [4:0] klmsel$j1$20;
    reg  [4:0] klmsel$j1$21;
    reg  [4:0] klmsel$j1$22;
    reg  [4:0] klmsel$j1$23;
    reg  [4:0] klmsel$j2$0;
    reg  [4:0] klmsel$j2$1;
    reg  [4:0] klmsel$j2$2;
    reg  [4:0] klmsel$j2$3;
    reg  [4:0] klmsel$j2$4;
    reg  [4:0] klmsel$j2$5;
    reg  [4:0] klmsel$j2$6;
    reg  [4:0] klmsel$j2$7;
    reg  [4:0] klmsel$j2$8;
    reg  [4:0] klmsel$j2$9;
    reg  [4:0] klmsel$j2$10;
    reg  [4:0] klmsel$j2$11;
    reg  [4:0] klmsel$j2$12;
    reg  [4:0] klmsel$j2$13;
    reg  [4:0] klmsel$j2$14;
    reg  [4:0] klmsel$j2$15;
    reg  [4:0] klmsel$j2$16;
    reg  [4:0] klmsel$j2$17;
    reg  [4:0] klmsel$j2$18;
    reg  [4:0] klmsel$j2$19;
    reg  [4:0] klmsel$j2$20;
    reg  [4:0] klmsel$j2$21;
    reg  [4:0] klmsel$j2$22;
    reg  [4:0] klmsel$j2$23;
    wire  [31:0] klmsel$y0$0;
    wire  [31:0] klmsel$y0$1;
    wire  [31:0] klmsel$y0$2;
    wire  [31:0] klmsel$y0$3;
    wire  [31:0] klmsel$y0$4;
    wire  [31:0] klmsel$y0$5;
    wire  [31:0] klmsel$y0$6;
    wire  [31:0] klmsel$y0$7;
    wire  [31:0] klmsel$y0$8;
    wire  [31:0] klmsel$y0$9;
    wire  [31:0] klmsel$y0$10;
    wire  [31:0] klmsel$y0$11;
    wire  [31:0] klmsel$y0$12;
    wire  [31:0] klmsel$y0$13;
    wire  [31:0] klmsel$y0$14;
    wire  [31:0] klmsel$y0$15;
    wire  [31:0] klmsel$y0$16;
    wire  [31:0] klmsel$y0$17;
    wire  [31:0] klmsel$y0$18;
    wire  [31:0] klmsel$y0$19;
    wire  [31:0] klmsel$y0$20;
    wire  [31:0] klmsel$y0$21;
    wire  [31:0] klmsel$y0$22;
    wire  [31:0] klmsel$y0$23;
    wire  [31:0] klmsel$y1$0;
    wire  [31:0] klmsel$y1$1;
    wire  [31:0] klmsel$y1$2;
    wire  [31:0] klmsel$y1$3;
    wire  [31:0] klmsel$y1$4;
    wire  [31:0] klmsel$y1$5;
    wire  [31:0] klmsel$y1$6;
    wire  [31:0] klmsel$y1$7;
    wire  [31:0] klmsel$y1$8;
    wire  [31:0] klmsel$y1$9;
    wire  [31:0] klmsel$y1$10;
    wire  [31:0] klmsel$y1$11;
    wire  [31:0] klmsel$y1$12;
    wire  [31:0] klmsel$y1$13;
    wire  [31:0] klmsel$y1$14;
    wire  [31:0] klmsel$y1$15;
    wire  [31:0] klmsel$y1$16;
    wire  [31:0] klmsel$y1$17;
    wire  [31:0] klmsel$y1$18;
    wire  [31:0] klmsel$y1$19;
    wire  [31:0] klmsel$y1$20;
    wire  [31:0] klmsel$y1$21;
    wire  [31:0] klmsel$y1$22;
    wire  [31:0] klmsel$y1$23;
    wire  [31:0] klmsel$y2$0;
    wire  [31:0] klmsel$y2$1;
    wire  [31:0] klmsel$y2$2;
    wire  [31:0] klmsel$y2$3;
    wire  [31:0] klmsel$y2$4;
    wire  [31:0] klmsel$y2$5;
    wire  [31:0] klmsel$y2$6;
    wire  [31:0] klmsel$y2$7;
    wire  [31:0] klmsel$y2$8;
    wire  [31:0] klmsel$y2$9;
    wire  [31:0] klmsel$y2$10;
    wire  [31:0] klmsel$y2$11;
    wire  [31:0] klmsel$y2$12;
    wire  [31:0] klmsel$y2$13;
    wire  [31:0] klmsel$y2$14;
    wire  [31:0] klmsel$y2$15;
    wire  [31:0] klmsel$y2$16;
    wire  [31:0] klmsel$y2$17;
    wire  [31:0] klmsel$y2$18;
    wire  [31:0] klmsel$y2$19;
    wire  [31:0] klmsel$y2$20;
    wire  [31:0] klmsel$y2$21;
    wire  [31:0] klmsel$y2$22;
    wire  [31:0] klmsel$y2$23;
    reg  doptrf$0$clock;
    reg  [31:0] doptrf$0$d0;
    reg  [31:0] doptrf$0$d1;
    reg  [31:0] doptrf$0$d2;
    reg  [31:0] doptrf$0$c0;
    reg  [31:0] doptrf$0$c1;
    reg  [31:0] doptrf$0$c2;
    reg  [31:0] doptrf$0$c;
    reg  [31:0] doptrf$0$e;
    reg  doptrf$0$valid_in;
    reg  doptrf$0$round_up;
    wire  [31:0] doptrf$0$s;
    wire  doptrf$0$flag;
    wire  doptrf$0$valid_out;
    reg  doptrf$1$clock;
    reg  [31:0] doptrf$1$d0;
    reg  [31:0] doptrf$1$d1;
    reg  [31:0] doptrf$1$d2;
    reg  [31:0] doptrf$1$c0;
    reg  [31:0] doptrf$1$c1;
    reg  [31:0] doptrf$1$c2;
    reg  [31:0] doptrf$1$c;
    reg  [31:0] doptrf$1$e;
    reg  doptrf$1$valid_in;
    reg  doptrf$1$round_up;
    wire  [31:0] doptrf$1$s;
    wire  doptrf$1$flag;
    wire  doptrf$1$valid_out;
    reg  doptrf$2$clock;
    reg  [31:0] doptrf$2$d0;
    reg  [31:0] doptrf$2$d1;
    reg  [31:0] doptrf$2$d2;
    reg  [31:0] doptrf$2$c0;
    reg  [31:0] doptrf$2$c1;
    reg  [31:0] doptrf$2$c2;
    reg  [31:0] doptrf$2$c;
    reg  [31:0] doptrf$2$e;
    reg  doptrf$2$valid_in;
    reg  doptrf$2$round_up;
    wire  [31:0] doptrf$2$s;
    wire  doptrf$2$flag;
    wire  doptrf$2$valid_out;
    reg  doptrf$3$clock;
    reg  [31:0] doptrf$3$d0;
    reg  [31:0] doptrf$3$d1;
    reg  [31:0] doptrf$3$d2;
    reg  [31:0] doptrf$3$c0;
    reg  [31:0] doptrf$3$c1;
    reg  [31:0] doptrf$3$c2;
    reg  [31:0] doptrf$3$c;
    reg  [31:0] doptrf$3$e;
    reg  doptrf$3$valid_in;
    reg  doptrf$3$round_up;
    wire  [31:0] doptrf$3$s;
    wire  doptrf$3$flag;
    wire  doptrf$3$valid_out;
    reg  doptrf$4$clock;
    reg  [31:0] doptrf$4$d0;
    reg  [31:0] doptrf$4$d1;
    reg  [31:0] doptrf$4$d2;
    reg  [31:0] doptrf$4$c0;
    reg  [31:0] doptrf$4$c1;
    reg  [31:0] doptrf$4$c2;
    reg  [31:0] doptrf$4$c;
    reg  [31:0] doptrf$4$e;
    reg  doptrf$4$valid_in;
    reg  doptrf$4$round_up;
    wire  [31:0] doptrf$4$s;
    wire  doptrf$4$flag;
    wire  doptrf$4$valid_out;
    reg  doptrf$5$clock;
    reg  [31:0] doptrf$5$d0;
    reg  [31:0] doptrf$5$d1;
    reg  [31:0] doptrf$5$d2;
    reg  [31:0] doptrf$5$c0;
    reg  [31:0] doptrf$5$c1;
    reg  [31:0] doptrf$5$c2;
    reg  [31:0] doptrf$5$c;
    reg  [31:0] doptrf$5$e;
    reg  doptrf$5$valid_in;
    reg  doptrf$5$round_up;
    wire  [31:0] doptrf$5$s;
    wire  doptrf$5$flag;
    wire  doptrf$5$valid_out;
    reg  doptrf$6$clock;
    reg  [31:0] doptrf$6$d0;
    reg  [31:0] doptrf$6$d1;
    reg  [31:0] doptrf$6$d2;
    reg  [31:0] doptrf$6$c0;
    reg  [31:0] doptrf$6$c1;
    reg  [31:0] doptrf$6$c2;
    reg  [31:0] doptrf$6$c;
    reg  [31:0] doptrf$6$e;
    reg  doptrf$6$valid_in;
    reg  doptrf$6$round_up;
    wire  [31:0] doptrf$6$s;
    wire  doptrf$6$flag;
    wire  doptrf$6$valid_out;
    reg  doptrf$7$clock;
    reg  [31:0] doptrf$7$d0;
    reg  [31:0] doptrf$7$d1;
    reg  [31:0] doptrf$7$d2;
    reg  [31:0] doptrf$7$c0;
    reg  [31:0] doptrf$7$c1;
    reg  [31:0] doptrf$7$c2;
    reg  [31:0] doptrf$7$c;
    reg  [31:0] doptrf$7$e;
    reg  doptrf$7$valid_in;
    reg  doptrf$7$round_up;
    wire  [31:0] doptrf$7$s;
    wire  doptrf$7$flag;
    wire  doptrf$7$valid_out;
    reg  doptrf$8$clock;
    reg  [31:0] doptrf$8$d0;
    reg  [31:0] doptrf$8$d1;
    reg  [31:0] doptrf$8$d2;
    reg  [31:0] doptrf$8$c0;
    reg  [31:0] doptrf$8$c1;
    reg  [31:0] doptrf$8$c2;
    reg  [31:0] doptrf$8$c;
    reg  [31:0] doptrf$8$e;
    reg  doptrf$8$valid_in;
    reg  doptrf$8$round_up;
    wire  [31:0] doptrf$8$s;
    wire  doptrf$8$flag;
    wire  doptrf$8$valid_out;
    reg  doptrf$9$clock;
    reg  [31:0] doptrf$9$d0;
    reg  [31:0] doptrf$9$d1;
    reg  [31:0] doptrf$9$d2;
    reg  [31:0] doptrf$9$c0;
    reg  [31:0] doptrf$9$c1;
    reg  [31:0] doptrf$9$c2;
    reg  [31:0] doptrf$9$c;
    reg  [31:0] doptrf$9$e;
    reg  doptrf$9$valid_in;
    reg  doptrf$9$round_up;
    wire  [31:0] doptrf$9$s;
    wire  doptrf$9$flag;
    wire  doptrf$9$valid_out;
    reg  doptrf$10$clock;
    reg  [31:0] doptrf$10$d0;
    reg  [31:0] doptrf$10$d1;
    reg  [31:0] doptrf$10$d2;
    reg  [31:0] doptrf$10$c0;
    reg  [31:0] doptrf$10$c1;
    reg  [31:0] doptrf$10$c2;
    reg  [31:0] doptrf$10$c;
    reg  [31:0] doptrf$10$e;
    reg  doptrf$10$valid_in;
    reg  doptrf$10$round_up;
    wire  [31:0] doptrf$10$s;
    wire  doptrf$10$flag;
    wire  doptrf$10$valid_out;
    reg  doptrf$11$clock;
    reg  [31:0] doptrf$11$d0;
    reg  [31:0] doptrf$11$d1;
    reg  [31:0] doptrf$11$d2;
    reg  [31:0] doptrf$11$c0;
    reg  [31:0] doptrf$11$c1;
    reg  [31:0] doptrf$11$c2;
    reg  [31:0] doptrf$11$c;
    reg  [31:0] doptrf$11$e;
    reg  doptrf$11$valid_in;
    reg  doptrf$11$round_up;
    wire  [31:0] doptrf$11$s;
    wire  doptrf$11$flag;
    wire  doptrf$11$valid_out;
    reg  doptrf$12$clock;
    reg  [31:0] doptrf$12$d0;
    reg  [31:0] doptrf$12$d1;
    reg  [31:0] doptrf$12$d2;
    reg  [31:0] doptrf$12$c0;
    reg  [31:0] doptrf$12$c1;
    reg  [31:0] doptrf$12$c2;
    reg  [31:0] doptrf$12$c;
    reg  [31:0] doptrf$12$e;
    reg  doptrf$12$valid_in;
    reg  doptrf$12$round_up;
    wire  [31:0] doptrf$12$s;
    wire  doptrf$12$flag;
    wire  doptrf$12$valid_out;
    reg  doptrf$13$clock;
    reg  [31:0] doptrf$13$d0;
    reg  [31:0] doptrf$13$d1;
    reg  [31:0] doptrf$13$d2;
    reg  [31:0] doptrf$13$c0;
    reg  [31:0] doptrf$13$c1;
    reg  [31:0] doptrf$13$c2;
    reg  [31:0] doptrf$13$c;
    reg  [31:0] doptrf$13$e;
    reg  doptrf$13$valid_in;
    reg  doptrf$13$round_up;
    wire  [31:0] doptrf$13$s;
    wire  doptrf$13$flag;
    wire  doptrf$13$valid_out;
    reg  doptrf$14$clock;
    reg  [31:0] doptrf$14$d0;
    reg  [31:0] doptrf$14$d1;
    reg  [31:0] doptrf$14$d2;
    reg  [31:0] doptrf$14$c0;
    reg  [31:0] doptrf$14$c1;
    reg  [31:0] doptrf$14$c2;
    reg  [31:0] doptrf$14$c;
    reg  [31:0] doptrf$14$e;
    reg  doptrf$14$valid_in;
    reg  doptrf$14$round_up;
    wire  [31:0] doptrf$14$s;
    wire  doptrf$14$flag;
    wire  doptrf$14$valid_out;
    reg  doptrf$15$clock;
    reg  [31:0] doptrf$15$d0;
    reg  [31:0] doptrf$15$d1;
    reg  [31:0] doptrf$15$d2;
    reg  [31:0] doptrf$15$c0;
    reg  [31:0] doptrf$15$c1;
    reg  [31:0] doptrf$15$c2;
    reg  [31:0] doptrf$15$c;
    reg  [31:0] doptrf$15$e;
    reg  doptrf$15$valid_in;
    reg  doptrf$15$round_up;
    wire  [31:0] doptrf$15$s;
    wire  doptrf$15$flag;
    wire  doptrf$15$valid_out;
    reg  doptrf$16$clock;
    reg  [31:0] doptrf$16$d0;
    reg  [31:0] doptrf$16$d1;
    reg  [31:0] doptrf$16$d2;
    reg  [31:0] doptrf$16$c0;
    reg  [31:0] doptrf$16$c1;
    reg  [31:0] doptrf$16$c2;
    reg  [31:0] doptrf$16$c;
    reg  [31:0] doptrf$16$e;
    reg  doptrf$16$valid_in;
    reg  doptrf$16$round_up;
    wire  [31:0] doptrf$16$s;
    wire  doptrf$16$flag;
    wire  doptrf$16$valid_out;
    reg  doptrf$17$clock;
    reg  [31:0] doptrf$17$d0;
    reg  [31:0] doptrf$17$d1;
    reg  [31:0] doptrf$17$d2;
    reg  [31:0] doptrf$17$c0;
    reg  [31:0] doptrf$17$c1;
    reg  [31:0] doptrf$17$c2;
    reg  [31:0] doptrf$17$c;
    reg  [31:0] doptrf$17$e;
    reg  doptrf$17$valid_in;
    reg  doptrf$17$round_up;
    wire  [31:0] doptrf$17$s;
    wire  doptrf$17$flag;
    wire  doptrf$17$valid_out;
    reg  doptrf$18$clock;
    reg  [31:0] doptrf$18$d0;
    reg  [31:0] doptrf$18$d1;
    reg  [31:0] doptrf$18$d2;
    reg  [31:0] doptrf$18$c0;
    reg  [31:0] doptrf$18$c1;
    reg  [31:0] doptrf$18$c2;
    reg  [31:0] doptrf$18$c;
    reg  [31:0] doptrf$18$e;
    reg  doptrf$18$valid_in;
    reg  doptrf$18$round_up;
    wire  [31:0] doptrf$18$s;
    wire  doptrf$18$flag;
    wire  doptrf$18$valid_out;
    reg  doptrf$19$clock;
    reg  [31:0] doptrf$19$d0;
    reg  [31:0] doptrf$19$d1;
    reg  [31:0] doptrf$19$d2;
    reg  [31:0] doptrf$19$c0;
    reg  [31:0] doptrf$19$c1;
    reg  [31:0] doptrf$19$c2;
    reg  [31:0] doptrf$19$c;
    reg  [31:0] doptrf$19$e;
    reg  doptrf$19$valid_in;
    reg  doptrf$19$round_up;
    wire  [31:0] doptrf$19$s;
    wire  doptrf$19$flag;
    wire  doptrf$19$valid_out;
    reg  doptrf$20$clock;
    reg  [31:0] doptrf$20$d0;
    reg  [31:0] doptrf$20$d1;
    reg  [31:0] doptrf$20$d2;
    reg  [31:0] doptrf$20$c0;
    reg  [31:0] doptrf$20$c1;
    reg  [31:0] doptrf$20$c2;
    reg  [31:0] doptrf$20$c;
    reg  [31:0] doptrf$20$e;
    reg  doptrf$20$valid_in;
    reg  doptrf$20$round_up;
    wire  [31:0] doptrf$20$s;
    wire  doptrf$20$flag;
    wire  doptrf$20$valid_out;
    reg  doptrf$21$clock;
    reg  [31:0] doptrf$21$d0;
    reg  [31:0] doptrf$21$d1;
    reg  [31:0] doptrf$21$d2;
    reg  [31:0] doptrf$21$c0;
    reg  [31:0] doptrf$21$c1;
    reg  [31:0] doptrf$21$c2;
    reg  [31:0] doptrf$21$c;
    reg  [31:0] doptrf$21$e;
    reg  doptrf$21$valid_in;
    reg  doptrf$21$round_up;
    wire  [31:0] doptrf$21$s;
    wire  doptrf$21$flag;
    wire  doptrf$21$valid_out;
    reg  doptrf$22$clock;
    reg  [31:0] doptrf$22$d0;
    reg  [31:0] doptrf$22$d1;
    reg  [31:0] doptrf$22$d2;
    reg  [31:0] doptrf$22$c0;
    reg  [31:0] doptrf$22$c1;
    reg  [31:0] doptrf$22$c2;
    reg  [31:0] doptrf$22$c;
    reg  [31:0] doptrf$22$e;
    reg  doptrf$22$valid_in;
    reg  doptrf$22$round_up;
    wire  [31:0] doptrf$22$s;
    wire  doptrf$22$flag;
    wire  doptrf$22$valid_out;
    reg  doptrf$23$clock;
    reg  [31:0] doptrf$23$d0;
    reg  [31:0] doptrf$23$d1;
    reg  [31:0] doptrf$23$d2;
    reg  [31:0] doptrf$23$c0;
    reg  [31:0] doptrf$23$c1;
    reg  [31:0] doptrf$23$c2;
    reg  [31:0] doptrf$23$c;
    reg  [31:0] doptrf$23$e;
    reg  doptrf$23$valid_in;
    reg  doptrf$23$round_up;
    wire  [31:0] doptrf$23$s;
    wire  doptrf$23$flag;
    wire  doptrf$23$valid_out;
    reg  [15:0] tag_1$d;
    wire  [15:0] tag_1$q;
    reg  tag_1$clock;
    reg  [15:0] tag_2$d;
    wire  [15:0] tag_2$q;
    reg  tag_2$clock;
    reg  [15:0] tag_3$d;
    wire  [15:0] tag_3$q;
    reg  tag_3$clock;
    reg  [15:0] tag_4$d;
    wire  [15:0] tag_4$q;
    reg  tag_4$clock;
    reg  [15:0] tag_5$d;
    wire  [15:0] tag_5$q;
    reg  tag_5$clock;
    reg  [15:0] tag_6$d;
    wire  [15:0] tag_6$q;
    reg  tag_6$clock;
    reg  [15:0] tag_7$d;
    wire  [15:0] tag_7$q;
    reg  tag_7$clock;
    reg  [15:0] tag_8$d;
    wire  [15:0] tag_8$q;
    reg  tag_8$clock;
    reg  [15:0] tag_9$d;
    wire  [15:0] tag_9$q;
    reg  tag_9$clock;
    reg  [15:0] tag_10$d;
    wire  [15:0] tag_10$q;
    reg  tag_10$clock;
    reg  [15:0] tag_11$d;
    wire  [15:0] tag_11$q;
    reg  tag_11$clock;
    reg  [15:0] tag_12$d;
    wire  [15:0] tag_12$q;
    reg  tag_12$clock;
    reg  [15:0] tag_13$d;
    wire  [15:0] tag_13$q;
    reg  tag_13$clock;
    reg  [15:0] tag_14$d;
    wire  [15:0] tag_14$q;
    reg  tag_14$clock;
    reg  [15:0] tag_15$d;
    wire  [15:0] tag_15$q;
    reg  tag_15$clock;
    
    // Local signals
    reg  c_any;
    
    // Sub module instances
    top$dop$unit$setup setup(
        .clock(setup$clock),
        .load_en(setup$load_en),
        .load_addr(setup$load_addr),
        .load_data(setup$load_data),
        .c0$0(setup$c0$0),
        .c0$1(setup$c0$1),
        .c0$2(setup$c0$2),
        .c0$3(setup$c0$3),
        .c0$4(setup$c0$4),
        .c0$5(setup$c0$5),
        .c0$6(setup$c0$6),
        .c0$7(setup$c0$7),
        .c0$8(setup$c0$8),
        .c0$9(setup$c0$9),
        .c0$10(setup$c0$10),
        .c0$11(setup$c0$11),
        .c0$12(setup$c0$12),
        .c0$13(setup$c0$13),
        .c0$14(setup$c0$14),
        .c0$15(setup$c0$15),
        .c0$16(setup$c0$16),
        .c0$17(setup$c0$17),
        .c0$18(setup$c0$18),
        .c0$19(setup$c0$19),
        .c0$20(setup$c0$20),
        .c0$21(setup$c0$21),
        .c0$22(setup$c0$22),
        .c0$23(setup$c0$23),
        .c1$0(setup$c1$0),
        .c1$1(setup$c1$1),
        .c1$2(setup$c1$2),
        .c1$3(setup$c1$3),
        .c1$4(setup$c1$4),
        .c1$5(setup$c1$5),
        .c1$6(setup$c1$6),
        .c1$7(setup$c1$7),
        .c1$8(setup$c1$8),
        .c1$9(setup$c1$9),
        .c1$10(setup$c1$10),
        .c1$11(setup$c1$11),
        .c1$12(setup$c1$12),
        .c1$13(setup$c1$13),
        .c1$14(setup$c1$14),
        .c1$15(setup$c1$15),
        .c1$16(setup$c1$16),
        .c1$17(setup$c1$17),
        .c1$18(setup$c1$18),
        .c1$19(setup$c1$19),
        .c1$20(setup$c1$20),
        .c1$21(setup$c1$21),
        .c1$22(setup$c1$22),
        .c1$23(setup$c1$23),
        .c2$0(setup$c2$0),
        .c2$1(setup$c2$1),
        .c2$2(setup$c2$2),
        .c2$3(setup$c2$3),
        .c2$4(setup$c2$4),
        .c2$5(setup$c2$5),
        .c2$6(setup$c2$6),
        .c2$7(setup$c2$7),
        .c2$8(setup$c2$8),
        .c2$9(setup$c2$9),
        .c2$10(setup$c2$10),
        .c2$11(setup$c2$11),
        .c2$12(setup$c2$12),
        .c2$13(setup$c2$13),
        .c2$14(setup$c2$14),
        .c2$15(setup$c2$15),
        .c2$16(setup$c2$16),
        .c2$17(setup$c2$17),
        .c2$18(setup$c2$18),
        .c2$19(setup$c2$19),
        .c2$20(setup$c2$20),
        .c2$21(setup$c2$21),
        .c2$22(setup$c2$22),
        .c2$23(setup$c2$23),
        .c$0(setup$c$0),
        .c$1(setup$c$1),
        .c$2(setup$c$2),
        .c$3(setup$c$3),
        .c$4(setup$c$4),
        .c$5(setup$c$5),
        .c$6(setup$c$6),
        .c$7(setup$c$7),
        .c$8(setup$c$8),
        .c$9(setup$c$9),
        .c$10(setup$c$10),
        .c$11(setup$c$11),
        .c$12(setup$c$12),
        .c$13(setup$c$13),
        .c$14(setup$c$14),
        .c$15(setup$c$15),
        .c$16(setup$c$16),
        .c$17(setup$c$17),
        .c$18(setup$c$18),
        .c$19(setup$c$19),
        .c$20(setup$c$20),
        .c$21(setup$c$21),
        .c$22(setup$c$22),
        .c$23(setup$c$23),
        .j0$0(setup$j0$0),
        .j0$1(setup$j0$1),
        .j0$2(setup$j0$2),
        .j0$3(setup$j0$3),
        .j0$4(setup$j0$4),
        .j0$5(setup$j0$5),
        .j0$6(setup$j0$6),
        .j0$7(setup$j0$7),
        .j0$8(setup$j0$8),
        .j0$9(setup$j0$9),
        .j0$10(setup$j0$10),
        .j0$11(setup$j0$11),
        .j0$12(setup$j0$12),
        .j0$13(setup$j0$13),
        .j0$14(setup$j0$14),
        .j0$15(setup$j0$15),
        .j0$16(setup$j0$16),
        .j0$17(setup$j0$17),
        .j0$18(setup$j0$18),
        .j0$19(setup$j0$19),
        .j0$20(setup$j0$20),
        .j0$21(setup$j0$21),
        .j0$22(setup$j0$22),
        .j0$23(setup$j0$23),
        .j1$0(setup$j1$0),
        .j1$1(setup$j1$1),
        .j1$2(setup$j1$2),
        .j1$3(setup$j1$3),
        .j1$4(setup$j1$4),
        .j1$5(setup$j1$5),
        .j1$6(setup$j1$6),
        .j1$7(setup$j1$7),
        .j1$8(setup$j1$8),
        .j1$9(setup$j1$9),
        .j1$10(setup$j1$10),
        .j1$11(setup$j1$11),
        .j1$12(setup$j1$12),
        .j1$13(setup$j1$13),
        .j1$14(setup$j1$14),
        .j1$15(setup$j1$15),
        .j1$16(setup$j1$16),
        .j1$17(setup$j1$17),
        .j1$18(setup$j1$18),
        .j1$19(setup$j1$19),
        .j1$20(setup$j1$20),
        .j1$21(setup$j1$21),
        .j1$22(setup$j1$22),
        .j1$23(setup$j1$23),
        .j2$0(setup$j2$0),
        .j2$1(setup$j2$1),
        .j2$2(setup$j2$2),
        .j2$3(setup$j2$3),
        .j2$4(setup$j2$4),
        .j2$5(setup$j2$5),
        .j2$6(setup$j2$6),
        .j2$7(setup$j2$7),
        .j2$8(setup$j2$8),
        .j2$9(setup$j2$9),
        .j2$10(setup$j2$10),
        .j2$11(setup$j2$11),
        .j2$12(setup$j2$12),
        .j2$13(setup$j2$13),
        .j2$14(setup$j2$14),
        .j2$15(setup$j2$15),
        .j2$16(setup$j2$16),
        .j2$17(setup$j2$17),
        .j2$18(setup$j2$18),
        .j2$19(setup$j2$19),
        .j2$20(setup$j2$20),
        .j2$21(setup$j2$21),
        .j2$22(setup$j2$22),
        .j2$23(setup$j2$23),
        .round_up$0(setup$round_up$0),
        .round_up$1(setup$round_up$1),
        .round_up$2(setup$round_up$2),
        .round_up$3(setup$round_up$3),
        .round_up$4(setup$round_up$4),
        .round_up$5(setup$round_up$5),
        .round_up$6(setup$round_up$6),
        .round_up$7(setup$round_up$7),
        .round_up$8(setup$round_up$8),
        .round_up$9(setup$round_up$9),
        .round_up$10(setup$round_up$10),
        .round_up$11(setup$round_up$11),
        .round_up$12(setup$round_up$12),
        .round_up$13(setup$round_up$13),
        .round_up$14(setup$round_up$14),
        .round_up$15(setup$round_up$15),
        .round_up$16(setup$round_up$16),
        .round_up$17(setup$round_up$17),
        .round_up$18(setup$round_up$18),
        .round_up$19(setup$round_up$19),
        .round_up$20(setup$round_up$20),
        .round_up$21(setup$round_up$21),
        .round_up$22(setup$round_up$22),
        .round_up$23(setup$round_up$23)
    );
    top$dop$unit$klmsel klmsel(
        .d$0(klmsel$d$0),
        .d$1(klmsel$d$1),
        .d$2(klmsel$d$2),
        .d$3(klmsel$d$3),
        .d$4(klmsel$d$4),
        .d$5(klmsel$d$5),
        .d$6(klmsel$d$6),
        .d$7(klmsel$d$7),
        .d$8(klmsel$d$8),
        .d$9(klmsel$d$9),
        .d$10(klmsel$d$10),
        .d$11(klmsel$d$11),
        .d$12(klmsel$d$12),
        .d$13(klmsel$d$13),
        .d$14(klmsel$d$14),
        .d$15(klmsel$d$15),
        .d$16(klmsel$d$16),
        .d$17(klmsel$d$17),
        .d$18(klmsel$d$18),
        .d$19(klmsel$d$19),
        .d$20(klmsel$d$20),
        .d$21(klmsel$d$21),
        .d$22(klmsel$d$22),
        .d$23(klmsel$d$23),
        .j0$0(klmsel$j0$0),
        .j0$1(klmsel$j0$1),
        .j0$2(klmsel$j0$2),
        .j0$3(klmsel$j0$3),
        .j0$4(klmsel$j0$4),
        .j0$5(klmsel$j0$5),
        .j0$6(klmsel$j0$6),
        .j0$7(klmsel$j0$7),
        .j0$8(klmsel$j0$8),
        .j0$9(klmsel$j0$9),
        .j0$10(klmsel$j0$10),
        .j0$11(klmsel$j0$11),
        .j0$12(klmsel$j0$12),
        .j0$13(klmsel$j0$13),
        .j0$14(klmsel$j0$14),
        .j0$15(klmsel$j0$15),
        .j0$16(klmsel$j0$16),
        .j0$17(klmsel$j0$17),
        .j0$18(klmsel$j0$18),
        .j0$19(klmsel$j0$19),
        .j0$20(klmsel$j0$20),
        .j0$21(klmsel$j0$21),
        .j0$22(klmsel$j0$22),
        .j0$23(klmsel$j0$23),
        .j1$0(klmsel$j1$0),
        .j1$1(klmsel$j1$1),
        .j1$2(klmsel$j1$2),
        .j1$3(klmsel$j1$3),
        .j1$4(klmsel$j1$4),
        .j1$5(klmsel$j1$5),
        .j1$6(klmsel$j1$6),
        .j1$7(klmsel$j1$7),
        .j1$8(klmsel$j1$8),
        .j1$9(klmsel$j1$9),
        .j1$10(klmsel$j1$10),
        .j1$11(klmsel$j1$11),
        .j1$12(klmsel$j1$12),
        .j1$13(klmsel$j1$13),
        .j1$14(klmsel$j1$14),
        .j1$15(klmsel$j1$15),
        .j1$16(klmsel$j1$16),
        .j1$17(klmsel$j1$17),
        .j1$18(klmsel$j1$18),
        .j1$19(klmsel$j1$19),
        .j1$20(klmsel$j1$20),
        .j1$21(klmsel$j1$21),
        .j1$22(klmsel$j1$22),
        .j1$23(klmsel$j1$23),
        .j2$0(klmsel$j2$0),
        .j2$1(klmsel$j2$1),
        .j2$2(klmsel$j2$2),
        .j2$3(klmsel$j2$3),
        .j2$4(klmsel$j2$4),
        .j2$5(klmsel$j2$5),
        .j2$6(klmsel$j2$6),
        .j2$7(klmsel$j2$7),
        .j2$8(klmsel$j2$8),
        .j2$9(klmsel$j2$9),
        .j2$10(klmsel$j2$10),
        .j2$11(klmsel$j2$11),
        .j2$12(klmsel$j2$12),
        .j2$13(klmsel$j2$13),
        .j2$14(klmsel$j2$14),
        .j2$15(klmsel$j2$15),
        .j2$16(klmsel$j2$16),
        .j2$17(klmsel$j2$17),
        .j2$18(klmsel$j2$18),
        .j2$19(klmsel$j2$19),
        .j2$20(klmsel$j2$20),
        .j2$21(klmsel$j2$21),
        .j2$22(klmsel$j2$22),
        .j2$23(klmsel$j2$23),
        .y0$0(klmsel$y0$0),
        .y0$1(klmsel$y0$1),
        .y0$2(klmsel$y0$2),
        .y0$3(klmsel$y0$3),
        .y0$4(klmsel$y0$4),
        .y0$5(klmsel$y0$5),
        .y0$6(klmsel$y0$6),
        .y0$7(klmsel$y0$7),
        .y0$8(klmsel$y0$8),
        .y0$9(klmsel$y0$9),
        .y0$10(klmsel$y0$10),
        .y0$11(klmsel$y0$11),
        .y0$12(klmsel$y0$12),
        .y0$13(klmsel$y0$13),
        .y0$14(klmsel$y0$14),
        .y0$15(klmsel$y0$15),
        .y0$16(klmsel$y0$16),
        .y0$17(klmsel$y0$17),
        .y0$18(klmsel$y0$18),
        .y0$19(klmsel$y0$19),
        .y0$20(klmsel$y0$20),
        .y0$21(klmsel$y0$21),
        .y0$22(klmsel$y0$22),
        .y0$23(klmsel$y0$23),
        .y1$0(klmsel$y1$0),
        .y1$1(klmsel$y1$1),
        .y1$2(klmsel$y1$2),
        .y1$3(klmsel$y1$3),
        .y1$4(klmsel$y1$4),
        .y1$5(klmsel$y1$5),
        .y1$6(klmsel$y1$6),
        .y1$7(klmsel$y1$7),
        .y1$8(klmsel$y1$8),
        .y1$9(klmsel$y1$9),
        .y1$10(klmsel$y1$10),
        .y1$11(klmsel$y1$11),
        .y1$12(klmsel$y1$12),
        .y1$13(klmsel$y1$13),
        .y1$14(klmsel$y1$14),
        .y1$15(klmsel$y1$15),
        .y1$16(klmsel$y1$16),
        .y1$17(klmsel$y1$17),
        .y1$18(klmsel$y1$18),
        .y1$19(klmsel$y1$19),
        .y1$20(klmsel$y1$20),
        .y1$21(klmsel$y1$21),
        .y1$22(klmsel$y1$22),
        .y1$23(klmsel$y1$23),
        .y2$0(klmsel$y2$0),
        .y2$1(klmsel$y2$1),
        .y2$2(klmsel$y2$2),
        .y2$3(klmsel$y2$3),
        .y2$4(klmsel$y2$4),
        .y2$5(klmsel$y2$5),
        .y2$6(klmsel$y2$6),
        .y2$7(klmsel$y2$7),
        .y2$8(klmsel$y2$8),
        .y2$9(klmsel$y2$9),
        .y2$10(klmsel$y2$10),
        .y2$11(klmsel$y2$11),
        .y2$12(klmsel$y2$12),
        .y2$13(klmsel$y2$13),
        .y2$14(klmsel$y2$14),
        .y2$15(klmsel$y2$15),
        .y2$16(klmsel$y2$16),
        .y2$17(klmsel$y2$17),
        .y2$18(klmsel$y2$18),
        .y2$19(klmsel$y2$19),
        .y2$20(klmsel$y2$20),
        .y2$21(klmsel$y2$21),
        .y2$22(klmsel$y2$22),
        .y2$23(klmsel$y2$23)
    );
    top$dop$unit$doptrf$0 doptrf$0(
        .clock(doptrf$0$clock),
        .d0(doptrf$0$d0),
        .d1(doptrf$0$d1),
        .d2(doptrf$0$d2),
        .c0(doptrf$0$c0),
        .c1(doptrf$0$c1),
        .c2(doptrf$0$c2),
        .c(doptrf$0$c),
        .e(doptrf$0$e),
        .valid_in(doptrf$0$valid_in),
        .round_up(doptrf$0$round_up),
        .s(doptrf$0$s),
        .flag(doptrf$0$flag),
        .valid_out(doptrf$0$valid_out)
    );
    top$dop$unit$doptrf$0 doptrf$1(
        .clock(doptrf$1$clock),
        .d0(doptrf$1$d0),
        .d1(doptrf$1$d1),
        .d2(doptrf$1$d2),
        .c0(doptrf$1$c0),
        .c1(doptrf$1$c1),
        .c2(doptrf$1$c2),
        .c(doptrf$1$c),
        .e(doptrf$1$e),
        .valid_in(doptrf$1$valid_in),
        .round_up(doptrf$1$round_up),
        .s(doptrf$1$s),
        .flag(doptrf$1$flag),
        .valid_out(doptrf$1$valid_out)
    );
    top$dop$unit$doptrf$0 doptrf$2(
        .clock(doptrf$2$clock),
        .d0(doptrf$2$d0),
        .d1(doptrf$2$d1),
        .d2(doptrf$2$d2),
        .c0(doptrf$2$c0),
        .c1(doptrf$2$c1),
        .c2(doptrf$2$c2),
        .c(doptrf$2$c),
        .e(doptrf$2$e),
        .valid_in(doptrf$2$valid_in),
        .round_up(doptrf$2$round_up),
        .s(doptrf$2$s),
        .flag(doptrf$2$flag),
        .valid_out(doptrf$2$valid_out)
    );
    top$dop$unit$doptrf$0 doptrf$3(
        .clock(doptrf$3$clock),
        .d0(doptrf$3$d0),
        .d1(doptrf$3$d1),
        .d2(doptrf$3$d2),
        .c0(doptrf$3$c0),
        .c1(doptrf$3$c1),
        .c2(doptrf$3$c2),
        .c(doptrf$3$c),
        .e(doptrf$3$e),
        .valid_in(doptrf$3$valid_in),
        .round_up(doptrf$3$round_up),
        .s(doptrf$3$s),
        .flag(doptrf$3$flag),
        .valid_out(doptrf$3$valid_out)
    );
    top$dop$unit$doptrf$0 doptrf$4(
        .clock(doptrf$4$clock),
        .d0(doptrf$4$d0),
        .d1(doptrf$4$d1),
        .d2(doptrf$4$d2),
        .c0(doptrf$4$c0),
        .c1(doptrf$4$c1),
        .c2(doptrf$4$c2),
        .c(doptrf$4$c),
        .e(doptrf$4$e),
        .valid_in(doptrf$4$valid_in),
        .round_up(doptrf$4$round_up),
        .s(doptrf$4$s),
        .flag(doptrf$4$flag),
        .valid_out(doptrf$4$valid_out)
    );
    top$dop$unit$doptrf$0 doptrf$5(
        .clock(doptrf$5$clock),
        .d0(doptrf$5$d0),
        .d1(doptrf$5$d1),
        .d2(doptrf$5$d2),
        .c0(doptrf$5$c0),
        .c1(doptrf$5$c1),
        .c2(doptrf$5$c2),
        .c(doptrf$5$c),
        .e(doptrf$5$e),
        .valid_in(doptrf$5$valid_in),
        .round_up(doptrf$5$round_up),
        .s(doptrf$5$s),
        .flag(doptrf$5$flag),
        .valid_out(doptrf$5$valid_out)
    );
    top$dop$unit$doptrf$0 doptrf$6(
        .clock(doptrf$6$clock),
        .d0(doptrf$6$d0),
        .d1(doptrf$6$d1),
        .d2(doptrf$6$d2),
        .c0(doptrf$6$c0),
        .c1(doptrf$6$c1),
        .c2(doptrf$6$c2),
        .c(doptrf$6$c),
        .e(doptrf$6$e),
        .valid_in(doptrf$6$valid_in),
        .round_up(doptrf$6$round_up),
        .s(doptrf$6$s),
        .flag(doptrf$6$flag),
        .valid_out(doptrf$6$valid_out)
    );
    top$dop$unit$doptrf$0 doptrf$7(
        .clock(doptrf$7$clock),
        .d0(doptrf$7$d0),
        .d1(doptrf$7$d1),
        .d2(doptrf$7$d2),
        .c0(doptrf$7$c0),
        .c1(doptrf$7$c1),
        .c2(doptrf$7$c2),
        .c(doptrf$7$c),
        .e(doptrf$7$e),
        .valid_in(doptrf$7$valid_in),
        .round_up(doptrf$7$round_up),
        .s(doptrf$7$s),
        .flag(doptrf$7$flag),
        .valid_out(doptrf$7$valid_out)
    );
    top$dop$unit$doptrf$0 doptrf$8(
        .clock(doptrf$8$clock),
        .d0(doptrf$8$d0),
        .d1(doptrf$8$d1),
        .d2(doptrf$8$d2),
        .c0(doptrf$8$c0),
        .c1(doptrf$8$c1),
        .c2(doptrf$8$c2),
        .c(doptrf$8$c),
        .e(doptrf$8$e),
        .valid_in(doptrf$8$valid_in),
        .round_up(doptrf$8$round_up),
        .s(doptrf$8$s),
        .flag(doptrf$8$flag),
        .valid_out(doptrf$8$valid_out)
    );
    top$dop$unit$doptrf$0 doptrf$9(
        .clock(doptrf$9$clock),
        .d0(doptrf$9$d0),
        .d1(doptrf$9$d1),
        .d2(doptrf$9$d2),
        .c0(doptrf$9$c0),
        .c1(doptrf$9$c1),
        .c2(doptrf$9$c2),
        .c(doptrf$9$c),
        .e(doptrf$9$e),
        .valid_in(doptrf$9$valid_in),
        .round_up(doptrf$9$round_up),
        .s(doptrf$9$s),
        .flag(doptrf$9$flag),
        .valid_out(doptrf$9$valid_out)
    );
    top$dop$unit$doptrf$0 doptrf$10(
        .clock(doptrf$10$clock),
        .d0(doptrf$10$d0),
        .d1(doptrf$10$d1),
        .d2(doptrf$10$d2),
        .c0(doptrf$10$c0),
        .c1(doptrf$10$c1),
        .c2(doptrf$10$c2),
        .c(doptrf$10$c),
        .e(doptrf$10$e),
        .valid_in(doptrf$10$valid_in),
        .round_up(doptrf$10$round_up),
        .s(doptrf$10$s),
        .flag(doptrf$10$flag),
        .valid_out(doptrf$10$valid_out)
    );
    top$dop$unit$doptrf$0 doptrf$11(
        .clock(doptrf$11$clock),
        .d0(doptrf$11$d0),
        .d1(doptrf$11$d1),
        .d2(doptrf$11$d2),
        .c0(doptrf$11$c0),
        .c1(doptrf$11$c1),
        .c2(doptrf$11$c2),
        .c(doptrf$11$c),
        .e(doptrf$11$e),
        .valid_in(doptrf$11$valid_in),
        .round_up(doptrf$11$round_up),
        .s(doptrf$11$s),
        .flag(doptrf$11$flag),
        .valid_out(doptrf$11$valid_out)
    );
    top$dop$unit$doptrf$0 doptrf$12(
        .clock(doptrf$12$clock),
        .d0(doptrf$12$d0),
        .d1(doptrf$12$d1),
        .d2(doptrf$12$d2),
        .c0(doptrf$12$c0),
        .c1(doptrf$12$c1),
        .c2(doptrf$12$c2),
        .c(doptrf$12$c),
        .e(doptrf$12$e),
        .valid_in(doptrf$12$valid_in),
        .round_up(doptrf$12$round_up),
        .s(doptrf$12$s),
        .flag(doptrf$12$flag),
        .valid_out(doptrf$12$valid_out)
    );
    top$dop$unit$doptrf$0 doptrf$13(
        .clock(doptrf$13$clock),
        .d0(doptrf$13$d0),
        .d1(doptrf$13$d1),
        .d2(doptrf$13$d2),
        .c0(doptrf$13$c0),
        .c1(doptrf$13$c1),
        .c2(doptrf$13$c2),
        .c(doptrf$13$c),
        .e(doptrf$13$e),
        .valid_in(doptrf$13$valid_in),
        .round_up(doptrf$13$round_up),
        .s(doptrf$13$s),
        .flag(doptrf$13$flag),
        .valid_out(doptrf$13$valid_out)
    );
    top$dop$unit$doptrf$0 doptrf$14(
        .clock(doptrf$14$clock),
        .d0(doptrf$14$d0),
        .d1(doptrf$14$d1),
        .d2(doptrf$14$d2),
        .c0(doptrf$14$c0),
        .c1(doptrf$14$c1),
        .c2(doptrf$14$c2),
        .c(doptrf$14$c),
        .e(doptrf$14$e),
        .valid_in(doptrf$14$valid_in),
        .round_up(doptrf$14$round_up),
        .s(doptrf$14$s),
        .flag(doptrf$14$flag),
        .valid_out(doptrf$14$valid_out)
    );
    top$dop$unit$doptrf$0 doptrf$15(
        .clock(doptrf$15$clock),
        .d0(doptrf$15$d0),
        .d1(doptrf$15$d1),
        .d2(doptrf$15$d2),
        .c0(doptrf$15$c0),
        .c1(doptrf$15$c1),
        .c2(doptrf$15$c2),
        .c(doptrf$15$c),
        .e(doptrf$15$e),
        .valid_in(doptrf$15$valid_in),
        .round_up(doptrf$15$round_up),
        .s(doptrf$15$s),
        .flag(doptrf$15$flag),
        .valid_out(doptrf$15$valid_out)
    );
    top$dop$unit$doptrf$0 doptrf$16(
        .clock(doptrf$16$clock),
        .d0(doptrf$16$d0),
        .d1(doptrf$16$d1),
        .d2(doptrf$16$d2),
        .c0(doptrf$16$c0),
        .c1(doptrf$16$c1),
        .c2(doptrf$16$c2),
        .c(doptrf$16$c),
        .e(doptrf$16$e),
        .valid_in(doptrf$16$valid_in),
        .round_up(doptrf$16$round_up),
        .s(doptrf$16$s),
        .flag(doptrf$16$flag),
        .valid_out(doptrf$16$valid_out)
    );
    top$dop$unit$doptrf$0 doptrf$17(
        .clock(doptrf$17$clock),
        .d0(doptrf$17$d0),
        .d1(doptrf$17$d1),
        .d2(doptrf$17$d2),
        .c0(doptrf$17$c0),
        .c1(doptrf$17$c1),
        .c2(doptrf$17$c2),
        .c(doptrf$17$c),
        .e(doptrf$17$e),
        .valid_in(doptrf$17$valid_in),
        .round_up(doptrf$17$round_up),
        .s(doptrf$17$s),
        .flag(doptrf$17$flag),
        .valid_out(doptrf$17$valid_out)
    );
    top$dop$unit$doptrf$0 doptrf$18(
        .clock(doptrf$18$clock),
        .d0(doptrf$18$d0),
        .d1(doptrf$18$d1),
        .d2(doptrf$18$d2),
        .c0(doptrf$18$c0),
        .c1(doptrf$18$c1),
        .c2(doptrf$18$c2),
        .c(doptrf$18$c),
        .e(doptrf$18$e),
        .valid_in(doptrf$18$valid_in),
        .round_up(doptrf$18$round_up),
        .s(doptrf$18$s),
        .flag(doptrf$18$flag),
        .valid_out(doptrf$18$valid_out)
    );
    top$dop$unit$doptrf$0 doptrf$19(
        .clock(doptrf$19$clock),
        .d0(doptrf$19$d0),
        .d1(doptrf$19$d1),
        .d2(doptrf$19$d2),
        .c0(doptrf$19$c0),
        .c1(doptrf$19$c1),
        .c2(doptrf$19$c2),
        .c(doptrf$19$c),
        .e(doptrf$19$e),
        .valid_in(doptrf$19$valid_in),
        .round_up(doptrf$19$round_up),
        .s(doptrf$19$s),
        .flag(doptrf$19$flag),
        .valid_out(doptrf$19$valid_out)
    );
    top$dop$unit$doptrf$0 doptrf$20(
        .clock(doptrf$20$clock),
        .d0(doptrf$20$d0),
        .d1(doptrf$20$d1),
        .d2(doptrf$20$d2),
        .c0(doptrf$20$c0),
        .c1(doptrf$20$c1),
        .c2(doptrf$20$c2),
        .c(doptrf$20$c),
        .e(doptrf$20$e),
        .valid_in(doptrf$20$valid_in),
        .round_up(doptrf$20$round_up),
        .s(doptrf$20$s),
        .flag(doptrf$20$flag),
        .valid_out(doptrf$20$valid_out)
    );
    top$dop$unit$doptrf$0 doptrf$21(
        .clock(doptrf$21$clock),
        .d0(doptrf$21$d0),
        .d1(doptrf$21$d1),
        .d2(doptrf$21$d2),
        .c0(doptrf$21$c0),
        .c1(doptrf$21$c1),
        .c2(doptrf$21$c2),
        .c(doptrf$21$c),
        .e(doptrf$21$e),
        .valid_in(doptrf$21$valid_in),
        .round_up(doptrf$21$round_up),
        .s(doptrf$21$s),
        .flag(doptrf$21$flag),
        .valid_out(doptrf$21$valid_out)
    );
    top$dop$unit$doptrf$0 doptrf$22(
        .clock(doptrf$22$clock),
        .d0(doptrf$22$d0),
        .d1(doptrf$22$d1),
        .d2(doptrf$22$d2),
        .c0(doptrf$22$c0),
        .c1(doptrf$22$c1),
        .c2(doptrf$22$c2),
        .c(doptrf$22$c),
        .e(doptrf$22$e),
        .valid_in(doptrf$22$valid_in),
        .round_up(doptrf$22$round_up),
        .s(doptrf$22$s),
        .flag(doptrf$22$flag),
        .valid_out(doptrf$22$valid_out)
    );
    top$dop$unit$doptrf$0 doptrf$23(
        .clock(doptrf$23$clock),
        .d0(doptrf$23$d0),
        .d1(doptrf$23$d1),
        .d2(doptrf$23$d2),
        .c0(doptrf$23$c0),
        .c1(doptrf$23$c1),
        .c2(doptrf$23$c2),
        .c(doptrf$23$c),
        .e(doptrf$23$e),
        .valid_in(doptrf$23$valid_in),
        .round_up(doptrf$23$round_up),
        .s(doptrf$23$s),
        .flag(doptrf$23$flag),
        .valid_out(doptrf$23$valid_out)
    );
    top$d_cntr$last_a tag_1(
        .d(tag_1$d),
        .q(tag_1$q),
        .clock(tag_1$clock)
    );
    top$d_cntr$last_a tag_2(
        .d(tag_2$d),
        .q(tag_2$q),
        .clock(tag_2$clock)
    );
    top$d_cntr$last_a tag_3(
        .d(tag_3$d),
        .q(tag_3$q),
        .clock(tag_3$clock)
    );
    top$d_cntr$last_a tag_4(
        .d(tag_4$d),
        .q(tag_4$q),
        .clock(tag_4$clock)
    );
    top$d_cntr$last_a tag_5(
        .d(tag_5$d),
        .q(tag_5$q),
        .clock(tag_5$clock)
    );
    top$d_cntr$last_a tag_6(
        .d(tag_6$d),
        .q(tag_6$q),
        .clock(tag_6$clock)
    );
    top$d_cntr$last_a tag_7(
        .d(tag_7$d),
        .q(tag_7$q),
        .clock(tag_7$clock)
    );
    top$d_cntr$last_a tag_8(
        .d(tag_8$d),
        .q(tag_8$q),
        .clock(tag_8$clock)
    );
    top$d_cntr$last_a tag_9(
        .d(tag_9$d),
        .q(tag_9$q),
        .clock(tag_9$clock)
    );
    top$d_cntr$last_a tag_10(
        .d(tag_10$d),
        .q(tag_10$q),
        .clock(tag_10$clock)
    );
    top$d_cntr$last_a tag_11(
        .d(tag_11$d),
        .q(tag_11$q),
        .clock(tag_11$clock)
    );
    top$d_cntr$last_a tag_12(
        .d(tag_12$d),
        .q(tag_12$q),
        .clock(tag_12$clock)
    );
    top$d_cntr$last_a tag_13(
        .d(tag_13$d),
        .q(tag_13$q),
        .clock(tag_13$clock)
    );
    top$d_cntr$last_a tag_14(
        .d(tag_14$d),
        .q(tag_14$q),
        .clock(tag_14$clock)
    );
    top$d_cntr$last_a tag_15(
        .d(tag_15$d),
        .q(tag_15$q),
        .clock(tag_15$clock)
    );
    
    // Update code
    always @(*) begin
        tag_1$clock = clock;
        tag_2$clock = clock;
        tag_3$clock = clock;
        tag_4$clock = clock;
        tag_5$clock = clock;
        tag_6$clock = clock;
        tag_7$clock = clock;
        tag_8$clock = clock;
        tag_1$d = tag_1$q;
        tag_2$d = tag_2$q;
        tag_3$d = tag_3$q;
        tag_4$d = tag_4$q;
        tag_5$d = tag_5$q;
        tag_6$d = tag_6$q;
        tag_7$d = tag_7$q;
        tag_8$d = tag_8$q;
        tag_9$clock = clock;
        tag_10$clock = clock;
        tag_11$clock = clock;
        tag_12$clock = clock;
        tag_13$clock = clock;
        tag_14$clock = clock;
        tag_15$clock = clock;
        tag_9$d = tag_9$q;
        tag_10$d = tag_10$q;
        tag_11$d = tag_11$q;
        tag_12$d = tag_12$q;
        tag_13$d = tag_13$q;
        tag_14$d = tag_14$q;
        tag_15$d = tag_15$q;
        setup$clock = clock;
        setup$load_en = load_en;
        setup$load_addr = load_addr;
        setup$load_data = load_data;
        doptrf$0$clock = clock;
        klmsel$d$0 = d$0;
        klmsel$j0$0 = setup$j0$0;
        klmsel$j1$0 = setup$j1$0;
        klmsel$j2$0 = setup$j2$0;
        doptrf$0$d0 = klmsel$y0$0;
        doptrf$0$d1 = klmsel$y1$0;
        doptrf$0$d2 = klmsel$y2$0;
        doptrf$0$c0 = setup$c0$0;
        doptrf$0$c1 = setup$c1$0;
        doptrf$0$c2 = setup$c2$0;
        doptrf$0$c = setup$c$0;
        doptrf$0$round_up = setup$round_up$0;
        doptrf$0$valid_in = valid_in;
        doptrf$1$clock = clock;
        klmsel$d$1 = d$1;
        klmsel$j0$1 = setup$j0$1;
        klmsel$j1$1 = setup$j1$1;
        klmsel$j2$1 = setup$j2$1;
        doptrf$1$d0 = klmsel$y0$1;
        doptrf$1$d1 = klmsel$y1$1;
        doptrf$1$d2 = klmsel$y2$1;
        doptrf$1$c0 = setup$c0$1;
        doptrf$1$c1 = setup$c1$1;
        doptrf$1$c2 = setup$c2$1;
        doptrf$1$c = setup$c$1;
        doptrf$1$round_up = setup$round_up$1;
        doptrf$1$valid_in = valid_in;
        doptrf$2$clock = clock;
        klmsel$d$2 = d$2;
        klmsel$j0$2 = setup$j0$2;
        klmsel$j1$2 = setup$j1$2;
        klmsel$j2$2 = setup$j2$2;
        doptrf$2$d0 = klmsel$y0$2;
        doptrf$2$d1 = klmsel$y1$2;
        doptrf$2$d2 = klmsel$y2$2;
        doptrf$2$c0 = setup$c0$2;
        doptrf$2$c1 = setup$c1$2;
        doptrf$2$c2 = setup$c2$2;
        doptrf$2$c = setup$c$2;
        doptrf$2$round_up = setup$round_up$2;
        doptrf$2$valid_in = valid_in;
        doptrf$3$clock = clock;
        klmsel$d$3 = d$3;
        klmsel$j0$3 = setup$j0$3;
        klmsel$j1$3 = setup$j1$3;
        klmsel$j2$3 = setup$j2$3;
        doptrf$3$d0 = klmsel$y0$3;
        doptrf$3$d1 = klmsel$y1$3;
        doptrf$3$d2 = klmsel$y2$3;
        doptrf$3$c0 = setup$c0$3;
        doptrf$3$c1 = setup$c1$3;
        doptrf$3$c2 = setup$c2$3;
        doptrf$3$c = setup$c$3;
        doptrf$3$round_up = setup$round_up$3;
        doptrf$3$valid_in = valid_in;
        doptrf$4$clock = clock;
        klmsel$d$4 = d$4;
        klmsel$j0$4 = setup$j0$4;
        klmsel$j1$4 = setup$j1$4;
        klmsel$j2$4 = setup$j2$4;
        doptrf$4$d0 = klmsel$y0$4;
        doptrf$4$d1 = klmsel$y1$4;
        doptrf$4$d2 = klmsel$y2$4;
        doptrf$4$c0 = setup$c0$4;
        doptrf$4$c1 = setup$c1$4;
        doptrf$4$c2 = setup$c2$4;
        doptrf$4$c = setup$c$4;
        doptrf$4$round_up = setup$round_up$4;
        doptrf$4$valid_in = valid_in;
        doptrf$5$clock = clock;
        klmsel$d$5 = d$5;
        klmsel$j0$5 = setup$j0$5;
        klmsel$j1$5 = setup$j1$5;
        klmsel$j2$5 = setup$j2$5;
        doptrf$5$d0 = klmsel$y0$5;
        doptrf$5$d1 = klmsel$y1$5;
        doptrf$5$d2 = klmsel$y2$5;
        doptrf$5$c0 = setup$c0$5;
        doptrf$5$c1 = setup$c1$5;
        doptrf$5$c2 = setup$c2$5;
        doptrf$5$c = setup$c$5;
        doptrf$5$round_up = setup$round_up$5;
        doptrf$5$valid_in = valid_in;
        doptrf$6$clock = clock;
        klmsel$d$6 = d$6;
        klmsel$j0$6 = setup$j0$6;
        klmsel$j1$6 = setup$j1$6;
        klmsel$j2$6 = setup$j2$6;
        doptrf$6$d0 = klmsel$y0$6;
        doptrf$6$d1 = klmsel$y1$6;
        doptrf$6$d2 = klmsel$y2$6;
        doptrf$6$c0 = setup$c0$6;
        doptrf$6$c1 = setup$c1$6;
        doptrf$6$c2 = setup$c2$6;
        doptrf$6$c = setup$c$6;
        doptrf$6$round_up = setup$round_up$6;
        doptrf$6$valid_in = valid_in;
        doptrf$7$clock = clock;
        klmsel$d$7 = d$7;
        klmsel$j0$7 = setup$j0$7;
        klmsel$j1$7 = setup$j1$7;
        klmsel$j2$7 = setup$j2$7;
        doptrf$7$d0 = klmsel$y0$7;
        doptrf$7$d1 = klmsel$y1$7;
        doptrf$7$d2 = klmsel$y2$7;
        doptrf$7$c0 = setup$c0$7;
        doptrf$7$c1 = setup$c1$7;
        doptrf$7$c2 = setup$c2$7;
        doptrf$7$c = setup$c$7;
        doptrf$7$round_up = setup$round_up$7;
        doptrf$7$valid_in = valid_in;
        doptrf$8$clock = clock;
        klmsel$d$8 = d$8;
        klmsel$j0$8 = setup$j0$8;
        klmsel$j1$8 = setup$j1$8;
        klmsel$j2$8 = setup$j2$8;
        doptrf$8$d0 = klmsel$y0$8;
        doptrf$8$d1 = klmsel$y1$8;
        doptrf$8$d2 = klmsel$y2$8;
        doptrf$8$c0 = setup$c0$8;
        doptrf$8$c1 = setup$c1$8;
        doptrf$8$c2 = setup$c2$8;
        doptrf$8$c = setup$c$8;
        doptrf$8$round_up = setup$round_up$8;
        doptrf$8$valid_in = valid_in;
        doptrf$9$clock = clock;
        klmsel$d$9 = d$9;
        klmsel$j0$9 = setup$j0$9;
        klmsel$j1$9 = setup$j1$9;
        klmsel$j2$9 = setup$j2$9;
        doptrf$9$d0 = klmsel$y0$9;
        doptrf$9$d1 = klmsel$y1$9;
        doptrf$9$d2 = klmsel$y2$9;
        doptrf$9$c0 = setup$c0$9;
        doptrf$9$c1 = setup$c1$9;
        doptrf$9$c2 = setup$c2$9;
        doptrf$9$c = setup$c$9;
        doptrf$9$round_up = setup$round_up$9;
        doptrf$9$valid_in = valid_in;
        doptrf$10$clock = clock;
        klmsel$d$10 = d$10;
        klmsel$j0$10 = setup$j0$10;
        klmsel$j1$10 = setup$j1$10;
        klmsel$j2$10 = setup$j2$10;
        doptrf$10$d0 = klmsel$y0$10;
        doptrf$10$d1 = klmsel$y1$10;
        doptrf$10$d2 = klmsel$y2$10;
        doptrf$10$c0 = setup$c0$10;
        doptrf$10$c1 = setup$c1$10;
        doptrf$10$c2 = setup$c2$10;
        doptrf$10$c = setup$c$10;
        doptrf$10$round_up = setup$round_up$10;
        doptrf$10$valid_in = valid_in;
        doptrf$11$clock = clock;
        klmsel$d$11 = d$11;
        klmsel$j0$11 = setup$j0$11;
        klmsel$j1$11 = setup$j1$11;
        klmsel$j2$11 = setup$j2$11;
        doptrf$11$d0 = klmsel$y0$11;
        doptrf$11$d1 = klmsel$y1$11;
        doptrf$11$d2 = klmsel$y2$11;
        doptrf$11$c0 = setup$c0$11;
        doptrf$11$c1 = setup$c1$11;
        doptrf$11$c2 = setup$c2$11;
        doptrf$11$c = setup$c$11;
        doptrf$11$round_up = setup$round_up$11;
        doptrf$11$valid_in = valid_in;
        doptrf$12$clock = clock;
        klmsel$d$12 = d$12;
        klmsel$j0$12 = setup$j0$12;
        klmsel$j1$12 = setup$j1$12;
        klmsel$j2$12 = setup$j2$12;
        doptrf$12$d0 = klmsel$y0$12;
        doptrf$12$d1 = klmsel$y1$12;
        doptrf$12$d2 = klmsel$y2$12;
        doptrf$12$c0 = setup$c0$12;
        doptrf$12$c1 = setup$c1$12;
        doptrf$12$c2 = setup$c2$12;
        doptrf$12$c = setup$c$12;
        doptrf$12$round_up = setup$round_up$12;
        doptrf$12$valid_in = valid_in;
        doptrf$13$clock = clock;
        klmsel$d$13 = d$13;
        klmsel$j0$13 = setup$j0$13;
        klmsel$j1$13 = setup$j1$13;
        klmsel$j2$13 = setup$j2$13;
        doptrf$13$d0 = klmsel$y0$13;
        doptrf$13$d1 = klmsel$y1$13;
        doptrf$13$d2 = klmsel$y2$13;
        doptrf$13$c0 = setup$c0$13;
        doptrf$13$c1 = setup$c1$13;
        doptrf$13$c2 = setup$c2$13;
        doptrf$13$c = setup$c$13;
        doptrf$13$round_up = setup$round_up$13;
        doptrf$13$valid_in = valid_in;
        doptrf$14$clock = clock;
        klmsel$d$14 = d$14;
        klmsel$j0$14 = setup$j0$14;
        klmsel$j1$14 = setup$j1$14;
        klmsel$j2$14 = setup$j2$14;
        doptrf$14$d0 = klmsel$y0$14;
        doptrf$14$d1 = klmsel$y1$14;
        doptrf$14$d2 = klmsel$y2$14;
        doptrf$14$c0 = setup$c0$14;
        doptrf$14$c1 = setup$c1$14;
        doptrf$14$c2 = setup$c2$14;
        doptrf$14$c = setup$c$14;
        doptrf$14$round_up = setup$round_up$14;
        doptrf$14$valid_in = valid_in;
        doptrf$15$clock = clock;
        klmsel$d$15 = d$15;
        klmsel$j0$15 = setup$j0$15;
        klmsel$j1$15 = setup$j1$15;
        klmsel$j2$15 = setup$j2$15;
        doptrf$15$d0 = klmsel$y0$15;
        doptrf$15$d1 = klmsel$y1$15;
        doptrf$15$d2 = klmsel$y2$15;
        doptrf$15$c0 = setup$c0$15;
        doptrf$15$c1 = setup$c1$15;
        doptrf$15$c2 = setup$c2$15;
        doptrf$15$c = setup$c$15;
        doptrf$15$round_up = setup$round_up$15;
        doptrf$15$valid_in = valid_in;
        doptrf$16$clock = clock;
        klmsel$d$16 = d$16;
        klmsel$j0$16 = setup$j0$16;
        klmsel$j1$16 = setup$j1$16;
        klmsel$j2$16 = setup$j2$16;
        doptrf$16$d0 = klmsel$y0$16;
        doptrf$16$d1 = klmsel$y1$16;
        doptrf$16$d2 = klmsel$y2$16;
        doptrf$16$c0 = setup$c0$16;
        doptrf$16$c1 = setup$c1$16;
        doptrf$16$c2 = setup$c2$16;
        doptrf$16$c = setup$c$16;
        doptrf$16$round_up = setup$round_up$16;
        doptrf$16$valid_in = valid_in;
        doptrf$17$clock = clock;
        klmsel$d$17 = d$17;
        klmsel$j0$17 = setup$j0$17;
        klmsel$j1$17 = setup$j1$17;
        klmsel$j2$17 = setup$j2$17;
        doptrf$17$d0 = klmsel$y0$17;
        doptrf$17$d1 = klmsel$y1$17;
        doptrf$17$d2 = klmsel$y2$17;
        doptrf$17$c0 = setup$c0$17;
        doptrf$17$c1 = setup$c1$17;
        doptrf$17$c2 = setup$c2$17;
        doptrf$17$c = setup$c$17;
        doptrf$17$round_up = setup$round_up$17;
        doptrf$17$valid_in = valid_in;
        doptrf$18$clock = clock;
        klmsel$d$18 = d$18;
        klmsel$j0$18 = setup$j0$18;
        klmsel$j1$18 = setup$j1$18;
        klmsel$j2$18 = setup$j2$18;
        doptrf$18$d0 = klmsel$y0$18;
        doptrf$18$d1 = klmsel$y1$18;
        doptrf$18$d2 = klmsel$y2$18;
        doptrf$18$c0 = setup$c0$18;
        doptrf$18$c1 = setup$c1$18;
        doptrf$18$c2 = setup$c2$18;
        doptrf$18$c = setup$c$18;
        doptrf$18$round_up = setup$round_up$18;
        doptrf$18$valid_in = valid_in;
        doptrf$19$clock = clock;
        klmsel$d$19 = d$19;
        klmsel$j0$19 = setup$j0$19;
        klmsel$j1$19 = setup$j1$19;
        klmsel$j2$19 = setup$j2$19;
        doptrf$19$d0 = klmsel$y0$19;
        doptrf$19$d1 = klmsel$y1$19;
        doptrf$19$d2 = klmsel$y2$19;
        doptrf$19$c0 = setup$c0$19;
        doptrf$19$c1 = setup$c1$19;
        doptrf$19$c2 = setup$c2$19;
        doptrf$19$c = setup$c$19;
        doptrf$19$round_up = setup$round_up$19;
        doptrf$19$valid_in = valid_in;
        doptrf$20$clock = clock;
        klmsel$d$20 = d$20;
        klmsel$j0$20 = setup$j0$20;
        klmsel$j1$20 = setup$j1$20;
        klmsel$j2$20 = setup$j2$20;
        doptrf$20$d0 = klmsel$y0$20;
        doptrf$20$d1 = klmsel$y1$20;
        doptrf$20$d2 = klmsel$y2$20;
        doptrf$20$c0 = setup$c0$20;
        doptrf$20$c1 = setup$c1$20;
        doptrf$20$c2 = setup$c2$20;
        doptrf$20$c = setup$c$20;
        doptrf$20$round_up = setup$round_up$20;
        doptrf$20$valid_in = valid_in;
        doptrf$21$clock = clock;
        klmsel$d$21 = d$21;
        klmsel$j0$21 = setup$j0$21;
        klmsel$j1$21 = setup$j1$21;
        klmsel$j2$21 = setup$j2$21;
        doptrf$21$d0 = klmsel$y0$21;
        doptrf$21$d1 = klmsel$y1$21;
        doptrf$21$d2 = klmsel$y2$21;
        doptrf$21$c0 = setup$c0$21;
        doptrf$21$c1 = setup$c1$21;
        doptrf$21$c2 = setup$c2$21;
        doptrf$21$c = setup$c$21;
        doptrf$21$round_up = setup$round_up$21;
        doptrf$21$valid_in = valid_in;
        doptrf$22$clock = clock;
        klmsel$d$22 = d$22;
        klmsel$j0$22 = setup$j0$22;
        klmsel$j1$22 = setup$j1$22;
        klmsel$j2$22 = setup$j2$22;
        doptrf$22$d0 = klmsel$y0$22;
        doptrf$22$d1 = klmsel$y1$22;
        doptrf$22$d2 = klmsel$y2$22;
        doptrf$22$c0 = setup$c0$22;
        doptrf$22$c1 = setup$c1$22;
        doptrf$22$c2 = setup$c2$22;
        doptrf$22$c = setup$c$22;
        doptrf$22$round_up = setup$round_up$22;
        doptrf$22$valid_in = valid_in;
        doptrf$23$clock = clock;
        klmsel$d$23 = d$23;
        klmsel$j0$23 = setup$j0$23;
        klmsel$j1$23 = setup$j1$23;
        klmsel$j2$23 = setup$j2$23;
        doptrf$23$d0 = klmsel$y0$23;
        doptrf$23$d1 = klmsel$y1$23;
        doptrf$23$d2 = klmsel$y2$23;
        doptrf$23$c0 = setup$c0$23;
        doptrf$23$c1 = setup$c1$23;
        doptrf$23$c2 = setup$c2$23;
        doptrf$23$c = setup$c$23;
        doptrf$23$round_up = setup$round_up$23;
        doptrf$23$valid_in = valid_in;
        doptrf$0$e = e$12;
        doptrf$1$e = e$13;
        doptrf$2$e = e$14;
        doptrf$3$e = e$15;
        doptrf$4$e = e$16;
        doptrf$5$e = e$17;
        doptrf$6$e = e$18;
        doptrf$7$e = e$19;
        doptrf$8$e = e$20;
        doptrf$9$e = e$21;
        doptrf$10$e = e$22;
        doptrf$11$e = e$23;
        doptrf$12$e = e$0;
        doptrf$13$e = e$1;
        doptrf$14$e = e$2;
        doptrf$15$e = e$3;
        doptrf$16$e = e$4;
        doptrf$17$e = e$5;
        doptrf$18$e = e$6;
        doptrf$19$e = e$7;
        doptrf$20$e = e$8;
        doptrf$21$e = e$9;
        doptrf$22$e = e$10;
        doptrf$23$e = e$11;
        tag_1$d = tag;
        tag_2$d = tag_1$q;
        tag_3$d = tag_2$q;
        tag_4$d = tag_3$q;
        tag_5$d = tag_4$q;
        tag_6$d = tag_5$q;
        tag_7$d = tag_6$q;
        tag_8$d = tag_7$q;
        tag_9$d = tag_8$q;
        tag_10$d = tag_9$q;
        tag_11$d = tag_10$q;
        tag_12$d = tag_11$q;
        tag_13$d = tag_12$q;
        tag_14$d = tag_13$q;
        tag_15$d = tag_14$q;
        c_any = 1'b0;
        if (doptrf$0$flag) begin
            c_any = 1'b1;
        end
        if (doptrf$1$flag) begin
            c_any = 1'b1;
        end
        if (doptrf$2$flag) begin
            c_any = 1'b1;
        end
        if (doptrf$3$flag) begin
            c_any = 1'b1;
        end
        if (doptrf$4$flag) begin
            c_any = 1'b1;
        end
        if (doptrf$5$flag) begin
            c_any = 1'b1;
        end
        if (doptrf$6$flag) begin
            c_any = 1'b1;
        end
        if (doptrf$7$flag) begin
            c_any = 1'b1;
        end
        if (doptrf$8$flag) begin
            c_any = 1'b1;
        end
        if (doptrf$9$flag) begin
            c_any = 1'b1;
        end
        if (doptrf$10$flag) begin
            c_any = 1'b1;
        end
        if (doptrf$11$flag) begin
            c_any = 1'b1;
        end
        if (doptrf$12$flag) begin
            c_any = 1'b1;
        end
        if (doptrf$13$flag) begin
            c_any = 1'b1;
        end
        if (doptrf$14$flag) begin
            c_any = 1'b1;
        end
        if (doptrf$15$flag) begin
            c_any = 1'b1;
        end
        if (doptrf$16$flag) begin
            c_any = 1'b1;
        end
        if (doptrf$17$flag) begin
            c_any = 1'b1;
        end
        if (doptrf$18$flag) begin
            c_any = 1'b1;
        end
        if (doptrf$19$flag) begin
            c_any = 1'b1;
        end
        if (doptrf$20$flag) begin
            c_any = 1'b1;
        end
        if (doptrf$21$flag) begin
            c_any = 1'b1;
        end
        if (doptrf$22$flag) begin
            c_any = 1'b1;
        end
        if (doptrf$23$flag) begin
            c_any = 1'b1;
        end
        overlap = ~c_any;
        tag_out = tag_15$q;
        valid_out = doptrf$0$valid_out;
    end
    
endmodule // top$dop$unit


module top$dop$unit$doptrf$0(clock,d0,d1,d2,c0,c1,c2,c,e,valid_in,round_up,s,flag,valid_out);
    
    // Module arguments
    input wire  clock;
    input wire  [31:0] d0;
    input wire  [31:0] d1;
    input wire  [31:0] d2;
    input wire  [31:0] c0;
    input wire  [31:0] c1;
    input wire  [31:0] c2;
    input wire  [31:0] c;
    input wire  [31:0] e;
    input wire  valid_in;
    input wire  round_up;
    output reg  [31:0] s;
    output reg  flag;
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
    reg  [31:0] s1_e$d;
    wire  [31:0] s1_e$q;
    reg  s1_e$clock;
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
    reg  r_s$clock;
    reg  r_s$d;
    wire  r_s$q;
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
    reg  add_3$clock;
    reg  [31:0] add_3$a;
    reg  [31:0] add_3$b;
    reg  add_3$sub;
    reg  add_3$valid_in;
    wire  [31:0] add_3$y;
    wire  add_3$valid_out;
    reg  add_3$round_up;
    reg  [31:0] e_2$d;
    wire  [31:0] e_2$q;
    reg  e_2$clock;
    reg  [31:0] e_3$d;
    wire  [31:0] e_3$q;
    reg  e_3$clock;
    reg  [31:0] e_4$d;
    wire  [31:0] e_4$q;
    reg  e_4$clock;
    reg  [31:0] e_5$d;
    wire  [31:0] e_5$q;
    reg  e_5$clock;
    reg  [31:0] e_6$d;
    wire  [31:0] e_6$q;
    reg  e_6$clock;
    reg  [31:0] e_7$d;
    wire  [31:0] e_7$q;
    reg  e_7$clock;
    reg  [31:0] e_8$d;
    wire  [31:0] e_8$q;
    reg  e_8$clock;
    reg  [31:0] e_9$d;
    wire  [31:0] e_9$q;
    reg  e_9$clock;
    reg  [31:0] e_10$d;
    wire  [31:0] e_10$q;
    reg  e_10$clock;
    reg  [31:0] e_11$d;
    wire  [31:0] e_11$q;
    reg  e_11$clock;
    reg  s15_valid$d;
    wire  s15_valid$q;
    reg  s15_valid$clock;
    reg  [31:0] s15_s$d;
    wire  [31:0] s15_s$q;
    reg  s15_s$clock;
    reg  s15_flag$d;
    wire  s15_flag$q;
    reg  s15_flag$clock;
    
    // Local signals
    reg  [7:0] c15_exp;
    reg  [22:0] c15_frac;
    reg  [30:0] c15_mag;
    reg  c15_nan;
    
    // Sub module instances
    top$cnt_dop$pending s1_valid(
        .d(s1_valid$d),
        .q(s1_valid$q),
        .clock(s1_valid$clock)
    );
    top$cnt_dop$total s1_d0(
        .d(s1_d0$d),
        .q(s1_d0$q),
        .clock(s1_d0$clock)
    );
    top$cnt_dop$total s1_d1(
        .d(s1_d1$d),
        .q(s1_d1$q),
        .clock(s1_d1$clock)
    );
    top$cnt_dop$total s1_d2(
        .d(s1_d2$d),
        .q(s1_d2$q),
        .clock(s1_d2$clock)
    );
    top$cnt_dop$total s1_c0(
        .d(s1_c0$d),
        .q(s1_c0$q),
        .clock(s1_c0$clock)
    );
    top$cnt_dop$total s1_c1(
        .d(s1_c1$d),
        .q(s1_c1$q),
        .clock(s1_c1$clock)
    );
    top$cnt_dop$total s1_c2(
        .d(s1_c2$d),
        .q(s1_c2$q),
        .clock(s1_c2$clock)
    );
    top$cnt_dop$total s1_c(
        .d(s1_c$d),
        .q(s1_c$q),
        .clock(s1_c$clock)
    );
    top$cnt_dop$total s1_e(
        .d(s1_e$d),
        .q(s1_e$q),
        .clock(s1_e$clock)
    );
    top$cnt_dop$pending s1_round(
        .d(s1_round$d),
        .q(s1_round$q),
        .clock(s1_round$clock)
    );
    top$dop$unit$doptrf$0$r_mul r_mul(
        .clock(r_mul$clock),
        .d(r_mul$d),
        .q(r_mul$q)
    );
    top$dop$unit$doptrf$0$r_mul r_sum(
        .clock(r_sum$clock),
        .d(r_sum$d),
        .q(r_sum$q)
    );
    top$dop$unit$doptrf$0$r_mul r_u(
        .clock(r_u$clock),
        .d(r_u$d),
        .q(r_u$q)
    );
    top$dop$unit$doptrf$0$r_mul r_s(
        .clock(r_s$clock),
        .d(r_s$d),
        .q(r_s$q)
    );
    top$dop$unit$doptrf$0$mul_0 mul_0(
        .clock(mul_0$clock),
        .a(mul_0$a),
        .b(mul_0$b),
        .valid_in(mul_0$valid_in),
        .y(mul_0$y),
        .valid_out(mul_0$valid_out),
        .round_up(mul_0$round_up)
    );
    top$dop$unit$doptrf$0$mul_0 mul_1(
        .clock(mul_1$clock),
        .a(mul_1$a),
        .b(mul_1$b),
        .valid_in(mul_1$valid_in),
        .y(mul_1$y),
        .valid_out(mul_1$valid_out),
        .round_up(mul_1$round_up)
    );
    top$dop$unit$doptrf$0$mul_0 mul_2(
        .clock(mul_2$clock),
        .a(mul_2$a),
        .b(mul_2$b),
        .valid_in(mul_2$valid_in),
        .y(mul_2$y),
        .valid_out(mul_2$valid_out),
        .round_up(mul_2$round_up)
    );
    top$cnt_dop$total c_2(
        .d(c_2$d),
        .q(c_2$q),
        .clock(c_2$clock)
    );
    top$cnt_dop$total c_3(
        .d(c_3$d),
        .q(c_3$q),
        .clock(c_3$clock)
    );
    top$cnt_dop$total c_4(
        .d(c_4$d),
        .q(c_4$q),
        .clock(c_4$clock)
    );
    top$cnt_dop$total c_5(
        .d(c_5$d),
        .q(c_5$q),
        .clock(c_5$clock)
    );
    top$dop$dec_d$0$add add_0(
        .clock(add_0$clock),
        .a(add_0$a),
        .b(add_0$b),
        .sub(add_0$sub),
        .valid_in(add_0$valid_in),
        .y(add_0$y),
        .valid_out(add_0$valid_out),
        .round_up(add_0$round_up)
    );
    top$dop$dec_d$0$add add_1(
        .clock(add_1$clock),
        .a(add_1$a),
        .b(add_1$b),
        .sub(add_1$sub),
        .valid_in(add_1$valid_in),
        .y(add_1$y),
        .valid_out(add_1$valid_out),
        .round_up(add_1$round_up)
    );
    top$dop$dec_d$0$add add_2(
        .clock(add_2$clock),
        .a(add_2$a),
        .b(add_2$b),
        .sub(add_2$sub),
        .valid_in(add_2$valid_in),
        .y(add_2$y),
        .valid_out(add_2$valid_out),
        .round_up(add_2$round_up)
    );
    top$dop$dec_d$0$add add_3(
        .clock(add_3$clock),
        .a(add_3$a),
        .b(add_3$b),
        .sub(add_3$sub),
        .valid_in(add_3$valid_in),
        .y(add_3$y),
        .valid_out(add_3$valid_out),
        .round_up(add_3$round_up)
    );
    top$cnt_dop$total e_2(
        .d(e_2$d),
        .q(e_2$q),
        .clock(e_2$clock)
    );
    top$cnt_dop$total e_3(
        .d(e_3$d),
        .q(e_3$q),
        .clock(e_3$clock)
    );
    top$cnt_dop$total e_4(
        .d(e_4$d),
        .q(e_4$q),
        .clock(e_4$clock)
    );
    top$cnt_dop$total e_5(
        .d(e_5$d),
        .q(e_5$q),
        .clock(e_5$clock)
    );
    top$cnt_dop$total e_6(
        .d(e_6$d),
        .q(e_6$q),
        .clock(e_6$clock)
    );
    top$cnt_dop$total e_7(
        .d(e_7$d),
        .q(e_7$q),
        .clock(e_7$clock)
    );
    top$cnt_dop$total e_8(
        .d(e_8$d),
        .q(e_8$q),
        .clock(e_8$clock)
    );
    top$cnt_dop$total e_9(
        .d(e_9$d),
        .q(e_9$q),
        .clock(e_9$clock)
    );
    top$cnt_dop$total e_10(
        .d(e_10$d),
        .q(e_10$q),
        .clock(e_10$clock)
    );
    top$cnt_dop$total e_11(
        .d(e_11$d),
        .q(e_11$q),
        .clock(e_11$clock)
    );
    top$cnt_dop$pending s15_valid(
        .d(s15_valid$d),
        .q(s15_valid$q),
        .clock(s15_valid$clock)
    );
    top$cnt_dop$total s15_s(
        .d(s15_s$d),
        .q(s15_s$q),
        .clock(s15_s$clock)
    );
    top$cnt_dop$pending s15_flag(
        .d(s15_flag$d),
        .q(s15_flag$q),
        .clock(s15_flag$clock)
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
        s1_e$clock = clock;
        s1_round$clock = clock;
        s1_valid$d = s1_valid$q;
        s1_d0$d = s1_d0$q;
        s1_d1$d = s1_d1$q;
        s1_d2$d = s1_d2$q;
        s1_c0$d = s1_c0$q;
        s1_c1$d = s1_c1$q;
        s1_c2$d = s1_c2$q;
        s1_c$d = s1_c$q;
        s1_e$d = s1_e$q;
        s1_round$d = s1_round$q;
        r_mul$clock = clock;
        r_sum$clock = clock;
        r_u$clock = clock;
        r_s$clock = clock;
        c_2$clock = clock;
        c_3$clock = clock;
        c_4$clock = clock;
        c_5$clock = clock;
        c_2$d = c_2$q;
        c_3$d = c_3$q;
        c_4$d = c_4$q;
        c_5$d = c_5$q;
        e_2$clock = clock;
        e_3$clock = clock;
        e_4$clock = clock;
        e_5$clock = clock;
        e_6$clock = clock;
        e_7$clock = clock;
        e_8$clock = clock;
        e_9$clock = clock;
        e_10$clock = clock;
        e_11$clock = clock;
        e_2$d = e_2$q;
        e_3$d = e_3$q;
        e_4$d = e_4$q;
        e_5$d = e_5$q;
        e_6$d = e_6$q;
        e_7$d = e_7$q;
        e_8$d = e_8$q;
        e_9$d = e_9$q;
        e_10$d = e_10$q;
        e_11$d = e_11$q;
        s15_valid$clock = clock;
        s15_s$clock = clock;
        s15_flag$clock = clock;
        s15_valid$d = s15_valid$q;
        s15_s$d = s15_s$q;
        s15_flag$d = s15_flag$q;
        mul_0$clock = clock;
        mul_1$clock = clock;
        mul_2$clock = clock;
        add_0$clock = clock;
        add_1$clock = clock;
        add_2$clock = clock;
        add_3$clock = clock;
        mul_0$round_up = r_mul$q;
        mul_1$round_up = r_mul$q;
        mul_2$round_up = r_mul$q;
        add_0$round_up = r_sum$q;
        add_1$round_up = r_sum$q;
        add_2$round_up = r_u$q;
        add_3$round_up = r_s$q;
        s1_valid$d = valid_in;
        s1_d0$d = d0;
        s1_d1$d = d1;
        s1_d2$d = d2;
        s1_c0$d = c0;
        s1_c1$d = c1;
        s1_c2$d = c2;
        s1_c$d = c;
        s1_e$d = e;
        s1_round$d = round_up;
        r_mul$d = s1_round$q;
        r_sum$d = r_mul$q;
        r_u$d = r_sum$q;
        r_s$d = r_u$q;
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
        e_2$d = s1_e$q;
        e_3$d = e_2$q;
        e_4$d = e_3$q;
        e_5$d = e_4$q;
        e_6$d = e_5$q;
        e_7$d = e_6$q;
        e_8$d = e_7$q;
        e_9$d = e_8$q;
        e_10$d = e_9$q;
        e_11$d = e_10$q;
        add_3$a = add_2$y;
        add_3$b = e_11$q;
        add_3$sub = 1'b0;
        add_3$valid_in = add_2$valid_out;
        c15_exp = add_3$y[(32'h17)+:(8)];
        c15_frac = add_3$y[(32'h0)+:(23)];
        c15_mag = add_3$y[(32'h0)+:(31)];
        c15_nan = &c15_exp & (c15_frac != 32'h0);
        s15_valid$d = add_3$valid_out;
        s15_s$d = add_3$y;
        s15_flag$d = add_3$y[32'h1f] & (c15_mag != 32'h0) & ~c15_nan;
        s = s15_s$q;
        flag = s15_flag$q;
        valid_out = s15_valid$q;
    end
    
endmodule // top$dop$unit$doptrf$0


module top$dop$unit$doptrf$0$mul_0(clock,a,b,valid_in,y,valid_out,round_up);
    
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
    top$dop$dec_d$0$add$unpack_a unpack_a(
        .x(unpack_a$x),
        .sign(unpack_a$sign),
        .exp(unpack_a$exp),
        .sig(unpack_a$sig),
        .is_zero(unpack_a$is_zero),
        .is_inf(unpack_a$is_inf),
        .is_nan(unpack_a$is_nan)
    );
    top$dop$dec_d$0$add$unpack_a unpack_b(
        .x(unpack_b$x),
        .sign(unpack_b$sign),
        .exp(unpack_b$exp),
        .sig(unpack_b$sig),
        .is_zero(unpack_b$is_zero),
        .is_inf(unpack_b$is_inf),
        .is_nan(unpack_b$is_nan)
    );
    top$dop$unit$doptrf$0$mul_0$norm_a norm_a(
        .x(norm_a$x),
        .y(norm_a$y),
        .lz(norm_a$lz)
    );
    top$dop$unit$doptrf$0$mul_0$norm_a norm_b(
        .x(norm_b$x),
        .y(norm_b$y),
        .lz(norm_b$lz)
    );
    top$cnt_dop$pending s1_valid(
        .d(s1_valid$d),
        .q(s1_valid$q),
        .clock(s1_valid$clock)
    );
    top$cnt_dop$pending s1_sign(
        .d(s1_sign$d),
        .q(s1_sign$q),
        .clock(s1_sign$clock)
    );
    top$cnt_dop$pending s1_nan(
        .d(s1_nan$d),
        .q(s1_nan$q),
        .clock(s1_nan$clock)
    );
    top$cnt_dop$pending s1_inf(
        .d(s1_inf$d),
        .q(s1_inf$q),
        .clock(s1_inf$clock)
    );
    top$cnt_dop$pending s1_zero(
        .d(s1_zero$d),
        .q(s1_zero$q),
        .clock(s1_zero$clock)
    );
    top$d_cntr$queue$rd1_x s1_exp(
        .d(s1_exp$d),
        .q(s1_exp$q),
        .clock(s1_exp$clock)
    );
    top$base_na s1_sig_a(
        .d(s1_sig_a$d),
        .q(s1_sig_a$q),
        .clock(s1_sig_a$clock)
    );
    top$base_na s1_sig_b(
        .d(s1_sig_b$d),
        .q(s1_sig_b$q),
        .clock(s1_sig_b$clock)
    );
    top$dop$unit$doptrf$0$mul_0$sig_mul sig_mul(
        .a(sig_mul$a),
        .b(sig_mul$b),
        .hi(sig_mul$hi),
        .sticky(sig_mul$sticky)
    );
    top$cnt_dop$pending s2_valid(
        .d(s2_valid$d),
        .q(s2_valid$q),
        .clock(s2_valid$clock)
    );
    top$cnt_dop$pending s2_sign(
        .d(s2_sign$d),
        .q(s2_sign$q),
        .clock(s2_sign$clock)
    );
    top$cnt_dop$pending s2_nan(
        .d(s2_nan$d),
        .q(s2_nan$q),
        .clock(s2_nan$clock)
    );
    top$cnt_dop$pending s2_inf(
        .d(s2_inf$d),
        .q(s2_inf$q),
        .clock(s2_inf$clock)
    );
    top$cnt_dop$pending s2_zero(
        .d(s2_zero$d),
        .q(s2_zero$q),
        .clock(s2_zero$clock)
    );
    top$d_cntr$queue$rd1_x s2_exp(
        .d(s2_exp$d),
        .q(s2_exp$q),
        .clock(s2_exp$clock)
    );
    top$dop$dec_d$0$add$s2_nm s2_hi(
        .d(s2_hi$d),
        .q(s2_hi$q),
        .clock(s2_hi$clock)
    );
    top$cnt_dop$pending s2_sticky(
        .d(s2_sticky$d),
        .q(s2_sticky$q),
        .clock(s2_sticky$clock)
    );
    top$cnt_dop$pending s3_valid(
        .d(s3_valid$d),
        .q(s3_valid$q),
        .clock(s3_valid$clock)
    );
    top$cnt_dop$pending s3_sign(
        .d(s3_sign$d),
        .q(s3_sign$q),
        .clock(s3_sign$clock)
    );
    top$cnt_dop$pending s3_nan(
        .d(s3_nan$d),
        .q(s3_nan$q),
        .clock(s3_nan$clock)
    );
    top$cnt_dop$pending s3_inf(
        .d(s3_inf$d),
        .q(s3_inf$q),
        .clock(s3_inf$clock)
    );
    top$cnt_dop$pending s3_zero(
        .d(s3_zero$d),
        .q(s3_zero$q),
        .clock(s3_zero$clock)
    );
    top$cnt_dop$pending s3_ovf(
        .d(s3_ovf$d),
        .q(s3_ovf$q),
        .clock(s3_ovf$clock)
    );
    top$dop$dec_d$0$add$s1_exp s3_efield(
        .d(s3_efield$d),
        .q(s3_efield$q),
        .clock(s3_efield$clock)
    );
    top$dop$dec_d$0$add$s2_nm s3_nm(
        .d(s3_nm$d),
        .q(s3_nm$q),
        .clock(s3_nm$clock)
    );
    top$dop$dec_d$0$add$round round(
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
    top$cnt_dop$pending s4_valid(
        .d(s4_valid$d),
        .q(s4_valid$q),
        .clock(s4_valid$clock)
    );
    top$cnt_dop$total s4_y(
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
    
endmodule // top$dop$unit$doptrf$0$mul_0


module top$dop$unit$doptrf$0$mul_0$norm_a(x,y,lz);
    
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
    
endmodule // top$dop$unit$doptrf$0$mul_0$norm_a


module top$dop$unit$doptrf$0$mul_0$sig_mul(a,b,hi,sticky);
    
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
endmodule // top$dop$unit$doptrf$0$mul_0$sig_mul


module top$dop$unit$doptrf$0$r_mul(clock,d,q);
    
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
    top$cnt_dop$pending line$0(
        .d(line$0$d),
        .q(line$0$q),
        .clock(line$0$clock)
    );
    top$cnt_dop$pending line$1(
        .d(line$1$d),
        .q(line$1$q),
        .clock(line$1$clock)
    );
    top$cnt_dop$pending line$2(
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
    
endmodule // top$dop$unit$doptrf$0$r_mul


module top$dop$unit$klmsel(d$0,d$1,d$2,d$3,d$4,d$5,d$6,d$7,d$8,d$9,d$10,d$11,d$12,d$13,d$14,d$15,d$16,d$17,d$18,d$19,d$20,d$21,d$22,d$23,j0$0,j0$1,j0$2,j0$3,j0$4,j0$5,j0$6,j0$7,j0$8,j0$9,j0$10,j0$11,j0$12,j0$13,j0$14,j0$15,j0$16,j0$17,j0$18,j0$19,j0$20,j0$21,j0$22,j0$23,j1$0,j1$1,j1$2,j1$3,j1$4,j1$5,j1$6,j1$7,j1$8,j1$9,j1$10,j1$11,j1$12,j1$13,j1$14,j1$15,j1$16,j1$17,j1$18,j1$19,j1$20,j1$21,j1$22,j1$23,j2$0,j2$1,j2$2,j2$3,j2$4,j2$5,j2$6,j2$7,j2$8,j2$9,j2$10,j2$11,j2$12,j2$13,j2$14,j2$15,j2$16,j2$17,j2$18,j2$19,j2$20,j2$21,j2$22,j2$23,y0$0,y0$1,y0$2,y0$3,y0$4,y0$5,y0$6,y0$7,y0$8,y0$9,y0$10,y0$11,y0$12,y0$13,y0$14,y0$15,y0$16,y0$17,y0$18,y0$19,y0$20,y0$21,y0$22,y0$23,y1$0,y1$1,y1$2,y1$3,y1$4,y1$5,y1$6,y1$7,y1$8,y1$9,y1$10,y1$11,y1$12,y1$13,y1$14,y1$15,y1$16,y1$17,y1$18,y1$19,y1$20,y1$21,y1$22,y1$23,y2$0,y2$1,y2$2,y2$3,y2$4,y2$5,y2$6,y2$7,y2$8,y2$9,y2$10,y2$11,y2$12,y2$13,y2$14,y2$15,y2$16,y2$17,y2$18,y2$19,y2$20,y2$21,y2$22,y2$23);
    
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
    input wire  [4:0] j0$1;
    input wire  [4:0] j0$2;
    input wire  [4:0] j0$3;
    input wire  [4:0] j0$4;
    input wire  [4:0] j0$5;
    input wire  [4:0] j0$6;
    input wire  [4:0] j0$7;
    input wire  [4:0] j0$8;
    input wire  [4:0] j0$9;
    input wire  [4:0] j0$10;
    input wire  [4:0] j0$11;
    input wire  [4:0] j0$12;
    input wire  [4:0] j0$13;
    input wire  [4:0] j0$14;
    input wire  [4:0] j0$15;
    input wire  [4:0] j0$16;
    input wire  [4:0] j0$17;
    input wire  [4:0] j0$18;
    input wire  [4:0] j0$19;
    input wire  [4:0] j0$20;
    input wire  [4:0] j0$21;
    input wire  [4:0] j0$22;
    input wire  [4:0] j0$23;
    input wire  [4:0] j1$0;
    input wire  [4:0] j1$1;
    input wire  [4:0] j1$2;
    input wire  [4:0] j1$3;
    input wire  [4:0] j1$4;
    input wire  [4:0] j1$5;
    input wire  [4:0] j1$6;
    input wire  [4:0] j1$7;
    input wire  [4:0] j1$8;
    input wire  [4:0] j1$9;
    input wire  [4:0] j1$10;
    input wire  [4:0] j1$11;
    input wire  [4:0] j1$12;
    input wire  [4:0] j1$13;
    input wire  [4:0] j1$14;
    input wire  [4:0] j1$15;
    input wire  [4:0] j1$16;
    input wire  [4:0] j1$17;
    input wire  [4:0] j1$18;
    input wire  [4:0] j1$19;
    input wire  [4:0] j1$20;
    input wire  [4:0] j1$21;
    input wire  [4:0] j1$22;
    input wire  [4:0] j1$23;
    input wire  [4:0] j2$0;
    input wire  [4:0] j2$1;
    input wire  [4:0] j2$2;
    input wire  [4:0] j2$3;
    input wire  [4:0] j2$4;
    input wire  [4:0] j2$5;
    input wire  [4:0] j2$6;
    input wire  [4:0] j2$7;
    input wire  [4:0] j2$8;
    input wire  [4:0] j2$9;
    input wire  [4:0] j2$10;
    input wire  [4:0] j2$11;
    input wire  [4:0] j2$12;
    input wire  [4:0] j2$13;
    input wire  [4:0] j2$14;
    input wire  [4:0] j2$15;
    input wire  [4:0] j2$16;
    input wire  [4:0] j2$17;
    input wire  [4:0] j2$18;
    input wire  [4:0] j2$19;
    input wire  [4:0] j2$20;
    input wire  [4:0] j2$21;
    input wire  [4:0] j2$22;
    input wire  [4:0] j2$23;
    output reg  [31:0] y0$0;
    output reg  [31:0] y0$1;
    output reg  [31:0] y0$2;
    output reg  [31:0] y0$3;
    output reg  [31:0] y0$4;
    output reg  [31:0] y0$5;
    output reg  [31:0] y0$6;
    output reg  [31:0] y0$7;
    output reg  [31:0] y0$8;
    output reg  [31:0] y0$9;
    output reg  [31:0] y0$10;
    output reg  [31:0] y0$11;
    output reg  [31:0] y0$12;
    output reg  [31:0] y0$13;
    output reg  [31:0] y0$14;
    output reg  [31:0] y0$15;
    output reg  [31:0] y0$16;
    output reg  [31:0] y0$17;
    output reg  [31:0] y0$18;
    output reg  [31:0] y0$19;
    output reg  [31:0] y0$20;
    output reg  [31:0] y0$21;
    output reg  [31:0] y0$22;
    output reg  [31:0] y0$23;
    output reg  [31:0] y1$0;
    output reg  [31:0] y1$1;
    output reg  [31:0] y1$2;
    output reg  [31:0] y1$3;
    output reg  [31:0] y1$4;
    output reg  [31:0] y1$5;
    output reg  [31:0] y1$6;
    output reg  [31:0] y1$7;
    output reg  [31:0] y1$8;
    output reg  [31:0] y1$9;
    output reg  [31:0] y1$10;
    output reg  [31:0] y1$11;
    output reg  [31:0] y1$12;
    output reg  [31:0] y1$13;
    output reg  [31:0] y1$14;
    output reg  [31:0] y1$15;
    output reg  [31:0] y1$16;
    output reg  [31:0] y1$17;
    output reg  [31:0] y1$18;
    output reg  [31:0] y1$19;
    output reg  [31:0] y1$20;
    output reg  [31:0] y1$21;
    output reg  [31:0] y1$22;
    output reg  [31:0] y1$23;
    output reg  [31:0] y2$0;
    output reg  [31:0] y2$1;
    output reg  [31:0] y2$2;
    output reg  [31:0] y2$3;
    output reg  [31:0] y2$4;
    output reg  [31:0] y2$5;
    output reg  [31:0] y2$6;
    output reg  [31:0] y2$7;
    output reg  [31:0] y2$8;
    output reg  [31:0] y2$9;
    output reg  [31:0] y2$10;
    output reg  [31:0] y2$11;
    output reg  [31:0] y2$12;
    output reg  [31:0] y2$13;
    output reg  [31:0] y2$14;
    output reg  [31:0] y2$15;
    output reg  [31:0] y2$16;
    output reg  [31:0] y2$17;
    output reg  [31:0] y2$18;
    output reg  [31:0] y2$19;
    output reg  [31:0] y2$20;
    output reg  [31:0] y2$21;
    output reg  [31:0] y2$22;
    output reg  [31:0] y2$23;
    
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
        y0$1 = 32'h0;
        y1$1 = 32'h0;
        y2$1 = 32'h0;
        if (j0$1 == idx$0) begin
            y0$1 = d$0;
        end
        if (j1$1 == idx$0) begin
            y1$1 = d$0;
        end
        if (j2$1 == idx$0) begin
            y2$1 = d$0;
        end
        if (j0$1 == idx$1) begin
            y0$1 = d$1;
        end
        if (j1$1 == idx$1) begin
            y1$1 = d$1;
        end
        if (j2$1 == idx$1) begin
            y2$1 = d$1;
        end
        if (j0$1 == idx$2) begin
            y0$1 = d$2;
        end
        if (j1$1 == idx$2) begin
            y1$1 = d$2;
        end
        if (j2$1 == idx$2) begin
            y2$1 = d$2;
        end
        if (j0$1 == idx$3) begin
            y0$1 = d$3;
        end
        if (j1$1 == idx$3) begin
            y1$1 = d$3;
        end
        if (j2$1 == idx$3) begin
            y2$1 = d$3;
        end
        if (j0$1 == idx$4) begin
            y0$1 = d$4;
        end
        if (j1$1 == idx$4) begin
            y1$1 = d$4;
        end
        if (j2$1 == idx$4) begin
            y2$1 = d$4;
        end
        if (j0$1 == idx$5) begin
            y0$1 = d$5;
        end
        if (j1$1 == idx$5) begin
            y1$1 = d$5;
        end
        if (j2$1 == idx$5) begin
            y2$1 = d$5;
        end
        if (j0$1 == idx$6) begin
            y0$1 = d$6;
        end
        if (j1$1 == idx$6) begin
            y1$1 = d$6;
        end
        if (j2$1 == idx$6) begin
            y2$1 = d$6;
        end
        if (j0$1 == idx$7) begin
            y0$1 = d$7;
        end
        if (j1$1 == idx$7) begin
            y1$1 = d$7;
        end
        if (j2$1 == idx$7) begin
            y2$1 = d$7;
        end
        if (j0$1 == idx$8) begin
            y0$1 = d$8;
        end
        if (j1$1 == idx$8) begin
            y1$1 = d$8;
        end
        if (j2$1 == idx$8) begin
            y2$1 = d$8;
        end
        if (j0$1 == idx$9) begin
            y0$1 = d$9;
        end
        if (j1$1 == idx$9) begin
            y1$1 = d$9;
        end
        if (j2$1 == idx$9) begin
            y2$1 = d$9;
        end
        if (j0$1 == idx$10) begin
            y0$1 = d$10;
        end
        if (j1$1 == idx$10) begin
            y1$1 = d$10;
        end
        if (j2$1 == idx$10) begin
            y2$1 = d$10;
        end
        if (j0$1 == idx$11) begin
            y0$1 = d$11;
        end
        if (j1$1 == idx$11) begin
            y1$1 = d$11;
        end
        if (j2$1 == idx$11) begin
            y2$1 = d$11;
        end
        if (j0$1 == idx$12) begin
            y0$1 = d$12;
        end
        if (j1$1 == idx$12) begin
            y1$1 = d$12;
        end
        if (j2$1 == idx$12) begin
            y2$1 = d$12;
        end
        if (j0$1 == idx$13) begin
            y0$1 = d$13;
        end
        if (j1$1 == idx$13) begin
            y1$1 = d$13;
        end
        if (j2$1 == idx$13) begin
            y2$1 = d$13;
        end
        if (j0$1 == idx$14) begin
            y0$1 = d$14;
        end
        if (j1$1 == idx$14) begin
            y1$1 = d$14;
        end
        if (j2$1 == idx$14) begin
            y2$1 = d$14;
        end
        if (j0$1 == idx$15) begin
            y0$1 = d$15;
        end
        if (j1$1 == idx$15) begin
            y1$1 = d$15;
        end
        if (j2$1 == idx$15) begin
            y2$1 = d$15;
        end
        if (j0$1 == idx$16) begin
            y0$1 = d$16;
        end
        if (j1$1 == idx$16) begin
            y1$1 = d$16;
        end
        if (j2$1 == idx$16) begin
            y2$1 = d$16;
        end
        if (j0$1 == idx$17) begin
            y0$1 = d$17;
        end
        if (j1$1 == idx$17) begin
            y1$1 = d$17;
        end
        if (j2$1 == idx$17) begin
            y2$1 = d$17;
        end
        if (j0$1 == idx$18) begin
            y0$1 = d$18;
        end
        if (j1$1 == idx$18) begin
            y1$1 = d$18;
        end
        if (j2$1 == idx$18) begin
            y2$1 = d$18;
        end
        if (j0$1 == idx$19) begin
            y0$1 = d$19;
        end
        if (j1$1 == idx$19) begin
            y1$1 = d$19;
        end
        if (j2$1 == idx$19) begin
            y2$1 = d$19;
        end
        if (j0$1 == idx$20) begin
            y0$1 = d$20;
        end
        if (j1$1 == idx$20) begin
            y1$1 = d$20;
        end
        if (j2$1 == idx$20) begin
            y2$1 = d$20;
        end
        if (j0$1 == idx$21) begin
            y0$1 = d$21;
        end
        if (j1$1 == idx$21) begin
            y1$1 = d$21;
        end
        if (j2$1 == idx$21) begin
            y2$1 = d$21;
        end
        if (j0$1 == idx$22) begin
            y0$1 = d$22;
        end
        if (j1$1 == idx$22) begin
            y1$1 = d$22;
        end
        if (j2$1 == idx$22) begin
            y2$1 = d$22;
        end
        if (j0$1 == idx$23) begin
            y0$1 = d$23;
        end
        if (j1$1 == idx$23) begin
            y1$1 = d$23;
        end
        if (j2$1 == idx$23) begin
            y2$1 = d$23;
        end
        y0$2 = 32'h0;
        y1$2 = 32'h0;
        y2$2 = 32'h0;
        if (j0$2 == idx$0) begin
            y0$2 = d$0;
        end
        if (j1$2 == idx$0) begin
            y1$2 = d$0;
        end
        if (j2$2 == idx$0) begin
            y2$2 = d$0;
        end
        if (j0$2 == idx$1) begin
            y0$2 = d$1;
        end
        if (j1$2 == idx$1) begin
            y1$2 = d$1;
        end
        if (j2$2 == idx$1) begin
            y2$2 = d$1;
        end
        if (j0$2 == idx$2) begin
            y0$2 = d$2;
        end
        if (j1$2 == idx$2) begin
            y1$2 = d$2;
        end
        if (j2$2 == idx$2) begin
            y2$2 = d$2;
        end
        if (j0$2 == idx$3) begin
            y0$2 = d$3;
        end
        if (j1$2 == idx$3) begin
            y1$2 = d$3;
        end
        if (j2$2 == idx$3) begin
            y2$2 = d$3;
        end
        if (j0$2 == idx$4) begin
            y0$2 = d$4;
        end
        if (j1$2 == idx$4) begin
            y1$2 = d$4;
        end
        if (j2$2 == idx$4) begin
            y2$2 = d$4;
        end
        if (j0$2 == idx$5) begin
            y0$2 = d$5;
        end
        if (j1$2 == idx$5) begin
            y1$2 = d$5;
        end
        if (j2$2 == idx$5) begin
            y2$2 = d$5;
        end
        if (j0$2 == idx$6) begin
            y0$2 = d$6;
        end
        if (j1$2 == idx$6) begin
            y1$2 = d$6;
        end
        if (j2$2 == idx$6) begin
            y2$2 = d$6;
        end
        if (j0$2 == idx$7) begin
            y0$2 = d$7;
        end
        if (j1$2 == idx$7) begin
            y1$2 = d$7;
        end
        if (j2$2 == idx$7) begin
            y2$2 = d$7;
        end
        if (j0$2 == idx$8) begin
            y0$2 = d$8;
        end
        if (j1$2 == idx$8) begin
            y1$2 = d$8;
        end
        if (j2$2 == idx$8) begin
            y2$2 = d$8;
        end
        if (j0$2 == idx$9) begin
            y0$2 = d$9;
        end
        if (j1$2 == idx$9) begin
            y1$2 = d$9;
        end
        if (j2$2 == idx$9) begin
            y2$2 = d$9;
        end
        if (j0$2 == idx$10) begin
            y0$2 = d$10;
        end
        if (j1$2 == idx$10) begin
            y1$2 = d$10;
        end
        if (j2$2 == idx$10) begin
            y2$2 = d$10;
        end
        if (j0$2 == idx$11) begin
            y0$2 = d$11;
        end
        if (j1$2 == idx$11) begin
            y1$2 = d$11;
        end
        if (j2$2 == idx$11) begin
            y2$2 = d$11;
        end
        if (j0$2 == idx$12) begin
            y0$2 = d$12;
        end
        if (j1$2 == idx$12) begin
            y1$2 = d$12;
        end
        if (j2$2 == idx$12) begin
            y2$2 = d$12;
        end
        if (j0$2 == idx$13) begin
            y0$2 = d$13;
        end
        if (j1$2 == idx$13) begin
            y1$2 = d$13;
        end
        if (j2$2 == idx$13) begin
            y2$2 = d$13;
        end
        if (j0$2 == idx$14) begin
            y0$2 = d$14;
        end
        if (j1$2 == idx$14) begin
            y1$2 = d$14;
        end
        if (j2$2 == idx$14) begin
            y2$2 = d$14;
        end
        if (j0$2 == idx$15) begin
            y0$2 = d$15;
        end
        if (j1$2 == idx$15) begin
            y1$2 = d$15;
        end
        if (j2$2 == idx$15) begin
            y2$2 = d$15;
        end
        if (j0$2 == idx$16) begin
            y0$2 = d$16;
        end
        if (j1$2 == idx$16) begin
            y1$2 = d$16;
        end
        if (j2$2 == idx$16) begin
            y2$2 = d$16;
        end
        if (j0$2 == idx$17) begin
            y0$2 = d$17;
        end
        if (j1$2 == idx$17) begin
            y1$2 = d$17;
        end
        if (j2$2 == idx$17) begin
            y2$2 = d$17;
        end
        if (j0$2 == idx$18) begin
            y0$2 = d$18;
        end
        if (j1$2 == idx$18) begin
            y1$2 = d$18;
        end
        if (j2$2 == idx$18) begin
            y2$2 = d$18;
        end
        if (j0$2 == idx$19) begin
            y0$2 = d$19;
        end
        if (j1$2 == idx$19) begin
            y1$2 = d$19;
        end
        if (j2$2 == idx$19) begin
            y2$2 = d$19;
        end
        if (j0$2 == idx$20) begin
            y0$2 = d$20;
        end
        if (j1$2 == idx$20) begin
            y1$2 = d$20;
        end
        if (j2$2 == idx$20) begin
            y2$2 = d$20;
        end
        if (j0$2 == idx$21) begin
            y0$2 = d$21;
        end
        if (j1$2 == idx$21) begin
            y1$2 = d$21;
        end
        if (j2$2 == idx$21) begin
            y2$2 = d$21;
        end
        if (j0$2 == idx$22) begin
            y0$2 = d$22;
        end
        if (j1$2 == idx$22) begin
            y1$2 = d$22;
        end
        if (j2$2 == idx$22) begin
            y2$2 = d$22;
        end
        if (j0$2 == idx$23) begin
            y0$2 = d$23;
        end
        if (j1$2 == idx$23) begin
            y1$2 = d$23;
        end
        if (j2$2 == idx$23) begin
            y2$2 = d$23;
        end
        y0$3 = 32'h0;
        y1$3 = 32'h0;
        y2$3 = 32'h0;
        if (j0$3 == idx$0) begin
            y0$3 = d$0;
        end
        if (j1$3 == idx$0) begin
            y1$3 = d$0;
        end
        if (j2$3 == idx$0) begin
            y2$3 = d$0;
        end
        if (j0$3 == idx$1) begin
            y0$3 = d$1;
        end
        if (j1$3 == idx$1) begin
            y1$3 = d$1;
        end
        if (j2$3 == idx$1) begin
            y2$3 = d$1;
        end
        if (j0$3 == idx$2) begin
            y0$3 = d$2;
        end
        if (j1$3 == idx$2) begin
            y1$3 = d$2;
        end
        if (j2$3 == idx$2) begin
            y2$3 = d$2;
        end
        if (j0$3 == idx$3) begin
            y0$3 = d$3;
        end
        if (j1$3 == idx$3) begin
            y1$3 = d$3;
        end
        if (j2$3 == idx$3) begin
            y2$3 = d$3;
        end
        if (j0$3 == idx$4) begin
            y0$3 = d$4;
        end
        if (j1$3 == idx$4) begin
            y1$3 = d$4;
        end
        if (j2$3 == idx$4) begin
            y2$3 = d$4;
        end
        if (j0$3 == idx$5) begin
            y0$3 = d$5;
        end
        if (j1$3 == idx$5) begin
            y1$3 = d$5;
        end
        if (j2$3 == idx$5) begin
            y2$3 = d$5;
        end
        if (j0$3 == idx$6) begin
            y0$3 = d$6;
        end
        if (j1$3 == idx$6) begin
            y1$3 = d$6;
        end
        if (j2$3 == idx$6) begin
            y2$3 = d$6;
        end
        if (j0$3 == idx$7) begin
            y0$3 = d$7;
        end
        if (j1$3 == idx$7) begin
            y1$3 = d$7;
        end
        if (j2$3 == idx$7) begin
            y2$3 = d$7;
        end
        if (j0$3 == idx$8) begin
            y0$3 = d$8;
        end
        if (j1$3 == idx$8) begin
            y1$3 = d$8;
        end
        if (j2$3 == idx$8) begin
            y2$3 = d$8;
        end
        if (j0$3 == idx$9) begin
            y0$3 = d$9;
        end
        if (j1$3 == idx$9) begin
            y1$3 = d$9;
        end
        if (j2$3 == idx$9) begin
            y2$3 = d$9;
        end
        if (j0$3 == idx$10) begin
            y0$3 = d$10;
        end
        if (j1$3 == idx$10) begin
            y1$3 = d$10;
        end
        if (j2$3 == idx$10) begin
            y2$3 = d$10;
        end
        if (j0$3 == idx$11) begin
            y0$3 = d$11;
        end
        if (j1$3 == idx$11) begin
            y1$3 = d$11;
        end
        if (j2$3 == idx$11) begin
            y2$3 = d$11;
        end
        if (j0$3 == idx$12) begin
            y0$3 = d$12;
        end
        if (j1$3 == idx$12) begin
            y1$3 = d$12;
        end
        if (j2$3 == idx$12) begin
            y2$3 = d$12;
        end
        if (j0$3 == idx$13) begin
            y0$3 = d$13;
        end
        if (j1$3 == idx$13) begin
            y1$3 = d$13;
        end
        if (j2$3 == idx$13) begin
            y2$3 = d$13;
        end
        if (j0$3 == idx$14) begin
            y0$3 = d$14;
        end
        if (j1$3 == idx$14) begin
            y1$3 = d$14;
        end
        if (j2$3 == idx$14) begin
            y2$3 = d$14;
        end
        if (j0$3 == idx$15) begin
            y0$3 = d$15;
        end
        if (j1$3 == idx$15) begin
            y1$3 = d$15;
        end
        if (j2$3 == idx$15) begin
            y2$3 = d$15;
        end
        if (j0$3 == idx$16) begin
            y0$3 = d$16;
        end
        if (j1$3 == idx$16) begin
            y1$3 = d$16;
        end
        if (j2$3 == idx$16) begin
            y2$3 = d$16;
        end
        if (j0$3 == idx$17) begin
            y0$3 = d$17;
        end
        if (j1$3 == idx$17) begin
            y1$3 = d$17;
        end
        if (j2$3 == idx$17) begin
            y2$3 = d$17;
        end
        if (j0$3 == idx$18) begin
            y0$3 = d$18;
        end
        if (j1$3 == idx$18) begin
            y1$3 = d$18;
        end
        if (j2$3 == idx$18) begin
            y2$3 = d$18;
        end
        if (j0$3 == idx$19) begin
            y0$3 = d$19;
        end
        if (j1$3 == idx$19) begin
            y1$3 = d$19;
        end
        if (j2$3 == idx$19) begin
            y2$3 = d$19;
        end
        if (j0$3 == idx$20) begin
            y0$3 = d$20;
        end
        if (j1$3 == idx$20) begin
            y1$3 = d$20;
        end
        if (j2$3 == idx$20) begin
            y2$3 = d$20;
        end
        if (j0$3 == idx$21) begin
            y0$3 = d$21;
        end
        if (j1$3 == idx$21) begin
            y1$3 = d$21;
        end
        if (j2$3 == idx$21) begin
            y2$3 = d$21;
        end
        if (j0$3 == idx$22) begin
            y0$3 = d$22;
        end
        if (j1$3 == idx$22) begin
            y1$3 = d$22;
        end
        if (j2$3 == idx$22) begin
            y2$3 = d$22;
        end
        if (j0$3 == idx$23) begin
            y0$3 = d$23;
        end
        if (j1$3 == idx$23) begin
            y1$3 = d$23;
        end
        if (j2$3 == idx$23) begin
            y2$3 = d$23;
        end
        y0$4 = 32'h0;
        y1$4 = 32'h0;
        y2$4 = 32'h0;
        if (j0$4 == idx$0) begin
            y0$4 = d$0;
        end
        if (j1$4 == idx$0) begin
            y1$4 = d$0;
        end
        if (j2$4 == idx$0) begin
            y2$4 = d$0;
        end
        if (j0$4 == idx$1) begin
            y0$4 = d$1;
        end
        if (j1$4 == idx$1) begin
            y1$4 = d$1;
        end
        if (j2$4 == idx$1) begin
            y2$4 = d$1;
        end
        if (j0$4 == idx$2) begin
            y0$4 = d$2;
        end
        if (j1$4 == idx$2) begin
            y1$4 = d$2;
        end
        if (j2$4 == idx$2) begin
            y2$4 = d$2;
        end
        if (j0$4 == idx$3) begin
            y0$4 = d$3;
        end
        if (j1$4 == idx$3) begin
            y1$4 = d$3;
        end
        if (j2$4 == idx$3) begin
            y2$4 = d$3;
        end
        if (j0$4 == idx$4) begin
            y0$4 = d$4;
        end
        if (j1$4 == idx$4) begin
            y1$4 = d$4;
        end
        if (j2$4 == idx$4) begin
            y2$4 = d$4;
        end
        if (j0$4 == idx$5) begin
            y0$4 = d$5;
        end
        if (j1$4 == idx$5) begin
            y1$4 = d$5;
        end
        if (j2$4 == idx$5) begin
            y2$4 = d$5;
        end
        if (j0$4 == idx$6) begin
            y0$4 = d$6;
        end
        if (j1$4 == idx$6) begin
            y1$4 = d$6;
        end
        if (j2$4 == idx$6) begin
            y2$4 = d$6;
        end
        if (j0$4 == idx$7) begin
            y0$4 = d$7;
        end
        if (j1$4 == idx$7) begin
            y1$4 = d$7;
        end
        if (j2$4 == idx$7) begin
            y2$4 = d$7;
        end
        if (j0$4 == idx$8) begin
            y0$4 = d$8;
        end
        if (j1$4 == idx$8) begin
            y1$4 = d$8;
        end
        if (j2$4 == idx$8) begin
            y2$4 = d$8;
        end
        if (j0$4 == idx$9) begin
            y0$4 = d$9;
        end
        if (j1$4 == idx$9) begin
            y1$4 = d$9;
        end
        if (j2$4 == idx$9) begin
            y2$4 = d$9;
        end
        if (j0$4 == idx$10) begin
            y0$4 = d$10;
        end
        if (j1$4 == idx$10) begin
            y1$4 = d$10;
        end
        if (j2$4 == idx$10) begin
            y2$4 = d$10;
        end
        if (j0$4 == idx$11) begin
            y0$4 = d$11;
        end
        if (j1$4 == idx$11) begin
            y1$4 = d$11;
        end
        if (j2$4 == idx$11) begin
            y2$4 = d$11;
        end
        if (j0$4 == idx$12) begin
            y0$4 = d$12;
        end
        if (j1$4 == idx$12) begin
            y1$4 = d$12;
        end
        if (j2$4 == idx$12) begin
            y2$4 = d$12;
        end
        if (j0$4 == idx$13) begin
            y0$4 = d$13;
        end
        if (j1$4 == idx$13) begin
            y1$4 = d$13;
        end
        if (j2$4 == idx$13) begin
            y2$4 = d$13;
        end
        if (j0$4 == idx$14) begin
            y0$4 = d$14;
        end
        if (j1$4 == idx$14) begin
            y1$4 = d$14;
        end
        if (j2$4 == idx$14) begin
            y2$4 = d$14;
        end
        if (j0$4 == idx$15) begin
            y0$4 = d$15;
        end
        if (j1$4 == idx$15) begin
            y1$4 = d$15;
        end
        if (j2$4 == idx$15) begin
            y2$4 = d$15;
        end
        if (j0$4 == idx$16) begin
            y0$4 = d$16;
        end
        if (j1$4 == idx$16) begin
            y1$4 = d$16;
        end
        if (j2$4 == idx$16) begin
            y2$4 = d$16;
        end
        if (j0$4 == idx$17) begin
            y0$4 = d$17;
        end
        if (j1$4 == idx$17) begin
            y1$4 = d$17;
        end
        if (j2$4 == idx$17) begin
            y2$4 = d$17;
        end
        if (j0$4 == idx$18) begin
            y0$4 = d$18;
        end
        if (j1$4 == idx$18) begin
            y1$4 = d$18;
        end
        if (j2$4 == idx$18) begin
            y2$4 = d$18;
        end
        if (j0$4 == idx$19) begin
            y0$4 = d$19;
        end
        if (j1$4 == idx$19) begin
            y1$4 = d$19;
        end
        if (j2$4 == idx$19) begin
            y2$4 = d$19;
        end
        if (j0$4 == idx$20) begin
            y0$4 = d$20;
        end
        if (j1$4 == idx$20) begin
            y1$4 = d$20;
        end
        if (j2$4 == idx$20) begin
            y2$4 = d$20;
        end
        if (j0$4 == idx$21) begin
            y0$4 = d$21;
        end
        if (j1$4 == idx$21) begin
            y1$4 = d$21;
        end
        if (j2$4 == idx$21) begin
            y2$4 = d$21;
        end
        if (j0$4 == idx$22) begin
            y0$4 = d$22;
        end
        if (j1$4 == idx$22) begin
            y1$4 = d$22;
        end
        if (j2$4 == idx$22) begin
            y2$4 = d$22;
        end
        if (j0$4 == idx$23) begin
            y0$4 = d$23;
        end
        if (j1$4 == idx$23) begin
            y1$4 = d$23;
        end
        if (j2$4 == idx$23) begin
            y2$4 = d$23;
        end
        y0$5 = 32'h0;
        y1$5 = 32'h0;
        y2$5 = 32'h0;
        if (j0$5 == idx$0) begin
            y0$5 = d$0;
        end
        if (j1$5 == idx$0) begin
            y1$5 = d$0;
        end
        if (j2$5 == idx$0) begin
            y2$5 = d$0;
        end
        if (j0$5 == idx$1) begin
            y0$5 = d$1;
        end
        if (j1$5 == idx$1) begin
            y1$5 = d$1;
        end
        if (j2$5 == idx$1) begin
            y2$5 = d$1;
        end
        if (j0$5 == idx$2) begin
            y0$5 = d$2;
        end
        if (j1$5 == idx$2) begin
            y1$5 = d$2;
        end
        if (j2$5 == idx$2) begin
            y2$5 = d$2;
        end
        if (j0$5 == idx$3) begin
            y0$5 = d$3;
        end
        if (j1$5 == idx$3) begin
            y1$5 = d$3;
        end
        if (j2$5 == idx$3) begin
            y2$5 = d$3;
        end
        if (j0$5 == idx$4) begin
            y0$5 = d$4;
        end
        if (j1$5 == idx$4) begin
            y1$5 = d$4;
        end
        if (j2$5 == idx$4) begin
            y2$5 = d$4;
        end
        if (j0$5 == idx$5) begin
            y0$5 = d$5;
        end
        if (j1$5 == idx$5) begin
            y1$5 = d$5;
        end
        if (j2$5 == idx$5) begin
            y2$5 = d$5;
        end
        if (j0$5 == idx$6) begin
            y0$5 = d$6;
        end
        if (j1$5 == idx$6) begin
            y1$5 = d$6;
        end
        if (j2$5 == idx$6) begin
            y2$5 = d$6;
        end
        if (j0$5 == idx$7) begin
            y0$5 = d$7;
        end
        if (j1$5 == idx$7) begin
            y1$5 = d$7;
        end
        if (j2$5 == idx$7) begin
            y2$5 = d$7;
        end
        if (j0$5 == idx$8) begin
            y0$5 = d$8;
        end
        if (j1$5 == idx$8) begin
            y1$5 = d$8;
        end
        if (j2$5 == idx$8) begin
            y2$5 = d$8;
        end
        if (j0$5 == idx$9) begin
            y0$5 = d$9;
        end
        if (j1$5 == idx$9) begin
            y1$5 = d$9;
        end
        if (j2$5 == idx$9) begin
            y2$5 = d$9;
        end
        if (j0$5 == idx$10) begin
            y0$5 = d$10;
        end
        if (j1$5 == idx$10) begin
            y1$5 = d$10;
        end
        if (j2$5 == idx$10) begin
            y2$5 = d$10;
        end
        if (j0$5 == idx$11) begin
            y0$5 = d$11;
        end
        if (j1$5 == idx$11) begin
            y1$5 = d$11;
        end
        if (j2$5 == idx$11) begin
            y2$5 = d$11;
        end
        if (j0$5 == idx$12) begin
            y0$5 = d$12;
        end
        if (j1$5 == idx$12) begin
            y1$5 = d$12;
        end
        if (j2$5 == idx$12) begin
            y2$5 = d$12;
        end
        if (j0$5 == idx$13) begin
            y0$5 = d$13;
        end
        if (j1$5 == idx$13) begin
            y1$5 = d$13;
        end
        if (j2$5 == idx$13) begin
            y2$5 = d$13;
        end
        if (j0$5 == idx$14) begin
            y0$5 = d$14;
        end
        if (j1$5 == idx$14) begin
            y1$5 = d$14;
        end
        if (j2$5 == idx$14) begin
            y2$5 = d$14;
        end
        if (j0$5 == idx$15) begin
            y0$5 = d$15;
        end
        if (j1$5 == idx$15) begin
            y1$5 = d$15;
        end
        if (j2$5 == idx$15) begin
            y2$5 = d$15;
        end
        if (j0$5 == idx$16) begin
            y0$5 = d$16;
        end
        if (j1$5 == idx$16) begin
            y1$5 = d$16;
        end
        if (j2$5 == idx$16) begin
            y2$5 = d$16;
        end
        if (j0$5 == idx$17) begin
            y0$5 = d$17;
        end
        if (j1$5 == idx$17) begin
            y1$5 = d$17;
        end
        if (j2$5 == idx$17) begin
            y2$5 = d$17;
        end
        if (j0$5 == idx$18) begin
            y0$5 = d$18;
        end
        if (j1$5 == idx$18) begin
            y1$5 = d$18;
        end
        if (j2$5 == idx$18) begin
            y2$5 = d$18;
        end
        if (j0$5 == idx$19) begin
            y0$5 = d$19;
        end
        if (j1$5 == idx$19) begin
            y1$5 = d$19;
        end
        if (j2$5 == idx$19) begin
            y2$5 = d$19;
        end
        if (j0$5 == idx$20) begin
            y0$5 = d$20;
        end
        if (j1$5 == idx$20) begin
            y1$5 = d$20;
        end
        if (j2$5 == idx$20) begin
            y2$5 = d$20;
        end
        if (j0$5 == idx$21) begin
            y0$5 = d$21;
        end
        if (j1$5 == idx$21) begin
            y1$5 = d$21;
        end
        if (j2$5 == idx$21) begin
            y2$5 = d$21;
        end
        if (j0$5 == idx$22) begin
            y0$5 = d$22;
        end
        if (j1$5 == idx$22) begin
            y1$5 = d$22;
        end
        if (j2$5 == idx$22) begin
            y2$5 = d$22;
        end
        if (j0$5 == idx$23) begin
            y0$5 = d$23;
        end
        if (j1$5 == idx$23) begin
            y1$5 = d$23;
        end
        if (j2$5 == idx$23) begin
            y2$5 = d$23;
        end
        y0$6 = 32'h0;
        y1$6 = 32'h0;
        y2$6 = 32'h0;
        if (j0$6 == idx$0) begin
            y0$6 = d$0;
        end
        if (j1$6 == idx$0) begin
            y1$6 = d$0;
        end
        if (j2$6 == idx$0) begin
            y2$6 = d$0;
        end
        if (j0$6 == idx$1) begin
            y0$6 = d$1;
        end
        if (j1$6 == idx$1) begin
            y1$6 = d$1;
        end
        if (j2$6 == idx$1) begin
            y2$6 = d$1;
        end
        if (j0$6 == idx$2) begin
            y0$6 = d$2;
        end
        if (j1$6 == idx$2) begin
            y1$6 = d$2;
        end
        if (j2$6 == idx$2) begin
            y2$6 = d$2;
        end
        if (j0$6 == idx$3) begin
            y0$6 = d$3;
        end
        if (j1$6 == idx$3) begin
            y1$6 = d$3;
        end
        if (j2$6 == idx$3) begin
            y2$6 = d$3;
        end
        if (j0$6 == idx$4) begin
            y0$6 = d$4;
        end
        if (j1$6 == idx$4) begin
            y1$6 = d$4;
        end
        if (j2$6 == idx$4) begin
            y2$6 = d$4;
        end
        if (j0$6 == idx$5) begin
            y0$6 = d$5;
        end
        if (j1$6 == idx$5) begin
            y1$6 = d$5;
        end
        if (j2$6 == idx$5) begin
            y2$6 = d$5;
        end
        if (j0$6 == idx$6) begin
            y0$6 = d$6;
        end
        if (j1$6 == idx$6) begin
            y1$6 = d$6;
        end
        if (j2$6 == idx$6) begin
            y2$6 = d$6;
        end
        if (j0$6 == idx$7) begin
            y0$6 = d$7;
        end
        if (j1$6 == idx$7) begin
            y1$6 = d$7;
        end
        if (j2$6 == idx$7) begin
            y2$6 = d$7;
        end
        if (j0$6 == idx$8) begin
            y0$6 = d$8;
        end
        if (j1$6 == idx$8) begin
            y1$6 = d$8;
        end
        if (j2$6 == idx$8) begin
            y2$6 = d$8;
        end
        if (j0$6 == idx$9) begin
            y0$6 = d$9;
        end
        if (j1$6 == idx$9) begin
            y1$6 = d$9;
        end
        if (j2$6 == idx$9) begin
            y2$6 = d$9;
        end
        if (j0$6 == idx$10) begin
            y0$6 = d$10;
        end
        if (j1$6 == idx$10) begin
            y1$6 = d$10;
        end
        if (j2$6 == idx$10) begin
            y2$6 = d$10;
        end
        if (j0$6 == idx$11) begin
            y0$6 = d$11;
        end
        if (j1$6 == idx$11) begin
            y1$6 = d$11;
        end
        if (j2$6 == idx$11) begin
            y2$6 = d$11;
        end
        if (j0$6 == idx$12) begin
            y0$6 = d$12;
        end
        if (j1$6 == idx$12) begin
            y1$6 = d$12;
        end
        if (j2$6 == idx$12) begin
            y2$6 = d$12;
        end
        if (j0$6 == idx$13) begin
            y0$6 = d$13;
        end
        if (j1$6 == idx$13) begin
            y1$6 = d$13;
        end
        if (j2$6 == idx$13) begin
            y2$6 = d$13;
        end
        if (j0$6 == idx$14) begin
            y0$6 = d$14;
        end
        if (j1$6 == idx$14) begin
            y1$6 = d$14;
        end
        if (j2$6 == idx$14) begin
            y2$6 = d$14;
        end
        if (j0$6 == idx$15) begin
            y0$6 = d$15;
        end
        if (j1$6 == idx$15) begin
            y1$6 = d$15;
        end
        if (j2$6 == idx$15) begin
            y2$6 = d$15;
        end
        if (j0$6 == idx$16) begin
            y0$6 = d$16;
        end
        if (j1$6 == idx$16) begin
            y1$6 = d$16;
        end
        if (j2$6 == idx$16) begin
            y2$6 = d$16;
        end
        if (j0$6 == idx$17) begin
            y0$6 = d$17;
        end
        if (j1$6 == idx$17) begin
            y1$6 = d$17;
        end
        if (j2$6 == idx$17) begin
            y2$6 = d$17;
        end
        if (j0$6 == idx$18) begin
            y0$6 = d$18;
        end
        if (j1$6 == idx$18) begin
            y1$6 = d$18;
        end
        if (j2$6 == idx$18) begin
            y2$6 = d$18;
        end
        if (j0$6 == idx$19) begin
            y0$6 = d$19;
        end
        if (j1$6 == idx$19) begin
            y1$6 = d$19;
        end
        if (j2$6 == idx$19) begin
            y2$6 = d$19;
        end
        if (j0$6 == idx$20) begin
            y0$6 = d$20;
        end
        if (j1$6 == idx$20) begin
            y1$6 = d$20;
        end
        if (j2$6 == idx$20) begin
            y2$6 = d$20;
        end
        if (j0$6 == idx$21) begin
            y0$6 = d$21;
        end
        if (j1$6 == idx$21) begin
            y1$6 = d$21;
        end
        if (j2$6 == idx$21) begin
            y2$6 = d$21;
        end
        if (j0$6 == idx$22) begin
            y0$6 = d$22;
        end
        if (j1$6 == idx$22) begin
            y1$6 = d$22;
        end
        if (j2$6 == idx$22) begin
            y2$6 = d$22;
        end
        if (j0$6 == idx$23) begin
            y0$6 = d$23;
        end
        if (j1$6 == idx$23) begin
            y1$6 = d$23;
        end
        if (j2$6 == idx$23) begin
            y2$6 = d$23;
        end
        y0$7 = 32'h0;
        y1$7 = 32'h0;
        y2$7 = 32'h0;
        if (j0$7 == idx$0) begin
            y0$7 = d$0;
        end
        if (j1$7 == idx$0) begin
            y1$7 = d$0;
        end
        if (j2$7 == idx$0) begin
            y2$7 = d$0;
        end
        if (j0$7 == idx$1) begin
            y0$7 = d$1;
        end
        if (j1$7 == idx$1) begin
            y1$7 = d$1;
        end
        if (j2$7 == idx$1) begin
            y2$7 = d$1;
        end
        if (j0$7 == idx$2) begin
            y0$7 = d$2;
        end
        if (j1$7 == idx$2) begin
            y1$7 = d$2;
        end
        if (j2$7 == idx$2) begin
            y2$7 = d$2;
        end
        if (j0$7 == idx$3) begin
            y0$7 = d$3;
        end
        if (j1$7 == idx$3) begin
            y1$7 = d$3;
        end
        if (j2$7 == idx$3) begin
            y2$7 = d$3;
        end
        if (j0$7 == idx$4) begin
            y0$7 = d$4;
        end
        if (j1$7 == idx$4) begin
            y1$7 = d$4;
        end
        if (j2$7 == idx$4) begin
            y2$7 = d$4;
        end
        if (j0$7 == idx$5) begin
            y0$7 = d$5;
        end
        if (j1$7 == idx$5) begin
            y1$7 = d$5;
        end
        if (j2$7 == idx$5) begin
            y2$7 = d$5;
        end
        if (j0$7 == idx$6) begin
            y0$7 = d$6;
        end
        if (j1$7 == idx$6) begin
            y1$7 = d$6;
        end
        if (j2$7 == idx$6) begin
            y2$7 = d$6;
        end
        if (j0$7 == idx$7) begin
            y0$7 = d$7;
        end
        if (j1$7 == idx$7) begin
            y1$7 = d$7;
        end
        if (j2$7 == idx$7) begin
            y2$7 = d$7;
        end
        if (j0$7 == idx$8) begin
            y0$7 = d$8;
        end
        if (j1$7 == idx$8) begin
            y1$7 = d$8;
        end
        if (j2$7 == idx$8) begin
            y2$7 = d$8;
        end
        if (j0$7 == idx$9) begin
            y0$7 = d$9;
        end
        if (j1$7 == idx$9) begin
            y1$7 = d$9;
        end
        if (j2$7 == idx$9) begin
            y2$7 = d$9;
        end
        if (j0$7 == idx$10) begin
            y0$7 = d$10;
        end
        if (j1$7 == idx$10) begin
            y1$7 = d$10;
        end
        if (j2$7 == idx$10) begin
            y2$7 = d$10;
        end
        if (j0$7 == idx$11) begin
            y0$7 = d$11;
        end
        if (j1$7 == idx$11) begin
            y1$7 = d$11;
        end
        if (j2$7 == idx$11) begin
            y2$7 = d$11;
        end
        if (j0$7 == idx$12) begin
            y0$7 = d$12;
        end
        if (j1$7 == idx$12) begin
            y1$7 = d$12;
        end
        if (j2$7 == idx$12) begin
            y2$7 = d$12;
        end
        if (j0$7 == idx$13) begin
            y0$7 = d$13;
        end
        if (j1$7 == idx$13) begin
            y1$7 = d$13;
        end
        if (j2$7 == idx$13) begin
            y2$7 = d$13;
        end
        if (j0$7 == idx$14) begin
            y0$7 = d$14;
        end
        if (j1$7 == idx$14) begin
            y1$7 = d$14;
        end
        if (j2$7 == idx$14) begin
            y2$7 = d$14;
        end
        if (j0$7 == idx$15) begin
            y0$7 = d$15;
        end
        if (j1$7 == idx$15) begin
            y1$7 = d$15;
        end
        if (j2$7 == idx$15) begin
            y2$7 = d$15;
        end
        if (j0$7 == idx$16) begin
            y0$7 = d$16;
        end
        if (j1$7 == idx$16) begin
            y1$7 = d$16;
        end
        if (j2$7 == idx$16) begin
            y2$7 = d$16;
        end
        if (j0$7 == idx$17) begin
            y0$7 = d$17;
        end
        if (j1$7 == idx$17) begin
            y1$7 = d$17;
        end
        if (j2$7 == idx$17) begin
            y2$7 = d$17;
        end
        if (j0$7 == idx$18) begin
            y0$7 = d$18;
        end
        if (j1$7 == idx$18) begin
            y1$7 = d$18;
        end
        if (j2$7 == idx$18) begin
            y2$7 = d$18;
        end
        if (j0$7 == idx$19) begin
            y0$7 = d$19;
        end
        if (j1$7 == idx$19) begin
            y1$7 = d$19;
        end
        if (j2$7 == idx$19) begin
            y2$7 = d$19;
        end
        if (j0$7 == idx$20) begin
            y0$7 = d$20;
        end
        if (j1$7 == idx$20) begin
            y1$7 = d$20;
        end
        if (j2$7 == idx$20) begin
            y2$7 = d$20;
        end
        if (j0$7 == idx$21) begin
            y0$7 = d$21;
        end
        if (j1$7 == idx$21) begin
            y1$7 = d$21;
        end
        if (j2$7 == idx$21) begin
            y2$7 = d$21;
        end
        if (j0$7 == idx$22) begin
            y0$7 = d$22;
        end
        if (j1$7 == idx$22) begin
            y1$7 = d$22;
        end
        if (j2$7 == idx$22) begin
            y2$7 = d$22;
        end
        if (j0$7 == idx$23) begin
            y0$7 = d$23;
        end
        if (j1$7 == idx$23) begin
            y1$7 = d$23;
        end
        if (j2$7 == idx$23) begin
            y2$7 = d$23;
        end
        y0$8 = 32'h0;
        y1$8 = 32'h0;
        y2$8 = 32'h0;
        if (j0$8 == idx$0) begin
            y0$8 = d$0;
        end
        if (j1$8 == idx$0) begin
            y1$8 = d$0;
        end
        if (j2$8 == idx$0) begin
            y2$8 = d$0;
        end
        if (j0$8 == idx$1) begin
            y0$8 = d$1;
        end
        if (j1$8 == idx$1) begin
            y1$8 = d$1;
        end
        if (j2$8 == idx$1) begin
            y2$8 = d$1;
        end
        if (j0$8 == idx$2) begin
            y0$8 = d$2;
        end
        if (j1$8 == idx$2) begin
            y1$8 = d$2;
        end
        if (j2$8 == idx$2) begin
            y2$8 = d$2;
        end
        if (j0$8 == idx$3) begin
            y0$8 = d$3;
        end
        if (j1$8 == idx$3) begin
            y1$8 = d$3;
        end
        if (j2$8 == idx$3) begin
            y2$8 = d$3;
        end
        if (j0$8 == idx$4) begin
            y0$8 = d$4;
        end
        if (j1$8 == idx$4) begin
            y1$8 = d$4;
        end
        if (j2$8 == idx$4) begin
            y2$8 = d$4;
        end
        if (j0$8 == idx$5) begin
            y0$8 = d$5;
        end
        if (j1$8 == idx$5) begin
            y1$8 = d$5;
        end
        if (j2$8 == idx$5) begin
            y2$8 = d$5;
        end
        if (j0$8 == idx$6) begin
            y0$8 = d$6;
        end
        if (j1$8 == idx$6) begin
            y1$8 = d$6;
        end
        if (j2$8 == idx$6) begin
            y2$8 = d$6;
        end
        if (j0$8 == idx$7) begin
            y0$8 = d$7;
        end
        if (j1$8 == idx$7) begin
            y1$8 = d$7;
        end
        if (j2$8 == idx$7) begin
            y2$8 = d$7;
        end
        if (j0$8 == idx$8) begin
            y0$8 = d$8;
        end
        if (j1$8 == idx$8) begin
            y1$8 = d$8;
        end
        if (j2$8 == idx$8) begin
            y2$8 = d$8;
        end
        if (j0$8 == idx$9) begin
            y0$8 = d$9;
        end
        if (j1$8 == idx$9) begin
            y1$8 = d$9;
        end
        if (j2$8 == idx$9) begin
            y2$8 = d$9;
        end
        if (j0$8 == idx$10) begin
            y0$8 = d$10;
        end
        if (j1$8 == idx$10) begin
            y1$8 = d$10;
        end
        if (j2$8 == idx$10) begin
            y2$8 = d$10;
        end
        if (j0$8 == idx$11) begin
            y0$8 = d$11;
        end
        if (j1$8 == idx$11) begin
            y1$8 = d$11;
        end
        if (j2$8 == idx$11) begin
            y2$8 = d$11;
        end
        if (j0$8 == idx$12) begin
            y0$8 = d$12;
        end
        if (j1$8 == idx$12) begin
            y1$8 = d$12;
        end
        if (j2$8 == idx$12) begin
            y2$8 = d$12;
        end
        if (j0$8 == idx$13) begin
            y0$8 = d$13;
        end
        if (j1$8 == idx$13) begin
            y1$8 = d$13;
        end
        if (j2$8 == idx$13) begin
            y2$8 = d$13;
        end
        if (j0$8 == idx$14) begin
            y0$8 = d$14;
        end
        if (j1$8 == idx$14) begin
            y1$8 = d$14;
        end
        if (j2$8 == idx$14) begin
            y2$8 = d$14;
        end
        if (j0$8 == idx$15) begin
            y0$8 = d$15;
        end
        if (j1$8 == idx$15) begin
            y1$8 = d$15;
        end
        if (j2$8 == idx$15) begin
            y2$8 = d$15;
        end
        if (j0$8 == idx$16) begin
            y0$8 = d$16;
        end
        if (j1$8 == idx$16) begin
            y1$8 = d$16;
        end
        if (j2$8 == idx$16) begin
            y2$8 = d$16;
        end
        if (j0$8 == idx$17) begin
            y0$8 = d$17;
        end
        if (j1$8 == idx$17) begin
            y1$8 = d$17;
        end
        if (j2$8 == idx$17) begin
            y2$8 = d$17;
        end
        if (j0$8 == idx$18) begin
            y0$8 = d$18;
        end
        if (j1$8 == idx$18) begin
            y1$8 = d$18;
        end
        if (j2$8 == idx$18) begin
            y2$8 = d$18;
        end
        if (j0$8 == idx$19) begin
            y0$8 = d$19;
        end
        if (j1$8 == idx$19) begin
            y1$8 = d$19;
        end
        if (j2$8 == idx$19) begin
            y2$8 = d$19;
        end
        if (j0$8 == idx$20) begin
            y0$8 = d$20;
        end
        if (j1$8 == idx$20) begin
            y1$8 = d$20;
        end
        if (j2$8 == idx$20) begin
            y2$8 = d$20;
        end
        if (j0$8 == idx$21) begin
            y0$8 = d$21;
        end
        if (j1$8 == idx$21) begin
            y1$8 = d$21;
        end
        if (j2$8 == idx$21) begin
            y2$8 = d$21;
        end
        if (j0$8 == idx$22) begin
            y0$8 = d$22;
        end
        if (j1$8 == idx$22) begin
            y1$8 = d$22;
        end
        if (j2$8 == idx$22) begin
            y2$8 = d$22;
        end
        if (j0$8 == idx$23) begin
            y0$8 = d$23;
        end
        if (j1$8 == idx$23) begin
            y1$8 = d$23;
        end
        if (j2$8 == idx$23) begin
            y2$8 = d$23;
        end
        y0$9 = 32'h0;
        y1$9 = 32'h0;
        y2$9 = 32'h0;
        if (j0$9 == idx$0) begin
            y0$9 = d$0;
        end
        if (j1$9 == idx$0) begin
            y1$9 = d$0;
        end
        if (j2$9 == idx$0) begin
            y2$9 = d$0;
        end
        if (j0$9 == idx$1) begin
            y0$9 = d$1;
        end
        if (j1$9 == idx$1) begin
            y1$9 = d$1;
        end
        if (j2$9 == idx$1) begin
            y2$9 = d$1;
        end
        if (j0$9 == idx$2) begin
            y0$9 = d$2;
        end
        if (j1$9 == idx$2) begin
            y1$9 = d$2;
        end
        if (j2$9 == idx$2) begin
            y2$9 = d$2;
        end
        if (j0$9 == idx$3) begin
            y0$9 = d$3;
        end
        if (j1$9 == idx$3) begin
            y1$9 = d$3;
        end
        if (j2$9 == idx$3) begin
            y2$9 = d$3;
        end
        if (j0$9 == idx$4) begin
            y0$9 = d$4;
        end
        if (j1$9 == idx$4) begin
            y1$9 = d$4;
        end
        if (j2$9 == idx$4) begin
            y2$9 = d$4;
        end
        if (j0$9 == idx$5) begin
            y0$9 = d$5;
        end
        if (j1$9 == idx$5) begin
            y1$9 = d$5;
        end
        if (j2$9 == idx$5) begin
            y2$9 = d$5;
        end
        if (j0$9 == idx$6) begin
            y0$9 = d$6;
        end
        if (j1$9 == idx$6) begin
            y1$9 = d$6;
        end
        if (j2$9 == idx$6) begin
            y2$9 = d$6;
        end
        if (j0$9 == idx$7) begin
            y0$9 = d$7;
        end
        if (j1$9 == idx$7) begin
            y1$9 = d$7;
        end
        if (j2$9 == idx$7) begin
            y2$9 = d$7;
        end
        if (j0$9 == idx$8) begin
            y0$9 = d$8;
        end
        if (j1$9 == idx$8) begin
            y1$9 = d$8;
        end
        if (j2$9 == idx$8) begin
            y2$9 = d$8;
        end
        if (j0$9 == idx$9) begin
            y0$9 = d$9;
        end
        if (j1$9 == idx$9) begin
            y1$9 = d$9;
        end
        if (j2$9 == idx$9) begin
            y2$9 = d$9;
        end
        if (j0$9 == idx$10) begin
            y0$9 = d$10;
        end
        if (j1$9 == idx$10) begin
            y1$9 = d$10;
        end
        if (j2$9 == idx$10) begin
            y2$9 = d$10;
        end
        if (j0$9 == idx$11) begin
            y0$9 = d$11;
        end
        if (j1$9 == idx$11) begin
            y1$9 = d$11;
        end
        if (j2$9 == idx$11) begin
            y2$9 = d$11;
        end
        if (j0$9 == idx$12) begin
            y0$9 = d$12;
        end
        if (j1$9 == idx$12) begin
            y1$9 = d$12;
        end
        if (j2$9 == idx$12) begin
            y2$9 = d$12;
        end
        if (j0$9 == idx$13) begin
            y0$9 = d$13;
        end
        if (j1$9 == idx$13) begin
            y1$9 = d$13;
        end
        if (j2$9 == idx$13) begin
            y2$9 = d$13;
        end
        if (j0$9 == idx$14) begin
            y0$9 = d$14;
        end
        if (j1$9 == idx$14) begin
            y1$9 = d$14;
        end
        if (j2$9 == idx$14) begin
            y2$9 = d$14;
        end
        if (j0$9 == idx$15) begin
            y0$9 = d$15;
        end
        if (j1$9 == idx$15) begin
            y1$9 = d$15;
        end
        if (j2$9 == idx$15) begin
            y2$9 = d$15;
        end
        if (j0$9 == idx$16) begin
            y0$9 = d$16;
        end
        if (j1$9 == idx$16) begin
            y1$9 = d$16;
        end
        if (j2$9 == idx$16) begin
            y2$9 = d$16;
        end
        if (j0$9 == idx$17) begin
            y0$9 = d$17;
        end
        if (j1$9 == idx$17) begin
            y1$9 = d$17;
        end
        if (j2$9 == idx$17) begin
            y2$9 = d$17;
        end
        if (j0$9 == idx$18) begin
            y0$9 = d$18;
        end
        if (j1$9 == idx$18) begin
            y1$9 = d$18;
        end
        if (j2$9 == idx$18) begin
            y2$9 = d$18;
        end
        if (j0$9 == idx$19) begin
            y0$9 = d$19;
        end
        if (j1$9 == idx$19) begin
            y1$9 = d$19;
        end
        if (j2$9 == idx$19) begin
            y2$9 = d$19;
        end
        if (j0$9 == idx$20) begin
            y0$9 = d$20;
        end
        if (j1$9 == idx$20) begin
            y1$9 = d$20;
        end
        if (j2$9 == idx$20) begin
            y2$9 = d$20;
        end
        if (j0$9 == idx$21) begin
            y0$9 = d$21;
        end
        if (j1$9 == idx$21) begin
            y1$9 = d$21;
        end
        if (j2$9 == idx$21) begin
            y2$9 = d$21;
        end
        if (j0$9 == idx$22) begin
            y0$9 = d$22;
        end
        if (j1$9 == idx$22) begin
            y1$9 = d$22;
        end
        if (j2$9 == idx$22) begin
            y2$9 = d$22;
        end
        if (j0$9 == idx$23) begin
            y0$9 = d$23;
        end
        if (j1$9 == idx$23) begin
            y1$9 = d$23;
        end
        if (j2$9 == idx$23) begin
            y2$9 = d$23;
        end
        y0$10 = 32'h0;
        y1$10 = 32'h0;
        y2$10 = 32'h0;
        if (j0$10 == idx$0) begin
            y0$10 = d$0;
        end
        if (j1$10 == idx$0) begin
            y1$10 = d$0;
        end
        if (j2$10 == idx$0) begin
            y2$10 = d$0;
        end
        if (j0$10 == idx$1) begin
            y0$10 = d$1;
        end
        if (j1$10 == idx$1) begin
            y1$10 = d$1;
        end
        if (j2$10 == idx$1) begin
            y2$10 = d$1;
        end
        if (j0$10 == idx$2) begin
            y0$10 = d$2;
        end
        if (j1$10 == idx$2) begin
            y1$10 = d$2;
        end
        if (j2$10 == idx$2) begin
            y2$10 = d$2;
        end
        if (j0$10 == idx$3) begin
            y0$10 = d$3;
        end
        if (j1$10 == idx$3) begin
            y1$10 = d$3;
        end
        if (j2$10 == idx$3) begin
            y2$10 = d$3;
        end
        if (j0$10 == idx$4) begin
            y0$10 = d$4;
        end
        if (j1$10 == idx$4) begin
            y1$10 = d$4;
        end
        if (j2$10 == idx$4) begin
            y2$10 = d$4;
        end
        if (j0$10 == idx$5) begin
            y0$10 = d$5;
        end
        if (j1$10 == idx$5) begin
            y1$10 = d$5;
        end
        if (j2$10 == idx$5) begin
            y2$10 = d$5;
        end
        if (j0$10 == idx$6) begin
            y0$10 = d$6;
        end
        if (j1$10 == idx$6) begin
            y1$10 = d$6;
        end
        if (j2$10 == idx$6) begin
            y2$10 = d$6;
        end
        if (j0$10 == idx$7) begin
            y0$10 = d$7;
        end
        if (j1$10 == idx$7) begin
            y1$10 = d$7;
        end
        if (j2$10 == idx$7) begin
            y2$10 = d$7;
        end
        if (j0$10 == idx$8) begin
            y0$10 = d$8;
        end
        if (j1$10 == idx$8) begin
            y1$10 = d$8;
        end
        if (j2$10 == idx$8) begin
            y2$10 = d$8;
        end
        if (j0$10 == idx$9) begin
            y0$10 = d$9;
        end
        if (j1$10 == idx$9) begin
            y1$10 = d$9;
        end
        if (j2$10 == idx$9) begin
            y2$10 = d$9;
        end
        if (j0$10 == idx$10) begin
            y0$10 = d$10;
        end
        if (j1$10 == idx$10) begin
            y1$10 = d$10;
        end
        if (j2$10 == idx$10) begin
            y2$10 = d$10;
        end
        if (j0$10 == idx$11) begin
            y0$10 = d$11;
        end
        if (j1$10 == idx$11) begin
            y1$10 = d$11;
        end
        if (j2$10 == idx$11) begin
            y2$10 = d$11;
        end
        if (j0$10 == idx$12) begin
            y0$10 = d$12;
        end
        if (j1$10 == idx$12) begin
            y1$10 = d$12;
        end
        if (j2$10 == idx$12) begin
            y2$10 = d$12;
        end
        if (j0$10 == idx$13) begin
            y0$10 = d$13;
        end
        if (j1$10 == idx$13) begin
            y1$10 = d$13;
        end
        if (j2$10 == idx$13) begin
            y2$10 = d$13;
        end
        if (j0$10 == idx$14) begin
            y0$10 = d$14;
        end
        if (j1$10 == idx$14) begin
            y1$10 = d$14;
        end
        if (j2$10 == idx$14) begin
            y2$10 = d$14;
        end
        if (j0$10 == idx$15) begin
            y0$10 = d$15;
        end
        if (j1$10 == idx$15) begin
            y1$10 = d$15;
        end
        if (j2$10 == idx$15) begin
            y2$10 = d$15;
        end
        if (j0$10 == idx$16) begin
            y0$10 = d$16;
        end
        if (j1$10 == idx$16) begin
            y1$10 = d$16;
        end
        if (j2$10 == idx$16) begin
            y2$10 = d$16;
        end
        if (j0$10 == idx$17) begin
            y0$10 = d$17;
        end
        if (j1$10 == idx$17) begin
            y1$10 = d$17;
        end
        if (j2$10 == idx$17) begin
            y2$10 = d$17;
        end
        if (j0$10 == idx$18) begin
            y0$10 = d$18;
        end
        if (j1$10 == idx$18) begin
            y1$10 = d$18;
        end
        if (j2$10 == idx$18) begin
            y2$10 = d$18;
        end
        if (j0$10 == idx$19) begin
            y0$10 = d$19;
        end
        if (j1$10 == idx$19) begin
            y1$10 = d$19;
        end
        if (j2$10 == idx$19) begin
            y2$10 = d$19;
        end
        if (j0$10 == idx$20) begin
            y0$10 = d$20;
        end
        if (j1$10 == idx$20) begin
            y1$10 = d$20;
        end
        if (j2$10 == idx$20) begin
            y2$10 = d$20;
        end
        if (j0$10 == idx$21) begin
            y0$10 = d$21;
        end
        if (j1$10 == idx$21) begin
            y1$10 = d$21;
        end
        if (j2$10 == idx$21) begin
            y2$10 = d$21;
        end
        if (j0$10 == idx$22) begin
            y0$10 = d$22;
        end
        if (j1$10 == idx$22) begin
            y1$10 = d$22;
        end
        if (j2$10 == idx$22) begin
            y2$10 = d$22;
        end
        if (j0$10 == idx$23) begin
            y0$10 = d$23;
        end
        if (j1$10 == idx$23) begin
            y1$10 = d$23;
        end
        if (j2$10 == idx$23) begin
            y2$10 = d$23;
        end
        y0$11 = 32'h0;
        y1$11 = 32'h0;
        y2$11 = 32'h0;
        if (j0$11 == idx$0) begin
            y0$11 = d$0;
        end
        if (j1$11 == idx$0) begin
            y1$11 = d$0;
        end
        if (j2$11 == idx$0) begin
            y2$11 = d$0;
        end
        if (j0$11 == idx$1) begin
            y0$11 = d$1;
        end
        if (j1$11 == idx$1) begin
            y1$11 = d$1;
        end
        if (j2$11 == idx$1) begin
            y2$11 = d$1;
        end
        if (j0$11 == idx$2) begin
            y0$11 = d$2;
        end
        if (j1$11 == idx$2) begin
            y1$11 = d$2;
        end
        if (j2$11 == idx$2) begin
            y2$11 = d$2;
        end
        if (j0$11 == idx$3) begin
            y0$11 = d$3;
        end
        if (j1$11 == idx$3) begin
            y1$11 = d$3;
        end
        if (j2$11 == idx$3) begin
            y2$11 = d$3;
        end
        if (j0$11 == idx$4) begin
            y0$11 = d$4;
        end
        if (j1$11 == idx$4) begin
            y1$11 = d$4;
        end
        if (j2$11 == idx$4) begin
            y2$11 = d$4;
        end
        if (j0$11 == idx$5) begin
            y0$11 = d$5;
        end
        if (j1$11 == idx$5) begin
            y1$11 = d$5;
        end
        if (j2$11 == idx$5) begin
            y2$11 = d$5;
        end
        if (j0$11 == idx$6) begin
            y0$11 = d$6;
        end
        if (j1$11 == idx$6) begin
            y1$11 = d$6;
        end
        if (j2$11 == idx$6) begin
            y2$11 = d$6;
        end
        if (j0$11 == idx$7) begin
            y0$11 = d$7;
        end
        if (j1$11 == idx$7) begin
            y1$11 = d$7;
        end
        if (j2$11 == idx$7) begin
            y2$11 = d$7;
        end
        if (j0$11 == idx$8) begin
            y0$11 = d$8;
        end
        if (j1$11 == idx$8) begin
            y1$11 = d$8;
        end
        if (j2$11 == idx$8) begin
            y2$11 = d$8;
        end
        if (j0$11 == idx$9) begin
            y0$11 = d$9;
        end
        if (j1$11 == idx$9) begin
            y1$11 = d$9;
        end
        if (j2$11 == idx$9) begin
            y2$11 = d$9;
        end
        if (j0$11 == idx$10) begin
            y0$11 = d$10;
        end
        if (j1$11 == idx$10) begin
            y1$11 = d$10;
        end
        if (j2$11 == idx$10) begin
            y2$11 = d$10;
        end
        if (j0$11 == idx$11) begin
            y0$11 = d$11;
        end
        if (j1$11 == idx$11) begin
            y1$11 = d$11;
        end
        if (j2$11 == idx$11) begin
            y2$11 = d$11;
        end
        if (j0$11 == idx$12) begin
            y0$11 = d$12;
        end
        if (j1$11 == idx$12) begin
            y1$11 = d$12;
        end
        if (j2$11 == idx$12) begin
            y2$11 = d$12;
        end
        if (j0$11 == idx$13) begin
            y0$11 = d$13;
        end
        if (j1$11 == idx$13) begin
            y1$11 = d$13;
        end
        if (j2$11 == idx$13) begin
            y2$11 = d$13;
        end
        if (j0$11 == idx$14) begin
            y0$11 = d$14;
        end
        if (j1$11 == idx$14) begin
            y1$11 = d$14;
        end
        if (j2$11 == idx$14) begin
            y2$11 = d$14;
        end
        if (j0$11 == idx$15) begin
            y0$11 = d$15;
        end
        if (j1$11 == idx$15) begin
            y1$11 = d$15;
        end
        if (j2$11 == idx$15) begin
            y2$11 = d$15;
        end
        if (j0$11 == idx$16) begin
            y0$11 = d$16;
        end
        if (j1$11 == idx$16) begin
            y1$11 = d$16;
        end
        if (j2$11 == idx$16) begin
            y2$11 = d$16;
        end
        if (j0$11 == idx$17) begin
            y0$11 = d$17;
        end
        if (j1$11 == idx$17) begin
            y1$11 = d$17;
        end
        if (j2$11 == idx$17) begin
            y2$11 = d$17;
        end
        if (j0$11 == idx$18) begin
            y0$11 = d$18;
        end
        if (j1$11 == idx$18) begin
            y1$11 = d$18;
        end
        if (j2$11 == idx$18) begin
            y2$11 = d$18;
        end
        if (j0$11 == idx$19) begin
            y0$11 = d$19;
        end
        if (j1$11 == idx$19) begin
            y1$11 = d$19;
        end
        if (j2$11 == idx$19) begin
            y2$11 = d$19;
        end
        if (j0$11 == idx$20) begin
            y0$11 = d$20;
        end
        if (j1$11 == idx$20) begin
            y1$11 = d$20;
        end
        if (j2$11 == idx$20) begin
            y2$11 = d$20;
        end
        if (j0$11 == idx$21) begin
            y0$11 = d$21;
        end
        if (j1$11 == idx$21) begin
            y1$11 = d$21;
        end
        if (j2$11 == idx$21) begin
            y2$11 = d$21;
        end
        if (j0$11 == idx$22) begin
            y0$11 = d$22;
        end
        if (j1$11 == idx$22) begin
            y1$11 = d$22;
        end
        if (j2$11 == idx$22) begin
            y2$11 = d$22;
        end
        if (j0$11 == idx$23) begin
            y0$11 = d$23;
        end
        if (j1$11 == idx$23) begin
            y1$11 = d$23;
        end
        if (j2$11 == idx$23) begin
            y2$11 = d$23;
        end
        y0$12 = 32'h0;
        y1$12 = 32'h0;
        y2$12 = 32'h0;
        if (j0$12 == idx$0) begin
            y0$12 = d$0;
        end
        if (j1$12 == idx$0) begin
            y1$12 = d$0;
        end
        if (j2$12 == idx$0) begin
            y2$12 = d$0;
        end
        if (j0$12 == idx$1) begin
            y0$12 = d$1;
        end
        if (j1$12 == idx$1) begin
            y1$12 = d$1;
        end
        if (j2$12 == idx$1) begin
            y2$12 = d$1;
        end
        if (j0$12 == idx$2) begin
            y0$12 = d$2;
        end
        if (j1$12 == idx$2) begin
            y1$12 = d$2;
        end
        if (j2$12 == idx$2) begin
            y2$12 = d$2;
        end
        if (j0$12 == idx$3) begin
            y0$12 = d$3;
        end
        if (j1$12 == idx$3) begin
            y1$12 = d$3;
        end
        if (j2$12 == idx$3) begin
            y2$12 = d$3;
        end
        if (j0$12 == idx$4) begin
            y0$12 = d$4;
        end
        if (j1$12 == idx$4) begin
            y1$12 = d$4;
        end
        if (j2$12 == idx$4) begin
            y2$12 = d$4;
        end
        if (j0$12 == idx$5) begin
            y0$12 = d$5;
        end
        if (j1$12 == idx$5) begin
            y1$12 = d$5;
        end
        if (j2$12 == idx$5) begin
            y2$12 = d$5;
        end
        if (j0$12 == idx$6) begin
            y0$12 = d$6;
        end
        if (j1$12 == idx$6) begin
            y1$12 = d$6;
        end
        if (j2$12 == idx$6) begin
            y2$12 = d$6;
        end
        if (j0$12 == idx$7) begin
            y0$12 = d$7;
        end
        if (j1$12 == idx$7) begin
            y1$12 = d$7;
        end
        if (j2$12 == idx$7) begin
            y2$12 = d$7;
        end
        if (j0$12 == idx$8) begin
            y0$12 = d$8;
        end
        if (j1$12 == idx$8) begin
            y1$12 = d$8;
        end
        if (j2$12 == idx$8) begin
            y2$12 = d$8;
        end
        if (j0$12 == idx$9) begin
            y0$12 = d$9;
        end
        if (j1$12 == idx$9) begin
            y1$12 = d$9;
        end
        if (j2$12 == idx$9) begin
            y2$12 = d$9;
        end
        if (j0$12 == idx$10) begin
            y0$12 = d$10;
        end
        if (j1$12 == idx$10) begin
            y1$12 = d$10;
        end
        if (j2$12 == idx$10) begin
            y2$12 = d$10;
        end
        if (j0$12 == idx$11) begin
            y0$12 = d$11;
        end
        if (j1$12 == idx$11) begin
            y1$12 = d$11;
        end
        if (j2$12 == idx$11) begin
            y2$12 = d$11;
        end
        if (j0$12 == idx$12) begin
            y0$12 = d$12;
        end
        if (j1$12 == idx$12) begin
            y1$12 = d$12;
        end
        if (j2$12 == idx$12) begin
            y2$12 = d$12;
        end
        if (j0$12 == idx$13) begin
            y0$12 = d$13;
        end
        if (j1$12 == idx$13) begin
            y1$12 = d$13;
        end
        if (j2$12 == idx$13) begin
            y2$12 = d$13;
        end
        if (j0$12 == idx$14) begin
            y0$12 = d$14;
        end
        if (j1$12 == idx$14) begin
            y1$12 = d$14;
        end
        if (j2$12 == idx$14) begin
            y2$12 = d$14;
        end
        if (j0$12 == idx$15) begin
            y0$12 = d$15;
        end
        if (j1$12 == idx$15) begin
            y1$12 = d$15;
        end
        if (j2$12 == idx$15) begin
            y2$12 = d$15;
        end
        if (j0$12 == idx$16) begin
            y0$12 = d$16;
        end
        if (j1$12 == idx$16) begin
            y1$12 = d$16;
        end
        if (j2$12 == idx$16) begin
            y2$12 = d$16;
        end
        if (j0$12 == idx$17) begin
            y0$12 = d$17;
        end
        if (j1$12 == idx$17) begin
            y1$12 = d$17;
        end
        if (j2$12 == idx$17) begin
            y2$12 = d$17;
        end
        if (j0$12 == idx$18) begin
            y0$12 = d$18;
        end
        if (j1$12 == idx$18) begin
            y1$12 = d$18;
        end
        if (j2$12 == idx$18) begin
            y2$12 = d$18;
        end
        if (j0$12 == idx$19) begin
            y0$12 = d$19;
        end
        if (j1$12 == idx$19) begin
            y1$12 = d$19;
        end
        if (j2$12 == idx$19) begin
            y2$12 = d$19;
        end
        if (j0$12 == idx$20) begin
            y0$12 = d$20;
        end
        if (j1$12 == idx$20) begin
            y1$12 = d$20;
        end
        if (j2$12 == idx$20) begin
            y2$12 = d$20;
        end
        if (j0$12 == idx$21) begin
            y0$12 = d$21;
        end
        if (j1$12 == idx$21) begin
            y1$12 = d$21;
        end
        if (j2$12 == idx$21) begin
            y2$12 = d$21;
        end
        if (j0$12 == idx$22) begin
            y0$12 = d$22;
        end
        if (j1$12 == idx$22) begin
            y1$12 = d$22;
        end
        if (j2$12 == idx$22) begin
            y2$12 = d$22;
        end
        if (j0$12 == idx$23) begin
            y0$12 = d$23;
        end
        if (j1$12 == idx$23) begin
            y1$12 = d$23;
        end
        if (j2$12 == idx$23) begin
            y2$12 = d$23;
        end
        y0$13 = 32'h0;
        y1$13 = 32'h0;
        y2$13 = 32'h0;
        if (j0$13 == idx$0) begin
            y0$13 = d$0;
        end
        if (j1$13 == idx$0) begin
            y1$13 = d$0;
        end
        if (j2$13 == idx$0) begin
            y2$13 = d$0;
        end
        if (j0$13 == idx$1) begin
            y0$13 = d$1;
        end
        if (j1$13 == idx$1) begin
            y1$13 = d$1;
        end
        if (j2$13 == idx$1) begin
            y2$13 = d$1;
        end
        if (j0$13 == idx$2) begin
            y0$13 = d$2;
        end
        if (j1$13 == idx$2) begin
            y1$13 = d$2;
        end
        if (j2$13 == idx$2) begin
            y2$13 = d$2;
        end
        if (j0$13 == idx$3) begin
            y0$13 = d$3;
        end
        if (j1$13 == idx$3) begin
            y1$13 = d$3;
        end
        if (j2$13 == idx$3) begin
            y2$13 = d$3;
        end
        if (j0$13 == idx$4) begin
            y0$13 = d$4;
        end
        if (j1$13 == idx$4) begin
            y1$13 = d$4;
        end
        if (j2$13 == idx$4) begin
            y2$13 = d$4;
        end
        if (j0$13 == idx$5) begin
            y0$13 = d$5;
        end
        if (j1$13 == idx$5) begin
            y1$13 = d$5;
        end
        if (j2$13 == idx$5) begin
            y2$13 = d$5;
        end
        if (j0$13 == idx$6) begin
            y0$13 = d$6;
        end
        if (j1$13 == idx$6) begin
            y1$13 = d$6;
        end
        if (j2$13 == idx$6) begin
            y2$13 = d$6;
        end
        if (j0$13 == idx$7) begin
            y0$13 = d$7;
        end
        if (j1$13 == idx$7) begin
            y1$13 = d$7;
        end
        if (j2$13 == idx$7) begin
            y2$13 = d$7;
        end
        if (j0$13 == idx$8) begin
            y0$13 = d$8;
        end
        if (j1$13 == idx$8) begin
            y1$13 = d$8;
        end
        if (j2$13 == idx$8) begin
            y2$13 = d$8;
        end
        if (j0$13 == idx$9) begin
            y0$13 = d$9;
        end
        if (j1$13 == idx$9) begin
            y1$13 = d$9;
        end
        if (j2$13 == idx$9) begin
            y2$13 = d$9;
        end
        if (j0$13 == idx$10) begin
            y0$13 = d$10;
        end
        if (j1$13 == idx$10) begin
            y1$13 = d$10;
        end
        if (j2$13 == idx$10) begin
            y2$13 = d$10;
        end
        if (j0$13 == idx$11) begin
            y0$13 = d$11;
        end
        if (j1$13 == idx$11) begin
            y1$13 = d$11;
        end
        if (j2$13 == idx$11) begin
            y2$13 = d$11;
        end
        if (j0$13 == idx$12) begin
            y0$13 = d$12;
        end
        if (j1$13 == idx$12) begin
            y1$13 = d$12;
        end
        if (j2$13 == idx$12) begin
            y2$13 = d$12;
        end
        if (j0$13 == idx$13) begin
            y0$13 = d$13;
        end
        if (j1$13 == idx$13) begin
            y1$13 = d$13;
        end
        if (j2$13 == idx$13) begin
            y2$13 = d$13;
        end
        if (j0$13 == idx$14) begin
            y0$13 = d$14;
        end
        if (j1$13 == idx$14) begin
            y1$13 = d$14;
        end
        if (j2$13 == idx$14) begin
            y2$13 = d$14;
        end
        if (j0$13 == idx$15) begin
            y0$13 = d$15;
        end
        if (j1$13 == idx$15) begin
            y1$13 = d$15;
        end
        if (j2$13 == idx$15) begin
            y2$13 = d$15;
        end
        if (j0$13 == idx$16) begin
            y0$13 = d$16;
        end
        if (j1$13 == idx$16) begin
            y1$13 = d$16;
        end
        if (j2$13 == idx$16) begin
            y2$13 = d$16;
        end
        if (j0$13 == idx$17) begin
            y0$13 = d$17;
        end
        if (j1$13 == idx$17) begin
            y1$13 = d$17;
        end
        if (j2$13 == idx$17) begin
            y2$13 = d$17;
        end
        if (j0$13 == idx$18) begin
            y0$13 = d$18;
        end
        if (j1$13 == idx$18) begin
            y1$13 = d$18;
        end
        if (j2$13 == idx$18) begin
            y2$13 = d$18;
        end
        if (j0$13 == idx$19) begin
            y0$13 = d$19;
        end
        if (j1$13 == idx$19) begin
            y1$13 = d$19;
        end
        if (j2$13 == idx$19) begin
            y2$13 = d$19;
        end
        if (j0$13 == idx$20) begin
            y0$13 = d$20;
        end
        if (j1$13 == idx$20) begin
            y1$13 = d$20;
        end
        if (j2$13 == idx$20) begin
            y2$13 = d$20;
        end
        if (j0$13 == idx$21) begin
            y0$13 = d$21;
        end
        if (j1$13 == idx$21) begin
            y1$13 = d$21;
        end
        if (j2$13 == idx$21) begin
            y2$13 = d$21;
        end
        if (j0$13 == idx$22) begin
            y0$13 = d$22;
        end
        if (j1$13 == idx$22) begin
            y1$13 = d$22;
        end
        if (j2$13 == idx$22) begin
            y2$13 = d$22;
        end
        if (j0$13 == idx$23) begin
            y0$13 = d$23;
        end
        if (j1$13 == idx$23) begin
            y1$13 = d$23;
        end
        if (j2$13 == idx$23) begin
            y2$13 = d$23;
        end
        y0$14 = 32'h0;
        y1$14 = 32'h0;
        y2$14 = 32'h0;
        if (j0$14 == idx$0) begin
            y0$14 = d$0;
        end
        if (j1$14 == idx$0) begin
            y1$14 = d$0;
        end
        if (j2$14 == idx$0) begin
            y2$14 = d$0;
        end
        if (j0$14 == idx$1) begin
            y0$14 = d$1;
        end
        if (j1$14 == idx$1) begin
            y1$14 = d$1;
        end
        if (j2$14 == idx$1) begin
            y2$14 = d$1;
        end
        if (j0$14 == idx$2) begin
            y0$14 = d$2;
        end
        if (j1$14 == idx$2) begin
            y1$14 = d$2;
        end
        if (j2$14 == idx$2) begin
            y2$14 = d$2;
        end
        if (j0$14 == idx$3) begin
            y0$14 = d$3;
        end
        if (j1$14 == idx$3) begin
            y1$14 = d$3;
        end
        if (j2$14 == idx$3) begin
            y2$14 = d$3;
        end
        if (j0$14 == idx$4) begin
            y0$14 = d$4;
        end
        if (j1$14 == idx$4) begin
            y1$14 = d$4;
        end
        if (j2$14 == idx$4) begin
            y2$14 = d$4;
        end
        if (j0$14 == idx$5) begin
            y0$14 = d$5;
        end
        if (j1$14 == idx$5) begin
            y1$14 = d$5;
        end
        if (j2$14 == idx$5) begin
            y2$14 = d$5;
        end
        if (j0$14 == idx$6) begin
            y0$14 = d$6;
        end
        if (j1$14 == idx$6) begin
            y1$14 = d$6;
        end
        if (j2$14 == idx$6) begin
            y2$14 = d$6;
        end
        if (j0$14 == idx$7) begin
            y0$14 = d$7;
        end
        if (j1$14 == idx$7) begin
            y1$14 = d$7;
        end
        if (j2$14 == idx$7) begin
            y2$14 = d$7;
        end
        if (j0$14 == idx$8) begin
            y0$14 = d$8;
        end
        if (j1$14 == idx$8) begin
            y1$14 = d$8;
        end
        if (j2$14 == idx$8) begin
            y2$14 = d$8;
        end
        if (j0$14 == idx$9) begin
            y0$14 = d$9;
        end
        if (j1$14 == idx$9) begin
            y1$14 = d$9;
        end
        if (j2$14 == idx$9) begin
            y2$14 = d$9;
        end
        if (j0$14 == idx$10) begin
            y0$14 = d$10;
        end
        if (j1$14 == idx$10) begin
            y1$14 = d$10;
        end
        if (j2$14 == idx$10) begin
            y2$14 = d$10;
        end
        if (j0$14 == idx$11) begin
            y0$14 = d$11;
        end
        if (j1$14 == idx$11) begin
            y1$14 = d$11;
        end
        if (j2$14 == idx$11) begin
            y2$14 = d$11;
        end
        if (j0$14 == idx$12) begin
            y0$14 = d$12;
        end
        if (j1$14 == idx$12) begin
            y1$14 = d$12;
        end
        if (j2$14 == idx$12) begin
            y2$14 = d$12;
        end
        if (j0$14 == idx$13) begin
            y0$14 = d$13;
        end
        if (j1$14 == idx$13) begin
            y1$14 = d$13;
        end
        if (j2$14 == idx$13) begin
            y2$14 = d$13;
        end
        if (j0$14 == idx$14) begin
            y0$14 = d$14;
        end
        if (j1$14 == idx$14) begin
            y1$14 = d$14;
        end
        if (j2$14 == idx$14) begin
            y2$14 = d$14;
        end
        if (j0$14 == idx$15) begin
            y0$14 = d$15;
        end
        if (j1$14 == idx$15) begin
            y1$14 = d$15;
        end
        if (j2$14 == idx$15) begin
            y2$14 = d$15;
        end
        if (j0$14 == idx$16) begin
            y0$14 = d$16;
        end
        if (j1$14 == idx$16) begin
            y1$14 = d$16;
        end
        if (j2$14 == idx$16) begin
            y2$14 = d$16;
        end
        if (j0$14 == idx$17) begin
            y0$14 = d$17;
        end
        if (j1$14 == idx$17) begin
            y1$14 = d$17;
        end
        if (j2$14 == idx$17) begin
            y2$14 = d$17;
        end
        if (j0$14 == idx$18) begin
            y0$14 = d$18;
        end
        if (j1$14 == idx$18) begin
            y1$14 = d$18;
        end
        if (j2$14 == idx$18) begin
            y2$14 = d$18;
        end
        if (j0$14 == idx$19) begin
            y0$14 = d$19;
        end
        if (j1$14 == idx$19) begin
            y1$14 = d$19;
        end
        if (j2$14 == idx$19) begin
            y2$14 = d$19;
        end
        if (j0$14 == idx$20) begin
            y0$14 = d$20;
        end
        if (j1$14 == idx$20) begin
            y1$14 = d$20;
        end
        if (j2$14 == idx$20) begin
            y2$14 = d$20;
        end
        if (j0$14 == idx$21) begin
            y0$14 = d$21;
        end
        if (j1$14 == idx$21) begin
            y1$14 = d$21;
        end
        if (j2$14 == idx$21) begin
            y2$14 = d$21;
        end
        if (j0$14 == idx$22) begin
            y0$14 = d$22;
        end
        if (j1$14 == idx$22) begin
            y1$14 = d$22;
        end
        if (j2$14 == idx$22) begin
            y2$14 = d$22;
        end
        if (j0$14 == idx$23) begin
            y0$14 = d$23;
        end
        if (j1$14 == idx$23) begin
            y1$14 = d$23;
        end
        if (j2$14 == idx$23) begin
            y2$14 = d$23;
        end
        y0$15 = 32'h0;
        y1$15 = 32'h0;
        y2$15 = 32'h0;
        if (j0$15 == idx$0) begin
            y0$15 = d$0;
        end
        if (j1$15 == idx$0) begin
            y1$15 = d$0;
        end
        if (j2$15 == idx$0) begin
            y2$15 = d$0;
        end
        if (j0$15 == idx$1) begin
            y0$15 = d$1;
        end
        if (j1$15 == idx$1) begin
            y1$15 = d$1;
        end
        if (j2$15 == idx$1) begin
            y2$15 = d$1;
        end
        if (j0$15 == idx$2) begin
            y0$15 = d$2;
        end
        if (j1$15 == idx$2) begin
            y1$15 = d$2;
        end
        if (j2$15 == idx$2) begin
            y2$15 = d$2;
        end
        if (j0$15 == idx$3) begin
            y0$15 = d$3;
        end
        if (j1$15 == idx$3) begin
            y1$15 = d$3;
        end
        if (j2$15 == idx$3) begin
            y2$15 = d$3;
        end
        if (j0$15 == idx$4) begin
            y0$15 = d$4;
        end
        if (j1$15 == idx$4) begin
            y1$15 = d$4;
        end
        if (j2$15 == idx$4) begin
            y2$15 = d$4;
        end
        if (j0$15 == idx$5) begin
            y0$15 = d$5;
        end
        if (j1$15 == idx$5) begin
            y1$15 = d$5;
        end
        if (j2$15 == idx$5) begin
            y2$15 = d$5;
        end
        if (j0$15 == idx$6) begin
            y0$15 = d$6;
        end
        if (j1$15 == idx$6) begin
            y1$15 = d$6;
        end
        if (j2$15 == idx$6) begin
            y2$15 = d$6;
        end
        if (j0$15 == idx$7) begin
            y0$15 = d$7;
        end
        if (j1$15 == idx$7) begin
            y1$15 = d$7;
        end
        if (j2$15 == idx$7) begin
            y2$15 = d$7;
        end
        if (j0$15 == idx$8) begin
            y0$15 = d$8;
        end
        if (j1$15 == idx$8) begin
            y1$15 = d$8;
        end
        if (j2$15 == idx$8) begin
            y2$15 = d$8;
        end
        if (j0$15 == idx$9) begin
            y0$15 = d$9;
        end
        if (j1$15 == idx$9) begin
            y1$15 = d$9;
        end
        if (j2$15 == idx$9) begin
            y2$15 = d$9;
        end
        if (j0$15 == idx$10) begin
            y0$15 = d$10;
        end
        if (j1$15 == idx$10) begin
            y1$15 = d$10;
        end
        if (j2$15 == idx$10) begin
            y2$15 = d$10;
        end
        if (j0$15 == idx$11) begin
            y0$15 = d$11;
        end
        if (j1$15 == idx$11) begin
            y1$15 = d$11;
        end
        if (j2$15 == idx$11) begin
            y2$15 = d$11;
        end
        if (j0$15 == idx$12) begin
            y0$15 = d$12;
        end
        if (j1$15 == idx$12) begin
            y1$15 = d$12;
        end
        if (j2$15 == idx$12) begin
            y2$15 = d$12;
        end
        if (j0$15 == idx$13) begin
            y0$15 = d$13;
        end
        if (j1$15 == idx$13) begin
            y1$15 = d$13;
        end
        if (j2$15 == idx$13) begin
            y2$15 = d$13;
        end
        if (j0$15 == idx$14) begin
            y0$15 = d$14;
        end
        if (j1$15 == idx$14) begin
            y1$15 = d$14;
        end
        if (j2$15 == idx$14) begin
            y2$15 = d$14;
        end
        if (j0$15 == idx$15) begin
            y0$15 = d$15;
        end
        if (j1$15 == idx$15) begin
            y1$15 = d$15;
        end
        if (j2$15 == idx$15) begin
            y2$15 = d$15;
        end
        if (j0$15 == idx$16) begin
            y0$15 = d$16;
        end
        if (j1$15 == idx$16) begin
            y1$15 = d$16;
        end
        if (j2$15 == idx$16) begin
            y2$15 = d$16;
        end
        if (j0$15 == idx$17) begin
            y0$15 = d$17;
        end
        if (j1$15 == idx$17) begin
            y1$15 = d$17;
        end
        if (j2$15 == idx$17) begin
            y2$15 = d$17;
        end
        if (j0$15 == idx$18) begin
            y0$15 = d$18;
        end
        if (j1$15 == idx$18) begin
            y1$15 = d$18;
        end
        if (j2$15 == idx$18) begin
            y2$15 = d$18;
        end
        if (j0$15 == idx$19) begin
            y0$15 = d$19;
        end
        if (j1$15 == idx$19) begin
            y1$15 = d$19;
        end
        if (j2$15 == idx$19) begin
            y2$15 = d$19;
        end
        if (j0$15 == idx$20) begin
            y0$15 = d$20;
        end
        if (j1$15 == idx$20) begin
            y1$15 = d$20;
        end
        if (j2$15 == idx$20) begin
            y2$15 = d$20;
        end
        if (j0$15 == idx$21) begin
            y0$15 = d$21;
        end
        if (j1$15 == idx$21) begin
            y1$15 = d$21;
        end
        if (j2$15 == idx$21) begin
            y2$15 = d$21;
        end
        if (j0$15 == idx$22) begin
            y0$15 = d$22;
        end
        if (j1$15 == idx$22) begin
            y1$15 = d$22;
        end
        if (j2$15 == idx$22) begin
            y2$15 = d$22;
        end
        if (j0$15 == idx$23) begin
            y0$15 = d$23;
        end
        if (j1$15 == idx$23) begin
            y1$15 = d$23;
        end
        if (j2$15 == idx$23) begin
            y2$15 = d$23;
        end
        y0$16 = 32'h0;
        y1$16 = 32'h0;
        y2$16 = 32'h0;
        if (j0$16 == idx$0) begin
            y0$16 = d$0;
        end
        if (j1$16 == idx$0) begin
            y1$16 = d$0;
        end
        if (j2$16 == idx$0) begin
            y2$16 = d$0;
        end
        if (j0$16 == idx$1) begin
            y0$16 = d$1;
        end
        if (j1$16 == idx$1) begin
            y1$16 = d$1;
        end
        if (j2$16 == idx$1) begin
            y2$16 = d$1;
        end
        if (j0$16 == idx$2) begin
            y0$16 = d$2;
        end
        if (j1$16 == idx$2) begin
            y1$16 = d$2;
        end
        if (j2$16 == idx$2) begin
            y2$16 = d$2;
        end
        if (j0$16 == idx$3) begin
            y0$16 = d$3;
        end
        if (j1$16 == idx$3) begin
            y1$16 = d$3;
        end
        if (j2$16 == idx$3) begin
            y2$16 = d$3;
        end
        if (j0$16 == idx$4) begin
            y0$16 = d$4;
        end
        if (j1$16 == idx$4) begin
            y1$16 = d$4;
        end
        if (j2$16 == idx$4) begin
            y2$16 = d$4;
        end
        if (j0$16 == idx$5) begin
            y0$16 = d$5;
        end
        if (j1$16 == idx$5) begin
            y1$16 = d$5;
        end
        if (j2$16 == idx$5) begin
            y2$16 = d$5;
        end
        if (j0$16 == idx$6) begin
            y0$16 = d$6;
        end
        if (j1$16 == idx$6) begin
            y1$16 = d$6;
        end
        if (j2$16 == idx$6) begin
            y2$16 = d$6;
        end
        if (j0$16 == idx$7) begin
            y0$16 = d$7;
        end
        if (j1$16 == idx$7) begin
            y1$16 = d$7;
        end
        if (j2$16 == idx$7) begin
            y2$16 = d$7;
        end
        if (j0$16 == idx$8) begin
            y0$16 = d$8;
        end
        if (j1$16 == idx$8) begin
            y1$16 = d$8;
        end
        if (j2$16 == idx$8) begin
            y2$16 = d$8;
        end
        if (j0$16 == idx$9) begin
            y0$16 = d$9;
        end
        if (j1$16 == idx$9) begin
            y1$16 = d$9;
        end
        if (j2$16 == idx$9) begin
            y2$16 = d$9;
        end
        if (j0$16 == idx$10) begin
            y0$16 = d$10;
        end
        if (j1$16 == idx$10) begin
            y1$16 = d$10;
        end
        if (j2$16 == idx$10) begin
            y2$16 = d$10;
        end
        if (j0$16 == idx$11) begin
            y0$16 = d$11;
        end
        if (j1$16 == idx$11) begin
            y1$16 = d$11;
        end
        if (j2$16 == idx$11) begin
            y2$16 = d$11;
        end
        if (j0$16 == idx$12) begin
            y0$16 = d$12;
        end
        if (j1$16 == idx$12) begin
            y1$16 = d$12;
        end
        if (j2$16 == idx$12) begin
            y2$16 = d$12;
        end
        if (j0$16 == idx$13) begin
            y0$16 = d$13;
        end
        if (j1$16 == idx$13) begin
            y1$16 = d$13;
        end
        if (j2$16 == idx$13) begin
            y2$16 = d$13;
        end
        if (j0$16 == idx$14) begin
            y0$16 = d$14;
        end
        if (j1$16 == idx$14) begin
            y1$16 = d$14;
        end
        if (j2$16 == idx$14) begin
            y2$16 = d$14;
        end
        if (j0$16 == idx$15) begin
            y0$16 = d$15;
        end
        if (j1$16 == idx$15) begin
            y1$16 = d$15;
        end
        if (j2$16 == idx$15) begin
            y2$16 = d$15;
        end
        if (j0$16 == idx$16) begin
            y0$16 = d$16;
        end
        if (j1$16 == idx$16) begin
            y1$16 = d$16;
        end
        if (j2$16 == idx$16) begin
            y2$16 = d$16;
        end
        if (j0$16 == idx$17) begin
            y0$16 = d$17;
        end
        if (j1$16 == idx$17) begin
            y1$16 = d$17;
        end
        if (j2$16 == idx$17) begin
            y2$16 = d$17;
        end
        if (j0$16 == idx$18) begin
            y0$16 = d$18;
        end
        if (j1$16 == idx$18) begin
            y1$16 = d$18;
        end
        if (j2$16 == idx$18) begin
            y2$16 = d$18;
        end
        if (j0$16 == idx$19) begin
            y0$16 = d$19;
        end
        if (j1$16 == idx$19) begin
            y1$16 = d$19;
        end
        if (j2$16 == idx$19) begin
            y2$16 = d$19;
        end
        if (j0$16 == idx$20) begin
            y0$16 = d$20;
        end
        if (j1$16 == idx$20) begin
            y1$16 = d$20;
        end
        if (j2$16 == idx$20) begin
            y2$16 = d$20;
        end
        if (j0$16 == idx$21) begin
            y0$16 = d$21;
        end
        if (j1$16 == idx$21) begin
            y1$16 = d$21;
        end
        if (j2$16 == idx$21) begin
            y2$16 = d$21;
        end
        if (j0$16 == idx$22) begin
            y0$16 = d$22;
        end
        if (j1$16 == idx$22) begin
            y1$16 = d$22;
        end
        if (j2$16 == idx$22) begin
            y2$16 = d$22;
        end
        if (j0$16 == idx$23) begin
            y0$16 = d$23;
        end
        if (j1$16 == idx$23) begin
            y1$16 = d$23;
        end
        if (j2$16 == idx$23) begin
            y2$16 = d$23;
        end
        y0$17 = 32'h0;
        y1$17 = 32'h0;
        y2$17 = 32'h0;
        if (j0$17 == idx$0) begin
            y0$17 = d$0;
        end
        if (j1$17 == idx$0) begin
            y1$17 = d$0;
        end
        if (j2$17 == idx$0) begin
            y2$17 = d$0;
        end
        if (j0$17 == idx$1) begin
            y0$17 = d$1;
        end
        if (j1$17 == idx$1) begin
            y1$17 = d$1;
        end
        if (j2$17 == idx$1) begin
            y2$17 = d$1;
        end
        if (j0$17 == idx$2) begin
            y0$17 = d$2;
        end
        if (j1$17 == idx$2) begin
            y1$17 = d$2;
        end
        if (j2$17 == idx$2) begin
            y2$17 = d$2;
        end
        if (j0$17 == idx$3) begin
            y0$17 = d$3;
        end
        if (j1$17 == idx$3) begin
            y1$17 = d$3;
        end
        if (j2$17 == idx$3) begin
            y2$17 = d$3;
        end
        if (j0$17 == idx$4) begin
            y0$17 = d$4;
        end
        if (j1$17 == idx$4) begin
            y1$17 = d$4;
        end
        if (j2$17 == idx$4) begin
            y2$17 = d$4;
        end
        if (j0$17 == idx$5) begin
            y0$17 = d$5;
        end
        if (j1$17 == idx$5) begin
            y1$17 = d$5;
        end
        if (j2$17 == idx$5) begin
            y2$17 = d$5;
        end
        if (j0$17 == idx$6) begin
            y0$17 = d$6;
        end
        if (j1$17 == idx$6) begin
            y1$17 = d$6;
        end
        if (j2$17 == idx$6) begin
            y2$17 = d$6;
        end
        if (j0$17 == idx$7) begin
            y0$17 = d$7;
        end
        if (j1$17 == idx$7) begin
            y1$17 = d$7;
        end
        if (j2$17 == idx$7) begin
            y2$17 = d$7;
        end
        if (j0$17 == idx$8) begin
            y0$17 = d$8;
        end
        if (j1$17 == idx$8) begin
            y1$17 = d$8;
        end
        if (j2$17 == idx$8) begin
            y2$17 = d$8;
        end
        if (j0$17 == idx$9) begin
            y0$17 = d$9;
        end
        if (j1$17 == idx$9) begin
            y1$17 = d$9;
        end
        if (j2$17 == idx$9) begin
            y2$17 = d$9;
        end
        if (j0$17 == idx$10) begin
            y0$17 = d$10;
        end
        if (j1$17 == idx$10) begin
            y1$17 = d$10;
        end
        if (j2$17 == idx$10) begin
            y2$17 = d$10;
        end
        if (j0$17 == idx$11) begin
            y0$17 = d$11;
        end
        if (j1$17 == idx$11) begin
            y1$17 = d$11;
        end
        if (j2$17 == idx$11) begin
            y2$17 = d$11;
        end
        if (j0$17 == idx$12) begin
            y0$17 = d$12;
        end
        if (j1$17 == idx$12) begin
            y1$17 = d$12;
        end
        if (j2$17 == idx$12) begin
            y2$17 = d$12;
        end
        if (j0$17 == idx$13) begin
            y0$17 = d$13;
        end
        if (j1$17 == idx$13) begin
            y1$17 = d$13;
        end
        if (j2$17 == idx$13) begin
            y2$17 = d$13;
        end
        if (j0$17 == idx$14) begin
            y0$17 = d$14;
        end
        if (j1$17 == idx$14) begin
            y1$17 = d$14;
        end
        if (j2$17 == idx$14) begin
            y2$17 = d$14;
        end
        if (j0$17 == idx$15) begin
            y0$17 = d$15;
        end
        if (j1$17 == idx$15) begin
            y1$17 = d$15;
        end
        if (j2$17 == idx$15) begin
            y2$17 = d$15;
        end
        if (j0$17 == idx$16) begin
            y0$17 = d$16;
        end
        if (j1$17 == idx$16) begin
            y1$17 = d$16;
        end
        if (j2$17 == idx$16) begin
            y2$17 = d$16;
        end
        if (j0$17 == idx$17) begin
            y0$17 = d$17;
        end
        if (j1$17 == idx$17) begin
            y1$17 = d$17;
        end
        if (j2$17 == idx$17) begin
            y2$17 = d$17;
        end
        if (j0$17 == idx$18) begin
            y0$17 = d$18;
        end
        if (j1$17 == idx$18) begin
            y1$17 = d$18;
        end
        if (j2$17 == idx$18) begin
            y2$17 = d$18;
        end
        if (j0$17 == idx$19) begin
            y0$17 = d$19;
        end
        if (j1$17 == idx$19) begin
            y1$17 = d$19;
        end
        if (j2$17 == idx$19) begin
            y2$17 = d$19;
        end
        if (j0$17 == idx$20) begin
            y0$17 = d$20;
        end
        if (j1$17 == idx$20) begin
            y1$17 = d$20;
        end
        if (j2$17 == idx$20) begin
            y2$17 = d$20;
        end
        if (j0$17 == idx$21) begin
            y0$17 = d$21;
        end
        if (j1$17 == idx$21) begin
            y1$17 = d$21;
        end
        if (j2$17 == idx$21) begin
            y2$17 = d$21;
        end
        if (j0$17 == idx$22) begin
            y0$17 = d$22;
        end
        if (j1$17 == idx$22) begin
            y1$17 = d$22;
        end
        if (j2$17 == idx$22) begin
            y2$17 = d$22;
        end
        if (j0$17 == idx$23) begin
            y0$17 = d$23;
        end
        if (j1$17 == idx$23) begin
            y1$17 = d$23;
        end
        if (j2$17 == idx$23) begin
            y2$17 = d$23;
        end
        y0$18 = 32'h0;
        y1$18 = 32'h0;
        y2$18 = 32'h0;
        if (j0$18 == idx$0) begin
            y0$18 = d$0;
        end
        if (j1$18 == idx$0) begin
            y1$18 = d$0;
        end
        if (j2$18 == idx$0) begin
            y2$18 = d$0;
        end
        if (j0$18 == idx$1) begin
            y0$18 = d$1;
        end
        if (j1$18 == idx$1) begin
            y1$18 = d$1;
        end
        if (j2$18 == idx$1) begin
            y2$18 = d$1;
        end
        if (j0$18 == idx$2) begin
            y0$18 = d$2;
        end
        if (j1$18 == idx$2) begin
            y1$18 = d$2;
        end
        if (j2$18 == idx$2) begin
            y2$18 = d$2;
        end
        if (j0$18 == idx$3) begin
            y0$18 = d$3;
        end
        if (j1$18 == idx$3) begin
            y1$18 = d$3;
        end
        if (j2$18 == idx$3) begin
            y2$18 = d$3;
        end
        if (j0$18 == idx$4) begin
            y0$18 = d$4;
        end
        if (j1$18 == idx$4) begin
            y1$18 = d$4;
        end
        if (j2$18 == idx$4) begin
            y2$18 = d$4;
        end
        if (j0$18 == idx$5) begin
            y0$18 = d$5;
        end
        if (j1$18 == idx$5) begin
            y1$18 = d$5;
        end
        if (j2$18 == idx$5) begin
            y2$18 = d$5;
        end
        if (j0$18 == idx$6) begin
            y0$18 = d$6;
        end
        if (j1$18 == idx$6) begin
            y1$18 = d$6;
        end
        if (j2$18 == idx$6) begin
            y2$18 = d$6;
        end
        if (j0$18 == idx$7) begin
            y0$18 = d$7;
        end
        if (j1$18 == idx$7) begin
            y1$18 = d$7;
        end
        if (j2$18 == idx$7) begin
            y2$18 = d$7;
        end
        if (j0$18 == idx$8) begin
            y0$18 = d$8;
        end
        if (j1$18 == idx$8) begin
            y1$18 = d$8;
        end
        if (j2$18 == idx$8) begin
            y2$18 = d$8;
        end
        if (j0$18 == idx$9) begin
            y0$18 = d$9;
        end
        if (j1$18 == idx$9) begin
            y1$18 = d$9;
        end
        if (j2$18 == idx$9) begin
            y2$18 = d$9;
        end
        if (j0$18 == idx$10) begin
            y0$18 = d$10;
        end
        if (j1$18 == idx$10) begin
            y1$18 = d$10;
        end
        if (j2$18 == idx$10) begin
            y2$18 = d$10;
        end
        if (j0$18 == idx$11) begin
            y0$18 = d$11;
        end
        if (j1$18 == idx$11) begin
            y1$18 = d$11;
        end
        if (j2$18 == idx$11) begin
            y2$18 = d$11;
        end
        if (j0$18 == idx$12) begin
            y0$18 = d$12;
        end
        if (j1$18 == idx$12) begin
            y1$18 = d$12;
        end
        if (j2$18 == idx$12) begin
            y2$18 = d$12;
        end
        if (j0$18 == idx$13) begin
            y0$18 = d$13;
        end
        if (j1$18 == idx$13) begin
            y1$18 = d$13;
        end
        if (j2$18 == idx$13) begin
            y2$18 = d$13;
        end
        if (j0$18 == idx$14) begin
            y0$18 = d$14;
        end
        if (j1$18 == idx$14) begin
            y1$18 = d$14;
        end
        if (j2$18 == idx$14) begin
            y2$18 = d$14;
        end
        if (j0$18 == idx$15) begin
            y0$18 = d$15;
        end
        if (j1$18 == idx$15) begin
            y1$18 = d$15;
        end
        if (j2$18 == idx$15) begin
            y2$18 = d$15;
        end
        if (j0$18 == idx$16) begin
            y0$18 = d$16;
        end
        if (j1$18 == idx$16) begin
            y1$18 = d$16;
        end
        if (j2$18 == idx$16) begin
            y2$18 = d$16;
        end
        if (j0$18 == idx$17) begin
            y0$18 = d$17;
        end
        if (j1$18 == idx$17) begin
            y1$18 = d$17;
        end
        if (j2$18 == idx$17) begin
            y2$18 = d$17;
        end
        if (j0$18 == idx$18) begin
            y0$18 = d$18;
        end
        if (j1$18 == idx$18) begin
            y1$18 = d$18;
        end
        if (j2$18 == idx$18) begin
            y2$18 = d$18;
        end
        if (j0$18 == idx$19) begin
            y0$18 = d$19;
        end
        if (j1$18 == idx$19) begin
            y1$18 = d$19;
        end
        if (j2$18 == idx$19) begin
            y2$18 = d$19;
        end
        if (j0$18 == idx$20) begin
            y0$18 = d$20;
        end
        if (j1$18 == idx$20) begin
            y1$18 = d$20;
        end
        if (j2$18 == idx$20) begin
            y2$18 = d$20;
        end
        if (j0$18 == idx$21) begin
            y0$18 = d$21;
        end
        if (j1$18 == idx$21) begin
            y1$18 = d$21;
        end
        if (j2$18 == idx$21) begin
            y2$18 = d$21;
        end
        if (j0$18 == idx$22) begin
            y0$18 = d$22;
        end
        if (j1$18 == idx$22) begin
            y1$18 = d$22;
        end
        if (j2$18 == idx$22) begin
            y2$18 = d$22;
        end
        if (j0$18 == idx$23) begin
            y0$18 = d$23;
        end
        if (j1$18 == idx$23) begin
            y1$18 = d$23;
        end
        if (j2$18 == idx$23) begin
            y2$18 = d$23;
        end
        y0$19 = 32'h0;
        y1$19 = 32'h0;
        y2$19 = 32'h0;
        if (j0$19 == idx$0) begin
            y0$19 = d$0;
        end
        if (j1$19 == idx$0) begin
            y1$19 = d$0;
        end
        if (j2$19 == idx$0) begin
            y2$19 = d$0;
        end
        if (j0$19 == idx$1) begin
            y0$19 = d$1;
        end
        if (j1$19 == idx$1) begin
            y1$19 = d$1;
        end
        if (j2$19 == idx$1) begin
            y2$19 = d$1;
        end
        if (j0$19 == idx$2) begin
            y0$19 = d$2;
        end
        if (j1$19 == idx$2) begin
            y1$19 = d$2;
        end
        if (j2$19 == idx$2) begin
            y2$19 = d$2;
        end
        if (j0$19 == idx$3) begin
            y0$19 = d$3;
        end
        if (j1$19 == idx$3) begin
            y1$19 = d$3;
        end
        if (j2$19 == idx$3) begin
            y2$19 = d$3;
        end
        if (j0$19 == idx$4) begin
            y0$19 = d$4;
        end
        if (j1$19 == idx$4) begin
            y1$19 = d$4;
        end
        if (j2$19 == idx$4) begin
            y2$19 = d$4;
        end
        if (j0$19 == idx$5) begin
            y0$19 = d$5;
        end
        if (j1$19 == idx$5) begin
            y1$19 = d$5;
        end
        if (j2$19 == idx$5) begin
            y2$19 = d$5;
        end
        if (j0$19 == idx$6) begin
            y0$19 = d$6;
        end
        if (j1$19 == idx$6) begin
            y1$19 = d$6;
        end
        if (j2$19 == idx$6) begin
            y2$19 = d$6;
        end
        if (j0$19 == idx$7) begin
            y0$19 = d$7;
        end
        if (j1$19 == idx$7) begin
            y1$19 = d$7;
        end
        if (j2$19 == idx$7) begin
            y2$19 = d$7;
        end
        if (j0$19 == idx$8) begin
            y0$19 = d$8;
        end
        if (j1$19 == idx$8) begin
            y1$19 = d$8;
        end
        if (j2$19 == idx$8) begin
            y2$19 = d$8;
        end
        if (j0$19 == idx$9) begin
            y0$19 = d$9;
        end
        if (j1$19 == idx$9) begin
            y1$19 = d$9;
        end
        if (j2$19 == idx$9) begin
            y2$19 = d$9;
        end
        if (j0$19 == idx$10) begin
            y0$19 = d$10;
        end
        if (j1$19 == idx$10) begin
            y1$19 = d$10;
        end
        if (j2$19 == idx$10) begin
            y2$19 = d$10;
        end
        if (j0$19 == idx$11) begin
            y0$19 = d$11;
        end
        if (j1$19 == idx$11) begin
            y1$19 = d$11;
        end
        if (j2$19 == idx$11) begin
            y2$19 = d$11;
        end
        if (j0$19 == idx$12) begin
            y0$19 = d$12;
        end
        if (j1$19 == idx$12) begin
            y1$19 = d$12;
        end
        if (j2$19 == idx$12) begin
            y2$19 = d$12;
        end
        if (j0$19 == idx$13) begin
            y0$19 = d$13;
        end
        if (j1$19 == idx$13) begin
            y1$19 = d$13;
        end
        if (j2$19 == idx$13) begin
            y2$19 = d$13;
        end
        if (j0$19 == idx$14) begin
            y0$19 = d$14;
        end
        if (j1$19 == idx$14) begin
            y1$19 = d$14;
        end
        if (j2$19 == idx$14) begin
            y2$19 = d$14;
        end
        if (j0$19 == idx$15) begin
            y0$19 = d$15;
        end
        if (j1$19 == idx$15) begin
            y1$19 = d$15;
        end
        if (j2$19 == idx$15) begin
            y2$19 = d$15;
        end
        if (j0$19 == idx$16) begin
            y0$19 = d$16;
        end
        if (j1$19 == idx$16) begin
            y1$19 = d$16;
        end
        if (j2$19 == idx$16) begin
            y2$19 = d$16;
        end
        if (j0$19 == idx$17) begin
            y0$19 = d$17;
        end
        if (j1$19 == idx$17) begin
            y1$19 = d$17;
        end
        if (j2$19 == idx$17) begin
            y2$19 = d$17;
        end
        if (j0$19 == idx$18) begin
            y0$19 = d$18;
        end
        if (j1$19 == idx$18) begin
            y1$19 = d$18;
        end
        if (j2$19 == idx$18) begin
            y2$19 = d$18;
        end
        if (j0$19 == idx$19) begin
            y0$19 = d$19;
        end
        if (j1$19 == idx$19) begin
            y1$19 = d$19;
        end
        if (j2$19 == idx$19) begin
            y2$19 = d$19;
        end
        if (j0$19 == idx$20) begin
            y0$19 = d$20;
        end
        if (j1$19 == idx$20) begin
            y1$19 = d$20;
        end
        if (j2$19 == idx$20) begin
            y2$19 = d$20;
        end
        if (j0$19 == idx$21) begin
            y0$19 = d$21;
        end
        if (j1$19 == idx$21) begin
            y1$19 = d$21;
        end
        if (j2$19 == idx$21) begin
            y2$19 = d$21;
        end
        if (j0$19 == idx$22) begin
            y0$19 = d$22;
        end
        if (j1$19 == idx$22) begin
            y1$19 = d$22;
        end
        if (j2$19 == idx$22) begin
            y2$19 = d$22;
        end
        if (j0$19 == idx$23) begin
            y0$19 = d$23;
        end
        if (j1$19 == idx$23) begin
            y1$19 = d$23;
        end
        if (j2$19 == idx$23) begin
            y2$19 = d$23;
        end
        y0$20 = 32'h0;
        y1$20 = 32'h0;
        y2$20 = 32'h0;
        if (j0$20 == idx$0) begin
            y0$20 = d$0;
        end
        if (j1$20 == idx$0) begin
            y1$20 = d$0;
        end
        if (j2$20 == idx$0) begin
            y2$20 = d$0;
        end
        if (j0$20 == idx$1) begin
            y0$20 = d$1;
        end
        if (j1$20 == idx$1) begin
            y1$20 = d$1;
        end
        if (j2$20 == idx$1) begin
            y2$20 = d$1;
        end
        if (j0$20 == idx$2) begin
            y0$20 = d$2;
        end
        if (j1$20 == idx$2) begin
            y1$20 = d$2;
        end
        if (j2$20 == idx$2) begin
            y2$20 = d$2;
        end
        if (j0$20 == idx$3) begin
            y0$20 = d$3;
        end
        if (j1$20 == idx$3) begin
            y1$20 = d$3;
        end
        if (j2$20 == idx$3) begin
            y2$20 = d$3;
        end
        if (j0$20 == idx$4) begin
            y0$20 = d$4;
        end
        if (j1$20 == idx$4) begin
            y1$20 = d$4;
        end
        if (j2$20 == idx$4) begin
            y2$20 = d$4;
        end
        if (j0$20 == idx$5) begin
            y0$20 = d$5;
        end
        if (j1$20 == idx$5) begin
            y1$20 = d$5;
        end
        if (j2$20 == idx$5) begin
            y2$20 = d$5;
        end
        if (j0$20 == idx$6) begin
            y0$20 = d$6;
        end
        if (j1$20 == idx$6) begin
            y1$20 = d$6;
        end
        if (j2$20 == idx$6) begin
            y2$20 = d$6;
        end
        if (j0$20 == idx$7) begin
            y0$20 = d$7;
        end
        if (j1$20 == idx$7) begin
            y1$20 = d$7;
        end
        if (j2$20 == idx$7) begin
            y2$20 = d$7;
        end
        if (j0$20 == idx$8) begin
            y0$20 = d$8;
        end
        if (j1$20 == idx$8) begin
            y1$20 = d$8;
        end
        if (j2$20 == idx$8) begin
            y2$20 = d$8;
        end
        if (j0$20 == idx$9) begin
            y0$20 = d$9;
        end
        if (j1$20 == idx$9) begin
            y1$20 = d$9;
        end
        if (j2$20 == idx$9) begin
            y2$20 = d$9;
        end
        if (j0$20 == idx$10) begin
            y0$20 = d$10;
        end
        if (j1$20 == idx$10) begin
            y1$20 = d$10;
        end
        if (j2$20 == idx$10) begin
            y2$20 = d$10;
        end
        if (j0$20 == idx$11) begin
            y0$20 = d$11;
        end
        if (j1$20 == idx$11) begin
            y1$20 = d$11;
        end
        if (j2$20 == idx$11) begin
            y2$20 = d$11;
        end
        if (j0$20 == idx$12) begin
            y0$20 = d$12;
        end
        if (j1$20 == idx$12) begin
            y1$20 = d$12;
        end
        if (j2$20 == idx$12) begin
            y2$20 = d$12;
        end
        if (j0$20 == idx$13) begin
            y0$20 = d$13;
        end
        if (j1$20 == idx$13) begin
            y1$20 = d$13;
        end
        if (j2$20 == idx$13) begin
            y2$20 = d$13;
        end
        if (j0$20 == idx$14) begin
            y0$20 = d$14;
        end
        if (j1$20 == idx$14) begin
            y1$20 = d$14;
        end
        if (j2$20 == idx$14) begin
            y2$20 = d$14;
        end
        if (j0$20 == idx$15) begin
            y0$20 = d$15;
        end
        if (j1$20 == idx$15) begin
            y1$20 = d$15;
        end
        if (j2$20 == idx$15) begin
            y2$20 = d$15;
        end
        if (j0$20 == idx$16) begin
            y0$20 = d$16;
        end
        if (j1$20 == idx$16) begin
            y1$20 = d$16;
        end
        if (j2$20 == idx$16) begin
            y2$20 = d$16;
        end
        if (j0$20 == idx$17) begin
            y0$20 = d$17;
        end
        if (j1$20 == idx$17) begin
            y1$20 = d$17;
        end
        if (j2$20 == idx$17) begin
            y2$20 = d$17;
        end
        if (j0$20 == idx$18) begin
            y0$20 = d$18;
        end
        if (j1$20 == idx$18) begin
            y1$20 = d$18;
        end
        if (j2$20 == idx$18) begin
            y2$20 = d$18;
        end
        if (j0$20 == idx$19) begin
            y0$20 = d$19;
        end
        if (j1$20 == idx$19) begin
            y1$20 = d$19;
        end
        if (j2$20 == idx$19) begin
            y2$20 = d$19;
        end
        if (j0$20 == idx$20) begin
            y0$20 = d$20;
        end
        if (j1$20 == idx$20) begin
            y1$20 = d$20;
        end
        if (j2$20 == idx$20) begin
            y2$20 = d$20;
        end
        if (j0$20 == idx$21) begin
            y0$20 = d$21;
        end
        if (j1$20 == idx$21) begin
            y1$20 = d$21;
        end
        if (j2$20 == idx$21) begin
            y2$20 = d$21;
        end
        if (j0$20 == idx$22) begin
            y0$20 = d$22;
        end
        if (j1$20 == idx$22) begin
            y1$20 = d$22;
        end
        if (j2$20 == idx$22) begin
            y2$20 = d$22;
        end
        if (j0$20 == idx$23) begin
            y0$20 = d$23;
        end
        if (j1$20 == idx$23) begin
            y1$20 = d$23;
        end
        if (j2$20 == idx$23) begin
            y2$20 = d$23;
        end
        y0$21 = 32'h0;
        y1$21 = 32'h0;
        y2$21 = 32'h0;
        if (j0$21 == idx$0) begin
            y0$21 = d$0;
        end
        if (j1$21 == idx$0) begin
            y1$21 = d$0;
        end
        if (j2$21 == idx$0) begin
            y2$21 = d$0;
        end
        if (j0$21 == idx$1) begin
            y0$21 = d$1;
        end
        if (j1$21 == idx$1) begin
            y1$21 = d$1;
        end
        if (j2$21 == idx$1) begin
            y2$21 = d$1;
        end
        if (j0$21 == idx$2) begin
            y0$21 = d$2;
        end
        if (j1$21 == idx$2) begin
            y1$21 = d$2;
        end
        if (j2$21 == idx$2) begin
            y2$21 = d$2;
        end
        if (j0$21 == idx$3) begin
            y0$21 = d$3;
        end
        if (j1$21 == idx$3) begin
            y1$21 = d$3;
        end
        if (j2$21 == idx$3) begin
            y2$21 = d$3;
        end
        if (j0$21 == idx$4) begin
            y0$21 = d$4;
        end
        if (j1$21 == idx$4) begin
            y1$21 = d$4;
        end
        if (j2$21 == idx$4) begin
            y2$21 = d$4;
        end
        if (j0$21 == idx$5) begin
            y0$21 = d$5;
        end
        if (j1$21 == idx$5) begin
            y1$21 = d$5;
        end
        if (j2$21 == idx$5) begin
            y2$21 = d$5;
        end
        if (j0$21 == idx$6) begin
            y0$21 = d$6;
        end
        if (j1$21 == idx$6) begin
            y1$21 = d$6;
        end
        if (j2$21 == idx$6) begin
            y2$21 = d$6;
        end
        if (j0$21 == idx$7) begin
            y0$21 = d$7;
        end
        if (j1$21 == idx$7) begin
            y1$21 = d$7;
        end
        if (j2$21 == idx$7) begin
            y2$21 = d$7;
        end
        if (j0$21 == idx$8) begin
            y0$21 = d$8;
        end
        if (j1$21 == idx$8) begin
            y1$21 = d$8;
        end
        if (j2$21 == idx$8) begin
            y2$21 = d$8;
        end
        if (j0$21 == idx$9) begin
            y0$21 = d$9;
        end
        if (j1$21 == idx$9) begin
            y1$21 = d$9;
        end
        if (j2$21 == idx$9) begin
            y2$21 = d$9;
        end
        if (j0$21 == idx$10) begin
            y0$21 = d$10;
        end
        if (j1$21 == idx$10) begin
            y1$21 = d$10;
        end
        if (j2$21 == idx$10) begin
            y2$21 = d$10;
        end
        if (j0$21 == idx$11) begin
            y0$21 = d$11;
        end
        if (j1$21 == idx$11) begin
            y1$21 = d$11;
        end
        if (j2$21 == idx$11) begin
            y2$21 = d$11;
        end
        if (j0$21 == idx$12) begin
            y0$21 = d$12;
        end
        if (j1$21 == idx$12) begin
            y1$21 = d$12;
        end
        if (j2$21 == idx$12) begin
            y2$21 = d$12;
        end
        if (j0$21 == idx$13) begin
            y0$21 = d$13;
        end
        if (j1$21 == idx$13) begin
            y1$21 = d$13;
        end
        if (j2$21 == idx$13) begin
            y2$21 = d$13;
        end
        if (j0$21 == idx$14) begin
            y0$21 = d$14;
        end
        if (j1$21 == idx$14) begin
            y1$21 = d$14;
        end
        if (j2$21 == idx$14) begin
            y2$21 = d$14;
        end
        if (j0$21 == idx$15) begin
            y0$21 = d$15;
        end
        if (j1$21 == idx$15) begin
            y1$21 = d$15;
        end
        if (j2$21 == idx$15) begin
            y2$21 = d$15;
        end
        if (j0$21 == idx$16) begin
            y0$21 = d$16;
        end
        if (j1$21 == idx$16) begin
            y1$21 = d$16;
        end
        if (j2$21 == idx$16) begin
            y2$21 = d$16;
        end
        if (j0$21 == idx$17) begin
            y0$21 = d$17;
        end
        if (j1$21 == idx$17) begin
            y1$21 = d$17;
        end
        if (j2$21 == idx$17) begin
            y2$21 = d$17;
        end
        if (j0$21 == idx$18) begin
            y0$21 = d$18;
        end
        if (j1$21 == idx$18) begin
            y1$21 = d$18;
        end
        if (j2$21 == idx$18) begin
            y2$21 = d$18;
        end
        if (j0$21 == idx$19) begin
            y0$21 = d$19;
        end
        if (j1$21 == idx$19) begin
            y1$21 = d$19;
        end
        if (j2$21 == idx$19) begin
            y2$21 = d$19;
        end
        if (j0$21 == idx$20) begin
            y0$21 = d$20;
        end
        if (j1$21 == idx$20) begin
            y1$21 = d$20;
        end
        if (j2$21 == idx$20) begin
            y2$21 = d$20;
        end
        if (j0$21 == idx$21) begin
            y0$21 = d$21;
        end
        if (j1$21 == idx$21) begin
            y1$21 = d$21;
        end
        if (j2$21 == idx$21) begin
            y2$21 = d$21;
        end
        if (j0$21 == idx$22) begin
            y0$21 = d$22;
        end
        if (j1$21 == idx$22) begin
            y1$21 = d$22;
        end
        if (j2$21 == idx$22) begin
            y2$21 = d$22;
        end
        if (j0$21 == idx$23) begin
            y0$21 = d$23;
        end
        if (j1$21 == idx$23) begin
            y1$21 = d$23;
        end
        if (j2$21 == idx$23) begin
            y2$21 = d$23;
        end
        y0$22 = 32'h0;
        y1$22 = 32'h0;
        y2$22 = 32'h0;
        if (j0$22 == idx$0) begin
            y0$22 = d$0;
        end
        if (j1$22 == idx$0) begin
            y1$22 = d$0;
        end
        if (j2$22 == idx$0) begin
            y2$22 = d$0;
        end
        if (j0$22 == idx$1) begin
            y0$22 = d$1;
        end
        if (j1$22 == idx$1) begin
            y1$22 = d$1;
        end
        if (j2$22 == idx$1) begin
            y2$22 = d$1;
        end
        if (j0$22 == idx$2) begin
            y0$22 = d$2;
        end
        if (j1$22 == idx$2) begin
            y1$22 = d$2;
        end
        if (j2$22 == idx$2) begin
            y2$22 = d$2;
        end
        if (j0$22 == idx$3) begin
            y0$22 = d$3;
        end
        if (j1$22 == idx$3) begin
            y1$22 = d$3;
        end
        if (j2$22 == idx$3) begin
            y2$22 = d$3;
        end
        if (j0$22 == idx$4) begin
            y0$22 = d$4;
        end
        if (j1$22 == idx$4) begin
            y1$22 = d$4;
        end
        if (j2$22 == idx$4) begin
            y2$22 = d$4;
        end
        if (j0$22 == idx$5) begin
            y0$22 = d$5;
        end
        if (j1$22 == idx$5) begin
            y1$22 = d$5;
        end
        if (j2$22 == idx$5) begin
            y2$22 = d$5;
        end
        if (j0$22 == idx$6) begin
            y0$22 = d$6;
        end
        if (j1$22 == idx$6) begin
            y1$22 = d$6;
        end
        if (j2$22 == idx$6) begin
            y2$22 = d$6;
        end
        if (j0$22 == idx$7) begin
            y0$22 = d$7;
        end
        if (j1$22 == idx$7) begin
            y1$22 = d$7;
        end
        if (j2$22 == idx$7) begin
            y2$22 = d$7;
        end
        if (j0$22 == idx$8) begin
            y0$22 = d$8;
        end
        if (j1$22 == idx$8) begin
            y1$22 = d$8;
        end
        if (j2$22 == idx$8) begin
            y2$22 = d$8;
        end
        if (j0$22 == idx$9) begin
            y0$22 = d$9;
        end
        if (j1$22 == idx$9) begin
            y1$22 = d$9;
        end
        if (j2$22 == idx$9) begin
            y2$22 = d$9;
        end
        if (j0$22 == idx$10) begin
            y0$22 = d$10;
        end
        if (j1$22 == idx$10) begin
            y1$22 = d$10;
        end
        if (j2$22 == idx$10) begin
            y2$22 = d$10;
        end
        if (j0$22 == idx$11) begin
            y0$22 = d$11;
        end
        if (j1$22 == idx$11) begin
            y1$22 = d$11;
        end
        if (j2$22 == idx$11) begin
            y2$22 = d$11;
        end
        if (j0$22 == idx$12) begin
            y0$22 = d$12;
        end
        if (j1$22 == idx$12) begin
            y1$22 = d$12;
        end
        if (j2$22 == idx$12) begin
            y2$22 = d$12;
        end
        if (j0$22 == idx$13) begin
            y0$22 = d$13;
        end
        if (j1$22 == idx$13) begin
            y1$22 = d$13;
        end
        if (j2$22 == idx$13) begin
            y2$22 = d$13;
        end
        if (j0$22 == idx$14) begin
            y0$22 = d$14;
        end
        if (j1$22 == idx$14) begin
            y1$22 = d$14;
        end
        if (j2$22 == idx$14) begin
            y2$22 = d$14;
        end
        if (j0$22 == idx$15) begin
            y0$22 = d$15;
        end
        if (j1$22 == idx$15) begin
            y1$22 = d$15;
        end
        if (j2$22 == idx$15) begin
            y2$22 = d$15;
        end
        if (j0$22 == idx$16) begin
            y0$22 = d$16;
        end
        if (j1$22 == idx$16) begin
            y1$22 = d$16;
        end
        if (j2$22 == idx$16) begin
            y2$22 = d$16;
        end
        if (j0$22 == idx$17) begin
            y0$22 = d$17;
        end
        if (j1$22 == idx$17) begin
            y1$22 = d$17;
        end
        if (j2$22 == idx$17) begin
            y2$22 = d$17;
        end
        if (j0$22 == idx$18) begin
            y0$22 = d$18;
        end
        if (j1$22 == idx$18) begin
            y1$22 = d$18;
        end
        if (j2$22 == idx$18) begin
            y2$22 = d$18;
        end
        if (j0$22 == idx$19) begin
            y0$22 = d$19;
        end
        if (j1$22 == idx$19) begin
            y1$22 = d$19;
        end
        if (j2$22 == idx$19) begin
            y2$22 = d$19;
        end
        if (j0$22 == idx$20) begin
            y0$22 = d$20;
        end
        if (j1$22 == idx$20) begin
            y1$22 = d$20;
        end
        if (j2$22 == idx$20) begin
            y2$22 = d$20;
        end
        if (j0$22 == idx$21) begin
            y0$22 = d$21;
        end
        if (j1$22 == idx$21) begin
            y1$22 = d$21;
        end
        if (j2$22 == idx$21) begin
            y2$22 = d$21;
        end
        if (j0$22 == idx$22) begin
            y0$22 = d$22;
        end
        if (j1$22 == idx$22) begin
            y1$22 = d$22;
        end
        if (j2$22 == idx$22) begin
            y2$22 = d$22;
        end
        if (j0$22 == idx$23) begin
            y0$22 = d$23;
        end
        if (j1$22 == idx$23) begin
            y1$22 = d$23;
        end
        if (j2$22 == idx$23) begin
            y2$22 = d$23;
        end
        y0$23 = 32'h0;
        y1$23 = 32'h0;
        y2$23 = 32'h0;
        if (j0$23 == idx$0) begin
            y0$23 = d$0;
        end
        if (j1$23 == idx$0) begin
            y1$23 = d$0;
        end
        if (j2$23 == idx$0) begin
            y2$23 = d$0;
        end
        if (j0$23 == idx$1) begin
            y0$23 = d$1;
        end
        if (j1$23 == idx$1) begin
            y1$23 = d$1;
        end
        if (j2$23 == idx$1) begin
            y2$23 = d$1;
        end
        if (j0$23 == idx$2) begin
            y0$23 = d$2;
        end
        if (j1$23 == idx$2) begin
            y1$23 = d$2;
        end
        if (j2$23 == idx$2) begin
            y2$23 = d$2;
        end
        if (j0$23 == idx$3) begin
            y0$23 = d$3;
        end
        if (j1$23 == idx$3) begin
            y1$23 = d$3;
        end
        if (j2$23 == idx$3) begin
            y2$23 = d$3;
        end
        if (j0$23 == idx$4) begin
            y0$23 = d$4;
        end
        if (j1$23 == idx$4) begin
            y1$23 = d$4;
        end
        if (j2$23 == idx$4) begin
            y2$23 = d$4;
        end
        if (j0$23 == idx$5) begin
            y0$23 = d$5;
        end
        if (j1$23 == idx$5) begin
            y1$23 = d$5;
        end
        if (j2$23 == idx$5) begin
            y2$23 = d$5;
        end
        if (j0$23 == idx$6) begin
            y0$23 = d$6;
        end
        if (j1$23 == idx$6) begin
            y1$23 = d$6;
        end
        if (j2$23 == idx$6) begin
            y2$23 = d$6;
        end
        if (j0$23 == idx$7) begin
            y0$23 = d$7;
        end
        if (j1$23 == idx$7) begin
            y1$23 = d$7;
        end
        if (j2$23 == idx$7) begin
            y2$23 = d$7;
        end
        if (j0$23 == idx$8) begin
            y0$23 = d$8;
        end
        if (j1$23 == idx$8) begin
            y1$23 = d$8;
        end
        if (j2$23 == idx$8) begin
            y2$23 = d$8;
        end
        if (j0$23 == idx$9) begin
            y0$23 = d$9;
        end
        if (j1$23 == idx$9) begin
            y1$23 = d$9;
        end
        if (j2$23 == idx$9) begin
            y2$23 = d$9;
        end
        if (j0$23 == idx$10) begin
            y0$23 = d$10;
        end
        if (j1$23 == idx$10) begin
            y1$23 = d$10;
        end
        if (j2$23 == idx$10) begin
            y2$23 = d$10;
        end
        if (j0$23 == idx$11) begin
            y0$23 = d$11;
        end
        if (j1$23 == idx$11) begin
            y1$23 = d$11;
        end
        if (j2$23 == idx$11) begin
            y2$23 = d$11;
        end
        if (j0$23 == idx$12) begin
            y0$23 = d$12;
        end
        if (j1$23 == idx$12) begin
            y1$23 = d$12;
        end
        if (j2$23 == idx$12) begin
            y2$23 = d$12;
        end
        if (j0$23 == idx$13) begin
            y0$23 = d$13;
        end
        if (j1$23 == idx$13) begin
            y1$23 = d$13;
        end
        if (j2$23 == idx$13) begin
            y2$23 = d$13;
        end
        if (j0$23 == idx$14) begin
            y0$23 = d$14;
        end
        if (j1$23 == idx$14) begin
            y1$23 = d$14;
        end
        if (j2$23 == idx$14) begin
            y2$23 = d$14;
        end
        if (j0$23 == idx$15) begin
            y0$23 = d$15;
        end
        if (j1$23 == idx$15) begin
            y1$23 = d$15;
        end
        if (j2$23 == idx$15) begin
            y2$23 = d$15;
        end
        if (j0$23 == idx$16) begin
            y0$23 = d$16;
        end
        if (j1$23 == idx$16) begin
            y1$23 = d$16;
        end
        if (j2$23 == idx$16) begin
            y2$23 = d$16;
        end
        if (j0$23 == idx$17) begin
            y0$23 = d$17;
        end
        if (j1$23 == idx$17) begin
            y1$23 = d$17;
        end
        if (j2$23 == idx$17) begin
            y2$23 = d$17;
        end
        if (j0$23 == idx$18) begin
            y0$23 = d$18;
        end
        if (j1$23 == idx$18) begin
            y1$23 = d$18;
        end
        if (j2$23 == idx$18) begin
            y2$23 = d$18;
        end
        if (j0$23 == idx$19) begin
            y0$23 = d$19;
        end
        if (j1$23 == idx$19) begin
            y1$23 = d$19;
        end
        if (j2$23 == idx$19) begin
            y2$23 = d$19;
        end
        if (j0$23 == idx$20) begin
            y0$23 = d$20;
        end
        if (j1$23 == idx$20) begin
            y1$23 = d$20;
        end
        if (j2$23 == idx$20) begin
            y2$23 = d$20;
        end
        if (j0$23 == idx$21) begin
            y0$23 = d$21;
        end
        if (j1$23 == idx$21) begin
            y1$23 = d$21;
        end
        if (j2$23 == idx$21) begin
            y2$23 = d$21;
        end
        if (j0$23 == idx$22) begin
            y0$23 = d$22;
        end
        if (j1$23 == idx$22) begin
            y1$23 = d$22;
        end
        if (j2$23 == idx$22) begin
            y2$23 = d$22;
        end
        if (j0$23 == idx$23) begin
            y0$23 = d$23;
        end
        if (j1$23 == idx$23) begin
            y1$23 = d$23;
        end
        if (j2$23 == idx$23) begin
            y2$23 = d$23;
        end
    end
    
endmodule // top$dop$unit$klmsel


module top$dop$unit$setup(clock,load_en,load_addr,load_data,c0$0,c0$1,c0$2,c0$3,c0$4,c0$5,c0$6,c0$7,c0$8,c0$9,c0$10,c0$11,c0$12,c0$13,c0$14,c0$15,c0$16,c0$17,c0$18,c0$19,c0$20,c0$21,c0$22,c0$23,c1$0,c1$1,c1$2,c1$3,c1$4,c1$5,c1$6,c1$7,c1$8,c1$9,c1$10,c1$11,c1$12,c1$13,c1$14,c1$15,c1$16,c1$17,c1$18,c1$19,c1$20,c1$21,c1$22,c1$23,c2$0,c2$1,c2$2,c2$3,c2$4,c2$5,c2$6,c2$7,c2$8,c2$9,c2$10,c2$11,c2$12,c2$13,c2$14,c2$15,c2$16,c2$17,c2$18,c2$19,c2$20,c2$21,c2$22,c2$23,c$0,c$1,c$2,c$3,c$4,c$5,c$6,c$7,c$8,c$9,c$10,c$11,c$12,c$13,c$14,c$15,c$16,c$17,c$18,c$19,c$20,c$21,c$22,c$23,j0$0,j0$1,j0$2,j0$3,j0$4,j0$5,j0$6,j0$7,j0$8,j0$9,j0$10,j0$11,j0$12,j0$13,j0$14,j0$15,j0$16,j0$17,j0$18,j0$19,j0$20,j0$21,j0$22,j0$23,j1$0,j1$1,j1$2,j1$3,j1$4,j1$5,j1$6,j1$7,j1$8,j1$9,j1$10,j1$11,j1$12,j1$13,j1$14,j1$15,j1$16,j1$17,j1$18,j1$19,j1$20,j1$21,j1$22,j1$23,j2$0,j2$1,j2$2,j2$3,j2$4,j2$5,j2$6,j2$7,j2$8,j2$9,j2$10,j2$11,j2$12,j2$13,j2$14,j2$15,j2$16,j2$17,j2$18,j2$19,j2$20,j2$21,j2$22,j2$23,round_up$0,round_up$1,round_up$2,round_up$3,round_up$4,round_up$5,round_up$6,round_up$7,round_up$8,round_up$9,round_up$10,round_up$11,round_up$12,round_up$13,round_up$14,round_up$15,round_up$16,round_up$17,round_up$18,round_up$19,round_up$20,round_up$21,round_up$22,round_up$23);
    
    // Module arguments
    input wire  clock;
    input wire  load_en;
    input wire  [7:0] load_addr;
    input wire  [31:0] load_data;
    output reg  [31:0] c0$0;
    output reg  [31:0] c0$1;
    output reg  [31:0] c0$2;
    output reg  [31:0] c0$3;
    output reg  [31:0] c0$4;
    output reg  [31:0] c0$5;
    output reg  [31:0] c0$6;
    output reg  [31:0] c0$7;
    output reg  [31:0] c0$8;
    output reg  [31:0] c0$9;
    output reg  [31:0] c0$10;
    output reg  [31:0] c0$11;
    output reg  [31:0] c0$12;
    output reg  [31:0] c0$13;
    output reg  [31:0] c0$14;
    output reg  [31:0] c0$15;
    output reg  [31:0] c0$16;
    output reg  [31:0] c0$17;
    output reg  [31:0] c0$18;
    output reg  [31:0] c0$19;
    output reg  [31:0] c0$20;
    output reg  [31:0] c0$21;
    output reg  [31:0] c0$22;
    output reg  [31:0] c0$23;
    output reg  [31:0] c1$0;
    output reg  [31:0] c1$1;
    output reg  [31:0] c1$2;
    output reg  [31:0] c1$3;
    output reg  [31:0] c1$4;
    output reg  [31:0] c1$5;
    output reg  [31:0] c1$6;
    output reg  [31:0] c1$7;
    output reg  [31:0] c1$8;
    output reg  [31:0] c1$9;
    output reg  [31:0] c1$10;
    output reg  [31:0] c1$11;
    output reg  [31:0] c1$12;
    output reg  [31:0] c1$13;
    output reg  [31:0] c1$14;
    output reg  [31:0] c1$15;
    output reg  [31:0] c1$16;
    output reg  [31:0] c1$17;
    output reg  [31:0] c1$18;
    output reg  [31:0] c1$19;
    output reg  [31:0] c1$20;
    output reg  [31:0] c1$21;
    output reg  [31:0] c1$22;
    output reg  [31:0] c1$23;
    output reg  [31:0] c2$0;
    output reg  [31:0] c2$1;
    output reg  [31:0] c2$2;
    output reg  [31:0] c2$3;
    output reg  [31:0] c2$4;
    output reg  [31:0] c2$5;
    output reg  [31:0] c2$6;
    output reg  [31:0] c2$7;
    output reg  [31:0] c2$8;
    output reg  [31:0] c2$9;
    output reg  [31:0] c2$10;
    output reg  [31:0] c2$11;
    output reg  [31:0] c2$12;
    output reg  [31:0] c2$13;
    output reg  [31:0] c2$14;
    output reg  [31:0] c2$15;
    output reg  [31:0] c2$16;
    output reg  [31:0] c2$17;
    output reg  [31:0] c2$18;
    output reg  [31:0] c2$19;
    output reg  [31:0] c2$20;
    output reg  [31:0] c2$21;
    output reg  [31:0] c2$22;
    output reg  [31:0] c2$23;
    output reg  [31:0] c$0;
    output reg  [31:0] c$1;
    output reg  [31:0] c$2;
    output reg  [31:0] c$3;
    output reg  [31:0] c$4;
    output reg  [31:0] c$5;
    output reg  [31:0] c$6;
    output reg  [31:0] c$7;
    output reg  [31:0] c$8;
    output reg  [31:0] c$9;
    output reg  [31:0] c$10;
    output reg  [31:0] c$11;
    output reg  [31:0] c$12;
    output reg  [31:0] c$13;
    output reg  [31:0] c$14;
    output reg  [31:0] c$15;
    output reg  [31:0] c$16;
    output reg  [31:0] c$17;
    output reg  [31:0] c$18;
    output reg  [31:0] c$19;
    output reg  [31:0] c$20;
    output reg  [31:0] c$21;
    output reg  [31:0] c$22;
    output reg  [31:0] c$23;
    output reg  [4:0] j0$0;
    output reg  [4:0] j0$1;
    output reg  [4:0] j0$2;
    output reg  [4:0] j0$3;
    output reg  [4:0] j0$4;
    output reg  [4:0] j0$5;
    output reg  [4:0] j0$6;
    output reg  [4:0] j0$7;
    output reg  [4:0] j0$8;
    output reg  [4:0] j0$9;
    output reg  [4:0] j0$10;
    output reg  [4:0] j0$11;
    output reg  [4:0] j0$12;
    output reg  [4:0] j0$13;
    output reg  [4:0] j0$14;
    output reg  [4:0] j0$15;
    output reg  [4:0] j0$16;
    output reg  [4:0] j0$17;
    output reg  [4:0] j0$18;
    output reg  [4:0] j0$19;
    output reg  [4:0] j0$20;
    output reg  [4:0] j0$21;
    output reg  [4:0] j0$22;
    output reg  [4:0] j0$23;
    output reg  [4:0] j1$0;
    output reg  [4:0] j1$1;
    output reg  [4:0] j1$2;
    output reg  [4:0] j1$3;
    output reg  [4:0] j1$4;
    output reg  [4:0] j1$5;
    output reg  [4:0] j1$6;
    output reg  [4:0] j1$7;
    output reg  [4:0] j1$8;
    output reg  [4:0] j1$9;
    output reg  [4:0] j1$10;
    output reg  [4:0] j1$11;
    output reg  [4:0] j1$12;
    output reg  [4:0] j1$13;
    output reg  [4:0] j1$14;
    output reg  [4:0] j1$15;
    output reg  [4:0] j1$16;
    output reg  [4:0] j1$17;
    output reg  [4:0] j1$18;
    output reg  [4:0] j1$19;
    output reg  [4:0] j1$20;
    output reg  [4:0] j1$21;
    output reg  [4:0] j1$22;
    output reg  [4:0] j1$23;
    output reg  [4:0] j2$0;
    output reg  [4:0] j2$1;
    output reg  [4:0] j2$2;
    output reg  [4:0] j2$3;
    output reg  [4:0] j2$4;
    output reg  [4:0] j2$5;
    output reg  [4:0] j2$6;
    output reg  [4:0] j2$7;
    output reg  [4:0] j2$8;
    output reg  [4:0] j2$9;
    output reg  [4:0] j2$10;
    output reg  [4:0] j2$11;
    output reg  [4:0] j2$12;
    output reg  [4:0] j2$13;
    output reg  [4:0] j2$14;
    output reg  [4:0] j2$15;
    output reg  [4:0] j2$16;
    output reg  [4:0] j2$17;
    output reg  [4:0] j2$18;
    output reg  [4:0] j2$19;
    output reg  [4:0] j2$20;
    output reg  [4:0] j2$21;
    output reg  [4:0] j2$22;
    output reg  [4:0] j2$23;
    output reg  round_up$0;
    output reg  round_up$1;
    output reg  round_up$2;
    output reg  round_up$3;
    output reg  round_up$4;
    output reg  round_up$5;
    output reg  round_up$6;
    output reg  round_up$7;
    output reg  round_up$8;
    output reg  round_up$9;
    output reg  round_up$10;
    output reg  round_up$11;
    output reg  round_up$12;
    output reg  round_up$13;
    output reg  round_up$14;
    output reg  round_up$15;
    output reg  round_up$16;
    output reg  round_up$17;
    output reg  round_up$18;
    output reg  round_up$19;
    output reg  round_up$20;
    output reg  round_up$21;
    output reg  round_up$22;
    output reg  round_up$23;
    
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
    
    // Stub signals
    reg  [31:0] cmat_0$0$d;
    wire  [31:0] cmat_0$0$q;
    reg  cmat_0$0$clock;
    reg  [31:0] cmat_0$1$d;
    wire  [31:0] cmat_0$1$q;
    reg  cmat_0$1$clock;
    reg  [31:0] cmat_0$2$d;
    wire  [31:0] cmat_0$2$q;
    reg  cmat_0$2$clock;
    reg  [31:0] cmat_0$3$d;
    wire  [31:0] cmat_0$3$q;
    reg  cmat_0$3$clock;
    reg  [31:0] cmat_0$4$d;
    wire  [31:0] cmat_0$4$q;
    reg  cmat_0$4$clock;
    reg  [31:0] cmat_0$5$d;
    wire  [31:0] cmat_0$5$q;
    reg  cmat_0$5$clock;
    reg  [31:0] cmat_0$6$d;
    wire  [31:0] cmat_0$6$q;
    reg  cmat_0$6$clock;
    reg  [31:0] cmat_0$7$d;
    wire  [31:0] cmat_0$7$q;
    reg  cmat_0$7$clock;
    reg  [31:0] cmat_0$8$d;
    wire  [31:0] cmat_0$8$q;
    reg  cmat_0$8$clock;
    reg  [31:0] cmat_0$9$d;
    wire  [31:0] cmat_0$9$q;
    reg  cmat_0$9$clock;
    reg  [31:0] cmat_0$10$d;
    wire  [31:0] cmat_0$10$q;
    reg  cmat_0$10$clock;
    reg  [31:0] cmat_0$11$d;
    wire  [31:0] cmat_0$11$q;
    reg  cmat_0$11$clock;
    reg  [31:0] cmat_0$12$d;
    wire  [31:0] cmat_0$12$q;
    reg  cmat_0$12$clock;
    reg  [31:0] cmat_0$13$d;
    wire  [31:0] cmat_0$13$q;
    reg  cmat_0$13$clock;
    reg  [31:0] cmat_0$14$d;
    wire  [31:0] cmat_0$14$q;
    reg  cmat_0$14$clock;
    reg  [31:0] cmat_0$15$d;
    wire  [31:0] cmat_0$15$q;
    reg  cmat_0$15$clock;
    reg  [31:0] cmat_0$16$d;
    wire  [31:0] cmat_0$16$q;
    reg  cmat_0$16$clock;
    reg  [31:0] cmat_0$17$d;
    wire  [31:0] cmat_0$17$q;
    reg  cmat_0$17$clock;
    reg  [31:0] cmat_0$18$d;
    wire  [31:0] cmat_0$18$q;
    reg  cmat_0$18$clock;
    reg  [31:0] cmat_0$19$d;
    wire  [31:0] cmat_0$19$q;
    reg  cmat_0$19$clock;
    reg  [31:0] cmat_0$20$d;
    wire  [31:0] cmat_0$20$q;
    reg  cmat_0$20$clock;
    reg  [31:0] cmat_0$21$d;
    wire  [31:0] cmat_0$21$q;
    reg  cmat_0$21$clock;
    reg  [31:0] cmat_0$22$d;
    wire  [31:0] cmat_0$22$q;
    reg  cmat_0$22$clock;
    reg  [31:0] cmat_0$23$d;
    wire  [31:0] cmat_0$23$q;
    reg  cmat_0$23$clock;
    reg  [31:0] cmat_1$0$d;
    wire  [31:0] cmat_1$0$q;
    reg  cmat_1$0$clock;
    reg  [31:0] cmat_1$1$d;
    wire  [31:0] cmat_1$1$q;
    reg  cmat_1$1$clock;
    reg  [31:0] cmat_1$2$d;
    wire  [31:0] cmat_1$2$q;
    reg  cmat_1$2$clock;
    reg  [31:0] cmat_1$3$d;
    wire  [31:0] cmat_1$3$q;
    reg  cmat_1$3$clock;
    reg  [31:0] cmat_1$4$d;
    wire  [31:0] cmat_1$4$q;
    reg  cmat_1$4$clock;
    reg  [31:0] cmat_1$5$d;
    wire  [31:0] cmat_1$5$q;
    reg  cmat_1$5$clock;
    reg  [31:0] cmat_1$6$d;
    wire  [31:0] cmat_1$6$q;
    reg  cmat_1$6$clock;
    reg  [31:0] cmat_1$7$d;
    wire  [31:0] cmat_1$7$q;
    reg  cmat_1$7$clock;
    reg  [31:0] cmat_1$8$d;
    wire  [31:0] cmat_1$8$q;
    reg  cmat_1$8$clock;
    reg  [31:0] cmat_1$9$d;
    wire  [31:0] cmat_1$9$q;
    reg  cmat_1$9$clock;
    reg  [31:0] cmat_1$10$d;
    wire  [31:0] cmat_1$10$q;
    reg  cmat_1$10$clock;
    reg  [31:0] cmat_1$11$d;
    wire  [31:0] cmat_1$11$q;
    reg  cmat_1$11$clock;
    reg  [31:0] cmat_1$12$d;
    wire  [31:0] cmat_1$12$q;
    reg  cmat_1$12$clock;
    reg  [31:0] cmat_1$13$d;
    wire  [31:0] cmat_1$13$q;
    reg  cmat_1$13$clock;
    reg  [31:0] cmat_1$14$d;
    wire  [31:0] cmat_1$14$q;
    reg  cmat_1$14$clock;
    reg  [31:0] cmat_1$15$d;
    wire  [31:0] cmat_1$15$q;
    reg  cmat_1$15$clock;
    reg  [31:0] cmat_1$16$d;
    wire  [31:0] cmat_1$16$q;
    reg  cmat_1$16$clock;
    reg  [31:0] cmat_1$17$d;
    wire  [31:0] cmat_1$17$q;
    reg  cmat_1$17$clock;
    reg  [31:0] cmat_1$18$d;
    wire  [31:0] cmat_1$18$q;
    reg  cmat_1$18$clock;
    reg  [31:0] cmat_1$19$d;
    wire  [31:0] cmat_1$19$q;
    reg  cmat_1$19$clock;
    reg  [31:0] cmat_1$20$d;
    wire  [31:0] cmat_1$20$q;
    reg  cmat_1$20$clock;
    reg  [31:0] cmat_1$21$d;
    wire  [31:0] cmat_1$21$q;
    reg  cmat_1$21$clock;
    reg  [31:0] cmat_1$22$d;
    wire  [31:0] cmat_1$22$q;
    reg  cmat_1$22$clock;
    reg  [31:0] cmat_1$23$d;
    wire  [31:0] cmat_1$23$q;
    reg  cmat_1$23$clock;
    reg  [31:0] cmat_2$0$d;
    wire  [31:0] cmat_2$0$q;
    reg  cmat_2$0$clock;
    reg  [31:0] cmat_2$1$d;
    wire  [31:0] cmat_2$1$q;
    reg  cmat_2$1$clock;
    reg  [31:0] cmat_2$2$d;
    wire  [31:0] cmat_2$2$q;
    reg  cmat_2$2$clock;
    reg  [31:0] cmat_2$3$d;
    wire  [31:0] cmat_2$3$q;
    reg  cmat_2$3$clock;
    reg  [31:0] cmat_2$4$d;
    wire  [31:0] cmat_2$4$q;
    reg  cmat_2$4$clock;
    reg  [31:0] cmat_2$5$d;
    wire  [31:0] cmat_2$5$q;
    reg  cmat_2$5$clock;
    reg  [31:0] cmat_2$6$d;
    wire  [31:0] cmat_2$6$q;
    reg  cmat_2$6$clock;
    reg  [31:0] cmat_2$7$d;
    wire  [31:0] cmat_2$7$q;
    reg  cmat_2$7$clock;
    reg  [31:0] cmat_2$8$d;
    wire  [31:0] cmat_2$8$q;
    reg  cmat_2$8$clock;
    reg  [31:0] cmat_2$9$d;
    wire  [31:0] cmat_2$9$q;
    reg  cmat_2$9$clock;
    reg  [31:0] cmat_2$10$d;
    wire  [31:0] cmat_2$10$q;
    reg  cmat_2$10$clock;
    reg  [31:0] cmat_2$11$d;
    wire  [31:0] cmat_2$11$q;
    reg  cmat_2$11$clock;
    reg  [31:0] cmat_2$12$d;
    wire  [31:0] cmat_2$12$q;
    reg  cmat_2$12$clock;
    reg  [31:0] cmat_2$13$d;
    wire  [31:0] cmat_2$13$q;
    reg  cmat_2$13$clock;
    reg  [31:0] cmat_2$14$d;
    wire  [31:0] cmat_2$14$q;
    reg  cmat_2$14$clock;
    reg  [31:0] cmat_2$15$d;
    wire  [31:0] cmat_2$15$q;
    reg  cmat_2$15$clock;
    reg  [31:0] cmat_2$16$d;
    wire  [31:0] cmat_2$16$q;
    reg  cmat_2$16$clock;
    reg  [31:0] cmat_2$17$d;
    wire  [31:0] cmat_2$17$q;
    reg  cmat_2$17$clock;
    reg  [31:0] cmat_2$18$d;
    wire  [31:0] cmat_2$18$q;
    reg  cmat_2$18$clock;
    reg  [31:0] cmat_2$19$d;
    wire  [31:0] cmat_2$19$q;
    reg  cmat_2$19$clock;
    reg  [31:0] cmat_2$20$d;
    wire  [31:0] cmat_2$20$q;
    reg  cmat_2$20$clock;
    reg  [31:0] cmat_2$21$d;
    wire  [31:0] cmat_2$21$q;
    reg  cmat_2$21$clock;
    reg  [31:0] cmat_2$22$d;
    wire  [31:0] cmat_2$22$q;
    reg  cmat_2$22$clock;
    reg  [31:0] cmat_2$23$d;
    wire  [31:0] cmat_2$23$q;
    reg  cmat_2$23$clock;
    reg  [31:0] cvec$0$d;
    wire  [31:0] cvec$0$q;
    reg  cvec$0$clock;
    reg  [31:0] cvec$1$d;
    wire  [31:0] cvec$1$q;
    reg  cvec$1$clock;
    reg  [31:0] cvec$2$d;
    wire  [31:0] cvec$2$q;
    reg  cvec$2$clock;
    reg  [31:0] cvec$3$d;
    wire  [31:0] cvec$3$q;
    reg  cvec$3$clock;
    reg  [31:0] cvec$4$d;
    wire  [31:0] cvec$4$q;
    reg  cvec$4$clock;
    reg  [31:0] cvec$5$d;
    wire  [31:0] cvec$5$q;
    reg  cvec$5$clock;
    reg  [31:0] cvec$6$d;
    wire  [31:0] cvec$6$q;
    reg  cvec$6$clock;
    reg  [31:0] cvec$7$d;
    wire  [31:0] cvec$7$q;
    reg  cvec$7$clock;
    reg  [31:0] cvec$8$d;
    wire  [31:0] cvec$8$q;
    reg  cvec$8$clock;
    reg  [31:0] cvec$9$d;
    wire  [31:0] cvec$9$q;
    reg  cvec$9$clock;
    reg  [31:0] cvec$10$d;
    wire  [31:0] cvec$10$q;
    reg  cvec$10$clock;
    reg  [31:0] cvec$11$d;
    wire  [31:0] cvec$11$q;
    reg  cvec$11$clock;
    reg  [31:0] cvec$12$d;
    wire  [31:0] cvec$12$q;
    reg  cvec$12$clock;
    reg  [31:0] cvec$13$d;
    wire  [31:0] cvec$13$q;
    reg  cvec$13$clock;
    reg  [31:0] cvec$14$d;
    wire  [31:0] cvec$14$q;
    reg  cvec$14$clock;
    reg  [31:0] cvec$15$d;
    wire  [31:0] cvec$15$q;
    reg  cvec$15$clock;
    reg  [31:0] cvec$16$d;
    wire  [31:0] cvec$16$q;
    reg  cvec$16$clock;
    reg  [31:0] cvec$17$d;
    wire  [31:0] cvec$17$q;
    reg  cvec$17$clock;
    reg  [31:0] cvec$18$d;
    wire  [31:0] cvec$18$q;
    reg  cvec$18$clock;
    reg  [31:0] cvec$19$d;
    wire  [31:0] cvec$19$q;
    reg  cvec$19$clock;
    reg  [31:0] cvec$20$d;
    wire  [31:0] cvec$20$q;
    reg  cvec$20$clock;
    reg  [31:0] cvec$21$d;
    wire  [31:0] cvec$21$q;
    reg  cvec$21$clock;
    reg  [31:0] cvec$22$d;
    wire  [31:0] cvec$22$q;
    reg  cvec$22$clock;
    reg  [31:0] cvec$23$d;
    wire  [31:0] cvec$23$q;
    reg  cvec$23$clock;
    reg  [4:0] jsel_0$0$d;
    wire  [4:0] jsel_0$0$q;
    reg  jsel_0$0$clock;
    reg  [4:0] jsel_0$1$d;
    wire  [4:0] jsel_0$1$q;
    reg  jsel_0$1$clock;
    reg  [4:0] jsel_0$2$d;
    wire  [4:0] jsel_0$2$q;
    reg  jsel_0$2$clock;
    reg  [4:0] jsel_0$3$d;
    wire  [4:0] jsel_0$3$q;
    reg  jsel_0$3$clock;
    reg  [4:0] jsel_0$4$d;
    wire  [4:0] jsel_0$4$q;
    reg  jsel_0$4$clock;
    reg  [4:0] jsel_0$5$d;
    wire  [4:0] jsel_0$5$q;
    reg  jsel_0$5$clock;
    reg  [4:0] jsel_0$6$d;
    wire  [4:0] jsel_0$6$q;
    reg  jsel_0$6$clock;
    reg  [4:0] jsel_0$7$d;
    wire  [4:0] jsel_0$7$q;
    reg  jsel_0$7$clock;
    reg  [4:0] jsel_0$8$d;
    wire  [4:0] jsel_0$8$q;
    reg  jsel_0$8$clock;
    reg  [4:0] jsel_0$9$d;
    wire  [4:0] jsel_0$9$q;
    reg  jsel_0$9$clock;
    reg  [4:0] jsel_0$10$d;
    wire  [4:0] jsel_0$10$q;
    reg  jsel_0$10$clock;
    reg  [4:0] jsel_0$11$d;
    wire  [4:0] jsel_0$11$q;
    reg  jsel_0$11$clock;
    reg  [4:0] jsel_0$12$d;
    wire  [4:0] jsel_0$12$q;
    reg  jsel_0$12$clock;
    reg  [4:0] jsel_0$13$d;
    wire  [4:0] jsel_0$13$q;
    reg  jsel_0$13$clock;
    reg  [4:0] jsel_0$14$d;
    wire  [4:0] jsel_0$14$q;
    reg  jsel_0$14$clock;
    reg  [4:0] jsel_0$15$d;
    wire  [4:0] jsel_0$15$q;
    reg  jsel_0$15$clock;
    reg  [4:0] jsel_0$16$d;
    wire  [4:0] jsel_0$16$q;
    reg  jsel_0$16$clock;
    reg  [4:0] jsel_0$17$d;
    wire  [4:0] jsel_0$17$q;
    reg  jsel_0$17$clock;
    reg  [4:0] jsel_0$18$d;
    wire  [4:0] jsel_0$18$q;
    reg  jsel_0$18$clock;
    reg  [4:0] jsel_0$19$d;
    wire  [4:0] jsel_0$19$q;
    reg  jsel_0$19$clock;
    reg  [4:0] jsel_0$20$d;
    wire  [4:0] jsel_0$20$q;
    reg  jsel_0$20$clock;
    reg  [4:0] jsel_0$21$d;
    wire  [4:0] jsel_0$21$q;
    reg  jsel_0$21$clock;
    reg  [4:0] jsel_0$22$d;
    wire  [4:0] jsel_0$22$q;
    reg  jsel_0$22$clock;
    reg  [4:0] jsel_0$23$d;
    wire  [4:0] jsel_0$23$q;
    reg  jsel_0$23$clock;
    reg  [4:0] jsel_1$0$d;
    wire  [4:0] jsel_1$0$q;
    reg  jsel_1$0$clock;
    reg  [4:0] jsel_1$1$d;
    wire  [4:0] jsel_1$1$q;
    reg  jsel_1$1$clock;
    reg  [4:0] jsel_1$2$d;
    wire  [4:0] jsel_1$2$q;
    reg  jsel_1$2$clock;
    reg  [4:0] jsel_1$3$d;
    wire  [4:0] jsel_1$3$q;
    reg  jsel_1$3$clock;
    reg  [4:0] jsel_1$4$d;
    wire  [4:0] jsel_1$4$q;
    reg  jsel_1$4$clock;
    reg  [4:0] jsel_1$5$d;
    wire  [4:0] jsel_1$5$q;
    reg  jsel_1$5$clock;
    reg  [4:0] jsel_1$6$d;
    wire  [4:0] jsel_1$6$q;
    reg  jsel_1$6$clock;
    reg  [4:0] jsel_1$7$d;
    wire  [4:0] jsel_1$7$q;
    reg  jsel_1$7$clock;
    reg  [4:0] jsel_1$8$d;
    wire  [4:0] jsel_1$8$q;
    reg  jsel_1$8$clock;
    reg  [4:0] jsel_1$9$d;
    wire  [4:0] jsel_1$9$q;
    reg  jsel_1$9$clock;
    reg  [4:0] jsel_1$10$d;
    wire  [4:0] jsel_1$10$q;
    reg  jsel_1$10$clock;
    reg  [4:0] jsel_1$11$d;
    wire  [4:0] jsel_1$11$q;
    reg  jsel_1$11$clock;
    reg  [4:0] jsel_1$12$d;
    wire  [4:0] jsel_1$12$q;
    reg  jsel_1$12$clock;
    reg  [4:0] jsel_1$13$d;
    wire  [4:0] jsel_1$13$q;
    reg  jsel_1$13$clock;
    reg  [4:0] jsel_1$14$d;
    wire  [4:0] jsel_1$14$q;
    reg  jsel_1$14$clock;
    reg  [4:0] jsel_1$15$d;
    wire  [4:0] jsel_1$15$q;
    reg  jsel_1$15$clock;
    reg  [4:0] jsel_1$16$d;
    wire  [4:0] jsel_1$16$q;
    reg  jsel_1$16$clock;
    reg  [4:0] jsel_1$17$d;
    wire  [4:0] jsel_1$17$q;
    reg  jsel_1$17$clock;
    reg  [4:0] jsel_1$18$d;
    wire  [4:0] jsel_1$18$q;
    reg  jsel_1$18$clock;
    reg  [4:0] jsel_1$19$d;
    wire  [4:0] jsel_1$19$q;
    reg  jsel_1$19$clock;
    reg  [4:0] jsel_1$20$d;
    wire  [4:0] jsel_1$20$q;
    reg  jsel_1$20$clock;
    reg  [4:0] jsel_1$21$d;
    wire  [4:0] jsel_1$21$q;
    reg  jsel_1$21$clock;
    reg  [4:0] jsel_1$22$d;
    wire  [4:0] jsel_1$22$q;
    reg  jsel_1$22$clock;
    reg  [4:0] jsel_1$23$d;
    wire  [4:0] jsel_1$23$q;
    reg  jsel_1$23$clock;
    reg  [4:0] jsel_2$0$d;
    wire  [4:0] jsel_2$0$q;
    reg  jsel_2$0$clock;
    reg  [4:0] jsel_2$1$d;
    wire  [4:0] jsel_2$1$q;
    reg  jsel_2$1$clock;
    reg  [4:0] jsel_2$2$d;
    wire  [4:0] jsel_2$2$q;
    reg  jsel_2$2$clock;
    reg  [4:0] jsel_2$3$d;
    wire  [4:0] jsel_2$3$q;
    reg  jsel_2$3$clock;
    reg  [4:0] jsel_2$4$d;
    wire  [4:0] jsel_2$4$q;
    reg  jsel_2$4$clock;
    reg  [4:0] jsel_2$5$d;
    wire  [4:0] jsel_2$5$q;
    reg  jsel_2$5$clock;
    reg  [4:0] jsel_2$6$d;
    wire  [4:0] jsel_2$6$q;
    reg  jsel_2$6$clock;
    reg  [4:0] jsel_2$7$d;
    wire  [4:0] jsel_2$7$q;
    reg  jsel_2$7$clock;
    reg  [4:0] jsel_2$8$d;
    wire  [4:0] jsel_2$8$q;
    reg  jsel_2$8$clock;
    reg  [4:0] jsel_2$9$d;
    wire  [4:0] jsel_2$9$q;
    reg  jsel_2$9$clock;
    reg  [4:0] jsel_2$10$d;
    wire  [4:0] jsel_2$10$q;
    reg  jsel_2$10$clock;
    reg  [4:0] jsel_2$11$d;
    wire  [4:0] jsel_2$11$q;
    reg  jsel_2$11$clock;
    reg  [4:0] jsel_2$12$d;
    wire  [4:0] jsel_2$12$q;
    reg  jsel_2$12$clock;
    reg  [4:0] jsel_2$13$d;
    wire  [4:0] jsel_2$13$q;
    reg  jsel_2$13$clock;
    reg  [4:0] jsel_2$14$d;
    wire  [4:0] jsel_2$14$q;
    reg  jsel_2$14$clock;
    reg  [4:0] jsel_2$15$d;
    wire  [4:0] jsel_2$15$q;
    reg  jsel_2$15$clock;
    reg  [4:0] jsel_2$16$d;
    wire  [4:0] jsel_2$16$q;
    reg  jsel_2$16$clock;
    reg  [4:0] jsel_2$17$d;
    wire  [4:0] jsel_2$17$q;
    reg  jsel_2$17$clock;
    reg  [4:0] jsel_2$18$d;
    wire  [4:0] jsel_2$18$q;
    reg  jsel_2$18$clock;
    reg  [4:0] jsel_2$19$d;
    wire  [4:0] jsel_2$19$q;
    reg  jsel_2$19$clock;
    reg  [4:0] jsel_2$20$d;
    wire  [4:0] jsel_2$20$q;
    reg  jsel_2$20$clock;
    reg  [4:0] jsel_2$21$d;
    wire  [4:0] jsel_2$21$q;
    reg  jsel_2$21$clock;
    reg  [4:0] jsel_2$22$d;
    wire  [4:0] jsel_2$22$q;
    reg  jsel_2$22$clock;
    reg  [4:0] jsel_2$23$d;
    wire  [4:0] jsel_2$23$q;
    reg  jsel_2$23$clock;
    reg  rnd$0$d;
    wire  rnd$0$q;
    reg  rnd$0$clock;
    reg  rnd$1$d;
    wire  rnd$1$q;
    reg  rnd$1$clock;
    reg  rnd$2$d;
    wire  rnd$2$q;
    reg  rnd$2$clock;
    reg  rnd$3$d;
    wire  rnd$3$q;
    reg  rnd$3$clock;
    reg  rnd$4$d;
    wire  rnd$4$q;
    reg  rnd$4$clock;
    reg  rnd$5$d;
    wire  rnd$5$q;
    reg  rnd$5$clock;
    reg  rnd$6$d;
    wire  rnd$6$q;
    reg  rnd$6$clock;
    reg  rnd$7$d;
    wire  rnd$7$q;
    reg  rnd$7$clock;
    reg  rnd$8$d;
    wire  rnd$8$q;
    reg  rnd$8$clock;
    reg  rnd$9$d;
    wire  rnd$9$q;
    reg  rnd$9$clock;
    reg  rnd$10$d;
    wire  rnd$10$q;
    reg  rnd$10$clock;
    reg  rnd$11$d;
    wire  rnd$11$q;
    reg  rnd$11$clock;
    reg  rnd$12$d;
    wire  rnd$12$q;
    reg  rnd$12$clock;
    reg  rnd$13$d;
    wire  rnd$13$q;
    reg  rnd$13$clock;
    reg  rnd$14$d;
    wire  rnd$14$q;
    reg  rnd$14$clock;
    reg  rnd$15$d;
    wire  rnd$15$q;
    reg  rnd$15$clock;
    reg  rnd$16$d;
    wire  rnd$16$q;
    reg  rnd$16$clock;
    reg  rnd$17$d;
    wire  rnd$17$q;
    reg  rnd$17$clock;
    reg  rnd$18$d;
    wire  rnd$18$q;
    reg  rnd$18$clock;
    reg  rnd$19$d;
    wire  rnd$19$q;
    reg  rnd$19$clock;
    reg  rnd$20$d;
    wire  rnd$20$q;
    reg  rnd$20$clock;
    reg  rnd$21$d;
    wire  rnd$21$q;
    reg  rnd$21$clock;
    reg  rnd$22$d;
    wire  rnd$22$q;
    reg  rnd$22$clock;
    reg  rnd$23$d;
    wire  rnd$23$q;
    reg  rnd$23$clock;
    
    // Local signals
    reg  [4:0] c_lane;
    reg  [2:0] c_field;
    
    // Sub module instances
    top$cnt_dop$total cmat_0$0(
        .d(cmat_0$0$d),
        .q(cmat_0$0$q),
        .clock(cmat_0$0$clock)
    );
    top$cnt_dop$total cmat_0$1(
        .d(cmat_0$1$d),
        .q(cmat_0$1$q),
        .clock(cmat_0$1$clock)
    );
    top$cnt_dop$total cmat_0$2(
        .d(cmat_0$2$d),
        .q(cmat_0$2$q),
        .clock(cmat_0$2$clock)
    );
    top$cnt_dop$total cmat_0$3(
        .d(cmat_0$3$d),
        .q(cmat_0$3$q),
        .clock(cmat_0$3$clock)
    );
    top$cnt_dop$total cmat_0$4(
        .d(cmat_0$4$d),
        .q(cmat_0$4$q),
        .clock(cmat_0$4$clock)
    );
    top$cnt_dop$total cmat_0$5(
        .d(cmat_0$5$d),
        .q(cmat_0$5$q),
        .clock(cmat_0$5$clock)
    );
    top$cnt_dop$total cmat_0$6(
        .d(cmat_0$6$d),
        .q(cmat_0$6$q),
        .clock(cmat_0$6$clock)
    );
    top$cnt_dop$total cmat_0$7(
        .d(cmat_0$7$d),
        .q(cmat_0$7$q),
        .clock(cmat_0$7$clock)
    );
    top$cnt_dop$total cmat_0$8(
        .d(cmat_0$8$d),
        .q(cmat_0$8$q),
        .clock(cmat_0$8$clock)
    );
    top$cnt_dop$total cmat_0$9(
        .d(cmat_0$9$d),
        .q(cmat_0$9$q),
        .clock(cmat_0$9$clock)
    );
    top$cnt_dop$total cmat_0$10(
        .d(cmat_0$10$d),
        .q(cmat_0$10$q),
        .clock(cmat_0$10$clock)
    );
    top$cnt_dop$total cmat_0$11(
        .d(cmat_0$11$d),
        .q(cmat_0$11$q),
        .clock(cmat_0$11$clock)
    );
    top$cnt_dop$total cmat_0$12(
        .d(cmat_0$12$d),
        .q(cmat_0$12$q),
        .clock(cmat_0$12$clock)
    );
    top$cnt_dop$total cmat_0$13(
        .d(cmat_0$13$d),
        .q(cmat_0$13$q),
        .clock(cmat_0$13$clock)
    );
    top$cnt_dop$total cmat_0$14(
        .d(cmat_0$14$d),
        .q(cmat_0$14$q),
        .clock(cmat_0$14$clock)
    );
    top$cnt_dop$total cmat_0$15(
        .d(cmat_0$15$d),
        .q(cmat_0$15$q),
        .clock(cmat_0$15$clock)
    );
    top$cnt_dop$total cmat_0$16(
        .d(cmat_0$16$d),
        .q(cmat_0$16$q),
        .clock(cmat_0$16$clock)
    );
    top$cnt_dop$total cmat_0$17(
        .d(cmat_0$17$d),
        .q(cmat_0$17$q),
        .clock(cmat_0$17$clock)
    );
    top$cnt_dop$total cmat_0$18(
        .d(cmat_0$18$d),
        .q(cmat_0$18$q),
        .clock(cmat_0$18$clock)
    );
    top$cnt_dop$total cmat_0$19(
        .d(cmat_0$19$d),
        .q(cmat_0$19$q),
        .clock(cmat_0$19$clock)
    );
    top$cnt_dop$total cmat_0$20(
        .d(cmat_0$20$d),
        .q(cmat_0$20$q),
        .clock(cmat_0$20$clock)
    );
    top$cnt_dop$total cmat_0$21(
        .d(cmat_0$21$d),
        .q(cmat_0$21$q),
        .clock(cmat_0$21$clock)
    );
    top$cnt_dop$total cmat_0$22(
        .d(cmat_0$22$d),
        .q(cmat_0$22$q),
        .clock(cmat_0$22$clock)
    );
    top$cnt_dop$total cmat_0$23(
        .d(cmat_0$23$d),
        .q(cmat_0$23$q),
        .clock(cmat_0$23$clock)
    );
    top$cnt_dop$total cmat_1$0(
        .d(cmat_1$0$d),
        .q(cmat_1$0$q),
        .clock(cmat_1$0$clock)
    );
    top$cnt_dop$total cmat_1$1(
        .d(cmat_1$1$d),
        .q(cmat_1$1$q),
        .clock(cmat_1$1$clock)
    );
    top$cnt_dop$total cmat_1$2(
        .d(cmat_1$2$d),
        .q(cmat_1$2$q),
        .clock(cmat_1$2$clock)
    );
    top$cnt_dop$total cmat_1$3(
        .d(cmat_1$3$d),
        .q(cmat_1$3$q),
        .clock(cmat_1$3$clock)
    );
    top$cnt_dop$total cmat_1$4(
        .d(cmat_1$4$d),
        .q(cmat_1$4$q),
        .clock(cmat_1$4$clock)
    );
    top$cnt_dop$total cmat_1$5(
        .d(cmat_1$5$d),
        .q(cmat_1$5$q),
        .clock(cmat_1$5$clock)
    );
    top$cnt_dop$total cmat_1$6(
        .d(cmat_1$6$d),
        .q(cmat_1$6$q),
        .clock(cmat_1$6$clock)
    );
    top$cnt_dop$total cmat_1$7(
        .d(cmat_1$7$d),
        .q(cmat_1$7$q),
        .clock(cmat_1$7$clock)
    );
    top$cnt_dop$total cmat_1$8(
        .d(cmat_1$8$d),
        .q(cmat_1$8$q),
        .clock(cmat_1$8$clock)
    );
    top$cnt_dop$total cmat_1$9(
        .d(cmat_1$9$d),
        .q(cmat_1$9$q),
        .clock(cmat_1$9$clock)
    );
    top$cnt_dop$total cmat_1$10(
        .d(cmat_1$10$d),
        .q(cmat_1$10$q),
        .clock(cmat_1$10$clock)
    );
    top$cnt_dop$total cmat_1$11(
        .d(cmat_1$11$d),
        .q(cmat_1$11$q),
        .clock(cmat_1$11$clock)
    );
    top$cnt_dop$total cmat_1$12(
        .d(cmat_1$12$d),
        .q(cmat_1$12$q),
        .clock(cmat_1$12$clock)
    );
    top$cnt_dop$total cmat_1$13(
        .d(cmat_1$13$d),
        .q(cmat_1$13$q),
        .clock(cmat_1$13$clock)
    );
    top$cnt_dop$total cmat_1$14(
        .d(cmat_1$14$d),
        .q(cmat_1$14$q),
        .clock(cmat_1$14$clock)
    );
    top$cnt_dop$total cmat_1$15(
        .d(cmat_1$15$d),
        .q(cmat_1$15$q),
        .clock(cmat_1$15$clock)
    );
    top$cnt_dop$total cmat_1$16(
        .d(cmat_1$16$d),
        .q(cmat_1$16$q),
        .clock(cmat_1$16$clock)
    );
    top$cnt_dop$total cmat_1$17(
        .d(cmat_1$17$d),
        .q(cmat_1$17$q),
        .clock(cmat_1$17$clock)
    );
    top$cnt_dop$total cmat_1$18(
        .d(cmat_1$18$d),
        .q(cmat_1$18$q),
        .clock(cmat_1$18$clock)
    );
    top$cnt_dop$total cmat_1$19(
        .d(cmat_1$19$d),
        .q(cmat_1$19$q),
        .clock(cmat_1$19$clock)
    );
    top$cnt_dop$total cmat_1$20(
        .d(cmat_1$20$d),
        .q(cmat_1$20$q),
        .clock(cmat_1$20$clock)
    );
    top$cnt_dop$total cmat_1$21(
        .d(cmat_1$21$d),
        .q(cmat_1$21$q),
        .clock(cmat_1$21$clock)
    );
    top$cnt_dop$total cmat_1$22(
        .d(cmat_1$22$d),
        .q(cmat_1$22$q),
        .clock(cmat_1$22$clock)
    );
    top$cnt_dop$total cmat_1$23(
        .d(cmat_1$23$d),
        .q(cmat_1$23$q),
        .clock(cmat_1$23$clock)
    );
    top$cnt_dop$total cmat_2$0(
        .d(cmat_2$0$d),
        .q(cmat_2$0$q),
        .clock(cmat_2$0$clock)
    );
    top$cnt_dop$total cmat_2$1(
        .d(cmat_2$1$d),
        .q(cmat_2$1$q),
        .clock(cmat_2$1$clock)
    );
    top$cnt_dop$total cmat_2$2(
        .d(cmat_2$2$d),
        .q(cmat_2$2$q),
        .clock(cmat_2$2$clock)
    );
    top$cnt_dop$total cmat_2$3(
        .d(cmat_2$3$d),
        .q(cmat_2$3$q),
        .clock(cmat_2$3$clock)
    );
    top$cnt_dop$total cmat_2$4(
        .d(cmat_2$4$d),
        .q(cmat_2$4$q),
        .clock(cmat_2$4$clock)
    );
    top$cnt_dop$total cmat_2$5(
        .d(cmat_2$5$d),
        .q(cmat_2$5$q),
        .clock(cmat_2$5$clock)
    );
    top$cnt_dop$total cmat_2$6(
        .d(cmat_2$6$d),
        .q(cmat_2$6$q),
        .clock(cmat_2$6$clock)
    );
    top$cnt_dop$total cmat_2$7(
        .d(cmat_2$7$d),
        .q(cmat_2$7$q),
        .clock(cmat_2$7$clock)
    );
    top$cnt_dop$total cmat_2$8(
        .d(cmat_2$8$d),
        .q(cmat_2$8$q),
        .clock(cmat_2$8$clock)
    );
    top$cnt_dop$total cmat_2$9(
        .d(cmat_2$9$d),
        .q(cmat_2$9$q),
        .clock(cmat_2$9$clock)
    );
    top$cnt_dop$total cmat_2$10(
        .d(cmat_2$10$d),
        .q(cmat_2$10$q),
        .clock(cmat_2$10$clock)
    );
    top$cnt_dop$total cmat_2$11(
        .d(cmat_2$11$d),
        .q(cmat_2$11$q),
        .clock(cmat_2$11$clock)
    );
    top$cnt_dop$total cmat_2$12(
        .d(cmat_2$12$d),
        .q(cmat_2$12$q),
        .clock(cmat_2$12$clock)
    );
    top$cnt_dop$total cmat_2$13(
        .d(cmat_2$13$d),
        .q(cmat_2$13$q),
        .clock(cmat_2$13$clock)
    );
    top$cnt_dop$total cmat_2$14(
        .d(cmat_2$14$d),
        .q(cmat_2$14$q),
        .clock(cmat_2$14$clock)
    );
    top$cnt_dop$total cmat_2$15(
        .d(cmat_2$15$d),
        .q(cmat_2$15$q),
        .clock(cmat_2$15$clock)
    );
    top$cnt_dop$total cmat_2$16(
        .d(cmat_2$16$d),
        .q(cmat_2$16$q),
        .clock(cmat_2$16$clock)
    );
    top$cnt_dop$total cmat_2$17(
        .d(cmat_2$17$d),
        .q(cmat_2$17$q),
        .clock(cmat_2$17$clock)
    );
    top$cnt_dop$total cmat_2$18(
        .d(cmat_2$18$d),
        .q(cmat_2$18$q),
        .clock(cmat_2$18$clock)
    );
    top$cnt_dop$total cmat_2$19(
        .d(cmat_2$19$d),
        .q(cmat_2$19$q),
        .clock(cmat_2$19$clock)
    );
    top$cnt_dop$total cmat_2$20(
        .d(cmat_2$20$d),
        .q(cmat_2$20$q),
        .clock(cmat_2$20$clock)
    );
    top$cnt_dop$total cmat_2$21(
        .d(cmat_2$21$d),
        .q(cmat_2$21$q),
        .clock(cmat_2$21$clock)
    );
    top$cnt_dop$total cmat_2$22(
        .d(cmat_2$22$d),
        .q(cmat_2$22$q),
        .clock(cmat_2$22$clock)
    );
    top$cnt_dop$total cmat_2$23(
        .d(cmat_2$23$d),
        .q(cmat_2$23$q),
        .clock(cmat_2$23$clock)
    );
    top$cnt_dop$total cvec$0(
        .d(cvec$0$d),
        .q(cvec$0$q),
        .clock(cvec$0$clock)
    );
    top$cnt_dop$total cvec$1(
        .d(cvec$1$d),
        .q(cvec$1$q),
        .clock(cvec$1$clock)
    );
    top$cnt_dop$total cvec$2(
        .d(cvec$2$d),
        .q(cvec$2$q),
        .clock(cvec$2$clock)
    );
    top$cnt_dop$total cvec$3(
        .d(cvec$3$d),
        .q(cvec$3$q),
        .clock(cvec$3$clock)
    );
    top$cnt_dop$total cvec$4(
        .d(cvec$4$d),
        .q(cvec$4$q),
        .clock(cvec$4$clock)
    );
    top$cnt_dop$total cvec$5(
        .d(cvec$5$d),
        .q(cvec$5$q),
        .clock(cvec$5$clock)
    );
    top$cnt_dop$total cvec$6(
        .d(cvec$6$d),
        .q(cvec$6$q),
        .clock(cvec$6$clock)
    );
    top$cnt_dop$total cvec$7(
        .d(cvec$7$d),
        .q(cvec$7$q),
        .clock(cvec$7$clock)
    );
    top$cnt_dop$total cvec$8(
        .d(cvec$8$d),
        .q(cvec$8$q),
        .clock(cvec$8$clock)
    );
    top$cnt_dop$total cvec$9(
        .d(cvec$9$d),
        .q(cvec$9$q),
        .clock(cvec$9$clock)
    );
    top$cnt_dop$total cvec$10(
        .d(cvec$10$d),
        .q(cvec$10$q),
        .clock(cvec$10$clock)
    );
    top$cnt_dop$total cvec$11(
        .d(cvec$11$d),
        .q(cvec$11$q),
        .clock(cvec$11$clock)
    );
    top$cnt_dop$total cvec$12(
        .d(cvec$12$d),
        .q(cvec$12$q),
        .clock(cvec$12$clock)
    );
    top$cnt_dop$total cvec$13(
        .d(cvec$13$d),
        .q(cvec$13$q),
        .clock(cvec$13$clock)
    );
    top$cnt_dop$total cvec$14(
        .d(cvec$14$d),
        .q(cvec$14$q),
        .clock(cvec$14$clock)
    );
    top$cnt_dop$total cvec$15(
        .d(cvec$15$d),
        .q(cvec$15$q),
        .clock(cvec$15$clock)
    );
    top$cnt_dop$total cvec$16(
        .d(cvec$16$d),
        .q(cvec$16$q),
        .clock(cvec$16$clock)
    );
    top$cnt_dop$total cvec$17(
        .d(cvec$17$d),
        .q(cvec$17$q),
        .clock(cvec$17$clock)
    );
    top$cnt_dop$total cvec$18(
        .d(cvec$18$d),
        .q(cvec$18$q),
        .clock(cvec$18$clock)
    );
    top$cnt_dop$total cvec$19(
        .d(cvec$19$d),
        .q(cvec$19$q),
        .clock(cvec$19$clock)
    );
    top$cnt_dop$total cvec$20(
        .d(cvec$20$d),
        .q(cvec$20$q),
        .clock(cvec$20$clock)
    );
    top$cnt_dop$total cvec$21(
        .d(cvec$21$d),
        .q(cvec$21$q),
        .clock(cvec$21$clock)
    );
    top$cnt_dop$total cvec$22(
        .d(cvec$22$d),
        .q(cvec$22$q),
        .clock(cvec$22$clock)
    );
    top$cnt_dop$total cvec$23(
        .d(cvec$23$d),
        .q(cvec$23$q),
        .clock(cvec$23$clock)
    );
    top$d_cntr$ahd_pairs jsel_0$0(
        .d(jsel_0$0$d),
        .q(jsel_0$0$q),
        .clock(jsel_0$0$clock)
    );
    top$d_cntr$ahd_pairs jsel_0$1(
        .d(jsel_0$1$d),
        .q(jsel_0$1$q),
        .clock(jsel_0$1$clock)
    );
    top$d_cntr$ahd_pairs jsel_0$2(
        .d(jsel_0$2$d),
        .q(jsel_0$2$q),
        .clock(jsel_0$2$clock)
    );
    top$d_cntr$ahd_pairs jsel_0$3(
        .d(jsel_0$3$d),
        .q(jsel_0$3$q),
        .clock(jsel_0$3$clock)
    );
    top$d_cntr$ahd_pairs jsel_0$4(
        .d(jsel_0$4$d),
        .q(jsel_0$4$q),
        .clock(jsel_0$4$clock)
    );
    top$d_cntr$ahd_pairs jsel_0$5(
        .d(jsel_0$5$d),
        .q(jsel_0$5$q),
        .clock(jsel_0$5$clock)
    );
    top$d_cntr$ahd_pairs jsel_0$6(
        .d(jsel_0$6$d),
        .q(jsel_0$6$q),
        .clock(jsel_0$6$clock)
    );
    top$d_cntr$ahd_pairs jsel_0$7(
        .d(jsel_0$7$d),
        .q(jsel_0$7$q),
        .clock(jsel_0$7$clock)
    );
    top$d_cntr$ahd_pairs jsel_0$8(
        .d(jsel_0$8$d),
        .q(jsel_0$8$q),
        .clock(jsel_0$8$clock)
    );
    top$d_cntr$ahd_pairs jsel_0$9(
        .d(jsel_0$9$d),
        .q(jsel_0$9$q),
        .clock(jsel_0$9$clock)
    );
    top$d_cntr$ahd_pairs jsel_0$10(
        .d(jsel_0$10$d),
        .q(jsel_0$10$q),
        .clock(jsel_0$10$clock)
    );
    top$d_cntr$ahd_pairs jsel_0$11(
        .d(jsel_0$11$d),
        .q(jsel_0$11$q),
        .clock(jsel_0$11$clock)
    );
    top$d_cntr$ahd_pairs jsel_0$12(
        .d(jsel_0$12$d),
        .q(jsel_0$12$q),
        .clock(jsel_0$12$clock)
    );
    top$d_cntr$ahd_pairs jsel_0$13(
        .d(jsel_0$13$d),
        .q(jsel_0$13$q),
        .clock(jsel_0$13$clock)
    );
    top$d_cntr$ahd_pairs jsel_0$14(
        .d(jsel_0$14$d),
        .q(jsel_0$14$q),
        .clock(jsel_0$14$clock)
    );
    top$d_cntr$ahd_pairs jsel_0$15(
        .d(jsel_0$15$d),
        .q(jsel_0$15$q),
        .clock(jsel_0$15$clock)
    );
    top$d_cntr$ahd_pairs jsel_0$16(
        .d(jsel_0$16$d),
        .q(jsel_0$16$q),
        .clock(jsel_0$16$clock)
    );
    top$d_cntr$ahd_pairs jsel_0$17(
        .d(jsel_0$17$d),
        .q(jsel_0$17$q),
        .clock(jsel_0$17$clock)
    );
    top$d_cntr$ahd_pairs jsel_0$18(
        .d(jsel_0$18$d),
        .q(jsel_0$18$q),
        .clock(jsel_0$18$clock)
    );
    top$d_cntr$ahd_pairs jsel_0$19(
        .d(jsel_0$19$d),
        .q(jsel_0$19$q),
        .clock(jsel_0$19$clock)
    );
    top$d_cntr$ahd_pairs jsel_0$20(
        .d(jsel_0$20$d),
        .q(jsel_0$20$q),
        .clock(jsel_0$20$clock)
    );
    top$d_cntr$ahd_pairs jsel_0$21(
        .d(jsel_0$21$d),
        .q(jsel_0$21$q),
        .clock(jsel_0$21$clock)
    );
    top$d_cntr$ahd_pairs jsel_0$22(
        .d(jsel_0$22$d),
        .q(jsel_0$22$q),
        .clock(jsel_0$22$clock)
    );
    top$d_cntr$ahd_pairs jsel_0$23(
        .d(jsel_0$23$d),
        .q(jsel_0$23$q),
        .clock(jsel_0$23$clock)
    );
    top$d_cntr$ahd_pairs jsel_1$0(
        .d(jsel_1$0$d),
        .q(jsel_1$0$q),
        .clock(jsel_1$0$clock)
    );
    top$d_cntr$ahd_pairs jsel_1$1(
        .d(jsel_1$1$d),
        .q(jsel_1$1$q),
        .clock(jsel_1$1$clock)
    );
    top$d_cntr$ahd_pairs jsel_1$2(
        .d(jsel_1$2$d),
        .q(jsel_1$2$q),
        .clock(jsel_1$2$clock)
    );
    top$d_cntr$ahd_pairs jsel_1$3(
        .d(jsel_1$3$d),
        .q(jsel_1$3$q),
        .clock(jsel_1$3$clock)
    );
    top$d_cntr$ahd_pairs jsel_1$4(
        .d(jsel_1$4$d),
        .q(jsel_1$4$q),
        .clock(jsel_1$4$clock)
    );
    top$d_cntr$ahd_pairs jsel_1$5(
        .d(jsel_1$5$d),
        .q(jsel_1$5$q),
        .clock(jsel_1$5$clock)
    );
    top$d_cntr$ahd_pairs jsel_1$6(
        .d(jsel_1$6$d),
        .q(jsel_1$6$q),
        .clock(jsel_1$6$clock)
    );
    top$d_cntr$ahd_pairs jsel_1$7(
        .d(jsel_1$7$d),
        .q(jsel_1$7$q),
        .clock(jsel_1$7$clock)
    );
    top$d_cntr$ahd_pairs jsel_1$8(
        .d(jsel_1$8$d),
        .q(jsel_1$8$q),
        .clock(jsel_1$8$clock)
    );
    top$d_cntr$ahd_pairs jsel_1$9(
        .d(jsel_1$9$d),
        .q(jsel_1$9$q),
        .clock(jsel_1$9$clock)
    );
    top$d_cntr$ahd_pairs jsel_1$10(
        .d(jsel_1$10$d),
        .q(jsel_1$10$q),
        .clock(jsel_1$10$clock)
    );
    top$d_cntr$ahd_pairs jsel_1$11(
        .d(jsel_1$11$d),
        .q(jsel_1$11$q),
        .clock(jsel_1$11$clock)
    );
    top$d_cntr$ahd_pairs jsel_1$12(
        .d(jsel_1$12$d),
        .q(jsel_1$12$q),
        .clock(jsel_1$12$clock)
    );
    top$d_cntr$ahd_pairs jsel_1$13(
        .d(jsel_1$13$d),
        .q(jsel_1$13$q),
        .clock(jsel_1$13$clock)
    );
    top$d_cntr$ahd_pairs jsel_1$14(
        .d(jsel_1$14$d),
        .q(jsel_1$14$q),
        .clock(jsel_1$14$clock)
    );
    top$d_cntr$ahd_pairs jsel_1$15(
        .d(jsel_1$15$d),
        .q(jsel_1$15$q),
        .clock(jsel_1$15$clock)
    );
    top$d_cntr$ahd_pairs jsel_1$16(
        .d(jsel_1$16$d),
        .q(jsel_1$16$q),
        .clock(jsel_1$16$clock)
    );
    top$d_cntr$ahd_pairs jsel_1$17(
        .d(jsel_1$17$d),
        .q(jsel_1$17$q),
        .clock(jsel_1$17$clock)
    );
    top$d_cntr$ahd_pairs jsel_1$18(
        .d(jsel_1$18$d),
        .q(jsel_1$18$q),
        .clock(jsel_1$18$clock)
    );
    top$d_cntr$ahd_pairs jsel_1$19(
        .d(jsel_1$19$d),
        .q(jsel_1$19$q),
        .clock(jsel_1$19$clock)
    );
    top$d_cntr$ahd_pairs jsel_1$20(
        .d(jsel_1$20$d),
        .q(jsel_1$20$q),
        .clock(jsel_1$20$clock)
    );
    top$d_cntr$ahd_pairs jsel_1$21(
        .d(jsel_1$21$d),
        .q(jsel_1$21$q),
        .clock(jsel_1$21$clock)
    );
    top$d_cntr$ahd_pairs jsel_1$22(
        .d(jsel_1$22$d),
        .q(jsel_1$22$q),
        .clock(jsel_1$22$clock)
    );
    top$d_cntr$ahd_pairs jsel_1$23(
        .d(jsel_1$23$d),
        .q(jsel_1$23$q),
        .clock(jsel_1$23$clock)
    );
    top$d_cntr$ahd_pairs jsel_2$0(
        .d(jsel_2$0$d),
        .q(jsel_2$0$q),
        .clock(jsel_2$0$clock)
    );
    top$d_cntr$ahd_pairs jsel_2$1(
        .d(jsel_2$1$d),
        .q(jsel_2$1$q),
        .clock(jsel_2$1$clock)
    );
    top$d_cntr$ahd_pairs jsel_2$2(
        .d(jsel_2$2$d),
        .q(jsel_2$2$q),
        .clock(jsel_2$2$clock)
    );
    top$d_cntr$ahd_pairs jsel_2$3(
        .d(jsel_2$3$d),
        .q(jsel_2$3$q),
        .clock(jsel_2$3$clock)
    );
    top$d_cntr$ahd_pairs jsel_2$4(
        .d(jsel_2$4$d),
        .q(jsel_2$4$q),
        .clock(jsel_2$4$clock)
    );
    top$d_cntr$ahd_pairs jsel_2$5(
        .d(jsel_2$5$d),
        .q(jsel_2$5$q),
        .clock(jsel_2$5$clock)
    );
    top$d_cntr$ahd_pairs jsel_2$6(
        .d(jsel_2$6$d),
        .q(jsel_2$6$q),
        .clock(jsel_2$6$clock)
    );
    top$d_cntr$ahd_pairs jsel_2$7(
        .d(jsel_2$7$d),
        .q(jsel_2$7$q),
        .clock(jsel_2$7$clock)
    );
    top$d_cntr$ahd_pairs jsel_2$8(
        .d(jsel_2$8$d),
        .q(jsel_2$8$q),
        .clock(jsel_2$8$clock)
    );
    top$d_cntr$ahd_pairs jsel_2$9(
        .d(jsel_2$9$d),
        .q(jsel_2$9$q),
        .clock(jsel_2$9$clock)
    );
    top$d_cntr$ahd_pairs jsel_2$10(
        .d(jsel_2$10$d),
        .q(jsel_2$10$q),
        .clock(jsel_2$10$clock)
    );
    top$d_cntr$ahd_pairs jsel_2$11(
        .d(jsel_2$11$d),
        .q(jsel_2$11$q),
        .clock(jsel_2$11$clock)
    );
    top$d_cntr$ahd_pairs jsel_2$12(
        .d(jsel_2$12$d),
        .q(jsel_2$12$q),
        .clock(jsel_2$12$clock)
    );
    top$d_cntr$ahd_pairs jsel_2$13(
        .d(jsel_2$13$d),
        .q(jsel_2$13$q),
        .clock(jsel_2$13$clock)
    );
    top$d_cntr$ahd_pairs jsel_2$14(
        .d(jsel_2$14$d),
        .q(jsel_2$14$q),
        .clock(jsel_2$14$clock)
    );
    top$d_cntr$ahd_pairs jsel_2$15(
        .d(jsel_2$15$d),
        .q(jsel_2$15$q),
        .clock(jsel_2$15$clock)
    );
    top$d_cntr$ahd_pairs jsel_2$16(
        .d(jsel_2$16$d),
        .q(jsel_2$16$q),
        .clock(jsel_2$16$clock)
    );
    top$d_cntr$ahd_pairs jsel_2$17(
        .d(jsel_2$17$d),
        .q(jsel_2$17$q),
        .clock(jsel_2$17$clock)
    );
    top$d_cntr$ahd_pairs jsel_2$18(
        .d(jsel_2$18$d),
        .q(jsel_2$18$q),
        .clock(jsel_2$18$clock)
    );
    top$d_cntr$ahd_pairs jsel_2$19(
        .d(jsel_2$19$d),
        .q(jsel_2$19$q),
        .clock(jsel_2$19$clock)
    );
    top$d_cntr$ahd_pairs jsel_2$20(
        .d(jsel_2$20$d),
        .q(jsel_2$20$q),
        .clock(jsel_2$20$clock)
    );
    top$d_cntr$ahd_pairs jsel_2$21(
        .d(jsel_2$21$d),
        .q(jsel_2$21$q),
        .clock(jsel_2$21$clock)
    );
    top$d_cntr$ahd_pairs jsel_2$22(
        .d(jsel_2$22$d),
        .q(jsel_2$22$q),
        .clock(jsel_2$22$clock)
    );
    top$d_cntr$ahd_pairs jsel_2$23(
        .d(jsel_2$23$d),
        .q(jsel_2$23$q),
        .clock(jsel_2$23$clock)
    );
    top$cnt_dop$pending rnd$0(
        .d(rnd$0$d),
        .q(rnd$0$q),
        .clock(rnd$0$clock)
    );
    top$cnt_dop$pending rnd$1(
        .d(rnd$1$d),
        .q(rnd$1$q),
        .clock(rnd$1$clock)
    );
    top$cnt_dop$pending rnd$2(
        .d(rnd$2$d),
        .q(rnd$2$q),
        .clock(rnd$2$clock)
    );
    top$cnt_dop$pending rnd$3(
        .d(rnd$3$d),
        .q(rnd$3$q),
        .clock(rnd$3$clock)
    );
    top$cnt_dop$pending rnd$4(
        .d(rnd$4$d),
        .q(rnd$4$q),
        .clock(rnd$4$clock)
    );
    top$cnt_dop$pending rnd$5(
        .d(rnd$5$d),
        .q(rnd$5$q),
        .clock(rnd$5$clock)
    );
    top$cnt_dop$pending rnd$6(
        .d(rnd$6$d),
        .q(rnd$6$q),
        .clock(rnd$6$clock)
    );
    top$cnt_dop$pending rnd$7(
        .d(rnd$7$d),
        .q(rnd$7$q),
        .clock(rnd$7$clock)
    );
    top$cnt_dop$pending rnd$8(
        .d(rnd$8$d),
        .q(rnd$8$q),
        .clock(rnd$8$clock)
    );
    top$cnt_dop$pending rnd$9(
        .d(rnd$9$d),
        .q(rnd$9$q),
        .clock(rnd$9$clock)
    );
    top$cnt_dop$pending rnd$10(
        .d(rnd$10$d),
        .q(rnd$10$q),
        .clock(rnd$10$clock)
    );
    top$cnt_dop$pending rnd$11(
        .d(rnd$11$d),
        .q(rnd$11$q),
        .clock(rnd$11$clock)
    );
    top$cnt_dop$pending rnd$12(
        .d(rnd$12$d),
        .q(rnd$12$q),
        .clock(rnd$12$clock)
    );
    top$cnt_dop$pending rnd$13(
        .d(rnd$13$d),
        .q(rnd$13$q),
        .clock(rnd$13$clock)
    );
    top$cnt_dop$pending rnd$14(
        .d(rnd$14$d),
        .q(rnd$14$q),
        .clock(rnd$14$clock)
    );
    top$cnt_dop$pending rnd$15(
        .d(rnd$15$d),
        .q(rnd$15$q),
        .clock(rnd$15$clock)
    );
    top$cnt_dop$pending rnd$16(
        .d(rnd$16$d),
        .q(rnd$16$q),
        .clock(rnd$16$clock)
    );
    top$cnt_dop$pending rnd$17(
        .d(rnd$17$d),
        .q(rnd$17$q),
        .clock(rnd$17$clock)
    );
    top$cnt_dop$pending rnd$18(
        .d(rnd$18$d),
        .q(rnd$18$q),
        .clock(rnd$18$clock)
    );
    top$cnt_dop$pending rnd$19(
        .d(rnd$19$d),
        .q(rnd$19$q),
        .clock(rnd$19$clock)
    );
    top$cnt_dop$pending rnd$20(
        .d(rnd$20$d),
        .q(rnd$20$q),
        .clock(rnd$20$clock)
    );
    top$cnt_dop$pending rnd$21(
        .d(rnd$21$d),
        .q(rnd$21$q),
        .clock(rnd$21$clock)
    );
    top$cnt_dop$pending rnd$22(
        .d(rnd$22$d),
        .q(rnd$22$q),
        .clock(rnd$22$clock)
    );
    top$cnt_dop$pending rnd$23(
        .d(rnd$23$d),
        .q(rnd$23$q),
        .clock(rnd$23$clock)
    );
    
    // Update code
    always @(*) begin
        c_lane = load_addr[(32'h3)+:(5)];
        c_field = load_addr[(32'h0)+:(3)];
        cmat_0$0$clock = clock;
        cmat_1$0$clock = clock;
        cmat_2$0$clock = clock;
        cvec$0$clock = clock;
        jsel_0$0$clock = clock;
        jsel_1$0$clock = clock;
        jsel_2$0$clock = clock;
        rnd$0$clock = clock;
        cmat_0$0$d = cmat_0$0$q;
        cmat_1$0$d = cmat_1$0$q;
        cmat_2$0$d = cmat_2$0$q;
        cvec$0$d = cvec$0$q;
        jsel_0$0$d = jsel_0$0$q;
        jsel_1$0$d = jsel_1$0$q;
        jsel_2$0$d = jsel_2$0$q;
        rnd$0$d = rnd$0$q;
        if (load_en & (c_lane == idx$0)) begin
            if (c_field == 32'h0) begin
                cmat_0$0$d = load_data;
            end
            if (c_field == 32'h1) begin
                cmat_1$0$d = load_data;
            end
            if (c_field == 32'h2) begin
                cmat_2$0$d = load_data;
            end
            if (c_field == 32'h3) begin
                cvec$0$d = load_data;
            end
            if (c_field == 32'h4) begin
                jsel_0$0$d = load_data[(32'h0)+:(5)];
                jsel_1$0$d = load_data[(32'h5)+:(5)];
                jsel_2$0$d = load_data[(32'ha)+:(5)];
                rnd$0$d = load_data[32'hf];
            end
        end
        c0$0 = cmat_0$0$q;
        c1$0 = cmat_1$0$q;
        c2$0 = cmat_2$0$q;
        c$0 = cvec$0$q;
        j0$0 = jsel_0$0$q;
        j1$0 = jsel_1$0$q;
        j2$0 = jsel_2$0$q;
        round_up$0 = rnd$0$q;
        cmat_0$1$clock = clock;
        cmat_1$1$clock = clock;
        cmat_2$1$clock = clock;
        cvec$1$clock = clock;
        jsel_0$1$clock = clock;
        jsel_1$1$clock = clock;
        jsel_2$1$clock = clock;
        rnd$1$clock = clock;
        cmat_0$1$d = cmat_0$1$q;
        cmat_1$1$d = cmat_1$1$q;
        cmat_2$1$d = cmat_2$1$q;
        cvec$1$d = cvec$1$q;
        jsel_0$1$d = jsel_0$1$q;
        jsel_1$1$d = jsel_1$1$q;
        jsel_2$1$d = jsel_2$1$q;
        rnd$1$d = rnd$1$q;
        if (load_en & (c_lane == idx$1)) begin
            if (c_field == 32'h0) begin
                cmat_0$1$d = load_data;
            end
            if (c_field == 32'h1) begin
                cmat_1$1$d = load_data;
            end
            if (c_field == 32'h2) begin
                cmat_2$1$d = load_data;
            end
            if (c_field == 32'h3) begin
                cvec$1$d = load_data;
            end
            if (c_field == 32'h4) begin
                jsel_0$1$d = load_data[(32'h0)+:(5)];
                jsel_1$1$d = load_data[(32'h5)+:(5)];
                jsel_2$1$d = load_data[(32'ha)+:(5)];
                rnd$1$d = load_data[32'hf];
            end
        end
        c0$1 = cmat_0$1$q;
        c1$1 = cmat_1$1$q;
        c2$1 = cmat_2$1$q;
        c$1 = cvec$1$q;
        j0$1 = jsel_0$1$q;
        j1$1 = jsel_1$1$q;
        j2$1 = jsel_2$1$q;
        round_up$1 = rnd$1$q;
        cmat_0$2$clock = clock;
        cmat_1$2$clock = clock;
        cmat_2$2$clock = clock;
        cvec$2$clock = clock;
        jsel_0$2$clock = clock;
        jsel_1$2$clock = clock;
        jsel_2$2$clock = clock;
        rnd$2$clock = clock;
        cmat_0$2$d = cmat_0$2$q;
        cmat_1$2$d = cmat_1$2$q;
        cmat_2$2$d = cmat_2$2$q;
        cvec$2$d = cvec$2$q;
        jsel_0$2$d = jsel_0$2$q;
        jsel_1$2$d = jsel_1$2$q;
        jsel_2$2$d = jsel_2$2$q;
        rnd$2$d = rnd$2$q;
        if (load_en & (c_lane == idx$2)) begin
            if (c_field == 32'h0) begin
                cmat_0$2$d = load_data;
            end
            if (c_field == 32'h1) begin
                cmat_1$2$d = load_data;
            end
            if (c_field == 32'h2) begin
                cmat_2$2$d = load_data;
            end
            if (c_field == 32'h3) begin
                cvec$2$d = load_data;
            end
            if (c_field == 32'h4) begin
                jsel_0$2$d = load_data[(32'h0)+:(5)];
                jsel_1$2$d = load_data[(32'h5)+:(5)];
                jsel_2$2$d = load_data[(32'ha)+:(5)];
                rnd$2$d = load_data[32'hf];
            end
        end
        c0$2 = cmat_0$2$q;
        c1$2 = cmat_1$2$q;
        c2$2 = cmat_2$2$q;
        c$2 = cvec$2$q;
        j0$2 = jsel_0$2$q;
        j1$2 = jsel_1$2$q;
        j2$2 = jsel_2$2$q;
        round_up$2 = rnd$2$q;
        cmat_0$3$clock = clock;
        cmat_1$3$clock = clock;
        cmat_2$3$clock = clock;
        cvec$3$clock = clock;
        jsel_0$3$clock = clock;
        jsel_1$3$clock = clock;
        jsel_2$3$clock = clock;
        rnd$3$clock = clock;
        cmat_0$3$d = cmat_0$3$q;
        cmat_1$3$d = cmat_1$3$q;
        cmat_2$3$d = cmat_2$3$q;
        cvec$3$d = cvec$3$q;
        jsel_0$3$d = jsel_0$3$q;
        jsel_1$3$d = jsel_1$3$q;
        jsel_2$3$d = jsel_2$3$q;
        rnd$3$d = rnd$3$q;
        if (load_en & (c_lane == idx$3)) begin
            if (c_field == 32'h0) begin
                cmat_0$3$d = load_data;
            end
            if (c_field == 32'h1) begin
                cmat_1$3$d = load_data;
            end
            if (c_field == 32'h2) begin
                cmat_2$3$d = load_data;
            end
            if (c_field == 32'h3) begin
                cvec$3$d = load_data;
            end
            if (c_field == 32'h4) begin
                jsel_0$3$d = load_data[(32'h0)+:(5)];
                jsel_1$3$d = load_data[(32'h5)+:(5)];
                jsel_2$3$d = load_data[(32'ha)+:(5)];
                rnd$3$d = load_data[32'hf];
            end
        end
        c0$3 = cmat_0$3$q;
        c1$3 = cmat_1$3$q;
        c2$3 = cmat_2$3$q;
        c$3 = cvec$3$q;
        j0$3 = jsel_0$3$q;
        j1$3 = jsel_1$3$q;
        j2$3 = jsel_2$3$q;
        round_up$3 = rnd$3$q;
        cmat_0$4$clock = clock;
        cmat_1$4$clock = clock;
        cmat_2$4$clock = clock;
        cvec$4$clock = clock;
        jsel_0$4$clock = clock;
        jsel_1$4$clock = clock;
        jsel_2$4$clock = clock;
        rnd$4$clock = clock;
        cmat_0$4$d = cmat_0$4$q;
        cmat_1$4$d = cmat_1$4$q;
        cmat_2$4$d = cmat_2$4$q;
        cvec$4$d = cvec$4$q;
        jsel_0$4$d = jsel_0$4$q;
        jsel_1$4$d = jsel_1$4$q;
        jsel_2$4$d = jsel_2$4$q;
        rnd$4$d = rnd$4$q;
        if (load_en & (c_lane == idx$4)) begin
            if (c_field == 32'h0) begin
                cmat_0$4$d = load_data;
            end
            if (c_field == 32'h1) begin
                cmat_1$4$d = load_data;
            end
            if (c_field == 32'h2) begin
                cmat_2$4$d = load_data;
            end
            if (c_field == 32'h3) begin
                cvec$4$d = load_data;
            end
            if (c_field == 32'h4) begin
                jsel_0$4$d = load_data[(32'h0)+:(5)];
                jsel_1$4$d = load_data[(32'h5)+:(5)];
                jsel_2$4$d = load_data[(32'ha)+:(5)];
                rnd$4$d = load_data[32'hf];
            end
        end
        c0$4 = cmat_0$4$q;
        c1$4 = cmat_1$4$q;
        c2$4 = cmat_2$4$q;
        c$4 = cvec$4$q;
        j0$4 = jsel_0$4$q;
        j1$4 = jsel_1$4$q;
        j2$4 = jsel_2$4$q;
        round_up$4 = rnd$4$q;
        cmat_0$5$clock = clock;
        cmat_1$5$clock = clock;
        cmat_2$5$clock = clock;
        cvec$5$clock = clock;
        jsel_0$5$clock = clock;
        jsel_1$5$clock = clock;
        jsel_2$5$clock = clock;
        rnd$5$clock = clock;
        cmat_0$5$d = cmat_0$5$q;
        cmat_1$5$d = cmat_1$5$q;
        cmat_2$5$d = cmat_2$5$q;
        cvec$5$d = cvec$5$q;
        jsel_0$5$d = jsel_0$5$q;
        jsel_1$5$d = jsel_1$5$q;
        jsel_2$5$d = jsel_2$5$q;
        rnd$5$d = rnd$5$q;
        if (load_en & (c_lane == idx$5)) begin
            if (c_field == 32'h0) begin
                cmat_0$5$d = load_data;
            end
            if (c_field == 32'h1) begin
                cmat_1$5$d = load_data;
            end
            if (c_field == 32'h2) begin
                cmat_2$5$d = load_data;
            end
            if (c_field == 32'h3) begin
                cvec$5$d = load_data;
            end
            if (c_field == 32'h4) begin
                jsel_0$5$d = load_data[(32'h0)+:(5)];
                jsel_1$5$d = load_data[(32'h5)+:(5)];
                jsel_2$5$d = load_data[(32'ha)+:(5)];
                rnd$5$d = load_data[32'hf];
            end
        end
        c0$5 = cmat_0$5$q;
        c1$5 = cmat_1$5$q;
        c2$5 = cmat_2$5$q;
        c$5 = cvec$5$q;
        j0$5 = jsel_0$5$q;
        j1$5 = jsel_1$5$q;
        j2$5 = jsel_2$5$q;
        round_up$5 = rnd$5$q;
        cmat_0$6$clock = clock;
        cmat_1$6$clock = clock;
        cmat_2$6$clock = clock;
        cvec$6$clock = clock;
        jsel_0$6$clock = clock;
        jsel_1$6$clock = clock;
        jsel_2$6$clock = clock;
        rnd$6$clock = clock;
        cmat_0$6$d = cmat_0$6$q;
        cmat_1$6$d = cmat_1$6$q;
        cmat_2$6$d = cmat_2$6$q;
        cvec$6$d = cvec$6$q;
        jsel_0$6$d = jsel_0$6$q;
        jsel_1$6$d = jsel_1$6$q;
        jsel_2$6$d = jsel_2$6$q;
        rnd$6$d = rnd$6$q;
        if (load_en & (c_lane == idx$6)) begin
            if (c_field == 32'h0) begin
                cmat_0$6$d = load_data;
            end
            if (c_field == 32'h1) begin
                cmat_1$6$d = load_data;
            end
            if (c_field == 32'h2) begin
                cmat_2$6$d = load_data;
            end
            if (c_field == 32'h3) begin
                cvec$6$d = load_data;
            end
            if (c_field == 32'h4) begin
                jsel_0$6$d = load_data[(32'h0)+:(5)];
                jsel_1$6$d = load_data[(32'h5)+:(5)];
                jsel_2$6$d = load_data[(32'ha)+:(5)];
                rnd$6$d = load_data[32'hf];
            end
        end
        c0$6 = cmat_0$6$q;
        c1$6 = cmat_1$6$q;
        c2$6 = cmat_2$6$q;
        c$6 = cvec$6$q;
        j0$6 = jsel_0$6$q;
        j1$6 = jsel_1$6$q;
        j2$6 = jsel_2$6$q;
        round_up$6 = rnd$6$q;
        cmat_0$7$clock = clock;
        cmat_1$7$clock = clock;
        cmat_2$7$clock = clock;
        cvec$7$clock = clock;
        jsel_0$7$clock = clock;
        jsel_1$7$clock = clock;
        jsel_2$7$clock = clock;
        rnd$7$clock = clock;
        cmat_0$7$d = cmat_0$7$q;
        cmat_1$7$d = cmat_1$7$q;
        cmat_2$7$d = cmat_2$7$q;
        cvec$7$d = cvec$7$q;
        jsel_0$7$d = jsel_0$7$q;
        jsel_1$7$d = jsel_1$7$q;
        jsel_2$7$d = jsel_2$7$q;
        rnd$7$d = rnd$7$q;
        if (load_en & (c_lane == idx$7)) begin
            if (c_field == 32'h0) begin
                cmat_0$7$d = load_data;
            end
            if (c_field == 32'h1) begin
                cmat_1$7$d = load_data;
            end
            if (c_field == 32'h2) begin
                cmat_2$7$d = load_data;
            end
            if (c_field == 32'h3) begin
                cvec$7$d = load_data;
            end
            if (c_field == 32'h4) begin
                jsel_0$7$d = load_data[(32'h0)+:(5)];
                jsel_1$7$d = load_data[(32'h5)+:(5)];
                jsel_2$7$d = load_data[(32'ha)+:(5)];
                rnd$7$d = load_data[32'hf];
            end
        end
        c0$7 = cmat_0$7$q;
        c1$7 = cmat_1$7$q;
        c2$7 = cmat_2$7$q;
        c$7 = cvec$7$q;
        j0$7 = jsel_0$7$q;
        j1$7 = jsel_1$7$q;
        j2$7 = jsel_2$7$q;
        round_up$7 = rnd$7$q;
        cmat_0$8$clock = clock;
        cmat_1$8$clock = clock;
        cmat_2$8$clock = clock;
        cvec$8$clock = clock;
        jsel_0$8$clock = clock;
        jsel_1$8$clock = clock;
        jsel_2$8$clock = clock;
        rnd$8$clock = clock;
        cmat_0$8$d = cmat_0$8$q;
        cmat_1$8$d = cmat_1$8$q;
        cmat_2$8$d = cmat_2$8$q;
        cvec$8$d = cvec$8$q;
        jsel_0$8$d = jsel_0$8$q;
        jsel_1$8$d = jsel_1$8$q;
        jsel_2$8$d = jsel_2$8$q;
        rnd$8$d = rnd$8$q;
        if (load_en & (c_lane == idx$8)) begin
            if (c_field == 32'h0) begin
                cmat_0$8$d = load_data;
            end
            if (c_field == 32'h1) begin
                cmat_1$8$d = load_data;
            end
            if (c_field == 32'h2) begin
                cmat_2$8$d = load_data;
            end
            if (c_field == 32'h3) begin
                cvec$8$d = load_data;
            end
            if (c_field == 32'h4) begin
                jsel_0$8$d = load_data[(32'h0)+:(5)];
                jsel_1$8$d = load_data[(32'h5)+:(5)];
                jsel_2$8$d = load_data[(32'ha)+:(5)];
                rnd$8$d = load_data[32'hf];
            end
        end
        c0$8 = cmat_0$8$q;
        c1$8 = cmat_1$8$q;
        c2$8 = cmat_2$8$q;
        c$8 = cvec$8$q;
        j0$8 = jsel_0$8$q;
        j1$8 = jsel_1$8$q;
        j2$8 = jsel_2$8$q;
        round_up$8 = rnd$8$q;
        cmat_0$9$clock = clock;
        cmat_1$9$clock = clock;
        cmat_2$9$clock = clock;
        cvec$9$clock = clock;
        jsel_0$9$clock = clock;
        jsel_1$9$clock = clock;
        jsel_2$9$clock = clock;
        rnd$9$clock = clock;
        cmat_0$9$d = cmat_0$9$q;
        cmat_1$9$d = cmat_1$9$q;
        cmat_2$9$d = cmat_2$9$q;
        cvec$9$d = cvec$9$q;
        jsel_0$9$d = jsel_0$9$q;
        jsel_1$9$d = jsel_1$9$q;
        jsel_2$9$d = jsel_2$9$q;
        rnd$9$d = rnd$9$q;
        if (load_en & (c_lane == idx$9)) begin
            if (c_field == 32'h0) begin
                cmat_0$9$d = load_data;
            end
            if (c_field == 32'h1) begin
                cmat_1$9$d = load_data;
            end
            if (c_field == 32'h2) begin
                cmat_2$9$d = load_data;
            end
            if (c_field == 32'h3) begin
                cvec$9$d = load_data;
            end
            if (c_field == 32'h4) begin
                jsel_0$9$d = load_data[(32'h0)+:(5)];
                jsel_1$9$d = load_data[(32'h5)+:(5)];
                jsel_2$9$d = load_data[(32'ha)+:(5)];
                rnd$9$d = load_data[32'hf];
            end
        end
        c0$9 = cmat_0$9$q;
        c1$9 = cmat_1$9$q;
        c2$9 = cmat_2$9$q;
        c$9 = cvec$9$q;
        j0$9 = jsel_0$9$q;
        j1$9 = jsel_1$9$q;
        j2$9 = jsel_2$9$q;
        round_up$9 = rnd$9$q;
        cmat_0$10$clock = clock;
        cmat_1$10$clock = clock;
        cmat_2$10$clock = clock;
        cvec$10$clock = clock;
        jsel_0$10$clock = clock;
        jsel_1$10$clock = clock;
        jsel_2$10$clock = clock;
        rnd$10$clock = clock;
        cmat_0$10$d = cmat_0$10$q;
        cmat_1$10$d = cmat_1$10$q;
        cmat_2$10$d = cmat_2$10$q;
        cvec$10$d = cvec$10$q;
        jsel_0$10$d = jsel_0$10$q;
        jsel_1$10$d = jsel_1$10$q;
        jsel_2$10$d = jsel_2$10$q;
        rnd$10$d = rnd$10$q;
        if (load_en & (c_lane == idx$10)) begin
            if (c_field == 32'h0) begin
                cmat_0$10$d = load_data;
            end
            if (c_field == 32'h1) begin
                cmat_1$10$d = load_data;
            end
            if (c_field == 32'h2) begin
                cmat_2$10$d = load_data;
            end
            if (c_field == 32'h3) begin
                cvec$10$d = load_data;
            end
            if (c_field == 32'h4) begin
                jsel_0$10$d = load_data[(32'h0)+:(5)];
                jsel_1$10$d = load_data[(32'h5)+:(5)];
                jsel_2$10$d = load_data[(32'ha)+:(5)];
                rnd$10$d = load_data[32'hf];
            end
        end
        c0$10 = cmat_0$10$q;
        c1$10 = cmat_1$10$q;
        c2$10 = cmat_2$10$q;
        c$10 = cvec$10$q;
        j0$10 = jsel_0$10$q;
        j1$10 = jsel_1$10$q;
        j2$10 = jsel_2$10$q;
        round_up$10 = rnd$10$q;
        cmat_0$11$clock = clock;
        cmat_1$11$clock = clock;
        cmat_2$11$clock = clock;
        cvec$11$clock = clock;
        jsel_0$11$clock = clock;
        jsel_1$11$clock = clock;
        jsel_2$11$clock = clock;
        rnd$11$clock = clock;
        cmat_0$11$d = cmat_0$11$q;
        cmat_1$11$d = cmat_1$11$q;
        cmat_2$11$d = cmat_2$11$q;
        cvec$11$d = cvec$11$q;
        jsel_0$11$d = jsel_0$11$q;
        jsel_1$11$d = jsel_1$11$q;
        jsel_2$11$d = jsel_2$11$q;
        rnd$11$d = rnd$11$q;
        if (load_en & (c_lane == idx$11)) begin
            if (c_field == 32'h0) begin
                cmat_0$11$d = load_data;
            end
            if (c_field == 32'h1) begin
                cmat_1$11$d = load_data;
            end
            if (c_field == 32'h2) begin
                cmat_2$11$d = load_data;
            end
            if (c_field == 32'h3) begin
                cvec$11$d = load_data;
            end
            if (c_field == 32'h4) begin
                jsel_0$11$d = load_data[(32'h0)+:(5)];
                jsel_1$11$d = load_data[(32'h5)+:(5)];
                jsel_2$11$d = load_data[(32'ha)+:(5)];
                rnd$11$d = load_data[32'hf];
            end
        end
        c0$11 = cmat_0$11$q;
        c1$11 = cmat_1$11$q;
        c2$11 = cmat_2$11$q;
        c$11 = cvec$11$q;
        j0$11 = jsel_0$11$q;
        j1$11 = jsel_1$11$q;
        j2$11 = jsel_2$11$q;
        round_up$11 = rnd$11$q;
        cmat_0$12$clock = clock;
        cmat_1$12$clock = clock;
        cmat_2$12$clock = clock;
        cvec$12$clock = clock;
        jsel_0$12$clock = clock;
        jsel_1$12$clock = clock;
        jsel_2$12$clock = clock;
        rnd$12$clock = clock;
        cmat_0$12$d = cmat_0$12$q;
        cmat_1$12$d = cmat_1$12$q;
        cmat_2$12$d = cmat_2$12$q;
        cvec$12$d = cvec$12$q;
        jsel_0$12$d = jsel_0$12$q;
        jsel_1$12$d = jsel_1$12$q;
        jsel_2$12$d = jsel_2$12$q;
        rnd$12$d = rnd$12$q;
        if (load_en & (c_lane == idx$12)) begin
            if (c_field == 32'h0) begin
                cmat_0$12$d = load_data;
            end
            if (c_field == 32'h1) begin
                cmat_1$12$d = load_data;
            end
            if (c_field == 32'h2) begin
                cmat_2$12$d = load_data;
            end
            if (c_field == 32'h3) begin
                cvec$12$d = load_data;
            end
            if (c_field == 32'h4) begin
                jsel_0$12$d = load_data[(32'h0)+:(5)];
                jsel_1$12$d = load_data[(32'h5)+:(5)];
                jsel_2$12$d = load_data[(32'ha)+:(5)];
                rnd$12$d = load_data[32'hf];
            end
        end
        c0$12 = cmat_0$12$q;
        c1$12 = cmat_1$12$q;
        c2$12 = cmat_2$12$q;
        c$12 = cvec$12$q;
        j0$12 = jsel_0$12$q;
        j1$12 = jsel_1$12$q;
        j2$12 = jsel_2$12$q;
        round_up$12 = rnd$12$q;
        cmat_0$13$clock = clock;
        cmat_1$13$clock = clock;
        cmat_2$13$clock = clock;
        cvec$13$clock = clock;
        jsel_0$13$clock = clock;
        jsel_1$13$clock = clock;
        jsel_2$13$clock = clock;
        rnd$13$clock = clock;
        cmat_0$13$d = cmat_0$13$q;
        cmat_1$13$d = cmat_1$13$q;
        cmat_2$13$d = cmat_2$13$q;
        cvec$13$d = cvec$13$q;
        jsel_0$13$d = jsel_0$13$q;
        jsel_1$13$d = jsel_1$13$q;
        jsel_2$13$d = jsel_2$13$q;
        rnd$13$d = rnd$13$q;
        if (load_en & (c_lane == idx$13)) begin
            if (c_field == 32'h0) begin
                cmat_0$13$d = load_data;
            end
            if (c_field == 32'h1) begin
                cmat_1$13$d = load_data;
            end
            if (c_field == 32'h2) begin
                cmat_2$13$d = load_data;
            end
            if (c_field == 32'h3) begin
                cvec$13$d = load_data;
            end
            if (c_field == 32'h4) begin
                jsel_0$13$d = load_data[(32'h0)+:(5)];
                jsel_1$13$d = load_data[(32'h5)+:(5)];
                jsel_2$13$d = load_data[(32'ha)+:(5)];
                rnd$13$d = load_data[32'hf];
            end
        end
        c0$13 = cmat_0$13$q;
        c1$13 = cmat_1$13$q;
        c2$13 = cmat_2$13$q;
        c$13 = cvec$13$q;
        j0$13 = jsel_0$13$q;
        j1$13 = jsel_1$13$q;
        j2$13 = jsel_2$13$q;
        round_up$13 = rnd$13$q;
        cmat_0$14$clock = clock;
        cmat_1$14$clock = clock;
        cmat_2$14$clock = clock;
        cvec$14$clock = clock;
        jsel_0$14$clock = clock;
        jsel_1$14$clock = clock;
        jsel_2$14$clock = clock;
        rnd$14$clock = clock;
        cmat_0$14$d = cmat_0$14$q;
        cmat_1$14$d = cmat_1$14$q;
        cmat_2$14$d = cmat_2$14$q;
        cvec$14$d = cvec$14$q;
        jsel_0$14$d = jsel_0$14$q;
        jsel_1$14$d = jsel_1$14$q;
        jsel_2$14$d = jsel_2$14$q;
        rnd$14$d = rnd$14$q;
        if (load_en & (c_lane == idx$14)) begin
            if (c_field == 32'h0) begin
                cmat_0$14$d = load_data;
            end
            if (c_field == 32'h1) begin
                cmat_1$14$d = load_data;
            end
            if (c_field == 32'h2) begin
                cmat_2$14$d = load_data;
            end
            if (c_field == 32'h3) begin
                cvec$14$d = load_data;
            end
            if (c_field == 32'h4) begin
                jsel_0$14$d = load_data[(32'h0)+:(5)];
                jsel_1$14$d = load_data[(32'h5)+:(5)];
                jsel_2$14$d = load_data[(32'ha)+:(5)];
                rnd$14$d = load_data[32'hf];
            end
        end
        c0$14 = cmat_0$14$q;
        c1$14 = cmat_1$14$q;
        c2$14 = cmat_2$14$q;
        c$14 = cvec$14$q;
        j0$14 = jsel_0$14$q;
        j1$14 = jsel_1$14$q;
        j2$14 = jsel_2$14$q;
        round_up$14 = rnd$14$q;
        cmat_0$15$clock = clock;
        cmat_1$15$clock = clock;
        cmat_2$15$clock = clock;
        cvec$15$clock = clock;
        jsel_0$15$clock = clock;
        jsel_1$15$clock = clock;
        jsel_2$15$clock = clock;
        rnd$15$clock = clock;
        cmat_0$15$d = cmat_0$15$q;
        cmat_1$15$d = cmat_1$15$q;
        cmat_2$15$d = cmat_2$15$q;
        cvec$15$d = cvec$15$q;
        jsel_0$15$d = jsel_0$15$q;
        jsel_1$15$d = jsel_1$15$q;
        jsel_2$15$d = jsel_2$15$q;
        rnd$15$d = rnd$15$q;
        if (load_en & (c_lane == idx$15)) begin
            if (c_field == 32'h0) begin
                cmat_0$15$d = load_data;
            end
            if (c_field == 32'h1) begin
                cmat_1$15$d = load_data;
            end
            if (c_field == 32'h2) begin
                cmat_2$15$d = load_data;
            end
            if (c_field == 32'h3) begin
                cvec$15$d = load_data;
            end
            if (c_field == 32'h4) begin
                jsel_0$15$d = load_data[(32'h0)+:(5)];
                jsel_1$15$d = load_data[(32'h5)+:(5)];
                jsel_2$15$d = load_data[(32'ha)+:(5)];
                rnd$15$d = load_data[32'hf];
            end
        end
        c0$15 = cmat_0$15$q;
        c1$15 = cmat_1$15$q;
        c2$15 = cmat_2$15$q;
        c$15 = cvec$15$q;
        j0$15 = jsel_0$15$q;
        j1$15 = jsel_1$15$q;
        j2$15 = jsel_2$15$q;
        round_up$15 = rnd$15$q;
        cmat_0$16$clock = clock;
        cmat_1$16$clock = clock;
        cmat_2$16$clock = clock;
        cvec$16$clock = clock;
        jsel_0$16$clock = clock;
        jsel_1$16$clock = clock;
        jsel_2$16$clock = clock;
        rnd$16$clock = clock;
        cmat_0$16$d = cmat_0$16$q;
        cmat_1$16$d = cmat_1$16$q;
        cmat_2$16$d = cmat_2$16$q;
        cvec$16$d = cvec$16$q;
        jsel_0$16$d = jsel_0$16$q;
        jsel_1$16$d = jsel_1$16$q;
        jsel_2$16$d = jsel_2$16$q;
        rnd$16$d = rnd$16$q;
        if (load_en & (c_lane == idx$16)) begin
            if (c_field == 32'h0) begin
                cmat_0$16$d = load_data;
            end
            if (c_field == 32'h1) begin
                cmat_1$16$d = load_data;
            end
            if (c_field == 32'h2) begin
                cmat_2$16$d = load_data;
            end
            if (c_field == 32'h3) begin
                cvec$16$d = load_data;
            end
            if (c_field == 32'h4) begin
                jsel_0$16$d = load_data[(32'h0)+:(5)];
                jsel_1$16$d = load_data[(32'h5)+:(5)];
                jsel_2$16$d = load_data[(32'ha)+:(5)];
                rnd$16$d = load_data[32'hf];
            end
        end
        c0$16 = cmat_0$16$q;
        c1$16 = cmat_1$16$q;
        c2$16 = cmat_2$16$q;
        c$16 = cvec$16$q;
        j0$16 = jsel_0$16$q;
        j1$16 = jsel_1$16$q;
        j2$16 = jsel_2$16$q;
        round_up$16 = rnd$16$q;
        cmat_0$17$clock = clock;
        cmat_1$17$clock = clock;
        cmat_2$17$clock = clock;
        cvec$17$clock = clock;
        jsel_0$17$clock = clock;
        jsel_1$17$clock = clock;
        jsel_2$17$clock = clock;
        rnd$17$clock = clock;
        cmat_0$17$d = cmat_0$17$q;
        cmat_1$17$d = cmat_1$17$q;
        cmat_2$17$d = cmat_2$17$q;
        cvec$17$d = cvec$17$q;
        jsel_0$17$d = jsel_0$17$q;
        jsel_1$17$d = jsel_1$17$q;
        jsel_2$17$d = jsel_2$17$q;
        rnd$17$d = rnd$17$q;
        if (load_en & (c_lane == idx$17)) begin
            if (c_field == 32'h0) begin
                cmat_0$17$d = load_data;
            end
            if (c_field == 32'h1) begin
                cmat_1$17$d = load_data;
            end
            if (c_field == 32'h2) begin
                cmat_2$17$d = load_data;
            end
            if (c_field == 32'h3) begin
                cvec$17$d = load_data;
            end
            if (c_field == 32'h4) begin
                jsel_0$17$d = load_data[(32'h0)+:(5)];
                jsel_1$17$d = load_data[(32'h5)+:(5)];
                jsel_2$17$d = load_data[(32'ha)+:(5)];
                rnd$17$d = load_data[32'hf];
            end
        end
        c0$17 = cmat_0$17$q;
        c1$17 = cmat_1$17$q;
        c2$17 = cmat_2$17$q;
        c$17 = cvec$17$q;
        j0$17 = jsel_0$17$q;
        j1$17 = jsel_1$17$q;
        j2$17 = jsel_2$17$q;
        round_up$17 = rnd$17$q;
        cmat_0$18$clock = clock;
        cmat_1$18$clock = clock;
        cmat_2$18$clock = clock;
        cvec$18$clock = clock;
        jsel_0$18$clock = clock;
        jsel_1$18$clock = clock;
        jsel_2$18$clock = clock;
        rnd$18$clock = clock;
        cmat_0$18$d = cmat_0$18$q;
        cmat_1$18$d = cmat_1$18$q;
        cmat_2$18$d = cmat_2$18$q;
        cvec$18$d = cvec$18$q;
        jsel_0$18$d = jsel_0$18$q;
        jsel_1$18$d = jsel_1$18$q;
        jsel_2$18$d = jsel_2$18$q;
        rnd$18$d = rnd$18$q;
        if (load_en & (c_lane == idx$18)) begin
            if (c_field == 32'h0) begin
                cmat_0$18$d = load_data;
            end
            if (c_field == 32'h1) begin
                cmat_1$18$d = load_data;
            end
            if (c_field == 32'h2) begin
                cmat_2$18$d = load_data;
            end
            if (c_field == 32'h3) begin
                cvec$18$d = load_data;
            end
            if (c_field == 32'h4) begin
                jsel_0$18$d = load_data[(32'h0)+:(5)];
                jsel_1$18$d = load_data[(32'h5)+:(5)];
                jsel_2$18$d = load_data[(32'ha)+:(5)];
                rnd$18$d = load_data[32'hf];
            end
        end
        c0$18 = cmat_0$18$q;
        c1$18 = cmat_1$18$q;
        c2$18 = cmat_2$18$q;
        c$18 = cvec$18$q;
        j0$18 = jsel_0$18$q;
        j1$18 = jsel_1$18$q;
        j2$18 = jsel_2$18$q;
        round_up$18 = rnd$18$q;
        cmat_0$19$clock = clock;
        cmat_1$19$clock = clock;
        cmat_2$19$clock = clock;
        cvec$19$clock = clock;
        jsel_0$19$clock = clock;
        jsel_1$19$clock = clock;
        jsel_2$19$clock = clock;
        rnd$19$clock = clock;
        cmat_0$19$d = cmat_0$19$q;
        cmat_1$19$d = cmat_1$19$q;
        cmat_2$19$d = cmat_2$19$q;
        cvec$19$d = cvec$19$q;
        jsel_0$19$d = jsel_0$19$q;
        jsel_1$19$d = jsel_1$19$q;
        jsel_2$19$d = jsel_2$19$q;
        rnd$19$d = rnd$19$q;
        if (load_en & (c_lane == idx$19)) begin
            if (c_field == 32'h0) begin
                cmat_0$19$d = load_data;
            end
            if (c_field == 32'h1) begin
                cmat_1$19$d = load_data;
            end
            if (c_field == 32'h2) begin
                cmat_2$19$d = load_data;
            end
            if (c_field == 32'h3) begin
                cvec$19$d = load_data;
            end
            if (c_field == 32'h4) begin
                jsel_0$19$d = load_data[(32'h0)+:(5)];
                jsel_1$19$d = load_data[(32'h5)+:(5)];
                jsel_2$19$d = load_data[(32'ha)+:(5)];
                rnd$19$d = load_data[32'hf];
            end
        end
        c0$19 = cmat_0$19$q;
        c1$19 = cmat_1$19$q;
        c2$19 = cmat_2$19$q;
        c$19 = cvec$19$q;
        j0$19 = jsel_0$19$q;
        j1$19 = jsel_1$19$q;
        j2$19 = jsel_2$19$q;
        round_up$19 = rnd$19$q;
        cmat_0$20$clock = clock;
        cmat_1$20$clock = clock;
        cmat_2$20$clock = clock;
        cvec$20$clock = clock;
        jsel_0$20$clock = clock;
        jsel_1$20$clock = clock;
        jsel_2$20$clock = clock;
        rnd$20$clock = clock;
        cmat_0$20$d = cmat_0$20$q;
        cmat_1$20$d = cmat_1$20$q;
        cmat_2$20$d = cmat_2$20$q;
        cvec$20$d = cvec$20$q;
        jsel_0$20$d = jsel_0$20$q;
        jsel_1$20$d = jsel_1$20$q;
        jsel_2$20$d = jsel_2$20$q;
        rnd$20$d = rnd$20$q;
        if (load_en & (c_lane == idx$20)) begin
            if (c_field == 32'h0) begin
                cmat_0$20$d = load_data;
            end
            if (c_field == 32'h1) begin
                cmat_1$20$d = load_data;
            end
            if (c_field == 32'h2) begin
                cmat_2$20$d = load_data;
            end
            if (c_field == 32'h3) begin
                cvec$20$d = load_data;
            end
            if (c_field == 32'h4) begin
                jsel_0$20$d = load_data[(32'h0)+:(5)];
                jsel_1$20$d = load_data[(32'h5)+:(5)];
                jsel_2$20$d = load_data[(32'ha)+:(5)];
                rnd$20$d = load_data[32'hf];
            end
        end
        c0$20 = cmat_0$20$q;
        c1$20 = cmat_1$20$q;
        c2$20 = cmat_2$20$q;
        c$20 = cvec$20$q;
        j0$20 = jsel_0$20$q;
        j1$20 = jsel_1$20$q;
        j2$20 = jsel_2$20$q;
        round_up$20 = rnd$20$q;
        cmat_0$21$clock = clock;
        cmat_1$21$clock = clock;
        cmat_2$21$clock = clock;
        cvec$21$clock = clock;
        jsel_0$21$clock = clock;
        jsel_1$21$clock = clock;
        jsel_2$21$clock = clock;
        rnd$21$clock = clock;
        cmat_0$21$d = cmat_0$21$q;
        cmat_1$21$d = cmat_1$21$q;
        cmat_2$21$d = cmat_2$21$q;
        cvec$21$d = cvec$21$q;
        jsel_0$21$d = jsel_0$21$q;
        jsel_1$21$d = jsel_1$21$q;
        jsel_2$21$d = jsel_2$21$q;
        rnd$21$d = rnd$21$q;
        if (load_en & (c_lane == idx$21)) begin
            if (c_field == 32'h0) begin
                cmat_0$21$d = load_data;
            end
            if (c_field == 32'h1) begin
                cmat_1$21$d = load_data;
            end
            if (c_field == 32'h2) begin
                cmat_2$21$d = load_data;
            end
            if (c_field == 32'h3) begin
                cvec$21$d = load_data;
            end
            if (c_field == 32'h4) begin
                jsel_0$21$d = load_data[(32'h0)+:(5)];
                jsel_1$21$d = load_data[(32'h5)+:(5)];
                jsel_2$21$d = load_data[(32'ha)+:(5)];
                rnd$21$d = load_data[32'hf];
            end
        end
        c0$21 = cmat_0$21$q;
        c1$21 = cmat_1$21$q;
        c2$21 = cmat_2$21$q;
        c$21 = cvec$21$q;
        j0$21 = jsel_0$21$q;
        j1$21 = jsel_1$21$q;
        j2$21 = jsel_2$21$q;
        round_up$21 = rnd$21$q;
        cmat_0$22$clock = clock;
        cmat_1$22$clock = clock;
        cmat_2$22$clock = clock;
        cvec$22$clock = clock;
        jsel_0$22$clock = clock;
        jsel_1$22$clock = clock;
        jsel_2$22$clock = clock;
        rnd$22$clock = clock;
        cmat_0$22$d = cmat_0$22$q;
        cmat_1$22$d = cmat_1$22$q;
        cmat_2$22$d = cmat_2$22$q;
        cvec$22$d = cvec$22$q;
        jsel_0$22$d = jsel_0$22$q;
        jsel_1$22$d = jsel_1$22$q;
        jsel_2$22$d = jsel_2$22$q;
        rnd$22$d = rnd$22$q;
        if (load_en & (c_lane == idx$22)) begin
            if (c_field == 32'h0) begin
                cmat_0$22$d = load_data;
            end
            if (c_field == 32'h1) begin
                cmat_1$22$d = load_data;
            end
            if (c_field == 32'h2) begin
                cmat_2$22$d = load_data;
            end
            if (c_field == 32'h3) begin
                cvec$22$d = load_data;
            end
            if (c_field == 32'h4) begin
                jsel_0$22$d = load_data[(32'h0)+:(5)];
                jsel_1$22$d = load_data[(32'h5)+:(5)];
                jsel_2$22$d = load_data[(32'ha)+:(5)];
                rnd$22$d = load_data[32'hf];
            end
        end
        c0$22 = cmat_0$22$q;
        c1$22 = cmat_1$22$q;
        c2$22 = cmat_2$22$q;
        c$22 = cvec$22$q;
        j0$22 = jsel_0$22$q;
        j1$22 = jsel_1$22$q;
        j2$22 = jsel_2$22$q;
        round_up$22 = rnd$22$q;
        cmat_0$23$clock = clock;
        cmat_1$23$clock = clock;
        cmat_2$23$clock = clock;
        cvec$23$clock = clock;
        jsel_0$23$clock = clock;
        jsel_1$23$clock = clock;
        jsel_2$23$clock = clock;
        rnd$23$clock = clock;
        cmat_0$23$d = cmat_0$23$q;
        cmat_1$23$d = cmat_1$23$q;
        cmat_2$23$d = cmat_2$23$q;
        cvec$23$d = cvec$23$q;
        jsel_0$23$d = jsel_0$23$q;
        jsel_1$23$d = jsel_1$23$q;
        jsel_2$23$d = jsel_2$23$q;
        rnd$23$d = rnd$23$q;
        if (load_en & (c_lane == idx$23)) begin
            if (c_field == 32'h0) begin
                cmat_0$23$d = load_data;
            end
            if (c_field == 32'h1) begin
                cmat_1$23$d = load_data;
            end
            if (c_field == 32'h2) begin
                cmat_2$23$d = load_data;
            end
            if (c_field == 32'h3) begin
                cvec$23$d = load_data;
            end
            if (c_field == 32'h4) begin
                jsel_0$23$d = load_data[(32'h0)+:(5)];
                jsel_1$23$d = load_data[(32'h5)+:(5)];
                jsel_2$23$d = load_data[(32'ha)+:(5)];
                rnd$23$d = load_data[32'hf];
            end
        end
        c0$23 = cmat_0$23$q;
        c1$23 = cmat_1$23$q;
        c2$23 = cmat_2$23$q;
        c$23 = cvec$23$q;
        j0$23 = jsel_0$23$q;
        j1$23 = jsel_1$23$q;
        j2$23 = jsel_2$23$q;
        round_up$23 = rnd$23$q;
    end
    
endmodule // top$dop$unit$setup


module top$leaf_count(d,q,clock);
    
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
          
endmodule // top$leaf_count


module top$leaf_fifo(clock,read,data_out,empty,almost_empty,underflow,write,data_in,full,almost_full,overflow);
    
    // Module arguments
    input wire  clock;
    input wire  read;
    output reg  [63:0] data_out;
    output reg  empty;
    output reg  almost_empty;
    output reg  underflow;
    input wire  write;
    input wire  [63:0] data_in;
    output reg  full;
    output reg  almost_full;
    output reg  overflow;
    
    // Stub signals
    reg  [5:0] ram$read_address;
    reg  ram$read_clock;
    wire  [63:0] ram$read_data;
    reg  [5:0] ram$write_address;
    reg  ram$write_clock;
    reg  [63:0] ram$write_data;
    reg  ram$write_enable;
    reg  read_logic$clock;
    reg  read_logic$read;
    wire  [63:0] read_logic$data_out;
    wire  read_logic$empty;
    wire  read_logic$almost_empty;
    wire  read_logic$underflow;
    reg  [6:0] read_logic$write_address_delayed;
    wire  [5:0] read_logic$ram_read_address;
    reg  [63:0] read_logic$ram_read_data;
    wire  read_logic$ram_read_clock;
    wire  [6:0] read_logic$read_address_out;
    wire  [6:0] read_logic$fill_level;
    reg  write_logic$write;
    reg  [63:0] write_logic$data_in;
    wire  write_logic$full;
    wire  write_logic$almost_full;
    wire  write_logic$overflow;
    reg  write_logic$clock;
    wire  [5:0] write_logic$ram_write_address;
    wire  write_logic$ram_write_clock;
    wire  [63:0] write_logic$ram_write_data;
    wire  write_logic$ram_write_enable;
    reg  [6:0] write_logic$read_address;
    wire  [6:0] write_logic$write_address_delayed;
    wire  [6:0] write_logic$fill_level;
    
    // Sub module instances
    top$leaf_fifo$ram ram(
        .read_address(ram$read_address),
        .read_clock(ram$read_clock),
        .read_data(ram$read_data),
        .write_address(ram$write_address),
        .write_clock(ram$write_clock),
        .write_data(ram$write_data),
        .write_enable(ram$write_enable)
    );
    top$leaf_fifo$read_logic read_logic(
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
    top$leaf_fifo$write_logic write_logic(
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
    
endmodule // top$leaf_fifo


module top$leaf_fifo$ram(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [5:0] read_address;
    input wire  read_clock;
    output reg  [63:0] read_data;
    input wire  [5:0] write_address;
    input wire  write_clock;
    input wire  [63:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    reg[63:0] mem[63:0];
    
    
    
    always @(posedge read_clock) begin
       read_data <= mem[read_address];
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address] <= write_data;
       end
    end
                
endmodule // top$leaf_fifo$ram


module top$leaf_fifo$read_logic(clock,read,data_out,empty,almost_empty,underflow,write_address_delayed,ram_read_address,ram_read_data,ram_read_clock,read_address_out,fill_level);
    
    // Module arguments
    input wire  clock;
    input wire  read;
    output reg  [63:0] data_out;
    output reg  empty;
    output reg  almost_empty;
    output reg  underflow;
    input wire  [6:0] write_address_delayed;
    output reg  [5:0] ram_read_address;
    input wire  [63:0] ram_read_data;
    output reg  ram_read_clock;
    output reg  [6:0] read_address_out;
    output reg  [6:0] fill_level;
    
    // Constant declarations
    localparam  fifo_address_mask = 7'b111111;
    localparam  fifo_size = 7'b1000000;
    localparam  block_size = 7'b1;
    
    // Stub signals
    reg  [6:0] read_address$d;
    wire  [6:0] read_address$q;
    reg  read_address$clock;
    reg  dff_underflow$d;
    wire  dff_underflow$q;
    reg  dff_underflow$clock;
    
    // Local signals
    reg  is_empty;
    reg  is_full;
    
    // Sub module instances
    top$leaf_fifo$read_logic$read_address read_address(
        .d(read_address$d),
        .q(read_address$q),
        .clock(read_address$clock)
    );
    top$cnt_dop$pending dff_underflow(
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
        ram_read_address = ((read_address$q & fifo_address_mask) & 6'h3f);
        data_out = ram_read_data;
        if (read & ~is_empty) begin
            read_address$d = read_address$q + 32'h1;
            ram_read_address = (((read_address$q + 32'h1) & fifo_address_mask) & 6'h3f);
        end
        else begin
            read_address$d = read_address$q;
        end
        dff_underflow$d = dff_underflow$q | (is_empty & read);
        underflow = dff_underflow$q;
        read_address_out = read_address$q;
    end
    
endmodule // top$leaf_fifo$read_logic


module top$leaf_fifo$read_logic$read_address(d,q,clock);
    
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
          
endmodule // top$leaf_fifo$read_logic$read_address


module top$leaf_fifo$write_logic(write,data_in,full,almost_full,overflow,clock,ram_write_address,ram_write_clock,ram_write_data,ram_write_enable,read_address,write_address_delayed,fill_level);
    
    // Module arguments
    input wire  write;
    input wire  [63:0] data_in;
    output reg  full;
    output reg  almost_full;
    output reg  overflow;
    input wire  clock;
    output reg  [5:0] ram_write_address;
    output reg  ram_write_clock;
    output reg  [63:0] ram_write_data;
    output reg  ram_write_enable;
    input wire  [6:0] read_address;
    output reg  [6:0] write_address_delayed;
    output reg  [6:0] fill_level;
    
    // Constant declarations
    localparam  fifo_address_mask = 7'b111111;
    localparam  fifo_size = 7'b1000000;
    localparam  almost_full_level = 7'b111111;
    
    // Stub signals
    reg  [6:0] write_address$d;
    wire  [6:0] write_address$q;
    reg  write_address$clock;
    reg  [6:0] dff_write_address_delay$d;
    wire  [6:0] dff_write_address_delay$q;
    reg  dff_write_address_delay$clock;
    reg  dff_overflow$d;
    wire  dff_overflow$q;
    reg  dff_overflow$clock;
    
    // Local signals
    reg  is_empty;
    reg  is_full;
    
    // Sub module instances
    top$leaf_fifo$read_logic$read_address write_address(
        .d(write_address$d),
        .q(write_address$q),
        .clock(write_address$clock)
    );
    top$leaf_fifo$read_logic$read_address dff_write_address_delay(
        .d(dff_write_address_delay$d),
        .q(dff_write_address_delay$q),
        .clock(dff_write_address_delay$clock)
    );
    top$cnt_dop$pending dff_overflow(
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
        ram_write_address = ((write_address$q & fifo_address_mask) & 6'h3f);
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
    
endmodule // top$leaf_fifo$write_logic


module top$leaf_tag(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$leaf_tag


module top$map(d,q,clock);
    
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
          
endmodule // top$map


module top$mem_port(clock,clear,go,pf_on,slot_bits,port_out,base_na,base_nb,base_ta,base_tb,map,pop,pop_entry,pop_fetch,issue,cur_fa,cur_fb,cur_sa,cur_sb,need_ta,need_tb,leaf_tag,mem_req_ready,mem_resp_valid,mem_resp_data,mem_req_valid,mem_req_addr,req_dst,accept,resp,resp_dst,ta_req,tb_req,outstanding,na_in,nb_in,na_sh,nb_sh,wa_empty,wb_empty);
    
    // Module arguments
    input wire  clock;
    input wire  clear;
    input wire  go;
    input wire  pf_on;
    input wire  [2:0] slot_bits;
    input wire  [3:0] port_out;
    input wire  [23:0] base_na;
    input wire  [23:0] base_nb;
    input wire  [23:0] base_ta;
    input wire  [23:0] base_tb;
    input wire  [19:0] map;
    input wire  pop;
    input wire  [66:0] pop_entry;
    input wire  [3:0] pop_fetch;
    input wire  issue;
    input wire  cur_fa;
    input wire  cur_fb;
    input wire  [2:0] cur_sa;
    input wire  [2:0] cur_sb;
    input wire  need_ta;
    input wire  need_tb;
    input wire  [31:0] leaf_tag;
    input wire  mem_req_ready;
    input wire  mem_resp_valid;
    input wire  [2047:0] mem_resp_data;
    output reg  mem_req_valid;
    output reg  [23:0] mem_req_addr;
    output reg  [1:0] req_dst;
    output reg  accept;
    output reg  resp;
    output reg  [1:0] resp_dst;
    output reg  [15:0] ta_req;
    output reg  [15:0] tb_req;
    output reg  outstanding;
    output reg  [160:0] na_in;
    output reg  [160:0] nb_in;
    output reg  [983:0] na_sh;
    output reg  [983:0] nb_sh;
    output reg  wa_empty;
    output reg  wb_empty;
    
    // Constant declarations
    localparam  c_ask_b = 22'h10000;
    localparam  c_one24 = 24'h1;
    localparam  c_one16 = 16'h1;
    localparam  c_one32 = 32'h1;
    localparam  c_one8 = 8'h1;
    
    // Stub signals
    reg  [21:0] ask_w$0$d;
    wire  [21:0] ask_w$0$q;
    reg  ask_w$0$clock;
    reg  [21:0] ask_w$1$d;
    wire  [21:0] ask_w$1$q;
    reg  ask_w$1$clock;
    reg  [21:0] ask_w$2$d;
    wire  [21:0] ask_w$2$q;
    reg  ask_w$2$clock;
    reg  [21:0] ask_w$3$d;
    wire  [21:0] ask_w$3$q;
    reg  ask_w$3$clock;
    reg  [21:0] ask_w$4$d;
    wire  [21:0] ask_w$4$q;
    reg  ask_w$4$clock;
    reg  [21:0] ask_w$5$d;
    wire  [21:0] ask_w$5$q;
    reg  ask_w$5$clock;
    reg  [21:0] ask_w$6$d;
    wire  [21:0] ask_w$6$q;
    reg  ask_w$6$clock;
    reg  [21:0] ask_w$7$d;
    wire  [21:0] ask_w$7$q;
    reg  ask_w$7$clock;
    reg  [21:0] ask_w$8$d;
    wire  [21:0] ask_w$8$q;
    reg  ask_w$8$clock;
    reg  [21:0] ask_w$9$d;
    wire  [21:0] ask_w$9$q;
    reg  ask_w$9$clock;
    reg  [21:0] ask_w$10$d;
    wire  [21:0] ask_w$10$q;
    reg  ask_w$10$clock;
    reg  [21:0] ask_w$11$d;
    wire  [21:0] ask_w$11$q;
    reg  ask_w$11$clock;
    reg  [21:0] ask_w$12$d;
    wire  [21:0] ask_w$12$q;
    reg  ask_w$12$clock;
    reg  [21:0] ask_w$13$d;
    wire  [21:0] ask_w$13$q;
    reg  ask_w$13$clock;
    reg  [21:0] ask_w$14$d;
    wire  [21:0] ask_w$14$q;
    reg  ask_w$14$clock;
    reg  [21:0] ask_w$15$d;
    wire  [21:0] ask_w$15$q;
    reg  ask_w$15$clock;
    reg  [21:0] ask_w$16$d;
    wire  [21:0] ask_w$16$q;
    reg  ask_w$16$clock;
    reg  [21:0] ask_w$17$d;
    wire  [21:0] ask_w$17$q;
    reg  ask_w$17$clock;
    reg  [21:0] ask_w$18$d;
    wire  [21:0] ask_w$18$q;
    reg  ask_w$18$clock;
    reg  [21:0] ask_w$19$d;
    wire  [21:0] ask_w$19$q;
    reg  ask_w$19$clock;
    reg  [21:0] ask_w$20$d;
    wire  [21:0] ask_w$20$q;
    reg  ask_w$20$clock;
    reg  [21:0] ask_w$21$d;
    wire  [21:0] ask_w$21$q;
    reg  ask_w$21$clock;
    reg  [21:0] ask_w$22$d;
    wire  [21:0] ask_w$22$q;
    reg  ask_w$22$clock;
    reg  [21:0] ask_w$23$d;
    wire  [21:0] ask_w$23$q;
    reg  ask_w$23$clock;
    reg  [21:0] ask_w$24$d;
    wire  [21:0] ask_w$24$q;
    reg  ask_w$24$clock;
    reg  [21:0] ask_w$25$d;
    wire  [21:0] ask_w$25$q;
    reg  ask_w$25$clock;
    reg  [21:0] ask_w$26$d;
    wire  [21:0] ask_w$26$q;
    reg  ask_w$26$clock;
    reg  [21:0] ask_w$27$d;
    wire  [21:0] ask_w$27$q;
    reg  ask_w$27$clock;
    reg  [21:0] ask_w$28$d;
    wire  [21:0] ask_w$28$q;
    reg  ask_w$28$clock;
    reg  [21:0] ask_w$29$d;
    wire  [21:0] ask_w$29$q;
    reg  ask_w$29$clock;
    reg  [21:0] ask_w$30$d;
    wire  [21:0] ask_w$30$q;
    reg  ask_w$30$clock;
    reg  [21:0] ask_w$31$d;
    wire  [21:0] ask_w$31$q;
    reg  ask_w$31$clock;
    reg  [4:0] ask_head$d;
    wire  [4:0] ask_head$q;
    reg  ask_head$clock;
    reg  [4:0] ask_tail$d;
    wire  [4:0] ask_tail$q;
    reg  ask_tail$clock;
    reg  [5:0] ask_n$d;
    wire  [5:0] ask_n$q;
    reg  ask_n$clock;
    reg  [4:0] seq_head$d;
    wire  [4:0] seq_head$q;
    reg  seq_head$clock;
    reg  [4:0] seq_tail$d;
    wire  [4:0] seq_tail$q;
    reg  seq_tail$clock;
    reg  wa$clock;
    reg  [15:0] wa$wsel;
    reg  [1949:0] wa$wdata;
    reg  [15:0] wa$rsel;
    wire  [1949:0] wa$rdata;
    reg  [3:0] wa_head$d;
    wire  [3:0] wa_head$q;
    reg  wa_head$clock;
    reg  [3:0] wa_tail$d;
    wire  [3:0] wa_tail$q;
    reg  wa_tail$clock;
    reg  [4:0] wa_n$d;
    wire  [4:0] wa_n$q;
    reg  wa_n$clock;
    reg  wb$clock;
    reg  [15:0] wb$wsel;
    reg  [1949:0] wb$wdata;
    reg  [15:0] wb$rsel;
    wire  [1949:0] wb$rdata;
    reg  [3:0] wb_head$d;
    wire  [3:0] wb_head$q;
    reg  wb_head$clock;
    reg  [3:0] wb_tail$d;
    wire  [3:0] wb_tail$q;
    reg  wb_tail$clock;
    reg  [4:0] wb_n$d;
    wire  [4:0] wb_n$q;
    reg  wb_n$clock;
    reg  [1949:0] na_word$d;
    wire  [1949:0] na_word$q;
    reg  na_word$clock;
    reg  [1949:0] nb_word$d;
    wire  [1949:0] nb_word$q;
    reg  nb_word$clock;
    reg  tags$clock;
    reg  [15:0] tags$wsel;
    reg  [1:0] tags$wdata;
    reg  [15:0] tags$rsel;
    wire  [1:0] tags$rdata;
    reg  [3:0] tag_head$d;
    wire  [3:0] tag_head$q;
    reg  tag_head$clock;
    reg  [3:0] tag_tail$d;
    wire  [3:0] tag_tail$q;
    reg  tag_tail$clock;
    reg  [4:0] tag_n$d;
    wire  [4:0] tag_n$q;
    reg  tag_n$clock;
    reg  ta_pend$d;
    wire  ta_pend$q;
    reg  ta_pend$clock;
    reg  [15:0] ta_req_r$d;
    wire  [15:0] ta_req_r$q;
    reg  ta_req_r$clock;
    reg  tb_pend$d;
    wire  tb_pend$q;
    reg  tb_pend$clock;
    reg  [15:0] tb_req_r$d;
    wire  [15:0] tb_req_r$q;
    reg  tb_req_r$clock;
    
    // Local signals
    reg  [4:0] seq_tail1;
    reg  [31:0] ask_dec;
    reg  [21:0] ask_front;
    reg  ask_ok;
    reg  [4:0] ask_off1;
    reg  [4:0] ask_off2;
    reg  [4:0] ask_off3;
    reg  [4:0] ask_new;
    reg  ask_take;
    reg  top_two;
    reg  [31:0] put0;
    reg  [31:0] put1;
    reg  [31:0] put2;
    reg  [31:0] put3;
    reg  [1949:0] rec_a;
    reg  [1949:0] rec_b;
    reg  [7:0] sa_dec;
    reg  [7:0] sb_dec;
    reg  port_free;
    reg  req;
    reg  [15:0] req_id;
    reg  [15:0] ask_rec;
    reg  [23:0] req_addr;
    reg  [23:0] req_base;
    reg  [23:0] req_rec;
    reg  [4:0] map_ln;
    reg  [4:0] map_lp;
    reg  [4:0] map_lb;
    
    // Sub module instances
    top$mem_port$ask_w$0 ask_w$0(
        .d(ask_w$0$d),
        .q(ask_w$0$q),
        .clock(ask_w$0$clock)
    );
    top$mem_port$ask_w$0 ask_w$1(
        .d(ask_w$1$d),
        .q(ask_w$1$q),
        .clock(ask_w$1$clock)
    );
    top$mem_port$ask_w$0 ask_w$2(
        .d(ask_w$2$d),
        .q(ask_w$2$q),
        .clock(ask_w$2$clock)
    );
    top$mem_port$ask_w$0 ask_w$3(
        .d(ask_w$3$d),
        .q(ask_w$3$q),
        .clock(ask_w$3$clock)
    );
    top$mem_port$ask_w$0 ask_w$4(
        .d(ask_w$4$d),
        .q(ask_w$4$q),
        .clock(ask_w$4$clock)
    );
    top$mem_port$ask_w$0 ask_w$5(
        .d(ask_w$5$d),
        .q(ask_w$5$q),
        .clock(ask_w$5$clock)
    );
    top$mem_port$ask_w$0 ask_w$6(
        .d(ask_w$6$d),
        .q(ask_w$6$q),
        .clock(ask_w$6$clock)
    );
    top$mem_port$ask_w$0 ask_w$7(
        .d(ask_w$7$d),
        .q(ask_w$7$q),
        .clock(ask_w$7$clock)
    );
    top$mem_port$ask_w$0 ask_w$8(
        .d(ask_w$8$d),
        .q(ask_w$8$q),
        .clock(ask_w$8$clock)
    );
    top$mem_port$ask_w$0 ask_w$9(
        .d(ask_w$9$d),
        .q(ask_w$9$q),
        .clock(ask_w$9$clock)
    );
    top$mem_port$ask_w$0 ask_w$10(
        .d(ask_w$10$d),
        .q(ask_w$10$q),
        .clock(ask_w$10$clock)
    );
    top$mem_port$ask_w$0 ask_w$11(
        .d(ask_w$11$d),
        .q(ask_w$11$q),
        .clock(ask_w$11$clock)
    );
    top$mem_port$ask_w$0 ask_w$12(
        .d(ask_w$12$d),
        .q(ask_w$12$q),
        .clock(ask_w$12$clock)
    );
    top$mem_port$ask_w$0 ask_w$13(
        .d(ask_w$13$d),
        .q(ask_w$13$q),
        .clock(ask_w$13$clock)
    );
    top$mem_port$ask_w$0 ask_w$14(
        .d(ask_w$14$d),
        .q(ask_w$14$q),
        .clock(ask_w$14$clock)
    );
    top$mem_port$ask_w$0 ask_w$15(
        .d(ask_w$15$d),
        .q(ask_w$15$q),
        .clock(ask_w$15$clock)
    );
    top$mem_port$ask_w$0 ask_w$16(
        .d(ask_w$16$d),
        .q(ask_w$16$q),
        .clock(ask_w$16$clock)
    );
    top$mem_port$ask_w$0 ask_w$17(
        .d(ask_w$17$d),
        .q(ask_w$17$q),
        .clock(ask_w$17$clock)
    );
    top$mem_port$ask_w$0 ask_w$18(
        .d(ask_w$18$d),
        .q(ask_w$18$q),
        .clock(ask_w$18$clock)
    );
    top$mem_port$ask_w$0 ask_w$19(
        .d(ask_w$19$d),
        .q(ask_w$19$q),
        .clock(ask_w$19$clock)
    );
    top$mem_port$ask_w$0 ask_w$20(
        .d(ask_w$20$d),
        .q(ask_w$20$q),
        .clock(ask_w$20$clock)
    );
    top$mem_port$ask_w$0 ask_w$21(
        .d(ask_w$21$d),
        .q(ask_w$21$q),
        .clock(ask_w$21$clock)
    );
    top$mem_port$ask_w$0 ask_w$22(
        .d(ask_w$22$d),
        .q(ask_w$22$q),
        .clock(ask_w$22$clock)
    );
    top$mem_port$ask_w$0 ask_w$23(
        .d(ask_w$23$d),
        .q(ask_w$23$q),
        .clock(ask_w$23$clock)
    );
    top$mem_port$ask_w$0 ask_w$24(
        .d(ask_w$24$d),
        .q(ask_w$24$q),
        .clock(ask_w$24$clock)
    );
    top$mem_port$ask_w$0 ask_w$25(
        .d(ask_w$25$d),
        .q(ask_w$25$q),
        .clock(ask_w$25$clock)
    );
    top$mem_port$ask_w$0 ask_w$26(
        .d(ask_w$26$d),
        .q(ask_w$26$q),
        .clock(ask_w$26$clock)
    );
    top$mem_port$ask_w$0 ask_w$27(
        .d(ask_w$27$d),
        .q(ask_w$27$q),
        .clock(ask_w$27$clock)
    );
    top$mem_port$ask_w$0 ask_w$28(
        .d(ask_w$28$d),
        .q(ask_w$28$q),
        .clock(ask_w$28$clock)
    );
    top$mem_port$ask_w$0 ask_w$29(
        .d(ask_w$29$d),
        .q(ask_w$29$q),
        .clock(ask_w$29$clock)
    );
    top$mem_port$ask_w$0 ask_w$30(
        .d(ask_w$30$d),
        .q(ask_w$30$q),
        .clock(ask_w$30$clock)
    );
    top$mem_port$ask_w$0 ask_w$31(
        .d(ask_w$31$d),
        .q(ask_w$31$q),
        .clock(ask_w$31$clock)
    );
    top$d_cntr$ahd_pairs ask_head(
        .d(ask_head$d),
        .q(ask_head$q),
        .clock(ask_head$clock)
    );
    top$d_cntr$ahd_pairs ask_tail(
        .d(ask_tail$d),
        .q(ask_tail$q),
        .clock(ask_tail$clock)
    );
    top$leaf_count ask_n(
        .d(ask_n$d),
        .q(ask_n$q),
        .clock(ask_n$clock)
    );
    top$d_cntr$ahd_pairs seq_head(
        .d(seq_head$d),
        .q(seq_head$q),
        .clock(seq_head$clock)
    );
    top$d_cntr$ahd_pairs seq_tail(
        .d(seq_tail$d),
        .q(seq_tail$q),
        .clock(seq_tail$clock)
    );
    top$mem_port$wa wa(
        .clock(wa$clock),
        .wsel(wa$wsel),
        .wdata(wa$wdata),
        .rsel(wa$rsel),
        .rdata(wa$rdata)
    );
    top$d_cntr$ahd_fetch$row$0 wa_head(
        .d(wa_head$d),
        .q(wa_head$q),
        .clock(wa_head$clock)
    );
    top$d_cntr$ahd_fetch$row$0 wa_tail(
        .d(wa_tail$d),
        .q(wa_tail$q),
        .clock(wa_tail$clock)
    );
    top$d_cntr$ahd_pairs wa_n(
        .d(wa_n$d),
        .q(wa_n$q),
        .clock(wa_n$clock)
    );
    top$mem_port$wa wb(
        .clock(wb$clock),
        .wsel(wb$wsel),
        .wdata(wb$wdata),
        .rsel(wb$rsel),
        .rdata(wb$rdata)
    );
    top$d_cntr$ahd_fetch$row$0 wb_head(
        .d(wb_head$d),
        .q(wb_head$q),
        .clock(wb_head$clock)
    );
    top$d_cntr$ahd_fetch$row$0 wb_tail(
        .d(wb_tail$d),
        .q(wb_tail$q),
        .clock(wb_tail$clock)
    );
    top$d_cntr$ahd_pairs wb_n(
        .d(wb_n$d),
        .q(wb_n$q),
        .clock(wb_n$clock)
    );
    top$mem_port$na_word na_word(
        .d(na_word$d),
        .q(na_word$q),
        .clock(na_word$clock)
    );
    top$mem_port$na_word nb_word(
        .d(nb_word$d),
        .q(nb_word$q),
        .clock(nb_word$clock)
    );
    top$mem_port$tags tags(
        .clock(tags$clock),
        .wsel(tags$wsel),
        .wdata(tags$wdata),
        .rsel(tags$rsel),
        .rdata(tags$rdata)
    );
    top$d_cntr$ahd_fetch$row$0 tag_head(
        .d(tag_head$d),
        .q(tag_head$q),
        .clock(tag_head$clock)
    );
    top$d_cntr$ahd_fetch$row$0 tag_tail(
        .d(tag_tail$d),
        .q(tag_tail$q),
        .clock(tag_tail$clock)
    );
    top$d_cntr$ahd_pairs tag_n(
        .d(tag_n$d),
        .q(tag_n$q),
        .clock(tag_n$clock)
    );
    top$cnt_dop$pending ta_pend(
        .d(ta_pend$d),
        .q(ta_pend$q),
        .clock(ta_pend$clock)
    );
    top$d_cntr$last_a ta_req_r(
        .d(ta_req_r$d),
        .q(ta_req_r$q),
        .clock(ta_req_r$clock)
    );
    top$cnt_dop$pending tb_pend(
        .d(tb_pend$d),
        .q(tb_pend$q),
        .clock(tb_pend$clock)
    );
    top$d_cntr$last_a tb_req_r(
        .d(tb_req_r$d),
        .q(tb_req_r$q),
        .clock(tb_req_r$clock)
    );
    
    // Update code
    always @(*) begin
        ask_head$clock = clock;
        ask_tail$clock = clock;
        ask_n$clock = clock;
        seq_head$clock = clock;
        seq_tail$clock = clock;
        ask_head$d = ask_head$q;
        ask_tail$d = ask_tail$q;
        ask_n$d = ask_n$q;
        seq_head$d = seq_head$q;
        seq_tail$d = seq_tail$q;
        wa_head$clock = clock;
        wa_tail$clock = clock;
        wa_n$clock = clock;
        wb_head$clock = clock;
        wb_tail$clock = clock;
        wb_n$clock = clock;
        na_word$clock = clock;
        nb_word$clock = clock;
        wa_head$d = wa_head$q;
        wa_tail$d = wa_tail$q;
        wa_n$d = wa_n$q;
        wb_head$d = wb_head$q;
        wb_tail$d = wb_tail$q;
        wb_n$d = wb_n$q;
        na_word$d = na_word$q;
        nb_word$d = nb_word$q;
        tag_head$clock = clock;
        tag_tail$clock = clock;
        tag_n$clock = clock;
        ta_pend$clock = clock;
        ta_req_r$clock = clock;
        tb_pend$clock = clock;
        tb_req_r$clock = clock;
        tag_head$d = tag_head$q;
        tag_tail$d = tag_tail$q;
        tag_n$d = tag_n$q;
        ta_pend$d = ta_pend$q;
        ta_req_r$d = ta_req_r$q;
        tb_pend$d = tb_pend$q;
        tb_req_r$d = tb_req_r$q;
        ask_w$0$clock = clock;
        ask_w$0$d = ask_w$0$q;
        ask_w$1$clock = clock;
        ask_w$1$d = ask_w$1$q;
        ask_w$2$clock = clock;
        ask_w$2$d = ask_w$2$q;
        ask_w$3$clock = clock;
        ask_w$3$d = ask_w$3$q;
        ask_w$4$clock = clock;
        ask_w$4$d = ask_w$4$q;
        ask_w$5$clock = clock;
        ask_w$5$d = ask_w$5$q;
        ask_w$6$clock = clock;
        ask_w$6$d = ask_w$6$q;
        ask_w$7$clock = clock;
        ask_w$7$d = ask_w$7$q;
        ask_w$8$clock = clock;
        ask_w$8$d = ask_w$8$q;
        ask_w$9$clock = clock;
        ask_w$9$d = ask_w$9$q;
        ask_w$10$clock = clock;
        ask_w$10$d = ask_w$10$q;
        ask_w$11$clock = clock;
        ask_w$11$d = ask_w$11$q;
        ask_w$12$clock = clock;
        ask_w$12$d = ask_w$12$q;
        ask_w$13$clock = clock;
        ask_w$13$d = ask_w$13$q;
        ask_w$14$clock = clock;
        ask_w$14$d = ask_w$14$q;
        ask_w$15$clock = clock;
        ask_w$15$d = ask_w$15$q;
        ask_w$16$clock = clock;
        ask_w$16$d = ask_w$16$q;
        ask_w$17$clock = clock;
        ask_w$17$d = ask_w$17$q;
        ask_w$18$clock = clock;
        ask_w$18$d = ask_w$18$q;
        ask_w$19$clock = clock;
        ask_w$19$d = ask_w$19$q;
        ask_w$20$clock = clock;
        ask_w$20$d = ask_w$20$q;
        ask_w$21$clock = clock;
        ask_w$21$d = ask_w$21$q;
        ask_w$22$clock = clock;
        ask_w$22$d = ask_w$22$q;
        ask_w$23$clock = clock;
        ask_w$23$d = ask_w$23$q;
        ask_w$24$clock = clock;
        ask_w$24$d = ask_w$24$q;
        ask_w$25$clock = clock;
        ask_w$25$d = ask_w$25$q;
        ask_w$26$clock = clock;
        ask_w$26$d = ask_w$26$q;
        ask_w$27$clock = clock;
        ask_w$27$d = ask_w$27$q;
        ask_w$28$clock = clock;
        ask_w$28$d = ask_w$28$q;
        ask_w$29$clock = clock;
        ask_w$29$d = ask_w$29$q;
        ask_w$30$clock = clock;
        ask_w$30$d = ask_w$30$q;
        ask_w$31$clock = clock;
        ask_w$31$d = ask_w$31$q;
        wa$clock = clock;
        wb$clock = clock;
        tags$clock = clock;
        wa$rsel = c_one16 << wa_head$q;
        wb$rsel = c_one16 << wb_head$q;
        rec_a = na_word$q;
        if (cur_fa) begin
            rec_a = wa$rdata;
        end
        rec_b = nb_word$q;
        if (cur_fb) begin
            rec_b = wb$rdata;
        end
        sa_dec = c_one8 << cur_sa;
        sb_dec = c_one8 << cur_sb;
        na_in = rec_a[(32'h0)+:(161)];
        nb_in = rec_b[(32'h0)+:(161)];
        if (sa_dec[1]) begin
            na_in = rec_a[(1 * 32'ha1)+:(161)];
        end
        if (sb_dec[1]) begin
            nb_in = rec_b[(1 * 32'ha1)+:(161)];
        end
        if (sa_dec[2]) begin
            na_in = rec_a[(2 * 32'ha1)+:(161)];
        end
        if (sb_dec[2]) begin
            nb_in = rec_b[(2 * 32'ha1)+:(161)];
        end
        if (sa_dec[3]) begin
            na_in = rec_a[(3 * 32'ha1)+:(161)];
        end
        if (sb_dec[3]) begin
            nb_in = rec_b[(3 * 32'ha1)+:(161)];
        end
        if (sa_dec[4]) begin
            na_in = rec_a[(4 * 32'ha1)+:(161)];
        end
        if (sb_dec[4]) begin
            nb_in = rec_b[(4 * 32'ha1)+:(161)];
        end
        if (sa_dec[5]) begin
            na_in = rec_a[(5 * 32'ha1)+:(161)];
        end
        if (sb_dec[5]) begin
            nb_in = rec_b[(5 * 32'ha1)+:(161)];
        end
        na_sh = rec_a[(32'h6 * 32'ha1)+:(984)];
        nb_sh = rec_b[(32'h6 * 32'ha1)+:(984)];
        wa_empty = wa_n$q == 32'h0;
        wb_empty = wb_n$q == 32'h0;
        ask_dec = c_one32 << ask_head$q;
        ask_front = 32'h0;
        if (ask_dec[0]) begin
            ask_front = ask_w$0$q;
        end
        if (ask_dec[1]) begin
            ask_front = ask_w$1$q;
        end
        if (ask_dec[2]) begin
            ask_front = ask_w$2$q;
        end
        if (ask_dec[3]) begin
            ask_front = ask_w$3$q;
        end
        if (ask_dec[4]) begin
            ask_front = ask_w$4$q;
        end
        if (ask_dec[5]) begin
            ask_front = ask_w$5$q;
        end
        if (ask_dec[6]) begin
            ask_front = ask_w$6$q;
        end
        if (ask_dec[7]) begin
            ask_front = ask_w$7$q;
        end
        if (ask_dec[8]) begin
            ask_front = ask_w$8$q;
        end
        if (ask_dec[9]) begin
            ask_front = ask_w$9$q;
        end
        if (ask_dec[10]) begin
            ask_front = ask_w$10$q;
        end
        if (ask_dec[11]) begin
            ask_front = ask_w$11$q;
        end
        if (ask_dec[12]) begin
            ask_front = ask_w$12$q;
        end
        if (ask_dec[13]) begin
            ask_front = ask_w$13$q;
        end
        if (ask_dec[14]) begin
            ask_front = ask_w$14$q;
        end
        if (ask_dec[15]) begin
            ask_front = ask_w$15$q;
        end
        if (ask_dec[16]) begin
            ask_front = ask_w$16$q;
        end
        if (ask_dec[17]) begin
            ask_front = ask_w$17$q;
        end
        if (ask_dec[18]) begin
            ask_front = ask_w$18$q;
        end
        if (ask_dec[19]) begin
            ask_front = ask_w$19$q;
        end
        if (ask_dec[20]) begin
            ask_front = ask_w$20$q;
        end
        if (ask_dec[21]) begin
            ask_front = ask_w$21$q;
        end
        if (ask_dec[22]) begin
            ask_front = ask_w$22$q;
        end
        if (ask_dec[23]) begin
            ask_front = ask_w$23$q;
        end
        if (ask_dec[24]) begin
            ask_front = ask_w$24$q;
        end
        if (ask_dec[25]) begin
            ask_front = ask_w$25$q;
        end
        if (ask_dec[26]) begin
            ask_front = ask_w$26$q;
        end
        if (ask_dec[27]) begin
            ask_front = ask_w$27$q;
        end
        if (ask_dec[28]) begin
            ask_front = ask_w$28$q;
        end
        if (ask_dec[29]) begin
            ask_front = ask_w$29$q;
        end
        if (ask_dec[30]) begin
            ask_front = ask_w$30$q;
        end
        if (ask_dec[31]) begin
            ask_front = ask_w$31$q;
        end
        ask_ok = go & (ask_n$q != 32'h0) & (pf_on | (ask_front[(32'h11)+:(5)] == seq_head$q));
        port_free = tag_n$q <= ((port_out) & 5'h1f);
        req_dst = ((ask_front[(32'h10)+:(1)]) & 2'h3);
        req_id = ask_front[(32'h0)+:(16)];
        ask_rec = ask_front[(32'h0)+:(16)] >> slot_bits;
        req_base = base_na;
        if (ask_front[32'h10]) begin
            req_base = base_nb;
        end
        req_rec = ((ask_rec) & 24'hffffff);
        req = port_free & ask_ok;
        if (need_tb & ~tb_pend$q) begin
            req_dst = 32'h3;
            req_id = leaf_tag[(32'h10)+:(16)];
            req_base = base_tb;
            req_rec = ((leaf_tag[(32'h10)+:(16)]) & 24'hffffff);
            req = port_free;
        end
        if (need_ta & ~ta_pend$q) begin
            req_dst = 32'h2;
            req_id = leaf_tag[(32'h0)+:(16)];
            req_base = base_ta;
            req_rec = ((leaf_tag[(32'h0)+:(16)]) & 24'hffffff);
            req = port_free;
        end
        map_ln = ((map[(32'h0)+:(3)]) & 5'h1f);
        if (req_dst == 32'h1) begin
            map_ln = ((map[(32'h3)+:(3)]) & 5'h1f);
        end
        if (req_dst == 32'h2) begin
            map_ln = ((map[(32'h6)+:(3)]) & 5'h1f);
        end
        if (req_dst == 32'h3) begin
            map_ln = ((map[(32'h9)+:(3)]) & 5'h1f);
        end
        map_lp = ((map[(32'hc)+:(4)]) & 5'h1f);
        map_lb = ((map[(32'h10)+:(4)]) & 5'h1f);
        req_addr = req_base + ((req_rec >> (map_ln + map_lp)) << (map_lb + map_lp)) + ((req_rec & ((c_one24 << map_ln) - 32'h1)) << map_lp) + ((req_rec >> map_ln) & ((c_one24 << map_lp) - 32'h1));
        mem_req_valid = req;
        mem_req_addr = req_addr;
        accept = req & mem_req_ready;
        tags$rsel = c_one16 << tag_head$q;
        resp_dst = tags$rdata;
        tags$wsel = 32'h0;
        if (accept) begin
            tags$wsel = c_one16 << tag_tail$q;
        end
        tags$wdata = req_dst;
        resp = mem_resp_valid & (tag_n$q != 32'h0);
        if (accept) begin
            tag_tail$d = tag_tail$q + 32'h1;
            if (~req_dst[32'h1]) begin
                ask_head$d = ask_head$q + 32'h1;
            end
            if (req_dst == 32'h2) begin
                ta_pend$d = 1'b1;
                ta_req_r$d = req_id;
            end
            if (req_dst == 32'h3) begin
                tb_pend$d = 1'b1;
                tb_req_r$d = req_id;
            end
        end
        if (accept & ~resp) begin
            tag_n$d = tag_n$q + 32'h1;
        end
        if (resp & ~accept) begin
            tag_n$d = tag_n$q - 32'h1;
        end
        wa$wsel = 32'h0;
        if (resp & (resp_dst == 32'h0)) begin
            wa$wsel = c_one16 << wa_tail$q;
        end
        wa$wdata = mem_resp_data[(32'h0)+:(1950)];
        wb$wsel = 32'h0;
        if (resp & (resp_dst == 32'h1)) begin
            wb$wsel = c_one16 << wb_tail$q;
        end
        wb$wdata = mem_resp_data[(32'h0)+:(1950)];
        if (resp) begin
            tag_head$d = tag_head$q + 32'h1;
            if (resp_dst == 32'h0) begin
                wa_tail$d = wa_tail$q + 32'h1;
            end
            if (resp_dst == 32'h1) begin
                wb_tail$d = wb_tail$q + 32'h1;
            end
            if (resp_dst == 32'h2) begin
                ta_pend$d = 1'b0;
            end
            if (resp_dst == 32'h3) begin
                tb_pend$d = 1'b0;
            end
        end
        if (issue) begin
            seq_head$d = seq_head$q + 32'h1;
            if (cur_fa) begin
                na_word$d = wa$rdata;
                wa_head$d = wa_head$q + 32'h1;
            end
            if (cur_fb) begin
                nb_word$d = wb$rdata;
                wb_head$d = wb_head$q + 32'h1;
            end
        end
        wa_n$d = wa_n$q + (((resp & (resp_dst == 32'h0))) & 5'h1f) - (((issue & cur_fa)) & 5'h1f);
        wb_n$d = wb_n$q + (((resp & (resp_dst == 32'h1))) & 5'h1f) - (((issue & cur_fb)) & 5'h1f);
        top_two = pop_entry[32'h42];
        if (pop) begin
            seq_tail$d = seq_tail$q + 32'h1 + ((top_two) & 5'h1f);
        end
        seq_tail1 = seq_tail$q + 32'h1;
        ask_off1 = ((pop_fetch[(32'h0)+:(1)]) & 5'h1f);
        ask_off2 = ask_off1 + ((pop_fetch[(32'h1)+:(1)]) & 5'h1f);
        ask_off3 = ask_off2 + ((pop_fetch[(32'h2)+:(1)]) & 5'h1f);
        ask_new = ask_off3 + ((pop_fetch[(32'h3)+:(1)]) & 5'h1f);
        put0 = c_one32 << ask_tail$q;
        put1 = c_one32 << (ask_tail$q + ask_off1);
        put2 = c_one32 << (ask_tail$q + ask_off2);
        put3 = c_one32 << (ask_tail$q + ask_off3);
        if (pop & pop_fetch[32'h0] & put0[0]) begin
            ask_w$0$d = ((pop_entry[(32'h0)+:(16)]) & 22'h3fffff) | (((seq_tail$q) & 22'h3fffff) << 32'h11);
        end
        if (pop & pop_fetch[32'h1] & put1[0]) begin
            ask_w$0$d = ((pop_entry[(32'h10)+:(16)]) & 22'h3fffff) | (((seq_tail$q) & 22'h3fffff) << 32'h11) | c_ask_b;
        end
        if (pop & pop_fetch[32'h2] & put2[0]) begin
            ask_w$0$d = ((pop_entry[(32'h21)+:(16)]) & 22'h3fffff) | (((seq_tail1) & 22'h3fffff) << 32'h11);
        end
        if (pop & pop_fetch[32'h3] & put3[0]) begin
            ask_w$0$d = ((pop_entry[(32'h31)+:(16)]) & 22'h3fffff) | (((seq_tail1) & 22'h3fffff) << 32'h11) | c_ask_b;
        end
        if (pop & pop_fetch[32'h0] & put0[1]) begin
            ask_w$1$d = ((pop_entry[(32'h0)+:(16)]) & 22'h3fffff) | (((seq_tail$q) & 22'h3fffff) << 32'h11);
        end
        if (pop & pop_fetch[32'h1] & put1[1]) begin
            ask_w$1$d = ((pop_entry[(32'h10)+:(16)]) & 22'h3fffff) | (((seq_tail$q) & 22'h3fffff) << 32'h11) | c_ask_b;
        end
        if (pop & pop_fetch[32'h2] & put2[1]) begin
            ask_w$1$d = ((pop_entry[(32'h21)+:(16)]) & 22'h3fffff) | (((seq_tail1) & 22'h3fffff) << 32'h11);
        end
        if (pop & pop_fetch[32'h3] & put3[1]) begin
            ask_w$1$d = ((pop_entry[(32'h31)+:(16)]) & 22'h3fffff) | (((seq_tail1) & 22'h3fffff) << 32'h11) | c_ask_b;
        end
        if (pop & pop_fetch[32'h0] & put0[2]) begin
            ask_w$2$d = ((pop_entry[(32'h0)+:(16)]) & 22'h3fffff) | (((seq_tail$q) & 22'h3fffff) << 32'h11);
        end
        if (pop & pop_fetch[32'h1] & put1[2]) begin
            ask_w$2$d = ((pop_entry[(32'h10)+:(16)]) & 22'h3fffff) | (((seq_tail$q) & 22'h3fffff) << 32'h11) | c_ask_b;
        end
        if (pop & pop_fetch[32'h2] & put2[2]) begin
            ask_w$2$d = ((pop_entry[(32'h21)+:(16)]) & 22'h3fffff) | (((seq_tail1) & 22'h3fffff) << 32'h11);
        end
        if (pop & pop_fetch[32'h3] & put3[2]) begin
            ask_w$2$d = ((pop_entry[(32'h31)+:(16)]) & 22'h3fffff) | (((seq_tail1) & 22'h3fffff) << 32'h11) | c_ask_b;
        end
        if (pop & pop_fetch[32'h0] & put0[3]) begin
            ask_w$3$d = ((pop_entry[(32'h0)+:(16)]) & 22'h3fffff) | (((seq_tail$q) & 22'h3fffff) << 32'h11);
        end
        if (pop & pop_fetch[32'h1] & put1[3]) begin
            ask_w$3$d = ((pop_entry[(32'h10)+:(16)]) & 22'h3fffff) | (((seq_tail$q) & 22'h3fffff) << 32'h11) | c_ask_b;
        end
        if (pop & pop_fetch[32'h2] & put2[3]) begin
            ask_w$3$d = ((pop_entry[(32'h21)+:(16)]) & 22'h3fffff) | (((seq_tail1) & 22'h3fffff) << 32'h11);
        end
        if (pop & pop_fetch[32'h3] & put3[3]) begin
            ask_w$3$d = ((pop_entry[(32'h31)+:(16)]) & 22'h3fffff) | (((seq_tail1) & 22'h3fffff) << 32'h11) | c_ask_b;
        end
        if (pop & pop_fetch[32'h0] & put0[4]) begin
            ask_w$4$d = ((pop_entry[(32'h0)+:(16)]) & 22'h3fffff) | (((seq_tail$q) & 22'h3fffff) << 32'h11);
        end
        if (pop & pop_fetch[32'h1] & put1[4]) begin
            ask_w$4$d = ((pop_entry[(32'h10)+:(16)]) & 22'h3fffff) | (((seq_tail$q) & 22'h3fffff) << 32'h11) | c_ask_b;
        end
        if (pop & pop_fetch[32'h2] & put2[4]) begin
            ask_w$4$d = ((pop_entry[(32'h21)+:(16)]) & 22'h3fffff) | (((seq_tail1) & 22'h3fffff) << 32'h11);
        end
        if (pop & pop_fetch[32'h3] & put3[4]) begin
            ask_w$4$d = ((pop_entry[(32'h31)+:(16)]) & 22'h3fffff) | (((seq_tail1) & 22'h3fffff) << 32'h11) | c_ask_b;
        end
        if (pop & pop_fetch[32'h0] & put0[5]) begin
            ask_w$5$d = ((pop_entry[(32'h0)+:(16)]) & 22'h3fffff) | (((seq_tail$q) & 22'h3fffff) << 32'h11);
        end
        if (pop & pop_fetch[32'h1] & put1[5]) begin
            ask_w$5$d = ((pop_entry[(32'h10)+:(16)]) & 22'h3fffff) | (((seq_tail$q) & 22'h3fffff) << 32'h11) | c_ask_b;
        end
        if (pop & pop_fetch[32'h2] & put2[5]) begin
            ask_w$5$d = ((pop_entry[(32'h21)+:(16)]) & 22'h3fffff) | (((seq_tail1) & 22'h3fffff) << 32'h11);
        end
        if (pop & pop_fetch[32'h3] & put3[5]) begin
            ask_w$5$d = ((pop_entry[(32'h31)+:(16)]) & 22'h3fffff) | (((seq_tail1) & 22'h3fffff) << 32'h11) | c_ask_b;
        end
        if (pop & pop_fetch[32'h0] & put0[6]) begin
            ask_w$6$d = ((pop_entry[(32'h0)+:(16)]) & 22'h3fffff) | (((seq_tail$q) & 22'h3fffff) << 32'h11);
        end
        if (pop & pop_fetch[32'h1] & put1[6]) begin
            ask_w$6$d = ((pop_entry[(32'h10)+:(16)]) & 22'h3fffff) | (((seq_tail$q) & 22'h3fffff) << 32'h11) | c_ask_b;
        end
        if (pop & pop_fetch[32'h2] & put2[6]) begin
            ask_w$6$d = ((pop_entry[(32'h21)+:(16)]) & 22'h3fffff) | (((seq_tail1) & 22'h3fffff) << 32'h11);
        end
        if (pop & pop_fetch[32'h3] & put3[6]) begin
            ask_w$6$d = ((pop_entry[(32'h31)+:(16)]) & 22'h3fffff) | (((seq_tail1) & 22'h3fffff) << 32'h11) | c_ask_b;
        end
        if (pop & pop_fetch[32'h0] & put0[7]) begin
            ask_w$7$d = ((pop_entry[(32'h0)+:(16)]) & 22'h3fffff) | (((seq_tail$q) & 22'h3fffff) << 32'h11);
        end
        if (pop & pop_fetch[32'h1] & put1[7]) begin
            ask_w$7$d = ((pop_entry[(32'h10)+:(16)]) & 22'h3fffff) | (((seq_tail$q) & 22'h3fffff) << 32'h11) | c_ask_b;
        end
        if (pop & pop_fetch[32'h2] & put2[7]) begin
            ask_w$7$d = ((pop_entry[(32'h21)+:(16)]) & 22'h3fffff) | (((seq_tail1) & 22'h3fffff) << 32'h11);
        end
        if (pop & pop_fetch[32'h3] & put3[7]) begin
            ask_w$7$d = ((pop_entry[(32'h31)+:(16)]) & 22'h3fffff) | (((seq_tail1) & 22'h3fffff) << 32'h11) | c_ask_b;
        end
        if (pop & pop_fetch[32'h0] & put0[8]) begin
            ask_w$8$d = ((pop_entry[(32'h0)+:(16)]) & 22'h3fffff) | (((seq_tail$q) & 22'h3fffff) << 32'h11);
        end
        if (pop & pop_fetch[32'h1] & put1[8]) begin
            ask_w$8$d = ((pop_entry[(32'h10)+:(16)]) & 22'h3fffff) | (((seq_tail$q) & 22'h3fffff) << 32'h11) | c_ask_b;
        end
        if (pop & pop_fetch[32'h2] & put2[8]) begin
            ask_w$8$d = ((pop_entry[(32'h21)+:(16)]) & 22'h3fffff) | (((seq_tail1) & 22'h3fffff) << 32'h11);
        end
        if (pop & pop_fetch[32'h3] & put3[8]) begin
            ask_w$8$d = ((pop_entry[(32'h31)+:(16)]) & 22'h3fffff) | (((seq_tail1) & 22'h3fffff) << 32'h11) | c_ask_b;
        end
        if (pop & pop_fetch[32'h0] & put0[9]) begin
            ask_w$9$d = ((pop_entry[(32'h0)+:(16)]) & 22'h3fffff) | (((seq_tail$q) & 22'h3fffff) << 32'h11);
        end
        if (pop & pop_fetch[32'h1] & put1[9]) begin
            ask_w$9$d = ((pop_entry[(32'h10)+:(16)]) & 22'h3fffff) | (((seq_tail$q) & 22'h3fffff) << 32'h11) | c_ask_b;
        end
        if (pop & pop_fetch[32'h2] & put2[9]) begin
            ask_w$9$d = ((pop_entry[(32'h21)+:(16)]) & 22'h3fffff) | (((seq_tail1) & 22'h3fffff) << 32'h11);
        end
        if (pop & pop_fetch[32'h3] & put3[9]) begin
            ask_w$9$d = ((pop_entry[(32'h31)+:(16)]) & 22'h3fffff) | (((seq_tail1) & 22'h3fffff) << 32'h11) | c_ask_b;
        end
        if (pop & pop_fetch[32'h0] & put0[10]) begin
            ask_w$10$d = ((pop_entry[(32'h0)+:(16)]) & 22'h3fffff) | (((seq_tail$q) & 22'h3fffff) << 32'h11);
        end
        if (pop & pop_fetch[32'h1] & put1[10]) begin
            ask_w$10$d = ((pop_entry[(32'h10)+:(16)]) & 22'h3fffff) | (((seq_tail$q) & 22'h3fffff) << 32'h11) | c_ask_b;
        end
        if (pop & pop_fetch[32'h2] & put2[10]) begin
            ask_w$10$d = ((pop_entry[(32'h21)+:(16)]) & 22'h3fffff) | (((seq_tail1) & 22'h3fffff) << 32'h11);
        end
        if (pop & pop_fetch[32'h3] & put3[10]) begin
            ask_w$10$d = ((pop_entry[(32'h31)+:(16)]) & 22'h3fffff) | (((seq_tail1) & 22'h3fffff) << 32'h11) | c_ask_b;
        end
        if (pop & pop_fetch[32'h0] & put0[11]) begin
            ask_w$11$d = ((pop_entry[(32'h0)+:(16)]) & 22'h3fffff) | (((seq_tail$q) & 22'h3fffff) << 32'h11);
        end
        if (pop & pop_fetch[32'h1] & put1[11]) begin
            ask_w$11$d = ((pop_entry[(32'h10)+:(16)]) & 22'h3fffff) | (((seq_tail$q) & 22'h3fffff) << 32'h11) | c_ask_b;
        end
        if (pop & pop_fetch[32'h2] & put2[11]) begin
            ask_w$11$d = ((pop_entry[(32'h21)+:(16)]) & 22'h3fffff) | (((seq_tail1) & 22'h3fffff) << 32'h11);
        end
        if (pop & pop_fetch[32'h3] & put3[11]) begin
            ask_w$11$d = ((pop_entry[(32'h31)+:(16)]) & 22'h3fffff) | (((seq_tail1) & 22'h3fffff) << 32'h11) | c_ask_b;
        end
        if (pop & pop_fetch[32'h0] & put0[12]) begin
            ask_w$12$d = ((pop_entry[(32'h0)+:(16)]) & 22'h3fffff) | (((seq_tail$q) & 22'h3fffff) << 32'h11);
        end
        if (pop & pop_fetch[32'h1] & put1[12]) begin
            ask_w$12$d = ((pop_entry[(32'h10)+:(16)]) & 22'h3fffff) | (((seq_tail$q) & 22'h3fffff) << 32'h11) | c_ask_b;
        end
        if (pop & pop_fetch[32'h2] & put2[12]) begin
            ask_w$12$d = ((pop_entry[(32'h21)+:(16)]) & 22'h3fffff) | (((seq_tail1) & 22'h3fffff) << 32'h11);
        end
        if (pop & pop_fetch[32'h3] & put3[12]) begin
            ask_w$12$d = ((pop_entry[(32'h31)+:(16)]) & 22'h3fffff) | (((seq_tail1) & 22'h3fffff) << 32'h11) | c_ask_b;
        end
        if (pop & pop_fetch[32'h0] & put0[13]) begin
            ask_w$13$d = ((pop_entry[(32'h0)+:(16)]) & 22'h3fffff) | (((seq_tail$q) & 22'h3fffff) << 32'h11);
        end
        if (pop & pop_fetch[32'h1] & put1[13]) begin
            ask_w$13$d = ((pop_entry[(32'h10)+:(16)]) & 22'h3fffff) | (((seq_tail$q) & 22'h3fffff) << 32'h11) | c_ask_b;
        end
        if (pop & pop_fetch[32'h2] & put2[13]) begin
            ask_w$13$d = ((pop_entry[(32'h21)+:(16)]) & 22'h3fffff) | (((seq_tail1) & 22'h3fffff) << 32'h11);
        end
        if (pop & pop_fetch[32'h3] & put3[13]) begin
            ask_w$13$d = ((pop_entry[(32'h31)+:(16)]) & 22'h3fffff) | (((seq_tail1) & 22'h3fffff) << 32'h11) | c_ask_b;
        end
        if (pop & pop_fetch[32'h0] & put0[14]) begin
            ask_w$14$d = ((pop_entry[(32'h0)+:(16)]) & 22'h3fffff) | (((seq_tail$q) & 22'h3fffff) << 32'h11);
        end
        if (pop & pop_fetch[32'h1] & put1[14]) begin
            ask_w$14$d = ((pop_entry[(32'h10)+:(16)]) & 22'h3fffff) | (((seq_tail$q) & 22'h3fffff) << 32'h11) | c_ask_b;
        end
        if (pop & pop_fetch[32'h2] & put2[14]) begin
            ask_w$14$d = ((pop_entry[(32'h21)+:(16)]) & 22'h3fffff) | (((seq_tail1) & 22'h3fffff) << 32'h11);
        end
        if (pop & pop_fetch[32'h3] & put3[14]) begin
            ask_w$14$d = ((pop_entry[(32'h31)+:(16)]) & 22'h3fffff) | (((seq_tail1) & 22'h3fffff) << 32'h11) | c_ask_b;
        end
        if (pop & pop_fetch[32'h0] & put0[15]) begin
            ask_w$15$d = ((pop_entry[(32'h0)+:(16)]) & 22'h3fffff) | (((seq_tail$q) & 22'h3fffff) << 32'h11);
        end
        if (pop & pop_fetch[32'h1] & put1[15]) begin
            ask_w$15$d = ((pop_entry[(32'h10)+:(16)]) & 22'h3fffff) | (((seq_tail$q) & 22'h3fffff) << 32'h11) | c_ask_b;
        end
        if (pop & pop_fetch[32'h2] & put2[15]) begin
            ask_w$15$d = ((pop_entry[(32'h21)+:(16)]) & 22'h3fffff) | (((seq_tail1) & 22'h3fffff) << 32'h11);
        end
        if (pop & pop_fetch[32'h3] & put3[15]) begin
            ask_w$15$d = ((pop_entry[(32'h31)+:(16)]) & 22'h3fffff) | (((seq_tail1) & 22'h3fffff) << 32'h11) | c_ask_b;
        end
        if (pop & pop_fetch[32'h0] & put0[16]) begin
            ask_w$16$d = ((pop_entry[(32'h0)+:(16)]) & 22'h3fffff) | (((seq_tail$q) & 22'h3fffff) << 32'h11);
        end
        if (pop & pop_fetch[32'h1] & put1[16]) begin
            ask_w$16$d = ((pop_entry[(32'h10)+:(16)]) & 22'h3fffff) | (((seq_tail$q) & 22'h3fffff) << 32'h11) | c_ask_b;
        end
        if (pop & pop_fetch[32'h2] & put2[16]) begin
            ask_w$16$d = ((pop_entry[(32'h21)+:(16)]) & 22'h3fffff) | (((seq_tail1) & 22'h3fffff) << 32'h11);
        end
        if (pop & pop_fetch[32'h3] & put3[16]) begin
            ask_w$16$d = ((pop_entry[(32'h31)+:(16)]) & 22'h3fffff) | (((seq_tail1) & 22'h3fffff) << 32'h11) | c_ask_b;
        end
        if (pop & pop_fetch[32'h0] & put0[17]) begin
            ask_w$17$d = ((pop_entry[(32'h0)+:(16)]) & 22'h3fffff) | (((seq_tail$q) & 22'h3fffff) << 32'h11);
        end
        if (pop & pop_fetch[32'h1] & put1[17]) begin
            ask_w$17$d = ((pop_entry[(32'h10)+:(16)]) & 22'h3fffff) | (((seq_tail$q) & 22'h3fffff) << 32'h11) | c_ask_b;
        end
        if (pop & pop_fetch[32'h2] & put2[17]) begin
            ask_w$17$d = ((pop_entry[(32'h21)+:(16)]) & 22'h3fffff) | (((seq_tail1) & 22'h3fffff) << 32'h11);
        end
        if (pop & pop_fetch[32'h3] & put3[17]) begin
            ask_w$17$d = ((pop_entry[(32'h31)+:(16)]) & 22'h3fffff) | (((seq_tail1) & 22'h3fffff) << 32'h11) | c_ask_b;
        end
        if (pop & pop_fetch[32'h0] & put0[18]) begin
            ask_w$18$d = ((pop_entry[(32'h0)+:(16)]) & 22'h3fffff) | (((seq_tail$q) & 22'h3fffff) << 32'h11);
        end
        if (pop & pop_fetch[32'h1] & put1[18]) begin
            ask_w$18$d = ((pop_entry[(32'h10)+:(16)]) & 22'h3fffff) | (((seq_tail$q) & 22'h3fffff) << 32'h11) | c_ask_b;
        end
        if (pop & pop_fetch[32'h2] & put2[18]) begin
            ask_w$18$d = ((pop_entry[(32'h21)+:(16)]) & 22'h3fffff) | (((seq_tail1) & 22'h3fffff) << 32'h11);
        end
        if (pop & pop_fetch[32'h3] & put3[18]) begin
            ask_w$18$d = ((pop_entry[(32'h31)+:(16)]) & 22'h3fffff) | (((seq_tail1) & 22'h3fffff) << 32'h11) | c_ask_b;
        end
        if (pop & pop_fetch[32'h0] & put0[19]) begin
            ask_w$19$d = ((pop_entry[(32'h0)+:(16)]) & 22'h3fffff) | (((seq_tail$q) & 22'h3fffff) << 32'h11);
        end
        if (pop & pop_fetch[32'h1] & put1[19]) begin
            ask_w$19$d = ((pop_entry[(32'h10)+:(16)]) & 22'h3fffff) | (((seq_tail$q) & 22'h3fffff) << 32'h11) | c_ask_b;
        end
        if (pop & pop_fetch[32'h2] & put2[19]) begin
            ask_w$19$d = ((pop_entry[(32'h21)+:(16)]) & 22'h3fffff) | (((seq_tail1) & 22'h3fffff) << 32'h11);
        end
        if (pop & pop_fetch[32'h3] & put3[19]) begin
            ask_w$19$d = ((pop_entry[(32'h31)+:(16)]) & 22'h3fffff) | (((seq_tail1) & 22'h3fffff) << 32'h11) | c_ask_b;
        end
        if (pop & pop_fetch[32'h0] & put0[20]) begin
            ask_w$20$d = ((pop_entry[(32'h0)+:(16)]) & 22'h3fffff) | (((seq_tail$q) & 22'h3fffff) << 32'h11);
        end
        if (pop & pop_fetch[32'h1] & put1[20]) begin
            ask_w$20$d = ((pop_entry[(32'h10)+:(16)]) & 22'h3fffff) | (((seq_tail$q) & 22'h3fffff) << 32'h11) | c_ask_b;
        end
        if (pop & pop_fetch[32'h2] & put2[20]) begin
            ask_w$20$d = ((pop_entry[(32'h21)+:(16)]) & 22'h3fffff) | (((seq_tail1) & 22'h3fffff) << 32'h11);
        end
        if (pop & pop_fetch[32'h3] & put3[20]) begin
            ask_w$20$d = ((pop_entry[(32'h31)+:(16)]) & 22'h3fffff) | (((seq_tail1) & 22'h3fffff) << 32'h11) | c_ask_b;
        end
        if (pop & pop_fetch[32'h0] & put0[21]) begin
            ask_w$21$d = ((pop_entry[(32'h0)+:(16)]) & 22'h3fffff) | (((seq_tail$q) & 22'h3fffff) << 32'h11);
        end
        if (pop & pop_fetch[32'h1] & put1[21]) begin
            ask_w$21$d = ((pop_entry[(32'h10)+:(16)]) & 22'h3fffff) | (((seq_tail$q) & 22'h3fffff) << 32'h11) | c_ask_b;
        end
        if (pop & pop_fetch[32'h2] & put2[21]) begin
            ask_w$21$d = ((pop_entry[(32'h21)+:(16)]) & 22'h3fffff) | (((seq_tail1) & 22'h3fffff) << 32'h11);
        end
        if (pop & pop_fetch[32'h3] & put3[21]) begin
            ask_w$21$d = ((pop_entry[(32'h31)+:(16)]) & 22'h3fffff) | (((seq_tail1) & 22'h3fffff) << 32'h11) | c_ask_b;
        end
        if (pop & pop_fetch[32'h0] & put0[22]) begin
            ask_w$22$d = ((pop_entry[(32'h0)+:(16)]) & 22'h3fffff) | (((seq_tail$q) & 22'h3fffff) << 32'h11);
        end
        if (pop & pop_fetch[32'h1] & put1[22]) begin
            ask_w$22$d = ((pop_entry[(32'h10)+:(16)]) & 22'h3fffff) | (((seq_tail$q) & 22'h3fffff) << 32'h11) | c_ask_b;
        end
        if (pop & pop_fetch[32'h2] & put2[22]) begin
            ask_w$22$d = ((pop_entry[(32'h21)+:(16)]) & 22'h3fffff) | (((seq_tail1) & 22'h3fffff) << 32'h11);
        end
        if (pop & pop_fetch[32'h3] & put3[22]) begin
            ask_w$22$d = ((pop_entry[(32'h31)+:(16)]) & 22'h3fffff) | (((seq_tail1) & 22'h3fffff) << 32'h11) | c_ask_b;
        end
        if (pop & pop_fetch[32'h0] & put0[23]) begin
            ask_w$23$d = ((pop_entry[(32'h0)+:(16)]) & 22'h3fffff) | (((seq_tail$q) & 22'h3fffff) << 32'h11);
        end
        if (pop & pop_fetch[32'h1] & put1[23]) begin
            ask_w$23$d = ((pop_entry[(32'h10)+:(16)]) & 22'h3fffff) | (((seq_tail$q) & 22'h3fffff) << 32'h11) | c_ask_b;
        end
        if (pop & pop_fetch[32'h2] & put2[23]) begin
            ask_w$23$d = ((pop_entry[(32'h21)+:(16)]) & 22'h3fffff) | (((seq_tail1) & 22'h3fffff) << 32'h11);
        end
        if (pop & pop_fetch[32'h3] & put3[23]) begin
            ask_w$23$d = ((pop_entry[(32'h31)+:(16)]) & 22'h3fffff) | (((seq_tail1) & 22'h3fffff) << 32'h11) | c_ask_b;
        end
        if (pop & pop_fetch[32'h0] & put0[24]) begin
            ask_w$24$d = ((pop_entry[(32'h0)+:(16)]) & 22'h3fffff) | (((seq_tail$q) & 22'h3fffff) << 32'h11);
        end
        if (pop & pop_fetch[32'h1] & put1[24]) begin
            ask_w$24$d = ((pop_entry[(32'h10)+:(16)]) & 22'h3fffff) | (((seq_tail$q) & 22'h3fffff) << 32'h11) | c_ask_b;
        end
        if (pop & pop_fetch[32'h2] & put2[24]) begin
            ask_w$24$d = ((pop_entry[(32'h21)+:(16)]) & 22'h3fffff) | (((seq_tail1) & 22'h3fffff) << 32'h11);
        end
        if (pop & pop_fetch[32'h3] & put3[24]) begin
            ask_w$24$d = ((pop_entry[(32'h31)+:(16)]) & 22'h3fffff) | (((seq_tail1) & 22'h3fffff) << 32'h11) | c_ask_b;
        end
        if (pop & pop_fetch[32'h0] & put0[25]) begin
            ask_w$25$d = ((pop_entry[(32'h0)+:(16)]) & 22'h3fffff) | (((seq_tail$q) & 22'h3fffff) << 32'h11);
        end
        if (pop & pop_fetch[32'h1] & put1[25]) begin
            ask_w$25$d = ((pop_entry[(32'h10)+:(16)]) & 22'h3fffff) | (((seq_tail$q) & 22'h3fffff) << 32'h11) | c_ask_b;
        end
        if (pop & pop_fetch[32'h2] & put2[25]) begin
            ask_w$25$d = ((pop_entry[(32'h21)+:(16)]) & 22'h3fffff) | (((seq_tail1) & 22'h3fffff) << 32'h11);
        end
        if (pop & pop_fetch[32'h3] & put3[25]) begin
            ask_w$25$d = ((pop_entry[(32'h31)+:(16)]) & 22'h3fffff) | (((seq_tail1) & 22'h3fffff) << 32'h11) | c_ask_b;
        end
        if (pop & pop_fetch[32'h0] & put0[26]) begin
            ask_w$26$d = ((pop_entry[(32'h0)+:(16)]) & 22'h3fffff) | (((seq_tail$q) & 22'h3fffff) << 32'h11);
        end
        if (pop & pop_fetch[32'h1] & put1[26]) begin
            ask_w$26$d = ((pop_entry[(32'h10)+:(16)]) & 22'h3fffff) | (((seq_tail$q) & 22'h3fffff) << 32'h11) | c_ask_b;
        end
        if (pop & pop_fetch[32'h2] & put2[26]) begin
            ask_w$26$d = ((pop_entry[(32'h21)+:(16)]) & 22'h3fffff) | (((seq_tail1) & 22'h3fffff) << 32'h11);
        end
        if (pop & pop_fetch[32'h3] & put3[26]) begin
            ask_w$26$d = ((pop_entry[(32'h31)+:(16)]) & 22'h3fffff) | (((seq_tail1) & 22'h3fffff) << 32'h11) | c_ask_b;
        end
        if (pop & pop_fetch[32'h0] & put0[27]) begin
            ask_w$27$d = ((pop_entry[(32'h0)+:(16)]) & 22'h3fffff) | (((seq_tail$q) & 22'h3fffff) << 32'h11);
        end
        if (pop & pop_fetch[32'h1] & put1[27]) begin
            ask_w$27$d = ((pop_entry[(32'h10)+:(16)]) & 22'h3fffff) | (((seq_tail$q) & 22'h3fffff) << 32'h11) | c_ask_b;
        end
        if (pop & pop_fetch[32'h2] & put2[27]) begin
            ask_w$27$d = ((pop_entry[(32'h21)+:(16)]) & 22'h3fffff) | (((seq_tail1) & 22'h3fffff) << 32'h11);
        end
        if (pop & pop_fetch[32'h3] & put3[27]) begin
            ask_w$27$d = ((pop_entry[(32'h31)+:(16)]) & 22'h3fffff) | (((seq_tail1) & 22'h3fffff) << 32'h11) | c_ask_b;
        end
        if (pop & pop_fetch[32'h0] & put0[28]) begin
            ask_w$28$d = ((pop_entry[(32'h0)+:(16)]) & 22'h3fffff) | (((seq_tail$q) & 22'h3fffff) << 32'h11);
        end
        if (pop & pop_fetch[32'h1] & put1[28]) begin
            ask_w$28$d = ((pop_entry[(32'h10)+:(16)]) & 22'h3fffff) | (((seq_tail$q) & 22'h3fffff) << 32'h11) | c_ask_b;
        end
        if (pop & pop_fetch[32'h2] & put2[28]) begin
            ask_w$28$d = ((pop_entry[(32'h21)+:(16)]) & 22'h3fffff) | (((seq_tail1) & 22'h3fffff) << 32'h11);
        end
        if (pop & pop_fetch[32'h3] & put3[28]) begin
            ask_w$28$d = ((pop_entry[(32'h31)+:(16)]) & 22'h3fffff) | (((seq_tail1) & 22'h3fffff) << 32'h11) | c_ask_b;
        end
        if (pop & pop_fetch[32'h0] & put0[29]) begin
            ask_w$29$d = ((pop_entry[(32'h0)+:(16)]) & 22'h3fffff) | (((seq_tail$q) & 22'h3fffff) << 32'h11);
        end
        if (pop & pop_fetch[32'h1] & put1[29]) begin
            ask_w$29$d = ((pop_entry[(32'h10)+:(16)]) & 22'h3fffff) | (((seq_tail$q) & 22'h3fffff) << 32'h11) | c_ask_b;
        end
        if (pop & pop_fetch[32'h2] & put2[29]) begin
            ask_w$29$d = ((pop_entry[(32'h21)+:(16)]) & 22'h3fffff) | (((seq_tail1) & 22'h3fffff) << 32'h11);
        end
        if (pop & pop_fetch[32'h3] & put3[29]) begin
            ask_w$29$d = ((pop_entry[(32'h31)+:(16)]) & 22'h3fffff) | (((seq_tail1) & 22'h3fffff) << 32'h11) | c_ask_b;
        end
        if (pop & pop_fetch[32'h0] & put0[30]) begin
            ask_w$30$d = ((pop_entry[(32'h0)+:(16)]) & 22'h3fffff) | (((seq_tail$q) & 22'h3fffff) << 32'h11);
        end
        if (pop & pop_fetch[32'h1] & put1[30]) begin
            ask_w$30$d = ((pop_entry[(32'h10)+:(16)]) & 22'h3fffff) | (((seq_tail$q) & 22'h3fffff) << 32'h11) | c_ask_b;
        end
        if (pop & pop_fetch[32'h2] & put2[30]) begin
            ask_w$30$d = ((pop_entry[(32'h21)+:(16)]) & 22'h3fffff) | (((seq_tail1) & 22'h3fffff) << 32'h11);
        end
        if (pop & pop_fetch[32'h3] & put3[30]) begin
            ask_w$30$d = ((pop_entry[(32'h31)+:(16)]) & 22'h3fffff) | (((seq_tail1) & 22'h3fffff) << 32'h11) | c_ask_b;
        end
        if (pop & pop_fetch[32'h0] & put0[31]) begin
            ask_w$31$d = ((pop_entry[(32'h0)+:(16)]) & 22'h3fffff) | (((seq_tail$q) & 22'h3fffff) << 32'h11);
        end
        if (pop & pop_fetch[32'h1] & put1[31]) begin
            ask_w$31$d = ((pop_entry[(32'h10)+:(16)]) & 22'h3fffff) | (((seq_tail$q) & 22'h3fffff) << 32'h11) | c_ask_b;
        end
        if (pop & pop_fetch[32'h2] & put2[31]) begin
            ask_w$31$d = ((pop_entry[(32'h21)+:(16)]) & 22'h3fffff) | (((seq_tail1) & 22'h3fffff) << 32'h11);
        end
        if (pop & pop_fetch[32'h3] & put3[31]) begin
            ask_w$31$d = ((pop_entry[(32'h31)+:(16)]) & 22'h3fffff) | (((seq_tail1) & 22'h3fffff) << 32'h11) | c_ask_b;
        end
        ask_take = accept & ~req_dst[32'h1];
        ask_n$d = ask_n$q - ((ask_take) & 6'h3f);
        if (pop) begin
            ask_tail$d = ask_tail$q + ask_new;
            ask_n$d = ask_n$q - ((ask_take) & 6'h3f) + ((ask_new) & 6'h3f);
        end
        if (clear) begin
            ask_head$d = 32'h0;
            ask_tail$d = 32'h0;
            ask_n$d = 32'h0;
            seq_head$d = 32'h0;
            seq_tail$d = 32'h0;
            wa_head$d = 32'h0;
            wa_tail$d = 32'h0;
            wa_n$d = 32'h0;
            wb_head$d = 32'h0;
            wb_tail$d = 32'h0;
            wb_n$d = 32'h0;
        end
        ta_req = ta_req_r$q;
        tb_req = tb_req_r$q;
        outstanding = tag_n$q != 32'h0;
    end
    
endmodule // top$mem_port


module top$mem_port$ask_w$0(d,q,clock);
    
    // Module arguments
    input wire  [21:0] d;
    output reg  [21:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 22'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$mem_port$ask_w$0


module top$mem_port$na_word(d,q,clock);
    
    // Module arguments
    input wire  [1949:0] d;
    output reg  [1949:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1950'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$mem_port$na_word


module top$mem_port$tags(clock,wsel,wdata,rsel,rdata);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] wsel;
    input wire  [1:0] wdata;
    input wire  [15:0] rsel;
    output reg  [1:0] rdata;
    
    // Stub signals
    reg  [1:0] row$0$d;
    wire  [1:0] row$0$q;
    reg  row$0$clock;
    reg  [1:0] row$1$d;
    wire  [1:0] row$1$q;
    reg  row$1$clock;
    reg  [1:0] row$2$d;
    wire  [1:0] row$2$q;
    reg  row$2$clock;
    reg  [1:0] row$3$d;
    wire  [1:0] row$3$q;
    reg  row$3$clock;
    reg  [1:0] row$4$d;
    wire  [1:0] row$4$q;
    reg  row$4$clock;
    reg  [1:0] row$5$d;
    wire  [1:0] row$5$q;
    reg  row$5$clock;
    reg  [1:0] row$6$d;
    wire  [1:0] row$6$q;
    reg  row$6$clock;
    reg  [1:0] row$7$d;
    wire  [1:0] row$7$q;
    reg  row$7$clock;
    reg  [1:0] row$8$d;
    wire  [1:0] row$8$q;
    reg  row$8$clock;
    reg  [1:0] row$9$d;
    wire  [1:0] row$9$q;
    reg  row$9$clock;
    reg  [1:0] row$10$d;
    wire  [1:0] row$10$q;
    reg  row$10$clock;
    reg  [1:0] row$11$d;
    wire  [1:0] row$11$q;
    reg  row$11$clock;
    reg  [1:0] row$12$d;
    wire  [1:0] row$12$q;
    reg  row$12$clock;
    reg  [1:0] row$13$d;
    wire  [1:0] row$13$q;
    reg  row$13$clock;
    reg  [1:0] row$14$d;
    wire  [1:0] row$14$q;
    reg  row$14$clock;
    reg  [1:0] row$15$d;
    wire  [1:0] row$15$q;
    reg  row$15$clock;
    
    // Local signals
    reg  [1:0] picked;
    
    // Sub module instances
    top$mem_port$tags$row$0 row$0(
        .d(row$0$d),
        .q(row$0$q),
        .clock(row$0$clock)
    );
    top$mem_port$tags$row$0 row$1(
        .d(row$1$d),
        .q(row$1$q),
        .clock(row$1$clock)
    );
    top$mem_port$tags$row$0 row$2(
        .d(row$2$d),
        .q(row$2$q),
        .clock(row$2$clock)
    );
    top$mem_port$tags$row$0 row$3(
        .d(row$3$d),
        .q(row$3$q),
        .clock(row$3$clock)
    );
    top$mem_port$tags$row$0 row$4(
        .d(row$4$d),
        .q(row$4$q),
        .clock(row$4$clock)
    );
    top$mem_port$tags$row$0 row$5(
        .d(row$5$d),
        .q(row$5$q),
        .clock(row$5$clock)
    );
    top$mem_port$tags$row$0 row$6(
        .d(row$6$d),
        .q(row$6$q),
        .clock(row$6$clock)
    );
    top$mem_port$tags$row$0 row$7(
        .d(row$7$d),
        .q(row$7$q),
        .clock(row$7$clock)
    );
    top$mem_port$tags$row$0 row$8(
        .d(row$8$d),
        .q(row$8$q),
        .clock(row$8$clock)
    );
    top$mem_port$tags$row$0 row$9(
        .d(row$9$d),
        .q(row$9$q),
        .clock(row$9$clock)
    );
    top$mem_port$tags$row$0 row$10(
        .d(row$10$d),
        .q(row$10$q),
        .clock(row$10$clock)
    );
    top$mem_port$tags$row$0 row$11(
        .d(row$11$d),
        .q(row$11$q),
        .clock(row$11$clock)
    );
    top$mem_port$tags$row$0 row$12(
        .d(row$12$d),
        .q(row$12$q),
        .clock(row$12$clock)
    );
    top$mem_port$tags$row$0 row$13(
        .d(row$13$d),
        .q(row$13$q),
        .clock(row$13$clock)
    );
    top$mem_port$tags$row$0 row$14(
        .d(row$14$d),
        .q(row$14$q),
        .clock(row$14$clock)
    );
    top$mem_port$tags$row$0 row$15(
        .d(row$15$d),
        .q(row$15$q),
        .clock(row$15$clock)
    );
    
    // Update code
    always @(*) begin
        picked = 32'h0;
        row$0$clock = clock;
        row$0$d = row$0$q;
        if (wsel[0]) begin
            row$0$d = wdata;
        end
        if (rsel[0]) begin
            picked = row$0$q;
        end
        row$1$clock = clock;
        row$1$d = row$1$q;
        if (wsel[1]) begin
            row$1$d = wdata;
        end
        if (rsel[1]) begin
            picked = row$1$q;
        end
        row$2$clock = clock;
        row$2$d = row$2$q;
        if (wsel[2]) begin
            row$2$d = wdata;
        end
        if (rsel[2]) begin
            picked = row$2$q;
        end
        row$3$clock = clock;
        row$3$d = row$3$q;
        if (wsel[3]) begin
            row$3$d = wdata;
        end
        if (rsel[3]) begin
            picked = row$3$q;
        end
        row$4$clock = clock;
        row$4$d = row$4$q;
        if (wsel[4]) begin
            row$4$d = wdata;
        end
        if (rsel[4]) begin
            picked = row$4$q;
        end
        row$5$clock = clock;
        row$5$d = row$5$q;
        if (wsel[5]) begin
            row$5$d = wdata;
        end
        if (rsel[5]) begin
            picked = row$5$q;
        end
        row$6$clock = clock;
        row$6$d = row$6$q;
        if (wsel[6]) begin
            row$6$d = wdata;
        end
        if (rsel[6]) begin
            picked = row$6$q;
        end
        row$7$clock = clock;
        row$7$d = row$7$q;
        if (wsel[7]) begin
            row$7$d = wdata;
        end
        if (rsel[7]) begin
            picked = row$7$q;
        end
        row$8$clock = clock;
        row$8$d = row$8$q;
        if (wsel[8]) begin
            row$8$d = wdata;
        end
        if (rsel[8]) begin
            picked = row$8$q;
        end
        row$9$clock = clock;
        row$9$d = row$9$q;
        if (wsel[9]) begin
            row$9$d = wdata;
        end
        if (rsel[9]) begin
            picked = row$9$q;
        end
        row$10$clock = clock;
        row$10$d = row$10$q;
        if (wsel[10]) begin
            row$10$d = wdata;
        end
        if (rsel[10]) begin
            picked = row$10$q;
        end
        row$11$clock = clock;
        row$11$d = row$11$q;
        if (wsel[11]) begin
            row$11$d = wdata;
        end
        if (rsel[11]) begin
            picked = row$11$q;
        end
        row$12$clock = clock;
        row$12$d = row$12$q;
        if (wsel[12]) begin
            row$12$d = wdata;
        end
        if (rsel[12]) begin
            picked = row$12$q;
        end
        row$13$clock = clock;
        row$13$d = row$13$q;
        if (wsel[13]) begin
            row$13$d = wdata;
        end
        if (rsel[13]) begin
            picked = row$13$q;
        end
        row$14$clock = clock;
        row$14$d = row$14$q;
        if (wsel[14]) begin
            row$14$d = wdata;
        end
        if (rsel[14]) begin
            picked = row$14$q;
        end
        row$15$clock = clock;
        row$15$d = row$15$q;
        if (wsel[15]) begin
            row$15$d = wdata;
        end
        if (rsel[15]) begin
            picked = row$15$q;
        end
        rdata = picked;
    end
    
endmodule // top$mem_port$tags


module top$mem_port$tags$row$0(d,q,clock);
    
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
          
endmodule // top$mem_port$tags$row$0


module top$mem_port$wa(clock,wsel,wdata,rsel,rdata);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] wsel;
    input wire  [1949:0] wdata;
    input wire  [15:0] rsel;
    output reg  [1949:0] rdata;
    
    // Stub signals
    reg  [1949:0] row$0$d;
    wire  [1949:0] row$0$q;
    reg  row$0$clock;
    reg  [1949:0] row$1$d;
    wire  [1949:0] row$1$q;
    reg  row$1$clock;
    reg  [1949:0] row$2$d;
    wire  [1949:0] row$2$q;
    reg  row$2$clock;
    reg  [1949:0] row$3$d;
    wire  [1949:0] row$3$q;
    reg  row$3$clock;
    reg  [1949:0] row$4$d;
    wire  [1949:0] row$4$q;
    reg  row$4$clock;
    reg  [1949:0] row$5$d;
    wire  [1949:0] row$5$q;
    reg  row$5$clock;
    reg  [1949:0] row$6$d;
    wire  [1949:0] row$6$q;
    reg  row$6$clock;
    reg  [1949:0] row$7$d;
    wire  [1949:0] row$7$q;
    reg  row$7$clock;
    reg  [1949:0] row$8$d;
    wire  [1949:0] row$8$q;
    reg  row$8$clock;
    reg  [1949:0] row$9$d;
    wire  [1949:0] row$9$q;
    reg  row$9$clock;
    reg  [1949:0] row$10$d;
    wire  [1949:0] row$10$q;
    reg  row$10$clock;
    reg  [1949:0] row$11$d;
    wire  [1949:0] row$11$q;
    reg  row$11$clock;
    reg  [1949:0] row$12$d;
    wire  [1949:0] row$12$q;
    reg  row$12$clock;
    reg  [1949:0] row$13$d;
    wire  [1949:0] row$13$q;
    reg  row$13$clock;
    reg  [1949:0] row$14$d;
    wire  [1949:0] row$14$q;
    reg  row$14$clock;
    reg  [1949:0] row$15$d;
    wire  [1949:0] row$15$q;
    reg  row$15$clock;
    
    // Local signals
    reg  [1949:0] picked;
    
    // Sub module instances
    top$mem_port$na_word row$0(
        .d(row$0$d),
        .q(row$0$q),
        .clock(row$0$clock)
    );
    top$mem_port$na_word row$1(
        .d(row$1$d),
        .q(row$1$q),
        .clock(row$1$clock)
    );
    top$mem_port$na_word row$2(
        .d(row$2$d),
        .q(row$2$q),
        .clock(row$2$clock)
    );
    top$mem_port$na_word row$3(
        .d(row$3$d),
        .q(row$3$q),
        .clock(row$3$clock)
    );
    top$mem_port$na_word row$4(
        .d(row$4$d),
        .q(row$4$q),
        .clock(row$4$clock)
    );
    top$mem_port$na_word row$5(
        .d(row$5$d),
        .q(row$5$q),
        .clock(row$5$clock)
    );
    top$mem_port$na_word row$6(
        .d(row$6$d),
        .q(row$6$q),
        .clock(row$6$clock)
    );
    top$mem_port$na_word row$7(
        .d(row$7$d),
        .q(row$7$q),
        .clock(row$7$clock)
    );
    top$mem_port$na_word row$8(
        .d(row$8$d),
        .q(row$8$q),
        .clock(row$8$clock)
    );
    top$mem_port$na_word row$9(
        .d(row$9$d),
        .q(row$9$q),
        .clock(row$9$clock)
    );
    top$mem_port$na_word row$10(
        .d(row$10$d),
        .q(row$10$q),
        .clock(row$10$clock)
    );
    top$mem_port$na_word row$11(
        .d(row$11$d),
        .q(row$11$q),
        .clock(row$11$clock)
    );
    top$mem_port$na_word row$12(
        .d(row$12$d),
        .q(row$12$q),
        .clock(row$12$clock)
    );
    top$mem_port$na_word row$13(
        .d(row$13$d),
        .q(row$13$q),
        .clock(row$13$clock)
    );
    top$mem_port$na_word row$14(
        .d(row$14$d),
        .q(row$14$q),
        .clock(row$14$clock)
    );
    top$mem_port$na_word row$15(
        .d(row$15$d),
        .q(row$15$q),
        .clock(row$15$clock)
    );
    
    // Update code
    always @(*) begin
        picked = 32'h0;
        row$0$clock = clock;
        row$0$d = row$0$q;
        if (wsel[0]) begin
            row$0$d = wdata;
        end
        if (rsel[0]) begin
            picked = row$0$q;
        end
        row$1$clock = clock;
        row$1$d = row$1$q;
        if (wsel[1]) begin
            row$1$d = wdata;
        end
        if (rsel[1]) begin
            picked = row$1$q;
        end
        row$2$clock = clock;
        row$2$d = row$2$q;
        if (wsel[2]) begin
            row$2$d = wdata;
        end
        if (rsel[2]) begin
            picked = row$2$q;
        end
        row$3$clock = clock;
        row$3$d = row$3$q;
        if (wsel[3]) begin
            row$3$d = wdata;
        end
        if (rsel[3]) begin
            picked = row$3$q;
        end
        row$4$clock = clock;
        row$4$d = row$4$q;
        if (wsel[4]) begin
            row$4$d = wdata;
        end
        if (rsel[4]) begin
            picked = row$4$q;
        end
        row$5$clock = clock;
        row$5$d = row$5$q;
        if (wsel[5]) begin
            row$5$d = wdata;
        end
        if (rsel[5]) begin
            picked = row$5$q;
        end
        row$6$clock = clock;
        row$6$d = row$6$q;
        if (wsel[6]) begin
            row$6$d = wdata;
        end
        if (rsel[6]) begin
            picked = row$6$q;
        end
        row$7$clock = clock;
        row$7$d = row$7$q;
        if (wsel[7]) begin
            row$7$d = wdata;
        end
        if (rsel[7]) begin
            picked = row$7$q;
        end
        row$8$clock = clock;
        row$8$d = row$8$q;
        if (wsel[8]) begin
            row$8$d = wdata;
        end
        if (rsel[8]) begin
            picked = row$8$q;
        end
        row$9$clock = clock;
        row$9$d = row$9$q;
        if (wsel[9]) begin
            row$9$d = wdata;
        end
        if (rsel[9]) begin
            picked = row$9$q;
        end
        row$10$clock = clock;
        row$10$d = row$10$q;
        if (wsel[10]) begin
            row$10$d = wdata;
        end
        if (rsel[10]) begin
            picked = row$10$q;
        end
        row$11$clock = clock;
        row$11$d = row$11$q;
        if (wsel[11]) begin
            row$11$d = wdata;
        end
        if (rsel[11]) begin
            picked = row$11$q;
        end
        row$12$clock = clock;
        row$12$d = row$12$q;
        if (wsel[12]) begin
            row$12$d = wdata;
        end
        if (rsel[12]) begin
            picked = row$12$q;
        end
        row$13$clock = clock;
        row$13$d = row$13$q;
        if (wsel[13]) begin
            row$13$d = wdata;
        end
        if (rsel[13]) begin
            picked = row$13$q;
        end
        row$14$clock = clock;
        row$14$d = row$14$q;
        if (wsel[14]) begin
            row$14$d = wdata;
        end
        if (rsel[14]) begin
            picked = row$14$q;
        end
        row$15$clock = clock;
        row$15$d = row$15$q;
        if (wsel[15]) begin
            row$15$d = wdata;
        end
        if (rsel[15]) begin
            picked = row$15$q;
        end
        rdata = picked;
    end
    
endmodule // top$mem_port$wa


module top$mode_slot(d,q,clock);
    
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
          
endmodule // top$mode_slot


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
    top$dop$dec_d$0$s0_ef open_r(
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


module top$side(clock,d,q);
    
    // Module arguments
    input wire  clock;
    input wire  [98:0] d;
    output reg  [98:0] q;
    
    // Stub signals
    reg  [98:0] line$0$d;
    wire  [98:0] line$0$q;
    reg  line$0$clock;
    reg  [98:0] line$1$d;
    wire  [98:0] line$1$q;
    reg  line$1$clock;
    reg  [98:0] line$2$d;
    wire  [98:0] line$2$q;
    reg  line$2$clock;
    reg  [98:0] line$3$d;
    wire  [98:0] line$3$q;
    reg  line$3$clock;
    reg  [98:0] line$4$d;
    wire  [98:0] line$4$q;
    reg  line$4$clock;
    reg  [98:0] line$5$d;
    wire  [98:0] line$5$q;
    reg  line$5$clock;
    reg  [98:0] line$6$d;
    wire  [98:0] line$6$q;
    reg  line$6$clock;
    reg  [98:0] line$7$d;
    wire  [98:0] line$7$q;
    reg  line$7$clock;
    reg  [98:0] line$8$d;
    wire  [98:0] line$8$q;
    reg  line$8$clock;
    reg  [98:0] line$9$d;
    wire  [98:0] line$9$q;
    reg  line$9$clock;
    reg  [98:0] line$10$d;
    wire  [98:0] line$10$q;
    reg  line$10$clock;
    reg  [98:0] line$11$d;
    wire  [98:0] line$11$q;
    reg  line$11$clock;
    reg  [98:0] line$12$d;
    wire  [98:0] line$12$q;
    reg  line$12$clock;
    reg  [98:0] line$13$d;
    wire  [98:0] line$13$q;
    reg  line$13$clock;
    reg  [98:0] line$14$d;
    wire  [98:0] line$14$q;
    reg  line$14$clock;
    reg  [98:0] line$15$d;
    wire  [98:0] line$15$q;
    reg  line$15$clock;
    reg  [98:0] line$16$d;
    wire  [98:0] line$16$q;
    reg  line$16$clock;
    reg  [98:0] line$17$d;
    wire  [98:0] line$17$q;
    reg  line$17$clock;
    reg  [98:0] line$18$d;
    wire  [98:0] line$18$q;
    reg  line$18$clock;
    
    // Sub module instances
    top$side$line$0 line$0(
        .d(line$0$d),
        .q(line$0$q),
        .clock(line$0$clock)
    );
    top$side$line$0 line$1(
        .d(line$1$d),
        .q(line$1$q),
        .clock(line$1$clock)
    );
    top$side$line$0 line$2(
        .d(line$2$d),
        .q(line$2$q),
        .clock(line$2$clock)
    );
    top$side$line$0 line$3(
        .d(line$3$d),
        .q(line$3$q),
        .clock(line$3$clock)
    );
    top$side$line$0 line$4(
        .d(line$4$d),
        .q(line$4$q),
        .clock(line$4$clock)
    );
    top$side$line$0 line$5(
        .d(line$5$d),
        .q(line$5$q),
        .clock(line$5$clock)
    );
    top$side$line$0 line$6(
        .d(line$6$d),
        .q(line$6$q),
        .clock(line$6$clock)
    );
    top$side$line$0 line$7(
        .d(line$7$d),
        .q(line$7$q),
        .clock(line$7$clock)
    );
    top$side$line$0 line$8(
        .d(line$8$d),
        .q(line$8$q),
        .clock(line$8$clock)
    );
    top$side$line$0 line$9(
        .d(line$9$d),
        .q(line$9$q),
        .clock(line$9$clock)
    );
    top$side$line$0 line$10(
        .d(line$10$d),
        .q(line$10$q),
        .clock(line$10$clock)
    );
    top$side$line$0 line$11(
        .d(line$11$d),
        .q(line$11$q),
        .clock(line$11$clock)
    );
    top$side$line$0 line$12(
        .d(line$12$d),
        .q(line$12$q),
        .clock(line$12$clock)
    );
    top$side$line$0 line$13(
        .d(line$13$d),
        .q(line$13$q),
        .clock(line$13$clock)
    );
    top$side$line$0 line$14(
        .d(line$14$d),
        .q(line$14$q),
        .clock(line$14$clock)
    );
    top$side$line$0 line$15(
        .d(line$15$d),
        .q(line$15$q),
        .clock(line$15$clock)
    );
    top$side$line$0 line$16(
        .d(line$16$d),
        .q(line$16$q),
        .clock(line$16$clock)
    );
    top$side$line$0 line$17(
        .d(line$17$d),
        .q(line$17$q),
        .clock(line$17$clock)
    );
    top$side$line$0 line$18(
        .d(line$18$d),
        .q(line$18$q),
        .clock(line$18$clock)
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
        q = line$0$q;
    end
    
endmodule // top$side


module top$side$line$0(d,q,clock);
    
    // Module arguments
    input wire  [98:0] d;
    output reg  [98:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 99'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$side$line$0


module top$tb_word(d,q,clock);
    
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
          
endmodule // top$tb_word


module top$tri_cache(clock,clear,mask,fill,fill_id,fill_word,id,next_id,hit,word);
    
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
    top$tri_cache$valid valid(
        .d(valid$d),
        .q(valid$q),
        .clock(valid$clock)
    );
    top$tri_cache$ids ids(
        .read_address(ids$read_address),
        .read_clock(ids$read_clock),
        .read_data(ids$read_data),
        .write_address(ids$write_address),
        .write_clock(ids$write_clock),
        .write_data(ids$write_data),
        .write_enable(ids$write_enable)
    );
    top$tri_cache$words words(
        .read_address(words$read_address),
        .read_clock(words$read_clock),
        .read_data(words$read_data),
        .write_address(words$write_address),
        .write_clock(words$write_clock),
        .write_data(words$write_data),
        .write_enable(words$write_enable)
    );
    top$cnt_dop$pending byp(
        .d(byp$d),
        .q(byp$q),
        .clock(byp$clock)
    );
    top$d_cntr$last_a last_id(
        .d(last_id$d),
        .q(last_id$q),
        .clock(last_id$clock)
    );
    top$tb_word last_word(
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
    
endmodule // top$tri_cache


module top$tri_cache$ids(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
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
                
endmodule // top$tri_cache$ids


module top$tri_cache$valid(d,q,clock);
    
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
          
endmodule // top$tri_cache$valid


module top$tri_cache$words(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
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
                
endmodule // top$tri_cache$words


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
    top$cnt_dop$total ab_0$0(
        .d(ab_0$0$d),
        .q(ab_0$0$q),
        .clock(ab_0$0$clock)
    );
    top$cnt_dop$total ab_0$1(
        .d(ab_0$1$d),
        .q(ab_0$1$q),
        .clock(ab_0$1$clock)
    );
    top$cnt_dop$total ab_0$2(
        .d(ab_0$2$d),
        .q(ab_0$2$q),
        .clock(ab_0$2$clock)
    );
    top$cnt_dop$total ab_0$3(
        .d(ab_0$3$d),
        .q(ab_0$3$q),
        .clock(ab_0$3$clock)
    );
    top$cnt_dop$total ab_1$0(
        .d(ab_1$0$d),
        .q(ab_1$0$q),
        .clock(ab_1$0$clock)
    );
    top$cnt_dop$total ab_1$1(
        .d(ab_1$1$d),
        .q(ab_1$1$q),
        .clock(ab_1$1$clock)
    );
    top$cnt_dop$total ab_1$2(
        .d(ab_1$2$d),
        .q(ab_1$2$q),
        .clock(ab_1$2$clock)
    );
    top$cnt_dop$total ab_1$3(
        .d(ab_1$3$d),
        .q(ab_1$3$q),
        .clock(ab_1$3$clock)
    );
    top$cnt_dop$total ab_2$0(
        .d(ab_2$0$d),
        .q(ab_2$0$q),
        .clock(ab_2$0$clock)
    );
    top$cnt_dop$total ab_2$1(
        .d(ab_2$1$d),
        .q(ab_2$1$q),
        .clock(ab_2$1$clock)
    );
    top$cnt_dop$total ab_2$2(
        .d(ab_2$2$d),
        .q(ab_2$2$q),
        .clock(ab_2$2$clock)
    );
    top$cnt_dop$total ab_2$3(
        .d(ab_2$3$d),
        .q(ab_2$3$q),
        .clock(ab_2$3$clock)
    );
    top$cnt_dop$total ab_bm(
        .d(ab_bm$d),
        .q(ab_bm$q),
        .clock(ab_bm$clock)
    );
    top$cnt_dop$total ab_bf(
        .d(ab_bf$d),
        .q(ab_bf$q),
        .clock(ab_bf$clock)
    );
    top$cnt_dop$total ab_s(
        .d(ab_s$d),
        .q(ab_s$q),
        .clock(ab_s$clock)
    );
    top$cnt_dop$total ba_0$0(
        .d(ba_0$0$d),
        .q(ba_0$0$q),
        .clock(ba_0$0$clock)
    );
    top$cnt_dop$total ba_0$1(
        .d(ba_0$1$d),
        .q(ba_0$1$q),
        .clock(ba_0$1$clock)
    );
    top$cnt_dop$total ba_0$2(
        .d(ba_0$2$d),
        .q(ba_0$2$q),
        .clock(ba_0$2$clock)
    );
    top$cnt_dop$total ba_0$3(
        .d(ba_0$3$d),
        .q(ba_0$3$q),
        .clock(ba_0$3$clock)
    );
    top$cnt_dop$total ba_1$0(
        .d(ba_1$0$d),
        .q(ba_1$0$q),
        .clock(ba_1$0$clock)
    );
    top$cnt_dop$total ba_1$1(
        .d(ba_1$1$d),
        .q(ba_1$1$q),
        .clock(ba_1$1$clock)
    );
    top$cnt_dop$total ba_1$2(
        .d(ba_1$2$d),
        .q(ba_1$2$q),
        .clock(ba_1$2$clock)
    );
    top$cnt_dop$total ba_1$3(
        .d(ba_1$3$d),
        .q(ba_1$3$q),
        .clock(ba_1$3$clock)
    );
    top$cnt_dop$total ba_2$0(
        .d(ba_2$0$d),
        .q(ba_2$0$q),
        .clock(ba_2$0$clock)
    );
    top$cnt_dop$total ba_2$1(
        .d(ba_2$1$d),
        .q(ba_2$1$q),
        .clock(ba_2$1$clock)
    );
    top$cnt_dop$total ba_2$2(
        .d(ba_2$2$d),
        .q(ba_2$2$q),
        .clock(ba_2$2$clock)
    );
    top$cnt_dop$total ba_2$3(
        .d(ba_2$3$d),
        .q(ba_2$3$q),
        .clock(ba_2$3$clock)
    );
    top$cnt_dop$total ba_bm(
        .d(ba_bm$d),
        .q(ba_bm$q),
        .clock(ba_bm$clock)
    );
    top$cnt_dop$total ba_bf(
        .d(ba_bf$d),
        .q(ba_bf$q),
        .clock(ba_bf$clock)
    );
    top$cnt_dop$total ba_s(
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
    top$dop$dec_d$0$s0_ef count(
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
    top$mem_port$tags$row$0 line$0(
        .d(line$0$d),
        .q(line$0$q),
        .clock(line$0$clock)
    );
    top$mem_port$tags$row$0 line$1(
        .d(line$1$d),
        .q(line$1$q),
        .clock(line$1$clock)
    );
    top$mem_port$tags$row$0 line$2(
        .d(line$2$d),
        .q(line$2$q),
        .clock(line$2$clock)
    );
    top$mem_port$tags$row$0 line$3(
        .d(line$3$d),
        .q(line$3$q),
        .clock(line$3$clock)
    );
    top$mem_port$tags$row$0 line$4(
        .d(line$4$d),
        .q(line$4$q),
        .clock(line$4$clock)
    );
    top$mem_port$tags$row$0 line$5(
        .d(line$5$d),
        .q(line$5$q),
        .clock(line$5$clock)
    );
    top$mem_port$tags$row$0 line$6(
        .d(line$6$d),
        .q(line$6$q),
        .clock(line$6$clock)
    );
    top$mem_port$tags$row$0 line$7(
        .d(line$7$d),
        .q(line$7$q),
        .clock(line$7$clock)
    );
    top$mem_port$tags$row$0 line$8(
        .d(line$8$d),
        .q(line$8$q),
        .clock(line$8$clock)
    );
    top$mem_port$tags$row$0 line$9(
        .d(line$9$d),
        .q(line$9$q),
        .clock(line$9$clock)
    );
    top$mem_port$tags$row$0 line$10(
        .d(line$10$d),
        .q(line$10$q),
        .clock(line$10$clock)
    );
    top$mem_port$tags$row$0 line$11(
        .d(line$11$d),
        .q(line$11$q),
        .clock(line$11$clock)
    );
    top$mem_port$tags$row$0 line$12(
        .d(line$12$d),
        .q(line$12$q),
        .clock(line$12$clock)
    );
    top$mem_port$tags$row$0 line$13(
        .d(line$13$d),
        .q(line$13$q),
        .clock(line$13$clock)
    );
    top$mem_port$tags$row$0 line$14(
        .d(line$14$d),
        .q(line$14$q),
        .clock(line$14$clock)
    );
    top$mem_port$tags$row$0 line$15(
        .d(line$15$d),
        .q(line$15$q),
        .clock(line$15$clock)
    );
    top$mem_port$tags$row$0 line$16(
        .d(line$16$d),
        .q(line$16$q),
        .clock(line$16$clock)
    );
    top$mem_port$tags$row$0 line$17(
        .d(line$17$d),
        .q(line$17$q),
        .clock(line$17$clock)
    );
    top$mem_port$tags$row$0 line$18(
        .d(line$18$d),
        .q(line$18$q),
        .clock(line$18$clock)
    );
    top$mem_port$tags$row$0 line$19(
        .d(line$19$d),
        .q(line$19$q),
        .clock(line$19$clock)
    );
    top$mem_port$tags$row$0 line$20(
        .d(line$20$d),
        .q(line$20$q),
        .clock(line$20$clock)
    );
    top$mem_port$tags$row$0 line$21(
        .d(line$21$d),
        .q(line$21$q),
        .clock(line$21$clock)
    );
    top$mem_port$tags$row$0 line$22(
        .d(line$22$d),
        .q(line$22$q),
        .clock(line$22$clock)
    );
    top$mem_port$tags$row$0 line$23(
        .d(line$23$d),
        .q(line$23$q),
        .clock(line$23$clock)
    );
    top$mem_port$tags$row$0 line$24(
        .d(line$24$d),
        .q(line$24$q),
        .clock(line$24$clock)
    );
    top$mem_port$tags$row$0 line$25(
        .d(line$25$d),
        .q(line$25$q),
        .clock(line$25$clock)
    );
    top$mem_port$tags$row$0 line$26(
        .d(line$26$d),
        .q(line$26$q),
        .clock(line$26$clock)
    );
    top$mem_port$tags$row$0 line$27(
        .d(line$27$d),
        .q(line$27$q),
        .clock(line$27$clock)
    );
    top$mem_port$tags$row$0 line$28(
        .d(line$28$d),
        .q(line$28$q),
        .clock(line$28$clock)
    );
    top$mem_port$tags$row$0 line$29(
        .d(line$29$d),
        .q(line$29$q),
        .clock(line$29$clock)
    );
    top$mem_port$tags$row$0 line$30(
        .d(line$30$d),
        .q(line$30$q),
        .clock(line$30$clock)
    );
    top$mem_port$tags$row$0 line$31(
        .d(line$31$d),
        .q(line$31$q),
        .clock(line$31$clock)
    );
    top$mem_port$tags$row$0 line$32(
        .d(line$32$d),
        .q(line$32$q),
        .clock(line$32$clock)
    );
    top$mem_port$tags$row$0 line$33(
        .d(line$33$d),
        .q(line$33$q),
        .clock(line$33$clock)
    );
    top$mem_port$tags$row$0 line$34(
        .d(line$34$d),
        .q(line$34$q),
        .clock(line$34$clock)
    );
    top$mem_port$tags$row$0 line$35(
        .d(line$35$d),
        .q(line$35$q),
        .clock(line$35$clock)
    );
    top$mem_port$tags$row$0 line$36(
        .d(line$36$d),
        .q(line$36$q),
        .clock(line$36$clock)
    );
    top$mem_port$tags$row$0 line$37(
        .d(line$37$d),
        .q(line$37$q),
        .clock(line$37$clock)
    );
    top$mem_port$tags$row$0 line$38(
        .d(line$38$d),
        .q(line$38$q),
        .clock(line$38$clock)
    );
    top$mem_port$tags$row$0 line$39(
        .d(line$39$d),
        .q(line$39$q),
        .clock(line$39$clock)
    );
    top$mem_port$tags$row$0 line$40(
        .d(line$40$d),
        .q(line$40$q),
        .clock(line$40$clock)
    );
    top$mem_port$tags$row$0 line$41(
        .d(line$41$d),
        .q(line$41$q),
        .clock(line$41$clock)
    );
    top$mem_port$tags$row$0 line$42(
        .d(line$42$d),
        .q(line$42$q),
        .clock(line$42$clock)
    );
    top$mem_port$tags$row$0 line$43(
        .d(line$43$d),
        .q(line$43$q),
        .clock(line$43$clock)
    );
    top$mem_port$tags$row$0 line$44(
        .d(line$44$d),
        .q(line$44$q),
        .clock(line$44$clock)
    );
    top$mem_port$tags$row$0 line$45(
        .d(line$45$d),
        .q(line$45$q),
        .clock(line$45$clock)
    );
    top$mem_port$tags$row$0 line$46(
        .d(line$46$d),
        .q(line$46$q),
        .clock(line$46$clock)
    );
    top$mem_port$tags$row$0 line$47(
        .d(line$47$d),
        .q(line$47$q),
        .clock(line$47$clock)
    );
    top$mem_port$tags$row$0 line$48(
        .d(line$48$d),
        .q(line$48$q),
        .clock(line$48$clock)
    );
    top$mem_port$tags$row$0 line$49(
        .d(line$49$d),
        .q(line$49$q),
        .clock(line$49$clock)
    );
    top$mem_port$tags$row$0 line$50(
        .d(line$50$d),
        .q(line$50$q),
        .clock(line$50$clock)
    );
    top$mem_port$tags$row$0 line$51(
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
    top$dop$dec_d$0$s0_ef read_address(
        .d(read_address$d),
        .q(read_address$q),
        .clock(read_address$clock)
    );
    top$cnt_dop$pending dff_underflow(
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
    top$dop$dec_d$0$s0_ef write_address(
        .d(write_address$d),
        .q(write_address$q),
        .clock(write_address$clock)
    );
    top$dop$dec_d$0$s0_ef dff_write_address_delay(
        .d(dff_write_address_delay$d),
        .q(dff_write_address_delay$q),
        .clock(dff_write_address_delay$clock)
    );
    top$cnt_dop$pending dff_overflow(
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
    top$cnt_dop$total in_m_0$0(
        .d(in_m_0$0$d),
        .q(in_m_0$0$q),
        .clock(in_m_0$0$clock)
    );
    top$cnt_dop$total in_m_0$1(
        .d(in_m_0$1$d),
        .q(in_m_0$1$q),
        .clock(in_m_0$1$clock)
    );
    top$cnt_dop$total in_m_0$2(
        .d(in_m_0$2$d),
        .q(in_m_0$2$q),
        .clock(in_m_0$2$clock)
    );
    top$cnt_dop$total in_m_0$3(
        .d(in_m_0$3$d),
        .q(in_m_0$3$q),
        .clock(in_m_0$3$clock)
    );
    top$cnt_dop$total in_m_1$0(
        .d(in_m_1$0$d),
        .q(in_m_1$0$q),
        .clock(in_m_1$0$clock)
    );
    top$cnt_dop$total in_m_1$1(
        .d(in_m_1$1$d),
        .q(in_m_1$1$q),
        .clock(in_m_1$1$clock)
    );
    top$cnt_dop$total in_m_1$2(
        .d(in_m_1$2$d),
        .q(in_m_1$2$q),
        .clock(in_m_1$2$clock)
    );
    top$cnt_dop$total in_m_1$3(
        .d(in_m_1$3$d),
        .q(in_m_1$3$q),
        .clock(in_m_1$3$clock)
    );
    top$cnt_dop$total in_m_2$0(
        .d(in_m_2$0$d),
        .q(in_m_2$0$q),
        .clock(in_m_2$0$clock)
    );
    top$cnt_dop$total in_m_2$1(
        .d(in_m_2$1$d),
        .q(in_m_2$1$q),
        .clock(in_m_2$1$clock)
    );
    top$cnt_dop$total in_m_2$2(
        .d(in_m_2$2$d),
        .q(in_m_2$2$q),
        .clock(in_m_2$2$clock)
    );
    top$cnt_dop$total in_m_2$3(
        .d(in_m_2$3$d),
        .q(in_m_2$3$q),
        .clock(in_m_2$3$clock)
    );
    top$cnt_dop$total in_alpha_m(
        .d(in_alpha_m$d),
        .q(in_alpha_m$q),
        .clock(in_alpha_m$clock)
    );
    top$cnt_dop$total in_alpha_f(
        .d(in_alpha_f$d),
        .q(in_alpha_f$q),
        .clock(in_alpha_f$clock)
    );
    top$cnt_dop$total in_f_0$0(
        .d(in_f_0$0$d),
        .q(in_f_0$0$q),
        .clock(in_f_0$0$clock)
    );
    top$cnt_dop$total in_f_0$1(
        .d(in_f_0$1$d),
        .q(in_f_0$1$q),
        .clock(in_f_0$1$clock)
    );
    top$cnt_dop$total in_f_0$2(
        .d(in_f_0$2$d),
        .q(in_f_0$2$q),
        .clock(in_f_0$2$clock)
    );
    top$cnt_dop$total in_f_0$3(
        .d(in_f_0$3$d),
        .q(in_f_0$3$q),
        .clock(in_f_0$3$clock)
    );
    top$cnt_dop$total in_f_1$0(
        .d(in_f_1$0$d),
        .q(in_f_1$0$q),
        .clock(in_f_1$0$clock)
    );
    top$cnt_dop$total in_f_1$1(
        .d(in_f_1$1$d),
        .q(in_f_1$1$q),
        .clock(in_f_1$1$clock)
    );
    top$cnt_dop$total in_f_1$2(
        .d(in_f_1$2$d),
        .q(in_f_1$2$q),
        .clock(in_f_1$2$clock)
    );
    top$cnt_dop$total in_f_1$3(
        .d(in_f_1$3$d),
        .q(in_f_1$3$q),
        .clock(in_f_1$3$clock)
    );
    top$cnt_dop$total in_f_2$0(
        .d(in_f_2$0$d),
        .q(in_f_2$0$q),
        .clock(in_f_2$0$clock)
    );
    top$cnt_dop$total in_f_2$1(
        .d(in_f_2$1$d),
        .q(in_f_2$1$q),
        .clock(in_f_2$1$clock)
    );
    top$cnt_dop$total in_f_2$2(
        .d(in_f_2$2$d),
        .q(in_f_2$2$q),
        .clock(in_f_2$2$clock)
    );
    top$cnt_dop$total in_f_2$3(
        .d(in_f_2$3$d),
        .q(in_f_2$3$q),
        .clock(in_f_2$3$clock)
    );
    top$cnt_dop$total in_beta_m(
        .d(in_beta_m$d),
        .q(in_beta_m$q),
        .clock(in_beta_m$clock)
    );
    top$cnt_dop$total in_beta_f(
        .d(in_beta_f$d),
        .q(in_beta_f$q),
        .clock(in_beta_f$clock)
    );
    top$cnt_dop$total in_scale(
        .d(in_scale$d),
        .q(in_scale$q),
        .clock(in_scale$clock)
    );
    top$cnt_dop$total in_v_x$0(
        .d(in_v_x$0$d),
        .q(in_v_x$0$q),
        .clock(in_v_x$0$clock)
    );
    top$cnt_dop$total in_v_x$1(
        .d(in_v_x$1$d),
        .q(in_v_x$1$q),
        .clock(in_v_x$1$clock)
    );
    top$cnt_dop$total in_v_x$2(
        .d(in_v_x$2$d),
        .q(in_v_x$2$q),
        .clock(in_v_x$2$clock)
    );
    top$cnt_dop$total in_v_y$0(
        .d(in_v_y$0$d),
        .q(in_v_y$0$q),
        .clock(in_v_y$0$clock)
    );
    top$cnt_dop$total in_v_y$1(
        .d(in_v_y$1$d),
        .q(in_v_y$1$q),
        .clock(in_v_y$1$clock)
    );
    top$cnt_dop$total in_v_y$2(
        .d(in_v_y$2$d),
        .q(in_v_y$2$q),
        .clock(in_v_y$2$clock)
    );
    top$cnt_dop$total in_v_z$0(
        .d(in_v_z$0$d),
        .q(in_v_z$0$q),
        .clock(in_v_z$0$clock)
    );
    top$cnt_dop$total in_v_z$1(
        .d(in_v_z$1$d),
        .q(in_v_z$1$q),
        .clock(in_v_z$1$clock)
    );
    top$cnt_dop$total in_v_z$2(
        .d(in_v_z$2$d),
        .q(in_v_z$2$q),
        .clock(in_v_z$2$clock)
    );
    top$cnt_dop$pending in_v_exact(
        .d(in_v_exact$d),
        .q(in_v_exact$q),
        .clock(in_v_exact$clock)
    );
    top$cnt_dop$total in_tag(
        .d(in_tag$d),
        .q(in_tag$q),
        .clock(in_tag$clock)
    );
    top$cnt_dop$pending in_valid(
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
    top$cnt_dop$total mbr_0$0(
        .d(mbr_0$0$d),
        .q(mbr_0$0$q),
        .clock(mbr_0$0$clock)
    );
    top$cnt_dop$total mbr_0$1(
        .d(mbr_0$1$d),
        .q(mbr_0$1$q),
        .clock(mbr_0$1$clock)
    );
    top$cnt_dop$total mbr_0$2(
        .d(mbr_0$2$d),
        .q(mbr_0$2$q),
        .clock(mbr_0$2$clock)
    );
    top$cnt_dop$total mbr_0$3(
        .d(mbr_0$3$d),
        .q(mbr_0$3$q),
        .clock(mbr_0$3$clock)
    );
    top$cnt_dop$total mbr_1$0(
        .d(mbr_1$0$d),
        .q(mbr_1$0$q),
        .clock(mbr_1$0$clock)
    );
    top$cnt_dop$total mbr_1$1(
        .d(mbr_1$1$d),
        .q(mbr_1$1$q),
        .clock(mbr_1$1$clock)
    );
    top$cnt_dop$total mbr_1$2(
        .d(mbr_1$2$d),
        .q(mbr_1$2$q),
        .clock(mbr_1$2$clock)
    );
    top$cnt_dop$total mbr_1$3(
        .d(mbr_1$3$d),
        .q(mbr_1$3$q),
        .clock(mbr_1$3$clock)
    );
    top$cnt_dop$total mbr_2$0(
        .d(mbr_2$0$d),
        .q(mbr_2$0$q),
        .clock(mbr_2$0$clock)
    );
    top$cnt_dop$total mbr_2$1(
        .d(mbr_2$1$d),
        .q(mbr_2$1$q),
        .clock(mbr_2$1$clock)
    );
    top$cnt_dop$total mbr_2$2(
        .d(mbr_2$2$d),
        .q(mbr_2$2$q),
        .clock(mbr_2$2$clock)
    );
    top$cnt_dop$total mbr_2$3(
        .d(mbr_2$3$d),
        .q(mbr_2$3$q),
        .clock(mbr_2$3$clock)
    );
    top$cnt_dop$total mgr_0$0(
        .d(mgr_0$0$d),
        .q(mgr_0$0$q),
        .clock(mgr_0$0$clock)
    );
    top$cnt_dop$total mgr_0$1(
        .d(mgr_0$1$d),
        .q(mgr_0$1$q),
        .clock(mgr_0$1$clock)
    );
    top$cnt_dop$total mgr_0$2(
        .d(mgr_0$2$d),
        .q(mgr_0$2$q),
        .clock(mgr_0$2$clock)
    );
    top$cnt_dop$total mgr_0$3(
        .d(mgr_0$3$d),
        .q(mgr_0$3$q),
        .clock(mgr_0$3$clock)
    );
    top$cnt_dop$total mgr_1$0(
        .d(mgr_1$0$d),
        .q(mgr_1$0$q),
        .clock(mgr_1$0$clock)
    );
    top$cnt_dop$total mgr_1$1(
        .d(mgr_1$1$d),
        .q(mgr_1$1$q),
        .clock(mgr_1$1$clock)
    );
    top$cnt_dop$total mgr_1$2(
        .d(mgr_1$2$d),
        .q(mgr_1$2$q),
        .clock(mgr_1$2$clock)
    );
    top$cnt_dop$total mgr_1$3(
        .d(mgr_1$3$d),
        .q(mgr_1$3$q),
        .clock(mgr_1$3$clock)
    );
    top$cnt_dop$total mgr_2$0(
        .d(mgr_2$0$d),
        .q(mgr_2$0$q),
        .clock(mgr_2$0$clock)
    );
    top$cnt_dop$total mgr_2$1(
        .d(mgr_2$1$d),
        .q(mgr_2$1$q),
        .clock(mgr_2$1$clock)
    );
    top$cnt_dop$total mgr_2$2(
        .d(mgr_2$2$d),
        .q(mgr_2$2$q),
        .clock(mgr_2$2$clock)
    );
    top$cnt_dop$total mgr_2$3(
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
    top$cnt_dop$total vtr_0$0(
        .d(vtr_0$0$d),
        .q(vtr_0$0$q),
        .clock(vtr_0$0$clock)
    );
    top$cnt_dop$total vtr_0$1(
        .d(vtr_0$1$d),
        .q(vtr_0$1$q),
        .clock(vtr_0$1$clock)
    );
    top$cnt_dop$total vtr_0$2(
        .d(vtr_0$2$d),
        .q(vtr_0$2$q),
        .clock(vtr_0$2$clock)
    );
    top$cnt_dop$total vtr_1$0(
        .d(vtr_1$0$d),
        .q(vtr_1$0$q),
        .clock(vtr_1$0$clock)
    );
    top$cnt_dop$total vtr_1$1(
        .d(vtr_1$1$d),
        .q(vtr_1$1$q),
        .clock(vtr_1$1$clock)
    );
    top$cnt_dop$total vtr_1$2(
        .d(vtr_1$2$d),
        .q(vtr_1$2$q),
        .clock(vtr_1$2$clock)
    );
    top$cnt_dop$total vtr_2$0(
        .d(vtr_2$0$d),
        .q(vtr_2$0$q),
        .clock(vtr_2$0$clock)
    );
    top$cnt_dop$total vtr_2$1(
        .d(vtr_2$1$d),
        .q(vtr_2$1$q),
        .clock(vtr_2$1$clock)
    );
    top$cnt_dop$total vtr_2$2(
        .d(vtr_2$2$d),
        .q(vtr_2$2$q),
        .clock(vtr_2$2$clock)
    );
    top$cnt_dop$total vmr_0$0(
        .d(vmr_0$0$d),
        .q(vmr_0$0$q),
        .clock(vmr_0$0$clock)
    );
    top$cnt_dop$total vmr_0$1(
        .d(vmr_0$1$d),
        .q(vmr_0$1$q),
        .clock(vmr_0$1$clock)
    );
    top$cnt_dop$total vmr_0$2(
        .d(vmr_0$2$d),
        .q(vmr_0$2$q),
        .clock(vmr_0$2$clock)
    );
    top$cnt_dop$total vmr_1$0(
        .d(vmr_1$0$d),
        .q(vmr_1$0$q),
        .clock(vmr_1$0$clock)
    );
    top$cnt_dop$total vmr_1$1(
        .d(vmr_1$1$d),
        .q(vmr_1$1$q),
        .clock(vmr_1$1$clock)
    );
    top$cnt_dop$total vmr_1$2(
        .d(vmr_1$2$d),
        .q(vmr_1$2$q),
        .clock(vmr_1$2$clock)
    );
    top$cnt_dop$total vmr_2$0(
        .d(vmr_2$0$d),
        .q(vmr_2$0$q),
        .clock(vmr_2$0$clock)
    );
    top$cnt_dop$total vmr_2$1(
        .d(vmr_2$1$d),
        .q(vmr_2$1$q),
        .clock(vmr_2$1$clock)
    );
    top$cnt_dop$total vmr_2$2(
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
    top$cnt_dop$pending v_cross_t$0(
        .d(v_cross_t$0$d),
        .q(v_cross_t$0$q),
        .clock(v_cross_t$0$clock)
    );
    top$cnt_dop$pending v_cross_t$1(
        .d(v_cross_t$1$d),
        .q(v_cross_t$1$q),
        .clock(v_cross_t$1$clock)
    );
    top$cnt_dop$pending v_cross_t$2(
        .d(v_cross_t$2$d),
        .q(v_cross_t$2$q),
        .clock(v_cross_t$2$clock)
    );
    top$cnt_dop$pending v_cross_f$0(
        .d(v_cross_f$0$d),
        .q(v_cross_f$0$q),
        .clock(v_cross_f$0$clock)
    );
    top$cnt_dop$pending v_cross_f$1(
        .d(v_cross_f$1$d),
        .q(v_cross_f$1$q),
        .clock(v_cross_f$1$clock)
    );
    top$cnt_dop$pending v_cross_f$2(
        .d(v_cross_f$2$d),
        .q(v_cross_f$2$q),
        .clock(v_cross_f$2$clock)
    );
    top$cnt_dop$total v_s_x$0(
        .d(v_s_x$0$d),
        .q(v_s_x$0$q),
        .clock(v_s_x$0$clock)
    );
    top$cnt_dop$total v_s_x$1(
        .d(v_s_x$1$d),
        .q(v_s_x$1$q),
        .clock(v_s_x$1$clock)
    );
    top$cnt_dop$total v_s_x$2(
        .d(v_s_x$2$d),
        .q(v_s_x$2$q),
        .clock(v_s_x$2$clock)
    );
    top$cnt_dop$total v_s_b$0(
        .d(v_s_b$0$d),
        .q(v_s_b$0$q),
        .clock(v_s_b$0$clock)
    );
    top$cnt_dop$total v_s_b$1(
        .d(v_s_b$1$d),
        .q(v_s_b$1$q),
        .clock(v_s_b$1$clock)
    );
    top$cnt_dop$total v_s_b$2(
        .d(v_s_b$2$d),
        .q(v_s_b$2$q),
        .clock(v_s_b$2$clock)
    );
    top$cnt_dop$total out_s_x$0(
        .d(out_s_x$0$d),
        .q(out_s_x$0$q),
        .clock(out_s_x$0$clock)
    );
    top$cnt_dop$total out_s_x$1(
        .d(out_s_x$1$d),
        .q(out_s_x$1$q),
        .clock(out_s_x$1$clock)
    );
    top$cnt_dop$total out_s_x$2(
        .d(out_s_x$2$d),
        .q(out_s_x$2$q),
        .clock(out_s_x$2$clock)
    );
    top$cnt_dop$total out_s_b$0(
        .d(out_s_b$0$d),
        .q(out_s_b$0$q),
        .clock(out_s_b$0$clock)
    );
    top$cnt_dop$total out_s_b$1(
        .d(out_s_b$1$d),
        .q(out_s_b$1$q),
        .clock(out_s_b$1$clock)
    );
    top$cnt_dop$total out_s_b$2(
        .d(out_s_b$2$d),
        .q(out_s_b$2$q),
        .clock(out_s_b$2$clock)
    );
    top$cnt_dop$pending out_cross_t$0(
        .d(out_cross_t$0$d),
        .q(out_cross_t$0$q),
        .clock(out_cross_t$0$clock)
    );
    top$cnt_dop$pending out_cross_t$1(
        .d(out_cross_t$1$d),
        .q(out_cross_t$1$q),
        .clock(out_cross_t$1$clock)
    );
    top$cnt_dop$pending out_cross_t$2(
        .d(out_cross_t$2$d),
        .q(out_cross_t$2$q),
        .clock(out_cross_t$2$clock)
    );
    top$cnt_dop$pending out_cross_f$0(
        .d(out_cross_f$0$d),
        .q(out_cross_f$0$q),
        .clock(out_cross_f$0$clock)
    );
    top$cnt_dop$pending out_cross_f$1(
        .d(out_cross_f$1$d),
        .q(out_cross_f$1$q),
        .clock(out_cross_f$1$clock)
    );
    top$cnt_dop$pending out_cross_f$2(
        .d(out_cross_f$2$d),
        .q(out_cross_f$2$q),
        .clock(out_cross_f$2$clock)
    );
    top$cnt_dop$pending out_hit(
        .d(out_hit$d),
        .q(out_hit$q),
        .clock(out_hit$clock)
    );
    top$cnt_dop$pending out_miss(
        .d(out_miss$d),
        .q(out_miss$q),
        .clock(out_miss$clock)
    );
    top$cnt_dop$total out_tag(
        .d(out_tag$d),
        .q(out_tag$q),
        .clock(out_tag$clock)
    );
    top$cnt_dop$pending out_valid(
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
    top$dop$dec_d$0$add$unpack_a unpack_a(
        .x(unpack_a$x),
        .sign(unpack_a$sign),
        .exp(unpack_a$exp),
        .sig(unpack_a$sig),
        .is_zero(unpack_a$is_zero),
        .is_inf(unpack_a$is_inf),
        .is_nan(unpack_a$is_nan)
    );
    top$dop$dec_d$0$add$unpack_a unpack_b(
        .x(unpack_b$x),
        .sign(unpack_b$sign),
        .exp(unpack_b$exp),
        .sig(unpack_b$sig),
        .is_zero(unpack_b$is_zero),
        .is_inf(unpack_b$is_inf),
        .is_nan(unpack_b$is_nan)
    );
    top$cnt_dop$pending s1_valid(
        .d(s1_valid$d),
        .q(s1_valid$q),
        .clock(s1_valid$clock)
    );
    top$cnt_dop$pending s1_nan(
        .d(s1_nan$d),
        .q(s1_nan$q),
        .clock(s1_nan$clock)
    );
    top$cnt_dop$pending s1_inf(
        .d(s1_inf$d),
        .q(s1_inf$q),
        .clock(s1_inf$clock)
    );
    top$cnt_dop$pending s1_inf_sign(
        .d(s1_inf_sign$d),
        .q(s1_inf_sign$q),
        .clock(s1_inf_sign$clock)
    );
    top$cnt_dop$pending s1_zero_sign(
        .d(s1_zero_sign$d),
        .q(s1_zero_sign$q),
        .clock(s1_zero_sign$clock)
    );
    top$cnt_dop$pending s1_sign(
        .d(s1_sign$d),
        .q(s1_sign$q),
        .clock(s1_sign$clock)
    );
    top$cnt_dop$pending s1_eff_sub(
        .d(s1_eff_sub$d),
        .q(s1_eff_sub$q),
        .clock(s1_eff_sub$clock)
    );
    top$dop$dec_d$0$add$s1_exp s1_exp(
        .d(s1_exp$d),
        .q(s1_exp$q),
        .clock(s1_exp$clock)
    );
    top$dop$dec_d$0$add$s1_big s1_big(
        .d(s1_big$d),
        .q(s1_big$q),
        .clock(s1_big$clock)
    );
    top$dop$dec_d$0$add$s1_big s1_small(
        .d(s1_small$d),
        .q(s1_small$q),
        .clock(s1_small$clock)
    );
    top$dop$dec_d$0$add$norm norm(
        .x(norm$x),
        .y(norm$y),
        .lz(norm$lz)
    );
    top$cnt_dop$pending s2_valid(
        .d(s2_valid$d),
        .q(s2_valid$q),
        .clock(s2_valid$clock)
    );
    top$cnt_dop$pending s2_sign(
        .d(s2_sign$d),
        .q(s2_sign$q),
        .clock(s2_sign$clock)
    );
    top$cnt_dop$pending s2_nan(
        .d(s2_nan$d),
        .q(s2_nan$q),
        .clock(s2_nan$clock)
    );
    top$cnt_dop$pending s2_inf(
        .d(s2_inf$d),
        .q(s2_inf$q),
        .clock(s2_inf$clock)
    );
    top$cnt_dop$pending s2_zero(
        .d(s2_zero$d),
        .q(s2_zero$q),
        .clock(s2_zero$clock)
    );
    top$cnt_dop$pending s2_ovf(
        .d(s2_ovf$d),
        .q(s2_ovf$q),
        .clock(s2_ovf$clock)
    );
    top$dop$dec_d$0$add$s1_exp s2_efield(
        .d(s2_efield$d),
        .q(s2_efield$q),
        .clock(s2_efield$clock)
    );
    top$dop$dec_d$0$add$s2_nm s2_nm(
        .d(s2_nm$d),
        .q(s2_nm$q),
        .clock(s2_nm$clock)
    );
    top$dop$dec_d$0$add$round round(
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
    top$cnt_dop$pending s3_valid(
        .d(s3_valid$d),
        .q(s3_valid$q),
        .clock(s3_valid$clock)
    );
    top$cnt_dop$total s3_y(
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
    top$cnt_dop$total line$0(
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
    top$dop$dec_d$0$add$unpack_a unpack_a(
        .x(unpack_a$x),
        .sign(unpack_a$sign),
        .exp(unpack_a$exp),
        .sig(unpack_a$sig),
        .is_zero(unpack_a$is_zero),
        .is_inf(unpack_a$is_inf),
        .is_nan(unpack_a$is_nan)
    );
    top$dop$dec_d$0$add$unpack_a unpack_b(
        .x(unpack_b$x),
        .sign(unpack_b$sign),
        .exp(unpack_b$exp),
        .sig(unpack_b$sig),
        .is_zero(unpack_b$is_zero),
        .is_inf(unpack_b$is_inf),
        .is_nan(unpack_b$is_nan)
    );
    top$dop$unit$doptrf$0$mul_0$norm_a norm_a(
        .x(norm_a$x),
        .y(norm_a$y),
        .lz(norm_a$lz)
    );
    top$dop$unit$doptrf$0$mul_0$norm_a norm_b(
        .x(norm_b$x),
        .y(norm_b$y),
        .lz(norm_b$lz)
    );
    top$cnt_dop$pending s1_valid(
        .d(s1_valid$d),
        .q(s1_valid$q),
        .clock(s1_valid$clock)
    );
    top$cnt_dop$pending s1_sign(
        .d(s1_sign$d),
        .q(s1_sign$q),
        .clock(s1_sign$clock)
    );
    top$cnt_dop$pending s1_nan(
        .d(s1_nan$d),
        .q(s1_nan$q),
        .clock(s1_nan$clock)
    );
    top$cnt_dop$pending s1_inf(
        .d(s1_inf$d),
        .q(s1_inf$q),
        .clock(s1_inf$clock)
    );
    top$cnt_dop$pending s1_zero(
        .d(s1_zero$d),
        .q(s1_zero$q),
        .clock(s1_zero$clock)
    );
    top$d_cntr$queue$rd1_x s1_exp(
        .d(s1_exp$d),
        .q(s1_exp$q),
        .clock(s1_exp$clock)
    );
    top$base_na s1_sig_a(
        .d(s1_sig_a$d),
        .q(s1_sig_a$q),
        .clock(s1_sig_a$clock)
    );
    top$base_na s1_sig_b(
        .d(s1_sig_b$d),
        .q(s1_sig_b$q),
        .clock(s1_sig_b$clock)
    );
    top$dop$unit$doptrf$0$mul_0$sig_mul sig_mul(
        .a(sig_mul$a),
        .b(sig_mul$b),
        .hi(sig_mul$hi),
        .sticky(sig_mul$sticky)
    );
    top$cnt_dop$pending s2_valid(
        .d(s2_valid$d),
        .q(s2_valid$q),
        .clock(s2_valid$clock)
    );
    top$cnt_dop$pending s2_sign(
        .d(s2_sign$d),
        .q(s2_sign$q),
        .clock(s2_sign$clock)
    );
    top$cnt_dop$pending s2_nan(
        .d(s2_nan$d),
        .q(s2_nan$q),
        .clock(s2_nan$clock)
    );
    top$cnt_dop$pending s2_inf(
        .d(s2_inf$d),
        .q(s2_inf$q),
        .clock(s2_inf$clock)
    );
    top$cnt_dop$pending s2_zero(
        .d(s2_zero$d),
        .q(s2_zero$q),
        .clock(s2_zero$clock)
    );
    top$d_cntr$queue$rd1_x s2_exp(
        .d(s2_exp$d),
        .q(s2_exp$q),
        .clock(s2_exp$clock)
    );
    top$dop$dec_d$0$add$s2_nm s2_hi(
        .d(s2_hi$d),
        .q(s2_hi$q),
        .clock(s2_hi$clock)
    );
    top$cnt_dop$pending s2_sticky(
        .d(s2_sticky$d),
        .q(s2_sticky$q),
        .clock(s2_sticky$clock)
    );
    top$cnt_dop$pending s3_valid(
        .d(s3_valid$d),
        .q(s3_valid$q),
        .clock(s3_valid$clock)
    );
    top$cnt_dop$pending s3_sign(
        .d(s3_sign$d),
        .q(s3_sign$q),
        .clock(s3_sign$clock)
    );
    top$cnt_dop$pending s3_nan(
        .d(s3_nan$d),
        .q(s3_nan$q),
        .clock(s3_nan$clock)
    );
    top$cnt_dop$pending s3_inf(
        .d(s3_inf$d),
        .q(s3_inf$q),
        .clock(s3_inf$clock)
    );
    top$cnt_dop$pending s3_zero(
        .d(s3_zero$d),
        .q(s3_zero$q),
        .clock(s3_zero$clock)
    );
    top$cnt_dop$pending s3_ovf(
        .d(s3_ovf$d),
        .q(s3_ovf$q),
        .clock(s3_ovf$clock)
    );
    top$dop$dec_d$0$add$s1_exp s3_efield(
        .d(s3_efield$d),
        .q(s3_efield$q),
        .clock(s3_efield$clock)
    );
    top$dop$dec_d$0$add$s2_nm s3_nm(
        .d(s3_nm$d),
        .q(s3_nm$q),
        .clock(s3_nm$clock)
    );
    top$dop$dec_d$0$add$round round(
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
    top$cnt_dop$pending s4_valid(
        .d(s4_valid$d),
        .q(s4_valid$q),
        .clock(s4_valid$clock)
    );
    top$cnt_dop$total s4_y(
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
    top$cnt_dop$total line$0(
        .d(line$0$d),
        .q(line$0$q),
        .clock(line$0$clock)
    );
    top$cnt_dop$total line$1(
        .d(line$1$d),
        .q(line$1$q),
        .clock(line$1$clock)
    );
    top$cnt_dop$total line$2(
        .d(line$2$d),
        .q(line$2$q),
        .clock(line$2$clock)
    );
    top$cnt_dop$total line$3(
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
    top$mem_port$tags$row$0 r_pz(
        .d(r_pz$d),
        .q(r_pz$q),
        .clock(r_pz$clock)
    );
    top$mem_port$tags$row$0 r_qz(
        .d(r_qz$d),
        .q(r_qz$q),
        .clock(r_qz$clock)
    );
    top$mem_port$tags$row$0 r_rz(
        .d(r_rz$d),
        .q(r_rz$q),
        .clock(r_rz$clock)
    );
    top$mem_port$tags$row$0 r_a(
        .d(r_a$d),
        .q(r_a$q),
        .clock(r_a$clock)
    );
    top$mem_port$tags$row$0 r_b(
        .d(r_b$d),
        .q(r_b$q),
        .clock(r_b$clock)
    );
    top$mem_port$tags$row$0 r_s(
        .d(r_s$d),
        .q(r_s$q),
        .clock(r_s$clock)
    );
    top$cnt_dop$total r_s_x(
        .d(r_s_x$d),
        .q(r_s_x$q),
        .clock(r_s_x$clock)
    );
    top$cnt_dop$total r_s_b(
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
    top$dop$dec_d$0$add$unpack_a unpack_a(
        .x(unpack_a$x),
        .sign(unpack_a$sign),
        .exp(unpack_a$exp),
        .sig(unpack_a$sig),
        .is_zero(unpack_a$is_zero),
        .is_inf(unpack_a$is_inf),
        .is_nan(unpack_a$is_nan)
    );
    top$dop$dec_d$0$add$unpack_a unpack_b(
        .x(unpack_b$x),
        .sign(unpack_b$sign),
        .exp(unpack_b$exp),
        .sig(unpack_b$sig),
        .is_zero(unpack_b$is_zero),
        .is_inf(unpack_b$is_inf),
        .is_nan(unpack_b$is_nan)
    );
    top$cnt_dop$pending s1_valid(
        .d(s1_valid$d),
        .q(s1_valid$q),
        .clock(s1_valid$clock)
    );
    top$cnt_dop$pending s1_nan(
        .d(s1_nan$d),
        .q(s1_nan$q),
        .clock(s1_nan$clock)
    );
    top$cnt_dop$pending s1_inf(
        .d(s1_inf$d),
        .q(s1_inf$q),
        .clock(s1_inf$clock)
    );
    top$cnt_dop$pending s1_inf_sign(
        .d(s1_inf_sign$d),
        .q(s1_inf_sign$q),
        .clock(s1_inf_sign$clock)
    );
    top$cnt_dop$pending s1_zero_sign(
        .d(s1_zero_sign$d),
        .q(s1_zero_sign$q),
        .clock(s1_zero_sign$clock)
    );
    top$cnt_dop$pending s1_sign(
        .d(s1_sign$d),
        .q(s1_sign$q),
        .clock(s1_sign$clock)
    );
    top$cnt_dop$pending s1_eff_sub(
        .d(s1_eff_sub$d),
        .q(s1_eff_sub$q),
        .clock(s1_eff_sub$clock)
    );
    top$dop$dec_d$0$add$s1_exp s1_exp(
        .d(s1_exp$d),
        .q(s1_exp$q),
        .clock(s1_exp$clock)
    );
    top$dop$dec_d$0$add$s1_big s1_big(
        .d(s1_big$d),
        .q(s1_big$q),
        .clock(s1_big$clock)
    );
    top$dop$dec_d$0$add$s1_big s1_small(
        .d(s1_small$d),
        .q(s1_small$q),
        .clock(s1_small$clock)
    );
    top$dop$dec_d$0$add$norm norm(
        .x(norm$x),
        .y(norm$y),
        .lz(norm$lz)
    );
    top$cnt_dop$pending s2_valid(
        .d(s2_valid$d),
        .q(s2_valid$q),
        .clock(s2_valid$clock)
    );
    top$cnt_dop$pending s2_sign(
        .d(s2_sign$d),
        .q(s2_sign$q),
        .clock(s2_sign$clock)
    );
    top$cnt_dop$pending s2_nan(
        .d(s2_nan$d),
        .q(s2_nan$q),
        .clock(s2_nan$clock)
    );
    top$cnt_dop$pending s2_inf(
        .d(s2_inf$d),
        .q(s2_inf$q),
        .clock(s2_inf$clock)
    );
    top$cnt_dop$pending s2_zero(
        .d(s2_zero$d),
        .q(s2_zero$q),
        .clock(s2_zero$clock)
    );
    top$cnt_dop$pending s2_ovf(
        .d(s2_ovf$d),
        .q(s2_ovf$q),
        .clock(s2_ovf$clock)
    );
    top$dop$dec_d$0$add$s1_exp s2_efield(
        .d(s2_efield$d),
        .q(s2_efield$q),
        .clock(s2_efield$clock)
    );
    top$dop$dec_d$0$add$s2_nm s2_nm(
        .d(s2_nm$d),
        .q(s2_nm$q),
        .clock(s2_nm$clock)
    );
    top$dop$dec_d$0$add$round round(
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
    top$cnt_dop$pending s3_valid(
        .d(s3_valid$d),
        .q(s3_valid$q),
        .clock(s3_valid$clock)
    );
    top$cnt_dop$total s3_y(
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
    top$mem_port$tags$row$0 line$0(
        .d(line$0$d),
        .q(line$0$q),
        .clock(line$0$clock)
    );
    top$mem_port$tags$row$0 line$1(
        .d(line$1$d),
        .q(line$1$q),
        .clock(line$1$clock)
    );
    top$mem_port$tags$row$0 line$2(
        .d(line$2$d),
        .q(line$2$q),
        .clock(line$2$clock)
    );
    top$mem_port$tags$row$0 line$3(
        .d(line$3$d),
        .q(line$3$q),
        .clock(line$3$clock)
    );
    top$mem_port$tags$row$0 line$4(
        .d(line$4$d),
        .q(line$4$q),
        .clock(line$4$clock)
    );
    top$mem_port$tags$row$0 line$5(
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
    top$cnt_dop$total line$0(
        .d(line$0$d),
        .q(line$0$q),
        .clock(line$0$clock)
    );
    top$cnt_dop$total line$1(
        .d(line$1$d),
        .q(line$1$q),
        .clock(line$1$clock)
    );
    top$cnt_dop$total line$2(
        .d(line$2$d),
        .q(line$2$q),
        .clock(line$2$clock)
    );
    top$cnt_dop$total line$3(
        .d(line$3$d),
        .q(line$3$q),
        .clock(line$3$clock)
    );
    top$cnt_dop$total line$4(
        .d(line$4$d),
        .q(line$4$q),
        .clock(line$4$clock)
    );
    top$cnt_dop$total line$5(
        .d(line$5$d),
        .q(line$5$q),
        .clock(line$5$clock)
    );
    top$cnt_dop$total line$6(
        .d(line$6$d),
        .q(line$6$q),
        .clock(line$6$clock)
    );
    top$cnt_dop$total line$7(
        .d(line$7$d),
        .q(line$7$q),
        .clock(line$7$clock)
    );
    top$cnt_dop$total line$8(
        .d(line$8$d),
        .q(line$8$q),
        .clock(line$8$clock)
    );
    top$cnt_dop$total line$9(
        .d(line$9$d),
        .q(line$9$q),
        .clock(line$9$clock)
    );
    top$cnt_dop$total line$10(
        .d(line$10$d),
        .q(line$10$q),
        .clock(line$10$clock)
    );
    top$cnt_dop$total line$11(
        .d(line$11$d),
        .q(line$11$q),
        .clock(line$11$clock)
    );
    top$cnt_dop$total line$12(
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
    top$cnt_dop$total line$0(
        .d(line$0$d),
        .q(line$0$q),
        .clock(line$0$clock)
    );
    top$cnt_dop$total line$1(
        .d(line$1$d),
        .q(line$1$q),
        .clock(line$1$clock)
    );
    top$cnt_dop$total line$2(
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
    top$cnt_dop$total line$0(
        .d(line$0$d),
        .q(line$0$q),
        .clock(line$0$clock)
    );
    top$cnt_dop$total line$1(
        .d(line$1$d),
        .q(line$1$q),
        .clock(line$1$clock)
    );
    top$cnt_dop$total line$2(
        .d(line$2$d),
        .q(line$2$q),
        .clock(line$2$clock)
    );
    top$cnt_dop$total line$3(
        .d(line$3$d),
        .q(line$3$q),
        .clock(line$3$clock)
    );
    top$cnt_dop$total line$4(
        .d(line$4$d),
        .q(line$4$q),
        .clock(line$4$clock)
    );
    top$cnt_dop$total line$5(
        .d(line$5$d),
        .q(line$5$q),
        .clock(line$5$clock)
    );
    top$cnt_dop$total line$6(
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
    top$dop$dec_d$0$add$unpack_a unpack_a(
        .x(unpack_a$x),
        .sign(unpack_a$sign),
        .exp(unpack_a$exp),
        .sig(unpack_a$sig),
        .is_zero(unpack_a$is_zero),
        .is_inf(unpack_a$is_inf),
        .is_nan(unpack_a$is_nan)
    );
    top$dop$dec_d$0$add$unpack_a unpack_b(
        .x(unpack_b$x),
        .sign(unpack_b$sign),
        .exp(unpack_b$exp),
        .sig(unpack_b$sig),
        .is_zero(unpack_b$is_zero),
        .is_inf(unpack_b$is_inf),
        .is_nan(unpack_b$is_nan)
    );
    top$dop$unit$doptrf$0$mul_0$norm_a norm_a(
        .x(norm_a$x),
        .y(norm_a$y),
        .lz(norm_a$lz)
    );
    top$dop$unit$doptrf$0$mul_0$norm_a norm_b(
        .x(norm_b$x),
        .y(norm_b$y),
        .lz(norm_b$lz)
    );
    top$cnt_dop$pending s1_valid(
        .d(s1_valid$d),
        .q(s1_valid$q),
        .clock(s1_valid$clock)
    );
    top$cnt_dop$pending s1_sign(
        .d(s1_sign$d),
        .q(s1_sign$q),
        .clock(s1_sign$clock)
    );
    top$cnt_dop$pending s1_nan(
        .d(s1_nan$d),
        .q(s1_nan$q),
        .clock(s1_nan$clock)
    );
    top$cnt_dop$pending s1_inf(
        .d(s1_inf$d),
        .q(s1_inf$q),
        .clock(s1_inf$clock)
    );
    top$cnt_dop$pending s1_zero(
        .d(s1_zero$d),
        .q(s1_zero$q),
        .clock(s1_zero$clock)
    );
    top$d_cntr$queue$rd1_x s1_exp(
        .d(s1_exp$d),
        .q(s1_exp$q),
        .clock(s1_exp$clock)
    );
    top$base_na s1_sig_a(
        .d(s1_sig_a$d),
        .q(s1_sig_a$q),
        .clock(s1_sig_a$clock)
    );
    top$base_na s1_sig_b(
        .d(s1_sig_b$d),
        .q(s1_sig_b$q),
        .clock(s1_sig_b$clock)
    );
    top$dop$unit$doptrf$0$mul_0$sig_mul sig_mul(
        .a(sig_mul$a),
        .b(sig_mul$b),
        .hi(sig_mul$hi),
        .sticky(sig_mul$sticky)
    );
    top$cnt_dop$pending s2_valid(
        .d(s2_valid$d),
        .q(s2_valid$q),
        .clock(s2_valid$clock)
    );
    top$cnt_dop$pending s2_sign(
        .d(s2_sign$d),
        .q(s2_sign$q),
        .clock(s2_sign$clock)
    );
    top$cnt_dop$pending s2_nan(
        .d(s2_nan$d),
        .q(s2_nan$q),
        .clock(s2_nan$clock)
    );
    top$cnt_dop$pending s2_inf(
        .d(s2_inf$d),
        .q(s2_inf$q),
        .clock(s2_inf$clock)
    );
    top$cnt_dop$pending s2_zero(
        .d(s2_zero$d),
        .q(s2_zero$q),
        .clock(s2_zero$clock)
    );
    top$d_cntr$queue$rd1_x s2_exp(
        .d(s2_exp$d),
        .q(s2_exp$q),
        .clock(s2_exp$clock)
    );
    top$dop$dec_d$0$add$s2_nm s2_hi(
        .d(s2_hi$d),
        .q(s2_hi$q),
        .clock(s2_hi$clock)
    );
    top$cnt_dop$pending s2_sticky(
        .d(s2_sticky$d),
        .q(s2_sticky$q),
        .clock(s2_sticky$clock)
    );
    top$cnt_dop$pending s3_valid(
        .d(s3_valid$d),
        .q(s3_valid$q),
        .clock(s3_valid$clock)
    );
    top$cnt_dop$pending s3_sign(
        .d(s3_sign$d),
        .q(s3_sign$q),
        .clock(s3_sign$clock)
    );
    top$cnt_dop$pending s3_nan(
        .d(s3_nan$d),
        .q(s3_nan$q),
        .clock(s3_nan$clock)
    );
    top$cnt_dop$pending s3_inf(
        .d(s3_inf$d),
        .q(s3_inf$q),
        .clock(s3_inf$clock)
    );
    top$cnt_dop$pending s3_zero(
        .d(s3_zero$d),
        .q(s3_zero$q),
        .clock(s3_zero$clock)
    );
    top$cnt_dop$pending s3_ovf(
        .d(s3_ovf$d),
        .q(s3_ovf$q),
        .clock(s3_ovf$clock)
    );
    top$dop$dec_d$0$add$s1_exp s3_efield(
        .d(s3_efield$d),
        .q(s3_efield$q),
        .clock(s3_efield$clock)
    );
    top$dop$dec_d$0$add$s2_nm s3_nm(
        .d(s3_nm$d),
        .q(s3_nm$q),
        .clock(s3_nm$clock)
    );
    top$dop$dec_d$0$add$round round(
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
    top$cnt_dop$pending s4_valid(
        .d(s4_valid$d),
        .q(s4_valid$q),
        .clock(s4_valid$clock)
    );
    top$cnt_dop$total s4_y(
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
    top$mem_port$tags$row$0 line$0(
        .d(line$0$d),
        .q(line$0$q),
        .clock(line$0$clock)
    );
    top$mem_port$tags$row$0 line$1(
        .d(line$1$d),
        .q(line$1$q),
        .clock(line$1$clock)
    );
    top$mem_port$tags$row$0 line$2(
        .d(line$2$d),
        .q(line$2$q),
        .clock(line$2$clock)
    );
    top$mem_port$tags$row$0 line$3(
        .d(line$3$d),
        .q(line$3$q),
        .clock(line$3$clock)
    );
    top$mem_port$tags$row$0 line$4(
        .d(line$4$d),
        .q(line$4$q),
        .clock(line$4$clock)
    );
    top$mem_port$tags$row$0 line$5(
        .d(line$5$d),
        .q(line$5$q),
        .clock(line$5$clock)
    );
    top$mem_port$tags$row$0 line$6(
        .d(line$6$d),
        .q(line$6$q),
        .clock(line$6$clock)
    );
    top$mem_port$tags$row$0 line$7(
        .d(line$7$d),
        .q(line$7$q),
        .clock(line$7$clock)
    );
    top$mem_port$tags$row$0 line$8(
        .d(line$8$d),
        .q(line$8$q),
        .clock(line$8$clock)
    );
    top$mem_port$tags$row$0 line$9(
        .d(line$9$d),
        .q(line$9$q),
        .clock(line$9$clock)
    );
    top$mem_port$tags$row$0 line$10(
        .d(line$10$d),
        .q(line$10$q),
        .clock(line$10$clock)
    );
    top$mem_port$tags$row$0 line$11(
        .d(line$11$d),
        .q(line$11$q),
        .clock(line$11$clock)
    );
    top$mem_port$tags$row$0 line$12(
        .d(line$12$d),
        .q(line$12$q),
        .clock(line$12$clock)
    );
    top$mem_port$tags$row$0 line$13(
        .d(line$13$d),
        .q(line$13$q),
        .clock(line$13$clock)
    );
    top$mem_port$tags$row$0 line$14(
        .d(line$14$d),
        .q(line$14$q),
        .clock(line$14$clock)
    );
    top$mem_port$tags$row$0 line$15(
        .d(line$15$d),
        .q(line$15$q),
        .clock(line$15$clock)
    );
    top$mem_port$tags$row$0 line$16(
        .d(line$16$d),
        .q(line$16$q),
        .clock(line$16$clock)
    );
    top$mem_port$tags$row$0 line$17(
        .d(line$17$d),
        .q(line$17$q),
        .clock(line$17$clock)
    );
    top$mem_port$tags$row$0 line$18(
        .d(line$18$d),
        .q(line$18$q),
        .clock(line$18$clock)
    );
    top$mem_port$tags$row$0 line$19(
        .d(line$19$d),
        .q(line$19$q),
        .clock(line$19$clock)
    );
    top$mem_port$tags$row$0 line$20(
        .d(line$20$d),
        .q(line$20$q),
        .clock(line$20$clock)
    );
    top$mem_port$tags$row$0 line$21(
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
    top$mem_port$tags$row$0 line$0(
        .d(line$0$d),
        .q(line$0$q),
        .clock(line$0$clock)
    );
    top$mem_port$tags$row$0 line$1(
        .d(line$1$d),
        .q(line$1$q),
        .clock(line$1$clock)
    );
    top$mem_port$tags$row$0 line$2(
        .d(line$2$d),
        .q(line$2$q),
        .clock(line$2$clock)
    );
    top$mem_port$tags$row$0 line$3(
        .d(line$3$d),
        .q(line$3$q),
        .clock(line$3$clock)
    );
    top$mem_port$tags$row$0 line$4(
        .d(line$4$d),
        .q(line$4$q),
        .clock(line$4$clock)
    );
    top$mem_port$tags$row$0 line$5(
        .d(line$5$d),
        .q(line$5$q),
        .clock(line$5$clock)
    );
    top$mem_port$tags$row$0 line$6(
        .d(line$6$d),
        .q(line$6$q),
        .clock(line$6$clock)
    );
    top$mem_port$tags$row$0 line$7(
        .d(line$7$d),
        .q(line$7$q),
        .clock(line$7$clock)
    );
    top$mem_port$tags$row$0 line$8(
        .d(line$8$d),
        .q(line$8$q),
        .clock(line$8$clock)
    );
    top$mem_port$tags$row$0 line$9(
        .d(line$9$d),
        .q(line$9$q),
        .clock(line$9$clock)
    );
    top$mem_port$tags$row$0 line$10(
        .d(line$10$d),
        .q(line$10$q),
        .clock(line$10$clock)
    );
    top$mem_port$tags$row$0 line$11(
        .d(line$11$d),
        .q(line$11$q),
        .clock(line$11$clock)
    );
    top$mem_port$tags$row$0 line$12(
        .d(line$12$d),
        .q(line$12$q),
        .clock(line$12$clock)
    );
    top$mem_port$tags$row$0 line$13(
        .d(line$13$d),
        .q(line$13$q),
        .clock(line$13$clock)
    );
    top$mem_port$tags$row$0 line$14(
        .d(line$14$d),
        .q(line$14$q),
        .clock(line$14$clock)
    );
    top$mem_port$tags$row$0 line$15(
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
    top$cnt_dop$pending line$0(
        .d(line$0$d),
        .q(line$0$q),
        .clock(line$0$clock)
    );
    top$cnt_dop$pending line$1(
        .d(line$1$d),
        .q(line$1$q),
        .clock(line$1$clock)
    );
    top$cnt_dop$pending line$2(
        .d(line$2$d),
        .q(line$2$q),
        .clock(line$2$clock)
    );
    top$cnt_dop$pending line$3(
        .d(line$3$d),
        .q(line$3$q),
        .clock(line$3$clock)
    );
    top$cnt_dop$pending line$4(
        .d(line$4$d),
        .q(line$4$q),
        .clock(line$4$clock)
    );
    top$cnt_dop$pending line$5(
        .d(line$5$d),
        .q(line$5$q),
        .clock(line$5$clock)
    );
    top$cnt_dop$pending line$6(
        .d(line$6$d),
        .q(line$6$q),
        .clock(line$6$clock)
    );
    top$cnt_dop$pending line$7(
        .d(line$7$d),
        .q(line$7$q),
        .clock(line$7$clock)
    );
    top$cnt_dop$pending line$8(
        .d(line$8$d),
        .q(line$8$q),
        .clock(line$8$clock)
    );
    top$cnt_dop$pending line$9(
        .d(line$9$d),
        .q(line$9$q),
        .clock(line$9$clock)
    );
    top$cnt_dop$pending line$10(
        .d(line$10$d),
        .q(line$10$q),
        .clock(line$10$clock)
    );
    top$cnt_dop$pending line$11(
        .d(line$11$d),
        .q(line$11$q),
        .clock(line$11$clock)
    );
    top$cnt_dop$pending line$12(
        .d(line$12$d),
        .q(line$12$q),
        .clock(line$12$clock)
    );
    top$cnt_dop$pending line$13(
        .d(line$13$d),
        .q(line$13$q),
        .clock(line$13$clock)
    );
    top$cnt_dop$pending line$14(
        .d(line$14$d),
        .q(line$14$q),
        .clock(line$14$clock)
    );
    top$cnt_dop$pending line$15(
        .d(line$15$d),
        .q(line$15$q),
        .clock(line$15$clock)
    );
    top$cnt_dop$pending line$16(
        .d(line$16$d),
        .q(line$16$q),
        .clock(line$16$clock)
    );
    top$cnt_dop$pending line$17(
        .d(line$17$d),
        .q(line$17$q),
        .clock(line$17$clock)
    );
    top$cnt_dop$pending line$18(
        .d(line$18$d),
        .q(line$18$q),
        .clock(line$18$clock)
    );
    top$cnt_dop$pending line$19(
        .d(line$19$d),
        .q(line$19$q),
        .clock(line$19$clock)
    );
    top$cnt_dop$pending line$20(
        .d(line$20$d),
        .q(line$20$q),
        .clock(line$20$clock)
    );
    top$cnt_dop$pending line$21(
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
    top$cnt_dop$total line$0(
        .d(line$0$d),
        .q(line$0$q),
        .clock(line$0$clock)
    );
    top$cnt_dop$total line$1(
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
    top$cnt_dop$total line$0(
        .d(line$0$d),
        .q(line$0$q),
        .clock(line$0$clock)
    );
    top$cnt_dop$total line$1(
        .d(line$1$d),
        .q(line$1$q),
        .clock(line$1$clock)
    );
    top$cnt_dop$total line$2(
        .d(line$2$d),
        .q(line$2$q),
        .clock(line$2$clock)
    );
    top$cnt_dop$total line$3(
        .d(line$3$d),
        .q(line$3$q),
        .clock(line$3$clock)
    );
    top$cnt_dop$total line$4(
        .d(line$4$d),
        .q(line$4$q),
        .clock(line$4$clock)
    );
    top$cnt_dop$total line$5(
        .d(line$5$d),
        .q(line$5$q),
        .clock(line$5$clock)
    );
    top$cnt_dop$total line$6(
        .d(line$6$d),
        .q(line$6$q),
        .clock(line$6$clock)
    );
    top$cnt_dop$total line$7(
        .d(line$7$d),
        .q(line$7$q),
        .clock(line$7$clock)
    );
    top$cnt_dop$total line$8(
        .d(line$8$d),
        .q(line$8$q),
        .clock(line$8$clock)
    );
    top$cnt_dop$total line$9(
        .d(line$9$d),
        .q(line$9$q),
        .clock(line$9$clock)
    );
    top$cnt_dop$total line$10(
        .d(line$10$d),
        .q(line$10$q),
        .clock(line$10$clock)
    );
    top$cnt_dop$total line$11(
        .d(line$11$d),
        .q(line$11$q),
        .clock(line$11$clock)
    );
    top$cnt_dop$total line$12(
        .d(line$12$d),
        .q(line$12$q),
        .clock(line$12$clock)
    );
    top$cnt_dop$total line$13(
        .d(line$13$d),
        .q(line$13$q),
        .clock(line$13$clock)
    );
    top$cnt_dop$total line$14(
        .d(line$14$d),
        .q(line$14$q),
        .clock(line$14$clock)
    );
    top$cnt_dop$total line$15(
        .d(line$15$d),
        .q(line$15$q),
        .clock(line$15$clock)
    );
    top$cnt_dop$total line$16(
        .d(line$16$d),
        .q(line$16$q),
        .clock(line$16$clock)
    );
    top$cnt_dop$total line$17(
        .d(line$17$d),
        .q(line$17$q),
        .clock(line$17$clock)
    );
    top$cnt_dop$total line$18(
        .d(line$18$d),
        .q(line$18$q),
        .clock(line$18$clock)
    );
    top$cnt_dop$total line$19(
        .d(line$19$d),
        .q(line$19$q),
        .clock(line$19$clock)
    );
    top$cnt_dop$total line$20(
        .d(line$20$d),
        .q(line$20$q),
        .clock(line$20$clock)
    );
    top$cnt_dop$total line$21(
        .d(line$21$d),
        .q(line$21$q),
        .clock(line$21$clock)
    );
    top$cnt_dop$total line$22(
        .d(line$22$d),
        .q(line$22$q),
        .clock(line$22$clock)
    );
    top$cnt_dop$total line$23(
        .d(line$23$d),
        .q(line$23$q),
        .clock(line$23$clock)
    );
    top$cnt_dop$total line$24(
        .d(line$24$d),
        .q(line$24$q),
        .clock(line$24$clock)
    );
    top$cnt_dop$total line$25(
        .d(line$25$d),
        .q(line$25$q),
        .clock(line$25$clock)
    );
    top$cnt_dop$total line$26(
        .d(line$26$d),
        .q(line$26$q),
        .clock(line$26$clock)
    );
    top$cnt_dop$total line$27(
        .d(line$27$d),
        .q(line$27$q),
        .clock(line$27$clock)
    );
    top$cnt_dop$total line$28(
        .d(line$28$d),
        .q(line$28$q),
        .clock(line$28$clock)
    );
    top$cnt_dop$total line$29(
        .d(line$29$d),
        .q(line$29$q),
        .clock(line$29$clock)
    );
    top$cnt_dop$total line$30(
        .d(line$30$d),
        .q(line$30$q),
        .clock(line$30$clock)
    );
    top$cnt_dop$total line$31(
        .d(line$31$d),
        .q(line$31$q),
        .clock(line$31$clock)
    );
    top$cnt_dop$total line$32(
        .d(line$32$d),
        .q(line$32$q),
        .clock(line$32$clock)
    );
    top$cnt_dop$total line$33(
        .d(line$33$d),
        .q(line$33$q),
        .clock(line$33$clock)
    );
    top$cnt_dop$total line$34(
        .d(line$34$d),
        .q(line$34$q),
        .clock(line$34$clock)
    );
    top$cnt_dop$total line$35(
        .d(line$35$d),
        .q(line$35$q),
        .clock(line$35$clock)
    );
    top$cnt_dop$total line$36(
        .d(line$36$d),
        .q(line$36$q),
        .clock(line$36$clock)
    );
    top$cnt_dop$total line$37(
        .d(line$37$d),
        .q(line$37$q),
        .clock(line$37$clock)
    );
    top$cnt_dop$total line$38(
        .d(line$38$d),
        .q(line$38$q),
        .clock(line$38$clock)
    );
    top$cnt_dop$total line$39(
        .d(line$39$d),
        .q(line$39$q),
        .clock(line$39$clock)
    );
    top$cnt_dop$total line$40(
        .d(line$40$d),
        .q(line$40$q),
        .clock(line$40$clock)
    );
    top$cnt_dop$total line$41(
        .d(line$41$d),
        .q(line$41$q),
        .clock(line$41$clock)
    );
    top$cnt_dop$total line$42(
        .d(line$42$d),
        .q(line$42$q),
        .clock(line$42$clock)
    );
    top$cnt_dop$total line$43(
        .d(line$43$d),
        .q(line$43$q),
        .clock(line$43$clock)
    );
    top$cnt_dop$total line$44(
        .d(line$44$d),
        .q(line$44$q),
        .clock(line$44$clock)
    );
    top$cnt_dop$total line$45(
        .d(line$45$d),
        .q(line$45$q),
        .clock(line$45$clock)
    );
    top$cnt_dop$total line$46(
        .d(line$46$d),
        .q(line$46$q),
        .clock(line$46$clock)
    );
    top$cnt_dop$total line$47(
        .d(line$47$d),
        .q(line$47$q),
        .clock(line$47$clock)
    );
    top$cnt_dop$total line$48(
        .d(line$48$d),
        .q(line$48$q),
        .clock(line$48$clock)
    );
    top$cnt_dop$total line$49(
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
    top$cnt_dop$total line$0(
        .d(line$0$d),
        .q(line$0$q),
        .clock(line$0$clock)
    );
    top$cnt_dop$total line$1(
        .d(line$1$d),
        .q(line$1$q),
        .clock(line$1$clock)
    );
    top$cnt_dop$total line$2(
        .d(line$2$d),
        .q(line$2$q),
        .clock(line$2$clock)
    );
    top$cnt_dop$total line$3(
        .d(line$3$d),
        .q(line$3$q),
        .clock(line$3$clock)
    );
    top$cnt_dop$total line$4(
        .d(line$4$d),
        .q(line$4$q),
        .clock(line$4$clock)
    );
    top$cnt_dop$total line$5(
        .d(line$5$d),
        .q(line$5$q),
        .clock(line$5$clock)
    );
    top$cnt_dop$total line$6(
        .d(line$6$d),
        .q(line$6$q),
        .clock(line$6$clock)
    );
    top$cnt_dop$total line$7(
        .d(line$7$d),
        .q(line$7$q),
        .clock(line$7$clock)
    );
    top$cnt_dop$total line$8(
        .d(line$8$d),
        .q(line$8$q),
        .clock(line$8$clock)
    );
    top$cnt_dop$total line$9(
        .d(line$9$d),
        .q(line$9$q),
        .clock(line$9$clock)
    );
    top$cnt_dop$total line$10(
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
    top$cnt_dop$pending line$0(
        .d(line$0$d),
        .q(line$0$q),
        .clock(line$0$clock)
    );
    top$cnt_dop$pending line$1(
        .d(line$1$d),
        .q(line$1$q),
        .clock(line$1$clock)
    );
    top$cnt_dop$pending line$2(
        .d(line$2$d),
        .q(line$2$q),
        .clock(line$2$clock)
    );
    top$cnt_dop$pending line$3(
        .d(line$3$d),
        .q(line$3$q),
        .clock(line$3$clock)
    );
    top$cnt_dop$pending line$4(
        .d(line$4$d),
        .q(line$4$q),
        .clock(line$4$clock)
    );
    top$cnt_dop$pending line$5(
        .d(line$5$d),
        .q(line$5$q),
        .clock(line$5$clock)
    );
    top$cnt_dop$pending line$6(
        .d(line$6$d),
        .q(line$6$q),
        .clock(line$6$clock)
    );
    top$cnt_dop$pending line$7(
        .d(line$7$d),
        .q(line$7$q),
        .clock(line$7$clock)
    );
    top$cnt_dop$pending line$8(
        .d(line$8$d),
        .q(line$8$q),
        .clock(line$8$clock)
    );
    top$cnt_dop$pending line$9(
        .d(line$9$d),
        .q(line$9$q),
        .clock(line$9$clock)
    );
    top$cnt_dop$pending line$10(
        .d(line$10$d),
        .q(line$10$q),
        .clock(line$10$clock)
    );
    top$cnt_dop$pending line$11(
        .d(line$11$d),
        .q(line$11$q),
        .clock(line$11$clock)
    );
    top$cnt_dop$pending line$12(
        .d(line$12$d),
        .q(line$12$q),
        .clock(line$12$clock)
    );
    top$cnt_dop$pending line$13(
        .d(line$13$d),
        .q(line$13$q),
        .clock(line$13$clock)
    );
    top$cnt_dop$pending line$14(
        .d(line$14$d),
        .q(line$14$q),
        .clock(line$14$clock)
    );
    top$cnt_dop$pending line$15(
        .d(line$15$d),
        .q(line$15$q),
        .clock(line$15$clock)
    );
    top$cnt_dop$pending line$16(
        .d(line$16$d),
        .q(line$16$q),
        .clock(line$16$clock)
    );
    top$cnt_dop$pending line$17(
        .d(line$17$d),
        .q(line$17$q),
        .clock(line$17$clock)
    );
    top$cnt_dop$pending line$18(
        .d(line$18$d),
        .q(line$18$q),
        .clock(line$18$clock)
    );
    top$cnt_dop$pending line$19(
        .d(line$19$d),
        .q(line$19$q),
        .clock(line$19$clock)
    );
    top$cnt_dop$pending line$20(
        .d(line$20$d),
        .q(line$20$q),
        .clock(line$20$clock)
    );
    top$cnt_dop$pending line$21(
        .d(line$21$d),
        .q(line$21$q),
        .clock(line$21$clock)
    );
    top$cnt_dop$pending line$22(
        .d(line$22$d),
        .q(line$22$q),
        .clock(line$22$clock)
    );
    top$cnt_dop$pending line$23(
        .d(line$23$d),
        .q(line$23$q),
        .clock(line$23$clock)
    );
    top$cnt_dop$pending line$24(
        .d(line$24$d),
        .q(line$24$q),
        .clock(line$24$clock)
    );
    top$cnt_dop$pending line$25(
        .d(line$25$d),
        .q(line$25$q),
        .clock(line$25$clock)
    );
    top$cnt_dop$pending line$26(
        .d(line$26$d),
        .q(line$26$q),
        .clock(line$26$clock)
    );
    top$cnt_dop$pending line$27(
        .d(line$27$d),
        .q(line$27$q),
        .clock(line$27$clock)
    );
    top$cnt_dop$pending line$28(
        .d(line$28$d),
        .q(line$28$q),
        .clock(line$28$clock)
    );
    top$cnt_dop$pending line$29(
        .d(line$29$d),
        .q(line$29$q),
        .clock(line$29$clock)
    );
    top$cnt_dop$pending line$30(
        .d(line$30$d),
        .q(line$30$q),
        .clock(line$30$clock)
    );
    top$cnt_dop$pending line$31(
        .d(line$31$d),
        .q(line$31$q),
        .clock(line$31$clock)
    );
    top$cnt_dop$pending line$32(
        .d(line$32$d),
        .q(line$32$q),
        .clock(line$32$clock)
    );
    top$cnt_dop$pending line$33(
        .d(line$33$d),
        .q(line$33$q),
        .clock(line$33$clock)
    );
    top$cnt_dop$pending line$34(
        .d(line$34$d),
        .q(line$34$q),
        .clock(line$34$clock)
    );
    top$cnt_dop$pending line$35(
        .d(line$35$d),
        .q(line$35$q),
        .clock(line$35$clock)
    );
    top$cnt_dop$pending line$36(
        .d(line$36$d),
        .q(line$36$q),
        .clock(line$36$clock)
    );
    top$cnt_dop$pending line$37(
        .d(line$37$d),
        .q(line$37$q),
        .clock(line$37$clock)
    );
    top$cnt_dop$pending line$38(
        .d(line$38$d),
        .q(line$38$q),
        .clock(line$38$clock)
    );
    top$cnt_dop$pending line$39(
        .d(line$39$d),
        .q(line$39$q),
        .clock(line$39$clock)
    );
    top$cnt_dop$pending line$40(
        .d(line$40$d),
        .q(line$40$q),
        .clock(line$40$clock)
    );
    top$cnt_dop$pending line$41(
        .d(line$41$d),
        .q(line$41$q),
        .clock(line$41$clock)
    );
    top$cnt_dop$pending line$42(
        .d(line$42$d),
        .q(line$42$q),
        .clock(line$42$clock)
    );
    top$cnt_dop$pending line$43(
        .d(line$43$d),
        .q(line$43$q),
        .clock(line$43$clock)
    );
    top$cnt_dop$pending line$44(
        .d(line$44$d),
        .q(line$44$q),
        .clock(line$44$clock)
    );
    top$cnt_dop$pending line$45(
        .d(line$45$d),
        .q(line$45$q),
        .clock(line$45$clock)
    );
    top$cnt_dop$pending line$46(
        .d(line$46$d),
        .q(line$46$q),
        .clock(line$46$clock)
    );
    top$cnt_dop$pending line$47(
        .d(line$47$d),
        .q(line$47$q),
        .clock(line$47$clock)
    );
    top$cnt_dop$pending line$48(
        .d(line$48$d),
        .q(line$48$q),
        .clock(line$48$clock)
    );
    top$cnt_dop$pending line$49(
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
