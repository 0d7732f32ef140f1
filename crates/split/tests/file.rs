//! Part files: a part survives its EXR file bit for bit, the file is the
//! same bytes every time, image readers see its pixel values, and damaged or
//! foreign files are refused.

use lowdisc::catalog::SamplerName;
use lowdisc_image::{ImageFormat, ReadOptions, WriteOptions, decode_image, encode_image};
use lowdisc_render::cornell::cornell_box;
use lowdisc_render::film::PixelBounds;
use lowdisc_render::integrator::PathIntegrator;
use lowdisc_render::render::{NoProgress, RenderOptions, SampleRange, render};
use lowdisc_split::{RenderPart, decode_part, encode_part};

fn part() -> RenderPart {
    let (scene, view) = cornell_box([20, 12]).unwrap();
    let o = RenderOptions {
        integrator: PathIntegrator {
            max_depth: 2,
            ..PathIntegrator::default()
        },
        window: Some(PixelBounds::new([3, 2], [17, 9])),
        samples: Some(SampleRange::new(1, 3)),
        ..RenderOptions::new(SamplerName::SobolOwen, 4, 3)
    };
    let out = render(&scene, &view, &o, &NoProgress).unwrap();
    RenderPart::new(&scene, &view, &o, &out)
}

#[test]
fn a_part_round_trips_through_its_file_exactly() {
    let p = part();
    let bytes = encode_part(&p).unwrap();
    assert_eq!(decode_part(&bytes).unwrap(), p);
    assert_eq!(
        encode_part(&p).unwrap(),
        bytes,
        "the same part, the same bytes"
    );
}

#[test]
fn image_readers_see_the_pixel_values() {
    let p = part();
    let bytes = encode_part(&p).unwrap();
    let image = decode_image(&bytes, ImageFormat::Exr, &ReadOptions::default()).unwrap();
    assert_eq!(image, p.image().unwrap());
}

#[test]
fn damaged_and_foreign_files_are_refused() {
    let bytes = encode_part(&part()).unwrap();
    let e = decode_part(&bytes[..bytes.len() - 100])
        .unwrap_err()
        .to_string();
    assert!(e.starts_with("not a readable EXR file"), "{e}");
    let e = decode_part(b"hello").unwrap_err().to_string();
    assert!(e.starts_with("not a readable EXR file"), "{e}");
    let plain = part().image().unwrap();
    let plain = encode_image(&plain, ImageFormat::Exr, &WriteOptions::default()).unwrap();
    let e = decode_part(&plain).unwrap_err().to_string();
    assert!(
        e.starts_with("no `lowdisc.part` header: not a render part"),
        "{e}"
    );
}
