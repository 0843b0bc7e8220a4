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
use crate::light::Light;
use crate::material::{Material, power};
use crate::ray::Ray;
#[cfg(doc)]
use crate::render::light_term;
use crate::render::{Cast, Layers, Renderer, T_MIN, sum_layers};
use crate::scene::Object;
use crate::shapes::{Crossing, Hit};
use cga_core::euclid::{E3, add, dot, norm, reflect, scale, sub, tolerance, unit};
#[cfg(target_arch = "x86_64")]
use cga_core::simd::avx2;
use cga_core::simd::{F64x4, Lanes};
use cga_core::{InnerProduct, LeftContraction, Line, Plane, Real, Sphere, Vector, ei};

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

impl Packet {
    /// Four rays from origins along unit directions given in lanes (secondary rays), as
    /// [`Ray::unit`] makes each.
    #[inline(always)]
    pub fn from_lanes(origin: [F64x4; 3], dir: [F64x4; 3]) -> Self {
        let line = Line::from_point_unit_direction(origin, dir);
        let lines = Line::unpack(line);
        let rays = core::array::from_fn(|l| Ray { origin: lane(&origin, l), dir: lane(&dir, l), line: lines[l] });
        Packet { rays, origin, dir, line }
    }
}

/// Four points (or vectors) as three coordinates in lanes.
#[inline(always)]
fn lanes3(v: [E3; 4]) -> [F64x4; 3] {
    core::array::from_fn(|k| F64x4::new([v[0][k], v[1][k], v[2][k], v[3][k]]))
}

/// `x` in the lanes where `keep`, `other` elsewhere.
#[inline(always)]
fn select(keep: &[bool; 4], x: [F64x4; 3], other: E3) -> [F64x4; 3] {
    core::array::from_fn(|k| {
        let x = x[k].to_array();
        F64x4::new(core::array::from_fn(|l| if keep[l] { x[l] } else { other[k] }))
    })
}

/// [`leaving_origin`](crate::ray::leaving_origin) in lanes: `x ± 1e-6 (1 + |x|∞) n`, on
/// the side of the ray's direction, `n_dir` being `n · dir`.
#[inline(always)]
fn leaving_origin4(x: [F64x4; 3], n: [F64x4; 3], n_dir: F64x4) -> [F64x4; 3] {
    let side = F64x4::new(n_dir.to_array().map(|c| if c >= 0.0 { 1.0 } else { -1.0 }));
    let largest = x.iter().fold(F64x4::splat(1.0), |m, v| m.max(v.abs()));
    add(x, scale(n, side * (F64x4::splat(1e-6) * largest)))
}

/// The mirror bounces of the lanes that `bounce` (`mirror_ray` lane by lane); the other
/// lanes keep their ray (a zero normal reflects nothing).
#[inline(always)]
fn mirror_packet(p: &Packet, hits: &[Option<(Hit, &Object)>; 4], bounce: &[bool; 4]) -> Packet {
    let at = |l: usize| match hits[l] {
        Some((hit, _)) if bounce[l] => (hit.point, hit.normal),
        _ => (p.rays[l].origin, [0.0; 3]),
    };
    let (x, n) = (lanes3(core::array::from_fn(|l| at(l).0)), lanes3(core::array::from_fn(|l| at(l).1)));
    let r = reflect(p.dir, n);
    Packet::from_lanes(leaving_origin4(x, n, dot(n, r)), r)
}

/// A material for lanes without a hit (their terms are not used).
const NO_MATERIAL: Material = Material { colour: [0.0; 3], ka: 0.0, kd: 0.0, ks: 0.0, q: 0.0, kr: 0.0 };

