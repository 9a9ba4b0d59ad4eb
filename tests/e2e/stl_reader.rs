//! A minimal binary STL reader written for the tests (independent of stl_io, which the
//! program writes with), plus a watertightness check on the welded vertices.

use std::collections::HashMap;

/// Triangles of a binary STL file as `[[x, y, z]; 3]` (f32, as stored).
pub fn read_binary_stl(bytes: &[u8]) -> Vec<[[f32; 3]; 3]> {
    assert!(bytes.len() >= 84, "binary STL needs an 80-byte header and a count");
    let count = u32::from_le_bytes(bytes[80..84].try_into().unwrap()) as usize;
    assert_eq!(bytes.len(), 84 + 50 * count, "file size matches the triangle count");
    (0..count)
        .map(|i| {
            let record = &bytes[84 + 50 * i..84 + 50 * (i + 1)];
            let value = |k: usize| f32::from_le_bytes(record[4 * k..4 * k + 4].try_into().unwrap());
            // Skip the stored normal (values 0..3); vertices are values 3..12.
            [
                [value(3), value(4), value(5)],
                [value(6), value(7), value(8)],
                [value(9), value(10), value(11)],
            ]
        })
        .collect()
}

/// Every directed edge appears once and its reverse once (closed, consistently oriented),
/// after welding bit-identical vertices. Returns the signed volume (m^3).
pub fn check_closed_oriented(triangles: &[[[f32; 3]; 3]]) -> Result<f64, String> {
    let mut ids: HashMap<[u32; 3], usize> = HashMap::new();
    let mut id = |p: [f32; 3]| {
        let key = [p[0].to_bits(), p[1].to_bits(), p[2].to_bits()];
        let next = ids.len();
        *ids.entry(key).or_insert(next)
    };
    let mut directed: HashMap<(usize, usize), usize> = HashMap::new();
    let mut volume = 0.0;
    for t in triangles {
        let v = [id(t[0]), id(t[1]), id(t[2])];
        if v[0] == v[1] || v[1] == v[2] || v[0] == v[2] {
            return Err(format!("degenerate triangle {t:?}"));
        }
        for k in 0..3 {
            *directed.entry((v[k], v[(k + 1) % 3])).or_default() += 1;
        }
        let p = t.map(|p| p.map(f64::from));
        volume += (p[0][0] * (p[1][1] * p[2][2] - p[1][2] * p[2][1])
            - p[0][1] * (p[1][0] * p[2][2] - p[1][2] * p[2][0])
            + p[0][2] * (p[1][0] * p[2][1] - p[1][1] * p[2][0]))
            / 6.0;
    }
    for (&(a, b), &count) in &directed {
        if count != 1 {
            return Err(format!(
                "directed edge {a}->{b} used {count} times (inconsistent orientation or non-manifold)"
            ));
        }
        if !directed.contains_key(&(b, a)) {
            return Err(format!("edge {a}->{b} has no twin (hole in the surface)"));
        }
    }
    Ok(volume)
}
