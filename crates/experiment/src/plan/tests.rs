//! Tests of the plan's units and of `plan.json`.

use std::path::Path;

use lowdisc::catalog::{SamplerConfig, SamplerName};

use lowdisc_render::integrator::PathIntegrator;
use lowdisc_render::render::SampleRange;

use super::file::PlanFile;
use super::*;

fn config() -> ExperimentConfig {
    ExperimentConfig {
        scene: None,
        samplers: vec![SamplerName::Sobol, SamplerName::Halton],
        net: lowdisc::net::Net::SOBOL,
        spp: 4,
        runs: 3,
        resolution: [10, 10],
        ref_spp: 64,
        conv_max: 8,
        conv_res: [5, 5],
        conv_seeds: 1,
        conv_ref_spp: 32,
        envmap: None,
        approximate: false,
        threshold: 0.3,
        max_depth: 5,
        threads: None,
        spectral: false,
        unit_samples: None,
        out: "out".into(),
        command: vec!["lowdisc".into(), "experiment".into()],
        preset: None,
        emitter_border: 3,
        blur_sigma: 1.1,
    }
}

#[test]
fn the_units_count_every_stage_once() {
    let c = config();
    // Runs: 2 samplers x 3 runs x 400; sweep: 7 x 3 x 400; convergence:
    // 2 x 25 x 15; references: 100 x 64 and 25 x 32.
    let runs = 2 * 3 * 400 + 7 * 3 * 400 + 2 * 25 * 15;
    assert_eq!(Plan::new(c.clone(), 0, [true, true]).samples(), runs);
    assert_eq!(
        Plan::new(c.clone(), 0, [false, true]).samples(),
        runs + 6400
    );
    let all = Plan::new(c.clone(), 0, [false, false]);
    assert_eq!(all.samples(), runs + 6400 + 800);
    // 2 references, 6 runs, 21 sweep renders, 2 x 4 convergence points.
    assert_eq!(all.units.len(), 2 + 6 + 21 + 8);
    assert!(all.units.iter().enumerate().all(|(i, u)| u.index == i));
    // One reference serves both when resolution and spp agree.
    let mut same = c;
    same.conv_res = same.resolution;
    same.conv_ref_spp = same.ref_spp;
    let runs_same = 2 * 3 * 400 + 7 * 3 * 400 + 2 * 100 * 15;
    assert_eq!(
        Plan::new(same, 0, [false, false]).samples(),
        runs_same + 6400
    );
}

#[test]
fn the_units_come_in_the_order_of_the_one_machine_run() {
    let plan = Plan::new(config(), 0, [false, false]);
    let w: Vec<String> = plan.units.iter().map(|u| u.work.describe()).collect();
    assert_eq!(w[0], "reference main");
    assert_eq!(w[1], "run sobol seed 0");
    assert_eq!(w[6], "run halton seed 2");
    assert_eq!(w[7], "sweep threshold 0 seed 0");
    assert_eq!(w[27], "sweep threshold 1 seed 2");
    assert_eq!(w[28], "reference convergence");
    assert_eq!(w[29], "convergence sobol seed 0 1 spp");
    assert_eq!(w[36], "convergence halton seed 0 8 spp");
    let sweep = plan.units[10].options(&plan.config).unwrap();
    assert_eq!(sweep.sampler.name, SamplerName::PaperRepro);
    assert_eq!(sweep.sampler.threshold, 0.1);
    assert_eq!(plan.units[28].resolution(&plan.config), [5, 5]);
    assert_eq!(
        plan.units[28].options(&plan.config).unwrap().sampler.spp,
        32
    );
}

/// A unit's options are the experiment's settings and the unit's own,
/// the defaults filling the rest, and a bad flag is named.
#[test]
fn a_units_options_resolve_the_experiments_settings_and_its_own() {
    let mut c = config();
    c.threads = Some(2);
    c.spectral = true;
    let plan = Plan::new(c.clone(), 0, [false, false]);
    let expected = RenderOptions {
        sampler: SamplerConfig {
            seed: 2,
            spp: 4,
            threshold: 0.3,
            ..SamplerConfig::new(SamplerName::Halton)
        },
        integrator: PathIntegrator {
            max_depth: 5,
            ..PathIntegrator::default()
        },
        threads: Some(2),
        spectral: true,
        ..RenderOptions::default()
    };
    assert_eq!(plan.units[6].work.describe(), "run halton seed 2");
    assert_eq!(plan.units[6].options(&c).unwrap(), expected);
    c.threshold = 7.0;
    let e = c.validate_ranges().unwrap_err().to_string();
    assert!(
        e.contains("--threshold: threshold 7 must lie in [0, 1]"),
        "{e}"
    );
}

#[test]
fn an_index_out_of_range_names_the_range() {
    let plan = Plan::new(config(), 0, [true, true]);
    let err = plan.unit(35).unwrap_err().to_string();
    assert_eq!(
        err,
        "unit index 35 is out of range: the plan has 35 units (0 to 34)"
    );
}

