//! Limb arithmetic on little-endian slices of `u64`: the kernels of
//! [`super::Fixed`] (addition, comparison, products, Knuth's long division).

use core::cmp::Ordering;

use super::SCRATCH;

/// True when every limb is 0.
pub(super) fn limbs_zero(a: &[u64]) -> bool {
    a.iter().all(|&x| x == 0)
}

/// `a += b` over `a.len()` limbs (`b` shorter or equal, read as zero
/// beyond its end); returns the carry out of the top limb.
pub(super) fn limbs_add(a: &mut [u64], b: &[u64]) -> bool {
    let mut carry = false;
    let mut loops = crate::loop_counters::count!(REAL_LIMBS);
    for (i, x) in a.iter_mut().enumerate() {
        loops.tick();
        let y = b.get(i).copied().unwrap_or(0);
        let (s1, c1) = x.overflowing_add(y);
        let (s2, c2) = s1.overflowing_add(u64::from(carry));
        *x = s2;
        carry = c1 || c2;
    }
    carry
}

/// `a -= b` over `a.len()` limbs; returns the borrow out of the top limb.
pub(super) fn limbs_sub(a: &mut [u64], b: &[u64]) -> bool {
    let mut borrow = false;
    let mut loops = crate::loop_counters::count!(REAL_LIMBS);
    for (i, x) in a.iter_mut().enumerate() {
        loops.tick();
        let y = b.get(i).copied().unwrap_or(0);
        let (s1, b1) = x.overflowing_sub(y);
        let (s2, b2) = s1.overflowing_sub(u64::from(borrow));
        *x = s2;
        borrow = b1 || b2;
    }
    borrow
}

/// `a += 1`; returns the carry out.
pub(super) fn limbs_inc(a: &mut [u64]) -> bool {
    let mut loops = crate::loop_counters::count!(REAL_LIMBS);
    for x in a.iter_mut() {
        loops.tick();
        let (s, c) = x.overflowing_add(1);
        *x = s;
        if !c {
            return false;
        }
    }
    true
}

/// Two's complement negation in place.
pub(super) fn limbs_neg(a: &mut [u64]) {
    let mut loops = crate::loop_counters::count!(REAL_LIMBS);
    for x in a.iter_mut() {
        loops.tick();
        *x = !*x;
    }
    limbs_inc(a);
}

/// Unsigned comparison of `a` and `b` (the shorter read as zero-extended).
pub(super) fn limbs_cmp(a: &[u64], b: &[u64]) -> Ordering {
    let n = a.len().max(b.len());
    let mut loops = crate::loop_counters::count!(REAL_LIMBS);
    for i in (0..n).rev() {
        loops.tick();
        let x = a.get(i).copied().unwrap_or(0);
        let y = b.get(i).copied().unwrap_or(0);
        match x.cmp(&y) {
            Ordering::Equal => {}
            o => return o,
        }
    }
    Ordering::Equal
}

/// `out = a · b`; `out` must be zero on entry and hold `a.len() + b.len()`
/// limbs (the product of an `m`- and an `n`-limb number fits `m + n` limbs).
pub(super) fn limbs_mul(a: &[u64], b: &[u64], out: &mut [u64]) {
    let mut loops = crate::loop_counters::count!(REAL_LIMBS);
    for (i, &x) in a.iter().enumerate() {
        loops.tick();
        if x == 0 {
            continue;
        }
        let mut carry: u64 = 0;
        let mut loops = crate::loop_counters::count!(REAL_LIMBS);
        for (j, &y) in b.iter().enumerate() {
            loops.tick();
            if let Some(slot) = out.get_mut(i + j) {
                // x·y + slot + carry ≤ (2^64 − 1)^2 + 2(2^64 − 1) = 2^128 − 1.
                let t = u128::from(x) * u128::from(y) + u128::from(*slot) + u128::from(carry);
                *slot = low64(t);
                carry = high64(t);
            }
        }
        let mut k = i + b.len();
        let mut loops = crate::loop_counters::count!(REAL_LIMBS);
        while carry != 0 {
            loops.tick();
            if let Some(slot) = out.get_mut(k) {
                let (s, c) = slot.overflowing_add(carry);
                *slot = s;
                carry = u64::from(c);
                k += 1;
            } else {
                break;
            }
        }
    }
}

