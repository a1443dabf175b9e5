//! How episodes end, per simulated second: the measurement the simulator is
//! validated by against the real rcssserver with the real keepaway 0.6
//! players (issue 28). For each configuration and benchmark policy it plays
//! `episodes` episodes and prints the mean duration with its standard error,
//! the endings by cause × the team that kicked last per simulated second
//! (the oracle's `end_by_last_kicker` divided by the total time), passes per
//! second, and the endings that came within 10 cycles of a strong (≥ 50)
//! keeper kick with no taker kick since (passes that rolled out or were taken),
//! and the endings by the teams that kicked in the last cycle with a kick.
//! The episodes are split between ten games (seeds `1000 · SEED + g`), each
//! with its own draw of the see phases.
//!
//! usage: `cargo run --release -p rlfd-keepaway --example mechanisms -- [EPISODES] [SEED] [POLICY] [VARIANT]`
//! (POLICY: hand | hold | rand | all | hand-all; default 2000 episodes, seed 1,
//! hand on 3 vs 2 20 m and 25 m; `all` runs the twelve benchmark
//! configurations, `hand-all` Hand-coded on all four; VARIANT
//! `far-velocity-always` gives every see the ball's velocity, as the
//! simulator did before `KeepawayParams::drop_far_ball_velocity`, and
//! `unnumbered-far-players` turns on `KeepawayParams::unnumbered_far_players`).

use rlfd_env::random::seeded;
use rlfd_keepaway::{BenchmarkPolicy, EndCause, Keepaway, KeepawayParams, MAX_STATE_VARS};

/// Counts over a run of episodes.
#[derive(Default)]
struct Counts {
    episodes: u32,
    cycles: u64,
    sum2: f64,
    /// [out, taken] × [keeper last, taker last, nobody]
    ends: [[u32; 3]; 2],
    passes: u64,
    /// [out, taken] within 10 cycles of a strong keeper kick
    lost_pass: [u32; 2],
    /// [out, taken] whose last cycle with a kick had kicks of both teams:
    /// the team counted last is then the one whose command arrived last
    mixed_last: [[u32; 2]; 2],
}

/// Games the episodes are split between: each game draws its players' see
/// phases once (as a server run fixes them when the players connect), so the
/// counts average over ten draws rather than resting on one.
const GAMES: u32 = 10;

/// A mechanism switched from the simulator's default, to measure it.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Variant {
    /// Every see carries the ball's velocity (before `drop_far_ball_velocity`).
    FarVelocityAlways,
    /// Far players seen without their numbers (`unnumbered_far_players`).
    UnnumberedFarPlayers,
}

fn run(
    policy: BenchmarkPolicy,
    (nk, nt, side): (usize, usize, f64),
    episodes: u32,
    seed: u64,
    variant: Option<Variant>,
) -> Counts {
    let mut c = Counts::default();
    for g in 0..GAMES {
        let n = episodes / GAMES + u32::from(g < episodes % GAMES);
        play(policy, (nk, nt, side), n, seed * 1000 + u64::from(g), variant, &mut c);
    }
    c
}

fn play(
    policy: BenchmarkPolicy,
    (nk, nt, side): (usize, usize, f64),
    episodes: u32,
    seed: u64,
    variant: Option<Variant>,
    c: &mut Counts,
) {
    let mut params = KeepawayParams::configuration(nk, nt, side);
    params.drop_far_ball_velocity = variant != Some(Variant::FarVelocityAlways);
    params.unnumbered_far_players = variant == Some(Variant::UnnumberedFarPlayers);
    let mut game = Keepaway::new(params).expect("valid configuration");
    let len = game.params().state_len();
    let mut rng = seeded(seed);
    let mut state = [0.0; MAX_STATE_VARS];
    for _ in 0..episodes {
        let (d, cause) = game.play_episode(&mut rng, |g, _, rng| {
            g.state_vars_into(&mut state[..len]);
            policy.choose_in(&state[..len], nk, nt, rng)
        });
        let t = game.tally();
        let how = usize::from(cause == EndCause::Taken);
        let who = match t.last_by_keeper {
            Some(true) => 0,
            Some(false) => 1,
            None => 2,
        };
        c.episodes += 1;
        c.cycles += u64::from(d);
        c.sum2 += f64::from(d).powi(2);
        c.ends[how][who] += 1;
        c.passes += u64::from(t.passes);
        if t.lost_after_strong_kick(d, 10) {
            c.lost_pass[how] += 1;
        }
        if t.both_teams_in_last_kick_cycle() && who < 2 {
            c.mixed_last[how][who] += 1;
        }
    }
}

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let episodes: u32 = args.get(1).and_then(|a| a.parse().ok()).unwrap_or(2000);
    let seed: u64 = args.get(2).and_then(|a| a.parse().ok()).unwrap_or(1);
    let which = args.get(3).map_or("hand", String::as_str);
    let variant = match args.get(4).map(String::as_str) {
        Some("far-velocity-always") => Some(Variant::FarVelocityAlways),
        Some("unnumbered-far-players") => Some(Variant::UnnumberedFarPlayers),
        _ => None,
    };
    let policies: &[BenchmarkPolicy] = match which {
        "hold" => &[BenchmarkPolicy::AlwaysHold],
        "rand" => &[BenchmarkPolicy::Random],
        "all" => &BenchmarkPolicy::ALL,
        _ => &[BenchmarkPolicy::HandCoded],
    };
    let configs: &[(usize, usize, f64)] = if which == "all" || which == "hand-all" {
        &[(3, 2, 20.0), (3, 2, 25.0), (4, 3, 20.0), (4, 3, 25.0)]
    } else {
        &[(3, 2, 20.0), (3, 2, 25.0)]
    };
    println!(
        "config policy n mean_s se_s out_k/s out_t/s taken_k/s taken_t/s passes/s lost_out/s lost_taken/s out_keepers_only/s out_takers_only/s out_both/s taken_keepers_only/s taken_takers_only/s taken_both/s"
    );
    for &(nk, nt, side) in configs {
        for &policy in policies {
            let c = run(policy, (nk, nt, side), episodes, seed, variant);
            let n = f64::from(c.episodes);
            let secs = c.cycles as f64 / 10.0;
            let mean = secs / n;
            let var = (c.sum2 / 100.0 - n * mean * mean) / (n - 1.0);
            let rate = |x: u32| f64::from(x) / secs;
            println!(
                "{nk}v{nt}-{side} {} {} {:.3} {:.3} {:.4} {:.4} {:.4} {:.4} {:.3} {:.4} {:.4} {:.4} {:.4} {:.4} {:.4} {:.4} {:.4}",
                policy.slug(),
                c.episodes,
                mean,
                (var / n).sqrt(),
                rate(c.ends[0][0]),
                rate(c.ends[0][1]),
                rate(c.ends[1][0]),
                rate(c.ends[1][1]),
                c.passes as f64 / secs,
                rate(c.lost_pass[0]),
                rate(c.lost_pass[1]),
                rate(c.ends[0][0] - c.mixed_last[0][0]),
                rate(c.ends[0][1] - c.mixed_last[0][1]),
                rate(c.mixed_last[0][0] + c.mixed_last[0][1]),
                rate(c.ends[1][0] - c.mixed_last[1][0]),
                rate(c.ends[1][1] - c.mixed_last[1][1]),
                rate(c.mixed_last[1][0] + c.mixed_last[1][1]),
            );
        }
    }
}
