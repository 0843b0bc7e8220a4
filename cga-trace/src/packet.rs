//! Ray packets: four neighbouring camera rays, and the four shadow rays from their hits
//! towards one light, met with the scene's spheres, planes and disks on the generated types
//! instantiated on four f64 lanes ([`F64x4`]) — the same meets as the scalar path
//! ([`crate::shapes`]), operation for operation, so the same bits.
//!
//! Only the CGA products run in lanes: classifying a meet, reading its points and keeping
//! the nearest crossing stay per lane (they branch). Other shapes (triangles, evolved and
//! ruled surfaces) are met one lane at a time through their own code, normals and shading
//! are per lane, and mirror bounces continue one ray at a time (they scatter). A scene
//! whose rays do not come four to a row (a crop narrower than four, the last pixels of a
//! row) uses the scalar path for the remainder.

use crate::backend::{Backend, Sparse, SparseShape};
use crate::ray::Ray;
use crate::render::{Cast, Layers, Renderer, T_MIN, light_term, mirror_ray, sum_layers};
use crate::scene::Object;
use crate::shapes::{Crossing, Hit};
use cga_core::euclid::{E3, tolerance};
#[cfg(target_arch = "x86_64")]
use cga_core::simd::avx2;
use cga_core::simd::{F64x4, Lanes};
use cga_core::{InnerProduct, LeftContraction, Line, Plane, Sphere, Vector, ei};

/// Four rays, lane `k` being ray `k`.
#[derive(Clone, Copy, Debug)]
pub struct Packet {
    /// The scalar rays (for the per-lane steps).
    pub rays: [Ray; 4],
    /// Their origins in lanes.
    pub origin: [F64x4; 3],
    /// Their unit directions in lanes.
    pub dir: [F64x4; 3],
    /// Their lines in lanes.
    pub line: Line<F64x4>,
}

impl Packet {
    /// Four rays as a packet.
    pub fn new(rays: [Ray; 4]) -> Self {
        Packet::with_line(rays, Line::pack(rays.map(|r| r.line)))
    }

    /// Four rays whose lines are already in lanes (the camera builds them so).
    pub fn with_line(rays: [Ray; 4], line: Line<F64x4>) -> Self {
        let lanes = |f: fn(&Ray) -> E3| {
            let v = rays.each_ref().map(f);
            [0, 1, 2].map(|k| F64x4::new([v[0][k], v[1][k], v[2][k], v[3][k]]))
        };
        Packet { rays, origin: lanes(|r| r.origin), dir: lanes(|r| r.dir), line }
    }
}

/// A crossing per lane, `None` where the lane's ray misses.
type Crossings = [Option<Crossing>; 4];

/// Lane-wise `a − b` and `a · b` for points in lanes.
fn dot4(a: [F64x4; 3], b: [F64x4; 3]) -> F64x4 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

/// `(x − o) · d` per lane, as [`Ray::t_of`] computes it.
fn t_of4(p: &Packet, x: [F64x4; 3]) -> F64x4 {
    dot4([x[0] - p.origin[0], x[1] - p.origin[1], x[2] - p.origin[2]], p.dir)
}

/// `down(X)` in lanes: the Euclidean point and whether it is finite, as [`cga_core::down`]
/// decides it lane by lane.
fn down4(x: Vector<F64x4>) -> ([F64x4; 3], [bool; 4]) {
    let inv = F64x4::splat(1.0) / x.eo;
    let point = [x.e1 * inv, x.e2 * inv, x.e3 * inv];
    let (w, inv) = (x.eo.to_array(), inv.to_array());
    let e = [x.e1.to_array(), x.e2.to_array(), x.e3.to_array()];
    let finite = core::array::from_fn(|l| {
        let m = e.iter().fold(1.0f64, |m, c| if c[l].abs() > m { c[l].abs() } else { m });
        w[l].abs() > tolerance(m) * f64::EPSILON.sqrt() && inv[l].is_finite()
    });
    (point, finite)
}

