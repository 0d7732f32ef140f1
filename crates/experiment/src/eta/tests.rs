//! The estimator against a fake render whose rows differ in cost, timed by
//! a fake clock: every ray costs the same time, a sky row's samples trace
//! one ray each and the rows below seven, and the rows finish top first.

use super::*;

/// Rows of the fake image, camera samples per row, and the sky rows.
const ROWS: u64 = 30;
const PER_ROW: u64 = 1000;
const SKY_ROWS: u64 = 10;
/// Seconds per ray: the whole image takes 300 s.
const SECONDS_PER_RAY: f64 = 300.0 / ((SKY_ROWS + 7 * (ROWS - SKY_ROWS)) * PER_ROW) as f64;

fn rays_of_row(row: u64) -> u64 {
    if row < SKY_ROWS { PER_ROW } else { 7 * PER_ROW }
}

/// The work done and the fake clock after the first `rows` rows.
fn after(rows: u64) -> (Done, f64) {
    let rays: u64 = (0..rows).map(rays_of_row).sum();
    let done = Done {
        samples: rows * PER_ROW,
        rays,
    };
    (done, rays as f64 * SECONDS_PER_RAY)
}

/// The estimate a calibration of the fake image at `speed` times its true
/// speed gives for `images` renders of it.
fn estimate(images: u64, speed: f64) -> Estimate {
    let (whole, seconds) = after(ROWS);
    let samples = images * whole.samples;
    let samples_per_second = speed * whole.samples as f64 / seconds;
    Estimate {
        samples,
        samples_per_second,
        rays_per_sample: whole.rays as f64 / whole.samples as f64,
        seconds: samples as f64 / samples_per_second,
    }
}

#[test]
fn a_stages_time_left_counts_its_expensive_rows() {
    let mut eta = Eta::default();
    eta.estimate(&estimate(1, 1.0));
    eta.begin(ROWS * PER_ROW, 0.0);
    let (_, total) = after(ROWS);
    for rows in 1..ROWS {
        let (done, now) = after(rows);
        eta.advance(done);
        let left = eta.stage(now).unwrap();
        let truth = total - now;
        // Counted in samples, after the sky rows (a third of the samples
        // in 1/15 of the time) the time left would be 40 s, not 280 s.
        assert!(
            (left.seconds - truth).abs() <= 0.01 * truth,
            "after {rows} rows: {} s left, truly {truth} s",
            left.seconds
        );
        let fraction = now / total;
        assert!((left.fraction - fraction).abs() < 1e-9);
    }
}

#[test]
fn the_runs_time_left_follows_the_measured_speed() {
    // The calibration believed the machine twice as fast as it is (another
    // job started); after a few seconds the measured speed takes over.
    let mut eta = Eta::default();
    eta.estimate(&estimate(3, 2.0));
    let (whole, total) = after(ROWS);
    for image in 0..3u64 {
        let start = image as f64 * total;
        eta.begin(whole.samples, start);
        for rows in 1..=ROWS {
            let (done, t) = after(rows);
            eta.advance(done);
            let now = start + t;
            let run = eta.run(now).unwrap();
            let truth = 3.0 * total - now;
            if now > 60.0 {
                assert!(
                    (run.seconds - truth).abs() <= 0.1 * truth + 1e-9,
                    "image {image}, {rows} rows: {} s left, truly {truth} s",
                    run.seconds
                );
            }
            assert!((run.fraction - now / (3.0 * total)).abs() < 1e-9);
        }
        eta.end(start + total);
    }
    let run = eta.run(3.0 * total).unwrap();
    assert_eq!((run.fraction, run.seconds), (1.0, 0.0));
}

#[test]
fn without_an_estimate_work_is_counted_in_samples() {
    let mut eta = Eta::default();
    eta.begin(100, 10.0);
    eta.advance(Done {
        samples: 25,
        rays: 0,
    });
    let stage = eta.stage(20.0).unwrap();
    assert_eq!(stage.fraction, 0.25);
    assert!((stage.seconds - 30.0).abs() < 1e-9);
    assert_eq!(eta.run(20.0), None);
}