/// `max(n·h, 0)^q` per lane, `h = unit(l + v)`, as [`light_term`] computes it lane by lane:
/// the power in lanes where all four share a whole `q`, the scalar path for the rest.
#[inline(always)]
fn specular4(m: &[&Material; 4], n: [F64x4; 3], lv: [F64x4; 3]) -> [f64; 4] {
    let inv = F64x4::splat(1.0) / norm(lv);
    let c = dot(n, scale(lv, inv));
    let q = m[0].whole_exponent().filter(|_| m.iter().all(|x| x.q == m[0].q));
    let powers = q.map(|q| power(c, q).to_array());
    let (c, inv) = (c.to_array(), inv.to_array());
    core::array::from_fn(|l| {
        if !(inv[l].is_finite() && inv[l] > 0.0) {
            // `unit` rescales, or there is no `h`.
            return unit(lane(&lv, l)).map_or(0.0, |h| m[l].specular(dot(lane(&n, l), h)));
        }
        match powers {
            Some(p) if c[l] > 0.0 => p[l],
            _ => m[l].specular(c[l]),
        }
    })
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

    /// The nearest crossing per active lane over all objects, and its object.
    #[inline(always)]
    fn nearest_packet(&self, p: &Packet, active: &[bool; 4]) -> [Option<(Crossing, usize)>; 4] {
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

    /// Which lanes' rays are blocked before their `t_max` by an object other than the lane's
    /// `skip` (a lane with `t_max = 0` is inactive and never blocked): stops once every
    /// active lane is blocked, and skips an object no lane tests.
    #[inline(always)]
    fn blocked_packet(&self, p: &Packet, t_max: &[f64; 4], skip: &[Option<usize>; 4]) -> [bool; 4] {
        let mut blocked = t_max.map(|t| t.is_nan() || t <= 0.0);
        let active = blocked.map(|b| !b);
        let t_min = [0.0; 4];
        for k in 0..self.shapes.len() {
            if blocked.iter().all(|&b| b) {
                break;
            }
            let tests: [bool; 4] = core::array::from_fn(|l| !blocked[l] && skip[l] != Some(k));
            if !tests.iter().any(|&b| b) {
                continue;
            }
            let limit: [f64; 4] = core::array::from_fn(|l| if tests[l] { t_max[l] } else { f64::NEG_INFINITY });
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
    /// bounce up. Compiled for AVX2 and FMA where the CPU has them (the lanes then run in
    /// one register each).
    pub fn pixels4(&self, i0: u32, j: u32, cast: &mut Cast) -> Option<[[f64; 3]; 4]> {
        #[cfg(target_arch = "x86_64")]
        if avx2() {
            // SAFETY: the CPU has the features the function is compiled for.
            return unsafe { self.pixels4_avx2(i0, j, cast) };
        }
        self.pixels4_lanes(i0, j, cast)
    }

    #[cfg(target_arch = "x86_64")]
    #[target_feature(enable = "avx2,fma")]
    unsafe fn pixels4_avx2(&self, i0: u32, j: u32, cast: &mut Cast) -> Option<[[f64; 3]; 4]> {
        self.pixels4_lanes(i0, j, cast)
    }

    #[inline(always)]
    fn pixels4_lanes(&self, i0: u32, j: u32, cast: &mut Cast) -> Option<[[f64; 3]; 4]> {
        let (camera, settings) = (&self.scene.camera, &self.scene.settings);
        let v = f64::from(j) + 0.5;
        let (rays, line) = camera.rays4([0, 1, 2, 3].map(|k| f64::from(i0 + k) + 0.5), v)?;
        cast.primary += 4;
        let mut packet = Packet::with_line(rays, line);
        let mut active = [true; 4];
        let mut deepest = [settings.background; 4];
        let mut layers: [Layers; 4] = Default::default();
        let mut depth = 0;
        while active.iter().any(|&a| a) {
            let nearest = self.nearest_packet(&packet, &active);
            let own = nearest.map(|n| n.and_then(|(_, k)| self.skip_own(k)));
            let hits: [Option<(Hit, &Object)>; 4] = core::array::from_fn(|l| {
                nearest[l].map(|(c, k)| {
                    let normal = Sparse::normal(&self.shapes[k], &packet.rays[l], &c);
                    (Hit { t: c.t, point: c.point, normal, alpha: c.alpha }, &self.scene.objects[k])
                })
            });
            let local = self.shade_packet(&packet, &hits, &own, cast);
            let mut bounce = [false; 4];
            for l in 0..4 {
                if !active[l] {
                    continue;
                }
                let Some((_, object)) = hits[l] else {
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
                bounce[l] = true;
            }
            if bounce.iter().any(|&b| b) {
                packet = mirror_packet(&packet, &hits, &bounce);
            }
            depth += 1;
        }
        Some(core::array::from_fn(|l| sum_layers(&layers[l], deepest[l])))
    }

    /// The ambient and direct light at the lanes' hits, in lanes ([`light_term`] and
    /// [`Renderer::add_light`] lane by lane, the same bits), the shadow rays towards each
    /// light cast as one packet (skipping each lane's `own` object); the background where a
    /// lane has no hit.
    #[inline(always)]
    fn shade_packet(
        &self,
        p: &Packet,
        hits: &[Option<(Hit, &Object)>; 4],
        own: &[Option<usize>; 4],
        cast: &mut Cast,
    ) -> [[f64; 3]; 4] {
        let settings = &self.scene.settings;
        let mut colours: [[f64; 3]; 4] =
            core::array::from_fn(|l| hits[l].map_or(settings.background, |(_, o)| self.ambient(o)));
        if !hits.iter().any(Option::is_some) {
            return colours;
        }
        let x = lanes3(hits.map(|h| h.map_or([0.0; 3], |(h, _)| h.point)));
        let n = lanes3(hits.map(|h| h.map_or([0.0; 3], |(h, _)| h.normal)));
        let v = p.dir.map(|d| -d);
        let m = hits.map(|h| h.map_or(&NO_MATERIAL, |(_, o)| &o.material));
        for light in &self.scene.lights {
            let to_light = sub(light.position.map(F64x4::splat), x);
            let distance = norm(to_light);
            let l = scale(to_light, F64x4::splat(1.0) / distance);
            let diffuse = dot(n, l);
            let specular = specular4(&m, n, add(l, v));
            let (d, c) = (distance.to_array(), diffuse.to_array());
            // Where `light_term` gives a term.
            let lit: [bool; 4] = core::array::from_fn(|k| {
                hits[k].is_some() && d[k] > 0.0 && d[k].is_finite() && !(c[k] <= 0.0 && specular[k] <= 0.0)
            });
            if !lit.iter().any(|&b| b) {
                continue;
            }
            let mut s = [1.0; 4];
            if settings.shadows {
                cast.shadow += lit.iter().filter(|&&b| b).count() as u64;
                // Unlit lanes cast a harmless ray with an empty range.
                let origin = select(&lit, leaving_origin4(x, n, diffuse), [0.0; 3]);
                let shadow = Packet::from_lanes(origin, select(&lit, l, [0.0, 0.0, 1.0]));
                let t_max = core::array::from_fn(|k| if lit[k] { d[k] } else { 0.0 });
                let blocked = self.blocked_packet(&shadow, &t_max, own);
                s = blocked.map(|b| if b { settings.shadow_transmission } else { 1.0 });
            }
            let term = self.light4(&m, light, distance, diffuse, &specular, s);
            for (k, colour) in colours.iter_mut().enumerate().filter(|(k, _)| lit[*k]) {
                for (out, t) in colour.iter_mut().zip(&term) {
                    *out += t.to_array()[k];
                }
            }
        }
        colours
    }

    /// One light's term per lane, as [`Renderer::add_light`] adds it:
    /// `s f_att (c k_d max(n·l, 0) + k_s spec) L`.
    #[inline(always)]
    fn light4(
        &self,
        m: &[&Material; 4],
        light: &Light,
        distance: F64x4,
        diffuse: F64x4,
        specular: &[f64; 4],
        s: [f64; 4],
    ) -> [F64x4; 3] {
        let [c0, c1, c2] = self.scene.settings.attenuation.map(F64x4::splat);
        let distance = distance * F64x4::splat(self.scene.frame.scale);
        let f_att =
            (F64x4::splat(1.0) / (c0 + c1 * distance + c2 * distance * distance)).to_array().map(|f| f.min(1.0));
        let sf = F64x4::new(s) * F64x4::new(f_att);
        let (kd, ks) = (F64x4::new(m.map(|m| m.kd)), F64x4::new(m.map(|m| m.ks)));
        let (facing, shine) = (diffuse.max(F64x4::splat(0.0)), ks * F64x4::new(*specular));
        core::array::from_fn(|k| {
            let c = F64x4::new(m.map(|m| m.colour[k]));
            sf * (c * kd * facing + shine) * F64x4::splat(light.colour[k])
        })
    }
}
