//! The modified Dyna Maze of the thesis's section 6.3.1 (Figure 6.1), in
//! the three layouts of the `maze-layout` reading.
//!
//! The thesis draws its maze but does not list the walls. It says it is "a
//! modified version of the Dyna Maze" (Sutton & Barto, Fig. 8.2: 9 × 6 cells,
//! start in row 2 of column 0, goal in the top-right cell, seven wall cells)
//! and that the optimal path is 2.665 long, i.e. 133 steps of 0.02. The plain
//! Dyna Maze scaled to the unit square needs only 84 steps, so walls were
//! added (the project's decision, `spec/ch6-irl-shaping.md`): keep the Dyna
//! walls, the start and the goal, and add whole cells and thin walls until
//! the shortest 4-connected path is 133 ± 2 steps (tested by breadth-first
//! search in [`super::search`]).
//!
//! **Low detour** ([`LayoutId::LowDetour`], the default, round 1's): four
//! cells and one thin wall; the shortest path needs 134 steps (2.68):
//!
//! ```text
//!   row 0   . . . . . . . # G      # Dyna walls (1,2) (2,2) (3,2) (4,5)
//!   row 1   . . # . . . . # .        (0,7) (1,7) (2,7)
//!   row 2   S . # . . . . # .      + added cells (3,6) (4,2) (4,6) (5,2)
//!   row 3   . . # . . . # . .      + a thin wall: the upper 0.1 of cell (5,6)
//!   row 4   . . # . . # # . .
//!   row 5   . . # . . . ▀ . .      S = (0.08, 0.60), G: x ≥ 0.9 and y ≥ 0.9
//! ```
//!
//! Column 2 reaches the bottom, so the way leads over its top, down the
//! middle to the bottom row and through the narrow gap under column 6 (0.067
//! high) to the goal column.
//!
//! **High detour** ([`LayoutId::HighDetour`], designed before any learner ran
//! on it so that the detour lies in the upper half; see the reading's docs
//! in `readings`): three cells and three thin walls, each 1/15 high, on the
//! bottom edges of rows 0, 1 and 2; the shortest path needs 132 steps (2.64):
//!
//! ```text
//!   row 0   . . . . . . . # G      # Dyna walls, + added cells (3,7) (4,2) (5,2)
//!           . . . ‾ ‾ ‾ . . .      ‾ thin walls: under row 0 in columns 3–5,
//!   row 1   . . # . . . . # .        under row 1 in columns 4–6,
//!           . . . . ‾ ‾ ‾ . .        under row 2 in columns 3–5
//!   row 2   S . # . . . . # .
//!           . . . ‾ ‾ ‾ . . .
//!   row 3   . . # . . . . # .
//!   row 4   . . # . . # . . .
//!   row 5   . . # . . . . . .
//! ```
//!
//! The way leads over column 2, right along the top, down at column 6, left
//! along row 1, down at column 3, right along row 2, down column 6 to row 4
//! (column 7's wall now reaches row 3), right, and up the goal column.
//!
//! **Floor route** ([`LayoutId::FloorRoute`], designed before any learner
//! ran on it, after the high detour's RE-IRL fit turned out to be x alone
//! too; see the reading's docs): six cells; the shortest path needs 134
//! steps (2.68):
//!
//! ```text
//!   row 0   . . # . . . . # G      # Dyna walls, + added cells (0,2) (3,5)
//!   row 1   . . # . . . . # .        (3,7) (4,2) (4,7) (5,5)
//!   row 2   S . # . . . . # .
//!   row 3   . . # . . # . # .
//!   row 4   . . # . . # . # .
//!   row 5   . . . . . # . . .
//! ```
//!
//! The way leads down the start column to the floor, under column 2, up
//! over column 5 (into row 2), down column 6 to the floor, under column 7
//! and up the goal column: the route keeps to the lower half but for the
//! climb over column 5 and the last climb.
//!
//! Cells are `1/9` wide and `1/6` high; rows count from the top as in the
//! Dyna Maze. Walls are stored exactly, in units of 1/900 (the least common
//! multiple of 9, 6 and 100), and rasterised on the 0.01 lattice that every
//! position of the agent (steps of 0.02) and of the demonstrator (recorded at
//! 0.01, see [`super::demonstrator`]) lies on.

