//! A query of the RTL set ([`ChipQuery`]: the queries that run on the rust-hdl chips,
//! tb/rtl_chip.rs, and, from `vectors/chip/`, on their Verilog) and what it is prepared
//! into; the set itself is `query_lists`.

use super::QueryImage;
use crate::chip::config::{ChipConfig, DopRounding, MemLayout};
use crate::chip::memory::MemTiming;
use crate::chip::reg::Mode;
use crate::chip::reg::Order;
use crate::chip::rtl::{self as chips, ChipKind};
use crate::chip::wscg03::Architecture;
use crate::cycle::drive::Reader;
use crate::harness::wscg03_io::chip::query_image as wscg03_image;
use crate::pose::Pose;
use crate::traversal::QueryResult;

/// A query of the RTL test set: two meshes, a pose, order, mode and memory timing. The
/// same set runs in rust-hdl (tb/rtl_chip.rs) and, from `vectors/chip/`, in Verilog.
#[derive(Clone, Debug)]
pub struct ChipQuery {
    pub name: &'static str,
    /// Built-in mesh names ([`crate::mesh::builtin`]), or `bunny-patch:N`: the N bunny
    /// triangles whose centroids are nearest to triangle 0's.
    pub a: &'static str,
    pub b: &'static str,
    pub pose: crate::pose::Pose,
    /// The chip that runs it: DATE'05's chip of this kind or, with `architecture` wscg03,
    /// WSCG'03's (its memory image that of this kind in the `records` layout).
    pub chip: ChipKind,
    pub architecture: Architecture,
    pub order: Order,
    pub mode: Mode,
    pub timing: MemTiming,
    /// How the host reads results.
    pub reader: Reader,
    /// The memory port (register [`PORT`](crate::chip::reg::PORT)): node pairs prefetched, requests outstanding at
    /// most, clocks between DOP issues (1: the queue's second write port), the credit.
    pub prefetch: u32,
    pub outstanding: u32,
    pub issue_spacing: u32,
    pub credit: u32,
    /// Lines of A's triangle cache (register [`TRI_CACHE`](crate::chip::reg::TRI_CACHE); 1: the single word held).
    pub tri_cache: u32,
    /// The memory layout (register [`MODE`](crate::chip::reg::MODE) bit 2; `records` on a chip that reads it).
    pub layout: MemLayout,
    /// The DOP lanes' rounding (bit 15 of their setup words; outward unless the name says `rne`).
    pub dop_rounding: DopRounding,
    /// Too long for rust-hdl (more than 500 s at [`ChipKind::rtl_clocks_per_second`]): its
    /// trace comes from the cycle model, and Verilator must reproduce it.
    pub large: bool,
}

/// The triangles of a [`ChipQuery`] mesh spec.
pub fn query_mesh(spec: &str) -> Result<Vec<crate::dop::tree::Tri>, String> {
    if let Some(n) = spec.strip_prefix("bunny-patch:") {
        let n: usize = n
            .parse()
            .map_err(|_| format!("`{spec}`: the patch size is not a number"))?;
        let tris = crate::mesh::builtin("bunny")
            .map_err(|e| e.to_string())?
            .triangles_f64();
        let c = |t: &crate::dop::tree::Tri| (t[0].coords + t[1].coords + t[2].coords) / 3.0;
        let c0 = c(&tris[0]);
        let mut idx: Vec<usize> = (0..tris.len()).collect();
        idx.sort_by(|&i, &j| {
            (c(&tris[i]) - c0)
                .norm()
                .total_cmp(&(c(&tris[j]) - c0).norm())
        });
        return Ok(idx[..n.min(tris.len())].iter().map(|&i| tris[i]).collect());
    }
    Ok(crate::mesh::builtin(spec)
        .map_err(|e| e.to_string())?
        .triangles_f64())
}

/// A query ready to run: the golden model's images and all-pairs answer, and the chip's
/// memory image and register writes.
pub struct PreparedQuery {
    pub chip: crate::query::Chip,
    pub golden_all: QueryResult,
    pub image: QueryImage,
}

impl ChipQuery {
    /// The cycle model's parameters of this query: the RTL chip's, with its memory and port.
    pub fn params(&self) -> crate::chip::params::Params {
        crate::chip::params::Params {
            memory: self.timing.into(),
            prefetch: self.prefetch,
            outstanding: self.outstanding,
            issue_spacing: self.issue_spacing,
            credit: self.credit,
            ..crate::chip::params::Params::of(self.chip)
        }
    }

    /// The exported Verilog that runs it (`rtl/<name>.v`).
    pub fn chip_name(&self) -> &'static str {
        match self.architecture {
            Architecture::Date05 => self.chip.name(),
            Architecture::Wscg03 => chips::WSCG03_CHIP,
        }
    }

    pub fn prepare(&self) -> Result<PreparedQuery, String> {
        let cfg = ChipConfig {
            tri_cache: self.tri_cache,
            layout: self.layout,
            dop_rounding: self.dop_rounding,
            ..self.chip.config()
        };
        let chip = crate::query::Chip::new(&query_mesh(self.a)?, &query_mesh(self.b)?, cfg)?;
        let golden_all = chip.query(&self.pose, Mode::All, crate::traversal::Traversal::Fifo);
        if self.architecture == Architecture::Wscg03 {
            let first = self.mode == Mode::First;
            let setup = chip.setup(&self.pose);
            let (_, image) = wscg03_image(&chip, &setup, first, &self.params())?;
            return Ok(PreparedQuery {
                chip,
                golden_all,
                image,
            });
        }
        let image = QueryImage::new(
            self.chip,
            &chip.a,
            &chip.b,
            &chip.setup(&self.pose),
            self.order,
            self.mode,
            &self.params(),
            &cfg,
        )?;
        Ok(PreparedQuery {
            chip,
            golden_all,
            image,
        })
    }
}

/// A small query of mesh `a` against itself on the k = 6 e8m15 chip, its memory port and
/// triangle cache at their reset point, the host reading results at full speed.
pub(super) fn q(
    name: &'static str,
    a: &'static str,
    pose: Pose,
    order: Order,
    mode: Mode,
    latency: u32,
    interval: u32,
) -> ChipQuery {
    ChipQuery {
        name,
        a,
        b: a,
        pose,
        chip: ChipKind::K6E8m15,
        order,
        mode,
        timing: MemTiming {
            latency,
            interval,
            bus_bits: None,
        },
        reader: Reader::default(),
        prefetch: 0,
        outstanding: 1,
        issue_spacing: 2,
        credit: chips::CREDIT as u32,
        tri_cache: 1,
        layout: MemLayout::Words,
        dop_rounding: DopRounding::Outward,
        architecture: Architecture::Date05,
        large: false,
    }
}

/// [`q`], large, the host reading a result every `period` clocks.
pub(super) fn big(
    name: &'static str,
    a: &'static str,
    pose: Pose,
    order: Order,
    mode: Mode,
    latency: u32,
    interval: u32,
    period: u32,
) -> ChipQuery {
    ChipQuery {
        reader: Reader { period },
        large: true,
        ..q(name, a, pose, order, mode, latency, interval)
    }
}
