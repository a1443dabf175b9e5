//! Tile coding (CMAC): several offset grids over the state space, one active
//! tile per grid.
//!
//! The quantisation follows Sutton's `tiles3`: with `n` tilings, each input is
//! scaled so that 1.0 is one tile width, quantised to `q_i = floor(f_i * n)`,
//! and tiling `t` puts dimension `i` in tile `floor((q_i + b_i) / n)` with the
//! asymmetric displacement `b_i = t * (2i + 1)` (offsets 1, 3, 5, … tile
//! widths / n per dimension; uniform offsets would line the tilings up along
//! the diagonal). Because the tile depends only on the integer `q_i`, two
//! states in the same `1/n`-tile-width cell share every tile: the coder is
//! exact arithmetic after one multiplication and one floor per dimension.
//!
//! Two ways to number the tiles:
//! - [`TileIndexing::Dense`]: for bounded, low-dimensional inputs. Inputs are
//!   clamped to their declared range; every tile of every tiling has its own
//!   index, so there are no collisions. The displacement is taken modulo `n`
//!   (a relabelling of whole tiles), which keeps the grid compact.
//! - [`TileIndexing::Hashed`]: for many dimensions, where a dense grid would be
//!   astronomically large. The tiling number and the tile coordinates are
//!   hashed into `size` buckets with the fixed hash described in
//!   [`TILE_HASH_DESCRIPTION`] (not `std`'s `DefaultHasher`, whose output may
//!   change between Rust releases). Collisions are accepted, as in `tiles3`
//!   with an integer size.

use super::{ActiveFeatures, FeatureMap};
use crate::params::{ParamError, check_positive};

/// The hash behind [`TileIndexing::Hashed`], in words, for the reports.
pub const TILE_HASH_DESCRIPTION: &str = "FNV-1a over 64-bit words (offset basis 0xcbf29ce484222325, \
prime 0x100000001b3) of the tiling number and each tile coordinate, finished with the SplitMix64 \
mixer, reduced modulo the table size";

/// Dense indexing is for low-dimensional inputs; more dimensions go hashed.
const MAX_DENSE_DIMS: usize = 8;

/// The fast hashed path's limits (stack buffers); beyond them the general loop runs.
const MAX_FAST_TILINGS: usize = 64;
const MAX_FAST_DIMS: usize = 32;

/// Tilings hashed side by side on the fast path (a power of two, so it divides the tiling count).
const LANES: usize = 4;

/// How tiles are numbered.
#[derive(Clone, Debug, PartialEq)]
pub enum TileIndexing {
    /// Every tile its own index; inputs clamped to `[lower, upper]` per dimension.
    Dense {
        /// Lower bound of each input.
        lower: Vec<f64>,
        /// Upper bound of each input.
        upper: Vec<f64>,
    },
    /// Tiles hashed into a table of `size` entries.
    Hashed {
        /// Number of buckets (features).
        size: usize,
    },
}

/// A tile coder over `widths.len()` dimensions with `tilings` offset grids.
#[derive(Clone, Debug)]
pub struct TileCoder {
    tilings: usize,
    inv_width: Vec<f64>,
    lower: Vec<f64>,
    indexing: Indexing,
}

#[derive(Clone, Debug)]
enum Indexing {
    Dense {
        /// Largest quantised value `q_i` per dimension (inputs are clamped to it).
        q_max: Vec<i64>,
        /// `carry[(i * n + r) * n + t]`: what dimension `i` adds to tiling
        /// `t`'s index beyond `(q_i / n) · stride_i` when `q_i mod n = r`,
        /// i.e. `stride_i` if `r + t(2i + 1) mod n ≥ n`, else 0.
        carry: Vec<u32>,
        /// `t · per_tiling` for every tiling.
        tiling_base: Vec<u32>,
        /// Index stride per dimension within one tiling.
        strides: Vec<usize>,
        per_tiling: usize,
    },
    Hashed {
        size: u64,
    },
}

