//! PNG plots reproducing the paper's figures 2–6, drawn with plotters and an embedded
//! DejaVu Sans font (no system font libraries needed).

use ab_glyph::{Font, FontRef, GlyphId, ScaleFont};
use plotters::coord::Shift;
use plotters::prelude::*;
use plotters::style::FontStyle;
use plotters_backend::text_anchor::{HPos, VPos};
use plotters_backend::{BackendColor, BackendCoord, BackendTextStyle, DrawingErrorKind};
use std::borrow::Cow;
use std::path::{Path, PathBuf};
use std::sync::{Once, OnceLock};
use symbody::fk::Sample;
use symbody::generic::Recording;
use symbody::scenario::Run;

static FONT: &[u8] = include_bytes!("../assets/fonts/DejaVuSans.ttf");
static REGISTER: Once = Once::new();

/// Registers the embedded font as `sans-serif`; every drawing function calls it first.
pub fn register_font() {
    REGISTER.call_once(|| {
        // The font is compiled in; failing to parse it is a build defect, reported on use.
        let _ = plotters::style::register_font("sans-serif", FontStyle::Normal, FONT);
    });
}

/// One panel: a y-axis label and named series over the common time axis.
pub struct Panel<'a> {
    pub y_label: Cow<'a, str>,
    pub series: Vec<(&'a str, Vec<f64>)>,
}

const COLORS: [RGBColor; 6] = [
    RGBColor(0, 90, 181),
    RGBColor(220, 50, 32),
    RGBColor(0, 140, 70),
    RGBColor(230, 150, 0),
    RGBColor(130, 60, 170),
    RGBColor(90, 90, 90),
];

/// plotters' bitmap backend with its text drawn here. plotters 0.3.7 places each glyph's
/// ink at the pen position, dropping the glyph's left side bearing (and rounding the pen to
/// whole pixels), so a wide glyph followed by a narrow one leaves a gap: "tim e t (s)". Here
/// every glyph is positioned at its fractional pen position and its ink drawn where its own
/// outline bounds put it; the vertical placement and anchors are plotters'.
pub struct Backend<'a>(BitMapBackend<'a>);

type BackendError = <BitMapBackend<'static> as DrawingBackend>::ErrorType;

impl DrawingBackend for Backend<'_> {
    type ErrorType = BackendError;

    fn get_size(&self) -> (u32, u32) {
        self.0.get_size()
    }

    fn ensure_prepared(&mut self) -> Result<(), DrawingErrorKind<BackendError>> {
        self.0.ensure_prepared()
    }

    fn present(&mut self) -> Result<(), DrawingErrorKind<BackendError>> {
        self.0.present()
    }

    fn draw_pixel(
        &mut self,
        point: BackendCoord,
        color: BackendColor,
    ) -> Result<(), DrawingErrorKind<BackendError>> {
        self.0.draw_pixel(point, color)
    }

    fn draw_line<S: plotters_backend::BackendStyle>(
        &mut self,
        from: BackendCoord,
        to: BackendCoord,
        style: &S,
    ) -> Result<(), DrawingErrorKind<BackendError>> {
        self.0.draw_line(from, to, style)
    }

    fn draw_rect<S: plotters_backend::BackendStyle>(
        &mut self,
        upper_left: BackendCoord,
        bottom_right: BackendCoord,
        style: &S,
        fill: bool,
    ) -> Result<(), DrawingErrorKind<BackendError>> {
        self.0.draw_rect(upper_left, bottom_right, style, fill)
    }

    fn blit_bitmap(
        &mut self,
        pos: BackendCoord,
        (iw, ih): (u32, u32),
        src: &[u8],
    ) -> Result<(), DrawingErrorKind<BackendError>> {
        self.0.blit_bitmap(pos, (iw, ih), src)
    }

    fn estimate_text_size<S: BackendTextStyle>(
        &self,
        text: &str,
        style: &S,
    ) -> Result<(u32, u32), DrawingErrorKind<BackendError>> {
        let (width, height) = text_box(style.size(), text);
        Ok((width as u32, height as u32))
    }

    fn draw_text<S: BackendTextStyle>(
        &mut self,
        text: &str,
        style: &S,
        pos: BackendCoord,
    ) -> Result<(), DrawingErrorKind<BackendError>> {
        let color = style.color();
        if color.alpha == 0.0 {
            return Ok(());
        }
        let (width, height) = text_box(style.size(), text);
        let anchor = style.anchor();
        let dx = match anchor.h_pos {
            HPos::Left => 0,
            HPos::Right => -width,
            HPos::Center => -width / 2,
        };
        let dy = match anchor.v_pos {
            VPos::Top => 0,
            VPos::Center => -height / 2,
            VPos::Bottom => -height,
        };
        let transform = style.transform();
        let (w, h) = self.get_size();
        for (x, y, coverage) in ink(style.size() as f32, text) {
            let (x, y) = transform.transform(x + dx, y + dy);
            let (x, y) = (pos.0 + x, pos.1 + y);
            if x >= 0 && x < w as i32 && y >= 0 && y < h as i32 {
                let c = BackendColor {
                    alpha: color.alpha * f64::from(coverage),
                    rgb: color.rgb,
                };
                self.0.draw_pixel((x, y), c)?;
            }
        }
        Ok(())
    }
}

