//! Text files: numbers in rows under a header (`scan`, `decimal`,
//! `header`), read as a height matrix (`matrix`), two columns — a line
//! scan or a PSD table (`columns`, `colunits`, `validity`, `psd`) — or a
//! contact.engineering TXT download (`ce`); several channels concatenated
//! (`channels`) give one.

pub(crate) mod ce;
pub(crate) mod channels;
pub(crate) mod columns;
pub(crate) mod colunits;
pub(crate) mod decimal;
pub(crate) mod header;
pub(crate) mod matrix;
pub(crate) mod psd;
pub(crate) mod scan;
pub(crate) mod validity;
