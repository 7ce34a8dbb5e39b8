//! The memory a query runs against, as parameters: the ideal memory of fixed latency and
//! interval, or DDR SDRAM with banks and pages (WSCG'03's and DATE'05's presets). The
//! models that serve it are [`cycle::memory`](crate::cycle::memory)'s, the testbench memory of every level.

/// The ideal memory: a word moves in `beats = ceil(W / bus_bits)` clocks (W the memory
/// word's bits; one clock without a `bus_bits`); a request accepted at rising edge `t` is
/// answered in the cycle that ends with edge `t + latency + beats - 1` (`mem_resp_valid`
/// high, the chip takes it at that edge); after an accepted request the next is accepted
/// `max(interval, beats)` edges later at the earliest (the memory's throughput is
/// `1 / interval` words per clock, the bus's `1 / beats`). Responses come in request order.
#[derive(Clone, Copy, Debug, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
#[serde(deny_unknown_fields)]
pub struct MemTiming {
    pub latency: u32,
    pub interval: u32,
    #[serde(default)]
    pub bus_bits: Option<u32>,
}

impl Default for MemTiming {
    fn default() -> Self {
        MemTiming {
            latency: 1,
            interval: 1,
            bus_bits: None,
        }
    }
}

impl MemTiming {
    /// Errors unless latency and interval are at least 1 and a bus is at least 1 bit wide.
    pub fn check(&self) -> Result<(), String> {
        if self.latency == 0 || self.interval == 0 {
            return Err(format!(
                "memory latency and interval must be at least 1 clock (got latency {}, interval {})",
                self.latency, self.interval
            ));
        }
        if self.bus_bits == Some(0) {
            return Err(
                "memory bus_bits must be at least 1 (leave it out for a word per clock)".into(),
            );
        }
        Ok(())
    }
}

/// DDR SDRAM (WSCG'03 §4.3, §4.5) as its data sheet states it, in picoseconds: `banks`
/// banks, each with one open row (page) of `page_bytes`; word address a starts at byte
/// `a * word_bytes`, in page `p = a * word_bytes / page_bytes`, bank `p % banks`, row
/// `p / banks` (page interleaving). The data bus moves one beat of `bus_bits` every
/// `beat_ps` (the data rate), in bursts of `burst` beats, so a word of W bits moves in
/// `ceil(W / (bus_bits * burst))` bursts. An access whose bank has its row open takes
/// `hit_ps` from the request to its first burst complete, a closed or other row `miss_ps`.
/// The chip counts these in its own clocks ([`at`](Self::at)), so a chip with a faster
/// clock waits more of its clocks for the same access.
#[derive(Clone, Copy, Debug, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
pub struct Ddr {
    pub banks: u32,
    pub page_bytes: u32,
    pub bus_bits: u32,
    pub burst: u32,
    pub beat_ps: u32,
    pub hit_ps: u32,
    pub miss_ps: u32,
}

/// A [`Ddr`] part's times in the chip's clocks, the unit of the models that serve the chip
/// (the cycle model's, the rust-hdl driver's and `scripts/verilog/chip_tb.v`'s `+ddr`): a
/// burst holds the data bus `burst_clocks` clocks; an access whose bank has its row open
/// costs `hit` clocks from the request to the word complete, a closed or other row `miss`
/// clocks, each counting one burst of data. The part before the data (the command part)
/// overlaps with other banks' transfers and, for reads of a bank's open row, with that
/// bank's earlier reads: a bank takes the next read of its open row a transfer after the
/// last (DDR's tCCD: page-mode reads stream at the bus's rate), and closes its row for a
/// miss only once its last transfer is over. The data bus carries one transfer at a time,
/// in request order.
#[derive(Clone, Copy, Debug, PartialEq, Eq, serde::Serialize)]
pub struct DdrClocks {
    /// The part: its banks, pages, bus and beats a burst.
    pub part: Ddr,
    pub burst_clocks: u32,
    pub hit: u32,
    pub miss: u32,
}

