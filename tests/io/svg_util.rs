//! Reading plotters' SVG output back: the polylines of one stroke colour and the text elements.

/// The point lists of every `<polyline>` whose stroke is `color` ("#D55E00").
pub fn polylines(svg: &str, color: &str) -> Vec<Vec<(f64, f64)>> {
    let want = format!("stroke=\"{color}\"");
    svg.split("<polyline")
        .skip(1)
        .filter(|e| e[..e.find("/>").unwrap_or(e.len())].contains(&want))
        .map(|e| {
            let start = e.find("points=\"").unwrap() + 8;
            let end = start + e[start..].find('"').unwrap();
            e[start..end]
                .split_whitespace()
                .map(|p| {
                    let (x, y) = p.split_once(',').unwrap();
                    (x.parse().unwrap(), y.parse().unwrap())
                })
                .collect()
        })
        .collect()
}

/// The pixel x of the vertical dashed marker drawn in `color` (its dashes share one x; the
/// legend's sample dashes are horizontal and left out).
pub fn marker_x(svg: &str, color: &str) -> f64 {
    let xs: Vec<f64> = polylines(svg, color)
        .into_iter()
        .filter(|p| p.len() == 2 && p[0].0 == p[1].0 && p[0].1 != p[1].1)
        .map(|p| p[0].0)
        .collect();
    assert!(xs.len() > 3, "no dashed vertical marker in {color}");
    assert!(xs.iter().all(|&x| x == xs[0]), "{color}: dashes at {xs:?}");
    xs[0]
}

/// The contents of every `<text …>…</text>` element.
pub fn texts(svg: &str) -> Vec<String> {
    svg.split("<text")
        .skip(1)
        .filter_map(|e| {
            let start = e.find('>')? + 1;
            let end = e.find("</text>")?;
            Some(e[start..end].trim().to_string())
        })
        .collect()
}