fn font() -> &'static FontRef<'static> {
    static PARSED: OnceLock<FontRef<'static>> = OnceLock::new();
    PARSED.get_or_init(|| FontRef::try_from_slice(FONT).expect("the embedded font parses"))
}

/// The pen position (px) of each glyph of `text` at `size` px: advances and kerning.
pub fn pen_positions(size: f32, text: &str) -> Vec<(GlyphId, f32)> {
    let font = font().as_scaled(size);
    let mut x = 0.0;
    let mut prev: Option<GlyphId> = None;
    text.chars()
        .map(|c| {
            let id = font.glyph_id(c);
            if let Some(p) = prev {
                x += font.kern(p, id);
            }
            let at = x;
            x += font.h_advance(id);
            prev = Some(id);
            (id, at)
        })
        .collect()
}

/// The size plotters lays text out in: the advance width and its nominal line height.
fn text_box(size: f64, text: &str) -> (i32, i32) {
    let font = font().as_scaled(size as f32);
    let width = pen_positions(size as f32, text)
        .last()
        .map_or(0.0, |&(id, x)| x + font.h_advance(id));
    (width as i32, (size / 1.24) as i32)
}

/// The pixels of `text` at `size` px with their coverage, relative to the top left of its
/// box; the baseline at half the size below the top, as plotters has it.
pub fn ink(size: f32, text: &str) -> Vec<(i32, i32, f32)> {
    glyph_ink(size, text).into_iter().flatten().collect()
}

/// [`ink`] glyph by glyph (none for a blank one).
fn glyph_ink(size: f32, text: &str) -> Vec<Vec<(i32, i32, f32)>> {
    let font = font();
    pen_positions(size, text)
        .into_iter()
        .map(|(id, x)| {
            let mut pixels = Vec::new();
            let glyph = id.with_scale_and_position(size, ab_glyph::point(x, size / 2.0));
            if let Some(outline) = font.outline_glyph(glyph) {
                let b = outline.px_bounds();
                outline.draw(|gx, gy, c| {
                    pixels.push((b.min.x as i32 + gx as i32, b.min.y as i32 + gy as i32, c));
                });
            }
            pixels
        })
        .collect()
}

