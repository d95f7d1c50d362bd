//! The cycleref command.
fn main() {}
