//! The RTL query set's queries, per chip ([`queries`]), and the files that carry them to
//! the Verilog ([`write_vectors`]).

use super::query_set::{big, q, ChipQuery};
use crate::chip::config::{DopRounding, MemLayout};
use crate::chip::reg::Mode;
use crate::chip::reg::Order::{Fifo, Lifo};
use crate::chip::rtl::ChipKind;
use crate::chip::wscg03::Architecture;
use crate::pose::Pose;
use std::fmt::Write as _;

/// The RTL query set. Small (rust-hdl in lockstep with the cycle model, in `cargo test`):
/// both orders and modes, three memory timings, procedural spheres and a bunny patch
/// against a slightly shifted copy of itself (sure hits and many uncertain pairs), and two
/// spheres apart (the root test only). Large (10^4 to 10^5 cycles; the exported Verilog
/// under Verilator in CI against the cycle model's traces): a few hundred triangles, both
/// orders and modes, several memory timings, a host that reads results slowly enough to
/// stall the traversal, sure hits mixed with uncertain pairs.
pub fn queries() -> Vec<ChipQuery> {
    let p = Poses::new();
    [
        e8m15_k6(&p),
        port(&p),
        tri_cache(&p),
        k24(&p),
        k24_records(&p),
        k24_coded(&p),
        k24r(&p),
        k24_three(
            &p,
            ChipKind::K24E8m15,
            [
                "k24e_apart_lifo_first",
                "k24e_rne_patch_fifo_all",
                "k24e_big_rec_sphere_lifo_cache",
            ],
        ),
        k24_three(
            &p,
            ChipKind::K24E8m10,
            [
                "k24m10_apart_lifo_first",
                "k24m10_rne_patch_fifo_all",
                "k24m10_big_rec_sphere_lifo_cache",
            ],
        ),
        fold16(&p),
        dop6tri32(&p),
        wscg03(&p),
    ]
    .concat()
}

/// The poses of the set (B in A's frame): spheres that overlap, a bunny patch against a
/// slightly shifted copy of itself, and the large queries' spheres.
struct Poses {
    spheres: Pose,
    patch: Pose,
    big_spheres: Pose,
}

impl Poses {
    fn new() -> Self {
        Poses {
            spheres: Pose::new(10.0, 20.0, 30.0, 0.8, 0.1, 0.0),
            patch: Pose::new(0.0, 0.0, 0.0, 0.002, 0.001, 0.0),
            big_spheres: Pose::new(10.0, 20.0, 30.0, 0.9, 0.1, 0.05),
        }
    }
}

/// The k = 6 e8m15 chip at the reset point of its memory port: spheres, a bunny
/// patch and spheres apart (rust-hdl), and large queries (Verilator).
fn e8m15_k6(p: &Poses) -> Vec<ChipQuery> {
    vec![
        q(
            "sphere_fifo_all",
            "sphere:12",
            p.spheres,
            Fifo,
            Mode::All,
            1,
            1,
        ),
        q(
            "sphere_lifo_all",
            "sphere:12",
            p.spheres,
            Lifo,
            Mode::All,
            3,
            2,
        ),
        q(
            "sphere_fifo_first",
            "sphere:12",
            p.spheres,
            Fifo,
            Mode::First,
            2,
            1,
        ),
        q(
            "sphere_lifo_first",
            "sphere:12",
            p.spheres,
            Lifo,
            Mode::First,
            1,
            1,
        ),
        q(
            "bunny_lifo_all",
            "bunny-patch:12",
            p.patch,
            Lifo,
            Mode::All,
            1,
            1,
        ),
        q(
            "bunny_fifo_first",
            "bunny-patch:12",
            p.patch,
            Fifo,
            Mode::First,
            1,
            1,
        ),
        q(
            "apart_lifo_first",
            "sphere:12",
            Pose::new(10.0, 20.0, 30.0, 3.0, 0.1, 0.0),
            Lifo,
            Mode::First,
            1,
            1,
        ),
        // sure hits and uncertain pairs; the FIFO holds about 1,000 entries at its widest
        big(
            "big_sphere_fifo_all",
            "sphere:200",
            p.big_spheres,
            Fifo,
            Mode::All,
            1,
            1,
            1,
        ),
        big(
            "big_sphere_lifo_all",
            "sphere:320",
            p.big_spheres,
            Lifo,
            Mode::All,
            4,
            2,
            1,
        ),
        // the host reads one result in 40 clocks: TRI_UNIT's FIFO fills and the credit
        // stalls the DOP unit
        big(
            "big_patch_lifo_all_slow_host",
            "bunny-patch:300",
            p.patch,
            Lifo,
            Mode::All,
            2,
            1,
            40,
        ),
        // in e8m15 the first sure hit comes after 180 uncertain results (a long first-hit query)
        big(
            "big_patch_fifo_first",
            "bunny-patch:120",
            p.patch,
            Fifo,
            Mode::First,
            3,
            1,
            1,
        ),
        big(
            "big_patch_lifo_first",
            "bunny-patch:300",
            p.patch,
            Lifo,
            Mode::First,
            1,
            1,
            1,
        ),
    ]
}

