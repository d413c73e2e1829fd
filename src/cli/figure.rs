//! `pounding figure`: the paper's figures and the explorer's scenes as SVG
//! or PNG files (drawn by [`crate::figure`]).

use std::path::{Path, PathBuf};
use std::time::Instant;

use clap::Args;

use super::CliError;
use super::figure_risk::{self, RiskArgs};
use super::params::ParamArgs;
use super::spectrum::SpectrumPlan;
use crate::figure::{self, FigureError, FigureName, Format, Options, Scene, SpectrumInput};
use crate::model::Method;

/// Default canvas, pixels.
const DEFAULT_SIZE: (u32, u32) = (1200, 900);

#[derive(Debug, Clone, Default, Args)]
pub struct FigureArgs {
    /// fig3 … fig10 (the paper's), a scene (history, loops, contact-laws,
    /// spectrum, map), a suite study (ida, fragility, separation), or `all`.
    #[arg(value_name = "NAME")]
    pub name: String,
    /// Output file [default: NAME.FORMAT]; with `all`, a directory [default: figures].
    #[arg(long, value_name = "FILE|DIR")]
    pub out: Option<PathBuf>,
    /// svg or png [default: the extension of --out, else svg; `all` writes both].
    #[arg(long, value_name = "svg|png")]
    pub format: Option<String>,
    /// Canvas width in pixels (SVG user units).
    #[arg(long, value_name = "W")]
    pub width: Option<String>,
    /// Canvas height in pixels.
    #[arg(long, value_name = "H")]
    pub height: Option<String>,
    /// The Π_ω1 grid of a spectrum figure START:STOP:STEP [default: the preset's, else 0.1:3.0:0.01].
    #[arg(long, value_name = "START:STOP:STEP", allow_hyphen_values = true)]
    pub omega1: Option<String>,
    /// Frequency ratio μ of the spectrum scene.
    #[arg(long, value_name = "X", allow_hyphen_values = true)]
    pub mu: Option<String>,
    /// One spectrum-scene curve per value of a key, e.g. gap=0.2,1.5,inf.
    #[arg(long, value_name = "KEY=V1,V2,...")]
    pub family: Option<String>,
    #[command(flatten)]
    pub params: ParamArgs,
    /// The suite study of ida, fragility and separation.
    #[command(flatten)]
    pub risk: RiskArgs,
    /// The row for `figure buildings`, and for `ida`, `fragility` and
    /// `separation` with `--buildings` (SPEC §13).
    #[command(flatten)]
    pub row: super::buildings::BuildingsArgs,
    /// `figure map --buildings`: the retrofit map's axes, any two keys
    /// `--set` takes, as `pounding map --buildings` takes them.
    #[arg(long, value_name = "KEY=START:STOP:STEP", allow_hyphen_values = true)]
    pub x: Option<String>,
    #[arg(long, value_name = "KEY=START:STOP:STEP", allow_hyphen_values = true)]
    pub y: Option<String>,
    /// `figure match`: the target spectrum and its rule (T1 is `--period`).
    #[command(flatten)]
    pub design: super::design::TargetArgs,
    /// `figure ida|fragility|separation --buildings`: overlay the same
    /// study of each of these rows too (a retrofit, say: built-in names or
    /// paths), one colour per row, each with the first row's buildings.
    #[arg(long, value_name = "NAME|PATH", num_args = 1.., value_delimiter = ',')]
    pub compare: Vec<String>,
}

fn usage(msg: impl std::fmt::Display) -> CliError {
    CliError::Usage(msg.to_string())
}

impl From<FigureError> for CliError {
    fn from(e: FigureError) -> Self {
        match e {
            FigureError::Input(_) => CliError::Usage(e.to_string()),
            FigureError::Run(_) | FigureError::Draw(_) => CliError::Failed(e.to_string()),
        }
    }
}

fn parse_format(text: &str) -> Result<Format, CliError> {
    match text.trim().to_ascii_lowercase().as_str() {
        "svg" => Ok(Format::Svg),
        "png" => Ok(Format::Png),
        _ => Err(usage(format!("--format {text}: must be `svg` or `png`"))),
    }
}

fn parse_side(key: &str, text: Option<&str>, default: u32) -> Result<u32, CliError> {
    let Some(text) = text else {
        return Ok(default);
    };
    text.trim().parse::<u32>().map_err(|_| {
        usage(format!(
            "{key} {text}: must be an integer in [{}, {}] pixels",
            figure::render::MIN_SIDE,
            figure::render::MAX_SIDE
        ))
    })
}

/// Whether any parameter option was given (they apply to scenes only).
fn has_param_options(p: &ParamArgs) -> bool {
    p.preset.is_some()
        || !p.overrides.is_empty()
        || p.model.is_some()
        || p.dt.is_some()
        || p.cycles.is_some()
        || p.no_pounding
}

fn write(path: &Path, bytes: &[u8]) -> Result<(), CliError> {
    crate::output::write_file(path, bytes)?;
    super::output::print(&format!("wrote {}\n", path.display()))
}

