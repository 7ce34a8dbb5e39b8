use collision_chip::config::ChipConfig;
use collision_chip::format::{Format, Rounding};
use collision_chip::golden::tcheck::{edges, stage1, Certificate};
use collision_chip::query::Chip;
use collision_chip::scene::{sweep_poses, Sweep};
fn main() {
    let fname = std::env::args().nth(1).unwrap_or("e8m15".into());
    let mesh = std::env::args().nth(2).unwrap_or("bunny".into());
    let f: Format = fname.parse().unwrap();
    let r = Rounding::NearestEven;
    let m = collision_chip::mesh::resolve(&mesh).unwrap().scaled_into_unit_cube().unwrap();
    let tris = m.triangles_f64();
    let cfg = ChipConfig { k: 24, format: f.into(), ..Default::default() };
    let chip = Chip::new(&tris, &tris, cfg).unwrap();
    let cert = Certificate::new(f, r);
    println!("cert {:?}", cert);
    let poses = sweep_poses(&Sweep { distances: vec![0.8], orientations: 2, seed: 1 }).unwrap();
    let mut shown = 0;
    let mut stats = [0usize; 4];
    for sp in &poses {
        let setup = chip.setup(&sp.pose);
        println!("beta_ab {:?} beta_ba {:?}", setup.beta_ab, setup.beta_ba);
        let res = chip.query(&sp.pose, collision_chip::traversal::Mode::All, collision_chip::traversal::Traversal::Lifo);
        for &(ta, tb) in res.uncertain.iter() {
            let (a, b) = (&chip.a.tris[ta as usize], &chip.b.tris[tb as usize]);
            let s1 = stage1(f, r, b, &setup.m_ab, setup.beta_ab);
            let t = edges(f, r, &cert, &s1, a);
            let mut s0 = s1; s0.a_err = 0.0;
            let t0 = edges(f, r, &cert, &s0, a);
            stats[0] += 1;
            if t0.result().is_some() { stats[1] += 1; }
            if shown < 3 {
                shown += 1;
                println!("pair {ta},{tb}: alpha {} {} a_err {} result {:?} (without A' {:?})", b.alpha_m, b.alpha_f, s1.a_err, t.result(), t0.result());
                for k in 0..3 { println!("  v{k} {:?} mag {:?} vb {:?}", t.v[k], t.v_mag[k], t.v_bound[k]); }
                for e in 0..3 { println!("  e{e} a {} ({}) b {} ({}) rz {} ({}) s {} ({})", t.a[e], t.a_bound[e], t.b[e], t.b_bound[e], t.rz[e], t.rz_bound[e], t.s[e], t.s_bound[e]); }
            }
        }
    }
    println!("uncertain {} decided without A' {}", stats[0], stats[1]);
}
