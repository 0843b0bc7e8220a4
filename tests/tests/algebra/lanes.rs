//! Lanes for every algebra: `algebra! { lanes = cga_core::simd; … }` makes a type of any
//! algebra batch through `simd::run`, `run_packed`, `run_columns` and `map` as cga-core's
//! own do, with the bits of one operation at a time — checked for PGA (cga-algebras) and for
//! an algebra declared here, as a user would.

use cga_algebras::pga::{Line as PLine, Motor, Plane as PPlane, Point as PPoint, Sandwich};
use cga_core::simd::{F64x4, F64x8, Kernel, Lane, Lanes, Over, map, run, run_columns, run_packed, splat};

/// 2D projective geometric algebra G(2,0,1), declared as a user would, with lanes.
mod pga2 {
    cga_macros::algebra! {
        scalar = cga_core::Real;
        signature = (2, 0, 1);
        basis = [e0 = e3, e1, e2];
        lanes = cga_core::simd;
        /// A line `a x + b y + c = 0` as `a e1 + b e2 + c e0`.
        type Line = [grade(1)];
        /// A point: `e12 + x e20 + y e01`.
        type Point = [grade(2)];
        /// A motor: rotation or translation of the plane.
        versor Motor = [s, grade(2)];
    }
}

/// Deterministic values in `[-2, 2)` for test inputs, from a counter (no shared state).
fn value(k: usize) -> f64 {
    let x = (k as u64).wrapping_mul(0x9E37_79B9_7F4A_7C15).rotate_left(17);
    (x >> 11) as f64 / (1u64 << 53) as f64 * 4.0 - 2.0
}

fn filled<X: Lanes>(n: usize, from_array: impl Fn(usize) -> X) -> Vec<X> {
    (0..n).map(from_array).collect()
}

fn pga_points(n: usize) -> Vec<PPoint> {
    filled(n, |k| PPoint::at([value(3 * k), value(3 * k + 1), value(3 * k + 2)]))
}

fn pga_motor(k: usize) -> Motor {
    Motor::from_array(core::array::from_fn(|i| value(1000 + 8 * k + i)))
}

/// Bit for bit: the same coefficients, NaN-free.
fn same_bits<const N: usize>(a: [f64; N], b: [f64; N]) -> bool {
    a.iter().zip(&b).all(|(x, y)| x.to_bits() == y.to_bits())
}

/// One motor, given at run time, moving every point.
struct Moved(Motor);

impl Kernel for Moved {
    type Input = PPoint;
    type Output = PPoint;
    #[inline(always)]
    fn apply<L: Lane>(&self, x: PPoint<L>) -> PPoint<L> {
        splat::<Motor, L>(self.0).sandwich(x)
    }
}

#[test]
fn pga_batches_by_run_with_the_bits_of_one_at_a_time() {
    // 37 rows: blocks of eight (or four) lanes and a partial block.
    let (motor, points) = (pga_motor(0), pga_points(37));
    let mut out = vec![PPoint::zero(); 37];
    run(&Moved(motor), &points, &mut out).unwrap();
    for (p, o) in points.iter().zip(&out) {
        assert!(same_bits(motor.sandwich(*p).to_array(), o.to_array()), "{p:?}");
    }
}

#[test]
fn pga_batches_pairs_by_map_and_columns_with_the_bits_of_one_at_a_time() {
    let points = pga_points(41);
    let others = pga_points(82)[41..].to_vec();
    let pairs: Vec<(PPoint, PPoint)> = points.iter().copied().zip(others.iter().copied()).collect();
    let mut joins = vec![PLine::zero(); 41];
    map(
        &pairs,
        &mut joins,
        #[inline(always)]
        |(p, q): (PPoint<F64x4>, PPoint<F64x4>)| p & q,
    );
    let mut by_columns = vec![PLine::zero(); 41];
    struct Join;
    impl Kernel for Join {
        type Input = (PPoint, PPoint);
        type Output = PLine;
        #[inline(always)]
        fn apply<L: Lane>(&self, (p, q): Over<(PPoint, PPoint), L>) -> PLine<L> {
            p & q
        }
    }
    run_columns(&Join, (&points[..], &others[..]), &mut by_columns).unwrap();
    for k in 0..41 {
        let one = (points[k] & others[k]).to_array();
        assert!(same_bits(one, joins[k].to_array()) && same_bits(one, by_columns[k].to_array()), "row {k}");
    }
    // Motors compose on lanes too, eight at a time.
    let motors: Vec<(Motor, Motor)> = (0..19).map(|k| (pga_motor(k), pga_motor(k + 19))).collect();
    let mut products = vec![Motor::zero(); 19];
    map(
        &motors,
        &mut products,
        #[inline(always)]
        |(a, b): (Motor<F64x8>, Motor<F64x8>)| a * b,
    );
    for ((a, b), m) in motors.iter().zip(&products) {
        assert!(same_bits((*a * *b).to_array(), m.to_array()));
    }
}

