//! The 3D viewer end to end: `simulate --html` writes one file that headless Chromium opens
//! offline; screenshots at two times must differ (the platform moved) and both must show the
//! platform (its plate colour covers a sizeable area).

use std::path::{Path, PathBuf};
use std::process::Command;

/// The fill colour the viewer gives plates (`PLATE` in cli/src/viewer.html).
const PLATE: [u8; 3] = [70, 130, 180];

fn find_chromium() -> Option<PathBuf> {
    ["chromium", "chromium-browser", "google-chrome"]
        .iter()
        .find_map(|name| {
            let o = Command::new("which").arg(name).output().ok()?;
            o.status
                .success()
                .then(|| PathBuf::from(String::from_utf8_lossy(&o.stdout).trim()))
        })
}

/// Headless Chromium; the test's setup installs Debian's package when it is missing and the
/// test runs as root (as on CI), so `cargo test --workspace` works on a fresh machine.
fn chromium() -> PathBuf {
    static INSTALL: std::sync::Once = std::sync::Once::new();
    INSTALL.call_once(|| {
        let root = Command::new("id")
            .arg("-u")
            .output()
            .map(|o| o.stdout == b"0\n");
        if find_chromium().is_none() && root.unwrap_or(false) {
            let apt = |args: &[&str]| Command::new("apt-get").args(args).output();
            let _ = apt(&["update", "-qq"]);
            let _ = apt(&["install", "-y", "-qq", "chromium"]);
        }
    });
    find_chromium().expect(
        "the viewer test needs headless Chromium: install Debian's `chromium` package \
         (the test does so itself when run as root)",
    )
}

fn screenshot(html: &Path, t: f64, png: &Path) -> Vec<[u8; 3]> {
    let url = format!("file://{}?t={t}", html.display());
    let status = Command::new(chromium())
        .args([
            "--headless",
            "--no-sandbox",
            "--disable-gpu",
            "--hide-scrollbars",
            "--window-size=900,700",
            "--virtual-time-budget=3000",
        ])
        .arg(format!("--screenshot={}", png.display()))
        .arg(url)
        .output()
        .expect("chromium runs");
    assert!(
        status.status.success(),
        "{}",
        String::from_utf8_lossy(&status.stderr)
    );
    let decoder = png::Decoder::new(std::fs::File::open(png).unwrap());
    let mut reader = decoder.read_info().unwrap();
    let mut buf = vec![0; reader.output_buffer_size()];
    let info = reader.next_frame(&mut buf).unwrap();
    let channels = info.color_type.samples();
    buf[..info.buffer_size()]
        .chunks(channels)
        .map(|p| [p[0], p[1], p[2]])
        .collect()
}

#[test]
fn the_viewer_animates_the_platform_offline() {
    let out = std::env::temp_dir().join(format!("symbody-viewer-{}", std::process::id()));
    let o = Command::new(env!("CARGO_BIN_EXE_symbody"))
        .args(["simulate", "--t-end", "3", "--html", "--no-plots", "--out"])
        .arg(&out)
        .output()
        .unwrap();
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let html = out.join("view.html");
    let text = std::fs::read_to_string(&html).unwrap();
    // Offline: nothing is loaded from anywhere.
    assert!(!text.contains("http://") && !text.contains("https://") && !text.contains("src="));

    let a = screenshot(&html, 0.0, &out.join("a.png"));
    let b = screenshot(&html, 1.5, &out.join("b.png"));
    assert_eq!(a.len(), b.len());
    let plate = |img: &[[u8; 3]]| img.iter().filter(|p| **p == PLATE).count();
    let (pa, pb) = (plate(&a), plate(&b));
    assert!(pa > 1000 && pb > 1000, "platform pixels: {pa} and {pb}");
    let changed = a.iter().zip(&b).filter(|(x, y)| x != y).count();
    assert!(
        changed > 2000,
        "only {changed} pixels differ between t = 0 and t = 1.5 s"
    );
    std::fs::remove_dir_all(&out).ok();
}