/// Draws with `paint` on a `size` canvas and writes it to `path` as PNG. plotters' own file
/// output would compile the `image` crate (JPEG, BMP and PNG codecs, ≈ 20 s of every fresh
/// build) for this one format; the `png` crate alone encodes it.
fn png(
    path: &Path,
    size: (u32, u32),
    paint: impl FnOnce(&DrawingArea<Backend<'_>, Shift>) -> Result<(), String>,
) -> Result<(), String> {
    let err = |e: &dyn std::fmt::Display| format!("cannot draw {}: {e}", path.display());
    // White from the start, the background of every figure: plotters' fill would blend
    // each pixel of the canvas in turn.
    let mut pixels = vec![255u8; size.0 as usize * size.1 as usize * 3];
    {
        let root = Backend(BitMapBackend::with_buffer(&mut pixels, size)).into_drawing_area();
        paint(&root)?;
        root.present().map_err(|e| err(&e))?;
    }
    let file = std::fs::File::create(path).map_err(|e| err(&e))?;
    let mut encoder = ::png::Encoder::new(std::io::BufWriter::new(file), size.0, size.1);
    encoder.set_color(::png::ColorType::Rgb);
    encoder.set_depth(::png::BitDepth::Eight);
    let mut writer = encoder.write_header().map_err(|e| err(&e))?;
    writer.write_image_data(&pixels).map_err(|e| err(&e))?;
    writer.finish().map_err(|e| err(&e))
}

/// Draws panels stacked vertically, sharing the time axis.
pub fn draw(path: &Path, title: &str, t: &[f64], panels: &[Panel<'_>]) -> Result<(), String> {
    draw_against(path, title, "time t (s)", t, panels)
}

/// Draws panels stacked vertically, sharing the x axis `x` (labelled `x_label`, ascending).
pub fn draw_against(
    path: &Path,
    title: &str,
    x_label: &str,
    t: &[f64],
    panels: &[Panel<'_>],
) -> Result<(), String> {
    register_font();
    let height = 260 * panels.len() as u32 + 60;
    let err = |e: &dyn std::fmt::Display| format!("cannot draw {}: {e}", path.display());
    png(path, (900, height), |root| {
        let root = root
            .titled(title, ("sans-serif", 24))
            .map_err(|e| err(&e))?;
        let areas = root.split_evenly((panels.len(), 1));
        let (t0, t1) = (
            t.first().copied().unwrap_or(0.0),
            t.last().copied().unwrap_or(1.0),
        );
        for (area, panel) in areas.iter().zip(panels) {
            let (mut lo, mut hi) = panel
                .series
                .iter()
                .flat_map(|(_, v)| v.iter().copied())
                .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), v| {
                    (a.min(v), b.max(v))
                });
            if !lo.is_finite() || !hi.is_finite() {
                (lo, hi) = (-1.0, 1.0);
            }
            // A series flat to roundoff (a planar mechanism's Z) gets a readable unit-scale
            // axis instead of one spanning 1e-9 whose tick labels all round to the same value.
            let scale = 1.0 + hi.abs().max(lo.abs());
            let pad = if hi - lo <= 1e-9 * scale {
                0.1 * scale
            } else {
                (hi - lo) * 0.08
            };
            let mut chart = ChartBuilder::on(area)
                .margin(12)
                .x_label_area_size(40)
                .y_label_area_size(80)
                .build_cartesian_2d(t0..t1.max(t0 + 1e-9), (lo - pad)..(hi + pad))
                .map_err(|e| err(&e))?;
            chart
                .configure_mesh()
                .x_desc(x_label)
                .y_desc(&*panel.y_label)
                .label_style(("sans-serif", 15))
                .axis_desc_style(("sans-serif", 17))
                .draw()
                .map_err(|e| err(&e))?;
            for (k, (name, values)) in panel.series.iter().enumerate() {
                let color = COLORS[k % COLORS.len()];
                chart
                    .draw_series(LineSeries::new(
                        t.iter().copied().zip(values.iter().copied()),
                        color.stroke_width(2),
                    ))
                    .map_err(|e| err(&e))?
                    .label(*name)
                    .legend(move |(x, y)| {
                        PathElement::new(vec![(x, y), (x + 20, y)], color.stroke_width(2))
                    });
            }
            if panel.series.len() > 1 {
                chart
                    .configure_series_labels()
                    .background_style(WHITE.mix(0.85))
                    .border_style(BLACK)
                    .label_font(("sans-serif", 15))
                    .draw()
                    .map_err(|e| err(&e))?;
            }
        }
        Ok(())
    })
}

/// One heat map: a colour-bar label and a value per grid point, `values[iy][ix]` (NaN where
/// there is none, drawn grey).
pub struct HeatMap<'a> {
    pub label: &'a str,
    pub values: Vec<Vec<f64>>,
}

/// The viridis colour map's anchors (perceptually uniform, readable in grey and by most
/// colour-blind readers), interpolated linearly between.
const VIRIDIS: [(f64, f64, f64); 5] = [
    (68.0, 1.0, 84.0),
    (59.0, 82.0, 139.0),
    (33.0, 145.0, 140.0),
    (94.0, 201.0, 98.0),
    (253.0, 231.0, 37.0),
];

