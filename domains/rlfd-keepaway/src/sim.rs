//! One Keepaway game: the referee, the players' behaviours and the
//! macro-action interface the keepers with the ball are driven through.
//!
//! The referee (rcssserver's `KeepawayRef`): at the start of an episode the
//! keepers stand at three corners of the region in a random cyclic order
//! (the first corner drawn uniformly), each up to 3 m in from it on both
//! axes, a fourth or fifth keeper within 1 m of the centre, every taker in
//! the fourth corner likewise, and the ball at rest 4 m in from the first
//! corner (−L/2 + 4, −W/2 + 4); velocities are zeroed and body directions
//! kept from the episode before. After every cycle the episode ends when the
//! ball has left the region ("o"), or when the takers have had the ball
//! within a kickable area for 4 analyses without a keeper alone touching it
//! in between ("t"). The duration is the number of cycles.
//!
//! Every cycle, each player sends one command (`KeepawayPlayer::keeper` and `taker`):
//! - every keeper with the ball kickable runs its macro-action:
//!   [`KeeperAction::HOLD`] (`holdBall`, one cycle) or a pass to the `i`-th
//!   nearest teammate (`kickTo` its position with end speed 1.2, the players'
//!   default `pass_end_speed`), which continues on its own while the ball
//!   stays kickable the next cycle;
//! - the other keepers run Receive: the keeper fastest to the ball
//!   intercepts it, the others GetOpen from where it will get it (`players`);
//! - the takers run their hand-coded policy (`players`).
//!
//! Then the server moves everything, resolves collisions and the referee
//! analyses ([`super::server`]).
//!
//! [`Keepaway::run`] simulates cycles until a keeper with the ball must
//! choose (returning [`Status::Decision`]) or the episode ends; [`Keepaway::act`]
//! records the choice and runs on (when two keepers have the ball kickable
//! both choose before the cycle runs). A keeper's SMDP reward is the number
//! of cycles since its previous action ([`Keepaway::last_action_cycle`]).
//!
//! Perception: every player sees the ball as the server shows it (quantised,
//! two looks in every three cycles, a see every 150 ms, in phases set by
//! when the players connected: [`SeePhases`], by default one for the keepers
//! and one for the takers as keepaway.sh starts them), carries it on every cycle with its own
//! kicks only, moves it as its sense message shows a collision with it, and
//! hears one teammate's say message a cycle later
//! ([`super::vision`]; `makeSayMessage` and `WMBallInfo::process`). It sees
//! the other players quantised the same way in the same looks and carries
//! them on between looks with Trilearn's rules; its own body it knows.
//!
//! What it is not: a network server; the players do not hear one another's
//! positions (the say messages' `OurPos`/`OppPos` parts), they know their
//! own position exactly (the real players localise from flags), sees of
//! players always carry their numbers (the server drops them with a
//! probability rising beyond 20 m, as it drops the ball's velocity, which is
//! modelled: [`KeepawayParams::drop_far_ball_velocity`]; the players' numbers
//! are a measured switch, [`KeepawayParams::unnumbered_far_players`]), and there is no stamina (unlimited in
//! keepaway.sh). No see arrives after a cycle's think, as none does in the
//! server's synch mode ([`SeePhases`]); the real-time mode, where the
//! players synchronise their sees with `change_view`, is not modelled. It
//! knows no learner: policies live outside this module.

use rand::Rng;
use rlfd_env::random::{below, uniform01};
use serde::{Deserialize, Serialize};
use thiserror::Error;

use super::geometry::Vec2;
use super::players::{Congestion, GetOpenGrid, Region, TakerView, closest, fastest_to_ball, get_open};
use super::server::{
    Ball, Body, Command, MAX_PLAYERS, ServerParams, advance_ball, advance_player, collisions, execute,
};
use super::skills::{BallForecast, InterceptMemory, Interceptor, Kinematics, hold_ball, kick_to};
use super::state::{KeeperAction, MAX_STATE_VARS, STATE_VARS, sort_indices_by_distance, state_len, state_vars_general};
use super::vision::{
    BallBelief, BallMessage, Heading, OwnMotion, PairSight, seen_player_with, seen_unnumbered_player, sends_velocity,
    sensed_velocity, senses_collision,
};

/// Keepers in the thesis's 3 vs 2.
pub const KEEPERS: usize = 3;

/// Takers in the thesis's 3 vs 2.
pub const TAKERS: usize = 2;

/// The most keepers a game may have.
pub const MAX_KEEPERS: usize = 5;

/// The most takers a game may have.
pub const MAX_TAKERS: usize = 4;

/// Cycles per simulated second (one cycle is 100 ms).
pub const CYCLES_PER_SECOND: f64 = 10.0;

/// Cycles per simulated hour.
pub const CYCLES_PER_HOUR: u64 = 36_000;

/// The keepers' forward direction (the left team's +x).
const KEEPER_FORWARD: Vec2 = Vec2 { x: 1.0, y: 0.0 };

/// The goal keepers turn to when holding the ball (`getPosOpponentGoal`, the right goal).
const KEEPER_GOAL: Vec2 = Vec2 { x: 52.5, y: 0.0 };

/// A parameter of the simulator outside its domain.
#[derive(Debug, Clone, PartialEq, Error)]
#[error("keepaway parameter `{name}` = {value} is invalid: {expected}")]
pub struct KeepawayParamError {
    /// The field's name.
    pub name: &'static str,
    /// Its value.
    pub value: String,
    /// What it should be.
    pub expected: &'static str,
}

/// The game's parameters: the server's physics and the keepaway task's setup.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct KeepawayParams {
    /// Soccer-server constants.
    pub server: ServerParams,
    /// Number of keepers (keepaway.sh `num_keepers`; the thesis: 3).
    pub keepers: usize,
    /// Number of takers (keepaway.sh `num_takers`; the thesis: 2).
    pub takers: usize,
    /// The region's length (m): `keepaway_length`.
    pub length: f64,
    /// The region's width (m): `keepaway_width`.
    pub width: f64,
    /// Largest random inset of a starting player from its corner, per axis (m; `KeepawayRef::resetField`'s 3).
    pub start_inset: f64,
    /// The ball's start, inset from the first corner on both axes (m; `resetField`'s 4).
    pub ball_inset: f64,
    /// Cycles a taker must control the ball to end the episode (`TURNOVER_TIME`, 4 since rcssserver 10.0.4).
    pub turnover_cycles: u32,
    /// The speed a pass should have when it reaches the teammate
    /// (`pass_end_speed`: 1.2 in `PlayerSettings.cc`, which applies because
    /// keepaway.sh starts the players without `-c`; `player.conf` says 1.7).
    pub pass_end_speed: f64,
    /// How far beyond its body a keeper holds the ball, as a fraction of the kickable margin (`holdBall`'s 0.7).
    pub keeper_hold_ratio: f64,
    /// The same for a taker (`holdBall(0.3)`).
    pub taker_hold_ratio: f64,
    /// When each player's see messages come ([`SeePhases`]).
    pub see_phases: SeePhases,
    /// Whether a see of a ball beyond 20 m leaves out its velocity as the
    /// server's does (`sendHighBall`: with probability `(qd − 20) / (40 −
    /// 20)` for the quantised distance `qd`, always from 40 m), the player
    /// then keeping the velocity it predicted (`calculateStateBall`). On by
    /// default; off, every see carries the velocity (the simulator before
    /// issue 28's last mechanism, kept to measure what this one changes;
    /// parameters stored before the field read as off, as they played).
    #[serde(default)]
    pub drop_far_ball_velocity: bool,
    /// Whether a see of a player beyond 20 m leaves out its number at the
    /// same rate (`sendHighPlayer`), the observer then believing it still
    /// and facing Trilearn's unknown angle ([`super::vision::seen_unnumbered_player`]).
    /// Off by default: measured (no effect on the Hand-coded durations
    /// beyond 1.3 standard errors), not the simulator's behaviour. Left out
    /// of serialised parameters when off, so that trial identities stay.
    #[serde(default, skip_serializing_if = "std::ops::Not::not")]
    pub unnumbered_far_players: bool,
}

