//! Reading an input file's text: bounded in size before and while it is read, UTF-8 with
//! an optional byte-order mark, a bad byte reported with its line and offset.

use std::io::Read;
use std::path::Path;

use crate::limits::MAX_FILE_BYTES;
use crate::load::CaseError;

/// The UTF-8 byte-order mark some editors write first; stripped (it used to make the file
/// kind `` and the file unreadable).
const BOM: &[u8] = b"\xEF\xBB\xBF";

/// The text of `file`, at most [`MAX_FILE_BYTES`]: a regular file's size is checked from
/// its metadata before reading, and any file (`/dev/zero`, a pipe) is read only up to one
/// byte past the limit.
pub(crate) fn read_text(file: &Path) -> Result<String, CaseError> {
    let io = |source| CaseError::Io {
        file: file.to_path_buf(),
        source,
    };
    let too_large = |bytes: Option<u64>| CaseError::TooLarge {
        file: file.to_path_buf(),
        bytes,
    };
    let meta = std::fs::metadata(file).map_err(io)?;
    if meta.is_file() && meta.len() > MAX_FILE_BYTES {
        return Err(too_large(Some(meta.len())));
    }
    let mut bytes = Vec::new();
    std::fs::File::open(file)
        .map_err(io)?
        .take(MAX_FILE_BYTES + 1)
        .read_to_end(&mut bytes)
        .map_err(io)?;
    if bytes.len() as u64 > MAX_FILE_BYTES {
        return Err(too_large(None));
    }
    decode(file, bytes)
}

/// `bytes` as UTF-8 text without a leading byte-order mark; an error names the first
/// invalid byte, its 1-based line and its 0-based offset in the file.
fn decode(file: &Path, mut bytes: Vec<u8>) -> Result<String, CaseError> {
    let skipped = if bytes.starts_with(BOM) {
        bytes.drain(..BOM.len());
        BOM.len()
    } else {
        0
    };
    String::from_utf8(bytes).map_err(|e| {
        let at = e.utf8_error().valid_up_to();
        let bytes = e.as_bytes();
        CaseError::Encoding {
            file: file.to_path_buf(),
            line: 1 + bytes[..at].iter().filter(|&&b| b == b'\n').count(),
            offset: at + skipped,
            byte: bytes[at],
        }
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn bom_is_stripped_and_bad_bytes_are_located() {
        let f = Path::new("x.ron");
        assert_eq!(decode(f, b"\xEF\xBB\xBFCase(".to_vec()).unwrap(), "Case(");
        match decode(f, b"\xEF\xBB\xBF// a\n// \xff\n".to_vec()) {
            Err(CaseError::Encoding {
                line, offset, byte, ..
            }) => assert_eq!((line, offset, byte), (2, 11, 0xff)),
            other => panic!("{other:?}"),
        }
    }
}
