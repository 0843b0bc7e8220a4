//! Evolved circle surfaces: where a ray meets the family `C_α`, α ∈ [0, 1].
//!
//! A ray's line `L` touches `C_α` exactly when `f(α) = (C_α ∨ L)²` vanishes (the meet is
//! then the touching point). Every method:
//! 1. rejects rays that miss the surface's bounding sphere;
//! 2. finds candidate α in [0, 1] (the ends included, so hits at α = 0 and 1 count) — by
//!    sampling `f`, by the roots of a degree-8 polynomial, or through a tree of bounding
//!    spheres over α-intervals ([`Method`]);
//! 3. verifies every candidate geometrically: the point must lie on the circle and on the
//!    line. Where the meet degenerates — the line lies in the circle's plane, so
//!    `C ∨ L = 0` for every point — the points come from the line–circle intersection
//!    in that plane instead of being missed. The nearest with `t_min < t < t_max` counts.
//!
//! Everything is computed in a frame centred between the two circles: conformal
//! coordinates carry `½x²`, and far from the origin precision falls as (|c|/r)³
//! (docs/STABILITY.md). Methods, errors and timings: docs/SURFACE.md.

pub mod bernstein;
pub mod family;
mod tree;

use crate::ray::Ray;
use crate::shapes::Crossing;
use bernstein::Roots;
use cga_core::euclid::{E3, add, norm, scale, sub};
use cga_core::{Circle, GeometryError, InterpolationError, Line, Pair, Sandwich, Translator};
pub use family::{Family, Finder};
use tree::{PAD, Tree, crosses};

