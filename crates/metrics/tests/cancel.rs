//! The `_cancellable` variants of the star-discrepancy bounds, the distances and the
//! radial spectrum: with the flag clear they return exactly the plain functions'
//! results; with it set they return `None`; set while they run, they stop early.

mod common;

use std::sync::atomic::{AtomicBool, Ordering};
use std::time::{Duration, Instant};

use common::{coarse, hammersley, random};
use lowdisc_metrics::{
    BoundsOptions, DistanceMetric, PointSet, distance_stats, distance_stats_cancellable,
    min_distance, min_distance_cancellable, nearest_neighbour_distances,
    nearest_neighbour_distances_cancellable, radial_power_spectrum,
    radial_power_spectrum_cancellable, star_bounds, star_bounds_cancellable,
};

/// Point sets of several shapes (ties, structure, randomness).
fn sets() -> Vec<PointSet> {
    vec![
        random(300, 2, 1),
        random(200, 3, 2),
        coarse(150, 2, 7, 3),
        hammersley(256),
        random(100, 5, 4),
    ]
}

#[test]
fn a_clear_flag_changes_nothing_and_a_set_flag_stops_at_once() {
    let (go, stop) = (AtomicBool::new(false), AtomicBool::new(true));
    let options = BoundsOptions {
        random_boxes: 500,
        ta_iterations: 200,
        ta_restarts: 3,
        ..BoundsOptions::default()
    };
    for p in sets() {
        let plain = star_bounds(&p, &options).unwrap();
        assert_eq!(
            star_bounds_cancellable(&p, &options, &go).unwrap(),
            Some(plain)
        );
        assert_eq!(star_bounds_cancellable(&p, &options, &stop).unwrap(), None);
        for metric in [DistanceMetric::Euclidean, DistanceMetric::Toroidal] {
            let nn = nearest_neighbour_distances(&p, metric).unwrap();
            let got = nearest_neighbour_distances_cancellable(&p, metric, &go).unwrap();
            assert_eq!(got, Some(nn));
            let stats = distance_stats(&p, metric).unwrap();
            assert_eq!(
                distance_stats_cancellable(&p, metric, &go).unwrap(),
                Some(stats)
            );
            let min = min_distance(&p, metric).unwrap();
            assert_eq!(
                min_distance_cancellable(&p, metric, &go).unwrap(),
                Some(min)
            );
            assert_eq!(
                nearest_neighbour_distances_cancellable(&p, metric, &stop).unwrap(),
                None
            );
            assert_eq!(min_distance_cancellable(&p, metric, &stop).unwrap(), None);
            assert_eq!(distance_stats_cancellable(&p, metric, &stop).unwrap(), None);
        }
        if p.dims() == 2 {
            let s = radial_power_spectrum(&p, 24).unwrap();
            assert_eq!(
                radial_power_spectrum_cancellable(&p, 24, &go).unwrap(),
                Some(s)
            );
            assert_eq!(
                radial_power_spectrum_cancellable(&p, 24, &stop).unwrap(),
                None
            );
        }
    }
}

#[test]
fn errors_come_before_the_flag() {
    let stop = AtomicBool::new(true);
    let one = PointSet::new(2, vec![0.5, 0.5]).unwrap();
    assert!(
        nearest_neighbour_distances_cancellable(&one, DistanceMetric::Euclidean, &stop).is_err()
    );
    assert!(radial_power_spectrum_cancellable(&random(10, 3, 1), 4, &stop).is_err());
    let bad_grid = BoundsOptions {
        grid_cells: Some(0),
        random_boxes: 1,
        ta_iterations: 1,
        ta_restarts: 1,
        ..BoundsOptions::default()
    };
    let go = AtomicBool::new(false);
    assert!(star_bounds_cancellable(&random(10, 2, 1), &bad_grid, &go).is_err());
}

/// Runs `work(cancel)` on another thread, sets the flag after 50 ms and returns
/// whether it reported a cancellation, and how long it took after the flag.
fn cancel_midway(work: impl FnOnce(&AtomicBool) -> bool + Send) -> (bool, Duration) {
    let cancel = AtomicBool::new(false);
    std::thread::scope(|scope| {
        let handle = scope.spawn(|| work(&cancel));
        std::thread::sleep(Duration::from_millis(50));
        let set = Instant::now();
        cancel.store(true, Ordering::Relaxed);
        let stopped = handle.join().unwrap();
        (stopped, set.elapsed())
    })
}

#[test]
fn a_flag_set_while_they_run_stops_them() {
    // Each of these runs for many seconds uncancelled.
    let big = random(400_000, 3, 7);
    let (stopped, took) = cancel_midway(|c| {
        star_bounds_cancellable(&big, &BoundsOptions::default(), c)
            .unwrap()
            .is_none()
    });
    assert!(stopped && took < Duration::from_secs(5), "{took:?}");

    let high = random(60_000, 20, 8);
    let (stopped, took) = cancel_midway(|c| {
        nearest_neighbour_distances_cancellable(&high, DistanceMetric::Euclidean, c)
            .unwrap()
            .is_none()
    });
    assert!(stopped && took < Duration::from_secs(5), "{took:?}");

    let plane = random(1_000, 2, 9);
    let (stopped, took) = cancel_midway(|c| {
        radial_power_spectrum_cancellable(&plane, 2048, c)
            .unwrap()
            .is_none()
    });
    assert!(stopped && took < Duration::from_secs(5), "{took:?}");
}