/// Which cycles each player gets a see message in.
///
/// The server sends a player's see every `send_step` = 150 ms at normal
/// width and high quality (the players never send `change_view` in synch
/// mode: `SenseHandler::synchronize` returns at once), counting its own
/// calls of `sendVisuals` from the moment the player connected
/// (`VisualSenderPlayerV1::sendVisual`, every fourth call). In synch mode
/// the timer (`SyncTimer::run`) calls `sendVisuals` at 40, 80, 120 and
/// 150 ms of every 150, steps the game at every 100 ms and sends `think`
/// at 80 ms into each cycle, after that iteration's visuals; a player's
/// `init` is read while the server waits for the `done`s of a think, so a
/// player connects at 80 ms into some cycle `k`. Its first see then comes
/// 230, 200 or 220 ms after cycle `k` began (for `k mod 3` = 0, 1, 2: the
/// fourth `sendVisuals` call after the connection), and one every 150 ms
/// after: in every case it sees in cycles `k + 2` and `k + 3` of every
/// three, 0 to 80 ms into the cycle, so before the cycle's think (no see
/// arrives after a player's command), and never in the cycles `≡ k + 1`
/// (mod 3). A player's phase is its connection cycle mod 3.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
pub enum SeePhases {
    /// As keepaway.sh starts the players (and the oracle's `run.sh`): the
    /// keepers all at once (connecting in the same cycle, one phase), the
    /// takers two seconds later (one phase of their own). Before kick-off a
    /// synch-mode cycle lasts 50 ms of wall-clock sleep plus the players'
    /// replies, so the two seconds are some forty cycles whose count mod 3
    /// depends on the machine's timing: each team's phase is drawn
    /// uniformly, once per game. Checked on the real server and players
    /// (`ch5-hat-keepaway/data/oracle_see_phases.sh` and `.py`, five starts
    /// on the oracle's machine): every player saw in exactly two cycles of
    /// three and never after the think, the three keepers always shared one
    /// phase and the two takers one; the takers' phase was the keepers' + 1
    /// (mod 3, in [`SeePhases::Teams`]' terms) in four starts and equal in
    /// one, so on that machine the offset is not uniform, while the
    /// thesis's machine's is unknown.
    KeepawaySh,
    /// Every player's phase drawn uniformly on its own, once per game (this
    /// simulator's model before issue 28; kept to measure what the shared
    /// phases change).
    Independent,
    /// The keepers' and the takers' phases given (each taken mod 3), for tests and measurements.
    Teams {
        /// The keepers' phase.
        keepers: u8,
        /// The takers' phase.
        takers: u8,
    },
}

impl SeePhases {
    /// The phases as keepaway.sh starts the players: the default.
    pub const KEEPAWAY_SH: SeePhases = SeePhases::KeepawaySh;

    /// Every player's phase (keepers first), drawn as the variant says.
    fn draw<R: Rng + ?Sized>(self, keepers: usize, rng: &mut R) -> [u8; MAX_PLAYERS] {
        match self {
            SeePhases::KeepawaySh => {
                let (k, t) = (below(rng, 3) as u8, below(rng, 3) as u8);
                std::array::from_fn(|i| if i < keepers { k } else { t })
            }
            SeePhases::Independent => std::array::from_fn(|_| below(rng, 3) as u8),
            SeePhases::Teams { keepers: k, takers: t } => {
                std::array::from_fn(|i| if i < keepers { k % 3 } else { t % 3 })
            }
        }
    }
}

impl KeepawayParams {
    /// 3 vs 2 on the 20 m × 20 m region, as the thesis ran it (rcssserver 11.1.0, players v0.6).
    pub fn benchmark() -> Self {
        Self::configuration(3, 2, 20.0)
    }

    /// `keepers` vs `takers` on a `side` × `side` region, everything else as the benchmark.
    pub fn configuration(keepers: usize, takers: usize, side: f64) -> Self {
        KeepawayParams {
            server: ServerParams::rcssserver_11(),
            keepers,
            takers,
            length: side,
            width: side,
            start_inset: 3.0,
            ball_inset: 4.0,
            turnover_cycles: 4,
            pass_end_speed: 1.2,
            keeper_hold_ratio: 0.7,
            taker_hold_ratio: 0.3,
            see_phases: SeePhases::KEEPAWAY_SH,
            drop_far_ball_velocity: true,
            unnumbered_far_players: false,
        }
    }

    /// Checks every field once.
    pub fn check(&self) -> Result<(), KeepawayParamError> {
        let bad = |name: &'static str, value: String, expected: &'static str| {
            Err(KeepawayParamError { name, value, expected })
        };
        if !(3..=MAX_KEEPERS).contains(&self.keepers) {
            return bad("keepers", self.keepers.to_string(), "3 to 5 (keepaway's state needs three keepers)");
        }
        if !(2..=MAX_TAKERS).contains(&self.takers) {
            return bad("takers", self.takers.to_string(), "2 to 4 (keepaway's state needs two takers)");
        }
        for (name, v) in [("length", self.length), ("width", self.width), ("pass_end_speed", self.pass_end_speed)] {
            if !(v.is_finite() && v > 0.0) {
                return bad(name, v.to_string(), "a finite number > 0");
            }
        }
        if !(self.start_inset >= 0.0 && 2.0 * self.start_inset < self.length.min(self.width)) {
            return bad("start_inset", self.start_inset.to_string(), "at least 0 and under half the region");
        }
        if !(self.ball_inset >= 0.0 && 2.0 * self.ball_inset < self.length.min(self.width)) {
            return bad("ball_inset", self.ball_inset.to_string(), "at least 0 and under half the region");
        }
        if self.turnover_cycles == 0 {
            return bad("turnover_cycles", "0".into(), "at least 1");
        }
        for (name, v) in [("keeper_hold_ratio", self.keeper_hold_ratio), ("taker_hold_ratio", self.taker_hold_ratio)] {
            if !(0.0..=1.0).contains(&v) {
                return bad(name, v.to_string(), "a fraction in [0, 1]");
            }
        }
        let s = &self.server;
        for (name, v) in [
            ("ball_decay", s.ball_decay),
            ("player_decay", s.player_decay),
            ("ball_rand", s.ball_rand),
            ("player_rand", s.player_rand),
        ] {
            if !(0.0..1.0).contains(&v) {
                return bad(name, v.to_string(), "a number in [0, 1)");
            }
        }
        for (name, v) in [
            ("ball_size", s.ball_size),
            ("player_size", s.player_size),
            ("ball_speed_max", s.ball_speed_max),
            ("ball_accel_max", s.ball_accel_max),
            ("player_speed_max", s.player_speed_max),
            ("player_accel_max", s.player_accel_max),
            ("dash_power_rate", s.dash_power_rate),
            ("kick_power_rate", s.kick_power_rate),
            ("kickable_margin", s.kickable_margin),
            ("max_power", s.max_power),
            ("max_moment", s.max_moment),
        ] {
            if !(v.is_finite() && v > 0.0) {
                return bad(name, v.to_string(), "a finite number > 0");
            }
        }
        if !(s.inertia_moment.is_finite() && s.inertia_moment >= 0.0) {
            return bad("inertia_moment", s.inertia_moment.to_string(), "a finite number ≥ 0");
        }
        Ok(())
    }

    /// The region.
    pub fn region(&self) -> Region {
        Region { length: self.length, width: self.width }
    }

    /// The number of state variables of this configuration.
    pub fn state_len(&self) -> usize {
        state_len(self.keepers, self.takers)
    }
}

/// Why an episode ended.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
pub enum EndCause {
    /// The ball left the region (the referee's "o").
    Out,
    /// The takers kept the ball for the turnover time ("t").
    Taken,
}

