//! The mean of the worst pixels: a mean error hides a few badly wrong pixels (fireflies, a missed
//! thin object), the worst 1% shows them.

/// The share of pixels the "worst pixels" statistics average: 1%.
pub(crate) const WORST_FRACTION: f64 = 0.01;

/// The mean of the largest `ceil(fraction · n)` values (at least one value; 0 for no values).
///
/// `fraction` is clamped to [0, 1]. NaN values count as the largest.
pub(crate) fn mean_of_worst(values: &[f64], fraction: f64) -> f64 {
    if values.is_empty() {
        return 0.0;
    }
    let share = fraction.clamp(0.0, 1.0) * values.len() as f64;
    let count = (share.ceil() as usize).clamp(1, values.len());
    let mut sorted = values.to_vec();
    // Descending, NaN first: `total_cmp` orders NaN above every number.
    let split = count - 1;
    sorted.select_nth_unstable_by(split, |a, b| b.total_cmp(a));
    sorted[..count].iter().sum::<f64>() / count as f64
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn averages_the_top_share() {
        let values: Vec<f64> = (1..=200).map(f64::from).collect();
        // 1% of 200 is 2 values: 200 and 199.
        assert_eq!(mean_of_worst(&values, WORST_FRACTION), 199.5);
        // A share below one value still takes the largest value.
        assert_eq!(mean_of_worst(&values[..10], WORST_FRACTION), 10.0);
        assert_eq!(mean_of_worst(&values, 1.0), 100.5);
        assert_eq!(mean_of_worst(&[], WORST_FRACTION), 0.0);
    }
}
