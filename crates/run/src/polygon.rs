//! The area of a polygon inside a rectangle, exactly: the polygon clipped by each of the
//! rectangle's four sides in turn (Sutherland & Hodgman 1974, Comm. ACM 17, 32: exact for a
//! convex clipping region, any simple polygon), then the shoelace formula. The cells of a
//! polygon's release (`initial.polygons`) take the fraction of their area it covers, so that
//! the released mass is its area × εs × ρs on every grid.

/// The area of `polygon` inside the rectangle [x0, x1] × [y0, y1] [m²].
pub(crate) fn area_inside(
    polygon: &[(f64, f64)],
    (x0, x1): (f64, f64),
    (y0, y1): (f64, f64),
) -> f64 {
    // side by side, keep the points at a distance ≥ 0 inside it and add where edges cross it
    let mut points = polygon.to_vec();
    for side in 0..4 {
        if points.is_empty() {
            return 0.0;
        }
        let distance = |p: (f64, f64)| match side {
            0 => p.0 - x0,
            1 => x1 - p.0,
            2 => p.1 - y0,
            _ => y1 - p.1,
        };
        let mut kept = Vec::with_capacity(points.len() + 4);
        for k in 0..points.len() {
            let (a, b) = (points[k], points[(k + 1) % points.len()]);
            let (da, db) = (distance(a), distance(b));
            if da >= 0.0 {
                kept.push(a);
            }
            if (da >= 0.0) != (db >= 0.0) {
                let t = da / (da - db);
                kept.push((a.0 + t * (b.0 - a.0), a.1 + t * (b.1 - a.1)));
            }
        }
        points = kept;
    }
    runout_case::release::signed_area(&points).abs()
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A triangle over a grid of rectangles: the pieces sum to its area (1e-14), a rectangle
    /// wholly inside holds its own area, one outside none.
    #[test]
    fn the_pieces_sum_to_the_whole() {
        let wedge = [(0.1, 0.05), (0.93, 0.4), (0.2, 0.71)];
        let area = runout_case::release::signed_area(&wedge).abs();
        let (n, m) = (37, 23);
        let mut sum = 0.0;
        for i in 0..n {
            for j in 0..m {
                let x = (i as f64 / n as f64, (i + 1) as f64 / n as f64);
                let y = (j as f64 / m as f64, (j + 1) as f64 / m as f64);
                sum += area_inside(&wedge, x, y);
            }
        }
        assert!((sum - area).abs() < 1e-14, "{sum} vs {area}");
        assert!((area_inside(&wedge, (0.3, 0.35), (0.35, 0.4)) - 0.0025).abs() < 1e-17);
        assert_eq!(area_inside(&wedge, (0.9, 1.0), (0.9, 1.0)), 0.0);
        // a non-convex polygon (an L) clipped by a rectangle through its notch
        let ell = [
            (0.0, 0.0),
            (2.0, 0.0),
            (2.0, 1.0),
            (1.0, 1.0),
            (1.0, 2.0),
            (0.0, 2.0),
        ];
        assert!((area_inside(&ell, (0.5, 1.5), (0.5, 1.5)) - 0.75).abs() < 1e-15);
    }
}
