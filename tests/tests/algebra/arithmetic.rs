//! Arithmetic that reads like the maths: scalars on either side, `one()`, inverses, the
//! scalar and commutator products, checked conversions, `cast` and `normalise`'s errors.

use cga_tests::common;

use cga_core::{
    Bivector, Circle, CommutatorProduct, Dilator, Dual, Even, FlatPoint, Generator, Infinity, Line, Motor, Multivector,
    NormaliseError, Odd, Plane, Pseudoscalar, Real, Rotor, Scalar, ScalarProduct, ScalarQuadvector, Sphere, Translator,
    Transversor, TruncationError, Vector, inverse_table, up,
};
use common::{Rng, max_rel_diff};

/// A value of `X` with coefficients uniform in [−2, 2).
fn random<const N: usize, X>(rng: &mut Rng, from_array: fn([f64; N]) -> X) -> X {
    from_array(std::array::from_fn(|_| rng.range(-2.0, 2.0)))
}

/// `x * s`, `s * x` (f64 and f32), `x / s`, `x *= s` and `x /= s` against `scale`, for each
/// listed type.
macro_rules! scaling {
    ($rng:expr, $($ty:ident),*) => {$({
        let x = random($rng, $ty::from_array);
        let s = $rng.range(-3.0, 3.0);
        assert_eq!(x * s, x.scale(s), "{}: x * s", stringify!($ty));
        assert_eq!(s * x, x.scale(s), "{}: s * x", stringify!($ty));
        let x32 = x.cast::<f32>();
        assert_eq!((s as f32) * x32, x32.scale(s as f32), "{}: f32 s * x", stringify!($ty));
        let mut y = x;
        y *= s;
        assert_eq!(y, x.scale(s), "{}: x *= s", stringify!($ty));
        let quotient = $ty::from_array(x.to_array().map(|c| c / s));
        assert_eq!(x / s, quotient, "{}: x / s", stringify!($ty));
        let mut y = x;
        y /= s;
        assert_eq!(y, quotient, "{}: x /= s", stringify!($ty));
        assert!(max_rel_diff(&(x / s).to_array(), &x.scale(1.0 / s).to_array()) < 1e-15);
    })*};
}

#[test]
fn scalars_scale_on_either_side() {
    let mut rng = Rng::new(1);
    for _ in 0..16 {
        scaling!(
            &mut rng,
            Scalar,
            Infinity,
            Vector,
            Bivector,
            FlatPoint,
            Line,
            Circle,
            Plane,
            Sphere,
            Pseudoscalar,
            ScalarQuadvector,
            Rotor,
            Translator,
            Motor,
            Dilator,
            Transversor,
            Generator,
            Even,
            Odd
        );
    }
    // The point in the issue: `2.0 * up(x)` reads as written.
    let p = up([1.0, -2.0, 0.5]);
    assert_eq!(2.0 * p, p.scale(2.0));
    assert_eq!(2.0f32 * up([1.0f32, 0.0, 0.0]), up([1.0f32, 0.0, 0.0]).scale(2.0));
}

/// `x + s`, `s + x`, `x − s` and `s − x` for each `(type, type of the sum)`: the sum is
/// `Sum::from(x) ± s·1`, and the sum's type is the one named (checked by the compiler).
macro_rules! adding {
    ($rng:expr, $($ty:ident => $sum:ident),*) => {$({
        let x = random($rng, $ty::from_array);
        let s = $rng.range(-3.0, 3.0);
        let (wide, one) = ($sum::from(x), $sum::<f64>::one());
        let (plus, plus_left): ($sum, $sum) = (x + s, s + x);
        assert_eq!(plus, wide + one.scale(s), "{}: x + s", stringify!($ty));
        assert_eq!(plus_left, plus, "{}: s + x", stringify!($ty));
        let (minus, minus_left): ($sum, $sum) = (x - s, s - x);
        assert_eq!(minus, wide - one.scale(s), "{}: x - s", stringify!($ty));
        assert_eq!(minus_left, one.scale(s) - wide, "{}: s - x", stringify!($ty));
        let s32 = s as f32;
        let x32 = x.cast::<f32>();
        assert_eq!(s32 - x32, $sum::<f32>::one().scale(s32) - $sum::from(x32), "{}: f32 s - x", stringify!($ty));
    })*};
}

