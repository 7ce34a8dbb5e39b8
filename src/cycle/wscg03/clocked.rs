//! WSCG'03's CollisionChip clocked register by register: the Stack Engine's sequencer
//! ([`Sequencer`]) around its lists ([`ListStack`]), the Memory Controller
//! ([`MemoryController`]: a node pair per burst), the DOP Unit ([`ClockedDopUnit`]), the
//! Triangle Unit's input stage ([`ClockedTriInput`]) and TRI_UNIT ([`TriUnit`]), each
//! clock's decisions read from the state before its edge. It is the design the chip's RTL
//! is to follow; values come from the golden functions through the clocked units.
//!
//! The memory holds a node pair per record (the `records` layout, one level: an inner
//! node's two children in one record, the root alone in record 0), node words as the
//! memory image has them, and the chip knows a node by its id (`record << 1 | slot`): it
//! reads what it decides from the node words it fetched, as the RTL will, never the tree.
//! The sequencer, per list (level λ, branch b): the tumbled group G (B's root at level 1;
//! below, the children of the group one level up's member b, or that member itself if it is
//! a leaf) is in a d' set already, or is loaded into one; once G's words have streamed, the
//! children of G's left member are loaded speculatively into the other set. The list's
//! pointers are read one a clock and asked for as aligned DOPs against G's set; each one's
//! flags, with the aligned node's fields that streamed with its last bundle, turn into
//! actions (appends onto the next level's lists, leaf pairs for the Triangle Unit), one a
//! clock. The list is done when every pointer is read, compared and its actions done:
//! `next_list`.

use super::dop_unit::{ClockOut, ClockedDopUnit};
use super::memory_controller::{
    Ask, Fields, Images, McIn, McOut, MemoryController, NodeWord, Record,
};
use super::sequencer::{SeqIn, Sequencer};
use super::stack_engine::{ListCmd, ListOut, ListStack};
use super::tri_unit::{ClockedTriInput, LeafPair, TriInputIn, TriInputOut};
use crate::chip::config::MemLayout::Records;
use crate::chip::layout::Dst;
use crate::chip::layout::{node_ids, node_records, tri_records};
use crate::chip::ports::{ChipIn, ChipOut, Clocked};
use crate::chip::reg;
use crate::chip::rtl::{LIST_LEVELS, LIST_SRAM_BITS, MC_ASKS};
use crate::cycle::drive::{ChipTrace, VcdFile, Watch};
use crate::cycle::tri_unit::TriUnit;
use crate::cycle::VcdOut;
use crate::dop::Node;
use crate::golden::memory::ObjectImage;

/// The query's run: the trace in DATE'05's format, the lists processed and where its
/// clocks went.
pub struct ClockedRun {
    pub trace: ChipTrace,
    pub lists: u64,
    pub booked: Booked,
    /// A's triangle words fetched (its triangle cache's misses).
    pub tri_fetches_a: u64,
    /// Tumbled DOPs transformed (a group loaded: one or two), and the most pointers the
    /// list SRAMs held ([`ListStack::held`]).
    pub transforms: u64,
    pub max_pointers: u64,
}

/// Where a query's clocks went: each clock from `start` to `done` booked to what the DOP
/// Unit's input did, or what its head ask waited for.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, serde::Serialize)]
pub struct Booked {
    /// An aligned bundle streams into the compare units.
    pub compare: u64,
    /// A tumbled bundle streams into the DOTADD units (a group loaded).
    pub load: u64,
    /// The head ask waits for its record from memory.
    pub memory: u64,
    /// The head ask waits for its d' set (busy: the DOTADD units transform a group into it).
    pub transform: u64,
    /// No ask: the sequencer enters or ends a list, waits for flags or actions, or the
    /// lists step up.
    pub list: u64,
    /// The lists done or the query halted: the Triangle Unit finishes.
    pub drain: u64,
}

impl Booked {
    pub fn total(&self) -> u64 {
        self.compare + self.load + self.memory + self.transform + self.list + self.drain
    }
}

