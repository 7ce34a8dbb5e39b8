

module top(clock,clear,mask,halt,leaf_in,leaf_ids,leaf_tag,leaf_side,fill_a,fill_b,fill_id,fill_word,tri_ready,leaf_ready,need_a,need_b,ta_id,tb_id,pair_valid,pair_tag,a_word,b_word,busy);
    
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
    top$cache cache(
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
    top$b_ok0 leaf_v(
        .d(leaf_v$d),
        .q(leaf_v$q),
        .clock(leaf_v$clock)
    );
    top$leaf_id leaf_id(
        .d(leaf_id$d),
        .q(leaf_id$q),
        .clock(leaf_id$clock)
    );
    top$leaf_id leaf_t(
        .d(leaf_t$d),
        .q(leaf_t$q),
        .clock(leaf_t$clock)
    );
    top$b_ok0 side(
        .d(side$d),
        .q(side$q),
        .clock(side$clock)
    );
    top$b_ok0 b_ok0(
        .d(b_ok0$d),
        .q(b_ok0$q),
        .clock(b_ok0$clock)
    );
    top$b_ok0 b_ok1(
        .d(b_ok1$d),
        .q(b_ok1$q),
        .clock(b_ok1$clock)
    );
    top$b_id0 b_id0(
        .d(b_id0$d),
        .q(b_id0$q),
        .clock(b_id0$clock)
    );
    top$b_id0 b_id1(
        .d(b_id1$d),
        .q(b_id1$q),
        .clock(b_id1$clock)
    );
    top$b_word0 b_word0(
        .d(b_word0$d),
        .q(b_word0$q),
        .clock(b_word0$clock)
    );
    top$b_word0 b_word1(
        .d(b_word1$d),
        .q(b_word1$q),
        .clock(b_word1$clock)
    );
    top$b_ok0 pair_v(
        .d(pair_v$d),
        .q(pair_v$q),
        .clock(pair_v$clock)
    );
    top$leaf_id pair_t(
        .d(pair_t$d),
        .q(pair_t$q),
        .clock(pair_t$clock)
    );
    top$b_word0 pair_a(
        .d(pair_a$d),
        .q(pair_a$q),
        .clock(pair_a$clock)
    );
    top$b_word0 pair_b(
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
    
endmodule // top


module top$b_id0(d,q,clock);
    
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
          
endmodule // top$b_id0


module top$b_ok0(d,q,clock);
    
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
          
endmodule // top$b_ok0


module top$b_word0(d,q,clock);
    
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
          
endmodule // top$b_word0


module top$cache(clock,clear,mask,fill,fill_id,fill_word,id,next_id,hit,word);
    
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
    top$cache$valid valid(
        .d(valid$d),
        .q(valid$q),
        .clock(valid$clock)
    );
    top$cache$ids ids(
        .read_address(ids$read_address),
        .read_clock(ids$read_clock),
        .read_data(ids$read_data),
        .write_address(ids$write_address),
        .write_clock(ids$write_clock),
        .write_data(ids$write_data),
        .write_enable(ids$write_enable)
    );
    top$cache$words words(
        .read_address(words$read_address),
        .read_clock(words$read_clock),
        .read_data(words$read_data),
        .write_address(words$write_address),
        .write_clock(words$write_clock),
        .write_data(words$write_data),
        .write_enable(words$write_enable)
    );
    top$b_ok0 byp(
        .d(byp$d),
        .q(byp$q),
        .clock(byp$clock)
    );
    top$b_id0 last_id(
        .d(last_id$d),
        .q(last_id$q),
        .clock(last_id$clock)
    );
    top$b_word0 last_word(
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
    
endmodule // top$cache


module top$cache$ids(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
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
                
endmodule // top$cache$ids


module top$cache$valid(d,q,clock);
    
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
          
endmodule // top$cache$valid


module top$cache$words(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
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
                
endmodule // top$cache$words


module top$leaf_id(d,q,clock);
    
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
          
endmodule // top$leaf_id
