//! RGB film: weighted means, the sensor's imaging ratio and clamping,
//! NaN/inf accounting, crop windows, tiles merged in any order, output files.

use lowdisc_render::film::{Film, FilmError, FilmParams, PixelBounds};
use lowdisc_render::spectrum::Rgb;

fn film(w: u32, h: u32) -> Film {
    Film::new(&FilmParams {
        resolution: [w, h],
        ..Default::default()
    })
    .unwrap()
}

/// SplitMix64 (Steele, Lea & Flood 2014): seeded test data.
struct Rng(u64);
impl Rng {
    fn next(&mut self) -> f32 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        (lowdisc::hash::mix64(self.0) >> 40) as f32 * (1.0 / 16_777_216.0)
    }
}

#[test]
fn pixel_value_is_the_weighted_mean() {
    let mut f = film(4, 3);
    f.add_sample([1, 2], Rgb::new(1.0, 2.0, 3.0), 1.0);
    f.add_sample([1, 2], Rgb::new(3.0, 0.0, 1.0), 3.0);
    // (1*1 + 3*3) / 4 = 2.5, (2 + 0) / 4 = 0.5, (3 + 3) / 4 = 1.5
    assert_eq!(f.pixel_rgb([1, 2]), Some(Rgb::new(2.5, 0.5, 1.5)));
    // Untouched pixels are black; pixels outside are None.
    assert_eq!(f.pixel_rgb([0, 0]), Some(Rgb::ZERO));
    assert_eq!(f.pixel_rgb([4, 0]), None);
    let img = f.to_image().unwrap();
    assert_eq!((img.width(), img.height()), (4, 3));
    assert_eq!(img.get(1, 2), Some([2.5, 0.5, 1.5]));
    // Negative weights (negative filter lobes) enter the sums as they are.
    f.add_sample([0, 0], Rgb::splat(1.0), 2.0);
    f.add_sample([0, 0], Rgb::splat(4.0), -0.5);
    assert_eq!(f.pixel_rgb([0, 0]), Some(Rgb::splat((2.0 - 2.0) / 1.5)));
}

#[test]
fn nonfinite_samples_are_counted_and_dropped() {
    let mut f = film(2, 2);
    f.add_sample([0, 0], Rgb::splat(0.5), 1.0);
    f.add_sample([0, 0], Rgb::new(f32::NAN, 0.0, 0.0), 1.0);
    f.add_sample([0, 0], Rgb::new(0.0, f32::INFINITY, 0.0), 1.0);
    f.add_sample([0, 0], Rgb::splat(1.0), f32::NAN);
    f.add_sample([1, 1], Rgb::new(0.0, 0.0, f32::NEG_INFINITY), 1.0);
    assert_eq!(f.nonfinite_count(), 4);
    assert_eq!(f.pixel_rgb([0, 0]), Some(Rgb::splat(0.5)));
    assert_eq!(f.pixel_rgb([1, 1]), Some(Rgb::ZERO));
    assert!(
        f.to_image()
            .unwrap()
            .pixels()
            .iter()
            .flatten()
            .all(|v| v.is_finite())
    );
    // Out-of-film samples are counted separately.
    f.add_sample([2, 0], Rgb::ONE, 1.0);
    assert_eq!(f.outside_count(), 1);
}

#[test]
fn imaging_ratio_and_max_component() {
    let p = FilmParams {
        resolution: [1, 1],
        iso: 400.0,
        exposure_time: 0.5,
        ..Default::default()
    };
    let mut f = Film::new(&p).unwrap();
    assert_eq!(f.imaging_ratio(), 2.0);
    f.add_sample([0, 0], Rgb::new(1.0, 2.0, 3.0), 1.0);
    assert_eq!(f.pixel_rgb([0, 0]), Some(Rgb::new(2.0, 4.0, 6.0)));
    // Clamping scales the whole colour so its largest channel is the maximum.
    let p = FilmParams {
        resolution: [1, 1],
        max_component_value: 3.0,
        ..Default::default()
    };
    let mut f = Film::new(&p).unwrap();
    f.add_sample([0, 0], Rgb::new(1.0, 2.0, 6.0), 1.0);
    assert_eq!(f.pixel_rgb([0, 0]), Some(Rgb::new(0.5, 1.0, 3.0)));
    // An infinite channel would become NaN under clamping: counted, dropped.
    f.add_sample([0, 0], Rgb::new(1.0, f32::INFINITY, 0.0), 1.0);
    assert_eq!(f.nonfinite_count(), 1);
}

