//! G(9,1): ten basis vectors, `e1..e9` squaring to +1 and the tenth, `ea`, to −1 (the default
//! labels go on past 9 with letters). Vectors, bivectors, trivectors, rotors and the odd
//! elements of grades 1 and 3; no dense type (its tables would have 4¹⁰ entries).

cga_macros::algebra! {
    scalar = crate::Real;
    signature = (9, 1);
    lanes = cga_core::simd;
    prelude = f64;

    /// A scalar.
    type Scalar = [s];
    /// A vector.
    type Vector = [grade(1)];
    /// A bivector.
    type Bivector = [grade(2)];
    /// A trivector.
    type Trivector = [grade(3)];
    /// A rotor: a scalar and a bivector.
    versor Rotor = [s, grade(2)];
    /// Grades 1 and 3: a vector times a bivector.
    type Odd = [grade(1), grade(3)];
}
