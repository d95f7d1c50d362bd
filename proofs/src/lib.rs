//! # cycleref-proofs
//!
//! Proof harnesses of the cycle properties. Each harness body is written
//! once against [`verify`], which is the real `kani` API under `cargo kani`
//! and the [`shim`] (exhaustive small-scope enumeration and random sampling)
//! under `cargo test`.
#![forbid(unsafe_code)]
#![deny(missing_docs)]

pub mod bodies;
#[cfg(not(kani))]
pub mod catalogue;
pub mod contracts;
pub mod g75_exact;
pub mod g76_exact;
pub mod g92;
pub mod groove;
pub mod harness;
#[cfg(kani)]
mod kani_proofs;
pub mod linuxcnc;
pub mod schedule;
pub mod shim;
pub mod thread;
pub mod windows;

/// `any_in`, `any_bool`, `assume`, `declare` and `cover`: Kani's under
/// `cfg(kani)`, the shim's otherwise.
pub mod verify {
    #[cfg(not(kani))]
    pub use crate::shim::{any_bool, any_i128_in, any_in, any_u128_in, assume, declare};

    /// A value in `lo..=hi`; `lo` itself, not a symbolic value, when the
    /// range holds one value (a fixed input stays a constant for the solver).
    #[cfg(kani)]
    pub fn any_in(lo: i64, hi: i64) -> i64 {
        if lo == hi {
            return lo;
        }
        let v: i64 = kani::any();
        kani::assume(lo <= v && v <= hi);
        v
    }

    /// A `u128` in `lo..=hi` (`lo` itself when the range holds one value).
    #[cfg(kani)]
    pub fn any_u128_in(lo: u128, hi: u128) -> u128 {
        if lo == hi {
            return lo;
        }
        let v: u128 = kani::any();
        kani::assume(lo <= v && v <= hi);
        v
    }

    /// An `i128` in `lo..=hi` (`lo` itself when the range holds one value).
    #[cfg(kani)]
    pub fn any_i128_in(lo: i128, hi: i128) -> i128 {
        if lo == hi {
            return lo;
        }
        let v: i128 = kani::any();
        kani::assume(lo <= v && v <= hi);
        v
    }

    /// The covers a harness declares ([`crate::shim::declare`]): nothing to
    /// do under Kani, where every `kani::cover` is a property.
    #[cfg(kani)]
    pub fn declare(_covers: &[&'static str]) {}

    /// A `bool`.
    #[cfg(kani)]
    pub fn any_bool() -> bool {
        kani::any()
    }

    /// `kani::assume`.
    #[cfg(kani)]
    pub fn assume(cond: bool) {
        kani::assume(cond);
    }
}

/// `kani::cover(cond, "message")` under Kani (at the call site, where Kani
/// wants the literal message), [`shim::cover`] otherwise.
#[macro_export]
macro_rules! cover {
    ($cond:expr, $msg:literal) => {{
        #[cfg(kani)]
        {
            kani::cover($cond, $msg);
        }
        #[cfg(not(kani))]
        {
            $crate::shim::cover($cond, $msg);
        }
    }};
}
