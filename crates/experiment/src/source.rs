//! The units' renders as the assembly reads them: what a unit leaves
//! ([`UnitOutput`]), where it comes from ([`UnitSource`]: rendered in this
//! process or read from a unit's file), what it is measured with
//! ([`Measures`]), the plan's units in order ([`Cursor`]) and the pieces of a
//! cut render joined into one image ([`join_cut`]).

use anyhow::{Result, bail};
use lowdisc_image::RgbImage;
use lowdisc_render::view::{View, ViewSpec};
use lowdisc_split::RenderPart;

use crate::cut::{Cut, Joiner, Piece};
use crate::plan::{Plan, Unit, Work};
use crate::progress::Stage;
use crate::quality::Evaluator;
use crate::subject::Subject;

/// What a unit's render leaves: an image, or (a piece of a cut render,
/// [`Work::keeps_sums`]) its pixels' exact sums.
#[derive(Debug, Clone)]
pub enum Rendered {
    /// The image of a whole render.
    Image(RgbImage),
    /// The sums of a piece, to be merged with the other pieces.
    Sums(RenderPart),
}

/// The render of one unit.
#[derive(Debug, Clone)]
pub struct UnitOutput {
    /// What it left.
    pub rendered: Rendered,
    /// The render's time in seconds (what `results.json` reports).
    pub render_time_s: f64,
}

impl UnitOutput {
    /// The image of a whole render.
    pub(crate) fn into_image(self, unit: &Unit) -> Result<RgbImage> {
        match self.rendered {
            Rendered::Image(image) => Ok(image),
            Rendered::Sums(_) => bail!("unit {} left sums, not an image", unit.index),
        }
    }

    /// The sums of a piece.
    pub(crate) fn into_sums(self, unit: &Unit) -> Result<RenderPart> {
        match self.rendered {
            Rendered::Sums(part) => Ok(part),
            Rendered::Image(_) => bail!("unit {} left an image, not sums", unit.index),
        }
    }
}

/// Where the assembly gets each unit's render from. `output` reports the
/// render's samples (and rays, when it traced them) to `stage` (by
/// [`Stage::finished_render`]).
pub trait UnitSource {
    /// The render of `unit`.
    fn output(&mut self, unit: &Unit, stage: &Stage) -> Result<UnitOutput>;
}

/// What renders are measured with: the scene's metrics at the plan's
/// resolution and its view (whose film turns merged sums into images).
pub struct Measures {
    /// The masked, blurred and FLIP metrics.
    pub evaluator: Evaluator,
    /// The scene's view.
    pub view: ViewSpec,
}

impl Measures {
    /// The measures of the experiment `plan` on `subject`, at the plan's
    /// resolution.
    pub fn new(plan: &Plan, subject: &Subject) -> Result<Measures> {
        let c = &plan.config;
        let view = subject.view_at(c.resolution)?;
        Ok(Measures {
            evaluator: Evaluator::new(&subject.scene, &view, c.emitter_border, c.blur_sigma)?,
            view: subject.view.clone(),
        })
    }

    /// The view at `resolution`.
    pub(crate) fn view_at(&self, resolution: [u32; 2]) -> Result<View> {
        Ok(View::new(&self.view, resolution)?)
    }
}

/// The plan's units in order; each step of the assembly takes the next one
/// and checks that it is the render it expects.
pub(crate) struct Cursor<'a> {
    units: std::slice::Iter<'a, Unit>,
}

impl<'a> Cursor<'a> {
    /// The cursor before the first unit of `plan`.
    pub(crate) fn new(plan: &'a Plan) -> Cursor<'a> {
        Cursor {
            units: plan.units.iter(),
        }
    }

    /// The unit of `work`, the next in the plan.
    pub(crate) fn next(&mut self, work: Work) -> Result<&'a Unit> {
        match self.units.next() {
            Some(u) if u.work == work => Ok(u),
            Some(u) => bail!(
                "unit {} is `{}`, expected `{}`",
                u.index,
                u.work.describe(),
                work.describe()
            ),
            None => bail!("the plan has no unit `{}`", work.describe()),
        }
    }

    /// Checks that every unit of the plan was used.
    pub(crate) fn finish(mut self) -> Result<()> {
        match self.units.next() {
            Some(u) => bail!("unit {} (`{}`) is not used", u.index, u.work.describe()),
            None => Ok(()),
        }
    }
}

/// The image of a render cut into `cut`, whose pieces are the next units
/// of `cursor` (the unit of each piece is `work(piece)`), as the film of
/// `view` (spectral or not), and the sum of the pieces' render times.
pub(crate) fn join_cut(
    cursor: &mut Cursor,
    source: &mut dyn UnitSource,
    stage: &Stage,
    cut: Cut,
    work: &dyn Fn(Piece) -> Work,
    view: &View,
    spectral: bool,
) -> Result<(RgbImage, f64)> {
    let mut joiner = Joiner::new();
    let mut time_s = 0.0;
    for piece in cut.pieces() {
        let unit = cursor.next(work(piece))?;
        let out = source.output(unit, stage)?;
        time_s += out.render_time_s;
        let name = format!("unit {} ({})", unit.index, unit.work.describe());
        joiner.push(piece, name, out.into_sums(unit)?)?;
    }
    Ok((joiner.finish(view, spectral)?, time_s))
}
