//! The reports' figures: a figure's data (a [`Table`] of named columns, written as CSV and
//! JSON) and its panels, drawn stacked into one SVG or PNG (plotters, the embedded font), the
//! legend placed where the lines leave room.

use plotters::coord::ranged1d::{AsRangedCoord, ValueFormatter};
use plotters::prelude::*;
use serde::ser::SerializeMap;
use serde::Serialize;
use std::path::{Path, PathBuf};

/// A table cell.
#[derive(Clone, Debug, PartialEq, Serialize)]
#[serde(untagged)]
pub enum Cell {
    Text(String),
    Int(u64),
    Num(f64),
    /// No value (the parry peer without the feature).
    None,
}

impl Cell {
    fn csv(&self) -> String {
        match self {
            Cell::Text(s) => s.clone(),
            Cell::Int(i) => i.to_string(),
            Cell::Num(x) => format!("{x}"),
            Cell::None => String::new(),
        }
    }
}

/// A figure's data: named columns, one row per plotted point (and series).
#[derive(Clone, Debug, Default)]
pub struct Table {
    pub columns: Vec<&'static str>,
    pub rows: Vec<Vec<Cell>>,
}

impl Table {
    pub fn csv(&self) -> String {
        let mut s = self.columns.join(",") + "\n";
        for r in &self.rows {
            s += &r.iter().map(Cell::csv).collect::<Vec<_>>().join(",");
            s.push('\n');
        }
        s
    }

    /// The rows as JSON objects, keys in column order.
    pub fn json(&self) -> String {
        struct Row<'a>(&'a [&'static str], &'a [Cell]);
        impl Serialize for Row<'_> {
            fn serialize<S: serde::Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
                let mut m = s.serialize_map(Some(self.0.len()))?;
                for (k, v) in self.0.iter().zip(self.1) {
                    m.serialize_entry(k, v)?;
                }
                m.end()
            }
        }
        let rows: Vec<Row> = self.rows.iter().map(|r| Row(&self.columns, r)).collect();
        serde_json::to_string_pretty(&rows).expect("serialisable") + "\n"
    }
}