/// Lane `l` of a point in lanes.
fn lane(x: &[F64x4; 3], l: usize) -> E3 {
    [x[0].to_array()[l], x[1].to_array()[l], x[2].to_array()[l]]
}

/// `L ∨ S` in lanes, as [`SphereShape::intersect`](crate::shapes::SphereShape) meets it:
/// classified by the pair's square (rays and spheres normalised: weight 1), its points
/// `P·e ∓ √(P²) e` with `e = ei ⌋ P`, ordered along the ray, the first within range kept.
#[inline(always)]
fn meet_sphere(p: &Packet, sphere: &Sphere<F64x4>, t_min: &[f64; 4], t_max: &[f64; 4]) -> Crossings {
    let pair = p.line & *sphere;
    let square = pair.inner(pair).s.to_array();
    let tol = tolerance(1.0);
    let hit = square.map(|q| q.abs() <= tol || q > 0.0);
    if !hit.iter().any(|&h| h) {
        return [None; 4];
    }
    let e = ei::<F64x4>().lc(pair);
    let pe = pair | e;
    // The double point of a tangent meet: `√P² = 0` in the same formula.
    let s = F64x4::new(square.map(|q| if q.abs() <= tol { 0.0 } else { q.sqrt() }));
    let ((a, a_ok), (b, b_ok)) = (down4(pe - e.scale(s)), down4(pe + e.scale(s)));
    let (ta, tb) = (t_of4(p, a).to_array(), t_of4(p, b).to_array());
    let ab = dot4([b[0] - a[0], b[1] - a[1], b[2] - a[2]], p.dir).to_array();
    core::array::from_fn(|l| {
        if !(hit[l] && a_ok[l] && b_ok[l]) {
            return None;
        }
        let (first, second) = if ab[l] < 0.0 { ((tb[l], &b), (ta[l], &a)) } else { ((ta[l], &a), (tb[l], &b)) };
        [first, second].into_iter().find(|(t, _)| *t > t_min[l] && *t < t_max[l]).map(|(t, x)| Crossing {
            t,
            point: lane(x, l),
            alpha: None,
        })
    })
}

/// `L ∨ Π` in lanes, as the plane and disk shapes meet it: the flat point's point where
/// its weight is not zero to rounding, within range, and for a disk within the rim.
#[inline(always)]
fn meet_plane(
    p: &Packet,
    plane: &Plane<F64x4>,
    rim: Option<(E3, f64)>,
    t_min: &[f64; 4],
    t_max: &[f64; 4],
) -> Crossings {
    let flat = p.line & *plane;
    let inv = F64x4::splat(1.0) / flat.eoi;
    let x = [flat.e1i * inv, flat.e2i * inv, flat.e3i * inv];
    let t = t_of4(p, x).to_array();
    let (w, inv) = (flat.eoi.to_array(), inv.to_array());
    let inside = rim.map(|(c, r)| {
        let d = [x[0] - F64x4::splat(c[0]), x[1] - F64x4::splat(c[1]), x[2] - F64x4::splat(c[2])];
        dot4(d, d).to_array().map(|q| q <= r * r)
    });
    core::array::from_fn(|l| {
        let ok = w[l].abs() > tolerance(1.0) && inv[l].is_finite() && t[l] > t_min[l] && t[l] < t_max[l];
        (ok && inside.is_none_or(|i| i[l])).then(|| Crossing { t: t[l], point: lane(&x, l), alpha: None })
    })
}

/// A scene object as the packet path meets it.
#[derive(Clone, Debug)]
pub enum PacketShape {
    /// A sphere, the same in every lane.
    Sphere(Sphere<F64x4>),
    /// A plane, and a disk's rim.
    Plane(Plane<F64x4>, Option<(E3, f64)>),
    /// Met one lane at a time.
    PerLane,
}

impl PacketShape {
    /// The packet form of a prepared sparse shape.
    pub fn of(shape: &SparseShape) -> Self {
        match shape {
            SparseShape::Sphere(s) => PacketShape::Sphere(Sphere::pack([s.sphere; 4])),
            SparseShape::Plane(p) => PacketShape::Plane(Plane::pack([p.plane; 4]), None),
            SparseShape::Disk(d) => {
                PacketShape::Plane(Plane::pack([d.disk.plane; 4]), Some((d.disk.centre, d.disk.radius)))
            }
            _ => PacketShape::PerLane,
        }
    }
}

