//! Streaming reader of the deck's contact dump (`dump local`: pair distance and the two atom
//! IDs per slider–substrate pair in contact), one frame at a time (memory: one frame).

use super::deck::DUMP_COLUMNS;
use crate::DemError;
use std::io::BufRead;

/// One pair of a frame (LAMMPS units: µm).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct DumpPair {
    /// Centre distance (µm).
    pub dist: f64,
    /// First atom ID.
    pub id1: u64,
    /// Second atom ID.
    pub id2: u64,
}

/// One dump frame.
#[derive(Debug, Clone, PartialEq)]
pub struct DumpFrame {
    /// LAMMPS timestep.
    pub step: u64,
    /// The pairs, in file order.
    pub pairs: Vec<DumpPair>,
}

/// Iterator over the frames of a dump. Errors name the file and line.
pub struct DumpReader<R> {
    input: R,
    name: String,
    line_no: usize,
    buf: String,
    done: bool,
}

impl<R: BufRead> DumpReader<R> {
    /// Reads frames from `input`; `name` (the path) appears in errors.
    pub fn new(input: R, name: &str) -> Self {
        DumpReader {
            input,
            name: name.to_string(),
            line_no: 0,
            buf: String::new(),
            done: false,
        }
    }

    fn err(&self, why: impl std::fmt::Display) -> DemError {
        DemError::invalid(
            "DUMP",
            format!("{} line {}", self.name, self.line_no),
            &why.to_string(),
        )
    }

    /// Next line without its newline, `None` at the end.
    fn line(&mut self) -> Result<Option<&str>, DemError> {
        self.buf.clear();
        let n = self
            .input
            .read_line(&mut self.buf)
            .map_err(|e| DemError::invalid("DUMP", &self.name, &e.to_string()))?;
        if n == 0 {
            return Ok(None);
        }
        self.line_no += 1;
        Ok(Some(self.buf.trim_end_matches(['\n', '\r'])))
    }

    fn expect_line(&mut self, what: &str) -> Result<String, DemError> {
        match self.line()? {
            Some(l) => Ok(l.to_string()),
            None => Err(self.err(format!("file ends where {what} was expected"))),
        }
    }

    fn number<T: std::str::FromStr>(&self, text: &str, what: &str) -> Result<T, DemError> {
        text.trim()
            .parse()
            .map_err(|_| self.err(format!("`{}` is not a valid {what}", text.trim())))
    }

    fn frame(&mut self) -> Result<Option<DumpFrame>, DemError> {
        // skip blank lines before a frame
        let first = loop {
            match self.line()? {
                None => return Ok(None),
                Some(l) if l.trim().is_empty() => continue,
                Some(l) => break l.to_string(),
            }
        };
        if first.trim() != "ITEM: TIMESTEP" {
            return Err(self.err(format!(
                "expected `ITEM: TIMESTEP`, found `{first}` (is this a LAMMPS `dump local` file?)"
            )));
        }
        let l = self.expect_line("the timestep")?;
        let step: u64 = self.number(&l, "timestep")?;
        let mut count: Option<usize> = None;
        loop {
            let item = self.expect_line("an ITEM line")?;
            let item = item.trim();
            if item == "ITEM: NUMBER OF ENTRIES" {
                let l = self.expect_line("the number of entries")?;
                count = Some(self.number(&l, "number of entries")?);
            } else if item.starts_with("ITEM: BOX BOUNDS") {
                for _ in 0..3 {
                    self.expect_line("a box bound")?;
                }
            } else if let Some(cols) = item.strip_prefix("ITEM: ENTRIES") {
                let names: Vec<&str> = cols.split_whitespace().collect();
                let idx: Vec<usize> = DUMP_COLUMNS
                    .iter()
                    .map(|c| {
                        names.iter().position(|n| n == c).ok_or_else(|| {
                            self.err(format!(
                                "the ENTRIES header lacks column `{c}` (columns: {}); write the dump with the exported deck",
                                names.join(" ")
                            ))
                        })
                    })
                    .collect::<Result<_, _>>()?;
                let n = count.ok_or_else(|| self.err("ENTRIES before NUMBER OF ENTRIES"))?;
                let mut pairs = Vec::with_capacity(n);
                for _ in 0..n {
                    let l = self.expect_line("a dump entry")?;
                    let f: Vec<&str> = l.split_whitespace().collect();
                    if f.len() != names.len() {
                        return Err(self.err(format!(
                            "{} fields, the header names {}",
                            f.len(),
                            names.len()
                        )));
                    }
                    let dist: f64 = self.number(f[idx[0]], "distance")?;
                    // LAMMPS writes IDs of local computes as floating-point numbers
                    let id1: f64 = self.number(f[idx[1]], "atom ID")?;
                    let id2: f64 = self.number(f[idx[2]], "atom ID")?;
                    if !(dist.is_finite() && id1 >= 1.0 && id2 >= 1.0) {
                        return Err(self.err("non-finite distance or atom ID below 1"));
                    }
                    pairs.push(DumpPair {
                        dist,
                        id1: id1 as u64,
                        id2: id2 as u64,
                    });
                }
                return Ok(Some(DumpFrame { step, pairs }));
            } else {
                return Err(self.err(format!("unexpected line `{item}`")));
            }
        }
    }
}

