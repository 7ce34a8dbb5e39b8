//! "What accuracy costs": the same tumbling sweep (WSCG'03 protocol) run with several number
//! formats, k, DOP roundings and memory systems (the chip presets), each query compared with
//! the exact oracle and run on the cycle model for its clocks, at the configuration's
//! measured clock period ([`Clock`]), with the host's share measured: the time end to end.
//! A study splits into shards (`--shard K/N`) whose rows add up to the serial run's.

use crate::chip::config::{ChipConfig, DopBits, DopRounding, Formats};
use crate::chip::memory::Memory;
use crate::chip::params::Params;
use crate::chip::preset::Preset;
use crate::chip::reg::{Mode, Order};
use crate::chip::timing::{self, Clock, Folds, PeriodSource, Technology};
use crate::cycle::{self, drive::Reader};
use crate::dop::tree::Tri;
use crate::golden::memory::TriWord;
use crate::measure::parallel_map;
use crate::oracle;
use crate::pose::{sweep_poses, Sweep};
use crate::query::{exact_pairs, place, Accuracy, Chip};
use crate::report::plot::{Cell, Figure, Panel, Series, Style, Table, PALETTE};
use crate::traversal::Traversal;
use serde::{Deserialize, Serialize};
use std::fmt::Write;

/// What a study runs: each mesh against a copy of itself over the sweep, in every memory
/// preset x k x format x DOP rounding x fold, at `technology`'s clock.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Plan {
    pub meshes: Vec<String>,
    pub presets: Vec<Preset>,
    pub ks: Vec<usize>,
    pub formats: Vec<Formats>,
    pub roundings: Vec<DopRounding>,
    pub sweep: Sweep,
    /// The ideal memory's bus (the `rtl` preset): a word moves in ceil(bits / bus_bits) clocks.
    pub bus_bits: Option<u32>,
    pub technology: Technology,
    /// TRI_UNIT's and the DOP unit's pair intervals (what area costs in time);
    /// `[Folds::NONE]` (both unfolded) in studies written before folds.
    #[serde(default = "unfolded")]
    pub folds: Vec<Folds>,
    /// Stored DOP precisions; empty: each preset's own (`[DopBits::Full]` in studies written
    /// before them).
    #[serde(default = "full")]
    pub dop_bits: Vec<DopBits>,
    /// Node records held per object on every preset (`--node-cache`); each preset's own in
    /// studies written before it.
    #[serde(default)]
    pub node_cache: NodeCache,
}

/// The node records a study's chips hold per object (`ChipConfig::node_cache`): each
/// preset's own (16 on date05 and wscg03, 64 on date05-treelets), or `Held(n)` on every
/// preset. The RTL chips hold one (`cchip accuracy`'s default): with more, a configuration's
/// chip is not built and its period is estimated.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum NodeCache {
    #[default]
    Preset,
    Held(u32),
}

impl std::str::FromStr for NodeCache {
    type Err = String;
    fn from_str(s: &str) -> Result<Self, String> {
        match s {
            "preset" => Ok(NodeCache::Preset),
            n => match n.parse() {
                Ok(l) if (1..=crate::chip::config::NODE_CACHE_MAX_LINES).contains(&l) => Ok(NodeCache::Held(l)),
                _ => Err(format!("`{n}`: give node records held per object, 1 (the RTL chips') to {}, or `preset` for each preset's own", crate::chip::config::NODE_CACHE_MAX_LINES)),
            },
        }
    }
}

impl NodeCache {
    /// The records held on `preset`.
    pub fn on(self, preset: Preset) -> u32 {
        match self {
            NodeCache::Preset => preset.chip().node_cache,
            NodeCache::Held(n) => n,
        }
    }
}

fn unfolded() -> Vec<Folds> {
    vec![Folds::NONE]
}

fn full() -> Vec<DopBits> {
    vec![DopBits::Full]
}

