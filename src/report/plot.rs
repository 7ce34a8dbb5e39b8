//! The reports' figures: a figure's data (a [`Table`] of named columns, written as CSV and
//! JSON) and its panels, drawn stacked into one SVG or PNG (plotters, the embedded font):
//! titles wrapped to the figure's width, each panel's legend in a column beside its chart
//! (off the data), point labels placed where they overlap no other label.

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
    /// Short dashes.
    Dotted,
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

/// The width of a panel's chart; its legend goes to the right of it, off the data.
const WIDTH: u32 = 900;
const PANEL_HEIGHT: u32 = 420;
const TITLE_SIZE: u32 = 18;
const CAPTION_SIZE: u32 = 16;
const LEGEND_SIZE: u32 = 12;
const LABEL_SIZE: u32 = 11;
/// Pixels around a title's lines and a legend's rows.
const PAD: u32 = 8;

/// `text`'s width and height in the embedded font at `size` pixels (0 if it cannot tell).
fn text_size(text: &str, size: u32) -> (u32, u32) {
    register_font();
    ("sans-serif", size)
        .into_font()
        .box_size(text)
        .unwrap_or((0, 0))
}

/// `text` broken at spaces into lines at most `width` pixels wide at `size`, so that a long
/// title wraps instead of running off the figure.
fn wrap(text: &str, size: u32, width: u32) -> Vec<String> {
    let mut lines: Vec<String> = vec![];
    for word in text.split(' ') {
        match lines.last_mut() {
            Some(l) if text_size(&format!("{l} {word}"), size).0 <= width => {
                l.push(' ');
                l.push_str(word);
            }
            _ => lines.push(word.to_string()),
        }
    }
    lines
}

/// The height of `text`'s lines wrapped into `width` at `size`, with the padding.
fn title_height(text: &str, size: u32, width: u32) -> u32 {
    PAD + wrap(text, size, width).len() as u32 * (size + 6)
}

/// The legend column's width: the figure's longest series label beside its glyph.
fn legend_width(f: &Figure) -> u32 {
    let longest = f
        .panels
        .iter()
        .flat_map(|p| &p.series)
        .map(|s| text_size(&s.label, LEGEND_SIZE).0)
        .max()
        .unwrap_or(0);
    longest + 3 * PAD + 30
}

/// Each panel's height: its chart and its caption's lines.
fn panel_height(p: &Panel) -> u32 {
    PANEL_HEIGHT + title_height(&p.title, CAPTION_SIZE, WIDTH - 2 * PAD)
}