/// One line of a panel.
#[derive(Clone, Debug)]
pub struct Series {
    pub label: String,
    /// Index into the palette (one colour per mesh, or per distance).
    pub color: usize,
    pub style: Style,
    pub points: Vec<(f64, f64)>,
    /// A label beside each point (none if empty).
    pub labels: Vec<String>,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Style {
    Solid,
    Dashed,
    /// Markers only.
    Points,
}

/// One chart of a figure; a figure's panels are stacked top to bottom.
#[derive(Clone, Debug)]
pub struct Panel {
    pub title: String,
    pub x_label: &'static str,
    pub y_label: &'static str,
    pub log_x: bool,
    pub log_y: bool,
    pub series: Vec<Series>,
}

/// A figure: file stem, title, panels, data.
#[derive(Clone, Debug)]
pub struct Figure {
    pub stem: &'static str,
    pub title: String,
    pub panels: Vec<Panel>,
    pub table: Table,
}

pub fn write_text(p: &Path, text: &str) -> Result<(), String> {
    std::fs::write(p, text).map_err(|e| format!("{}: {e}", p.display()))
}

/// Makes the directory `out` for figures (and its parents), before the run that fills it:
/// an error names the path and why (a file there, no permission).
pub fn output_dir(out: &Path) -> Result<(), String> {
    std::fs::create_dir_all(out).map_err(|e| {
        format!(
            "{}: cannot make the output directory ({e}): give a directory's path",
            out.display()
        )
    })
}

/// Writes `<stem>.csv`, `.json`, `.svg` and `.png` of `f` into `out` (which must exist);
/// returns the paths.
pub fn write_figure(f: &Figure, out: &Path) -> Result<Vec<PathBuf>, String> {
    let p = |ext: &str| out.join(format!("{}.{ext}", f.stem));
    write_text(&p("csv"), &f.table.csv())?;
    write_text(&p("json"), &f.table.json())?;
    draw(f, &p("svg"))?;
    draw(f, &p("png"))?;
    Ok(["csv", "json", "svg", "png"].map(p).to_vec())
}

pub const PALETTE: [RGBColor; 9] = [
    RGBColor(31, 119, 180),
    RGBColor(214, 39, 40),
    RGBColor(44, 160, 44),
    RGBColor(148, 103, 189),
    RGBColor(255, 127, 14),
    RGBColor(23, 190, 207),
    RGBColor(140, 86, 75),
    RGBColor(227, 119, 194),
    RGBColor(70, 70, 70),
];

/// The embedded font (Liberation Sans, SIL OFL 1.1, assets/fonts/): PNG text needs no font
/// installed on the machine.
fn register_font() {
    static ONCE: std::sync::Once = std::sync::Once::new();
    ONCE.call_once(|| {
        let bytes: &'static [u8] = include_bytes!("../../assets/fonts/LiberationSans-Regular.ttf");
        plotters::style::register_font("sans-serif", FontStyle::Normal, bytes)
            .unwrap_or_else(|_| panic!("the embedded font is valid"));
    });
}

const WIDTH: u32 = 900;
const PANEL_HEIGHT: u32 = 420;

/// Writes `f` to `path`, SVG or PNG by its extension.
pub fn draw(f: &Figure, path: &Path) -> Result<(), String> {
    register_font();
    let size = (WIDTH, 40 + PANEL_HEIGHT * f.panels.len() as u32);
    let err = |e: String| format!("{}: {e}", path.display());
    if path.extension().is_some_and(|e| e == "svg") {
        return draw_on(SVGBackend::new(path, size).into_drawing_area(), f).map_err(err);
    }
    let mut rgb = vec![0u8; 3 * (size.0 * size.1) as usize];
    draw_on(
        BitMapBackend::with_buffer(&mut rgb, size).into_drawing_area(),
        f,
    )
    .map_err(err)?;
    write_png(path, size, &rgb).map_err(|e| err(e.to_string()))
}

/// PNG at the best compression, with a palette where the image has at most 256 colours
/// (the figures are committed to docs/: plotters' own encoder writes them 2-3 times larger).
fn write_png(path: &Path, (w, h): (u32, u32), rgb: &[u8]) -> Result<(), png::EncodingError> {
    let mut palette: Vec<[u8; 3]> = vec![];
    let mut index = std::collections::HashMap::new();
    let mut indexed = Vec::with_capacity(rgb.len() / 3);
    for px in rgb.chunks_exact(3) {
        let c = [px[0], px[1], px[2]];
        let i = *index.entry(c).or_insert_with(|| {
            palette.push(c);
            palette.len() - 1
        });
        indexed.push(i);
    }
    let file = std::io::BufWriter::new(std::fs::File::create(path)?);
    let mut enc = png::Encoder::new(file, w, h);
    enc.set_compression(png::Compression::Best);
    enc.set_adaptive_filter(png::AdaptiveFilterType::Adaptive);
    if palette.len() <= 256 {
        enc.set_color(png::ColorType::Indexed);
        enc.set_palette(palette.concat());
        let bytes: Vec<u8> = indexed.iter().map(|&i| i as u8).collect();
        enc.write_header()?.write_image_data(&bytes)
    } else {
        enc.set_color(png::ColorType::Rgb);
        enc.write_header()?.write_image_data(rgb)
    }
}

fn draw_on<DB: DrawingBackend>(
    root: DrawingArea<DB, plotters::coord::Shift>,
    f: &Figure,
) -> Result<(), String> {
    let e = |e: DrawingAreaErrorKind<DB::ErrorType>| e.to_string();
    root.fill(&WHITE).map_err(e)?;
    let root = root.titled(&f.title, ("sans-serif", 18)).map_err(e)?;
    for (area, p) in root.split_evenly((f.panels.len(), 1)).iter().zip(&f.panels) {
        let (xr, yr) = (
            range(p, |q| q.0, p.log_x, false),
            range(p, |q| q.1, p.log_y, true),
        );
        match (p.log_x, p.log_y) {
            (false, false) => chart(area, p, xr, yr),
            (false, true) => chart(area, p, xr, yr.log_scale()),
            (true, false) => chart(area, p, xr.log_scale(), yr),
            (true, true) => chart(area, p, xr.log_scale(), yr.log_scale()),
        }?;
    }
    root.present().map_err(e)
}

/// The corner (or top or bottom middle) of the panel with the fewest data points, for the
/// legend.
fn legend_corner(p: &Panel) -> SeriesLabelPosition {
    let axis = |v: fn(&(f64, f64)) -> f64, log: bool, decades: bool| {
        let r = range(p, v, log, decades);
        let t = move |x: f64| if log { x.log10() } else { x };
        let (lo, hi) = (t(r.start), t(r.end));
        move |x: f64| (t(x) - lo) / (hi - lo)
    };
    let (nx, ny) = (axis(|q| q.0, p.log_x, false), axis(|q| q.1, p.log_y, true));
    // the lines' points, and 8 more along each segment
    let pts: Vec<(f64, f64)> = p
        .series
        .iter()
        .flat_map(|s| {
            let n: Vec<(f64, f64)> = s
                .points
                .iter()
                .map(|q| (nx(q.0), ny(q.1)))
                .filter(|q| q.0.is_finite() && q.1.is_finite())
                .collect();
            let segs: Vec<(f64, f64)> = n
                .windows(2)
                .flat_map(|w| {
                    (1..9).map(move |i| {
                        let f = i as f64 / 9.0;
                        (
                            w[0].0 + f * (w[1].0 - w[0].0),
                            w[0].1 + f * (w[1].1 - w[0].1),
                        )
                    })
                })
                .collect();
            n.into_iter().chain(segs)
        })
        .collect();
    // (position, its horizontal span, upper)
    let places = [
        (SeriesLabelPosition::UpperRight, (0.45, 1.0), true),
        (SeriesLabelPosition::UpperLeft, (0.0, 0.55), true),
        (SeriesLabelPosition::LowerRight, (0.45, 1.0), false),
        (SeriesLabelPosition::LowerLeft, (0.0, 0.55), false),
        (SeriesLabelPosition::UpperMiddle, (0.22, 0.78), true),
        (SeriesLabelPosition::LowerMiddle, (0.22, 0.78), false),
    ];
    let inside = |&(x, y): &(f64, f64), (lo, hi): (f64, f64), upper: bool| {
        x > lo && x < hi && (if upper { y > 0.55 } else { y < 0.45 })
    };
    let (pos, ..) = places
        .into_iter()
        .min_by_key(|&(_, span, u)| pts.iter().filter(|q| inside(q, span, u)).count())
        .expect("six places");
    pos
}

/// An axis label: no trailing zeros, exponent form from 10^5.
fn tick(v: &f64) -> String {
    match v.abs() {
        a if a >= 1e5 => format!("{v:.0e}"),
        a if a >= 10.0 => format!("{v:.0}"),
        _ => format!("{v:.2}")
            .trim_end_matches('0')
            .trim_end_matches('.')
            .to_string(),
    }
}

/// The axis range of a panel's values, with a margin; positive values only on a log axis,
/// whole decades on a log y axis (plotters labels no value below a log axis's first
/// power of ten).
fn range(
    p: &Panel,
    v: impl Fn(&(f64, f64)) -> f64,
    log: bool,
    decades: bool,
) -> std::ops::Range<f64> {
    let vals = p
        .series
        .iter()
        .flat_map(|s| s.points.iter().map(&v))
        .filter(|x| x.is_finite() && (!log || *x > 0.0));
    let (lo, hi) = vals.fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), x| {
        (lo.min(x), hi.max(x))
    });
    match (lo.is_finite(), log) {
        (false, _) => 1.0..10.0,
        (true, true) if decades => {
            10f64.powf(lo.log10().floor())..10f64.powf((hi * 1.01).log10().ceil())
        }
        (true, true) => lo / 1.5..hi * 1.5,
        (true, false) => {
            let m = ((hi - lo) * 0.05).max(1e-9);
            lo - m..hi + m
        }
    }
}