/// `a / d` in place for a one-limb divisor `d > 0`; returns the remainder.
pub(super) fn limbs_div_small(a: &mut [u64], d: u64) -> u64 {
    let mut rem: u64 = 0;
    let mut loops = crate::loop_counters::count!(REAL_LIMBS);
    for x in a.iter_mut().rev() {
        loops.tick();
        // rem < d, so the partial dividend is below d·2^64 and the quotient
        // digit fits a limb.
        let cur = (u128::from(rem) << 64) | u128::from(*x);
        let d128 = u128::from(d);
        *x = low64(cur / d128);
        rem = low64(cur % d128);
    }
    rem
}

/// `a · k` in place for a one-limb factor; returns the limb carried out.
pub(super) fn limbs_mul_small(a: &mut [u64], k: u64) -> u64 {
    let mut carry: u64 = 0;
    let mut loops = crate::loop_counters::count!(REAL_LIMBS);
    for x in a.iter_mut() {
        loops.tick();
        let t = u128::from(*x) * u128::from(k) + u128::from(carry);
        *x = low64(t);
        carry = high64(t);
    }
    carry
}

/// The number of significant bits of `a` (0 for zero).
pub(super) fn limbs_bits(a: &[u64]) -> usize {
    let mut loops = crate::loop_counters::count!(REAL_LIMBS);
    for i in (0..a.len()).rev() {
        loops.tick();
        if let Some(&x) = a.get(i) {
            if x != 0 {
                return 64 * i + (64 - x.leading_zeros() as usize);
            }
        }
    }
    0
}

/// Long division `num / den` (Knuth's algorithm D, TAOCP vol. 2 §4.3.1,
/// with 64-bit digits): the quotient goes to `q` (as long as `num`, zero on
/// entry), the remainder is left in `rem` (zero on entry, one limb longer
/// than `den`). `den` must not be zero (a zero `den` leaves both zero).
///
/// One quotient limb per step, each estimated from the top two limbs of the
/// partial remainder and the top limb of the normalised divisor (at most two
/// too large after the test on the second limb, and then at most one: the
/// add-back). It replaced a bit-by-bit restoring division (kept as the
/// tests' oracle, `limbs_divmod_bits`), which took 128 + 64·k steps for a
/// quotient of a `k`-limb number and was 15 % of `expand` (benches/README).
pub(super) fn limbs_divmod(num: &[u64], den: &[u64], q: &mut [u64], rem: &mut [u64]) {
    let n = limbs_bits(den).div_ceil(64);
    let m = limbs_bits(num).div_ceil(64);
    if n == 0 {
        return;
    }
    let (Some(num), Some(den)) = (num.get(..m), den.get(..n)) else { return };
    if m < n {
        limbs_copy(rem, num);
        return;
    }
    if n == 1 {
        let d = den.first().copied().unwrap_or(1);
        let mut r: u64 = 0;
        let mut loops = crate::loop_counters::count!(REAL_DIVMOD);
        for (qi, &x) in q.iter_mut().zip(num).rev() {
            loops.tick();
            // r < d, so the partial dividend is below d·2^64: the digit fits.
            let cur = (u128::from(r) << 64) | u128::from(x);
            *qi = low64(cur / u128::from(d));
            r = low64(cur % u128::from(d));
        }
        if let Some(r0) = rem.first_mut() {
            *r0 = r;
        }
        return;
    }
    // D1: normalise, so that the divisor's top limb has its top bit set.
    let shift = den.get(n - 1).map_or(0, |x| x.leading_zeros());
    let mut v = [0_u64; SCRATCH];
    let mut u = [0_u64; SCRATCH + 1];
    let (Some(v), Some(u)) = (v.get_mut(..n), u.get_mut(..=m)) else { return };
    limbs_shl_into(den, shift, v);
    limbs_shl_into(num, shift, u);
    let v_top = u128::from(v.get(n - 1).copied().unwrap_or(1));
    let v_next = u128::from(v.get(n - 2).copied().unwrap_or(0));
    let mut loops = crate::loop_counters::count!(REAL_DIVMOD);
    for j in (0..=m - n).rev() {
        loops.tick();
        let limb = |u: &[u64], i: usize| u128::from(u.get(i).copied().unwrap_or(0));
        // D3: the estimate q̂ from the top two limbs, corrected by the next.
        let top = (limb(u, j + n) << 64) | limb(u, j + n - 1);
        let mut q_hat = top / v_top;
        let mut r_hat = top % v_top;
        let mut fixes = crate::loop_counters::count!(REAL_DIVMOD);
        while q_hat > u128::from(u64::MAX) || q_hat * v_next > ((r_hat << 64) | limb(u, j + n - 2)) {
            fixes.tick();
            q_hat -= 1;
            r_hat += v_top;
            if r_hat > u128::from(u64::MAX) {
                break;
            }
        }
        // D4: u[j..=j+n] −= q̂ · v.
        let q_digit = low64(q_hat);
        let mut borrow: u64 = 0;
        let mut carry: u64 = 0;
        let mut limbs = crate::loop_counters::count!(REAL_LIMBS);
        for (i, &vi) in v.iter().enumerate() {
            limbs.tick();
            let p = u128::from(q_digit) * u128::from(vi) + u128::from(carry);
            carry = high64(p);
            if let Some(x) = u.get_mut(i + j) {
                let (d1, b1) = x.overflowing_sub(low64(p));
                let (d2, b2) = d1.overflowing_sub(borrow);
                *x = d2;
                borrow = u64::from(b1 || b2);
            }
        }
        let mut negative = false;
        if let Some(x) = u.get_mut(j + n) {
            let (d1, b1) = x.overflowing_sub(carry);
            let (d2, b2) = d1.overflowing_sub(borrow);
            *x = d2;
            negative = b1 || b2;
        }
        // D5, D6: q̂ was one too large (rare): add v back.
        let q_digit = if negative {
            let mut c = false;
            let mut limbs = crate::loop_counters::count!(REAL_LIMBS);
            for (i, &vi) in v.iter().enumerate() {
                limbs.tick();
                if let Some(x) = u.get_mut(i + j) {
                    let (s1, c1) = x.overflowing_add(vi);
                    let (s2, c2) = s1.overflowing_add(u64::from(c));
                    *x = s2;
                    c = c1 || c2;
                }
            }
            if let Some(x) = u.get_mut(j + n) {
                *x = x.wrapping_add(u64::from(c));
            }
            #[cfg(test)]
            ADD_BACKS.fetch_add(1, core::sync::atomic::Ordering::Relaxed);
            q_digit.wrapping_sub(1)
        } else {
            q_digit
        };
        if let Some(x) = q.get_mut(j) {
            *x = q_digit;
        }
    }
    // D8: the remainder is u[..n], shifted back.
    limbs_shr_into(u.get(..n).unwrap_or(&[]), shift, rem);
}

