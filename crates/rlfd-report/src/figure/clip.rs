//! Clipping in data coordinates to the plot's ranges, since plotters draws
//! whatever it is given, also outside the plotting area: polylines with
//! Liang–Barsky (a polyline leaving and re-entering the window becomes
//! several runs), polygons with Sutherland–Hodgman (the window is convex,
//! so a concave band clips correctly, at worst with edges along the border).
//! Plain arithmetic only, so results are the same on every machine.

/// The plot window: `x` and `y` ranges, `lo < hi`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Window {
    pub x: (f64, f64),
    pub y: (f64, f64),
}

impl Window {
    pub(crate) fn contains(&self, (x, y): (f64, f64)) -> bool {
        x >= self.x.0 && x <= self.x.1 && y >= self.y.0 && y <= self.y.1
    }

    /// The part of segment `a`–`b` inside the window (Liang–Barsky).
    pub(crate) fn segment(&self, a: (f64, f64), b: (f64, f64)) -> Option<((f64, f64), (f64, f64))> {
        let (dx, dy) = (b.0 - a.0, b.1 - a.1);
        let (mut t0, mut t1) = (0.0_f64, 1.0_f64);
        for (p, q) in [(-dx, a.0 - self.x.0), (dx, self.x.1 - a.0), (-dy, a.1 - self.y.0), (dy, self.y.1 - a.1)] {
            if p == 0.0 {
                if q < 0.0 {
                    return None;
                }
            } else {
                let r = q / p;
                if p < 0.0 {
                    t0 = t0.max(r);
                } else {
                    t1 = t1.min(r);
                }
            }
        }
        if t0 > t1 {
            return None;
        }
        let at = |t: f64| {
            if t == 0.0 {
                a
            } else if t == 1.0 {
                b
            } else {
                (a.0 + dx * t, a.1 + dy * t)
            }
        };
        Some((at(t0), at(t1)))
    }

    /// A polyline's parts inside the window, as runs of at least two points
    /// (a lone point inside is kept as a one-point run).
    pub(crate) fn polyline(&self, points: &[(f64, f64)]) -> Vec<Vec<(f64, f64)>> {
        if points.len() == 1 {
            return if self.contains(points[0]) { vec![points.to_vec()] } else { Vec::new() };
        }
        let mut runs: Vec<Vec<(f64, f64)>> = Vec::new();
        for w in points.windows(2) {
            let Some((a, b)) = self.segment(w[0], w[1]) else {
                continue;
            };
            match runs.last_mut() {
                Some(run) if run.last() == Some(&a) => run.push(b),
                _ => runs.push(vec![a, b]),
            }
        }
        runs
    }

    /// A polygon clipped to the window (Sutherland–Hodgman); empty if outside.
    pub(crate) fn polygon(&self, points: &[(f64, f64)]) -> Vec<(f64, f64)> {
        let mut poly = points.to_vec();
        // (axis, bound, keep when coordinate >= bound?)
        for (axis, bound, above) in
            [(0, self.x.0, true), (0, self.x.1, false), (1, self.y.0, true), (1, self.y.1, false)]
        {
            if poly.is_empty() {
                break;
            }
            let coord = |p: (f64, f64)| if axis == 0 { p.0 } else { p.1 };
            let inside = |p: (f64, f64)| {
                if above { coord(p) >= bound } else { coord(p) <= bound }
            };
            let cross = |a: (f64, f64), b: (f64, f64)| {
                let t = (bound - coord(a)) / (coord(b) - coord(a));
                if axis == 0 { (bound, a.1 + (b.1 - a.1) * t) } else { (a.0 + (b.0 - a.0) * t, bound) }
            };
            let mut out = Vec::with_capacity(poly.len() + 4);
            for i in 0..poly.len() {
                let current = poly[i];
                let previous = poly[(i + poly.len() - 1) % poly.len()];
                match (inside(previous), inside(current)) {
                    (true, true) => out.push(current),
                    (true, false) => out.push(cross(previous, current)),
                    (false, true) => {
                        out.push(cross(previous, current));
                        out.push(current);
                    }
                    (false, false) => {}
                }
            }
            poly = out;
        }
        poly
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    const W: Window = Window { x: (0.0, 10.0), y: (0.0, 10.0) };

    #[test]
    fn polylines_split_where_they_leave() {
        let runs = W.polyline(&[(1.0, 1.0), (3.0, 5.0), (5.0, 15.0), (7.0, 5.0), (9.0, 5.0)]);
        assert_eq!(runs, vec![vec![(1.0, 1.0), (3.0, 5.0), (4.0, 10.0)], vec![(6.0, 10.0), (7.0, 5.0), (9.0, 5.0)],]);
        assert!(W.polyline(&[(20.0, 1.0), (30.0, 5.0)]).is_empty());
        assert_eq!(W.polyline(&[(2.0, 2.0)]), vec![vec![(2.0, 2.0)]]);
    }

    #[test]
    fn polygons_are_cut_at_the_border() {
        let band = [(0.0, 12.0), (10.0, 8.0), (10.0, 6.0), (0.0, 6.0)];
        assert_eq!(W.polygon(&band), vec![(0.0, 10.0), (5.0, 10.0), (10.0, 8.0), (10.0, 6.0), (0.0, 6.0)]);
        assert!(W.polygon(&[(20.0, 1.0), (30.0, 1.0), (30.0, 5.0)]).is_empty());
    }
}
