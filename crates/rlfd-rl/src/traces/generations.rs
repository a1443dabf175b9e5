//! Replacing traces of binary features, kept by generation.
//!
//! With binary features and replacing traces, every trace set at one step
//! starts at 1 and is multiplied by the same factor γλ at every later step,
//! so all the traces set at one step hold the same number. The traces are
//! therefore kept as a ring of *generations*: the weights marked at one step
//! and one value for all of them. Applying `w += step · e` is one
//! multiplication per generation and one addition per traced weight;
//! decaying is one multiplication per generation, and the oldest generation
//! leaves whole once its value falls below the threshold: no test and no move
//! per trace (the per-trace test of [`SparseTraces`] takes a mispredicted
//! branch for every trace that leaves).
//!
//! A feature marked again moves from its older generation to the new one
//! (the replacing rule: its trace is 1 again, for the new action only); a
//! slot per feature says where its trace is. When a step's state is the last
//! step's (a third of Mario's steps: the 27 variables often hold for several
//! ticks), its generation is simply renewed.
//!
//! The arithmetic is the general traces', number for number: a trace's
//! value is the same product `((1 · f) · f) …`, the same `step · e` is added
//! to the same weight, and a trace leaves at the same step. Each traced
//! weight belongs to one feature and each feature to one generation, so every
//! weight gets at most one addition per step and the order of the additions
//! cannot matter. [`crate::td_lambda`] uses these traces for replacing traces
//! of binary features and its tests check the weights against the general
//! traces bit for bit.

use super::SparseTraces;

/// Most generations kept: a decay slower than this many steps to fall below
/// the threshold (γλ ≥ 0.93 for the 0.01 threshold) is left to the general traces.
pub const MAX_GENERATIONS: usize = 64;

/// No trace for this feature (0, so that the slots start as zeroed memory
/// the system hands out lazily: a trial touches only its features' slots).
const NONE: u32 = 0;

/// Replacing traces of binary features, one generation per step (see the module docs).
///
/// The generations share one array: ring slot `g` holds its traced weights
/// at positions `g · cap …`, `cap` a power of two at least the largest
/// number of features marked in one step, so that a position says its
/// generation by a shift.
#[derive(Clone, Debug)]
pub struct GenerationTraces {
    /// The traced weights of ring slot `g` at `g · cap .. g · cap + lens[g]`.
    entries: Vec<Entry>,
    /// Traced weights per ring slot.
    lens: Vec<u32>,
    /// The trace of each ring slot's weights.
    values: Vec<f64>,
    /// `log2 cap`.
    cap_shift: u32,
    /// Most generations alive at once (the ring is a power of two at least this long).
    max_live: usize,
    /// Ring slot of the newest generation.
    head: usize,
    /// Number of live generations (the newest `live` ring slots, backwards from `head`).
    live: usize,
    /// Where each feature's trace is: its position in `entries` plus one, or [`NONE`].
    slot: Vec<u32>,
    /// Number of traced weights.
    len: usize,
    factor: f64,
    threshold: f64,
}

/// A traced weight and its feature.
#[derive(Clone, Copy, Debug, Default)]
struct Entry {
    key: u32,
    weight: u32,
}

impl GenerationTraces {
    /// Traces of `num_features` features decaying by `factor` per step and
    /// dropped below `threshold`; `None` when a trace of 1 would outlive
    /// [`MAX_GENERATIONS`] steps (use [`SparseTraces`] then).
    ///
    /// # Panics
    /// If `num_features` does not fit below `u32::MAX`.
    pub fn new(num_features: usize, factor: f64, threshold: f64) -> Option<Self> {
        assert!(u32::try_from(num_features).is_ok(), "too many features for u32 slots");
        // Generations alive at once: a trace set at step t is applied at
        // steps t, t+1, … until its value falls below the threshold.
        let (mut v, mut n) = (1.0f64, 1usize);
        loop {
            v *= factor;
            if v.abs() < threshold {
                break;
            }
            n += 1;
            if n > MAX_GENERATIONS || !v.is_finite() {
                return None;
            }
        }
        let ring = n.next_power_of_two();
        Some(GenerationTraces {
            entries: vec![Entry::default(); ring],
            lens: vec![0; ring],
            values: vec![0.0; ring],
            cap_shift: 0,
            max_live: n,
            head: 0,
            live: 0,
            slot: vec![NONE; num_features],
            len: 0,
            factor,
            threshold,
        })
    }

