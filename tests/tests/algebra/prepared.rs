//! Prepared sandwiches: `V.prepare()` (the matrix of `X ↦ V X Ṽ`, computed once) gives the
//! sandwich's value up to rounding, for every versor on every type it acts on, in CGA, PGA
//! and the other algebras; and the matrix is as sparse as klein's (a PGA motor moves a point
//! with 12 multiplications and keeps its weight's).

/// Deterministic values in `[-2, 2)`.
fn value(k: usize) -> f64 {
    let x = (k as u64).wrapping_mul(0x9E37_79B9_7F4A_7C15).rotate_left(17);
    (x >> 11) as f64 / (1u64 << 53) as f64 * 4.0 - 2.0
}

fn norm(c: &[f64]) -> f64 {
    c.iter().map(|x| x * x).sum::<f64>().sqrt()
}

/// Both ways for `rounds` random versors and operands of each named pair: the difference
/// within 64 ε of `|V|² |X|`, the scale of every term of `V X Ṽ`.
macro_rules! agree {
    ($module:path; $($v:ident on $x:ident),* $(,)?) => {{
        use $module as m;
        #[allow(unused_imports)]
        use m::Sandwich as _;
        $(
            for round in 0..50 {
                let v = m::$v::<f64>::from_array(core::array::from_fn(|i| value(round * 101 + i)));
                let xs: Vec<m::$x<f64>> =
                    (0..3).map(|k| m::$x::from_array(core::array::from_fn(|i| value(round * 103 + 37 * k + i)))).collect();
                let prepared = v.prepare();
                let batch = v.apply_to(&xs);
                for (x, b) in xs.iter().zip(&batch) {
                    let (want, got) = (v.sandwich(*x).to_array(), prepared.apply(*x).to_array());
                    let scale = norm(&v.to_array()).powi(2) * norm(&x.to_array());
                    let diff: Vec<f64> = want.iter().zip(&got).map(|(a, b)| a - b).collect();
                    assert!(norm(&diff) <= 64.0 * f64::EPSILON * scale, "{} on {}: {want:?} vs {got:?}", stringify!($v), stringify!($x));
                    assert_eq!(b.to_array(), got, "apply_to is apply");
                }
            }
        )*
    }};
}

#[test]
fn prepared_sandwiches_agree_with_the_sandwich_in_cga() {
    agree!(cga_core; Motor on Vector, Motor on Line, Motor on Circle, Motor on Sphere, Motor on Plane,
        Motor on Bivector, Motor on FlatPoint, Motor on Motor, Rotor on Vector, Rotor on Circle,
        Translator on Vector, Translator on Line, Dilator on Vector, Transversor on Vector, Vector on Vector,
        Vector on Circle);
}

#[test]
fn prepared_sandwiches_agree_with_the_sandwich_in_pga_and_the_other_algebras() {
    agree!(cga_algebras::pga; Motor on Point, Motor on Line, Motor on Plane, Motor on Motor, Plane on Point, Plane on Line);
    agree!(cga_algebras::cga2; Motor on Vector, Rotor on Vector);
    agree!(cga_algebras::vga; Rotor on Vector, Rotor on Bivector, Odd on Vector);
}

#[test]
fn a_pga_motor_moves_a_point_with_klein_s_twelve_multiplications_and_the_weight_s_one() {
    use cga_algebras::pga::{Motor, Point};
    let m = Motor::<f64>::from_array(core::array::from_fn(value));
    // The entries: 3 × 4 for the position rows (three rotation terms and a translation), and
    // one for the weight row, which a motor scales by its norm alone.
    let matrix = <Motor as cga_algebras::pga::Prepare<Point>>::matrix(m);
    assert_eq!(matrix.len(), 13);
    let p = Point::at([1.0, 2.0, 3.0]);
    let (moved, want) = (m.prepare().apply(p).to_array(), cga_algebras::pga::Sandwich::sandwich(m, p).to_array());
    let diff: Vec<f64> = moved.iter().zip(want).map(|(a, b)| a - b).collect();
    assert!(norm(&diff) < 64.0 * f64::EPSILON * norm(&m.to_array()).powi(2) * norm(&p.to_array()));
}