/// The chip's units and the sequencer's registers, with the units' outputs after the last
/// edge (`ls`, `dout`), the host's registers and what the query did so far. Its ports are
/// DATE'05's ([`Clocked`]: host registers, `start`, the memory port, the result port).
pub struct Chip<'a> {
    img: &'a Images,
    p: crate::chip::params::Params,
    dop: ClockedDopUnit<'a>,
    lists: ListStack,
    tin: ClockedTriInput,
    tri: TriUnit<'a>,
    mc: MemoryController<'a>,
    sq: Sequencer,
    ls: ListOut,
    dout: ClockOut,
    /// The host's registers: first hit (`MODE`), the regions' first words (`BASE_*`), a
    /// record map written (`MAP`: WSCG'03's Memory Controller reads records in order).
    first: bool,
    bases: [u32; 4],
    map: u32,
    /// A's triangle cache's lines less one.
    mask: u8,
    /// A query runs (from `start`); it is done.
    run: bool,
    done: bool,
    /// First hit: a sure verdict came, nothing more streams or is offered (from the clock
    /// it is at TRI_UNIT's output: [`halt`](Self::halt)).
    halted: bool,
    now: u64,
    tri_tests: u64,
    max_level: u64,
    transforms: u64,
    max_pointers: u64,
    booked: Booked,
    /// The Memory Controller's and the sequencer's inputs, each clock, if asked for.
    log: Option<UnitInputs>,
}

/// What a working clock decided, for the probes: the Triangle Unit's input stage's
/// outputs, the leaf pair offered, the ask, the bundles into the DOP Unit (tumbled: `load`,
/// aligned: `compare`), the lists' command.
#[derive(Default)]
struct Worked {
    to: TriInputOut,
    offer: Option<LeafPair>,
    ask: Option<Ask>,
    load: bool,
    compare: bool,
    cmd: ListCmd,
}

/// What the probes read before a clock's edge.
struct Before {
    o: ChipOut,
    ls: ListOut,
    dout: ClockOut,
    halt: bool,
    lists: u64,
    room: usize,
    in_ready: bool,
    out: Option<crate::cycle::tri_unit::TriOut>,
}

/// The inputs of the Memory Controller and of the sequencer in every working clock of a
/// query, and every clock of the chip as its RTL core sees it: traffic for their RTL.
#[derive(Default)]
pub struct UnitInputs {
    pub mc: Vec<McIn>,
    pub seq: Vec<SeqIn>,
    pub core: Vec<CoreClock>,
}

/// One clock of the chip as its RTL core (`rtl::wscg03::chip::ChipCore`) sees it, TRI_UNIT
/// and the result port outside it: the chip's inputs; TRI_UNIT's `in_ready`, a sure
/// verdict at its output, no pair in it; the chip's outputs; the pair register (its tag and
/// its words' ids, if valid).
#[derive(Clone, Copy, Debug, Default)]
pub struct CoreClock {
    pub i: ChipIn,
    pub tri_ready: bool,
    pub tri_sure: bool,
    pub tri_idle: bool,
    pub o: ChipOut,
    pub pair: Option<(u32, [u16; 2])>,
}

/// An object's node records in the `records` layout of one level (a node pair a record),
/// each node word's fields as the memory image holds them (the ids of
/// [`node_ids`], the triangle records of [`tri_records`]).
fn records(o: &ObjectImage) -> Vec<Record> {
    let (t, children) = (&o.tree, o.tree.children());
    let (rec, ids) = (
        node_records(Records, 1, &children),
        node_ids(Records, 1, &children),
    );
    let tris = tri_records(Records, &t.leaf_tris());
    let mut out = vec![Record::default(); *rec.iter().max().unwrap() as usize + 1];
    for n in 0..t.len() as u32 {
        let (leaf, f) = match t.node(n) {
            Node::Inner([c0, c1]) => (false, [ids[c0 as usize], ids[c1 as usize]]),
            Node::Leaf(tri) => (true, [tri, tris[tri as usize]]),
        };
        let id = ids[n as usize];
        out[rec[n as usize] as usize][id as usize & 1] = NodeWord {
            dop: t.dop(n).to_vec(),
            fields: Fields { id, leaf, f },
        };
    }
    out
}

/// The memory of `chip`'s query: A's and B's node records, the regions' first words.
pub fn images(chip: &crate::query::Chip) -> Images {
    let (ra, rb) = (records(&chip.a), records(&chip.b));
    let (na, nb) = (ra.len() as u32, rb.len() as u32);
    Images {
        records: [ra, rb],
        bases: crate::chip::layout::image_bases(na, chip.a.tri_count() as u32, nb),
        k: chip.cfg.k,
    }
}

