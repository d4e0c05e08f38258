//! Anti-aliased PNG: the box filter of `plot::raster` returns a block-constant image unchanged,
//! and a steep straight line drawn through the supersampled backend stays straight to a
//! fraction of a pixel, where plotters' plain bitmap backend steps it by whole pixels.

use boltzone::plot::raster::{downsample, Supersampled, FACTOR};
use boltzone::plot::{Curve, CurveFigure, Figure, PALETTE};
use plotters::prelude::*;

#[test]
fn downsampling_a_block_constant_image_returns_it() {
    let (w, h, k) = (5usize, 3usize, FACTOR as usize);
    let small: Vec<u8> = (0..w * h * 3).map(|i| (i * 37 % 256) as u8).collect();
    let mut big = vec![0u8; w * h * 3 * k * k];
    for y in 0..h * k {
        for x in 0..w * k {
            for c in 0..3 {
                big[(y * w * k + x) * 3 + c] = small[((y / k) * w + x / k) * 3 + c];
            }
        }
    }
    assert_eq!(downsample(&big, (w as u32, h as u32)), small);
}

/// How far a drawn steep straight line strays from straight: per pixel row of the lower left
/// quarter (clear of the legend; images are 400 × 300 RGB), the centroid in x of the darkness
/// the line adds to `bg` (the same figure without it); the RMS residual of these centroids
/// from their least-squares line, in pixels (whole-pixel stair steps alone give 1/√12 ≈ 0.29).
fn stair_rms(img: &[u8], bg: &[u8]) -> f64 {
    let mut pts = Vec::new();
    for y in 150..300 {
        let (mut w, mut wx) = (0.0, 0.0);
        for x in 0..200 {
            let k = (y * 400 + x) * 3;
            let dark = f64::from(bg[k]) - f64::from(img[k]);
            if dark > 0.0 {
                w += dark;
                wx += dark * x as f64;
            }
        }
        if w > 100.0 {
            pts.push((y as f64, wx / w));
        }
    }
    // drop the line's two end columns (caps)
    let pts = &pts[2..pts.len() - 2];
    let n = pts.len() as f64;
    let (mx, my) = (
        pts.iter().map(|p| p.0).sum::<f64>() / n,
        pts.iter().map(|p| p.1).sum::<f64>() / n,
    );
    let sxy: f64 = pts.iter().map(|p| (p.0 - mx) * (p.1 - my)).sum();
    let sxx: f64 = pts.iter().map(|p| (p.0 - mx).powi(2)).sum();
    let slope = sxy / sxx;
    (pts.iter()
        .map(|p| (p.1 - my - slope * (p.0 - mx)).powi(2))
        .sum::<f64>()
        / n)
        .sqrt()
}

/// `fig` drawn by plotters' plain bitmap backend and by the supersampled one, as RGB.
fn render(fig: &CurveFigure, size: (u32, u32)) -> (Vec<u8>, Vec<u8>) {
    boltzone::plot::register_font();
    let n = (size.0 * size.1 * 3) as usize;
    let mut plain = vec![255u8; n];
    {
        let root = BitMapBackend::with_buffer(&mut plain, size).into_drawing_area();
        fig.draw(&root).unwrap();
        root.present().unwrap();
    }
    let k = FACTOR as usize;
    let mut big = vec![255u8; n * k * k];
    {
        let root = Supersampled::new(&mut big, size).into_drawing_area();
        fig.draw(&root).unwrap();
        root.present().unwrap();
    }
    (plain, downsample(&big, size))
}

#[test]
fn a_slanted_line_is_anti_aliased() {
    // a steep line: plotters' plain rasteriser steps it by whole pixels in x
    let line = Curve {
        label: String::new(),
        points: vec![(0.1, 0.02), (0.19, 0.45)],
        color: PALETTE[0],
    };
    let mut fig = CurveFigure {
        title: String::new(),
        x_label: String::new(),
        y_label: String::new(),
        curves: vec![],
        markers: vec![],
        x_range: (0.0, 1.0),
        y_range: (0.0, 1.0),
    };
    let size = (400u32, 300u32);
    let (plain_bg, smooth_bg) = render(&fig, size);
    fig.curves.push(line);
    let (plain, smooth) = render(&fig, size);
    let (rms_plain, rms_smooth) = (stair_rms(&plain, &plain_bg), stair_rms(&smooth, &smooth_bg));
    eprintln!("RMS of the line's row centroids from straight: plain {rms_plain:.3} px, supersampled {rms_smooth:.3} px");
    // the plain backend's stair steps (measured 0.148 px: half the 1/√12 ≈ 0.29 px of pure
    // whole-pixel steps, its polygon fill covers part of each step)
    assert!(rms_plain > 0.1, "plain backend {rms_plain}");
    // supersampled: at most half of it (1/FACTOR expected; measured 0.043 px)
    assert!(rms_smooth < 0.5 * rms_plain, "supersampled {rms_smooth}");
}
