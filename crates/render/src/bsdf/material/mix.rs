//! pbrt-v4's `mix` material: one of two materials per shading point, chosen
//! with a probability given by a (possibly textured) `amount`.

use super::{BsdfContext, Material};
use crate::math::Vec3;
use crate::texture::FloatTexture;
use lowdisc::hash::{hash_words, unit_f64};

/// pbrt-v4's `mix` material: at each shading point one of two materials,
/// the second with probability `amount` (a float texture), chosen by
/// [`mix_choice`] from a hash of the point, `wo` and the seed (so the choice
/// is deterministic for a given point and direction, as in pbrt-v4).
#[derive(Clone, Debug, PartialEq)]
pub struct MixMaterial {
    /// The materials at amount 0 and 1.
    pub materials: [Material; 2],
    /// The probability of the second material.
    pub amount: FloatTexture,
}

impl MixMaterial {
    /// The material used at `ctx`.
    pub fn choose(&self, ctx: &BsdfContext) -> &Material {
        let amount = self.amount.evaluate(&ctx.texture_context());
        &self.materials[mix_choice(amount, ctx.p, ctx.wo, ctx.seed)]
    }
}

/// pbrt-v4's `MixMaterial::ChooseMaterial`: which of two materials (0 or 1)
/// to use at shading point `p` seen from `wo`. Material 1 is chosen with
/// probability `amount` (clamped to `[0, 1]`), decided by a hash of `p`, `wo`
/// and `seed` so that the choice is stable for a given point and direction.
pub fn mix_choice(amount: f32, p: Vec3, wo: Vec3, seed: u64) -> usize {
    if !(amount > 0.0) {
        return 0;
    }
    if amount >= 1.0 {
        return 1;
    }
    let bits = |x: f32| u64::from(x.to_bits());
    let h = hash_words(&[
        seed,
        bits(p.x),
        bits(p.y),
        bits(p.z),
        bits(wo.x),
        bits(wo.y),
        bits(wo.z),
    ]);
    if (amount as f64) < unit_f64(h) { 0 } else { 1 }
}