impl TileCoder {
    /// A coder with `tilings` tilings and tile width `widths[i]` in dimension `i`.
    ///
    /// For [`TileIndexing::Dense`] the bounds must have one entry per dimension
    /// with `lower < upper`; for [`TileIndexing::Hashed`] the size must be positive.
    pub fn new(tilings: usize, widths: &[f64], indexing: TileIndexing) -> Result<Self, ParamError> {
        if tilings == 0 {
            return Err(ParamError::new("tilings", 0, "at least 1"));
        }
        if widths.is_empty() {
            return Err(ParamError::new("widths", "[]", "one tile width per input dimension"));
        }
        for &w in widths {
            check_positive("widths", w)?;
        }
        let dims = widths.len();
        let inv_width: Vec<f64> = widths.iter().map(|w| 1.0 / w).collect();
        let n = tilings as i64;
        let (lower, indexing) = match indexing {
            TileIndexing::Dense { lower, upper } => {
                if lower.len() != dims || upper.len() != dims {
                    return Err(ParamError::new(
                        "lower/upper",
                        format!("{}/{}", lower.len(), upper.len()),
                        "one bound per input dimension",
                    ));
                }
                if dims > MAX_DENSE_DIMS {
                    return Err(ParamError::new(
                        "widths",
                        dims,
                        "at most 8 dimensions for dense indexing (use hashed indexing)",
                    ));
                }
                let mut q_max = Vec::with_capacity(dims);
                let mut tiles_per_dim = Vec::with_capacity(dims);
                for i in 0..dims {
                    if !(lower[i].is_finite() && upper[i].is_finite() && lower[i] < upper[i]) {
                        return Err(ParamError::new(
                            "lower/upper",
                            format!("{}..{}", lower[i], upper[i]),
                            "finite bounds with lower < upper",
                        ));
                    }
                    let q = ((upper[i] - lower[i]) * inv_width[i] * n as f64).floor() as i64;
                    q_max.push(q);
                    // The largest coordinate is floor((q_max + n - 1) / n).
                    tiles_per_dim.push(((q + n - 1) / n + 1) as usize);
                }
                let mut strides = vec![0usize; dims];
                let mut per_tiling = 1usize;
                for i in 0..dims {
                    strides[i] = per_tiling;
                    per_tiling = per_tiling
                        .checked_mul(tiles_per_dim[i])
                        .filter(|&p| p.checked_mul(tilings).is_some_and(|t| t <= u32::MAX as usize))
                        .ok_or_else(|| {
                            ParamError::new(
                                "widths",
                                format!("{widths:?}"),
                                "a dense grid small enough to index with u32 (use hashed indexing)",
                            )
                        })?;
                }
                let mut carry = Vec::with_capacity(dims * (n * n) as usize);
                for (i, &stride) in strides.iter().enumerate() {
                    for r in 0..n {
                        for t in 0..n {
                            let b = (t * (2 * i as i64 + 1)) % n;
                            carry.push(if r + b >= n { stride as u32 } else { 0 });
                        }
                    }
                }
                let tiling_base = (0..tilings).map(|t| (t * per_tiling) as u32).collect();
                (lower, Indexing::Dense { q_max, carry, tiling_base, strides, per_tiling })
            }
            TileIndexing::Hashed { size } => {
                if size == 0 || size > u32::MAX as usize {
                    return Err(ParamError::new("size", size, "between 1 and 2^32 - 1"));
                }
                (vec![0.0; dims], Indexing::Hashed { size: size as u64 })
            }
        };
        Ok(TileCoder { tilings, inv_width, lower, indexing })
    }

    /// Number of tilings (active features per state).
    pub fn tilings(&self) -> usize {
        self.tilings
    }

    /// Number of input dimensions.
    pub fn dims(&self) -> usize {
        self.inv_width.len()
    }