/// The prefetching memory port (register `reg::PORT`): node words asked for pairs ahead,
/// several requests outstanding, at a memory latency of 8; an issue every clock (both child
/// entries pushed in one) with a credit of 24 to 48 but in the last.
fn port(p: &Poses) -> Vec<ChipQuery> {
    vec![
        ChipQuery {
            prefetch: 6,
            outstanding: 8,
            issue_spacing: 1,
            credit: 32,
            ..q(
                "sphere_lifo_prefetch",
                "sphere:12",
                p.spheres,
                Lifo,
                Mode::All,
                8,
                1,
            )
        },
        ChipQuery {
            prefetch: 3,
            outstanding: 4,
            issue_spacing: 1,
            credit: 24,
            ..q(
                "bunny_fifo_prefetch",
                "bunny-patch:12",
                p.patch,
                Fifo,
                Mode::First,
                8,
                1,
            )
        },
        ChipQuery {
            prefetch: 14,
            outstanding: 16,
            issue_spacing: 1,
            credit: 48,
            ..big(
                "big_sphere_lifo_prefetch",
                "sphere:320",
                p.big_spheres,
                Lifo,
                Mode::All,
                8,
                1,
                1,
            )
        },
        ChipQuery {
            prefetch: 14,
            outstanding: 16,
            ..big(
                "big_sphere_fifo_prefetch",
                "sphere:200",
                p.big_spheres,
                Fifo,
                Mode::All,
                8,
                1,
                1,
            )
        },
    ]
}

/// A's triangle cache (register `reg::TRI_CACHE`): 4 lines, so that lines are shared and
/// replaced, at full speed (rust-hdl); 128 lines (WSCG'03) on a bunny patch.
fn tri_cache(p: &Poses) -> Vec<ChipQuery> {
    vec![
        ChipQuery {
            prefetch: 6,
            outstanding: 8,
            issue_spacing: 1,
            credit: 32,
            tri_cache: 4,
            ..q(
                "sphere_fifo_cache",
                "sphere:12",
                p.spheres,
                Fifo,
                Mode::All,
                8,
                1,
            )
        },
        ChipQuery {
            prefetch: 14,
            outstanding: 16,
            issue_spacing: 1,
            credit: 48,
            tri_cache: 128,
            ..big(
                "big_patch_lifo_cache",
                "bunny-patch:300",
                p.patch,
                Lifo,
                Mode::All,
                8,
                1,
                1,
            )
        },
    ]
}