/// What [`Keepaway::run`] stopped for.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Status {
    /// Keeper `k` has the ball and must choose a macro-action.
    Decision(usize),
    /// The episode is over.
    Ended(EndCause),
}

/// Where everything was at the start of a cycle.
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct Snapshot {
    /// The cycle (from the episode's start).
    pub cycle: u32,
    /// The ball's position.
    pub ball: Vec2,
    /// The ball's velocity.
    pub ball_vel: Vec2,
    /// The keepers' positions, by keeper number (the first `keepers`).
    pub keepers: [Vec2; MAX_KEEPERS],
    /// The takers' positions (the first `takers`).
    pub takers: [Vec2; MAX_TAKERS],
}

/// Kicks of one episode, counted as the oracle counts them from the
/// server's log of received commands (`analyze.py`).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
pub struct KickTally {
    /// Kick commands sent by keepers.
    pub keeper_kicks: u32,
    /// Of those, with power at least 50.
    pub strong_keeper_kicks: u32,
    /// Kick commands sent by takers.
    pub taker_kicks: u32,
    /// Keeper kicks whose previous kick (no taker kick between) was another
    /// keeper's: completed possession transfers.
    pub passes: u32,
    /// The last kicker: `Some(true)` a keeper, `Some(false)` a taker.
    pub last_by_keeper: Option<bool>,
    /// Whether the last kick had power at least 50.
    pub last_strong: bool,
    /// The cycle of the last keeper kick with power at least 50 (a pass or
    /// a clearing kick), `None` once a taker has kicked since: an episode
    /// that ends within a few cycles of it was lost to that kick.
    pub last_strong_keeper_kick: Option<u32>,
    /// The keeper that kicked last, if the last kick was a keeper's.
    last_keeper: Option<u8>,
    /// The cycle of the last kick command and the teams that sent one in it
    /// (bit 0 the keepers, bit 1 the takers).
    last_kick_cycle: Option<(u32, u8)>,
}

impl KickTally {
    /// Whether both teams sent a kick command in the last cycle in which
    /// anyone did. The team counted as kicking last is then the one whose
    /// command the server received last (the oracle's analysis reads the
    /// server's log in that order), a matter of the players' processes,
    /// not of play; the validation reports these endings on their own.
    pub fn both_teams_in_last_kick_cycle(&self) -> bool {
        self.last_kick_cycle.is_some_and(|(_, teams)| teams == 0b11)
    }

    /// Whether an episode that ended at `end` (its duration in cycles) was
    /// lost within `cycles` cycles of a strong keeper kick with no taker
    /// kick since (a pass that rolled out or was taken).
    pub fn lost_after_strong_kick(&self, end: u32, cycles: u32) -> bool {
        self.last_by_keeper == Some(true) && self.last_strong_keeper_kick.is_some_and(|c| end <= c + cycles)
    }
}

/// The last snapshots of the episode, for observers who react with a delay.
#[derive(Clone, Debug)]
struct History {
    ring: Vec<Snapshot>,
    len: usize,
    next: usize,
}

impl History {
    fn new(capacity: usize) -> History {
        History { ring: vec![Snapshot::default(); capacity.max(1)], len: 0, next: 0 }
    }

    fn clear(&mut self) {
        self.len = 0;
        self.next = 0;
    }

    fn push(&mut self, s: Snapshot) {
        let cap = self.ring.len();
        self.ring[self.next] = s;
        self.next = (self.next + 1) % cap;
        self.len = (self.len + 1).min(cap);
    }

    /// The snapshot `ago` cycles back (0: the latest), the oldest kept if fewer.
    fn ago(&self, ago: usize) -> Option<&Snapshot> {
        if self.len == 0 {
            return None;
        }
        let cap = self.ring.len();
        let back = ago.min(self.len - 1);
        Some(&self.ring[(self.next + cap - 1 - back) % cap])
    }
}

/// A Keepaway game (see the module docs).
#[derive(Clone, Debug)]
pub struct Keepaway {
    params: KeepawayParams,
    region: Region,
    grid: GetOpenGrid,
    kin: Kinematics,
    ball: Ball,
    /// The keepers (the first `params.keepers`) then the takers.
    bodies: [Body; MAX_PLAYERS],
    memory: [InterceptMemory; MAX_PLAYERS],
    cycle: u32,
    take_time: u32,
    last_action: [Option<KeeperAction>; MAX_KEEPERS],
    last_action_cycle: [Option<u32>; MAX_KEEPERS],
    /// This cycle's actions of the keepers with the ball (`None`: not yet chosen or not holding).
    chosen: [Option<KeeperAction>; MAX_KEEPERS],
    holding: [bool; MAX_KEEPERS],
    pending: Option<usize>,
    ended: Option<EndCause>,
    started: bool,
    /// Each player's belief of the ball ([`super::vision`]), and the cycle they are for.
    beliefs: [BallBelief; MAX_PLAYERS],
    perceived: Option<u32>,
    /// Cycles since the game began (the server's clock, which the see messages follow).
    clock: u64,
    /// Each player's see phase: it sees in cycles `c` of the clock with `(c + phase) mod 3 < 2`
    /// (a see every 150 ms of 100 ms cycles).
    phase: [u8; MAX_PLAYERS],
    /// The acceleration each player's kick of last cycle gave the ball as
    /// the player computed it from its own belief (`None`: it sent no kick,
    /// or believed the ball beyond its reach), for its own prediction.
    own_kick: [Option<Vec2>; MAX_PLAYERS],
    /// The ball message each player said last cycle (`None`: none), heard this cycle.
    said: [Option<BallMessage>; MAX_PLAYERS],
    /// Each player's own motion of last cycle as it predicted it from its
    /// command (`None` at an episode's start), against which its sense
    /// message shows a collision ([`super::vision::senses_collision`]).
    own_motion: [Option<OwnMotion>; MAX_PLAYERS],
    /// The clock of each player's last look at the ball this episode.
    last_seen: [Option<u64>; MAX_PLAYERS],
    started_phases: bool,
    /// Each player's view of every player (keepers then takers; its own
    /// body exact): what its last see showed, carried on between looks
    /// (`updateDynamicObjectForNextCycle`, see [`Keepaway::perceive`]).
    views: [[Body; MAX_PLAYERS]; MAX_PLAYERS],
    history: Option<History>,
    trace: Option<Vec<Snapshot>>,
    beliefs_log: Option<Vec<BeliefRecord>>,
    tally: KickTally,
    kick_log: Option<Vec<KickEvent>>,
}

/// What one player believed of the ball in one cycle, after its sense, see
/// and hear updates and before it chose its command (see
/// [`Keepaway::record_beliefs`]): for comparing with the true ball (the
/// trace) and with the real players' world-model logs.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct BeliefRecord {
    /// The cycle (from the episode's start).
    pub cycle: u32,
    /// The player: keepers first, then takers.
    pub player: u8,
    /// Where it believed the ball.
    pub pos: Vec2,
    /// The ball's velocity as it believed it.
    pub vel: Vec2,
    /// Whether it saw the ball this cycle.
    pub saw: bool,
    /// Whether it sensed a collision with the ball this cycle (and moved its belief).
    pub collided: bool,
    /// Whether it took a teammate's ball message this cycle.
    pub heard: bool,
}

/// One kick command, as the server's text log records it.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct KickEvent {
    /// The cycle (from the episode's start).
    pub cycle: u32,
    /// The kicker: keepers first, then takers.
    pub player: u8,
    /// The power sent.
    pub power: f64,
}