impl Plan {
    /// The configurations in the order of the table: (memory preset, chip, its timing).
    pub fn configs(&self) -> Result<Vec<(Preset, ChipConfig, Params)>, String> {
        let mut out = vec![];
        for &preset in &self.presets {
            let mut params = preset.params();
            match (&mut params.memory, self.bus_bits) {
                (Memory::Ideal(t), Some(b)) => t.bus_bits = Some(b),
                (Memory::Ddr(d), Some(b)) => {
                    return Err(format!(
                        "--bus-bits {b} sets the ideal memory's bus (preset rtl's memory); preset {}'s memory is DDR SDRAM on a bus of its own ({} bits): leave --bus-bits out, or give --presets rtl",
                        preset.name(),
                        d.bus_bits
                    ))
                }
                (_, None) => {}
            }
            params.check()?;
            for &k in &self.ks {
                for &format in &self.formats {
                    for &dop_rounding in &self.roundings {
                        for &f in &self.folds {
                            let params = Params {
                                tri_interval: f.tri,
                                dop_interval: f.dop,
                                depth: f.depth,
                                ..params
                            };
                            params
                                .check()
                                .and_then(|_| params.check_dop_interval(k))
                                .map_err(|e| {
                                    format!(
                                        "k = {k}, TRI_UNIT interval {}, DOP interval {}: {e}",
                                        f.tri, f.dop
                                    )
                                })?;
                            let own = [preset.chip().dop_bits];
                            let bits = if self.dop_bits.is_empty() {
                                &own[..]
                            } else {
                                &self.dop_bits[..]
                            };
                            for &dop_bits in bits {
                                let cfg = ChipConfig {
                                    k,
                                    format,
                                    dop_rounding,
                                    dop_bits,
                                    node_cache: self.node_cache.on(preset),
                                    ..preset.chip()
                                };
                                cfg.check().map_err(|e| {
                                    format!(
                                        "--dop-bits {dop_bits} on preset {}: {e}",
                                        preset.name()
                                    )
                                })?;
                                out.push((preset, cfg, params));
                            }
                        }
                    }
                }
            }
        }
        Ok(out)
    }
}

/// Which share of a study's (mesh, pose) items to run: the `k`-th of `n` (1-based), items
/// dealt round-robin.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
pub struct Shard {
    pub k: usize,
    pub n: usize,
}

impl Shard {
    pub const ALL: Shard = Shard { k: 1, n: 1 };

    fn has(self, item: usize) -> bool {
        item % self.n == self.k - 1
    }
}

impl std::str::FromStr for Shard {
    type Err = String;

    /// `K/N` with 1 <= K <= N.
    fn from_str(s: &str) -> Result<Shard, String> {
        let bad = || {
            format!(
                "shard {s:?}: give K/N with 1 <= K <= N (e.g. 3/8; SLURM: $SLURM_ARRAY_TASK_ID/N)"
            )
        };
        let (k, n) = s.split_once('/').ok_or_else(bad)?;
        let (k, n) = (
            k.trim().parse().map_err(|_| bad())?,
            n.trim().parse().map_err(|_| bad())?,
        );
        if k == 0 || k > n {
            Err(bad())
        } else {
            Ok(Shard { k, n })
        }
    }
}

/// One shard's output (`--shard K/N`): its plan and its rows' sums over its items.
#[derive(Clone, Debug, Serialize, Deserialize)]
pub struct ShardFile {
    pub plan: Plan,
    pub shard: Shard,
    pub rows: Vec<Row>,
}

impl ShardFile {
    /// A shard's output as `--merge` reads it: `text`, the contents of the file `path`.
    pub fn parse(text: &str, path: &std::path::Path) -> Result<ShardFile, String> {
        serde_json::from_str(text).map_err(|e| {
            format!(
                "{}:{}: not a shard's output ({e}); write shards with cchip accuracy --shard K/N > FILE",
                path.display(),
                e.line()
            )
        })
    }
}

