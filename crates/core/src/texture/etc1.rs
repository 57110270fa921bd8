//! `OES_compressed_ETC1_RGB8_texture`: sizes, one 4 × 4 block, and whole images.

use super::unpack::word;
use super::{BaseFormat, Image};
use crate::target::expand_to_8;

/// `OES_compressed_ETC1_RGB8_texture`: bytes of a `width` × `height` image, 8 per 4 × 4
/// block (partial blocks at the edges count whole).
pub fn etc1_size(width: u32, height: u32) -> usize {
    width.div_ceil(4) as usize * height.div_ceil(4) as usize * 8
}

/// The ETC1 intensity modifier tables, indexed by the 3-bit table codeword; pixel index
/// values 0 and 1 add the two entries, 2 and 3 subtract them.
const ETC1_MODIFIERS: [[i32; 2]; 8] = [
    [2, 8],
    [5, 17],
    [9, 29],
    [13, 42],
    [18, 60],
    [24, 80],
    [33, 106],
    [47, 183],
];

/// ETC1 widens its 5-bit base colors by bit replication (the format's own rule, which differs
/// from GL's rounding conversion for some values).
fn etc1_widen5(v: u32) -> i32 {
    ((v << 3) | (v >> 2)) as i32
}

/// Decodes one 64-bit ETC1 block (read big-endian) into 16 RGB texels, `out[y * 4 + x]`.
pub fn etc1_block(block: [u8; 8]) -> [[u8; 3]; 16] {
    let hi = u32::from_be_bytes([block[0], block[1], block[2], block[3]]);
    let lo = u32::from_be_bytes([block[4], block[5], block[6], block[7]]);
    let diff = hi & 2 != 0;
    let flip = hi & 1 != 0;
    // Base colors of the two subblocks, 8 bits per channel.
    let mut base = [[0i32; 3]; 2];
    #[allow(clippy::needless_range_loop)] // c indexes both subblocks' channels
    for c in 0..3 {
        let shift = 24 - 8 * c as u32;
        if diff {
            let b1 = (hi >> (shift + 3)) & 31;
            let d = ((hi >> shift) & 7) as i32;
            let d = if d >= 4 { d - 8 } else { d };
            let b2 = (b1 as i32 + d) & 31;
            base[0][c] = etc1_widen5(b1);
            base[1][c] = etc1_widen5(b2 as u32);
        } else {
            base[0][c] = expand_to_8((hi >> (shift + 4)) & 15, 4) as i32;
            base[1][c] = expand_to_8((hi >> shift) & 15, 4) as i32;
        }
    }
    let tables = [(hi >> 5) & 7, (hi >> 2) & 7];
    let mut out = [[0u8; 3]; 16];
    for x in 0..4 {
        for y in 0..4 {
            let sub = if flip {
                (y >= 2) as usize
            } else {
                (x >= 2) as usize
            };
            let i = x * 4 + y;
            let msb = (lo >> (16 + i)) & 1;
            let lsb = (lo >> i) & 1;
            let m = ETC1_MODIFIERS[tables[sub] as usize];
            let modifier = match (msb << 1) | lsb {
                0 => m[0],
                1 => m[1],
                2 => -m[0],
                _ => -m[1],
            };
            out[y * 4 + x] = base[sub].map(|b| (b + modifier).clamp(0, 255) as u8);
        }
    }
    out
}

/// Decodes an ETC1 image of exactly [`etc1_size`] bytes into an RGB level, or `None` when
/// `data` has another size.
pub fn decode_etc1(width: u32, height: u32, data: &[u8]) -> Option<Image> {
    if data.len() != etc1_size(width, height) {
        return None;
    }
    let mut texels = vec![0u32; width as usize * height as usize];
    let blocks_x = width.div_ceil(4) as usize;
    for (n, b) in data.chunks_exact(8).enumerate() {
        let (bx, by) = (n % blocks_x * 4, n / blocks_x * 4);
        let px = etc1_block(b.try_into().expect("8 bytes"));
        for y in 0..4 {
            for x in 0..4 {
                let (tx, ty) = (bx + x, by + y);
                if tx < width as usize && ty < height as usize {
                    let [r, g, b] = px[y * 4 + x];
                    texels[ty * width as usize + tx] = word(r, g, b, 255);
                }
            }
        }
    }
    Some(Image {
        width,
        height,
        format: BaseFormat::Rgb,
        texels,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn etc1_individual_and_differential_blocks() {
        // Individual mode, no flip: left subblock base (0x1, 0x2, 0x3) -> (17, 34, 51) with
        // table 0, right subblock base (0xf, 0xe, 0xd) with table 7. All indices 0 (+a)
        // except pixel (x=1, y=2): index 3 (-b); pixel (x=3, y=0): index 1 (+b).
        let hi: u32 = 0x1f << 24 | 0x2e << 16 | 0x3d << 8 | (7 << 2);
        let i_12 = 4 + 2; // x * 4 + y
        let i_30 = 3 * 4;
        let lo: u32 = (1 << (16 + i_12)) | (1 << i_12) | (1 << i_30);
        let mut b = [0u8; 8];
        b[..4].copy_from_slice(&hi.to_be_bytes());
        b[4..].copy_from_slice(&lo.to_be_bytes());
        let px = etc1_block(b);
        assert_eq!(px[0], [19, 36, 53]); // (0, 0): +2
        assert_eq!(px[2 * 4 + 1], [9, 26, 43]); // (1, 2): -8
        assert_eq!(px[2], [255, 255, 255]); // (2, 0): (255, 238, 221) + 47, clamped
        assert_eq!(px[3], [255, 255, 255]); // (3, 0): +183 clamped

        // Differential mode with flip: top base 5-bit (16, 8, 4), delta (-1, +3, 0).
        let hi: u32 = (16 << 3 | 7) << 24 | (8 << 3 | 3) << 16 | (4 << 3) << 8 | 3;
        b[..4].copy_from_slice(&hi.to_be_bytes());
        b[4..].copy_from_slice(&0u32.to_be_bytes());
        let px = etc1_block(b);
        let e = |v: u32| etc1_widen5(v) + 2;
        assert_eq!(px[0], [e(16) as u8, e(8) as u8, e(4) as u8]);
        assert_eq!(px[3 * 4 + 3], [e(15) as u8, e(11) as u8, e(4) as u8]);
        // Sizes: partial blocks count whole; a 2 × 2 image keeps its top-left texels.
        assert_eq!(etc1_size(4, 4), 8);
        assert_eq!(etc1_size(5, 1), 16);
        let img = decode_etc1(2, 2, &b).unwrap();
        assert_eq!(img.texel(1, 1), [e(16) as u8, e(8) as u8, e(4) as u8, 255]);
        assert!(decode_etc1(8, 8, &b).is_none());
    }
}
