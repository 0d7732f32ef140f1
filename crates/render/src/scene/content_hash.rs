//! The content of a [`Scene`] ([`crate::content_hash`]): everything that
//! determines its pixels (shapes, materials, each shape's material and
//! area lights, lights and their emission spectra). The acceleration
//! structure is fed as its shapes only (its tree is derived from them, and
//! carries its build time); the infinite lights' indices and the light
//! sampler are derived from the lights. How the scene is seen (camera,
//! film, filter) is the view's ([`crate::view::ViewSpec`]).

use super::{Scene, ShapeInfo};
use crate::content_hash::{ContentHash, ContentSink};

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
        } = self;
        (accel.shapes(), materials).feed(sink);
        (mesh_info, sphere_info, disk_info).feed(sink);
        (lights, light_spectra).feed(sink);
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
