//! An explicit serialisation of what a render depends on, for content
//! hashes: [`ContentHash::feed`] writes a value's bytes to a
//! [`ContentSink`] (a hasher), field by field.
//!
//! The format is fixed by the implementations, not by `Debug` text:
//! integers are little-endian (`usize` as `u64`), floats their `to_bits()`,
//! `bool` one byte, a sequence its length before its items, an `Option` and
//! every enum an explicit tag (a `u8`, `0u8` for the first variant) before
//! its fields, a struct or tuple its fields in order. Each
//! implementation for a struct destructures it without `..`, so a new
//! field does not compile until its author decides whether it is fed
//! (fields derived from others, such as inverse transforms, sampling
//! tables and cached areas, are named and left out). Whoever changes what
//! is fed raises the version of the hash built on it
//! (`lowdisc_split::SCENE_HASH_VERSION`).
//!
//! The implementations live beside their types; this module holds the two
//! traits and the implementations for the standard library's types.
//!
//! ```
//! use lowdisc_render::content_hash::{ContentHash, ContentSink};
//!
//! /// A sink that keeps the bytes (a hasher would digest them).
//! struct Bytes(Vec<u8>);
//! impl ContentSink for Bytes {
//!     fn write(&mut self, bytes: &[u8]) {
//!         self.0.extend_from_slice(bytes);
//!     }
//! }
//!
//! let mut sink = Bytes(Vec::new());
//! (vec![1.5f32], Some(true)).feed(&mut sink);
//! // The length, the float's bits, the `Some` tag, the bool.
//! assert_eq!(sink.0, [1, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0xc0, 0x3f, 1, 1]);
//! ```

use std::collections::BTreeMap;
use std::sync::Arc;

/// Where [`ContentHash::feed`] writes: a hasher, usually.
pub trait ContentSink {
    /// Takes the next bytes.
    fn write(&mut self, bytes: &[u8]);
}

/// A value that writes its content to a [`ContentSink`] (see the module
/// documentation for the format).
pub trait ContentHash {
    /// Writes the value's content to `sink`.
    fn feed<S: ContentSink + ?Sized>(&self, sink: &mut S);
}

macro_rules! little_endian {
    ($($t:ty),*) => {$(
        impl ContentHash for $t {
            #[inline]
            fn feed<S: ContentSink + ?Sized>(&self, sink: &mut S) {
                sink.write(&self.to_le_bytes());
            }
        }
    )*};
}

little_endian!(u8, u16, u32, u64, i32, i64);

impl ContentHash for usize {
    #[inline]
    fn feed<S: ContentSink + ?Sized>(&self, sink: &mut S) {
        (*self as u64).feed(sink);
    }
}

impl ContentHash for f32 {
    #[inline]
    fn feed<S: ContentSink + ?Sized>(&self, sink: &mut S) {
        self.to_bits().feed(sink);
    }
}

impl ContentHash for f64 {
    #[inline]
    fn feed<S: ContentSink + ?Sized>(&self, sink: &mut S) {
        self.to_bits().feed(sink);
    }
}

impl ContentHash for bool {
    #[inline]
    fn feed<S: ContentSink + ?Sized>(&self, sink: &mut S) {
        u8::from(*self).feed(sink);
    }
}

impl ContentHash for str {
    fn feed<S: ContentSink + ?Sized>(&self, sink: &mut S) {
        self.len().feed(sink);
        sink.write(self.as_bytes());
    }
}

impl ContentHash for String {
    fn feed<S: ContentSink + ?Sized>(&self, sink: &mut S) {
        self.as_str().feed(sink);
    }
}

impl<T: ContentHash> ContentHash for [T] {
    fn feed<S: ContentSink + ?Sized>(&self, sink: &mut S) {
        self.len().feed(sink);
        for x in self {
            x.feed(sink);
        }
    }
}

impl<T: ContentHash> ContentHash for Vec<T> {
    fn feed<S: ContentSink + ?Sized>(&self, sink: &mut S) {
        self.as_slice().feed(sink);
    }
}

/// Arrays have their length in their type: only the items are written.
impl<T: ContentHash, const N: usize> ContentHash for [T; N] {
    #[inline]
    fn feed<S: ContentSink + ?Sized>(&self, sink: &mut S) {
        for x in self {
            x.feed(sink);
        }
    }
}

impl<T: ContentHash> ContentHash for Option<T> {
    fn feed<S: ContentSink + ?Sized>(&self, sink: &mut S) {
        match self {
            None => 0u8.feed(sink),
            Some(x) => (1u8, x).feed(sink),
        }
    }
}

impl<T: ContentHash + ?Sized> ContentHash for &T {
    #[inline]
    fn feed<S: ContentSink + ?Sized>(&self, sink: &mut S) {
        (**self).feed(sink);
    }
}

impl<T: ContentHash + ?Sized> ContentHash for Box<T> {
    #[inline]
    fn feed<S: ContentSink + ?Sized>(&self, sink: &mut S) {
        (**self).feed(sink);
    }
}

/// The shared value's content (two `Arc`s of equal values feed alike).
impl<T: ContentHash + ?Sized> ContentHash for Arc<T> {
    #[inline]
    fn feed<S: ContentSink + ?Sized>(&self, sink: &mut S) {
        (**self).feed(sink);
    }
}

impl<K: ContentHash, V: ContentHash> ContentHash for BTreeMap<K, V> {
    fn feed<S: ContentSink + ?Sized>(&self, sink: &mut S) {
        self.len().feed(sink);
        for (k, v) in self {
            k.feed(sink);
            v.feed(sink);
        }
    }
}

macro_rules! tuple {
    ($($t:ident $x:ident),+) => {
        /// The items in order.
        impl<$($t: ContentHash),+> ContentHash for ($($t,)+) {
            fn feed<S: ContentSink + ?Sized>(&self, sink: &mut S) {
                let ($($x,)+) = self;
                $($x.feed(sink);)+
            }
        }
    };
}

tuple!(A a, B b);
tuple!(A a, B b, C c);
tuple!(A a, B b, C c, D d);
tuple!(A a, B b, C c, D d, E e);
tuple!(A a, B b, C c, D d, E e, F f);

#[cfg(test)]
mod tests {
    use super::*;

    impl ContentSink for Vec<u8> {
        fn write(&mut self, bytes: &[u8]) {
            self.extend_from_slice(bytes);
        }
    }

    fn bytes(x: &impl ContentHash) -> Vec<u8> {
        let mut v = Vec::new();
        x.feed(&mut v);
        v
    }

    #[test]
    fn lengths_and_tags_keep_neighbouring_values_apart() {
        // Without lengths these two would write the same bytes.
        let a = (vec![1u8, 2], vec![3u8]);
        let b = (vec![1u8], vec![2u8, 3]);
        assert_ne!(bytes(&a), bytes(&b));
        assert_ne!(
            bytes(&(None::<u8>, Some(0u8))),
            bytes(&(Some(0u8), None::<u8>))
        );
        assert_ne!(bytes(&"ab".to_string()), bytes(&("a", "b")));
    }

    #[test]
    fn floats_are_their_bits() {
        assert_eq!(bytes(&1.0f32), 0x3f80_0000u32.to_le_bytes());
        assert_ne!(bytes(&0.0f32), bytes(&-0.0f32));
        assert_eq!(bytes(&7usize), bytes(&7u64));
    }
}
