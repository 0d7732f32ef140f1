//! The macro that turns the sampler table ([`super::table`]) into code.
//!
//! The table lists the pixel sampler types; under each type, the catalog
//! names built on it, each with its command-line name, [`Family`], one-line
//! description and constructor. From that one list the macro writes:
//! * [`SamplerName`], `SamplerName::ALL` (table order), `as_str`,
//!   `description`, `family` and the crate-internal `build`;
//! * [`Sampler`], the enum over every pixel sampler type, its `From` impls,
//!   its [`PixelSampler`] implementation (one `match` per call) and the
//!   crate-internal `words` view of the types that produce digit words.
//!
//! A type is marked `words` when it implements [`WordSampler`] (its names'
//! points are the digit words of pixel (0,0)), `values` when it implements
//! only [`PixelSampler`].
//!
//! [`SamplerName`]: super::SamplerName
//! [`Sampler`]: super::Sampler
//! [`Family`]: super::Family
//! [`PixelSampler`]: crate::pixel::PixelSampler
//! [`WordSampler`]: crate::pixel::WordSampler

/// Writes the catalog's name enum and sampler enum from the table; see the
/// module documentation.
macro_rules! sampler_table {
    (@words words $inner:ident) => {
        Some($inner as &mut dyn $crate::pixel::WordSampler)
    };
    (@words values $inner:ident) => {{
        let _ = $inner;
        None
    }};
    (
        $(
            $(#[$type_doc:meta])*
            $kind:ident $variant:ident($ty:ty) {
                $(
                    $name:ident $text:literal, $family:expr, $description:literal,
                    |$p:ident| $build:expr;
                )+
            }
        )+
    ) => {
        /// The samplers the catalog knows, by name (see the table in
        /// `catalog/table.rs`).
        #[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
        pub enum SamplerName {
            $($(
                #[doc = concat!("`", $text, "`: ", $description, ".")]
                $name,
            )+)+
        }

        impl SamplerName {
            /// Every name, in the table's order (the order the
            /// documentation lists them).
            pub const ALL: [SamplerName; [$($($text,)+)+].len()] =
                [$($(SamplerName::$name,)+)+];

            /// The name as written on the command line.
            pub fn as_str(self) -> &'static str {
                match self {
                    $($(SamplerName::$name => $text,)+)+
                }
            }

            /// A one-line description.
            pub fn description(self) -> &'static str {
                match self {
                    $($(SamplerName::$name => $description,)+)+
                }
            }

            /// The family: how the name's raw points are made, and which
            /// point order applies.
            pub fn family(self) -> Family {
                match self {
                    $($(SamplerName::$name => $family,)+)+
                }
            }

            /// The pixel sampler of this name, built from checked `params`.
            pub(crate) fn build(self, params: &Params) -> Result<Sampler, Error> {
                match self {
                    $($(SamplerName::$name => {
                        let $p: &Params = params;
                        $build.map(Sampler::$variant)
                    })+)+
                }
            }
        }

        /// Every pixel sampler type of the crate, dispatching
        /// [`PixelSampler`] by `match` so renderers can hold a concrete,
        /// `Clone + Send + Sync` value without trait objects. Build one from
        /// a [`SamplerConfig`](super::SamplerConfig).
        #[derive(Debug, Clone)]
        pub enum Sampler {
            $(
                $(#[$type_doc])*
                $variant($ty),
            )+
        }

        $(
            impl From<$ty> for Sampler {
                fn from(s: $ty) -> Self {
                    Sampler::$variant(s)
                }
            }
        )+

        impl Sampler {
            /// The sampler as a producer of digit words, for the types that
            /// are one.
            pub(crate) fn words(&mut self) -> Option<&mut dyn $crate::pixel::WordSampler> {
                match self {
                    $(Sampler::$variant(s) => sampler_table!(@words $kind s),)+
                }
            }
        }

        impl PixelSampler for Sampler {
            fn samples_per_pixel(&self) -> u32 {
                match self {
                    $(Sampler::$variant(s) => PixelSampler::samples_per_pixel(s),)+
                }
            }

            fn start_pixel_sample(&mut self, pixel: [u32; 2], sample_index: u32, dimension: u32) {
                match self {
                    $(Sampler::$variant(s) => PixelSampler::start_pixel_sample(s, pixel, sample_index, dimension),)+
                }
            }

            fn get_1d(&mut self) -> f32 {
                match self {
                    $(Sampler::$variant(s) => PixelSampler::get_1d(s),)+
                }
            }

            fn get_2d(&mut self) -> [f32; 2] {
                match self {
                    $(Sampler::$variant(s) => PixelSampler::get_2d(s),)+
                }
            }

            fn get_pixel_2d(&mut self) -> [f32; 2] {
                match self {
                    $(Sampler::$variant(s) => PixelSampler::get_pixel_2d(s),)+
                }
            }

            fn get_values<const N: usize>(&mut self, dims: [Dims; N]) -> [[f32; 2]; N]
            where
                Self: Sized,
            {
                match self {
                    $(Sampler::$variant(s) => PixelSampler::get_values(s, dims),)+
                }
            }
        }
    };
}

pub(crate) use sampler_table;
