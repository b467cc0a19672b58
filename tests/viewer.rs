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