impl<'a> Chip<'a> {
    /// A chip after reset on the memory `img` (its host registers zero: write
    /// [`control_writes`](crate::chip::reg::control_writes) before `start`), `chip`'s
    /// TRI_UNIT values and B placed by `setup` (the DOP Unit's and TRI_UNIT's setup words
    /// are the golden [`HostSetup`](crate::golden::host::HostSetup)), the requests
    /// outstanding and TRI_UNIT of `p`.
    pub fn new(
        chip: &'a crate::query::Chip,
        img: &'a Images,
        setup: &'a crate::golden::host::HostSetup,
        p: &crate::chip::params::Params,
    ) -> Result<Self, String> {
        let cfg = &chip.cfg;
        let values = crate::golden::tri_unit::TriUnit::new(
            cfg.format.tri,
            cfg.tri_rounding,
            setup,
            chip.a.tri_count(),
            chip.b.tri_count(),
        );
        Ok(Chip {
            img,
            p: *p,
            dop: ClockedDopUnit::new(cfg.format.dop, cfg.dop_rounding.op(), setup),
            lists: ListStack::new(LIST_SRAM_BITS),
            tin: ClockedTriInput::default(),
            tri: TriUnit::new(&chip.a, &chip.b, values, p)?,
            mc: MemoryController::new(img, [0; 4], p.outstanding as usize),
            sq: Sequencer::new(LIST_LEVELS),
            ls: ListOut::default(),
            dout: ClockOut::default(),
            first: false,
            bases: [0; 4],
            map: 0,
            mask: (cfg.tri_cache - 1) as u8,
            run: false,
            done: false,
            halted: false,
            now: 0,
            tri_tests: 0,
            max_level: 0,
            transforms: 0,
            max_pointers: 0,
            booked: Booked::default(),
            log: None,
        })
    }

    /// Lists entered in the query so far.
    pub fn lists(&self) -> u64 {
        self.sq.lists
    }

    /// Nothing left to do (after a halt: nothing left in flight).
    fn finished(&self) -> bool {
        let idle = !self.tin.busy() && self.tri.open() == 0 && self.mc.outstanding() == 0;
        let asks = self.mc.room() < MC_ASKS;
        idle && (self.halted || self.ls.done && self.sq.idle() && !asks)
    }

    /// A host write to one of the chip's registers (`chip::reg`; the DOP Unit's and
    /// TRI_UNIT's setup words are the golden setup, the port's and the cache's are `p`'s
    /// and the configuration's).
    fn host_write(&mut self, addr: u32, data: u32) {
        match addr {
            reg::MODE => self.first = reg::mode_fields(data).1 == reg::Mode::First,
            reg::BASE_NA..=reg::BASE_TB => {
                self.bases[(addr - reg::BASE_NA) as usize] = data & 0xff_ffff;
            }
            reg::MAP => self.map = data,
            _ => {}
        }
    }

    /// A start: the query runs from B's root's pointer, every unit and counter empty.
    fn start(&mut self) {
        (self.run, self.done, self.halted) = (true, false, false);
        self.mc = MemoryController::new(self.img, self.bases, self.p.outstanding as usize);
        self.sq = Sequencer::new(LIST_LEVELS);
        self.lists = ListStack::new(LIST_SRAM_BITS);
        self.tin = ClockedTriInput::default();
        (self.ls, self.dout) = Default::default();
        (self.tri_tests, self.max_level, self.booked) = (0, 0, Booked::default());
        (self.transforms, self.max_pointers) = (0, 0);
    }

    /// The Triangle Unit in this clock: a response from memory (`resp`: a triangle word
    /// for the input stage), the input stage (offered the sequencer's leaf pair), TRI_UNIT,
    /// its verdict given out (`res_ready`: the host reads a kept one; a sure one halts a
    /// first-hit query).
    fn triangles(&mut self, resp: bool, res_ready: bool) -> TriInputOut {
        let now = self.now;
        self.halted = self.halt();
        let ready = self.tri.in_ready(now);
        let to = self.tin.step(&TriInputIn {
            clear: false,
            mask: self.mask,
            halt: self.halted,
            leaf: self.sq.offer(self.halted),
            fill: self.mc.fill(resp),
            tri_ready: ready,
        });
        if to.pair_valid && ready {
            self.tri.take(now, to.pair_tag & 0xffff, to.pair_tag >> 16);
            self.tri_tests += 1;
        }
        if self.tri.out(now).is_some_and(|r| res_ready || !r.kept()) {
            self.tri.give(now);
        }
        to
    }

