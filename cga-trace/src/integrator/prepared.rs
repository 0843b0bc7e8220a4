//! What a renderer prepares of each object — its shape in the back end's form, its bounds,
//! crossing error, flatness and the rest — kept between the pictures of one scene at several
//! instants (a shutter's, an animation's frames): prepared again only for an object whose
//! shape is not the very one it was prepared from (one that moved; the scene's source keeps
//! the others as built), so an instant costs what its moving objects cost, not the scene.

use super::media;
use crate::backend::Backend;
use crate::bvh;
use crate::material::Material;
use crate::object::Object;
use crate::shapes::Shape;
use cga_core::euclid::E3;
use std::any::Any;
use std::borrow::Cow;
use std::sync::Arc;

/// What renderers of one scene keep from one picture to the next: each object as prepared
/// for the back end last used, and the hierarchy over the objects that do not move.
#[derive(Default)]
pub struct Kept {
    hierarchy: bvh::Kept,
    /// A [`Prepared`] for the back end last used.
    prepared: Option<Box<dyn Any + Send + Sync>>,
}

/// What an object was prepared from: its shape (the very one), material, solid and whether
/// it moves.
type Source = (Arc<dyn Shape>, Material, Option<usize>, bool);

/// Each object as back end `B` prepared it, in scene order.
pub(super) struct Prepared<B: Backend> {
    /// What each entry was prepared from, to know an object that is the same (empty where
    /// the lists are for one picture).
    from: Vec<Source>,
    /// Whether `from` is kept.
    keeps: bool,
    /// Whether an object that does not move was prepared anew at the last update (the
    /// hierarchy over them must then be built again).
    still_changed: bool,
    shapes: Vec<B::Shape>,
    /// Bounding spheres (`None`: unbounded).
    all: Vec<Option<(E3, f64)>>,
    /// Bounding spheres of the objects worth culling.
    cull: Vec<Option<(E3, f64)>>,
    flat: Vec<bool>,
    clear: Vec<bool>,
    errors: Vec<f64>,
    tie: Vec<(bool, f64, usize)>,
    medium: Vec<Option<usize>>,
    moving: Vec<bool>,
}

/// A renderer's per-object lists, borrowed from a [`Prepared`] or owned.
pub(super) struct Parts<'a, B: Backend> {
    pub(super) shapes: Cow<'a, [B::Shape]>,
    pub(super) all: Cow<'a, [Option<(E3, f64)>]>,
    pub(super) cull: Cow<'a, [Option<(E3, f64)>]>,
    pub(super) flat: Cow<'a, [bool]>,
    pub(super) clear: Cow<'a, [bool]>,
    pub(super) errors: Cow<'a, [f64]>,
    pub(super) tie: Cow<'a, [(bool, f64, usize)]>,
    pub(super) medium: Cow<'a, [Option<usize>]>,
    pub(super) moving: Cow<'a, [bool]>,
    /// Whether an object that does not move is not as it was at the last picture.
    pub(super) still_changed: bool,
}