#[test]
fn plan_json_reads_back_to_the_same_plan_and_id() {
    let plan = Plan::new(config(), 0xfeed_beef_0123_4567, [false, true]);
    let file = PlanFile::new(plan, "/work".into()).unwrap();
    let text = file.to_json().unwrap();
    let back = PlanFile::parse(&text, Path::new("elsewhere")).unwrap();
    assert_eq!(back.id, file.id);
    assert_eq!(back.plan.units, file.plan.units);
    assert_eq!(back.plan.scene_hash, 0xfeed_beef_0123_4567);
    assert_eq!(back.plan.config.threshold, 0.3);
    assert_eq!(back.plan.config.blur_sigma, 1.1);
    assert_eq!(back.plan.config.out, Path::new("elsewhere"));
    assert_eq!(back.to_json().unwrap(), text);
}

#[test]
fn a_net_is_written_in_full_and_read_back_for_the_compared_samplers_only() {
    let mut c = config();
    c.samplers = vec![SamplerName::ZSobol, SamplerName::Halton];
    c.net = lowdisc::net::Net::named("onetwo").unwrap();
    let file = PlanFile::new(Plan::new(c, 1, [false, true]), "/w".into()).unwrap();
    let text = file.to_json().unwrap();
    let back = PlanFile::parse(&text, Path::new("d")).unwrap();
    assert_eq!(back.plan.config.net, file.plan.config.net);
    assert_eq!(back.id, file.id);
    let nets: Vec<_> = back
        .plan
        .units
        .iter()
        .map(|u| u.options(&back.plan.config).unwrap().sampler)
        .map(|s| (s.name, s.net.is_sobol()))
        .collect();
    assert!(nets.contains(&(SamplerName::ZSobol, false)));
    assert!(nets.contains(&(SamplerName::Halton, true)));
    assert!(
        nets.contains(&(SamplerName::SobolOwen, true)),
        "the reference"
    );
    assert!(
        nets.iter()
            .all(|&(n, sobol)| sobol != (n == SamplerName::ZSobol))
    );
    // A column changed: the matrices no longer hash to the recorded id.
    let edited = text.replacen("2147483648", "2147483649", 1);
    assert!(PlanFile::parse(&edited, Path::new("d")).is_err());
}

#[test]
fn an_edited_or_foreign_plan_is_refused() {
    let file = PlanFile::new(Plan::new(config(), 1, [true, true]), "/w".into()).unwrap();
    let text = file.to_json().unwrap();
    let edited = text.replace("\"spp\": 4", "\"spp\": 8");
    assert_ne!(edited, text);
    let err = PlanFile::parse(&edited, Path::new("d")).unwrap_err();
    assert!(
        err.to_string().contains("does not match its content"),
        "{err}"
    );
    let other = text.replace(super::file::FORMAT, "something-else");
    let err = PlanFile::parse(&other, Path::new("d")).unwrap_err();
    assert!(err.to_string().contains("not a version-3"), "{err}");
}

#[test]
fn relative_paths_start_at_the_planning_folder() {
    let mut c = config();
    c.scene = Some("scenes/a.pbrt".into());
    c.envmap = Some("/abs/sky.exr".into());
    let file = PlanFile::new(Plan::new(c, 1, [true, true]), "/work/x".into()).unwrap();
    let loading = file.loading_config();
    assert_eq!(loading.scene.unwrap(), Path::new("/work/x/scenes/a.pbrt"));
    assert_eq!(loading.envmap.unwrap(), Path::new("/abs/sky.exr"));
    // The report keeps the path as given.
    assert_eq!(file.plan.config.scene.unwrap(), Path::new("scenes/a.pbrt"));
}

/// Each convergence series is rendered once per seed, seeds in turn, and
/// the seed reaches the render's options.
#[test]
fn every_convergence_seed_is_a_series_of_its_own() {
    let mut c = config();
    c.conv_seeds = 3;
    let plan = Plan::new(c.clone(), 0, [true, true]);
    let conv: Vec<&Unit> = plan
        .units
        .iter()
        .filter(|u| matches!(u.work, Work::Convergence { .. }))
        .collect();
    // 2 samplers x 3 seeds x 4 points (1, 2, 4, 8 spp).
    assert_eq!(conv.len(), 2 * 3 * 4);
    assert_eq!(conv[4].work.describe(), "convergence sobol seed 1 1 spp");
    assert_eq!(conv[23].work.describe(), "convergence halton seed 2 8 spp");
    assert_eq!(conv[23].options(&c).unwrap().sampler.seed, 2);
    assert_eq!(conv[23].options(&c).unwrap().sampler.spp, 8);
    let one = Plan::new(config(), 0, [true, true]).samples();
    assert_eq!(plan.samples() - one, 2 * 2 * 25 * 15);
}