use serde::{Deserialize, Serialize};

/// Lattice points per unit length: positions are integers in hundredths.
pub const LATTICE: i32 = 100;

/// A wall rectangle `[x0, x1) × [y0, y1)` in units of 1/900.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct WallRect {
    /// Left edge.
    pub x0: i32,
    /// Right edge (exclusive).
    pub x1: i32,
    /// Bottom edge.
    pub y0: i32,
    /// Top edge (exclusive).
    pub y1: i32,
}

/// Units of 1/900 per unit length.
pub const WALL_UNITS: i32 = 900;

impl WallRect {
    /// The wall filling Dyna cell (`row` from the top, `col`).
    pub const fn cell(row: i32, col: i32) -> Self {
        WallRect { x0: col * 100, x1: (col + 1) * 100, y0: (5 - row) * 150, y1: (6 - row) * 150 }
    }

    /// Whether lattice point `(ix, iy)` (hundredths) lies inside.
    pub fn contains(&self, ix: i32, iy: i32) -> bool {
        let (x, y) = (ix * 9, iy * 9);
        self.x0 <= x && x < self.x1 && self.y0 <= y && y < self.y1
    }

    /// The corners in unit-square coordinates `(x0, y0, x1, y1)`, for drawing.
    pub fn unit_square(&self) -> (f64, f64, f64, f64) {
        let u = f64::from(WALL_UNITS);
        (f64::from(self.x0) / u, f64::from(self.y0) / u, f64::from(self.x1) / u, f64::from(self.y1) / u)
    }
}

/// The seven wall cells of Sutton & Barto's Dyna Maze, (row from top, column).
pub const DYNA_WALL_CELLS: [(i32, i32); 7] = [(1, 2), (2, 2), (3, 2), (4, 5), (0, 7), (1, 7), (2, 7)];

/// The cells the low-detour layout adds.
pub const ADDED_WALL_CELLS: [(i32, i32); 4] = [(3, 6), (4, 2), (4, 6), (5, 2)];

/// The thin wall the low-detour layout adds: the upper 0.1 of cell (5, 6), `y ∈ [1/15, 1/6)`.
pub const ADDED_THIN_WALL: WallRect = WallRect { x0: 600, x1: 700, y0: 60, y1: 150 };

/// The cells the high-detour layout adds: column 2 down to the bottom, column 7 one row lower.
pub const HIGH_DETOUR_CELLS: [(i32, i32); 3] = [(3, 7), (4, 2), (5, 2)];

/// The thin walls the high-detour layout adds, each 1/15 high on the bottom
/// edge of a row: under row 0 in columns 3–5, under row 1 in columns 4–6,
/// under row 2 in columns 3–5.
pub const HIGH_DETOUR_THIN_WALLS: [WallRect; 3] = [
    WallRect { x0: 300, x1: 600, y0: 690, y1: 750 },
    WallRect { x0: 400, x1: 700, y0: 540, y1: 600 },
    WallRect { x0: 300, x1: 600, y0: 390, y1: 450 },
];

/// The cells the floor-route layout adds: column 2 from the top down to row
/// 4, column 5 from row 3 to the floor, column 7 down to row 4.
pub const FLOOR_ROUTE_CELLS: [(i32, i32); 6] = [(0, 2), (3, 5), (3, 7), (4, 2), (4, 7), (5, 5)];

/// Which modified Dyna Maze (the `maze-layout` reading).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash, PartialOrd, Ord, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum LayoutId {
    /// Round 1's: the detour runs along the bottom row (the default).
    #[default]
    LowDetour,
    /// The detour winds under the top edge.
    HighDetour,
    /// The whole route runs in the lower half, along the floor.
    FloorRoute,
}

impl LayoutId {
    /// Every layout, the default first.
    pub const ALL: [LayoutId; 3] = [LayoutId::LowDetour, LayoutId::HighDetour, LayoutId::FloorRoute];

