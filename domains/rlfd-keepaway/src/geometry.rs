//! Plane vectors for the Keepaway simulator: positions, velocities and
//! directions in metres (and metres per cycle), with the few operations the
//! soccer-server physics and the players' skills need.
//!
//! What it is not: no angles in degrees and no platform trigonometry. The
//! few transcendental functions (`atan2`, `sin`, `cos`) go through `libm`, so
//! a simulation gives the same bits on every platform; everything else is
//! arithmetic and `sqrt`, exact in IEEE 754.

use std::ops::{Add, AddAssign, Mul, Neg, Sub, SubAssign};

use serde::{Deserialize, Serialize};

/// A point or a vector in the plane.
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct Vec2 {
    /// Metres along the field's length.
    pub x: f64,
    /// Metres along the field's width.
    pub y: f64,
}

impl Vec2 {
    /// The origin (the keepaway region's centre).
    pub const ZERO: Vec2 = Vec2 { x: 0.0, y: 0.0 };

    /// `(x, y)`.
    #[inline]
    pub const fn new(x: f64, y: f64) -> Vec2 {
        Vec2 { x, y }
    }

    /// The unit vector at `angle` radians from the x axis.
    #[inline]
    pub fn from_angle(angle: f64) -> Vec2 {
        Vec2 { x: libm::cos(angle), y: libm::sin(angle) }
    }

    /// Dot product.
    #[inline]
    pub fn dot(self, o: Vec2) -> f64 {
        self.x * o.x + self.y * o.y
    }

    /// The z component of the cross product (positive when `o` lies counter-clockwise of `self`).
    #[inline]
    pub fn cross(self, o: Vec2) -> f64 {
        self.x * o.y - self.y * o.x
    }

    /// Squared length.
    #[inline]
    pub fn norm2(self) -> f64 {
        self.x * self.x + self.y * self.y
    }

    /// Length.
    #[inline]
    pub fn norm(self) -> f64 {
        self.norm2().sqrt()
    }

    /// Distance to `o`.
    #[inline]
    pub fn dist(self, o: Vec2) -> f64 {
        (self - o).norm()
    }

    /// Squared distance to `o`.
    #[inline]
    pub fn dist2(self, o: Vec2) -> f64 {
        (self - o).norm2()
    }

    /// The direction of this vector, radians in `(-π, π]` (0 for the zero vector).
    #[inline]
    pub fn angle(self) -> f64 {
        libm::atan2(self.y, self.x)
    }

    /// The unit vector along `self`, or `fallback` for a (near) zero vector.
    #[inline]
    pub fn normalized_or(self, fallback: Vec2) -> Vec2 {
        let n = self.norm();
        if n > 1e-12 { self * (1.0 / n) } else { fallback }
    }

    /// `self` rotated by +90°.
    #[inline]
    pub fn perp(self) -> Vec2 {
        Vec2 { x: -self.y, y: self.x }
    }

    /// `self` rotated by the direction of the unit vector `u` (complex product).
    #[inline]
    pub fn rotate(self, u: Vec2) -> Vec2 {
        Vec2 { x: self.x * u.x - self.y * u.y, y: self.x * u.y + self.y * u.x }
    }

    /// `self` rotated back by the direction of the unit vector `u`: its
    /// coordinates in a frame whose x axis is `u`.
    #[inline]
    pub fn unrotate(self, u: Vec2) -> Vec2 {
        Vec2 { x: self.x * u.x + self.y * u.y, y: self.y * u.x - self.x * u.y }
    }

    /// `self` scaled to length `len` (the zero vector stays zero).
    #[inline]
    pub fn with_norm(self, len: f64) -> Vec2 {
        let n = self.norm();
        if n > 0.0 { self * (len / n) } else { self }
    }
}

/// The unsigned angle between two directions, radians in `[0, π]`
/// (0 when either is the zero vector).
#[inline]
pub fn angle_between(a: Vec2, b: Vec2) -> f64 {
    libm::atan2(a.cross(b).abs(), a.dot(b))
}

/// The signed angle from direction `a` to direction `b`, radians in `(-π, π]`.
#[inline]
pub fn signed_angle(a: Vec2, b: Vec2) -> f64 {
    libm::atan2(a.cross(b), a.dot(b))
}

/// Radians per degree.
pub const RAD_PER_DEG: f64 = std::f64::consts::PI / 180.0;

/// The unit vector of `deg` whole degrees (`deg` in `[-360, 360]`), from a
/// table filled once with `libm`, so integer-degree directions (the players'
/// kick commands) cost no trigonometry.
#[inline]
pub fn unit_deg(deg: i32) -> Vec2 {
    static TABLE: std::sync::OnceLock<Vec<Vec2>> = std::sync::OnceLock::new();
    let t = TABLE.get_or_init(|| (-360..=360).map(|d| Vec2::from_angle(f64::from(d) * RAD_PER_DEG)).collect());
    t[(deg.clamp(-360, 360) + 360) as usize]
}

