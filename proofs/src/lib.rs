//! Proof harnesses for cycleref.
