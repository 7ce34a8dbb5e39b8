//! D.KLMSEL (DATE'05 Fig. 3, Eq. 10): the operand selection in front of the DOPTRF lanes.
//! Lane i multiplies the three distances of B's DOP that the host's correspondence j_i
//! names (DATE'05 Eq. 6), and compares against A's distance along the opposite normal.

/// The distances `d_j0, d_j1, d_j2` lane i reads of B's DOP `d` under control `j` = `j_i`.
pub fn klmsel(d: &[f64], j: [u8; 3]) -> [f64; 3] {
    [d[j[0] as usize], d[j[1] as usize], d[j[2] as usize]]
}

/// A's distance `e_opp(i)` along the normal opposite B_i (normal i + k/2, mod k).
pub fn opposite(e: &[f64], i: usize) -> f64 {
    e[opposite_lane(e.len(), i)]
}

/// The normal opposite normal `i` of `k`: i + k/2, mod k. Its own inverse, so A's distance
/// `e_g` meets lane `opposite_lane(k, g)`'s d' (WSCG'03's d' memory holds them in this order,
/// [`compare_bundles`](super::dop_unit::compare_bundles)).
pub fn opposite_lane(k: usize, i: usize) -> usize {
    let h = k / 2;
    if i < h {
        i + h
    } else {
        i - h
    }
}
