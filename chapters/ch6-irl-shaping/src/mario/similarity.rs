//! SBS's similarity potential as Mario evaluates it: the nearest
//! demonstrated state of each action found by scanning packed keys.
//!
//! Mario's 27 variables take few values (booleans, directions −1 … 1, the
//! closest enemy's offsets in whole cells), so the scaled squared distance
//! between two states is `first · (1/σ₁)² + second · (1/σ₂)²` with `first`
//! and `second` whole numbers of [`packed_differences`]: one XOR, a
//! population count and four small squares per demonstrated state. The
//! general potential's k-d tree backtracks through most of its points in 27
//! dimensions of ties: about 160,000 instructions a query (callgrind, 300
//! episodes; the master seed's set holds 3,312 distinct states over the 12
//! actions). One SBS trial of 1,000 paper episodes took 6.0–7.7 s with the
//! tree, 5.2 s with the scan and 3.5 s with the scan and the larger memo
//! of [`super::params`] (`mario_estimate 1000 sbs`, 7 December 2026, a paper
//! run on the other core; the record's digest unchanged).
//!
//! An action with many demonstrated states (the master seed's largest hold
//! 1,360, 1,027 and 577 states in about 200 cells each) is searched by the
//! closest enemy's offsets: its keys are ordered by offset cell, and the
//! cells are visited nearest first until the offsets alone are no nearer
//! than the best state found. 2,000 paper episodes took 4.2–4.7 s against
//! 5.0–6.8 s for the whole scan (`mario_estimate 2000 sbs`, three
//! interleaved runs each on 7 December 2026 with a paper run on both cores;
//! the digest unchanged).
//!
//! The values are the general potential's to the bit. With the σ's powers
//! of two (the default, ½ tile: 1 and 2, and the `sbs-sigma` reading's
//! halves and doubles), every scaled variable, every difference and square,
//! and their sum are exact in `f64`, so the general potential's minimum
//! over its points is exactly `u · min(w₁ · first + w₂ · second)` with `u`
//! the smaller of the two `(1/σ)²` and `w₁`, `w₂` the whole ratios to it.
//! The tests compare the two on random states. Other σ's, and a state
//! [`pack`] refuses, take the general potential.

use rlfd_lfd::similarity::SimilarityPotential;
use rlfd_rl::shaping::StateActionFunction;

use super::observation::{CLOSEST, STATE_VARIABLES, pack, packed_differences};

/// SBS's potential over packed states (see the module docs).
#[derive(Clone, Debug)]
pub struct PackedSimilarity {
    general: SimilarityPotential,
    /// `None` when the σ's or the demonstrated states do not allow the exact scan.
    packed: Option<Packed>,
}

#[derive(Clone, Debug)]
struct Packed {
    /// The demonstrated states' keys, action after action, each action's
    /// ordered by their closest-enemy offsets ([`cell`]).
    keys: Vec<u64>,
    /// Action `a`'s keys are `keys[starts[a]..starts[a + 1]]`.
    starts: Vec<usize>,
    /// Action `a`'s keys with offsets cell `c` are `keys[cells[a · (CELLS + 1) + c] .. cells[a · (CELLS + 1) + c + 1]]`.
    cells: Vec<u32>,
    /// Every offset difference `(dx, dy)` with its squared length, shortest first.
    ring: Vec<(i8, i8, u16)>,
    /// The unit of the distance (the smaller `(1/σ)²`) and the two groups' weights in it.
    unit: f64,
    weights: (u32, u32),
}

/// Cells of the closest enemy's two offsets as [`pack`] lays them out (5 bits each).
const CELLS: usize = 1 << 10;

/// An action with fewer demonstrated states than this is scanned whole:
/// the search by offset cells would visit more empty cells than it skips keys.
const SCANNED_WHOLE: usize = 128;

/// A key's closest-enemy offsets cell: its low 10 bits (`x` then `y`, 5 bits each).
#[inline]
fn cell(key: u64) -> usize {
    (key & (CELLS as u64 - 1)) as usize
}

/// `x` is a positive power of two (a normal float with an empty mantissa).
fn power_of_two(x: f64) -> bool {
    x.is_normal() && x > 0.0 && x.to_bits() & ((1u64 << 52) - 1) == 0
}

impl PackedSimilarity {
    /// Mario's view of `general`: the packed scan where it is exact, else `general` itself.
    pub fn new(general: SimilarityPotential) -> Self {
        let packed = Packed::new(&general);
        PackedSimilarity { general, packed }
    }

    /// Whether the packed scan is used (else every state goes to the general potential).
    pub fn is_packed(&self) -> bool {
        self.packed.is_some()
    }
}

