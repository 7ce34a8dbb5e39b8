//! The exported chip under Verilator as a cross-check level of a scene: the binary is built
//! on demand by scripts/run-chip.sh (from this build's chip Verilog, cached under
//! `target/verilog/verilator/<chip>` while nothing changed), each pose's memory image and
//! register writes go to files, and scripts/verilog/chip_tb.v's `+ports` lines (every output
//! port whenever one changes) are compared with the cycle model's, clock by clock.

use super::chip_io::QueryImage;
use crate::chip::memory::{MemClocks, Memory};
use crate::chip::ports::{ChipIn, ChipOut};
use crate::chip::probes::DATE05;
use crate::cycle::drive::ChipTrace;
use std::path::{Path, PathBuf};

/// Memory words of chip_tb.v's memory (its `DEPTH`).
pub const TB_MEMORY_WORDS: usize = 1 << 16;

/// The exported Verilog under Verilator runs the chip at about this many clocks per second
/// on this project's machine (the hierarchical -O1 build of scripts/run-chip.sh: about 4,000
/// for the k = 6 chip, 2,400 for the k = 24 one on the checked-in queries): for estimates.
pub const VERILATOR_CLOCKS_PER_SECOND: f64 = 2000.0;

/// The ports chip_tb.v prints on a `ports` line, in order, by their [`DATE05`] probes' names.
pub const PORTS: [(&str, &str); 16] = [
    ("host", "busy"),
    ("host", "done"),
    ("host", "overflow"),
    ("d_cntr", "max_depth"),
    ("memory", "req_valid"),
    ("memory", "req_ready"),
    ("memory", "req_addr"),
    ("memory", "resp_valid"),
    ("results", "res_valid"),
    ("results", "res_uncertain"),
    ("results", "res_a"),
    ("results", "res_b"),
    ("counters", "dop_tests"),
    ("counters", "tri_tests"),
    ("counters", "node_fetches"),
    ("counters", "tri_fetches"),
];

fn probe_index(p: (&str, &str)) -> usize {
    DATE05.index(p.0, p.1).expect("every port is a probe")
}

type Ports = [u64; PORTS.len()];

/// The ports of every cycle from 1 on whose values differ from the last recorded ones
/// (what chip_tb.v prints with `+ports`).
#[derive(Debug, Default)]
pub struct PortLog(Vec<(u64, Ports)>);

impl PortLog {
    /// Records cycle `t` from the cycle model's [`DATE05`] values.
    pub fn record(&mut self, t: u64, probes: &[u64]) {
        let mut p = [0; PORTS.len()];
        for (k, &port) in PORTS.iter().enumerate() {
            p[k] = probes[probe_index(port)];
        }
        self.push(t, p);
    }

    /// Records cycle `t` from a level's outputs `o` and inputs `i` (a level without probes:
    /// [`Watch`](crate::cycle::drive::Watch)).
    pub fn record_ports(&mut self, t: u64, o: &ChipOut, i: &ChipIn) {
        let b = |x: bool| x as u64;
        let p = [
            b(o.busy),
            b(o.done),
            b(o.overflow),
            o.max_depth,
            b(o.mem_req_valid),
            b(i.mem_req_ready),
            o.mem_req_addr as u64,
            b(i.mem_resp.is_some()),
            b(o.res_valid),
            b(o.res_uncertain),
            o.res_tag.0 as u64,
            o.res_tag.1 as u64,
            o.dop_tests,
            o.tri_tests,
            o.node_fetches,
            o.tri_fetches,
        ];
        self.push(t, p);
    }

    fn push(&mut self, t: u64, p: Ports) {
        if t > 0 && self.0.last().is_none_or(|l| l.1 != p) {
            self.0.push((t, p));
        }
    }

    fn parse(text: &str) -> Result<PortLog, String> {
        let mut log = PortLog::default();
        for line in text.lines().filter(|l| l.starts_with("ports ")) {
            let v: Vec<u64> = line[6..]
                .split(' ')
                .map(str::parse)
                .collect::<Result<_, _>>()
                .map_err(|e| format!("testbench line {line:?}: {e}"))?;
            let p: Ports = v.get(1..).and_then(|s| s.try_into().ok()).ok_or_else(|| {
                format!(
                    "testbench line {line:?}: expected {} values",
                    PORTS.len() + 1
                )
            })?;
            log.0.push((v[0], p));
        }
        Ok(log)
    }