    /// Dense indices for `D` dimensions (a compile-time count, so the inner
    /// loops unroll).
    ///
    /// Tilings differ only by the displacement `b < n`, so the coordinate
    /// `(q + b) / n` is `q / n` plus a carry of 0 or 1 that depends on
    /// `q mod n` and the tiling alone. The carries (times the stride) are
    /// tabulated at construction, which turns the per-tiling work into adding
    /// `D` table rows: a loop the compiler vectorises.
    #[inline]
    fn dense<const D: usize>(&self, state: &[f64], out: &mut ActiveFeatures) {
        let Indexing::Dense { q_max, carry, tiling_base, strides, .. } = &self.indexing else {
            unreachable!("dense indexing checked by the caller")
        };
        let n = self.tilings;
        let mut whole = 0u32;
        let mut rows: [&[u32]; D] = [&[]; D];
        for i in 0..D {
            let q = self.quantise(i, state[i]).clamp(0, q_max[i]) as usize;
            // A power-of-two tiling count (32 in every experiment of the
            // thesis) divides by shifting: a hardware division costs tens of
            // cycles, twice per dimension per lookup.
            let (w, r) = if n.is_power_of_two() { (q >> n.trailing_zeros(), q & (n - 1)) } else { (q / n, q % n) };
            whole += (w * strides[i]) as u32;
            rows[i] = &carry[(i * n + r) * n..(i * n + r + 1) * n];
        }
        // The buffer is reused every step with the same length, so this
        // resize is free after the first call; one pass then adds the rows
        // lane by lane (the compiler vectorises it).
        out.indices.resize(n, 0);
        let indices = &mut out.indices[..n];
        let base = &tiling_base[..n];
        for t in 0..n {
            let mut index = base[t] + whole;
            for row in &rows {
                index += row[t];
            }
            indices[t] = index;
        }
    }

    /// The hashed indices, any tiling count and table size (the definition
    /// [`TileCoder::hashed_pow2`] computes faster).
    fn hashed_any(&self, state: &[f64], size: u64, out: &mut ActiveFeatures) {
        let n = self.tilings as i64;
        out.indices.clear();
        for t in 0..n {
            let mut h = hash_words(0xcbf2_9ce4_8422_2325, t as u64);
            for (i, &x) in state.iter().enumerate() {
                let b = t * (2 * i as i64 + 1);
                let coord = (self.quantise(i, x) + b).div_euclid(n);
                h = hash_words(h, coord as u64);
            }
            out.indices.push((splitmix_finish(h) % size) as u32);
        }
    }

    /// The hashed indices when the tiling count and the table size are
    /// powers of two (32 tilings and 2^18 weights in Mario): the same hash
    /// inputs in the same order as the general loop below, computed faster.
    ///
    /// - Each input is quantised once, not once per tiling.
    /// - `(q + b).div_euclid(n)` is an arithmetic shift by `log2 n` (floor
    ///   division by a power of two), and `h % size` is `h & (size − 1)`:
    ///   no hardware division.
    /// - The tilings' hash chains are independent, so four advance side by
    ///   side through the dimensions, in registers: the multiplications of
    ///   different tilings overlap instead of waiting on each other.
    #[inline]
    fn hashed_pow2(&self, state: &[f64], size: u64, out: &mut ActiveFeatures) {
        let n = self.tilings;
        let shift = n.trailing_zeros();
        let mut q = [0i64; MAX_FAST_DIMS];
        for (i, &x) in state.iter().enumerate() {
            q[i] = self.quantise(i, x);
        }
        let q = &q[..state.len()];
        out.indices.clear();
        let finish = |h: u64| (splitmix_finish(h) & (size - 1)) as u32;
        if n < LANES {
            for t in 0..n as i64 {
                let mut h = hash_words(0xcbf2_9ce4_8422_2325, t as u64);
                for (i, &q) in q.iter().enumerate() {
                    h = hash_words(h, ((q + t * (2 * i as i64 + 1)) >> shift) as u64);
                }
                out.indices.push(finish(h));
            }
            return;
        }
        for t0 in (0..n as i64).step_by(LANES) {
            let mut h = [0u64; LANES];
            for (k, h) in h.iter_mut().enumerate() {
                *h = hash_words(0xcbf2_9ce4_8422_2325, (t0 + k as i64) as u64);
            }
            for (i, &q) in q.iter().enumerate() {
                // Tiling t's displacement along dimension i: t · (2i + 1).
                let step = 2 * i as i64 + 1;
                let b = q + t0 * step;
                for (k, h) in h.iter_mut().enumerate() {
                    *h = hash_words(*h, ((b + k as i64 * step) >> shift) as u64);
                }
            }
            out.indices.extend(h.iter().map(|&h| finish(h)));
        }
    }

    #[inline]
    fn quantise(&self, i: usize, x: f64) -> i64 {
        floor_to_int((x - self.lower[i]) * self.inv_width[i] * self.tilings as f64)
    }
}

/// `floor(v)` as an integer without a call into the C library (`f64::floor`
/// is a library call unless the target has SSE4.1); exact for |v| < 2^63.
#[inline]
fn floor_to_int(v: f64) -> i64 {
    let t = v as i64;
    t - i64::from((t as f64) > v)
}