#[test]
fn pga_packs_and_unpacks_every_type_losslessly() {
    let planes = filled(4, |k| PPlane::new(value(k), value(k + 4), value(k + 8), value(k + 12)));
    let packed = PPlane::pack([planes[0], planes[1], planes[2], planes[3]]);
    assert_eq!(PPlane::unpack(packed).to_vec(), planes);
    let lanes: PPlane<F64x4> = splat(planes[2]);
    assert_eq!(PPlane::unpack(lanes), [planes[2]; 4]);
}

#[test]
fn a_users_algebra_batches_by_run_packed_with_the_bits_of_one_at_a_time() {
    use pga2::{Line, Motor, Point, Sandwich as _};
    let lines: Vec<Line> = filled(12, |k| Line::from_array([value(5 * k), value(5 * k + 1), value(5 * k + 2)]));
    let others: Vec<Line> = filled(12, |k| Line::from_array([value(7 * k + 3), value(7 * k), value(7 * k + 1)]));
    // Three packets of four: the meets of the lines, then each moved by a motor.
    let motor = Motor::from_array([value(90), value(91), value(92), value(93)]);
    let packets: Vec<(Line<F64x4>, Line<F64x4>)> = (0..3)
        .map(|p| {
            let four = |v: &[Line]| Line::pack([v[4 * p], v[4 * p + 1], v[4 * p + 2], v[4 * p + 3]]);
            (four(&lines), four(&others))
        })
        .collect();
    struct MeetMoved(Motor);
    impl Kernel for MeetMoved {
        type Input = (Line, Line);
        type Output = Point;
        #[inline(always)]
        fn apply<L: Lane>(&self, (a, b): Over<(Line, Line), L>) -> Point<L> {
            splat::<Motor, L>(self.0).sandwich(a ^ b)
        }
    }
    let mut out = vec![Point::<F64x4>::zero(); 3];
    run_packed(&MeetMoved(motor), &packets, &mut out).unwrap();
    for k in 0..12 {
        let one = motor.sandwich(lines[k] ^ others[k]).to_array();
        let batched = Point::unpack(out[k / 4])[k % 4].to_array();
        assert!(same_bits(one, batched), "row {k}");
    }
}