#[test]
fn crop_window_and_pixel_bounds_follow_pbrt() {
    // pbrt-v4: ceil(res * crop) on both corners.
    let p = FilmParams {
        resolution: [10, 10],
        crop_window: Some([0.25, 0.75, 0.0, 0.5]),
        ..Default::default()
    };
    let f = Film::new(&p).unwrap();
    assert_eq!(f.pixel_bounds(), PixelBounds::new([3, 0], [8, 5]));
    assert_eq!(f.full_resolution(), [10, 10]);
    let img = f.to_image().unwrap();
    assert_eq!((img.width(), img.height()), (5, 5));
    let p = FilmParams {
        resolution: [10, 10],
        pixel_bounds: Some([2, 4, 6, 20]),
        ..Default::default()
    };
    assert_eq!(
        Film::new(&p).unwrap().pixel_bounds(),
        PixelBounds::new([2, 6], [4, 10])
    );
    let bad = FilmParams {
        resolution: [10, 10],
        crop_window: Some([0.5, 0.4, 0.0, 1.0]),
        ..Default::default()
    };
    assert!(matches!(
        Film::new(&bad),
        Err(FilmError::InvalidCropWindow(_))
    ));
    let empty = FilmParams {
        resolution: [10, 10],
        pixel_bounds: Some([20, 30, 0, 5]),
        ..Default::default()
    };
    assert!(matches!(
        Film::new(&empty),
        Err(FilmError::EmptyPixelBounds(_))
    ));
    assert!(
        Film::new(&FilmParams {
            resolution: [0, 5],
            ..Default::default()
        })
        .is_err()
    );
    assert!(
        Film::new(&FilmParams {
            iso: -1.0,
            ..Default::default()
        })
        .is_err()
    );
}

#[test]
fn tiles_cover_the_bounds_once_in_row_major_order() {
    let b = PixelBounds::new([1, 2], [11, 9]);
    let tiles = b.tiles(4);
    assert_eq!(tiles.len(), 3 * 2);
    assert_eq!(tiles[0], PixelBounds::new([1, 2], [5, 6]));
    assert_eq!(tiles[2], PixelBounds::new([9, 2], [11, 6]));
    assert_eq!(tiles[5], PixelBounds::new([9, 6], [11, 9]));
    let mut seen = vec![0u8; b.area()];
    for t in &tiles {
        for p in t.pixels() {
            seen[((p[1] - 2) * 10 + (p[0] - 1)) as usize] += 1;
        }
    }
    assert!(seen.iter().all(|&c| c == 1));
}

/// Deterministic samples for pixel `p`: several per pixel with varied weights.
fn samples_for(p: [i32; 2], seed: u64) -> Vec<(Rgb, f32)> {
    let mut rng = Rng(seed ^ ((p[0] as u64) << 32) ^ p[1] as u64);
    (0..7)
        .map(|k| {
            let v = if k == 3 && (p[0] + p[1]) % 5 == 0 {
                f32::NAN
            } else {
                rng.next() * 10.0
            };
            (Rgb::new(v, rng.next(), rng.next() * 0.1), 0.25 + rng.next())
        })
        .collect()
}

