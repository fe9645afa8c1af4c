//! Text in ASCII: the names of the symbols outside it (Ψ Psi, ζ zeta,
//! µ u, ½ 1/2), for a screen that shows only ASCII and for the class's
//! CSV, which a spreadsheet reads in any encoding.

/// The ASCII name of a character outside ASCII: Greek letters by name
/// (ζ zeta, Ψ Psi), µ as u, arrows and dashes as ASCII art; any other
/// character `?` (one column, as the character took at most two).
pub fn ascii_name(c: char) -> &'static str {
    match c {
        'Ψ' => "Psi",
        'ψ' => "psi",
        'ζ' => "zeta",
        'λ' => "lambda",
        'ε' => "eps",
        'µ' | 'μ' => "u",
        'π' => "pi",
        'ρ' => "rho",
        'α' => "alpha",
        'β' => "beta",
        'γ' => "gamma",
        'δ' => "delta",
        'Δ' => "Delta",
        'θ' => "theta",
        'σ' => "sigma",
        'φ' => "phi",
        'ν' => "nu",
        '½' => "1/2",
        '¼' => "1/4",
        '¾' => "3/4",
        '×' => "x",
        '±' => "+/-",
        '∞' => "inf",
        '≈' => "~",
        '≃' => "~",
        '≤' => "<=",
        '≥' => ">=",
        '≠' => "!=",
        '√' => "sqrt",
        '′' => "'",
        '″' => "\"",
        '²' => "^2",
        '³' => "^3",
        '⁴' => "^4",
        '°' => "deg",
        '−' | '–' | '—' | '‐' | '─' | '━' => "-",
        '…' => "...",
        '‘' | '’' => "'",
        '“' | '”' => "\"",
        '·' | '•' | '⋅' => "*",
        '→' => "->",
        '←' => "<-",
        '↔' => "<->",
        '↑' => "^",
        '↓' => "v",
        '⇧' => "Shift-",
        '⏎' => "Enter",
        '⌫' => "Bksp",
        '▶' | '▸' | '►' => ">",
        '◂' | '◄' => "<",
        '●' | '◦' | '○' => "o",
        '◆' => "X",
        '┄' => "..",
        '│' | '┃' => "|",
        '├' | '┤' | '┬' | '┴' | '└' | '┘' | '┌' | '┐' | '┼' => "+",
        '█' | '▀' | '▄' => "#",
        '\u{0304}' => "bar",
        '\u{00a0}' => " ",
        'à' | 'á' | 'â' | 'ã' | 'ä' | 'å' => "a",
        'è' | 'é' | 'ê' | 'ë' => "e",
        'ì' | 'í' | 'î' | 'ï' => "i",
        'ò' | 'ó' | 'ô' | 'õ' | 'ö' => "o",
        'ù' | 'ú' | 'û' | 'ü' => "u",
        'ç' => "c",
        'ñ' => "n",
        'ß' => "ss",
        'À' | 'Á' | 'Â' | 'Ã' | 'Ä' | 'Å' => "A",
        'È' | 'É' | 'Ê' | 'Ë' => "E",
        'Ö' => "O",
        'Ü' => "U",
        _ => "?",
    }
}

/// `text` in ASCII: a middle dot between spaces (a separator, " · ")
/// becomes "|", elsewhere (a product, H0·dA) "*"; every other character
/// outside ASCII its [`ascii_name`].
pub fn to_ascii(text: &str) -> String {
    // "µm (um)" names the unit and how to type it; in ASCII once is enough.
    let text = text.replace("µm (um)", "um");
    let chars: Vec<char> = text.chars().collect();
    let mut out = String::with_capacity(text.len());
    for (i, &c) in chars.iter().enumerate() {
        if c.is_ascii() {
            out.push(c);
        } else if c == '·'
            && i > 0
            && chars[i - 1] == ' '
            && chars.get(i + 1).is_none_or(|n| *n == ' ')
        {
            out.push('|');
        } else {
            out.push_str(ascii_name(c));
        }
    }
    out
}
