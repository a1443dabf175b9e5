//! The table: three hexbugs, the robot's magnet and brush, and the user's
//! hand, advanced in ticks of 0.1 s.
//!
//! What the robot's tools do (section 4.3.2, with our timing): the pickup
//! action lowers the magnet onto the pickup mark (an obstacle there from
//! 2.5 s to 6.5 s of its 9 s) and, at 4.5 s, lifts the bug nearest the mark
//! if that bug is in the pickup zone ("Once a bug was attached to the
//! magnet, the Nao raised its arm and asked the user to remove it
//! manually"); the zone is where the magnet reaches, by the spec's zone
//! decision. The sweep action draws the brush inward along the bottom band
//! of the image (the sweep zone's rows) from the left edge to 10 px into the
//! pickup zone between 1 s and 4 s of its 5 s, pushing every bug it meets
//! ahead of it "toward the pickup location". Waiting moves nothing.
//!
//! The user's hand: placing a bug leaves the hand at that spot for one
//! second, an obstacle bugs bump into. The state the robot sees
//! ([`Table::observe`]) is the pixel of the visible bug nearest the pickup
//! mark, or `(0, 0)` when none is seen.
//!
//! The table allocates nothing per tick.

use rand::Rng;
use rlfd_env::random::uniform01;
use serde::{Deserialize, Serialize};

use super::action::{Action, TICKS_PER_SECOND};
use super::camera::{Camera, Pixel};
use super::hexbug::{Hexbug, HexbugParams};
use super::zones::{PICKUP_MARK, SWEEP_ZONE, Zone, zone_at};

/// Number of bugs: "A red, blue, and green hexbug toy".
pub const NUM_BUGS: usize = 3;

/// The table's constants.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct TableParams {
    /// Table width (in): 25".
    pub width: f64,
    /// Table depth (in): 19".
    pub height: f64,
    pub camera: Camera,
    pub bug: HexbugParams,
    /// Radius of the lowered magnet as an obstacle (in).
    pub magnet_radius: f64,
    /// Radius of the user's hand as an obstacle (in).
    pub hand_radius: f64,
    /// How long the hand stays after placing a bug (ticks).
    pub hand_ticks: u32,
}

impl TableParams {
    /// The thesis's table (25" × 19") with our choices for the sizes it does not give.
    pub const fn thesis() -> TableParams {
        TableParams {
            width: 25.0,
            height: 19.0,
            camera: Camera::thesis(),
            bug: HexbugParams::thesis(),
            magnet_radius: 1.2,
            hand_radius: 1.5,
            hand_ticks: TICKS_PER_SECOND,
        }
    }

    /// A uniformly random spot on the table, a bug's body clear of the walls.
    pub fn random_place<R: Rng + ?Sized>(&self, rng: &mut R) -> (f64, f64) {
        let r = self.bug.body_radius;
        (r + uniform01(rng) * (self.width - 2.0 * r), r + uniform01(rng) * (self.height - 2.0 * r))
    }

    /// The table point of continuous image coordinates.
    pub fn table_point(&self, px: f64, py: f64) -> (f64, f64) {
        self.camera.unproject(px, py)
    }
}

/// Where a bug is.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
pub enum BugPlace {
    /// On the table (on or off).
    OnTable,
    /// Held by the magnet, waiting for the user.
    Lifted,
    /// In the user's hand, off the table.
    InHand,
}

/// What happened during one tick.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct StepEvents {
    /// The magnet lifted this bug.
    pub lifted: Option<usize>,
    /// Bugs the brush pushed this tick.
    pub pushed: u8,
    /// An arm motion ended with this tick.
    pub action_done: bool,
}

#[derive(Clone, Copy, Debug, PartialEq)]
struct Tool {
    action: Action,
    tick: u32,
}

/// The simulated table.
#[derive(Clone, Debug)]
pub struct Table {
    params: TableParams,
    bugs: [Hexbug; NUM_BUGS],
    places: [BugPlace; NUM_BUGS],
    /// The right arm's magnet and the left arm's brush (both may move at once).
    tools: [Option<Tool>; 2],
    hand: Option<((f64, f64), u32)>,
    /// The mark in table inches.
    mark: (f64, f64),
    dt: f64,
}

/// Magnet timing within the 9 s pickup (ticks).
const MAGNET_DOWN: (u32, u32) = (25, 65);
const MAGNET_LIFT: u32 = 45;
/// Brush timing within the 5 s sweep (ticks) and its reach (px).
const BRUSH_MOVE: (u32, u32) = (10, 40);
const BRUSH_END_PX: f64 = 130.0;