impl<'a> Renderer<'a, Sparse> {
    /// The crossings of the packet's rays with object `k`.
    #[inline(always)]
    fn cross(&self, k: usize, p: &Packet, t_min: &[f64; 4], t_max: &[f64; 4]) -> Crossings {
        match &self.packets[k] {
            PacketShape::Sphere(s) => meet_sphere(p, s, t_min, t_max),
            PacketShape::Plane(plane, rim) => meet_plane(p, plane, *rim, t_min, t_max),
            PacketShape::PerLane => {
                core::array::from_fn(|l| Sparse::intersect(&self.shapes[k], &p.rays[l], t_min[l], t_max[l]))
            }
        }
    }

    /// The nearest crossing per active lane over all objects, and its object: compiled for AVX2
    /// and FMA where the CPU has them (the lanes' products then run in one register each).
    fn nearest_packet(&self, p: &Packet, active: &[bool; 4]) -> [Option<(Crossing, usize)>; 4] {
        #[cfg(target_arch = "x86_64")]
        if avx2() {
            // SAFETY: the CPU has the features the function is compiled for.
            return unsafe { self.nearest_packet_avx2(p, active) };
        }
        self.nearest_packet_lanes(p, active)
    }

    #[cfg(target_arch = "x86_64")]
    #[target_feature(enable = "avx2,fma")]
    unsafe fn nearest_packet_avx2(&self, p: &Packet, active: &[bool; 4]) -> [Option<(Crossing, usize)>; 4] {
        self.nearest_packet_lanes(p, active)
    }

    /// Which lanes' rays are blocked before their `t_max` (a lane with `t_max = 0` is
    /// inactive and never blocked); dispatched as [`Renderer::nearest_packet`].
    fn blocked_packet(&self, p: &Packet, t_max: &[f64; 4]) -> [bool; 4] {
        #[cfg(target_arch = "x86_64")]
        if avx2() {
            // SAFETY: the CPU has the features the function is compiled for.
            return unsafe { self.blocked_packet_avx2(p, t_max) };
        }
        self.blocked_packet_lanes(p, t_max)
    }

    #[cfg(target_arch = "x86_64")]
    #[target_feature(enable = "avx2,fma")]
    unsafe fn blocked_packet_avx2(&self, p: &Packet, t_max: &[f64; 4]) -> [bool; 4] {
        self.blocked_packet_lanes(p, t_max)
    }

    #[inline(always)]
    fn nearest_packet_lanes(&self, p: &Packet, active: &[bool; 4]) -> [Option<(Crossing, usize)>; 4] {
        // An inactive lane's range is empty: it finds nothing.
        let t_min = [T_MIN; 4];
        let mut t_max = active.map(|a| if a { f64::INFINITY } else { f64::NEG_INFINITY });
        let mut best = [None; 4];
        for k in 0..self.shapes.len() {
            for (l, c) in self.cross(k, p, &t_min, &t_max).into_iter().enumerate() {
                if let Some(c) = c {
                    t_max[l] = c.t;
                    best[l] = Some((c, k));
                }
            }
        }
        best
    }

    /// [`Renderer::blocked_packet`]'s loop: stops once every active lane is blocked.
    #[inline(always)]
    fn blocked_packet_lanes(&self, p: &Packet, t_max: &[f64; 4]) -> [bool; 4] {
        let mut blocked = t_max.map(|t| t.is_nan() || t <= 0.0);
        let active = blocked.map(|b| !b);
        let t_min = [0.0; 4];
        for k in 0..self.shapes.len() {
            if blocked.iter().all(|&b| b) {
                break;
            }
            let limit: [f64; 4] = core::array::from_fn(|l| if blocked[l] { f64::NEG_INFINITY } else { t_max[l] });
            for (l, c) in self.cross(k, p, &t_min, &limit).into_iter().enumerate() {
                blocked[l] |= c.is_some();
            }
        }
        core::array::from_fn(|l| active[l] && blocked[l])
    }