    /// First hit, this clock: halted, or a sure verdict at TRI_UNIT's output.
    fn halt(&self) -> bool {
        let sure = self.tri.out(self.now).is_some_and(|r| r.sure_hit());
        self.halted || self.first && sure
    }

    /// One working clock, then its edge: the Triangle Unit, the sequencer's ask, the
    /// Memory Controller (a request, a response, the bundle into the DOP Unit), the
    /// sequencer's command to the lists.
    fn work(&mut self, i: &ChipIn) -> Worked {
        let resp = i.mem_resp.is_some();
        let to = self.triangles(resp, i.res_ready);
        let mut si = SeqIn {
            halt: self.halted,
            ls: self.ls,
            flags_valid: self.dout.flags_valid,
            overlap: self.dout.overlap,
            room: self.mc.room(),
            leaf_ready: to.leaf_ready,
            ..SeqIn::default()
        };
        let mi = McIn {
            halt: self.halted,
            push: self.sq.ask(&si),
            need: to.need,
            ids: to.ids,
            mem_ready: i.mem_req_ready,
            resp,
            busy: self.dout.busy,
        };
        let head = self.mc.head();
        let o = self.mc.step(&mi);
        self.book(head, &o);
        self.transforms += o.loaded.as_ref().map_or(0, |l| l.1.len() as u64);
        (si.aligned, si.loaded) = (o.dop_in.a.is_some().then_some(o.aligned), o.loaded);
        if let Some(log) = &mut self.log {
            log.mc.push(mi);
            log.seq.push(si.clone());
        }
        let offer = self.sq.offer(self.halted);
        let cmd = self.sq.step(&si);
        self.ls = self.lists.step(&cmd);
        self.max_level = self.max_level.max(self.ls.level as u64);
        self.max_pointers = self.max_pointers.max(self.lists.held());
        self.dout = self.dop.step(&o.dop_in);
        Worked {
            to,
            offer,
            ask: mi.push,
            load: o.dop_in.t.is_some(),
            compare: o.dop_in.a.is_some(),
            cmd,
        }
    }

    /// What the probes read before the edge.
    fn before(&self) -> Before {
        Before {
            o: self.outputs(),
            ls: self.ls,
            dout: self.dout,
            halt: self.halt(),
            lists: self.sq.lists,
            room: self.mc.room(),
            in_ready: self.tri.in_ready(self.now),
            out: self.tri.out(self.now).copied(),
        }
    }
}

impl Chip<'_> {
    /// Books this clock from the Memory Controller's outputs `o` and its head ask before
    /// the edge (`head`: its set, its record there; a head that has its record and streams
    /// nothing waits for its set, or the query halted).
    fn book(&mut self, head: Option<(usize, bool)>, o: &McOut) {
        let b = &mut self.booked;
        match head {
            _ if o.dop_in.a.is_some() => b.compare += 1,
            _ if o.dop_in.t.is_some() => b.load += 1,
            _ if self.halted || head.is_none() && self.ls.done => b.drain += 1,
            Some((_, false)) => b.memory += 1,
            Some((_, true)) => b.transform += 1,
            None => b.list += 1,
        }
    }
}