    /// The first cycle and port at which `self` (the cycle model) and `other` (the Verilog)
    /// differ on a specified value, as a message.
    pub fn first_difference(&self, other: &PortLog) -> Option<String> {
        let qualifier: Vec<Option<usize>> = PORTS
            .iter()
            .map(|&p| {
                DATE05.valid(probe_index(p)).map(|v| {
                    PORTS
                        .iter()
                        .position(|&q| probe_index(q) == v)
                        .expect("qualifiers are ports")
                })
            })
            .collect();
        let specified = |s: &Ports, k: usize| qualifier[k].is_none_or(|q| s[q] == 1);
        let (mut i, mut j) = (0, 0);
        let (mut a, mut b): (Option<Ports>, Option<Ports>) = (None, None);
        while i < self.0.len() || j < other.0.len() {
            let t = self
                .0
                .get(i)
                .map_or(u64::MAX, |e| e.0)
                .min(other.0.get(j).map_or(u64::MAX, |e| e.0));
            if self.0.get(i).is_some_and(|e| e.0 == t) {
                a = Some(self.0[i].1);
                i += 1;
            }
            if other.0.get(j).is_some_and(|e| e.0 == t) {
                b = Some(other.0[j].1);
                j += 1;
            }
            let (Some(x), Some(y)) = (a, b) else {
                return Some(format!(
                    "cycle {t}: only the {} shows its ports",
                    if a.is_some() {
                        "cycle model"
                    } else {
                        "Verilog"
                    }
                ));
            };
            if let Some(k) =
                (0..PORTS.len()).find(|&k| (specified(&x, k) || specified(&y, k)) && x[k] != y[k])
            {
                let (scope, name) = PORTS[k];
                return Some(format!(
                    "cycle {t}: signal chip.{scope}.{name}: cycle model {}, Verilog {}",
                    x[k], y[k]
                ));
            }
        }
        None
    }
}

fn root() -> &'static Path {
    Path::new(env!("CARGO_MANIFEST_DIR"))
}

/// Refuses a chip whose memory image on `memory` does not fit the testbench's memory.
pub fn check_size(chip: &crate::query::Chip, memory: &Memory) -> Result<(), String> {
    let words = chip.image_span(memory) as usize;
    if words > TB_MEMORY_WORDS {
        return Err(format!(
            "the Verilog cross-check's testbench memory holds {TB_MEMORY_WORDS} words and these meshes need {words} (DOP nodes and triangles of both): use meshes of at most a few thousand triangles, or cross-check on the cycle model's level only"
        ));
    }
    Ok(())
}

/// Builds (or finds built) the Verilator binary of the exported chip `name` (its Verilog
/// `verilog()`, this build's); errors say what is missing.
pub fn chip_binary(name: &str, verilog: impl FnOnce() -> String) -> Result<PathBuf, String> {
    let script = root().join("scripts/run-chip.sh");
    if !script.is_file() {
        return Err(format!("the Verilog cross-check needs the collision-chip repository this binary was built from ({} is missing)", script.display()));
    }
    let dir = root().join("target/cchip");
    let v = dir.join(format!("{name}.v"));
    let text = verilog();
    // rewritten only when it changed, so that the build's inputs keep their times
    if std::fs::read_to_string(&v).ok().as_deref() != Some(&text) {
        std::fs::create_dir_all(&dir)
            .and_then(|()| std::fs::write(&v, &text))
            .map_err(|e| format!("{}: {e}", v.display()))?;
    }
    let out = std::process::Command::new("bash")
        .arg(&script)
        .args(["--build-only", "--chip"])
        .arg(&v)
        .current_dir(root())
        .output()
        .map_err(|e| format!("cannot run {}: {e}", script.display()))?;
    if !out.status.success() {
        let err = String::from_utf8_lossy(&out.stderr);
        let tail: Vec<&str> = err.lines().rev().take(15).collect();
        return Err(format!(
            "building the exported chip under Verilator failed (scripts/run-chip.sh --build-only):\n{}",
            tail.into_iter().rev().collect::<Vec<_>>().join("\n")
        ));
    }
    let bin = String::from_utf8_lossy(&out.stdout).trim().to_string();
    Ok(root().join(bin))
}

/// Where a run's pose files go (removed after a pose agrees).
pub fn work_dir() -> PathBuf {
    root().join(format!(
        "target/cchip/verilog-cross-check/{}",
        std::process::id()
    ))
}

