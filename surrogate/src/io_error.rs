//! The plain wording of a file error a user meets: `no such file` rather than the operating
//! system's `No such file or directory (os error 2)`. Every input file the tool reads (scene
//! and site files, an index, shards, a dump) words its error with [`plain`] beside the flag or
//! field that named the file.

/// `e` in plain words: `no such file`, `permission denied`, or the system's own text without
/// its `(os error N)` code. O(1).
pub fn plain(e: &std::io::Error) -> String {
    match e.kind() {
        std::io::ErrorKind::NotFound => "no such file".to_string(),
        std::io::ErrorKind::PermissionDenied => "permission denied".to_string(),
        _ => {
            let text = e.to_string();
            match e.raw_os_error() {
                Some(code) => text
                    .trim_end_matches(&format!(" (os error {code})"))
                    .to_string(),
                None => text,
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_missing_file_reads_plainly() {
        let e = std::fs::File::open("/nonexistent/superlube-io-error-test").unwrap_err();
        assert_eq!(plain(&e), "no such file");
        let e = std::io::Error::from_raw_os_error(21);
        assert!(!plain(&e).contains("os error"), "{}", plain(&e));
    }
}