impl Clocked for Chip<'_> {
    fn outputs(&self) -> ChipOut {
        let (need, ids) = self.tin.need(self.halt(), self.mask);
        let req = self.run.then(|| self.mc.request(need, ids)).flatten();
        let res = self.tri.out(self.now).filter(|o| self.run && o.kept());
        ChipOut {
            busy: self.run,
            done: self.done,
            overflow: self.ls.overflow,
            max_depth: self.max_level,
            dop_tests: self.sq.dop_tests,
            tri_tests: self.tri_tests,
            node_fetches: self.mc.node_fetches,
            tri_fetches: self.mc.tri_fetches,
            mem_req_valid: req.is_some(),
            mem_req_addr: req.map_or(0, |r| r.2),
            res_valid: res.is_some(),
            res_tag: res.map_or((0, 0), |o| (o.a, o.b)),
            res_uncertain: res.is_some_and(|o| o.res.uncertain),
        }
    }

    fn step(&mut self, i: &ChipIn, probe: bool) -> Option<Vec<u64>> {
        let before = probe.then(|| self.before());
        let mut core = self.log.is_some().then(|| CoreClock {
            i: *i,
            tri_ready: self.tri.in_ready(self.now),
            tri_sure: self.tri.out(self.now).is_some_and(|r| r.sure_hit()),
            tri_idle: self.tri.open() == 0,
            o: self.outputs(),
            pair: None,
        });
        if i.host_we {
            self.host_write(i.host_addr, i.host_data);
        }
        let mut worked = Worked::default();
        if self.run {
            worked = self.work(i);
            let to = &worked.to;
            if let Some(c) = &mut core {
                let ids = to.words.map(|w| w.unwrap_or(0));
                c.pair = to.pair_valid.then_some((to.pair_tag, ids));
            }
            if self.finished() {
                (self.run, self.done) = (false, true);
            }
        }
        if let (Some(log), Some(c)) = (&mut self.log, core) {
            log.core.push(c);
        }
        if i.start && !self.run {
            self.start();
        }
        self.now += 1;
        before.map(|b| probes(&b, i, &worked))
    }

    fn probe_list(&self) -> &'static crate::chip::probes::Probes {
        &crate::chip::probes::WSCG03
    }

    fn fault(&self) -> Option<String> {
        (self.map != 0).then(|| {
            "a record map: WSCG'03's Memory Controller reads records in order (base + record)"
                .to_string()
        })
    }
}

/// The host's writes of `chip`'s query on the memory `img` (all pairs or the first hit:
/// `first`; the image in order, no record map) on `p`'s memory.
pub fn writes(
    chip: &crate::query::Chip,
    img: &Images,
    first: bool,
    p: &crate::chip::params::Params,
) -> Vec<(u32, u32)> {
    let mode = if first {
        reg::Mode::First
    } else {
        reg::Mode::All
    };
    let cfg = records_cfg(&chip.cfg);
    reg::query_writes(img.bases, None, reg::Order::Fifo, mode, p, &cfg)
}

/// `cfg` with the memory laid out as WSCG'03's chip reads it: a node pair a record.
fn records_cfg(cfg: &crate::chip::config::ChipConfig) -> crate::chip::config::ChipConfig {
    crate::chip::config::ChipConfig {
        layout: Records,
        dop_bits: crate::chip::config::DopBits::Full,
        ..*cfg
    }
}

/// Drives one query on `c` (the chip on `img` of `chip`): the units' setup words `setup`
/// (which the model takes from the golden setup, the RTL from its host port), its writes,
/// `start`, then clocks until `done`, the memory of `p` serving it, the host reading every
/// result at once, at most `max_cycles` clocks; its traversal signals into `vcd`, if any.
fn drive(
    c: &mut impl Clocked,
    chip: &crate::query::Chip,
    img: &Images,
    (setup, first): (&[(u32, u32)], bool),
    p: &crate::chip::params::Params,
    max_cycles: u64,
    mut vcd: Option<VcdFile>,
) -> Result<ChipTrace, String> {
    let layout = crate::chip::layout::Layout::new(&records_cfg(&chip.cfg));
    let d = crate::cycle::drive::Drive {
        memory: p.memory_clocks()?,
        word_bits: layout.word_bits(),
        reader: Default::default(),
        words: img.bases[Dst::TriB as usize] + chip.b.tri_count() as u32,
        max_cycles,
    };
    let w = [setup, &writes(chip, img, first, p)].concat();
    let probe = vcd.is_some();
    let observe = |t, v| VcdFile::observe(&mut vcd, t, v);
    crate::cycle::drive::run_query(c, &w, &d, probe, observe, false).map_err(|e| e.0)
}