fn chart<DB: DrawingBackend, X: AsRangedCoord<Value = f64>, Y: AsRangedCoord<Value = f64>>(
    area: &DrawingArea<DB, plotters::coord::Shift>,
    p: &Panel,
    x: X,
    y: Y,
) -> Result<(), String>
where
    X::CoordDescType: ValueFormatter<f64>,
    Y::CoordDescType: ValueFormatter<f64>,
{
    let e = |e: DrawingAreaErrorKind<DB::ErrorType>| e.to_string();
    let mut c = ChartBuilder::on(area)
        .caption(&p.title, ("sans-serif", 16))
        .margin(12)
        .x_label_area_size(40)
        .y_label_area_size(70)
        .build_cartesian_2d(x, y)
        .map_err(e)?;
    c.configure_mesh()
        .x_desc(p.x_label)
        .y_desc(p.y_label)
        .label_style(("sans-serif", 13))
        .x_labels(if p.log_x { 4 } else { 10 })
        .y_labels(12)
        .x_label_formatter(&tick)
        .y_label_formatter(&tick)
        .light_line_style(WHITE.mix(0.0))
        .draw()
        .map_err(e)?;
    for s in &p.series {
        let color = PALETTE[s.color % PALETTE.len()];
        let style = color.stroke_width(2);
        let pts = s
            .points
            .iter()
            .copied()
            .filter(|q| q.0.is_finite() && q.1.is_finite());
        let ann = match s.style {
            Style::Solid => c
                .draw_series(LineSeries::new(pts.clone(), style))
                .map_err(e)?,
            Style::Dashed => c
                .draw_series(DashedLineSeries::new(pts.clone(), 6, 4, style))
                .map_err(e)?,
            Style::Points => c
                .draw_series(pts.clone().map(|q| Circle::new(q, 5, color.filled())))
                .map_err(e)?,
        };
        // the legend's line: segments 0..a and b..20 (a dashed line is two), markers only a dot
        let (a, b, dot) = match s.style {
            Style::Solid => (8, 8, 0),
            Style::Dashed => (8, 13, 0),
            Style::Points => (0, 20, 5),
        };
        ann.label(&s.label).legend(move |(x, y)| {
            EmptyElement::at((x, y))
                + PathElement::new(vec![(0, 0), (a, 0)], color.stroke_width(2))
                + PathElement::new(vec![(b, 0), (20, 0)], color.stroke_width(2))
                + Circle::new((10, 0), dot, color.filled())
        });
        let font = ("sans-serif", 11).into_font().color(&color);
        c.draw_series(
            s.points
                .iter()
                .zip(&s.labels)
                .map(|(&q, l)| Text::new(l.clone(), q, font.clone())),
        )
        .map_err(e)?;
        c.draw_series(pts.map(|q| Circle::new(q, 3, color.filled())))
            .map_err(e)?;
    }
    c.configure_series_labels()
        .position(legend_corner(p))
        .label_font(("sans-serif", 12))
        .background_style(WHITE.mix(0.85))
        .border_style(BLACK.mix(0.4))
        .draw()
        .map_err(e)?;
    Ok(())
}