impl<B: Backend> Prepared<B> {
    /// `objects` prepared, owned (for one picture).
    pub(super) fn parts_of(objects: &[Object]) -> Parts<'static, B> {
        let mut p = Prepared::<B>::empty();
        p.keeps = false;
        p.update(objects);
        Parts {
            shapes: Cow::Owned(p.shapes),
            all: Cow::Owned(p.all),
            cull: Cow::Owned(p.cull),
            flat: Cow::Owned(p.flat),
            clear: Cow::Owned(p.clear),
            errors: Cow::Owned(p.errors),
            tie: Cow::Owned(p.tie),
            medium: Cow::Owned(p.medium),
            moving: Cow::Owned(p.moving),
            still_changed: true,
        }
    }

    /// The lists, borrowed.
    fn parts(&self) -> Parts<'_, B> {
        Parts {
            shapes: Cow::Borrowed(&self.shapes),
            all: Cow::Borrowed(&self.all),
            cull: Cow::Borrowed(&self.cull),
            flat: Cow::Borrowed(&self.flat),
            clear: Cow::Borrowed(&self.clear),
            errors: Cow::Borrowed(&self.errors),
            tie: Cow::Borrowed(&self.tie),
            medium: Cow::Borrowed(&self.medium),
            moving: Cow::Borrowed(&self.moving),
            still_changed: self.still_changed,
        }
    }

    fn empty() -> Self {
        Prepared {
            from: Vec::new(),
            shapes: Vec::new(),
            all: Vec::new(),
            cull: Vec::new(),
            flat: Vec::new(),
            clear: Vec::new(),
            errors: Vec::new(),
            tie: Vec::new(),
            medium: Vec::new(),
            moving: Vec::new(),
            keeps: true,
            still_changed: true,
        }
    }

    /// Room for `n` objects in every list.
    fn reserve(&mut self, n: usize) {
        self.from.reserve(if self.keeps { n } else { 0 });
        self.shapes.reserve(n);
        self.all.reserve(n);
        self.cull.reserve(n);
        self.flat.reserve(n);
        self.clear.reserve(n);
        self.errors.reserve(n);
        self.tie.reserve(n);
        self.moving.reserve(n);
    }

    /// Object `k` prepared into place `k` (pushed where the lists are shorter).
    fn set(&mut self, k: usize, o: &Object) {
        let bounds = o.shape.bounds();
        let dielectric = o.material.dielectric();
        if self.keeps {
            let from = (o.shape.clone(), o.material, o.solid, o.moving);
            match self.from.get_mut(k) {
                Some(f) => *f = from,
                None => self.from.push(from),
            }
        }
        let entry = (
            B::prepare(&o.shape),
            bounds,
            bounds.filter(|_| o.shape.cull()),
            o.shape.flat(),
            dielectric,
            B::crossing_error(o.shape.as_ref()),
            (dielectric, bounds.map_or(f64::INFINITY, |(_, r)| r), k),
            o.moving,
        );
        if k < self.shapes.len() {
            (
                self.shapes[k],
                self.all[k],
                self.cull[k],
                self.flat[k],
                self.clear[k],
                self.errors[k],
                self.tie[k],
                self.moving[k],
            ) = entry;
        } else {
            self.shapes.push(entry.0);
            self.all.push(entry.1);
            self.cull.push(entry.2);
            self.flat.push(entry.3);
            self.clear.push(entry.4);
            self.errors.push(entry.5);
            self.tie.push(entry.6);
            self.moving.push(entry.7);
        }
    }

    /// These lists for `objects`, keeping every entry whose object is the one it was
    /// prepared from (the very shape, the same material and solid).
    fn update(&mut self, objects: &[Object]) {
        let n = objects.len();
        if n != self.shapes.len() || !self.keeps {
            *self = Prepared { keeps: self.keeps, ..Prepared::empty() };
            self.reserve(n);
        }
        self.still_changed = self.shapes.is_empty();
        let mut changed = false;
        for (k, o) in objects.iter().enumerate() {
            let same = self.from.get(k).is_some_and(|(s, m, solid, moving)| {
                Arc::ptr_eq(s, &o.shape) && *m == o.material && *solid == o.solid && *moving == o.moving
            });
            if !same {
                changed = true;
                self.still_changed |= !o.moving;
                self.set(k, o);
            }
        }
        // Which solid each object bounds: only a new object can change it.
        if changed || self.medium.len() != n {
            self.medium = media::media(objects);
        }
    }
}

impl Kept {
    /// `objects` prepared for back end `B`, reusing what was prepared for the last picture
    /// wherever an object is the same, and the hierarchy kept.
    pub(super) fn prepared<B: Backend>(&mut self, objects: &[Object]) -> (Parts<'_, B>, &mut bvh::Kept) {
        let mut p = match self.prepared.take().map(|p| p.downcast::<Prepared<B>>()) {
            Some(Ok(p)) => p,
            _ => Box::new(Prepared::<B>::empty()),
        };
        p.update(objects);
        let p: &Prepared<B> = self.prepared.insert(p).downcast_ref().expect("just put");
        (p.parts(), &mut self.hierarchy)
    }
}