#[test]
fn scalars_add_on_either_side() {
    let mut rng = Rng::new(2);
    for _ in 0..16 {
        adding!(
            &mut rng,
            Scalar => Scalar, ScalarQuadvector => ScalarQuadvector, Rotor => Rotor, Translator => Translator,
            Motor => Motor, Even => Even,
            // Types without `s`: the smallest declared type holding `s` and their blades.
            Bivector => Even, FlatPoint => Dilator, Plane => ScalarQuadvector, Sphere => ScalarQuadvector,
            Generator => Motor, Transversor => Transversor, Dilator => Dilator
        );
    }
    let mut r = Rotor { s: 0.5, e12: 1.0, e13: -2.0, e23: 0.25 };
    assert_eq!(1.0 - r, Rotor { s: 0.5, e12: -1.0, e13: 2.0, e23: -0.25 });
    r += 2.0;
    assert_eq!(r.s, 2.5);
    r -= 0.5;
    assert_eq!(r.s, 2.0);
}

/// Scalars on the right are generic: dual numbers, say.
#[test]
fn scalar_operators_are_generic() {
    fn affine<T: Real>(r: Rotor<T>, a: T, b: T) -> Rotor<T> {
        (r * a + b) / a - b
    }
    let r = Rotor::<Dual> { s: Dual::variable(0.5), e12: Dual::constant(1.0), ..Rotor::zero() };
    let y = affine(r, Dual::constant(2.0), Dual::constant(3.0));
    assert_eq!((y.s.re, y.s.du), (0.5 + 1.5 - 3.0, 1.0));
    assert_eq!(y.e12.re, 1.0);
    let sum: Even<Dual> = Bivector::<Dual>::zero() + Dual::constant(1.0);
    assert_eq!(sum.s.re, 1.0);
}

#[test]
fn one_is_the_unit() {
    let one = Multivector::from(Scalar::<f64>::one());
    assert_eq!(one.coeffs[0], 1.0);
    assert!(one.coeffs[1..].iter().all(|&c| c == 0.0));
    for m in [
        Multivector::from(ScalarQuadvector::<f64>::one()),
        Rotor::<f64>::one().into(),
        Translator::<f64>::one().into(),
        Motor::<f64>::one().into(),
        Even::<f64>::one().into(),
    ] {
        assert_eq!(m, one);
    }
    let motor = Motor::from_rotor_translator(
        Rotor::from_axis_angle([0.0, 0.0, 1.0], 0.3).unwrap(),
        Translator::from_vector([1.0, 2.0, 3.0]),
    );
    assert_eq!(Motor::one() * motor, motor);
    assert_eq!(motor * Rotor::one(), motor);
}

/// The types with a generated inverse: those whose `X X̃` is a scalar for every value.
const INVERTIBLE: [&str; 10] = [
    "Scalar",
    "Vector",
    "FlatPoint",
    "Plane",
    "Sphere",
    "Pseudoscalar",
    "Rotor",
    "Translator",
    "Dilator",
    "Transversor",
];

#[test]
fn inverses_of_every_invertible_type() {
    let table = inverse_table::<f64>();
    let names: Vec<&str> = table.iter().map(|e| e.input).collect();
    assert_eq!(names, INVERTIBLE);
    let mut rng = Rng::new(3);
    let mut one = [0.0; 32];
    one[0] = 1.0;
    for e in &table {
        for _ in 0..64 {
            let mut a = [0.0; 32];
            for &i in e.input_blades {
                a[i] = rng.range(-2.0, 2.0);
            }
            let inv = (e.eval)(&a).unwrap_or_else(|| panic!("{}: no inverse of {a:?}", e.input));
            let (x, y) = (Multivector::from_storage(&a), Multivector::from_storage(&inv));
            // ⟨X X̃⟩₀ can be small for indefinite types: measure against its size.
            let size = x.norm_squared().abs().recip().max(1.0);
            for product in [x * y, y * x] {
                let d = max_rel_diff(&product.to_storage(), &one);
                assert!(d < 1e-13 * size, "{}: X X⁻¹ differs from 1 by {d:e}", e.input);
            }
        }
        // Zero has no inverse.
        assert_eq!((e.eval)(&[0.0; 32]), None, "{}: zero", e.input);
    }
}

