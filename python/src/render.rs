//! Pictures of a domain's current state as RGB arrays (height × width × 3
//! bytes, row-major), for Gymnasium's `render_mode="rgb_array"`.
//!
//! - Maze: the 0.01 lattice, 4 pixels per hundredth (400 × 400): walls
//!   black, the goal region green, the agent a red square.
//! - Mario: 32 columns × 15 rows of tiles around Mario, 8 pixels per tile
//!   (256 × 120): sky, solid tiles, blocks, coins, tubes; enemies, shells
//!   and power-ups as coloured boxes; Mario red.
//! - Keepaway: the region at 10 pixels per metre with a 2 m margin:
//!   keepers blue, takers red, the ball white.
//!
//! Drawings, not the benchmark's graphics: cheap enough to call every step.
//! Nothing here changes the simulation.

use rlfd_mario::level::{CELL, ROWS, tile};
use rlfd_mario::sprites::SpriteKind;
use rlfd_maze::layout::{GOAL, LATTICE};

use crate::domain::{Domain, Simulator};

/// An RGB picture.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Picture {
    /// Rows.
    pub height: usize,
    /// Columns.
    pub width: usize,
    /// `height * width * 3` bytes.
    pub pixels: Vec<u8>,
}

impl Picture {
    fn new(height: usize, width: usize, background: [u8; 3]) -> Picture {
        let mut pixels = Vec::with_capacity(height * width * 3);
        for _ in 0..height * width {
            pixels.extend_from_slice(&background);
        }
        Picture { height, width, pixels }
    }

    /// Fills the rectangle of rows `r0..r1`, columns `c0..c1` (clipped).
    fn fill(&mut self, r0: i64, r1: i64, c0: i64, c1: i64, colour: [u8; 3]) {
        let (r0, r1) = (r0.max(0) as usize, (r1.max(0) as usize).min(self.height));
        let (c0, c1) = (c0.max(0) as usize, (c1.max(0) as usize).min(self.width));
        for r in r0..r1 {
            for c in c0..c1 {
                let i = (r * self.width + c) * 3;
                self.pixels[i..i + 3].copy_from_slice(&colour);
            }
        }
    }

    /// The colour at row `r`, column `c`.
    pub fn at(&self, r: usize, c: usize) -> [u8; 3] {
        let i = (r * self.width + c) * 3;
        [self.pixels[i], self.pixels[i + 1], self.pixels[i + 2]]
    }
}

const MAZE_SCALE: i64 = 4;