    /// Its name, as the reading's level.
    pub fn name(self) -> &'static str {
        match self {
            LayoutId::LowDetour => "low-detour",
            LayoutId::HighDetour => "high-detour",
            LayoutId::FloorRoute => "floor-route",
        }
    }

    /// The whole cells it adds to the Dyna walls, (row from the top, column).
    pub fn added_cells(self) -> &'static [(i32, i32)] {
        match self {
            LayoutId::LowDetour => &ADDED_WALL_CELLS,
            LayoutId::HighDetour => &HIGH_DETOUR_CELLS,
            LayoutId::FloorRoute => &FLOOR_ROUTE_CELLS,
        }
    }

    /// The thin walls it adds.
    pub fn thin_walls(self) -> &'static [WallRect] {
        match self {
            LayoutId::LowDetour => std::slice::from_ref(&ADDED_THIN_WALL),
            LayoutId::HighDetour => &HIGH_DETOUR_THIN_WALLS,
            LayoutId::FloorRoute => &[],
        }
    }
}

/// The start position in hundredths: (0.08, 0.60).
pub const START: (i32, i32) = (8, 60);

/// The goal region's corner in hundredths: `x ≥ 0.9 && y ≥ 0.9`.
pub const GOAL: (i32, i32) = (90, 90);

/// The maze: its walls and their rasterisation on the 0.01 lattice.
#[derive(Clone, Debug, PartialEq)]
pub struct MazeLayout {
    walls: Vec<WallRect>,
    blocked: Vec<bool>,
}

impl MazeLayout {
    /// The thesis's modified Dyna Maze as this project reconstructs it by
    /// default (the low-detour layout).
    pub fn thesis() -> Self {
        Self::of(LayoutId::LowDetour)
    }

    /// The modified Dyna Maze `id`: the Dyna walls, its added cells, its thin walls.
    pub fn of(id: LayoutId) -> Self {
        let mut walls: Vec<WallRect> =
            DYNA_WALL_CELLS.iter().chain(id.added_cells()).map(|&(r, c)| WallRect::cell(r, c)).collect();
        walls.extend_from_slice(id.thin_walls());
        Self::from_walls(walls)
    }

    /// The unmodified Dyna Maze on the unit square (for comparison in tests and the report).
    pub fn dyna() -> Self {
        Self::from_walls(DYNA_WALL_CELLS.iter().map(|&(r, c)| WallRect::cell(r, c)).collect())
    }

    fn from_walls(walls: Vec<WallRect>) -> Self {
        let n = LATTICE as usize;
        let mut blocked = vec![false; n * n];
        for iy in 0..LATTICE {
            for ix in 0..LATTICE {
                blocked[iy as usize * n + ix as usize] = walls.iter().any(|w| w.contains(ix, iy));
            }
        }
        MazeLayout { walls, blocked }
    }

    /// The wall rectangles.
    pub fn walls(&self) -> &[WallRect] {
        &self.walls
    }

    /// Whether a lattice point is outside the unit square or inside a wall.
    #[inline]
    pub fn is_blocked(&self, ix: i32, iy: i32) -> bool {
        !(0..LATTICE).contains(&ix)
            || !(0..LATTICE).contains(&iy)
            || self.blocked[iy as usize * LATTICE as usize + ix as usize]
    }

    /// Whether a point of the unit square, anywhere, lies inside a wall or
    /// outside the square. A point on the 0.01 lattice (within 10⁻⁹) is
    /// judged as [`Self::is_blocked`] judges its lattice point, so that the
    /// two never disagree; any other point by the wall rectangles themselves.
    pub fn is_blocked_at(&self, x: f64, y: f64) -> bool {
        if !((0.0..1.0).contains(&x) && (0.0..1.0).contains(&y)) {
            return true;
        }
        let lattice = f64::from(LATTICE);
        let (ix, iy) = ((x * lattice).round(), (y * lattice).round());
        let on_lattice = (x * lattice - ix).abs() < 1e-9 && (y * lattice - iy).abs() < 1e-9;
        if on_lattice && ix < lattice && iy < lattice {
            // Whole numbers in 0..100: exact as i32.
            return self.is_blocked(ix as i32, iy as i32);
        }
        let units = f64::from(WALL_UNITS);
        let (ux, uy) = (x * units, y * units);
        self.walls
            .iter()
            .any(|w| f64::from(w.x0) <= ux && ux < f64::from(w.x1) && f64::from(w.y0) <= uy && uy < f64::from(w.y1))
    }