impl Keepaway {
    /// A game with checked parameters (call [`Keepaway::reset`] before running).
    pub fn new(params: KeepawayParams) -> Result<Keepaway, KeepawayParamError> {
        params.check()?;
        let region = params.region();
        Ok(Keepaway {
            grid: GetOpenGrid::new(&region),
            kin: Kinematics::new(&params.server),
            region,
            params,
            ball: Ball::default(),
            bodies: [Body::default(); MAX_PLAYERS],
            memory: [InterceptMemory::default(); MAX_PLAYERS],
            cycle: 0,
            take_time: 0,
            last_action: [None; MAX_KEEPERS],
            last_action_cycle: [None; MAX_KEEPERS],
            chosen: [None; MAX_KEEPERS],
            holding: [false; MAX_KEEPERS],
            pending: None,
            ended: Some(EndCause::Out),
            started: false,
            beliefs: [BallBelief::default(); MAX_PLAYERS],
            perceived: None,
            clock: 0,
            phase: [0; MAX_PLAYERS],
            own_kick: [None; MAX_PLAYERS],
            said: [None; MAX_PLAYERS],
            own_motion: [None; MAX_PLAYERS],
            last_seen: [None; MAX_PLAYERS],
            started_phases: false,
            views: [[Body::default(); MAX_PLAYERS]; MAX_PLAYERS],
            history: None,
            trace: None,
            beliefs_log: None,
            tally: KickTally::default(),
            kick_log: None,
        })
    }

    /// The benchmark game ([`KeepawayParams::benchmark`]).
    pub fn benchmark() -> Keepaway {
        Keepaway::new(KeepawayParams::benchmark()).expect("the benchmark parameters are valid")
    }

    /// Keeps the last `capacity` snapshots of every episode (for observers with a reaction delay).
    pub fn keep_history(&mut self, capacity: usize) {
        self.history = Some(History::new(capacity));
    }

    /// Records every cycle of the episodes from the next reset on (for pictures); `false` stops.
    pub fn record_trace(&mut self, on: bool) {
        self.trace = on.then(Vec::new);
    }

    /// Logs every player's belief of the ball every cycle of the episodes
    /// from the next reset on ([`BeliefRecord`]); `false` stops.
    pub fn record_beliefs(&mut self, on: bool) {
        self.beliefs_log = on.then(Vec::new);
    }

    /// This episode's belief records (empty unless recording).
    pub fn beliefs(&self) -> &[BeliefRecord] {
        self.beliefs_log.as_deref().unwrap_or(&[])
    }

    /// Logs every kick command of the episodes from the next reset on; `false` stops.
    pub fn record_kicks(&mut self, on: bool) {
        self.kick_log = on.then(Vec::new);
    }

    /// This episode's kick commands (empty unless logging).
    pub fn kicks(&self) -> &[KickEvent] {
        self.kick_log.as_deref().unwrap_or(&[])
    }

    /// The recorded cycles of the current episode (empty unless recording).
    pub fn trace(&self) -> &[Snapshot] {
        self.trace.as_deref().unwrap_or(&[])
    }

    /// The parameters.
    pub fn params(&self) -> &KeepawayParams {
        &self.params
    }

    /// Cycles since the episode started.
    pub fn cycle(&self) -> u32 {
        self.cycle
    }

    /// The ball.
    pub fn ball(&self) -> &Ball {
        &self.ball
    }

    /// The keepers, by number.
    pub fn keepers(&self) -> &[Body] {
        &self.bodies[..self.params.keepers]
    }

    /// The takers.
    pub fn takers(&self) -> &[Body] {
        &self.bodies[self.params.keepers..self.params.keepers + self.params.takers]
    }

    /// Why the episode ended, if it has.
    pub fn ended(&self) -> Option<EndCause> {
        self.ended
    }

    /// This episode's kicks so far.
    pub fn tally(&self) -> &KickTally {
        &self.tally
    }

    /// The cycle at which keeper `k` last acted this episode (a decision or
    /// the continuation of a pass), if it has.
    pub fn last_action_cycle(&self, k: usize) -> Option<u32> {
        self.last_action_cycle[k]
    }

    /// Where everything is now.
    pub fn snapshot(&self) -> Snapshot {
        let mut s = Snapshot { cycle: self.cycle, ball: self.ball.pos, ball_vel: self.ball.vel, ..Snapshot::default() };
        for (i, b) in self.keepers().iter().enumerate() {
            s.keepers[i] = b.pos;
        }
        for (i, b) in self.takers().iter().enumerate() {
            s.takers[i] = b.pos;
        }
        s
    }

    /// The snapshot `ago` cycles back in this episode (the episode's first if
    /// it is younger); `None` without [`Keepaway::keep_history`].
    pub fn snapshot_ago(&self, ago: usize) -> Option<&Snapshot> {
        self.history.as_ref().and_then(|h| h.ago(ago))
    }

    /// Where player `i` (keepers first) believes the ball is this cycle, and
    /// its velocity ([`super::vision`]; `None` before its first look this episode).
    pub fn believed_ball(&self, i: usize) -> Option<(Vec2, Vec2)> {
        let b = &self.beliefs[i];
        b.known.then_some((b.pos, b.vel))
    }

    /// The keeper closest to the ball (`PB` of `keeperStateVars`; the first on ties).
    pub fn closest_keeper(&self) -> usize {
        closest(self.keepers(), self.ball.pos).0
    }

    /// The state variables ([`KeepawayParams::state_len`] of them) as the
    /// keepers compute them: from the view of the keeper closest to the ball
    /// (`keeperStateVars`), the region's centre at the origin.
    pub fn state_vars_into(&self, out: &mut [f64]) {
        let pb = self.closest_keeper();
        let (nk, nt) = (self.params.keepers, self.params.takers);
        // The others as keeper `pb` sees them (its own position exact).
        let view = &self.views[pb];
        let mut mates = [Vec2::ZERO; MAX_KEEPERS];
        let mut n = 0;
        for (i, b) in view[..nk].iter().enumerate() {
            if i != pb {
                mates[n] = b.pos;
                n += 1;
            }
        }
        let mut takers = [Vec2::ZERO; MAX_TAKERS];
        for (i, b) in view[nk..nk + nt].iter().enumerate() {
            takers[i] = b.pos;
        }
        state_vars_general(self.bodies[pb].pos, &mates[..n], &takers[..nt], Vec2::ZERO, out);
    }

    /// The 13 state variables of 3 vs 2 (see [`Keepaway::state_vars_into`]);
    /// `k`, the keeper deciding, is the closest to the ball but for rare ties.
    pub fn state_vars(&self, _k: usize, out: &mut [f64; STATE_VARS]) {
        debug_assert_eq!(self.params.state_len(), STATE_VARS, "the 13 variables are 3 vs 2's");
        self.state_vars_into(out);
    }

    /// The keeper number an action of keeper `k` passes to: the `i`-th
    /// nearest teammate now (`None` for Hold or beyond the teammates).
    pub fn pass_receiver(&self, k: usize, action: KeeperAction) -> Option<usize> {
        if !action.is_pass() || action.index() >= self.params.keepers {
            return None;
        }
        // As keeper `k` sees its teammates.
        let view = &self.views[k];
        let positions: [Vec2; MAX_KEEPERS] =
            std::array::from_fn(|i| if i < self.params.keepers { view[i].pos } else { Vec2::ZERO });
        let mut idx = [0usize; MAX_KEEPERS];
        let mut n = 0;
        for i in 0..self.params.keepers {
            if i != k {
                idx[n] = i;
                n += 1;
            }
        }
        sort_indices_by_distance(view[k].pos, &positions, &mut idx[..n]);
        Some(idx[action.index() - 1])
    }