impl Packed {
    fn new(general: &SimilarityPotential) -> Option<Self> {
        let inv = general.inv_sigma();
        if inv.len() != STATE_VARIABLES {
            return None;
        }
        let (first, second) = (inv[0], inv[CLOSEST]);
        let grouped = inv.iter().enumerate().all(|(j, &v)| v == if j < CLOSEST { first } else { second });
        if !(grouped && power_of_two(first) && power_of_two(second)) {
            return None;
        }
        let (sq1, sq2) = (first * first, second * second);
        let unit = sq1.min(sq2);
        let (w1, w2) = (sq1 / unit, sq2 / unit);
        // Keep the weighted sums in u32: at most 27 + 2 · 27² per unit weight.
        if !(power_of_two(unit) && w1 <= 4096.0 && w2 <= 4096.0) {
            return None;
        }
        let mut keys = Vec::new();
        let mut starts = vec![0];
        let mut cells = Vec::with_capacity(general.num_actions() * (CELLS + 1));
        let mut state = [0.0f64; STATE_VARIABLES];
        for a in 0..general.num_actions() {
            for scaled in general.scaled_states(a) {
                // Dividing by a power of two undoes the scaling exactly.
                for ((x, &p), &i) in state.iter_mut().zip(scaled).zip(inv) {
                    *x = p / i;
                }
                keys.push(pack(&state)?);
            }
            let start = starts[starts.len() - 1];
            let own = &mut keys[start..];
            own.sort_unstable_by_key(|&k| cell(k));
            let mut at = 0;
            for c in 0..=CELLS {
                while at < own.len() && cell(own[at]) < c {
                    at += 1;
                }
                cells.push(u32::try_from(start + at).ok()?);
            }
            starts.push(keys.len());
        }
        let mut ring: Vec<(i8, i8, u16)> = (-31i8..=31)
            .flat_map(|dx| (-31i8..=31).map(move |dy| (dx, dy, (dx as i32 * dx as i32 + dy as i32 * dy as i32) as u16)))
            .collect();
        ring.sort_by_key(|&(dx, dy, n)| (n, dx, dy));
        Some(Packed { keys, starts, cells, ring, unit, weights: (w1 as u32, w2 as u32) })
    }

    /// The squared scaled distance from `key` to action `a`'s nearest demonstrated state (∞ when none).
    ///
    /// The minimum of whole numbers, so any order of the states gives it.
    /// A large action is searched by offset cells, nearest offsets first:
    /// the keys in the cell at offset difference `(dx, dy)` are all
    /// `w₂ · (dx² + dy²)` away in the second group, and once that alone is
    /// no nearer than the best so far no later cell can be nearer.
    #[inline]
    fn nearest_sq(&self, key: u64, a: usize) -> f64 {
        let (w1, w2) = self.weights;
        let own = &self.keys[self.starts[a]..self.starts[a + 1]];
        let mut best = u32::MAX;
        if own.len() < SCANNED_WHOLE {
            for &k in own {
                let (first, second) = packed_differences(key, k);
                best = best.min(w1 * first + w2 * second);
            }
        } else {
            let cells = &self.cells[a * (CELLS + 1)..(a + 1) * (CELLS + 1)];
            let (qx, qy) = (((key >> 5) & 31) as i32, (key & 31) as i32);
            for &(dx, dy, n) in &self.ring {
                let second = w2 * u32::from(n);
                if second >= best {
                    break;
                }
                let (x, y) = (qx + i32::from(dx), qy + i32::from(dy));
                if !(0..32).contains(&x) || !(0..32).contains(&y) {
                    continue;
                }
                let c = ((x << 5) | y) as usize;
                for &k in &self.keys[cells[c] as usize..cells[c + 1] as usize] {
                    best = best.min(w1 * packed_differences(key, k).0 + second);
                }
            }
        }
        if best == u32::MAX { f64::INFINITY } else { self.unit * f64::from(best) }
    }
}