    /// Four neighbouring pixels of a row, `(i₀ + k, j)`, through packets — the camera rays,
    /// the mirror bounces of those that hit mirrors (lanes whose ray has ended ride along,
    /// inactive), and at every hit the shadow rays towards each light; `None` where a
    /// camera ray cannot be formed (the scalar path then says why). Each lane gets the bits
    /// [`Renderer::trace`] gives its ray: the same meets, shading and sum from the deepest
    /// bounce up.
    pub fn pixels4(&self, i0: u32, j: u32, cast: &mut Cast) -> Option<[[f64; 3]; 4]> {
        let (camera, settings) = (&self.scene.camera, &self.scene.settings);
        let v = f64::from(j) + 0.5;
        let (mut rays, line) = camera.rays4([0, 1, 2, 3].map(|k| f64::from(i0 + k) + 0.5), v)?;
        cast.primary += 4;
        let mut packet = Packet::with_line(rays, line);
        let mut active = [true; 4];
        let mut deepest = [settings.background; 4];
        let mut layers: [Layers; 4] = Default::default();
        let mut depth = 0;
        while active.iter().any(|&a| a) {
            if depth > 0 {
                packet = Packet::new(rays);
            }
            let nearest = self.nearest_packet(&packet, &active);
            let hits: [Option<(Hit, &Object)>; 4] = core::array::from_fn(|l| {
                nearest[l].map(|(c, k)| {
                    let normal = Sparse::normal(&self.shapes[k], &rays[l], &c);
                    (Hit { t: c.t, point: c.point, normal, alpha: c.alpha }, &self.scene.objects[k])
                })
            });
            let local = self.shade_packet(&rays, &hits, cast);
            for l in 0..4 {
                if !active[l] {
                    continue;
                }
                let Some((hit, object)) = hits[l] else {
                    (deepest[l], active[l]) = (settings.background, false);
                    continue;
                };
                let kr = object.material.kr;
                if !(kr > 0.0 && depth < settings.max_depth) {
                    (deepest[l], active[l]) = (local[l], false);
                    continue;
                }
                cast.reflection += 1;
                layers[l].push((local[l], kr));
                rays[l] = mirror_ray::<Sparse>(&rays[l], &hit);
            }
            depth += 1;
        }
        Some(core::array::from_fn(|l| sum_layers(&layers[l], deepest[l])))
    }

    /// The ambient and direct light at the lanes' hits, the shadow rays towards each light
    /// cast as one packet; the background where a lane has no hit.
    fn shade_packet(&self, rays: &[Ray; 4], hits: &[Option<(Hit, &Object)>; 4], cast: &mut Cast) -> [[f64; 3]; 4] {
        let settings = &self.scene.settings;
        let mut colours: [[f64; 3]; 4] =
            core::array::from_fn(|l| hits[l].map_or(settings.background, |(_, o)| self.ambient(o)));
        for light in &self.scene.lights {
            let terms: [_; 4] =
                core::array::from_fn(|l| hits[l].and_then(|(h, o)| light_term(rays[l].dir, &h, &o.material, light)));
            let mut s = [1.0; 4];
            if settings.shadows && terms.iter().any(Option::is_some) {
                let (mut shadow, mut t_max) = (*rays, [0.0; 4]);
                for (l, term) in terms.iter().enumerate() {
                    if let Some(term) = term {
                        cast.shadow += 1;
                        shadow[l] = Sparse::ray(term.shadow_origin, term.l);
                        t_max[l] = term.distance;
                    }
                }
                let blocked = self.blocked_packet(&Packet::new(shadow), &t_max);
                s = blocked.map(|b| if b { settings.shadow_transmission } else { 1.0 });
            }
            for l in 0..4 {
                if let (Some(term), Some((_, object))) = (&terms[l], hits[l]) {
                    self.add_light(&mut colours[l], object, light, term, s[l]);
                }
            }
        }
        colours
    }
}
