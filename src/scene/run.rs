//! Runs a scene by its [`Plan`]: the units the plan keeps are built and run, the others not
//! at all; [`Activity`] counts what ran, so that tests can prove it.

use super::graph::{Plan, Unit};
use super::record::{CycleRecord, MemoryRecord, PoseRecord};
use super::{CrossCheck, Scene};
use crate::chip::layout::Layout;
use crate::chip::memory::MemClocks;
use crate::chip::reg::Mode;
use crate::chip::timing::Clock;
use crate::chip::wscg03::Architecture;
use crate::cycle::{self, drive::Reader};
use crate::harness::{chip_io, verilator, wscg03_io};
use crate::measure::{fastest_us, parallel_map, TIMING_RUNS};
use crate::pose::ScenePose;
use crate::query::{exact_pairs, Accuracy, Chip};
use crate::traversal::QueryResult;
use crate::traversal::Traversal;
use serde::Serialize;

/// What a scene run built and ran (counted where it happens, not inferred from the
/// outputs).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize)]
pub struct Activity {
    /// Poses queried on the golden model (with the host settling their uncertain pairs;
    /// each timed as the fastest of [`TIMING_RUNS`] runs).
    pub golden_queries: u64,
    /// Exact-oracle queries (all pairs of a pose).
    pub oracle_queries: u64,
    /// Cycle-model queries, and how many of them counted where the clocks went.
    pub cycle_runs: u64,
    pub counted_runs: u64,
    /// Clocks the cycle model stepped or skipped.
    pub cycle_clocks: u64,
    /// Traversal VCD files written.
    pub vcd_files: u64,
    /// Poses run by rust-hdl, and by the exported Verilog.
    pub rtl_runs: u64,
    pub verilog_runs: u64,
}

/// [`Activity`] shared by the poses' threads.
#[derive(Default)]
struct Counts(std::sync::Mutex<Activity>);

impl Counts {
    fn add(&self, f: impl FnOnce(&mut Activity)) {
        f(&mut self.0.lock().expect("a pose's thread panicked"));
    }
}

/// A scene ready to run: meshes loaded, the chip's images built, everything the plan needs
/// checked before anything is simulated.
pub struct Prepared<'s> {
    pub scene: &'s Scene,
    pub plan: Plan,
    /// The images and the host's geometry of both objects ([`Chip::geometry`]).
    pub chip: Chip,
    /// The exported chip's Verilator binary (a Verilog cross-check).
    verilog: Option<std::path::PathBuf>,
}

/// The result of a scene run.
pub struct SceneRun {
    pub records: Vec<PoseRecord>,
    pub activity: Activity,
}

impl<'s> Prepared<'s> {
    /// Loads and checks; errors name the scene. `load` reads a mesh spec (scaled into the
    /// unit cube if the scene says so).
    pub fn new(
        scene: &'s Scene,
        load: impl Fn(&str) -> Result<crate::mesh::Mesh, String>,
    ) -> Result<Self, String> {
        let named = |e: String| format!("{}: {e}", scene.name);
        let plan = Plan::of(scene);
        let wscg03 = scene.architecture == Architecture::Wscg03;
        // DATE'05's RTL chip a cross-check runs, and its order (the scene is refused without one)
        let rtl = plan
            .cross_check
            .filter(|_| !wscg03)
            .map(|_| chip_io::rtl_order(&scene.cfg, scene.traversal, &scene.params))
            .transpose()
            .map_err(named)?;
        let (ma, mb) =
            crate::mesh::pair(&scene.objects.a, &scene.objects.b, &load).map_err(named)?;
        let (a, b) = (ma.triangles_f64(), mb.triangles_f64());
        drop((ma, mb));
        let chip = Chip::of(a, b, scene.cfg).map_err(named)?;
        scene
            .poses
            .iter()
            .try_for_each(|sp| chip.check_pose(&sp.pose))
            .map_err(named)?;
        if let Some((kind, order)) = rtl {
            // the images the RTL reads: node ids and memory words within its widths
            chip_io::QueryImage::new(
                kind,
                &chip.a,
                &chip.b,
                &chip.setup(&scene.poses[0].pose),
                order,
                scene.mode,
                &scene.params,
                &chip.cfg,
            )
            .map_err(named)?;
        }
        if wscg03 && plan.cross_check.is_some() {
            // WSCG'03's RTL chip reads this configuration's images
            let setup = chip.setup(&scene.poses[0].pose);
            let first = scene.mode == Mode::First;
            wscg03_io::chip::query_image(&chip, &setup, first, &scene.params).map_err(named)?;
        }
        let verilog = match plan.cross_check {
            Some(CrossCheck::Verilog) => {
                verilator::check_size(&chip, &scene.params.memory).map_err(named)?;
                let bin = match rtl {
                    Some((kind, _)) => {
                        verilator::chip_binary(kind.name(), || chip_io::verilog(kind))
                    }
                    None => verilator::chip_binary(
                        crate::chip::rtl::WSCG03_CHIP,
                        wscg03_io::chip::verilog,
                    ),
                };
                Some(bin.map_err(named)?)
            }
            _ => None,
        };
        Ok(Prepared {
            scene,
            plan,
            chip,
            verilog,
        })
    }