/// The colour of `s` in [0, 1] (clamped) on [`VIRIDIS`].
fn viridis(s: f64) -> RGBColor {
    let s = s.clamp(0.0, 1.0) * (VIRIDIS.len() - 1) as f64;
    let k = (s.floor() as usize).min(VIRIDIS.len() - 2);
    let f = s - k as f64;
    let (a, b) = (VIRIDIS[k], VIRIDIS[k + 1]);
    let mix = |x: f64, y: f64| (x + (y - x) * f).round() as u8;
    RGBColor(mix(a.0, b.0), mix(a.1, b.1), mix(a.2, b.2))
}

/// The cell edges around ascending values: halfway between neighbours, the ends as far
/// out as their neighbour's half spacing (a lone value gets a cell of its size's tenth).
fn cell_edges(v: &[f64]) -> Vec<f64> {
    match v {
        [] => vec![0.0, 1.0],
        [x] => {
            let h = 0.05 * x.abs().max(1e-9);
            vec![x - h, x + h]
        }
        _ => {
            let n = v.len();
            let mut e = Vec::with_capacity(n + 1);
            e.push(v[0] - (v[1] - v[0]) / 2.0);
            e.extend(v.windows(2).map(|w| (w[0] + w[1]) / 2.0));
            e.push(v[n - 1] + (v[n - 1] - v[n - 2]) / 2.0);
            e
        }
    }
}

/// Draws heat maps stacked vertically over the grid `xs` × `ys` (ascending), each with its
/// colour bar.
pub fn draw_heat_maps(
    path: &Path,
    title: &str,
    (x_label, xs): (&str, &[f64]),
    (y_label, ys): (&str, &[f64]),
    maps: &[HeatMap<'_>],
) -> Result<(), String> {
    register_font();
    let size = heat_map_size(maps.len());
    let err = |e: &dyn std::fmt::Display| format!("cannot draw {}: {e}", path.display());
    let (xe, ye) = (cell_edges(xs), cell_edges(ys));
    png(path, size, |root| {
        let root = root
            .titled(title, ("sans-serif", 24))
            .map_err(|e| err(&e))?;
        for (area, map) in root.split_evenly((maps.len().max(1), 1)).iter().zip(maps) {
            let (mut lo, mut hi) = map
                .values
                .iter()
                .flatten()
                .copied()
                .filter(|v| v.is_finite())
                .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), v| {
                    (a.min(v), b.max(v))
                });
            if !lo.is_finite() {
                (lo, hi) = (0.0, 1.0);
            }
            // A map flat to roundoff gets a readable range around its value, as the curves do.
            let scale = 1.0 + hi.abs().max(lo.abs());
            if hi - lo <= 1e-9 * scale {
                (lo, hi) = (lo - 0.05 * scale, hi + 0.05 * scale);
            }
            let (cells, bar) = area.split_horizontally(size.0 as i32 - 170);
            let mut chart = ChartBuilder::on(&cells)
                .margin(12)
                .x_label_area_size(40)
                .y_label_area_size(80)
                .build_cartesian_2d(xe[0]..xe[xe.len() - 1], ye[0]..ye[ye.len() - 1])
                .map_err(|e| err(&e))?;
            chart
                .configure_mesh()
                .disable_mesh()
                .x_desc(x_label)
                .y_desc(y_label)
                .label_style(("sans-serif", 15))
                .axis_desc_style(("sans-serif", 17))
                .draw()
                .map_err(|e| err(&e))?;
            let grey = RGBColor(200, 200, 200);
            let colour = |v: f64| match v.is_finite() {
                true => viridis((v - lo) / (hi - lo)),
                false => grey,
            };
            chart
                .draw_series(map.values.iter().enumerate().flat_map(|(iy, row)| {
                    let (xe, ye) = (&xe, &ye);
                    row.iter().enumerate().map(move |(ix, &v)| {
                        Rectangle::new(
                            [(xe[ix], ye[iy]), (xe[ix + 1], ye[iy + 1])],
                            colour(v).filled(),
                        )
                    })
                }))
                .map_err(|e| err(&e))?;
            // The colour bar: the map's range top to bottom, in 100 bands.
            let mut scale_chart = ChartBuilder::on(&bar)
                .margin(12)
                .margin_left(4)
                .x_label_area_size(40)
                .y_label_area_size(110)
                .build_cartesian_2d(0.0..1.0, lo..hi)
                .map_err(|e| err(&e))?;
            scale_chart
                .configure_mesh()
                .disable_mesh()
                .x_labels(0)
                .y_desc(map.label)
                .label_style(("sans-serif", 15))
                .axis_desc_style(("sans-serif", 17))
                .draw()
                .map_err(|e| err(&e))?;
            const BANDS: usize = 100;
            scale_chart
                .draw_series((0..BANDS).map(|k| {
                    let (a, b) = (k as f64 / BANDS as f64, (k + 1) as f64 / BANDS as f64);
                    Rectangle::new(
                        [(0.0, lo + (hi - lo) * a), (1.0, lo + (hi - lo) * b)],
                        viridis((a + b) / 2.0).filled(),
                    )
                }))
                .map_err(|e| err(&e))?;
        }
        Ok(())
    })
}