impl Table {
    /// "For each test, bugs were randomly put on the table": three bugs at
    /// random spots and headings, switched on.
    pub fn new<R: Rng + ?Sized>(params: TableParams, rng: &mut R) -> Table {
        let mut bugs = [Hexbug::new(0.0, 0.0, 0.0, true); NUM_BUGS];
        for b in &mut bugs {
            let (x, y) = params.random_place(rng);
            *b = Hexbug::new(x, y, 2.0 * std::f64::consts::PI * uniform01(rng), true);
        }
        Table {
            params,
            bugs,
            places: [BugPlace::OnTable; NUM_BUGS],
            tools: [None, None],
            hand: None,
            mark: params.camera.unproject(PICKUP_MARK.0, PICKUP_MARK.1),
            dt: 1.0 / f64::from(TICKS_PER_SECOND),
        }
    }

    /// The constants.
    pub fn params(&self) -> &TableParams {
        &self.params
    }

    /// The bugs.
    pub fn bugs(&self) -> &[Hexbug; NUM_BUGS] {
        &self.bugs
    }

    /// Where each bug is.
    pub fn places(&self) -> &[BugPlace; NUM_BUGS] {
        &self.places
    }

    /// Whether an arm is moving.
    pub fn arm_busy(&self) -> bool {
        self.tools.iter().any(Option::is_some)
    }

    /// Starts an arm motion (pickup: the right arm, sweep: the left arm;
    /// waiting moves no arm). A motion of the same arm under way is replaced.
    pub fn start_action(&mut self, action: Action) {
        match action {
            Action::Pickup => self.tools[0] = Some(Tool { action, tick: 0 }),
            Action::Sweep => self.tools[1] = Some(Tool { action, tick: 0 }),
            Action::Wait => {}
        }
    }

    /// The bug hanging on the magnet, if any.
    pub fn lifted_bug(&self) -> Option<usize> {
        self.places.iter().position(|&p| p == BugPlace::Lifted)
    }

    /// The user takes bug `i` into the hand (off the table, or off the magnet).
    pub fn remove_to_hand(&mut self, i: usize) {
        self.places[i] = BugPlace::InHand;
    }

    /// The user puts bug `i` down at `(x, y)` (inches), switched on or off;
    /// the hand stays there a moment.
    pub fn place(&mut self, i: usize, (x, y): (f64, f64), on: bool) {
        let r = self.params.bug.body_radius;
        let at = (x.clamp(r, self.params.width - r), y.clamp(r, self.params.height - r));
        let heading = self.bugs[i].heading;
        self.bugs[i] = Hexbug::new(at.0, at.1, heading, on);
        self.places[i] = BugPlace::OnTable;
        self.hand = Some((at, self.params.hand_ticks));
    }

    /// Switches bug `i` on or off where it is.
    pub fn set_on(&mut self, i: usize, on: bool) {
        self.bugs[i].on = on;
    }

    /// The continuous image coordinates of bug `i`, if it is on the table and in view.
    pub fn image_position(&self, i: usize) -> Option<(f64, f64)> {
        if self.places[i] != BugPlace::OnTable {
            return None;
        }
        let b = &self.bugs[i];
        self.params.camera.pixel(b.x, b.y)?;
        Some(self.params.camera.project(b.x, b.y))
    }

    /// The robot's state: the visible bug nearest the pickup mark, `(0, 0)` when none is seen.
    pub fn observe(&self) -> Pixel {
        self.nearest_visible().map_or(Pixel::NONE_SEEN, |i| {
            let b = &self.bugs[i];
            self.params.camera.pixel(b.x, b.y).expect("visible")
        })
    }

    /// The visible bug nearest the mark.
    pub fn nearest_visible(&self) -> Option<usize> {
        let mut best: Option<(f64, usize)> = None;
        for i in 0..NUM_BUGS {
            if let Some((px, py)) = self.image_position(i) {
                let d = (px - PICKUP_MARK.0).powi(2) + (py - PICKUP_MARK.1).powi(2);
                if best.is_none_or(|(bd, _)| d < bd) {
                    best = Some((d, i));
                }
            }
        }
        best.map(|(_, i)| i)
    }

    /// Whether some visible bug is in `zone` (what a perception behaviour detects).
    pub fn zone_occupied(&self, zone: Zone) -> bool {
        (0..NUM_BUGS).any(|i| self.image_position(i).is_some_and(|(x, y)| zone_at(x, y) == zone))
    }