pub fn execute(args: &FigureArgs) -> Result<(), CliError> {
    let compared = ["ida", "fragility", "separation"];
    if !args.compare.is_empty() && !compared.contains(&args.name.trim()) {
        return Err(usage(format!(
            "--compare applies to figure ida, fragility and separation (with --buildings), \
             not {}",
            args.name
        )));
    }
    if args.name.trim() == "buildings" {
        let long = args.risk.long.allow_long;
        return super::buildings::figure(&args.row, &args.params, args.out.as_deref(), long);
    }
    if args.name.trim() == "match" {
        return match_figure(args);
    }
    if args.name.trim() == "map" && args.row.buildings.is_some() {
        return retrofit_map(args);
    }
    if args.x.is_some() || args.y.is_some() {
        return Err(usage(format!(
            "--x and --y apply to figure map --buildings, not {}",
            args.name
        )));
    }
    if let Some(flag) = [
        ("--target", args.design.target.is_some()),
        ("--code", args.design.code.is_some()),
        ("--range", args.design.range.is_some()),
    ]
    .into_iter()
    .find_map(|(flag, given)| given.then_some(flag))
    {
        return Err(usage(format!(
            "{flag} applies to figure match, not {}",
            args.name
        )));
    }
    let all = args.name.trim() == "all";
    let name = if all {
        None
    } else {
        Some(args.name.parse::<FigureName>()?)
    };
    // `--method` is the shared option's: exact unless named (spectra run
    // thousands of cases, and exact is far faster).
    let method: Method = args
        .params
        .method
        .as_deref()
        .unwrap_or("exact")
        .parse()
        .map_err(|e| usage(format!("--method: {e}")))?;
    let size = figure::check_size(
        parse_side("--width", args.width.as_deref(), DEFAULT_SIZE.0)?,
        parse_side("--height", args.height.as_deref(), DEFAULT_SIZE.1)?,
    )?;
    let format = match (&args.format, &args.out) {
        (Some(f), _) => Some(parse_format(f)?),
        (None, Some(out)) if !all => match out.extension().and_then(|e| e.to_str()) {
            Some(ext) if ext.eq_ignore_ascii_case("png") => Some(Format::Png),
            _ => Some(Format::Svg),
        },
        _ => None,
    };
    let scene_only = name.is_none_or(FigureName::is_paper);
    if scene_only && has_param_options(&args.params) {
        return Err(usage(format!(
            "figure {}: --preset, --set, --model, --dt, --cycles and --no-pounding apply to the scenes \
             (history, loops, contact-laws, spectrum); the paper's figures use the paper's values",
            args.name
        )));
    }
    if (args.mu.is_some() || args.family.is_some()) && name != Some(FigureName::Spectrum) {
        return Err(usage(
            "--mu and --family apply to the `spectrum` scene only",
        ));
    }
    if args.omega1.is_some() && !(all || name.is_some_and(FigureName::is_spectrum)) {
        return Err(usage(format!(
            "--omega1 applies to spectrum figures (fig7–fig10, spectrum), not {}",
            args.name
        )));
    }
    let risk = name.is_some_and(FigureName::is_risk);
    if let Some(flag) = args.row.motion_flags().first() {
        let why = if risk {
            " (a suite scales its records by --level, --levels or its list)"
        } else {
            ""
        };
        return Err(usage(format!(
            "{flag} applies to figure buildings, not {}{why}",
            args.name
        )));
    }
    if !risk {
        args.risk.check_applies(name, &args.name)?;
        if args.row.buildings.is_some() {
            return Err(usage(format!(
                "--buildings applies to figure buildings, ida, fragility and separation, not {}",
                args.name
            )));
        }
    }
    let grid = match &args.omega1 {
        Some(text) => Some(text.parse().map_err(|e| usage(&e))?),
        None => None,
    };
    let mut options = Options {
        method,
        grid,
        scene: Scene::default(),
        suite: None,
    };
    if let Some(n) = name.filter(|n| n.is_risk()) {
        let buildings = args.row.buildings.as_deref();
        options.suite = Some(if args.compare.is_empty() {
            figure_risk::study(&args.risk, &args.params, buildings, n)?
        } else {
            figure_risk::compare(&args.risk, &args.params, buildings, &args.compare, n)?
        });
    } else if let Some(n) = name.filter(|n| !n.is_paper()) {
        let plan = SpectrumPlan::resolve(
            &args.params,
            args.omega1.as_deref(),
            args.mu.as_deref(),
            args.family.as_deref(),
        )?;
        options.scene = Scene {
            name: plan.preset.name.clone(),
            params: plan.params.clone(),
            spectrum: (n == FigureName::Spectrum).then(|| SpectrumInput {
                name: plan.preset.name.clone(),
                params: plan.params.clone(),
                mu: plan.mu,
                family: plan.family.clone(),
                grid: plan.grid,
            }),
        };
    }

    match name {
        Some(n) => {
            let format = format.unwrap_or(Format::Svg);
            let out = args
                .out
                .clone()
                .unwrap_or_else(|| PathBuf::from(format!("{}.{}", n.name(), format.extension())));
            let fig = figure::build(n, &options)?;
            write(&out, &figure::encode(&fig, format, size)?)
        }
        None => {
            let dir = args.out.clone().unwrap_or_else(|| PathBuf::from("figures"));
            // `all` names a directory to fill: it is made if missing (its files follow the output rules).
            if !dir.is_dir() {
                std::fs::create_dir_all(&dir).map_err(|e| {
                    CliError::Failed(format!("cannot create directory {}: {e}", dir.display()))
                })?;
            }
            let formats = match format {
                Some(f) => vec![f],
                None => vec![Format::Svg, Format::Png],
            };
            for n in FigureName::PAPER {
                let t = Instant::now();
                let fig = figure::build(n, &options)?;
                for f in &formats {
                    write(
                        &dir.join(format!("{}.{}", n.name(), f.extension())),
                        &figure::encode(&fig, *f, size)?,
                    )?;
                }
                eprintln!("{}: {:.0} ms", n.name(), t.elapsed().as_secs_f64() * 1e3);
            }
            Ok(())
        }
    }
}