/// The size of a PNG of `n` heat maps ([`draw_heat_maps`]).
pub fn heat_map_size(n: usize) -> (u32, u32) {
    (900, 360 * n.max(1) as u32 + 60)
}

/// Writes the paper's figures 2–6 into `dir`; returns the files written.
pub fn paper_figures(run: &Run, dir: &Path) -> Result<Vec<PathBuf>, String> {
    std::fs::create_dir_all(dir).map_err(|e| format!("cannot create {}: {e}", dir.display()))?;
    let col = |k: usize| run.platform.iter().map(|p| p[k]).collect::<Vec<f64>>();
    let force = |c: usize| run.upper.iter().map(|f| f[0][c]).collect::<Vec<f64>>();
    let mut figures = vec![
        Figure {
            path: dir.join("fig2_platform_position.png"),
            title: "Fig. 2: platform centre of mass position".into(),
            panels: vec![
                Panel {
                    y_label: "X (m)".into(),
                    series: vec![("X", col(0))],
                },
                Panel {
                    y_label: "Y (m)".into(),
                    series: vec![("Y", col(1))],
                },
                Panel {
                    y_label: "Z (m)".into(),
                    series: vec![("Z", col(2))],
                },
            ],
        },
        Figure {
            path: dir.join("fig3_platform_orientation.png"),
            title: "Fig. 3: platform orientation (Rz·Ry·Rx Euler angles)".into(),
            panels: vec![Panel {
                y_label: "angle (rad)".into(),
                series: vec![
                    ("θ about X", col(3)),
                    ("β about Y", col(4)),
                    ("γ about Z", col(5)),
                ],
            }],
        },
    ];
    for (k, axis) in ["X", "Y", "Z"].iter().enumerate() {
        figures.push(Figure {
            path: dir.join(format!(
                "fig{}_upper1_force_{}.png",
                4 + k,
                axis.to_lowercase()
            )),
            title: format!(
                "Fig. {}: {axis} reaction force on the platform at leg 1's upper joint",
                4 + k
            ),
            panels: vec![Panel {
                y_label: format!("F{} (N)", axis.to_lowercase()).into(),
                series: vec![(axis, force(k))],
            }],
        });
    }
    draw_all(&run.t, figures)
}

/// One figure of [`draw_all`]: its file, title and panels.
pub struct Figure<'a> {
    pub path: PathBuf,
    pub title: String,
    pub panels: Vec<Panel<'a>>,
}

/// Draws each figure over the common time axis `t`, on as many threads as there are cores
/// and figures: each figure is its own canvas and file, and rasterising and compressing
/// them is most of a run command's time on scenes with many figures. The paths come back
/// in the figures' order; on failure, the first failing figure's error in that order.
pub fn draw_all(t: &[f64], figures: Vec<Figure<'_>>) -> Result<Vec<PathBuf>, String> {
    register_font();
    let threads = std::thread::available_parallelism()
        .map_or(1, |n| n.get())
        .min(figures.len());
    let next = std::sync::atomic::AtomicUsize::new(0);
    let work = || {
        let mut done = Vec::new();
        loop {
            let k = next.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
            let Some(f) = figures.get(k) else { break done };
            done.push((k, draw(&f.path, &f.title, t, &f.panels)));
        }
    };
    let mut drawn = std::thread::scope(|scope| {
        let helpers: Vec<_> = (1..threads).map(|_| scope.spawn(work)).collect();
        let mut drawn = work();
        for h in helpers {
            drawn.extend(h.join().unwrap_or_else(|p| std::panic::resume_unwind(p)));
        }
        drawn
    });
    drawn.sort_by_key(|&(k, _)| k);
    for (_, r) in drawn {
        r?;
    }
    Ok(figures.into_iter().map(|f| f.path).collect())
}