impl StateActionFunction for PackedSimilarity {
    fn values(&self, state: &[f64], out: &mut [f64]) {
        let (Some(packed), Some(key)) = (&self.packed, pack(state)) else {
            return self.general.values(state, out);
        };
        for (a, o) in out.iter_mut().enumerate() {
            let d2 = packed.nearest_sq(key, a);
            *o = if d2.is_finite() { libm::exp(-0.5 * d2) } else { 0.0 };
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::mario::ACTIONS;
    use proptest::prelude::*;

    /// A state as the game produces it, from small random choices.
    fn state(picks: &[(u8, i8)]) -> [f64; STATE_VARIABLES] {
        let mut s = [0.0; STATE_VARIABLES];
        for (j, &(p, o)) in picks.iter().enumerate() {
            s[j] = match j {
                3 | 4 => f64::from(p as i32 % 3 - 1),
                CLOSEST.. => f64::from(o.clamp(-11, 16)),
                _ => f64::from(p % 2),
            };
        }
        s
    }

    fn sigma(boolean: f64, distance: f64) -> [f64; STATE_VARIABLES] {
        let mut s = [boolean; STATE_VARIABLES];
        s[CLOSEST] = distance;
        s[CLOSEST + 1] = distance;
        s
    }

    fn potentials(demos: &[(Vec<(u8, i8)>, usize)], sigma: &[f64]) -> (SimilarityPotential, PackedSimilarity) {
        let states: Vec<([f64; STATE_VARIABLES], usize)> = demos.iter().map(|(p, a)| (state(p), *a)).collect();
        let general = SimilarityPotential::new(states.iter().map(|(s, a)| (&s[..], *a)), ACTIONS, sigma).unwrap();
        (general.clone(), PackedSimilarity::new(general))
    }

    fn picks() -> impl Strategy<Value = Vec<(u8, i8)>> {
        proptest::collection::vec((0u8..6, -11i8..17), STATE_VARIABLES)
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(64))]
        // Bit for bit the general potential's, at the default σ's, the
        // reading's halves and doubles and unequal powers of two.
        #[test]
        fn the_scan_is_the_general_potential_to_the_bit(
            demos in proptest::collection::vec((picks(), 0usize..ACTIONS - 2), 1..60),
            queries in proptest::collection::vec(picks(), 1..20),
            sigmas in proptest::sample::select(vec![(1.0, 2.0), (0.5, 1.0), (2.0, 4.0), (1.0, 0.25), (8.0, 1.0)]),
        ) {
            let (general, packed) = potentials(&demos, &sigma(sigmas.0, sigmas.1));
            prop_assert!(packed.is_packed());
            let (mut want, mut got) = ([0.0; ACTIONS], [0.0; ACTIONS]);
            for q in &queries {
                let s = state(q);
                general.values(&s, &mut want);
                packed.values(&s, &mut got);
                prop_assert_eq!(want.map(f64::to_bits), got.map(f64::to_bits));
            }
        }

        // The same with actions large enough to be searched by offset cells
        // (at least SCANNED_WHOLE states), queried at random states and at
        // demonstrated ones (distance 0) with an offset moved.
        #[test]
        fn the_cell_search_is_the_general_potential_to_the_bit(
            demos in proptest::collection::vec((picks(), 0usize..2), 2 * SCANNED_WHOLE + 20..3 * SCANNED_WHOLE),
            queries in proptest::collection::vec(picks(), 1..12),
            moved in proptest::collection::vec((0usize..1000, -3i8..4), 1..12),
            sigmas in proptest::sample::select(vec![(1.0, 2.0), (0.5, 1.0), (1.0, 0.25), (8.0, 1.0)]),
        ) {
            let (general, packed) = potentials(&demos, &sigma(sigmas.0, sigmas.1));
            prop_assert!(packed.is_packed());
            let inner = packed.packed.as_ref().unwrap();
            prop_assert!((0..2).any(|a| inner.starts[a + 1] - inner.starts[a] >= SCANNED_WHOLE));
            let near = moved.iter().map(|&(i, d)| {
                let mut p = demos[i % demos.len()].0.clone();
                p[CLOSEST].1 = p[CLOSEST].1.saturating_add(d);
                p
            });
            let (mut want, mut got) = ([0.0; ACTIONS], [0.0; ACTIONS]);
            for q in queries.iter().cloned().chain(near) {
                let s = state(&q);
                general.values(&s, &mut want);
                packed.values(&s, &mut got);
                prop_assert_eq!(want.map(f64::to_bits), got.map(f64::to_bits));
            }
        }
    }

    #[test]
    fn other_sigmas_and_states_take_the_general_potential() {
        let demos = vec![(vec![(1, 3); STATE_VARIABLES], 0), (vec![(0, -2); STATE_VARIABLES], 5)];
        let (general, packed) = potentials(&demos, &sigma(0.3, 2.0));
        assert!(!packed.is_packed());
        let (general_ok, packed_ok) = potentials(&demos, &sigma(1.0, 2.0));
        assert!(packed_ok.is_packed());
        // A state the game never produces (a fraction) is the general potential's.
        let mut odd = state(&[(1, 3); STATE_VARIABLES]);
        odd[CLOSEST] = 2.5;
        let (mut want, mut got) = ([0.0; ACTIONS], [0.0; ACTIONS]);
        general_ok.values(&odd, &mut want);
        packed_ok.values(&odd, &mut got);
        assert_eq!(want, got);
        general.values(&odd, &mut want);
        packed.values(&odd, &mut got);
        assert_eq!(want, got);
        // Never-demonstrated actions read 0; a demonstrated state reads 1.
        packed_ok.values(&state(&demos[1].0), &mut got);
        assert_eq!((got[5], got[1]), (1.0, 0.0));
    }
}