/// One mesh and configuration over all poses of the sweep.
#[derive(Clone, Debug, Serialize, Deserialize)]
pub struct Row {
    pub mesh: String,
    /// The memory system: the chip preset whose memory, port, caches and layout ran.
    pub memory: Preset,
    pub k: usize,
    pub format: Formats,
    pub dop_rounding: DopRounding,
    /// The stored DOP precision (full in rows written before it).
    #[serde(default)]
    pub dop_bits: DopBits,
    /// The pair intervals of TRI_UNIT and the DOP unit (1: unfolded).
    #[serde(default)]
    pub folds: Folds,
    /// Node records held per object (the memory preset's own in rows written before it).
    #[serde(default)]
    pub node_cache: Option<u32>,
    /// The clock period, whether measured or estimated, and from what ([`Clock::source`]).
    pub period_ns: f64,
    pub period_source: PeriodSource,
    pub clock: String,
    #[serde(flatten)]
    pub sums: Sums,
    /// The host's share, measured (wall clock, the poses on every core: noisy).
    pub host: HostSums,
}

/// The host's measured time over the queries, in microseconds.
#[derive(Clone, Copy, Debug, Default, Serialize, Deserialize)]
pub struct HostSums {
    pub setup_us: f64,
    pub settle_us: f64,
}

impl Row {
    /// The chip this row ran: its memory preset's with the row's k, formats, DOP rounding,
    /// stored DOP precision and node records held.
    pub fn chip(&self) -> ChipConfig {
        let preset = self.memory.chip();
        ChipConfig {
            k: self.k,
            format: self.format,
            dop_rounding: self.dop_rounding,
            dop_bits: self.dop_bits,
            node_cache: self.node_cache.unwrap_or(preset.node_cache),
            ..preset
        }
    }

    /// The memory column: the preset, and the node records held where not its own.
    fn memory_name(&self) -> String {
        let own = self.memory.chip().node_cache;
        match self.node_cache {
            Some(n) if n != own => format!("{}, {n} held", self.memory.name()),
            _ => self.memory.name().to_string(),
        }
    }

    fn per_query(&self, x: f64) -> f64 {
        x / self.sums.queries.max(1) as f64
    }

    pub fn chip_us(&self) -> f64 {
        self.per_query(self.sums.cycles as f64) * self.period_ns / 1000.0
    }

    pub fn host_us(&self) -> f64 {
        self.per_query(self.host.setup_us + self.host.settle_us)
    }

    /// Per query: the host's setup + the chip's clocks x period + the host's settling.
    pub fn end_to_end_us(&self) -> f64 {
        self.host_us() + self.chip_us()
    }
}

/// Sums over the queries.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
pub struct Sums {
    pub queries: u64,
    pub exact_pairs: u64,
    pub dop_tests: u64,
    pub tri_tests: u64,
    pub uncertain: u64,
    /// Uncertain by cause ([`Cause`]), each pair counted once, in this order.
    pub uncertain_degenerate: u64,
    pub uncertain_on_plane: u64,
    pub uncertain_bound: u64,
    pub memory_bytes: u64,
    pub misses: u64,
    pub extras: u64,
    /// The cycle model's clocks (LIFO, all pairs, the memory preset's port and memory).
    pub cycles: u64,
}

impl std::ops::AddAssign for HostSums {
    fn add_assign(&mut self, h: HostSums) {
        self.setup_us += h.setup_us;
        self.settle_us += h.settle_us;
    }
}

impl std::ops::AddAssign for Sums {
    fn add_assign(&mut self, q: Sums) {
        *self = self
            .checked_add(q)
            .expect("a study's counts fit in 64 bits (merge checks a file's)");
    }
}

impl Sums {
    /// `self + q`, or `None` where a count would pass 2^64 - 1 (counts read from a file).
    pub fn checked_add(self, q: Sums) -> Option<Sums> {
        Some(Sums {
            queries: self.queries.checked_add(q.queries)?,
            exact_pairs: self.exact_pairs.checked_add(q.exact_pairs)?,
            dop_tests: self.dop_tests.checked_add(q.dop_tests)?,
            tri_tests: self.tri_tests.checked_add(q.tri_tests)?,
            uncertain: self.uncertain.checked_add(q.uncertain)?,
            uncertain_degenerate: self
                .uncertain_degenerate
                .checked_add(q.uncertain_degenerate)?,
            uncertain_on_plane: self.uncertain_on_plane.checked_add(q.uncertain_on_plane)?,
            uncertain_bound: self.uncertain_bound.checked_add(q.uncertain_bound)?,
            memory_bytes: self.memory_bytes.checked_add(q.memory_bytes)?,
            misses: self.misses.checked_add(q.misses)?,
            extras: self.extras.checked_add(q.extras)?,
            cycles: self.cycles.checked_add(q.cycles)?,
        })
    }

