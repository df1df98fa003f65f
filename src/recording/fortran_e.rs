//! Numbers in Fortran's E format (`E20.12`: right-aligned, one digit before the point,
//! a signed exponent of two digits at least), as the universal file format's data
//! records hold them, written fast enough for a recorder streaming hundreds of thousands
//! a second and byte for byte as Rust's exactly rounded `{:.11e}` gives them.

use std::fmt::Write as _;
use std::io::Write;

/// Most digits after the point the fast path writes (12 significant digits in all fit a
/// `u64` product of two exact powers of ten).
const FAST_DIGITS_MAX: usize = 15;

/// Writes numbers in Fortran E format without allocating once warmed up.
#[derive(Debug, Default)]
pub struct FortranE {
    scratch: String,
    line: String,
}

/// A number in scientific notation: its sign, its significant digits (ASCII, the first
/// before the point) and its decimal exponent.
struct Scientific {
    negative: bool,
    digits: [u8; FAST_DIGITS_MAX + 1],
    count: usize,
    exponent: i32,
}

impl FortranE {
    /// Appends `value` to `out` right-aligned in `width` characters with `digits` after
    /// the point.
    pub fn push(&mut self, out: &mut String, value: f64, width: usize, digits: usize) {
        let number = match fast_scientific(value, digits) {
            Some(number) => number,
            None => self.exact_scientific(value, digits),
        };
        let exponent_digits = if number.exponent.abs() >= 100 { 3 } else { 2 };
        let point = usize::from(number.count > 1);
        let length = usize::from(number.negative) + number.count + point + 2 + exponent_digits;
        out.extend(std::iter::repeat_n(' ', width.saturating_sub(length)));
        if number.negative {
            out.push('-');
        }
        out.push(char::from(number.digits[0]));
        if point == 1 {
            out.push('.');
            out.extend(
                number.digits[1..number.count]
                    .iter()
                    .map(|&d| char::from(d)),
            );
        }
        out.push('e');
        out.push(if number.exponent < 0 { '-' } else { '+' });
        let mut exponent = number.exponent.unsigned_abs();
        let mut text = [b'0'; 3];
        for d in text[..exponent_digits].iter_mut().rev() {
            *d = b'0' + (exponent % 10) as u8;
            exponent /= 10;
        }
        out.extend(text[..exponent_digits].iter().map(|&d| char::from(d)));
    }

    /// `value` as Rust's exactly rounded `{:.digits$e}` writes it, taken apart; the slow
    /// path, for what [`fast_scientific`] leaves (with more digits than it holds, the
    /// first 16 are kept).
    fn exact_scientific(&mut self, value: f64, digits: usize) -> Scientific {
        self.scratch.clear();
        let _ = write!(self.scratch, "{value:.digits$e}");
        let (mantissa, exponent) = self.scratch.split_once('e').unwrap_or((&self.scratch, "0"));
        let negative = mantissa.starts_with('-');
        let mut number = Scientific {
            negative,
            digits: [b'0'; FAST_DIGITS_MAX + 1],
            count: 0,
            exponent: exponent.parse().unwrap_or(0),
        };
        for d in mantissa
            .bytes()
            .filter(u8::is_ascii_digit)
            .take(FAST_DIGITS_MAX + 1)
        {
            number.digits[number.count] = d;
            number.count += 1;
        }
        number
    }

    /// Writes `values` as dataset 58's record 12: four `E20.12` numbers a line.
    pub fn write_values(&mut self, out: &mut impl Write, values: &[f64]) -> std::io::Result<()> {
        let mut line = std::mem::take(&mut self.line);
        for row in values.chunks(4) {
            line.clear();
            for &v in row {
                self.push(&mut line, v, 20, 11);
            }
            line.push('\n');
            out.write_all(line.as_bytes())?;
        }
        self.line = line;
        Ok(())
    }
}