impl Ddr {
    /// WSCG'03 §4.3, §4.5: four 64-bit modules of 133 MHz DDR SDRAM in parallel (a 256-bit
    /// bus, a beat every 3.75 ns), 4 banks, 4 KiB pages across the modules, bursts of 8 (a
    /// node pair's 256 bytes); the paper's chip, at the burst rate (266 MHz), counts a page
    /// hit 8 clocks (the burst, 30 ns) and a page miss 20 (75 ns).
    pub const WSCG03: Ddr = Ddr {
        banks: 4,
        page_bytes: 4096,
        bus_bits: 256,
        burst: 8,
        beat_ps: 3750,
        hit_ps: 30_000,
        miss_ps: 75_000,
    };
    /// DATE'05 §4.1 gives only the bus: 756 bits of DDR2. The rest is our assumption,
    /// DDR2-800 at 5-5-5 (a 2.5 ns memory clock, a beat every 1.25 ns): 8 banks, 8 KiB
    /// pages, bursts of 4 (5 ns), a hit CL + burst = 12.5 + 5 ns, a miss tRP + tRCD + hit
    /// = 12.5 + 12.5 + 17.5 ns (at the paper's 800 MHz: 14 and 34 clocks).
    pub const DATE05: Ddr = Ddr {
        banks: 8,
        page_bytes: 8192,
        bus_bits: 756,
        burst: 4,
        beat_ps: 1250,
        hit_ps: 17_500,
        miss_ps: 42_500,
    };

    /// Banks at most (scripts/verilog/chip_tb.v keeps this many).
    pub const MAX_BANKS: u32 = 64;
    /// Clocks an access may take at most (the testbench counts in 32-bit integers).
    pub const MAX_CLOCKS: u64 = 1 << 20;

    /// The preset of this name (`wscg03`, `date05`).
    pub fn preset(name: &str) -> Option<Ddr> {
        match name {
            "wscg03" => Some(Ddr::WSCG03),
            "date05" => Some(Ddr::DATE05),
            _ => None,
        }
    }

    /// A burst's time on the data bus.
    pub fn burst_ps(&self) -> u64 {
        self.burst as u64 * self.beat_ps as u64
    }

    /// In the clocks of a chip whose period is `clock_ps`: each time rounded up to whole
    /// clocks (a response is taken at a clock edge; a burst holds the bus for whole clocks).
    /// Err if an access would take more than [`MAX_CLOCKS`](Self::MAX_CLOCKS).
    pub fn at(&self, clock_ps: u64) -> Result<DdrClocks, String> {
        let clocks = |ps: u64| ps.div_ceil(clock_ps.max(1));
        if clocks(self.miss_ps as u64) > Ddr::MAX_CLOCKS {
            return Err(format!(
                "DDR memory: a page miss of {} ns is {} clocks at the chip's {} ns, over the {} that the models count: give a slower clock or a faster memory",
                ns(self.miss_ps as u64), clocks(self.miss_ps as u64), ns(clock_ps), Ddr::MAX_CLOCKS
            ));
        }
        Ok(DdrClocks {
            part: *self,
            burst_clocks: clocks(self.burst_ps()) as u32,
            hit: clocks(self.hit_ps as u64) as u32,
            miss: clocks(self.miss_ps as u64) as u32,
        })
    }

    /// Errors name the parameter out of range.
    pub fn check(&self) -> Result<(), String> {
        for (n, v) in [
            ("banks", self.banks),
            ("page_bytes", self.page_bytes),
            ("bus_bits", self.bus_bits),
            ("burst", self.burst),
            ("beat_ns", self.beat_ps),
        ] {
            if v == 0 {
                return Err(format!("DDR memory: {n} must be more than 0"));
            }
        }
        if self.banks > Ddr::MAX_BANKS {
            return Err(format!(
                "DDR memory: at most {} banks (got {})",
                Ddr::MAX_BANKS,
                self.banks
            ));
        }
        if (self.hit_ps as u64) < self.burst_ps() || self.miss_ps < self.hit_ps {
            return Err(format!(
                "DDR memory: need burst x beat_ns <= hit_ns <= miss_ns (a hit includes one burst of data; got {} x {} ns, hit {} ns, miss {} ns)",
                self.burst, ns(self.beat_ps as u64), ns(self.hit_ps as u64), ns(self.miss_ps as u64)
            ));
        }
        Ok(())
    }
}