    /// The zone a table point's image position falls in (outside the view: wait).
    pub fn zone_of_point(&self, x: f64, y: f64) -> Zone {
        let (px, py) = self.params.camera.project(x, y);
        zone_at(px, py)
    }

    fn magnet_down(&self) -> bool {
        matches!(self.tools[0], Some(Tool { tick, .. }) if (MAGNET_DOWN.0..MAGNET_DOWN.1).contains(&tick))
    }

    /// The brush's image x while it moves.
    fn brush_px(&self) -> Option<f64> {
        match self.tools[1] {
            Some(Tool { tick, .. }) if (BRUSH_MOVE.0..=BRUSH_MOVE.1).contains(&tick) => {
                Some(BRUSH_END_PX * f64::from(tick - BRUSH_MOVE.0) / f64::from(BRUSH_MOVE.1 - BRUSH_MOVE.0))
            }
            _ => None,
        }
    }

    fn touches(&self, me: usize, tip: (f64, f64), brush: Option<f64>) -> bool {
        let p = &self.params;
        if tip.0 <= 0.0 || tip.1 <= 0.0 || tip.0 >= p.width || tip.1 >= p.height {
            return true;
        }
        let d2 = |a: (f64, f64), b: (f64, f64)| (a.0 - b.0).powi(2) + (a.1 - b.1).powi(2);
        for j in 0..NUM_BUGS {
            if j != me && self.places[j] == BugPlace::OnTable {
                let o = &self.bugs[j];
                if d2(tip, (o.x, o.y)) < (p.bug.body_radius * 2.0).powi(2) {
                    return true;
                }
            }
        }
        if self.magnet_down() && d2(tip, self.mark) < p.magnet_radius.powi(2) {
            return true;
        }
        if let Some((at, _)) = self.hand
            && d2(tip, at) < p.hand_radius.powi(2)
        {
            return true;
        }
        if let Some(bx) = brush {
            let (tx, ty) = p.camera.project(tip.0, tip.1);
            if ty >= f64::from(SWEEP_ZONE.2) && (tx - bx).abs() < 6.0 {
                return true;
            }
        }
        false
    }