/// `figure match --suite LIST --target TARGET --period T1`: the suite at its
/// list's scales (as a study runs it) against the target and the rule
/// ([`figure::matching`]).
fn match_figure(args: &FigureArgs) -> Result<(), CliError> {
    let suite = args.risk.suite.as_deref().ok_or_else(|| {
        usage("figure match: give --suite LIST (a list `records scale --out` wrote, or any suite)")
    })?;
    let period = args
        .row
        .period
        .ok_or_else(|| usage("figure match: give --period T1 (s)"))?;
    let design = args
        .design
        .required(super::design::parse_period(&period.to_string())?)?;
    let size = figure::check_size(
        parse_side("--width", args.width.as_deref(), DEFAULT_SIZE.0)?,
        parse_side("--height", args.height.as_deref(), DEFAULT_SIZE.1)?,
    )?;
    let format = match (&args.format, &args.out) {
        (Some(f), _) => parse_format(f)?,
        (None, Some(out))
            if out
                .extension()
                .is_some_and(|e| e.eq_ignore_ascii_case("png")) =>
        {
            Format::Png
        }
        _ => Format::Svg,
    };
    let members = super::records::members(suite)?;
    let matching = crate::analysis::record_scaling::check(&design, &members)
        .map_err(|e| usage(e.to_string()))?;
    let fig = figure::matching::match_figure(suite, &design, &members, &matching)?;
    let out = args
        .out
        .clone()
        .unwrap_or_else(|| PathBuf::from(format!("match.{}", format.extension())));
    write(&out, &figure::encode(&fig, format, size)?)
}

/// `figure map --buildings ROW --suite S --level L --x … --y …`: the
/// retrofit map ([`crate::figure::retrofit_map`]) of the cells `pounding
/// map --buildings` computes.
fn retrofit_map(args: &FigureArgs) -> Result<(), CliError> {
    use super::output::{Format as Out, FormatArg};
    let (Some(x), Some(y)) = (&args.x, &args.y) else {
        return Err(usage(
            "figure map --buildings: give --x KEY=START:STOP:STEP and --y KEY=START:STOP:STEP",
        ));
    };
    let r = &args.risk;
    let suite = r
        .suite
        .clone()
        .ok_or_else(|| usage("figure map --buildings: give --suite SUITE (and --level X)"))?;
    let suite_args = super::suite::SuiteArgs {
        params: args.params.clone(),
        suite,
        im: r.im.clone(),
        level: r.level.clone(),
        output: FormatArg { format: Out::Json },
        long: r.long,
        allow_unreliable: true,
        buildings: args.row.buildings.clone(),
        ..Default::default()
    };
    let Some(map) = super::map_suite::row::run(&suite_args, x, y)? else {
        return Ok(());
    };
    let level = map.level_g.map_or(String::new(), |l| {
        format!(", each scaled to {} = {l} g", map.measure)
    });
    let fig = crate::figure::retrofit_map::retrofit_map_figure(
        &crate::figure::retrofit_map::RetrofitMap {
            row: suite_args.buildings.as_deref().unwrap_or_default(),
            suite: format!("{} ({} records{level})", suite_args.suite, map.records),
            joints: &map.names.joints,
            buildings: &map.names.buildings,
            links: &map.names.links,
            x: &map.x,
            y: &map.y,
            cells: &map.cells,
        },
    );
    let format = match &args.format {
        Some(f) => parse_format(f)?,
        None => match args
            .out
            .as_ref()
            .and_then(|o| o.extension())
            .and_then(|e| e.to_str())
        {
            Some(ext) if ext.eq_ignore_ascii_case("png") => Format::Png,
            _ => Format::Svg,
        },
    };
    let size = figure::check_size(
        parse_side("--width", args.width.as_deref(), DEFAULT_SIZE.0)?,
        parse_side("--height", args.height.as_deref(), DEFAULT_SIZE.1)?,
    )?;
    let out = args
        .out
        .clone()
        .unwrap_or_else(|| PathBuf::from(format!("map.{}", format.extension())));
    write(&out, &figure::encode(&fig, format, size)?)
}