/// Why two circles make no surface this renderer can draw.
#[derive(Clone, Copy, Debug, PartialEq, thiserror::Error)]
pub enum SurfaceError {
    /// An end circle is not a real circle (a line, imaginary, degenerate).
    #[error("circle {which} is not a real circle: {reason}")]
    NotACircle {
        /// 1 or 2.
        which: u8,
        /// What it is instead.
        reason: GeometryError,
    },
    /// The two circles cannot be normalised and aligned.
    #[error("the circles cannot be normalised")]
    Degenerate,
    /// Somewhere between them the interpolation has no circle.
    #[error("the circles do not interpolate: {0}")]
    NoInterpolation(#[from] InterpolationError),
    /// Somewhere between them the family passes through a line (infinite radius).
    #[error("the surface is unbounded: at α = {alpha} the interpolated circle is a line")]
    Unbounded {
        /// Where.
        alpha: f64,
    },
}

/// How rays are intersected with the surface.
#[derive(Clone, Copy, Debug, PartialEq, serde::Deserialize)]
#[serde(rename_all = "lowercase", tag = "method", deny_unknown_fields)]
pub enum Method {
    /// Baseline (the paper's): `samples` uniform samples of `f` over [0, 1] per ray, sign
    /// changes bisected, local minima of `|f|` searched.
    Sampling {
        /// Samples per ray.
        samples: usize,
    },
    /// The degree-8 polynomial in α ([`Family::polynomial`]) per ray, its roots in [0, 1]
    /// isolated by Bernstein subdivision and refined to `tolerance` in α.
    Polynomial {
        /// Refinement tolerance in α (0: to rounding level).
        tolerance: f64,
    },
    /// Bounding spheres over `leaves` α-intervals (a binary tree, built once per surface)
    /// reject rays and isolate the intervals a ray can hit; each is sampled `per_leaf`
    /// times and roots are refined by safeguarded Newton with the exact `f'`.
    Hierarchy {
        /// α-intervals at the bottom of the tree (a power of two).
        leaves: usize,
        /// Samples per interval a ray reaches.
        per_leaf: usize,
    },
    /// The tree of [`Method::Hierarchy`] to cull, and the polynomial of
    /// [`Method::Polynomial`], restricted to the intervals reached, to find the roots.
    Hybrid {
        /// α-intervals at the bottom of the tree (a power of two).
        leaves: usize,
        /// Refinement tolerance in α.
        tolerance: f64,
    },
}

impl Default for Method {
    fn default() -> Self {
        Method::Hybrid { leaves: 16, tolerance: 0.0 }
    }
}

impl Method {
    /// Why these settings cannot work, if they cannot.
    pub fn check(&self) -> Result<(), String> {
        let leaves_ok = |leaves: usize| (1..=1 << 16).contains(&leaves);
        let tolerance_ok = |t: f64| (0.0..=0.1).contains(&t);
        match *self {
            Method::Sampling { samples } if samples < 2 => Err("samples must be at least 2".into()),
            Method::Hierarchy { leaves, per_leaf } if !leaves_ok(leaves) || per_leaf < 2 => {
                Err("leaves must be 1 to 65536 and per_leaf at least 2".into())
            }
            Method::Polynomial { tolerance } if !tolerance_ok(tolerance) => Err("tolerance must be 0 to 0.1".into()),
            Method::Hybrid { leaves, tolerance } if !leaves_ok(leaves) || !tolerance_ok(tolerance) => {
                Err("leaves must be 1 to 65536 and tolerance 0 to 0.1".into())
            }
            _ => Ok(()),
        }
    }
}

/// A surface swept by the circles interpolated between two circles.
#[derive(Clone, Debug)]
pub struct EvolvedSurface {
    /// The circles in the local frame, with per-surface constants.
    family: Family<f64>,
    /// The local frame's origin, in world coordinates.
    origin: E3,
    /// Bounding-sphere radius about `origin`.
    radius: f64,
    /// How rays are intersected.
    method: Method,
    /// Bounding spheres over α-intervals, for the methods that cull with them.
    tree: Option<Tree>,
}

/// The bounding sphere is sampled this finely, then padded.
const BOUND_SAMPLES: usize = 512;

impl EvolvedSurface {
    /// The surface between `c1` (α = 0) and `c2` (α = 1), given in world coordinates and
    /// moved to a frame centred between them.
    pub fn new(c1: Circle, c2: Circle, method: Method) -> Result<Self, SurfaceError> {
        let centre =
            |c: &Circle, which| c.centre_normal_radius().map_err(|reason| SurfaceError::NotACircle { which, reason });
        let ((p1, _, _), (p2, _, _)) = (centre(&c1, 1)?, centre(&c2, 2)?);
        let origin = scale(add(p1, p2), 0.5);
        let to_local = Translator::from_vector(origin.map(|x| -x));
        Self::in_frame(origin, to_local.sandwich(c1), to_local.sandwich(c2), method)
    }

    /// The surface between circles given in a frame whose origin is `origin` (world
    /// coordinates). Building them there, rather than far out in world coordinates, keeps
    /// their precision. All per-surface work (bounds, tree, polynomial constants) is done here.
    ///
    /// The circles are rebuilt from their centre, normal and radius: a trivector typed with
    /// rounded coefficients is not exactly a blade (`C C̃` then has a 4-vector part), and the
    /// polynomial method relies on `⟨−X X̃⟩₄ = α(1 − α) W` exactly.
    pub fn in_frame(origin: E3, c1: Circle, c2: Circle, method: Method) -> Result<Self, SurfaceError> {
        let blade = |c: Circle, which| {
            let not_a_circle = |reason| SurfaceError::NotACircle { which, reason };
            let (centre, normal, radius) = c.centre_normal_radius().map_err(not_a_circle)?;
            Circle::from_centre_normal_radius(centre, normal, radius).map_err(not_a_circle)
        };
        let pair = Pair::new(blade(c1, 1)?, blade(c2, 2)?).ok_or(SurfaceError::Degenerate)?;
        let mut radius = 0.0f64;
        for k in 0..=BOUND_SAMPLES {
            let alpha = k as f64 / BOUND_SAMPLES as f64;
            let (c, _, r) = pair.at(alpha)?.centre_normal_radius().map_err(|_| SurfaceError::Unbounded { alpha })?;
            radius = radius.max(norm(c) + r);
        }
        let tree = match method {
            Method::Hierarchy { leaves, .. } | Method::Hybrid { leaves, .. } => {
                Some(Tree::new(&pair, leaves.next_power_of_two().max(1))?)
            }
            Method::Sampling { .. } | Method::Polynomial { .. } => None,
        };
        Ok(EvolvedSurface { family: Family::new(pair), origin, radius: radius * PAD, method, tree })
    }

