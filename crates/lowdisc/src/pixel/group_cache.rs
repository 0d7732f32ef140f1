//! The caches of the group-padded Z-order samplers (`zsobol-4d`,
//! `zsobol-joint` in [`super::zsobol_joint`], `zorder-sz` in
//! [`super::zorder_sz`]). They never change a value; they only keep what
//! the definition would compute again:
//!
//! * **per sample**, the permuted Z-order index of every dimension group
//!   ([`ZSobolSampler::sample_index`]), computed on first use and kept
//!   until the next sample for groups `0..CACHED_GROUPS`;
//! * **per pixel**, for the same groups, the group key's level hashes and
//!   permuted pixel digits ([`KeyIndex`]), so a sample's index costs the
//!   bit mixes of its sample digits only;
//! * **per sampler**, the scramble key of every lane of every group: the
//!   randomizer seed of a group is a hash of the sampler seed, the group's
//!   dimension key and the index bits above 31 (zero unless the image has
//!   more than `2^32` Z-order indices), and each lane's key is derived from
//!   it, so for groups `0..KEYED_GROUPS` the keys are kept and rehashed only
//!   when those high bits change.
//!
//! A value is then `strategy.apply(word, seed, lane)` computed as
//! `strategy.apply_key_reversed(word.reverse_bits(), key)`, which is the
//! same function (see [`RandomizeStrategy::apply_key_reversed`]).

use alloc::vec::Vec;

use super::zsobol::KeyIndex;
use super::{SEED_PAD, ZSobolSampler};
use crate::RandomizeStrategy;
use crate::hash::hash_words;
use crate::scramble::dimension_seed;

/// Groups whose permuted index is kept for the current sample.
const CACHED_GROUPS: usize = 32;
/// Groups whose lane scramble keys are kept.
const KEYED_GROUPS: usize = 64;
/// Lanes per group (four sequence lanes and `zorder-sz`'s index lane).
pub(super) const LANES: usize = 5;

/// The scramble keys of one group's lanes.
#[derive(Debug, Clone, Copy, Default)]
struct GroupKeys {
    /// The index bits above 31 the keys are for.
    high: u64,
    /// Bit `l` set when `keys[l]` is computed for `high`.
    known: u8,
    keys: [u32; LANES],
}

/// The caches of one group-padded sampler; see the module documentation.
#[derive(Debug, Clone, Default)]
pub(super) struct GroupCache {
    /// Permuted indices of groups `0..CACHED_GROUPS` at the current sample.
    indices: [u64; CACHED_GROUPS],
    /// Bit `g` set when `indices[g]` is computed.
    known: u64,
    /// The index permutations of groups `0..CACHED_GROUPS`, made on use.
    key_indices: Vec<Option<KeyIndex>>,
    /// Lane keys of groups `0..KEYED_GROUPS`, grown on use.
    keys: Vec<GroupKeys>,
}

impl GroupCache {
    /// Forgets every kept index (a new sample starts).
    pub(super) fn clear(&mut self) {
        self.known = 0;
    }

    /// The permuted index of `group`, whose dimension key is `key`, at
    /// `order`'s current sample.
    #[inline]
    pub(super) fn index(&mut self, order: &ZSobolSampler, group: u64, key: u64) -> u64 {
        let Some(slot) = usize::try_from(group).ok().filter(|&g| g < CACHED_GROUPS) else {
            return order.sample_index(key);
        };
        if self.known & (1 << slot) == 0 {
            if slot >= self.key_indices.len() {
                self.key_indices.resize(slot + 1, None);
            }
            let key_index = self.key_indices[slot].get_or_insert_with(|| order.key_index(key));
            self.indices[slot] = order.sample_index_with(key_index);
            self.known |= 1 << slot;
        }
        self.indices[slot]
    }

    /// `strategy.apply(word, hash_words(&[seed, SEED_PAD, key, index >> 32]),
    /// lane)`: the scramble of `lane` (`< LANES`) of `group` (dimension key
    /// `key`) at permuted index `index`.
    #[inline]
    pub(super) fn scramble(
        &mut self,
        strategy: RandomizeStrategy,
        seed: u64,
        (group, key): (u64, u64),
        index: u64,
        lane: u32,
        word: u32,
    ) -> u32 {
        let high = index >> 32;
        let lane_key = |strategy: RandomizeStrategy| {
            let group_seed = hash_words(&[seed, SEED_PAD, key, high]);
            strategy.scramble_key(dimension_seed(group_seed, lane))
        };
        let Some(slot) = usize::try_from(group).ok().filter(|&g| g < KEYED_GROUPS) else {
            return strategy.apply_key_reversed(word.reverse_bits(), lane_key(strategy));
        };
        if slot >= self.keys.len() {
            self.keys.resize(slot + 1, GroupKeys::default());
        }
        let entry = &mut self.keys[slot];
        if entry.high != high {
            entry.high = high;
            entry.known = 0;
        }
        let l = lane as usize;
        if entry.known & (1 << l) == 0 {
            entry.keys[l] = lane_key(strategy);
            entry.known |= 1 << l;
        }
        strategy.apply_key_reversed(word.reverse_bits(), entry.keys[l])
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_cached_scramble_is_the_definition() {
        let order = ZSobolSampler::new(16, [8, 8], RandomizeStrategy::FastOwen, 3).unwrap();
        for strategy in RandomizeStrategy::ALL {
            let mut cache = GroupCache::default();
            for round in 0..3u64 {
                for group in [0u64, 5, 31, 32, 63, 64, 200] {
                    let key = 99 + group;
                    // High index bits change between rounds.
                    let index = ((round % 2) << 40) | (group * 77);
                    for lane in 0..LANES as u32 {
                        let word = (group as u32).wrapping_mul(0x9e37_79b9) ^ lane;
                        let seed = hash_words(&[11, SEED_PAD, key, index >> 32]);
                        let want = strategy.apply(word, seed, lane);
                        let got = cache.scramble(strategy, 11, (group, key), index, lane, word);
                        assert_eq!(got, want, "{strategy:?} {group} {lane}");
                    }
                }
            }
        }
        let mut cache = GroupCache::default();
        for group in [0u64, 31, 32, 64] {
            assert_eq!(cache.index(&order, group, 7), order.sample_index(7));
        }
    }
}