    /// Triangle tests whose pair does not intersect: the DOP hierarchy's false positives at
    /// the leaves (the chip's pairs equal the exact ones, so this is tri_tests - pairs).
    pub fn dop_false_positive_rate(&self) -> f64 {
        ratio(
            self.tri_tests
                .saturating_sub(self.exact_pairs - self.misses),
            self.tri_tests,
        )
    }

    pub fn uncertain_rate(&self) -> f64 {
        ratio(self.uncertain, self.tri_tests)
    }
}

/// Why TRI_UNIT left a pair to the host, first cause that applies.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Cause {
    /// A leaf has no unit-triangle map (zero area, or too ill-conditioned for the format):
    /// its direction of TRI_UNIT cannot decide.
    Degenerate,
    /// A vertex of one triangle lies exactly on the other's plane in the oracle's geometry
    /// (touching, coplanar): a deciding value is exactly 0, no bound can decide it.
    OnPlane,
    /// Every deciding value is non-zero, but some sign lies inside its error bound.
    Bound,
}

impl Cause {
    /// The cause for the uncertain pair of words `wa`, `wb` whose triangles are `ta` of A and
    /// `tb` of B as the oracle places them.
    pub fn of(wa: &TriWord, wb: &TriWord, ta: &Tri, tb: &Tri) -> Cause {
        if wa.degenerate || wb.degenerate {
            Cause::Degenerate
        } else if oracle::vertex_on_plane(ta, tb) {
            Cause::OnPlane
        } else {
            Cause::Bound
        }
    }
}

fn ratio(a: u64, b: u64) -> f64 {
    if b == 0 {
        0.0
    } else {
        a as f64 / b as f64
    }
}