/// One line of a log-log chart: a name and its `(x, y)` points (non-positive points are
/// dropped, a log axis cannot show them).
pub struct LogSeries {
    pub name: String,
    pub points: Vec<(f64, f64)>,
    /// Drawn with a thin line and triangle markers, to tell a second family of lines apart
    /// when the palette repeats.
    pub secondary: bool,
}

/// Draws named lines (with point markers) on log-log axes, e.g. a work-precision diagram.
pub fn draw_log_log(
    path: &Path,
    title: &str,
    x_label: &str,
    y_label: &str,
    series: &[LogSeries],
) -> Result<(), String> {
    register_font();
    let err = |e: &dyn std::fmt::Display| format!("cannot draw {}: {e}", path.display());
    let usable = |&(x, y): &(f64, f64)| x > 0.0 && y > 0.0 && x.is_finite() && y.is_finite();
    let pts = || {
        series
            .iter()
            .flat_map(|s| s.points.iter().copied().filter(usable))
    };
    let range = |f: fn((f64, f64)) -> f64| {
        let (lo, hi) = pts()
            .map(f)
            .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), v| {
                (a.min(v), b.max(v))
            });
        if lo.is_finite() {
            // Half a decade of margin so end points and markers stay inside the frame.
            (lo / 2.0, hi * 2.0)
        } else {
            (1.0, 10.0)
        }
    };
    let ((x0, x1), (y0, y1)) = (range(|p| p.0), range(|p| p.1));
    // The chart on the left, the legend in its own column so it never hides data.
    png(path, (1240, 640), |root| {
        let (plot_area, legend_area) = root.split_horizontally(900);
        let mut chart = ChartBuilder::on(&plot_area)
            .caption(title, ("sans-serif", 22))
            .margin(16)
            .x_label_area_size(48)
            .y_label_area_size(90)
            .build_cartesian_2d((x0..x1).log_scale(), (y0..y1).log_scale())
            .map_err(|e| err(&e))?;
        chart
            .configure_mesh()
            .x_desc(x_label)
            .y_desc(y_label)
            .x_label_formatter(&|v| format!("{v:.0e}"))
            .y_label_formatter(&|v| format!("{v:.0e}"))
            .label_style(("sans-serif", 15))
            .axis_desc_style(("sans-serif", 17))
            .draw()
            .map_err(|e| err(&e))?;
        const PALETTE: [RGBColor; 8] = [
            RGBColor(0, 90, 181),
            RGBColor(220, 50, 32),
            RGBColor(0, 140, 70),
            RGBColor(230, 150, 0),
            RGBColor(120, 60, 170),
            RGBColor(90, 90, 90),
            RGBColor(0, 170, 200),
            RGBColor(200, 0, 140),
        ];
        for (k, s) in series.iter().enumerate() {
            let color = PALETTE[k % PALETTE.len()];
            let width = if s.secondary { 1 } else { 2 };
            let p: Vec<(f64, f64)> = s.points.iter().copied().filter(usable).collect();
            chart
                .draw_series(LineSeries::new(
                    p.iter().copied(),
                    color.stroke_width(width),
                ))
                .map_err(|e| err(&e))?;
            let y = 60 + 24 * k as i32;
            legend_area
                .draw(&PathElement::new(
                    vec![(10, y), (40, y)],
                    color.stroke_width(width),
                ))
                .map_err(|e| err(&e))?;
            legend_area
                .draw(&Text::new(s.name.as_str(), (48, y - 8), ("sans-serif", 15)))
                .map_err(|e| err(&e))?;
            if s.secondary {
                chart
                    .draw_series(p.iter().map(|&c| TriangleMarker::new(c, 5, color.filled())))
                    .map_err(|e| err(&e))?;
            } else {
                chart
                    .draw_series(p.iter().map(|&c| Circle::new(c, 4, color.filled())))
                    .map_err(|e| err(&e))?;
            }
        }
        Ok(())
    })
}

