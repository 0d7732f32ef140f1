//! Shared test helpers: a seeded generator and random geometry.
#![allow(dead_code)]

use lowdisc_render::math::{Point2, Point3, Ray, Vec3};

/// SplitMix64: small, seeded, good enough for test inputs.
pub struct Rng(u64);

impl Rng {
    pub fn new(seed: u64) -> Self {
        Rng(seed)
    }
    pub fn next_u64(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9e3779b97f4a7c15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xbf58476d1ce4e5b9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94d049bb133111eb);
        z ^ (z >> 31)
    }
    /// Uniform in [0, 1).
    pub fn f32(&mut self) -> f32 {
        (self.next_u64() >> 40) as f32 / (1u64 << 24) as f32
    }
    pub fn range(&mut self, lo: f32, hi: f32) -> f32 {
        lo + (hi - lo) * self.f32()
    }
    pub fn vec(&mut self, lo: f32, hi: f32) -> Vec3 {
        Vec3::new(self.range(lo, hi), self.range(lo, hi), self.range(lo, hi))
    }
    pub fn p2(&mut self) -> Point2 {
        Point2::new(self.f32(), self.f32())
    }
    /// A unit direction, not uniformly distributed but covering the sphere.
    pub fn dir(&mut self) -> Vec3 {
        loop {
            let v = self.vec(-1.0, 1.0);
            let l = v.length();
            if l > 1e-3 && l <= 1.0 {
                return v / l;
            }
        }
    }
}

/// A random ray from outside-ish the box `[-s, s]^3` aimed inside it.
pub fn random_ray(rng: &mut Rng, s: f32) -> Ray {
    let o: Point3 = rng.vec(-1.6 * s, 1.6 * s);
    let target = rng.vec(-s, s);
    Ray::new(o, (target - o).normalize())
}
