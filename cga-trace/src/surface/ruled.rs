//! Ruled surfaces: the lines of an interpolation (eq. 3–5) of two point pairs — each ruling
//! the segment between the interpolated pair's points, as the original renders them — or of
//! two lines, each ruling kept within a bounding sphere.
//!
//! A ray `L` meets the ruling `L_α` where the two lines are coplanar: the bilinear Plücker
//! form `Pl(L, M) = ⟨L M⟩_{e123i}` (the `e123i` coefficient of the product, the dual of
//! `L* ∧ M*`) vanishes. It is homogeneous, so the projector's normalisation drops out:
//!
//! - **Lines.** `X = (1 − α) L₁ + α L₂`, `−X X̃ = S + g W` (`g = α(1 − α)`, `W ∝ e123i`,
//!   `W² = 0`), so `K = √S + g W/(2√S)` and `L_α ∝ K* X ∝ 2S X − g ⟨W X⟩₃`:
//!   `R(α) = 2 S a − g b`, `a = Pl(L, X)`, `b = Pl(L, ⟨W Xᵢ⟩₃)` interpolated linearly — a
//!   **cubic**, with no radical at all.
//! - **Point pairs.** `P_α ∝ (2σ − gW) X` with `σ² − Sσ + g²w/4 = 0` (`w = W²`, as for circles)
//!   and `L_α = P_α ∧ ei`: `2σ a − g b = 0` for `a = Pl(L, X ∧ ei)`, `b = Pl(L, ⟨W X⟩₂ ∧ ei)`.
//!   Then `σ = g b/(2a)`, put back: `g²b² − 2Sgab + g²wa² = 0`, and dividing by `g`:
//!   `R(α) = g (b² + w a²) − 2 S a b` — a **quartic**. Its extra roots (the other branch of
//!   `σ`) are rejected by verification.
//!
//! Each root is verified: the ray and the ruling come within rounding of each other, inside
//! the ruling's segment (pairs) or bound (lines). The normal is eq. 6–11 with the ruling as
//! `L_C`: `Ω = ⟨L_C L̇_C⟩₂` for the normalised ruling (`L̇_C` exact on dual numbers; for
//! point pairs the ruling `P_α ∧ ei`, whose motion — unlike that of `P_α`, which moves the
//! pair's points but not the points between them — keeps the ruling a line), `Ẋ = X · Ω`,
//! `L_T = Ẋ ∧ X ∧ ei`, `N = ⟨L_T L_C I5⟩₃`.

use super::SurfaceError;
use super::bernstein::{Roots, Scaled};
use crate::ray::{Ray, crosses};
use crate::shapes::{Crossing, Shape, facing};
use cga_core::euclid::{E3, add, cross, dot, norm, scale, sub, unit};
use cga_core::{Bivector, Dual, Interpolable, Line, Pair, Pseudoscalar, ScalarQuadvector, Vector, ei, up};

/// What is interpolated.
#[derive(Clone, Debug)]
pub enum Rulings {
    /// Point pairs: each ruling is the segment between the pair's two points.
    PointPairs(Pair<Bivector>),
    /// Lines: each ruling is the part of the line within `bound` (centre, radius) of the
    /// local frame.
    Lines {
        /// The end lines.
        pair: Pair<Line>,
        /// `(centre, radius)` in the local frame.
        bound: (E3, f64),
    },
}

/// A ruled surface in its local frame.
#[derive(Clone, Debug)]
pub struct RuledSurface {
    rulings: Rulings,
    /// The local frame's origin, in the scene's frame.
    origin: E3,
    /// `S(α) = ⟨−X X̃⟩₀`, degree 2.
    s: Scaled<f64>,
    /// `w = W²` (0 for lines).
    w: f64,
    /// `⟨W Xᵢ⟩` at the ends, as lines (`∧ ei` for point pairs).
    wx: [Line; 2],
    /// The ends as lines.
    ends: [Line; 2],
    /// Bounding sphere about the local origin.
    radius: f64,
    /// `W = 0` (point pairs on one circle or sphere): `K` is a scalar and `L_α ∝ X ∧ ei`.
    trivial: bool,
}

/// `Pl(A, B)`: the `e123i` coefficient of `A B`, zero exactly when the lines are coplanar.
fn plucker(a: &Line, b: &Line) -> f64 {
    (*a * *b).e123i
}

/// Rulings sampled to bound the surface.
const BOUND_SAMPLES: usize = 256;