    /// Advances one tick: the robot's tool, the bugs, the hand.
    pub fn step<R: Rng + ?Sized>(&mut self, rng: &mut R) -> StepEvents {
        let mut events = StepEvents::default();
        let brush = self.brush_px();
        // The brush pushes every bug in the band behind it to its front.
        if let Some(bx) = brush {
            for i in 0..NUM_BUGS {
                if let Some((px, py)) = self.image_position(i)
                    && py >= f64::from(SWEEP_ZONE.2)
                    && px < bx
                {
                    let (x, _) = self.params.camera.unproject(bx + 1.0, py);
                    self.bugs[i].x = x;
                    if self.bugs[i].on {
                        self.bugs[i].bump(&self.params.bug, self.dt, rng);
                    }
                    events.pushed += 1;
                }
            }
        }
        if let Some(Tool { tick: MAGNET_LIFT, .. }) = self.tools[0]
            && let Some(i) = self.nearest_visible()
            && let Some((px, py)) = self.image_position(i)
            && zone_at(px, py) == Zone::Pickup
        {
            self.places[i] = BugPlace::Lifted;
            events.lifted = Some(i);
        }
        let bounds = (self.params.width, self.params.height);
        for i in 0..NUM_BUGS {
            if self.places[i] != BugPlace::OnTable {
                continue;
            }
            let mut bug = self.bugs[i];
            let p = self.params.bug;
            bug.advance(&p, self.dt, bounds, |tip| self.touches(i, tip, brush), rng);
            self.bugs[i] = bug;
        }
        if let Some((at, left)) = self.hand {
            self.hand = if left <= 1 { None } else { Some((at, left - 1)) };
        }
        for slot in &mut self.tools {
            if let Some(t) = slot {
                t.tick += 1;
                if t.tick >= t.action.duration_ticks() {
                    *slot = None;
                    events.action_done = true;
                }
            }
        }
        events
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::zones::zone_of;
    use rlfd_env::random::seeded;

    fn run(table: &mut Table, ticks: u32, rng: &mut rlfd_env::random::SimRng) -> Vec<StepEvents> {
        (0..ticks).map(|_| table.step(rng)).collect()
    }

    #[test]
    fn state_is_the_bug_nearest_the_mark_or_origin() {
        let mut rng = seeded(3);
        let mut t = Table::new(TableParams::thesis(), &mut rng);
        let p = *t.params();
        for i in 0..NUM_BUGS {
            t.remove_to_hand(i);
        }
        assert_eq!(t.observe(), Pixel::NONE_SEEN);
        // Out of view (the left strip): still no state.
        t.place(0, (0.6, 10.0), false);
        assert_eq!(t.observe(), Pixel::NONE_SEEN);
        t.place(1, p.table_point(170.5, 100.5), false);
        t.place(2, p.table_point(60.5, 220.5), false);
        assert_eq!(t.observe(), Pixel::new(170, 100), "100 px from the mark beats 111 px");
        assert!(t.zone_occupied(Zone::Sweep) && !t.zone_occupied(Zone::Pickup));
    }

    #[test]
    fn pickup_lifts_a_bug_in_the_pickup_zone_only() {
        let mut rng = seeded(4);
        let mut t = Table::new(TableParams::thesis(), &mut rng);
        let p = *t.params();
        for i in 0..NUM_BUGS {
            t.remove_to_hand(i);
        }
        t.place(0, p.table_point(130.5, 170.5), false);
        t.start_action(Action::Pickup);
        let ev = run(&mut t, 90, &mut rng);
        assert_eq!(ev.iter().filter_map(|e| e.lifted).collect::<Vec<_>>(), vec![0]);
        assert!(ev[89].action_done && !t.arm_busy());
        assert_eq!(t.lifted_bug(), Some(0));
        assert_eq!(t.observe(), Pixel::NONE_SEEN, "a lifted bug is not on the table");
        // A bug in the wait zone stays.
        t.remove_to_hand(0);
        t.place(1, p.table_point(250.5, 120.5), false);
        t.start_action(Action::Pickup);
        assert!(run(&mut t, 90, &mut rng).iter().all(|e| e.lifted.is_none()));
    }

    #[test]
    fn sweep_pushes_bugs_toward_the_mark() {
        let mut rng = seeded(5);
        let mut t = Table::new(TableParams::thesis(), &mut rng);
        let p = *t.params();
        for i in 0..NUM_BUGS {
            t.remove_to_hand(i);
        }
        t.place(0, p.table_point(30.5, 210.5), false);
        t.place(1, p.table_point(60.5, 120.5), false);
        assert_eq!(zone_of(t.observe()), Zone::Wait, "the wait-zone bug is nearer the mark");
        t.start_action(Action::Sweep);
        let ev = run(&mut t, 50, &mut rng);
        assert!(ev.iter().map(|e| u32::from(e.pushed)).sum::<u32>() > 0);
        let (x, y) = t.image_position(0).unwrap();
        assert!((125.0..140.0).contains(&x) && (y - 210.5).abs() < 1e-6, "pushed to the brush's end: {x}");
        assert_eq!(zone_at(x, y), Zone::Pickup);
        assert_eq!(t.image_position(1).unwrap().0.round(), 61.0, "outside the band: untouched");
    }

    #[test]
    fn bugs_keep_moving_and_stay_on_the_table() {
        let mut rng = seeded(6);
        let mut t = Table::new(TableParams::thesis(), &mut rng);
        let start: Vec<(f64, f64)> = t.bugs().iter().map(|b| (b.x, b.y)).collect();
        let mut seen = [0u32; 3];
        for _ in 0..6000 {
            t.step(&mut rng);
            seen[crate::zones::zone_of(t.observe()).index()] += 1;
            for b in t.bugs() {
                assert!(b.x > 0.0 && b.x < 25.0 && b.y > 0.0 && b.y < 19.0);
            }
        }
        for (b, s) in t.bugs().iter().zip(&start) {
            assert!((b.x - s.0).abs() + (b.y - s.1).abs() > 0.1);
        }
        // Over ten minutes the nearest bug visits every zone.
        assert!(seen.iter().all(|&n| n > 0), "{seen:?}");
    }

    #[test]
    fn busy_table_is_deterministic() {
        assert_eq!(crate::busy_table_ticks(9, 5000), 5000);
        let a = {
            let mut rng = seeded(10);
            let mut t = Table::new(TableParams::thesis(), &mut rng);
            run(&mut t, 500, &mut rng);
            t.observe()
        };
        let b = {
            let mut rng = seeded(10);
            let mut t = Table::new(TableParams::thesis(), &mut rng);
            run(&mut t, 500, &mut rng);
            t.observe()
        };
        assert_eq!(a, b);
    }
}
