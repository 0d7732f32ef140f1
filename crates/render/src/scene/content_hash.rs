//! The content of a [`Scene`] ([`crate::content_hash`]): everything that
//! determines its pixels (shapes, materials, each shape's material and
//! area lights, lights and their emission spectra). The acceleration
//! structure is fed as its shapes only (its tree is derived from them, and
//! carries its build time); the infinite lights' indices and the light
//! sampler are derived from the lights. The media are fed only when the
//! scene has some, so a scene without media hashes as it did before media
//! existed. How the scene is seen (camera, film, filter) is the view's
//! ([`crate::view::ViewSpec`]).

use super::{MediaOfScene, Scene, ShapeInfo};
use crate::content_hash::{ContentHash, ContentSink};
use crate::medium::{HomogeneousMedium, Medium, MediumInterface};

impl ContentHash for Scene {
    fn feed<S: ContentSink + ?Sized>(&self, sink: &mut S) {
        let Scene {
            accel,
            materials,
            mesh_info,
            sphere_info,
            disk_info,
            lights,
            light_spectra,
            infinite_lights: _,
            light_sampler: _,
            media,
        } = self;
        (accel.shapes(), materials).feed(sink);
        (mesh_info, sphere_info, disk_info).feed(sink);
        (lights, light_spectra).feed(sink);
        if media.active {
            media.feed(sink);
        }
    }
}

impl ContentHash for MediaOfScene {
    fn feed<S: ContentSink + ?Sized>(&self, sink: &mut S) {
        let MediaOfScene {
            media,
            shape_media,
            camera_medium,
            active: _,
        } = self;
        (media, shape_media, camera_medium).feed(sink);
    }
}

impl ContentHash for Medium {
    fn feed<S: ContentSink + ?Sized>(&self, sink: &mut S) {
        match self {
            Medium::Homogeneous(m) => (0u8, m).feed(sink),
        }
    }
}

impl ContentHash for HomogeneousMedium {
    fn feed<S: ContentSink + ?Sized>(&self, sink: &mut S) {
        let HomogeneousMedium {
            sigma_a,
            sigma_s,
            le,
            g,
        } = self;
        (sigma_a, sigma_s, le, g).feed(sink);
    }
}

impl ContentHash for MediumInterface {
    fn feed<S: ContentSink + ?Sized>(&self, sink: &mut S) {
        let MediumInterface { inside, outside } = self;
        (inside, outside).feed(sink);
    }
}

impl ContentHash for ShapeInfo {
    fn feed<S: ContentSink + ?Sized>(&self, sink: &mut S) {
        let ShapeInfo {
            material,
            first_light,
        } = self;
        (material, first_light).feed(sink);
    }
}
