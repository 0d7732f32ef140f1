//! Alpha cut-outs (pbrt-v4's shape `"alpha"`): rays and shadow rays pass
//! where alpha is 0, hit where it is 1, and in between keep a hit with
//! probability alpha, decided by a hash of the ray.

use lowdisc::catalog::SamplerName;
use lowdisc_render::math::{Point3, Ray, Vec3};
use lowdisc_render::pbrt::{LoadOptions, LoadedScene, load_pbrt_scene};
use lowdisc_render::render::{NoProgress, RenderOptions, render};
use lowdisc_render::view::View;

fn load(tag: &str, text: &str, approximate: bool) -> Result<LoadedScene, String> {
    let dir = std::env::temp_dir().join(format!("lowdisc-alpha-{tag}-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join("scene.pbrt");
    std::fs::write(&path, text).unwrap();
    let options = LoadOptions {
        approximate,
        ..LoadOptions::default()
    };
    let l = load_pbrt_scene(&path, &options).map_err(|e| e.to_string());
    std::fs::remove_dir_all(&dir).ok();
    l
}

/// A ground square `[-2, 2]^2` at `z = 0`, seen from above and lit by a
/// distant light from above, with an occluding unit square at `z = 1`
/// (uv from 0 to 1 across it) whose shape parameters are `occluder`
/// (`None`: no occluder).
fn scene(textures: &str, occluder: Option<&str>) -> String {
    let occluder = occluder.map_or(String::new(), |params| {
        format!(
            "Material \"diffuse\"\nShape \"bilinearmesh\" \
             \"point3 P\" [-1 -1 1 1 -1 1 -1 1 1 1 1 1] \"point2 uv\" [0 0 1 0 0 1 1 1] {params}\n"
        )
    });
    format!(
        "LookAt 0 0 6 0 0 0 0 1 0\nCamera \"perspective\" \"float fov\" 40\n\
         Film \"rgb\" \"integer xresolution\" 16 \"integer yresolution\" 16\n\
         WorldBegin\n\
         LightSource \"distant\" \"point3 from\" [0.1 0.2 1] \"point3 to\" [0 0 0]\n\
         {textures}\n\
         Material \"diffuse\"\n\
         Shape \"bilinearmesh\" \"point3 P\" [-2 -2 0 2 -2 0 -2 2 0 2 2 0]\n\
         {occluder}"
    )
}

fn render_pixels(l: &LoadedScene) -> Vec<[f32; 3]> {
    render_with_threads(l, 2)
}

fn render_with_threads(l: &LoadedScene, threads: usize) -> Vec<[f32; 3]> {
    let view = View::native(&l.view).unwrap();
    let opts = RenderOptions {
        threads: Some(threads),
        ..RenderOptions::new(SamplerName::ZSobol, 5, 4)
    };
    render(&l.scene, &view, &opts, &NoProgress)
        .unwrap()
        .image
        .into_pixels()
}

/// A ray straight down through `(x, y)` from above the occluder.
fn down(x: f32, y: f32) -> Ray {
    Ray::new(Point3::new(x, y, 3.0), Vec3::new(0.0, 0.0, -1.0))
}

#[test]
fn an_occluder_of_alpha_zero_is_invisible_and_casts_no_shadow() {
    let none = load("none", &scene("", None), false).unwrap();
    let cut = load("zero", &scene("", Some("\"float alpha\" 0")), false).unwrap();
    let opaque = load("one", &scene("", Some("\"float alpha\" 1")), false).unwrap();
    assert!(cut.warnings.is_empty(), "{:?}", cut.warnings);
    // Rays go through it to the ground; shadow rays too.
    let hit = cut.scene.intersect(&down(0.2, 0.3)).unwrap();
    assert!(hit.hit.surface.p.z.abs() < 1e-6, "{:?}", hit.hit.surface.p);
    assert!(!cut.scene.intersect_p(&down(0.2, 0.3), 2.5));
    let hit = opaque.scene.intersect(&down(0.2, 0.3)).unwrap();
    assert!((hit.hit.surface.p.z - 1.0).abs() < 1e-6);
    assert!(opaque.scene.intersect_p(&down(0.2, 0.3), 2.5));
    // The image is the one without the occluder, bit for bit; the opaque
    // occluder's is not.
    let (a, b, c) = (
        render_pixels(&none),
        render_pixels(&cut),
        render_pixels(&opaque),
    );
    assert_eq!(a, b);
    assert_ne!(a, c);
}

#[test]
fn an_alpha_texture_half_zero_half_one_cuts_half_the_square() {
    // floor(2u) + floor(v) is even (tex1 = 0) for u < 1/2.
    let textures = "Texture \"half\" \"float\" \"checkerboard\" \"float tex1\" 0 \
                    \"float tex2\" 1 \"float uscale\" 2";
    let l = load(
        "half",
        &scene(textures, Some("\"texture alpha\" \"half\"")),
        false,
    )
    .unwrap();
    assert!(l.warnings.is_empty(), "{:?}", l.warnings);
    let n = 40;
    let (mut kept, mut shadowed) = (0, 0);
    for i in 0..n {
        for j in 0..n {
            // Inside the square, away from the line u = 1/2 (x = 0).
            let x = -0.95 + 1.9 * (i as f32 + 0.5) / n as f32;
            let y = -0.95 + 1.9 * (j as f32 + 0.5) / n as f32;
            let ray = down(x, y);
            let on_occluder = l.scene.intersect(&ray).unwrap().hit.surface.p.z > 0.5;
            assert_eq!(on_occluder, x > 0.0, "({x}, {y})");
            assert_eq!(l.scene.intersect_p(&ray, 2.5), on_occluder, "({x}, {y})");
            kept += usize::from(on_occluder);
            shadowed += usize::from(l.scene.intersect_p(&ray, 2.5));
        }
    }
    assert_eq!((kept, shadowed), (n * n / 2, n * n / 2));
}

#[test]
fn a_fractional_alpha_keeps_that_fraction_of_rays_the_same_way_every_time() {
    let l = load("quarter", &scene("", Some("\"float alpha\" 0.25")), false).unwrap();
    let n = 4000;
    let rays: Vec<Ray> = (0..n)
        .map(|k| {
            let x = -0.9 + 1.8 * ((k as f32 * 0.618_034) % 1.0);
            let y = -0.9 + 1.8 * (k as f32 + 0.5) / n as f32;
            down(x, y)
        })
        .collect();
    let hits = |r: &Ray| l.scene.intersect(r).unwrap().hit.surface.p.z > 0.5;
    let kept = rays.iter().filter(|r| hits(r)).count();
    // Binomial(4000, 0.25): mean 1000, standard deviation 27.
    assert!((kept as i64 - 1000).abs() < 140, "{kept}");
    for r in &rays {
        assert_eq!(hits(r), hits(r));
        assert_eq!(hits(r), l.scene.intersect_p(r, 2.5));
    }
}

#[test]
fn a_sphere_cut_out_lets_rays_reach_its_far_side_or_through() {
    let text = "LookAt 0 0 6 0 0 0 0 1 0\nCamera \"perspective\"\nWorldBegin\n\
                LightSource \"point\"\nMaterial \"diffuse\"\n\
                Shape \"sphere\" \"float radius\" 1 \"float alpha\" 0\n";
    let l = load("sphere", text, false).unwrap();
    assert!(l.scene.intersect(&down(0.1, 0.2)).is_none());
    assert!(!l.scene.intersect_p(&down(0.1, 0.2), f32::INFINITY));
}

#[test]
fn an_alpha_on_an_area_light_is_refused_without_approximate() {
    let text = "LookAt 0 0 6 0 0 0 0 1 0\nCamera \"perspective\"\nWorldBegin\n\
                AttributeBegin\nAreaLightSource \"diffuse\"\n\
                Shape \"sphere\" \"float alpha\" 0.5\nAttributeEnd\n";
    let e = load("light", text, false).unwrap_err();
    assert!(e.contains("scene.pbrt:6:") && e.contains("alpha"), "{e}");
    let l = load("light-approx", text, true).unwrap();
    assert!(
        l.warnings.iter().any(|w| w.contains("alpha")),
        "{:?}",
        l.warnings
    );
}

#[test]
fn fractional_cut_outs_and_bumps_render_the_same_whatever_the_thread_count() {
    let textures = "Texture \"ridges\" \"float\" \"checkerboard\" \"float tex1\" 0 \
                    \"float tex2\" 0.02 \"float uscale\" 8";
    let occluder = "\"float alpha\" 0.5\nMaterial \"diffuse\" \"texture displacement\" \"ridges\"\n\
                    Shape \"sphere\" \"float radius\" 0.5 \"float alpha\" 0.3";
    let l = load("threads", &scene(textures, Some(occluder)), false).unwrap();
    assert!(l.warnings.is_empty(), "{:?}", l.warnings);
    let one = render_with_threads(&l, 1);
    assert!(one.iter().flatten().all(|v| v.is_finite()));
    assert_eq!(one, render_with_threads(&l, 3));
}
