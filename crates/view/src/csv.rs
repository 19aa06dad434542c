//! The numeric CSV tables `biped walk` and `biped simulate` write (plain or gzip-compressed):
//! one header line of column names, then one row of numbers per sample.

use crate::ViewError;
use flate2::read::GzDecoder;
use std::io::Read;
use std::path::Path;

/// A numeric table: column names and rows.
#[derive(Debug, Clone, PartialEq)]
pub struct Table {
    /// Column names from the header.
    pub columns: Vec<String>,
    /// Rows, each as long as `columns`.
    pub rows: Vec<Vec<f64>>,
}

impl Table {
    /// Index of a column by name.
    pub fn column(&self, name: &str) -> Option<usize> {
        self.columns.iter().position(|c| c == name)
    }

    /// Appends the columns of `other` this table lacks, each row taking the values of the
    /// row of `other` nearest in time (both tables sorted by their time column `t`).
    pub fn join(&mut self, other: &Table, t: usize, other_t: usize) {
        let new: Vec<usize> = (0..other.columns.len())
            .filter(|&c| c != other_t && self.column(&other.columns[c]).is_none())
            .collect();
        if other.rows.is_empty() || new.is_empty() {
            return;
        }
        self.columns
            .extend(new.iter().map(|&c| other.columns[c].clone()));
        let mut k = 0;
        for row in &mut self.rows {
            let time = row[t];
            while k + 1 < other.rows.len()
                && (other.rows[k + 1][other_t] - time).abs()
                    <= (other.rows[k][other_t] - time).abs()
            {
                k += 1;
            }
            row.extend(new.iter().map(|&c| other.rows[k][c]));
        }
    }
}

/// Splits one line at commas outside double quotes (`""` inside quotes is one quote).
fn fields(line: &str) -> Vec<String> {
    let mut out = vec![String::new()];
    let mut quoted = false;
    let mut chars = line.chars().peekable();
    while let Some(c) = chars.next() {
        match c {
            '"' if quoted && chars.peek() == Some(&'"') => {
                chars.next();
                out.last_mut().unwrap().push('"');
            }
            '"' => quoted = !quoted,
            ',' if !quoted => out.push(String::new()),
            c => out.last_mut().unwrap().push(c),
        }
    }
    out
}

/// Largest decompressed text of a `.gz` table read (what a compressed file may expand to).
pub const MAX_TEXT: u64 = 4 << 30;

/// Reads a table, gzip-compressed if its name ends in `.gz`; errors name the file, line and
/// column.
pub fn read(path: &Path) -> Result<Table, ViewError> {
    let file = path.display();
    let cannot = |e: std::io::Error| ViewError::Recording(format!("{file}: cannot read: {e}"));
    let text = match path.extension().is_some_and(|e| e == "gz") {
        true => {
            let mut text = String::new();
            let f = std::fs::File::open(path).map_err(cannot)?;
            GzDecoder::new(std::io::BufReader::new(f))
                .take(MAX_TEXT + 1)
                .read_to_string(&mut text)
                .map_err(cannot)?;
            if text.len() as u64 > MAX_TEXT {
                return Err(ViewError::Recording(format!(
                    "{file}: more than {} GiB of text once decompressed",
                    MAX_TEXT >> 30
                )));
            }
            text
        }
        false => std::fs::read_to_string(path).map_err(cannot)?,
    };
    parse(&text, &file.to_string())
}

/// Parses table text; `file` labels errors.
pub fn parse(text: &str, file: &str) -> Result<Table, ViewError> {
    let mut lines = text
        .lines()
        .enumerate()
        .filter(|(_, l)| !l.trim().is_empty());
    let Some((_, header)) = lines.next() else {
        return Err(ViewError::Recording(format!("{file}: empty file")));
    };
    let columns: Vec<String> = fields(header.trim_end_matches('\r'))
        .into_iter()
        .map(|c| c.trim().to_string())
        .collect();
    let mut rows = Vec::new();
    for (i, line) in lines {
        let values = fields(line.trim_end_matches('\r'));
        if values.len() != columns.len() {
            return Err(ViewError::Recording(format!(
                "{file}:{}: {} fields, the header has {}",
                i + 1,
                values.len(),
                columns.len()
            )));
        }
        let parse = |(v, name): (&String, &String)| {
            v.trim().parse::<f64>().map_err(|_| {
                ViewError::Recording(format!(
                    "{file}:{}: column `{name}`: `{v}` is not a number",
                    i + 1
                ))
            })
        };
        rows.push(
            values
                .iter()
                .zip(&columns)
                .map(parse)
                .collect::<Result<_, _>>()?,
        );
    }
    Ok(Table { columns, rows })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn quoted_header_and_numbers() {
        let t = parse("time,\"q[a,b]\",x\n0,1.5,NaN\n0.1,-2,3e-3\n", "t.csv").unwrap();
        assert_eq!(t.columns, ["time", "q[a,b]", "x"]);
        assert_eq!(t.rows[1], [0.1, -2.0, 0.003]);
        assert!(t.rows[0][2].is_nan());
    }

    #[test]
    fn join_takes_the_nearest_row_in_time() {
        let mut a = parse("time,x\n0,1\n0.1,2\n0.2,3\n", "a.csv").unwrap();
        let b = parse("time,x,y\n0,9,10\n0.09,9,20\n0.5,9,30\n", "b.csv").unwrap();
        a.join(&b, 0, 0);
        assert_eq!(a.columns, ["time", "x", "y"]);
        let y: Vec<f64> = a.rows.iter().map(|r| r[2]).collect();
        assert_eq!(y, [10.0, 20.0, 20.0]);
    }

    #[test]
    fn located_errors() {
        let e = parse("time,x\n0,1\n0.1,oops\n", "t.csv")
            .unwrap_err()
            .to_string();
        assert_eq!(e, "t.csv:3: column `x`: `oops` is not a number");
        let e = parse("time,x\n0\n", "t.csv").unwrap_err().to_string();
        assert_eq!(e, "t.csv:2: 1 fields, the header has 2");
    }
}