    /// Runs every pose: the golden queries one at a time (their time is the software's on an
    /// otherwise idle machine, warm: the fastest of [`TIMING_RUNS`] runs of each pose, the
    /// first a warm-up), the rest on every core; `progress` after each pose.
    pub fn run(&self, progress: impl Fn() + Sync) -> Result<SceneRun, String> {
        let s = self.scene;
        let counts = Counts::default();
        let golden: Vec<(QueryResult, f64)> = s
            .poses
            .iter()
            .map(|sp| {
                let timed = fastest_us(|| self.chip.query(&sp.pose, s.mode, s.traversal));
                counts.add(|a| a.golden_queries += 1);
                timed
            })
            .collect();
        let mut records = parallel_map(&s.poses, |i, sp| {
            let r = self.pose(i, sp, &golden[i], &counts);
            progress();
            r
        })
        .into_iter()
        .collect::<Result<Vec<_>, String>>()
        .map_err(|e| format!("{}: {e}", s.name))?;
        // the host's share, one pose at a time (as the golden queries: an otherwise idle machine)
        for (r, sp) in records.iter_mut().zip(&s.poses) {
            if let Some(c) = r.cycles.as_mut() {
                c.add_host(self.chip.host_time(&sp.pose, &c.uncertain_pairs));
            }
        }
        Ok(SceneRun {
            records,
            activity: counts.0.into_inner().expect("a pose's thread panicked"),
        })
    }

    /// One pose after its golden query: the exact oracle and the cycle model (with what
    /// hangs on it) as the plan says.
    fn pose(
        &self,
        i: usize,
        sp: &ScenePose,
        golden: &(QueryResult, f64),
        counts: &Counts,
    ) -> Result<PoseRecord, String> {
        let (res, software_us) = (&golden.0, golden.1);
        let exact = self.plan.runs(Unit::ExactOracle).then(|| {
            counts.add(|a| a.oracle_queries += 1);
            exact_pairs(self.chip.geometry(0), self.chip.geometry(1), &sp.pose)
        });
        let cycles = match self.plan.runs(Unit::DCntr) {
            false => None,
            true => Some(self.cycles(i, sp, res, software_us, counts)?),
        };
        // the chip's answer where its queue overflowed (incomplete), else the golden model's
        // (the cycle model's, checked)
        let answer = cycles
            .as_ref()
            .filter(|c| c.overflow)
            .map(|c| c.answer(&self.chip.host(&sp.pose)));
        Ok(PoseRecord {
            pose: sp.pose,
            distance: sp.distance,
            pair_count: res.pairs.len(),
            accuracy: exact
                .as_ref()
                .map(|x| Accuracy::of(self.scene.mode, answer.as_deref().unwrap_or(&res.pairs), x)),
            exact_pair_count: exact.as_ref().map(Vec::len),
            pairs: self.scene.outputs.pairs.then(|| res.pairs.clone()),
            counters: res.counters,
            cycles,
        })
    }

