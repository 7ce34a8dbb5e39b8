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
use super::memory_controller::{Fields, Images, McIn, MemoryController, NodeWord, Record};
use super::sequencer::{SeqIn, Sequencer};
use super::stack_engine::{ListOut, ListStack};
use super::tri_unit::{ClockedTriInput, TriInputIn, TriInputOut};
use crate::chip::config::MemLayout::Records;
use crate::chip::layout::{node_ids, node_records, tri_records};
use crate::cycle::memory::MemModel;
use crate::cycle::tri_unit::TriUnit;
use crate::dop::Node;
use crate::golden::memory::ObjectImage;

/// The query's run: the trace in DATE'05's format, and the lists processed.
pub struct ClockedRun {
    pub trace: crate::cycle::drive::ChipTrace,
    pub lists: u64,
}

/// The chip's units and the sequencer's registers, with the units' outputs after the last
/// edge (`ls`, `dout`) and what the query did so far.
struct Chip<'a> {
    mem: MemModel,
    dop: ClockedDopUnit<'a>,
    lists: ListStack,
    tin: ClockedTriInput,
    tri: TriUnit<'a>,
    mc: MemoryController<'a>,
    sq: Sequencer,
    ls: ListOut,
    dout: ClockOut,
    first: bool,
    /// A's triangle cache's lines less one.
    mask: u8,
    /// First hit: a sure verdict came, nothing more streams or is offered.
    halted: bool,
    out: crate::cycle::drive::ChipTrace,
    /// The Memory Controller's and the sequencer's inputs, each clock, if asked for.
    log: Option<UnitInputs>,
}

/// The inputs of the Memory Controller and of the sequencer in every clock of a query:
/// traffic for their RTL.
#[derive(Default)]
pub struct UnitInputs {
    pub mc: Vec<McIn>,
    pub seq: Vec<SeqIn>,
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
    fn new(
        chip: &'a crate::query::Chip,
        img: &'a Images,
        setup: &'a crate::golden::host::HostSetup,
        first: bool,
        p: &crate::chip::params::Params,
    ) -> Result<Self, String> {
        let cfg = &chip.cfg;
        let layout = crate::chip::layout::Layout::new(&crate::chip::config::ChipConfig {
            layout: Records,
            dop_bits: crate::chip::config::DopBits::Full,
            ..*cfg
        });
        let values = crate::golden::tri_unit::TriUnit::new(
            cfg.format.tri,
            cfg.tri_rounding,
            setup,
            chip.a.tri_count(),
            chip.b.tri_count(),
        );
        Ok(Chip {
            mem: MemModel::new(p.memory_clocks()?, layout.word_bits()),
            dop: ClockedDopUnit::new(cfg.format.dop, cfg.dop_rounding.op(), setup),
            lists: ListStack::new(crate::chip::rtl::LIST_SRAM_BITS),
            tin: ClockedTriInput::default(),
            tri: TriUnit::new(&chip.a, &chip.b, values, p)?,
            mc: MemoryController::new(img, p.outstanding as usize),
            sq: Sequencer::new(crate::chip::rtl::LIST_LEVELS),
            ls: ListOut::default(),
            dout: ClockOut::default(),
            first,
            mask: (cfg.tri_cache - 1) as u8,
            out: crate::cycle::drive::ChipTrace {
                results: vec![],
                cycles: 0,
                overflow: false,
                max_depth: 0,
                dop_tests: 0,
                tri_tests: 0,
                node_fetches: 0,
                tri_fetches: 0,
                memory: Default::default(),
            },
            halted: false,
            log: None,
        })
    }

    /// Nothing left to do (after a halt: nothing left in flight).
    fn finished(&self) -> bool {
        let idle = !self.tin.busy() && self.tri.open() == 0 && self.mc.outstanding() == 0;
        let asks = self.mc.room() < crate::chip::rtl::MC_ASKS;
        idle && (self.halted || self.ls.done && self.sq.idle() && !asks)
    }

