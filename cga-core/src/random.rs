//! Seeded random objects of every kind, for tests, examples and benchmarks
//! (clifford.tools.g3c's `random_circle`, `random_sphere`, …; the Python package's
//! `cga.random`). Each draw is a proper object of its kind: a circle is a real circle of
//! positive radius, a rotor has unit norm, a motor is rigid.
//!
//! Distributions (the same as `python/cga/random.py`'s):
//! - positions (centres, points on flats, translations) normal with standard deviation
//!   `scale` in each coordinate, about the origin;
//! - sizes (radii, a point pair's half separation) uniform in `[0.1, 1] · scale`;
//! - directions, normals and axes uniform on the unit sphere (three normal draws
//!   normalised);
//! - angles uniform in `(−π, π]`.
//!
//! Normal draws are Box–Muller of two uniform draws. Any generator of the `rand` traits
//! works; [`seeded`] gives the crate's reproducible stream (PCG64, `rand_pcg`), the same for
//! a seed on every platform.
//!
//! `scale` must be positive and finite, else `NonFinite` (not finite) or `ZeroRadius` (not
//! positive); objects are built by this crate's constructors, so their errors (an
//! overflowing `scale`) are theirs.
//!
//! ```
//! use cga_core::random::{random_circle, seeded};
//! let mut rng = seeded(7);
//! let circle = random_circle::<f64, _>(&mut rng, 2.0)?;
//! let (_, _, r) = circle.centre_normal_radius()?;
//! assert!((0.2..=2.0).contains(&r));
//! # Ok::<(), cga_core::GeometryError>(())
//! ```

use crate::conformal::{GeometryError, Result, up};
use crate::euclid::{E3, add, norm, scale as times};
use crate::{Bivector, Circle, Line, Motor, Plane, Real, Rotor, Sphere, Translator, Vector};
use rand::{Rng, RngExt, SeedableRng};

/// The crate's reproducible stream: PCG64 (`rand_pcg::Pcg64`, 128-bit state).
pub type Stream = rand_pcg::Pcg64;

/// A [`Stream`] from a seed (`SeedableRng::seed_from_u64`): the same draws for the same
/// seed, on every platform and in every release of `rand_pcg` 0.10.
pub fn seeded(seed: u64) -> Stream {
    Stream::seed_from_u64(seed)
}

/// `scale` positive and finite, as f64.
fn checked<T: Real>(scale: T) -> Result<f64> {
    let s = scale.to_f64();
    if !s.is_finite() {
        Err(GeometryError::NonFinite)
    } else if s <= 0.0 {
        Err(GeometryError::ZeroRadius)
    } else {
        Ok(s)
    }
}

/// A standard normal draw: Box–Muller, `√(−2 ln u₁) cos(2π u₂)` with `u₁` in `(0, 1]`.
pub fn standard_normal<R: Rng + ?Sized>(rng: &mut R) -> f64 {
    let u1 = 1.0 - rng.random::<f64>();
    let u2 = rng.random::<f64>();
    (-2.0 * u1.ln()).sqrt() * (core::f64::consts::TAU * u2).cos()
}

fn position<T: Real, R: Rng + ?Sized>(rng: &mut R, s: f64) -> E3<T> {
    [0; 3].map(|_| T::from_f64(s * standard_normal(rng)))
}

fn size<T: Real, R: Rng + ?Sized>(rng: &mut R, s: f64) -> T {
    T::from_f64(s * (0.1 + 0.9 * rng.random::<f64>()))
}

/// A Euclidean point, each coordinate normal with standard deviation `scale`.
pub fn random_point<T: Real, R: Rng + ?Sized>(rng: &mut R, scale: T) -> Result<E3<T>> {
    let s = checked(scale)?;
    Ok(position(rng, s))
}

/// A conformal point `up(x)` of a [`random_point`] `x`.
pub fn random_conformal_point<T: Real, R: Rng + ?Sized>(rng: &mut R, scale: T) -> Result<Vector<T>> {
    Ok(up(random_point(rng, scale)?))
}

