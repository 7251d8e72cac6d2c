//! glTF accessors read by hand: the `gltf` crate's reader subtracts 1 from an accessor's count
//! and asserts on stride and size (panics on files such as a zero-count accessor), so each
//! accessor is checked here (type, component, stride, byte range within its view and buffer,
//! with checked arithmetic) before a value is read.

use glam::Vec3;
use gltf::accessor::{DataType, Dimensions};

use super::obj_error::MeshError;

/// The bytes of each element of accessor `a` (checked), with its element size.
pub(super) fn elements<'b>(
    buffers: &'b [Vec<u8>],
    a: &gltf::Accessor<'_>,
    size: usize,
) -> Result<impl Iterator<Item = &'b [u8]>, MeshError> {
    let name = format!("accessor {}", a.index());
    if a.sparse().is_some() {
        return Err(malformed(format!(
            "{name} is sparse, which rtc does not read"
        )));
    }
    let view = a
        .view()
        .ok_or_else(|| malformed(format!("{name} has no buffer view")))?;
    let data = buffers
        .get(view.buffer().index())
        .ok_or_else(|| malformed(format!("the buffer of {name} is missing")))?;
    let stride = view.stride().unwrap_or(size);
    let view_end = view.offset().checked_add(view.length());
    let bytes = view_end
        .and_then(|end| data.get(view.offset()..end))
        .ok_or_else(|| malformed(format!("the buffer view of {name} lies outside its buffer")))?;
    let count = a.count();
    let end = count
        .checked_sub(1)
        .and_then(|n| n.checked_mul(stride))
        .and_then(|n| n.checked_add(size))
        .and_then(|n| n.checked_add(a.offset()));
    if count == 0 || stride < size || end.is_none_or(|e| e > bytes.len()) {
        return Err(malformed(format!(
            "{name} ({count} elements of {size} bytes, stride {stride}) does not fit its buffer view"
        )));
    }
    let start = a.offset();
    Ok((0..count).map(move |i| &bytes[start + i * stride..start + i * stride + size]))
}

/// The `N`-component float vectors of accessor `a` (the attribute `what`).
pub(super) fn floats<const N: usize>(
    buffers: &[Vec<u8>],
    a: &gltf::Accessor<'_>,
    what: &str,
) -> Result<Vec<[f32; N]>, MeshError> {
    let dims = match N {
        2 => Dimensions::Vec2,
        _ => Dimensions::Vec3,
    };
    if a.data_type() != DataType::F32 || a.dimensions() != dims {
        return Err(malformed(format!(
            "{what} is {:?} of {:?}; rtc reads {dims:?} of F32",
            a.dimensions(),
            a.data_type()
        )));
    }
    Ok(elements(buffers, a, 4 * N)?
        .map(|e| {
            std::array::from_fn(|k| {
                f32::from_le_bytes([e[4 * k], e[4 * k + 1], e[4 * k + 2], e[4 * k + 3]])
            })
        })
        .collect())
}

/// Vertex colours (`COLOR_0`): RGB or RGBA (alpha not read) of F32, or of normalised U8
/// or U16; channels clamped to [0, 1] (NaN is 0).
pub(super) fn colors(buffers: &[Vec<u8>], a: &gltf::Accessor<'_>) -> Result<Vec<Vec3>, MeshError> {
    let n = match a.dimensions() {
        Dimensions::Vec3 => 3,
        Dimensions::Vec4 => 4,
        other => {
            return Err(malformed(format!(
                "COLOR_0 is {other:?}; glTF allows Vec3 and Vec4"
            )));
        }
    };
    let size = match a.data_type() {
        DataType::F32 => 4,
        DataType::U8 if a.normalized() => 1,
        DataType::U16 if a.normalized() => 2,
        other => {
            return Err(malformed(format!(
                "COLOR_0 is of {other:?}; glTF allows F32 and normalised U8 and U16"
            )));
        }
    };
    let channel = |b: &[u8]| -> f32 {
        let c = match b {
            [x] => f32::from(*x) / 255.0,
            [x, y] => f32::from(u16::from_le_bytes([*x, *y])) / 65535.0,
            [a, b, c, d] => f32::from_le_bytes([*a, *b, *c, *d]),
            _ => 0.0,
        };
        if c.is_nan() { 0.0 } else { c.clamp(0.0, 1.0) }
    };
    Ok(elements(buffers, a, n * size)?
        .map(|e| {
            Vec3::from_array(std::array::from_fn(|k| {
                channel(&e[k * size..(k + 1) * size])
            }))
        })
        .collect())
}

/// Triangle corner indices (unsigned 8, 16 or 32 bit scalars).
pub(super) fn indices(buffers: &[Vec<u8>], a: &gltf::Accessor<'_>) -> Result<Vec<u32>, MeshError> {
    let size = match a.data_type() {
        DataType::U8 => 1,
        DataType::U16 => 2,
        DataType::U32 => 4,
        other => {
            return Err(malformed(format!(
                "indices of type {other:?}; glTF allows U8, U16 and U32"
            )));
        }
    };
    if a.dimensions() != Dimensions::Scalar {
        return Err(malformed("indices must be scalars"));
    }
    Ok(elements(buffers, a, size)?
        .map(|e| match e {
            [b] => u32::from(*b),
            [a, b] => u32::from(u16::from_le_bytes([*a, *b])),
            [a, b, c, d] => u32::from_le_bytes([*a, *b, *c, *d]),
            _ => u32::MAX,
        })
        .collect())
}

/// A malformed glTF file's error, with the fix every such error shares.
pub(super) fn malformed(message: impl Into<String>) -> MeshError {
    MeshError {
        fix: Some("check the file with the Khronos glTF validator, or export it again".to_owned()),
        ..MeshError::new(message, None)
    }
}