impl RuledSurface {
    /// The surface of point pairs from `p1 = [a, b]` (α = 0) to `p2` (α = 1), given in a
    /// frame whose origin is `origin`.
    pub fn point_pairs(origin: E3, p1: [E3; 2], p2: [E3; 2]) -> Result<Self, SurfaceError> {
        let not = |which| move |reason| SurfaceError::NotACircle { which, reason };
        let b1 = Bivector::from_points(p1[0], p1[1]).map_err(not(1))?;
        let b2 = Bivector::from_points(p2[0], p2[1]).map_err(not(2))?;
        let pair = Pair::new(b1, b2)?;
        let (s, w) = square(pair.c1, pair.c2, cross_term!(pair.c1, pair.c2));
        let w4 = w.grade4();
        let wx = [pair.c1, pair.c2].map(|c| Bivector::from_storage(&(w4 * c).to_storage()) ^ ei());
        let ends = [pair.c1 ^ ei(), pair.c2 ^ ei()];
        let w = (w4 * w4).s;
        let mut radius = 0.0f64;
        for k in 0..=BOUND_SAMPLES {
            let alpha = k as f64 / BOUND_SAMPLES as f64;
            let [a, b] = pair.at(alpha)?.end_points().map_err(|_| SurfaceError::Unbounded { alpha })?;
            radius = radius.max(norm(a)).max(norm(b));
        }
        let rulings = Rulings::PointPairs(pair);
        let trivial = w4.to_array().iter().all(|x| x.abs() <= f64::EPSILON);
        Ok(RuledSurface { rulings, origin, s, w, wx, ends, radius: radius * 1.02 + 1e-12, trivial })
    }

    /// The surface of lines from `l1` (α = 0) to `l2`, each `(point, direction)`, within the
    /// sphere `bound`, all given in a frame whose origin is `origin`.
    pub fn lines(origin: E3, l1: (E3, E3), l2: (E3, E3), bound: (E3, f64)) -> Result<Self, SurfaceError> {
        let not = |which| move |reason| SurfaceError::NotACircle { which, reason };
        let a = Line::from_point_direction(l1.0, l1.1).map_err(not(1))?;
        let b = Line::from_point_direction(l2.0, l2.1).map_err(not(2))?;
        let pair = Pair::new(a, b)?;
        let (s, w) = square(pair.c1, pair.c2, cross_term!(pair.c1, pair.c2));
        let w4 = w.grade4();
        let wx = [pair.c1, pair.c2].map(|c| Line::from_storage(&(w4 * c).to_storage()));
        let ends = [pair.c1, pair.c2];
        for k in 0..=BOUND_SAMPLES {
            let alpha = k as f64 / BOUND_SAMPLES as f64;
            pair.at(alpha)?.direction().map_err(|_| SurfaceError::Unbounded { alpha })?;
        }
        let radius = norm(bound.0) + bound.1;
        let rulings = Rulings::Lines { pair, bound };
        Ok(RuledSurface { rulings, origin, s, w: 0.0, wx, ends, radius, trivial: false })
    }

    /// A polynomial whose roots in [0, 1] include every α where the ray's line `line` (in the
    /// local frame) is coplanar with the ruling (module docs).
    pub fn polynomial(&self, line: &Line) -> Scaled<f64> {
        let pl = |m: &[Line; 2]| Scaled::linear(plucker(line, &m[0]), plucker(line, &m[1]));
        let (a, b) = (pl(&self.ends), pl(&self.wx));
        match self.rulings {
            Rulings::Lines { .. } => self.s.mul(&a).scale(2.0).add_scaled(-1.0, &b.times_g()),
            // W = 0: R vanishes identically, and L_α ∝ X ∧ ei meets L where a does.
            Rulings::PointPairs(_) if self.trivial => a,
            Rulings::PointPairs(_) => {
                let r = b.mul(&b).add_scaled(self.w, &a.mul(&a)).times_g();
                r.add_scaled(-2.0, &self.s.mul(&a).mul(&b))
            }
        }
    }

    /// The ruling at α: a point on it, its unit direction, and the parameter range along the
    /// direction that belongs to the surface.
    fn ruling(&self, alpha: f64) -> Option<(E3, E3, (f64, f64))> {
        match &self.rulings {
            Rulings::PointPairs(pair) => {
                let [a, b] = pair.at(alpha).ok()?.end_points().ok()?;
                let d = sub(b, a);
                Some((a, unit(d)?, (0.0, norm(d))))
            }
            Rulings::Lines { pair, bound } => {
                let l = pair.at(alpha).ok()?;
                let (p, d) = (l.point().ok()?, l.direction().ok()?);
                // Where the line crosses the bounding sphere.
                let pc = sub(p, bound.0);
                let (half_b, c) = (dot(pc, d), dot(pc, pc) - bound.1 * bound.1);
                let disc = half_b * half_b - c;
                (disc > 0.0).then(|| (p, d, (-half_b - disc.sqrt(), -half_b + disc.sqrt())))
            }
        }
    }

