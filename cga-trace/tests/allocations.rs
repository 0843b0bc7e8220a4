//! No allocation per ray or pixel: tracing every pixel of the combined scene (evolved surface,
//! shadows, reflections), of a scene of 200 spheres (through the BVH), of a cubic spline surface
//! and of the ruled surfaces allocates nothing.

use cga_trace::{Renderer, Scene};
use std::alloc::{GlobalAlloc, Layout, System};
use std::sync::atomic::{AtomicUsize, Ordering::Relaxed};

/// The system allocator, counting allocations.
struct Counting;

static ALLOCATIONS: AtomicUsize = AtomicUsize::new(0);

unsafe impl GlobalAlloc for Counting {
    unsafe fn alloc(&self, layout: Layout) -> *mut u8 {
        ALLOCATIONS.fetch_add(1, Relaxed);
        unsafe { System.alloc(layout) }
    }
    unsafe fn dealloc(&self, ptr: *mut u8, layout: Layout) {
        unsafe { System.dealloc(ptr, layout) }
    }
}

#[global_allocator]
static GLOBAL: Counting = Counting;

fn spheres(n: usize) -> String {
    let mut t = String::from(
        "[camera]\nposition = [0.0, -30.0, 8.0]\nlook_at = [0.0, 0.0, 0.0]\nwidth = 48\nheight = 36\n\
         [[lights]]\nposition = [10.0, -20.0, 30.0]\n\
         [[objects]]\ntype = \"plane\"\npoint = [0.0, 0.0, -1.0]\nnormal = [0.0, 0.0, 1.0]\n\
         material = { colour = [0.6, 0.6, 0.6], kr = 0.3 }\n",
    );
    for k in 0..n {
        let (x, y, z) = ((k % 10) as f64 - 4.5, ((k / 10) % 10) as f64 - 4.5, (k / 100) as f64);
        t += &format!(
            "[[objects]]\ntype = \"sphere\"\ncentre = [{x}, {y}, {z}]\nradius = 0.4\nmaterial = {{ colour = [0.8, 0.3, 0.2], kr = 0.4 }}\n"
        );
    }
    t
}

#[test]
fn tracing_allocates_nothing() {
    let combined = Scene::load(std::path::Path::new(concat!(env!("CARGO_MANIFEST_DIR"), "/scenes/combined.toml")))
        .expect("the combined scene");
    let many = Scene::parse(&spheres(200), "spheres.toml").expect("a scene of spheres");
    // Spline surfaces (cubic Bézier segments, degree-32 polynomials), ruled surfaces, tori, boxes
    // and cones too; smaller, for a debug build.
    let shipped = |name: &str| {
        let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("scenes").join(name);
        let mut scene = Scene::load(&path).expect(name);
        scene.resize(Some(80), None).unwrap();
        scene
    };
    let (spline, ruled) = (shipped("fig3c.toml"), shipped("ruled.toml"));
    let (tori, boxes, cones) = (shipped("torus.toml"), shipped("box.toml"), shipped("cylinder.toml"));
    for scene in [&combined, &many, &spline, &ruled, &tori, &boxes, &cones] {
        let renderer = Renderer::new(scene);
        let camera = &scene.camera;
        let rays: Vec<_> = (0..camera.height)
            .flat_map(|j| (0..camera.width).map(move |i| (i, j)))
            .step_by(7)
            .filter_map(|(i, j)| camera.ray(f64::from(i) + 0.5, f64::from(j) + 0.5))
            .collect();
        let before = ALLOCATIONS.load(Relaxed);
        let mut sum = 0.0;
        for ray in &rays {
            sum += renderer.trace(ray, 0).iter().sum::<f64>();
        }
        let allocations = ALLOCATIONS.load(Relaxed) - before;
        assert!(sum.is_finite() && sum > 0.0);
        assert_eq!(allocations, 0, "{allocations} allocations over {} traced pixels", rays.len());
    }
}