    /// Whether a lattice point is in the goal region.
    #[inline]
    pub fn is_goal(ix: i32, iy: i32) -> bool {
        ix >= GOAL.0 && iy >= GOAL.1
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn start_and_goal_are_free() {
        let m = MazeLayout::thesis();
        assert!(!m.is_blocked(START.0, START.1));
        assert!(!m.is_blocked(95, 95));
        assert!(m.is_blocked(-1, 50) && m.is_blocked(100, 50) && m.is_blocked(50, 100));
    }

    #[test]
    fn cells_map_to_the_dyna_grid() {
        let m = MazeLayout::thesis();
        // Cell (1, 2): x in [2/9, 3/9), y in [4/6, 5/6).
        assert!(m.is_blocked(25, 70));
        assert!(!m.is_blocked(21, 70)); // x = 0.21 < 2/9
        // y = 0.5 lies on a row boundary and belongs to the row above it (row 2 from the top).
        assert!(m.is_blocked(70, 49)); // cell (3, 6)
        assert!(!m.is_blocked(70, 50)); // cell (2, 6) is free
        // The thin wall: y in [1/15, 1/6) in column 6.
        assert!(m.is_blocked(70, 7));
        assert!(!m.is_blocked(70, 6));
    }

    #[test]
    fn the_high_detour_s_thin_walls_lie_under_their_rows() {
        let m = MazeLayout::of(LayoutId::HighDetour);
        assert!(!m.is_blocked(START.0, START.1) && !m.is_blocked(95, 95));
        // Under row 0 (y < 5/6) in columns 3–5, open in column 6.
        assert!(m.is_blocked(40, 80) && m.is_blocked(60, 77) && !m.is_blocked(40, 84) && !m.is_blocked(40, 76));
        assert!(!m.is_blocked(70, 80));
        // Under row 1 in columns 4–6, open in column 3.
        assert!(m.is_blocked(50, 64) && m.is_blocked(75, 60) && !m.is_blocked(40, 64) && !m.is_blocked(50, 59));
        // Under row 2 in columns 3–5, open in column 6.
        assert!(m.is_blocked(40, 45) && !m.is_blocked(40, 42) && !m.is_blocked(70, 45));
        // Column 7 down to row 3, open in row 4; column 2 down to the bottom.
        assert!(m.is_blocked(80, 40) && !m.is_blocked(80, 30) && m.is_blocked(25, 10));
        assert_eq!(LayoutId::ALL.map(LayoutId::name), ["low-detour", "high-detour", "floor-route"]);
        let f = MazeLayout::of(LayoutId::FloorRoute);
        // Column 2 open only on the floor, column 5 only above row 3, column 7 only on the floor.
        assert!(f.is_blocked(25, 95) && f.is_blocked(25, 20) && !f.is_blocked(25, 15));
        assert!(f.is_blocked(60, 5) && f.is_blocked(60, 45) && !f.is_blocked(60, 55));
        assert!(f.is_blocked(80, 20) && !f.is_blocked(80, 15));
        assert_eq!(MazeLayout::of(LayoutId::LowDetour), MazeLayout::thesis());
    }

    #[test]
    fn points_off_the_lattice_are_judged_by_the_walls() {
        let m = MazeLayout::thesis();
        for iy in 0..LATTICE {
            for ix in 0..LATTICE {
                let (x, y) = (f64::from(ix) / 100.0, f64::from(iy) / 100.0);
                assert_eq!(m.is_blocked_at(x, y), m.is_blocked(ix, iy), "({x}, {y})");
            }
        }
        assert!(m.is_blocked_at(0.255, 0.705)); // inside cell (1, 2)
        assert!(!m.is_blocked_at(0.215, 0.705)); // left of it
        assert!(m.is_blocked_at(-0.001, 0.5) && m.is_blocked_at(0.5, 1.0));
        assert!(!m.is_blocked_at(0.999_999, 0.999_999)); // the goal's far corner
        let h = MazeLayout::of(LayoutId::HighDetour);
        for iy in 0..LATTICE {
            for ix in 0..LATTICE {
                let (x, y) = (f64::from(ix) / 100.0, f64::from(iy) / 100.0);
                assert_eq!(h.is_blocked_at(x, y), h.is_blocked(ix, iy), "({x}, {y})");
            }
        }
    }
}
