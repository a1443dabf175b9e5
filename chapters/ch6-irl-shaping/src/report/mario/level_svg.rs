//! The picture of a Mario level: its solid tiles, enemies, exit and the
//! path Mario took (the report's level figure, and `cargo xtask render
//! mario`).

use rlfd_report::Provenance;
use rlfd_report::figure::{Marker, PathEmphasis, Rect, Scene, ScenePath};

use crate::mario::demonstrator;
use crate::mario::level::{CELL, EnemyKind, Level, ROWS, tile};
use crate::mario::{LevelParams, MarioEnv, Mode, Status};

/// Solid tiles of a level as merged runs per row, in scene coordinates (cells, y up).
fn level_rects(level: &Level) -> Vec<Rect> {
    let mut out = Vec::new();
    for y in 0..ROWS {
        let mut x = 0;
        while x < level.width() {
            let t = level.get(x, y);
            let solid = t != tile::EMPTY && t != tile::COIN && t != tile::HIDDEN && t != tile::HILL;
            if !solid {
                x += 1;
                continue;
            }
            let start = x;
            while x < level.width() && {
                let u = level.get(x, y);
                u != tile::EMPTY && u != tile::COIN && u != tile::HIDDEN && u != tile::HILL
            } {
                x += 1;
            }
            let top = f64::from(ROWS - y);
            out.push(Rect::new(f64::from(start), top - 1.0, f64::from(x), top));
        }
    }
    out
}

/// The level of a demonstration with the enemies' and coins' places and the path Mario took.
pub fn level_scene(level: &Level, path: &[(f32, f32)], title: &str) -> Scene {
    let w = f64::from(level.width());
    let mut scene = Scene::new(title, Rect::new(0.0, 0.0, w, f64::from(ROWS)));
    scene.x_label = "x (cells)".into();
    scene.y_label = "height (cells)".into();
    // A level is 256 cells long: cut it into strips of at most 80
    // cells, 8 px a cell, so blocks, enemies and text stay legible on a page.
    scene.rows = (level.width() as usize).div_ceil(80).max(1);
    scene.plot_width = ((level.width() as u32 * 8) / scene.rows as u32).max(200);
    scene.ticks = 11;
    scene.wall_label = "block".into();
    scene.goal_label = "exit".into();
    scene.walls = level_rects(level);
    let exit = f64::from(level.x_exit());
    scene.goal = Some(Rect::new(exit, 0.0, (exit + 1.0).min(w), f64::from(ROWS)));
    for t in level.templates() {
        let label = match t.kind {
            EnemyKind::Goomba => "g",
            EnemyKind::RedKoopa => "rk",
            EnemyKind::GreenKoopa => "gk",
            EnemyKind::Spiky => "s",
            EnemyKind::Flower => "p",
        };
        scene.markers.push(Marker { label: label.into(), at: (f64::from(t.x) + 0.5, f64::from(ROWS - t.y) - 0.5) });
    }
    if !path.is_empty() {
        scene.paths.push(ScenePath {
            name: Some("Mario's path".into()),
            points: path
                .iter()
                .map(|&(x, y)| {
                    (f64::from(x / CELL), (f64::from(ROWS) - f64::from(y / CELL)).clamp(0.0, f64::from(ROWS)))
                })
                .collect(),
            emphasis: PathEmphasis::Primary,
        });
    }
    scene
}

/// The SVG of the level of `level_seed` under `params`, with the path of the
/// calibrated demonstrator playing it from `mode` (for `cargo xtask render mario`).
pub fn render_level(
    params: LevelParams,
    level_seed: u64,
    mode: Mode,
    provenance: &Provenance,
) -> rlfd_report::Result<String> {
    let mut env = MarioEnv::new(params);
    let mut rng = rlfd_rl::random::seeded(level_seed ^ 0x5eed);
    let d = demonstrator::MarioDemonstrator::thesis().demonstrate_on(&mut env, level_seed, mode, &mut rng);
    let level = Level::generate(params, level_seed);
    let title = format!(
        "Mario level {level_seed} (width {}, difficulty {}): the demonstrator from {:?} mode, {} ticks, {} points, {}",
        params.width,
        params.difficulty,
        mode,
        d.len(),
        d.score,
        outcome(d.outcome)
    );
    level_scene(&level, &d.path, &title).to_svg(provenance)
}

/// How an episode ended, in words.
pub(super) fn outcome(s: Status) -> &'static str {
    match s {
        Status::Won => "level finished",
        Status::Dead => "died",
        Status::Running => "running",
    }
}