    fn cycles(
        &self,
        i: usize,
        sp: &ScenePose,
        res: &QueryResult,
        software_us: f64,
        counts: &Counts,
    ) -> Result<CycleRecord, String> {
        if self.scene.architecture == Architecture::Wscg03 {
            return self.stack_cycles(i, sp, res, software_us, counts);
        }
        let (s, plan, chip) = (self.scene, &self.plan, &self.chip);
        let order = s.traversal.order().expect("checked in Prepared::new");
        let setup = chip.setup(&sp.pose);
        let wave = self.waveforms(i);
        // the exported Verilog's ports, recorded from the cycle model's probes
        let mut ports = verilator::PortLog::default();
        let mut observe = |t: u64, v: &[u64]| {
            ports.record(t, v);
            Ok(())
        };
        let rec = cycle::Record {
            counters: plan.runs(Unit::Counters),
            vcd: wave.as_ref().map(|w| w.out()),
            probes: self
                .verilog
                .as_ref()
                .map(|_| &mut observe as &mut cycle::ProbeObserver),
        };
        let (trace, stats) = cycle::run_query(
            chip,
            &setup,
            order,
            s.mode,
            s.params,
            Reader::default(),
            cycle::MAX_CYCLES,
            rec,
        )
        .map_err(|e| format!("pose {i}: {e}"))?;
        counts.add(|a| {
            a.cycle_runs += 1;
            a.counted_runs += stats.is_some() as u64;
            a.cycle_clocks += trace.cycles;
            a.vcd_files += wave.is_some() as u64;
        });
        if plan.runs(Unit::GoldenCheck) {
            let golden_all = match s.mode {
                Mode::All => res.clone(),
                Mode::First => chip.query(&sp.pose, Mode::All, s.traversal),
            };
            // an overflow is the chip's answer (incomplete, flagged), not a disagreement
            if let Err(e) = trace.check(s.mode, &golden_all).or_else(|e| {
                if trace.overflow {
                    Ok(())
                } else {
                    Err(e)
                }
            }) {
                return Err(format!(
                    "pose {i}: the cycle model disagrees with the golden model: {e}"
                ));
            }
        }
        let cross_checked = match plan.cross_check {
            None => None,
            Some(CrossCheck::Rtl) => {
                let speed = crate::chip::rtl::ChipKind::of(
                    &chip.cfg,
                    s.params.dop_interval,
                    s.params.tri_interval,
                    s.params.depth,
                )
                .map_or(1.0, |k| k.rtl_clocks_per_second());
                let hours = trace.cycles as f64 / speed / 3600.0;
                if hours > 0.5 {
                    return Err(format!(
                        "pose {i}: the rust-hdl cross-check would take about {hours:.1} hours ({} clocks at ~{} clocks/s); use smaller meshes (e.g. vectors/scenes/rtl_spheres.toml), cross_check = \"verilog\", or drop cross_check",
                        trace.cycles,
                        speed
                    ));
                }
                let rtl = chip_io::cross_check(
                    chip,
                    &sp.pose,
                    s.mode,
                    s.traversal,
                    s.params,
                    2 * trace.cycles + 1000,
                )
                .map_err(|e| format!("pose {i}: rust-hdl and the cycle model differ: {e}"))?;
                counts.add(|a| a.rtl_runs += 1);
                if rtl != trace {
                    return Err(format!(
                        "pose {i}: rust-hdl's trace differs from the cycle model's:\n{}\n{}",
                        rtl.text(),
                        trace.text()
                    ));
                }
                Some(CrossCheck::Rtl)
            }
            Some(CrossCheck::Verilog) => {
                let bin = self.verilog.as_deref().expect("built in Prepared::new");
                let (kind, _) = chip_io::rtl_order(&chip.cfg, s.traversal, &s.params)
                    .map_err(|e| format!("pose {i}: {e}"))?;
                let image = chip_io::QueryImage::new(
                    kind, &chip.a, &chip.b, &setup, order, s.mode, &s.params, &chip.cfg,
                )
                .map_err(|e| format!("pose {i}: {e}"))?;
                let dir = verilator::work_dir().join(format!("pose{i}"));
                verilator::cross_check(
                    bin,
                    &dir,
                    &image,
                    s.params.memory_clocks()?,
                    2 * trace.cycles + 1000,
                    &ports,
                    &trace,
                )
                .map_err(|e| format!("pose {i}: {e}"))?;
                counts.add(|a| a.verilog_runs += 1);
                Some(CrossCheck::Verilog)
            }
        };
        let mut r = record(
            &chip.layout,
            &trace,
            s.clock.as_ref().expect(CLOCKED),
            s.params.memory_clocks()?,
            software_us,
        );
        (r.stats, r.vcd, r.cross_checked) = (
            stats,
            wave.map(|w| w.0.display().to_string()),
            cross_checked.map(|c| c.to_string()),
        );
        Ok(r)
    }