    /// The point at fraction `v ∈ [0, 1]` along the ruling at α (scene frame), and the unit
    /// normal there (eq. 6–11) unless the surface is singular there (`N = 0`: the point does
    /// not move off its ruling): for meshes.
    pub fn point_and_normal(&self, alpha: f64, v: f64) -> Option<(E3, Option<E3>)> {
        let (p, u, (lo, hi)) = self.ruling(alpha)?;
        let x = add(p, scale(u, lo + v * (hi - lo)));
        Some((add(x, self.origin), self.normal_at(alpha, x)))
    }

    /// Where the ray (local frame) meets the ruling at α, if it does within rounding:
    /// `(t, point)`.
    fn meet(&self, origin: E3, dir: E3, alpha: f64) -> Option<(f64, E3)> {
        let (p, u, (lo, hi)) = self.ruling(alpha)?;
        // Closest points of o + t d and p + s u.
        let w0 = sub(origin, p);
        let (b, d, e) = (dot(dir, u), dot(dir, w0), dot(u, w0));
        let den = 1.0 - b * b;
        if den <= 1e-12 {
            return None;
        }
        let t = (b * e - d) / den;
        let s = (e - b * d) / den;
        let (x, y) = (add(origin, scale(dir, t)), add(p, scale(u, s)));
        let size = self.radius.max(norm(origin));
        let tol = 1e-9 * size;
        (norm(sub(x, y)) <= tol && s >= lo - tol && s <= hi + tol).then_some((t, x))
    }

    /// The unit normal at `x` (local frame) on the ruling at α (module docs), `None` where
    /// `N` vanishes.
    fn normal_at(&self, alpha: f64, x: E3) -> Option<E3> {
        let point = up(x);
        // The ruling as a normalised line and its exact derivative: for point pairs the line
        // P_α ∧ ei (the conformal motion P Ṗ generates moves the pair's points along the
        // surface, but not the points between them; the line's own motion does).
        let (l_c, l_dot) = match &self.rulings {
            Rulings::PointPairs(pair) => {
                let lifted = Pair { c1: pair.c1.lift(), c2: pair.c2.lift() };
                let line = (lifted.at(Dual::variable(alpha)).ok()? ^ ei()).try_normalise()?;
                Line::split(line)
            }
            Rulings::Lines { pair, .. } => pair.with_derivative(alpha).ok()?,
        };
        let omega = Bivector::from_storage(&(l_c * l_dot).to_storage());
        let x_dot: Vector = point | omega;
        let l_t = (x_dot ^ point) ^ ei();
        let i5 = Pseudoscalar { e123oi: -1.0 };
        Line::from_storage(&((l_t * l_c) * i5).to_storage()).direction().ok()
    }

    /// The curvature at `x` (scene frame) on the ruling at α: the surface
    /// `x(α, v) = p(α) + v d(α)` of the ruling's point and direction, their first and second
    /// derivatives exact (the interpolation run on dual numbers over dual numbers), `x_vv = 0`
    /// so `K = −M²/(EG − F²) ≤ 0`; [`cga_core::from_fundamental_forms`] does the rest, with
    /// the ruling as the tangent the postulate's angle is measured from.
    pub fn curvature_at(&self, alpha: f64, x: E3) -> Option<cga_core::Curvature> {
        type D2 = Dual<Dual<f64>>;
        let a = D2 { re: Dual::variable(alpha), du: Dual { re: 1.0, du: 0.0 } };
        let lift2 = |l: Line| l.lift().lift();
        let (p, d) = match &self.rulings {
            Rulings::Lines { pair, .. } => {
                let l = Pair { c1: lift2(pair.c1), c2: lift2(pair.c2) }.at(a).ok()?;
                (l.point().ok()?, l.direction().ok()?)
            }
            Rulings::PointPairs(pair) => {
                let lift = |b: Bivector| b.lift().lift();
                let [p, q] = Pair { c1: lift(pair.c1), c2: lift(pair.c2) }.at(a).ok()?.end_points().ok()?;
                (p, sub(q, p))
            }
        };
        // Value, first and second derivative of each coordinate.
        let parts = |v: E3<D2>| (v.map(|c| c.re.re), v.map(|c| c.re.du), v.map(|c| c.du.du));
        let ((p0, p1, p2), (d0, d1, d2)) = (parts(p), parts(d));
        let v = dot(sub(sub(x, self.origin), p0), d0) / dot(d0, d0);
        let x_a = add(p1, scale(d1, v));
        let x_aa = add(p2, scale(d2, v));
        let nu = unit(cross(x_a, d0))?;
        let second = [dot(x_aa, nu), dot(d1, nu), 0.0];
        cga_core::from_fundamental_forms(x_a, d0, nu, second, unit(d0)?).ok()
    }

