//! The Pareto front of (time, error) points: the settings no other setting beats on both.

/// The indices of the points no other point dominates (another point is at most as slow and
/// at most as wrong, and better in one), ordered by time. Of equal points the first is kept;
/// points with a NaN coordinate are never on the front.
pub(crate) fn pareto_front(points: &[(f64, f64)]) -> Vec<usize> {
    let mut order: Vec<usize> = (0..points.len())
        .filter(|&i| !points[i].0.is_nan() && !points[i].1.is_nan())
        .collect();
    // By time, then error, then index: a sweep keeps each point that lowers the best error yet.
    order.sort_by(|&a, &b| {
        let (pa, pb) = (points[a], points[b]);
        pa.0.total_cmp(&pb.0)
            .then(pa.1.total_cmp(&pb.1))
            .then(a.cmp(&b))
    });
    let mut best = f64::INFINITY;
    let mut front = Vec::new();
    for i in order {
        if points[i].1 < best {
            best = points[i].1;
            front.push(i);
        }
    }
    front
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn keeps_only_undominated_points() {
        let points = [
            (1.0, 0.5), // 0: fastest
            (2.0, 0.6), // 1: slower and worse than 0
            (2.0, 0.3), // 2: on the front
            (4.0, 0.3), // 3: as wrong as 2 but slower
            (8.0, 0.1), // 4: most accurate
            (f64::NAN, 0.0),
            (1.0, 0.5), // 6: equal to 0; the first is kept
        ];
        assert_eq!(pareto_front(&points), vec![0, 2, 4]);
        assert!(pareto_front(&[]).is_empty());
    }
}
