//! The README's gallery, drawn with `cga_trace::figure::Figure` from cga-core objects:
//! every kind of blade, the meets of two spheres and a plane, and a motor moving a circle in
//! steps. `cargo run --release -p cga-trace --example gallery -- docs/gallery` writes
//! `blades.png`, `meets.png` and `motor.png` (and each figure's scene file beside it) there.

use cga_core::euclid::E3;
use cga_core::{Bivector, Circle, FlatPoint, Line, Motor, Plane, Sandwich, Sphere, Vector, up};
use cga_trace::figure::Figure;
use std::path::PathBuf;

/// A dual sphere `c + eo + ½(c² − σ r²) ei`: real for `σ = 1`, imaginary for `σ = −1`.
fn dual_sphere(c: E3, r: f64, sigma: f64) -> Vector {
    let c2 = c[0] * c[0] + c[1] * c[1] + c[2] * c[2];
    Vector { e1: c[0], e2: c[1], e3: c[2], eo: 1.0, ei: 0.5 * (c2 - sigma * r * r) }
}

/// One object of every kind, in two rows above a line and a plane.
fn blades() -> Result<Figure, Box<dyn std::error::Error>> {
    let pair: Bivector = up([-3.3, 0.0, 1.5]) ^ up([-2.3, 0.0, 2.5]);
    let circle = Circle::from_centre_normal_radius([0.0, 0.0, 2.0], [0.2, -1.0, 0.3], 0.8)?;
    // Two spheres apart meet in an imaginary circle, drawn dashed.
    let apart = Sphere::from_centre_radius([3.3, -1.0, 2.0], 0.4)? & Sphere::from_centre_radius([3.3, 1.0, 2.0], 0.4)?;
    let sphere = Sphere::from_centre_radius([-4.2, 0.0, -0.5], 0.7)?;
    let flat = FlatPoint::from_storage(&(up([0.5, 0.0, -0.5]) ^ cga_core::ei()).to_storage());
    // A tangent vector: `eo ∧ t` (a point pair of zero radius at the origin along t) moved
    // to x.
    let at_origin = Bivector { e3o: -1.0, e1o: -0.4, ..Bivector::zero() };
    let tangent = Motor::from_translation([3.0, 0.0, -0.9]).sandwich(at_origin);
    let line = Line::new([0.0, 0.0, -2.2], [1.0, 0.1, 0.0])?;
    let plane = Plane::new([0.0, 0.0, -3.2], [0.0, 0.05, 1.0])?;
    Ok(Figure::new()
        .add(&up([-5.0, 0.0, 2.0]), "white")
        .label("point")
        .add(&pair, "red")
        .segment()
        .label("point pair")
        .add(&circle, "yellow")
        .label("circle")
        .add(&apart, "orange")
        .label("imaginary circle")
        .add(&sphere, "cyan")
        .label("sphere")
        .add(&dual_sphere([-1.6, 0.0, -0.5], 0.6, -1.0), "purple")
        .label("imaginary sphere")
        .add(&flat, "pink")
        .label("flat point")
        .add(&tangent, "magenta")
        .label("tangent")
        .add(&line, "sky")
        .label("line")
        .add(&plane, "green")
        .label("plane"))
}

/// Two spheres and a plane, and their meets: the spheres' circle, each sphere's circle in
/// the plane, and the point pair all three share; seen from above the plane.
fn meets() -> Result<Figure, Box<dyn std::error::Error>> {
    let s1 = Sphere::from_centre_radius([-0.8, 0.0, -0.3], 1.3)?;
    let s2 = Sphere::from_centre_radius([0.8, 0.4, -0.1], 1.0)?;
    let plane = Plane::new([0.0, 0.0, 0.2], [0.05, -0.1, 1.0])?;
    let c12: Circle = s1 & s2;
    let (c1, c2) = (s1 & plane, s2 & plane);
    let pair: Bivector = c12 & plane;
    Ok(Figure::new()
        .camera([1.0, -3.5, 7.5], [0.0, 0.0, 0.0])
        .add(&s1, "#4a78c8")
        .label("S1")
        .add(&s2, "#c8784a")
        .label("S2")
        .add(&plane, "grey")
        .size(2.6)
        .add(&c12, "yellow")
        .tube(0.03)
        .label("S1 v S2")
        .add(&c1, "sky")
        .tube(0.03)
        .label("S1 v P")
        .add(&c2, "orange")
        .tube(0.03)
        .label("S2 v P")
        .add(&pair, "red")
        .size(0.08)
        .label("S1 v S2 v P"))
}

/// A circle moved in steps by powers of one screw motor, and the screw's axis.
fn motor() -> Result<Figure, Box<dyn std::error::Error>> {
    let axis = Line::new([0.0, 0.0, 0.0], [0.0, 0.0, 1.0])?;
    let step = Motor::screw(&axis, 0.45, 0.5)?;
    let mut circle = Circle::from_centre_normal_radius([2.0, 0.0, -1.5], [1.0, 0.0, 0.3], 0.7)?;
    let mut figure = Figure::new().add(&axis, "white").label("axis");
    let colours = ["#3050f0", "#4070e0", "#5090d0", "#60b0c0", "#70d0a0", "#90e080", "#c0e060", "#f0d040", "#f0a030"];
    for (k, colour) in colours.iter().enumerate() {
        figure = figure.add(&circle, colour).tube(0.035);
        if k == 0 {
            figure = figure.label("C");
        } else if k + 1 == colours.len() {
            figure = figure.label("M^8 C ~M^8");
        }
        circle = step.sandwich(circle);
    }
    Ok(figure)
}

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let dir = PathBuf::from(std::env::args().nth(1).unwrap_or_else(|| "docs/gallery".into()));
    std::fs::create_dir_all(&dir)?;
    for (name, figure) in [("blades", blades()?), ("meets", meets()?), ("motor", motor()?)] {
        let figure = figure.resolution(720, 480);
        figure.write_scene(dir.join(format!("{name}.toml")))?;
        figure.render(dir.join(format!("{name}.png")))?;
        println!("{}", dir.join(format!("{name}.png")).display());
    }
    Ok(())
}