#[test]
fn typed_inverses() {
    let v = Vector { e1: 1.0, e2: -0.5, e3: 2.0, eo: 0.25, ei: 3.0 };
    let unit: Even = v * v.try_inverse().unwrap();
    assert!(max_rel_diff(&unit.to_array(), &Even::one().to_array()) < 1e-15);
    let r = Rotor::from_axis_angle([1.0, 2.0, 2.0], 0.7).unwrap().scale(3.0);
    let unit: Rotor = r * r.inverse();
    assert!(max_rel_diff(&unit.to_array(), &Rotor::one().to_array()) < 1e-15);
    let t = Translator::from_vector([1.0, -4.0, 2.0]);
    assert_eq!(t.try_inverse(), Some(Translator::from_vector([-1.0, 4.0, -2.0])));
    // A conformal point is null (X X = 0) and zero is zero: neither has an inverse.
    assert_eq!(up([1.0, 2.0, 3.0]).try_inverse(), None);
    assert_eq!(Vector::<f64>::zero().try_inverse(), None);
    assert_eq!(Sphere::<f64>::zero().try_inverse(), None);
    assert!(!up([1.0, 2.0, 3.0]).inverse().e1.is_finite(), "unchecked: non-finite");
    // Past the range: `⟨X X̃⟩₀` overflows, the result is not finite.
    assert_eq!(Vector { e1: 1e300, ..Vector::zero() }.try_inverse(), None);
}

#[test]
fn scalar_product_is_the_scalar_part() {
    let mut rng = Rng::new(4);
    for _ in 0..32 {
        let (a, b) = (random(&mut rng, Circle::from_array), random(&mut rng, Circle::from_array));
        let full: Even = a * b;
        assert!((a.scalar_product(b) - full.s).abs() < 1e-14);
        let (m, v) = (random(&mut rng, Motor::from_array), random(&mut rng, Rotor::from_array));
        assert!((m.scalar_product(v) - (m * v).s).abs() < 1e-14);
        let (p, q) = (random(&mut rng, Vector::from_array), random(&mut rng, Odd::from_array));
        let full: Even = p * q;
        assert!((p.scalar_product(q) - full.s).abs() < 1e-14);
    }
    // A point with itself: zero (null); with a sphere: the signed power.
    let p = up([1.0, 0.0, 0.0]);
    assert_eq!(p.scalar_product(p), 0.0);
}

#[test]
fn commutator_is_half_the_difference() {
    let mut rng = Rng::new(5);
    for _ in 0..32 {
        let (b, v) = (random(&mut rng, Bivector::from_array), random(&mut rng, Vector::from_array));
        let (db, dv) = (Multivector::from(b), Multivector::from(v));
        let want = (db * dv - dv * db).scale(0.5);
        let got = Multivector::from(b.commutator(v));
        assert!(max_rel_diff(&got.coeffs, &want.coeffs) < 1e-14);
        assert!(max_rel_diff(&db.commutator(dv).coeffs, &want.coeffs) < 1e-14, "dense");
        let (l, m) = (random(&mut rng, Line::from_array), random(&mut rng, Motor::from_array));
        let (dl, dm) = (Multivector::from(l), Multivector::from(m));
        let want = (dl * dm - dm * dl).scale(0.5);
        assert!(max_rel_diff(&Multivector::from(l.commutator(m)).coeffs, &want.coeffs) < 1e-14);
    }
    // Bivectors close under the commutator (a Lie algebra); a rotor's generator commutes
    // with its own plane.
    let b = Bivector { e12: 1.0, e13: -0.5, ..Bivector::zero() };
    let _: Bivector = b.commutator(b);
    assert_eq!(b.commutator(b), Bivector::zero());
}