/// PGA in f32 stored packed (eight to a packet, [`Packed`]): `run_packed` gives the bits of
/// one at a time for the join of points, the meets of planes, the motor product and a
/// motor's prepared matrix on points, at lengths about the packet's eight (a last packet
/// padded with zeros).
#[test]
fn pga_f32_batches_by_run_packed_with_the_bits_of_one_at_a_time() {
    use cga_algebras::pga::Prepare;
    use cga_core::simd::{F32x8, Packed};
    let to32 = |a: &[f64]| a.iter().map(|&c| c as f32).collect::<Vec<_>>();
    let point = |k: usize| PPoint::<f32>::from_array(to32(&pga_points(k + 1)[k].to_array()).try_into().unwrap());
    let plane =
        |k: usize| PPlane::<f32>::new(value(k) as f32, value(k + 4) as f32, value(k + 8) as f32, value(k + 12) as f32);
    let motor = |k: usize| Motor::<f32>::from_array(to32(&pga_motor(k).to_array()).try_into().unwrap());

    /// The kernel `$body` of `$input` to `$output`, on f32.
    macro_rules! kernel {
        ($name:ident: ($($input:ident),*) -> $output:ident, |$x:pat_param| $body:expr) => {
            struct $name;
            impl Kernel for $name {
                type Input = ($($input<f32>,)*);
                type Output = $output<f32>;
                #[inline(always)]
                fn apply<L: Lane>(&self, $x: ($($input<L>,)*)) -> $output<L> {
                    $body
                }
            }
        };
    }
    kernel!(Join: (PPoint, PPoint) -> PLine, |(p, q)| p & q);
    kernel!(Meet: (PPlane, PPlane) -> PLine, |(p, q)| p ^ q);
    kernel!(Meet3: (PPlane, PPlane, PPlane) -> PPoint, |(p, q, r)| p ^ q ^ r);
    kernel!(Compose: (Motor, Motor) -> Motor, |(a, b)| a * b);
    struct Prepared([f32; 13]);
    impl Kernel for Prepared {
        type Input = PPoint<f32>;
        type Output = PPoint<f32>;
        #[inline(always)]
        fn apply<L: Lane>(&self, x: PPoint<L>) -> PPoint<L> {
            let m = self.0.map(|c| L::from_fn(|_| c.into()));
            <Motor<L> as Prepare<PPoint<L>>>::apply_matrix(&m, x)
        }
    }

    /// `K` on `input` stored packed against one at a time, bit for bit.
    fn check<K: Kernel>(k: &K, input: &[K::Input], one: impl Fn(K::Input) -> K::Output)
    where
        K::Output: Lanes<Element = f32> + PartialEq + core::fmt::Debug,
        K::Input: Lanes<Element = f32>,
    {
        let packets: Vec<Packed<K::Input>> = input.chunks(8).map(K::Input::pack_lanes::<F32x8>).collect();
        let mut out: Vec<Packed<K::Output>> =
            packets.iter().map(|_| K::Output::pack_lanes::<F32x8>(&[K::Output::pack_filler()])).collect();
        run_packed(k, &packets, &mut out).unwrap();
        let mut back = vec![K::Output::pack_filler(); 8 * out.len()];
        for (p, b) in out.iter().zip(back.chunks_mut(8)) {
            K::Output::unpack_lanes::<F32x8>(*p, b);
        }
        let want: Vec<K::Output> = input.iter().map(|&x| one(x)).collect();
        assert_eq!(back[..input.len()], want[..], "{} rows", input.len());
    }
    let m = motor(3);
    for n in [1, 7, 8, 9, 16, 17, 33] {
        let pairs: Vec<_> = (0..n).map(|k| (point(k), point(k + 50))).collect();
        check(&Join, &pairs, |(p, q)| p & q);
        let planes: Vec<_> = (0..n).map(|k| (plane(k), plane(k + 20), plane(k + 40))).collect();
        check(&Meet, &planes.iter().map(|&(p, q, _)| (p, q)).collect::<Vec<_>>(), |(p, q)| p ^ q);
        check(&Meet3, &planes, |(p, q, r)| p ^ q ^ r);
        let motors: Vec<_> = (0..n).map(|k| (motor(k), motor(k + 40))).collect();
        check(&Compose, &motors, |(a, b)| a * b);
        let points: Vec<_> = (0..n).map(point).collect();
        let prepared = m.prepare::<PPoint<f32>>();
        check(&Prepared(Prepare::<PPoint<f32>>::matrix(m)), &points, |x| prepared.apply(x));
    }
}