/// Runs one pose on the Verilator binary `bin` (files in `dir`) and compares it with the
/// cycle model's `ports` and `trace`: the first difference names the cycle and the port.
pub fn cross_check(
    bin: &Path,
    dir: &Path,
    image: &QueryImage,
    memory: MemClocks,
    max_cycles: u64,
    ports: &PortLog,
    trace: &ChipTrace,
) -> Result<(), String> {
    let minutes = trace.cycles as f64 / VERILATOR_CLOCKS_PER_SECOND / 60.0;
    if minutes > 30.0 {
        return Err(format!("the Verilog cross-check would take about {minutes:.0} minutes ({} clocks at ~{VERILATOR_CLOCKS_PER_SECOND} clocks/s); use smaller meshes", trace.cycles));
    }
    let io = |p: &Path, e: std::io::Error| format!("{}: {e}", p.display());
    std::fs::create_dir_all(dir).map_err(|e| io(dir, e))?;
    let (mem, host) = (dir.join("q.mem"), dir.join("q.host"));
    std::fs::write(&mem, image.memory_hex()).map_err(|e| io(&mem, e))?;
    std::fs::write(&host, image.writes_hex()).map_err(|e| io(&host, e))?;
    let memory_args = match memory {
        MemClocks::Ideal(t) => {
            let mut a = vec![
                format!("+latency={}", t.latency),
                format!("+interval={}", t.interval),
            ];
            a.extend(t.bus_bits.map(|b| format!("+bus_bits={b}")));
            a
        }
        MemClocks::Ddr(d) => {
            vec![
                "+ddr".into(),
                format!("+banks={}", d.part.banks),
                format!("+page_bytes={}", d.part.page_bytes),
                format!("+bus_bits={}", d.part.bus_bits),
                format!("+burst={}", d.part.burst),
                format!("+burst_clocks={}", d.burst_clocks),
                format!("+hit={}", d.hit),
                format!("+miss={}", d.miss),
            ]
        }
    };
    let out = std::process::Command::new(bin)
        .arg(format!("+mem={}", mem.display()))
        .arg(format!("+host={}", host.display()))
        .args(memory_args)
        .arg(format!("+word_bits={}", image.word_bits))
        .arg("+reader=1")
        .arg(format!("+max_cycles={max_cycles}"))
        .arg("+ports")
        .output()
        .map_err(|e| format!("cannot run {}: {e}", bin.display()))?;
    let stdout = String::from_utf8_lossy(&out.stdout);
    if !out.status.success() {
        return Err(format!(
            "{} failed: {}",
            bin.display(),
            String::from_utf8_lossy(&out.stderr)
        ));
    }
    let verilog = PortLog::parse(&stdout)?;
    if let Some(d) = ports.first_difference(&verilog) {
        return Err(format!(
            "the exported Verilog and the cycle model differ at {d} (files in {})",
            dir.display()
        ));
    }
    let text: String = stdout
        .lines()
        .filter(|l| l.starts_with("result ") || l.starts_with("done ") || l.starts_with("timeout"))
        .map(|l| format!("{l}\n"))
        .collect();
    if text != trace.text() {
        return Err(format!("the exported Verilog's trace differs from the cycle model's (files in {}):\n{text}\n{}", dir.display(), trace.text()));
    }
    std::fs::remove_dir_all(dir).map_err(|e| io(dir, e))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// chip_tb.v's memory depth is [`TB_MEMORY_WORDS`], and its `ports` line is [`PORTS`].
    #[test]
    fn testbench_agrees() {
        let tb = include_str!("../../scripts/verilog/chip_tb.v");
        assert!(tb.contains(&format!(
            "localparam DEPTH = 1 << {};",
            TB_MEMORY_WORDS.trailing_zeros()
        )));
        let at = tb
            .find("//   ports <cycle> ")
            .expect("the ports line is documented");
        let doc: Vec<&str> = tb[at..]
            .lines()
            .take(2)
            .flat_map(|l| l.split_whitespace())
            .filter(|w| *w != "//")
            .skip(2)
            .collect();
        assert_eq!(doc, PORTS.iter().map(|p| p.1).collect::<Vec<_>>());
    }

    #[test]
    fn differences_name_the_cycle_and_the_port() {
        let mut a = PortLog::default();
        let mut probes = vec![0u64; DATE05.signals.len()];
        a.record(0, &probes);
        a.record(1, &probes);
        probes[probe_index(("memory", "req_valid"))] = 1;
        probes[probe_index(("memory", "req_addr"))] = 7;
        a.record(3, &probes);
        a.record(4, &probes);
        let same = PortLog(a.0.clone());
        assert_eq!(a.first_difference(&same), None);
        let mut b = PortLog(a.0.clone());
        b.0[1].1[6] = 8;
        assert_eq!(
            a.first_difference(&b).unwrap(),
            "cycle 3: signal chip.memory.req_addr: cycle model 7, Verilog 8"
        );
        // an address without a request is nobody's business
        let mut c = PortLog(a.0.clone());
        c.0[0].1[6] = 5;
        assert_eq!(a.first_difference(&c), None);
        let d = PortLog(a.0[..1].to_vec());
        assert!(a
            .first_difference(&d)
            .unwrap()
            .starts_with("cycle 3: signal chip.memory.req_valid"));
    }
}