/// Draws `drivers.png` (one panel per driver, if any) and `position_<body>.png` (X, Y, Z
/// panels of its centre of mass) for every recorded body.
pub fn write_plots(rec: &Recording, dir: &Path) -> Result<Vec<PathBuf>, String> {
    let info = rec.info;
    let mut figures = Vec::new();
    if !rec.drivers.is_empty() {
        figures.push(Figure {
            path: dir.join("drivers.png"),
            title: format!("{}: driver efforts", info.name),
            panels: rec
                .drivers
                .iter()
                .enumerate()
                .map(|(d, &j)| Panel {
                    y_label: format!("{} ({})", info.joints[j].name, info.joints[j].effort_unit)
                        .into(),
                    series: vec![("effort", rec.efforts.iter().map(|e| e[d]).collect())],
                })
                .collect(),
        });
    }
    for &b in &rec.bodies {
        let body = &info.bodies[b];
        // One panel per axis: a coordinate that barely moves keeps its own scale instead
        // of being flattened by the others' range.
        figures.push(Figure {
            path: dir.join(format!("position_{}.png", body.name)),
            title: format!("{}: centre of mass of {}", info.name, body.name),
            panels: ["X (m)", "Y (m)", "Z (m)"]
                .into_iter()
                .enumerate()
                .map(|(c, label)| Panel {
                    y_label: label.into(),
                    series: vec![(label, rec.poses.iter().map(|p| p[b].0[c]).collect())],
                })
                .collect(),
        });
    }
    draw_all(&rec.t, figures)
}

