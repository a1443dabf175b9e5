//! Multiplying a speed by a damping factor without subnormal arithmetic, bit
//! for bit.
//!
//! A creature standing on the ground keeps its vertical speed, damped by
//! 0.85 every tick (the benchmark does the same): after about 540 ticks it
//! is subnormal, and it ends at 3 · 2⁻¹⁴⁹, which 0.85 rounds back to
//! itself: a creature standing on the ground stays subnormal for good.
//! x86 processors multiply subnormals in microcode, some hundred cycles each,
//! and that one multiplication was the costliest instruction of the
//! simulator (issue 30's profile). [`damp`] gives the same bits as `v * f`
//! (IEEE 754 binary32, round to nearest, ties to even) for every `v`, and
//! computes the tiny products in integers.

/// Below this magnitude the product of a damping factor in [0.5, 1) is
/// subnormal or in the lowest normal binade: both share the spacing 2⁻¹⁴⁹.
const TINY: f32 = f32::from_bits(0x0100_0000); // 2⁻¹²⁵

/// `v * f`, bit for bit, for a damping factor `f` in [0.5, 1).
#[inline(always)]
pub fn damp(v: f32, f: f32) -> f32 {
    debug_assert!((0.5..1.0).contains(&f), "a damping factor in [0.5, 1)");
    if v.abs() < TINY { damp_tiny(v, f) } else { v * f }
}

/// `v * f` for |v| < 2⁻¹²⁵ and `f` in [0.5, 1), in integers.
///
/// With `v = m_v·2⁻¹⁴⁹` (`m_v` < 2²⁴: subnormal or lowest binade) and
/// `f = m_f·2⁻²⁴` (`f` in [0.5, 1): exponent field 126, `m_f` < 2²⁴), the
/// product is `m_v·m_f·2⁻¹⁷³`, and its binary32 value is the nearest multiple
/// of 2⁻¹⁴⁹ (ties to even), whose encoding is that multiple's count (counts up
/// to 2²⁴ encode the lowest normal binade alike).
#[inline(never)]
fn damp_tiny(v: f32, f: f32) -> f32 {
    let bits = v.to_bits();
    let (sign, exponent, fraction) = (bits & 0x8000_0000, (bits >> 23) & 0xff, bits & 0x007f_ffff);
    let m_v = u64::from(if exponent == 0 { fraction } else { fraction | 0x0080_0000 });
    let m_f = u64::from((f.to_bits() & 0x007f_ffff) | 0x0080_0000);
    let product = m_v * m_f;
    let (q, rest) = (product >> 24, product & 0x00ff_ffff);
    let half = 1 << 23;
    let q = if rest > half || (rest == half && q & 1 == 1) { q + 1 } else { q };
    // q ≤ 2²⁴ · (1 − 2⁻²⁴) rounded: at most 2²⁴, the binade's top, encoded alike.
    f32::from_bits(sign | q as u32)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The factors the simulator damps with.
    const FACTORS: [f32; 5] = [0.85, 0.95, 0.89, 0.5, 0.9];

    #[test]
    fn tiny_products_are_the_hardware_s_bit_for_bit() {
        // Magnitudes below 2⁻¹²⁵ by a stride (a prime, so every residue of
        // the low bits comes up), the first and last thousand whole; both signs.
        let top = TINY.to_bits();
        let sampled = (0..top).step_by(101).chain(0..1000).chain(top - 1000..top);
        for m in sampled {
            for &f in &FACTORS {
                for sign in [0, 0x8000_0000] {
                    let v = f32::from_bits(sign | m);
                    assert_eq!(damp(v, f).to_bits(), (v * f).to_bits(), "{v:e} × {f}");
                }
            }
        }
    }

    #[test]
    fn ordinary_products_are_the_hardware_s() {
        for &f in &FACTORS {
            for v in [TINY, -TINY, 1e-30, 2.0, -10.0, 207.0, f32::MAX, f32::INFINITY, f32::NAN, 0.0, -0.0] {
                assert_eq!(damp(v, f).to_bits(), (v * f).to_bits(), "{v:e} × {f}");
            }
        }
    }

    #[test]
    fn a_standing_speed_sinks_to_a_fixed_subnormal_as_the_hardware_s() {
        // 3 · 2⁻¹⁴⁹ · 0.85 = 2.55 · 2⁻¹⁴⁹ rounds back to 3 · 2⁻¹⁴⁹: the speed never reaches zero.
        let (mut a, mut b) = (2.0f32, 2.0f32);
        for _ in 0..800 {
            a *= 0.85;
            b = damp(b, 0.85);
            assert_eq!(a.to_bits(), b.to_bits());
        }
        assert_eq!(b.to_bits(), 3, "3 · 2⁻¹⁴⁹ for good");
    }
}
