//! The afl program: `cchip-fuzz TARGET` feeds afl's inputs to one target
//! (collision_chip_fuzz::TARGETS); scripts/fuzz.sh runs it.
fn main() {
    let target = std::env::args().nth(1).unwrap_or_default();
    if !collision_chip_fuzz::TARGETS.contains(&target.as_str()) {
        eprintln!(
            "usage: cchip-fuzz TARGET (one of {:?})",
            collision_chip_fuzz::TARGETS
        );
        std::process::exit(2);
    }
    afl::fuzz!(|bytes: &[u8]| {
        let _ = collision_chip_fuzz::run(&target, bytes);
    });
}
