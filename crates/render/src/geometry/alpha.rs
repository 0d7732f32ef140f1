//! Alpha cut-outs (pbrt-v4's shape parameter `"alpha"`, a float or a float
//! texture): where a shape's alpha is 0 rays pass through it, where it is 1
//! they hit it, and in between a hit is kept with probability `alpha`.
//!
//! As in pbrt-v4's `GeometricPrimitive`, that choice is not drawn from the
//! sampler but from a hash of the ray (its origin and direction, here
//! lowdisc's [`hash_words`] where pbrt-v4 uses MurmurHash): the same ray
//! always makes the same choice, so images stay bit-identical whatever the
//! thread count. Closest-hit and shadow (any-hit) queries both apply it. A
//! rejected hit on a sphere is followed by a test of its far side, from a
//! ray spawned at the rejected hit (hashed anew), as pbrt-v4 retraces.

use super::{Prim, PrimHit, ShapeSet};
use crate::content_hash::{ContentHash, ContentSink};
use crate::math::{Ray, spawn_ray};
use crate::texture::{FloatTexture, TextureEvalContext};
use lowdisc::hash::hash_words;

/// A shape of a [`ShapeSet`] (all triangles of a mesh share one alpha).
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub enum ShapeId {
    /// Mesh index in [`ShapeSet::meshes`].
    Mesh(u32),
    /// Sphere index in [`ShapeSet::spheres`].
    Sphere(u32),
    /// Disk index in [`ShapeSet::disks`].
    Disk(u32),
}

impl Prim {
    /// The shape the primitive belongs to.
    #[inline]
    pub fn shape(self) -> ShapeId {
        match self {
            Prim::Triangle { mesh, .. } => ShapeId::Mesh(mesh),
            Prim::Sphere(i) => ShapeId::Sphere(i),
            Prim::Disk(i) => ShapeId::Disk(i),
        }
    }
}

/// A value in `[0, 1)` from a hash of `ray`'s origin and direction (pbrt-v4's
/// `HashFloat(ray.o, ray.d)`).
pub fn ray_hash_float(ray: &Ray) -> f32 {
    let bits = |x: f32| u64::from(x.to_bits());
    let h = hash_words(&[
        bits(ray.o.x),
        bits(ray.o.y),
        bits(ray.o.z),
        bits(ray.d.x),
        bits(ray.d.y),
        bits(ray.d.z),
    ]);
    (h >> 40) as f32 * (1.0 / (1u64 << 24) as f32)
}

/// True when a hit of alpha `alpha` along `ray` counts: always for
/// `alpha >= 1`, never for `alpha <= 0` (or NaN), else when
/// [`ray_hash_float`] `<= alpha`.
///
/// ```
/// use lowdisc_render::geometry::alpha::alpha_keeps;
/// use lowdisc_render::math::{Ray, Vec3};
///
/// let ray = Ray::new(Vec3::ZERO, Vec3::Z);
/// assert!(alpha_keeps(1.0, &ray) && !alpha_keeps(0.0, &ray));
/// ```
pub fn alpha_keeps(alpha: f32, ray: &Ray) -> bool {
    if alpha >= 1.0 {
        return true;
    }
    alpha > 0.0 && ray_hash_float(ray) <= alpha
}

impl ShapeSet {
    /// Gives `shape` the alpha texture `alpha` (pbrt-v4's `"alpha"`).
    pub fn set_alpha(&mut self, shape: ShapeId, alpha: FloatTexture) {
        self.alpha.insert(shape, alpha);
    }

    /// The alpha texture of primitive `p`'s shape, if it has one.
    #[inline]
    pub fn alpha(&self, p: Prim) -> Option<&FloatTexture> {
        if self.alpha.is_empty() {
            return None;
        }
        self.alpha.get(&p.shape())
    }

    /// True when some shape has an alpha texture.
    #[inline]
    pub fn has_alpha(&self) -> bool {
        !self.alpha.is_empty()
    }

    /// True when the hit `h` on `p` along `ray` counts under `p`'s alpha
    /// (always when `p` has none).
    #[inline(never)]
    pub fn alpha_keeps_hit(&self, p: Prim, ray: &Ray, h: &PrimHit) -> bool {
        let Some(alpha) = self.alpha(p) else {
            return true;
        };
        let hit = self.surface_hit(p, ray, h);
        let a = alpha.evaluate(&TextureEvalContext {
            p: hit.p,
            uv: hit.uv,
        });
        alpha_keeps(a, ray)
    }

    /// [`ShapeSet::intersect`] with `p`'s alpha applied: a rejected hit is
    /// followed by the next hit on the same primitive beyond it (the far
    /// side of a sphere).
    #[inline(never)]
    pub fn intersect_alpha(&self, p: Prim, ray: &Ray, t_max: f32) -> Option<PrimHit> {
        let h = self.intersect(p, ray, t_max)?;
        if self.alpha_keeps_hit(p, ray, &h) {
            return Some(h);
        }
        let Prim::Sphere(_) = p else { return None };
        let hit = self.surface_hit(p, ray, &h);
        let next = spawn_ray(hit.p, hit.ng, ray.d);
        let far = self.intersect(p, &next, t_max - h.t)?;
        self.alpha_keeps_hit(p, &next, &far).then_some(PrimHit {
            t: h.t + far.t,
            ..far
        })
    }
}

impl ContentHash for ShapeId {
    fn feed<S: ContentSink + ?Sized>(&self, sink: &mut S) {
        match self {
            ShapeId::Mesh(i) => (0u8, i).feed(sink),
            ShapeId::Sphere(i) => (1u8, i).feed(sink),
            ShapeId::Disk(i) => (2u8, i).feed(sink),
        }
    }
}
