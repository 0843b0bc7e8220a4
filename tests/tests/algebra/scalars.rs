//! The generated code is generic over the scalar: dual numbers give exact derivatives, and
//! f32 tracks f64 to single precision.

use cga_core::{Circle, Dual, Line, Motor, Real, Rotor, Sandwich, Translator, Vector, product_table};

fn dual_circle(a: Circle, da: Circle) -> Circle<Dual> {
    let (x, dx) = (a.to_array(), da.to_array());
    Circle::from_array(std::array::from_fn(|i| Dual::new(x[i], dx[i])))
}

fn circle(seed: f64) -> Circle {
    Circle::from_array(std::array::from_fn(|i| (seed * (i as f64 + 1.3)).sin()))
}

/// A product is bilinear, so the ε part of `(A + εA') ∨ L` is exactly `A' ∨ L`.
#[test]
fn dual_numbers_differentiate_products_exactly() {
    let (a, da) = (circle(0.7), circle(1.9));
    let line = Line { e12i: 0.3, e13i: -1.2, e23i: 0.8, e1oi: 0.5, e2oi: -0.25, e3oi: 1.0 };
    let line_d: Line<Dual> = Line::from_array(line.to_array().map(Dual::constant));
    let meet = dual_circle(a, da) & line_d;
    let want = da & line;
    let du: Vec<f64> = meet.to_array().iter().map(|d| d.du).collect();
    assert_eq!(du, want.to_array().to_vec());
    let re: Vec<f64> = meet.to_array().iter().map(|d| d.re).collect();
    assert_eq!(re, (a & line).to_array().to_vec());
}

/// Through a nonlinear map (normalisation: a square root and a division) the dual part
/// matches a central finite difference to its truncation error.
#[test]
fn dual_numbers_differentiate_normalisation() {
    let (a, da) = (circle(0.4), circle(2.3));
    let exact = dual_circle(a, da).normalise().unwrap();
    let h = 1e-6;
    let plus = (a + da.scale(h)).normalise().unwrap();
    let minus = (a - da.scale(h)).normalise().unwrap();
    for ((d, p), m) in exact.to_array().iter().zip(plus.to_array()).zip(minus.to_array()) {
        let fd = (p - m) / (2.0 * h);
        approx::assert_relative_eq!(d.du, fd, epsilon = 1e-7, max_relative = 1e-7);
    }
}

/// Every generated product in f32 agrees with f64 to single precision.
#[test]
fn f32_products_track_f64() {
    let a64: [f64; 32] = std::array::from_fn(|i| ((i * 7 % 13) as f64 - 6.0) / 4.0);
    let b64: [f64; 32] = std::array::from_fn(|i| ((i * 5 % 11) as f64 - 5.0) / 3.0);
    let (a32, b32) = (a64.map(|x| x as f32), b64.map(|x| x as f32));
    let (t64, t32) = (product_table::<f64>(), product_table::<f32>());
    let mut worst = 0.0f64;
    for (e64, e32) in t64.iter().zip(&t32) {
        let (r64, r32) = ((e64.eval)(&a64, &b64), (e32.eval)(&a32, &b32));
        let scale = r64.iter().fold(1.0f64, |m, x| m.max(x.abs()));
        for (x, y) in r64.iter().zip(r32) {
            worst = worst.max((x - y as f64).abs() / scale);
        }
    }
    assert!(worst < 1e-5, "f32 drifts from f64 by {worst:e}");
}

/// A motor in f32 moves a point to where f64 puts it.
#[test]
fn f32_motor_on_point() {
    let motor: Motor =
        Rotor { s: 0.8, e12: 0.36, e13: 0.0, e23: -0.48 } * Translator { s: 1.0, e1i: 1.5, e2i: -0.5, e3i: 2.0 };
    let x = Vector { e1: 1.0, e2: -2.0, e3: 0.5, eo: 1.0, ei: 0.5 * (1.0 + 4.0 + 0.25) };
    let m32 = Motor::from_array(motor.to_array().map(|c| c as f32));
    let x32 = Vector::from_array(x.to_array().map(|c| c as f32));
    let (p64, p32) = (motor.sandwich(x), m32.sandwich(x32));
    for (a, b) in p64.to_array().iter().zip(p32.to_array()) {
        approx::assert_relative_eq!(*a, b.to_f64(), epsilon = 1e-5, max_relative = 1e-5);
    }
}