    /// Starts an episode: the referee's placement (see the module docs).
    pub fn reset<R: Rng + ?Sized>(&mut self, rng: &mut R) {
        let (hl, hw, inset) = (0.5 * self.params.length, 0.5 * self.params.width, self.params.start_inset);
        let (nk, nt) = (self.params.keepers, self.params.takers);
        let mut corner = below(rng, nk);
        for p in 0..nk {
            let pos = match corner {
                0 => Vec2::new(-hl + inset * uniform01(rng), -hw + inset * uniform01(rng)),
                1 => Vec2::new(hl - inset * uniform01(rng), -hw + inset * uniform01(rng)),
                2 => Vec2::new(hl - inset * uniform01(rng), hw - inset * uniform01(rng)),
                _ => Vec2::new(2.0 * uniform01(rng) - 1.0, 2.0 * uniform01(rng) - 1.0),
            };
            self.place(p, pos, rng);
            corner = (corner + 1) % nk;
        }
        for t in 0..nt {
            let pos = Vec2::new(-hl + inset * uniform01(rng), hw - inset * uniform01(rng));
            self.place(nk + t, pos, rng);
        }
        self.ball =
            Ball { pos: Vec2::new(-hl + self.params.ball_inset, -hw + self.params.ball_inset), ..Ball::default() };
        self.cycle = 0;
        self.take_time = 0;
        self.last_action = [None; MAX_KEEPERS];
        self.last_action_cycle = [None; MAX_KEEPERS];
        self.chosen = [None; MAX_KEEPERS];
        self.holding = [false; MAX_KEEPERS];
        for m in &mut self.memory {
            m.clear();
        }
        self.pending = None;
        self.ended = None;
        self.started = true;
        if !self.started_phases {
            self.phase = self.params.see_phases.draw(nk, rng);
            self.started_phases = true;
        }
        self.beliefs = [BallBelief::default(); MAX_PLAYERS];
        self.perceived = None;
        self.own_kick = [None; MAX_PLAYERS];
        self.said = [None; MAX_PLAYERS];
        self.own_motion = [None; MAX_PLAYERS];
        self.last_seen = [None; MAX_PLAYERS];
        self.tally = KickTally::default();
        if let Some(h) = &mut self.history {
            h.clear();
        }
        if let Some(t) = &mut self.trace {
            t.clear();
        }
        if let Some(k) = &mut self.kick_log {
            k.clear();
        }
        if let Some(b) = &mut self.beliefs_log {
            b.clear();
        }
        self.record();
    }

    /// Places player `i` at rest at `pos`, its body direction kept from the
    /// episode before (drawn uniformly the first time: one draw then).
    fn place<R: Rng + ?Sized>(&mut self, i: usize, pos: Vec2, rng: &mut R) {
        let angle =
            if self.started { self.bodies[i].angle } else { std::f64::consts::PI * (2.0 * uniform01(rng) - 1.0) };
        self.bodies[i] = Body::at(pos, angle);
    }

    /// The players see the ball (once per cycle: each player that gets a
    /// see message updates its belief, the others predict it,
    /// [`super::vision`]), and the keepers who believe the ball kickable are
    /// marked as holding it (the players' strict test).
    fn perceive<R: Rng + ?Sized>(&mut self, rng: &mut R) {
        if self.perceived == Some(self.cycle) {
            return;
        }
        self.perceived = Some(self.cycle);
        let (nk, nt) = (self.params.keepers, self.params.takers);
        self.perceive_players(nk, nt, rng);
        let ka = self.kin.ka();
        let p = &self.kin.p;
        let ball = self.ball;
        let mut collided = [false; MAX_PLAYERS];
        for i in 0..nk + nt {
            let team = usize::from(i >= nk);
            let (olo, ohi) = if team == 0 { (nk, nk + nt) } else { (0, nk) };
            let sees = self.sees(i);
            let belief = &mut self.beliefs[i];
            // The sense message's update comes first every cycle, then the see's.
            if belief.known {
                let predicted = belief.pos + belief.vel;
                // The opponent closest to the believed ball has it at its feet?
                let opponents = &self.views[i][olo..ohi];
                let (c, _) = closest(opponents, belief.pos);
                let at_feet = opponents[c].pos.dist2(predicted) < ka * ka;
                belief.predict(self.own_kick[i], p.ball_speed_max, p.ball_decay, at_feet);
                // Then the sense message's speed: a collision the player
                // senses with the ball nearer than any player moves its
                // belief of the ball (`updateBallForCollision`). Every branch
                // of the test needs the ball within the kick reach + 0.5 m.
                if let Some(own) = self.own_motion[i] {
                    let dist_ball = own.pos.dist(belief.pos);
                    if dist_ball < ka + 0.5 {
                        let sensed = sensed_velocity(&self.bodies[i]);
                        let touch = p.player_size + p.ball_size;
                        if senses_collision(own.vel, sensed, dist_ball, touch, ka) && dist_ball < own.closest_player {
                            belief.collide(own.pos);
                            collided[i] = true;
                        }
                    }
                }
            }
            if sees {
                let with_velocity =
                    !self.params.drop_far_ball_velocity || sends_velocity(self.bodies[i].pos.dist(ball.pos), rng);
                belief.update(&self.bodies[i], &ball, p.ball_rand, &self.views[i][olo..ohi], ka, with_velocity);
                self.last_seen[i] = Some(self.clock);
            }
        }
        // Then what it hears: every player says something every cycle (its
        // own position at least), and the server passes each player one
        // teammate's message of last cycle, drawn uniformly (hear_max =
        // hear_inc = hear_decay = 1; `AudioSenderPlayerv8::Unfocused`).
        let mut heard = [false; MAX_PLAYERS];
        for i in 0..nk + nt {
            let (lo, n) = if i < nk { (0, nk) } else { (nk, nt) };
            let j = lo + (below(rng, n - 1) + i - lo + 1) % n;
            if let Some(msg) = self.said[j] {
                let since = self.last_seen[i].map(|c| self.clock - c);
                heard[i] = self.beliefs[i].hear(&msg, self.bodies[i].pos, since);
            }
        }
        if let Some(log) = &mut self.beliefs_log {
            for (i, b) in self.beliefs[..nk + nt].iter().enumerate() {
                if b.known {
                    let saw = self.last_seen[i] == Some(self.clock);
                    log.push(BeliefRecord {
                        cycle: self.cycle,
                        player: i as u8,
                        pos: b.pos,
                        vel: b.vel,
                        saw,
                        collided: collided[i],
                        heard: heard[i],
                    });
                }
            }
        }
        for k in 0..nk {
            let b = &self.beliefs[k];
            self.holding[k] = b.known && self.bodies[k].pos.dist2(b.pos) < ka * ka;
        }
    }