/// Writes `f` to `path`, SVG or PNG by its extension.
pub fn draw(f: &Figure, path: &Path) -> Result<(), String> {
    register_font();
    let width = WIDTH + legend_width(f);
    let height = title_height(&f.title, TITLE_SIZE, width - 2 * PAD)
        + f.panels.iter().map(panel_height).sum::<u32>();
    let size = (width, height);
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

type Area<DB> = DrawingArea<DB, plotters::coord::Shift>;

/// Draws `text` wrapped and centred at the top of `area`; returns the area below it.
fn titled<DB: DrawingBackend>(area: &Area<DB>, text: &str, size: u32) -> Result<Area<DB>, String> {
    let e = |e: DrawingAreaErrorKind<DB::ErrorType>| e.to_string();
    let width = area.dim_in_pixel().0;
    let font = ("sans-serif", size).into_font();
    for (i, line) in wrap(text, size, width - 2 * PAD).iter().enumerate() {
        let x = (width as i32 - text_size(line, size).0 as i32) / 2;
        let y = (PAD / 2 + i as u32 * (size + 6)) as i32;
        area.draw(&Text::new(line.clone(), (x, y), font.clone()))
            .map_err(e)?;
    }
    Ok(area
        .split_vertically(title_height(text, size, width - 2 * PAD))
        .1)
}

fn draw_on<DB: DrawingBackend>(root: Area<DB>, f: &Figure) -> Result<(), String> {
    let e = |e: DrawingAreaErrorKind<DB::ErrorType>| e.to_string();
    root.fill(&WHITE).map_err(e)?;
    let mut rest = titled(&root, &f.title, TITLE_SIZE)?;
    for p in &f.panels {
        let (panel, below) = rest.split_vertically(panel_height(p));
        rest = below;
        let (area, legend_area) = titled(&panel, &p.title, CAPTION_SIZE)?.split_horizontally(WIDTH);
        let (xr, yr) = (
            range(p, |q| q.0, p.log_x, false),
            range(p, |q| q.1, p.log_y, true),
        );
        match (p.log_x, p.log_y) {
            (false, false) => chart(&area, p, xr, yr),
            (false, true) => chart(&area, p, xr, yr.log_scale()),
            (true, false) => chart(&area, p, xr.log_scale(), yr),
            (true, true) => chart(&area, p, xr.log_scale(), yr.log_scale()),
        }?;
        legend(&legend_area, p)?;
    }
    root.present().map_err(e)
}

/// Draws a series' glyph in its legend from (x, y) rightwards: a line (a dashed one is two
/// segments), or a dot for markers only.
fn glyph<DB: DrawingBackend>(
    area: &Area<DB>,
    s: &Series,
    (x, y): (i32, i32),
) -> Result<(), String> {
    let e = |e: DrawingAreaErrorKind<DB::ErrorType>| e.to_string();
    let color = PALETTE[s.color % PALETTE.len()];
    // segments 0..a and b..20, and a dot's radius
    let (a, b, dot) = match s.style {
        Style::Solid => (8, 8, 0),
        Style::Dashed => (8, 13, 0),
        Style::Dotted => (3, 17, 2),
        Style::Points => (0, 20, 5),
    };
    area.draw(
        &(EmptyElement::at((x, y))
            + PathElement::new(vec![(0, 0), (a, 0)], color.stroke_width(2))
            + PathElement::new(vec![(b, 0), (20, 0)], color.stroke_width(2))
            + Circle::new((10, 0), dot, color.filled())),
    )
    .map_err(e)
}

/// The panel's legend in its own column beside the chart (so that it covers no data),
/// aligned with the chart's top.
fn legend<DB: DrawingBackend>(area: &Area<DB>, p: &Panel) -> Result<(), String> {
    let e = |e: DrawingAreaErrorKind<DB::ErrorType>| e.to_string();
    let row = (LEGEND_SIZE + 6) as i32;
    let (x0, y0) = (PAD as i32, 12);
    let w = area.dim_in_pixel().0 as i32 - 2 * PAD as i32;
    let h = row * p.series.len() as i32 + PAD as i32;
    area.draw(&Rectangle::new(
        [(x0, y0), (x0 + w, y0 + h)],
        BLACK.mix(0.4),
    ))
    .map_err(e)?;
    let font = ("sans-serif", LEGEND_SIZE).into_font();
    for (i, s) in p.series.iter().enumerate() {
        let y = y0 + PAD as i32 / 2 + i as i32 * row + row / 2;
        glyph(area, s, (x0 + PAD as i32, y))?;
        let text_y = y - text_size(&s.label, LEGEND_SIZE).1 as i32 / 2 - 1;
        area.draw(&Text::new(
            s.label.clone(),
            (x0 + PAD as i32 + 28, text_y),
            font.clone(),
        ))
        .map_err(e)?;
    }
    Ok(())
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
        match s.style {
            Style::Solid => c.draw_series(LineSeries::new(pts.clone(), style)),
            Style::Dashed => c.draw_series(DashedLineSeries::new(pts.clone(), 6, 4, style)),
            Style::Dotted => c.draw_series(DashedLineSeries::new(pts.clone(), 2, 4, style)),
            Style::Points => c.draw_series(pts.clone().map(|q| Circle::new(q, 5, color.filled()))),
        }
        .map_err(e)?;
        c.draw_series(pts.map(|q| Circle::new(q, 3, color.filled())))
            .map_err(e)?;
    }
    let px = |q: &(f64, f64)| c.backend_coord(q);
    point_labels(area, p, px, c.plotting_area().get_pixel_range())?;
    Ok(())
}