/// `assembly_modes_over_time.png`: the number of real assembly modes, the distance to the
/// nearest other mode and the conditions along the driver motion (`fk --over-time`).
pub fn modes_over_time(dir: &Path, samples: &[Sample]) -> Result<String, String> {
    let t: Vec<f64> = samples.iter().map(|s| s.t).collect();
    let col = |f: fn(&Sample) -> f64| samples.iter().map(f).collect::<Vec<f64>>();
    draw(
        &dir.join("assembly_modes_over_time.png"),
        "Assembly modes along the driver motion",
        &t,
        &[
            Panel {
                y_label: "real modes".into(),
                series: vec![("real assembly modes", col(|s| s.real as f64))],
            },
            Panel {
                y_label: "distance (m)".into(),
                series: vec![("to the nearest other mode", col(|s| s.nearest))],
            },
            Panel {
                y_label: "log10 condition".into(),
                series: vec![
                    ("current mode", col(|s| s.condition.log10())),
                    ("nearest mode", col(|s| s.nearest_condition.log10())),
                ],
            },
        ],
    )?;
    Ok("assembly_modes_over_time.png".to_string())
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Figures drawn on several threads come back in their own order, each file as the
    /// same figure drawn alone makes it, and the error is the first failing figure's in
    /// that order (two figures fail here, one on each side of a good one).
    #[test]
    fn figures_drawn_together_are_the_figures_drawn_alone_in_order() {
        let dir = std::env::temp_dir().join(format!("symbody-draw-all-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let t: Vec<f64> = (0..50).map(|k| k as f64 * 0.1).collect();
        let figure = |name: &str, k: f64| Figure {
            path: dir.join(name),
            title: format!("figure {name}"),
            panels: vec![Panel {
                y_label: format!("y{k}").into(),
                series: vec![("y", t.iter().map(|x| (k * x).sin()).collect())],
            }],
        };
        let names = ["a.png", "b.png", "c.png", "d.png", "e.png"];
        let together = names.iter().zip(1..).map(|(n, k)| figure(n, k as f64));
        let paths = draw_all(&t, together.collect()).unwrap();
        assert_eq!(paths, names.map(|n| dir.join(n)));
        for (n, k) in names.iter().zip(1..) {
            let alone = dir.join(format!("alone_{n}"));
            let f = figure(n, k as f64);
            draw(&alone, &f.title, &t, &f.panels).unwrap();
            assert_eq!(
                std::fs::read(&alone).unwrap(),
                std::fs::read(dir.join(n)).unwrap()
            );
        }
        let missing = dir.join("no such directory");
        let mut failing: Vec<Figure> = names
            .iter()
            .zip(1..)
            .map(|(n, k)| figure(n, k as f64))
            .collect();
        failing[1].path = missing.join("first.png");
        failing[3].path = missing.join("second.png");
        let err = draw_all(&t, failing).unwrap_err();
        assert!(err.contains("first.png"), "{err}");
        std::fs::remove_dir_all(&dir).unwrap();
    }

    /// The widest run of blank pixel columns between the first and last inked column of
    /// `text` drawn at (10, 10) of a white canvas by `draw`.
    fn widest_gap(draw: impl FnOnce(&mut [u8], (u32, u32))) -> usize {
        let size = (400u32, 60u32);
        let mut pixels = vec![255u8; (size.0 * size.1 * 3) as usize];
        draw(&mut pixels, size);
        let inked: Vec<bool> = (0..size.0 as usize)
            .map(|x| (0..size.1 as usize).any(|y| pixels[(y * size.0 as usize + x) * 3] < 160))
            .collect();
        let first = inked.iter().position(|&i| i).expect("some ink");
        let last = inked.iter().rposition(|&i| i).unwrap();
        inked[first..=last]
            .split(|&i| i)
            .map(<[bool]>::len)
            .max()
            .unwrap_or(0)
    }

    fn label(text: &str, size: u32) -> (usize, usize) {
        register_font();
        let style = ("sans-serif", size).into_font().color(&BLACK);
        let ours = widest_gap(|buf, size| {
            let root = Backend(BitMapBackend::with_buffer(buf, size)).into_drawing_area();
            root.draw_text(text, &style, (10, 10)).unwrap();
            root.present().unwrap();
        });
        let plotters = widest_gap(|buf, size| {
            let root = BitMapBackend::with_buffer(buf, size).into_drawing_area();
            root.draw_text(text, &style, (10, 10)).unwrap();
            root.present().unwrap();
        });
        (ours, plotters)
    }

    /// Inside a word no gap between glyphs comes near a space's width at the sizes the plots
    /// use (15 px tick labels, 17 px axis descriptions). plotters' own drawing, which drops
    /// the side bearings, leaves one in "time" ("tim e"); when it no longer does,
    /// `Backend::draw_text` can go.
    #[test]
    fn glyphs_of_a_word_leave_no_gap_as_wide_as_a_space() {
        for size in [15, 17] {
            let space = font()
                .as_scaled(size as f32)
                .h_advance(font().glyph_id(' '));
            for word in [
                "time",
                "position",
                "force",
                "Newton",
                "assembly",
                "orientation",
            ] {
                let (ours, _) = label(word, size);
                assert!(
                    (ours as f32) < 0.75 * space,
                    "{word} at {size} px: a gap of {ours} px, a space is {space} px"
                );
            }
        }
        let space = font().as_scaled(17.0).h_advance(font().glyph_id(' '));
        let (_, plotters) = label("time", 17);
        assert!(
            plotters as f32 >= 0.75 * space,
            "plotters' widest gap in `time` is {plotters} px"
        );
    }

    /// Each glyph's ink starts where its pen position and left side bearing put it (within
    /// the pixel the rasterizer rounds to), and words keep their spaces.
    #[test]
    fn each_glyph_starts_at_its_pen_position_plus_its_bearing() {
        for size in [17.0f32, 34.0] {
            let scaled = font().as_scaled(size);
            let text = "time t (s)";
            for ((id, pen), pixels) in pen_positions(size, text)
                .into_iter()
                .zip(glyph_ink(size, text))
            {
                let Some(left) = pixels.iter().filter(|p| p.2 > 0.0).map(|p| p.0).min() else {
                    continue;
                };
                let want = pen + scaled.h_side_bearing(id);
                assert!(
                    (left as f32 - want).abs() <= 1.0,
                    "{size} px, glyph {id:?}: ink from {left}, pen + bearing {want}"
                );
            }
        }
        let (ours, _) = label("time t (s)", 17);
        let space = font().as_scaled(17.0).h_advance(font().glyph_id(' '));
        assert!(ours as f32 >= 0.7 * space, "{ours} px between words");
    }
}