    /// Every player's view of the others this cycle: a player with a see
    /// message sees each other player quantised ([`super::vision::seen_player`]); one
    /// without carries its view on as Trilearn's
    /// `updateDynamicObjectForNextCycle` does: a teammate rolls on with its
    /// seen velocity (decayed), except teammate number 1, which stays; the
    /// opponent closest to the ball (the real players take the fastest) moves
    /// 0.3 m towards the believed ball; the other opponents move 0.25 m (0.5
    /// when the ball is faster than 1 m/cycle along x) in the direction of the
    /// ball's x velocity, their velocities decayed. Its own body it knows.
    /// Called at the start of [`Keepaway::perceive`], before the ball is
    /// updated (the players are carried on with last cycle's ball belief).
    fn perceive_players<R: Rng + ?Sized>(&mut self, nk: usize, nt: usize, rng: &mut R) {
        let p = &self.kin.p;
        let unnumbered = self.params.unnumbered_far_players;
        let n = nk + nt;
        // At an episode's first cycle (the referee's placement) every
        // player is taken to have seen the others.
        let sees: [bool; MAX_PLAYERS] =
            std::array::from_fn(|i| i < n && (self.cycle == 0 || (self.clock + u64::from(self.phase[i])) % 3 < 2));
        // What every look shares, computed once this cycle: each player's
        // heading in whole degrees, and each pair's quantised distance and
        // changes (the same bits from either side, [`PairSight`]).
        let heading: [Heading; MAX_PLAYERS] = std::array::from_fn(|j| Heading::of(&self.bodies[j]));
        for i in 0..n {
            for j in i + 1..n {
                if !(sees[i] || sees[j]) {
                    continue;
                }
                let (a, b) = (&self.bodies[i], &self.bodies[j]);
                let sight = PairSight::new(a.pos, a.vel, b.pos, b.vel);
                if sees[i] {
                    self.views[i][j] = if unnumbered && !sends_velocity(a.pos.dist(b.pos), rng) {
                        seen_unnumbered_player(a, b, sight)
                    } else {
                        seen_player_with(a, b, sight, heading[j], p.player_speed_max)
                    };
                }
                if sees[j] {
                    self.views[j][i] = if unnumbered && !sends_velocity(a.pos.dist(b.pos), rng) {
                        seen_unnumbered_player(b, a, sight)
                    } else {
                        seen_player_with(b, a, sight, heading[i], p.player_speed_max)
                    };
                }
            }
        }
        for i in 0..n {
            let view = &mut self.views[i];
            view[i] = self.bodies[i];
            if sees[i] {
                continue;
            }
            let team = (i >= nk, if i < nk { 0 } else { nk });
            let ball = self.beliefs[i];
            let (olo, ohi) = if team.0 { (0, nk) } else { (nk, nk + nt) };
            let fastest = olo + closest(&view[olo..ohi], ball.pos).0;
            for j in (0..nk + nt).filter(|&j| j != i) {
                let b = &mut view[j];
                if (j >= nk) == team.0 {
                    if j != team.1 {
                        b.pos += b.vel;
                        b.vel = b.vel * p.player_decay;
                    }
                } else {
                    if j == fastest {
                        let to = ball.pos - b.pos;
                        let d = to.norm();
                        if d > 0.0 {
                            b.pos += to * (0.3 / d);
                        }
                    } else {
                        // In the player's own frame (the takers play right to
                        // left, Trilearn mirrors their x).
                        let sign = if team.0 { -1.0 } else { 1.0 };
                        let vx = sign * ball.vel.x;
                        let dx = if vx > 0.0 {
                            if vx > 1.0 { 0.5 } else { 0.25 }
                        } else if vx < -1.0 {
                            -0.5
                        } else {
                            -0.25
                        };
                        b.pos.x += sign * dx;
                    }
                    b.vel = b.vel * p.player_decay;
                }
            }
        }
    }

    /// What player `i` believes its command `sent` does to the ball
    /// (`predictBallInfoAfterCommand`): a kick's acceleration at the kick
    /// power rate of the ball where it believes it, when it believes the
    /// ball within its reach (`updateBallAfterKick`); `None` otherwise.
    fn own_kick_estimate(&self, i: usize, sent: Command) -> Option<Vec2> {
        let Command::Kick { power, dir } = sent else { return None };
        let b = &self.beliefs[i];
        let me = &self.bodies[i];
        let ka = self.kin.ka();
        if !b.known || me.pos.dist2(b.pos) >= ka * ka {
            return None;
        }
        let rate = self.kin.p.actual_kick_power_rate(me.pos, me.dir, b.pos);
        Some(me.dir.rotate(super::geometry::unit_deg(dir as i32)) * (power * rate))
    }

    /// Player `i`'s own motion this cycle as it predicts it from its command
    /// `sent`, before the server runs it ([`OwnMotion`]).
    fn own_motion_estimate(&self, i: usize, sent: Command) -> OwnMotion {
        let p = &self.kin.p;
        let me = &self.bodies[i];
        let n = self.params.keepers + self.params.takers;
        let view = &self.views[i];
        let closest_player = (0..n).filter(|&j| j != i).map(|j| me.pos.dist(view[j].pos)).fold(f64::INFINITY, f64::min);
        let (pos, vel) = match sent {
            Command::Dash { .. } | Command::Turn { .. } => {
                let mut vel = me.vel;
                if let Command::Dash { power } = sent {
                    vel += me.dir * (power * p.dash_power_rate);
                }
                let v = vel.norm();
                if v > p.player_speed_max {
                    vel = vel * (p.player_speed_max / v);
                }
                (me.pos + vel, vel * p.player_decay)
            }
            Command::Kick { .. } | Command::Idle => (me.pos, me.vel),
        };
        OwnMotion { pos, vel, closest_player }
    }

    /// The ball message player `i` says with its command `sent`
    /// (`makeSayMessage`), from its belief: said when it saw the ball this
    /// cycle within 20 m, or it has the ball and its command sends it out of
    /// its reach. With the ball, a kick that sends it more than 0.2 m beyond
    /// its reach is said as where the kick sends it (0 cycles to carry on);
    /// otherwise the ball is said at rest where it is. Without the ball, its
    /// belief is said (1 cycle to carry on).
    fn ball_message(&self, i: usize, sent: Command) -> Option<BallMessage> {
        let b = &self.beliefs[i];
        if !b.known {
            return None;
        }
        let p = &self.kin.p;
        let me = &self.bodies[i];
        let ka = self.kin.ka();
        let mut after = *b;
        after.predict(self.own_kick[i], p.ball_speed_max, p.ball_decay, false);
        let me_next = me.pos + me.vel;
        let near = me.pos.dist(b.pos) < ka;
        let saw = self.last_seen[i] == Some(self.clock);
        if !((saw && me.pos.dist(b.pos) < 20.0) || (near && after.pos.dist(me_next) > ka)) {
            return None;
        }
        Some(if near {
            if matches!(sent, Command::Kick { .. }) && after.pos.dist(me_next) > ka + 0.2 {
                BallMessage { pos: after.pos, vel: after.vel, cycles: 0 }
            } else {
                BallMessage { pos: b.pos, vel: Vec2::ZERO, cycles: 1 }
            }
        } else {
            BallMessage { pos: b.pos, vel: b.vel, cycles: 1 }
        })
    }

    /// Whether player `i` gets a see message this cycle.
    #[inline]
    fn sees(&self, i: usize) -> bool {
        (self.clock + u64::from(self.phase[i])) % 3 < 2
    }

    /// The next keeper with the ball that still has to choose this cycle
    /// (a keeper in the middle of a pass follows through without choosing).
    fn next_decision(&mut self) -> Option<usize> {
        for k in 0..self.params.keepers {
            if !self.holding[k] || self.chosen[k].is_some() {
                continue;
            }
            let continuing = match (self.last_action[k], self.last_action_cycle[k]) {
                (Some(a), Some(c)) => a.is_pass() && c + 1 == self.cycle,
                _ => false,
            };
            if continuing {
                self.chosen[k] = self.last_action[k];
                self.last_action_cycle[k] = Some(self.cycle);
            } else {
                return Some(k);
            }
        }
        None
    }

    /// Simulates cycles until a keeper must choose or the episode ends.
    pub fn run<R: Rng + ?Sized>(&mut self, rng: &mut R) -> Status {
        if let Some(k) = self.pending {
            return Status::Decision(k);
        }
        loop {
            if let Some(cause) = self.ended {
                return Status::Ended(cause);
            }
            self.perceive(rng);
            if let Some(k) = self.next_decision() {
                self.pending = Some(k);
                return Status::Decision(k);
            }
            self.step_cycle(rng);
        }
    }

    /// The keeper awaiting a decision, if any.
    pub fn pending(&self) -> Option<usize> {
        self.pending
    }

    /// Records the pending keeper's choice, then runs on (see [`Keepaway::run`]).
    ///
    /// Panics if no keeper is waiting for a decision (a driver bug).
    pub fn act<R: Rng + ?Sized>(&mut self, action: KeeperAction, rng: &mut R) -> Status {
        let k = self.pending.take().expect("act() needs a keeper waiting for a decision; call run() first");
        self.last_action[k] = Some(action);
        self.last_action_cycle[k] = Some(self.cycle);
        self.chosen[k] = Some(action);
        self.run(rng)
    }