/// Nanoseconds to the picosecond (at least 1 ps): a clock period in the unit the models
/// count a DDR part's times in.
pub fn ps(ns: f64) -> u64 {
    (ns * 1000.0).round().max(1.0) as u64
}

/// Picoseconds as nanoseconds, without trailing zeros (17500 -> "17.5").
pub fn ns(ps: u64) -> String {
    let s = format!("{}.{:03}", ps / 1000, ps % 1000);
    s.trim_end_matches('0').trim_end_matches('.').to_string()
}

/// The memory a query runs against: the ideal one of fixed latency and interval, or DDR
/// SDRAM with banks and pages.
#[derive(Clone, Copy, Debug, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
pub enum Memory {
    Ideal(MemTiming),
    Ddr(Ddr),
}

impl Default for Memory {
    fn default() -> Self {
        Memory::Ideal(MemTiming::default())
    }
}

impl From<MemTiming> for Memory {
    fn from(t: MemTiming) -> Self {
        Memory::Ideal(t)
    }
}

impl Memory {
    pub fn check(&self) -> Result<(), String> {
        match self {
            Memory::Ideal(t) => t.check(),
            Memory::Ddr(d) => d.check(),
        }
    }

    /// In the clocks of a chip whose period is `clock_ps` (the ideal memory is in clocks
    /// already).
    pub fn at(&self, clock_ps: u64) -> Result<MemClocks, String> {
        self.check()?;
        Ok(match self {
            Memory::Ideal(t) => MemClocks::Ideal(*t),
            Memory::Ddr(d) => MemClocks::Ddr(d.at(clock_ps)?),
        })
    }

    /// This memory and, for DDR, its timings in the clocks of a chip whose period is
    /// `clock_ps` (both, as `--explain` prints them).
    pub fn describe_at(&self, clock_ps: u64) -> String {
        match self.at(clock_ps) {
            Ok(MemClocks::Ddr(c)) => {
                format!(
                "{self}; at the chip's {} ns clock: a burst {} clock(s), a page hit {}, a miss {}",
                ns(clock_ps), c.burst_clocks, c.hit, c.miss
            )
            }
            Ok(MemClocks::Ideal(_)) => self.to_string(),
            Err(e) => format!("{self} ({e})"),
        }
    }
}

/// A [`Memory`] in the chip's clocks ([`Memory::at`]): what the models that serve the chip
/// run.
#[derive(Clone, Copy, Debug, PartialEq, Eq, serde::Serialize)]
pub enum MemClocks {
    Ideal(MemTiming),
    Ddr(DdrClocks),
}

impl MemClocks {
    pub fn check(&self) -> Result<(), String> {
        match self {
            MemClocks::Ideal(t) => t.check(),
            MemClocks::Ddr(_) => Ok(()),
        }
    }
}

impl From<MemTiming> for MemClocks {
    fn from(t: MemTiming) -> Self {
        MemClocks::Ideal(t)
    }
}

impl std::fmt::Display for Memory {
    fn fmt(&self, f: &mut std::fmt::Formatter) -> std::fmt::Result {
        match self {
            Memory::Ideal(t) => {
                write!(f, "ideal: answers a request after {} clock(s), accepts one every {}", t.latency, t.interval)?;
                match t.bus_bits {
                    Some(b) => write!(f, ", a bus of {b} bits (a word in ceil(word bits / {b}) clocks)"),
                    None => write!(f, ", a word per clock"),
                }
            }
            Memory::Ddr(d) => write!(
                f,
                "DDR SDRAM: {} banks, {}-byte pages, {}-bit bus, bursts of {} beats of {} ns, page hit {} ns and miss {} ns",
                d.banks, d.page_bytes, d.bus_bits, d.burst, ns(d.beat_ps as u64), ns(d.hit_ps as u64), ns(d.miss_ps as u64)
            ),
        }
    }
}
