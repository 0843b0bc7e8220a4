mod common;
use cga::euclid::*;
use cga::*;
use common::dd::{Dd, dd3, f3};
fn cnr(c: &Circle<f64>) -> (E3, E3, f64) { c.centre_normal_radius().unwrap() }
#[test]
fn scratch() {
    for &d in &[1.0, 10.0, 1e2, 1e3, 1e4, 1e5, 1.5e5] {
        let c1 = [d, 0.3 * d, -0.2 * d];
        let c2 = add(c1, [0.5, 0.2, 2.0]);
        let (n1, n2) = ([0.0, 0.2, 1.0], [0.3, -0.1, 1.0]);
        let p = Pair::new(Circle::from_centre_normal_radius(c1, n1, 1.0).unwrap(), Circle::from_centre_normal_radius(c2, n2, 1.5).unwrap()).unwrap();
        let q = Pair::new(Circle::<Dd>::from_centre_normal_radius(dd3(c1), dd3(n1), Dd::from_f64(1.0)).unwrap(), Circle::<Dd>::from_centre_normal_radius(dd3(c2), dd3(n2), Dd::from_f64(1.5)).unwrap()).unwrap();
        let a = p.at(0.5);
        let b = q.at(Dd::from_f64(0.5)).unwrap().centre_normal_radius().unwrap();
        let (bc, br) = (f3(b.0), b.2.hi());
        match a {
            Ok(a) => match a.centre_normal_radius() { Ok((ac, _, ar)) =>
            println!("d {d:e}: centre err {:e} radius err {:e} (r {br}) ; /eps rho^k: {:e} {:e}", norm(sub(ac, bc)) / br, (ar - br).abs() / br, (ar-br).abs()/br/(f64::EPSILON*d*d), (ar-br).abs()/br/(f64::EPSILON*d*d*d)),
            Err(e) => println!("d {d:e}: {e}") },
            Err(e) => println!("d {d:e}: {e}"),
        }
        let x = { let (c, n, r) = (bc, f3(b.1), br); let u = perpendicular(n); add(c, scale(u, r)) };
        let nf = p.normal(0.5, x);
        let nd = q.normal(Dd::from_f64(0.5), dd3(x)).map(f3);
        if let (Ok(nf), Ok(nd)) = (nf, nd) { println!("   normal angle err {:e}", norm(cross(nf, nd))); }
    }
    for &delta in &[1e-3, 1e-6, 1e-9, 1e-12, 1e-15] {
        let c1 = [0.0, 0.0, 0.0];
        let c2 = [delta, 0.0, 0.0];
        let (n1, n2) = ([0.0, 0.0, 1.0], [0.0, 0.0, 1.0]);
        let p = Pair::new(Circle::from_centre_normal_radius(c1, n1, 1.0).unwrap(), Circle::from_centre_normal_radius(c2, n2, 1.0 + delta).unwrap()).unwrap();
        let q = Pair::new(Circle::<Dd>::from_centre_normal_radius(dd3(c1), dd3(n1), Dd::from_f64(1.0)).unwrap(), Circle::<Dd>::from_centre_normal_radius(dd3(c2), dd3(n2), Dd::from_f64(1.0+delta)).unwrap()).unwrap();
        let x = cnr(&p.at(0.5).unwrap()); let x = add(x.0, scale(perpendicular(x.1), x.2));
        let nf = p.normal(0.5, x);
        let nd = q.normal(Dd::from_f64(0.5), dd3(x)).map(f3);
        println!("delta {delta:e}: {:?} {:?}", nf, nd);
    }
}