/// How many times step D6 (add back) ran: the tests check that they reach it.
#[cfg(test)]
pub(super) static ADD_BACKS: core::sync::atomic::AtomicUsize = core::sync::atomic::AtomicUsize::new(0);

/// Copies `src` into the start of `dst` (as far as `dst` goes).
pub(super) fn limbs_copy(dst: &mut [u64], src: &[u64]) {
    let mut loops = crate::loop_counters::count!(REAL_LIMBS);
    for (d, &s) in dst.iter_mut().zip(src) {
        loops.tick();
        *d = s;
    }
}

/// `out = a << shift` for `shift < 64`; `out` has at least `a.len()` limbs
/// (one more receives the bits shifted out of the top, when it is there).
pub(super) fn limbs_shl_into(a: &[u64], shift: u32, out: &mut [u64]) {
    let mut carry: u64 = 0;
    let mut loops = crate::loop_counters::count!(REAL_LIMBS);
    for (o, &x) in out.iter_mut().zip(a) {
        loops.tick();
        *o = (x << shift) | carry;
        carry = if shift == 0 { 0 } else { x >> (64 - shift) };
    }
    if let Some(o) = out.get_mut(a.len()) {
        *o = carry;
    }
}

/// `out = a >> shift` for `shift < 64`, `a.len()` limbs into the start of
/// `out`.
pub(super) fn limbs_shr_into(a: &[u64], shift: u32, out: &mut [u64]) {
    let mut loops = crate::loop_counters::count!(REAL_LIMBS);
    for (i, o) in out.iter_mut().enumerate().take(a.len()) {
        loops.tick();
        let x = a.get(i).copied().unwrap_or(0);
        let above = a.get(i + 1).copied().unwrap_or(0);
        *o = if shift == 0 { x } else { (x >> shift) | (above << (64 - shift)) };
    }
}

/// The low 64 bits of `v`.
pub(super) const fn low64(v: u128) -> u64 {
    // Truncation on purpose: the low limb.
    #[allow(clippy::cast_possible_truncation)]
    let r = v as u64;
    r
}

/// The high 64 bits of `v`.
pub(super) const fn high64(v: u128) -> u64 {
    low64(v >> 64)
}