/// FNV-1a over 64-bit words, then the SplitMix64 finaliser (see [`TILE_HASH_DESCRIPTION`]).
#[inline]
fn hash_words(h: u64, word: u64) -> u64 {
    (h ^ word).wrapping_mul(0x0000_0100_0000_01b3)
}

#[inline]
fn splitmix_finish(mut z: u64) -> u64 {
    z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
    z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
    z ^ (z >> 31)
}

impl FeatureMap for TileCoder {
    fn num_features(&self) -> usize {
        match &self.indexing {
            Indexing::Dense { per_tiling, .. } => per_tiling * self.tilings,
            Indexing::Hashed { size } => *size as usize,
        }
    }

    fn max_active(&self) -> usize {
        self.tilings
    }

    fn features(&self, state: &[f64], out: &mut ActiveFeatures) {
        assert_eq!(
            state.len(),
            self.dims(),
            "tile coder: state has {} dimensions, the coder {}",
            state.len(),
            self.dims()
        );
        // Tile features are binary: no values. The dense path overwrites the
        // indices in place; the hashed one pushes them.
        out.values.clear();
        match &self.indexing {
            Indexing::Dense { .. } => match self.dims() {
                1 => self.dense::<1>(state, out),
                2 => self.dense::<2>(state, out),
                3 => self.dense::<3>(state, out),
                4 => self.dense::<4>(state, out),
                5 => self.dense::<5>(state, out),
                6 => self.dense::<6>(state, out),
                7 => self.dense::<7>(state, out),
                _ => self.dense::<8>(state, out),
            },
            Indexing::Hashed { size } => {
                if self.tilings.is_power_of_two()
                    && self.tilings <= MAX_FAST_TILINGS
                    && state.len() <= MAX_FAST_DIMS
                    && size.is_power_of_two()
                {
                    self.hashed_pow2(state, *size, out);
                } else {
                    self.hashed_any(state, *size, out);
                }
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    fn maze_coder() -> TileCoder {
        TileCoder::new(32, &[0.1, 0.1], TileIndexing::Dense { lower: vec![0.0, 0.0], upper: vec![1.0, 1.0] }).unwrap()
    }

    #[test]
    fn dense_grid_has_the_expected_size() {
        // q_max = floor(1.0 / 0.1 * 32) = 320; coordinates 0..=10 with displacement, so 11 tiles
        // per dimension, 121 per tiling, 32 tilings.
        let c = maze_coder();
        assert_eq!(c.num_features(), 11 * 11 * 32);
        assert_eq!(c.max_active(), 32);
    }

    #[test]
    fn displacement_is_asymmetric() {
        // One tiling-width step (1/32 of a tile) along x changes the tiles of
        // some tilings and not others; along y the pattern differs (offsets 1 vs 3).
        let c = maze_coder();
        let mut a = ActiveFeatures::default();
        let mut bx = ActiveFeatures::default();
        let mut by = ActiveFeatures::default();
        let d = 0.1 / 32.0;
        c.features(&[0.5 + d / 2.0, 0.5 + d / 2.0], &mut a);
        c.features(&[0.5 + 1.5 * d, 0.5 + d / 2.0], &mut bx);
        c.features(&[0.5 + d / 2.0, 0.5 + 1.5 * d], &mut by);
        let changed = |u: &ActiveFeatures, v: &ActiveFeatures| -> Vec<usize> {
            (0..32).filter(|&t| u.indices[t] != v.indices[t]).collect()
        };
        let cx = changed(&a, &bx);
        let cy = changed(&a, &by);
        assert_eq!(cx.len(), 1, "one tiling boundary is crossed per 1/n step: {cx:?}");
        assert_eq!(cy.len(), 1);
        assert_ne!(cx, cy, "x and y offsets must differ");
    }

    #[test]
    fn same_cell_same_tiles_and_generalisation_decays_with_distance() {
        let c = maze_coder();
        let mut a = ActiveFeatures::default();
        let mut b = ActiveFeatures::default();
        c.features(&[0.30, 0.40], &mut a);
        c.features(&[0.30 + 1e-9, 0.40], &mut b);
        assert_eq!(a, b);
        let mut shared = |x: f64| {
            c.features(&[0.30 + x, 0.40], &mut b);
            a.indices.iter().zip(&b.indices).filter(|(p, q)| p == q).count()
        };
        assert!(shared(0.02) > shared(0.05));
        assert!(shared(0.05) > shared(0.09));
        assert_eq!(shared(0.2), 0);
    }

    #[test]
    fn hashed_coder_is_stable() {
        // Pinned indices: the hash is part of the results' meaning.
        let c = TileCoder::new(4, &[1.0, 1.0, 1.0], TileIndexing::Hashed { size: 1 << 20 }).unwrap();
        let mut a = ActiveFeatures::default();
        c.features(&[0.0, 1.0, -1.0], &mut a);
        let expected: Vec<u32> =
            include_str!("tile_hash_stability.txt").split_whitespace().map(|s| s.parse().unwrap()).collect();
        assert_eq!(a.indices, expected, "got {:?}", a.indices);
    }

    #[test]
    fn bad_parameters_are_rejected() {
        assert!(TileCoder::new(0, &[0.1], TileIndexing::Hashed { size: 10 }).is_err());
        assert!(TileCoder::new(4, &[0.0], TileIndexing::Hashed { size: 10 }).is_err());
        assert!(TileCoder::new(4, &[0.1], TileIndexing::Hashed { size: 0 }).is_err());
        let e = TileCoder::new(4, &[0.1, 0.1], TileIndexing::Dense { lower: vec![0.0], upper: vec![1.0] });
        assert!(e.is_err());
        let e = TileCoder::new(4, &[0.1], TileIndexing::Dense { lower: vec![1.0], upper: vec![0.0] });
        assert!(e.is_err());
    }

    proptest! {
        #[test]
        fn floor_to_int_is_floor(v in -1e12f64..1e12) {
            prop_assert_eq!(floor_to_int(v), v.floor() as i64);
        }

        // Invariants of any tile coder: exactly one active tile per tiling,
        // every index in range, tilings use disjoint index blocks (dense).
        #[test]
        fn dense_one_tile_per_tiling_in_range(
            tilings in 1usize..40,
            w0 in 0.01f64..2.0, w1 in 0.01f64..2.0,
            x in -1.0f64..3.0, y in -1.0f64..3.0,
        ) {
            let c = TileCoder::new(tilings, &[w0, w1], TileIndexing::Dense { lower: vec![0.0, 0.0], upper: vec![2.0, 1.0] }).unwrap();
            let mut a = ActiveFeatures::default();
            c.features(&[x, y], &mut a);
            prop_assert_eq!(a.len(), tilings);
            prop_assert!(a.is_binary());
            let per = c.num_features() / tilings;
            for (t, &i) in a.indices.iter().enumerate() {
                prop_assert!((i as usize) < c.num_features());
                prop_assert_eq!(i as usize / per, t, "tile of tiling {} lies in its own block", t);
            }
        }

        // The power-of-two fast path computes exactly the general loop's indices.
        #[test]
        fn hashed_fast_path_equals_the_general_loop(
            log_tilings in 0u32..7, log_size in 0u32..24,
            xs in proptest::collection::vec(-100.0f64..100.0, 1..33),
            width in 0.1f64..4.0,
        ) {
            let widths = vec![width; xs.len()];
            let c = TileCoder::new(1 << log_tilings, &widths, TileIndexing::Hashed { size: 1 << log_size }).unwrap();
            let (mut fast, mut general) = (ActiveFeatures::default(), ActiveFeatures::default());
            c.features(&xs, &mut fast);
            c.hashed_any(&xs, 1 << log_size, &mut general);
            prop_assert_eq!(fast, general);
        }

        #[test]
        fn hashed_one_tile_per_tiling_in_range(
            tilings in 1usize..40, size in 1usize..5000,
            xs in proptest::collection::vec(-100.0f64..100.0, 1..30),
        ) {
            let widths = vec![1.0; xs.len()];
            let c = TileCoder::new(tilings, &widths, TileIndexing::Hashed { size }).unwrap();
            let mut a = ActiveFeatures::default();
            c.features(&xs, &mut a);
            prop_assert_eq!(a.len(), tilings);
            prop_assert!(a.indices.iter().all(|&i| (i as usize) < size));
        }
    }
}