/// Runs `plan`'s configurations on its `index`-th mesh against a copy of itself, the poses of
/// `shard` on every core; `progress` is called once per pose run.
pub fn study(
    plan: &Plan,
    index: usize,
    tris: &[Tri],
    shard: Shard,
    progress: impl Fn() + Sync,
) -> Result<Vec<Row>, String> {
    let mesh = &plan.meshes[index];
    let all = sweep_poses(&plan.sweep)?;
    let poses: Vec<_> = all
        .iter()
        .enumerate()
        .filter(|(i, _)| shard.has(index * all.len() + i))
        .map(|(_, p)| *p)
        .collect();
    let mut configs = plan.configs()?;
    let mut rows = vec![];
    let mut chips: Vec<Chip> = vec![];
    let mut chip_of = vec![];
    for (preset, cfg, params) in &mut configs {
        let (preset, cfg) = (*preset, *cfg);
        let folds = Folds::of(params);
        let clock = Clock::of(plan.technology, &cfg, folds, preset)?;
        // the memory's nanoseconds in this configuration's clocks
        params.clock_ps = clock.ps();
        params.check()?;
        rows.push(Row {
            mesh: mesh.clone(),
            memory: preset,
            k: cfg.k,
            format: cfg.format,
            dop_rounding: cfg.dop_rounding,
            dop_bits: cfg.dop_bits,
            folds,
            node_cache: Some(cfg.node_cache),
            period_ns: clock.period_ns,
            period_source: clock.source,
            clock: clock.source(),
            sums: Sums::default(),
            host: HostSums::default(),
        });
        // one image per distinct chip (the presets share some)
        chip_of.push(match chips.iter().position(|c| c.cfg == cfg) {
            Some(i) => i,
            None => {
                chips.push(Chip::new(tris, tris, cfg)?);
                chips.len() - 1
            }
        });
    }
    if let Some(chip) = chips.first() {
        all.iter().try_for_each(|sp| chip.check_pose(&sp.pose))?;
    }
    let per_pose = parallel_map(&poses, |_, sp| {
        let exact = exact_pairs(tris, tris, &sp.pose);
        let placed = place(tris, &sp.pose);
        let golden: Vec<_> = chips
            .iter()
            .map(|chip| chip.query(&sp.pose, Mode::All, Traversal::Lifo))
            .collect();
        let rows = configs.iter().zip(&chip_of).map(|(&(_, _, params), &c)| {
            let (chip, r) = (&chips[c], &golden[c]);
            let acc = Accuracy::of(Mode::All, &r.pairs, &exact);
            let (trace, _) = cycle::run_query(
                chip,
                &chip.setup(&sp.pose),
                Order::Lifo,
                Mode::All,
                params,
                Reader::default(),
                cycle::MAX_CYCLES,
                Default::default(),
            )?;
            trace.check(Mode::All, r).map_err(|e| {
                format!(
                    "{mesh} k={} {} at {}: the cycle model disagrees with the golden model: {e}",
                    chip.cfg.k,
                    chip.cfg.format,
                    sp.pose.text()
                )
            })?;
            let mut causes = [0u64; 3];
            for &(a, b) in &r.uncertain {
                let (a, b) = (a as usize, b as usize);
                causes[Cause::of(
                    &chip.a.tri(a as u32),
                    &chip.b.tri(b as u32),
                    &tris[a],
                    &placed[b],
                ) as usize] += 1;
            }
            let h = chip.host_time(&sp.pose, &r.uncertain);
            Ok((
                Sums {
                    queries: 1,
                    uncertain_degenerate: causes[Cause::Degenerate as usize],
                    uncertain_on_plane: causes[Cause::OnPlane as usize],
                    uncertain_bound: causes[Cause::Bound as usize],
                    exact_pairs: exact.len() as u64,
                    dop_tests: r.counters.dop_tests,
                    tri_tests: r.counters.tri_tests,
                    uncertain: r.counters.uncertain,
                    memory_bytes: r.counters.memory_bytes,
                    misses: acc.misses,
                    extras: acc.extras,
                    cycles: trace.cycles,
                },
                HostSums {
                    setup_us: h.setup_us,
                    settle_us: h.settle_us,
                },
            ))
        });
        let rows = rows.collect::<Result<Vec<_>, String>>();
        progress();
        rows
    });
    for pose_rows in per_pose {
        for (row, (q, h)) in rows.iter_mut().zip(pose_rows?) {
            row.sums += q;
            row.host += h;
        }
    }
    Ok(rows)
}

/// Runs `plan` on `shard`, each mesh's triangles from `load`.
pub fn run(
    plan: &Plan,
    load: impl Fn(&str) -> Result<Vec<Tri>, String>,
    shard: Shard,
    progress: impl Fn() + Sync,
) -> Result<Vec<Row>, String> {
    let mut rows = vec![];
    for (i, m) in plan.meshes.iter().enumerate() {
        rows.extend(study(plan, i, &load(m)?, shard, &progress)?);
    }
    Ok(rows)
}

