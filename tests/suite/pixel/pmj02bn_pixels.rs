//! The PMJ02BN pixel sampler: its tables as pbrt builds them, per-pixel nets, blue-noise
//! shifts and refusals.

use super::Draw;
use crate::common::first_net_failure;
use qmckit::pixel::pmj02bn::{TABLE_LEN, build_tables};
use qmckit::pixel::{PixelSampler, Pmj02BnPixels, Pmj02BnTables};
use qmckit::pmj::bn::workspace_len;

fn tables(spp: u32) -> (Vec<[u32; 2]>, Vec<[u32; 2]>) {
    let (mut table, mut tile) = (vec![[0u32; 2]; TABLE_LEN], vec![[0u32; 2]; TABLE_LEN]);
    let mut work = vec![0u32; workspace_len(TABLE_LEN).unwrap()];
    build_tables(3, spp, &mut table, &mut tile, &mut work).unwrap();
    (table, tile)
}

/// The tile holds every table point exactly once, each in its pixel; a pixel's samples
/// are a (0, m, 2)-net for spp = 4^k, and the other dimensions are stratified in 1D.
#[test]
fn tile_is_the_table_and_pixels_are_nets() {
    for (spp, t) in [
        (1u32, 256u32),
        (4, 128),
        (16, 64),
        (64, 32),
        (256, 16),
        (8, 64),
    ] {
        let (table, tile) = tables(spp);
        let s = Pmj02BnPixels::new(300, 200, spp, 1, &table, &tile).unwrap();
        let per = (spp.next_power_of_two().trailing_zeros().div_ceil(2) * 2) as usize;
        let per = 1usize << per;
        let mut rebuilt: Vec<[u32; 2]> = Vec::with_capacity(TABLE_LEN);
        let tb = t.trailing_zeros();
        for py in 0..t {
            for px in 0..t {
                for i in 0..per {
                    let q = tile[((py * t + px) as usize) * per + i];
                    let back = |c: u32, p: u32| {
                        if tb == 0 {
                            c
                        } else {
                            (p << (32 - tb)) | (c >> tb)
                        }
                    };
                    rebuilt.push([back(q[0], px), back(q[1], py)]);
                }
            }
        }
        let mut want = table.clone();
        // The low tb bits are lost in the bucketing shift.
        let strip = |v: &mut Vec<[u32; 2]>| {
            v.iter_mut().for_each(|p| {
                if tb > 0 {
                    p[0] &= !((1u32 << tb) - 1);
                    p[1] &= !((1u32 << tb) - 1);
                }
            });
            v.sort_unstable();
        };
        strip(&mut rebuilt);
        strip(&mut want);
        assert_eq!(rebuilt, want, "spp {spp}");
        for (x, y) in [(0u32, 0u32), (299, 199), (t, 1), (17, 130)] {
            let pts: Vec<[u32; 2]> = (0..spp)
                .map(|i| s.get_pixel_2d(x, y, i, 0).unwrap())
                .collect();
            if spp.trailing_zeros() % 2 == 0 {
                let m = spp.trailing_zeros();
                assert_eq!(first_net_failure(&pts, m), None, "spp {spp} ({x}, {y})");
            }
            // Tiles repeat with period T.
            assert_eq!(
                s.get_pixel_2d(x % t, y % t, 0, 0).unwrap(),
                s.get_pixel_2d(x, y, 0, 0).unwrap()
            );
            for dim in [2usize, 3, 7, 40, (1 << 32) + 2] {
                let mut strata = vec![false; spp as usize];
                for i in 0..spp {
                    let v = s.get_1d(x, y, i, dim).unwrap();
                    strata[((v as u64 * spp as u64) >> 32) as usize] = true;
                }
                assert!(strata.iter().all(|&b| b), "1D strata, spp {spp} dim {dim}");
                let a = s.get_2d(x, y, 0, dim).unwrap();
                assert_ne!(a, s.get_2d(x, y, 0, dim + 2).unwrap());
            }
        }
    }
}

#[test]
fn bad_input_is_an_error() {
    let (table, tile) = tables(16);
    assert!(Pmj02BnPixels::new(10, 10, 0, 0, &table, &tile).is_err());
    assert!(Pmj02BnPixels::new(10, 10, 1 << 17, 0, &table, &tile).is_err());
    assert!(Pmj02BnPixels::new(10, 10, 16, 0, &table[..100], &tile).is_err());
    let s = Pmj02BnPixels::new(10, 10, 16, 0, &table, &tile).unwrap();
    assert!(s.start_pixel_sample(10, 0, 0).is_err());
    assert!(s.start_pixel_sample(0, 0, 16).is_err());
    assert!(s.start_pixel_sample(0, 10, 0).is_err());
    let (mut a, mut b) = (vec![[0u32; 2]; TABLE_LEN], vec![[0u32; 2]; 10]);
    let mut work = vec![0u32; workspace_len(TABLE_LEN).unwrap()];
    assert!(build_tables(0, 16, &mut a, &mut b, &mut work).is_err());
    assert!(Pmj02BnTables::new(1 << 17, 0).is_err());
}