    /// One cycle: every player's command, the physics, the collisions, the referee.
    fn step_cycle<R: Rng + ?Sized>(&mut self, rng: &mut R) {
        let (nk, nt) = (self.params.keepers, self.params.takers);
        let mut commands = [Command::Idle; MAX_PLAYERS];
        for i in 0..nk {
            commands[i] = self.keeper_command(i);
        }
        for t in 0..nt {
            commands[nk + t] = self.taker_command(t);
        }
        // The server executes the commands in the order they arrive, which in
        // synch mode is no team's first: rotating the order each cycle keeps
        // the kicks' sum (order-free) and gives no team the "last kick" of a
        // cycle in which both kicked (the oracle's tally counts by arrival).
        let n = nk + nt;
        let first = self.cycle as usize % n;
        for j in 0..n {
            let i = (first + j) % n;
            let cmd = &commands[i];
            let sent = cmd.as_sent(&self.kin.p);
            if let Command::Kick { power, .. } = sent {
                self.count_kick(i, power);
            }
            self.own_kick[i] = self.own_kick_estimate(i, sent);
            self.said[i] = self.ball_message(i, sent);
            self.own_motion[i] = Some(self.own_motion_estimate(i, sent));
            execute(&self.kin.p, &mut self.bodies[i], &mut self.ball, sent, rng);
        }
        let p = &self.kin.p;
        advance_ball(p, &mut self.ball, rng);
        for b in &mut self.bodies[..nk + nt] {
            advance_player(p, b, rng);
        }
        collisions(p, &mut self.ball, &mut self.bodies[..nk + nt], rng);
        self.cycle += 1;
        self.clock += 1;
        self.chosen = [None; MAX_KEEPERS];
        self.referee();
        self.record();
    }

    /// Keeper `i`'s command this cycle, from its belief of the ball: its
    /// macro-action when it has the ball, the interception when it believes
    /// itself fastest to it, else GetOpen from where the fastest will get it;
    /// nothing before it has seen the ball this episode.
    fn keeper_command(&mut self, i: usize) -> Command {
        let (nk, nt) = (self.params.keepers, self.params.takers);
        let k = &self.kin;
        let belief = self.beliefs[i];
        if !belief.known {
            return Command::Idle;
        }
        let ball = belief.ball();
        let view = &self.views[i];
        let keepers = &view[..nk];
        let takers = &view[nk..nk + nt];
        let me = &self.bodies[i];
        if let Some(action) = self.chosen[i] {
            let (ct, ct_dist) = closest(takers, ball.pos);
            if action.is_pass()
                && let Some(to) = self.pass_receiver(i, action)
            {
                return kick_to(k, me, &ball, view[to].pos, self.params.pass_end_speed, ct_dist);
            }
            // The holder knows the taker's body direction as its last see
            // gave it (whole degrees; a cycle old when it saw nothing now).
            return hold_ball(k, me, &ball, Some(&takers[ct]), self.params.keeper_hold_ratio, KEEPER_GOAL);
        }
        let forecast = BallForecast::new(&k.p, &ball);
        let ka = k.ka();
        let (fastest, when) = match keepers.iter().position(|b| b.pos.dist2(ball.pos) < ka * ka) {
            Some(_) => (closest(keepers, ball.pos).0, 0),
            None => fastest_to_ball(k, keepers, &forecast),
        };
        if fastest == i {
            let opp_dist = closest(takers, me.pos).1;
            return Interceptor { k, ball: &forecast, forward: KEEPER_FORWARD, opp_dist, cycle: self.cycle }
                .intercept(me, &mut self.memory[i]);
        }
        let mut players = [Vec2::ZERO; MAX_PLAYERS];
        for (j, b) in view[..nk + nt].iter().enumerate() {
            players[j] = b.pos;
        }
        // GetOpen's congestion from this keeper's view of the others.
        let point = Congestion::best_point_for(
            &self.grid,
            &players[..nk + nt],
            forecast.after(when),
            &players[nk..nk + nt],
            i,
            Vec2::ZERO,
        );
        get_open(&self.kin, me, ball.pos, point)
    }

    /// Taker `t`'s command this cycle, from its belief of the ball.
    fn taker_command(&mut self, t: usize) -> Command {
        let (nk, nt) = (self.params.keepers, self.params.takers);
        let belief = self.beliefs[nk + t];
        if !belief.known {
            return Command::Idle;
        }
        let k = &self.kin;
        let ball = belief.ball();
        let forecast = BallForecast::new(&k.p, &ball);
        let seen = &self.views[nk + t];
        let keepers = &seen[..nk];
        let view = TakerView {
            k,
            takers: &seen[nk..nk + nt],
            keepers,
            ball: &forecast,
            moving: &forecast,
            ball_now: &ball,
            fastest_keeper: if nt > 2 { fastest_to_ball(k, keepers, &forecast).0 } else { 0 },
            cycle: self.cycle,
        };
        view.command(t, self.params.taker_hold_ratio, &mut self.memory[nk + t])
    }

    /// Counts a kick command of player `i` (keepers first) with `power`.
    fn count_kick(&mut self, i: usize, power: f64) {
        if let Some(log) = &mut self.kick_log {
            log.push(KickEvent { cycle: self.cycle, player: i as u8, power });
        }
        let t = &mut self.tally;
        let team = if i < self.params.keepers { 0b01 } else { 0b10 };
        t.last_kick_cycle = Some(match t.last_kick_cycle {
            Some((c, teams)) if c == self.cycle => (c, teams | team),
            _ => (self.cycle, team),
        });
        if i < self.params.keepers {
            t.keeper_kicks += 1;
            if power >= 50.0 {
                t.strong_keeper_kicks += 1;
            }
            if t.last_keeper.is_some_and(|l| usize::from(l) != i) && t.last_by_keeper == Some(true) {
                t.passes += 1;
            }
            t.last_by_keeper = Some(true);
            t.last_keeper = Some(i as u8);
            t.last_strong = power >= 50.0;
            if power >= 50.0 {
                t.last_strong_keeper_kick = Some(self.cycle);
            }
        } else {
            t.taker_kicks += 1;
            t.last_by_keeper = Some(false);
            t.last_keeper = None;
            t.last_strong_keeper_kick = None;
            t.last_strong = power >= 50.0;
        }
    }

    /// Appends the current positions to the history and the trace, if kept.
    fn record(&mut self) {
        if self.history.is_none() && self.trace.is_none() {
            return;
        }
        let s = self.snapshot();
        if let Some(h) = &mut self.history {
            h.push(s);
        }
        if let Some(t) = &mut self.trace {
            t.push(s);
        }
    }

    /// The referee's analysis after a cycle (`KeepawayRef::analyse`).
    fn referee(&mut self) {
        if !self.region.contains(self.ball.pos) {
            self.ended = Some(EndCause::Out);
            return;
        }
        if self.take_time >= self.params.turnover_cycles {
            self.ended = Some(EndCause::Taken);
            return;
        }
        let ka = self.kin.ka();
        let ka2 = ka * ka;
        if self.takers().iter().any(|t| t.pos.dist2(self.ball.pos) < ka2) {
            self.take_time += 1;
        } else if self.keepers().iter().any(|k| k.pos.dist2(self.ball.pos) < ka2) {
            self.take_time = 0;
        }
    }

    /// Plays one whole episode with `choose` deciding for each keeper with
    /// the ball; returns its duration in cycles and how it ended.
    pub fn play_episode<R: Rng + ?Sized>(
        &mut self,
        rng: &mut R,
        mut choose: impl FnMut(&Keepaway, usize, &mut R) -> KeeperAction,
    ) -> (u32, EndCause) {
        self.reset(rng);
        let mut status = self.run(rng);
        loop {
            match status {
                Status::Decision(k) => {
                    let a = choose(self, k, rng);
                    status = self.act(a, rng);
                }
                Status::Ended(cause) => return (self.cycle, cause),
            }
        }
    }
}

