

module top(clock,clear,halt,push,push_load,push_set,push_pair,push_id,need_a,need_b,ta_id,tb_id,base_na,base_nb,base_ta,base_tb,port_out,mem_req_ready,mem_resp_valid,mem_resp_data,busy,room,pending,mem_req_valid,mem_req_addr,req_tri,fill_a,fill_b,fill_id,fill_word,t_valid,t_set,t_side,t_entry,t_last,t_data,a_valid,a_first,a_set,a_entry,e,al_valid,al_id,al_leaf,al_f0,al_f1,ld_valid,ld_set,ld_pair,ld_id,ld_leaf0,ld_leaf1,ld_f00,ld_f01,ld_f10,ld_f11);
    
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
    top$ask_e$0 ask_e$0(
        .d(ask_e$0$d),
        .q(ask_e$0$q),
        .clock(ask_e$0$clock)
    );
    top$ask_e$0 ask_e$1(
        .d(ask_e$1$d),
        .q(ask_e$1$q),
        .clock(ask_e$1$clock)
    );
    top$ask_e$0 ask_e$2(
        .d(ask_e$2$d),
        .q(ask_e$2$q),
        .clock(ask_e$2$clock)
    );
    top$ask_e$0 ask_e$3(
        .d(ask_e$3$d),
        .q(ask_e$3$q),
        .clock(ask_e$3$clock)
    );
    top$ask_e$0 ask_e$4(
        .d(ask_e$4$d),
        .q(ask_e$4$q),
        .clock(ask_e$4$clock)
    );
    top$ask_e$0 ask_e$5(
        .d(ask_e$5$d),
        .q(ask_e$5$q),
        .clock(ask_e$5$clock)
    );
    top$ask_e$0 ask_e$6(
        .d(ask_e$6$d),
        .q(ask_e$6$q),
        .clock(ask_e$6$clock)
    );
    top$ask_e$0 ask_e$7(
        .d(ask_e$7$d),
        .q(ask_e$7$q),
        .clock(ask_e$7$clock)
    );
    top$ask_req$0 ask_req$0(
        .d(ask_req$0$d),
        .q(ask_req$0$q),
        .clock(ask_req$0$clock)
    );
    top$ask_req$0 ask_req$1(
        .d(ask_req$1$d),
        .q(ask_req$1$q),
        .clock(ask_req$1$clock)
    );
    top$ask_req$0 ask_req$2(
        .d(ask_req$2$d),
        .q(ask_req$2$q),
        .clock(ask_req$2$clock)
    );
    top$ask_req$0 ask_req$3(
        .d(ask_req$3$d),
        .q(ask_req$3$q),
        .clock(ask_req$3$clock)
    );
    top$ask_req$0 ask_req$4(
        .d(ask_req$4$d),
        .q(ask_req$4$q),
        .clock(ask_req$4$clock)
    );
    top$ask_req$0 ask_req$5(
        .d(ask_req$5$d),
        .q(ask_req$5$q),
        .clock(ask_req$5$clock)
    );
    top$ask_req$0 ask_req$6(
        .d(ask_req$6$d),
        .q(ask_req$6$q),
        .clock(ask_req$6$clock)
    );
    top$ask_req$0 ask_req$7(
        .d(ask_req$7$d),
        .q(ask_req$7$q),
        .clock(ask_req$7$clock)
    );
    top$ask_n ask_n(
        .d(ask_n$d),
        .q(ask_n$q),
        .clock(ask_n$clock)
    );
    top$last_al last_al(
        .d(last_al$d),
        .q(last_al$q),
        .clock(last_al$clock)
    );
    top$ask_req$0 last_al_v(
        .d(last_al_v$d),
        .q(last_al_v$q),
        .clock(last_al_v$clock)
    );
    top$held_n tag_d$0(
        .d(tag_d$0$d),
        .q(tag_d$0$q),
        .clock(tag_d$0$clock)
    );
    top$held_n tag_d$1(
        .d(tag_d$1$d),
        .q(tag_d$1$q),
        .clock(tag_d$1$clock)
    );
    top$held_n tag_d$2(
        .d(tag_d$2$d),
        .q(tag_d$2$q),
        .clock(tag_d$2$clock)
    );
    top$held_n tag_d$3(
        .d(tag_d$3$d),
        .q(tag_d$3$q),
        .clock(tag_d$3$clock)
    );
    top$held_n tag_d$4(
        .d(tag_d$4$d),
        .q(tag_d$4$q),
        .clock(tag_d$4$clock)
    );
    top$held_n tag_d$5(
        .d(tag_d$5$d),
        .q(tag_d$5$q),
        .clock(tag_d$5$clock)
    );
    top$held_n tag_d$6(
        .d(tag_d$6$d),
        .q(tag_d$6$q),
        .clock(tag_d$6$clock)
    );
    top$held_n tag_d$7(
        .d(tag_d$7$d),
        .q(tag_d$7$q),
        .clock(tag_d$7$clock)
    );
    top$held_n tag_d$8(
        .d(tag_d$8$d),
        .q(tag_d$8$q),
        .clock(tag_d$8$clock)
    );
    top$held_n tag_d$9(
        .d(tag_d$9$d),
        .q(tag_d$9$q),
        .clock(tag_d$9$clock)
    );
    top$held_n tag_d$10(
        .d(tag_d$10$d),
        .q(tag_d$10$q),
        .clock(tag_d$10$clock)
    );
    top$held_n tag_d$11(
        .d(tag_d$11$d),
        .q(tag_d$11$q),
        .clock(tag_d$11$clock)
    );
    top$held_n tag_d$12(
        .d(tag_d$12$d),
        .q(tag_d$12$q),
        .clock(tag_d$12$clock)
    );
    top$held_n tag_d$13(
        .d(tag_d$13$d),
        .q(tag_d$13$q),
        .clock(tag_d$13$clock)
    );
    top$held_n tag_d$14(
        .d(tag_d$14$d),
        .q(tag_d$14$q),
        .clock(tag_d$14$clock)
    );
    top$held_n tag_d$15(
        .d(tag_d$15$d),
        .q(tag_d$15$q),
        .clock(tag_d$15$clock)
    );
    top$last_al tag_r$0(
        .d(tag_r$0$d),
        .q(tag_r$0$q),
        .clock(tag_r$0$clock)
    );
    top$last_al tag_r$1(
        .d(tag_r$1$d),
        .q(tag_r$1$q),
        .clock(tag_r$1$clock)
    );
    top$last_al tag_r$2(
        .d(tag_r$2$d),
        .q(tag_r$2$q),
        .clock(tag_r$2$clock)
    );
    top$last_al tag_r$3(
        .d(tag_r$3$d),
        .q(tag_r$3$q),
        .clock(tag_r$3$clock)
    );
    top$last_al tag_r$4(
        .d(tag_r$4$d),
        .q(tag_r$4$q),
        .clock(tag_r$4$clock)
    );
    top$last_al tag_r$5(
        .d(tag_r$5$d),
        .q(tag_r$5$q),
        .clock(tag_r$5$clock)
    );
    top$last_al tag_r$6(
        .d(tag_r$6$d),
        .q(tag_r$6$q),
        .clock(tag_r$6$clock)
    );
    top$last_al tag_r$7(
        .d(tag_r$7$d),
        .q(tag_r$7$q),
        .clock(tag_r$7$clock)
    );
    top$last_al tag_r$8(
        .d(tag_r$8$d),
        .q(tag_r$8$q),
        .clock(tag_r$8$clock)
    );
    top$last_al tag_r$9(
        .d(tag_r$9$d),
        .q(tag_r$9$q),
        .clock(tag_r$9$clock)
    );
    top$last_al tag_r$10(
        .d(tag_r$10$d),
        .q(tag_r$10$q),
        .clock(tag_r$10$clock)
    );
    top$last_al tag_r$11(
        .d(tag_r$11$d),
        .q(tag_r$11$q),
        .clock(tag_r$11$clock)
    );
    top$last_al tag_r$12(
        .d(tag_r$12$d),
        .q(tag_r$12$q),
        .clock(tag_r$12$clock)
    );
    top$last_al tag_r$13(
        .d(tag_r$13$d),
        .q(tag_r$13$q),
        .clock(tag_r$13$clock)
    );
    top$last_al tag_r$14(
        .d(tag_r$14$d),
        .q(tag_r$14$q),
        .clock(tag_r$14$clock)
    );
    top$last_al tag_r$15(
        .d(tag_r$15$d),
        .q(tag_r$15$q),
        .clock(tag_r$15$clock)
    );
    top$ask_n tag_head(
        .d(tag_head$d),
        .q(tag_head$q),
        .clock(tag_head$clock)
    );
    top$tag_n tag_n(
        .d(tag_n$d),
        .q(tag_n$q),
        .clock(tag_n$clock)
    );
    top$ask_req$0 ta_out(
        .d(ta_out$d),
        .q(ta_out$q),
        .clock(ta_out$clock)
    );
    top$ask_req$0 tb_out(
        .d(tb_out$d),
        .q(tb_out$q),
        .clock(tb_out$clock)
    );
    top$held_n node_inf(
        .d(node_inf$d),
        .q(node_inf$q),
        .clock(node_inf$clock)
    );
    top$cur held0(
        .d(held0$d),
        .q(held0$q),
        .clock(held0$clock)
    );
    top$cur held1(
        .d(held1$d),
        .q(held1$q),
        .clock(held1$clock)
    );
    top$held_n held_n(
        .d(held_n$d),
        .q(held_n$q),
        .clock(held_n$clock)
    );
    top$cur cur(
        .d(cur$d),
        .q(cur$q),
        .clock(cur$clock)
    );
    top$beat beat(
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
    
endmodule // top


module top$ask_e$0(d,q,clock);
    
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
          
endmodule // top$ask_e$0


module top$ask_n(d,q,clock);
    
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
          
endmodule // top$ask_n


module top$ask_req$0(d,q,clock);
    
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
          
endmodule // top$ask_req$0


module top$beat(d,q,clock);
    
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
          
endmodule // top$beat


module top$cur(d,q,clock);
    
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
          
endmodule // top$cur


module top$held_n(d,q,clock);
    
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
          
endmodule // top$held_n


module top$last_al(d,q,clock);
    
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
          
endmodule // top$last_al


module top$tag_n(d,q,clock);
    
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
          
endmodule // top$tag_n
