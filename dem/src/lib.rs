//! # dem — dynamic DEM tier of superlube (placeholder; filled by the DEM issue)