#[test]
fn conversions_refuse_to_drop_coefficients() {
    let motor = Motor::from_rotor_translator(
        Rotor::from_axis_angle([0.0, 1.0, 0.0], 1.1).unwrap(),
        Translator::from_vector([0.5, 0.0, -2.0]),
    );
    // An even element that is exactly a motor converts back, exactly.
    let even = Even::from(motor);
    assert_eq!(Motor::try_from(even), Ok(motor));
    let mut bad = even;
    (bad.e1o, bad.e2o) = (0.5, -1.0);
    let err = Motor::try_from(bad).unwrap_err();
    assert_eq!(err, TruncationError { from: "Even", to: "Motor", dropped: vec![("e1o", 0.5), ("e2o", -1.0)] });
    assert_eq!(err.to_string(), "converting Even to Motor would drop e1o = 0.5, e2o = -1.0");
    let _: &dyn std::error::Error = &err;

    // Two Euclidean vectors make a rotor; two conformal points do not.
    let (a, b) = (Vector { e1: 1.0, e2: 0.5, ..Vector::zero() }, Vector { e3: 2.0, e1: -1.0, ..Vector::zero() });
    let rotor = Rotor::try_from(b * a).unwrap();
    assert_eq!(Multivector::from(rotor), Multivector::from(b) * Multivector::from(a));
    let points = Rotor::try_from(up([1.0, 0.0, 0.0]) * up([0.0, 1.0, 0.0])).unwrap_err();
    assert_eq!(points.dropped.iter().map(|d| d.0).collect::<Vec<_>>(), ["e1o", "e1i", "e2o", "e2i"]);

    // Across grades: an odd element with only its vector part converts to a vector.
    let v = Vector { e1: 1.0, e2: 2.0, e3: 3.0, eo: 4.0, ei: 5.0 };
    assert_eq!(Vector::try_from(Odd::from(v)), Ok(v));
    assert_eq!(Vector::try_from(Odd { e12i: 1e-300, ..Odd::from(v) }).unwrap_err().dropped, [("e12i", 1e-300)]);
    // Overlapping types, neither inside the other: a flat point and a translator share `e_k i`.
    let t = Translator::from_vector([2.0, 0.0, 0.0]);
    assert_eq!(FlatPoint::try_from(t).unwrap_err().dropped, [("s", 1.0)]);
    assert_eq!(
        FlatPoint::try_from(t - 1.0),
        Ok(FlatPoint { e1i: -1.0, e2i: 0.0, e3i: 0.0, eoi: 0.0 }),
        "exactly representable"
    );

    // From the dense type, and from storage arrays.
    let circle = Circle::through([1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [-1.0, 0.0, 2.0]).unwrap();
    let back = Circle::try_from(Multivector::from(circle)).unwrap();
    assert!(max_rel_diff(&back.to_array(), &circle.to_array()) < 1e-15);
    let dense = Multivector::from(circle) + Multivector::from(Plane { e123i: 0.25, ..Plane::zero() });
    let err = Circle::try_from(dense).unwrap_err();
    assert_eq!((err.from, err.to, err.dropped.as_slice()), ("Multivector", "Circle", [("e123i", 0.25)].as_slice()));
    assert_eq!(Circle::try_from_storage(&circle.to_storage()), Ok(circle));
    let mut storage = circle.to_storage();
    storage[0] = f64::NAN;
    let err = Circle::try_from_storage(&storage).unwrap_err();
    assert_eq!((err.from, err.dropped[0].0), ("storage array", "s"));
    assert_eq!(Circle::from_storage(&storage), circle, "from_storage drops silently");
}

#[test]
fn cast_round_trips() {
    let mut rng = Rng::new(6);
    for _ in 0..32 {
        // f32 values survive f32 → f64 → f32 exactly, and f64 → f32 → f64 to f32 rounding.
        let c = random(&mut rng, Circle::from_array);
        let c32 = c.cast::<f32>();
        assert_eq!(c32.cast::<f64>().cast::<f32>(), c32);
        let back = c32.cast::<f64>();
        assert!(max_rel_diff(&back.to_array(), &c.to_array()) < 1e-7);
        assert_eq!(back, Circle::from_array(c.to_array().map(|x| x as f32 as f64)));
        let m = random(&mut rng, Motor::from_array);
        assert_eq!(m.cast::<f64>(), m);
    }
    // The dense type too.
    let dense = Multivector::from(Circle { e12o: 0.1, ..Circle::zero() });
    assert_eq!(dense.cast::<f32>().cast::<f64>(), Multivector::from(Circle { e12o: 0.1f32 as f64, ..Circle::zero() }));
    // Dual numbers keep their value and lose their derivative.
    let d = Line::<Dual> { e12i: Dual::new(2.0, 7.0), ..Line::zero() };
    assert_eq!(d.cast::<f64>(), Line { e12i: 2.0, ..Line::zero() });
    assert_eq!(Line { e12i: 2.0, ..Line::zero() }.cast::<Dual>().e12i, Dual::constant(2.0));
}

#[test]
fn normalise_names_its_failures() {
    let sphere = Sphere::from_centre_radius([1.0, 2.0, 3.0], 2.0).unwrap().scale(5.0);
    let unit = sphere.normalise().unwrap();
    assert_eq!(Some(unit), sphere.try_normalise());
    assert!((unit.norm_squared().abs() - 1.0).abs() < 1e-15);

    let zero = Vector::<f64>::zero().normalise();
    assert_eq!(zero, Err(NormaliseError::Zero { type_name: "Vector" }));
    let null = up([1.0, 2.0, 3.0]).normalise();
    assert_eq!(null, Err(NormaliseError::Null { type_name: "Vector" }));
    assert_eq!(
        null.unwrap_err().to_string(),
        "cannot normalise Vector: it is null (⟨A Ã⟩₀ = 0 with nonzero coefficients)"
    );
    let infinite = Circle { e123: f64::INFINITY, ..Circle::zero() }.normalise();
    assert_eq!(infinite, Err(NormaliseError::NonFinite { type_name: "Circle" }));
    assert_eq!(infinite.unwrap_err().type_name(), "Circle");
    let nan = Line { e12i: f64::NAN, ..Line::zero() }.normalise();
    assert!(matches!(nan, Err(NormaliseError::NonFinite { .. })));
    // A squared norm that overflows, and a finite one whose unit overflows.
    let overflow = Vector { e1: 1e200, eo: 1e200, ei: 0.5e200, ..Vector::zero() };
    assert_eq!(overflow.normalise(), Err(NormaliseError::NonFinite { type_name: "Vector" }));
    let lopsided = Vector { e1: 1e-150, eo: 1e300, ..Vector::zero() };
    assert_eq!(lopsided.norm_squared(), 1e-300);
    assert_eq!(lopsided.normalise(), Err(NormaliseError::NonFinite { type_name: "Vector" }));
    assert_eq!(lopsided.try_normalise(), None);
    // Never a non-finite `Ok` or `Some`, on any coefficients.
    let mut rng = Rng::new(7);
    for _ in 0..2000 {
        let scale = [0.0, 1e-320, 1e-160, 1.0, 1e160, 1e300, f64::INFINITY, f64::NAN][(rng.unit() * 8.0) as usize];
        let x = Pseudoscalar { e123oi: scale * rng.range(-1.0, 1.0) };
        let v = Vector::from_array(std::array::from_fn(|_| scale * rng.range(-1.0, 1.0)));
        if let Ok(u) = x.normalise() {
            assert!(u.e123oi.is_finite());
        }
        match v.normalise() {
            Ok(u) => assert!(u.to_array().iter().all(|c| c.is_finite()), "{v:?} -> {u:?}"),
            Err(e) => assert_eq!(e.type_name(), "Vector"),
        }
        assert_eq!(v.normalise().ok(), v.try_normalise());
    }
}

/// `A + B` and `A − B` of two types land in the smallest declared type holding both, and
/// agree with the dense type's sum and difference.
macro_rules! mixed_sums {
    ($rng:expr, $(($a:ident, $b:ident, $out:ident)),*) => {$({
        let (x, y) = (random($rng, $a::from_array), random($rng, $b::from_array));
        let (sum, difference): ($out, $out) = (x + y, x - y);
        let (dx, dy) = (Multivector::from(x), Multivector::from(y));
        let name = concat!(stringify!($a), " ± ", stringify!($b));
        assert!(max_rel_diff(&Multivector::from(sum).coeffs, &(dx + dy).coeffs) < 1e-15, "{name}");
        assert!(max_rel_diff(&Multivector::from(difference).coeffs, &(dx - dy).coeffs) < 1e-15, "{name}");
    })*};
}

#[test]
fn sums_of_different_types_land_in_the_covering_type() {
    let rng = &mut Rng::new(12);
    mixed_sums!(
        rng,
        (Rotor, Translator, Motor),
        (Translator, Rotor, Motor),
        (Scalar, Bivector, Even),
        (Vector, Circle, Odd),
        (FlatPoint, Bivector, Bivector),
        (Line, Circle, Circle),
        (Plane, Sphere, Sphere)
    );
}

/// `magnitude_squared` is the sum of the squares of the orthonormal-basis coefficients (the
/// dense type's), through the null basis's change of basis.
#[test]
fn magnitude_is_the_orthonormal_coefficients_length() {
    let rng = &mut Rng::new(13);
    macro_rules! check {
        ($($ty:ident),*) => {$({
            let x = random(rng, $ty::from_array);
            let want: f64 = Multivector::from(x).coeffs.iter().map(|c| c * c).sum();
            let got = x.magnitude_squared();
            assert!((got - want).abs() <= 1e-13 * want, "{}: {got} vs {want}", stringify!($ty));
            assert!(x.magnitude_squared() > 0.0);
        })*};
    }
    check!(Vector, Line, Circle, Plane, Sphere, Motor, FlatPoint, Bivector, Even, Odd);
}
