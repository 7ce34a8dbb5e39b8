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

/// DDR SDRAM (WSCG'03 §4.3, §4.5): `banks` banks, each with one open row (page) of
/// `page_bytes`; word address a starts at byte `a * word_bytes`, in page
/// `p = a * word_bytes / page_bytes`, bank `p % banks`, row `p / banks` (page interleaving).
/// The chip runs at the data rate: one beat of `bus_bits` per clock, bursts of `burst`
/// beats, so a word of W bits moves in `ceil(W / (bus_bits * burst))` bursts. An access
/// whose bank has its row open costs `hit` clocks from the request to the word complete, a
/// closed or other row `miss` clocks, each counting one burst of data; the part before the
/// data (the command part) overlaps with other banks' transfers, the data bus carries one
/// transfer at a time, in request order.
#[derive(Clone, Copy, Debug, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
pub struct Ddr {
    pub banks: u32,
    pub page_bytes: u32,
    pub bus_bits: u32,
    pub burst: u32,
    pub hit: u32,
    pub miss: u32,
}

impl Ddr {
    /// WSCG'03 §4.3, §4.5: four 64-bit modules of 133 MHz DDR SDRAM in parallel (a 256-bit
    /// bus), 4 banks, 4 KiB pages across the modules, bursts of 8 (a node pair's 256 bytes),
    /// the chip at the burst rate (266 MHz): a page hit 8 clocks, a page miss 20.
    pub const WSCG03: Ddr = Ddr {
        banks: 4,
        page_bytes: 4096,
        bus_bits: 256,
        burst: 8,
        hit: 8,
        miss: 20,
    };
    /// DATE'05 §4.1 gives only the bus: 756 bits of DDR2. The rest is our assumption, DDR2-800
    /// at 5-5-5 with the chip at the data rate (800 MHz, two clocks per memory clock):
    /// 8 banks, 8 KiB pages, bursts of 4, a hit CL + burst = 10 + 4, a miss tRP + tRCD + hit
    /// = 10 + 10 + 14.
    pub const DATE05: Ddr = Ddr {
        banks: 8,
        page_bytes: 8192,
        bus_bits: 756,
        burst: 4,
        hit: 14,
        miss: 34,
    };

    /// Banks at most (scripts/verilog/chip_tb.v keeps this many).
    pub const MAX_BANKS: u32 = 64;

    /// The preset of this name (`wscg03`, `date05`).
    pub fn preset(name: &str) -> Option<Ddr> {
        match name {
            "wscg03" => Some(Ddr::WSCG03),
            "date05" => Some(Ddr::DATE05),
            _ => None,
        }
    }

    /// Errors name the parameter out of range.
    pub fn check(&self) -> Result<(), String> {
        for (n, v) in [
            ("banks", self.banks),
            ("page_bytes", self.page_bytes),
            ("bus_bits", self.bus_bits),
            ("burst", self.burst),
        ] {
            if v == 0 {
                return Err(format!("DDR memory: {n} must be at least 1"));
            }
        }
        if self.banks > Ddr::MAX_BANKS {
            return Err(format!(
                "DDR memory: at most {} banks (got {})",
                Ddr::MAX_BANKS,
                self.banks
            ));
        }
        if self.hit < self.burst || self.miss < self.hit {
            return Err(format!(
                "DDR memory: need burst <= hit <= miss (a hit includes one burst of data; got burst {}, hit {}, miss {})",
                self.burst, self.hit, self.miss
            ));
        }
        Ok(())
    }
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
                "DDR SDRAM: {} banks, {}-byte pages, {}-bit bus, bursts of {}, page hit {} and miss {} clocks",
                d.banks, d.page_bytes, d.bus_bits, d.burst, d.hit, d.miss
            ),
        }
    }
}