/// The serial run's rows from its shards' files: the same plan, each of 1..=N once; the
/// counted sums add up exactly (the host's measured times are each shard's).
pub fn merge(files: Vec<ShardFile>) -> Result<(Plan, Vec<Row>), String> {
    let first = files.first().ok_or("--merge: no shard files")?;
    let (plan, n) = (first.plan.clone(), first.shard.n);
    // the shards seen, as many as files (N comes from a file: nothing sized by it)
    let mut seen = std::collections::BTreeSet::new();
    // every row of every shard added up: the merged rows' and the figures' sums are parts of it
    let mut total = Sums::default();
    let mut rows: Vec<Row> = first
        .rows
        .iter()
        .map(|r| Row {
            sums: Sums::default(),
            host: HostSums::default(),
            ..r.clone()
        })
        .collect();
    for f in &files {
        if f.plan != plan || f.shard.n != n {
            return Err(format!("--merge: shard {}/{} is of another study (its plan or N differs from shard {}/{}'s)", f.shard.k, f.shard.n, first.shard.k, n));
        }
        if f.shard.k == 0 || f.shard.k > n {
            return Err(format!(
                "--merge: shard {}/{n} is not one of 1..={n}",
                f.shard.k
            ));
        }
        if !seen.insert(f.shard.k) {
            return Err(format!("--merge: shard {}/{n} given twice", f.shard.k));
        }
        let same = |a: &Row, b: &Row| {
            (&a.mesh, a.memory, a.chip(), a.folds) == (&b.mesh, b.memory, b.chip(), b.folds)
        };
        if f.rows.len() != rows.len() || !f.rows.iter().zip(&rows).all(|(a, b)| same(a, b)) {
            return Err(format!(
                "--merge: shard {}/{n}'s rows are not the study's configurations",
                f.shard.k
            ));
        }
        check_counts(f, &mut total)?;
        for (row, r) in rows.iter_mut().zip(&f.rows) {
            row.sums += r.sums;
            row.host += r.host;
        }
    }
    if seen.len() < n {
        let missing = (1..=n)
            .find(|k| !seen.contains(k))
            .expect("fewer seen than N");
        return Err(format!("--merge: shard {missing}/{n} is missing (a study of {n} shards needs all {n} files; {} given)", files.len()));
    }
    Ok((plan, rows))
}

/// Refuses counts no study writes, on which the sums and the table's rates would overflow:
/// a row's misses are exact pairs the chip missed, and all rows of all shards together
/// (`total`, which this adds `f`'s rows to) count fewer than 2^64 of each thing.
fn check_counts(f: &ShardFile, total: &mut Sums) -> Result<(), String> {
    let shard = format!("--merge: shard {}/{}", f.shard.k, f.shard.n);
    for r in &f.rows {
        if r.sums.misses > r.sums.exact_pairs {
            return Err(format!(
                "{shard}, {} k = {} {}: {} misses of {} exact pairs (a miss is an exact pair the chip did not find): not a shard's output",
                r.mesh, r.k, r.format, r.sums.misses, r.sums.exact_pairs
            ));
        }
        *total = total.checked_add(r.sums).ok_or_else(|| {
            format!("{shard}: the shards' counts add up past 2^64 - 1: not a study's output")
        })?;
    }
    Ok(())
}

/// The Markdown table of docs/explanation/accuracy.md; with `area`, the cells of each configuration's
/// DOP unit and TRI_UNIT ("-" where the RTL is not built in its format). The times are per
/// query: the chip's at its period, the host's measured, end to end; um^2 where the timing
/// table measured both units.
pub fn table(plan: &Plan, rows: &[Row], area: Option<&Area>) -> Result<String, String> {
    let mut columns = vec![
        "mesh",
        "memory",
        "k",
        "format",
        "DOP rounding",
        "stored DOP bits",
        "pair interval: TRI_UNIT / DOP unit",
        "queries",
        "exact pairs / query",
        "DOP tests / query",
        "triangle tests / query",
        "DOP false positives",
        "uncertain",
        "uncertain: degenerate / on plane / bound",
        "misses",
        "extra pairs",
        "memory KiB / query",
        "cycles / query",
        "period ns (how)",
        "chip us",
        "host us (measured)",
        "end to end us",
        "um^2: DOP unit + TRI_UNIT (+ decode)",
    ];
    if area.is_some() {
        columns.push("cells: DOP unit + TRI_UNIT (+ decode)");
    }
    let timing = timing::Table::of(plan.technology)?;
    let mut out = format!(
        "| {} |\n|{}\n",
        columns.join(" | "),
        "---|".repeat(columns.len())
    );
    for row in rows {
        let r = &row.sums;
        let q = r.queries.max(1) as f64;
        let cfg = row.chip();
        let um2 = timing
            .as_ref()
            .and_then(|t| t.datapath_area_um2(&cfg, row.folds))
            .map_or("-".into(), |a| format!("{a:.0}"));
        let _ = write!(
            out,
            "| {} | {} | {} | {} | {} | {} | {} | {} | {:.1} | {:.0} | {:.1} | {:.1}% | {:.2}% | {} / {} / {} | {} | {} | {:.1} | {:.0} | {:.3} {} | {:.1} | {:.1} | {:.1} | {um2} |",
            row.mesh,
            row.memory_name(),
            row.k,
            row.format,
            row.dop_rounding,
            row.dop_bits,
            row.folds,
            r.queries,
            r.exact_pairs as f64 / q,
            r.dop_tests as f64 / q,
            r.tri_tests as f64 / q,
            100.0 * r.dop_false_positive_rate(),
            100.0 * r.uncertain_rate(),
            r.uncertain_degenerate,
            r.uncertain_on_plane,
            r.uncertain_bound,
            r.misses,
            r.extras,
            r.memory_bytes as f64 / q / 1024.0,
            r.cycles as f64 / q,
            row.period_ns,
            row.period_source.name(),
            row.chip_us(),
            row.host_us(),
            row.end_to_end_us(),
        );
        if let Some(a) = area {
            let _ = write!(
                out,
                " {} |",
                a.of(&cfg, row.folds).map_or("-".into(), |c| c.to_string())
            );
        }
        out.push('\n');
    }
    Ok(out)
}

