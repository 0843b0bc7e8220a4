//! Which dielectric solid each object bounds, and which one holds a point (the camera):
//! decided once, when a renderer is made, from the geometry alone.

use crate::object::Object;
use crate::ray::Ray;
use cga_core::euclid::E3;
use std::collections::HashMap;

/// Each object's medium (see [`Renderer::medium`](super::Renderer::medium)): its solid's first object, or `None` for
/// a thin sheet.
pub(crate) fn media(objects: &[Object]) -> Vec<Option<usize>> {
    let mut first: HashMap<usize, usize> = HashMap::new();
    let medium = |(k, o): (usize, &Object)| match o.solid {
        Some(s) => Some(*first.entry(s).or_insert(k)),
        None => (!o.shape.flat()).then_some(k),
    };
    objects.iter().enumerate().map(medium).collect()
}

/// The dielectric solid holding `point`, if any: the medium (as [`media`] names it) whose
/// surfaces a ray from `point` crosses an odd number of times, decided by the geometry alone
/// (no normal is read), by two of three rays in directions off every axis (a ray through a
/// mesh's edge or a tangent can miscount; three cannot all). Dielectrics do not overlap, so
/// at most one holds it.
pub(crate) fn medium_at(objects: &[Object], medium: &[Option<usize>], errors: &[f64], point: E3) -> Option<usize> {
    const DIRECTIONS: [E3; 3] = [
        [0.267_261_2, 0.534_522_5, 0.801_783_7],
        [-0.801_783_7, 0.267_261_2, 0.534_522_5],
        [0.534_522_5, -0.801_783_7, -0.267_261_2],
    ];
    // Crossings counted per shape at most (a bound on the time a pathological shape takes).
    const MOST: usize = 64;
    let mut votes: HashMap<usize, u32> = HashMap::new();
    for dir in DIRECTIONS {
        let Some(ray) = Ray::new(point, dir) else { continue };
        let mut odd: HashMap<usize, bool> = HashMap::new();
        for (k, object) in objects.iter().enumerate() {
            let Some(m) = medium[k].filter(|_| object.material.dielectric()) else { continue };
            let mut t = 0.0;
            let mut crossings = 0;
            while let Some(c) = object.shape.intersect(&ray, t, f64::INFINITY) {
                crossings += 1;
                // Past this crossing by its error (and the rounding of t), to the next one.
                t = c.t + errors[k].max(c.t.abs() * 1e-12).max(f64::MIN_POSITIVE);
                if crossings == MOST {
                    break;
                }
            }
            *odd.entry(m).or_default() ^= crossings % 2 == 1;
        }
        for (m, inside) in odd {
            *votes.entry(m).or_default() += u32::from(inside);
        }
    }
    votes.into_iter().filter(|&(_, v)| v >= 2).map(|(m, _)| m).min()
}
