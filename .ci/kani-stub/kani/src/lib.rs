//! A stand-in for the `kani` crate with the signatures the harnesses use,
//! so that `.ci/kani-typecheck` can compile `proofs/` under `cfg(kani)` on a
//! machine without Kani. It proves nothing; `cargo kani` uses the real crate.
pub use kani_macros::{ensures, proof, proof_for_contract, requires, solver, stub_verified, unwind};

/// `kani::any`: a symbolic value under Kani; here any value of the type.
pub fn any<T: Default>() -> T {
    T::default()
}

/// `kani::assume`.
pub fn assume(_cond: bool) {}

/// `kani::cover`.
pub const fn cover(_cond: bool, _msg: &'static str) {}