    /// The decay factor per step (γλ).
    pub fn factor(&self) -> f64 {
        self.factor
    }

    /// Number of traced weights.
    pub fn len(&self) -> usize {
        self.len
    }

    /// No trace is set.
    pub fn is_empty(&self) -> bool {
        self.len == 0
    }

    /// Ring slot of the generation `age` steps old.
    #[inline]
    fn slot_of_age(&self, age: usize) -> usize {
        self.head.wrapping_sub(age) & (self.lens.len() - 1)
    }

    /// The traced weights of ring slot `g`.
    #[inline]
    fn generation(&self, g: usize) -> &[Entry] {
        let start = g << self.cap_shift;
        &self.entries[start..start + self.lens[g] as usize]
    }

    /// Room for `marks` features in one generation: a larger `cap`, every
    /// live trace moved to its new position (while a learner warms up).
    #[cold]
    fn make_room(&mut self, marks: usize) {
        let shift = marks.next_power_of_two().trailing_zeros().max(self.cap_shift);
        let old = std::mem::replace(&mut self.entries, vec![Entry::default(); self.lens.len() << shift]);
        for (g, &n) in self.lens.iter().enumerate() {
            let start = g << self.cap_shift;
            for (p, &e) in old[start..start + n as usize].iter().enumerate() {
                let at = (g << shift) + p;
                self.entries[at] = e;
                self.slot[e.key as usize] = at as u32 + 1;
            }
        }
        self.cap_shift = shift;
    }

    /// Sets the traces of this step's active `features` to 1, for weight
    /// `weight(k)` of feature `k`, clearing the trace each feature had for
    /// any action (the replacing rule), and returns `Σ weights[weight(k)]`
    /// over the features in order: the learner's `Q(s, a)`, summed in the
    /// same pass so that the marking runs while the additions, one after
    /// the other, wait on each other.
    ///
    /// `None` when the ring is full (steps without decay, e.g. after a
    /// terminal update, followed by more steps than the ring holds): nothing
    /// changes, and the caller moves to [`SparseTraces`] with
    /// [`GenerationTraces::to_sparse`].
    ///
    /// # Panics
    /// If a feature or weight is out of range, or the positions of the
    /// traces do not fit in `u32`.
    #[inline]
    pub fn mark_state(&mut self, features: &[u32], weight: impl Fn(u32) -> u32, weights: &[f64]) -> Option<f64> {
        let mut sum = 0.0;
        if self.live > 0 && same_keys(self.generation(self.head), features) {
            // The state of the last step again: the newest generation holds
            // exactly these features and nothing else does (a generation
            // loses features only to newer ones), so it becomes this step's
            // generation (trace 1, the new action's weights).
            for &k in features {
                sum += weights[weight(k) as usize];
            }
            let start = self.head << self.cap_shift;
            let n = self.lens[self.head] as usize;
            for e in &mut self.entries[start..start + n] {
                e.weight = weight(e.key);
            }
            self.values[self.head] = 1.0;
            return Some(sum);
        }
        if self.live == self.max_live {
            return None;
        }
        if features.len() > 1 << self.cap_shift {
            self.make_room(features.len());
            assert!(u32::try_from(self.entries.len()).is_ok(), "too many traces for u32 positions");
        }
        if self.live > 0 {
            self.head = (self.head + 1) & (self.lens.len() - 1);
        }
        self.live += 1;
        let (sum, marked, moved) = mark_new_generation(
            &mut self.entries,
            &mut self.lens,
            &mut self.slot,
            (self.head, self.cap_shift),
            features,
            weight,
            weights,
        );
        self.values[self.head] = 1.0;
        self.len += marked - moved;
        Some(sum)
    }

    /// `w[i] += step · e[i]` for every traced weight.
    #[inline]
    pub fn apply(&self, weights: &mut [f64], step: f64) {
        for age in 0..self.live {
            let g = self.slot_of_age(age);
            let s = step * self.values[g];
            for e in self.generation(g) {
                weights[e.weight as usize] += s;
            }
        }
    }

    /// [`GenerationTraces::apply`], then every trace times the factor, and
    /// the generations whose trace falls below the threshold leave.
    #[inline]
    pub fn apply_and_decay(&mut self, weights: &mut [f64], step: f64) {
        self.apply(weights, step);
        for age in 0..self.live {
            let g = self.slot_of_age(age);
            self.values[g] *= self.factor;
        }
        while self.live > 0 {
            let oldest = self.slot_of_age(self.live - 1);
            // The general traces' test, `|v| < threshold`, word for word.
            let leaves = self.values[oldest].abs() < self.threshold;
            if !leaves {
                break;
            }
            self.drop_generation(oldest);
            self.live -= 1;
        }
    }