    /// What is interpolated, in the local frame.
    pub fn rulings(&self) -> &Rulings {
        &self.rulings
    }

    /// The local frame's origin, in the scene's frame.
    pub fn origin(&self) -> E3 {
        self.origin
    }

    /// The bounding sphere `(centre, radius)` in the scene's frame.
    pub fn bounds(&self) -> (E3, f64) {
        (self.origin, self.radius)
    }

    /// The surface's unit normal at a crossing (scene frame), from eq. 6–11 with the ruling
    /// as `L_C`; where it vanishes, any direction across the ruling.
    pub fn normal(&self, crossing: &Crossing) -> E3 {
        let (alpha, x) = (crossing.alpha.unwrap_or(0.0), sub(crossing.point, self.origin));
        self.normal_at(alpha, x)
            .or_else(|| self.ruling(alpha).and_then(|(_, u, _)| unit(cross(u, cga_core::euclid::perpendicular(u)))))
            .unwrap_or([0.0, 0.0, 1.0])
    }
}

/// `−X X̃ = S + g W` for the interpolation of `c1`, `c2` (whose cross term
/// `−(c1 c̃2 + c2 c̃1)` is `cross`): `S` in the scaled basis, and `W`.
fn square<X: Interpolable<f64>>(c1: X, c2: X, cross: ScalarQuadvector) -> (Scaled<f64>, ScalarQuadvector) {
    let s = Scaled::quadratic(c1.neg_square().s, cross.s, c2.neg_square().s);
    (s, cross)
}

/// `−(A B̃ + B Ã)`, scalar and 4-vector parts.
macro_rules! cross_term {
    ($a:expr, $b:expr) => {
        -ScalarQuadvector::from_storage(&($a * $b.reverse() + $b * $a.reverse()).to_storage())
    };
}
use cross_term;

impl Shape for RuledSurface {
    fn intersect(&self, ray: &Ray, t_min: f64, t_max: f64) -> Option<Crossing> {
        if !crosses(ray, self.origin, self.radius, t_min, t_max) {
            return None;
        }
        let o = sub(ray.origin, self.origin);
        let line = Line::from_point_unit_direction(o, ray.dir);
        let poly = self.polynomial(&line).bernstein();
        let mut alphas = Roots::new();
        poly.roots_in(0.0, 1.0, 0.0, 1e-12, &mut alphas);
        let mut best: Option<Crossing> = None;
        for alpha in alphas {
            if let Some((t, x)) = self.meet(o, ray.dir, alpha)
                && t > t_min
                && t < t_max
                && best.is_none_or(|b| t < b.t)
            {
                best = Some(Crossing { t, point: add(x, self.origin), alpha: Some(alpha), part: 0 });
            }
        }
        best
    }

    fn normal(&self, ray: &Ray, crossing: &Crossing) -> E3 {
        facing(RuledSurface::normal(self, crossing), ray.dir)
    }

    fn bounds(&self) -> Option<(E3, f64)> {
        Some(RuledSurface::bounds(self))
    }

    fn crossing_error(&self) -> f64 {
        super::swept_error(self.origin, self.radius)
    }

    fn curvature(&self, crossing: &Crossing) -> Option<cga_core::Curvature> {
        self.curvature_at(crossing.alpha?, crossing.point)
    }

    /// `(α, v)`: the ruling and the fraction of the way along it, `x = p + (lo + v (hi −
    /// lo)) u` (the form [`RuledSurface::point_and_normal`] takes).
    fn uv(&self, crossing: &Crossing) -> Option<([f64; 2], crate::shapes::Unit)> {
        let alpha = crossing.alpha?;
        let (p, u, (lo, hi)) = self.ruling(alpha)?;
        let s = dot(sub(sub(crossing.point, self.origin), p), u);
        Some(([alpha, (s - lo) / (hi - lo)], crate::shapes::Unit::Fraction))
    }
}