/// 2⁵²: from this magnitude on every `f64` is a whole number.
const TWO_POW_52: f64 = 4_503_599_627_370_496.0;

/// `x` rounded to the nearest whole number, ties to even (C's `rint` in the
/// default rounding mode), bit for bit what `libm::rint` returns, signed
/// zeros and NaN included, but inline: adding and subtracting 2⁵² leaves
/// exactly the rounded magnitude, because the sum has no bits below the
/// units and IEEE addition rounds to nearest even.
#[inline]
pub fn rint(x: f64) -> f64 {
    let a = x.abs();
    if a < TWO_POW_52 { ((a + TWO_POW_52) - TWO_POW_52).copysign(x) } else { x }
}

/// `angle` wrapped into `(-π, π]`.
#[inline]
pub fn normalize_angle(angle: f64) -> f64 {
    let two_pi = 2.0 * std::f64::consts::PI;
    let mut a = angle % two_pi;
    if a > std::f64::consts::PI {
        a -= two_pi;
    } else if a <= -std::f64::consts::PI {
        a += two_pi;
    }
    a
}

impl Add for Vec2 {
    type Output = Vec2;
    #[inline]
    fn add(self, o: Vec2) -> Vec2 {
        Vec2 { x: self.x + o.x, y: self.y + o.y }
    }
}

impl Sub for Vec2 {
    type Output = Vec2;
    #[inline]
    fn sub(self, o: Vec2) -> Vec2 {
        Vec2 { x: self.x - o.x, y: self.y - o.y }
    }
}

impl Mul<f64> for Vec2 {
    type Output = Vec2;
    #[inline]
    fn mul(self, k: f64) -> Vec2 {
        Vec2 { x: self.x * k, y: self.y * k }
    }
}

impl Neg for Vec2 {
    type Output = Vec2;
    #[inline]
    fn neg(self) -> Vec2 {
        Vec2 { x: -self.x, y: -self.y }
    }
}

impl AddAssign for Vec2 {
    #[inline]
    fn add_assign(&mut self, o: Vec2) {
        self.x += o.x;
        self.y += o.y;
    }
}

impl SubAssign for Vec2 {
    #[inline]
    fn sub_assign(&mut self, o: Vec2) {
        self.x -= o.x;
        self.y -= o.y;
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::f64::consts::PI;

    #[test]
    fn angles_and_rotations() {
        let a = Vec2::new(1.0, 0.0);
        let b = Vec2::new(0.0, 2.0);
        assert!((angle_between(a, b) - PI / 2.0).abs() < 1e-15);
        assert!((signed_angle(b, a) + PI / 2.0).abs() < 1e-15);
        assert_eq!(a.perp(), Vec2::new(0.0, 1.0));
        assert!((Vec2::from_angle(PI / 3.0).angle() - PI / 3.0).abs() < 1e-15);
        assert!((normalize_angle(3.0 * PI) - PI).abs() < 1e-12);
        assert!((normalize_angle(-3.5 * PI) - 0.5 * PI).abs() < 1e-12);
        assert_eq!(Vec2::ZERO.normalized_or(a), a);
        assert!((Vec2::new(3.0, 4.0).with_norm(10.0).norm() - 10.0).abs() < 1e-12);
    }

    #[test]
    fn rint_is_libms_bit_for_bit() {
        let same = |x: f64| rint(x).to_bits() == libm::rint(x).to_bits();
        let edges = [
            0.0,
            -0.0,
            0.5,
            -0.5,
            1.5,
            2.5,
            -2.5,
            0.49999999999999994,
            -0.49999999999999994,
            4503599627370495.5,
            -4503599627370495.5,
            4503599627370496.0,
            9007199254740993.0,
            1e300,
            -1e-300,
            f64::MIN_POSITIVE,
            f64::INFINITY,
            f64::NEG_INFINITY,
            f64::MAX,
            2.0f64.powi(52) - 0.5,
            2.0f64.powi(51) + 0.5,
        ];
        for x in edges {
            assert!(same(x), "{x:e}: {} vs {}", rint(x), libm::rint(x));
        }
        assert!(rint(f64::NAN).is_nan());
        let mut rng = rlfd_env::random::seeded(2);
        for _ in 0..200_000 {
            let u = rlfd_env::random::uniform01(&mut rng);
            let scale = 2.0f64.powi((60.0 * rlfd_env::random::uniform01(&mut rng)) as i32 - 8);
            let x = (2.0 * u - 1.0) * scale;
            // Around the ties, too.
            let tie = (x * 2.0).trunc() * 0.5;
            for y in [x, tie, f64::from_bits(tie.to_bits() + 1), f64::from_bits(tie.to_bits().saturating_sub(1))] {
                assert!(same(y), "{y:e}");
            }
        }
    }
}