#[test]
fn tile_merges_in_any_order_are_bit_identical() {
    let params = FilmParams {
        resolution: [23, 17],
        crop_window: Some([0.1, 0.9, 0.0, 1.0]),
        ..Default::default()
    };
    let reference = {
        let mut f = Film::new(&params).unwrap();
        for p in f.pixel_bounds().pixels() {
            for (rgb, w) in samples_for(p, 42) {
                f.add_sample(p, rgb, w);
            }
        }
        f
    };
    let tiled = |order: &[usize], tile_size: u32| {
        let mut f = Film::new(&params).unwrap();
        let tiles: Vec<_> = f
            .pixel_bounds()
            .tiles(tile_size)
            .into_iter()
            .map(|b| {
                let mut t = f.tile(b);
                for p in b.pixels() {
                    for (rgb, w) in samples_for(p, 42) {
                        t.add_sample(p, rgb, w);
                    }
                }
                t
            })
            .collect();
        for &i in order {
            f.merge_tile(&tiles[i]);
        }
        f
    };
    let n = Film::new(&params).unwrap().pixel_bounds().tiles(5).len();
    let forward: Vec<usize> = (0..n).collect();
    let backward: Vec<usize> = (0..n).rev().collect();
    let shuffled: Vec<usize> = (0..n).map(|i| (i * 7 + 3) % n).collect();
    let mut sorted = shuffled.clone();
    sorted.sort_unstable();
    assert_eq!(sorted, forward, "the shuffled order must be a permutation");
    let ref_img = reference.to_image().unwrap();
    for order in [&forward, &backward, &shuffled] {
        let f = tiled(order, 5);
        let img = f.to_image().unwrap();
        let bits = |i: &lowdisc_image::RgbImage| {
            i.pixels()
                .iter()
                .flatten()
                .map(|v| v.to_bits())
                .collect::<Vec<_>>()
        };
        assert_eq!(bits(&img), bits(&ref_img));
        assert_eq!(f.nonfinite_count(), reference.nonfinite_count());
    }
    assert!(reference.nonfinite_count() > 0);
    // A different tile size gives the same image too (one tile per pixel owner).
    let n3 = Film::new(&params).unwrap().pixel_bounds().tiles(3).len();
    assert_eq!(
        tiled(&(0..n3).collect::<Vec<_>>(), 3).to_image().unwrap(),
        ref_img
    );
}

#[test]
fn tile_rejects_pixels_outside_it() {
    let f = film(8, 8);
    let mut t = f.tile(PixelBounds::new([4, 4], [12, 12]));
    assert_eq!(t.bounds(), PixelBounds::new([4, 4], [8, 8]));
    t.add_sample([0, 0], Rgb::ONE, 1.0);
    t.add_sample([5, 5], Rgb::new(f32::NAN, 0.0, 0.0), 1.0);
    assert_eq!((t.outside_count(), t.nonfinite_count()), (1, 1));
}

#[test]
fn writes_exr_and_png() {
    let dir = std::env::temp_dir().join(format!("lowdisc-film-test-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let mut f = film(3, 2);
    f.add_sample([0, 0], Rgb::new(0.25, 1.5, 0.0), 1.0);
    f.add_sample([2, 1], Rgb::new(0.214_041_14, 0.0, 1.0), 1.0);
    let exr = dir.join("out.exr");
    f.write(&exr, 1.0).unwrap();
    let back = lowdisc_image::read_image(&exr).unwrap();
    assert_eq!(back, f.to_image().unwrap());
    // PNG: sRGB with exposure 2: 0.25 * 2 = 0.5 -> code 188; 1.5 * 2 clamps to 255;
    // 0.21404114 * 2 = 0.42808228 -> sRGB 0.6863 -> code 175.
    let png = dir.join("out.png");
    f.write(&png, 2.0).unwrap();
    let codes = lowdisc_image::read_image_with(&png, &lowdisc_image::ReadOptions::raw()).unwrap();
    let code = |x: usize, y: usize, c: usize| (codes.get(x, y).unwrap()[c] * 255.0).round() as u8;
    assert_eq!((code(0, 0, 0), code(0, 0, 1), code(0, 0, 2)), (188, 255, 0));
    assert_eq!(code(2, 1, 0), 175);
    assert!(f.write(dir.join("out.xyz"), 1.0).is_err());
    std::fs::remove_dir_all(&dir).ok();
}