/// A box in pixels: left, top, right, bottom.
type Boxed = (i32, i32, i32, i32);

fn overlap(a: &Boxed, b: &Boxed) -> bool {
    a.0 < b.2 && b.0 < a.2 && a.1 < b.3 && b.1 < a.3
}

/// The pixels a panel's data covers (`px`: a point's pixel): its markers, and its lines
/// every 3 pixels.
fn data_boxes(p: &Panel, px: impl Fn(&(f64, f64)) -> (i32, i32)) -> Vec<Boxed> {
    let mut boxes = vec![];
    for s in &p.series {
        let pts: Vec<(i32, i32)> = s
            .points
            .iter()
            .filter(|q| q.0.is_finite() && q.1.is_finite())
            .map(&px)
            .collect();
        boxes.extend(pts.iter().map(|&(x, y)| (x - 5, y - 5, x + 5, y + 5)));
        if s.style == Style::Points {
            continue;
        }
        for w in pts.windows(2) {
            let (dx, dy) = (w[1].0 - w[0].0, w[1].1 - w[0].1);
            let n = (dx.abs().max(dy.abs()) / 3).max(1);
            boxes.extend((1..n).map(|i| {
                let (x, y) = (w[0].0 + dx * i / n, w[0].1 + dy * i / n);
                (x - 1, y - 1, x + 1, y + 1)
            }));
        }
    }
    boxes
}

/// Writes the series' point labels beside their points (`px`: a point's pixel): each takes
/// the first place around its point (right, left, above, below, the corners) that overlaps
/// no label already placed, stays inside the plot (`plot`: its pixel ranges) and covers the
/// least data ([`data_boxes`]); a label with no such place is left out (the figure's table
/// holds it).
fn point_labels<DB: DrawingBackend>(
    area: &Area<DB>,
    p: &Panel,
    px: impl Fn(&(f64, f64)) -> (i32, i32),
    plot: (std::ops::Range<i32>, std::ops::Range<i32>),
) -> Result<(), String> {
    let e = |e: DrawingAreaErrorKind<DB::ErrorType>| e.to_string();
    let finite = |q: &&(f64, f64)| q.0.is_finite() && q.1.is_finite();
    let data = data_boxes(p, &px);
    let (base_x, base_y) = area.get_base_pixel();
    let mut placed: Vec<Boxed> = vec![];
    for s in &p.series {
        let font = ("sans-serif", LABEL_SIZE)
            .into_font()
            .color(&PALETTE[s.color % PALETTE.len()]);
        for (q, text) in s.points.iter().zip(&s.labels) {
            let text = text.trim();
            if text.is_empty() || !finite(&q) {
                continue;
            }
            let (x, y) = px(q);
            let (w, h) = text_size(text, LABEL_SIZE);
            let (w, h, r) = (w as i32, h as i32, 7);
            let places = [
                (r, -h / 2),
                (-r - w, -h / 2),
                (-w / 2, -r - h),
                (-w / 2, r),
                (r - 2, -h - 2),
                (r - 2, 2),
                (-w - r + 2, -h - 2),
                (-w - r + 2, 2),
            ]
            .map(|(dx, dy)| (x + dx, y + dy, x + dx + w, y + dy + h));
            let inside = |b: &Boxed| {
                b.0 >= plot.0.start && b.2 <= plot.0.end && b.1 >= plot.1.start && b.3 <= plot.1.end
            };
            let best = places
                .into_iter()
                .filter(|b| inside(b) && !placed.iter().any(|o| overlap(b, o)))
                .min_by_key(|b| data.iter().filter(|m| overlap(b, m)).count());
            if let Some(b) = best {
                placed.push(b);
                area.draw(&Text::new(
                    text.to_string(),
                    (b.0 - base_x, b.1 - base_y),
                    font.clone(),
                ))
                .map_err(e)?;
            }
        }
    }
    Ok(())
}