/// The default experiment's settings (with `config()`'s two samplers).
fn default_settings() -> ExperimentConfig {
    let mut c = config();
    (c.resolution, c.spp, c.ref_spp) = ([256, 144], 16, 1024);
    (c.conv_res, c.conv_max, c.conv_ref_spp) = ([64, 36], 1024, 8192);
    c.conv_seeds = 4;
    c
}

#[test]
fn the_default_plan_cuts_what_exceeds_2_to_the_23_samples() {
    let c = default_settings();
    assert_eq!(c.unit_budget(), 1 << 23);
    // 256x144 at 1024 spp: 2 rows of tiles (8.4 M samples) per band.
    assert_eq!(
        reference_cut(&c, Target::Main),
        Cut {
            bands: 5,
            ranges: 1
        }
    );
    // 64x36 at 8192 spp: one row of tiles is 2^23 samples, one band each.
    let conv = Cut {
        bands: 3,
        ranges: 1,
    };
    assert_eq!(reference_cut(&c, Target::Convergence), conv);
    // 64x36 at 1024 spp: 2.4 M samples.
    assert_eq!(convergence_cut(&c, 1024), Cut::WHOLE);
    let plan = Plan::new(c.clone(), 0, [false, false]);
    let w: Vec<String> = plan.units.iter().map(|u| u.work.describe()).collect();
    assert_eq!(w[4], "reference main band 5 of 5");
    let conv_at = w
        .iter()
        .position(|d| d.starts_with("reference conv"))
        .unwrap();
    assert_eq!(w[conv_at], "reference convergence band 1 of 3");
    assert_eq!(w[conv_at + 2], "reference convergence band 3 of 3");
    // The last band is the last 4 rows.
    let last = &plan.units[conv_at + 2];
    assert_eq!(last.samples(&c), 64 * 4 * 8192);
    assert!(w.contains(&"convergence halton seed 3 1024 spp".to_string()));
    // Cutting moves no sample: the plan renders what the whole renders do.
    let whole = 256 * 144 * 1024 + 64 * 36 * 8192;
    let runs = (2 + 7) * 3 * 256 * 144 * 16 + 2 * 4 * 64 * 36 * 2047;
    assert_eq!(plan.samples(), whole + runs);
    // The cache key names the ranges: a cut with other ranges is another file.
    let key = |c: &ExperimentConfig| crate::reference::cache_file(c, Target::Convergence, 1);
    let mut finer = c.clone();
    finer.unit_samples = Some(1 << 21);
    // A row of tiles (2^23) in 4 ranges of 2^21.
    assert_eq!(reference_cut(&finer, Target::Convergence).ranges, 4);
    let fine = Plan::new(finer.clone(), 0, [false, false]);
    let last = fine
        .units
        .iter()
        .rfind(|u| u.work.describe().starts_with("reference conv"))
        .unwrap();
    assert_eq!(
        last.work.describe(),
        "reference convergence band 3 of 3 range 4 of 4"
    );
    assert_eq!(
        last.options(&finer).unwrap().sample_range(),
        SampleRange::new(6144, 8192)
    );
    assert_ne!(key(&c), key(&finer));
    finer.unit_samples = Some((1 << 23) + 1);
    assert_eq!(key(&c), key(&finer));
}

#[test]
fn the_paper_plans_longest_unit_is_a_run() {
    let mut c = default_settings();
    (c.resolution, c.runs, c.ref_spp) = ([1280, 720], 10, 4096);
    c.conv_res = [320, 180];
    let run = 1280 * 720 * 16;
    assert_eq!(c.unit_budget(), run);
    assert_eq!(
        reference_cut(&c, Target::Main),
        Cut {
            bands: 45,
            ranges: 6
        }
    );
    // 320x180 at 8192 spp: a row of tiles (41.9 M samples) per band, in 3
    // ranges.
    let conv = Cut {
        bands: 12,
        ranges: 3,
    };
    assert_eq!(reference_cut(&c, Target::Convergence), conv);
    // At 1024 spp two rows of tiles (10.5 M) fit a run, three do not; at
    // 512, five rows; at 256, eleven of the twelve (the last, 4 pixels
    // high, is budgeted as a whole row); at 128, all twelve.
    assert_eq!(
        convergence_cut(&c, 1024),
        Cut {
            bands: 6,
            ranges: 1
        }
    );
    assert_eq!(
        convergence_cut(&c, 512),
        Cut {
            bands: 3,
            ranges: 1
        }
    );
    assert_eq!(
        convergence_cut(&c, 256),
        Cut {
            bands: 2,
            ranges: 1
        }
    );
    assert_eq!(convergence_cut(&c, 128), Cut::WHOLE);
    let plan = Plan::new(c.clone(), 0, [false, false]);
    let longest = plan.units.iter().map(|u| u.samples(&c)).max().unwrap();
    assert_eq!(longest, run);
    // 270 + 36 reference pieces, 20 runs, 70 sweep renders and 2 samplers
    // x 4 seeds x (8 + 2 + 3 + 6) convergence pieces.
    assert_eq!(plan.units.len(), 270 + 36 + 20 + 70 + 2 * 4 * 19);
}