/// The papers' chip (k = 24, binary32): the root test only (Icarus), a short first-hit
/// query at full speed (rust-hdl), whole queries at full speed and at the reset point.
fn k24(p: &Poses) -> Vec<ChipQuery> {
    vec![
        ChipQuery {
            chip: ChipKind::K24B32,
            ..q(
                "k24_apart_lifo_first",
                "sphere:12",
                Pose::new(10.0, 20.0, 30.0, 3.0, 0.1, 0.0),
                Lifo,
                Mode::First,
                1,
                1,
            )
        },
        ChipQuery {
            chip: ChipKind::K24B32,
            prefetch: 3,
            outstanding: 4,
            issue_spacing: 1,
            credit: 24,
            ..q(
                "k24_sphere_lifo_first",
                "sphere:12",
                p.spheres,
                Lifo,
                Mode::First,
                8,
                1,
            )
        },
        ChipQuery {
            chip: ChipKind::K24B32,
            prefetch: 14,
            outstanding: 16,
            issue_spacing: 1,
            credit: 48,
            ..big(
                "k24_big_sphere_lifo_prefetch",
                "sphere:320",
                p.big_spheres,
                Lifo,
                Mode::All,
                8,
                1,
                1,
            )
        },
        ChipQuery {
            chip: ChipKind::K24B32,
            prefetch: 14,
            outstanding: 16,
            issue_spacing: 1,
            credit: 63,
            ..big(
                "k24_big_sphere_fifo_prefetch",
                "sphere:200",
                p.big_spheres,
                Fifo,
                Mode::All,
                8,
                1,
                1,
            )
        },
        ChipQuery {
            chip: ChipKind::K24B32,
            ..big(
                "k24_big_patch_lifo_first",
                "bunny-patch:300",
                p.patch,
                Lifo,
                Mode::First,
                2,
                1,
                1,
            )
        },
        ChipQuery {
            chip: ChipKind::K24B32,
            prefetch: 14,
            outstanding: 16,
            issue_spacing: 1,
            credit: 48,
            tri_cache: 128,
            ..big(
                "k24_big_sphere_fifo_cache",
                "sphere:200",
                p.big_spheres,
                Fifo,
                Mode::All,
                8,
                1,
                1,
            )
        },
    ]
}

/// The papers' chip reading records of 4-bit stored DOPs (`chip_b32_k24_q4`: a node's
/// children and grandchildren in one record, register `reg::MODE` bits 5:3 the slot field's
/// 3 bits, the decode stage ahead of the DOP unit): a bunny patch at full speed (rust-hdl),
/// a whole query through the 128-line cache (Verilator), spheres apart (the root test:
/// Icarus).
fn k24_coded(p: &Poses) -> Vec<ChipQuery> {
    vec![
        ChipQuery {
            chip: ChipKind::K24B32Q4,
            layout: MemLayout::Records,
            ..q(
                "k24q4_apart_lifo_first",
                "sphere:12",
                Pose::new(10.0, 20.0, 30.0, 3.0, 0.1, 0.0),
                Lifo,
                Mode::First,
                1,
                1,
            )
        },
        ChipQuery {
            chip: ChipKind::K24B32Q4,
            layout: MemLayout::Records,
            prefetch: 3,
            outstanding: 4,
            issue_spacing: 1,
            credit: 24,
            tri_cache: 2,
            ..q(
                "k24q4_patch_fifo_all",
                "bunny-patch:8",
                p.patch,
                Fifo,
                Mode::All,
                8,
                1,
            )
        },
        ChipQuery {
            chip: ChipKind::K24B32Q4,
            layout: MemLayout::Records,
            prefetch: 14,
            outstanding: 16,
            issue_spacing: 1,
            credit: 48,
            tri_cache: 128,
            ..big(
                "k24q4_big_sphere_fifo_cache",
                "sphere:200",
                p.big_spheres,
                Fifo,
                Mode::All,
                8,
                1,
                1,
            )
        },
    ]
}