/// The rows as JSON (`cchip accuracy --json`); with `area`, each with its `cells` (as the
/// table's column: null where a unit has no row), for tables made from the data.
pub fn json(rows: &[Row], area: Option<&Area>) -> String {
    let out: Vec<serde_json::Value> = rows
        .iter()
        .map(|row| {
            let mut v = serde_json::to_value(row).expect("serialisable");
            if let (Some(a), Some(o)) = (area, v.as_object_mut()) {
                o.insert("cells".into(), a.of(&row.chip(), row.folds).into());
            }
            v
        })
        .collect();
    serde_json::to_string_pretty(&out).expect("serialisable")
}

/// Each distinct clock of the rows, once: the table's footnote.
pub fn clocks(rows: &[Row]) -> String {
    let mut seen: Vec<String> = vec![];
    for r in rows {
        let fold = if r.folds == Folds::NONE {
            String::new()
        } else {
            format!(", pair intervals {}", r.folds)
        };
        let bits = match r.dop_bits {
            DopBits::Full => String::new(),
            b => format!(", {b}-bit stored DOPs"),
        };
        let line = format!(
            "k = {}, {}, {} DOP rounding{bits}{fold}: {}",
            r.k, r.format, r.dop_rounding, r.clock
        );
        if !seen.contains(&line) {
            seen.push(line);
        }
    }
    seen.join("\n")
}

/// Yosys cells per unit: the file scripts/area-study.sh writes (`unit,cells`, one row per
/// unit, names as in rtl/).
pub struct Area {
    cells: std::collections::HashMap<String, u64>,
}

#[derive(serde::Deserialize)]
struct AreaRow {
    unit: String,
    cells: u64,
}

impl Area {
    pub fn load(path: &std::path::Path) -> Result<Area, String> {
        let what = "write it with scripts/area-study.sh";
        let mut r = csv::Reader::from_path(path)
            .map_err(|e| format!("{}: {e} ({what})", path.display()))?;
        let mut cells = std::collections::HashMap::new();
        for (i, row) in r.deserialize::<AreaRow>().enumerate() {
            let row = row.map_err(|e| {
                format!(
                    "{}:{}: {e}: each row is `unit,cells` ({what})",
                    path.display(),
                    i + 2
                )
            })?;
            cells.insert(row.unit, row.cells);
        }
        Ok(Area { cells })
    }

    /// Cells of the units a configuration changes ([`timing::datapath_units`]: its DOP unit,
    /// TRI_UNIT, and the decode stages of stored DOPs). `None` where the file has no row for
    /// one of them (a format the RTL is not built in, a fold the area study has not synthesized, or a
    /// stored precision whose decode stage the RTL does not build).
    pub fn of(&self, cfg: &ChipConfig, folds: Folds) -> Option<u64> {
        timing::datapath_units(cfg, folds)
            .iter()
            .map(|(u, n)| Some(self.cells.get(u)? * *n as u64))
            .sum()
    }
}

mod figures;
pub use figures::figures;

#[cfg(test)]
mod tests;
