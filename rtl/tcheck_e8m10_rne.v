

module top(clock,m_0$0,m_0$1,m_0$2,m_0$3,m_1$0,m_1$1,m_1$2,m_1$3,m_2$0,m_2$1,m_2$2,m_2$3,alpha_m,alpha_f,f_0$0,f_0$1,f_0$2,f_0$3,f_1$0,f_1$1,f_1$2,f_1$3,f_2$0,f_2$1,f_2$2,f_2$3,beta_m,beta_f,scale,v_x$0,v_x$1,v_x$2,v_y$0,v_y$1,v_y$2,v_z$0,v_z$1,v_z$2,v_exact,tag,valid_in,s_x$0,s_x$1,s_x$2,s_b$0,s_b$1,s_b$2,cross_t$0,cross_t$1,cross_t$2,cross_f$0,cross_f$1,cross_f$2,hit,miss,tag_out,valid_out);
    
    // Module arguments
    input wire  clock;
    input wire  [18:0] m_0$0;
    input wire  [18:0] m_0$1;
    input wire  [18:0] m_0$2;
    input wire  [18:0] m_0$3;
    input wire  [18:0] m_1$0;
    input wire  [18:0] m_1$1;
    input wire  [18:0] m_1$2;
    input wire  [18:0] m_1$3;
    input wire  [18:0] m_2$0;
    input wire  [18:0] m_2$1;
    input wire  [18:0] m_2$2;
    input wire  [18:0] m_2$3;
    input wire  [18:0] alpha_m;
    input wire  [18:0] alpha_f;
    input wire  [18:0] f_0$0;
    input wire  [18:0] f_0$1;
    input wire  [18:0] f_0$2;
    input wire  [18:0] f_0$3;
    input wire  [18:0] f_1$0;
    input wire  [18:0] f_1$1;
    input wire  [18:0] f_1$2;
    input wire  [18:0] f_1$3;
    input wire  [18:0] f_2$0;
    input wire  [18:0] f_2$1;
    input wire  [18:0] f_2$2;
    input wire  [18:0] f_2$3;
    input wire  [18:0] beta_m;
    input wire  [18:0] beta_f;
    input wire  [18:0] scale;
    input wire  [18:0] v_x$0;
    input wire  [18:0] v_x$1;
    input wire  [18:0] v_x$2;
    input wire  [18:0] v_y$0;
    input wire  [18:0] v_y$1;
    input wire  [18:0] v_y$2;
    input wire  [18:0] v_z$0;
    input wire  [18:0] v_z$1;
    input wire  [18:0] v_z$2;
    input wire  v_exact;
    input wire  [31:0] tag;
    input wire  valid_in;
    output reg  [18:0] s_x$0;
    output reg  [18:0] s_x$1;
    output reg  [18:0] s_x$2;
    output reg  [18:0] s_b$0;
    output reg  [18:0] s_b$1;
    output reg  [18:0] s_b$2;
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
    localparam  mask = 19'b111111111111111111;
    
    // Stub signals
    reg  [18:0] in_m_0$0$d;
    wire  [18:0] in_m_0$0$q;
    reg  in_m_0$0$clock;
    reg  [18:0] in_m_0$1$d;
    wire  [18:0] in_m_0$1$q;
    reg  in_m_0$1$clock;
    reg  [18:0] in_m_0$2$d;
    wire  [18:0] in_m_0$2$q;
    reg  in_m_0$2$clock;
    reg  [18:0] in_m_0$3$d;
    wire  [18:0] in_m_0$3$q;
    reg  in_m_0$3$clock;
    reg  [18:0] in_m_1$0$d;
    wire  [18:0] in_m_1$0$q;
    reg  in_m_1$0$clock;
    reg  [18:0] in_m_1$1$d;
    wire  [18:0] in_m_1$1$q;
    reg  in_m_1$1$clock;
    reg  [18:0] in_m_1$2$d;
    wire  [18:0] in_m_1$2$q;
    reg  in_m_1$2$clock;
    reg  [18:0] in_m_1$3$d;
    wire  [18:0] in_m_1$3$q;
    reg  in_m_1$3$clock;
    reg  [18:0] in_m_2$0$d;
    wire  [18:0] in_m_2$0$q;
    reg  in_m_2$0$clock;
    reg  [18:0] in_m_2$1$d;
    wire  [18:0] in_m_2$1$q;
    reg  in_m_2$1$clock;
    reg  [18:0] in_m_2$2$d;
    wire  [18:0] in_m_2$2$q;
    reg  in_m_2$2$clock;
    reg  [18:0] in_m_2$3$d;
    wire  [18:0] in_m_2$3$q;
    reg  in_m_2$3$clock;
    reg  [18:0] in_alpha_m$d;
    wire  [18:0] in_alpha_m$q;
    reg  in_alpha_m$clock;
    reg  [18:0] in_alpha_f$d;
    wire  [18:0] in_alpha_f$q;
    reg  in_alpha_f$clock;
    reg  [18:0] in_f_0$0$d;
    wire  [18:0] in_f_0$0$q;
    reg  in_f_0$0$clock;
    reg  [18:0] in_f_0$1$d;
    wire  [18:0] in_f_0$1$q;
    reg  in_f_0$1$clock;
    reg  [18:0] in_f_0$2$d;
    wire  [18:0] in_f_0$2$q;
    reg  in_f_0$2$clock;
    reg  [18:0] in_f_0$3$d;
    wire  [18:0] in_f_0$3$q;
    reg  in_f_0$3$clock;
    reg  [18:0] in_f_1$0$d;
    wire  [18:0] in_f_1$0$q;
    reg  in_f_1$0$clock;
    reg  [18:0] in_f_1$1$d;
    wire  [18:0] in_f_1$1$q;
    reg  in_f_1$1$clock;
    reg  [18:0] in_f_1$2$d;
    wire  [18:0] in_f_1$2$q;
    reg  in_f_1$2$clock;
    reg  [18:0] in_f_1$3$d;
    wire  [18:0] in_f_1$3$q;
    reg  in_f_1$3$clock;
    reg  [18:0] in_f_2$0$d;
    wire  [18:0] in_f_2$0$q;
    reg  in_f_2$0$clock;
    reg  [18:0] in_f_2$1$d;
    wire  [18:0] in_f_2$1$q;
    reg  in_f_2$1$clock;
    reg  [18:0] in_f_2$2$d;
    wire  [18:0] in_f_2$2$q;
    reg  in_f_2$2$clock;
    reg  [18:0] in_f_2$3$d;
    wire  [18:0] in_f_2$3$q;
    reg  in_f_2$3$clock;
    reg  [18:0] in_beta_m$d;
    wire  [18:0] in_beta_m$q;
    reg  in_beta_m$clock;
    reg  [18:0] in_beta_f$d;
    wire  [18:0] in_beta_f$q;
    reg  in_beta_f$clock;
    reg  [18:0] in_scale$d;
    wire  [18:0] in_scale$q;
    reg  in_scale$clock;
    reg  [18:0] in_v_x$0$d;
    wire  [18:0] in_v_x$0$q;
    reg  in_v_x$0$clock;
    reg  [18:0] in_v_x$1$d;
    wire  [18:0] in_v_x$1$q;
    reg  in_v_x$1$clock;
    reg  [18:0] in_v_x$2$d;
    wire  [18:0] in_v_x$2$q;
    reg  in_v_x$2$clock;
    reg  [18:0] in_v_y$0$d;
    wire  [18:0] in_v_y$0$q;
    reg  in_v_y$0$clock;
    reg  [18:0] in_v_y$1$d;
    wire  [18:0] in_v_y$1$q;
    reg  in_v_y$1$clock;
    reg  [18:0] in_v_y$2$d;
    wire  [18:0] in_v_y$2$q;
    reg  in_v_y$2$clock;
    reg  [18:0] in_v_z$0$d;
    wire  [18:0] in_v_z$0$q;
    reg  in_v_z$0$clock;
    reg  [18:0] in_v_z$1$d;
    wire  [18:0] in_v_z$1$q;
    reg  in_v_z$1$clock;
    reg  [18:0] in_v_z$2$d;
    wire  [18:0] in_v_z$2$q;
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
    reg  [18:0] mb_0$0$a0;
    reg  [18:0] mb_0$0$a1;
    reg  [18:0] mb_0$0$a2;
    reg  [18:0] mb_0$0$b0;
    reg  [18:0] mb_0$0$b1;
    reg  [18:0] mb_0$0$b2;
    reg  [18:0] mb_0$0$c;
    wire  [18:0] mb_0$0$y;
    reg  mb_0$1$clock;
    reg  [18:0] mb_0$1$a0;
    reg  [18:0] mb_0$1$a1;
    reg  [18:0] mb_0$1$a2;
    reg  [18:0] mb_0$1$b0;
    reg  [18:0] mb_0$1$b1;
    reg  [18:0] mb_0$1$b2;
    reg  [18:0] mb_0$1$c;
    wire  [18:0] mb_0$1$y;
    reg  mb_0$2$clock;
    reg  [18:0] mb_0$2$a0;
    reg  [18:0] mb_0$2$a1;
    reg  [18:0] mb_0$2$a2;
    reg  [18:0] mb_0$2$b0;
    reg  [18:0] mb_0$2$b1;
    reg  [18:0] mb_0$2$b2;
    reg  [18:0] mb_0$2$c;
    wire  [18:0] mb_0$2$y;
    reg  mb_0$3$clock;
    reg  [18:0] mb_0$3$a0;
    reg  [18:0] mb_0$3$a1;
    reg  [18:0] mb_0$3$a2;
    reg  [18:0] mb_0$3$b0;
    reg  [18:0] mb_0$3$b1;
    reg  [18:0] mb_0$3$b2;
    reg  [18:0] mb_0$3$c;
    wire  [18:0] mb_0$3$y;
    reg  mb_1$0$clock;
    reg  [18:0] mb_1$0$a0;
    reg  [18:0] mb_1$0$a1;
    reg  [18:0] mb_1$0$a2;
    reg  [18:0] mb_1$0$b0;
    reg  [18:0] mb_1$0$b1;
    reg  [18:0] mb_1$0$b2;
    reg  [18:0] mb_1$0$c;
    wire  [18:0] mb_1$0$y;
    reg  mb_1$1$clock;
    reg  [18:0] mb_1$1$a0;
    reg  [18:0] mb_1$1$a1;
    reg  [18:0] mb_1$1$a2;
    reg  [18:0] mb_1$1$b0;
    reg  [18:0] mb_1$1$b1;
    reg  [18:0] mb_1$1$b2;
    reg  [18:0] mb_1$1$c;
    wire  [18:0] mb_1$1$y;
    reg  mb_1$2$clock;
    reg  [18:0] mb_1$2$a0;
    reg  [18:0] mb_1$2$a1;
    reg  [18:0] mb_1$2$a2;
    reg  [18:0] mb_1$2$b0;
    reg  [18:0] mb_1$2$b1;
    reg  [18:0] mb_1$2$b2;
    reg  [18:0] mb_1$2$c;
    wire  [18:0] mb_1$2$y;
    reg  mb_1$3$clock;
    reg  [18:0] mb_1$3$a0;
    reg  [18:0] mb_1$3$a1;
    reg  [18:0] mb_1$3$a2;
    reg  [18:0] mb_1$3$b0;
    reg  [18:0] mb_1$3$b1;
    reg  [18:0] mb_1$3$b2;
    reg  [18:0] mb_1$3$c;
    wire  [18:0] mb_1$3$y;
    reg  mb_2$0$clock;
    reg  [18:0] mb_2$0$a0;
    reg  [18:0] mb_2$0$a1;
    reg  [18:0] mb_2$0$a2;
    reg  [18:0] mb_2$0$b0;
    reg  [18:0] mb_2$0$b1;
    reg  [18:0] mb_2$0$b2;
    reg  [18:0] mb_2$0$c;
    wire  [18:0] mb_2$0$y;
    reg  mb_2$1$clock;
    reg  [18:0] mb_2$1$a0;
    reg  [18:0] mb_2$1$a1;
    reg  [18:0] mb_2$1$a2;
    reg  [18:0] mb_2$1$b0;
    reg  [18:0] mb_2$1$b1;
    reg  [18:0] mb_2$1$b2;
    reg  [18:0] mb_2$1$c;
    wire  [18:0] mb_2$1$y;
    reg  mb_2$2$clock;
    reg  [18:0] mb_2$2$a0;
    reg  [18:0] mb_2$2$a1;
    reg  [18:0] mb_2$2$a2;
    reg  [18:0] mb_2$2$b0;
    reg  [18:0] mb_2$2$b1;
    reg  [18:0] mb_2$2$b2;
    reg  [18:0] mb_2$2$c;
    wire  [18:0] mb_2$2$y;
    reg  mb_2$3$clock;
    reg  [18:0] mb_2$3$a0;
    reg  [18:0] mb_2$3$a1;
    reg  [18:0] mb_2$3$a2;
    reg  [18:0] mb_2$3$b0;
    reg  [18:0] mb_2$3$b1;
    reg  [18:0] mb_2$3$b2;
    reg  [18:0] mb_2$3$c;
    wire  [18:0] mb_2$3$y;
    reg  mg_0$0$clock;
    reg  [18:0] mg_0$0$a0;
    reg  [18:0] mg_0$0$a1;
    reg  [18:0] mg_0$0$a2;
    reg  [18:0] mg_0$0$b0;
    reg  [18:0] mg_0$0$b1;
    reg  [18:0] mg_0$0$b2;
    reg  [18:0] mg_0$0$c;
    wire  [18:0] mg_0$0$y;
    reg  mg_0$1$clock;
    reg  [18:0] mg_0$1$a0;
    reg  [18:0] mg_0$1$a1;
    reg  [18:0] mg_0$1$a2;
    reg  [18:0] mg_0$1$b0;
    reg  [18:0] mg_0$1$b1;
    reg  [18:0] mg_0$1$b2;
    reg  [18:0] mg_0$1$c;
    wire  [18:0] mg_0$1$y;
    reg  mg_0$2$clock;
    reg  [18:0] mg_0$2$a0;
    reg  [18:0] mg_0$2$a1;
    reg  [18:0] mg_0$2$a2;
    reg  [18:0] mg_0$2$b0;
    reg  [18:0] mg_0$2$b1;
    reg  [18:0] mg_0$2$b2;
    reg  [18:0] mg_0$2$c;
    wire  [18:0] mg_0$2$y;
    reg  mg_0$3$clock;
    reg  [18:0] mg_0$3$a0;
    reg  [18:0] mg_0$3$a1;
    reg  [18:0] mg_0$3$a2;
    reg  [18:0] mg_0$3$b0;
    reg  [18:0] mg_0$3$b1;
    reg  [18:0] mg_0$3$b2;
    reg  [18:0] mg_0$3$c;
    wire  [18:0] mg_0$3$y;
    reg  mg_1$0$clock;
    reg  [18:0] mg_1$0$a0;
    reg  [18:0] mg_1$0$a1;
    reg  [18:0] mg_1$0$a2;
    reg  [18:0] mg_1$0$b0;
    reg  [18:0] mg_1$0$b1;
    reg  [18:0] mg_1$0$b2;
    reg  [18:0] mg_1$0$c;
    wire  [18:0] mg_1$0$y;
    reg  mg_1$1$clock;
    reg  [18:0] mg_1$1$a0;
    reg  [18:0] mg_1$1$a1;
    reg  [18:0] mg_1$1$a2;
    reg  [18:0] mg_1$1$b0;
    reg  [18:0] mg_1$1$b1;
    reg  [18:0] mg_1$1$b2;
    reg  [18:0] mg_1$1$c;
    wire  [18:0] mg_1$1$y;
    reg  mg_1$2$clock;
    reg  [18:0] mg_1$2$a0;
    reg  [18:0] mg_1$2$a1;
    reg  [18:0] mg_1$2$a2;
    reg  [18:0] mg_1$2$b0;
    reg  [18:0] mg_1$2$b1;
    reg  [18:0] mg_1$2$b2;
    reg  [18:0] mg_1$2$c;
    wire  [18:0] mg_1$2$y;
    reg  mg_1$3$clock;
    reg  [18:0] mg_1$3$a0;
    reg  [18:0] mg_1$3$a1;
    reg  [18:0] mg_1$3$a2;
    reg  [18:0] mg_1$3$b0;
    reg  [18:0] mg_1$3$b1;
    reg  [18:0] mg_1$3$b2;
    reg  [18:0] mg_1$3$c;
    wire  [18:0] mg_1$3$y;
    reg  mg_2$0$clock;
    reg  [18:0] mg_2$0$a0;
    reg  [18:0] mg_2$0$a1;
    reg  [18:0] mg_2$0$a2;
    reg  [18:0] mg_2$0$b0;
    reg  [18:0] mg_2$0$b1;
    reg  [18:0] mg_2$0$b2;
    reg  [18:0] mg_2$0$c;
    wire  [18:0] mg_2$0$y;
    reg  mg_2$1$clock;
    reg  [18:0] mg_2$1$a0;
    reg  [18:0] mg_2$1$a1;
    reg  [18:0] mg_2$1$a2;
    reg  [18:0] mg_2$1$b0;
    reg  [18:0] mg_2$1$b1;
    reg  [18:0] mg_2$1$b2;
    reg  [18:0] mg_2$1$c;
    wire  [18:0] mg_2$1$y;
    reg  mg_2$2$clock;
    reg  [18:0] mg_2$2$a0;
    reg  [18:0] mg_2$2$a1;
    reg  [18:0] mg_2$2$a2;
    reg  [18:0] mg_2$2$b0;
    reg  [18:0] mg_2$2$b1;
    reg  [18:0] mg_2$2$b2;
    reg  [18:0] mg_2$2$c;
    wire  [18:0] mg_2$2$y;
    reg  mg_2$3$clock;
    reg  [18:0] mg_2$3$a0;
    reg  [18:0] mg_2$3$a1;
    reg  [18:0] mg_2$3$a2;
    reg  [18:0] mg_2$3$b0;
    reg  [18:0] mg_2$3$b1;
    reg  [18:0] mg_2$3$b2;
    reg  [18:0] mg_2$3$c;
    wire  [18:0] mg_2$3$y;
    reg  c3_0$clock;
    reg  [18:0] c3_0$d;
    wire  [18:0] c3_0$q;
    reg  c3_1$clock;
    reg  [18:0] c3_1$d;
    wire  [18:0] c3_1$q;
    reg  c3_2$clock;
    reg  [18:0] c3_2$d;
    wire  [18:0] c3_2$q;
    reg  am$clock;
    reg  [18:0] am$a;
    reg  [18:0] am$b;
    reg  am$valid_in;
    wire  [18:0] am$y;
    wire  am$valid_out;
    reg  af$clock;
    reg  [18:0] af$a;
    reg  [18:0] af$b;
    reg  af$valid_in;
    wire  [18:0] af$y;
    wire  af$valid_out;
    reg  aerr$clock;
    reg  [18:0] aerr$a;
    reg  [18:0] aerr$b;
    reg  aerr$sub;
    reg  aerr$valid_in;
    wire  [18:0] aerr$y;
    wire  aerr$valid_out;
    reg  aerr_wait$clock;
    reg  [18:0] aerr_wait$d;
    wire  [18:0] aerr_wait$q;
    reg  la$0$clock;
    reg  [18:0] la$0$a;
    reg  [18:0] la$0$b;
    reg  la$0$sub;
    reg  la$0$valid_in;
    wire  [18:0] la$0$y;
    wire  la$0$valid_out;
    reg  la$1$clock;
    reg  [18:0] la$1$a;
    reg  [18:0] la$1$b;
    reg  la$1$sub;
    reg  la$1$valid_in;
    wire  [18:0] la$1$y;
    wire  la$1$valid_out;
    reg  la$2$clock;
    reg  [18:0] la$2$a;
    reg  [18:0] la$2$b;
    reg  la$2$sub;
    reg  la$2$valid_in;
    wire  [18:0] la$2$y;
    wire  la$2$valid_out;
    reg  lb$0$clock;
    reg  [18:0] lb$0$a;
    reg  [18:0] lb$0$b;
    reg  lb$0$sub;
    reg  lb$0$valid_in;
    wire  [18:0] lb$0$y;
    wire  lb$0$valid_out;
    reg  lb$1$clock;
    reg  [18:0] lb$1$a;
    reg  [18:0] lb$1$b;
    reg  lb$1$sub;
    reg  lb$1$valid_in;
    wire  [18:0] lb$1$y;
    wire  lb$1$valid_out;
    reg  lb$2$clock;
    reg  [18:0] lb$2$a;
    reg  [18:0] lb$2$b;
    reg  lb$2$sub;
    reg  lb$2$valid_in;
    wire  [18:0] lb$2$y;
    wire  lb$2$valid_out;
    reg  l1$0$clock;
    reg  [18:0] l1$0$a;
    reg  [18:0] l1$0$b;
    reg  l1$0$sub;
    reg  l1$0$valid_in;
    wire  [18:0] l1$0$y;
    wire  l1$0$valid_out;
    reg  l1$1$clock;
    reg  [18:0] l1$1$a;
    reg  [18:0] l1$1$b;
    reg  l1$1$sub;
    reg  l1$1$valid_in;
    wire  [18:0] l1$1$y;
    wire  l1$1$valid_out;
    reg  l1$2$clock;
    reg  [18:0] l1$2$a;
    reg  [18:0] l1$2$b;
    reg  l1$2$sub;
    reg  l1$2$valid_in;
    wire  [18:0] l1$2$y;
    wire  l1$2$valid_out;
    reg  l1_wait$0$clock;
    reg  [18:0] l1_wait$0$d;
    wire  [18:0] l1_wait$0$q;
    reg  l1_wait$1$clock;
    reg  [18:0] l1_wait$1$d;
    wire  [18:0] l1_wait$1$q;
    reg  l1_wait$2$clock;
    reg  [18:0] l1_wait$2$d;
    wire  [18:0] l1_wait$2$q;
    reg  err$0$clock;
    reg  [18:0] err$0$a;
    reg  [18:0] err$0$b;
    reg  err$0$valid_in;
    wire  [18:0] err$0$y;
    wire  err$0$valid_out;
    reg  err$1$clock;
    reg  [18:0] err$1$a;
    reg  [18:0] err$1$b;
    reg  err$1$valid_in;
    wire  [18:0] err$1$y;
    wire  err$1$valid_out;
    reg  err$2$clock;
    reg  [18:0] err$2$a;
    reg  [18:0] err$2$b;
    reg  err$2$valid_in;
    wire  [18:0] err$2$y;
    wire  err$2$valid_out;
    reg  [18:0] mbr_0$0$d;
    wire  [18:0] mbr_0$0$q;
    reg  mbr_0$0$clock;
    reg  [18:0] mbr_0$1$d;
    wire  [18:0] mbr_0$1$q;
    reg  mbr_0$1$clock;
    reg  [18:0] mbr_0$2$d;
    wire  [18:0] mbr_0$2$q;
    reg  mbr_0$2$clock;
    reg  [18:0] mbr_0$3$d;
    wire  [18:0] mbr_0$3$q;
    reg  mbr_0$3$clock;
    reg  [18:0] mbr_1$0$d;
    wire  [18:0] mbr_1$0$q;
    reg  mbr_1$0$clock;
    reg  [18:0] mbr_1$1$d;
    wire  [18:0] mbr_1$1$q;
    reg  mbr_1$1$clock;
    reg  [18:0] mbr_1$2$d;
    wire  [18:0] mbr_1$2$q;
    reg  mbr_1$2$clock;
    reg  [18:0] mbr_1$3$d;
    wire  [18:0] mbr_1$3$q;
    reg  mbr_1$3$clock;
    reg  [18:0] mbr_2$0$d;
    wire  [18:0] mbr_2$0$q;
    reg  mbr_2$0$clock;
    reg  [18:0] mbr_2$1$d;
    wire  [18:0] mbr_2$1$q;
    reg  mbr_2$1$clock;
    reg  [18:0] mbr_2$2$d;
    wire  [18:0] mbr_2$2$q;
    reg  mbr_2$2$clock;
    reg  [18:0] mbr_2$3$d;
    wire  [18:0] mbr_2$3$q;
    reg  mbr_2$3$clock;
    reg  [18:0] mgr_0$0$d;
    wire  [18:0] mgr_0$0$q;
    reg  mgr_0$0$clock;
    reg  [18:0] mgr_0$1$d;
    wire  [18:0] mgr_0$1$q;
    reg  mgr_0$1$clock;
    reg  [18:0] mgr_0$2$d;
    wire  [18:0] mgr_0$2$q;
    reg  mgr_0$2$clock;
    reg  [18:0] mgr_0$3$d;
    wire  [18:0] mgr_0$3$q;
    reg  mgr_0$3$clock;
    reg  [18:0] mgr_1$0$d;
    wire  [18:0] mgr_1$0$q;
    reg  mgr_1$0$clock;
    reg  [18:0] mgr_1$1$d;
    wire  [18:0] mgr_1$1$q;
    reg  mgr_1$1$clock;
    reg  [18:0] mgr_1$2$d;
    wire  [18:0] mgr_1$2$q;
    reg  mgr_1$2$clock;
    reg  [18:0] mgr_1$3$d;
    wire  [18:0] mgr_1$3$q;
    reg  mgr_1$3$clock;
    reg  [18:0] mgr_2$0$d;
    wire  [18:0] mgr_2$0$q;
    reg  mgr_2$0$clock;
    reg  [18:0] mgr_2$1$d;
    wire  [18:0] mgr_2$1$q;
    reg  mgr_2$1$clock;
    reg  [18:0] mgr_2$2$d;
    wire  [18:0] mgr_2$2$q;
    reg  mgr_2$2$clock;
    reg  [18:0] mgr_2$3$d;
    wire  [18:0] mgr_2$3$q;
    reg  mgr_2$3$clock;
    reg  mg3_0$clock;
    reg  [18:0] mg3_0$d;
    wire  [18:0] mg3_0$q;
    reg  mg3_1$clock;
    reg  [18:0] mg3_1$d;
    wire  [18:0] mg3_1$q;
    reg  mg3_2$clock;
    reg  [18:0] mg3_2$d;
    wire  [18:0] mg3_2$q;
    reg  m3_0$0$clock;
    reg  [18:0] m3_0$0$a;
    reg  [18:0] m3_0$0$b;
    reg  m3_0$0$sub;
    reg  m3_0$0$valid_in;
    wire  [18:0] m3_0$0$y;
    wire  m3_0$0$valid_out;
    reg  m3_0$1$clock;
    reg  [18:0] m3_0$1$a;
    reg  [18:0] m3_0$1$b;
    reg  m3_0$1$sub;
    reg  m3_0$1$valid_in;
    wire  [18:0] m3_0$1$y;
    wire  m3_0$1$valid_out;
    reg  m3_0$2$clock;
    reg  [18:0] m3_0$2$a;
    reg  [18:0] m3_0$2$b;
    reg  m3_0$2$sub;
    reg  m3_0$2$valid_in;
    wire  [18:0] m3_0$2$y;
    wire  m3_0$2$valid_out;
    reg  m3_1$0$clock;
    reg  [18:0] m3_1$0$a;
    reg  [18:0] m3_1$0$b;
    reg  m3_1$0$sub;
    reg  m3_1$0$valid_in;
    wire  [18:0] m3_1$0$y;
    wire  m3_1$0$valid_out;
    reg  m3_1$1$clock;
    reg  [18:0] m3_1$1$a;
    reg  [18:0] m3_1$1$b;
    reg  m3_1$1$sub;
    reg  m3_1$1$valid_in;
    wire  [18:0] m3_1$1$y;
    wire  m3_1$1$valid_out;
    reg  m3_1$2$clock;
    reg  [18:0] m3_1$2$a;
    reg  [18:0] m3_1$2$b;
    reg  m3_1$2$sub;
    reg  m3_1$2$valid_in;
    wire  [18:0] m3_1$2$y;
    wire  m3_1$2$valid_out;
    reg  m3_2$0$clock;
    reg  [18:0] m3_2$0$a;
    reg  [18:0] m3_2$0$b;
    reg  m3_2$0$sub;
    reg  m3_2$0$valid_in;
    wire  [18:0] m3_2$0$y;
    wire  m3_2$0$valid_out;
    reg  m3_2$1$clock;
    reg  [18:0] m3_2$1$a;
    reg  [18:0] m3_2$1$b;
    reg  m3_2$1$sub;
    reg  m3_2$1$valid_in;
    wire  [18:0] m3_2$1$y;
    wire  m3_2$1$valid_out;
    reg  m3_2$2$clock;
    reg  [18:0] m3_2$2$a;
    reg  [18:0] m3_2$2$b;
    reg  m3_2$2$sub;
    reg  m3_2$2$valid_in;
    wire  [18:0] m3_2$2$y;
    wire  m3_2$2$valid_out;
    reg  vc_0$clock;
    reg  [18:0] vc_0$d;
    wire  [18:0] vc_0$q;
    reg  vc_1$clock;
    reg  [18:0] vc_1$d;
    wire  [18:0] vc_1$q;
    reg  vc_2$clock;
    reg  [18:0] vc_2$d;
    wire  [18:0] vc_2$q;
    reg  v_x_wait$0$clock;
    reg  [18:0] v_x_wait$0$d;
    wire  [18:0] v_x_wait$0$q;
    reg  v_x_wait$1$clock;
    reg  [18:0] v_x_wait$1$d;
    wire  [18:0] v_x_wait$1$q;
    reg  v_x_wait$2$clock;
    reg  [18:0] v_x_wait$2$d;
    wire  [18:0] v_x_wait$2$q;
    reg  v_y_wait$0$clock;
    reg  [18:0] v_y_wait$0$d;
    wire  [18:0] v_y_wait$0$q;
    reg  v_y_wait$1$clock;
    reg  [18:0] v_y_wait$1$d;
    wire  [18:0] v_y_wait$1$q;
    reg  v_y_wait$2$clock;
    reg  [18:0] v_y_wait$2$d;
    wire  [18:0] v_y_wait$2$q;
    reg  v_z_wait$0$clock;
    reg  [18:0] v_z_wait$0$d;
    wire  [18:0] v_z_wait$0$q;
    reg  v_z_wait$1$clock;
    reg  [18:0] v_z_wait$1$d;
    wire  [18:0] v_z_wait$1$q;
    reg  v_z_wait$2$clock;
    reg  [18:0] v_z_wait$2$d;
    wire  [18:0] v_z_wait$2$q;
    reg  vt_0$0$clock;
    reg  [18:0] vt_0$0$a0;
    reg  [18:0] vt_0$0$a1;
    reg  [18:0] vt_0$0$a2;
    reg  [18:0] vt_0$0$b0;
    reg  [18:0] vt_0$0$b1;
    reg  [18:0] vt_0$0$b2;
    reg  [18:0] vt_0$0$c;
    wire  [18:0] vt_0$0$y;
    reg  vt_0$1$clock;
    reg  [18:0] vt_0$1$a0;
    reg  [18:0] vt_0$1$a1;
    reg  [18:0] vt_0$1$a2;
    reg  [18:0] vt_0$1$b0;
    reg  [18:0] vt_0$1$b1;
    reg  [18:0] vt_0$1$b2;
    reg  [18:0] vt_0$1$c;
    wire  [18:0] vt_0$1$y;
    reg  vt_0$2$clock;
    reg  [18:0] vt_0$2$a0;
    reg  [18:0] vt_0$2$a1;
    reg  [18:0] vt_0$2$a2;
    reg  [18:0] vt_0$2$b0;
    reg  [18:0] vt_0$2$b1;
    reg  [18:0] vt_0$2$b2;
    reg  [18:0] vt_0$2$c;
    wire  [18:0] vt_0$2$y;
    reg  vt_1$0$clock;
    reg  [18:0] vt_1$0$a0;
    reg  [18:0] vt_1$0$a1;
    reg  [18:0] vt_1$0$a2;
    reg  [18:0] vt_1$0$b0;
    reg  [18:0] vt_1$0$b1;
    reg  [18:0] vt_1$0$b2;
    reg  [18:0] vt_1$0$c;
    wire  [18:0] vt_1$0$y;
    reg  vt_1$1$clock;
    reg  [18:0] vt_1$1$a0;
    reg  [18:0] vt_1$1$a1;
    reg  [18:0] vt_1$1$a2;
    reg  [18:0] vt_1$1$b0;
    reg  [18:0] vt_1$1$b1;
    reg  [18:0] vt_1$1$b2;
    reg  [18:0] vt_1$1$c;
    wire  [18:0] vt_1$1$y;
    reg  vt_1$2$clock;
    reg  [18:0] vt_1$2$a0;
    reg  [18:0] vt_1$2$a1;
    reg  [18:0] vt_1$2$a2;
    reg  [18:0] vt_1$2$b0;
    reg  [18:0] vt_1$2$b1;
    reg  [18:0] vt_1$2$b2;
    reg  [18:0] vt_1$2$c;
    wire  [18:0] vt_1$2$y;
    reg  vt_2$0$clock;
    reg  [18:0] vt_2$0$a0;
    reg  [18:0] vt_2$0$a1;
    reg  [18:0] vt_2$0$a2;
    reg  [18:0] vt_2$0$b0;
    reg  [18:0] vt_2$0$b1;
    reg  [18:0] vt_2$0$b2;
    reg  [18:0] vt_2$0$c;
    wire  [18:0] vt_2$0$y;
    reg  vt_2$1$clock;
    reg  [18:0] vt_2$1$a0;
    reg  [18:0] vt_2$1$a1;
    reg  [18:0] vt_2$1$a2;
    reg  [18:0] vt_2$1$b0;
    reg  [18:0] vt_2$1$b1;
    reg  [18:0] vt_2$1$b2;
    reg  [18:0] vt_2$1$c;
    wire  [18:0] vt_2$1$y;
    reg  vt_2$2$clock;
    reg  [18:0] vt_2$2$a0;
    reg  [18:0] vt_2$2$a1;
    reg  [18:0] vt_2$2$a2;
    reg  [18:0] vt_2$2$b0;
    reg  [18:0] vt_2$2$b1;
    reg  [18:0] vt_2$2$b2;
    reg  [18:0] vt_2$2$c;
    wire  [18:0] vt_2$2$y;
    reg  vm_0$0$clock;
    reg  [18:0] vm_0$0$a0;
    reg  [18:0] vm_0$0$a1;
    reg  [18:0] vm_0$0$a2;
    reg  [18:0] vm_0$0$b0;
    reg  [18:0] vm_0$0$b1;
    reg  [18:0] vm_0$0$b2;
    reg  [18:0] vm_0$0$c;
    wire  [18:0] vm_0$0$y;
    reg  vm_0$1$clock;
    reg  [18:0] vm_0$1$a0;
    reg  [18:0] vm_0$1$a1;
    reg  [18:0] vm_0$1$a2;
    reg  [18:0] vm_0$1$b0;
    reg  [18:0] vm_0$1$b1;
    reg  [18:0] vm_0$1$b2;
    reg  [18:0] vm_0$1$c;
    wire  [18:0] vm_0$1$y;
    reg  vm_0$2$clock;
    reg  [18:0] vm_0$2$a0;
    reg  [18:0] vm_0$2$a1;
    reg  [18:0] vm_0$2$a2;
    reg  [18:0] vm_0$2$b0;
    reg  [18:0] vm_0$2$b1;
    reg  [18:0] vm_0$2$b2;
    reg  [18:0] vm_0$2$c;
    wire  [18:0] vm_0$2$y;
    reg  vm_1$0$clock;
    reg  [18:0] vm_1$0$a0;
    reg  [18:0] vm_1$0$a1;
    reg  [18:0] vm_1$0$a2;
    reg  [18:0] vm_1$0$b0;
    reg  [18:0] vm_1$0$b1;
    reg  [18:0] vm_1$0$b2;
    reg  [18:0] vm_1$0$c;
    wire  [18:0] vm_1$0$y;
    reg  vm_1$1$clock;
    reg  [18:0] vm_1$1$a0;
    reg  [18:0] vm_1$1$a1;
    reg  [18:0] vm_1$1$a2;
    reg  [18:0] vm_1$1$b0;
    reg  [18:0] vm_1$1$b1;
    reg  [18:0] vm_1$1$b2;
    reg  [18:0] vm_1$1$c;
    wire  [18:0] vm_1$1$y;
    reg  vm_1$2$clock;
    reg  [18:0] vm_1$2$a0;
    reg  [18:0] vm_1$2$a1;
    reg  [18:0] vm_1$2$a2;
    reg  [18:0] vm_1$2$b0;
    reg  [18:0] vm_1$2$b1;
    reg  [18:0] vm_1$2$b2;
    reg  [18:0] vm_1$2$c;
    wire  [18:0] vm_1$2$y;
    reg  vm_2$0$clock;
    reg  [18:0] vm_2$0$a0;
    reg  [18:0] vm_2$0$a1;
    reg  [18:0] vm_2$0$a2;
    reg  [18:0] vm_2$0$b0;
    reg  [18:0] vm_2$0$b1;
    reg  [18:0] vm_2$0$b2;
    reg  [18:0] vm_2$0$c;
    wire  [18:0] vm_2$0$y;
    reg  vm_2$1$clock;
    reg  [18:0] vm_2$1$a0;
    reg  [18:0] vm_2$1$a1;
    reg  [18:0] vm_2$1$a2;
    reg  [18:0] vm_2$1$b0;
    reg  [18:0] vm_2$1$b1;
    reg  [18:0] vm_2$1$b2;
    reg  [18:0] vm_2$1$c;
    wire  [18:0] vm_2$1$y;
    reg  vm_2$2$clock;
    reg  [18:0] vm_2$2$a0;
    reg  [18:0] vm_2$2$a1;
    reg  [18:0] vm_2$2$a2;
    reg  [18:0] vm_2$2$b0;
    reg  [18:0] vm_2$2$b1;
    reg  [18:0] vm_2$2$b2;
    reg  [18:0] vm_2$2$c;
    wire  [18:0] vm_2$2$y;
    reg  [18:0] vtr_0$0$d;
    wire  [18:0] vtr_0$0$q;
    reg  vtr_0$0$clock;
    reg  [18:0] vtr_0$1$d;
    wire  [18:0] vtr_0$1$q;
    reg  vtr_0$1$clock;
    reg  [18:0] vtr_0$2$d;
    wire  [18:0] vtr_0$2$q;
    reg  vtr_0$2$clock;
    reg  [18:0] vtr_1$0$d;
    wire  [18:0] vtr_1$0$q;
    reg  vtr_1$0$clock;
    reg  [18:0] vtr_1$1$d;
    wire  [18:0] vtr_1$1$q;
    reg  vtr_1$1$clock;
    reg  [18:0] vtr_1$2$d;
    wire  [18:0] vtr_1$2$q;
    reg  vtr_1$2$clock;
    reg  [18:0] vtr_2$0$d;
    wire  [18:0] vtr_2$0$q;
    reg  vtr_2$0$clock;
    reg  [18:0] vtr_2$1$d;
    wire  [18:0] vtr_2$1$q;
    reg  vtr_2$1$clock;
    reg  [18:0] vtr_2$2$d;
    wire  [18:0] vtr_2$2$q;
    reg  vtr_2$2$clock;
    reg  [18:0] vmr_0$0$d;
    wire  [18:0] vmr_0$0$q;
    reg  vmr_0$0$clock;
    reg  [18:0] vmr_0$1$d;
    wire  [18:0] vmr_0$1$q;
    reg  vmr_0$1$clock;
    reg  [18:0] vmr_0$2$d;
    wire  [18:0] vmr_0$2$q;
    reg  vmr_0$2$clock;
    reg  [18:0] vmr_1$0$d;
    wire  [18:0] vmr_1$0$q;
    reg  vmr_1$0$clock;
    reg  [18:0] vmr_1$1$d;
    wire  [18:0] vmr_1$1$q;
    reg  vmr_1$1$clock;
    reg  [18:0] vmr_1$2$d;
    wire  [18:0] vmr_1$2$q;
    reg  vmr_1$2$clock;
    reg  [18:0] vmr_2$0$d;
    wire  [18:0] vmr_2$0$q;
    reg  vmr_2$0$clock;
    reg  [18:0] vmr_2$1$d;
    wire  [18:0] vmr_2$1$q;
    reg  vmr_2$1$clock;
    reg  [18:0] vmr_2$2$d;
    wire  [18:0] vmr_2$2$q;
    reg  vmr_2$2$clock;
    reg  exact_wait$clock;
    reg  exact_wait$d;
    wire  exact_wait$q;
    reg  verts$0$clock;
    reg  [18:0] verts$0$z;
    reg  [18:0] verts$0$m0;
    reg  [18:0] verts$0$m1;
    reg  [18:0] verts$0$m2;
    reg  verts$0$exact;
    wire  [18:0] verts$0$e;
    wire  [18:0] verts$0$g;
    wire  [18:0] verts$0$f0;
    wire  [18:0] verts$0$f1;
    wire  [18:0] verts$0$f2;
    wire  [18:0] verts$0$h;
    reg  verts$1$clock;
    reg  [18:0] verts$1$z;
    reg  [18:0] verts$1$m0;
    reg  [18:0] verts$1$m1;
    reg  [18:0] verts$1$m2;
    reg  verts$1$exact;
    wire  [18:0] verts$1$e;
    wire  [18:0] verts$1$g;
    wire  [18:0] verts$1$f0;
    wire  [18:0] verts$1$f1;
    wire  [18:0] verts$1$f2;
    wire  [18:0] verts$1$h;
    reg  verts$2$clock;
    reg  [18:0] verts$2$z;
    reg  [18:0] verts$2$m0;
    reg  [18:0] verts$2$m1;
    reg  [18:0] verts$2$m2;
    reg  verts$2$exact;
    wire  [18:0] verts$2$e;
    wire  [18:0] verts$2$g;
    wire  [18:0] verts$2$f0;
    wire  [18:0] verts$2$f1;
    wire  [18:0] verts$2$f2;
    wire  [18:0] verts$2$h;
    reg  edges$0$clock;
    reg  [18:0] edges$0$p0;
    reg  [18:0] edges$0$p1;
    reg  [18:0] edges$0$p2;
    reg  [18:0] edges$0$q0;
    reg  [18:0] edges$0$q1;
    reg  [18:0] edges$0$q2;
    reg  [18:0] edges$0$pe;
    reg  [18:0] edges$0$qe;
    reg  [18:0] edges$0$pg;
    reg  [18:0] edges$0$qg;
    reg  [18:0] edges$0$pf0;
    reg  [18:0] edges$0$pf1;
    reg  [18:0] edges$0$pf2;
    reg  [18:0] edges$0$qf0;
    reg  [18:0] edges$0$qf1;
    reg  [18:0] edges$0$qf2;
    reg  [18:0] edges$0$ph;
    reg  [18:0] edges$0$qh;
    wire  [18:0] edges$0$s_x;
    wire  [18:0] edges$0$s_b;
    wire  edges$0$cross_t;
    wire  edges$0$cross_f;
    reg  edges$1$clock;
    reg  [18:0] edges$1$p0;
    reg  [18:0] edges$1$p1;
    reg  [18:0] edges$1$p2;
    reg  [18:0] edges$1$q0;
    reg  [18:0] edges$1$q1;
    reg  [18:0] edges$1$q2;
    reg  [18:0] edges$1$pe;
    reg  [18:0] edges$1$qe;
    reg  [18:0] edges$1$pg;
    reg  [18:0] edges$1$qg;
    reg  [18:0] edges$1$pf0;
    reg  [18:0] edges$1$pf1;
    reg  [18:0] edges$1$pf2;
    reg  [18:0] edges$1$qf0;
    reg  [18:0] edges$1$qf1;
    reg  [18:0] edges$1$qf2;
    reg  [18:0] edges$1$ph;
    reg  [18:0] edges$1$qh;
    wire  [18:0] edges$1$s_x;
    wire  [18:0] edges$1$s_b;
    wire  edges$1$cross_t;
    wire  edges$1$cross_f;
    reg  edges$2$clock;
    reg  [18:0] edges$2$p0;
    reg  [18:0] edges$2$p1;
    reg  [18:0] edges$2$p2;
    reg  [18:0] edges$2$q0;
    reg  [18:0] edges$2$q1;
    reg  [18:0] edges$2$q2;
    reg  [18:0] edges$2$pe;
    reg  [18:0] edges$2$qe;
    reg  [18:0] edges$2$pg;
    reg  [18:0] edges$2$qg;
    reg  [18:0] edges$2$pf0;
    reg  [18:0] edges$2$pf1;
    reg  [18:0] edges$2$pf2;
    reg  [18:0] edges$2$qf0;
    reg  [18:0] edges$2$qf1;
    reg  [18:0] edges$2$qf2;
    reg  [18:0] edges$2$ph;
    reg  [18:0] edges$2$qh;
    wire  [18:0] edges$2$s_x;
    wire  [18:0] edges$2$s_b;
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
    reg  [18:0] v_s_x$0$d;
    wire  [18:0] v_s_x$0$q;
    reg  v_s_x$0$clock;
    reg  [18:0] v_s_x$1$d;
    wire  [18:0] v_s_x$1$q;
    reg  v_s_x$1$clock;
    reg  [18:0] v_s_x$2$d;
    wire  [18:0] v_s_x$2$q;
    reg  v_s_x$2$clock;
    reg  [18:0] v_s_b$0$d;
    wire  [18:0] v_s_b$0$q;
    reg  v_s_b$0$clock;
    reg  [18:0] v_s_b$1$d;
    wire  [18:0] v_s_b$1$q;
    reg  v_s_b$1$clock;
    reg  [18:0] v_s_b$2$d;
    wire  [18:0] v_s_b$2$q;
    reg  v_s_b$2$clock;
    reg  [18:0] out_s_x$0$d;
    wire  [18:0] out_s_x$0$q;
    reg  out_s_x$0$clock;
    reg  [18:0] out_s_x$1$d;
    wire  [18:0] out_s_x$1$q;
    reg  out_s_x$1$clock;
    reg  [18:0] out_s_x$2$d;
    wire  [18:0] out_s_x$2$q;
    reg  out_s_x$2$clock;
    reg  [18:0] out_s_b$0$d;
    wire  [18:0] out_s_b$0$q;
    reg  out_s_b$0$clock;
    reg  [18:0] out_s_b$1$d;
    wire  [18:0] out_s_b$1$q;
    reg  out_s_b$1$clock;
    reg  [18:0] out_s_b$2$d;
    wire  [18:0] out_s_b$2$q;
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
    top$aerr$s3_y in_m_0$0(
        .d(in_m_0$0$d),
        .q(in_m_0$0$q),
        .clock(in_m_0$0$clock)
    );
    top$aerr$s3_y in_m_0$1(
        .d(in_m_0$1$d),
        .q(in_m_0$1$q),
        .clock(in_m_0$1$clock)
    );
    top$aerr$s3_y in_m_0$2(
        .d(in_m_0$2$d),
        .q(in_m_0$2$q),
        .clock(in_m_0$2$clock)
    );
    top$aerr$s3_y in_m_0$3(
        .d(in_m_0$3$d),
        .q(in_m_0$3$q),
        .clock(in_m_0$3$clock)
    );
    top$aerr$s3_y in_m_1$0(
        .d(in_m_1$0$d),
        .q(in_m_1$0$q),
        .clock(in_m_1$0$clock)
    );
    top$aerr$s3_y in_m_1$1(
        .d(in_m_1$1$d),
        .q(in_m_1$1$q),
        .clock(in_m_1$1$clock)
    );
    top$aerr$s3_y in_m_1$2(
        .d(in_m_1$2$d),
        .q(in_m_1$2$q),
        .clock(in_m_1$2$clock)
    );
    top$aerr$s3_y in_m_1$3(
        .d(in_m_1$3$d),
        .q(in_m_1$3$q),
        .clock(in_m_1$3$clock)
    );
    top$aerr$s3_y in_m_2$0(
        .d(in_m_2$0$d),
        .q(in_m_2$0$q),
        .clock(in_m_2$0$clock)
    );
    top$aerr$s3_y in_m_2$1(
        .d(in_m_2$1$d),
        .q(in_m_2$1$q),
        .clock(in_m_2$1$clock)
    );
    top$aerr$s3_y in_m_2$2(
        .d(in_m_2$2$d),
        .q(in_m_2$2$q),
        .clock(in_m_2$2$clock)
    );
    top$aerr$s3_y in_m_2$3(
        .d(in_m_2$3$d),
        .q(in_m_2$3$q),
        .clock(in_m_2$3$clock)
    );
    top$aerr$s3_y in_alpha_m(
        .d(in_alpha_m$d),
        .q(in_alpha_m$q),
        .clock(in_alpha_m$clock)
    );
    top$aerr$s3_y in_alpha_f(
        .d(in_alpha_f$d),
        .q(in_alpha_f$q),
        .clock(in_alpha_f$clock)
    );
    top$aerr$s3_y in_f_0$0(
        .d(in_f_0$0$d),
        .q(in_f_0$0$q),
        .clock(in_f_0$0$clock)
    );
    top$aerr$s3_y in_f_0$1(
        .d(in_f_0$1$d),
        .q(in_f_0$1$q),
        .clock(in_f_0$1$clock)
    );
    top$aerr$s3_y in_f_0$2(
        .d(in_f_0$2$d),
        .q(in_f_0$2$q),
        .clock(in_f_0$2$clock)
    );
    top$aerr$s3_y in_f_0$3(
        .d(in_f_0$3$d),
        .q(in_f_0$3$q),
        .clock(in_f_0$3$clock)
    );
    top$aerr$s3_y in_f_1$0(
        .d(in_f_1$0$d),
        .q(in_f_1$0$q),
        .clock(in_f_1$0$clock)
    );
    top$aerr$s3_y in_f_1$1(
        .d(in_f_1$1$d),
        .q(in_f_1$1$q),
        .clock(in_f_1$1$clock)
    );
    top$aerr$s3_y in_f_1$2(
        .d(in_f_1$2$d),
        .q(in_f_1$2$q),
        .clock(in_f_1$2$clock)
    );
    top$aerr$s3_y in_f_1$3(
        .d(in_f_1$3$d),
        .q(in_f_1$3$q),
        .clock(in_f_1$3$clock)
    );
    top$aerr$s3_y in_f_2$0(
        .d(in_f_2$0$d),
        .q(in_f_2$0$q),
        .clock(in_f_2$0$clock)
    );
    top$aerr$s3_y in_f_2$1(
        .d(in_f_2$1$d),
        .q(in_f_2$1$q),
        .clock(in_f_2$1$clock)
    );
    top$aerr$s3_y in_f_2$2(
        .d(in_f_2$2$d),
        .q(in_f_2$2$q),
        .clock(in_f_2$2$clock)
    );
    top$aerr$s3_y in_f_2$3(
        .d(in_f_2$3$d),
        .q(in_f_2$3$q),
        .clock(in_f_2$3$clock)
    );
    top$aerr$s3_y in_beta_m(
        .d(in_beta_m$d),
        .q(in_beta_m$q),
        .clock(in_beta_m$clock)
    );
    top$aerr$s3_y in_beta_f(
        .d(in_beta_f$d),
        .q(in_beta_f$q),
        .clock(in_beta_f$clock)
    );
    top$aerr$s3_y in_scale(
        .d(in_scale$d),
        .q(in_scale$q),
        .clock(in_scale$clock)
    );
    top$aerr$s3_y in_v_x$0(
        .d(in_v_x$0$d),
        .q(in_v_x$0$q),
        .clock(in_v_x$0$clock)
    );
    top$aerr$s3_y in_v_x$1(
        .d(in_v_x$1$d),
        .q(in_v_x$1$q),
        .clock(in_v_x$1$clock)
    );
    top$aerr$s3_y in_v_x$2(
        .d(in_v_x$2$d),
        .q(in_v_x$2$q),
        .clock(in_v_x$2$clock)
    );
    top$aerr$s3_y in_v_y$0(
        .d(in_v_y$0$d),
        .q(in_v_y$0$q),
        .clock(in_v_y$0$clock)
    );
    top$aerr$s3_y in_v_y$1(
        .d(in_v_y$1$d),
        .q(in_v_y$1$q),
        .clock(in_v_y$1$clock)
    );
    top$aerr$s3_y in_v_y$2(
        .d(in_v_y$2$d),
        .q(in_v_y$2$q),
        .clock(in_v_y$2$clock)
    );
    top$aerr$s3_y in_v_z$0(
        .d(in_v_z$0$d),
        .q(in_v_z$0$q),
        .clock(in_v_z$0$clock)
    );
    top$aerr$s3_y in_v_z$1(
        .d(in_v_z$1$d),
        .q(in_v_z$1$q),
        .clock(in_v_z$1$clock)
    );
    top$aerr$s3_y in_v_z$2(
        .d(in_v_z$2$d),
        .q(in_v_z$2$q),
        .clock(in_v_z$2$clock)
    );
    top$aerr$s1_eff_sub in_v_exact(
        .d(in_v_exact$d),
        .q(in_v_exact$q),
        .clock(in_v_exact$clock)
    );
    top$in_tag in_tag(
        .d(in_tag$d),
        .q(in_tag$q),
        .clock(in_tag$clock)
    );
    top$aerr$s1_eff_sub in_valid(
        .d(in_valid$d),
        .q(in_valid$q),
        .clock(in_valid$clock)
    );
    top$mb_0$0 mb_0$0(
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
    top$mb_0$0 mb_0$1(
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
    top$mb_0$0 mb_0$2(
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
    top$mb_0$3 mb_0$3(
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
    top$mb_0$0 mb_1$0(
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
    top$mb_0$0 mb_1$1(
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
    top$mb_0$0 mb_1$2(
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
    top$mb_0$3 mb_1$3(
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
    top$mb_0$0 mb_2$0(
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
    top$mb_0$0 mb_2$1(
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
    top$mb_0$0 mb_2$2(
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
    top$mb_0$3 mb_2$3(
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
    top$mg_0$0 mg_0$0(
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
    top$mg_0$0 mg_0$1(
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
    top$mg_0$0 mg_0$2(
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
    top$mg_0$3 mg_0$3(
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
    top$mg_0$0 mg_1$0(
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
    top$mg_0$0 mg_1$1(
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
    top$mg_0$0 mg_1$2(
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
    top$mg_0$3 mg_1$3(
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
    top$mg_0$0 mg_2$0(
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
    top$mg_0$0 mg_2$1(
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
    top$mg_0$0 mg_2$2(
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
    top$mg_0$3 mg_2$3(
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
    top$c3_0 c3_0(
        .clock(c3_0$clock),
        .d(c3_0$d),
        .q(c3_0$q)
    );
    top$c3_0 c3_1(
        .clock(c3_1$clock),
        .d(c3_1$d),
        .q(c3_1$q)
    );
    top$c3_0 c3_2(
        .clock(c3_2$clock),
        .d(c3_2$d),
        .q(c3_2$q)
    );
    top$af am(
        .clock(am$clock),
        .a(am$a),
        .b(am$b),
        .valid_in(am$valid_in),
        .y(am$y),
        .valid_out(am$valid_out)
    );
    top$af af(
        .clock(af$clock),
        .a(af$a),
        .b(af$b),
        .valid_in(af$valid_in),
        .y(af$y),
        .valid_out(af$valid_out)
    );
    top$aerr aerr(
        .clock(aerr$clock),
        .a(aerr$a),
        .b(aerr$b),
        .sub(aerr$sub),
        .valid_in(aerr$valid_in),
        .y(aerr$y),
        .valid_out(aerr$valid_out)
    );
    top$aerr_wait aerr_wait(
        .clock(aerr_wait$clock),
        .d(aerr_wait$d),
        .q(aerr_wait$q)
    );
    top$aerr la$0(
        .clock(la$0$clock),
        .a(la$0$a),
        .b(la$0$b),
        .sub(la$0$sub),
        .valid_in(la$0$valid_in),
        .y(la$0$y),
        .valid_out(la$0$valid_out)
    );
    top$aerr la$1(
        .clock(la$1$clock),
        .a(la$1$a),
        .b(la$1$b),
        .sub(la$1$sub),
        .valid_in(la$1$valid_in),
        .y(la$1$y),
        .valid_out(la$1$valid_out)
    );
    top$aerr la$2(
        .clock(la$2$clock),
        .a(la$2$a),
        .b(la$2$b),
        .sub(la$2$sub),
        .valid_in(la$2$valid_in),
        .y(la$2$y),
        .valid_out(la$2$valid_out)
    );
    top$aerr lb$0(
        .clock(lb$0$clock),
        .a(lb$0$a),
        .b(lb$0$b),
        .sub(lb$0$sub),
        .valid_in(lb$0$valid_in),
        .y(lb$0$y),
        .valid_out(lb$0$valid_out)
    );
    top$aerr lb$1(
        .clock(lb$1$clock),
        .a(lb$1$a),
        .b(lb$1$b),
        .sub(lb$1$sub),
        .valid_in(lb$1$valid_in),
        .y(lb$1$y),
        .valid_out(lb$1$valid_out)
    );
    top$aerr lb$2(
        .clock(lb$2$clock),
        .a(lb$2$a),
        .b(lb$2$b),
        .sub(lb$2$sub),
        .valid_in(lb$2$valid_in),
        .y(lb$2$y),
        .valid_out(lb$2$valid_out)
    );
    top$aerr l1$0(
        .clock(l1$0$clock),
        .a(l1$0$a),
        .b(l1$0$b),
        .sub(l1$0$sub),
        .valid_in(l1$0$valid_in),
        .y(l1$0$y),
        .valid_out(l1$0$valid_out)
    );
    top$aerr l1$1(
        .clock(l1$1$clock),
        .a(l1$1$a),
        .b(l1$1$b),
        .sub(l1$1$sub),
        .valid_in(l1$1$valid_in),
        .y(l1$1$y),
        .valid_out(l1$1$valid_out)
    );
    top$aerr l1$2(
        .clock(l1$2$clock),
        .a(l1$2$a),
        .b(l1$2$b),
        .sub(l1$2$sub),
        .valid_in(l1$2$valid_in),
        .y(l1$2$y),
        .valid_out(l1$2$valid_out)
    );
    top$l1_wait$0 l1_wait$0(
        .clock(l1_wait$0$clock),
        .d(l1_wait$0$d),
        .q(l1_wait$0$q)
    );
    top$l1_wait$0 l1_wait$1(
        .clock(l1_wait$1$clock),
        .d(l1_wait$1$d),
        .q(l1_wait$1$q)
    );
    top$l1_wait$0 l1_wait$2(
        .clock(l1_wait$2$clock),
        .d(l1_wait$2$d),
        .q(l1_wait$2$q)
    );
    top$af err$0(
        .clock(err$0$clock),
        .a(err$0$a),
        .b(err$0$b),
        .valid_in(err$0$valid_in),
        .y(err$0$y),
        .valid_out(err$0$valid_out)
    );
    top$af err$1(
        .clock(err$1$clock),
        .a(err$1$a),
        .b(err$1$b),
        .valid_in(err$1$valid_in),
        .y(err$1$y),
        .valid_out(err$1$valid_out)
    );
    top$af err$2(
        .clock(err$2$clock),
        .a(err$2$a),
        .b(err$2$b),
        .valid_in(err$2$valid_in),
        .y(err$2$y),
        .valid_out(err$2$valid_out)
    );
    top$aerr$s3_y mbr_0$0(
        .d(mbr_0$0$d),
        .q(mbr_0$0$q),
        .clock(mbr_0$0$clock)
    );
    top$aerr$s3_y mbr_0$1(
        .d(mbr_0$1$d),
        .q(mbr_0$1$q),
        .clock(mbr_0$1$clock)
    );
    top$aerr$s3_y mbr_0$2(
        .d(mbr_0$2$d),
        .q(mbr_0$2$q),
        .clock(mbr_0$2$clock)
    );
    top$aerr$s3_y mbr_0$3(
        .d(mbr_0$3$d),
        .q(mbr_0$3$q),
        .clock(mbr_0$3$clock)
    );
    top$aerr$s3_y mbr_1$0(
        .d(mbr_1$0$d),
        .q(mbr_1$0$q),
        .clock(mbr_1$0$clock)
    );
    top$aerr$s3_y mbr_1$1(
        .d(mbr_1$1$d),
        .q(mbr_1$1$q),
        .clock(mbr_1$1$clock)
    );
    top$aerr$s3_y mbr_1$2(
        .d(mbr_1$2$d),
        .q(mbr_1$2$q),
        .clock(mbr_1$2$clock)
    );
    top$aerr$s3_y mbr_1$3(
        .d(mbr_1$3$d),
        .q(mbr_1$3$q),
        .clock(mbr_1$3$clock)
    );
    top$aerr$s3_y mbr_2$0(
        .d(mbr_2$0$d),
        .q(mbr_2$0$q),
        .clock(mbr_2$0$clock)
    );
    top$aerr$s3_y mbr_2$1(
        .d(mbr_2$1$d),
        .q(mbr_2$1$q),
        .clock(mbr_2$1$clock)
    );
    top$aerr$s3_y mbr_2$2(
        .d(mbr_2$2$d),
        .q(mbr_2$2$q),
        .clock(mbr_2$2$clock)
    );
    top$aerr$s3_y mbr_2$3(
        .d(mbr_2$3$d),
        .q(mbr_2$3$q),
        .clock(mbr_2$3$clock)
    );
    top$aerr$s3_y mgr_0$0(
        .d(mgr_0$0$d),
        .q(mgr_0$0$q),
        .clock(mgr_0$0$clock)
    );
    top$aerr$s3_y mgr_0$1(
        .d(mgr_0$1$d),
        .q(mgr_0$1$q),
        .clock(mgr_0$1$clock)
    );
    top$aerr$s3_y mgr_0$2(
        .d(mgr_0$2$d),
        .q(mgr_0$2$q),
        .clock(mgr_0$2$clock)
    );
    top$aerr$s3_y mgr_0$3(
        .d(mgr_0$3$d),
        .q(mgr_0$3$q),
        .clock(mgr_0$3$clock)
    );
    top$aerr$s3_y mgr_1$0(
        .d(mgr_1$0$d),
        .q(mgr_1$0$q),
        .clock(mgr_1$0$clock)
    );
    top$aerr$s3_y mgr_1$1(
        .d(mgr_1$1$d),
        .q(mgr_1$1$q),
        .clock(mgr_1$1$clock)
    );
    top$aerr$s3_y mgr_1$2(
        .d(mgr_1$2$d),
        .q(mgr_1$2$q),
        .clock(mgr_1$2$clock)
    );
    top$aerr$s3_y mgr_1$3(
        .d(mgr_1$3$d),
        .q(mgr_1$3$q),
        .clock(mgr_1$3$clock)
    );
    top$aerr$s3_y mgr_2$0(
        .d(mgr_2$0$d),
        .q(mgr_2$0$q),
        .clock(mgr_2$0$clock)
    );
    top$aerr$s3_y mgr_2$1(
        .d(mgr_2$1$d),
        .q(mgr_2$1$q),
        .clock(mgr_2$1$clock)
    );
    top$aerr$s3_y mgr_2$2(
        .d(mgr_2$2$d),
        .q(mgr_2$2$q),
        .clock(mgr_2$2$clock)
    );
    top$aerr$s3_y mgr_2$3(
        .d(mgr_2$3$d),
        .q(mgr_2$3$q),
        .clock(mgr_2$3$clock)
    );
    top$aerr_wait mg3_0(
        .clock(mg3_0$clock),
        .d(mg3_0$d),
        .q(mg3_0$q)
    );
    top$aerr_wait mg3_1(
        .clock(mg3_1$clock),
        .d(mg3_1$d),
        .q(mg3_1$q)
    );
    top$aerr_wait mg3_2(
        .clock(mg3_2$clock),
        .d(mg3_2$d),
        .q(mg3_2$q)
    );
    top$aerr m3_0$0(
        .clock(m3_0$0$clock),
        .a(m3_0$0$a),
        .b(m3_0$0$b),
        .sub(m3_0$0$sub),
        .valid_in(m3_0$0$valid_in),
        .y(m3_0$0$y),
        .valid_out(m3_0$0$valid_out)
    );
    top$aerr m3_0$1(
        .clock(m3_0$1$clock),
        .a(m3_0$1$a),
        .b(m3_0$1$b),
        .sub(m3_0$1$sub),
        .valid_in(m3_0$1$valid_in),
        .y(m3_0$1$y),
        .valid_out(m3_0$1$valid_out)
    );
    top$aerr m3_0$2(
        .clock(m3_0$2$clock),
        .a(m3_0$2$a),
        .b(m3_0$2$b),
        .sub(m3_0$2$sub),
        .valid_in(m3_0$2$valid_in),
        .y(m3_0$2$y),
        .valid_out(m3_0$2$valid_out)
    );
    top$aerr m3_1$0(
        .clock(m3_1$0$clock),
        .a(m3_1$0$a),
        .b(m3_1$0$b),
        .sub(m3_1$0$sub),
        .valid_in(m3_1$0$valid_in),
        .y(m3_1$0$y),
        .valid_out(m3_1$0$valid_out)
    );
    top$aerr m3_1$1(
        .clock(m3_1$1$clock),
        .a(m3_1$1$a),
        .b(m3_1$1$b),
        .sub(m3_1$1$sub),
        .valid_in(m3_1$1$valid_in),
        .y(m3_1$1$y),
        .valid_out(m3_1$1$valid_out)
    );
    top$aerr m3_1$2(
        .clock(m3_1$2$clock),
        .a(m3_1$2$a),
        .b(m3_1$2$b),
        .sub(m3_1$2$sub),
        .valid_in(m3_1$2$valid_in),
        .y(m3_1$2$y),
        .valid_out(m3_1$2$valid_out)
    );
    top$aerr m3_2$0(
        .clock(m3_2$0$clock),
        .a(m3_2$0$a),
        .b(m3_2$0$b),
        .sub(m3_2$0$sub),
        .valid_in(m3_2$0$valid_in),
        .y(m3_2$0$y),
        .valid_out(m3_2$0$valid_out)
    );
    top$aerr m3_2$1(
        .clock(m3_2$1$clock),
        .a(m3_2$1$a),
        .b(m3_2$1$b),
        .sub(m3_2$1$sub),
        .valid_in(m3_2$1$valid_in),
        .y(m3_2$1$y),
        .valid_out(m3_2$1$valid_out)
    );
    top$aerr m3_2$2(
        .clock(m3_2$2$clock),
        .a(m3_2$2$a),
        .b(m3_2$2$b),
        .sub(m3_2$2$sub),
        .valid_in(m3_2$2$valid_in),
        .y(m3_2$2$y),
        .valid_out(m3_2$2$valid_out)
    );
    top$c3_0 vc_0(
        .clock(vc_0$clock),
        .d(vc_0$d),
        .q(vc_0$q)
    );
    top$c3_0 vc_1(
        .clock(vc_1$clock),
        .d(vc_1$d),
        .q(vc_1$q)
    );
    top$c3_0 vc_2(
        .clock(vc_2$clock),
        .d(vc_2$d),
        .q(vc_2$q)
    );
    top$v_x_wait$0 v_x_wait$0(
        .clock(v_x_wait$0$clock),
        .d(v_x_wait$0$d),
        .q(v_x_wait$0$q)
    );
    top$v_x_wait$0 v_x_wait$1(
        .clock(v_x_wait$1$clock),
        .d(v_x_wait$1$d),
        .q(v_x_wait$1$q)
    );
    top$v_x_wait$0 v_x_wait$2(
        .clock(v_x_wait$2$clock),
        .d(v_x_wait$2$d),
        .q(v_x_wait$2$q)
    );
    top$v_x_wait$0 v_y_wait$0(
        .clock(v_y_wait$0$clock),
        .d(v_y_wait$0$d),
        .q(v_y_wait$0$q)
    );
    top$v_x_wait$0 v_y_wait$1(
        .clock(v_y_wait$1$clock),
        .d(v_y_wait$1$d),
        .q(v_y_wait$1$q)
    );
    top$v_x_wait$0 v_y_wait$2(
        .clock(v_y_wait$2$clock),
        .d(v_y_wait$2$d),
        .q(v_y_wait$2$q)
    );
    top$v_x_wait$0 v_z_wait$0(
        .clock(v_z_wait$0$clock),
        .d(v_z_wait$0$d),
        .q(v_z_wait$0$q)
    );
    top$v_x_wait$0 v_z_wait$1(
        .clock(v_z_wait$1$clock),
        .d(v_z_wait$1$d),
        .q(v_z_wait$1$q)
    );
    top$v_x_wait$0 v_z_wait$2(
        .clock(v_z_wait$2$clock),
        .d(v_z_wait$2$d),
        .q(v_z_wait$2$q)
    );
    top$mb_0$3 vt_0$0(
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
    top$mb_0$3 vt_0$1(
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
    top$mb_0$3 vt_0$2(
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
    top$mb_0$3 vt_1$0(
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
    top$mb_0$3 vt_1$1(
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
    top$mb_0$3 vt_1$2(
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
    top$mb_0$3 vt_2$0(
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
    top$mb_0$3 vt_2$1(
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
    top$mb_0$3 vt_2$2(
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
    top$mg_0$3 vm_0$0(
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
    top$mg_0$3 vm_0$1(
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
    top$mg_0$3 vm_0$2(
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
    top$mg_0$3 vm_1$0(
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
    top$mg_0$3 vm_1$1(
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
    top$mg_0$3 vm_1$2(
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
    top$mg_0$3 vm_2$0(
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
    top$mg_0$3 vm_2$1(
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
    top$mg_0$3 vm_2$2(
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
    top$aerr$s3_y vtr_0$0(
        .d(vtr_0$0$d),
        .q(vtr_0$0$q),
        .clock(vtr_0$0$clock)
    );
    top$aerr$s3_y vtr_0$1(
        .d(vtr_0$1$d),
        .q(vtr_0$1$q),
        .clock(vtr_0$1$clock)
    );
    top$aerr$s3_y vtr_0$2(
        .d(vtr_0$2$d),
        .q(vtr_0$2$q),
        .clock(vtr_0$2$clock)
    );
    top$aerr$s3_y vtr_1$0(
        .d(vtr_1$0$d),
        .q(vtr_1$0$q),
        .clock(vtr_1$0$clock)
    );
    top$aerr$s3_y vtr_1$1(
        .d(vtr_1$1$d),
        .q(vtr_1$1$q),
        .clock(vtr_1$1$clock)
    );
    top$aerr$s3_y vtr_1$2(
        .d(vtr_1$2$d),
        .q(vtr_1$2$q),
        .clock(vtr_1$2$clock)
    );
    top$aerr$s3_y vtr_2$0(
        .d(vtr_2$0$d),
        .q(vtr_2$0$q),
        .clock(vtr_2$0$clock)
    );
    top$aerr$s3_y vtr_2$1(
        .d(vtr_2$1$d),
        .q(vtr_2$1$q),
        .clock(vtr_2$1$clock)
    );
    top$aerr$s3_y vtr_2$2(
        .d(vtr_2$2$d),
        .q(vtr_2$2$q),
        .clock(vtr_2$2$clock)
    );
    top$aerr$s3_y vmr_0$0(
        .d(vmr_0$0$d),
        .q(vmr_0$0$q),
        .clock(vmr_0$0$clock)
    );
    top$aerr$s3_y vmr_0$1(
        .d(vmr_0$1$d),
        .q(vmr_0$1$q),
        .clock(vmr_0$1$clock)
    );
    top$aerr$s3_y vmr_0$2(
        .d(vmr_0$2$d),
        .q(vmr_0$2$q),
        .clock(vmr_0$2$clock)
    );
    top$aerr$s3_y vmr_1$0(
        .d(vmr_1$0$d),
        .q(vmr_1$0$q),
        .clock(vmr_1$0$clock)
    );
    top$aerr$s3_y vmr_1$1(
        .d(vmr_1$1$d),
        .q(vmr_1$1$q),
        .clock(vmr_1$1$clock)
    );
    top$aerr$s3_y vmr_1$2(
        .d(vmr_1$2$d),
        .q(vmr_1$2$q),
        .clock(vmr_1$2$clock)
    );
    top$aerr$s3_y vmr_2$0(
        .d(vmr_2$0$d),
        .q(vmr_2$0$q),
        .clock(vmr_2$0$clock)
    );
    top$aerr$s3_y vmr_2$1(
        .d(vmr_2$1$d),
        .q(vmr_2$1$q),
        .clock(vmr_2$1$clock)
    );
    top$aerr$s3_y vmr_2$2(
        .d(vmr_2$2$d),
        .q(vmr_2$2$q),
        .clock(vmr_2$2$clock)
    );
    top$exact_wait exact_wait(
        .clock(exact_wait$clock),
        .d(exact_wait$d),
        .q(exact_wait$q)
    );
    top$verts$0 verts$0(
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
    top$verts$0 verts$1(
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
    top$verts$0 verts$2(
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
    top$edges$0 edges$0(
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
    top$edges$0 edges$1(
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
    top$edges$0 edges$2(
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
    top$tag_wait tag_wait(
        .clock(tag_wait$clock),
        .d(tag_wait$d),
        .q(tag_wait$q)
    );
    top$valid_wait valid_wait(
        .clock(valid_wait$clock),
        .d(valid_wait$d),
        .q(valid_wait$q)
    );
    top$aerr$s1_eff_sub v_cross_t$0(
        .d(v_cross_t$0$d),
        .q(v_cross_t$0$q),
        .clock(v_cross_t$0$clock)
    );
    top$aerr$s1_eff_sub v_cross_t$1(
        .d(v_cross_t$1$d),
        .q(v_cross_t$1$q),
        .clock(v_cross_t$1$clock)
    );
    top$aerr$s1_eff_sub v_cross_t$2(
        .d(v_cross_t$2$d),
        .q(v_cross_t$2$q),
        .clock(v_cross_t$2$clock)
    );
    top$aerr$s1_eff_sub v_cross_f$0(
        .d(v_cross_f$0$d),
        .q(v_cross_f$0$q),
        .clock(v_cross_f$0$clock)
    );
    top$aerr$s1_eff_sub v_cross_f$1(
        .d(v_cross_f$1$d),
        .q(v_cross_f$1$q),
        .clock(v_cross_f$1$clock)
    );
    top$aerr$s1_eff_sub v_cross_f$2(
        .d(v_cross_f$2$d),
        .q(v_cross_f$2$q),
        .clock(v_cross_f$2$clock)
    );
    top$aerr$s3_y v_s_x$0(
        .d(v_s_x$0$d),
        .q(v_s_x$0$q),
        .clock(v_s_x$0$clock)
    );
    top$aerr$s3_y v_s_x$1(
        .d(v_s_x$1$d),
        .q(v_s_x$1$q),
        .clock(v_s_x$1$clock)
    );
    top$aerr$s3_y v_s_x$2(
        .d(v_s_x$2$d),
        .q(v_s_x$2$q),
        .clock(v_s_x$2$clock)
    );
    top$aerr$s3_y v_s_b$0(
        .d(v_s_b$0$d),
        .q(v_s_b$0$q),
        .clock(v_s_b$0$clock)
    );
    top$aerr$s3_y v_s_b$1(
        .d(v_s_b$1$d),
        .q(v_s_b$1$q),
        .clock(v_s_b$1$clock)
    );
    top$aerr$s3_y v_s_b$2(
        .d(v_s_b$2$d),
        .q(v_s_b$2$q),
        .clock(v_s_b$2$clock)
    );
    top$aerr$s3_y out_s_x$0(
        .d(out_s_x$0$d),
        .q(out_s_x$0$q),
        .clock(out_s_x$0$clock)
    );
    top$aerr$s3_y out_s_x$1(
        .d(out_s_x$1$d),
        .q(out_s_x$1$q),
        .clock(out_s_x$1$clock)
    );
    top$aerr$s3_y out_s_x$2(
        .d(out_s_x$2$d),
        .q(out_s_x$2$q),
        .clock(out_s_x$2$clock)
    );
    top$aerr$s3_y out_s_b$0(
        .d(out_s_b$0$d),
        .q(out_s_b$0$q),
        .clock(out_s_b$0$clock)
    );
    top$aerr$s3_y out_s_b$1(
        .d(out_s_b$1$d),
        .q(out_s_b$1$q),
        .clock(out_s_b$1$clock)
    );
    top$aerr$s3_y out_s_b$2(
        .d(out_s_b$2$d),
        .q(out_s_b$2$q),
        .clock(out_s_b$2$clock)
    );
    top$aerr$s1_eff_sub out_cross_t$0(
        .d(out_cross_t$0$d),
        .q(out_cross_t$0$q),
        .clock(out_cross_t$0$clock)
    );
    top$aerr$s1_eff_sub out_cross_t$1(
        .d(out_cross_t$1$d),
        .q(out_cross_t$1$q),
        .clock(out_cross_t$1$clock)
    );
    top$aerr$s1_eff_sub out_cross_t$2(
        .d(out_cross_t$2$d),
        .q(out_cross_t$2$q),
        .clock(out_cross_t$2$clock)
    );
    top$aerr$s1_eff_sub out_cross_f$0(
        .d(out_cross_f$0$d),
        .q(out_cross_f$0$q),
        .clock(out_cross_f$0$clock)
    );
    top$aerr$s1_eff_sub out_cross_f$1(
        .d(out_cross_f$1$d),
        .q(out_cross_f$1$q),
        .clock(out_cross_f$1$clock)
    );
    top$aerr$s1_eff_sub out_cross_f$2(
        .d(out_cross_f$2$d),
        .q(out_cross_f$2$q),
        .clock(out_cross_f$2$clock)
    );
    top$aerr$s1_eff_sub out_hit(
        .d(out_hit$d),
        .q(out_hit$q),
        .clock(out_hit$clock)
    );
    top$aerr$s1_eff_sub out_miss(
        .d(out_miss$d),
        .q(out_miss$q),
        .clock(out_miss$clock)
    );
    top$in_tag out_tag(
        .d(out_tag$d),
        .q(out_tag$q),
        .clock(out_tag$clock)
    );
    top$aerr$s1_eff_sub out_valid(
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
    
endmodule // top


module top$aerr(clock,a,b,sub,valid_in,y,valid_out);
    
    // Module arguments
    input wire  clock;
    input wire  [18:0] a;
    input wire  [18:0] b;
    input wire  sub;
    input wire  valid_in;
    output reg  [18:0] y;
    output reg  valid_out;
    
    // Constant declarations
    localparam  round_up = 1'b1;
    localparam  c_align_cap = 8'he;
    localparam  c_exp_ones = 10'b11111111;
    
    // Stub signals
    reg  [18:0] unpack_a$x;
    wire  unpack_a$sign;
    wire  [7:0] unpack_a$exp;
    wire  [10:0] unpack_a$sig;
    wire  unpack_a$is_zero;
    wire  unpack_a$is_inf;
    wire  unpack_a$is_nan;
    reg  [18:0] unpack_b$x;
    wire  unpack_b$sign;
    wire  [7:0] unpack_b$exp;
    wire  [10:0] unpack_b$sig;
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
    reg  [13:0] s1_big$d;
    wire  [13:0] s1_big$q;
    reg  s1_big$clock;
    reg  [13:0] s1_small$d;
    wire  [13:0] s1_small$q;
    reg  s1_small$clock;
    reg  [13:0] norm$x;
    wire  [13:0] norm$y;
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
    reg  [12:0] s2_nm$d;
    wire  [12:0] s2_nm$q;
    reg  s2_nm$clock;
    reg  round$round_up;
    reg  round$sign;
    reg  round$nan;
    reg  round$inf;
    reg  round$zero;
    reg  round$ovf;
    reg  [7:0] round$efield;
    reg  [12:0] round$nm;
    wire  [18:0] round$y;
    reg  s3_valid$d;
    wire  s3_valid$q;
    reg  s3_valid$clock;
    reg  [18:0] s3_y$d;
    wire  [18:0] s3_y$q;
    reg  s3_y$clock;
    
    // Local signals
    reg  c1_b_sign;
    reg  c1_swap;
    reg  c1_big_sign;
    reg  [7:0] c1_big_exp;
    reg  [10:0] c1_big_sig;
    reg  c1_small_sign;
    reg  [7:0] c1_small_exp;
    reg  [10:0] c1_small_sig;
    reg  [7:0] c1_diff;
    reg  [7:0] c1_shift;
    reg  [13:0] c1_small_ext;
    reg  [13:0] c1_aligned;
    reg  [13:0] c1_back;
    reg  c1_lost;
    reg  c1_inf_sign;
    reg  [14:0] c2_sum;
    reg  c2_carry;
    reg  c2_zero;
    reg  [7:0] c2_limit;
    reg  [7:0] c2_lz;
    reg  [7:0] c2_shift;
    reg  [13:0] c2_shifted;
    reg  [9:0] c2_exp;
    reg  [12:0] c2_nm;
    reg  c2_sign;
    
    // Sub module instances
    top$aerr$unpack_a unpack_a(
        .x(unpack_a$x),
        .sign(unpack_a$sign),
        .exp(unpack_a$exp),
        .sig(unpack_a$sig),
        .is_zero(unpack_a$is_zero),
        .is_inf(unpack_a$is_inf),
        .is_nan(unpack_a$is_nan)
    );
    top$aerr$unpack_a unpack_b(
        .x(unpack_b$x),
        .sign(unpack_b$sign),
        .exp(unpack_b$exp),
        .sig(unpack_b$sig),
        .is_zero(unpack_b$is_zero),
        .is_inf(unpack_b$is_inf),
        .is_nan(unpack_b$is_nan)
    );
    top$aerr$s1_eff_sub s1_valid(
        .d(s1_valid$d),
        .q(s1_valid$q),
        .clock(s1_valid$clock)
    );
    top$aerr$s1_eff_sub s1_nan(
        .d(s1_nan$d),
        .q(s1_nan$q),
        .clock(s1_nan$clock)
    );
    top$aerr$s1_eff_sub s1_inf(
        .d(s1_inf$d),
        .q(s1_inf$q),
        .clock(s1_inf$clock)
    );
    top$aerr$s1_eff_sub s1_inf_sign(
        .d(s1_inf_sign$d),
        .q(s1_inf_sign$q),
        .clock(s1_inf_sign$clock)
    );
    top$aerr$s1_eff_sub s1_zero_sign(
        .d(s1_zero_sign$d),
        .q(s1_zero_sign$q),
        .clock(s1_zero_sign$clock)
    );
    top$aerr$s1_eff_sub s1_sign(
        .d(s1_sign$d),
        .q(s1_sign$q),
        .clock(s1_sign$clock)
    );
    top$aerr$s1_eff_sub s1_eff_sub(
        .d(s1_eff_sub$d),
        .q(s1_eff_sub$q),
        .clock(s1_eff_sub$clock)
    );
    top$aerr$s1_exp s1_exp(
        .d(s1_exp$d),
        .q(s1_exp$q),
        .clock(s1_exp$clock)
    );
    top$aerr$s1_big s1_big(
        .d(s1_big$d),
        .q(s1_big$q),
        .clock(s1_big$clock)
    );
    top$aerr$s1_big s1_small(
        .d(s1_small$d),
        .q(s1_small$q),
        .clock(s1_small$clock)
    );
    top$aerr$norm norm(
        .x(norm$x),
        .y(norm$y),
        .lz(norm$lz)
    );
    top$aerr$s1_eff_sub s2_valid(
        .d(s2_valid$d),
        .q(s2_valid$q),
        .clock(s2_valid$clock)
    );
    top$aerr$s1_eff_sub s2_sign(
        .d(s2_sign$d),
        .q(s2_sign$q),
        .clock(s2_sign$clock)
    );
    top$aerr$s1_eff_sub s2_nan(
        .d(s2_nan$d),
        .q(s2_nan$q),
        .clock(s2_nan$clock)
    );
    top$aerr$s1_eff_sub s2_inf(
        .d(s2_inf$d),
        .q(s2_inf$q),
        .clock(s2_inf$clock)
    );
    top$aerr$s1_eff_sub s2_zero(
        .d(s2_zero$d),
        .q(s2_zero$q),
        .clock(s2_zero$clock)
    );
    top$aerr$s1_eff_sub s2_ovf(
        .d(s2_ovf$d),
        .q(s2_ovf$q),
        .clock(s2_ovf$clock)
    );
    top$aerr$s1_exp s2_efield(
        .d(s2_efield$d),
        .q(s2_efield$q),
        .clock(s2_efield$clock)
    );
    top$aerr$s2_nm s2_nm(
        .d(s2_nm$d),
        .q(s2_nm$q),
        .clock(s2_nm$clock)
    );
    top$aerr$round round(
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
    top$aerr$s1_eff_sub s3_valid(
        .d(s3_valid$d),
        .q(s3_valid$q),
        .clock(s3_valid$clock)
    );
    top$aerr$s3_y s3_y(
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
        c1_swap = a[(32'h0)+:(18)] < b[(32'h0)+:(18)];
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
        c1_small_ext = ((c1_small_sig) & 14'h3fff) << 32'h3;
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
        s1_big$d = ((c1_big_sig) & 14'h3fff) << 32'h3;
        s1_small$d = (c1_aligned & ~(1 << (32'h0)) | ((c1_aligned[32'h0] | c1_lost) << (32'h0)));
        c2_sum = ((s1_big$q) & 15'h7fff) + ((s1_small$q) & 15'h7fff);
        if (s1_eff_sub$q) begin
            c2_sum = ((s1_big$q) & 15'h7fff) - ((s1_small$q) & 15'h7fff);
        end
        c2_carry = c2_sum[32'he];
        c2_zero = c2_sum == 32'h0;
        norm$x = c2_sum[(32'h0)+:(14)];
        c2_limit = s1_exp$q - 32'h1;
        c2_lz = ((norm$lz) & 8'hff);
        c2_shift = c2_lz;
        if (c2_lz > c2_limit) begin
            c2_shift = c2_limit;
        end
        c2_shifted = c2_sum[(32'h0)+:(14)] << c2_shift;
        c2_exp = ((s1_exp$q) & 10'h3ff) - ((c2_shift) & 10'h3ff);
        c2_nm = (((c2_shifted >> 32'h1) & 13'h1fff) & ~(1 << (32'h0)) | ((c2_shifted[32'h1] | c2_shifted[32'h0]) << (32'h0)));
        if (c2_carry) begin
            c2_exp = ((s1_exp$q) & 10'h3ff) + 32'h1;
            c2_nm = (((c2_sum >> 32'h2) & 13'h1fff) & ~(1 << (32'h0)) | ((c2_sum[32'h2] | c2_sum[32'h1] | c2_sum[32'h0]) << (32'h0)));
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
        if (c2_nm[32'hb + 32'h1]) begin
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
    
endmodule // top$aerr


module top$aerr$norm(x,y,lz);
    
    // Module arguments
    input wire  [13:0] x;
    output reg  [13:0] y;
    output reg  [4:0] lz;
    
    // Local signals
    reg  z8;
    reg  z4;
    reg  z2;
    reg  z1;
    reg  [13:0] x8;
    reg  [13:0] x4;
    reg  [13:0] x2;
    
    // Update code
    always @(*) begin
        z8 = x[(32'h6)+:(8)] == 32'h0;
        x8 = x;
        if (z8) begin
            x8 = x << 32'h8;
        end
        z4 = x8[(32'ha)+:(4)] == 32'h0;
        x4 = x8;
        if (z4) begin
            x4 = x8 << 32'h4;
        end
        z2 = x4[(32'hc)+:(2)] == 32'h0;
        x2 = x4;
        if (z2) begin
            x2 = x4 << 32'h2;
        end
        z1 = ~x2[32'hd];
        y = x2;
        if (z1) begin
            y = x2 << 32'h1;
        end
        lz = ((((((32'h0) & 5'h1f) & ~(1 << (32'h3)) | ((z8) << (32'h3))) & ~(1 << (32'h2)) | ((z4) << (32'h2))) & ~(1 << (32'h1)) | ((z2) << (32'h1))) & ~(1 << (32'h0)) | ((z1) << (32'h0)));
    end
    
endmodule // top$aerr$norm


module top$aerr$round(round_up,sign,nan,inf,zero,ovf,efield,nm,y);
    
    // Module arguments
    input wire  round_up;
    input wire  sign;
    input wire  nan;
    input wire  inf;
    input wire  zero;
    input wire  ovf;
    input wire  [7:0] efield;
    input wire  [12:0] nm;
    output reg  [18:0] y;
    
    // Constant declarations
    localparam  c_nan = 19'b111111111000000000;
    localparam  c_sign = 19'b1000000000000000000;
    localparam  c_inf = 18'b111111110000000000;
    localparam  c_max_finite = 18'b111111101111111111;
    
    // Local signals
    reg  lsb;
    reg  guard;
    reg  sticky;
    reg  inc;
    reg  [17:0] pack_word;
    reg  [17:0] rounded;
    reg  rexp_ones;
    reg  [17:0] mag;
    
    // Update code
    always @(*) begin
        lsb = nm[32'h2];
        guard = nm[32'h1];
        sticky = nm[32'h0];
        inc = guard & (sticky | lsb);
        if (round_up) begin
            inc = ~sign & (guard | sticky);
        end
        pack_word = (((efield) & 18'h3ffff) << 32'ha) | ((nm[(32'h2)+:(10)]) & 18'h3ffff);
        rounded = pack_word + inc;
        rexp_ones = &rounded[(32'ha)+:(8)];
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
        y = ((mag) & 19'h7ffff);
        if (sign) begin
            y = ((mag) & 19'h7ffff) | c_sign;
        end
        if (nan) begin
            y = c_nan;
        end
    end
    
endmodule // top$aerr$round


module top$aerr$s1_big(d,q,clock);
    
    // Module arguments
    input wire  [13:0] d;
    output reg  [13:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 14'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$aerr$s1_big


module top$aerr$s1_eff_sub(d,q,clock);
    
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
          
endmodule // top$aerr$s1_eff_sub


module top$aerr$s1_exp(d,q,clock);
    
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
          
endmodule // top$aerr$s1_exp


module top$aerr$s2_nm(d,q,clock);
    
    // Module arguments
    input wire  [12:0] d;
    output reg  [12:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 13'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$aerr$s2_nm


module top$aerr$s3_y(d,q,clock);
    
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
          
endmodule // top$aerr$s3_y


module top$aerr$unpack_a(x,sign,exp,sig,is_zero,is_inf,is_nan);
    
    // Module arguments
    input wire  [18:0] x;
    output reg  sign;
    output reg  [7:0] exp;
    output reg  [10:0] sig;
    output reg  is_zero;
    output reg  is_inf;
    output reg  is_nan;
    
    // Local signals
    reg  [7:0] field;
    reg  [9:0] frac;
    reg  exp_zero;
    reg  exp_ones;
    reg  frac_zero;
    
    // Update code
    always @(*) begin
        field = x[(32'ha)+:(8)];
        frac = x[(32'h0)+:(10)];
        sign = x[32'h12];
        exp_zero = field == 32'h0;
        exp_ones = &field;
        frac_zero = frac == 32'h0;
        is_zero = exp_zero & frac_zero;
        is_inf = exp_ones & frac_zero;
        is_nan = exp_ones & ~frac_zero;
        exp = field;
        sig = (((frac) & 11'h7ff) & ~(1 << (32'ha)) | ((1'b1) << (32'ha)));
        if (exp_zero) begin
            exp = 32'h1;
            sig = ((frac) & 11'h7ff);
        end
    end
    
endmodule // top$aerr$unpack_a


module top$aerr_wait(clock,d,q);
    
    // Module arguments
    input wire  clock;
    input wire  [18:0] d;
    output reg  [18:0] q;
    
    // Stub signals
    reg  [18:0] line$0$d;
    wire  [18:0] line$0$q;
    reg  line$0$clock;
    
    // Sub module instances
    top$aerr$s3_y line$0(
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
    
endmodule // top$aerr_wait


module top$af(clock,a,b,valid_in,y,valid_out);
    
    // Module arguments
    input wire  clock;
    input wire  [18:0] a;
    input wire  [18:0] b;
    input wire  valid_in;
    output reg  [18:0] y;
    output reg  valid_out;
    
    // Constant declarations
    localparam  round_up = 1'b1;
    localparam  c_exp_adj = 10'b10000001;
    localparam  c_exp_ofs = 10'b100000000;
    localparam  c_exp_norm_min = 10'b100000001;
    localparam  c_exp_ovf = 10'b111111111;
    localparam  c_shift_cap = 10'b1101;
    
    // Stub signals
    reg  [18:0] unpack_a$x;
    wire  unpack_a$sign;
    wire  [7:0] unpack_a$exp;
    wire  [10:0] unpack_a$sig;
    wire  unpack_a$is_zero;
    wire  unpack_a$is_inf;
    wire  unpack_a$is_nan;
    reg  [18:0] unpack_b$x;
    wire  unpack_b$sign;
    wire  [7:0] unpack_b$exp;
    wire  [10:0] unpack_b$sig;
    wire  unpack_b$is_zero;
    wire  unpack_b$is_inf;
    wire  unpack_b$is_nan;
    reg  [10:0] norm_a$x;
    wire  [10:0] norm_a$y;
    wire  [4:0] norm_a$lz;
    reg  [10:0] norm_b$x;
    wire  [10:0] norm_b$y;
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
    reg  [10:0] s1_sig_a$d;
    wire  [10:0] s1_sig_a$q;
    reg  s1_sig_a$clock;
    reg  [10:0] s1_sig_b$d;
    wire  [10:0] s1_sig_b$q;
    reg  s1_sig_b$clock;
    reg  [10:0] sig_mul$a;
    reg  [10:0] sig_mul$b;
    wire  [12:0] sig_mul$hi;
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
    reg  [12:0] s2_hi$d;
    wire  [12:0] s2_hi$q;
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
    reg  [12:0] s3_nm$d;
    wire  [12:0] s3_nm$q;
    reg  s3_nm$clock;
    reg  round$round_up;
    reg  round$sign;
    reg  round$nan;
    reg  round$inf;
    reg  round$zero;
    reg  round$ovf;
    reg  [7:0] round$efield;
    reg  [12:0] round$nm;
    wire  [18:0] round$y;
    reg  s4_valid$d;
    wire  s4_valid$q;
    reg  s4_valid$clock;
    reg  [18:0] s4_y$d;
    wire  [18:0] s4_y$q;
    reg  s4_y$clock;
    
    // Local signals
    reg  [9:0] c1_exp;
    reg  c3_top;
    reg  [12:0] c3_nm;
    reg  [9:0] c3_exp;
    reg  [9:0] c3_shift;
    reg  [9:0] c3_shift_cap;
    reg  [12:0] c3_shifted;
    reg  [12:0] c3_back;
    reg  c3_lost;
    reg  [7:0] c3_efield;
    
    // Sub module instances
    top$aerr$unpack_a unpack_a(
        .x(unpack_a$x),
        .sign(unpack_a$sign),
        .exp(unpack_a$exp),
        .sig(unpack_a$sig),
        .is_zero(unpack_a$is_zero),
        .is_inf(unpack_a$is_inf),
        .is_nan(unpack_a$is_nan)
    );
    top$aerr$unpack_a unpack_b(
        .x(unpack_b$x),
        .sign(unpack_b$sign),
        .exp(unpack_b$exp),
        .sig(unpack_b$sig),
        .is_zero(unpack_b$is_zero),
        .is_inf(unpack_b$is_inf),
        .is_nan(unpack_b$is_nan)
    );
    top$af$norm_a norm_a(
        .x(norm_a$x),
        .y(norm_a$y),
        .lz(norm_a$lz)
    );
    top$af$norm_a norm_b(
        .x(norm_b$x),
        .y(norm_b$y),
        .lz(norm_b$lz)
    );
    top$aerr$s1_eff_sub s1_valid(
        .d(s1_valid$d),
        .q(s1_valid$q),
        .clock(s1_valid$clock)
    );
    top$aerr$s1_eff_sub s1_sign(
        .d(s1_sign$d),
        .q(s1_sign$q),
        .clock(s1_sign$clock)
    );
    top$aerr$s1_eff_sub s1_nan(
        .d(s1_nan$d),
        .q(s1_nan$q),
        .clock(s1_nan$clock)
    );
    top$aerr$s1_eff_sub s1_inf(
        .d(s1_inf$d),
        .q(s1_inf$q),
        .clock(s1_inf$clock)
    );
    top$aerr$s1_eff_sub s1_zero(
        .d(s1_zero$d),
        .q(s1_zero$q),
        .clock(s1_zero$clock)
    );
    top$af$s1_exp s1_exp(
        .d(s1_exp$d),
        .q(s1_exp$q),
        .clock(s1_exp$clock)
    );
    top$af$s1_sig_a s1_sig_a(
        .d(s1_sig_a$d),
        .q(s1_sig_a$q),
        .clock(s1_sig_a$clock)
    );
    top$af$s1_sig_a s1_sig_b(
        .d(s1_sig_b$d),
        .q(s1_sig_b$q),
        .clock(s1_sig_b$clock)
    );
    top$af$sig_mul sig_mul(
        .a(sig_mul$a),
        .b(sig_mul$b),
        .hi(sig_mul$hi),
        .sticky(sig_mul$sticky)
    );
    top$aerr$s1_eff_sub s2_valid(
        .d(s2_valid$d),
        .q(s2_valid$q),
        .clock(s2_valid$clock)
    );
    top$aerr$s1_eff_sub s2_sign(
        .d(s2_sign$d),
        .q(s2_sign$q),
        .clock(s2_sign$clock)
    );
    top$aerr$s1_eff_sub s2_nan(
        .d(s2_nan$d),
        .q(s2_nan$q),
        .clock(s2_nan$clock)
    );
    top$aerr$s1_eff_sub s2_inf(
        .d(s2_inf$d),
        .q(s2_inf$q),
        .clock(s2_inf$clock)
    );
    top$aerr$s1_eff_sub s2_zero(
        .d(s2_zero$d),
        .q(s2_zero$q),
        .clock(s2_zero$clock)
    );
    top$af$s1_exp s2_exp(
        .d(s2_exp$d),
        .q(s2_exp$q),
        .clock(s2_exp$clock)
    );
    top$aerr$s2_nm s2_hi(
        .d(s2_hi$d),
        .q(s2_hi$q),
        .clock(s2_hi$clock)
    );
    top$aerr$s1_eff_sub s2_sticky(
        .d(s2_sticky$d),
        .q(s2_sticky$q),
        .clock(s2_sticky$clock)
    );
    top$aerr$s1_eff_sub s3_valid(
        .d(s3_valid$d),
        .q(s3_valid$q),
        .clock(s3_valid$clock)
    );
    top$aerr$s1_eff_sub s3_sign(
        .d(s3_sign$d),
        .q(s3_sign$q),
        .clock(s3_sign$clock)
    );
    top$aerr$s1_eff_sub s3_nan(
        .d(s3_nan$d),
        .q(s3_nan$q),
        .clock(s3_nan$clock)
    );
    top$aerr$s1_eff_sub s3_inf(
        .d(s3_inf$d),
        .q(s3_inf$q),
        .clock(s3_inf$clock)
    );
    top$aerr$s1_eff_sub s3_zero(
        .d(s3_zero$d),
        .q(s3_zero$q),
        .clock(s3_zero$clock)
    );
    top$aerr$s1_eff_sub s3_ovf(
        .d(s3_ovf$d),
        .q(s3_ovf$q),
        .clock(s3_ovf$clock)
    );
    top$aerr$s1_exp s3_efield(
        .d(s3_efield$d),
        .q(s3_efield$q),
        .clock(s3_efield$clock)
    );
    top$aerr$s2_nm s3_nm(
        .d(s3_nm$d),
        .q(s3_nm$q),
        .clock(s3_nm$clock)
    );
    top$aerr$round round(
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
    top$aerr$s1_eff_sub s4_valid(
        .d(s4_valid$d),
        .q(s4_valid$q),
        .clock(s4_valid$clock)
    );
    top$aerr$s3_y s4_y(
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
        c3_top = s2_hi$q[32'hb + 32'h1];
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
    
endmodule // top$af


module top$af$norm_a(x,y,lz);
    
    // Module arguments
    input wire  [10:0] x;
    output reg  [10:0] y;
    output reg  [4:0] lz;
    
    // Local signals
    reg  z8;
    reg  z4;
    reg  z2;
    reg  z1;
    reg  [10:0] x8;
    reg  [10:0] x4;
    reg  [10:0] x2;
    
    // Update code
    always @(*) begin
        z8 = x[(32'h3)+:(8)] == 32'h0;
        x8 = x;
        if (z8) begin
            x8 = x << 32'h8;
        end
        z4 = x8[(32'h7)+:(4)] == 32'h0;
        x4 = x8;
        if (z4) begin
            x4 = x8 << 32'h4;
        end
        z2 = x4[(32'h9)+:(2)] == 32'h0;
        x2 = x4;
        if (z2) begin
            x2 = x4 << 32'h2;
        end
        z1 = ~x2[32'ha];
        y = x2;
        if (z1) begin
            y = x2 << 32'h1;
        end
        lz = ((((((32'h0) & 5'h1f) & ~(1 << (32'h3)) | ((z8) << (32'h3))) & ~(1 << (32'h2)) | ((z4) << (32'h2))) & ~(1 << (32'h1)) | ((z2) << (32'h1))) & ~(1 << (32'h0)) | ((z1) << (32'h0)));
    end
    
endmodule // top$af$norm_a


module top$af$s1_exp(d,q,clock);
    
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
          
endmodule // top$af$s1_exp


module top$af$s1_sig_a(d,q,clock);
    
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
          
endmodule // top$af$s1_sig_a


module top$af$sig_mul(a,b,hi,sticky);
    
    // Module arguments
    input wire  [10:0] a;
    input wire  [10:0] b;
    output reg  [12:0] hi;
    output reg  sticky;
    
    // Update code (custom)
    wire [21:0] prod;
    assign prod = a * b;
    always @(*) begin
        hi = prod[21:9];
        sticky = |prod[8:0];
    end
endmodule // top$af$sig_mul


module top$c3_0(clock,d,q);
    
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
    top$aerr$s3_y line$0(
        .d(line$0$d),
        .q(line$0$q),
        .clock(line$0$clock)
    );
    top$aerr$s3_y line$1(
        .d(line$1$d),
        .q(line$1$q),
        .clock(line$1$clock)
    );
    top$aerr$s3_y line$2(
        .d(line$2$d),
        .q(line$2$q),
        .clock(line$2$clock)
    );
    top$aerr$s3_y line$3(
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
    
endmodule // top$c3_0


module top$edges$0(clock,p0,p1,p2,q0,q1,q2,pe,qe,pg,qg,pf0,pf1,pf2,qf0,qf1,qf2,ph,qh,s_x,s_b,cross_t,cross_f);
    
    // Module arguments
    input wire  clock;
    input wire  [18:0] p0;
    input wire  [18:0] p1;
    input wire  [18:0] p2;
    input wire  [18:0] q0;
    input wire  [18:0] q1;
    input wire  [18:0] q2;
    input wire  [18:0] pe;
    input wire  [18:0] qe;
    input wire  [18:0] pg;
    input wire  [18:0] qg;
    input wire  [18:0] pf0;
    input wire  [18:0] pf1;
    input wire  [18:0] pf2;
    input wire  [18:0] qf0;
    input wire  [18:0] qf1;
    input wire  [18:0] qf2;
    input wire  [18:0] ph;
    input wire  [18:0] qh;
    output reg  [18:0] s_x;
    output reg  [18:0] s_b;
    output reg  cross_t;
    output reg  cross_f;
    
    // Constant declarations
    localparam  mask = 19'b111111111111111111;
    
    // Stub signals
    reg  px_qz$clock;
    reg  [18:0] px_qz$a;
    reg  [18:0] px_qz$b;
    reg  px_qz$valid_in;
    wire  [18:0] px_qz$y;
    wire  px_qz$valid_out;
    reg  qx_pz$clock;
    reg  [18:0] qx_pz$a;
    reg  [18:0] qx_pz$b;
    reg  qx_pz$valid_in;
    wire  [18:0] qx_pz$y;
    wire  qx_pz$valid_out;
    reg  py_qz$clock;
    reg  [18:0] py_qz$a;
    reg  [18:0] py_qz$b;
    reg  py_qz$valid_in;
    wire  [18:0] py_qz$y;
    wire  py_qz$valid_out;
    reg  qy_pz$clock;
    reg  [18:0] qy_pz$a;
    reg  [18:0] qy_pz$b;
    reg  qy_pz$valid_in;
    wire  [18:0] qy_pz$y;
    wire  qy_pz$valid_out;
    reg  a$clock;
    reg  [18:0] a$a;
    reg  [18:0] a$b;
    reg  a$sub;
    reg  a$valid_in;
    wire  [18:0] a$y;
    wire  a$valid_out;
    reg  b$clock;
    reg  [18:0] b$a;
    reg  [18:0] b$b;
    reg  b$sub;
    reg  b$valid_in;
    wire  [18:0] b$y;
    wire  b$valid_out;
    reg  rz$clock;
    reg  [18:0] rz$a;
    reg  [18:0] rz$b;
    reg  rz$sub;
    reg  rz$valid_in;
    wire  [18:0] rz$y;
    wire  rz$valid_out;
    reg  rz_wait$clock;
    reg  [18:0] rz_wait$d;
    wire  [18:0] rz_wait$q;
    reg  ab$clock;
    reg  [18:0] ab$a;
    reg  [18:0] ab$b;
    reg  ab$sub;
    reg  ab$valid_in;
    wire  [18:0] ab$y;
    wire  ab$valid_out;
    reg  s$clock;
    reg  [18:0] s$a;
    reg  [18:0] s$b;
    reg  s$sub;
    reg  s$valid_in;
    wire  [18:0] s$y;
    wire  s$valid_out;
    reg  pf0_wait$clock;
    reg  [18:0] pf0_wait$d;
    wire  [18:0] pf0_wait$q;
    reg  qf0_wait$clock;
    reg  [18:0] qf0_wait$d;
    wire  [18:0] qf0_wait$q;
    reg  pf1_wait$clock;
    reg  [18:0] pf1_wait$d;
    wire  [18:0] pf1_wait$q;
    reg  qf1_wait$clock;
    reg  [18:0] qf1_wait$d;
    wire  [18:0] qf1_wait$q;
    reg  p0_wait$clock;
    reg  [18:0] p0_wait$d;
    wire  [18:0] p0_wait$q;
    reg  q0_wait$clock;
    reg  [18:0] q0_wait$d;
    wire  [18:0] q0_wait$q;
    reg  p1_wait$clock;
    reg  [18:0] p1_wait$d;
    wire  [18:0] p1_wait$q;
    reg  q1_wait$clock;
    reg  [18:0] q1_wait$d;
    wire  [18:0] q1_wait$q;
    reg  ta$0$clock;
    reg  [18:0] ta$0$a;
    reg  [18:0] ta$0$b;
    reg  ta$0$valid_in;
    wire  [18:0] ta$0$y;
    wire  ta$0$valid_out;
    reg  ta$1$clock;
    reg  [18:0] ta$1$a;
    reg  [18:0] ta$1$b;
    reg  ta$1$valid_in;
    wire  [18:0] ta$1$y;
    wire  ta$1$valid_out;
    reg  ta$2$clock;
    reg  [18:0] ta$2$a;
    reg  [18:0] ta$2$b;
    reg  ta$2$valid_in;
    wire  [18:0] ta$2$y;
    wire  ta$2$valid_out;
    reg  ta$3$clock;
    reg  [18:0] ta$3$a;
    reg  [18:0] ta$3$b;
    reg  ta$3$valid_in;
    wire  [18:0] ta$3$y;
    wire  ta$3$valid_out;
    reg  tb$0$clock;
    reg  [18:0] tb$0$a;
    reg  [18:0] tb$0$b;
    reg  tb$0$valid_in;
    wire  [18:0] tb$0$y;
    wire  tb$0$valid_out;
    reg  tb$1$clock;
    reg  [18:0] tb$1$a;
    reg  [18:0] tb$1$b;
    reg  tb$1$valid_in;
    wire  [18:0] tb$1$y;
    wire  tb$1$valid_out;
    reg  tb$2$clock;
    reg  [18:0] tb$2$a;
    reg  [18:0] tb$2$b;
    reg  tb$2$valid_in;
    wire  [18:0] tb$2$y;
    wire  tb$2$valid_out;
    reg  tb$3$clock;
    reg  [18:0] tb$3$a;
    reg  [18:0] tb$3$b;
    reg  tb$3$valid_in;
    wire  [18:0] tb$3$y;
    wire  tb$3$valid_out;
    reg  ta_wait$0$clock;
    reg  [18:0] ta_wait$0$d;
    wire  [18:0] ta_wait$0$q;
    reg  ta_wait$1$clock;
    reg  [18:0] ta_wait$1$d;
    wire  [18:0] ta_wait$1$q;
    reg  tb_wait$0$clock;
    reg  [18:0] tb_wait$0$d;
    wire  [18:0] tb_wait$0$q;
    reg  tb_wait$1$clock;
    reg  [18:0] tb_wait$1$d;
    wire  [18:0] tb_wait$1$q;
    reg  sa$0$clock;
    reg  [18:0] sa$0$a;
    reg  [18:0] sa$0$b;
    reg  sa$0$sub;
    reg  sa$0$valid_in;
    wire  [18:0] sa$0$y;
    wire  sa$0$valid_out;
    reg  sa$1$clock;
    reg  [18:0] sa$1$a;
    reg  [18:0] sa$1$b;
    reg  sa$1$sub;
    reg  sa$1$valid_in;
    wire  [18:0] sa$1$y;
    wire  sa$1$valid_out;
    reg  sb$0$clock;
    reg  [18:0] sb$0$a;
    reg  [18:0] sb$0$b;
    reg  sb$0$sub;
    reg  sb$0$valid_in;
    wire  [18:0] sb$0$y;
    wire  sb$0$valid_out;
    reg  sb$1$clock;
    reg  [18:0] sb$1$a;
    reg  [18:0] sb$1$b;
    reg  sb$1$sub;
    reg  sb$1$valid_in;
    wire  [18:0] sb$1$y;
    wire  sb$1$valid_out;
    reg  ba$clock;
    reg  [18:0] ba$a;
    reg  [18:0] ba$b;
    reg  ba$sub;
    reg  ba$valid_in;
    wire  [18:0] ba$y;
    wire  ba$valid_out;
    reg  bb$clock;
    reg  [18:0] bb$a;
    reg  [18:0] bb$b;
    reg  bb$sub;
    reg  bb$valid_in;
    wire  [18:0] bb$y;
    wire  bb$valid_out;
    reg  brz$clock;
    reg  [18:0] brz$a;
    reg  [18:0] brz$b;
    reg  brz$sub;
    reg  brz$valid_in;
    wire  [18:0] brz$y;
    wire  brz$valid_out;
    reg  brz_wait$clock;
    reg  [18:0] brz_wait$d;
    wire  [18:0] brz_wait$q;
    reg  rab$clock;
    reg  [18:0] rab$a;
    reg  [18:0] rab$b;
    reg  rab$sub;
    reg  rab$valid_in;
    wire  [18:0] rab$y;
    wire  rab$valid_out;
    reg  rabz$clock;
    reg  [18:0] rabz$a;
    reg  [18:0] rabz$b;
    reg  rabz$sub;
    reg  rabz$valid_in;
    wire  [18:0] rabz$y;
    wire  rabz$valid_out;
    reg  rs$clock;
    reg  [18:0] rs$a;
    reg  rs$sel;
    wire  [18:0] rs$y;
    reg  brs$clock;
    reg  [18:0] brs$a;
    reg  [18:0] brs$b;
    reg  brs$sub;
    reg  brs$valid_in;
    wire  [18:0] brs$y;
    wire  brs$valid_out;
    reg  brs_wait$clock;
    reg  [18:0] brs_wait$d;
    wire  [18:0] brs_wait$q;
    reg  bab$clock;
    reg  [18:0] bab$a;
    reg  [18:0] bab$b;
    reg  bab$sub;
    reg  bab$valid_in;
    wire  [18:0] bab$y;
    wire  bab$valid_out;
    reg  bs$clock;
    reg  [18:0] bs$a;
    reg  [18:0] bs$b;
    reg  bs$sub;
    reg  bs$valid_in;
    wire  [18:0] bs$y;
    wire  bs$valid_out;
    reg  pz_wait$clock;
    reg  [18:0] pz_wait$d;
    wire  [18:0] pz_wait$q;
    reg  qz_wait$clock;
    reg  [18:0] qz_wait$d;
    wire  [18:0] qz_wait$q;
    reg  a_wait$clock;
    reg  [18:0] a_wait$d;
    wire  [18:0] a_wait$q;
    reg  b_wait$clock;
    reg  [18:0] b_wait$d;
    wire  [18:0] b_wait$q;
    reg  s_wait$clock;
    reg  [18:0] s_wait$d;
    wire  [18:0] s_wait$q;
    reg  [18:0] sign_pz$x;
    reg  [18:0] sign_pz$e;
    wire  [1:0] sign_pz$sgn;
    reg  [18:0] sign_qz$x;
    reg  [18:0] sign_qz$e;
    wire  [1:0] sign_qz$sgn;
    reg  [18:0] sign_rz$x;
    reg  [18:0] sign_rz$e;
    wire  [1:0] sign_rz$sgn;
    reg  [18:0] sign_a$x;
    reg  [18:0] sign_a$e;
    wire  [1:0] sign_a$sgn;
    reg  [18:0] sign_b$x;
    reg  [18:0] sign_b$e;
    wire  [1:0] sign_b$sgn;
    reg  [18:0] sign_s$x;
    reg  [18:0] sign_s$e;
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
    reg  [18:0] r_s_x$d;
    wire  [18:0] r_s_x$q;
    reg  r_s_x$clock;
    reg  [18:0] r_s_b$d;
    wire  [18:0] r_s_b$q;
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
    top$edges$0$px_qz px_qz(
        .clock(px_qz$clock),
        .a(px_qz$a),
        .b(px_qz$b),
        .valid_in(px_qz$valid_in),
        .y(px_qz$y),
        .valid_out(px_qz$valid_out)
    );
    top$edges$0$px_qz qx_pz(
        .clock(qx_pz$clock),
        .a(qx_pz$a),
        .b(qx_pz$b),
        .valid_in(qx_pz$valid_in),
        .y(qx_pz$y),
        .valid_out(qx_pz$valid_out)
    );
    top$edges$0$px_qz py_qz(
        .clock(py_qz$clock),
        .a(py_qz$a),
        .b(py_qz$b),
        .valid_in(py_qz$valid_in),
        .y(py_qz$y),
        .valid_out(py_qz$valid_out)
    );
    top$edges$0$px_qz qy_pz(
        .clock(qy_pz$clock),
        .a(qy_pz$a),
        .b(qy_pz$b),
        .valid_in(qy_pz$valid_in),
        .y(qy_pz$y),
        .valid_out(qy_pz$valid_out)
    );
    top$edges$0$a a(
        .clock(a$clock),
        .a(a$a),
        .b(a$b),
        .sub(a$sub),
        .valid_in(a$valid_in),
        .y(a$y),
        .valid_out(a$valid_out)
    );
    top$edges$0$a b(
        .clock(b$clock),
        .a(b$a),
        .b(b$b),
        .sub(b$sub),
        .valid_in(b$valid_in),
        .y(b$y),
        .valid_out(b$valid_out)
    );
    top$edges$0$a rz(
        .clock(rz$clock),
        .a(rz$a),
        .b(rz$b),
        .sub(rz$sub),
        .valid_in(rz$valid_in),
        .y(rz$y),
        .valid_out(rz$valid_out)
    );
    top$edges$0$brz_wait rz_wait(
        .clock(rz_wait$clock),
        .d(rz_wait$d),
        .q(rz_wait$q)
    );
    top$edges$0$a ab(
        .clock(ab$clock),
        .a(ab$a),
        .b(ab$b),
        .sub(ab$sub),
        .valid_in(ab$valid_in),
        .y(ab$y),
        .valid_out(ab$valid_out)
    );
    top$edges$0$a s(
        .clock(s$clock),
        .a(s$a),
        .b(s$b),
        .sub(s$sub),
        .valid_in(s$valid_in),
        .y(s$y),
        .valid_out(s$valid_out)
    );
    top$edges$0$brs_wait pf0_wait(
        .clock(pf0_wait$clock),
        .d(pf0_wait$d),
        .q(pf0_wait$q)
    );
    top$edges$0$brs_wait qf0_wait(
        .clock(qf0_wait$clock),
        .d(qf0_wait$d),
        .q(qf0_wait$q)
    );
    top$edges$0$brs_wait pf1_wait(
        .clock(pf1_wait$clock),
        .d(pf1_wait$d),
        .q(pf1_wait$q)
    );
    top$edges$0$brs_wait qf1_wait(
        .clock(qf1_wait$clock),
        .d(qf1_wait$d),
        .q(qf1_wait$q)
    );
    top$edges$0$brz_wait p0_wait(
        .clock(p0_wait$clock),
        .d(p0_wait$d),
        .q(p0_wait$q)
    );
    top$edges$0$brz_wait q0_wait(
        .clock(q0_wait$clock),
        .d(q0_wait$d),
        .q(q0_wait$q)
    );
    top$edges$0$brz_wait p1_wait(
        .clock(p1_wait$clock),
        .d(p1_wait$d),
        .q(p1_wait$q)
    );
    top$edges$0$brz_wait q1_wait(
        .clock(q1_wait$clock),
        .d(q1_wait$d),
        .q(q1_wait$q)
    );
    top$af ta$0(
        .clock(ta$0$clock),
        .a(ta$0$a),
        .b(ta$0$b),
        .valid_in(ta$0$valid_in),
        .y(ta$0$y),
        .valid_out(ta$0$valid_out)
    );
    top$af ta$1(
        .clock(ta$1$clock),
        .a(ta$1$a),
        .b(ta$1$b),
        .valid_in(ta$1$valid_in),
        .y(ta$1$y),
        .valid_out(ta$1$valid_out)
    );
    top$af ta$2(
        .clock(ta$2$clock),
        .a(ta$2$a),
        .b(ta$2$b),
        .valid_in(ta$2$valid_in),
        .y(ta$2$y),
        .valid_out(ta$2$valid_out)
    );
    top$af ta$3(
        .clock(ta$3$clock),
        .a(ta$3$a),
        .b(ta$3$b),
        .valid_in(ta$3$valid_in),
        .y(ta$3$y),
        .valid_out(ta$3$valid_out)
    );
    top$af tb$0(
        .clock(tb$0$clock),
        .a(tb$0$a),
        .b(tb$0$b),
        .valid_in(tb$0$valid_in),
        .y(tb$0$y),
        .valid_out(tb$0$valid_out)
    );
    top$af tb$1(
        .clock(tb$1$clock),
        .a(tb$1$a),
        .b(tb$1$b),
        .valid_in(tb$1$valid_in),
        .y(tb$1$y),
        .valid_out(tb$1$valid_out)
    );
    top$af tb$2(
        .clock(tb$2$clock),
        .a(tb$2$a),
        .b(tb$2$b),
        .valid_in(tb$2$valid_in),
        .y(tb$2$y),
        .valid_out(tb$2$valid_out)
    );
    top$af tb$3(
        .clock(tb$3$clock),
        .a(tb$3$a),
        .b(tb$3$b),
        .valid_in(tb$3$valid_in),
        .y(tb$3$y),
        .valid_out(tb$3$valid_out)
    );
    top$edges$0$brs_wait ta_wait$0(
        .clock(ta_wait$0$clock),
        .d(ta_wait$0$d),
        .q(ta_wait$0$q)
    );
    top$edges$0$brs_wait ta_wait$1(
        .clock(ta_wait$1$clock),
        .d(ta_wait$1$d),
        .q(ta_wait$1$q)
    );
    top$edges$0$brs_wait tb_wait$0(
        .clock(tb_wait$0$clock),
        .d(tb_wait$0$d),
        .q(tb_wait$0$q)
    );
    top$edges$0$brs_wait tb_wait$1(
        .clock(tb_wait$1$clock),
        .d(tb_wait$1$d),
        .q(tb_wait$1$q)
    );
    top$aerr sa$0(
        .clock(sa$0$clock),
        .a(sa$0$a),
        .b(sa$0$b),
        .sub(sa$0$sub),
        .valid_in(sa$0$valid_in),
        .y(sa$0$y),
        .valid_out(sa$0$valid_out)
    );
    top$aerr sa$1(
        .clock(sa$1$clock),
        .a(sa$1$a),
        .b(sa$1$b),
        .sub(sa$1$sub),
        .valid_in(sa$1$valid_in),
        .y(sa$1$y),
        .valid_out(sa$1$valid_out)
    );
    top$aerr sb$0(
        .clock(sb$0$clock),
        .a(sb$0$a),
        .b(sb$0$b),
        .sub(sb$0$sub),
        .valid_in(sb$0$valid_in),
        .y(sb$0$y),
        .valid_out(sb$0$valid_out)
    );
    top$aerr sb$1(
        .clock(sb$1$clock),
        .a(sb$1$a),
        .b(sb$1$b),
        .sub(sb$1$sub),
        .valid_in(sb$1$valid_in),
        .y(sb$1$y),
        .valid_out(sb$1$valid_out)
    );
    top$aerr ba(
        .clock(ba$clock),
        .a(ba$a),
        .b(ba$b),
        .sub(ba$sub),
        .valid_in(ba$valid_in),
        .y(ba$y),
        .valid_out(ba$valid_out)
    );
    top$aerr bb(
        .clock(bb$clock),
        .a(bb$a),
        .b(bb$b),
        .sub(bb$sub),
        .valid_in(bb$valid_in),
        .y(bb$y),
        .valid_out(bb$valid_out)
    );
    top$aerr brz(
        .clock(brz$clock),
        .a(brz$a),
        .b(brz$b),
        .sub(brz$sub),
        .valid_in(brz$valid_in),
        .y(brz$y),
        .valid_out(brz$valid_out)
    );
    top$edges$0$brz_wait brz_wait(
        .clock(brz_wait$clock),
        .d(brz_wait$d),
        .q(brz_wait$q)
    );
    top$aerr rab(
        .clock(rab$clock),
        .a(rab$a),
        .b(rab$b),
        .sub(rab$sub),
        .valid_in(rab$valid_in),
        .y(rab$y),
        .valid_out(rab$valid_out)
    );
    top$aerr rabz(
        .clock(rabz$clock),
        .a(rabz$a),
        .b(rabz$b),
        .sub(rabz$sub),
        .valid_in(rabz$valid_in),
        .y(rabz$y),
        .valid_out(rabz$valid_out)
    );
    top$edges$0$rs rs(
        .clock(rs$clock),
        .a(rs$a),
        .sel(rs$sel),
        .y(rs$y)
    );
    top$aerr brs(
        .clock(brs$clock),
        .a(brs$a),
        .b(brs$b),
        .sub(brs$sub),
        .valid_in(brs$valid_in),
        .y(brs$y),
        .valid_out(brs$valid_out)
    );
    top$edges$0$brs_wait brs_wait(
        .clock(brs_wait$clock),
        .d(brs_wait$d),
        .q(brs_wait$q)
    );
    top$aerr bab(
        .clock(bab$clock),
        .a(bab$a),
        .b(bab$b),
        .sub(bab$sub),
        .valid_in(bab$valid_in),
        .y(bab$y),
        .valid_out(bab$valid_out)
    );
    top$aerr bs(
        .clock(bs$clock),
        .a(bs$a),
        .b(bs$b),
        .sub(bs$sub),
        .valid_in(bs$valid_in),
        .y(bs$y),
        .valid_out(bs$valid_out)
    );
    top$c3_0 pz_wait(
        .clock(pz_wait$clock),
        .d(pz_wait$d),
        .q(pz_wait$q)
    );
    top$c3_0 qz_wait(
        .clock(qz_wait$clock),
        .d(qz_wait$d),
        .q(qz_wait$q)
    );
    top$edges$0$a_wait a_wait(
        .clock(a_wait$clock),
        .d(a_wait$d),
        .q(a_wait$q)
    );
    top$edges$0$a_wait b_wait(
        .clock(b_wait$clock),
        .d(b_wait$d),
        .q(b_wait$q)
    );
    top$edges$0$a_wait s_wait(
        .clock(s_wait$clock),
        .d(s_wait$d),
        .q(s_wait$q)
    );
    top$edges$0$sign_a sign_pz(
        .x(sign_pz$x),
        .e(sign_pz$e),
        .sgn(sign_pz$sgn)
    );
    top$edges$0$sign_a sign_qz(
        .x(sign_qz$x),
        .e(sign_qz$e),
        .sgn(sign_qz$sgn)
    );
    top$edges$0$sign_a sign_rz(
        .x(sign_rz$x),
        .e(sign_rz$e),
        .sgn(sign_rz$sgn)
    );
    top$edges$0$sign_a sign_a(
        .x(sign_a$x),
        .e(sign_a$e),
        .sgn(sign_a$sgn)
    );
    top$edges$0$sign_a sign_b(
        .x(sign_b$x),
        .e(sign_b$e),
        .sgn(sign_b$sgn)
    );
    top$edges$0$sign_a sign_s(
        .x(sign_s$x),
        .e(sign_s$e),
        .sgn(sign_s$sgn)
    );
    top$edges$0$pz_sgn_wait pz_sgn_wait(
        .clock(pz_sgn_wait$clock),
        .d(pz_sgn_wait$d),
        .q(pz_sgn_wait$q)
    );
    top$edges$0$pz_sgn_wait qz_sgn_wait(
        .clock(qz_sgn_wait$clock),
        .d(qz_sgn_wait$d),
        .q(qz_sgn_wait$q)
    );
    top$edges$0$rz_sgn_wait rz_sgn_wait(
        .clock(rz_sgn_wait$clock),
        .d(rz_sgn_wait$d),
        .q(rz_sgn_wait$q)
    );
    top$edges$0$a_sgn_wait a_sgn_wait(
        .clock(a_sgn_wait$clock),
        .d(a_sgn_wait$d),
        .q(a_sgn_wait$q)
    );
    top$edges$0$a_sgn_wait b_sgn_wait(
        .clock(b_sgn_wait$clock),
        .d(b_sgn_wait$d),
        .q(b_sgn_wait$q)
    );
    top$edges$0$a_sgn_wait$line$0 r_pz(
        .d(r_pz$d),
        .q(r_pz$q),
        .clock(r_pz$clock)
    );
    top$edges$0$a_sgn_wait$line$0 r_qz(
        .d(r_qz$d),
        .q(r_qz$q),
        .clock(r_qz$clock)
    );
    top$edges$0$a_sgn_wait$line$0 r_rz(
        .d(r_rz$d),
        .q(r_rz$q),
        .clock(r_rz$clock)
    );
    top$edges$0$a_sgn_wait$line$0 r_a(
        .d(r_a$d),
        .q(r_a$q),
        .clock(r_a$clock)
    );
    top$edges$0$a_sgn_wait$line$0 r_b(
        .d(r_b$d),
        .q(r_b$q),
        .clock(r_b$clock)
    );
    top$edges$0$a_sgn_wait$line$0 r_s(
        .d(r_s$d),
        .q(r_s$q),
        .clock(r_s$clock)
    );
    top$aerr$s3_y r_s_x(
        .d(r_s_x$d),
        .q(r_s_x$q),
        .clock(r_s_x$clock)
    );
    top$aerr$s3_y r_s_b(
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
    
endmodule // top$edges$0


module top$edges$0$a(clock,a,b,sub,valid_in,y,valid_out);
    
    // Module arguments
    input wire  clock;
    input wire  [18:0] a;
    input wire  [18:0] b;
    input wire  sub;
    input wire  valid_in;
    output reg  [18:0] y;
    output reg  valid_out;
    
    // Constant declarations
    localparam  round_up = 1'b0;
    localparam  c_align_cap = 8'he;
    localparam  c_exp_ones = 10'b11111111;
    
    // Stub signals
    reg  [18:0] unpack_a$x;
    wire  unpack_a$sign;
    wire  [7:0] unpack_a$exp;
    wire  [10:0] unpack_a$sig;
    wire  unpack_a$is_zero;
    wire  unpack_a$is_inf;
    wire  unpack_a$is_nan;
    reg  [18:0] unpack_b$x;
    wire  unpack_b$sign;
    wire  [7:0] unpack_b$exp;
    wire  [10:0] unpack_b$sig;
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
    reg  [13:0] s1_big$d;
    wire  [13:0] s1_big$q;
    reg  s1_big$clock;
    reg  [13:0] s1_small$d;
    wire  [13:0] s1_small$q;
    reg  s1_small$clock;
    reg  [13:0] norm$x;
    wire  [13:0] norm$y;
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
    reg  [12:0] s2_nm$d;
    wire  [12:0] s2_nm$q;
    reg  s2_nm$clock;
    reg  round$round_up;
    reg  round$sign;
    reg  round$nan;
    reg  round$inf;
    reg  round$zero;
    reg  round$ovf;
    reg  [7:0] round$efield;
    reg  [12:0] round$nm;
    wire  [18:0] round$y;
    reg  s3_valid$d;
    wire  s3_valid$q;
    reg  s3_valid$clock;
    reg  [18:0] s3_y$d;
    wire  [18:0] s3_y$q;
    reg  s3_y$clock;
    
    // Local signals
    reg  c1_b_sign;
    reg  c1_swap;
    reg  c1_big_sign;
    reg  [7:0] c1_big_exp;
    reg  [10:0] c1_big_sig;
    reg  c1_small_sign;
    reg  [7:0] c1_small_exp;
    reg  [10:0] c1_small_sig;
    reg  [7:0] c1_diff;
    reg  [7:0] c1_shift;
    reg  [13:0] c1_small_ext;
    reg  [13:0] c1_aligned;
    reg  [13:0] c1_back;
    reg  c1_lost;
    reg  c1_inf_sign;
    reg  [14:0] c2_sum;
    reg  c2_carry;
    reg  c2_zero;
    reg  [7:0] c2_limit;
    reg  [7:0] c2_lz;
    reg  [7:0] c2_shift;
    reg  [13:0] c2_shifted;
    reg  [9:0] c2_exp;
    reg  [12:0] c2_nm;
    reg  c2_sign;
    
    // Sub module instances
    top$aerr$unpack_a unpack_a(
        .x(unpack_a$x),
        .sign(unpack_a$sign),
        .exp(unpack_a$exp),
        .sig(unpack_a$sig),
        .is_zero(unpack_a$is_zero),
        .is_inf(unpack_a$is_inf),
        .is_nan(unpack_a$is_nan)
    );
    top$aerr$unpack_a unpack_b(
        .x(unpack_b$x),
        .sign(unpack_b$sign),
        .exp(unpack_b$exp),
        .sig(unpack_b$sig),
        .is_zero(unpack_b$is_zero),
        .is_inf(unpack_b$is_inf),
        .is_nan(unpack_b$is_nan)
    );
    top$aerr$s1_eff_sub s1_valid(
        .d(s1_valid$d),
        .q(s1_valid$q),
        .clock(s1_valid$clock)
    );
    top$aerr$s1_eff_sub s1_nan(
        .d(s1_nan$d),
        .q(s1_nan$q),
        .clock(s1_nan$clock)
    );
    top$aerr$s1_eff_sub s1_inf(
        .d(s1_inf$d),
        .q(s1_inf$q),
        .clock(s1_inf$clock)
    );
    top$aerr$s1_eff_sub s1_inf_sign(
        .d(s1_inf_sign$d),
        .q(s1_inf_sign$q),
        .clock(s1_inf_sign$clock)
    );
    top$aerr$s1_eff_sub s1_zero_sign(
        .d(s1_zero_sign$d),
        .q(s1_zero_sign$q),
        .clock(s1_zero_sign$clock)
    );
    top$aerr$s1_eff_sub s1_sign(
        .d(s1_sign$d),
        .q(s1_sign$q),
        .clock(s1_sign$clock)
    );
    top$aerr$s1_eff_sub s1_eff_sub(
        .d(s1_eff_sub$d),
        .q(s1_eff_sub$q),
        .clock(s1_eff_sub$clock)
    );
    top$aerr$s1_exp s1_exp(
        .d(s1_exp$d),
        .q(s1_exp$q),
        .clock(s1_exp$clock)
    );
    top$aerr$s1_big s1_big(
        .d(s1_big$d),
        .q(s1_big$q),
        .clock(s1_big$clock)
    );
    top$aerr$s1_big s1_small(
        .d(s1_small$d),
        .q(s1_small$q),
        .clock(s1_small$clock)
    );
    top$aerr$norm norm(
        .x(norm$x),
        .y(norm$y),
        .lz(norm$lz)
    );
    top$aerr$s1_eff_sub s2_valid(
        .d(s2_valid$d),
        .q(s2_valid$q),
        .clock(s2_valid$clock)
    );
    top$aerr$s1_eff_sub s2_sign(
        .d(s2_sign$d),
        .q(s2_sign$q),
        .clock(s2_sign$clock)
    );
    top$aerr$s1_eff_sub s2_nan(
        .d(s2_nan$d),
        .q(s2_nan$q),
        .clock(s2_nan$clock)
    );
    top$aerr$s1_eff_sub s2_inf(
        .d(s2_inf$d),
        .q(s2_inf$q),
        .clock(s2_inf$clock)
    );
    top$aerr$s1_eff_sub s2_zero(
        .d(s2_zero$d),
        .q(s2_zero$q),
        .clock(s2_zero$clock)
    );
    top$aerr$s1_eff_sub s2_ovf(
        .d(s2_ovf$d),
        .q(s2_ovf$q),
        .clock(s2_ovf$clock)
    );
    top$aerr$s1_exp s2_efield(
        .d(s2_efield$d),
        .q(s2_efield$q),
        .clock(s2_efield$clock)
    );
    top$aerr$s2_nm s2_nm(
        .d(s2_nm$d),
        .q(s2_nm$q),
        .clock(s2_nm$clock)
    );
    top$aerr$round round(
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
    top$aerr$s1_eff_sub s3_valid(
        .d(s3_valid$d),
        .q(s3_valid$q),
        .clock(s3_valid$clock)
    );
    top$aerr$s3_y s3_y(
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
        c1_swap = a[(32'h0)+:(18)] < b[(32'h0)+:(18)];
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
        c1_small_ext = ((c1_small_sig) & 14'h3fff) << 32'h3;
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
        s1_big$d = ((c1_big_sig) & 14'h3fff) << 32'h3;
        s1_small$d = (c1_aligned & ~(1 << (32'h0)) | ((c1_aligned[32'h0] | c1_lost) << (32'h0)));
        c2_sum = ((s1_big$q) & 15'h7fff) + ((s1_small$q) & 15'h7fff);
        if (s1_eff_sub$q) begin
            c2_sum = ((s1_big$q) & 15'h7fff) - ((s1_small$q) & 15'h7fff);
        end
        c2_carry = c2_sum[32'he];
        c2_zero = c2_sum == 32'h0;
        norm$x = c2_sum[(32'h0)+:(14)];
        c2_limit = s1_exp$q - 32'h1;
        c2_lz = ((norm$lz) & 8'hff);
        c2_shift = c2_lz;
        if (c2_lz > c2_limit) begin
            c2_shift = c2_limit;
        end
        c2_shifted = c2_sum[(32'h0)+:(14)] << c2_shift;
        c2_exp = ((s1_exp$q) & 10'h3ff) - ((c2_shift) & 10'h3ff);
        c2_nm = (((c2_shifted >> 32'h1) & 13'h1fff) & ~(1 << (32'h0)) | ((c2_shifted[32'h1] | c2_shifted[32'h0]) << (32'h0)));
        if (c2_carry) begin
            c2_exp = ((s1_exp$q) & 10'h3ff) + 32'h1;
            c2_nm = (((c2_sum >> 32'h2) & 13'h1fff) & ~(1 << (32'h0)) | ((c2_sum[32'h2] | c2_sum[32'h1] | c2_sum[32'h0]) << (32'h0)));
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
        if (c2_nm[32'hb + 32'h1]) begin
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
    
endmodule // top$edges$0$a


module top$edges$0$a_sgn_wait(clock,d,q);
    
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
    top$edges$0$a_sgn_wait$line$0 line$0(
        .d(line$0$d),
        .q(line$0$q),
        .clock(line$0$clock)
    );
    top$edges$0$a_sgn_wait$line$0 line$1(
        .d(line$1$d),
        .q(line$1$q),
        .clock(line$1$clock)
    );
    top$edges$0$a_sgn_wait$line$0 line$2(
        .d(line$2$d),
        .q(line$2$q),
        .clock(line$2$clock)
    );
    top$edges$0$a_sgn_wait$line$0 line$3(
        .d(line$3$d),
        .q(line$3$q),
        .clock(line$3$clock)
    );
    top$edges$0$a_sgn_wait$line$0 line$4(
        .d(line$4$d),
        .q(line$4$q),
        .clock(line$4$clock)
    );
    top$edges$0$a_sgn_wait$line$0 line$5(
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
    
endmodule // top$edges$0$a_sgn_wait


module top$edges$0$a_sgn_wait$line$0(d,q,clock);
    
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
          
endmodule // top$edges$0$a_sgn_wait$line$0


module top$edges$0$a_wait(clock,d,q);
    
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
    reg  [18:0] line$4$d;
    wire  [18:0] line$4$q;
    reg  line$4$clock;
    reg  [18:0] line$5$d;
    wire  [18:0] line$5$q;
    reg  line$5$clock;
    reg  [18:0] line$6$d;
    wire  [18:0] line$6$q;
    reg  line$6$clock;
    reg  [18:0] line$7$d;
    wire  [18:0] line$7$q;
    reg  line$7$clock;
    reg  [18:0] line$8$d;
    wire  [18:0] line$8$q;
    reg  line$8$clock;
    reg  [18:0] line$9$d;
    wire  [18:0] line$9$q;
    reg  line$9$clock;
    reg  [18:0] line$10$d;
    wire  [18:0] line$10$q;
    reg  line$10$clock;
    reg  [18:0] line$11$d;
    wire  [18:0] line$11$q;
    reg  line$11$clock;
    reg  [18:0] line$12$d;
    wire  [18:0] line$12$q;
    reg  line$12$clock;
    
    // Sub module instances
    top$aerr$s3_y line$0(
        .d(line$0$d),
        .q(line$0$q),
        .clock(line$0$clock)
    );
    top$aerr$s3_y line$1(
        .d(line$1$d),
        .q(line$1$q),
        .clock(line$1$clock)
    );
    top$aerr$s3_y line$2(
        .d(line$2$d),
        .q(line$2$q),
        .clock(line$2$clock)
    );
    top$aerr$s3_y line$3(
        .d(line$3$d),
        .q(line$3$q),
        .clock(line$3$clock)
    );
    top$aerr$s3_y line$4(
        .d(line$4$d),
        .q(line$4$q),
        .clock(line$4$clock)
    );
    top$aerr$s3_y line$5(
        .d(line$5$d),
        .q(line$5$q),
        .clock(line$5$clock)
    );
    top$aerr$s3_y line$6(
        .d(line$6$d),
        .q(line$6$q),
        .clock(line$6$clock)
    );
    top$aerr$s3_y line$7(
        .d(line$7$d),
        .q(line$7$q),
        .clock(line$7$clock)
    );
    top$aerr$s3_y line$8(
        .d(line$8$d),
        .q(line$8$q),
        .clock(line$8$clock)
    );
    top$aerr$s3_y line$9(
        .d(line$9$d),
        .q(line$9$q),
        .clock(line$9$clock)
    );
    top$aerr$s3_y line$10(
        .d(line$10$d),
        .q(line$10$q),
        .clock(line$10$clock)
    );
    top$aerr$s3_y line$11(
        .d(line$11$d),
        .q(line$11$q),
        .clock(line$11$clock)
    );
    top$aerr$s3_y line$12(
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
    
endmodule // top$edges$0$a_wait


module top$edges$0$brs_wait(clock,d,q);
    
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
    
    // Sub module instances
    top$aerr$s3_y line$0(
        .d(line$0$d),
        .q(line$0$q),
        .clock(line$0$clock)
    );
    top$aerr$s3_y line$1(
        .d(line$1$d),
        .q(line$1$q),
        .clock(line$1$clock)
    );
    top$aerr$s3_y line$2(
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
    
endmodule // top$edges$0$brs_wait


module top$edges$0$brz_wait(clock,d,q);
    
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
    reg  [18:0] line$4$d;
    wire  [18:0] line$4$q;
    reg  line$4$clock;
    reg  [18:0] line$5$d;
    wire  [18:0] line$5$q;
    reg  line$5$clock;
    reg  [18:0] line$6$d;
    wire  [18:0] line$6$q;
    reg  line$6$clock;
    
    // Sub module instances
    top$aerr$s3_y line$0(
        .d(line$0$d),
        .q(line$0$q),
        .clock(line$0$clock)
    );
    top$aerr$s3_y line$1(
        .d(line$1$d),
        .q(line$1$q),
        .clock(line$1$clock)
    );
    top$aerr$s3_y line$2(
        .d(line$2$d),
        .q(line$2$q),
        .clock(line$2$clock)
    );
    top$aerr$s3_y line$3(
        .d(line$3$d),
        .q(line$3$q),
        .clock(line$3$clock)
    );
    top$aerr$s3_y line$4(
        .d(line$4$d),
        .q(line$4$q),
        .clock(line$4$clock)
    );
    top$aerr$s3_y line$5(
        .d(line$5$d),
        .q(line$5$q),
        .clock(line$5$clock)
    );
    top$aerr$s3_y line$6(
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
    
endmodule // top$edges$0$brz_wait


module top$edges$0$px_qz(clock,a,b,valid_in,y,valid_out);
    
    // Module arguments
    input wire  clock;
    input wire  [18:0] a;
    input wire  [18:0] b;
    input wire  valid_in;
    output reg  [18:0] y;
    output reg  valid_out;
    
    // Constant declarations
    localparam  round_up = 1'b0;
    localparam  c_exp_adj = 10'b10000001;
    localparam  c_exp_ofs = 10'b100000000;
    localparam  c_exp_norm_min = 10'b100000001;
    localparam  c_exp_ovf = 10'b111111111;
    localparam  c_shift_cap = 10'b1101;
    
    // Stub signals
    reg  [18:0] unpack_a$x;
    wire  unpack_a$sign;
    wire  [7:0] unpack_a$exp;
    wire  [10:0] unpack_a$sig;
    wire  unpack_a$is_zero;
    wire  unpack_a$is_inf;
    wire  unpack_a$is_nan;
    reg  [18:0] unpack_b$x;
    wire  unpack_b$sign;
    wire  [7:0] unpack_b$exp;
    wire  [10:0] unpack_b$sig;
    wire  unpack_b$is_zero;
    wire  unpack_b$is_inf;
    wire  unpack_b$is_nan;
    reg  [10:0] norm_a$x;
    wire  [10:0] norm_a$y;
    wire  [4:0] norm_a$lz;
    reg  [10:0] norm_b$x;
    wire  [10:0] norm_b$y;
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
    reg  [10:0] s1_sig_a$d;
    wire  [10:0] s1_sig_a$q;
    reg  s1_sig_a$clock;
    reg  [10:0] s1_sig_b$d;
    wire  [10:0] s1_sig_b$q;
    reg  s1_sig_b$clock;
    reg  [10:0] sig_mul$a;
    reg  [10:0] sig_mul$b;
    wire  [12:0] sig_mul$hi;
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
    reg  [12:0] s2_hi$d;
    wire  [12:0] s2_hi$q;
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
    reg  [12:0] s3_nm$d;
    wire  [12:0] s3_nm$q;
    reg  s3_nm$clock;
    reg  round$round_up;
    reg  round$sign;
    reg  round$nan;
    reg  round$inf;
    reg  round$zero;
    reg  round$ovf;
    reg  [7:0] round$efield;
    reg  [12:0] round$nm;
    wire  [18:0] round$y;
    reg  s4_valid$d;
    wire  s4_valid$q;
    reg  s4_valid$clock;
    reg  [18:0] s4_y$d;
    wire  [18:0] s4_y$q;
    reg  s4_y$clock;
    
    // Local signals
    reg  [9:0] c1_exp;
    reg  c3_top;
    reg  [12:0] c3_nm;
    reg  [9:0] c3_exp;
    reg  [9:0] c3_shift;
    reg  [9:0] c3_shift_cap;
    reg  [12:0] c3_shifted;
    reg  [12:0] c3_back;
    reg  c3_lost;
    reg  [7:0] c3_efield;
    
    // Sub module instances
    top$aerr$unpack_a unpack_a(
        .x(unpack_a$x),
        .sign(unpack_a$sign),
        .exp(unpack_a$exp),
        .sig(unpack_a$sig),
        .is_zero(unpack_a$is_zero),
        .is_inf(unpack_a$is_inf),
        .is_nan(unpack_a$is_nan)
    );
    top$aerr$unpack_a unpack_b(
        .x(unpack_b$x),
        .sign(unpack_b$sign),
        .exp(unpack_b$exp),
        .sig(unpack_b$sig),
        .is_zero(unpack_b$is_zero),
        .is_inf(unpack_b$is_inf),
        .is_nan(unpack_b$is_nan)
    );
    top$af$norm_a norm_a(
        .x(norm_a$x),
        .y(norm_a$y),
        .lz(norm_a$lz)
    );
    top$af$norm_a norm_b(
        .x(norm_b$x),
        .y(norm_b$y),
        .lz(norm_b$lz)
    );
    top$aerr$s1_eff_sub s1_valid(
        .d(s1_valid$d),
        .q(s1_valid$q),
        .clock(s1_valid$clock)
    );
    top$aerr$s1_eff_sub s1_sign(
        .d(s1_sign$d),
        .q(s1_sign$q),
        .clock(s1_sign$clock)
    );
    top$aerr$s1_eff_sub s1_nan(
        .d(s1_nan$d),
        .q(s1_nan$q),
        .clock(s1_nan$clock)
    );
    top$aerr$s1_eff_sub s1_inf(
        .d(s1_inf$d),
        .q(s1_inf$q),
        .clock(s1_inf$clock)
    );
    top$aerr$s1_eff_sub s1_zero(
        .d(s1_zero$d),
        .q(s1_zero$q),
        .clock(s1_zero$clock)
    );
    top$af$s1_exp s1_exp(
        .d(s1_exp$d),
        .q(s1_exp$q),
        .clock(s1_exp$clock)
    );
    top$af$s1_sig_a s1_sig_a(
        .d(s1_sig_a$d),
        .q(s1_sig_a$q),
        .clock(s1_sig_a$clock)
    );
    top$af$s1_sig_a s1_sig_b(
        .d(s1_sig_b$d),
        .q(s1_sig_b$q),
        .clock(s1_sig_b$clock)
    );
    top$af$sig_mul sig_mul(
        .a(sig_mul$a),
        .b(sig_mul$b),
        .hi(sig_mul$hi),
        .sticky(sig_mul$sticky)
    );
    top$aerr$s1_eff_sub s2_valid(
        .d(s2_valid$d),
        .q(s2_valid$q),
        .clock(s2_valid$clock)
    );
    top$aerr$s1_eff_sub s2_sign(
        .d(s2_sign$d),
        .q(s2_sign$q),
        .clock(s2_sign$clock)
    );
    top$aerr$s1_eff_sub s2_nan(
        .d(s2_nan$d),
        .q(s2_nan$q),
        .clock(s2_nan$clock)
    );
    top$aerr$s1_eff_sub s2_inf(
        .d(s2_inf$d),
        .q(s2_inf$q),
        .clock(s2_inf$clock)
    );
    top$aerr$s1_eff_sub s2_zero(
        .d(s2_zero$d),
        .q(s2_zero$q),
        .clock(s2_zero$clock)
    );
    top$af$s1_exp s2_exp(
        .d(s2_exp$d),
        .q(s2_exp$q),
        .clock(s2_exp$clock)
    );
    top$aerr$s2_nm s2_hi(
        .d(s2_hi$d),
        .q(s2_hi$q),
        .clock(s2_hi$clock)
    );
    top$aerr$s1_eff_sub s2_sticky(
        .d(s2_sticky$d),
        .q(s2_sticky$q),
        .clock(s2_sticky$clock)
    );
    top$aerr$s1_eff_sub s3_valid(
        .d(s3_valid$d),
        .q(s3_valid$q),
        .clock(s3_valid$clock)
    );
    top$aerr$s1_eff_sub s3_sign(
        .d(s3_sign$d),
        .q(s3_sign$q),
        .clock(s3_sign$clock)
    );
    top$aerr$s1_eff_sub s3_nan(
        .d(s3_nan$d),
        .q(s3_nan$q),
        .clock(s3_nan$clock)
    );
    top$aerr$s1_eff_sub s3_inf(
        .d(s3_inf$d),
        .q(s3_inf$q),
        .clock(s3_inf$clock)
    );
    top$aerr$s1_eff_sub s3_zero(
        .d(s3_zero$d),
        .q(s3_zero$q),
        .clock(s3_zero$clock)
    );
    top$aerr$s1_eff_sub s3_ovf(
        .d(s3_ovf$d),
        .q(s3_ovf$q),
        .clock(s3_ovf$clock)
    );
    top$aerr$s1_exp s3_efield(
        .d(s3_efield$d),
        .q(s3_efield$q),
        .clock(s3_efield$clock)
    );
    top$aerr$s2_nm s3_nm(
        .d(s3_nm$d),
        .q(s3_nm$q),
        .clock(s3_nm$clock)
    );
    top$aerr$round round(
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
    top$aerr$s1_eff_sub s4_valid(
        .d(s4_valid$d),
        .q(s4_valid$q),
        .clock(s4_valid$clock)
    );
    top$aerr$s3_y s4_y(
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
        c3_top = s2_hi$q[32'hb + 32'h1];
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
    
endmodule // top$edges$0$px_qz


module top$edges$0$pz_sgn_wait(clock,d,q);
    
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
    top$edges$0$a_sgn_wait$line$0 line$0(
        .d(line$0$d),
        .q(line$0$q),
        .clock(line$0$clock)
    );
    top$edges$0$a_sgn_wait$line$0 line$1(
        .d(line$1$d),
        .q(line$1$q),
        .clock(line$1$clock)
    );
    top$edges$0$a_sgn_wait$line$0 line$2(
        .d(line$2$d),
        .q(line$2$q),
        .clock(line$2$clock)
    );
    top$edges$0$a_sgn_wait$line$0 line$3(
        .d(line$3$d),
        .q(line$3$q),
        .clock(line$3$clock)
    );
    top$edges$0$a_sgn_wait$line$0 line$4(
        .d(line$4$d),
        .q(line$4$q),
        .clock(line$4$clock)
    );
    top$edges$0$a_sgn_wait$line$0 line$5(
        .d(line$5$d),
        .q(line$5$q),
        .clock(line$5$clock)
    );
    top$edges$0$a_sgn_wait$line$0 line$6(
        .d(line$6$d),
        .q(line$6$q),
        .clock(line$6$clock)
    );
    top$edges$0$a_sgn_wait$line$0 line$7(
        .d(line$7$d),
        .q(line$7$q),
        .clock(line$7$clock)
    );
    top$edges$0$a_sgn_wait$line$0 line$8(
        .d(line$8$d),
        .q(line$8$q),
        .clock(line$8$clock)
    );
    top$edges$0$a_sgn_wait$line$0 line$9(
        .d(line$9$d),
        .q(line$9$q),
        .clock(line$9$clock)
    );
    top$edges$0$a_sgn_wait$line$0 line$10(
        .d(line$10$d),
        .q(line$10$q),
        .clock(line$10$clock)
    );
    top$edges$0$a_sgn_wait$line$0 line$11(
        .d(line$11$d),
        .q(line$11$q),
        .clock(line$11$clock)
    );
    top$edges$0$a_sgn_wait$line$0 line$12(
        .d(line$12$d),
        .q(line$12$q),
        .clock(line$12$clock)
    );
    top$edges$0$a_sgn_wait$line$0 line$13(
        .d(line$13$d),
        .q(line$13$q),
        .clock(line$13$clock)
    );
    top$edges$0$a_sgn_wait$line$0 line$14(
        .d(line$14$d),
        .q(line$14$q),
        .clock(line$14$clock)
    );
    top$edges$0$a_sgn_wait$line$0 line$15(
        .d(line$15$d),
        .q(line$15$q),
        .clock(line$15$clock)
    );
    top$edges$0$a_sgn_wait$line$0 line$16(
        .d(line$16$d),
        .q(line$16$q),
        .clock(line$16$clock)
    );
    top$edges$0$a_sgn_wait$line$0 line$17(
        .d(line$17$d),
        .q(line$17$q),
        .clock(line$17$clock)
    );
    top$edges$0$a_sgn_wait$line$0 line$18(
        .d(line$18$d),
        .q(line$18$q),
        .clock(line$18$clock)
    );
    top$edges$0$a_sgn_wait$line$0 line$19(
        .d(line$19$d),
        .q(line$19$q),
        .clock(line$19$clock)
    );
    top$edges$0$a_sgn_wait$line$0 line$20(
        .d(line$20$d),
        .q(line$20$q),
        .clock(line$20$clock)
    );
    top$edges$0$a_sgn_wait$line$0 line$21(
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
    
endmodule // top$edges$0$pz_sgn_wait


module top$edges$0$rs(clock,a,sel,y);
    
    // Module arguments
    input wire  clock;
    input wire  [18:0] a;
    input wire  sel;
    output reg  [18:0] y;
    
    // Constant declarations
    localparam  c_k0 = 10'b11110110;
    localparam  c_k1 = 10'b11110110;
    localparam  c_sh0 = 8'h1;
    localparam  c_sh1 = 8'h1;
    localparam  c_t0 = 8'h1;
    localparam  c_t1 = 8'h1;
    localparam  c_en0 = 1'b0;
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
    top$c3_0 out(
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
    
endmodule // top$edges$0$rs


module top$edges$0$rz_sgn_wait(clock,d,q);
    
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
    top$edges$0$a_sgn_wait$line$0 line$0(
        .d(line$0$d),
        .q(line$0$q),
        .clock(line$0$clock)
    );
    top$edges$0$a_sgn_wait$line$0 line$1(
        .d(line$1$d),
        .q(line$1$q),
        .clock(line$1$clock)
    );
    top$edges$0$a_sgn_wait$line$0 line$2(
        .d(line$2$d),
        .q(line$2$q),
        .clock(line$2$clock)
    );
    top$edges$0$a_sgn_wait$line$0 line$3(
        .d(line$3$d),
        .q(line$3$q),
        .clock(line$3$clock)
    );
    top$edges$0$a_sgn_wait$line$0 line$4(
        .d(line$4$d),
        .q(line$4$q),
        .clock(line$4$clock)
    );
    top$edges$0$a_sgn_wait$line$0 line$5(
        .d(line$5$d),
        .q(line$5$q),
        .clock(line$5$clock)
    );
    top$edges$0$a_sgn_wait$line$0 line$6(
        .d(line$6$d),
        .q(line$6$q),
        .clock(line$6$clock)
    );
    top$edges$0$a_sgn_wait$line$0 line$7(
        .d(line$7$d),
        .q(line$7$q),
        .clock(line$7$clock)
    );
    top$edges$0$a_sgn_wait$line$0 line$8(
        .d(line$8$d),
        .q(line$8$q),
        .clock(line$8$clock)
    );
    top$edges$0$a_sgn_wait$line$0 line$9(
        .d(line$9$d),
        .q(line$9$q),
        .clock(line$9$clock)
    );
    top$edges$0$a_sgn_wait$line$0 line$10(
        .d(line$10$d),
        .q(line$10$q),
        .clock(line$10$clock)
    );
    top$edges$0$a_sgn_wait$line$0 line$11(
        .d(line$11$d),
        .q(line$11$q),
        .clock(line$11$clock)
    );
    top$edges$0$a_sgn_wait$line$0 line$12(
        .d(line$12$d),
        .q(line$12$q),
        .clock(line$12$clock)
    );
    top$edges$0$a_sgn_wait$line$0 line$13(
        .d(line$13$d),
        .q(line$13$q),
        .clock(line$13$clock)
    );
    top$edges$0$a_sgn_wait$line$0 line$14(
        .d(line$14$d),
        .q(line$14$q),
        .clock(line$14$clock)
    );
    top$edges$0$a_sgn_wait$line$0 line$15(
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
    
endmodule // top$edges$0$rz_sgn_wait


module top$edges$0$sign_a(x,e,sgn);
    
    // Module arguments
    input wire  [18:0] x;
    input wire  [18:0] e;
    output reg  [1:0] sgn;
    
    // Constant declarations
    localparam  c_pos = 2'b1;
    localparam  c_neg = 2'b10;
    
    // Local signals
    reg  nan;
    reg  big;
    
    // Update code
    always @(*) begin
        nan = &x[(32'ha)+:(8)] & (x[(32'h0)+:(10)] != 32'h0);
        big = ((x[(32'h0)+:(18)]) & 19'h7ffff) > e;
        sgn = 32'h0;
        if (big & ~nan) begin
            sgn = c_pos;
            if (x[32'h12]) begin
                sgn = c_neg;
            end
        end
    end
    
endmodule // top$edges$0$sign_a


module top$exact_wait(clock,d,q);
    
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
    top$aerr$s1_eff_sub line$0(
        .d(line$0$d),
        .q(line$0$q),
        .clock(line$0$clock)
    );
    top$aerr$s1_eff_sub line$1(
        .d(line$1$d),
        .q(line$1$q),
        .clock(line$1$clock)
    );
    top$aerr$s1_eff_sub line$2(
        .d(line$2$d),
        .q(line$2$q),
        .clock(line$2$clock)
    );
    top$aerr$s1_eff_sub line$3(
        .d(line$3$d),
        .q(line$3$q),
        .clock(line$3$clock)
    );
    top$aerr$s1_eff_sub line$4(
        .d(line$4$d),
        .q(line$4$q),
        .clock(line$4$clock)
    );
    top$aerr$s1_eff_sub line$5(
        .d(line$5$d),
        .q(line$5$q),
        .clock(line$5$clock)
    );
    top$aerr$s1_eff_sub line$6(
        .d(line$6$d),
        .q(line$6$q),
        .clock(line$6$clock)
    );
    top$aerr$s1_eff_sub line$7(
        .d(line$7$d),
        .q(line$7$q),
        .clock(line$7$clock)
    );
    top$aerr$s1_eff_sub line$8(
        .d(line$8$d),
        .q(line$8$q),
        .clock(line$8$clock)
    );
    top$aerr$s1_eff_sub line$9(
        .d(line$9$d),
        .q(line$9$q),
        .clock(line$9$clock)
    );
    top$aerr$s1_eff_sub line$10(
        .d(line$10$d),
        .q(line$10$q),
        .clock(line$10$clock)
    );
    top$aerr$s1_eff_sub line$11(
        .d(line$11$d),
        .q(line$11$q),
        .clock(line$11$clock)
    );
    top$aerr$s1_eff_sub line$12(
        .d(line$12$d),
        .q(line$12$q),
        .clock(line$12$clock)
    );
    top$aerr$s1_eff_sub line$13(
        .d(line$13$d),
        .q(line$13$q),
        .clock(line$13$clock)
    );
    top$aerr$s1_eff_sub line$14(
        .d(line$14$d),
        .q(line$14$q),
        .clock(line$14$clock)
    );
    top$aerr$s1_eff_sub line$15(
        .d(line$15$d),
        .q(line$15$q),
        .clock(line$15$clock)
    );
    top$aerr$s1_eff_sub line$16(
        .d(line$16$d),
        .q(line$16$q),
        .clock(line$16$clock)
    );
    top$aerr$s1_eff_sub line$17(
        .d(line$17$d),
        .q(line$17$q),
        .clock(line$17$clock)
    );
    top$aerr$s1_eff_sub line$18(
        .d(line$18$d),
        .q(line$18$q),
        .clock(line$18$clock)
    );
    top$aerr$s1_eff_sub line$19(
        .d(line$19$d),
        .q(line$19$q),
        .clock(line$19$clock)
    );
    top$aerr$s1_eff_sub line$20(
        .d(line$20$d),
        .q(line$20$q),
        .clock(line$20$clock)
    );
    top$aerr$s1_eff_sub line$21(
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
    
endmodule // top$exact_wait


module top$in_tag(d,q,clock);
    
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
          
endmodule // top$in_tag


module top$l1_wait$0(clock,d,q);
    
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
    
    // Sub module instances
    top$aerr$s3_y line$0(
        .d(line$0$d),
        .q(line$0$q),
        .clock(line$0$clock)
    );
    top$aerr$s3_y line$1(
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
    
endmodule // top$l1_wait$0


module top$mb_0$0(clock,a0,a1,a2,b0,b1,b2,c,y);
    
    // Module arguments
    input wire  clock;
    input wire  [18:0] a0;
    input wire  [18:0] a1;
    input wire  [18:0] a2;
    input wire  [18:0] b0;
    input wire  [18:0] b1;
    input wire  [18:0] b2;
    input wire  [18:0] c;
    output reg  [18:0] y;
    
    // Constant declarations
    localparam  affine = 1'b0;
    localparam  mask = 19'b1111111111111111111;
    
    // Stub signals
    reg  p$0$clock;
    reg  [18:0] p$0$a;
    reg  [18:0] p$0$b;
    reg  p$0$valid_in;
    wire  [18:0] p$0$y;
    wire  p$0$valid_out;
    reg  p$1$clock;
    reg  [18:0] p$1$a;
    reg  [18:0] p$1$b;
    reg  p$1$valid_in;
    wire  [18:0] p$1$y;
    wire  p$1$valid_out;
    reg  p$2$clock;
    reg  [18:0] p$2$a;
    reg  [18:0] p$2$b;
    reg  p$2$valid_in;
    wire  [18:0] p$2$y;
    wire  p$2$valid_out;
    reg  s01$clock;
    reg  [18:0] s01$a;
    reg  [18:0] s01$b;
    reg  s01$sub;
    reg  s01$valid_in;
    wire  [18:0] s01$y;
    wire  s01$valid_out;
    reg  s2c$clock;
    reg  [18:0] s2c$a;
    reg  [18:0] s2c$b;
    reg  s2c$sub;
    reg  s2c$valid_in;
    wire  [18:0] s2c$y;
    wire  s2c$valid_out;
    reg  s$clock;
    reg  [18:0] s$a;
    reg  [18:0] s$b;
    reg  s$sub;
    reg  s$valid_in;
    wire  [18:0] s$y;
    wire  s$valid_out;
    reg  p2_wait$clock;
    reg  [18:0] p2_wait$d;
    wire  [18:0] p2_wait$q;
    
    // Sub module instances
    top$edges$0$px_qz p$0(
        .clock(p$0$clock),
        .a(p$0$a),
        .b(p$0$b),
        .valid_in(p$0$valid_in),
        .y(p$0$y),
        .valid_out(p$0$valid_out)
    );
    top$edges$0$px_qz p$1(
        .clock(p$1$clock),
        .a(p$1$a),
        .b(p$1$b),
        .valid_in(p$1$valid_in),
        .y(p$1$y),
        .valid_out(p$1$valid_out)
    );
    top$edges$0$px_qz p$2(
        .clock(p$2$clock),
        .a(p$2$a),
        .b(p$2$b),
        .valid_in(p$2$valid_in),
        .y(p$2$y),
        .valid_out(p$2$valid_out)
    );
    top$edges$0$a s01(
        .clock(s01$clock),
        .a(s01$a),
        .b(s01$b),
        .sub(s01$sub),
        .valid_in(s01$valid_in),
        .y(s01$y),
        .valid_out(s01$valid_out)
    );
    top$edges$0$a s2c(
        .clock(s2c$clock),
        .a(s2c$a),
        .b(s2c$b),
        .sub(s2c$sub),
        .valid_in(s2c$valid_in),
        .y(s2c$y),
        .valid_out(s2c$valid_out)
    );
    top$edges$0$a s(
        .clock(s$clock),
        .a(s$a),
        .b(s$b),
        .sub(s$sub),
        .valid_in(s$valid_in),
        .y(s$y),
        .valid_out(s$valid_out)
    );
    top$edges$0$brs_wait p2_wait(
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
    
endmodule // top$mb_0$0


module top$mb_0$3(clock,a0,a1,a2,b0,b1,b2,c,y);
    
    // Module arguments
    input wire  clock;
    input wire  [18:0] a0;
    input wire  [18:0] a1;
    input wire  [18:0] a2;
    input wire  [18:0] b0;
    input wire  [18:0] b1;
    input wire  [18:0] b2;
    input wire  [18:0] c;
    output reg  [18:0] y;
    
    // Constant declarations
    localparam  affine = 1'b1;
    localparam  mask = 19'b1111111111111111111;
    
    // Stub signals
    reg  p$0$clock;
    reg  [18:0] p$0$a;
    reg  [18:0] p$0$b;
    reg  p$0$valid_in;
    wire  [18:0] p$0$y;
    wire  p$0$valid_out;
    reg  p$1$clock;
    reg  [18:0] p$1$a;
    reg  [18:0] p$1$b;
    reg  p$1$valid_in;
    wire  [18:0] p$1$y;
    wire  p$1$valid_out;
    reg  p$2$clock;
    reg  [18:0] p$2$a;
    reg  [18:0] p$2$b;
    reg  p$2$valid_in;
    wire  [18:0] p$2$y;
    wire  p$2$valid_out;
    reg  s01$clock;
    reg  [18:0] s01$a;
    reg  [18:0] s01$b;
    reg  s01$sub;
    reg  s01$valid_in;
    wire  [18:0] s01$y;
    wire  s01$valid_out;
    reg  s2c$clock;
    reg  [18:0] s2c$a;
    reg  [18:0] s2c$b;
    reg  s2c$sub;
    reg  s2c$valid_in;
    wire  [18:0] s2c$y;
    wire  s2c$valid_out;
    reg  s$clock;
    reg  [18:0] s$a;
    reg  [18:0] s$b;
    reg  s$sub;
    reg  s$valid_in;
    wire  [18:0] s$y;
    wire  s$valid_out;
    reg  p2_wait$clock;
    reg  [18:0] p2_wait$d;
    wire  [18:0] p2_wait$q;
    
    // Sub module instances
    top$edges$0$px_qz p$0(
        .clock(p$0$clock),
        .a(p$0$a),
        .b(p$0$b),
        .valid_in(p$0$valid_in),
        .y(p$0$y),
        .valid_out(p$0$valid_out)
    );
    top$edges$0$px_qz p$1(
        .clock(p$1$clock),
        .a(p$1$a),
        .b(p$1$b),
        .valid_in(p$1$valid_in),
        .y(p$1$y),
        .valid_out(p$1$valid_out)
    );
    top$edges$0$px_qz p$2(
        .clock(p$2$clock),
        .a(p$2$a),
        .b(p$2$b),
        .valid_in(p$2$valid_in),
        .y(p$2$y),
        .valid_out(p$2$valid_out)
    );
    top$edges$0$a s01(
        .clock(s01$clock),
        .a(s01$a),
        .b(s01$b),
        .sub(s01$sub),
        .valid_in(s01$valid_in),
        .y(s01$y),
        .valid_out(s01$valid_out)
    );
    top$edges$0$a s2c(
        .clock(s2c$clock),
        .a(s2c$a),
        .b(s2c$b),
        .sub(s2c$sub),
        .valid_in(s2c$valid_in),
        .y(s2c$y),
        .valid_out(s2c$valid_out)
    );
    top$edges$0$a s(
        .clock(s$clock),
        .a(s$a),
        .b(s$b),
        .sub(s$sub),
        .valid_in(s$valid_in),
        .y(s$y),
        .valid_out(s$valid_out)
    );
    top$edges$0$brs_wait p2_wait(
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
    
endmodule // top$mb_0$3


module top$mg_0$0(clock,a0,a1,a2,b0,b1,b2,c,y);
    
    // Module arguments
    input wire  clock;
    input wire  [18:0] a0;
    input wire  [18:0] a1;
    input wire  [18:0] a2;
    input wire  [18:0] b0;
    input wire  [18:0] b1;
    input wire  [18:0] b2;
    input wire  [18:0] c;
    output reg  [18:0] y;
    
    // Constant declarations
    localparam  affine = 1'b0;
    localparam  mask = 19'b111111111111111111;
    
    // Stub signals
    reg  p$0$clock;
    reg  [18:0] p$0$a;
    reg  [18:0] p$0$b;
    reg  p$0$valid_in;
    wire  [18:0] p$0$y;
    wire  p$0$valid_out;
    reg  p$1$clock;
    reg  [18:0] p$1$a;
    reg  [18:0] p$1$b;
    reg  p$1$valid_in;
    wire  [18:0] p$1$y;
    wire  p$1$valid_out;
    reg  p$2$clock;
    reg  [18:0] p$2$a;
    reg  [18:0] p$2$b;
    reg  p$2$valid_in;
    wire  [18:0] p$2$y;
    wire  p$2$valid_out;
    reg  s01$clock;
    reg  [18:0] s01$a;
    reg  [18:0] s01$b;
    reg  s01$sub;
    reg  s01$valid_in;
    wire  [18:0] s01$y;
    wire  s01$valid_out;
    reg  s2c$clock;
    reg  [18:0] s2c$a;
    reg  [18:0] s2c$b;
    reg  s2c$sub;
    reg  s2c$valid_in;
    wire  [18:0] s2c$y;
    wire  s2c$valid_out;
    reg  s$clock;
    reg  [18:0] s$a;
    reg  [18:0] s$b;
    reg  s$sub;
    reg  s$valid_in;
    wire  [18:0] s$y;
    wire  s$valid_out;
    reg  p2_wait$clock;
    reg  [18:0] p2_wait$d;
    wire  [18:0] p2_wait$q;
    
    // Sub module instances
    top$af p$0(
        .clock(p$0$clock),
        .a(p$0$a),
        .b(p$0$b),
        .valid_in(p$0$valid_in),
        .y(p$0$y),
        .valid_out(p$0$valid_out)
    );
    top$af p$1(
        .clock(p$1$clock),
        .a(p$1$a),
        .b(p$1$b),
        .valid_in(p$1$valid_in),
        .y(p$1$y),
        .valid_out(p$1$valid_out)
    );
    top$af p$2(
        .clock(p$2$clock),
        .a(p$2$a),
        .b(p$2$b),
        .valid_in(p$2$valid_in),
        .y(p$2$y),
        .valid_out(p$2$valid_out)
    );
    top$aerr s01(
        .clock(s01$clock),
        .a(s01$a),
        .b(s01$b),
        .sub(s01$sub),
        .valid_in(s01$valid_in),
        .y(s01$y),
        .valid_out(s01$valid_out)
    );
    top$aerr s2c(
        .clock(s2c$clock),
        .a(s2c$a),
        .b(s2c$b),
        .sub(s2c$sub),
        .valid_in(s2c$valid_in),
        .y(s2c$y),
        .valid_out(s2c$valid_out)
    );
    top$aerr s(
        .clock(s$clock),
        .a(s$a),
        .b(s$b),
        .sub(s$sub),
        .valid_in(s$valid_in),
        .y(s$y),
        .valid_out(s$valid_out)
    );
    top$edges$0$brs_wait p2_wait(
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
    
endmodule // top$mg_0$0


module top$mg_0$3(clock,a0,a1,a2,b0,b1,b2,c,y);
    
    // Module arguments
    input wire  clock;
    input wire  [18:0] a0;
    input wire  [18:0] a1;
    input wire  [18:0] a2;
    input wire  [18:0] b0;
    input wire  [18:0] b1;
    input wire  [18:0] b2;
    input wire  [18:0] c;
    output reg  [18:0] y;
    
    // Constant declarations
    localparam  affine = 1'b1;
    localparam  mask = 19'b111111111111111111;
    
    // Stub signals
    reg  p$0$clock;
    reg  [18:0] p$0$a;
    reg  [18:0] p$0$b;
    reg  p$0$valid_in;
    wire  [18:0] p$0$y;
    wire  p$0$valid_out;
    reg  p$1$clock;
    reg  [18:0] p$1$a;
    reg  [18:0] p$1$b;
    reg  p$1$valid_in;
    wire  [18:0] p$1$y;
    wire  p$1$valid_out;
    reg  p$2$clock;
    reg  [18:0] p$2$a;
    reg  [18:0] p$2$b;
    reg  p$2$valid_in;
    wire  [18:0] p$2$y;
    wire  p$2$valid_out;
    reg  s01$clock;
    reg  [18:0] s01$a;
    reg  [18:0] s01$b;
    reg  s01$sub;
    reg  s01$valid_in;
    wire  [18:0] s01$y;
    wire  s01$valid_out;
    reg  s2c$clock;
    reg  [18:0] s2c$a;
    reg  [18:0] s2c$b;
    reg  s2c$sub;
    reg  s2c$valid_in;
    wire  [18:0] s2c$y;
    wire  s2c$valid_out;
    reg  s$clock;
    reg  [18:0] s$a;
    reg  [18:0] s$b;
    reg  s$sub;
    reg  s$valid_in;
    wire  [18:0] s$y;
    wire  s$valid_out;
    reg  p2_wait$clock;
    reg  [18:0] p2_wait$d;
    wire  [18:0] p2_wait$q;
    
    // Sub module instances
    top$af p$0(
        .clock(p$0$clock),
        .a(p$0$a),
        .b(p$0$b),
        .valid_in(p$0$valid_in),
        .y(p$0$y),
        .valid_out(p$0$valid_out)
    );
    top$af p$1(
        .clock(p$1$clock),
        .a(p$1$a),
        .b(p$1$b),
        .valid_in(p$1$valid_in),
        .y(p$1$y),
        .valid_out(p$1$valid_out)
    );
    top$af p$2(
        .clock(p$2$clock),
        .a(p$2$a),
        .b(p$2$b),
        .valid_in(p$2$valid_in),
        .y(p$2$y),
        .valid_out(p$2$valid_out)
    );
    top$aerr s01(
        .clock(s01$clock),
        .a(s01$a),
        .b(s01$b),
        .sub(s01$sub),
        .valid_in(s01$valid_in),
        .y(s01$y),
        .valid_out(s01$valid_out)
    );
    top$aerr s2c(
        .clock(s2c$clock),
        .a(s2c$a),
        .b(s2c$b),
        .sub(s2c$sub),
        .valid_in(s2c$valid_in),
        .y(s2c$y),
        .valid_out(s2c$valid_out)
    );
    top$aerr s(
        .clock(s$clock),
        .a(s$a),
        .b(s$b),
        .sub(s$sub),
        .valid_in(s$valid_in),
        .y(s$y),
        .valid_out(s$valid_out)
    );
    top$edges$0$brs_wait p2_wait(
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
    
endmodule // top$mg_0$3


module top$tag_wait(clock,d,q);
    
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
    top$in_tag line$0(
        .d(line$0$d),
        .q(line$0$q),
        .clock(line$0$clock)
    );
    top$in_tag line$1(
        .d(line$1$d),
        .q(line$1$q),
        .clock(line$1$clock)
    );
    top$in_tag line$2(
        .d(line$2$d),
        .q(line$2$q),
        .clock(line$2$clock)
    );
    top$in_tag line$3(
        .d(line$3$d),
        .q(line$3$q),
        .clock(line$3$clock)
    );
    top$in_tag line$4(
        .d(line$4$d),
        .q(line$4$q),
        .clock(line$4$clock)
    );
    top$in_tag line$5(
        .d(line$5$d),
        .q(line$5$q),
        .clock(line$5$clock)
    );
    top$in_tag line$6(
        .d(line$6$d),
        .q(line$6$q),
        .clock(line$6$clock)
    );
    top$in_tag line$7(
        .d(line$7$d),
        .q(line$7$q),
        .clock(line$7$clock)
    );
    top$in_tag line$8(
        .d(line$8$d),
        .q(line$8$q),
        .clock(line$8$clock)
    );
    top$in_tag line$9(
        .d(line$9$d),
        .q(line$9$q),
        .clock(line$9$clock)
    );
    top$in_tag line$10(
        .d(line$10$d),
        .q(line$10$q),
        .clock(line$10$clock)
    );
    top$in_tag line$11(
        .d(line$11$d),
        .q(line$11$q),
        .clock(line$11$clock)
    );
    top$in_tag line$12(
        .d(line$12$d),
        .q(line$12$q),
        .clock(line$12$clock)
    );
    top$in_tag line$13(
        .d(line$13$d),
        .q(line$13$q),
        .clock(line$13$clock)
    );
    top$in_tag line$14(
        .d(line$14$d),
        .q(line$14$q),
        .clock(line$14$clock)
    );
    top$in_tag line$15(
        .d(line$15$d),
        .q(line$15$q),
        .clock(line$15$clock)
    );
    top$in_tag line$16(
        .d(line$16$d),
        .q(line$16$q),
        .clock(line$16$clock)
    );
    top$in_tag line$17(
        .d(line$17$d),
        .q(line$17$q),
        .clock(line$17$clock)
    );
    top$in_tag line$18(
        .d(line$18$d),
        .q(line$18$q),
        .clock(line$18$clock)
    );
    top$in_tag line$19(
        .d(line$19$d),
        .q(line$19$q),
        .clock(line$19$clock)
    );
    top$in_tag line$20(
        .d(line$20$d),
        .q(line$20$q),
        .clock(line$20$clock)
    );
    top$in_tag line$21(
        .d(line$21$d),
        .q(line$21$q),
        .clock(line$21$clock)
    );
    top$in_tag line$22(
        .d(line$22$d),
        .q(line$22$q),
        .clock(line$22$clock)
    );
    top$in_tag line$23(
        .d(line$23$d),
        .q(line$23$q),
        .clock(line$23$clock)
    );
    top$in_tag line$24(
        .d(line$24$d),
        .q(line$24$q),
        .clock(line$24$clock)
    );
    top$in_tag line$25(
        .d(line$25$d),
        .q(line$25$q),
        .clock(line$25$clock)
    );
    top$in_tag line$26(
        .d(line$26$d),
        .q(line$26$q),
        .clock(line$26$clock)
    );
    top$in_tag line$27(
        .d(line$27$d),
        .q(line$27$q),
        .clock(line$27$clock)
    );
    top$in_tag line$28(
        .d(line$28$d),
        .q(line$28$q),
        .clock(line$28$clock)
    );
    top$in_tag line$29(
        .d(line$29$d),
        .q(line$29$q),
        .clock(line$29$clock)
    );
    top$in_tag line$30(
        .d(line$30$d),
        .q(line$30$q),
        .clock(line$30$clock)
    );
    top$in_tag line$31(
        .d(line$31$d),
        .q(line$31$q),
        .clock(line$31$clock)
    );
    top$in_tag line$32(
        .d(line$32$d),
        .q(line$32$q),
        .clock(line$32$clock)
    );
    top$in_tag line$33(
        .d(line$33$d),
        .q(line$33$q),
        .clock(line$33$clock)
    );
    top$in_tag line$34(
        .d(line$34$d),
        .q(line$34$q),
        .clock(line$34$clock)
    );
    top$in_tag line$35(
        .d(line$35$d),
        .q(line$35$q),
        .clock(line$35$clock)
    );
    top$in_tag line$36(
        .d(line$36$d),
        .q(line$36$q),
        .clock(line$36$clock)
    );
    top$in_tag line$37(
        .d(line$37$d),
        .q(line$37$q),
        .clock(line$37$clock)
    );
    top$in_tag line$38(
        .d(line$38$d),
        .q(line$38$q),
        .clock(line$38$clock)
    );
    top$in_tag line$39(
        .d(line$39$d),
        .q(line$39$q),
        .clock(line$39$clock)
    );
    top$in_tag line$40(
        .d(line$40$d),
        .q(line$40$q),
        .clock(line$40$clock)
    );
    top$in_tag line$41(
        .d(line$41$d),
        .q(line$41$q),
        .clock(line$41$clock)
    );
    top$in_tag line$42(
        .d(line$42$d),
        .q(line$42$q),
        .clock(line$42$clock)
    );
    top$in_tag line$43(
        .d(line$43$d),
        .q(line$43$q),
        .clock(line$43$clock)
    );
    top$in_tag line$44(
        .d(line$44$d),
        .q(line$44$q),
        .clock(line$44$clock)
    );
    top$in_tag line$45(
        .d(line$45$d),
        .q(line$45$q),
        .clock(line$45$clock)
    );
    top$in_tag line$46(
        .d(line$46$d),
        .q(line$46$q),
        .clock(line$46$clock)
    );
    top$in_tag line$47(
        .d(line$47$d),
        .q(line$47$q),
        .clock(line$47$clock)
    );
    top$in_tag line$48(
        .d(line$48$d),
        .q(line$48$q),
        .clock(line$48$clock)
    );
    top$in_tag line$49(
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
    
endmodule // top$tag_wait


module top$v_x_wait$0(clock,d,q);
    
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
    reg  [18:0] line$4$d;
    wire  [18:0] line$4$q;
    reg  line$4$clock;
    reg  [18:0] line$5$d;
    wire  [18:0] line$5$q;
    reg  line$5$clock;
    reg  [18:0] line$6$d;
    wire  [18:0] line$6$q;
    reg  line$6$clock;
    reg  [18:0] line$7$d;
    wire  [18:0] line$7$q;
    reg  line$7$clock;
    reg  [18:0] line$8$d;
    wire  [18:0] line$8$q;
    reg  line$8$clock;
    reg  [18:0] line$9$d;
    wire  [18:0] line$9$q;
    reg  line$9$clock;
    reg  [18:0] line$10$d;
    wire  [18:0] line$10$q;
    reg  line$10$clock;
    
    // Sub module instances
    top$aerr$s3_y line$0(
        .d(line$0$d),
        .q(line$0$q),
        .clock(line$0$clock)
    );
    top$aerr$s3_y line$1(
        .d(line$1$d),
        .q(line$1$q),
        .clock(line$1$clock)
    );
    top$aerr$s3_y line$2(
        .d(line$2$d),
        .q(line$2$q),
        .clock(line$2$clock)
    );
    top$aerr$s3_y line$3(
        .d(line$3$d),
        .q(line$3$q),
        .clock(line$3$clock)
    );
    top$aerr$s3_y line$4(
        .d(line$4$d),
        .q(line$4$q),
        .clock(line$4$clock)
    );
    top$aerr$s3_y line$5(
        .d(line$5$d),
        .q(line$5$q),
        .clock(line$5$clock)
    );
    top$aerr$s3_y line$6(
        .d(line$6$d),
        .q(line$6$q),
        .clock(line$6$clock)
    );
    top$aerr$s3_y line$7(
        .d(line$7$d),
        .q(line$7$q),
        .clock(line$7$clock)
    );
    top$aerr$s3_y line$8(
        .d(line$8$d),
        .q(line$8$q),
        .clock(line$8$clock)
    );
    top$aerr$s3_y line$9(
        .d(line$9$d),
        .q(line$9$q),
        .clock(line$9$clock)
    );
    top$aerr$s3_y line$10(
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
    
endmodule // top$v_x_wait$0


module top$valid_wait(clock,d,q);
    
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
    top$aerr$s1_eff_sub line$0(
        .d(line$0$d),
        .q(line$0$q),
        .clock(line$0$clock)
    );
    top$aerr$s1_eff_sub line$1(
        .d(line$1$d),
        .q(line$1$q),
        .clock(line$1$clock)
    );
    top$aerr$s1_eff_sub line$2(
        .d(line$2$d),
        .q(line$2$q),
        .clock(line$2$clock)
    );
    top$aerr$s1_eff_sub line$3(
        .d(line$3$d),
        .q(line$3$q),
        .clock(line$3$clock)
    );
    top$aerr$s1_eff_sub line$4(
        .d(line$4$d),
        .q(line$4$q),
        .clock(line$4$clock)
    );
    top$aerr$s1_eff_sub line$5(
        .d(line$5$d),
        .q(line$5$q),
        .clock(line$5$clock)
    );
    top$aerr$s1_eff_sub line$6(
        .d(line$6$d),
        .q(line$6$q),
        .clock(line$6$clock)
    );
    top$aerr$s1_eff_sub line$7(
        .d(line$7$d),
        .q(line$7$q),
        .clock(line$7$clock)
    );
    top$aerr$s1_eff_sub line$8(
        .d(line$8$d),
        .q(line$8$q),
        .clock(line$8$clock)
    );
    top$aerr$s1_eff_sub line$9(
        .d(line$9$d),
        .q(line$9$q),
        .clock(line$9$clock)
    );
    top$aerr$s1_eff_sub line$10(
        .d(line$10$d),
        .q(line$10$q),
        .clock(line$10$clock)
    );
    top$aerr$s1_eff_sub line$11(
        .d(line$11$d),
        .q(line$11$q),
        .clock(line$11$clock)
    );
    top$aerr$s1_eff_sub line$12(
        .d(line$12$d),
        .q(line$12$q),
        .clock(line$12$clock)
    );
    top$aerr$s1_eff_sub line$13(
        .d(line$13$d),
        .q(line$13$q),
        .clock(line$13$clock)
    );
    top$aerr$s1_eff_sub line$14(
        .d(line$14$d),
        .q(line$14$q),
        .clock(line$14$clock)
    );
    top$aerr$s1_eff_sub line$15(
        .d(line$15$d),
        .q(line$15$q),
        .clock(line$15$clock)
    );
    top$aerr$s1_eff_sub line$16(
        .d(line$16$d),
        .q(line$16$q),
        .clock(line$16$clock)
    );
    top$aerr$s1_eff_sub line$17(
        .d(line$17$d),
        .q(line$17$q),
        .clock(line$17$clock)
    );
    top$aerr$s1_eff_sub line$18(
        .d(line$18$d),
        .q(line$18$q),
        .clock(line$18$clock)
    );
    top$aerr$s1_eff_sub line$19(
        .d(line$19$d),
        .q(line$19$q),
        .clock(line$19$clock)
    );
    top$aerr$s1_eff_sub line$20(
        .d(line$20$d),
        .q(line$20$q),
        .clock(line$20$clock)
    );
    top$aerr$s1_eff_sub line$21(
        .d(line$21$d),
        .q(line$21$q),
        .clock(line$21$clock)
    );
    top$aerr$s1_eff_sub line$22(
        .d(line$22$d),
        .q(line$22$q),
        .clock(line$22$clock)
    );
    top$aerr$s1_eff_sub line$23(
        .d(line$23$d),
        .q(line$23$q),
        .clock(line$23$clock)
    );
    top$aerr$s1_eff_sub line$24(
        .d(line$24$d),
        .q(line$24$q),
        .clock(line$24$clock)
    );
    top$aerr$s1_eff_sub line$25(
        .d(line$25$d),
        .q(line$25$q),
        .clock(line$25$clock)
    );
    top$aerr$s1_eff_sub line$26(
        .d(line$26$d),
        .q(line$26$q),
        .clock(line$26$clock)
    );
    top$aerr$s1_eff_sub line$27(
        .d(line$27$d),
        .q(line$27$q),
        .clock(line$27$clock)
    );
    top$aerr$s1_eff_sub line$28(
        .d(line$28$d),
        .q(line$28$q),
        .clock(line$28$clock)
    );
    top$aerr$s1_eff_sub line$29(
        .d(line$29$d),
        .q(line$29$q),
        .clock(line$29$clock)
    );
    top$aerr$s1_eff_sub line$30(
        .d(line$30$d),
        .q(line$30$q),
        .clock(line$30$clock)
    );
    top$aerr$s1_eff_sub line$31(
        .d(line$31$d),
        .q(line$31$q),
        .clock(line$31$clock)
    );
    top$aerr$s1_eff_sub line$32(
        .d(line$32$d),
        .q(line$32$q),
        .clock(line$32$clock)
    );
    top$aerr$s1_eff_sub line$33(
        .d(line$33$d),
        .q(line$33$q),
        .clock(line$33$clock)
    );
    top$aerr$s1_eff_sub line$34(
        .d(line$34$d),
        .q(line$34$q),
        .clock(line$34$clock)
    );
    top$aerr$s1_eff_sub line$35(
        .d(line$35$d),
        .q(line$35$q),
        .clock(line$35$clock)
    );
    top$aerr$s1_eff_sub line$36(
        .d(line$36$d),
        .q(line$36$q),
        .clock(line$36$clock)
    );
    top$aerr$s1_eff_sub line$37(
        .d(line$37$d),
        .q(line$37$q),
        .clock(line$37$clock)
    );
    top$aerr$s1_eff_sub line$38(
        .d(line$38$d),
        .q(line$38$q),
        .clock(line$38$clock)
    );
    top$aerr$s1_eff_sub line$39(
        .d(line$39$d),
        .q(line$39$q),
        .clock(line$39$clock)
    );
    top$aerr$s1_eff_sub line$40(
        .d(line$40$d),
        .q(line$40$q),
        .clock(line$40$clock)
    );
    top$aerr$s1_eff_sub line$41(
        .d(line$41$d),
        .q(line$41$q),
        .clock(line$41$clock)
    );
    top$aerr$s1_eff_sub line$42(
        .d(line$42$d),
        .q(line$42$q),
        .clock(line$42$clock)
    );
    top$aerr$s1_eff_sub line$43(
        .d(line$43$d),
        .q(line$43$q),
        .clock(line$43$clock)
    );
    top$aerr$s1_eff_sub line$44(
        .d(line$44$d),
        .q(line$44$q),
        .clock(line$44$clock)
    );
    top$aerr$s1_eff_sub line$45(
        .d(line$45$d),
        .q(line$45$q),
        .clock(line$45$clock)
    );
    top$aerr$s1_eff_sub line$46(
        .d(line$46$d),
        .q(line$46$q),
        .clock(line$46$clock)
    );
    top$aerr$s1_eff_sub line$47(
        .d(line$47$d),
        .q(line$47$q),
        .clock(line$47$clock)
    );
    top$aerr$s1_eff_sub line$48(
        .d(line$48$d),
        .q(line$48$q),
        .clock(line$48$clock)
    );
    top$aerr$s1_eff_sub line$49(
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
    
endmodule // top$valid_wait


module top$verts$0(clock,z,m0,m1,m2,exact,e,g,f0,f1,f2,h);
    
    // Module arguments
    input wire  clock;
    input wire  [18:0] z;
    input wire  [18:0] m0;
    input wire  [18:0] m1;
    input wire  [18:0] m2;
    input wire  exact;
    output reg  [18:0] e;
    output reg  [18:0] g;
    output reg  [18:0] f0;
    output reg  [18:0] f1;
    output reg  [18:0] f2;
    output reg  [18:0] h;
    
    // Constant declarations
    localparam  mask = 19'b111111111111111111;
    localparam  c_one = 19'b10000000000;
    
    // Stub signals
    reg  ef$0$clock;
    reg  [18:0] ef$0$a;
    reg  ef$0$sel;
    wire  [18:0] ef$0$y;
    reg  ef$1$clock;
    reg  [18:0] ef$1$a;
    reg  ef$1$sel;
    wire  [18:0] ef$1$y;
    reg  ef$2$clock;
    reg  [18:0] ef$2$a;
    reg  ef$2$sel;
    wire  [18:0] ef$2$y;
    reg  ez$clock;
    reg  [18:0] ez$a;
    reg  ez$sel;
    wire  [18:0] ez$y;
    reg  cz$clock;
    reg  [18:0] cz$a;
    reg  cz$sel;
    wire  [18:0] cz$y;
    reg  gz$clock;
    reg  [18:0] gz$a;
    reg  [18:0] gz$b;
    reg  gz$sub;
    reg  gz$valid_in;
    wire  [18:0] gz$y;
    wire  gz$valid_out;
    reg  hz$clock;
    reg  [18:0] hz$a;
    reg  [18:0] hz$b;
    reg  hz$sub;
    reg  hz$valid_in;
    wire  [18:0] hz$y;
    wire  hz$valid_out;
    reg  f_wait$0$clock;
    reg  [18:0] f_wait$0$d;
    wire  [18:0] f_wait$0$q;
    reg  f_wait$1$clock;
    reg  [18:0] f_wait$1$d;
    wire  [18:0] f_wait$1$q;
    reg  f_wait$2$clock;
    reg  [18:0] f_wait$2$d;
    wire  [18:0] f_wait$2$q;
    reg  z_wait$clock;
    reg  [18:0] z_wait$d;
    wire  [18:0] z_wait$q;
    reg  h_wait$clock;
    reg  [18:0] h_wait$d;
    wire  [18:0] h_wait$q;
    
    // Local signals
    reg  [18:0] e2z;
    
    // Sub module instances
    top$verts$0$ef$0 ef$0(
        .clock(ef$0$clock),
        .a(ef$0$a),
        .sel(ef$0$sel),
        .y(ef$0$y)
    );
    top$verts$0$ef$0 ef$1(
        .clock(ef$1$clock),
        .a(ef$1$a),
        .sel(ef$1$sel),
        .y(ef$1$y)
    );
    top$verts$0$ef$2 ef$2(
        .clock(ef$2$clock),
        .a(ef$2$a),
        .sel(ef$2$sel),
        .y(ef$2$y)
    );
    top$verts$0$ef$0 ez(
        .clock(ez$clock),
        .a(ez$a),
        .sel(ez$sel),
        .y(ez$y)
    );
    top$edges$0$rs cz(
        .clock(cz$clock),
        .a(cz$a),
        .sel(cz$sel),
        .y(cz$y)
    );
    top$aerr gz(
        .clock(gz$clock),
        .a(gz$a),
        .b(gz$b),
        .sub(gz$sub),
        .valid_in(gz$valid_in),
        .y(gz$y),
        .valid_out(gz$valid_out)
    );
    top$aerr hz(
        .clock(hz$clock),
        .a(hz$a),
        .b(hz$b),
        .sub(hz$sub),
        .valid_in(hz$valid_in),
        .y(hz$y),
        .valid_out(hz$valid_out)
    );
    top$edges$0$brs_wait f_wait$0(
        .clock(f_wait$0$clock),
        .d(f_wait$0$d),
        .q(f_wait$0$q)
    );
    top$edges$0$brs_wait f_wait$1(
        .clock(f_wait$1$clock),
        .d(f_wait$1$d),
        .q(f_wait$1$q)
    );
    top$edges$0$brs_wait f_wait$2(
        .clock(f_wait$2$clock),
        .d(f_wait$2$d),
        .q(f_wait$2$q)
    );
    top$c3_0 z_wait(
        .clock(z_wait$clock),
        .d(z_wait$d),
        .q(z_wait$q)
    );
    top$edges$0$brs_wait h_wait(
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
        if ((ez$y[(32'ha)+:(8)] != 32'h0) & ~&ez$y[(32'ha)+:(8)]) begin
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
    
endmodule // top$verts$0


module top$verts$0$ef$0(clock,a,sel,y);
    
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
    top$c3_0 out(
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
    
endmodule // top$verts$0$ef$0


module top$verts$0$ef$2(clock,a,sel,y);
    
    // Module arguments
    input wire  clock;
    input wire  [18:0] a;
    input wire  sel;
    output reg  [18:0] y;
    
    // Constant declarations
    localparam  c_k0 = 10'b11111000;
    localparam  c_k1 = 10'b11111000;
    localparam  c_sh0 = 8'ha;
    localparam  c_sh1 = 8'h9;
    localparam  c_t0 = 8'h1;
    localparam  c_t1 = 8'h1;
    localparam  c_en0 = 1'b1;
    localparam  c_en1 = 1'b1;
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
    top$c3_0 out(
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
    
endmodule // top$verts$0$ef$2
