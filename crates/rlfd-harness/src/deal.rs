//! Dealing a run's trials to N shards by their expected cost.
//!
//! Each group's trials (an experiment's batch at one run point: they share a
//! set-up, so a shard pays it once) stay together unless the group costs
//! more than a shard's fair share (the total over N), in which case it is
//! cut, in order, into pieces of about that share; the pieces, heaviest
//! first, go each to the shard with the least load so far (ties: the
//! earlier piece, then the lowest-numbered shard). A trial listed by several
//! groups belongs to the first. The deal depends on the plan alone, never
//! on a store, so N processes anywhere deal the same hands.

/// The shard (from 0) of each trial. `groups` lists trial indices into
/// `seconds` (each trial's expected CPU seconds).
pub fn deal(groups: &[Vec<usize>], seconds: &[f64], count: u32) -> Vec<u32> {
    let mut owned = vec![false; seconds.len()];
    let mut pieces: Vec<(f64, Vec<usize>)> = Vec::new();
    let total: f64 = seconds.iter().sum();
    let share = total / f64::from(count.max(1));
    for group in groups {
        let mut own: Vec<usize> = group.iter().copied().filter(|&t| !std::mem::replace(&mut owned[t], true)).collect();
        own.sort_unstable();
        own.dedup();
        let mut piece = (0.0, Vec::new());
        for t in own {
            piece.0 += seconds[t];
            piece.1.push(t);
            if piece.0 >= share {
                pieces.push(std::mem::take(&mut piece));
            }
        }
        if !piece.1.is_empty() {
            pieces.push(piece);
        }
    }
    let mut order: Vec<usize> = (0..pieces.len()).collect();
    order.sort_by(|&a, &b| pieces[b].0.total_cmp(&pieces[a].0).then(a.cmp(&b)));
    let mut load = vec![0.0_f64; count.max(1) as usize];
    let mut shard_of = vec![0u32; seconds.len()];
    for p in order {
        let lightest = (0..load.len()).min_by(|&x, &y| load[x].total_cmp(&load[y]).then(x.cmp(&y))).unwrap_or(0);
        load[lightest] += pieces[p].0;
        for &t in &pieces[p].1 {
            shard_of[t] = lightest as u32;
        }
    }
    shard_of
}

/// Per shard (from 0): its trials' expected CPU seconds and count.
pub fn loads(shard_of: &[u32], seconds: &[f64], count: u32) -> Vec<(f64, usize)> {
    let mut loads = vec![(0.0, 0); count.max(1) as usize];
    for (&s, &t) in shard_of.iter().zip(seconds) {
        loads[s as usize].0 += t;
        loads[s as usize].1 += 1;
    }
    loads
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn groups_stay_together_heavy_ones_are_cut_and_loads_balance() {
        // Two light groups and one heavy group of 8 × 10 s over 2 shards.
        let seconds = [1.0, 1.0, 1.0, 10.0, 10.0, 10.0, 10.0, 10.0, 10.0, 10.0, 10.0];
        let groups = vec![vec![0, 1], vec![2], (3..11).collect()];
        let d = deal(&groups, &seconds, 2);
        assert_eq!(d[0], d[1], "a light group stays on one shard");
        let l = loads(&d, &seconds, 2);
        assert_eq!(l.iter().map(|x| x.1).sum::<usize>(), 11);
        // Pieces overshoot the fair share by at most one trial, so shards differ by at most two.
        assert!((l[0].0 - l[1].0).abs() <= 20.0, "{l:?}");
        // The same plan deals the same hands; a trial listed twice is the first group's.
        assert_eq!(deal(&groups, &seconds, 2), d);
        let twice = vec![vec![0, 1], vec![1, 2], (3..11).collect()];
        assert_eq!(deal(&twice, &seconds, 2).len(), 11);
        assert_eq!(deal(&groups, &seconds, 1), vec![0; 11]);
    }
}