/// `value` with `digits` after the point as Rust's `{:.digits$e}` rounds it, where one
/// product by an exact power of ten decides every digit: the scaled value's error (half
/// an ulp) is under 1e-3 of a unit of the last digit, so the rounding is certain unless
/// the fraction lies within that of one half. Zero, a value beyond 1e±22 of the digits'
/// scale, or a near tie give `None`: Rust's exact formatting writes those.
fn fast_scientific(value: f64, digits: usize) -> Option<Scientific> {
    if !value.is_finite() || value == 0.0 || digits > FAST_DIGITS_MAX {
        return None;
    }
    let magnitude = value.abs();
    let mut exponent = magnitude.log10().floor() as i32;
    for _ in 0..3 {
        let scaled = scaled(magnitude, digits as i32 - exponent)?;
        let fraction = scaled - scaled.floor();
        if (fraction - 0.5).abs() < 1e-3 {
            return None;
        }
        let rounded = scaled.round();
        let low = 10f64.powi(digits as i32);
        if rounded < low {
            exponent -= 1;
            continue;
        }
        if rounded >= 10.0 * low {
            exponent += 1;
            continue;
        }
        let mut units = rounded as u64;
        let mut number = Scientific {
            negative: value < 0.0,
            digits: [b'0'; FAST_DIGITS_MAX + 1],
            count: digits + 1,
            exponent,
        };
        for d in number.digits[..=digits].iter_mut().rev() {
            *d = b'0' + (units % 10) as u8;
            units /= 10;
        }
        return Some(number);
    }
    None
}

/// `magnitude` × 10^`power` in one rounding, where 10^|power| is exact (|power| ≤ 22).
fn scaled(magnitude: f64, power: i32) -> Option<f64> {
    const EXACT: [f64; 23] = [
        1e0, 1e1, 1e2, 1e3, 1e4, 1e5, 1e6, 1e7, 1e8, 1e9, 1e10, 1e11, 1e12, 1e13, 1e14, 1e15, 1e16,
        1e17, 1e18, 1e19, 1e20, 1e21, 1e22,
    ];
    let factor = *EXACT.get(power.unsigned_abs() as usize)?;
    Some(if power >= 0 {
        magnitude * factor
    } else {
        magnitude / factor
    })
}

#[cfg(test)]
mod tests {
    use super::FortranE;
    use rand::{RngExt, SeedableRng};
    use rand_pcg::Pcg64Mcg;

    fn reference(value: f64, width: usize, digits: usize) -> String {
        let text = format!("{value:.digits$e}");
        let (mantissa, exponent) = text.split_once('e').expect("e");
        let exponent: i32 = exponent.parse().expect("exponent");
        let sign = if exponent < 0 { '-' } else { '+' };
        format!(
            "{:>width$}",
            format!("{mantissa}e{sign}{:02}", exponent.abs())
        )
    }

    #[test]
    fn every_number_is_written_as_rusts_exact_decimal_is() {
        let mut rng = Pcg64Mcg::seed_from_u64(58);
        let mut writer = FortranE::default();
        let mut values = vec![
            0.0,
            -0.0,
            1.0,
            -1.0,
            0.5,
            9.999_999_999_995,
            9.999_999_999_994_9,
            1e-300,
            1e300,
            123_456_789_012.5,
            0.1,
            2.712,
            f64::MIN_POSITIVE,
            f64::MAX,
            5e-324,
            1e22,
            1e23,
        ];
        values.extend((0..200_000).map(|_| {
            let mantissa: f64 = rng.random_range(-10.0..10.0);
            mantissa * 10f64.powi(rng.random_range(-30..30))
        }));
        values.extend(
            (0..20_000)
                .map(|_| f64::from_bits(rng.random::<u64>()))
                .filter(|v| v.is_finite()),
        );
        for v in values {
            for (width, digits) in [(20, 11), (13, 5)] {
                let mut got = String::new();
                writer.push(&mut got, v, width, digits);
                assert_eq!(got, reference(v, width, digits), "{v:e}");
            }
        }
    }
}
