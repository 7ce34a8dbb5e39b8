//! WSCG'03's CollisionChip (§4, Fig. 4) in RTL, unit by unit; the cycle model's event model
//! of the whole chip is [`cycle::wscg03`](crate::cycle::wscg03). So far: the DOP Unit
//! ([`dop_unit`]: `Wscg03DopUnit`, its compare bank and d' memory), the Stack Engine's
//! lists ([`stack_engine`]) and sequencer ([`sequencer`]), the Memory Controller
//! ([`memory_controller`]) and the Triangle Unit's input stage ([`tri_unit`]: `TriInput`);
//! all but TRI_UNIT and the result port joined ([`chip`]: `ChipCore`).

pub mod chip;
pub mod dop_unit;
pub mod memory_controller;
pub mod sequencer;
pub mod stack_engine;
pub mod tri_unit;