/// One query on WSCG'03's chip clocked register by register: `chip`'s trees, B placed by
/// `setup`, all pairs or the first hit (`first`), the memory and TRI_UNIT of `p`, at most
/// `max_cycles` clocks; `see` watches its ports every clock ([`Watch`]); a VCD of its
/// traversal signals ([`WSCG03`](crate::chip::probes::WSCG03)) written if asked.
pub fn run(
    chip: &crate::query::Chip,
    setup: &crate::golden::host::HostSetup,
    (first, p): (bool, &crate::chip::params::Params),
    max_cycles: u64,
    see: impl FnMut(u64, &ChipOut, &ChipIn),
    vcd: Option<VcdOut>,
) -> Result<ClockedRun, String> {
    let img = images(chip);
    let mut c = Chip::new(chip, &img, setup, p)?;
    let vcd = vcd
        .map(|v| v.open(&crate::chip::probes::WSCG03))
        .transpose()?;
    let watched = &mut Watch::new(&mut c, see);
    let trace = drive(watched, chip, &img, (&[], first), p, max_cycles, vcd)?;
    Ok(ClockedRun {
        trace,
        lists: c.lists(),
        booked: c.booked,
        tri_fetches_a: c.mc.tri_fetches_a,
        transforms: c.transforms,
        max_pointers: c.max_pointers,
    })
}

/// The units' inputs in every clock of [`run`]'s query on the memory `img` ([`images`] of
/// `chip`), the setup words `words` written first.
pub fn unit_inputs(
    chip: &crate::query::Chip,
    img: &Images,
    (setup, words): (&crate::golden::host::HostSetup, &[(u32, u32)]),
    first: bool,
    p: &crate::chip::params::Params,
    max_cycles: u64,
) -> Result<UnitInputs, String> {
    let mut c = Chip::new(chip, img, setup, p)?;
    c.log = Some(UnitInputs::default());
    drive(&mut c, chip, img, (words, first), p, max_cycles, None)?;
    // the clock `done` shows in, which the driver reads and does not clock
    let last = CoreClock {
        tri_ready: c.tri.in_ready(c.now),
        tri_idle: c.tri.open() == 0,
        o: c.outputs(),
        ..CoreClock::default()
    };
    let mut log = c.log.take().unwrap_or_default();
    log.core.push(last);
    Ok(log)
}

/// The values of [`WSCG03`](crate::chip::probes::WSCG03)'s signals in a clock: `b` read
/// before its edge, the inputs `i`, what the working clock decided `w`.
fn probes(b: &Before, i: &ChipIn, w: &Worked) -> Vec<u64> {
    let x = |v: bool| v as u64;
    let (o, ls, cmd) = (&b.o, &b.ls, &w.cmd);
    let (side, ptr) = cmd.append.unwrap_or_default();
    let (load, set, pair, id) = Ask::ports(w.ask);
    let leaf = w.offer.map_or(0, |l| l.tag as u64);
    let out = b.out;
    vec![
        x(i.start),
        x(o.busy),
        x(o.done),
        x(o.overflow),
        x(b.halt),
        ls.level as u64,
        ls.branch as u64,
        ls.remaining as u64,
        x(ls.busy),
        x(ls.done),
        x(cmd.read),
        x(cmd.next_list),
        x(cmd.append.is_some()),
        side as u64,
        ptr as u64,
        x(ls.rd.is_some()),
        ls.rd.unwrap_or(0) as u64,
        b.lists & 0xffff_ffff,
        x(w.ask.is_some()),
        x(load),
        set as u64,
        x(pair),
        id as u64 & 0xffff,
        b.room as u64,
        x(o.mem_req_valid),
        x(i.mem_req_ready),
        o.mem_req_addr as u64,
        x(i.mem_resp.is_some()),
        x(w.load),
        x(w.compare),
        x(b.dout.busy[0]) | x(b.dout.busy[1]) << 1,
        x(b.dout.flags_valid),
        x(b.dout.overlap[0]) | x(b.dout.overlap[1]) << 1,
        x(w.offer.is_some()),
        x(w.to.leaf_ready),
        leaf & 0xffff,
        leaf >> 16 & 0xffff,
        x(w.to.pair_valid),
        x(b.in_ready),
        x(out.is_some()),
        x(out.is_some_and(|r| r.res.hit)),
        x(out.is_some_and(|r| r.res.uncertain)),
        out.map_or(0, |r| r.a as u64),
        out.map_or(0, |r| r.b as u64),
        x(o.res_valid),
        x(o.res_uncertain),
        o.res_tag.0 as u64,
        o.res_tag.1 as u64,
        o.dop_tests & 0xffff_ffff,
        o.tri_tests & 0xffff_ffff,
        o.node_fetches & 0xffff_ffff,
        o.tri_fetches & 0xffff_ffff,
    ]
}
