//! A stand-in for the `kani` crate with the signatures the harnesses use,
//! so that `.ci/kani-typecheck` can compile `proofs/` under `cfg(kani)` on a
//! machine without Kani. It proves nothing; `cargo kani` uses the real crate.
//!
//! Like the real crate it is `no_std` and its `any` asks for `Arbitrary`
//! (not `Default`), so that a harness that would not compile under Kani
//! fails here too.
#![no_std]
pub use kani_macros::{ensures, proof, proof_for_contract, requires, solver, stub_verified, unwind};

/// `kani::Arbitrary`: the types `kani::any` can produce.
pub trait Arbitrary: Sized {
    /// A value (under Kani, symbolic).
    fn any() -> Self;
}

macro_rules! arbitrary {
    ($($t:ty),*) => {$(
        impl Arbitrary for $t {
            fn any() -> Self {
                0
            }
        }
    )*};
}
arbitrary!(u8, u16, u32, u64, u128, usize, i8, i16, i32, i64, i128, isize);

impl Arbitrary for bool {
    fn any() -> Self {
        false
    }
}

/// `kani::any`: a symbolic value under Kani.
pub fn any<T: Arbitrary>() -> T {
    T::any()
}

/// `kani::any_where`: a symbolic value satisfying `f`.
pub fn any_where<T: Arbitrary, F: FnOnce(&T) -> bool>(f: F) -> T {
    let v = T::any();
    assume(f(&v));
    v
}

/// `kani::assume`.
pub fn assume(_cond: bool) {}

/// `kani::cover`.
pub const fn cover(_cond: bool, _msg: &'static str) {}
