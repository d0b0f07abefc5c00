//! [`answer_notes`]: each pattern's answer as a log line.

use super::rows::dem_rows;
use super::words::answer_line;
use super::yields;
use crate::study::design::{DesignOutcome, DesignParams};
use crate::study::rows::label;
use surrogate::units::n_to_mn;

/// The answer of each pattern as a log line (the report's answer without its Markdown).
pub fn answer_notes(o: &DesignOutcome, p: &DesignParams) -> Vec<String> {
    let rows = dem_rows(o, p);
    let top = label(n_to_mn(*p.loads.last().unwrap_or(&0.0)));
    o.patterns
        .iter()
        .zip(&o.answers)
        .zip(o.yields.iter().chain(std::iter::repeat(&None)))
        .map(|((pr, a), y)| {
            let mut line = answer_line(pr, a, &rows, p, top);
            if let Some(s) = yields::sentence(pr, a, y.as_ref()) {
                line.push(' ');
                line.push_str(&s);
            }
            line.replace("**", "").replacen("- ", "answer: ", 1)
        })
        .collect()
}