/// Scratch space for a configuration's state variables (no allocation per decision).
pub type StateBuffer = [f64; MAX_STATE_VARS];

/// The two keeper numbers other than `k` in 3 vs 2, in increasing order.
#[inline]
pub fn other_two(k: usize) -> (usize, usize) {
    match k {
        0 => (1, 2),
        1 => (0, 2),
        _ => (0, 1),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use rlfd_env::random::seeded;

    fn always(a: KeeperAction) -> impl FnMut(&Keepaway, usize, &mut rlfd_env::random::SimRng) -> KeeperAction {
        move |_, _, _| a
    }

    #[test]
    fn keepaway_sh_gives_each_team_one_see_phase() {
        for seed in 0..30 {
            let mut rng = seeded(seed);
            let p = SeePhases::KEEPAWAY_SH.draw(3, &mut rng);
            assert!(p[..3].iter().all(|&x| x == p[0] && x < 3) && p[3..].iter().all(|&x| x == p[3] && x < 3));
        }
        let p = SeePhases::Teams { keepers: 4, takers: 2 }.draw(4, &mut seeded(0));
        assert_eq!(&p[..5], &[1, 1, 1, 1, 2]);
        // Every phase sees in two cycles of every three.
        let mut game = Keepaway::new(KeepawayParams {
            see_phases: SeePhases::Teams { keepers: 0, takers: 2 },
            ..KeepawayParams::benchmark()
        })
        .expect("valid");
        game.reset(&mut seeded(1));
        for c in 0..9 {
            game.clock = c;
            assert_eq!(game.sees(0), c % 3 != 2);
            assert_eq!(game.sees(3), c % 3 != 0);
        }
    }

    #[test]
    fn placement_follows_the_referee() {
        let mut game = Keepaway::benchmark();
        let mut rng = seeded(11);
        for _ in 0..50 {
            game.reset(&mut rng);
            assert_eq!(game.ball().pos, Vec2::new(-6.0, -6.0));
            let mut corners: Vec<(i8, i8)> = game
                .keepers()
                .iter()
                .map(|k| {
                    assert!(k.pos.x.abs() >= 7.0 && k.pos.y.abs() >= 7.0 && k.pos.x.abs() <= 10.0);
                    (k.pos.x.signum() as i8, k.pos.y.signum() as i8)
                })
                .collect();
            corners.sort();
            assert_eq!(corners, vec![(-1, -1), (1, -1), (1, 1)]);
            for t in game.takers() {
                assert!(t.pos.x <= -7.0 && t.pos.y >= 7.0);
            }
        }
        // 4 vs 3 on 25 m: the fourth keeper starts near the centre.
        let mut big = Keepaway::new(KeepawayParams::configuration(4, 3, 25.0)).unwrap();
        big.reset(&mut rng);
        assert_eq!(big.ball().pos, Vec2::new(-8.5, -8.5));
        assert_eq!(big.keepers().iter().filter(|k| k.pos.norm() < 1.5).count(), 1);
        assert_eq!(big.takers().len(), 3);
    }

    #[test]
    fn episodes_end_and_are_deterministic() {
        let run = |seed| {
            let mut game = Keepaway::benchmark();
            let mut rng = seeded(seed);
            (0..20).map(|_| game.play_episode(&mut rng, always(KeeperAction::HOLD))).collect::<Vec<_>>()
        };
        let a = run(5);
        assert_eq!(a, run(5));
        assert_ne!(a, run(6));
        // Always Hold loses the ball within seconds.
        let mean = a.iter().map(|e| f64::from(e.0)).sum::<f64>() / 20.0;
        assert!(mean > 15.0 && mean < 100.0, "{mean}");
    }

    #[test]
    fn decisions_come_only_with_the_ball_kickable_and_passes_continue() {
        let mut game = Keepaway::benchmark();
        let mut rng = seeded(3);
        let ka = game.params().server.kickable_area();
        let mut decisions = 0;
        for _ in 0..30 {
            game.reset(&mut rng);
            let mut status = game.run(&mut rng);
            while let Status::Decision(k) = status {
                decisions += 1;
                let (seen, _) = game.believed_ball(k).expect("a keeper decides on a ball it has seen");
                assert!(game.keepers()[k].pos.dist(seen) < ka);
                status = game.act(KeeperAction::PASS2, &mut rng);
            }
            assert!(game.cycle() > 0);
        }
        assert!(decisions > 30);
    }

    #[test]
    fn the_turnover_needs_four_cycles_of_taker_control() {
        let mut game = Keepaway::benchmark();
        let mut rng = seeded(8);
        game.reset(&mut rng);
        let nk = game.params().keepers;
        game.ball.pos = game.bodies[nk].pos + Vec2::new(0.5, 0.0);
        for k in 0..nk {
            game.bodies[k].pos = Vec2::new(8.0, 8.0 - k as f64);
        }
        let status = game.run(&mut rng);
        assert_eq!(status, Status::Ended(EndCause::Taken));
        // take_time counts 1..4 over four analyses; the fifth ends the episode.
        assert_eq!(game.cycle(), 5);
    }

    #[test]
    fn larger_configurations_run() {
        for (k, t, side) in [(3, 2, 25.0), (4, 3, 20.0), (4, 3, 25.0)] {
            let mut game = Keepaway::new(KeepawayParams::configuration(k, t, side)).unwrap();
            let mut rng = seeded(9);
            let mut state = [0.0; MAX_STATE_VARS];
            for _ in 0..10 {
                let (d, _) = game.play_episode(&mut rng, |g, _, rng| {
                    g.state_vars_into(&mut state[..g.params().state_len()]);
                    KeeperAction(below(rng, k) as u8)
                });
                assert!(d > 0);
            }
        }
        assert!(KeepawayParams::configuration(6, 2, 20.0).check().is_err());
    }

    proptest::proptest! {
        #![proptest_config(proptest::test_runner::Config::with_cases(24))]
        // Whatever the keepers choose, every decision comes with the ball
        // kickable, the ball stays in the region until the last cycle, and the
        // episode ends with the referee's reason.
        #[test]
        fn any_choices_give_a_well_formed_episode(seed in 0u64..1_000_000, choices in proptest::collection::vec(0usize..3, 1..64)) {
            let mut game = Keepaway::benchmark();
            let mut rng = seeded(seed);
            game.reset(&mut rng);
            let ka = game.params().server.kickable_area();
            let region = game.params().region();
            let mut i = 0;
            let mut status = game.run(&mut rng);
            while let Status::Decision(k) = status {
                let (seen, _) = game.believed_ball(k).expect("seen");
                proptest::prop_assert!(game.keepers()[k].pos.dist(seen) < ka);
                proptest::prop_assert!(region.contains(game.ball().pos));
                status = game.act(KeeperAction::ALL[choices[i % choices.len()]], &mut rng);
                i += 1;
                proptest::prop_assert!(game.cycle() < 100_000);
            }
            let Status::Ended(cause) = status else { unreachable!() };
            proptest::prop_assert_eq!(game.ended(), Some(cause));
            if cause == EndCause::Out {
                proptest::prop_assert!(!region.contains(game.ball().pos));
            }
        }
    }

    #[test]
    fn history_reaches_back_within_the_episode() {
        let mut game = Keepaway::benchmark();
        game.keep_history(16);
        let mut rng = seeded(4);
        game.reset(&mut rng);
        assert_eq!(game.snapshot_ago(0).unwrap().cycle, 0);
        let mut status = game.run(&mut rng);
        for _ in 0..40 {
            if let Status::Decision(_) = status {
                status = game.act(KeeperAction::HOLD, &mut rng);
            }
        }
        let now = game.cycle();
        assert!(now > 10, "{now}");
        assert_eq!(game.snapshot_ago(0).unwrap(), &game.snapshot());
        assert_eq!(game.snapshot_ago(3).unwrap().cycle, now - 3);
    }
}
