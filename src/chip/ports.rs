//! The chip's ports, one clock at a time, and the interface every level (the cycle model,
//! rust-hdl, Verilator) implements to be driven by one driver.

/// The chip's inputs in one clock cycle (the RTL's input ports; a memory response names
/// the word address it answers, which a level that needs the data looks up).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct ChipIn {
    pub host_we: bool,
    pub host_addr: u32,
    pub host_data: u32,
    pub start: bool,
    pub mem_req_ready: bool,
    /// `mem_resp_valid`, with the address of the word on `mem_resp_data`.
    pub mem_resp: Option<u32>,
    pub res_ready: bool,
}

/// The chip's outputs in one clock cycle: functions of its registers only, so they show
/// the state after the last rising edge.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct ChipOut {
    pub busy: bool,
    pub done: bool,
    pub overflow: bool,
    pub max_depth: u64,
    pub dop_tests: u64,
    pub tri_tests: u64,
    pub node_fetches: u64,
    pub tri_fetches: u64,
    pub mem_req_valid: bool,
    pub mem_req_addr: u32,
    pub res_valid: bool,
    /// A's triangle, B's triangle.
    pub res_tag: (u32, u32),
    pub res_uncertain: bool,
}

impl ChipOut {
    /// With the values nobody may read zeroed: the request address without a request,
    /// the result's fields without a result.
    pub fn specified(&self) -> ChipOut {
        let mut o = *self;
        if !o.mem_req_valid {
            o.mem_req_addr = 0;
        }
        if !o.res_valid {
            (o.res_tag, o.res_uncertain) = ((0, 0), false);
        }
        o
    }
}

/// The chip at any level: outputs from registers, one rising edge per [`step`](Self::step).
pub trait Clocked {
    /// The outputs in the current cycle.
    fn outputs(&self) -> ChipOut;
    /// Applies `i` for the current cycle and clocks one rising edge. With `probe`, returns
    /// the values of its [`probe_list`](Self::probe_list) in that cycle (inputs applied,
    /// before the edge).
    fn step(&mut self, i: &ChipIn, probe: bool) -> Option<Vec<u64>>;
    /// The traversal signals this chip shows.
    fn probe_list(&self) -> &'static super::probes::Probes;
    /// Why this level cannot go on (a lockstep difference), if so.
    fn fault(&self) -> Option<String> {
        None
    }
    /// Runs this level on its own from the driver's cycle `cyc` (inputs `i`, the memory
    /// served for it), serving `mem` as the driver would, until the driver is needed (a
    /// result shown that was not shown at `cyc`, the end of the query) or cycle `limit`;
    /// returns how many clocks it ran (0: the driver clocks it). The cycle model runs
    /// ([`Chip::wait`](crate::cycle::chip::Chip), skipping where nothing moves:
    /// [`quiet_until`](crate::cycle::chip::Chip::quiet_until)); the other levels leave every
    /// clock to the driver.
    fn wait<M: MemorySide>(
        &mut self,
        _i: &ChipIn,
        _mem: &mut M,
        _cyc: u64,
        _limit: u64,
    ) -> Result<u64, String> {
        Ok(0)
    }
}

/// The memory as the driver serves it, for a level that serves it itself while it
/// [`wait`](Clocked::wait)s: in a cycle, a response is taken out first, then a
/// request is taken if the memory is ready.
pub trait MemorySide {
    /// A request is taken in cycle `cyc`.
    fn ready(&self, cyc: u64) -> bool;
    /// The first cycle a request is taken.
    fn next_ready(&self) -> u64;
    /// The response in cycle `cyc` (the word's address), if one is due, taken out.
    fn respond(&mut self, cyc: u64) -> Option<u32>;
    /// The cycle the next response is due.
    fn next_response(&self) -> Option<u64>;
    /// The chip's request for word `addr` in cycle `cyc` (taken if ready); an error if
    /// the word is past the memory image.
    fn request(&mut self, cyc: u64, addr: u32) -> Result<(), String>;
}

impl<C: Clocked + ?Sized> Clocked for &mut C {
    fn outputs(&self) -> ChipOut {
        (**self).outputs()
    }

    fn step(&mut self, i: &ChipIn, probe: bool) -> Option<Vec<u64>> {
        (**self).step(i, probe)
    }

    fn probe_list(&self) -> &'static super::probes::Probes {
        (**self).probe_list()
    }

    fn fault(&self) -> Option<String> {
        (**self).fault()
    }

    fn wait<M: MemorySide>(
        &mut self,
        i: &ChipIn,
        mem: &mut M,
        cyc: u64,
        limit: u64,
    ) -> Result<u64, String> {
        (**self).wait(i, mem, cyc, limit)
    }
}