    /// Empties ring slot `g`.
    #[inline]
    fn drop_generation(&mut self, g: usize) {
        let start = g << self.cap_shift;
        let n = self.lens[g] as usize;
        for e in &self.entries[start..start + n] {
            self.slot[e.key as usize] = NONE;
        }
        self.len -= n;
        self.lens[g] = 0;
    }

    /// Removes every trace.
    #[inline]
    pub fn clear(&mut self) {
        for age in 0..self.live {
            let g = self.slot_of_age(age);
            self.drop_generation(g);
        }
        self.live = 0;
    }

    /// `(feature, weight index, trace)` of every traced weight, newest generation first.
    pub fn iter(&self) -> impl Iterator<Item = (usize, usize, f64)> + '_ {
        (0..self.live).flat_map(move |age| {
            let g = self.slot_of_age(age);
            let v = self.values[g];
            self.generation(g).iter().map(move |e| (e.key as usize, e.weight as usize, v))
        })
    }

    /// The same traces as general traces keyed per feature, for a learner
    /// that leaves the binary replacing case.
    pub fn to_sparse(&self) -> SparseTraces {
        let mut s = SparseTraces::per_feature(self.slot.len(), self.threshold);
        for (k, w, v) in self.iter() {
            s.replace(k, w, v);
        }
        s
    }
}

/// The marking loop of [`GenerationTraces::mark_state`] for a new generation
/// in ring slot `head` (`cap = 1 << shift`), over slices (their bounds stay in
/// registers): `(Σ weights[weight(k)], traces in the new generation, traces
/// moved there from older ones)`.
#[inline(always)]
fn mark_new_generation(
    entries: &mut [Entry],
    lens: &mut [u32],
    slot: &mut [u32],
    (head, shift): (usize, u32),
    features: &[u32],
    weight: impl Fn(u32) -> u32,
    weights: &[f64],
) -> (f64, usize, usize) {
    debug_assert_eq!(lens[head], 0);
    let base = head << shift;
    let (mut sum, mut n, mut moved) = (0.0, 0usize, 0usize);
    for &key in features {
        let entry = Entry { key, weight: weight(key) };
        sum += weights[entry.weight as usize];
        let at = slot[key as usize];
        if at != NONE {
            let at = at as usize - 1;
            let g = at >> shift;
            if g == head {
                // A feature active twice in one state (tilings hashed to one bucket).
                entries[at] = entry;
                continue;
            }
            // Out of its old generation: the old generation's last trace fills the gap.
            lens[g] -= 1;
            let last = entries[(g << shift) + lens[g] as usize];
            entries[at] = last;
            slot[last.key as usize] = at as u32 + 1;
            moved += 1;
        }
        entries[base + n] = entry;
        slot[key as usize] = (base + n) as u32 + 1;
        n += 1;
    }
    lens[head] = n as u32;
    (sum, n, moved)
}

