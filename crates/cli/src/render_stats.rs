//! `render --stats`: the counters of a finished render and the time of each
//! phase, printed as aligned lines (to stdout; a failed write is an error,
//! never a panic).

use std::io::Write;
use std::time::Duration;

use lowdisc_render::render::RenderOutput;
use lowdisc_render::scene::Scene;

/// Time spent in each phase.
#[derive(Debug, Default)]
pub struct Phases {
    /// Scene loading, BVH build included.
    pub load: Duration,
    /// Path tracing.
    pub render: Duration,
    /// Writing the image.
    pub write: Duration,
}

/// Prints the statistics of `out` (a render of `scene`) to `w`.
pub fn print_stats(
    mut w: impl Write,
    scene: &Scene,
    out: &RenderOutput,
    phases: &Phases,
) -> std::io::Result<()> {
    let s = &out.stats;
    let b = scene.bvh_stats();
    writeln!(w, "primitives        {}", scene.prim_count())?;
    writeln!(w, "lights            {}", scene.lights().len())?;
    writeln!(w, "{b}")?;
    writeln!(w, "samples           {}", s.samples)?;
    writeln!(w, "rays traced       {}", s.rays)?;
    let rate = s.rays_per_second();
    writeln!(w, "rays/s            {rate:.0} ({:.2} M)", rate / 1e6)?;
    writeln!(w, "nonfinite samples {}", s.nonfinite_samples)?;
    writeln!(w, "threads           {}", s.threads)?;
    let build = b.build_time.as_secs_f64();
    let load = (phases.load.as_secs_f64() - build).max(0.0);
    writeln!(w, "time load         {load:.3} s")?;
    writeln!(w, "time build (BVH)  {build:.3} s")?;
    writeln!(w, "time render       {:.3} s", phases.render.as_secs_f64())?;
    writeln!(w, "time write        {:.3} s", phases.write.as_secs_f64())?;
    w.flush()
}