    /// The Triangle Unit in clock `now`: a response from memory (`resp`: a triangle word
    /// for the input stage), the input stage (offered the sequencer's leaf pair), TRI_UNIT,
    /// the host reading its verdicts (a sure one halts a first-hit query).
    fn triangles(&mut self, now: u64, resp: bool) -> TriInputOut {
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
            self.out.tri_tests += 1;
        }
        if let Some(r) = self.tri.out(now) {
            if r.res.hit || r.res.uncertain {
                self.out.results.push((now, r.a, r.b, r.res.uncertain));
            }
            self.halted |= self.first && r.sure_hit();
            self.tri.give(now);
        }
        to
    }

    /// One clock, then its edge: the Triangle Unit, the sequencer's ask, the Memory
    /// Controller (a request, a response, the bundle into the DOP Unit), the sequencer's
    /// command to the lists.
    fn step(&mut self, now: u64) {
        let resp = self.mem.respond(now).is_some();
        let to = self.triangles(now, resp);
        let mut si = SeqIn {
            halt: self.halted,
            ls: self.ls,
            flags_valid: self.dout.flags_valid,
            overlap: self.dout.overlap,
            room: self.mc.room(),
            leaf_ready: to.leaf_ready,
            ..SeqIn::default()
        };
        let mem_ready = self.mem.ready(now);
        let i = McIn {
            halt: self.halted,
            push: self.sq.ask(&si),
            need: to.need,
            ids: to.ids,
            mem_ready,
            resp,
            busy: self.dout.busy,
        };
        let o = self.mc.step(&i);
        if let Some(addr) = o.req.filter(|_| mem_ready) {
            self.mem.request(now, addr);
        }
        (si.aligned, si.loaded) = (o.dop_in.a.is_some().then_some(o.aligned), o.loaded);
        if let Some(log) = &mut self.log {
            log.mc.push(i);
            log.seq.push(si.clone());
        }
        let cmd = self.sq.step(&si);
        self.ls = self.lists.step(&cmd);
        self.dout = self.dop.step(&o.dop_in);
    }
}

/// One query on WSCG'03's chip clocked register by register: `chip`'s trees, B placed by
/// `setup`, all pairs or the first hit (`first`), the memory and TRI_UNIT of `p`, at most
/// `max_cycles` clocks.
pub fn run(
    chip: &crate::query::Chip,
    setup: &crate::golden::host::HostSetup,
    first: bool,
    p: &crate::chip::params::Params,
    max_cycles: u64,
) -> Result<ClockedRun, String> {
    let img = images(chip);
    let mut c = Chip::new(chip, &img, setup, first, p)?;
    c.run(max_cycles)?;
    Ok(ClockedRun {
        trace: c.out,
        lists: c.sq.lists,
    })
}

/// The Memory Controller's and the sequencer's inputs in every clock of [`run`]'s query on
/// the memory `img` ([`images`] of `chip`).
pub fn unit_inputs(
    chip: &crate::query::Chip,
    img: &Images,
    setup: &crate::golden::host::HostSetup,
    first: bool,
    p: &crate::chip::params::Params,
    max_cycles: u64,
) -> Result<UnitInputs, String> {
    let mut c = Chip::new(chip, img, setup, first, p)?;
    c.log = Some(UnitInputs::default());
    c.run(max_cycles)?;
    Ok(c.log.unwrap_or_default())
}

impl Chip<'_> {
    /// Clocks until the query is finished, at most `max_cycles`.
    fn run(&mut self, max_cycles: u64) -> Result<(), String> {
        for now in 0..max_cycles {
            if self.finished() {
                let o = &mut self.out;
                (o.cycles, o.node_fetches) = (now, self.mc.node_fetches);
                o.dop_tests = self.sq.dop_tests;
                (o.tri_fetches, o.memory) = (self.mc.tri_fetches, self.mem.counters);
                return Ok(());
            }
            self.step(now);
        }
        Err(crate::cycle::drive::not_finished(max_cycles))
    }
}
