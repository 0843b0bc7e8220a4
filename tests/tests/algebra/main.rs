//! The algebra and the generator: products, sandwiches and unary maps of the generated types
//! against the dense multivector and clifford's golden vectors, the other algebras (PGA,
//! G(3,1), G(1,3), G(9,1)), scalars, exp and log, and the counts the READMEs state. One
//! module a subject; `cargo test -p cga-tests --test algebra -- MODULE::` runs one.

mod algebras;
mod arithmetic;
mod as_algebra_author;
mod as_cga2_user;
mod as_klein_user;
mod cga2_toolkit;
mod dimension;
mod exp_log;
mod facts;
mod fresh;
mod generated_vs_dense;
mod golden_products;
mod lanes;
mod multiplication_counts;
mod orthonormal_basis;
mod pga;
mod pga_toolkit;
mod prepared;
mod scalars;
mod sta_toolkit;