/// A prepared versor's `run_into` (generated for every versor and type it acts on, in
/// algebras with lanes) gives the bits of `apply_into`, in f64 and f32, at lengths about the
/// lanes' four, eight and sixteen, for PGA and for the algebra declared here; unequal lengths
/// give `None` and write nothing.
#[test]
fn prepared_versors_run_into_with_the_bits_of_apply_into() {
    use cga_algebras::pga::RunInto;
    use pga2::{Line as Line2, Motor as Motor2, Point as Point2, RunInto as _};
    let to32 = |a: &[f64]| a.iter().map(|&c| c as f32).collect::<Vec<_>>();
    for n in [0, 1, 3, 4, 7, 8, 15, 16, 17, 33, 41] {
        let (motor, points) = (pga_motor(n), pga_points(n));
        let prepared = motor.prepare();
        let (mut one, mut lanes) = (vec![PPoint::zero(); n], vec![PPoint::zero(); n]);
        prepared.apply_into(&points, &mut one);
        prepared.run_into(&points, &mut lanes).unwrap();
        assert!(one.iter().zip(&lanes).all(|(a, b)| same_bits(a.to_array(), b.to_array())), "{n} f64 points");

        let planes = filled(n, |k| PPlane::new(value(k), value(k + 4), value(k + 8), value(k + 12)));
        let prepared = motor.prepare::<PPlane>();
        let (mut one, mut lanes) = (vec![PPlane::zero(); n], vec![PPlane::zero(); n]);
        prepared.apply_into(&planes, &mut one);
        prepared.run_into(&planes, &mut lanes).unwrap();
        assert!(one.iter().zip(&lanes).all(|(a, b)| same_bits(a.to_array(), b.to_array())), "{n} f64 planes");

        let motor32 = Motor::<f32>::from_array(to32(&motor.to_array()).try_into().unwrap());
        let lines32: Vec<PLine<f32>> =
            (0..n).map(|k| PLine::from_array(core::array::from_fn(|i| value(6 * k + i + 500) as f32))).collect();
        let prepared = motor32.prepare::<PLine<f32>>();
        let (mut one, mut lanes) = (vec![PLine::<f32>::zero(); n], vec![PLine::<f32>::zero(); n]);
        prepared.apply_into(&lines32, &mut one);
        prepared.run_into(&lines32, &mut lanes).unwrap();
        let bits = |l: &PLine<f32>| l.to_array().map(f32::to_bits);
        assert!(one.iter().zip(&lanes).all(|(a, b)| bits(a) == bits(b)), "{n} f32 lines");

        let motor2 = Motor2::from_array([value(90 + n), value(91), value(92), value(93)]);
        let points2: Vec<Point2> =
            filled(n, |k| Point2::from_array([value(3 * k), value(3 * k + 1), value(3 * k + 2)]));
        let prepared = motor2.prepare::<Point2>();
        let (mut one, mut lanes) = (vec![Point2::zero(); n], vec![Point2::zero(); n]);
        prepared.apply_into(&points2, &mut one);
        prepared.run_into(&points2, &mut lanes).unwrap();
        assert!(one.iter().zip(&lanes).all(|(a, b)| same_bits(a.to_array(), b.to_array())), "{n} user points");
        let lines2: Vec<Line2> = filled(n, |k| Line2::from_array([value(5 * k), value(5 * k + 1), value(5 * k + 2)]));
        let (mut one, mut lanes) = (vec![Line2::zero(); n], vec![Line2::zero(); n]);
        let prepared = motor2.prepare::<Line2>();
        prepared.apply_into(&lines2, &mut one);
        prepared.run_into(&lines2, &mut lanes).unwrap();
        assert!(one.iter().zip(&lanes).all(|(a, b)| same_bits(a.to_array(), b.to_array())), "{n} user lines");
    }
    let (points, mut short) = (pga_points(9), vec![PPoint::zero(); 8]);
    assert!(pga_motor(1).prepare::<PPoint>().run_into(&points, &mut short).is_none());
    assert!(short.iter().all(|p| *p == PPoint::zero()), "nothing written");
}

/// Lanes gated off by an attribute on the `lanes` item (as a crate gates them behind a
/// feature): the algebra, its prelude included, builds without them.
mod gated {
    cga_macros::algebra! {
        scalar = cga_core::Real;
        #[cfg(any())]
        lanes = cga_core::simd;
        prelude = f64;
        signature = (2, 0);
        /// A vector x e1 + y e2.
        type Vector = [grade(1)];
        /// A rotor of the plane.
        versor Rotor = [s, e12];
    }
}

#[test]
fn an_algebra_whose_lanes_are_gated_off_keeps_its_prelude() {
    use gated::prelude::*;
    let (r, v) = (Rotor::from_array([0.0, 1.0]), Vector::from_array([1.0, 2.0]));
    // The half turn e12: e12 v e21 = −v.
    assert_eq!(r.sandwich(v).to_array(), [-1.0, -2.0]);
    assert_eq!(r.prepare().apply(v).to_array(), [-1.0, -2.0]);
}