/// A unit direction, uniform on the sphere: three normal draws normalised (drawn again in
/// the rare case, probability about 1e-36, that their length is below 1e-12).
pub fn random_direction<T: Real, R: Rng + ?Sized>(rng: &mut R) -> E3<T> {
    loop {
        let d = [0; 3].map(|_| standard_normal(rng));
        let n = norm(d);
        if n > 1e-12 {
            return d.map(|x| T::from_f64(x / n));
        }
    }
}

/// An angle uniform in `(−π, π]`: `π − 2π u`.
pub fn random_angle<T: Real, R: Rng + ?Sized>(rng: &mut R) -> T {
    T::from_f64(core::f64::consts::PI - core::f64::consts::TAU * rng.random::<f64>())
}

/// A sphere: a [`random_point`] centre, a radius uniform in `[0.1, 1] · scale`.
pub fn random_sphere<T: Real, R: Rng + ?Sized>(rng: &mut R, scale: T) -> Result<Sphere<T>> {
    let s = checked(scale)?;
    let c = position(rng, s);
    Sphere::new(c, size(rng, s))
}

/// A plane through a [`random_point`] with a [`random_direction`] normal.
pub fn random_plane<T: Real, R: Rng + ?Sized>(rng: &mut R, scale: T) -> Result<Plane<T>> {
    let s = checked(scale)?;
    let p = position(rng, s);
    Plane::new(p, random_direction(rng))
}

/// A line through a [`random_point`] along a [`random_direction`].
pub fn random_line<T: Real, R: Rng + ?Sized>(rng: &mut R, scale: T) -> Result<Line<T>> {
    let s = checked(scale)?;
    let p = position(rng, s);
    Line::new(p, random_direction(rng))
}

/// A circle: a [`random_point`] centre, a [`random_direction`] normal, a radius uniform in
/// `[0.1, 1] · scale`.
pub fn random_circle<T: Real, R: Rng + ?Sized>(rng: &mut R, scale: T) -> Result<Circle<T>> {
    let s = checked(scale)?;
    let c = position(rng, s);
    let n = random_direction(rng);
    Circle::new(c, n, size(rng, s))
}

/// A point pair `up(c + r d) ∧ up(c − r d)`, normalised (`P P̃ = −1`, as clifford's): a
/// [`random_point`] centre `c`, a [`random_direction`] `d`, a half separation `r` uniform in
/// `[0.1, 1] · scale`.
pub fn random_point_pair<T: Real, R: Rng + ?Sized>(rng: &mut R, scale: T) -> Result<Bivector<T>> {
    let s = checked(scale)?;
    let c = position(rng, s);
    let d = random_direction::<T, _>(rng);
    let r = size::<T, _>(rng, s);
    Bivector::from_points(add(c, times(d, r)), add(c, times(d, -r)))?.try_normalise().ok_or(GeometryError::Degenerate)
}

/// A rotor about a [`random_direction`] axis by a [`random_angle`].
pub fn random_rotor<T: Real, R: Rng + ?Sized>(rng: &mut R) -> Rotor<T> {
    let axis = random_direction(rng);
    let angle = random_angle(rng);
    Rotor::from_axis_angle(axis, angle).unwrap_or_else(|_| Rotor::identity())
}

/// A translator by a [`random_point`] vector.
pub fn random_translator<T: Real, R: Rng + ?Sized>(rng: &mut R, scale: T) -> Result<Translator<T>> {
    Ok(Translator::from_vector(random_point(rng, scale)?))
}

/// A rigid motion `T R`: a [`random_rotor`], then a [`random_translator`].
pub fn random_motor<T: Real, R: Rng + ?Sized>(rng: &mut R, scale: T) -> Result<Motor<T>> {
    let s = checked(scale)?;
    let r = random_rotor(rng);
    Ok(Motor::from_rotor_translation(r, position(rng, s)))
}