/// Whether a generation's features are `features`, in order (a state with
/// a feature twice never matches: its generation holds it once).
#[inline]
fn same_keys(entries: &[Entry], features: &[u32]) -> bool {
    entries.len() == features.len() && entries.iter().zip(features).all(|(e, &k)| e.key == k)
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    #[test]
    fn ring_size_follows_the_decay() {
        // 0.45: 1, .45, .2025, .091, .041, .0185 live; .0083 leaves → 6 generations.
        assert_eq!(GenerationTraces::new(8, 0.45, 0.01).unwrap().max_live, 6);
        assert_eq!(GenerationTraces::new(8, 0.0, 0.01).unwrap().max_live, 1);
        assert!(GenerationTraces::new(8, 1.0, 0.01).is_none());
        assert!(GenerationTraces::new(8, 0.99, 0.01).is_none());
    }

    #[test]
    fn a_generation_lives_until_its_trace_falls_below_the_threshold() {
        let mut t = GenerationTraces::new(8, 0.5, 0.1).unwrap(); // 1, .5, .25, .125 live; .0625 leaves
        let mut w = vec![0.0; 8];
        assert!(t.mark_state(&[3], |k| k, &w).is_some());
        for _ in 0..3 {
            t.apply_and_decay(&mut w, 1.0);
            assert!(t.mark_state(&[], |k| k, &w).is_some());
        }
        assert_eq!(t.len(), 1);
        t.apply_and_decay(&mut w, 1.0);
        assert!(t.is_empty());
        assert_eq!(w[3], 1.0 + 0.5 + 0.25 + 0.125);
    }

    #[test]
    fn marking_again_moves_the_feature_to_the_new_action() {
        let mut t = GenerationTraces::new(10, 0.5, 0.01).unwrap();
        let mut w: Vec<f64> = (0..100).map(f64::from).collect();
        assert_eq!(t.mark_state(&[7, 8, 9], |k| 10 * k, &w), Some(70.0 + 80.0 + 90.0));
        w.fill(0.0);
        t.apply_and_decay(&mut w, 1.0);
        assert!(t.mark_state(&[7, 7], |k| 10 * k + 1, &w).is_some());
        let mut got: Vec<_> = t.iter().map(|(k, w, v)| (k, w, v.to_bits())).collect();
        got.sort_unstable();
        assert_eq!(got, vec![(7, 71, 1f64.to_bits()), (8, 80, 0.5f64.to_bits()), (9, 90, 0.5f64.to_bits())]);
        assert_eq!(t.len(), 3);
        // The same state again renews its generation for the new action.
        t.apply_and_decay(&mut w, 1.0);
        assert!(t.mark_state(&[7, 7], |k| 10 * k + 2, &w).is_some());
        let mut got: Vec<_> = t.iter().map(|(k, w, v)| (k, w, v.to_bits())).collect();
        got.sort_unstable();
        assert_eq!(got, vec![(7, 72, 1f64.to_bits()), (8, 80, 0.25f64.to_bits()), (9, 90, 0.25f64.to_bits())]);
    }

    proptest! {
        // Any sequence of steps (states' binary features marked for an
        // action, decays, cuts, terminal updates) leaves the weights and
        // traces of the general per-feature traces, bit for bit.
        #[test]
        fn equals_the_general_traces(
            steps in proptest::collection::vec(
                (proptest::collection::vec(0u32..48, 0..12), proptest::bool::weighted(0.3), 0u32..3, 0u8..12, -2.0f64..2.0),
                1..150,
            ),
            factor in 0.0f64..0.9,
        ) {
            let mut generations = GenerationTraces::new(48, factor, 0.01).unwrap();
            let mut general = SparseTraces::per_feature(48, 0.01);
            let (mut wg, mut ws) = (vec![0.0f64; 48 * 3], vec![0.0f64; 48 * 3]);
            let mut state = vec![];
            for (features, repeat, a, op, step) in steps {
                if !repeat {
                    state = features;
                }
                let q: f64 = state.iter().fold(0.0, |q, &k| q + wg[(k * 3 + a) as usize]);
                let marked = match generations.mark_state(&state, |k| k * 3 + a, &wg) {
                    Some(sum) => sum,
                    None => {
                        generations.clear();
                        general.clear();
                        generations.mark_state(&state, |k| k * 3 + a, &wg).expect("room after a clear")
                    }
                };
                prop_assert_eq!(marked.to_bits(), q.to_bits());
                for &k in &state {
                    general.replace(k as usize, (k * 3 + a) as usize, 1.0);
                }
                match op {
                    0 => { generations.apply(&mut wg, step); general.apply(&mut ws, step); }
                    1 => {
                        generations.apply(&mut wg, step);
                        generations.clear();
                        general.apply(&mut ws, step);
                        general.clear();
                    }
                    _ => {
                        generations.apply_and_decay(&mut wg, step);
                        general.apply_and_decay(&mut ws, step, factor);
                    }
                }
                prop_assert_eq!(generations.len(), general.len());
                for (a, b) in wg.iter().zip(&ws) {
                    prop_assert_eq!(a.to_bits(), b.to_bits());
                }
                let mut g: Vec<(usize, u64)> = generations.iter().map(|(_, w, v)| (w, v.to_bits())).collect();
                let mut s: Vec<(usize, u64)> = general.iter().map(|(w, v)| (w, v.to_bits())).collect();
                g.sort_unstable();
                s.sort_unstable();
                prop_assert_eq!(g, s);
            }
            // And converted to general traces, they are the general traces.
            let mut c: Vec<(usize, u64)> = generations.to_sparse().iter().map(|(w, v)| (w, v.to_bits())).collect();
            let mut s: Vec<(usize, u64)> = general.iter().map(|(w, v)| (w, v.to_bits())).collect();
            c.sort_unstable();
            s.sort_unstable();
            prop_assert_eq!(c, s);
        }
    }
}