    /// One pose on WSCG'03's chip clocked as its RTL ([`cycle::wscg03::clocked`]), checked
    /// against the golden list traversal (WSCG'03 Algorithm 2) and, if asked, against its
    /// rust-hdl chip or its exported Verilog clock by clock.
    fn stack_cycles(
        &self,
        i: usize,
        sp: &ScenePose,
        res: &QueryResult,
        software_us: f64,
        counts: &Counts,
    ) -> Result<CycleRecord, String> {
        let (s, chip) = (self.scene, &self.chip);
        let (setup, first) = (chip.setup(&sp.pose), s.mode == Mode::First);
        let max = cycle::MAX_CYCLES;
        let mut ports = verilator::PortLog::default();
        let see = |t, o: &_, i: &_| ports.record_ports(t, o, i);
        let wave = self.waveforms(i);
        let vcd = wave.as_ref().map(|w| w.out());
        let run = cycle::wscg03::clocked::run(chip, &setup, (first, &s.params), max, see, vcd)
            .map_err(|e| format!("pose {i}: {e}"))?;
        counts.add(|a| {
            a.cycle_runs += 1;
            a.counted_runs += 1;
            a.cycle_clocks += run.trace.cycles;
            a.vcd_files += wave.is_some() as u64;
        });
        if self.plan.runs(Unit::GoldenCheck) {
            let golden = match (s.mode, s.traversal) {
                (Mode::All, Traversal::List) => res.clone(),
                _ => chip.query(&sp.pose, Mode::All, Traversal::List),
            };
            if let Err(e) = run.trace.check(s.mode, &golden) {
                return Err(format!(
                    "pose {i}: WSCG'03's chip disagrees with the golden list traversal: {e}"
                ));
            }
        }
        let cross_checked = match self.plan.cross_check {
            None => None,
            Some(CrossCheck::Rtl) => {
                let hours = run.trace.cycles as f64
                    / crate::chip::rtl::WSCG03_RTL_CLOCKS_PER_SECOND
                    / 3600.0;
                if hours > 0.5 {
                    return Err(format!(
                        "pose {i}: the rust-hdl cross-check would take about {hours:.1} hours ({} clocks at ~{} clocks/s); use smaller meshes, cross_check = \"verilog\", or drop cross_check",
                        run.trace.cycles,
                        crate::chip::rtl::WSCG03_RTL_CLOCKS_PER_SECOND
                    ));
                }
                let max = 2 * run.trace.cycles + 1000;
                let rtl = wscg03_io::chip::cross_check(chip, &setup, (first, &s.params), max, None)
                    .map_err(|e| format!("pose {i}: rust-hdl and the clocked chip differ: {e}"))?;
                counts.add(|a| a.rtl_runs += 1);
                if rtl != run.trace {
                    return Err(format!(
                        "pose {i}: rust-hdl's trace differs from the clocked chip's:\n{}\n{}",
                        rtl.text(),
                        run.trace.text()
                    ));
                }
                Some(CrossCheck::Rtl)
            }
            Some(CrossCheck::Verilog) => {
                let bin = self.verilog.as_deref().expect("built in Prepared::new");
                let (_, image) = wscg03_io::chip::query_image(chip, &setup, first, &s.params)
                    .map_err(|e| format!("pose {i}: {e}"))?;
                let dir = verilator::work_dir().join(format!("pose{i}"));
                let memory = s.params.memory_clocks()?;
                let max = 2 * run.trace.cycles + 1000;
                verilator::cross_check(bin, &dir, &image, memory, max, &ports, &run.trace)
                    .map_err(|e| format!("pose {i}: {e}"))?;
                counts.add(|a| a.verilog_runs += 1);
                Some(CrossCheck::Verilog)
            }
        };
        let mut r = record(
            &chip.layout,
            &run.trace,
            s.clock.as_ref().expect(CLOCKED),
            s.params.memory_clocks()?,
            software_us,
        );
        r.wscg03 = Some(crate::scene::record::StackRecord {
            booked: run.booked,
            lists: run.lists,
            tri_fetches_a: run.tri_fetches_a,
        });
        r.cross_checked = cross_checked.map(|c| c.to_string());
        r.vcd = wave.map(|w| w.0.display().to_string());
        Ok(r)
    }

    /// Pose `i`'s traversal VCD, if the scene writes waveforms: its path and what it holds.
    fn waveforms(&self, i: usize) -> Option<PoseVcd<'_>> {
        let w = (self.scene.outputs.waveforms.as_ref())
            .filter(|_| self.plan.runs(Unit::WaveformWriter))?;
        Some(PoseVcd(w.dir.join(format!("pose{i}.vcd")), w))
    }
}

/// A pose's traversal VCD: its path, the scene's waveforms.
struct PoseVcd<'s>(std::path::PathBuf, &'s crate::scene::Waveforms);

impl PoseVcd<'_> {
    fn out(&self) -> cycle::VcdOut<'_> {
        cycle::VcdOut(&self.0, &self.1.scopes, self.1.window.clone())
    }
}

/// A scene whose outputs run the chip has its clock ([`Scene::clock`]).
const CLOCKED: &str = "a scene that runs the cycle model has a clock";