/// The papers' chip reading the records layout (register `reg::MODE` bit 2: sibling nodes
/// in one 2,048-bit record, triangles in leaf order, one record held per object): a bunny
/// patch through a 2-line triangle cache at full speed (rust-hdl), whole queries at full
/// speed through the 128-line cache and at the reset point.
fn k24_records(p: &Poses) -> Vec<ChipQuery> {
    vec![
        ChipQuery {
            chip: ChipKind::K24B32,
            layout: MemLayout::Records,
            prefetch: 3,
            outstanding: 4,
            issue_spacing: 1,
            credit: 24,
            tri_cache: 2,
            ..q(
                "k24_rec_patch_fifo_all",
                "bunny-patch:4",
                p.patch,
                Fifo,
                Mode::All,
                8,
                1,
            )
        },
        ChipQuery {
            chip: ChipKind::K24B32,
            layout: MemLayout::Records,
            prefetch: 14,
            outstanding: 16,
            issue_spacing: 1,
            credit: 48,
            tri_cache: 128,
            ..big(
                "k24_big_rec_sphere_fifo_cache",
                "sphere:200",
                p.big_spheres,
                Fifo,
                Mode::All,
                8,
                1,
                1,
            )
        },
        ChipQuery {
            chip: ChipKind::K24B32,
            layout: MemLayout::Records,
            ..big(
                "k24_big_rec_patch_lifo_all",
                "bunny-patch:300",
                p.patch,
                Lifo,
                Mode::All,
                2,
                1,
                1,
            )
        },
    ]
}

/// The papers' chip with an e8m15 DOP unit (k24r: format e8m15/binary32): [`k24_three`]'s
/// queries (its patch in rust-hdl too), a whole query at full speed and one at the reset
/// point.
fn k24r(p: &Poses) -> Vec<ChipQuery> {
    let chip = ChipKind::K24E8m15B32;
    let mut v = k24_three(
        p,
        chip,
        [
            "k24r_apart_lifo_first",
            "k24r_rne_patch_fifo_all",
            "k24r_big_rec_sphere_lifo_cache",
        ],
    );
    v.insert(
        2,
        ChipQuery {
            chip,
            prefetch: 14,
            outstanding: 16,
            issue_spacing: 1,
            credit: 63,
            ..big(
                "k24r_big_sphere_fifo_prefetch",
                "sphere:200",
                p.big_spheres,
                Fifo,
                Mode::All,
                8,
                1,
                1,
            )
        },
    );
    v.push(ChipQuery {
        chip,
        ..big(
            "k24r_big_patch_lifo_first",
            "bunny-patch:300",
            p.patch,
            Lifo,
            Mode::First,
            2,
            1,
            1,
        )
    });
    v
}