impl<R: BufRead> Iterator for DumpReader<R> {
    type Item = Result<DumpFrame, DemError>;
    fn next(&mut self) -> Option<Self::Item> {
        if self.done {
            return None;
        }
        let r = self.frame();
        if !matches!(r, Ok(Some(_))) {
            self.done = true;
        }
        r.transpose()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    const TWO_FRAMES: &str = "ITEM: TIMESTEP\n0\nITEM: NUMBER OF ENTRIES\n2\nITEM: BOX BOUNDS ss ss ss\n-1 1\n-1 1\n-1 1\nITEM: ENTRIES c_cpl c_cpa[1] c_cpa[2]\n2.99 5 1\n2.999 2 6\nITEM: TIMESTEP\n100\nITEM: NUMBER OF ENTRIES\n0\nITEM: BOX BOUNDS ss ss ss\n-1 1\n-1 1\n-1 1\nITEM: ENTRIES c_cpl c_cpa[1] c_cpa[2]\n";

    #[test]
    fn reads_frames() {
        let f: Vec<DumpFrame> = DumpReader::new(TWO_FRAMES.as_bytes(), "t")
            .collect::<Result<_, _>>()
            .unwrap();
        assert_eq!(f.len(), 2);
        assert_eq!(f[0].step, 0);
        assert_eq!(
            f[0].pairs[1],
            DumpPair {
                dist: 2.999,
                id1: 2,
                id2: 6
            }
        );
        assert_eq!(f[1].step, 100);
        assert!(f[1].pairs.is_empty());
    }

    #[test]
    fn errors_name_the_line() {
        let bad = TWO_FRAMES.replace("2.999 2 6", "2.999 2");
        let e = DumpReader::new(bad.as_bytes(), "x.dump")
            .collect::<Result<Vec<_>, _>>()
            .unwrap_err()
            .to_string();
        assert!(e.contains("x.dump line 11"), "{e}");
        let e = DumpReader::new("hello\n".as_bytes(), "x.dump")
            .collect::<Result<Vec<_>, _>>()
            .unwrap_err()
            .to_string();
        assert!(e.contains("ITEM: TIMESTEP"), "{e}");
        let bad = TWO_FRAMES.replace("c_cpa[2]", "c_other");
        let e = DumpReader::new(bad.as_bytes(), "x.dump")
            .collect::<Result<Vec<_>, _>>()
            .unwrap_err()
            .to_string();
        assert!(e.contains("c_cpa[2]"), "{e}");
        let cut = &TWO_FRAMES[..TWO_FRAMES.find("2.999").unwrap()];
        let e = DumpReader::new(cut.as_bytes(), "x.dump")
            .collect::<Result<Vec<_>, _>>()
            .unwrap_err()
            .to_string();
        assert!(e.contains("file ends"), "{e}");
    }
}