/// A cycle-model trace as a record (no stall counts, VCD or cross-check yet).
fn record(
    layout: &Layout,
    trace: &cycle::drive::ChipTrace,
    clock: &Clock,
    memory_clocks: MemClocks,
    software_us: f64,
) -> CycleRecord {
    let (hits, unc) = trace.pairs();
    CycleRecord {
        cycles: trace.cycles,
        period_ns: clock.period_ns,
        period_source: clock.source,
        chip_us: trace.cycles as f64 * clock.period_ns / 1000.0,
        timing_runs: TIMING_RUNS,
        // the host's share: Prepared::run measures it after every pose ran
        host_setup_us: 0.0,
        settle_us: 0.0,
        end_to_end_us: 0.0,
        software_us,
        hit_pairs: hits,
        uncertain_pairs: unc,
        dop_tests: trace.dop_tests,
        tri_tests: trace.tri_tests,
        max_entries: trace.max_depth,
        overflow: trace.overflow,
        memory: MemoryRecord {
            node_words: trace.node_fetches,
            tri_words: trace.tri_fetches,
            bytes: trace.node_fetches * layout.record_bytes()[0]
                + trace.tri_fetches * layout.record_bytes()[1],
            page_hits: trace.memory.page_hits,
            page_misses: trace.memory.page_misses,
            bank_conflicts: trace.memory.bank_conflicts,
        },
        memory_clocks,
        stats: None,
        wscg03: None,
        vcd: None,
        cross_checked: None,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scene::Flags;

    const BASE: &str = "[objects]\na = \"sphere:80\"\nb = \"torus:60\"\n[chip]\nk = 14\n[sweep]\ndistances = [1.2, 0.6]\norientations = 2\n";

    /// BASE with more `[chip]` keys.
    fn chip(keys: &str) -> String {
        BASE.replace("k = 14\n", &format!("k = 14\n{keys}\n"))
    }

    fn run(outputs: &str) -> (Plan, SceneRun) {
        let s = Scene::parse(&format!("{BASE}[outputs]\n{outputs}"), "test").unwrap();
        let p = Prepared::new(&s, |spec| {
            crate::mesh::resolve(spec).map_err(|e| e.to_string())
        })
        .unwrap();
        let r = p.run(|| ()).unwrap();
        (p.plan, r)
    }

    fn vcd_dir(tag: &str) -> std::path::PathBuf {
        std::env::temp_dir().join(format!("cchip-plan-{tag}-{}", std::process::id()))
    }

    /// What was not asked for is not built: counted where each unit runs.
    #[test]
    fn only_what_the_outputs_need_runs() {
        let (plan, pairs) = run("");
        let kept: Vec<Unit> = plan.kept.iter().copied().collect();
        assert_eq!(
            kept,
            [
                Unit::Meshes,
                Unit::HostTrees,
                Unit::HostSetup,
                Unit::Golden,
                Unit::HostSettle,
                Unit::OutPairs
            ]
        );
        assert_eq!(
            pairs.activity,
            Activity {
                golden_queries: 4,
                ..Default::default()
            }
        );
        assert!(pairs
            .records
            .iter()
            .all(|r| r.cycles.is_none() && r.accuracy.is_none()));

        let (_, acc) = run("accuracy = true");
        assert_eq!(
            acc.activity,
            Activity {
                golden_queries: 4,
                oracle_queries: 4,
                ..Default::default()
            }
        );

        let (_, cyc) = run("cycles = true");
        let a = cyc.activity;
        assert_eq!(
            (a.oracle_queries, a.cycle_runs, a.counted_runs, a.vcd_files),
            (0, 4, 4, 0)
        );
        assert!(a.cycle_clocks > 1000);

        let dir = vcd_dir("only");
        let (wplan, wave) = run(&format!(
            "waveforms = {{ dir = {:?}, scopes = [\"memory\"], cycles = [10, 40] }}",
            dir.display().to_string()
        ));
        assert!(
            !wplan.runs(Unit::Counters)
                && !wplan.runs(Unit::GoldenCheck)
                && wplan.runs(Unit::WaveformWriter)
        );
        let a = wave.activity;
        assert_eq!(
            (a.oracle_queries, a.cycle_runs, a.counted_runs, a.vcd_files),
            (0, 4, 0, 4)
        );
        let vcd = std::fs::read_to_string(dir.join("pose3.vcd")).unwrap();
        let _ = std::fs::remove_dir_all(&dir);
        assert!(
            vcd.contains("$scope module memory $end") && !vcd.contains("$scope module d_cntr $end"),
            "{vcd}"
        );
        let times: Vec<u64> = vcd
            .lines()
            .filter_map(|l| l.strip_prefix('#')?.parse().ok())
            .collect();
        assert!(
            times.first() == Some(&10) && times.iter().all(|t| (10..=40).contains(t)),
            "{times:?}"
        );

        let (_, mem) = run("memory = true");
        let a = mem.activity;
        assert_eq!(
            (a.oracle_queries, a.cycle_runs, a.counted_runs, a.vcd_files),
            (0, 4, 4, 0)
        );
    }

    /// Asking for more never changes the pairs or the cycles.
    #[test]
    fn more_outputs_change_nothing() {
        let (_, pairs) = run("");
        let (_, cyc) = run("cycles = true");
        let dir = vcd_dir("all");
        let (_, all) = run(&format!(
            "cycles = true\nmemory = true\naccuracy = true\npairs = true\nwaveforms = {:?}",
            dir.display().to_string()
        ));
        let _ = std::fs::remove_dir_all(&dir);
        assert_eq!(all.activity.vcd_files, 4);
        for ((p, c), x) in pairs.records.iter().zip(&cyc.records).zip(&all.records) {
            assert_eq!((p.pair_count, p.counters), (x.pair_count, x.counters));
            let (c, x) = (c.cycles.as_ref().unwrap(), x.cycles.as_ref().unwrap());
            assert_eq!(
                (
                    c.cycles,
                    &c.hit_pairs,
                    &c.uncertain_pairs,
                    c.memory.bytes,
                    c.stats
                ),
                (
                    x.cycles,
                    &x.hit_pairs,
                    &x.uncertain_pairs,
                    x.memory.bytes,
                    x.stats
                )
            );
            assert_eq!(x.memory.bytes > 0, c.cycles > 100);
            // all pairs: the chip's tests are the golden traversal's
            assert_eq!(
                (c.dop_tests, c.tri_tests),
                (p.counters.dop_tests, p.counters.tri_tests)
            );
        }
    }

    /// `--json`: every pose of a cycles scene carries the clock period, the chip's time, the
    /// host's measured setup and settling, and their sum end to end.
    #[test]
    fn json_times_add_up() {
        let s = Scene::parse(&format!("{BASE}[outputs]\ncycles = true"), "test").unwrap();
        let r = Prepared::new(&s, |spec| {
            crate::mesh::resolve(spec).map_err(|e| e.to_string())
        })
        .unwrap()
        .run(|| ())
        .unwrap();
        let v = serde_json::to_value(&r.records).unwrap();
        for p in v.as_array().unwrap() {
            let c = &p["cycles"];
            let f = |k: &str| c[k].as_f64().unwrap_or_else(|| panic!("no {k} in {c}"));
            let close = |a: f64, b: f64| (a - b).abs() <= 1e-12 * b.abs();
            assert_eq!(f("period_ns"), s.clock.as_ref().unwrap().period_ns);
            assert_eq!(
                (c["period_source"].as_str(), c["timing_runs"].as_u64()),
                (Some("estimated"), Some(TIMING_RUNS as u64)),
                "k = 14 has no RTL chip"
            );
            assert!(
                close(f("chip_us"), f("cycles") * f("period_ns") / 1000.0),
                "{c}"
            );
            assert!(f("host_setup_us") > 0.0 && f("settle_us") > 0.0, "{c}");
            assert!(
                close(
                    f("end_to_end_us"),
                    f("host_setup_us") + f("chip_us") + f("settle_us")
                ),
                "{c}"
            );
        }
    }

    #[test]
    fn explain_shows_what_each_scene_builds() {
        let explain = |o: &str| {
            let s = Scene::parse(&format!("{BASE}[outputs]\n{o}"), "test").unwrap();
            Plan::of(&s).explain(&s)
        };
        let pairs = explain("");
        assert!(
            pairs.contains("skipped (not built, not run): exact_oracle, accuracy_counter, d_cntr"),
            "{pairs}"
        );
        for o in [
            "cycles = true",
            "waveforms = \"w\"",
            "accuracy = true",
            "memory = true",
        ] {
            assert_ne!(explain(o), pairs, "{o}");
        }
        assert!(
            explain("cycles = true").contains("stage 6 (clocked together, every clock)\n  d_cntr")
        );
        assert!(!explain("waveforms = \"w\"").contains("  counters "));
        let k6 = BASE.replace("k = 14", "k = 6\nformat = \"reduced\"");
        let rtl =
            Plan::of(&Scene::parse(&format!("{k6}[outputs]\ncross_check = \"rtl\""), "t").unwrap());
        let ver = Plan::of(
            &Scene::parse(&format!("{k6}[outputs]\ncross_check = \"verilog\""), "t").unwrap(),
        );
        assert!(rtl.runs(Unit::RtlChip) && !rtl.runs(Unit::VerilogChip) && rtl.runs(Unit::DCntr));
        assert!(
            ver.runs(Unit::VerilogChip) && !ver.runs(Unit::RtlChip) && !ver.runs(Unit::ExactOracle)
        );
        let s = Scene::parse(BASE, "t").unwrap();
        assert!(Plan::of(&s).dot(&s).contains(
            "exact_oracle [label=\"exact_oracle\\nfunctional\", shape=box, style=\"dashed\""
        ));
        // WSCG'03's chip: both views name its units
        let w = Scene::parse(
            &format!(
                "{}[outputs]\ncycles = true",
                chip("architecture = \"wscg03\"")
            ),
            "t",
        )
        .unwrap();
        let (explain, dot) = (Plan::of(&w).explain(&w), Plan::of(&w).dot(&w));
        for unit in [
            "stack_engine",
            "memory_controller",
            "triangle_unit",
            "pointer_fifo",
        ] {
            assert!(
                explain.contains(&format!("  {unit} "))
                    && dot.contains(&format!("label=\"{unit}\\ncycle\"")),
                "{unit}: {explain}\n{dot}"
            );
        }
    }

    /// The keys of the sections whose use depends on the chip, each with values to try
    /// ([`every_key_is_used_or_refused`]).
    const KEYS: &[(&str, &str, &[&str])] = &[
        ("chip", "architecture", &["\"wscg03\"", "\"date05\""]),
        ("chip", "k", &["6"]),
        ("chip", "format", &["\"e8m15\""]),
        ("chip", "dop_rounding", &["\"nearest-even\""]),
        ("chip", "tri_rounding", &["\"TowardPositive\""]),
        ("chip", "tri_cache", &["4", "1"]),
        ("chip", "tri_cache_b", &["4", "1"]),
        ("chip", "layout", &["\"records\"", "\"words\""]),
        ("chip", "node_cache", &["4", "1"]),
        ("chip", "dop_bits", &["8", "\"full\""]),
        ("timing", "queue_entries", &["4"]),
        ("timing", "dop_latency", &["40"]),
        ("timing", "dop_interval", &["4"]),
        ("timing", "tri_latency", &["90"]),
        ("timing", "tri_fifo", &["1"]),
        ("timing", "tri_interval", &["16"]),
        ("timing", "depth", &["\"fpga\""]),
        ("timing", "issue_spacing", &["1", "2"]),
        ("timing", "credit", &["2"]),
        ("timing", "outstanding", &["4", "1"]),
        ("timing", "prefetch", &["4", "0"]),
        ("timing", "tri_prefetch", &["true", "false"]),
        ("timing", "technology", &["\"paper\""]),
        ("timing", "clock_mhz", &["50"]),
        ("memory", "model", &["\"ddr\"", "\"ideal\""]),
        ("memory", "preset", &["\"wscg03\"", "\"date05\""]),
        ("memory", "latency", &["9"]),
        ("memory", "interval", &["3"]),
        ("memory", "bus_bits", &["16"]),
        ("memory", "banks", &["1"]),
        ("memory", "page_bytes", &["64"]),
        ("memory", "burst", &["1"]),
        ("memory", "beat_ns", &["2.5"]),
        ("memory", "hit_ns", &["30", "40"]),
        ("memory", "miss_ns", &["90"]),
        ("memory", "hit", &["16"]),
        ("memory", "miss", &["90"]),
        ("stack_engine", "sram_latency", &["9"]),
        ("stack_engine", "dotadd_stages", &["20"]),
        ("stack_engine", "data_bus_bits", &["32"]),
        ("stack_engine", "compare_latency", &["9"]),
        ("stack_engine", "word_buffer", &["1"]),
        ("stack_engine", "tri_interval", &["1000"]),
        ("stack_engine", "tri_latency", &["90"]),
    ];

    /// [`KEYS`] holds every key the parser takes in those sections: the list the parser's
    /// own error names for an unknown key (serde's `expected one of`), so a key added to a
    /// section's type and not here fails.
    #[test]
    fn the_key_list_is_every_key_the_parser_takes() {
        // ([stack_engine] takes any key, to refuse it: no scene uses it)
        for section in ["chip", "timing", "memory"] {
            let text = format!("[objects]\na = \"sphere:12\"\nb = \"sphere:12\"\n[[pose]]\nrot_deg = [0, 0, 0]\nt = [0, 0, 0]\n[{section}]\nzz_unknown = 1\n");
            let e = Scene::parse(&text, "s").unwrap_err();
            let (_, expected) = e
                .split_once("expected one of ")
                .unwrap_or_else(|| panic!("[{section}]: {e}"));
            let taken: Vec<&str> = expected.split(", ").map(|k| k.trim_matches('`')).collect();
            assert!(taken.len() > 3, "[{section}]: {e}");
            for key in taken {
                assert!(
                    KEYS.iter().any(|&(s, k, _)| (s, k) == (section, key)),
                    "[{section}] {key} is a key of the parser and not in KEYS"
                );
            }
        }
    }

    /// Every key of every section whose use depends on the chip, written on every preset and
    /// architecture, either is refused (naming its line) or changes what the scene reports:
    /// the chip's clocks, traffic, stalls, pairs or period, or the golden model's counters.
    /// Each key tries its values until one changes the resolved configuration (a preset may
    /// have the first already).
    #[test]
    fn every_key_is_used_or_refused() {
        let scene = |preset: &str, arch: &str, key: Option<(&str, &str, &str)>| {
            let mut sections = vec![("chip", format!("preset = \"{preset}\"\n{arch}"))];
            if let Some((section, k, v)) = key {
                match sections.iter_mut().find(|(s, _)| *s == section) {
                    Some((_, body)) => body.push_str(&format!("\n{k} = {v}")),
                    None => sections.push((section, format!("{k} = {v}"))),
                }
            }
            let body: String = sections
                .iter()
                .map(|(s, b)| format!("[{s}]\n{b}\n"))
                .collect();
            format!("[objects]\na = \"sphere:80\"\nb = \"torus:60\"\n[[pose]]\nrot_deg = [10, 20, 30]\nt = [0.6, 0.1, 0]\n[outputs]\ncycles = true\nmemory = true\n{body}")
        };
        // what a scene reports, its measured times aside
        let report = |s: &Scene| {
            let p = Prepared::new(s, |spec| {
                crate::mesh::resolve(spec).map_err(|e| e.to_string())
            })
            .unwrap();
            let mut v = serde_json::to_value(p.run(|| ()).unwrap().records).unwrap();
            for r in v.as_array_mut().unwrap() {
                for t in ["software_us", "host_setup_us", "settle_us", "end_to_end_us"] {
                    r["cycles"].as_object_mut().unwrap().remove(t);
                }
            }
            v
        };
        let mut used = 0;
        for preset in ["rtl", "date05", "wscg03"] {
            for arch in ["", "architecture = \"date05\"", "architecture = \"wscg03\""] {
                let base = Scene::parse(&scene(preset, arch, None), "s").unwrap();
                let base_report = report(&base);
                for &(section, key, values) in KEYS {
                    if section == "chip" && key == "architecture" && !arch.is_empty() {
                        continue;
                    }
                    let tried = values.iter().map(|v| {
                        (
                            v,
                            Scene::parse(&scene(preset, arch, Some((section, key, v))), "s"),
                        )
                    });
                    let changed = tried.clone().find(|(_, r)| {
                        r.as_ref()
                            .map_or(true, |s| s.configuration() != base.configuration())
                    });
                    let (v, parsed) = changed.unwrap_or_else(|| panic!("{preset} {arch}: [{section}] {key} = {values:?} accepted and resolved to the same configuration"));
                    match parsed {
                        Err(e) => assert!(
                            e.contains(&format!("[{section}] {key}")),
                            "{preset} {arch}: {key} = {v}: {e}"
                        ),
                        // a rounding moves a verdict only at a boundary, which this pose
                        // does not reach, and where the slowest unit's period does not move
                        // with it (both DOP roundings run on one chip; T.CHECK rounding up
                        // has no chip, and the DOP unit's 7.135 ns sets its estimate as the
                        // chip's) the report is the same: its use is the configuration's
                        Ok(s) if key.ends_with("_rounding") => {
                            assert_ne!(s.configuration(), base.configuration());
                            used += 1;
                        }
                        Ok(s) => {
                            assert_ne!(report(&s), base_report, "{preset} {arch}: [{section}] {key} = {v} accepted and changed nothing the scene reports");
                            used += 1;
                        }
                    }
                }
            }
        }
        assert!(used > 60, "{used}");
        // no output runs the chip: every key that sets it is refused
        for &(section, key, values) in KEYS
            .iter()
            .filter(|k| k.0 != "chip" || k.1 == "architecture")
        {
            let text = format!("[objects]\na = \"sphere:12\"\nb = \"sphere:12\"\n[[pose]]\nrot_deg = [0, 0, 0]\nt = [0, 0, 0]\n[{section}]\n{key} = {}\n", values[0]);
            let e = Scene::parse(&text, "s").unwrap_err();
            assert!(
                e.starts_with(&format!(
                    "s:8: [{section}] {key} sets the chip the cycle model runs"
                )),
                "{e}"
            );
        }
    }

    /// What `run` refuses before it builds anything, the scene refuses: `--explain` and
    /// `--dot` read the same scene, so they refuse it too (a format WSCG'03's chip does not
    /// stream, a scope it has not, the list traversal on D_CNTR, a cross-check of a
    /// configuration no RTL chip has).
    #[test]
    fn explain_refuses_what_run_refuses() {
        let refused =
            |text: String, flags: Flags| Scene::parse_with(&text, "t", flags).unwrap_err();
        let wscg03 = chip("architecture = \"wscg03\"");
        let e = refused(
            format!("{wscg03}[outputs]\nwaveforms = {{ dir = \"w\", scopes = [\"d_cntr\"] }}"),
            Flags::default(),
        );
        assert!(
            e.contains(
                "[outputs] waveforms: no scope \"d_cntr\"; the scopes are host, stack_engine"
            ),
            "{e}"
        );
        let e = refused(
            wscg03.replace("architecture", "format = \"reduced\"\narchitecture"),
            Flags {
                waveforms: Some("w".into()),
                ..Default::default()
            },
        );
        assert!(
            e.starts_with("t:6: [chip] format: WSCG'03's chip streams eight binary32"),
            "{e}"
        );
        let e = refused(
            format!("{BASE}[query]\ntraversal = \"list\"\n[outputs]\ncycles = true"),
            Flags::default(),
        );
        assert!(e.starts_with("t:10: [query] traversal: cycles, memory, waveforms and cross-checks come from DATE'05's D_CNTR") && e.contains("not list:"), "{e}");
        let e = refused(
            BASE.into(),
            Flags {
                cross_check: Some(CrossCheck::Rtl),
                ..Default::default()
            },
        );
        assert!(
            e.starts_with("t: --rtl: cross_check = \"rtl\" needs an RTL chip")
                && e.contains("k = 14"),
            "{e}"
        );
        let e = refused(
            format!(
                "{}[outputs]\ncross_check = \"verilog\"",
                BASE.replace("k = 14", "k = 6\nformat = \"reduced\"\nnode_cache = 16")
            ),
            Flags::default(),
        );
        assert!(e.contains("needs an RTL chip of the configuration"), "{e}");
        // the list traversal without the chip: the golden model alone
        assert!(Scene::parse_with(
            &format!("{BASE}[query]\ntraversal = \"list\""),
            "t",
            Flags::default()
        )
        .is_ok());
    }
}