    /// The same surface intersected by another method.
    pub fn with_method(&self, method: Method) -> Result<Self, SurfaceError> {
        Self::in_frame(self.origin, self.family.pair.c1, self.family.pair.c2, method)
    }

    /// The bounding sphere `(centre, radius)` in world coordinates.
    pub fn bounds(&self) -> (E3, f64) {
        (self.origin, self.radius)
    }

    /// The circles in the local frame (with per-surface constants), and the frame's origin.
    pub fn family(&self) -> (&Family<f64>, E3) {
        (&self.family, self.origin)
    }

    /// The method in use.
    pub fn method(&self) -> Method {
        self.method
    }

    /// The ray moved to the local frame, if it can reach the bounding sphere in
    /// `(t_min, t_max)`.
    pub fn local_ray(&self, ray: &Ray, t_min: f64, t_max: f64) -> Option<Ray> {
        if !crosses(ray, self.origin, self.radius, t_min, t_max) {
            return None;
        }
        let o = sub(ray.origin, self.origin);
        let line = Line::from_point_direction(o, ray.dir).ok()?;
        Some(Ray { origin: o, dir: ray.dir, line })
    }

    /// Candidate α for a ray in the local frame: what the method's root finder returns over
    /// the α-intervals it reaches, in increasing α per interval.
    pub fn candidates(&self, local: &Ray, t_min: f64, t_max: f64) -> Roots<f64> {
        let mut out = Roots::new();
        let line = &local.line;
        let culled = |finder: &dyn Fn(usize) -> Finder, out: &mut Roots<f64>| {
            let tree = self.tree.as_ref().expect("a tree for this method");
            for (lo, hi, leaves) in tree.intervals(local, t_min, t_max) {
                self.family.roots(line, finder(leaves), lo, hi, out);
            }
        };
        match self.method {
            Method::Sampling { samples } => self.family.roots(line, Finder::Samples(samples), 0.0, 1.0, &mut out),
            Method::Polynomial { tolerance } => {
                self.family.roots(line, Finder::Polynomial(tolerance), 0.0, 1.0, &mut out)
            }
            Method::Hierarchy { per_leaf, .. } => culled(&|leaves| Finder::Slope(per_leaf.max(2) * leaves), &mut out),
            Method::Hybrid { tolerance, .. } => culled(&|_| Finder::Polynomial(tolerance), &mut out),
        }
        out
    }

    /// The nearest crossing with `t_min < t < t_max`.
    pub fn intersect(&self, ray: &Ray, t_min: f64, t_max: f64) -> Option<Crossing> {
        let local = self.local_ray(ray, t_min, t_max)?;
        let alphas = self.candidates(&local, t_min, t_max);
        let (t, x, alpha) = self.family.nearest((local.origin, local.dir, &local.line), &alphas, t_min, t_max)?;
        Some(Crossing { t, point: add(x, self.origin), alpha: Some(alpha) })
    }

    /// The unit normal at a crossing (eq. 6–11, sign not yet turned to the ray). Where the
    /// circles do not move (`Ẋ = 0`, so `N = 0`) the surface has no normal of its own; the
    /// circle's outward radial direction is used there.
    pub fn normal(&self, crossing: &Crossing) -> E3 {
        let x = sub(crossing.point, self.origin);
        let alpha = crossing.alpha.unwrap_or(0.0);
        let pair = &self.family.pair;
        pair.normal(alpha, x)
            .ok()
            .or_else(|| {
                let (c, _, _) = pair.at(alpha).ok()?.centre_normal_radius().ok()?;
                cga_core::euclid::unit(sub(x, c))
            })
            .unwrap_or([0.0, 0.0, 1.0])
    }
}
