//! pbrt-v4's two blocks: the options block (camera, film, sampler,
//! integrator, filter) before `WorldBegin` and the world block (shapes,
//! lights, materials, textures, attributes) after it, checked as pbrt-v4
//! checks them: a directive in the wrong block, a second `WorldBegin`, a
//! file that ends before `WorldBegin` or with an `AttributeBegin` or
//! `TransformBegin` still open are errors, not silently wrong images.

use pbrt_format::{Directive, ErrorKind, Loc, ParseError};

use super::loader::PbrtLoader;

/// Where a directive may appear.
#[derive(Clone, Copy, PartialEq, Eq)]
enum Block {
    Options,
    World,
    Anywhere,
}

/// The directive's name and the block it belongs to.
fn block_of(d: &Directive) -> (&'static str, Block) {
    use Block::{Anywhere, Options, World};
    match d {
        Directive::Camera(..) => ("Camera", Options),
        Directive::Film(..) => ("Film", Options),
        Directive::Sampler(..) => ("Sampler", Options),
        Directive::Integrator(..) => ("Integrator", Options),
        Directive::PixelFilter(..) => ("PixelFilter", Options),
        Directive::Accelerator(..) => ("Accelerator", Options),
        Directive::WorldBegin => ("WorldBegin", Options),
        Directive::Shape(..) => ("Shape", World),
        Directive::Material(..) => ("Material", World),
        Directive::MakeNamedMaterial(..) => ("MakeNamedMaterial", World),
        Directive::NamedMaterial(..) => ("NamedMaterial", World),
        Directive::Texture(..) => ("Texture", World),
        Directive::LightSource(..) => ("LightSource", World),
        Directive::AreaLightSource(..) => ("AreaLightSource", World),
        Directive::AttributeBegin => ("AttributeBegin", World),
        Directive::AttributeEnd => ("AttributeEnd", World),
        Directive::Attribute(..) => ("Attribute", World),
        Directive::ReverseOrientation => ("ReverseOrientation", World),
        Directive::ObjectBegin(..) => ("ObjectBegin", World),
        Directive::ObjectEnd => ("ObjectEnd", World),
        Directive::ObjectInstance(..) => ("ObjectInstance", World),
        _ => ("", Anywhere),
    }
}

impl PbrtLoader {
    /// Refuses `d` outside its block; records `WorldBegin` and the opening
    /// and closing of attribute and transform blocks.
    pub(super) fn check_block(&mut self, d: &Directive, loc: &Loc) -> Result<(), ParseError> {
        let (name, block) = block_of(d);
        match (block, self.world_begin.is_some()) {
            (Block::Options, true) => {
                let first = self.world_begin.as_ref().map(ToString::to_string);
                let first = first.unwrap_or_default();
                let msg = if name == "WorldBegin" {
                    format!("a second WorldBegin (the first is at {first})")
                } else {
                    format!(
                        "{name} is not allowed after WorldBegin (at {first}); it belongs before it"
                    )
                };
                return Err(ParseError::scene(loc, msg));
            }
            (Block::World, false) => {
                let msg = format!("{name} is not allowed before WorldBegin");
                return Err(ParseError::scene(loc, msg));
            }
            _ => {}
        }
        match d {
            Directive::WorldBegin => self.world_begin = Some(loc.clone()),
            Directive::AttributeBegin => self.open_blocks.push(("AttributeBegin", loc.clone())),
            Directive::TransformBegin => self.open_blocks.push(("TransformBegin", loc.clone())),
            Directive::AttributeEnd | Directive::TransformEnd => {
                self.open_blocks.pop();
            }
            _ => {}
        }
        Ok(())
    }

    /// The end of the last file: it must have reached `WorldBegin` and
    /// closed every attribute and transform block.
    pub(super) fn check_end_of_files(&self) -> Result<(), ParseError> {
        if self.world_begin.is_none() {
            let msg = format!(
                "{}: the file ends before WorldBegin (a pbrt-v4 scene needs one)",
                self.main_file.display()
            );
            return Err(ParseError::without_loc(ErrorKind::Scene, msg));
        }
        if let Some((name, loc)) = self.open_blocks.last() {
            let end = name.replace("Begin", "End");
            let msg = format!("{name} is never closed (the file ends without its {end})");
            return Err(ParseError::scene(loc, msg));
        }
        Ok(())
    }
}
