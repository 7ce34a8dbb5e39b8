//! k-DOPs: the fixed normal sets and the DOP trees the host builds per object (the
//! per-pose setup is [`golden::host`](crate::golden::host)).

pub mod normals;
pub mod stored;
pub mod tree;
pub mod values;

pub use normals::DopNormals;
pub use tree::{Dop, DopTree, Node};
pub use values::Values;

/// Asks the CPU to bring the cache line at `x` (and the next: a node's row or a triangle
/// spans two) into its caches ahead of a read: software only, no effect on any value.
#[inline(always)]
pub fn prefetch<T>(x: *const T) {
    #[cfg(target_arch = "x86_64")]
    {
        use std::arch::x86_64::{_mm_prefetch, _MM_HINT_T0};
        let p = x as *const i8;
        // SAFETY: SSE is part of x86_64's baseline; a prefetch reads nothing the program
        // sees and never faults, whatever the address.
        unsafe {
            _mm_prefetch::<_MM_HINT_T0>(p);
            _mm_prefetch::<_MM_HINT_T0>(p.wrapping_add(64));
        }
    }
    #[cfg(not(target_arch = "x86_64"))]
    let _ = x;
}