/// Three queries `names` of a k = 24 chip: the root test (Icarus), a bunny patch at full
/// speed with the DOP lanes rounding to nearest-even and a whole query (in the `records`
/// layout where the chip reads it) through the 128-line triangle cache (Verilator). The whole set of
/// the chips in one narrow format throughout (`chip_e8m15_k24`, k24e; `chip_e8m10_k24`,
/// k24m10), whose units, one macro per format, are each checked in rust-hdl against the
/// golden model (the e8m15 ones also in lockstep in `chip_e8m15_b32_k24` and
/// `chip_e8m15_k6`).
fn k24_three(p: &Poses, chip: ChipKind, names: [&'static str; 3]) -> Vec<ChipQuery> {
    vec![
        ChipQuery {
            chip,
            ..q(
                names[0],
                "sphere:12",
                Pose::new(10.0, 20.0, 30.0, 3.0, 0.1, 0.0),
                Lifo,
                Mode::First,
                1,
                1,
            )
        },
        ChipQuery {
            chip,
            prefetch: 3,
            outstanding: 4,
            issue_spacing: 1,
            credit: 24,
            dop_rounding: DopRounding::NearestEven,
            ..q(names[1], "bunny-patch:4", p.patch, Fifo, Mode::All, 8, 1)
        },
        ChipQuery {
            chip,
            prefetch: 14,
            outstanding: 16,
            issue_spacing: 1,
            credit: 48,
            tri_cache: 128,
            layout: if chip.records() {
                MemLayout::Records
            } else {
                MemLayout::Words
            },
            ..big(
                names[2],
                "sphere:320",
                p.big_spheres,
                Lifo,
                Mode::All,
                8,
                1,
                1,
            )
        },
    ]
}

/// The k = 6 chip with TRI_UNIT folded to a pair every 16 clocks: the root test
/// (Icarus), a bunny patch whose leaf pairs wait for the unit's slots at full speed (rust-hdl),
/// whole queries at full speed and at the reset point (Verilator; rust-hdl runs this chip ten
/// times faster than `chip_e8m15_k6`, so they are not `large`, but only the first two run in
/// rust-hdl).
fn fold16(p: &Poses) -> Vec<ChipQuery> {
    vec![
        ChipQuery {
            chip: ChipKind::K6E8m15Fold16,
            ..q(
                "fold16_apart_lifo_first",
                "sphere:12",
                Pose::new(10.0, 20.0, 30.0, 3.0, 0.1, 0.0),
                Lifo,
                Mode::First,
                1,
                1,
            )
        },
        ChipQuery {
            chip: ChipKind::K6E8m15Fold16,
            prefetch: 3,
            outstanding: 4,
            issue_spacing: 1,
            credit: 24,
            ..q(
                "fold16_patch_fifo_all",
                "bunny-patch:12",
                p.patch,
                Fifo,
                Mode::All,
                8,
                1,
            )
        },
        ChipQuery {
            chip: ChipKind::K6E8m15Fold16,
            prefetch: 14,
            outstanding: 16,
            issue_spacing: 1,
            credit: 48,
            ..q(
                "fold16_sphere_lifo_prefetch",
                "sphere:320",
                p.big_spheres,
                Lifo,
                Mode::All,
                8,
                1,
            )
        },
        ChipQuery {
            chip: ChipKind::K6E8m15Fold16,
            ..q(
                "fold16_patch_lifo_first",
                "bunny-patch:300",
                p.patch,
                Lifo,
                Mode::First,
                1,
                1,
            )
        },
    ]
}

/// The k = 6 chip with both units folded, the DOP unit a pair every 6 clocks and TRI_UNIT every
/// 32 (the chip for an LFE5U-85F), at ASIC depth (`dop6tri32_*`) and FPGA depth
/// (`dop6tri32fpga_*`): the root test (Icarus), a bunny patch at full
/// speed whose pairs wait for both units' slots (rust-hdl), whole queries at full speed and at
/// the reset point (Verilator).
fn dop6tri32(p: &Poses) -> Vec<ChipQuery> {
    let asic = [
        "dop6tri32_apart_lifo_first",
        "dop6tri32_patch_fifo_all",
        "dop6tri32_sphere_lifo_prefetch",
        "dop6tri32_patch_lifo_first",
    ];
    let fpga = [
        "dop6tri32fpga_apart_lifo_first",
        "dop6tri32fpga_patch_fifo_all",
        "dop6tri32fpga_sphere_lifo_prefetch",
        "dop6tri32fpga_patch_lifo_first",
    ];
    let mut qs = dop6tri32_on(p, ChipKind::K6E8m15Dop6Tri32, asic);
    qs.extend(dop6tri32_on(p, ChipKind::K6E8m15Dop6Tri32Fpga, fpga));
    qs
}

/// [`dop6tri32`]'s queries on `chip`, named `names`.
fn dop6tri32_on(p: &Poses, chip: ChipKind, names: [&'static str; 4]) -> Vec<ChipQuery> {
    vec![
        ChipQuery {
            chip,
            ..q(
                names[0],
                "sphere:12",
                Pose::new(10.0, 20.0, 30.0, 3.0, 0.1, 0.0),
                Lifo,
                Mode::First,
                1,
                1,
            )
        },
        ChipQuery {
            chip,
            prefetch: 3,
            outstanding: 4,
            issue_spacing: 1,
            credit: 24,
            ..q(names[1], "bunny-patch:12", p.patch, Fifo, Mode::All, 8, 1)
        },
        ChipQuery {
            chip,
            prefetch: 14,
            outstanding: 16,
            issue_spacing: 1,
            credit: 48,
            ..q(names[2], "sphere:320", p.big_spheres, Lifo, Mode::All, 8, 1)
        },
        ChipQuery {
            chip,
            ..q(
                names[3],
                "bunny-patch:300",
                p.patch,
                Lifo,
                Mode::First,
                1,
                1,
            )
        },
    ]
}

/// Writes `<dir>/<query>.mem` and `<dir>/<query>.host` for every query of [`queries`] and
/// `<dir>/queries.txt` (`name latency interval reader-period chip` per line), the inputs of
/// scripts/run-chip.sh. The expected traces (`<query>.expect`) are the rust-hdl chip's,
/// written by `CCHIP_BLESS=1 cargo test --release --test rtl_chip`.
pub fn write_vectors(dir: &std::path::Path) -> Result<Vec<String>, String> {
    std::fs::create_dir_all(dir).map_err(|e| format!("{}: {e}", dir.display()))?;
    let mut list = String::new();
    let mut written = vec![];
    for q in queries() {
        let p = q.prepare()?;
        for (ext, text) in [
            ("mem", p.image.memory_hex()),
            ("host", p.image.writes_hex()),
        ] {
            let path = dir.join(format!("{}.{ext}", q.name));
            std::fs::write(&path, text).map_err(|e| format!("{}: {e}", path.display()))?;
            written.push(path.display().to_string());
        }
        let _ = writeln!(
            list,
            "{} {} {} {} {}",
            q.name,
            q.timing.latency,
            q.timing.interval,
            q.reader.period,
            q.chip_name()
        );
    }
    let path = dir.join("queries.txt");
    std::fs::write(&path, list).map_err(|e| format!("{}: {e}", path.display()))?;
    written.push(path.display().to_string());
    Ok(written)
}

/// WSCG'03's chip (`chip_wscg03_b32_k24`, its memory in DATE'05's k = 24 binary32 records):
/// spheres apart (the root's test only: Icarus), a bunny patch against itself (every
/// pair tested uncertain) and shifted (sure hits), all pairs and the first hit, on 4 requests
/// outstanding; large, for Verilator: spheres of 200 triangles, all pairs through A's
/// 128-line triangle cache, the host reading a result every 3 clocks.
fn wscg03(p: &Poses) -> Vec<ChipQuery> {
    let w3 = |q: ChipQuery| ChipQuery {
        chip: ChipKind::K24B32,
        architecture: Architecture::Wscg03,
        layout: MemLayout::Records,
        outstanding: 4,
        ..q
    };
    vec![
        w3(q(
            "w3_apart_first",
            "sphere:12",
            Pose::new(10.0, 20.0, 30.0, 3.0, 0.1, 0.0),
            Fifo,
            Mode::First,
            1,
            1,
        )),
        w3(q(
            "w3_self_all",
            "bunny-patch:12",
            Pose::default(),
            Fifo,
            Mode::All,
            5,
            1,
        )),
        w3(q(
            "w3_patch_all",
            "bunny-patch:24",
            p.patch,
            Fifo,
            Mode::All,
            5,
            1,
        )),
        w3(q(
            "w3_patch_first",
            "bunny-patch:24",
            p.patch,
            Fifo,
            Mode::First,
            5,
            1,
        )),
        w3(ChipQuery {
            tri_cache: 128,
            ..big(
                "w3_big_sphere_all_cache",
                "sphere:200",
                p.big_spheres,
                Fifo,
                Mode::All,
                8,
                1,
                3,
            )
        }),
    ]
}