/// A small mechanism (a 0.1 m crank) fills the view: the camera is fitted to the points of
/// the whole motion, not to a sphere around them, and the force strip has a labelled time
/// axis along its foot.
#[test]
fn a_small_mechanism_fills_the_view_and_the_force_strip_has_a_time_axis() {
    let out = std::env::temp_dir().join(format!("symbody-viewer-small-{}", std::process::id()));
    let o = Command::new(env!("CARGO_BIN_EXE_symbody"))
        .args([
            "simulate",
            "slider_crank",
            "--t-end",
            "1",
            "--html",
            "--out",
        ])
        .arg(&out)
        .output()
        .unwrap();
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let html = out.join("view.html");

    // The bounds the page computed hold every centre of mass of the run.
    let dom = Command::new(chromium())
        .args(["--headless", "--no-sandbox", "--disable-gpu", "--dump-dom"])
        .arg(format!("file://{}?t=0.5", html.display()))
        .output()
        .unwrap();
    let dom = String::from_utf8_lossy(&dom.stdout);
    let fit = dom
        .split("data-fit=\"")
        .nth(1)
        .and_then(|s| s.split('"').next())
        .unwrap_or_else(|| panic!("no data-fit on the page's body"))
        .replace("&quot;", "\"");
    let fit: serde_json::Value = serde_json::from_str(&fit).unwrap();
    let bodies = std::fs::read_to_string(out.join("bodies.csv")).unwrap();
    let header: Vec<&str> = bodies.lines().next().unwrap().split(',').collect();
    for line in bodies.lines().skip(1) {
        for (c, v) in header.iter().zip(line.split(',')) {
            let axis = match c.rsplit_once('.').map(|(_, p)| p) {
                Some("x") => 0,
                Some("y") => 1,
                Some("z") => 2,
                _ => continue,
            };
            let v: f64 = v.parse().unwrap();
            let (lo, hi) = (
                fit["lo"][axis].as_f64().unwrap(),
                fit["hi"][axis].as_f64().unwrap(),
            );
            assert!(
                lo <= v + 1e-12 && v <= hi + 1e-12,
                "{c} = {v} outside {lo}..{hi}"
            );
        }
    }

    let img = screenshot(&html, 0.5, &out.join("s.png"));
    let (w, h) = (900usize, img.len() / 900);
    let at = |x: usize, y: usize| img[y * w + x];
    // The view's rows have its background (#fafafa) somewhere at its edges or middle; the
    // strip's are white at its right edge.
    let view_rows: Vec<usize> = (0..h)
        .filter(|&y| {
            [1, w / 2, w - 2]
                .iter()
                .any(|&x| at(x, y) == [250, 250, 250])
        })
        .collect();
    let saturated = |p: [u8; 3]| {
        let (mx, mn) = (*p.iter().max().unwrap(), *p.iter().min().unwrap());
        mx - mn > 60
    };
    let (mut x0, mut x1, mut y0, mut y1) = (w, 0, h, 0);
    for &y in &view_rows {
        for x in 0..w {
            if saturated(at(x, y)) {
                (x0, x1, y0, y1) = (x0.min(x), x1.max(x), y0.min(y), y1.max(y));
            }
        }
    }
    assert!(x1 > x0 && y1 > y0, "no mechanism drawn");
    let (wide, high) = (
        (x1 - x0) as f64 / w as f64,
        (y1 - y0) as f64 / view_rows.len() as f64,
    );
    assert!(
        wide.max(high) > 0.45,
        "the mechanism covers {:.0}% of the view's width and {:.0}% of its height",
        100.0 * wide,
        100.0 * high
    );

    let strip: Vec<usize> = (view_rows.last().unwrap() + 1..h)
        .filter(|&y| at(w - 3, y) == [255, 255, 255])
        .collect();
    assert!(strip.len() > 50, "{} rows of force strip", strip.len());
    let foot = &strip[strip.len() - 14..];
    let labelled = (50..w - 5)
        .filter(|&x| foot.iter().any(|&y| at(x, y).iter().all(|&c| c < 120)))
        .count();
    assert!(
        labelled > 20,
        "only {labelled} columns of text along the strip's foot"
    );
    std::fs::remove_dir_all(&out).ok();
}

/// The paper scene keeps its states only for the viewer (`Options::states`): with `--html`
/// its page holds every output's time (630 over 2π s every 10 ms).
#[test]
fn the_paper_scene_keeps_its_states_for_the_viewer() {
    let out = std::env::temp_dir().join(format!("symbody-viewer-scene-{}", std::process::id()));
    let scene = concat!(env!("CARGO_MANIFEST_DIR"), "/scenes/paper.toml");
    let o = Command::new(env!("CARGO_BIN_EXE_symbody"))
        .args(["run", scene, "--html", "--no-plots", "--out"])
        .arg(&out)
        .output()
        .unwrap();
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let text = std::fs::read_to_string(out.join("view.html")).unwrap();
    let times = text.split("\"t\":[").nth(1).expect("the page's times");
    let times = &times[..times.find(']').unwrap()];
    assert_eq!(times.split(',').count(), 630);
    std::fs::remove_dir_all(&out).ok();
}