/// The current state of `domain` as a picture.
pub fn render(domain: &Domain) -> Picture {
    match domain.simulator() {
        Simulator::Maze(maze) => {
            let n = i64::from(LATTICE);
            let size = (n * MAZE_SCALE) as usize;
            let mut p = Picture::new(size, size, [255, 255, 255]);
            let layout = maze.layout();
            let row_of = |iy: i64| (n - 1 - iy) * MAZE_SCALE;
            for iy in 0..n {
                for ix in 0..n {
                    let colour = if layout.is_blocked(ix as i32, iy as i32) {
                        Some([0, 0, 0])
                    } else if ix >= i64::from(GOAL.0) && iy >= i64::from(GOAL.1) {
                        Some([120, 220, 120])
                    } else {
                        None
                    };
                    if let Some(c) = colour {
                        let r = row_of(iy);
                        p.fill(r, r + MAZE_SCALE, ix * MAZE_SCALE, (ix + 1) * MAZE_SCALE, c);
                    }
                }
            }
            let (x, y) = maze.position();
            let (r, c) = (row_of(i64::from(y)), i64::from(x) * MAZE_SCALE);
            p.fill(r - MAZE_SCALE, r + 2 * MAZE_SCALE, c - MAZE_SCALE, c + 2 * MAZE_SCALE, [220, 30, 30]);
            p
        }
        Simulator::Mario(env) => {
            const TILE: i64 = 8;
            const COLUMNS: i64 = 32;
            let world = env.world();
            let level = world.level();
            let mario = world.mario();
            let first = (mario.x / CELL) as i64 - COLUMNS / 2;
            let rows = i64::from(ROWS);
            let mut p = Picture::new((rows * TILE) as usize, (COLUMNS * TILE) as usize, [146, 190, 255]);
            for col in 0..COLUMNS {
                for row in 0..rows {
                    let t = level.get((first + col) as i32, row as i32);
                    let colour = match t {
                        tile::EMPTY | tile::HIDDEN => continue,
                        tile::COIN => [250, 210, 40],
                        tile::QUESTION_COIN | tile::QUESTION_POWERUP => [240, 170, 20],
                        tile::BRICK | tile::BRICK_COIN | tile::BRICK_POWERUP => [180, 80, 40],
                        tile::TUBE | tile::TUBE_TOP => [40, 170, 60],
                        tile::CANNON | tile::CANNON_TOP => [60, 60, 60],
                        _ => [130, 90, 50],
                    };
                    p.fill(row * TILE, (row + 1) * TILE, col * TILE, (col + 1) * TILE, colour);
                }
            }
            let to_px = |x: f32| ((f64::from(x) / f64::from(CELL) - first as f64) * TILE as f64) as i64;
            let to_row = |y: f32| (f64::from(y) / f64::from(CELL) * TILE as f64) as i64;
            for s in world.sprites() {
                if s.removed {
                    continue;
                }
                let colour = match s.kind {
                    SpriteKind::Mushroom | SpriteKind::FireFlower => [250, 120, 200],
                    SpriteKind::Fireball => [255, 140, 0],
                    SpriteKind::Shell => [90, 160, 90],
                    _ => [120, 30, 30],
                };
                let half = to_px(s.x + s.width) - to_px(s.x);
                let (c, bottom) = (to_px(s.x), to_row(s.y));
                p.fill(bottom - to_row(s.height).max(2), bottom, c - half.max(1), c + half.max(1), colour);
            }
            let (c, bottom) = (to_px(mario.x), to_row(mario.y));
            p.fill(bottom - to_row(mario.height()).max(2), bottom, c - 3, c + 3, [230, 20, 20]);
            p
        }
        Simulator::Keepaway(core) => {
            const SCALE: f64 = 10.0;
            const MARGIN: f64 = 2.0;
            let params = core.game.params();
            let (hl, hw) = (0.5 * params.length, 0.5 * params.width);
            let width = ((params.length + 2.0 * MARGIN) * SCALE) as usize;
            let height = ((params.width + 2.0 * MARGIN) * SCALE) as usize;
            let mut p = Picture::new(height, width, [40, 120, 40]);
            let px = |x: f64| ((x + hl + MARGIN) * SCALE) as i64;
            let py = |y: f64| ((y + hw + MARGIN) * SCALE) as i64;
            let white = [235, 235, 235];
            let (l, r, t, b) = (px(-hl), px(hl), py(-hw), py(hw));
            p.fill(t, t + 1, l, r + 1, white);
            p.fill(b, b + 1, l, r + 1, white);
            p.fill(t, b + 1, l, l + 1, white);
            p.fill(t, b + 1, r, r + 1, white);
            let mut dot = |pos: rlfd_keepaway::Vec2, radius: i64, colour: [u8; 3]| {
                let (c, row) = (px(pos.x), py(pos.y));
                p.fill(row - radius, row + radius + 1, c - radius, c + radius + 1, colour);
            };
            for k in core.game.keepers() {
                dot(k.pos, 3, [40, 80, 230]);
            }
            for t in core.game.takers() {
                dot(t.pos, 3, [220, 40, 40]);
            }
            dot(core.game.ball().pos, 1, [255, 255, 255]);
            p
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::domain::DomainSpec;

    #[test]
    fn the_maze_picture_shows_the_walls_the_goal_and_the_agent() {
        let mut d = Domain::new(DomainSpec::parse("maze", &[]).unwrap()).unwrap();
        d.reset(Some(0));
        let p = render(&d);
        assert_eq!((p.height, p.width, p.pixels.len()), (400, 400, 400 * 400 * 3));
        // The agent at (0.08, 0.60): column 32, row (99 − 60)·4.
        assert_eq!(p.at(39 * 4 + 1, 8 * 4 + 1), [220, 30, 30]);
        // Cell (1, 2) of the Dyna maze is a wall: (x, y) = (0.25, 0.70).
        assert_eq!(p.at((99 - 70) * 4, 25 * 4), [0, 0, 0]);
        // The goal region's corner (0.95, 0.95).
        assert_eq!(p.at((99 - 95) * 4, 95 * 4), [120, 220, 120]);
    }

    #[test]
    fn mario_and_keepaway_pictures_have_their_sizes() {
        for (name, h, w) in [("mario", 120, 256), ("keepaway", 240, 240)] {
            let mut d = Domain::new(DomainSpec::parse(name, &[]).unwrap()).unwrap();
            d.reset(Some(5));
            let p = render(&d);
            assert_eq!((p.height, p.width), (h, w), "{name}");
            assert!(p.pixels.iter().any(|&b| b != p.pixels[0]), "{name}: a blank picture");
        }
    }
}
