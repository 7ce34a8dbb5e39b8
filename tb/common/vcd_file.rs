//! Traversal VCDs as the testbenches read them: the results they show, the signals a GTKWave
//! save file names.

/// The results a traversal VCD shows: `(cycle, a, b, uncertain)` for every time step
/// (= cycle) with `chip.results.res_valid` high.
pub fn vcd_results(path: &std::path::Path) -> Vec<(u64, u32, u32, bool)> {
    use vcd::{Command, Value};
    let mut p = vcd::Parser::new(std::io::BufReader::new(std::fs::File::open(path).unwrap()));
    let h = p.parse_header().unwrap();
    let id = |n: &str| {
        h.find_var(&["chip", "results", n])
            .unwrap_or_else(|| panic!("no chip.results.{n}"))
            .code
    };
    let ids = [
        id("res_valid"),
        id("res_a"),
        id("res_b"),
        id("res_uncertain"),
    ];
    let num = |v: &[Value]| {
        v.iter()
            .fold(0u64, |a, x| a << 1 | (*x == Value::V1) as u64)
    };
    let (mut cur, mut time, mut out) = ([0u64; 4], None, vec![]);
    let mut flush = |t: Option<u64>, cur: &[u64; 4]| {
        if let Some(t) = t {
            if cur[0] == 1 {
                out.push((t, cur[1] as u32, cur[2] as u32, cur[3] == 1));
            }
        }
    };
    for c in p {
        match c.unwrap() {
            Command::Timestamp(t) => {
                // values hold until they change: every step from the last time to t
                if let Some(t0) = time {
                    for s in t0..t {
                        flush(Some(s), &cur);
                    }
                }
                time = Some(t);
            }
            Command::ChangeVector(i, v) => {
                if let Some(k) = ids.iter().position(|&x| x == i) {
                    cur[k] = num(&v);
                }
            }
            _ => {}
        }
    }
    flush(time, &cur);
    out
}

/// Every signal the GTKWave save file `gtkw` shows (its `chip.<scope>.<name>` lines) is a
/// variable of the VCD at `path`.
pub fn assert_shows(path: &std::path::Path, gtkw: &str) {
    let text = std::fs::read_to_string(gtkw).unwrap();
    let mut p = vcd::Parser::new(std::io::BufReader::new(std::fs::File::open(path).unwrap()));
    let h = p.parse_header().unwrap();
    let mut n = 0;
    for line in text.lines().filter(|l| l.starts_with("chip.")) {
        let name = line.split('[').next().unwrap();
        let parts: Vec<&str> = name.split('.').collect();
        assert!(
            h.find_var(&parts).is_some(),
            "{gtkw}: {name} is not in {}",
            path.display()
        );
        n += 1;
    }
    assert!(n > 0, "{gtkw} shows no signal");
}
