//! Generated equations of `hexapod_twist` (the paper's platform on massless legs twisted into its 90° parallel singularity). Do not edit.
//!
//! Regenerate with `cargo xtask generate hexapod_twist` from `mechanisms/hexapod_twist.toml`.
//!
//! 7 coordinates, 7 constraints, 46 structural nonzeros in Φq.
//! Rank 7 at the initial pose; mobility 6 (Grübler count 6), 0 DOF left with drivers.
//! Each body owns `[X, Y, Z]` (centre of mass), then `[θ, β, γ]` (A = Rz(γ)·Ry(β)·Rx(θ))
//! or Euler parameters `[e0, e1, e2, e3]`. Equations of motion: `M q̈ + Φqᵀλ = Q`, `Φq q̈ = γ`.
//! Sparse outputs hold the pattern's nonzeros in order (row-major, columns ascending).
//!
//! Coordinates:
//! - `0..7` platform (quaternion)
//!
//! Constraint rows:
//! - `0` leg1 (driver): point distance − f, f = (k - c * cos(alpha1.to_radians() + rate * t - phi1.to_radians())).sqrt(), initial = 0.400040306
//! - `1` leg2 (driver): point distance − f, f = (k - c * cos(alpha2.to_radians() + rate * t - phi2.to_radians())).sqrt(), initial = 0.400040306
//! - `2` leg3 (driver): point distance − f, f = (k - c * cos(alpha3.to_radians() + rate * t - phi3.to_radians())).sqrt(), initial = 0.400040306
//! - `3` leg4 (driver): point distance − f, f = (k - c * cos(alpha4.to_radians() + rate * t - phi4.to_radians())).sqrt(), initial = 0.400040306
//! - `4` leg5 (driver): point distance − f, f = (k - c * cos(alpha5.to_radians() + rate * t - phi5.to_radians())).sqrt(), initial = 0.400040306
//! - `5` leg6 (driver): point distance − f, f = (k - c * cos(alpha6.to_radians() + rate * t - phi6.to_radians())).sqrt(), initial = 0.400040306
//! - `6` platform.norm: eᵀe − 1
#![allow(
    clippy::approx_constant,
    clippy::excessive_precision,
    clippy::too_many_arguments,
    clippy::unreadable_literal
)]
use symbody_runtime::{
    BodyInfo, Entry, Formulation, JointInfo, JointKind, KinematicOutputs, LegInfo,
    Mechanism, MechanismInfo, NewtonOutputs, Origin, PlatformInfo, Rotation,
};
use symbody_runtime::parameters::{ParameterError, RunTimeParameters};
/// Constraint residual Φ(q, t).
pub fn phi(k: &[f64], q: &[f64], t: f64, out: &mut [f64]) {
    let k: &[f64; 51] = k.try_into().expect("k must have 51 entries");
    let q: &[f64; 7] = q.try_into().expect("q must have n_coords entries");
    let out: &mut [f64; 7] = out.try_into().expect("out must have 7 entries");
    phi_part_0(k, q, t, out);
}
#[inline(never)]
fn phi_part_0(k: &[f64; 51], q: &[f64; 7], t: f64, out: &mut [f64; 7]) {
    let x7 = 0.8726646259971648 * t;
    let x153 = q[3] * q[3];
    let x154 = q[4] * q[4];
    let x155 = q[5] * q[5];
    let x156 = q[6] * q[6];
    let x157 = x153 + x154;
    let x158 = 2.0 * x157;
    let x160 = x158 - 1.0;
    let x164 = x153 + x156;
    let x165 = 2.0 * x164;
    let x166 = x165 - 1.0;
    let x167 = q[4] * q[5];
    let x168 = 2.0 * x167;
    let x169 = q[3] * q[6];
    let x171 = 2.0 * x169;
    let x174 = q[4] * q[6];
    let x175 = 2.0 * x174;
    let x176 = q[3] * q[5];
    let x177 = 2.0 * x176;
    let x178 = x175 + x177;
    let x179 = x168 + x171;
    let x180 = q[5] * q[6];
    let x181 = 2.0 * x180;
    let x182 = q[3] * q[4];
    let x184 = 2.0 * x182;
    let x186 = x181 - x184;
    let x189 = x175 - x177;
    let x360 = x155 + x157;
    let x361 = x156 + x360;
    let x362 = x361 - 1.0;
    let x1702 = x7 + k[3];
    let x1703 = k[2] + x1702;
    let x1704 = x1703.cos();
    let x1705 = k[1] * x1704;
    let x1707 = k[0] - x1705;
    let x1708 = x1707.sqrt();
    let x1713 = x7 + k[7];
    let x1714 = k[6] + x1713;
    let x1715 = x1714.cos();
    let x1716 = k[5] * x1715;
    let x1718 = k[4] - x1716;
    let x1719 = x1718.sqrt();
    let x1724 = x7 + k[11];
    let x1725 = k[10] + x1724;
    let x1726 = x1725.cos();
    let x1727 = k[9] * x1726;
    let x1729 = k[8] - x1727;
    let x1730 = x1729.sqrt();
    let x1735 = x7 + k[15];
    let x1736 = k[14] + x1735;
    let x1737 = x1736.cos();
    let x1738 = k[13] * x1737;
    let x1740 = k[12] - x1738;
    let x1741 = x1740.sqrt();
    let x1746 = x7 + k[19];
    let x1747 = k[18] + x1746;
    let x1748 = x1747.cos();
    let x1749 = k[17] * x1748;
    let x1751 = k[16] - x1749;
    let x1752 = x1751.sqrt();
    let x1757 = x7 + k[23];
    let x1758 = k[22] + x1757;
    let x1759 = x1758.cos();
    let x1760 = k[21] * x1759;
    let x1762 = k[20] - x1760;
    let x1763 = x1762.sqrt();
    let x1766 = x160 * k[24];
    let x1767 = x178 * k[25];
    let x1768 = x1766 + x1767;
    let x1769 = x179 * k[24];
    let x1770 = x186 * k[25];
    let x1771 = x1769 + x1770;
    let x1772 = x189 * k[24];
    let x1773 = x166 * k[25];
    let x1774 = x1772 + x1773;
    let x1775 = q[0] + x1768;
    let x1776 = q[1] + x1771;
    let x1777 = q[2] + x1774;
    let x1779 = x1775 + k[26];
    let x1781 = x1777 + k[27];
    let x1782 = x1779 * x1779;
    let x1783 = x1776 * x1776;
    let x1784 = x1781 * x1781;
    let x1785 = x1782 + x1783;
    let x1786 = x1784 + x1785;
    let x1787 = x1786.sqrt();
    let x1789 = x1787 - x1708;
    let x1792 = x160 * k[28];
    let x1793 = x178 * k[29];
    let x1794 = x1792 + x1793;
    let x1795 = x179 * k[28];
    let x1796 = x186 * k[29];
    let x1797 = x1795 + x1796;
    let x1798 = x189 * k[28];
    let x1799 = x166 * k[29];
    let x1800 = x1798 + x1799;
    let x1801 = q[0] + x1794;
    let x1802 = q[1] + x1797;
    let x1803 = q[2] + x1800;
    let x1805 = x1801 + k[30];
    let x1807 = x1803 + k[31];
    let x1808 = x1805 * x1805;
    let x1809 = x1802 * x1802;
    let x1810 = x1807 * x1807;
    let x1811 = x1808 + x1809;
    let x1812 = x1810 + x1811;
    let x1813 = x1812.sqrt();
    let x1815 = x1813 - x1719;
    let x1818 = x160 * k[32];
    let x1819 = x178 * k[33];
    let x1820 = x1818 + x1819;
    let x1821 = x179 * k[32];
    let x1822 = x186 * k[33];
    let x1823 = x1821 + x1822;
    let x1824 = x189 * k[32];
    let x1825 = x166 * k[33];
    let x1826 = x1824 + x1825;
    let x1827 = q[0] + x1820;
    let x1828 = q[1] + x1823;
    let x1829 = q[2] + x1826;
    let x1831 = x1827 + k[34];
    let x1833 = x1829 + k[35];
    let x1834 = x1831 * x1831;
    let x1835 = x1828 * x1828;
    let x1836 = x1833 * x1833;
    let x1837 = x1834 + x1835;
    let x1838 = x1836 + x1837;
    let x1839 = x1838.sqrt();
    let x1841 = x1839 - x1730;
    let x1844 = x160 * k[36];
    let x1845 = x178 * k[37];
    let x1846 = x1844 + x1845;
    let x1847 = x179 * k[36];
    let x1848 = x186 * k[37];
    let x1849 = x1847 + x1848;
    let x1850 = x189 * k[36];
    let x1851 = x166 * k[37];
    let x1852 = x1850 + x1851;
    let x1853 = q[0] + x1846;
    let x1854 = q[1] + x1849;
    let x1855 = q[2] + x1852;
    let x1857 = x1853 + k[38];
    let x1859 = x1855 + k[39];
    let x1860 = x1857 * x1857;
    let x1861 = x1854 * x1854;
    let x1862 = x1859 * x1859;
    let x1863 = x1860 + x1861;
    let x1864 = x1862 + x1863;
    let x1865 = x1864.sqrt();
    let x1867 = x1865 - x1741;
    let x1870 = x160 * k[40];
    let x1871 = x178 * k[41];
    let x1872 = x1870 + x1871;
    let x1873 = x179 * k[40];
    let x1874 = x186 * k[41];
    let x1875 = x1873 + x1874;
    let x1876 = x189 * k[40];
    let x1877 = x166 * k[41];
    let x1878 = x1876 + x1877;
    let x1879 = q[0] + x1872;
    let x1880 = q[1] + x1875;
    let x1881 = q[2] + x1878;
    let x1883 = x1879 + k[42];
    let x1885 = x1881 + k[43];
    let x1886 = x1883 * x1883;
    let x1887 = x1880 * x1880;
    let x1888 = x1885 * x1885;
    let x1889 = x1886 + x1887;
    let x1890 = x1888 + x1889;
    let x1891 = x1890.sqrt();
    let x1893 = x1891 - x1752;
    let x1896 = x160 * k[44];
    let x1897 = x178 * k[45];
    let x1898 = x1896 + x1897;
    let x1899 = x179 * k[44];
    let x1900 = x186 * k[45];
    let x1901 = x1899 + x1900;
    let x1902 = x189 * k[44];
    let x1903 = x166 * k[45];
    let x1904 = x1902 + x1903;
    let x1905 = q[0] + x1898;
    let x1906 = q[1] + x1901;
    let x1907 = q[2] + x1904;
    let x1909 = x1905 + k[46];
    let x1911 = x1907 + k[47];
    let x1912 = x1909 * x1909;
    let x1913 = x1906 * x1906;
    let x1914 = x1911 * x1911;
    let x1915 = x1912 + x1913;
    let x1916 = x1914 + x1915;
    let x1917 = x1916.sqrt();
    let x1919 = x1917 - x1763;
    out[0] = x1789;
    out[1] = x1815;
    out[2] = x1841;
    out[3] = x1867;
    out[4] = x1893;
    out[5] = x1919;
    out[6] = x362;
}
/// Nonzeros of Φq in the order of `PHI_Q_ROWS`/`PHI_Q_COLS`.
pub fn phi_q(k: &[f64], q: &[f64], t: f64, out: &mut [f64]) {
    let k: &[f64; 51] = k.try_into().expect("k must have 51 entries");
    let q: &[f64; 7] = q.try_into().expect("q must have n_coords entries");
    let out: &mut [f64; 46] = out.try_into().expect("out must have 46 entries");
    let _ = t;
    phi_q_part_0(k, q, out);
}
#[inline(never)]
fn phi_q_part_0(k: &[f64; 51], q: &[f64; 7], out: &mut [f64; 46]) {
    let x153 = q[3] * q[3];
    let x154 = q[4] * q[4];
    let x156 = q[6] * q[6];
    let x157 = x153 + x154;
    let x158 = 2.0 * x157;
    let x160 = x158 - 1.0;
    let x164 = x153 + x156;
    let x165 = 2.0 * x164;
    let x166 = x165 - 1.0;
    let x167 = q[4] * q[5];
    let x168 = 2.0 * x167;
    let x169 = q[3] * q[6];
    let x171 = 2.0 * x169;
    let x174 = q[4] * q[6];
    let x175 = 2.0 * x174;
    let x176 = q[3] * q[5];
    let x177 = 2.0 * x176;
    let x178 = x175 + x177;
    let x179 = x168 + x171;
    let x180 = q[5] * q[6];
    let x181 = 2.0 * x180;
    let x182 = q[3] * q[4];
    let x184 = 2.0 * x182;
    let x186 = x181 - x184;
    let x189 = x175 - x177;
    let x363 = q[3] * 2.0;
    let x364 = q[4] * 2.0;
    let x365 = q[6] * 2.0;
    let x414 = q[5] * 2.0;
    let x415 = 2.0 * x363;
    let x520 = 2.0 * x364;
    let x660 = 2.0 * x365;
    let x1766 = x160 * k[24];
    let x1767 = x178 * k[25];
    let x1768 = x1766 + x1767;
    let x1769 = x179 * k[24];
    let x1770 = x186 * k[25];
    let x1771 = x1769 + x1770;
    let x1772 = x189 * k[24];
    let x1773 = x166 * k[25];
    let x1774 = x1772 + x1773;
    let x1775 = q[0] + x1768;
    let x1776 = q[1] + x1771;
    let x1777 = q[2] + x1774;
    let x1779 = x1775 + k[26];
    let x1781 = x1777 + k[27];
    let x1782 = x1779 * x1779;
    let x1783 = x1776 * x1776;
    let x1784 = x1781 * x1781;
    let x1785 = x1782 + x1783;
    let x1786 = x1784 + x1785;
    let x1787 = x1786.sqrt();
    let x1792 = x160 * k[28];
    let x1793 = x178 * k[29];
    let x1794 = x1792 + x1793;
    let x1795 = x179 * k[28];
    let x1796 = x186 * k[29];
    let x1797 = x1795 + x1796;
    let x1798 = x189 * k[28];
    let x1799 = x166 * k[29];
    let x1800 = x1798 + x1799;
    let x1801 = q[0] + x1794;
    let x1802 = q[1] + x1797;
    let x1803 = q[2] + x1800;
    let x1805 = x1801 + k[30];
    let x1807 = x1803 + k[31];
    let x1808 = x1805 * x1805;
    let x1809 = x1802 * x1802;
    let x1810 = x1807 * x1807;
    let x1811 = x1808 + x1809;
    let x1812 = x1810 + x1811;
    let x1813 = x1812.sqrt();
    let x1818 = x160 * k[32];
    let x1819 = x178 * k[33];
    let x1820 = x1818 + x1819;
    let x1821 = x179 * k[32];
    let x1822 = x186 * k[33];
    let x1823 = x1821 + x1822;
    let x1824 = x189 * k[32];
    let x1825 = x166 * k[33];
    let x1826 = x1824 + x1825;
    let x1827 = q[0] + x1820;
    let x1828 = q[1] + x1823;
    let x1829 = q[2] + x1826;
    let x1831 = x1827 + k[34];
    let x1833 = x1829 + k[35];
    let x1834 = x1831 * x1831;
    let x1835 = x1828 * x1828;
    let x1836 = x1833 * x1833;
    let x1837 = x1834 + x1835;
    let x1838 = x1836 + x1837;
    let x1839 = x1838.sqrt();
    let x1844 = x160 * k[36];
    let x1845 = x178 * k[37];
    let x1846 = x1844 + x1845;
    let x1847 = x179 * k[36];
    let x1848 = x186 * k[37];
    let x1849 = x1847 + x1848;
    let x1850 = x189 * k[36];
    let x1851 = x166 * k[37];
    let x1852 = x1850 + x1851;
    let x1853 = q[0] + x1846;
    let x1854 = q[1] + x1849;
    let x1855 = q[2] + x1852;
    let x1857 = x1853 + k[38];
    let x1859 = x1855 + k[39];
    let x1860 = x1857 * x1857;
    let x1861 = x1854 * x1854;
    let x1862 = x1859 * x1859;
    let x1863 = x1860 + x1861;
    let x1864 = x1862 + x1863;
    let x1865 = x1864.sqrt();
    let x1870 = x160 * k[40];
    let x1871 = x178 * k[41];
    let x1872 = x1870 + x1871;
    let x1873 = x179 * k[40];
    let x1874 = x186 * k[41];
    let x1875 = x1873 + x1874;
    let x1876 = x189 * k[40];
    let x1877 = x166 * k[41];
    let x1878 = x1876 + x1877;
    let x1879 = q[0] + x1872;
    let x1880 = q[1] + x1875;
    let x1881 = q[2] + x1878;
    let x1883 = x1879 + k[42];
    let x1885 = x1881 + k[43];
    let x1886 = x1883 * x1883;
    let x1887 = x1880 * x1880;
    let x1888 = x1885 * x1885;
    let x1889 = x1886 + x1887;
    let x1890 = x1888 + x1889;
    let x1891 = x1890.sqrt();
    let x1896 = x160 * k[44];
    let x1897 = x178 * k[45];
    let x1898 = x1896 + x1897;
    let x1899 = x179 * k[44];
    let x1900 = x186 * k[45];
    let x1901 = x1899 + x1900;
    let x1902 = x189 * k[44];
    let x1903 = x166 * k[45];
    let x1904 = x1902 + x1903;
    let x1905 = q[0] + x1898;
    let x1906 = q[1] + x1901;
    let x1907 = q[2] + x1904;
    let x1909 = x1905 + k[46];
    let x1911 = x1907 + k[47];
    let x1912 = x1909 * x1909;
    let x1913 = x1906 * x1906;
    let x1914 = x1911 * x1911;
    let x1915 = x1912 + x1913;
    let x1916 = x1914 + x1915;
    let x1917 = x1916.sqrt();
    let x1920 = 2.0 * x1779;
    let x1921 = 2.0 * x1776;
    let x1922 = 2.0 * x1781;
    let x1923 = 2.0 * x1787;
    let x1924 = 1.0 / x1923;
    let x1925 = x1920 * x1924;
    let x1926 = 2.0 * x1805;
    let x1927 = 2.0 * x1802;
    let x1928 = 2.0 * x1807;
    let x1929 = 2.0 * x1813;
    let x1930 = 1.0 / x1929;
    let x1931 = x1926 * x1930;
    let x1932 = 2.0 * x1831;
    let x1933 = 2.0 * x1828;
    let x1934 = 2.0 * x1833;
    let x1935 = 2.0 * x1839;
    let x1936 = 1.0 / x1935;
    let x1937 = x1932 * x1936;
    let x1938 = 2.0 * x1857;
    let x1939 = 2.0 * x1854;
    let x1940 = 2.0 * x1859;
    let x1941 = 2.0 * x1865;
    let x1942 = 1.0 / x1941;
    let x1943 = x1938 * x1942;
    let x1944 = 2.0 * x1883;
    let x1945 = 2.0 * x1880;
    let x1946 = 2.0 * x1885;
    let x1947 = 2.0 * x1891;
    let x1948 = 1.0 / x1947;
    let x1949 = x1944 * x1948;
    let x1950 = 2.0 * x1909;
    let x1951 = 2.0 * x1906;
    let x1952 = 2.0 * x1911;
    let x1953 = 2.0 * x1917;
    let x1954 = 1.0 / x1953;
    let x1955 = x1950 * x1954;
    let x1956 = x1921 * x1924;
    let x1957 = x1927 * x1930;
    let x1958 = x1933 * x1936;
    let x1959 = x1939 * x1942;
    let x1960 = x1945 * x1948;
    let x1961 = x1951 * x1954;
    let x1962 = x1922 * x1924;
    let x1963 = x1928 * x1930;
    let x1964 = x1934 * x1936;
    let x1965 = x1940 * x1942;
    let x1966 = x1946 * x1948;
    let x1967 = x1952 * x1954;
    let x1968 = x415 * k[24];
    let x1969 = x414 * k[25];
    let x1970 = x1968 + x1969;
    let x1971 = x365 * k[24];
    let x1972 = x364 * k[25];
    let x1974 = x1971 - x1972;
    let x1975 = x414 * k[24];
    let x1977 = x415 * k[25];
    let x1978 = x1977 - x1975;
    let x1979 = x1920 * x1970;
    let x1980 = x1921 * x1974;
    let x1981 = x1922 * x1978;
    let x1982 = x1979 + x1980;
    let x1983 = x1981 + x1982;
    let x1984 = x1924 * x1983;
    let x1985 = x415 * k[28];
    let x1986 = x414 * k[29];
    let x1987 = x1985 + x1986;
    let x1988 = x365 * k[28];
    let x1989 = x364 * k[29];
    let x1991 = x1988 - x1989;
    let x1992 = x414 * k[28];
    let x1994 = x415 * k[29];
    let x1995 = x1994 - x1992;
    let x1996 = x1926 * x1987;
    let x1997 = x1927 * x1991;
    let x1998 = x1928 * x1995;
    let x1999 = x1996 + x1997;
    let x2000 = x1998 + x1999;
    let x2001 = x1930 * x2000;
    let x2002 = x415 * k[32];
    let x2003 = x414 * k[33];
    let x2004 = x2002 + x2003;
    let x2005 = x365 * k[32];
    let x2006 = x364 * k[33];
    let x2008 = x2005 - x2006;
    let x2009 = x414 * k[32];
    let x2011 = x415 * k[33];
    let x2012 = x2011 - x2009;
    let x2013 = x1932 * x2004;
    let x2014 = x1933 * x2008;
    let x2015 = x1934 * x2012;
    let x2016 = x2013 + x2014;
    let x2017 = x2015 + x2016;
    let x2018 = x1936 * x2017;
    let x2019 = x415 * k[36];
    let x2020 = x414 * k[37];
    let x2021 = x2019 + x2020;
    let x2022 = x365 * k[36];
    let x2023 = x364 * k[37];
    let x2025 = x2022 - x2023;
    let x2026 = x414 * k[36];
    let x2028 = x415 * k[37];
    let x2029 = x2028 - x2026;
    let x2030 = x1938 * x2021;
    let x2031 = x1939 * x2025;
    let x2032 = x1940 * x2029;
    let x2033 = x2030 + x2031;
    let x2034 = x2032 + x2033;
    let x2035 = x1942 * x2034;
    let x2036 = x415 * k[40];
    let x2037 = x414 * k[41];
    let x2038 = x2036 + x2037;
    let x2039 = x365 * k[40];
    let x2040 = x364 * k[41];
    let x2042 = x2039 - x2040;
    let x2043 = x414 * k[40];
    let x2045 = x415 * k[41];
    let x2046 = x2045 - x2043;
    let x2047 = x1944 * x2038;
    let x2048 = x1945 * x2042;
    let x2049 = x1946 * x2046;
    let x2050 = x2047 + x2048;
    let x2051 = x2049 + x2050;
    let x2052 = x1948 * x2051;
    let x2053 = x415 * k[44];
    let x2054 = x414 * k[45];
    let x2055 = x2053 + x2054;
    let x2056 = x365 * k[44];
    let x2057 = x364 * k[45];
    let x2059 = x2056 - x2057;
    let x2060 = x414 * k[44];
    let x2062 = x415 * k[45];
    let x2063 = x2062 - x2060;
    let x2064 = x1950 * x2055;
    let x2065 = x1951 * x2059;
    let x2066 = x1952 * x2063;
    let x2067 = x2064 + x2065;
    let x2068 = x2066 + x2067;
    let x2069 = x1954 * x2068;
    let x2070 = x520 * k[24];
    let x2071 = x365 * k[25];
    let x2072 = x2070 + x2071;
    let x2073 = x363 * k[25];
    let x2075 = x1975 - x2073;
    let x2076 = x1920 * x2072;
    let x2077 = x1921 * x2075;
    let x2078 = x1922 * x1971;
    let x2079 = x2076 + x2077;
    let x2080 = x2078 + x2079;
    let x2081 = x1924 * x2080;
    let x2082 = x520 * k[28];
    let x2083 = x365 * k[29];
    let x2084 = x2082 + x2083;
    let x2085 = x363 * k[29];
    let x2087 = x1992 - x2085;
    let x2088 = x1926 * x2084;
    let x2089 = x1927 * x2087;
    let x2090 = x1928 * x1988;
    let x2091 = x2088 + x2089;
    let x2092 = x2090 + x2091;
    let x2093 = x1930 * x2092;
    let x2094 = x520 * k[32];
    let x2095 = x365 * k[33];
    let x2096 = x2094 + x2095;
    let x2097 = x363 * k[33];
    let x2099 = x2009 - x2097;
    let x2100 = x1932 * x2096;
    let x2101 = x1933 * x2099;
    let x2102 = x1934 * x2005;
    let x2103 = x2100 + x2101;
    let x2104 = x2102 + x2103;
    let x2105 = x1936 * x2104;
    let x2106 = x520 * k[36];
    let x2107 = x365 * k[37];
    let x2108 = x2106 + x2107;
    let x2109 = x363 * k[37];
    let x2111 = x2026 - x2109;
    let x2112 = x1938 * x2108;
    let x2113 = x1939 * x2111;
    let x2114 = x1940 * x2022;
    let x2115 = x2112 + x2113;
    let x2116 = x2114 + x2115;
    let x2117 = x1942 * x2116;
    let x2118 = x520 * k[40];
    let x2119 = x365 * k[41];
    let x2120 = x2118 + x2119;
    let x2121 = x363 * k[41];
    let x2123 = x2043 - x2121;
    let x2124 = x1944 * x2120;
    let x2125 = x1945 * x2123;
    let x2126 = x1946 * x2039;
    let x2127 = x2124 + x2125;
    let x2128 = x2126 + x2127;
    let x2129 = x1948 * x2128;
    let x2130 = x520 * k[44];
    let x2131 = x365 * k[45];
    let x2132 = x2130 + x2131;
    let x2133 = x363 * k[45];
    let x2135 = x2060 - x2133;
    let x2136 = x1950 * x2132;
    let x2137 = x1951 * x2135;
    let x2138 = x1952 * x2056;
    let x2139 = x2136 + x2137;
    let x2140 = x2138 + x2139;
    let x2141 = x1954 * x2140;
    let x2142 = x364 * k[24];
    let x2143 = x2071 + x2142;
    let x2144 = x363 * k[24];
    let x2145 = x1920 * x2073;
    let x2146 = x1921 * x2143;
    let x2147 = x1922 * x2144;
    let x2149 = x2145 + x2146;
    let x2150 = x2149 - x2147;
    let x2151 = x1924 * x2150;
    let x2152 = x364 * k[28];
    let x2153 = x2083 + x2152;
    let x2154 = x363 * k[28];
    let x2155 = x1926 * x2085;
    let x2156 = x1927 * x2153;
    let x2157 = x1928 * x2154;
    let x2159 = x2155 + x2156;
    let x2160 = x2159 - x2157;
    let x2161 = x1930 * x2160;
    let x2162 = x364 * k[32];
    let x2163 = x2095 + x2162;
    let x2164 = x363 * k[32];
    let x2165 = x1932 * x2097;
    let x2166 = x1933 * x2163;
    let x2167 = x1934 * x2164;
    let x2169 = x2165 + x2166;
    let x2170 = x2169 - x2167;
    let x2171 = x1936 * x2170;
    let x2172 = x364 * k[36];
    let x2173 = x2107 + x2172;
    let x2174 = x363 * k[36];
    let x2175 = x1938 * x2109;
    let x2176 = x1939 * x2173;
    let x2177 = x1940 * x2174;
    let x2179 = x2175 + x2176;
    let x2180 = x2179 - x2177;
    let x2181 = x1942 * x2180;
    let x2182 = x364 * k[40];
    let x2183 = x2119 + x2182;
    let x2184 = x363 * k[40];
    let x2185 = x1944 * x2121;
    let x2186 = x1945 * x2183;
    let x2187 = x1946 * x2184;
    let x2189 = x2185 + x2186;
    let x2190 = x2189 - x2187;
    let x2191 = x1948 * x2190;
    let x2192 = x364 * k[44];
    let x2193 = x2131 + x2192;
    let x2194 = x363 * k[44];
    let x2195 = x1950 * x2133;
    let x2196 = x1951 * x2193;
    let x2197 = x1952 * x2194;
    let x2199 = x2195 + x2196;
    let x2200 = x2199 - x2197;
    let x2201 = x1954 * x2200;
    let x2202 = x1969 + x2144;
    let x2203 = x660 * k[25];
    let x2204 = x2142 + x2203;
    let x2205 = x1920 * x1972;
    let x2206 = x1921 * x2202;
    let x2207 = x1922 * x2204;
    let x2208 = x2205 + x2206;
    let x2209 = x2207 + x2208;
    let x2210 = x1924 * x2209;
    let x2211 = x1986 + x2154;
    let x2212 = x660 * k[29];
    let x2213 = x2152 + x2212;
    let x2214 = x1926 * x1989;
    let x2215 = x1927 * x2211;
    let x2216 = x1928 * x2213;
    let x2217 = x2214 + x2215;
    let x2218 = x2216 + x2217;
    let x2219 = x1930 * x2218;
    let x2220 = x2003 + x2164;
    let x2221 = x660 * k[33];
    let x2222 = x2162 + x2221;
    let x2223 = x1932 * x2006;
    let x2224 = x1933 * x2220;
    let x2225 = x1934 * x2222;
    let x2226 = x2223 + x2224;
    let x2227 = x2225 + x2226;
    let x2228 = x1936 * x2227;
    let x2229 = x2020 + x2174;
    let x2230 = x660 * k[37];
    let x2231 = x2172 + x2230;
    let x2232 = x1938 * x2023;
    let x2233 = x1939 * x2229;
    let x2234 = x1940 * x2231;
    let x2235 = x2232 + x2233;
    let x2236 = x2234 + x2235;
    let x2237 = x1942 * x2236;
    let x2238 = x2037 + x2184;
    let x2239 = x660 * k[41];
    let x2240 = x2182 + x2239;
    let x2241 = x1944 * x2040;
    let x2242 = x1945 * x2238;
    let x2243 = x1946 * x2240;
    let x2244 = x2241 + x2242;
    let x2245 = x2243 + x2244;
    let x2246 = x1948 * x2245;
    let x2247 = x2054 + x2194;
    let x2248 = x660 * k[45];
    let x2249 = x2192 + x2248;
    let x2250 = x1950 * x2057;
    let x2251 = x1951 * x2247;
    let x2252 = x1952 * x2249;
    let x2253 = x2250 + x2251;
    let x2254 = x2252 + x2253;
    let x2255 = x1954 * x2254;
    out[0] = x1925;
    out[1] = x1956;
    out[2] = x1962;
    out[3] = x1984;
    out[4] = x2081;
    out[5] = x2151;
    out[6] = x2210;
    out[7] = x1931;
    out[8] = x1957;
    out[9] = x1963;
    out[10] = x2001;
    out[11] = x2093;
    out[12] = x2161;
    out[13] = x2219;
    out[14] = x1937;
    out[15] = x1958;
    out[16] = x1964;
    out[17] = x2018;
    out[18] = x2105;
    out[19] = x2171;
    out[20] = x2228;
    out[21] = x1943;
    out[22] = x1959;
    out[23] = x1965;
    out[24] = x2035;
    out[25] = x2117;
    out[26] = x2181;
    out[27] = x2237;
    out[28] = x1949;
    out[29] = x1960;
    out[30] = x1966;
    out[31] = x2052;
    out[32] = x2129;
    out[33] = x2191;
    out[34] = x2246;
    out[35] = x1955;
    out[36] = x1961;
    out[37] = x1967;
    out[38] = x2069;
    out[39] = x2141;
    out[40] = x2201;
    out[41] = x2255;
    out[42] = x363;
    out[43] = x364;
    out[44] = x414;
    out[45] = x365;
}
/// Partial time derivative Φt(q, t).
pub fn phi_t(k: &[f64], q: &[f64], t: f64, out: &mut [f64]) {
    let k: &[f64; 51] = k.try_into().expect("k must have 51 entries");
    let q: &[f64; 7] = q.try_into().expect("q must have n_coords entries");
    let out: &mut [f64; 7] = out.try_into().expect("out must have 7 entries");
    let _ = q;
    phi_t_part_0(k, t, out);
}
#[inline(never)]
fn phi_t_part_0(k: &[f64; 51], t: f64, out: &mut [f64; 7]) {
    let x7 = 0.8726646259971648 * t;
    let x1702 = x7 + k[3];
    let x1703 = k[2] + x1702;
    let x1704 = x1703.cos();
    let x1705 = k[1] * x1704;
    let x1707 = k[0] - x1705;
    let x1708 = x1707.sqrt();
    let x1713 = x7 + k[7];
    let x1714 = k[6] + x1713;
    let x1715 = x1714.cos();
    let x1716 = k[5] * x1715;
    let x1718 = k[4] - x1716;
    let x1719 = x1718.sqrt();
    let x1724 = x7 + k[11];
    let x1725 = k[10] + x1724;
    let x1726 = x1725.cos();
    let x1727 = k[9] * x1726;
    let x1729 = k[8] - x1727;
    let x1730 = x1729.sqrt();
    let x1735 = x7 + k[15];
    let x1736 = k[14] + x1735;
    let x1737 = x1736.cos();
    let x1738 = k[13] * x1737;
    let x1740 = k[12] - x1738;
    let x1741 = x1740.sqrt();
    let x1746 = x7 + k[19];
    let x1747 = k[18] + x1746;
    let x1748 = x1747.cos();
    let x1749 = k[17] * x1748;
    let x1751 = k[16] - x1749;
    let x1752 = x1751.sqrt();
    let x1757 = x7 + k[23];
    let x1758 = k[22] + x1757;
    let x1759 = x1758.cos();
    let x1760 = k[21] * x1759;
    let x1762 = k[20] - x1760;
    let x1763 = x1762.sqrt();
    let x2256 = x1703.sin();
    let x2257 = 0.8726646259971648 * x2256;
    let x2258 = k[1] * x2257;
    let x2259 = 2.0 * x1708;
    let x2260 = 1.0 / x2259;
    let x2261 = x2258 * x2260;
    let x2262 = x1714.sin();
    let x2263 = 0.8726646259971648 * x2262;
    let x2264 = k[5] * x2263;
    let x2265 = 2.0 * x1719;
    let x2266 = 1.0 / x2265;
    let x2267 = x2264 * x2266;
    let x2268 = x1725.sin();
    let x2269 = 0.8726646259971648 * x2268;
    let x2270 = k[9] * x2269;
    let x2271 = 2.0 * x1730;
    let x2272 = 1.0 / x2271;
    let x2273 = x2270 * x2272;
    let x2274 = x1736.sin();
    let x2275 = 0.8726646259971648 * x2274;
    let x2276 = k[13] * x2275;
    let x2277 = 2.0 * x1741;
    let x2278 = 1.0 / x2277;
    let x2279 = x2276 * x2278;
    let x2280 = x1747.sin();
    let x2281 = 0.8726646259971648 * x2280;
    let x2282 = k[17] * x2281;
    let x2283 = 2.0 * x1752;
    let x2284 = 1.0 / x2283;
    let x2285 = x2282 * x2284;
    let x2286 = x1758.sin();
    let x2287 = 0.8726646259971648 * x2286;
    let x2288 = k[21] * x2287;
    let x2289 = 2.0 * x1763;
    let x2290 = 1.0 / x2289;
    let x2291 = x2288 * x2290;
    let x2292 = -x2261;
    let x2293 = -x2267;
    let x2294 = -x2273;
    let x2295 = -x2279;
    let x2296 = -x2285;
    let x2297 = -x2291;
    out[0] = x2292;
    out[1] = x2293;
    out[2] = x2294;
    out[3] = x2295;
    out[4] = x2296;
    out[5] = x2297;
    out[6] = 0.0;
}
/// Acceleration right-hand side γ(q, q̇, t) = −D²Φ[(q̇,1),(q̇,1)].
pub fn gamma(k: &[f64], q: &[f64], qd: &[f64], t: f64, out: &mut [f64]) {
    let k: &[f64; 51] = k.try_into().expect("k must have 51 entries");
    let q: &[f64; 7] = q.try_into().expect("q must have n_coords entries");
    let qd: &[f64; 7] = qd.try_into().expect("qd must have n_coords entries");
    let out: &mut [f64; 7] = out.try_into().expect("out must have 7 entries");
    let mut s = [0.0f64; 96];
    gamma_shared_0(k, q, qd, t, &mut s);
    gamma_part_0(k, q, qd, &s, out);
    gamma_part_1(k, q, qd, &s, out);
}
#[inline(never)]
fn gamma_shared_0(
    _k: &[f64; 51],
    q: &[f64; 7],
    qd: &[f64; 7],
    t: f64,
    s: &mut [f64; 96],
) {
    let x7 = 0.8726646259971648 * t;
    s[0] = x7;
    let x153 = q[3] * q[3];
    s[1] = x153;
    let x154 = q[4] * q[4];
    s[2] = x154;
    let x156 = q[6] * q[6];
    s[3] = x156;
    let x157 = x153 + x154;
    s[4] = x157;
    let x158 = 2.0 * x157;
    s[5] = x158;
    let x160 = x158 - 1.0;
    s[6] = x160;
    let x164 = x153 + x156;
    s[7] = x164;
    let x165 = 2.0 * x164;
    s[8] = x165;
    let x166 = x165 - 1.0;
    s[9] = x166;
    let x167 = q[4] * q[5];
    s[10] = x167;
    let x168 = 2.0 * x167;
    s[11] = x168;
    let x169 = q[3] * q[6];
    s[12] = x169;
    let x171 = 2.0 * x169;
    s[13] = x171;
    let x174 = q[4] * q[6];
    s[14] = x174;
    let x175 = 2.0 * x174;
    s[15] = x175;
    let x176 = q[3] * q[5];
    s[16] = x176;
    let x177 = 2.0 * x176;
    s[17] = x177;
    let x178 = x175 + x177;
    s[18] = x178;
    let x179 = x168 + x171;
    s[19] = x179;
    let x180 = q[5] * q[6];
    s[20] = x180;
    let x181 = 2.0 * x180;
    s[21] = x181;
    let x182 = q[3] * q[4];
    s[22] = x182;
    let x184 = 2.0 * x182;
    s[23] = x184;
    let x186 = x181 - x184;
    s[24] = x186;
    let x189 = x175 - x177;
    s[25] = x189;
    let x363 = q[3] * 2.0;
    s[26] = x363;
    let x364 = q[4] * 2.0;
    s[27] = x364;
    let x365 = q[6] * 2.0;
    s[28] = x365;
    let x782 = x363 * qd[3];
    s[29] = x782;
    let x783 = x364 * qd[4];
    s[30] = x783;
    let x785 = x365 * qd[6];
    s[31] = x785;
    let x786 = x782 + x783;
    s[32] = x786;
    let x787 = 2.0 * x786;
    s[33] = x787;
    let x788 = x782 + x785;
    s[34] = x788;
    let x789 = 2.0 * x788;
    s[35] = x789;
    let x790 = q[5] * qd[4];
    s[36] = x790;
    let x791 = q[4] * qd[5];
    s[37] = x791;
    let x792 = x790 + x791;
    s[38] = x792;
    let x793 = 2.0 * x792;
    s[39] = x793;
    let x794 = q[6] * qd[3];
    s[40] = x794;
    let x795 = q[3] * qd[6];
    s[41] = x795;
    let x796 = x794 + x795;
    s[42] = x796;
    let x797 = 2.0 * x796;
    s[43] = x797;
    let x798 = q[6] * qd[4];
    s[44] = x798;
    let x799 = q[4] * qd[6];
    s[45] = x799;
    let x800 = x798 + x799;
    s[46] = x800;
    let x801 = 2.0 * x800;
    s[47] = x801;
    let x802 = q[5] * qd[3];
    s[48] = x802;
    let x803 = q[3] * qd[5];
    s[49] = x803;
    let x804 = x802 + x803;
    s[50] = x804;
    let x805 = 2.0 * x804;
    s[51] = x805;
    let x806 = x801 + x805;
    s[52] = x806;
    let x807 = x793 + x797;
    s[53] = x807;
    let x808 = q[6] * qd[5];
    s[54] = x808;
    let x809 = q[5] * qd[6];
    s[55] = x809;
    let x810 = x808 + x809;
    s[56] = x810;
    let x811 = 2.0 * x810;
    s[57] = x811;
    let x812 = q[4] * qd[3];
    s[58] = x812;
    let x813 = q[3] * qd[4];
    s[59] = x813;
    let x814 = x812 + x813;
    s[60] = x814;
    let x815 = 2.0 * x814;
    s[61] = x815;
    let x817 = x811 - x815;
    s[62] = x817;
    let x819 = x801 - x805;
    s[63] = x819;
    let x936 = 2.0 * qd[3];
    s[64] = x936;
    let x937 = 2.0 * qd[4];
    s[65] = x937;
    let x938 = 2.0 * qd[6];
    s[66] = x938;
    let x1054 = qd[3] * x936;
    s[67] = x1054;
    let x1055 = qd[4] * x937;
    s[68] = x1055;
    let x1057 = qd[6] * x938;
    s[69] = x1057;
    let x1058 = x1054 + x1055;
    s[70] = x1058;
    let x1059 = 2.0 * x1058;
    s[71] = x1059;
    let x1060 = x1054 + x1057;
    s[72] = x1060;
    let x1061 = 2.0 * x1060;
    s[73] = x1061;
    let x1062 = qd[4] * qd[5];
    s[74] = x1062;
    let x1063 = x1062 + x1062;
    s[75] = x1063;
    let x1064 = 2.0 * x1063;
    s[76] = x1064;
    let x1065 = qd[3] * qd[6];
    s[77] = x1065;
    let x1066 = x1065 + x1065;
    s[78] = x1066;
    let x1067 = 2.0 * x1066;
    s[79] = x1067;
    let x1068 = qd[4] * qd[6];
    s[80] = x1068;
    let x1069 = x1068 + x1068;
    s[81] = x1069;
    let x1070 = 2.0 * x1069;
    s[82] = x1070;
    let x1071 = qd[3] * qd[5];
    s[83] = x1071;
    let x1072 = x1071 + x1071;
    s[84] = x1072;
    let x1073 = 2.0 * x1072;
    s[85] = x1073;
    let x1074 = x1070 + x1073;
    s[86] = x1074;
    let x1075 = x1064 + x1067;
    s[87] = x1075;
    let x1076 = qd[5] * qd[6];
    s[88] = x1076;
    let x1077 = x1076 + x1076;
    s[89] = x1077;
    let x1078 = 2.0 * x1077;
    s[90] = x1078;
    let x1079 = qd[3] * qd[4];
    s[91] = x1079;
    let x1080 = x1079 + x1079;
    s[92] = x1080;
    let x1081 = 2.0 * x1080;
    s[93] = x1081;
    let x1083 = x1078 - x1081;
    s[94] = x1083;
    let x1085 = x1070 - x1073;
    s[95] = x1085;
}
#[inline(never)]
fn gamma_part_0(
    k: &[f64; 51],
    q: &[f64; 7],
    qd: &[f64; 7],
    s: &[f64; 96],
    out: &mut [f64; 7],
) {
    let x1702 = s[0] + k[3];
    let x1703 = k[2] + x1702;
    let x1704 = x1703.cos();
    let x1705 = k[1] * x1704;
    let x1707 = k[0] - x1705;
    let x1708 = x1707.sqrt();
    let x1713 = s[0] + k[7];
    let x1714 = k[6] + x1713;
    let x1715 = x1714.cos();
    let x1716 = k[5] * x1715;
    let x1718 = k[4] - x1716;
    let x1719 = x1718.sqrt();
    let x1724 = s[0] + k[11];
    let x1725 = k[10] + x1724;
    let x1726 = x1725.cos();
    let x1727 = k[9] * x1726;
    let x1729 = k[8] - x1727;
    let x1730 = x1729.sqrt();
    let x1735 = s[0] + k[15];
    let x1736 = k[14] + x1735;
    let x1737 = x1736.cos();
    let x1738 = k[13] * x1737;
    let x1740 = k[12] - x1738;
    let x1741 = x1740.sqrt();
    let x1746 = s[0] + k[19];
    let x1747 = k[18] + x1746;
    let x1748 = x1747.cos();
    let x1749 = k[17] * x1748;
    let x1751 = k[16] - x1749;
    let x1752 = x1751.sqrt();
    let x1766 = s[6] * k[24];
    let x1767 = s[18] * k[25];
    let x1768 = x1766 + x1767;
    let x1769 = s[19] * k[24];
    let x1770 = s[24] * k[25];
    let x1771 = x1769 + x1770;
    let x1772 = s[25] * k[24];
    let x1773 = s[9] * k[25];
    let x1774 = x1772 + x1773;
    let x1775 = q[0] + x1768;
    let x1776 = q[1] + x1771;
    let x1777 = q[2] + x1774;
    let x1779 = x1775 + k[26];
    let x1781 = x1777 + k[27];
    let x1782 = x1779 * x1779;
    let x1783 = x1776 * x1776;
    let x1784 = x1781 * x1781;
    let x1785 = x1782 + x1783;
    let x1786 = x1784 + x1785;
    let x1787 = x1786.sqrt();
    let x1792 = s[6] * k[28];
    let x1793 = s[18] * k[29];
    let x1794 = x1792 + x1793;
    let x1795 = s[19] * k[28];
    let x1796 = s[24] * k[29];
    let x1797 = x1795 + x1796;
    let x1798 = s[25] * k[28];
    let x1799 = s[9] * k[29];
    let x1800 = x1798 + x1799;
    let x1801 = q[0] + x1794;
    let x1802 = q[1] + x1797;
    let x1803 = q[2] + x1800;
    let x1805 = x1801 + k[30];
    let x1807 = x1803 + k[31];
    let x1808 = x1805 * x1805;
    let x1809 = x1802 * x1802;
    let x1810 = x1807 * x1807;
    let x1811 = x1808 + x1809;
    let x1812 = x1810 + x1811;
    let x1813 = x1812.sqrt();
    let x1818 = s[6] * k[32];
    let x1819 = s[18] * k[33];
    let x1820 = x1818 + x1819;
    let x1821 = s[19] * k[32];
    let x1822 = s[24] * k[33];
    let x1823 = x1821 + x1822;
    let x1824 = s[25] * k[32];
    let x1825 = s[9] * k[33];
    let x1826 = x1824 + x1825;
    let x1827 = q[0] + x1820;
    let x1828 = q[1] + x1823;
    let x1829 = q[2] + x1826;
    let x1831 = x1827 + k[34];
    let x1833 = x1829 + k[35];
    let x1834 = x1831 * x1831;
    let x1835 = x1828 * x1828;
    let x1836 = x1833 * x1833;
    let x1837 = x1834 + x1835;
    let x1838 = x1836 + x1837;
    let x1839 = x1838.sqrt();
    let x1844 = s[6] * k[36];
    let x1845 = s[18] * k[37];
    let x1846 = x1844 + x1845;
    let x1847 = s[19] * k[36];
    let x1848 = s[24] * k[37];
    let x1849 = x1847 + x1848;
    let x1850 = s[25] * k[36];
    let x1851 = s[9] * k[37];
    let x1852 = x1850 + x1851;
    let x1853 = q[0] + x1846;
    let x1854 = q[1] + x1849;
    let x1855 = q[2] + x1852;
    let x1857 = x1853 + k[38];
    let x1859 = x1855 + k[39];
    let x1860 = x1857 * x1857;
    let x1861 = x1854 * x1854;
    let x1862 = x1859 * x1859;
    let x1863 = x1860 + x1861;
    let x1864 = x1862 + x1863;
    let x1865 = x1864.sqrt();
    let x1870 = s[6] * k[40];
    let x1871 = s[18] * k[41];
    let x1872 = x1870 + x1871;
    let x1873 = s[19] * k[40];
    let x1874 = s[24] * k[41];
    let x1875 = x1873 + x1874;
    let x1876 = s[25] * k[40];
    let x1877 = s[9] * k[41];
    let x1878 = x1876 + x1877;
    let x1879 = q[0] + x1872;
    let x1880 = q[1] + x1875;
    let x1881 = q[2] + x1878;
    let x1883 = x1879 + k[42];
    let x1885 = x1881 + k[43];
    let x1886 = x1883 * x1883;
    let x1887 = x1880 * x1880;
    let x1888 = x1885 * x1885;
    let x1889 = x1886 + x1887;
    let x1890 = x1888 + x1889;
    let x1891 = x1890.sqrt();
    let x1920 = 2.0 * x1779;
    let x1921 = 2.0 * x1776;
    let x1922 = 2.0 * x1781;
    let x1923 = 2.0 * x1787;
    let x1924 = 1.0 / x1923;
    let x1926 = 2.0 * x1805;
    let x1927 = 2.0 * x1802;
    let x1928 = 2.0 * x1807;
    let x1929 = 2.0 * x1813;
    let x1930 = 1.0 / x1929;
    let x1932 = 2.0 * x1831;
    let x1933 = 2.0 * x1828;
    let x1934 = 2.0 * x1833;
    let x1935 = 2.0 * x1839;
    let x1936 = 1.0 / x1935;
    let x1938 = 2.0 * x1857;
    let x1939 = 2.0 * x1854;
    let x1940 = 2.0 * x1859;
    let x1941 = 2.0 * x1865;
    let x1942 = 1.0 / x1941;
    let x1944 = 2.0 * x1883;
    let x1945 = 2.0 * x1880;
    let x1946 = 2.0 * x1885;
    let x1947 = 2.0 * x1891;
    let x1948 = 1.0 / x1947;
    let x2256 = x1703.sin();
    let x2257 = 0.8726646259971648 * x2256;
    let x2258 = k[1] * x2257;
    let x2259 = 2.0 * x1708;
    let x2260 = 1.0 / x2259;
    let x2261 = x2258 * x2260;
    let x2262 = x1714.sin();
    let x2263 = 0.8726646259971648 * x2262;
    let x2264 = k[5] * x2263;
    let x2265 = 2.0 * x1719;
    let x2266 = 1.0 / x2265;
    let x2267 = x2264 * x2266;
    let x2268 = x1725.sin();
    let x2269 = 0.8726646259971648 * x2268;
    let x2270 = k[9] * x2269;
    let x2271 = 2.0 * x1730;
    let x2272 = 1.0 / x2271;
    let x2273 = x2270 * x2272;
    let x2274 = x1736.sin();
    let x2275 = 0.8726646259971648 * x2274;
    let x2276 = k[13] * x2275;
    let x2277 = 2.0 * x1741;
    let x2278 = 1.0 / x2277;
    let x2279 = x2276 * x2278;
    let x2280 = x1747.sin();
    let x2281 = 0.8726646259971648 * x2280;
    let x2282 = k[17] * x2281;
    let x2283 = 2.0 * x1752;
    let x2284 = 1.0 / x2283;
    let x2285 = x2282 * x2284;
    let x2298 = s[33] * k[24];
    let x2299 = s[52] * k[25];
    let x2300 = x2298 + x2299;
    let x2301 = s[53] * k[24];
    let x2302 = s[62] * k[25];
    let x2303 = x2301 + x2302;
    let x2304 = s[63] * k[24];
    let x2305 = s[35] * k[25];
    let x2306 = x2304 + x2305;
    let x2307 = qd[0] + x2300;
    let x2308 = qd[1] + x2303;
    let x2309 = qd[2] + x2306;
    let x2310 = x1920 * x2307;
    let x2311 = x1921 * x2308;
    let x2312 = x1922 * x2309;
    let x2313 = x2310 + x2311;
    let x2314 = x2312 + x2313;
    let x2315 = x1924 * x2314;
    let x2316 = s[33] * k[28];
    let x2317 = s[52] * k[29];
    let x2318 = x2316 + x2317;
    let x2319 = s[53] * k[28];
    let x2320 = s[62] * k[29];
    let x2321 = x2319 + x2320;
    let x2322 = s[63] * k[28];
    let x2323 = s[35] * k[29];
    let x2324 = x2322 + x2323;
    let x2325 = qd[0] + x2318;
    let x2326 = qd[1] + x2321;
    let x2327 = qd[2] + x2324;
    let x2328 = x1926 * x2325;
    let x2329 = x1927 * x2326;
    let x2330 = x1928 * x2327;
    let x2331 = x2328 + x2329;
    let x2332 = x2330 + x2331;
    let x2333 = x1930 * x2332;
    let x2334 = s[33] * k[32];
    let x2335 = s[52] * k[33];
    let x2336 = x2334 + x2335;
    let x2337 = s[53] * k[32];
    let x2338 = s[62] * k[33];
    let x2339 = x2337 + x2338;
    let x2340 = s[63] * k[32];
    let x2341 = s[35] * k[33];
    let x2342 = x2340 + x2341;
    let x2343 = qd[0] + x2336;
    let x2344 = qd[1] + x2339;
    let x2345 = qd[2] + x2342;
    let x2346 = x1932 * x2343;
    let x2347 = x1933 * x2344;
    let x2348 = x1934 * x2345;
    let x2349 = x2346 + x2347;
    let x2350 = x2348 + x2349;
    let x2351 = x1936 * x2350;
    let x2352 = s[33] * k[36];
    let x2353 = s[52] * k[37];
    let x2354 = x2352 + x2353;
    let x2355 = s[53] * k[36];
    let x2356 = s[62] * k[37];
    let x2357 = x2355 + x2356;
    let x2358 = s[63] * k[36];
    let x2359 = s[35] * k[37];
    let x2360 = x2358 + x2359;
    let x2361 = qd[0] + x2354;
    let x2362 = qd[1] + x2357;
    let x2363 = qd[2] + x2360;
    let x2364 = x1938 * x2361;
    let x2365 = x1939 * x2362;
    let x2366 = x1940 * x2363;
    let x2367 = x2364 + x2365;
    let x2368 = x2366 + x2367;
    let x2369 = x1942 * x2368;
    let x2370 = s[33] * k[40];
    let x2371 = s[52] * k[41];
    let x2372 = x2370 + x2371;
    let x2373 = s[53] * k[40];
    let x2374 = s[62] * k[41];
    let x2375 = x2373 + x2374;
    let x2376 = s[63] * k[40];
    let x2377 = s[35] * k[41];
    let x2378 = x2376 + x2377;
    let x2379 = qd[0] + x2372;
    let x2380 = qd[1] + x2375;
    let x2381 = qd[2] + x2378;
    let x2382 = x1944 * x2379;
    let x2383 = x1945 * x2380;
    let x2384 = x1946 * x2381;
    let x2385 = x2382 + x2383;
    let x2386 = x2384 + x2385;
    let x2387 = x1948 * x2386;
    let x2406 = 2.0 * x2307;
    let x2407 = 2.0 * x2308;
    let x2408 = 2.0 * x2309;
    let x2409 = 2.0 * x2315;
    let x2410 = x1924 * x1924;
    let x2411 = x2409 * x2410;
    let x2412 = 2.0 * x2325;
    let x2413 = 2.0 * x2326;
    let x2414 = 2.0 * x2327;
    let x2415 = 2.0 * x2333;
    let x2416 = x1930 * x1930;
    let x2417 = x2415 * x2416;
    let x2418 = 2.0 * x2343;
    let x2419 = 2.0 * x2344;
    let x2420 = 2.0 * x2345;
    let x2421 = 2.0 * x2351;
    let x2422 = x1936 * x1936;
    let x2423 = x2421 * x2422;
    let x2424 = 2.0 * x2361;
    let x2425 = 2.0 * x2362;
    let x2426 = 2.0 * x2363;
    let x2427 = 2.0 * x2369;
    let x2428 = x1942 * x1942;
    let x2429 = x2427 * x2428;
    let x2430 = 2.0 * x2379;
    let x2431 = 2.0 * x2380;
    let x2432 = 2.0 * x2381;
    let x2433 = 2.0 * x2387;
    let x2434 = x1948 * x1948;
    let x2435 = x2433 * x2434;
    let x2442 = 0.8726646259971648 * x1704;
    let x2443 = 0.8726646259971648 * x2442;
    let x2444 = k[1] * x2443;
    let x2445 = 2.0 * x2261;
    let x2446 = x2260 * x2260;
    let x2447 = x2445 * x2446;
    let x2448 = x2260 * x2444;
    let x2449 = x2258 * x2447;
    let x2451 = x2448 - x2449;
    let x2452 = 0.8726646259971648 * x1715;
    let x2453 = 0.8726646259971648 * x2452;
    let x2454 = k[5] * x2453;
    let x2455 = 2.0 * x2267;
    let x2456 = x2266 * x2266;
    let x2457 = x2455 * x2456;
    let x2458 = x2266 * x2454;
    let x2459 = x2264 * x2457;
    let x2461 = x2458 - x2459;
    let x2462 = 0.8726646259971648 * x1726;
    let x2463 = 0.8726646259971648 * x2462;
    let x2464 = k[9] * x2463;
    let x2465 = 2.0 * x2273;
    let x2466 = x2272 * x2272;
    let x2467 = x2465 * x2466;
    let x2468 = x2272 * x2464;
    let x2469 = x2270 * x2467;
    let x2471 = x2468 - x2469;
    let x2472 = 0.8726646259971648 * x1737;
    let x2473 = 0.8726646259971648 * x2472;
    let x2474 = k[13] * x2473;
    let x2475 = 2.0 * x2279;
    let x2476 = x2278 * x2278;
    let x2477 = x2475 * x2476;
    let x2478 = x2278 * x2474;
    let x2479 = x2276 * x2477;
    let x2481 = x2478 - x2479;
    let x2482 = 0.8726646259971648 * x1748;
    let x2483 = 0.8726646259971648 * x2482;
    let x2484 = k[17] * x2483;
    let x2485 = 2.0 * x2285;
    let x2486 = x2284 * x2284;
    let x2487 = x2485 * x2486;
    let x2488 = x2284 * x2484;
    let x2489 = x2282 * x2487;
    let x2491 = x2488 - x2489;
    let x2508 = s[71] * k[24];
    let x2509 = s[86] * k[25];
    let x2510 = x2508 + x2509;
    let x2511 = s[87] * k[24];
    let x2512 = s[94] * k[25];
    let x2513 = x2511 + x2512;
    let x2514 = s[95] * k[24];
    let x2515 = s[73] * k[25];
    let x2516 = x2514 + x2515;
    let x2517 = x2307 * x2406;
    let x2518 = x1920 * x2510;
    let x2519 = x2517 + x2518;
    let x2520 = x2308 * x2407;
    let x2521 = x1921 * x2513;
    let x2522 = x2520 + x2521;
    let x2523 = x2309 * x2408;
    let x2524 = x1922 * x2516;
    let x2525 = x2523 + x2524;
    let x2526 = x2519 + x2522;
    let x2527 = x2525 + x2526;
    let x2528 = x2314 * x2411;
    let x2530 = x1924 * x2527;
    let x2531 = x2530 - x2528;
    let x2532 = x2531 - x2451;
    let x2533 = s[71] * k[28];
    let x2534 = s[86] * k[29];
    let x2535 = x2533 + x2534;
    let x2536 = s[87] * k[28];
    let x2537 = s[94] * k[29];
    let x2538 = x2536 + x2537;
    let x2539 = s[95] * k[28];
    let x2540 = s[73] * k[29];
    let x2541 = x2539 + x2540;
    let x2542 = x2325 * x2412;
    let x2543 = x1926 * x2535;
    let x2544 = x2542 + x2543;
    let x2545 = x2326 * x2413;
    let x2546 = x1927 * x2538;
    let x2547 = x2545 + x2546;
    let x2548 = x2327 * x2414;
    let x2549 = x1928 * x2541;
    let x2550 = x2548 + x2549;
    let x2551 = x2544 + x2547;
    let x2552 = x2550 + x2551;
    let x2553 = x2332 * x2417;
    let x2555 = x1930 * x2552;
    let x2556 = x2555 - x2553;
    let x2557 = x2556 - x2461;
    let x2558 = s[71] * k[32];
    let x2559 = s[86] * k[33];
    let x2560 = x2558 + x2559;
    let x2561 = s[87] * k[32];
    let x2562 = s[94] * k[33];
    let x2563 = x2561 + x2562;
    let x2564 = s[95] * k[32];
    let x2565 = s[73] * k[33];
    let x2566 = x2564 + x2565;
    let x2567 = x2343 * x2418;
    let x2568 = x1932 * x2560;
    let x2569 = x2567 + x2568;
    let x2570 = x2344 * x2419;
    let x2571 = x1933 * x2563;
    let x2572 = x2570 + x2571;
    let x2573 = x2345 * x2420;
    let x2574 = x1934 * x2566;
    let x2575 = x2573 + x2574;
    let x2576 = x2569 + x2572;
    let x2577 = x2575 + x2576;
    let x2578 = x2350 * x2423;
    let x2580 = x1936 * x2577;
    let x2581 = x2580 - x2578;
    let x2582 = x2581 - x2471;
    let x2583 = s[71] * k[36];
    let x2584 = s[86] * k[37];
    let x2585 = x2583 + x2584;
    let x2586 = s[87] * k[36];
    let x2587 = s[94] * k[37];
    let x2588 = x2586 + x2587;
    let x2589 = s[95] * k[36];
    let x2590 = s[73] * k[37];
    let x2591 = x2589 + x2590;
    let x2592 = x2361 * x2424;
    let x2593 = x1938 * x2585;
    let x2594 = x2592 + x2593;
    let x2595 = x2362 * x2425;
    let x2596 = x1939 * x2588;
    let x2597 = x2595 + x2596;
    let x2598 = x2363 * x2426;
    let x2599 = x1940 * x2591;
    let x2600 = x2598 + x2599;
    let x2601 = x2594 + x2597;
    let x2602 = x2600 + x2601;
    let x2603 = x2368 * x2429;
    let x2605 = x1942 * x2602;
    let x2606 = x2605 - x2603;
    let x2607 = x2606 - x2481;
    let x2608 = s[71] * k[40];
    let x2609 = s[86] * k[41];
    let x2610 = x2608 + x2609;
    let x2611 = s[87] * k[40];
    let x2612 = s[94] * k[41];
    let x2613 = x2611 + x2612;
    let x2614 = s[95] * k[40];
    let x2615 = s[73] * k[41];
    let x2616 = x2614 + x2615;
    let x2617 = x2379 * x2430;
    let x2618 = x1944 * x2610;
    let x2619 = x2617 + x2618;
    let x2620 = x2380 * x2431;
    let x2621 = x1945 * x2613;
    let x2622 = x2620 + x2621;
    let x2623 = x2381 * x2432;
    let x2624 = x1946 * x2616;
    let x2625 = x2623 + x2624;
    let x2626 = x2619 + x2622;
    let x2627 = x2625 + x2626;
    let x2628 = x2386 * x2435;
    let x2630 = x1948 * x2627;
    let x2631 = x2630 - x2628;
    let x2632 = x2631 - x2491;
    let x2658 = -x2532;
    let x2659 = -x2557;
    let x2660 = -x2582;
    let x2661 = -x2607;
    let x2662 = -x2632;
    out[0] = x2658;
    out[1] = x2659;
    out[2] = x2660;
    out[3] = x2661;
    out[4] = x2662;
}
#[inline(never)]
fn gamma_part_1(
    k: &[f64; 51],
    q: &[f64; 7],
    qd: &[f64; 7],
    s: &[f64; 96],
    out: &mut [f64; 7],
) {
    let x981 = 2.0 * qd[5];
    let x1056 = qd[5] * x981;
    let x1236 = x1056 + s[70];
    let x1237 = s[69] + x1236;
    let x1244 = -x1237;
    let x1757 = s[0] + k[23];
    let x1758 = k[22] + x1757;
    let x1759 = x1758.cos();
    let x1760 = k[21] * x1759;
    let x1762 = k[20] - x1760;
    let x1763 = x1762.sqrt();
    let x1896 = s[6] * k[44];
    let x1897 = s[18] * k[45];
    let x1898 = x1896 + x1897;
    let x1899 = s[19] * k[44];
    let x1900 = s[24] * k[45];
    let x1901 = x1899 + x1900;
    let x1902 = s[25] * k[44];
    let x1903 = s[9] * k[45];
    let x1904 = x1902 + x1903;
    let x1905 = q[0] + x1898;
    let x1906 = q[1] + x1901;
    let x1907 = q[2] + x1904;
    let x1909 = x1905 + k[46];
    let x1911 = x1907 + k[47];
    let x1912 = x1909 * x1909;
    let x1913 = x1906 * x1906;
    let x1914 = x1911 * x1911;
    let x1915 = x1912 + x1913;
    let x1916 = x1914 + x1915;
    let x1917 = x1916.sqrt();
    let x1950 = 2.0 * x1909;
    let x1951 = 2.0 * x1906;
    let x1952 = 2.0 * x1911;
    let x1953 = 2.0 * x1917;
    let x1954 = 1.0 / x1953;
    let x2286 = x1758.sin();
    let x2287 = 0.8726646259971648 * x2286;
    let x2288 = k[21] * x2287;
    let x2289 = 2.0 * x1763;
    let x2290 = 1.0 / x2289;
    let x2291 = x2288 * x2290;
    let x2388 = s[33] * k[44];
    let x2389 = s[52] * k[45];
    let x2390 = x2388 + x2389;
    let x2391 = s[53] * k[44];
    let x2392 = s[62] * k[45];
    let x2393 = x2391 + x2392;
    let x2394 = s[63] * k[44];
    let x2395 = s[35] * k[45];
    let x2396 = x2394 + x2395;
    let x2397 = qd[0] + x2390;
    let x2398 = qd[1] + x2393;
    let x2399 = qd[2] + x2396;
    let x2400 = x1950 * x2397;
    let x2401 = x1951 * x2398;
    let x2402 = x1952 * x2399;
    let x2403 = x2400 + x2401;
    let x2404 = x2402 + x2403;
    let x2405 = x1954 * x2404;
    let x2436 = 2.0 * x2397;
    let x2437 = 2.0 * x2398;
    let x2438 = 2.0 * x2399;
    let x2439 = 2.0 * x2405;
    let x2440 = x1954 * x1954;
    let x2441 = x2439 * x2440;
    let x2492 = 0.8726646259971648 * x1759;
    let x2493 = 0.8726646259971648 * x2492;
    let x2494 = k[21] * x2493;
    let x2495 = 2.0 * x2291;
    let x2496 = x2290 * x2290;
    let x2497 = x2495 * x2496;
    let x2498 = x2290 * x2494;
    let x2499 = x2288 * x2497;
    let x2501 = x2498 - x2499;
    let x2633 = s[71] * k[44];
    let x2634 = s[86] * k[45];
    let x2635 = x2633 + x2634;
    let x2636 = s[87] * k[44];
    let x2637 = s[94] * k[45];
    let x2638 = x2636 + x2637;
    let x2639 = s[95] * k[44];
    let x2640 = s[73] * k[45];
    let x2641 = x2639 + x2640;
    let x2642 = x2397 * x2436;
    let x2643 = x1950 * x2635;
    let x2644 = x2642 + x2643;
    let x2645 = x2398 * x2437;
    let x2646 = x1951 * x2638;
    let x2647 = x2645 + x2646;
    let x2648 = x2399 * x2438;
    let x2649 = x1952 * x2641;
    let x2650 = x2648 + x2649;
    let x2651 = x2644 + x2647;
    let x2652 = x2650 + x2651;
    let x2653 = x2404 * x2441;
    let x2655 = x1954 * x2652;
    let x2656 = x2655 - x2653;
    let x2657 = x2656 - x2501;
    let x2663 = -x2657;
    out[5] = x2663;
    out[6] = x1244;
}
/// Φ, Φq, Φt and γ at one state in one pass, sharing every subexpression.
pub fn eval_kinematics(
    k: &[f64],
    q: &[f64],
    qd: &[f64],
    t: f64,
    phi: &mut [f64],
    phi_q: &mut [f64],
    phi_t: &mut [f64],
    gamma: &mut [f64],
) {
    let k: &[f64; 51] = k.try_into().expect("k must have 51 entries");
    let q: &[f64; 7] = q.try_into().expect("q must have n_coords entries");
    let qd: &[f64; 7] = qd.try_into().expect("qd must have n_coords entries");
    let phi: &mut [f64; 7] = phi.try_into().expect("phi must have 7 entries");
    let phi_q: &mut [f64; 46] = phi_q.try_into().expect("phi_q must have 46 entries");
    let phi_t: &mut [f64; 7] = phi_t.try_into().expect("phi_t must have 7 entries");
    let gamma: &mut [f64; 7] = gamma.try_into().expect("gamma must have 7 entries");
    let mut s = [0.0f64; 135];
    eval_kinematics_shared_0(k, q, qd, t, &mut s);
    eval_kinematics_part_0(k, q, qd, &s, phi, phi_q, phi_t, gamma);
    eval_kinematics_part_1(k, q, qd, &s, phi, phi_q, phi_t, gamma);
}
#[inline(never)]
fn eval_kinematics_shared_0(
    k: &[f64; 51],
    q: &[f64; 7],
    qd: &[f64; 7],
    t: f64,
    s: &mut [f64; 135],
) {
    let x7 = 0.8726646259971648 * t;
    s[0] = x7;
    let x153 = q[3] * q[3];
    s[1] = x153;
    let x154 = q[4] * q[4];
    s[2] = x154;
    let x156 = q[6] * q[6];
    s[3] = x156;
    let x157 = x153 + x154;
    s[4] = x157;
    let x158 = 2.0 * x157;
    s[5] = x158;
    let x160 = x158 - 1.0;
    s[6] = x160;
    let x164 = x153 + x156;
    s[7] = x164;
    let x165 = 2.0 * x164;
    s[8] = x165;
    let x166 = x165 - 1.0;
    s[9] = x166;
    let x167 = q[4] * q[5];
    s[10] = x167;
    let x168 = 2.0 * x167;
    s[11] = x168;
    let x169 = q[3] * q[6];
    s[12] = x169;
    let x171 = 2.0 * x169;
    s[13] = x171;
    let x174 = q[4] * q[6];
    s[14] = x174;
    let x175 = 2.0 * x174;
    s[15] = x175;
    let x176 = q[3] * q[5];
    s[16] = x176;
    let x177 = 2.0 * x176;
    s[17] = x177;
    let x178 = x175 + x177;
    s[18] = x178;
    let x179 = x168 + x171;
    s[19] = x179;
    let x180 = q[5] * q[6];
    s[20] = x180;
    let x181 = 2.0 * x180;
    s[21] = x181;
    let x182 = q[3] * q[4];
    s[22] = x182;
    let x184 = 2.0 * x182;
    s[23] = x184;
    let x186 = x181 - x184;
    s[24] = x186;
    let x189 = x175 - x177;
    s[25] = x189;
    let x363 = q[3] * 2.0;
    s[26] = x363;
    let x364 = q[4] * 2.0;
    s[27] = x364;
    let x365 = q[6] * 2.0;
    s[28] = x365;
    let x414 = q[5] * 2.0;
    s[29] = x414;
    let x415 = 2.0 * x363;
    s[30] = x415;
    let x520 = 2.0 * x364;
    s[31] = x520;
    let x660 = 2.0 * x365;
    s[32] = x660;
    let x782 = x363 * qd[3];
    s[33] = x782;
    let x783 = x364 * qd[4];
    s[34] = x783;
    let x785 = x365 * qd[6];
    s[35] = x785;
    let x786 = x782 + x783;
    s[36] = x786;
    let x787 = 2.0 * x786;
    s[37] = x787;
    let x788 = x782 + x785;
    s[38] = x788;
    let x789 = 2.0 * x788;
    s[39] = x789;
    let x790 = q[5] * qd[4];
    s[40] = x790;
    let x791 = q[4] * qd[5];
    s[41] = x791;
    let x792 = x790 + x791;
    s[42] = x792;
    let x793 = 2.0 * x792;
    s[43] = x793;
    let x794 = q[6] * qd[3];
    s[44] = x794;
    let x795 = q[3] * qd[6];
    s[45] = x795;
    let x796 = x794 + x795;
    s[46] = x796;
    let x797 = 2.0 * x796;
    s[47] = x797;
    let x798 = q[6] * qd[4];
    s[48] = x798;
    let x799 = q[4] * qd[6];
    s[49] = x799;
    let x800 = x798 + x799;
    s[50] = x800;
    let x801 = 2.0 * x800;
    s[51] = x801;
    let x802 = q[5] * qd[3];
    s[52] = x802;
    let x803 = q[3] * qd[5];
    s[53] = x803;
    let x804 = x802 + x803;
    s[54] = x804;
    let x805 = 2.0 * x804;
    s[55] = x805;
    let x806 = x801 + x805;
    s[56] = x806;
    let x807 = x793 + x797;
    s[57] = x807;
    let x808 = q[6] * qd[5];
    s[58] = x808;
    let x809 = q[5] * qd[6];
    s[59] = x809;
    let x810 = x808 + x809;
    s[60] = x810;
    let x811 = 2.0 * x810;
    s[61] = x811;
    let x812 = q[4] * qd[3];
    s[62] = x812;
    let x813 = q[3] * qd[4];
    s[63] = x813;
    let x814 = x812 + x813;
    s[64] = x814;
    let x815 = 2.0 * x814;
    s[65] = x815;
    let x817 = x811 - x815;
    s[66] = x817;
    let x819 = x801 - x805;
    s[67] = x819;
    let x936 = 2.0 * qd[3];
    s[68] = x936;
    let x937 = 2.0 * qd[4];
    s[69] = x937;
    let x938 = 2.0 * qd[6];
    s[70] = x938;
    let x1054 = qd[3] * x936;
    s[71] = x1054;
    let x1055 = qd[4] * x937;
    s[72] = x1055;
    let x1057 = qd[6] * x938;
    s[73] = x1057;
    let x1058 = x1054 + x1055;
    s[74] = x1058;
    let x1059 = 2.0 * x1058;
    s[75] = x1059;
    let x1060 = x1054 + x1057;
    s[76] = x1060;
    let x1061 = 2.0 * x1060;
    s[77] = x1061;
    let x1062 = qd[4] * qd[5];
    s[78] = x1062;
    let x1063 = x1062 + x1062;
    s[79] = x1063;
    let x1064 = 2.0 * x1063;
    s[80] = x1064;
    let x1065 = qd[3] * qd[6];
    s[81] = x1065;
    let x1066 = x1065 + x1065;
    s[82] = x1066;
    let x1067 = 2.0 * x1066;
    s[83] = x1067;
    let x1068 = qd[4] * qd[6];
    s[84] = x1068;
    let x1069 = x1068 + x1068;
    s[85] = x1069;
    let x1070 = 2.0 * x1069;
    s[86] = x1070;
    let x1071 = qd[3] * qd[5];
    s[87] = x1071;
    let x1072 = x1071 + x1071;
    s[88] = x1072;
    let x1073 = 2.0 * x1072;
    s[89] = x1073;
    let x1074 = x1070 + x1073;
    s[90] = x1074;
    let x1075 = x1064 + x1067;
    s[91] = x1075;
    let x1076 = qd[5] * qd[6];
    s[92] = x1076;
    let x1077 = x1076 + x1076;
    s[93] = x1077;
    let x1078 = 2.0 * x1077;
    s[94] = x1078;
    let x1079 = qd[3] * qd[4];
    s[95] = x1079;
    let x1080 = x1079 + x1079;
    s[96] = x1080;
    let x1081 = 2.0 * x1080;
    s[97] = x1081;
    let x1083 = x1078 - x1081;
    s[98] = x1083;
    let x1085 = x1070 - x1073;
    s[99] = x1085;
    let x1735 = x7 + k[15];
    s[100] = x1735;
    let x1736 = k[14] + x1735;
    s[101] = x1736;
    let x1737 = x1736.cos();
    s[102] = x1737;
    let x1738 = k[13] * x1737;
    s[103] = x1738;
    let x1740 = k[12] - x1738;
    s[104] = x1740;
    let x1741 = x1740.sqrt();
    s[105] = x1741;
    let x1844 = x160 * k[36];
    s[106] = x1844;
    let x1845 = x178 * k[37];
    s[107] = x1845;
    let x1846 = x1844 + x1845;
    s[108] = x1846;
    let x1847 = x179 * k[36];
    s[109] = x1847;
    let x1848 = x186 * k[37];
    s[110] = x1848;
    let x1849 = x1847 + x1848;
    s[111] = x1849;
    let x1850 = x189 * k[36];
    s[112] = x1850;
    let x1851 = x166 * k[37];
    s[113] = x1851;
    let x1852 = x1850 + x1851;
    s[114] = x1852;
    let x1853 = q[0] + x1846;
    s[115] = x1853;
    let x1854 = q[1] + x1849;
    s[116] = x1854;
    let x1855 = q[2] + x1852;
    s[117] = x1855;
    let x1857 = x1853 + k[38];
    s[118] = x1857;
    let x1859 = x1855 + k[39];
    s[119] = x1859;
    let x1860 = x1857 * x1857;
    s[120] = x1860;
    let x1861 = x1854 * x1854;
    s[121] = x1861;
    let x1862 = x1859 * x1859;
    s[122] = x1862;
    let x1863 = x1860 + x1861;
    s[123] = x1863;
    let x1864 = x1862 + x1863;
    s[124] = x1864;
    let x1865 = x1864.sqrt();
    s[125] = x1865;
    let x1938 = 2.0 * x1857;
    s[126] = x1938;
    let x1939 = 2.0 * x1854;
    s[127] = x1939;
    let x1940 = 2.0 * x1859;
    s[128] = x1940;
    let x1941 = 2.0 * x1865;
    s[129] = x1941;
    let x1942 = 1.0 / x1941;
    s[130] = x1942;
    let x2020 = x414 * k[37];
    s[131] = x2020;
    let x2023 = x364 * k[37];
    s[132] = x2023;
    let x2107 = x365 * k[37];
    s[133] = x2107;
    let x2109 = x363 * k[37];
    s[134] = x2109;
}
#[inline(never)]
fn eval_kinematics_part_0(
    k: &[f64; 51],
    q: &[f64; 7],
    qd: &[f64; 7],
    s: &[f64; 135],
    phi: &mut [f64; 7],
    phi_q: &mut [f64; 46],
    phi_t: &mut [f64; 7],
    gamma: &mut [f64; 7],
) {
    let x1702 = s[0] + k[3];
    let x1703 = k[2] + x1702;
    let x1704 = x1703.cos();
    let x1705 = k[1] * x1704;
    let x1707 = k[0] - x1705;
    let x1708 = x1707.sqrt();
    let x1713 = s[0] + k[7];
    let x1714 = k[6] + x1713;
    let x1715 = x1714.cos();
    let x1716 = k[5] * x1715;
    let x1718 = k[4] - x1716;
    let x1719 = x1718.sqrt();
    let x1724 = s[0] + k[11];
    let x1725 = k[10] + x1724;
    let x1726 = x1725.cos();
    let x1727 = k[9] * x1726;
    let x1729 = k[8] - x1727;
    let x1730 = x1729.sqrt();
    let x1766 = s[6] * k[24];
    let x1767 = s[18] * k[25];
    let x1768 = x1766 + x1767;
    let x1769 = s[19] * k[24];
    let x1770 = s[24] * k[25];
    let x1771 = x1769 + x1770;
    let x1772 = s[25] * k[24];
    let x1773 = s[9] * k[25];
    let x1774 = x1772 + x1773;
    let x1775 = q[0] + x1768;
    let x1776 = q[1] + x1771;
    let x1777 = q[2] + x1774;
    let x1779 = x1775 + k[26];
    let x1781 = x1777 + k[27];
    let x1782 = x1779 * x1779;
    let x1783 = x1776 * x1776;
    let x1784 = x1781 * x1781;
    let x1785 = x1782 + x1783;
    let x1786 = x1784 + x1785;
    let x1787 = x1786.sqrt();
    let x1789 = x1787 - x1708;
    let x1792 = s[6] * k[28];
    let x1793 = s[18] * k[29];
    let x1794 = x1792 + x1793;
    let x1795 = s[19] * k[28];
    let x1796 = s[24] * k[29];
    let x1797 = x1795 + x1796;
    let x1798 = s[25] * k[28];
    let x1799 = s[9] * k[29];
    let x1800 = x1798 + x1799;
    let x1801 = q[0] + x1794;
    let x1802 = q[1] + x1797;
    let x1803 = q[2] + x1800;
    let x1805 = x1801 + k[30];
    let x1807 = x1803 + k[31];
    let x1808 = x1805 * x1805;
    let x1809 = x1802 * x1802;
    let x1810 = x1807 * x1807;
    let x1811 = x1808 + x1809;
    let x1812 = x1810 + x1811;
    let x1813 = x1812.sqrt();
    let x1815 = x1813 - x1719;
    let x1818 = s[6] * k[32];
    let x1819 = s[18] * k[33];
    let x1820 = x1818 + x1819;
    let x1821 = s[19] * k[32];
    let x1822 = s[24] * k[33];
    let x1823 = x1821 + x1822;
    let x1824 = s[25] * k[32];
    let x1825 = s[9] * k[33];
    let x1826 = x1824 + x1825;
    let x1827 = q[0] + x1820;
    let x1828 = q[1] + x1823;
    let x1829 = q[2] + x1826;
    let x1831 = x1827 + k[34];
    let x1833 = x1829 + k[35];
    let x1834 = x1831 * x1831;
    let x1835 = x1828 * x1828;
    let x1836 = x1833 * x1833;
    let x1837 = x1834 + x1835;
    let x1838 = x1836 + x1837;
    let x1839 = x1838.sqrt();
    let x1841 = x1839 - x1730;
    let x1867 = s[125] - s[105];
    let x1920 = 2.0 * x1779;
    let x1921 = 2.0 * x1776;
    let x1922 = 2.0 * x1781;
    let x1923 = 2.0 * x1787;
    let x1924 = 1.0 / x1923;
    let x1925 = x1920 * x1924;
    let x1926 = 2.0 * x1805;
    let x1927 = 2.0 * x1802;
    let x1928 = 2.0 * x1807;
    let x1929 = 2.0 * x1813;
    let x1930 = 1.0 / x1929;
    let x1931 = x1926 * x1930;
    let x1932 = 2.0 * x1831;
    let x1933 = 2.0 * x1828;
    let x1934 = 2.0 * x1833;
    let x1935 = 2.0 * x1839;
    let x1936 = 1.0 / x1935;
    let x1937 = x1932 * x1936;
    let x1943 = s[126] * s[130];
    let x1956 = x1921 * x1924;
    let x1957 = x1927 * x1930;
    let x1958 = x1933 * x1936;
    let x1959 = s[127] * s[130];
    let x1962 = x1922 * x1924;
    let x1963 = x1928 * x1930;
    let x1964 = x1934 * x1936;
    let x1965 = s[128] * s[130];
    let x1968 = s[30] * k[24];
    let x1969 = s[29] * k[25];
    let x1970 = x1968 + x1969;
    let x1971 = s[28] * k[24];
    let x1972 = s[27] * k[25];
    let x1974 = x1971 - x1972;
    let x1975 = s[29] * k[24];
    let x1977 = s[30] * k[25];
    let x1978 = x1977 - x1975;
    let x1979 = x1920 * x1970;
    let x1980 = x1921 * x1974;
    let x1981 = x1922 * x1978;
    let x1982 = x1979 + x1980;
    let x1983 = x1981 + x1982;
    let x1984 = x1924 * x1983;
    let x1985 = s[30] * k[28];
    let x1986 = s[29] * k[29];
    let x1987 = x1985 + x1986;
    let x1988 = s[28] * k[28];
    let x1989 = s[27] * k[29];
    let x1991 = x1988 - x1989;
    let x1992 = s[29] * k[28];
    let x1994 = s[30] * k[29];
    let x1995 = x1994 - x1992;
    let x1996 = x1926 * x1987;
    let x1997 = x1927 * x1991;
    let x1998 = x1928 * x1995;
    let x1999 = x1996 + x1997;
    let x2000 = x1998 + x1999;
    let x2001 = x1930 * x2000;
    let x2002 = s[30] * k[32];
    let x2003 = s[29] * k[33];
    let x2004 = x2002 + x2003;
    let x2005 = s[28] * k[32];
    let x2006 = s[27] * k[33];
    let x2008 = x2005 - x2006;
    let x2009 = s[29] * k[32];
    let x2011 = s[30] * k[33];
    let x2012 = x2011 - x2009;
    let x2013 = x1932 * x2004;
    let x2014 = x1933 * x2008;
    let x2015 = x1934 * x2012;
    let x2016 = x2013 + x2014;
    let x2017 = x2015 + x2016;
    let x2018 = x1936 * x2017;
    let x2019 = s[30] * k[36];
    let x2021 = x2019 + s[131];
    let x2022 = s[28] * k[36];
    let x2025 = x2022 - s[132];
    let x2026 = s[29] * k[36];
    let x2028 = s[30] * k[37];
    let x2029 = x2028 - x2026;
    let x2030 = s[126] * x2021;
    let x2031 = s[127] * x2025;
    let x2032 = s[128] * x2029;
    let x2033 = x2030 + x2031;
    let x2034 = x2032 + x2033;
    let x2035 = s[130] * x2034;
    let x2070 = s[31] * k[24];
    let x2071 = s[28] * k[25];
    let x2072 = x2070 + x2071;
    let x2073 = s[26] * k[25];
    let x2075 = x1975 - x2073;
    let x2076 = x1920 * x2072;
    let x2077 = x1921 * x2075;
    let x2078 = x1922 * x1971;
    let x2079 = x2076 + x2077;
    let x2080 = x2078 + x2079;
    let x2081 = x1924 * x2080;
    let x2082 = s[31] * k[28];
    let x2083 = s[28] * k[29];
    let x2084 = x2082 + x2083;
    let x2085 = s[26] * k[29];
    let x2087 = x1992 - x2085;
    let x2088 = x1926 * x2084;
    let x2089 = x1927 * x2087;
    let x2090 = x1928 * x1988;
    let x2091 = x2088 + x2089;
    let x2092 = x2090 + x2091;
    let x2093 = x1930 * x2092;
    let x2094 = s[31] * k[32];
    let x2095 = s[28] * k[33];
    let x2096 = x2094 + x2095;
    let x2097 = s[26] * k[33];
    let x2099 = x2009 - x2097;
    let x2100 = x1932 * x2096;
    let x2101 = x1933 * x2099;
    let x2102 = x1934 * x2005;
    let x2103 = x2100 + x2101;
    let x2104 = x2102 + x2103;
    let x2105 = x1936 * x2104;
    let x2106 = s[31] * k[36];
    let x2108 = x2106 + s[133];
    let x2111 = x2026 - s[134];
    let x2112 = s[126] * x2108;
    let x2113 = s[127] * x2111;
    let x2114 = s[128] * x2022;
    let x2115 = x2112 + x2113;
    let x2116 = x2114 + x2115;
    let x2117 = s[130] * x2116;
    let x2142 = s[27] * k[24];
    let x2143 = x2071 + x2142;
    let x2144 = s[26] * k[24];
    let x2145 = x1920 * x2073;
    let x2146 = x1921 * x2143;
    let x2147 = x1922 * x2144;
    let x2149 = x2145 + x2146;
    let x2150 = x2149 - x2147;
    let x2151 = x1924 * x2150;
    let x2152 = s[27] * k[28];
    let x2153 = x2083 + x2152;
    let x2154 = s[26] * k[28];
    let x2155 = x1926 * x2085;
    let x2156 = x1927 * x2153;
    let x2157 = x1928 * x2154;
    let x2159 = x2155 + x2156;
    let x2160 = x2159 - x2157;
    let x2161 = x1930 * x2160;
    let x2162 = s[27] * k[32];
    let x2163 = x2095 + x2162;
    let x2164 = s[26] * k[32];
    let x2165 = x1932 * x2097;
    let x2166 = x1933 * x2163;
    let x2167 = x1934 * x2164;
    let x2169 = x2165 + x2166;
    let x2170 = x2169 - x2167;
    let x2171 = x1936 * x2170;
    let x2202 = x1969 + x2144;
    let x2203 = s[32] * k[25];
    let x2204 = x2142 + x2203;
    let x2205 = x1920 * x1972;
    let x2206 = x1921 * x2202;
    let x2207 = x1922 * x2204;
    let x2208 = x2205 + x2206;
    let x2209 = x2207 + x2208;
    let x2210 = x1924 * x2209;
    let x2211 = x1986 + x2154;
    let x2212 = s[32] * k[29];
    let x2213 = x2152 + x2212;
    let x2214 = x1926 * x1989;
    let x2215 = x1927 * x2211;
    let x2216 = x1928 * x2213;
    let x2217 = x2214 + x2215;
    let x2218 = x2216 + x2217;
    let x2219 = x1930 * x2218;
    let x2220 = x2003 + x2164;
    let x2221 = s[32] * k[33];
    let x2222 = x2162 + x2221;
    let x2223 = x1932 * x2006;
    let x2224 = x1933 * x2220;
    let x2225 = x1934 * x2222;
    let x2226 = x2223 + x2224;
    let x2227 = x2225 + x2226;
    let x2228 = x1936 * x2227;
    let x2256 = x1703.sin();
    let x2257 = 0.8726646259971648 * x2256;
    let x2258 = k[1] * x2257;
    let x2259 = 2.0 * x1708;
    let x2260 = 1.0 / x2259;
    let x2261 = x2258 * x2260;
    let x2262 = x1714.sin();
    let x2263 = 0.8726646259971648 * x2262;
    let x2264 = k[5] * x2263;
    let x2265 = 2.0 * x1719;
    let x2266 = 1.0 / x2265;
    let x2267 = x2264 * x2266;
    let x2268 = x1725.sin();
    let x2269 = 0.8726646259971648 * x2268;
    let x2270 = k[9] * x2269;
    let x2271 = 2.0 * x1730;
    let x2272 = 1.0 / x2271;
    let x2273 = x2270 * x2272;
    let x2292 = -x2261;
    let x2293 = -x2267;
    let x2294 = -x2273;
    let x2298 = s[37] * k[24];
    let x2299 = s[56] * k[25];
    let x2300 = x2298 + x2299;
    let x2301 = s[57] * k[24];
    let x2302 = s[66] * k[25];
    let x2303 = x2301 + x2302;
    let x2304 = s[67] * k[24];
    let x2305 = s[39] * k[25];
    let x2306 = x2304 + x2305;
    let x2307 = qd[0] + x2300;
    let x2308 = qd[1] + x2303;
    let x2309 = qd[2] + x2306;
    let x2310 = x1920 * x2307;
    let x2311 = x1921 * x2308;
    let x2312 = x1922 * x2309;
    let x2313 = x2310 + x2311;
    let x2314 = x2312 + x2313;
    let x2315 = x1924 * x2314;
    let x2316 = s[37] * k[28];
    let x2317 = s[56] * k[29];
    let x2318 = x2316 + x2317;
    let x2319 = s[57] * k[28];
    let x2320 = s[66] * k[29];
    let x2321 = x2319 + x2320;
    let x2322 = s[67] * k[28];
    let x2323 = s[39] * k[29];
    let x2324 = x2322 + x2323;
    let x2325 = qd[0] + x2318;
    let x2326 = qd[1] + x2321;
    let x2327 = qd[2] + x2324;
    let x2328 = x1926 * x2325;
    let x2329 = x1927 * x2326;
    let x2330 = x1928 * x2327;
    let x2331 = x2328 + x2329;
    let x2332 = x2330 + x2331;
    let x2333 = x1930 * x2332;
    let x2334 = s[37] * k[32];
    let x2335 = s[56] * k[33];
    let x2336 = x2334 + x2335;
    let x2337 = s[57] * k[32];
    let x2338 = s[66] * k[33];
    let x2339 = x2337 + x2338;
    let x2340 = s[67] * k[32];
    let x2341 = s[39] * k[33];
    let x2342 = x2340 + x2341;
    let x2343 = qd[0] + x2336;
    let x2344 = qd[1] + x2339;
    let x2345 = qd[2] + x2342;
    let x2346 = x1932 * x2343;
    let x2347 = x1933 * x2344;
    let x2348 = x1934 * x2345;
    let x2349 = x2346 + x2347;
    let x2350 = x2348 + x2349;
    let x2351 = x1936 * x2350;
    let x2406 = 2.0 * x2307;
    let x2407 = 2.0 * x2308;
    let x2408 = 2.0 * x2309;
    let x2409 = 2.0 * x2315;
    let x2410 = x1924 * x1924;
    let x2411 = x2409 * x2410;
    let x2412 = 2.0 * x2325;
    let x2413 = 2.0 * x2326;
    let x2414 = 2.0 * x2327;
    let x2415 = 2.0 * x2333;
    let x2416 = x1930 * x1930;
    let x2417 = x2415 * x2416;
    let x2418 = 2.0 * x2343;
    let x2419 = 2.0 * x2344;
    let x2420 = 2.0 * x2345;
    let x2421 = 2.0 * x2351;
    let x2422 = x1936 * x1936;
    let x2423 = x2421 * x2422;
    let x2442 = 0.8726646259971648 * x1704;
    let x2443 = 0.8726646259971648 * x2442;
    let x2444 = k[1] * x2443;
    let x2445 = 2.0 * x2261;
    let x2446 = x2260 * x2260;
    let x2447 = x2445 * x2446;
    let x2448 = x2260 * x2444;
    let x2449 = x2258 * x2447;
    let x2451 = x2448 - x2449;
    let x2452 = 0.8726646259971648 * x1715;
    let x2453 = 0.8726646259971648 * x2452;
    let x2454 = k[5] * x2453;
    let x2455 = 2.0 * x2267;
    let x2456 = x2266 * x2266;
    let x2457 = x2455 * x2456;
    let x2458 = x2266 * x2454;
    let x2459 = x2264 * x2457;
    let x2461 = x2458 - x2459;
    let x2462 = 0.8726646259971648 * x1726;
    let x2463 = 0.8726646259971648 * x2462;
    let x2464 = k[9] * x2463;
    let x2465 = 2.0 * x2273;
    let x2466 = x2272 * x2272;
    let x2467 = x2465 * x2466;
    let x2468 = x2272 * x2464;
    let x2469 = x2270 * x2467;
    let x2471 = x2468 - x2469;
    let x2508 = s[75] * k[24];
    let x2509 = s[90] * k[25];
    let x2510 = x2508 + x2509;
    let x2511 = s[91] * k[24];
    let x2512 = s[98] * k[25];
    let x2513 = x2511 + x2512;
    let x2514 = s[99] * k[24];
    let x2515 = s[77] * k[25];
    let x2516 = x2514 + x2515;
    let x2517 = x2307 * x2406;
    let x2518 = x1920 * x2510;
    let x2519 = x2517 + x2518;
    let x2520 = x2308 * x2407;
    let x2521 = x1921 * x2513;
    let x2522 = x2520 + x2521;
    let x2523 = x2309 * x2408;
    let x2524 = x1922 * x2516;
    let x2525 = x2523 + x2524;
    let x2526 = x2519 + x2522;
    let x2527 = x2525 + x2526;
    let x2528 = x2314 * x2411;
    let x2530 = x1924 * x2527;
    let x2531 = x2530 - x2528;
    let x2532 = x2531 - x2451;
    let x2533 = s[75] * k[28];
    let x2534 = s[90] * k[29];
    let x2535 = x2533 + x2534;
    let x2536 = s[91] * k[28];
    let x2537 = s[98] * k[29];
    let x2538 = x2536 + x2537;
    let x2539 = s[99] * k[28];
    let x2540 = s[77] * k[29];
    let x2541 = x2539 + x2540;
    let x2542 = x2325 * x2412;
    let x2543 = x1926 * x2535;
    let x2544 = x2542 + x2543;
    let x2545 = x2326 * x2413;
    let x2546 = x1927 * x2538;
    let x2547 = x2545 + x2546;
    let x2548 = x2327 * x2414;
    let x2549 = x1928 * x2541;
    let x2550 = x2548 + x2549;
    let x2551 = x2544 + x2547;
    let x2552 = x2550 + x2551;
    let x2553 = x2332 * x2417;
    let x2555 = x1930 * x2552;
    let x2556 = x2555 - x2553;
    let x2557 = x2556 - x2461;
    let x2558 = s[75] * k[32];
    let x2559 = s[90] * k[33];
    let x2560 = x2558 + x2559;
    let x2561 = s[91] * k[32];
    let x2562 = s[98] * k[33];
    let x2563 = x2561 + x2562;
    let x2564 = s[99] * k[32];
    let x2565 = s[77] * k[33];
    let x2566 = x2564 + x2565;
    let x2567 = x2343 * x2418;
    let x2568 = x1932 * x2560;
    let x2569 = x2567 + x2568;
    let x2570 = x2344 * x2419;
    let x2571 = x1933 * x2563;
    let x2572 = x2570 + x2571;
    let x2573 = x2345 * x2420;
    let x2574 = x1934 * x2566;
    let x2575 = x2573 + x2574;
    let x2576 = x2569 + x2572;
    let x2577 = x2575 + x2576;
    let x2578 = x2350 * x2423;
    let x2580 = x1936 * x2577;
    let x2581 = x2580 - x2578;
    let x2582 = x2581 - x2471;
    let x2658 = -x2532;
    let x2659 = -x2557;
    let x2660 = -x2582;
    phi[0] = x1789;
    phi_q[0] = x1925;
    phi_q[1] = x1956;
    phi_q[2] = x1962;
    phi_q[3] = x1984;
    phi_q[4] = x2081;
    phi_q[5] = x2151;
    phi_q[6] = x2210;
    phi_t[0] = x2292;
    gamma[0] = x2658;
    phi[1] = x1815;
    phi_q[7] = x1931;
    phi_q[8] = x1957;
    phi_q[9] = x1963;
    phi_q[10] = x2001;
    phi_q[11] = x2093;
    phi_q[12] = x2161;
    phi_q[13] = x2219;
    phi_t[1] = x2293;
    gamma[1] = x2659;
    phi[2] = x1841;
    phi_q[14] = x1937;
    phi_q[15] = x1958;
    phi_q[16] = x1964;
    phi_q[17] = x2018;
    phi_q[18] = x2105;
    phi_q[19] = x2171;
    phi_q[20] = x2228;
    phi_t[2] = x2294;
    gamma[2] = x2660;
    phi[3] = x1867;
    phi_q[21] = x1943;
    phi_q[22] = x1959;
    phi_q[23] = x1965;
    phi_q[24] = x2035;
    phi_q[25] = x2117;
}
#[inline(never)]
fn eval_kinematics_part_1(
    k: &[f64; 51],
    q: &[f64; 7],
    qd: &[f64; 7],
    s: &[f64; 135],
    phi: &mut [f64; 7],
    phi_q: &mut [f64; 46],
    phi_t: &mut [f64; 7],
    gamma: &mut [f64; 7],
) {
    let x155 = q[5] * q[5];
    let x360 = x155 + s[4];
    let x361 = s[3] + x360;
    let x362 = x361 - 1.0;
    let x981 = 2.0 * qd[5];
    let x1056 = qd[5] * x981;
    let x1236 = x1056 + s[74];
    let x1237 = s[73] + x1236;
    let x1244 = -x1237;
    let x1746 = s[0] + k[19];
    let x1747 = k[18] + x1746;
    let x1748 = x1747.cos();
    let x1749 = k[17] * x1748;
    let x1751 = k[16] - x1749;
    let x1752 = x1751.sqrt();
    let x1757 = s[0] + k[23];
    let x1758 = k[22] + x1757;
    let x1759 = x1758.cos();
    let x1760 = k[21] * x1759;
    let x1762 = k[20] - x1760;
    let x1763 = x1762.sqrt();
    let x1870 = s[6] * k[40];
    let x1871 = s[18] * k[41];
    let x1872 = x1870 + x1871;
    let x1873 = s[19] * k[40];
    let x1874 = s[24] * k[41];
    let x1875 = x1873 + x1874;
    let x1876 = s[25] * k[40];
    let x1877 = s[9] * k[41];
    let x1878 = x1876 + x1877;
    let x1879 = q[0] + x1872;
    let x1880 = q[1] + x1875;
    let x1881 = q[2] + x1878;
    let x1883 = x1879 + k[42];
    let x1885 = x1881 + k[43];
    let x1886 = x1883 * x1883;
    let x1887 = x1880 * x1880;
    let x1888 = x1885 * x1885;
    let x1889 = x1886 + x1887;
    let x1890 = x1888 + x1889;
    let x1891 = x1890.sqrt();
    let x1893 = x1891 - x1752;
    let x1896 = s[6] * k[44];
    let x1897 = s[18] * k[45];
    let x1898 = x1896 + x1897;
    let x1899 = s[19] * k[44];
    let x1900 = s[24] * k[45];
    let x1901 = x1899 + x1900;
    let x1902 = s[25] * k[44];
    let x1903 = s[9] * k[45];
    let x1904 = x1902 + x1903;
    let x1905 = q[0] + x1898;
    let x1906 = q[1] + x1901;
    let x1907 = q[2] + x1904;
    let x1909 = x1905 + k[46];
    let x1911 = x1907 + k[47];
    let x1912 = x1909 * x1909;
    let x1913 = x1906 * x1906;
    let x1914 = x1911 * x1911;
    let x1915 = x1912 + x1913;
    let x1916 = x1914 + x1915;
    let x1917 = x1916.sqrt();
    let x1919 = x1917 - x1763;
    let x1944 = 2.0 * x1883;
    let x1945 = 2.0 * x1880;
    let x1946 = 2.0 * x1885;
    let x1947 = 2.0 * x1891;
    let x1948 = 1.0 / x1947;
    let x1949 = x1944 * x1948;
    let x1950 = 2.0 * x1909;
    let x1951 = 2.0 * x1906;
    let x1952 = 2.0 * x1911;
    let x1953 = 2.0 * x1917;
    let x1954 = 1.0 / x1953;
    let x1955 = x1950 * x1954;
    let x1960 = x1945 * x1948;
    let x1961 = x1951 * x1954;
    let x1966 = x1946 * x1948;
    let x1967 = x1952 * x1954;
    let x2036 = s[30] * k[40];
    let x2037 = s[29] * k[41];
    let x2038 = x2036 + x2037;
    let x2039 = s[28] * k[40];
    let x2040 = s[27] * k[41];
    let x2042 = x2039 - x2040;
    let x2043 = s[29] * k[40];
    let x2045 = s[30] * k[41];
    let x2046 = x2045 - x2043;
    let x2047 = x1944 * x2038;
    let x2048 = x1945 * x2042;
    let x2049 = x1946 * x2046;
    let x2050 = x2047 + x2048;
    let x2051 = x2049 + x2050;
    let x2052 = x1948 * x2051;
    let x2053 = s[30] * k[44];
    let x2054 = s[29] * k[45];
    let x2055 = x2053 + x2054;
    let x2056 = s[28] * k[44];
    let x2057 = s[27] * k[45];
    let x2059 = x2056 - x2057;
    let x2060 = s[29] * k[44];
    let x2062 = s[30] * k[45];
    let x2063 = x2062 - x2060;
    let x2064 = x1950 * x2055;
    let x2065 = x1951 * x2059;
    let x2066 = x1952 * x2063;
    let x2067 = x2064 + x2065;
    let x2068 = x2066 + x2067;
    let x2069 = x1954 * x2068;
    let x2118 = s[31] * k[40];
    let x2119 = s[28] * k[41];
    let x2120 = x2118 + x2119;
    let x2121 = s[26] * k[41];
    let x2123 = x2043 - x2121;
    let x2124 = x1944 * x2120;
    let x2125 = x1945 * x2123;
    let x2126 = x1946 * x2039;
    let x2127 = x2124 + x2125;
    let x2128 = x2126 + x2127;
    let x2129 = x1948 * x2128;
    let x2130 = s[31] * k[44];
    let x2131 = s[28] * k[45];
    let x2132 = x2130 + x2131;
    let x2133 = s[26] * k[45];
    let x2135 = x2060 - x2133;
    let x2136 = x1950 * x2132;
    let x2137 = x1951 * x2135;
    let x2138 = x1952 * x2056;
    let x2139 = x2136 + x2137;
    let x2140 = x2138 + x2139;
    let x2141 = x1954 * x2140;
    let x2172 = s[27] * k[36];
    let x2173 = s[133] + x2172;
    let x2174 = s[26] * k[36];
    let x2175 = s[126] * s[134];
    let x2176 = s[127] * x2173;
    let x2177 = s[128] * x2174;
    let x2179 = x2175 + x2176;
    let x2180 = x2179 - x2177;
    let x2181 = s[130] * x2180;
    let x2182 = s[27] * k[40];
    let x2183 = x2119 + x2182;
    let x2184 = s[26] * k[40];
    let x2185 = x1944 * x2121;
    let x2186 = x1945 * x2183;
    let x2187 = x1946 * x2184;
    let x2189 = x2185 + x2186;
    let x2190 = x2189 - x2187;
    let x2191 = x1948 * x2190;
    let x2192 = s[27] * k[44];
    let x2193 = x2131 + x2192;
    let x2194 = s[26] * k[44];
    let x2195 = x1950 * x2133;
    let x2196 = x1951 * x2193;
    let x2197 = x1952 * x2194;
    let x2199 = x2195 + x2196;
    let x2200 = x2199 - x2197;
    let x2201 = x1954 * x2200;
    let x2229 = s[131] + x2174;
    let x2230 = s[32] * k[37];
    let x2231 = x2172 + x2230;
    let x2232 = s[126] * s[132];
    let x2233 = s[127] * x2229;
    let x2234 = s[128] * x2231;
    let x2235 = x2232 + x2233;
    let x2236 = x2234 + x2235;
    let x2237 = s[130] * x2236;
    let x2238 = x2037 + x2184;
    let x2239 = s[32] * k[41];
    let x2240 = x2182 + x2239;
    let x2241 = x1944 * x2040;
    let x2242 = x1945 * x2238;
    let x2243 = x1946 * x2240;
    let x2244 = x2241 + x2242;
    let x2245 = x2243 + x2244;
    let x2246 = x1948 * x2245;
    let x2247 = x2054 + x2194;
    let x2248 = s[32] * k[45];
    let x2249 = x2192 + x2248;
    let x2250 = x1950 * x2057;
    let x2251 = x1951 * x2247;
    let x2252 = x1952 * x2249;
    let x2253 = x2250 + x2251;
    let x2254 = x2252 + x2253;
    let x2255 = x1954 * x2254;
    let x2274 = s[101].sin();
    let x2275 = 0.8726646259971648 * x2274;
    let x2276 = k[13] * x2275;
    let x2277 = 2.0 * s[105];
    let x2278 = 1.0 / x2277;
    let x2279 = x2276 * x2278;
    let x2280 = x1747.sin();
    let x2281 = 0.8726646259971648 * x2280;
    let x2282 = k[17] * x2281;
    let x2283 = 2.0 * x1752;
    let x2284 = 1.0 / x2283;
    let x2285 = x2282 * x2284;
    let x2286 = x1758.sin();
    let x2287 = 0.8726646259971648 * x2286;
    let x2288 = k[21] * x2287;
    let x2289 = 2.0 * x1763;
    let x2290 = 1.0 / x2289;
    let x2291 = x2288 * x2290;
    let x2295 = -x2279;
    let x2296 = -x2285;
    let x2297 = -x2291;
    let x2352 = s[37] * k[36];
    let x2353 = s[56] * k[37];
    let x2354 = x2352 + x2353;
    let x2355 = s[57] * k[36];
    let x2356 = s[66] * k[37];
    let x2357 = x2355 + x2356;
    let x2358 = s[67] * k[36];
    let x2359 = s[39] * k[37];
    let x2360 = x2358 + x2359;
    let x2361 = qd[0] + x2354;
    let x2362 = qd[1] + x2357;
    let x2363 = qd[2] + x2360;
    let x2364 = s[126] * x2361;
    let x2365 = s[127] * x2362;
    let x2366 = s[128] * x2363;
    let x2367 = x2364 + x2365;
    let x2368 = x2366 + x2367;
    let x2369 = s[130] * x2368;
    let x2370 = s[37] * k[40];
    let x2371 = s[56] * k[41];
    let x2372 = x2370 + x2371;
    let x2373 = s[57] * k[40];
    let x2374 = s[66] * k[41];
    let x2375 = x2373 + x2374;
    let x2376 = s[67] * k[40];
    let x2377 = s[39] * k[41];
    let x2378 = x2376 + x2377;
    let x2379 = qd[0] + x2372;
    let x2380 = qd[1] + x2375;
    let x2381 = qd[2] + x2378;
    let x2382 = x1944 * x2379;
    let x2383 = x1945 * x2380;
    let x2384 = x1946 * x2381;
    let x2385 = x2382 + x2383;
    let x2386 = x2384 + x2385;
    let x2387 = x1948 * x2386;
    let x2388 = s[37] * k[44];
    let x2389 = s[56] * k[45];
    let x2390 = x2388 + x2389;
    let x2391 = s[57] * k[44];
    let x2392 = s[66] * k[45];
    let x2393 = x2391 + x2392;
    let x2394 = s[67] * k[44];
    let x2395 = s[39] * k[45];
    let x2396 = x2394 + x2395;
    let x2397 = qd[0] + x2390;
    let x2398 = qd[1] + x2393;
    let x2399 = qd[2] + x2396;
    let x2400 = x1950 * x2397;
    let x2401 = x1951 * x2398;
    let x2402 = x1952 * x2399;
    let x2403 = x2400 + x2401;
    let x2404 = x2402 + x2403;
    let x2405 = x1954 * x2404;
    let x2424 = 2.0 * x2361;
    let x2425 = 2.0 * x2362;
    let x2426 = 2.0 * x2363;
    let x2427 = 2.0 * x2369;
    let x2428 = s[130] * s[130];
    let x2429 = x2427 * x2428;
    let x2430 = 2.0 * x2379;
    let x2431 = 2.0 * x2380;
    let x2432 = 2.0 * x2381;
    let x2433 = 2.0 * x2387;
    let x2434 = x1948 * x1948;
    let x2435 = x2433 * x2434;
    let x2436 = 2.0 * x2397;
    let x2437 = 2.0 * x2398;
    let x2438 = 2.0 * x2399;
    let x2439 = 2.0 * x2405;
    let x2440 = x1954 * x1954;
    let x2441 = x2439 * x2440;
    let x2472 = 0.8726646259971648 * s[102];
    let x2473 = 0.8726646259971648 * x2472;
    let x2474 = k[13] * x2473;
    let x2475 = 2.0 * x2279;
    let x2476 = x2278 * x2278;
    let x2477 = x2475 * x2476;
    let x2478 = x2278 * x2474;
    let x2479 = x2276 * x2477;
    let x2481 = x2478 - x2479;
    let x2482 = 0.8726646259971648 * x1748;
    let x2483 = 0.8726646259971648 * x2482;
    let x2484 = k[17] * x2483;
    let x2485 = 2.0 * x2285;
    let x2486 = x2284 * x2284;
    let x2487 = x2485 * x2486;
    let x2488 = x2284 * x2484;
    let x2489 = x2282 * x2487;
    let x2491 = x2488 - x2489;
    let x2492 = 0.8726646259971648 * x1759;
    let x2493 = 0.8726646259971648 * x2492;
    let x2494 = k[21] * x2493;
    let x2495 = 2.0 * x2291;
    let x2496 = x2290 * x2290;
    let x2497 = x2495 * x2496;
    let x2498 = x2290 * x2494;
    let x2499 = x2288 * x2497;
    let x2501 = x2498 - x2499;
    let x2583 = s[75] * k[36];
    let x2584 = s[90] * k[37];
    let x2585 = x2583 + x2584;
    let x2586 = s[91] * k[36];
    let x2587 = s[98] * k[37];
    let x2588 = x2586 + x2587;
    let x2589 = s[99] * k[36];
    let x2590 = s[77] * k[37];
    let x2591 = x2589 + x2590;
    let x2592 = x2361 * x2424;
    let x2593 = s[126] * x2585;
    let x2594 = x2592 + x2593;
    let x2595 = x2362 * x2425;
    let x2596 = s[127] * x2588;
    let x2597 = x2595 + x2596;
    let x2598 = x2363 * x2426;
    let x2599 = s[128] * x2591;
    let x2600 = x2598 + x2599;
    let x2601 = x2594 + x2597;
    let x2602 = x2600 + x2601;
    let x2603 = x2368 * x2429;
    let x2605 = s[130] * x2602;
    let x2606 = x2605 - x2603;
    let x2607 = x2606 - x2481;
    let x2608 = s[75] * k[40];
    let x2609 = s[90] * k[41];
    let x2610 = x2608 + x2609;
    let x2611 = s[91] * k[40];
    let x2612 = s[98] * k[41];
    let x2613 = x2611 + x2612;
    let x2614 = s[99] * k[40];
    let x2615 = s[77] * k[41];
    let x2616 = x2614 + x2615;
    let x2617 = x2379 * x2430;
    let x2618 = x1944 * x2610;
    let x2619 = x2617 + x2618;
    let x2620 = x2380 * x2431;
    let x2621 = x1945 * x2613;
    let x2622 = x2620 + x2621;
    let x2623 = x2381 * x2432;
    let x2624 = x1946 * x2616;
    let x2625 = x2623 + x2624;
    let x2626 = x2619 + x2622;
    let x2627 = x2625 + x2626;
    let x2628 = x2386 * x2435;
    let x2630 = x1948 * x2627;
    let x2631 = x2630 - x2628;
    let x2632 = x2631 - x2491;
    let x2633 = s[75] * k[44];
    let x2634 = s[90] * k[45];
    let x2635 = x2633 + x2634;
    let x2636 = s[91] * k[44];
    let x2637 = s[98] * k[45];
    let x2638 = x2636 + x2637;
    let x2639 = s[99] * k[44];
    let x2640 = s[77] * k[45];
    let x2641 = x2639 + x2640;
    let x2642 = x2397 * x2436;
    let x2643 = x1950 * x2635;
    let x2644 = x2642 + x2643;
    let x2645 = x2398 * x2437;
    let x2646 = x1951 * x2638;
    let x2647 = x2645 + x2646;
    let x2648 = x2399 * x2438;
    let x2649 = x1952 * x2641;
    let x2650 = x2648 + x2649;
    let x2651 = x2644 + x2647;
    let x2652 = x2650 + x2651;
    let x2653 = x2404 * x2441;
    let x2655 = x1954 * x2652;
    let x2656 = x2655 - x2653;
    let x2657 = x2656 - x2501;
    let x2661 = -x2607;
    let x2662 = -x2632;
    let x2663 = -x2657;
    phi_q[26] = x2181;
    phi_q[27] = x2237;
    phi_t[3] = x2295;
    gamma[3] = x2661;
    phi[4] = x1893;
    phi_q[28] = x1949;
    phi_q[29] = x1960;
    phi_q[30] = x1966;
    phi_q[31] = x2052;
    phi_q[32] = x2129;
    phi_q[33] = x2191;
    phi_q[34] = x2246;
    phi_t[4] = x2296;
    gamma[4] = x2662;
    phi[5] = x1919;
    phi_q[35] = x1955;
    phi_q[36] = x1961;
    phi_q[37] = x1967;
    phi_q[38] = x2069;
    phi_q[39] = x2141;
    phi_q[40] = x2201;
    phi_q[41] = x2255;
    phi_t[5] = x2297;
    gamma[5] = x2663;
    phi[6] = x362;
    phi_q[42] = s[26];
    phi_q[43] = s[27];
    phi_q[44] = s[29];
    phi_q[45] = s[28];
    phi_t[6] = 0.0;
    gamma[6] = x1244;
}
/// Potential energy of gravity and springs, written to `out[0]`.
pub fn potential_into(k: &[f64], q: &[f64], out: &mut [f64]) {
    let k: &[f64; 51] = k.try_into().expect("k must have 51 entries");
    let q: &[f64; 7] = q.try_into().expect("q must have n_coords entries");
    let out: &mut [f64; 1] = out.try_into().expect("out must have 1 entries");
    let _ = k;
    potential_into_part_0(q, out);
}
#[inline(never)]
fn potential_into_part_0(q: &[f64; 7], out: &mut [f64; 1]) {
    let x1274 = q[1] * 14.715;
    out[0] = x1274;
}
/// Power of the non-conservative loads, written to `out[0]`.
pub fn power_nc_into(k: &[f64], q: &[f64], qd: &[f64], t: f64, out: &mut [f64]) {
    let k: &[f64; 51] = k.try_into().expect("k must have 51 entries");
    let q: &[f64; 7] = q.try_into().expect("q must have n_coords entries");
    let qd: &[f64; 7] = qd.try_into().expect("qd must have n_coords entries");
    let out: &mut [f64; 1] = out.try_into().expect("out must have 1 entries");
    let _ = k;
    let _ = q;
    let _ = qd;
    let _ = t;
    power_nc_into_part_0(out);
}
#[inline(never)]
fn power_nc_into_part_0(out: &mut [f64; 1]) {
    out[0] = 0.0;
}
/// Number of generalized coordinates.
pub const N_COORDS: usize = 7usize;
/// Number of constraint rows.
pub const N_CONSTRAINTS: usize = 7usize;
/// Row of each Φq nonzero.
pub static PHI_Q_ROWS: [u32; 46usize] = [
    0u32, 0u32, 0u32, 0u32, 0u32, 0u32, 0u32, 1u32, 1u32, 1u32, 1u32, 1u32, 1u32, 1u32,
    2u32, 2u32, 2u32, 2u32, 2u32, 2u32, 2u32, 3u32, 3u32, 3u32, 3u32, 3u32, 3u32, 3u32,
    4u32, 4u32, 4u32, 4u32, 4u32, 4u32, 4u32, 5u32, 5u32, 5u32, 5u32, 5u32, 5u32, 5u32,
    6u32, 6u32, 6u32, 6u32,
];
/// Column of each Φq nonzero.
pub static PHI_Q_COLS: [u32; 46usize] = [
    0u32, 1u32, 2u32, 3u32, 4u32, 5u32, 6u32, 0u32, 1u32, 2u32, 3u32, 4u32, 5u32, 6u32,
    0u32, 1u32, 2u32, 3u32, 4u32, 5u32, 6u32, 0u32, 1u32, 2u32, 3u32, 4u32, 5u32, 6u32,
    0u32, 1u32, 2u32, 3u32, 4u32, 5u32, 6u32, 0u32, 1u32, 2u32, 3u32, 4u32, 5u32, 6u32,
    3u32, 4u32, 5u32, 6u32,
];
/// Bodies in coordinate order.
pub static BODIES: [BodyInfo; 1usize] = [
    BodyInfo {
        name: "platform",
        coord_offset: 0usize,
        rotation: Rotation::Quaternion,
        mass: 1.5f64,
        inertia: [0.004134375f64, 0.00826875f64, 0.004134375f64],
    },
];
/// Joints in row order, then drivers.
pub static JOINTS: [JointInfo; 7usize] = [
    JointInfo {
        name: "leg1",
        kind: JointKind::Driver,
        body1: None,
        body2: Some(0usize),
        row_start: 0usize,
        rows: 1usize,
        point1: [0.2654788250422678f64, 0f64, -0.04920359188287982f64],
        point2: [0.06819204507466928f64, 0f64, -0.07984262638800324f64],
        effort_sign: 1f64,
        effort_unit: "N",
    },
    JointInfo {
        name: "leg2",
        kind: JointKind::Driver,
        body1: None,
        body2: Some(0usize),
        row_start: 1usize,
        rows: 1usize,
        point1: [-0.09012785199311818f64, 0f64, -0.2545132025948882f64],
        point2: [0.03504972021954594f64, 0f64, -0.09897735656467874f64],
        effort_sign: 1f64,
        effort_unit: "N",
    },
    JointInfo {
        name: "leg3",
        kind: JointKind::Driver,
        body1: None,
        body2: Some(0usize),
        row_start: 2usize,
        rows: 1usize,
        point1: [-0.17535097304914957f64, 0f64, -0.2053096107120084f64],
        point2: [-0.10324176529421522f64, 0f64, -0.01913473017667551f64],
        effort_sign: 1f64,
        effort_unit: "N",
    },
    JointInfo {
        name: "leg4",
        kind: JointKind::Driver,
        body1: None,
        body2: Some(0usize),
        row_start: 3usize,
        rows: 1usize,
        point1: [-0.17535097304914954f64, 0f64, 0.20530961071200843f64],
        point2: [-0.10324176529421523f64, 0f64, 0.019134730176675482f64],
        effort_sign: 1f64,
        effort_unit: "N",
    },
    JointInfo {
        name: "leg5",
        kind: JointKind::Driver,
        body1: None,
        body2: Some(0usize),
        row_start: 4usize,
        rows: 1usize,
        point1: [-0.09012785199311824f64, 0f64, 0.2545132025948882f64],
        point2: [0.03504972021954594f64, 0f64, 0.09897735656467874f64],
        effort_sign: 1f64,
        effort_unit: "N",
    },
    JointInfo {
        name: "leg6",
        kind: JointKind::Driver,
        body1: None,
        body2: Some(0usize),
        row_start: 5usize,
        rows: 1usize,
        point1: [0.2654788250422677f64, 0f64, 0.04920359188287992f64],
        point2: [0.0681920450746693f64, 0f64, 0.07984262638800323f64],
        effort_sign: 1f64,
        effort_unit: "N",
    },
    JointInfo {
        name: "platform.norm",
        kind: JointKind::Normalization,
        body1: Some(0usize),
        body2: None,
        row_start: 6usize,
        rows: 1usize,
        point1: [0f64, 0f64, 0f64],
        point2: [0f64, 0f64, 0f64],
        effort_sign: 0f64,
        effort_unit: "",
    },
];
/// Name of each coordinate.
pub static COORD_NAMES: [&str; 7usize] = [
    "platform.x",
    "platform.y",
    "platform.z",
    "platform.e0",
    "platform.e1",
    "platform.e2",
    "platform.e3",
];
/// Name of each constraint row.
pub static ROW_NAMES: [&str; 7usize] = [
    "leg1",
    "leg2",
    "leg3",
    "leg4",
    "leg5",
    "leg6",
    "platform.norm",
];
/// Initial coordinates: the file's pose, assembled.
pub static Q0: [f64; 7usize] = [0f64, 0.3466575f64, 0f64, 1f64, 0f64, 0f64, 0f64];
/// Initial velocities from the file (to be projected onto the constraints).
pub static QD0: [f64; 7usize] = [0f64, 0f64, 0f64, 0f64, 0f64, 0f64, 0f64];
/// Constraint rows dependent on others at the initial pose (dropped by the solvers).
pub static REDUNDANT_ROWS: [u32; 0usize] = [];
/// Simulation end time suggested by the mechanism file (s).
pub const T_END: f64 = 2.5f64;
/// The platform held by six legs of driven length, for forward kinematics (`None`:
/// not such a mechanism).
pub const PLATFORM: Option<PlatformInfo> = Some(PlatformInfo {
    body: 0usize,
    legs: &[
        LegInfo {
            driver: "leg1",
            base: [0.2654788250422678f64, 0f64, -0.04920359188287982f64],
            platform: [0.06819204507466928f64, 0f64, -0.07984262638800324f64],
            row: 0usize,
        },
        LegInfo {
            driver: "leg2",
            base: [-0.09012785199311818f64, 0f64, -0.2545132025948882f64],
            platform: [0.03504972021954594f64, 0f64, -0.09897735656467874f64],
            row: 1usize,
        },
        LegInfo {
            driver: "leg3",
            base: [-0.17535097304914957f64, 0f64, -0.2053096107120084f64],
            platform: [-0.10324176529421522f64, 0f64, -0.01913473017667551f64],
            row: 2usize,
        },
        LegInfo {
            driver: "leg4",
            base: [-0.17535097304914954f64, 0f64, 0.20530961071200843f64],
            platform: [-0.10324176529421523f64, 0f64, 0.019134730176675482f64],
            row: 3usize,
        },
        LegInfo {
            driver: "leg5",
            base: [-0.09012785199311824f64, 0f64, 0.2545132025948882f64],
            platform: [0.03504972021954594f64, 0f64, 0.09897735656467874f64],
            row: 4usize,
        },
        LegInfo {
            driver: "leg6",
            base: [0.2654788250422677f64, 0f64, 0.04920359188287992f64],
            platform: [0.0681920450746693f64, 0f64, 0.07984262638800323f64],
            row: 5usize,
        },
    ],
});
/// Potential energy of gravity and springs.
pub fn potential(k: &[f64], q: &[f64]) -> f64 {
    let mut out = [0.0];
    potential_into(k, q, &mut out);
    out[0]
}
/// Power of the non-conservative loads.
pub fn power_nc(k: &[f64], q: &[f64], qd: &[f64], t: f64) -> f64 {
    let mut out = [0.0];
    power_nc_into(k, q, qd, t, &mut out);
    out[0]
}
/// Number of values `setup` computes from the run-time parameters.
pub const N_K: usize = 51;
/// `setup` at the file's parameter values: what the types without parameters read.
pub static K: [f64; 51] = [
    0.20409642230625002f64,
    0.0567f64,
    -0.1832595714594046f64,
    0.8639379797371931f64,
    0.20409642230625002f64,
    0.0567f64,
    -1.911135530933791f64,
    1.2304571226560024f64,
    0.20409642230625002f64,
    0.0567f64,
    -2.2776546738526f64,
    2.9583330821303884f64,
    0.20409642230625002f64,
    0.0567f64,
    -4.005530633326987f64,
    3.324852225049198f64,
    0.20409642230625002f64,
    0.0567f64,
    -4.372049776245795f64,
    5.052728184523584f64,
    0.20409642230625002f64,
    0.0567f64,
    -6.0999257357201815f64,
    5.419247327442394f64,
    0.06819204507466928f64,
    -0.07984262638800324f64,
    -0.2654788250422678f64,
    0.04920359188287982f64,
    0.03504972021954594f64,
    -0.09897735656467874f64,
    0.09012785199311818f64,
    0.2545132025948882f64,
    -0.10324176529421522f64,
    -0.01913473017667551f64,
    0.17535097304914957f64,
    0.2053096107120084f64,
    -0.10324176529421523f64,
    0.019134730176675482f64,
    0.17535097304914954f64,
    -0.20530961071200843f64,
    0.03504972021954594f64,
    0.09897735656467874f64,
    0.09012785199311824f64,
    -0.2545132025948882f64,
    0.0681920450746693f64,
    0.07984262638800323f64,
    -0.2654788250422677f64,
    -0.04920359188287992f64,
    0.004134375f64,
    0.00826875f64,
    0.02205f64,
];
/// The values the per-step functions read (`k`), from the run-time parameters `p`.
pub fn setup(p: &[f64], k: &mut [f64]) {
    let p: &[f64; 66] = p.try_into().expect("p must have 66 entries");
    let k: &mut [f64; 51] = k.try_into().expect("k must have 51 entries");
    setup_part_0(p, k);
}
#[inline(never)]
fn setup_part_0(p: &[f64; 66], k: &mut [f64; 51]) {
    let x208 = -p[18];
    let x210 = -p[19];
    let x236 = -p[22];
    let x238 = -p[23];
    let x264 = -p[26];
    let x266 = -p[27];
    let x292 = -p[30];
    let x294 = -p[31];
    let x320 = -p[34];
    let x322 = -p[35];
    let x348 = -p[38];
    let x350 = -p[39];
    let x1264 = p[14] * 1.5;
    let x1265 = p[14] * x1264;
    let x1268 = x1265 * 0.25;
    let x1270 = x1265 * 0.5;
    let x1379 = x1268 + x1270;
    let x1380 = x1268 + x1379;
    let x1382 = 4.0 * x1380;
    let x1384 = x1382 * 0.3333333333333333;
    k[0] = p[42];
    k[1] = p[43];
    k[2] = p[44];
    k[3] = p[45];
    k[4] = p[46];
    k[5] = p[47];
    k[6] = p[48];
    k[7] = p[49];
    k[8] = p[50];
    k[9] = p[51];
    k[10] = p[52];
    k[11] = p[53];
    k[12] = p[54];
    k[13] = p[55];
    k[14] = p[56];
    k[15] = p[57];
    k[16] = p[58];
    k[17] = p[59];
    k[18] = p[60];
    k[19] = p[61];
    k[20] = p[62];
    k[21] = p[63];
    k[22] = p[64];
    k[23] = p[65];
    k[24] = p[20];
    k[25] = p[21];
    k[26] = x208;
    k[27] = x210;
    k[28] = p[24];
    k[29] = p[25];
    k[30] = x236;
    k[31] = x238;
    k[32] = p[28];
    k[33] = p[29];
    k[34] = x264;
    k[35] = x266;
    k[36] = p[32];
    k[37] = p[33];
    k[38] = x292;
    k[39] = x294;
    k[40] = p[36];
    k[41] = p[37];
    k[42] = x320;
    k[43] = x322;
    k[44] = p[40];
    k[45] = p[41];
    k[46] = x348;
    k[47] = x350;
    k[48] = x1268;
    k[49] = x1270;
    k[50] = x1384;
}
/// The parameters the generated code takes at run time by name: the file's
/// `[parameters]` entries that reach only masses, inertias and springs' constants.
pub static PARAMETERS: [&str; 0] = [];
/// Their values in the file.
pub static PARAMETER_VALUES: [f64; 0] = [];
/// Number of values `p` holds: the parameters by name, then the model's numbers that
/// the other parameters reach (read off the file loaded at their values: `DATA`).
pub const N_P: usize = 66;
/// `p` at the file's values.
pub static P0: [f64; 66] = [
    49.5f64,
    70.5f64,
    169.5f64,
    190.5f64,
    289.5f64,
    310.5f64,
    0.3466575f64,
    10.5f64,
    109.5f64,
    130.5f64,
    229.5f64,
    250.5f64,
    349.5f64,
    0.27f64,
    0.105f64,
    0.004134375f64,
    0.00826875f64,
    0.004134375f64,
    0.2654788250422678f64,
    -0.04920359188287982f64,
    0.06819204507466928f64,
    -0.07984262638800324f64,
    -0.09012785199311818f64,
    -0.2545132025948882f64,
    0.03504972021954594f64,
    -0.09897735656467874f64,
    -0.17535097304914957f64,
    -0.2053096107120084f64,
    -0.10324176529421522f64,
    -0.01913473017667551f64,
    -0.17535097304914954f64,
    0.20530961071200843f64,
    -0.10324176529421523f64,
    0.019134730176675482f64,
    -0.09012785199311824f64,
    0.2545132025948882f64,
    0.03504972021954594f64,
    0.09897735656467874f64,
    0.2654788250422677f64,
    0.04920359188287992f64,
    0.0681920450746693f64,
    0.07984262638800323f64,
    0.20409642230625002f64,
    0.0567f64,
    -0.1832595714594046f64,
    0.8639379797371931f64,
    0.20409642230625002f64,
    0.0567f64,
    -1.911135530933791f64,
    1.2304571226560024f64,
    0.20409642230625002f64,
    0.0567f64,
    -2.2776546738526f64,
    2.9583330821303884f64,
    0.20409642230625002f64,
    0.0567f64,
    -4.005530633326987f64,
    3.324852225049198f64,
    0.20409642230625002f64,
    0.0567f64,
    -4.372049776245795f64,
    5.052728184523584f64,
    0.20409642230625002f64,
    0.0567f64,
    -6.0999257357201815f64,
    5.419247327442394f64,
];
/// Where the numbers after the named parameters come from in the model (positions in
/// the generator's `slots::numbers`).
pub static DATA: [u32; 66] = [
    3u32, 4u32, 5u32, 6u32, 7u32, 8u32, 9u32, 10u32, 11u32, 12u32, 13u32, 14u32, 15u32,
    16u32, 17u32, 19u32, 20u32, 21u32, 22u32, 24u32, 31u32, 33u32, 40u32, 42u32, 49u32,
    51u32, 58u32, 60u32, 67u32, 69u32, 76u32, 78u32, 85u32, 87u32, 94u32, 96u32, 103u32,
    105u32, 112u32, 114u32, 121u32, 123u32, 130u32, 131u32, 132u32, 133u32, 135u32,
    136u32, 137u32, 138u32, 140u32, 141u32, 142u32, 143u32, 145u32, 146u32, 147u32,
    148u32, 150u32, 151u32, 152u32, 153u32, 155u32, 156u32, 157u32, 158u32,
];
static OTHER_PARAMETERS: [&str; 18] = [
    "alpha1",
    "alpha2",
    "alpha3",
    "alpha4",
    "alpha5",
    "alpha6",
    "c",
    "h",
    "k",
    "phi1",
    "phi2",
    "phi3",
    "phi4",
    "phi5",
    "phi6",
    "r_base",
    "r_platform",
    "rate",
];
static BODY_NAMES: [&str; 1] = ["platform"];
static FORCE_NAMES: [&str; 0] = [];
/// What a new parameter set is checked with.
pub static RUN_TIME: RunTimeParameters = RunTimeParameters {
    names: &PARAMETERS,
    others: &OTHER_PARAMETERS,
    bodies: &BODY_NAMES,
    mass_properties,
    forces: &FORCE_NAMES,
    force_constants,
};
/// Each body's mass and principal inertias at the run-time parameters `p`.
pub fn mass_properties(p: &[f64], out: &mut [f64]) {
    let p: &[f64; 66] = p.try_into().expect("p must have 66 entries");
    let out: &mut [f64; 4] = out.try_into().expect("out must have 4 entries");
    mass_properties_part_0(p, out);
}
#[inline(never)]
fn mass_properties_part_0(p: &[f64; 66], out: &mut [f64; 4]) {
    let x1264 = p[14] * 1.5;
    let x1265 = p[14] * x1264;
    let x1268 = x1265 * 0.25;
    let x1270 = x1265 * 0.5;
    out[0] = 1.5;
    out[1] = x1268;
    out[2] = x1270;
    out[3] = x1268;
}
/// Each force's stiffness and damping at the run-time parameters `p`.
pub fn force_constants(p: &[f64], out: &mut [f64]) {
    let p: &[f64; 66] = p.try_into().expect("p must have 66 entries");
    let _: &mut [f64; 0] = out.try_into().expect("out must have 0 entries");
    let _ = p;
}
/// One set of run-time parameter values and the values `setup` computed from it.
#[derive(Debug, Clone)]
pub struct Parameters {
    p: [f64; N_P],
    k: [f64; N_K],
}
impl Parameters {
    /// The file's values.
    pub fn file_values() -> Self {
        Parameters { p: P0, k: K }
    }
    /// All of `p` at once (`N_P` values: the named parameters, then the model's
    /// numbers `DATA` names, as the mechanism file loaded at other values gives them),
    /// checked as [`Parameters::set`] checks.
    pub fn from_values(values: &[f64]) -> Result<Self, ParameterError> {
        let mut p = [0.0; N_P];
        RUN_TIME.assign_all(&mut p, values)?;
        let (mut props, mut constants) = ([0.0; 4], [0.0; 0]);
        RUN_TIME.check(&p, &[], &mut props, &mut constants)?;
        let mut k = [0.0; N_K];
        setup(&p, &mut k);
        Ok(Parameters { p, k })
    }
    /// The file's values with `set` applied ([`Parameters::set`]).
    pub fn at(set: &[(&str, f64)]) -> Result<Self, ParameterError> {
        let mut p = Self::file_values();
        p.set(set)?;
        Ok(p)
    }
    /// Sets parameters by name. Checked first (known names, finite values, positive
    /// masses, inertias of a rigid body): a refused set changes nothing. Allocates
    /// nothing unless it is refused.
    pub fn set(&mut self, set: &[(&str, f64)]) -> Result<(), ParameterError> {
        let mut p = self.p;
        RUN_TIME.assign(&mut p, set)?;
        let (mut props, mut constants) = ([0.0; 4], [0.0; 0]);
        RUN_TIME.check(&p, set, &mut props, &mut constants)?;
        self.p = p;
        setup(&self.p, &mut self.k);
        Ok(())
    }
    /// The values: those of `PARAMETERS`, then the numbers `DATA` names.
    pub fn values(&self) -> &[f64] {
        &self.p
    }
}
fn built(p: Parameters) -> symbody_runtime::registry::Built {
    vec![
        (Formulation::Exact, Box::new(ExactAt(p.clone())) as Box < dyn Mechanism + Sync
        >)
    ]
}
fn at_parameters(
    set: &[(&str, f64)],
) -> Result<symbody_runtime::registry::Built, ParameterError> {
    Parameters::at(set).map(built)
}
fn at_values(
    values: &[f64],
) -> Result<symbody_runtime::registry::Built, ParameterError> {
    Parameters::from_values(values).map(built)
}
/// This mechanism at other values of its run-time parameters, for the registries.
pub static RUN_TIME_ENTRY: symbody_runtime::registry::RunTime = symbody_runtime::registry::RunTime {
    parameters: &RUN_TIME,
    build: at_parameters,
    build_reduced: None,
    data: &DATA,
    p0: &P0,
    build_values: at_values,
    build_reduced_values: None,
};
/// The `exact` formulation: mass matrix and forces derived from the exact kinetic energy.
pub mod exact {
    use super::*;
    /// Row of each mass-matrix nonzero (both triangles).
    pub static MASS_ROWS: [u32; 19usize] = [
        0u32, 1u32, 2u32, 3u32, 3u32, 3u32, 3u32, 4u32, 4u32, 4u32, 4u32, 5u32, 5u32,
        5u32, 5u32, 6u32, 6u32, 6u32, 6u32,
    ];
    /// Column of each mass-matrix nonzero.
    pub static MASS_COLS: [u32; 19usize] = [
        0u32, 1u32, 2u32, 3u32, 4u32, 5u32, 6u32, 3u32, 4u32, 5u32, 6u32, 3u32, 4u32,
        5u32, 6u32, 3u32, 4u32, 5u32, 6u32,
    ];
    /// Row and column of each ∂Q/∂q nonzero.
    pub static FORCE_Q_ROWS: [u32; 0usize] = [];
    pub static FORCE_Q_COLS: [u32; 0usize] = [];
    /// Row and column of each ∂Q/∂q̇ nonzero.
    pub static FORCE_QD_ROWS: [u32; 0usize] = [];
    pub static FORCE_QD_COLS: [u32; 0usize] = [];
    /// Sizes, patterns and names for this formulation.
    pub static INFO: MechanismInfo = MechanismInfo {
        name: "hexapod_twist",
        n_coords: N_COORDS,
        n_constraints: N_CONSTRAINTS,
        formulation: Formulation::Exact,
        gravity: [0f64, -9.81f64, 0f64],
        phi_q_rows: &PHI_Q_ROWS,
        phi_q_cols: &PHI_Q_COLS,
        mass_rows: &MASS_ROWS,
        mass_cols: &MASS_COLS,
        mass_is_constant: false,
        force_q_rows: &FORCE_Q_ROWS,
        force_q_cols: &FORCE_Q_COLS,
        force_qd_rows: &FORCE_QD_ROWS,
        force_qd_cols: &FORCE_QD_COLS,
        bodies: &BODIES,
        joints: &JOINTS,
        coord_names: &COORD_NAMES,
        row_names: &ROW_NAMES,
        q0: &Q0,
        qd0: &QD0,
        redundant_rows: &REDUNDANT_ROWS,
        platform: PLATFORM,
    };
    /// Nonzeros of ∂Q/∂q and ∂Q/∂q̇ in the order of `FORCE_Q_*` and `FORCE_QD_*`.
    pub fn force_jacobian(
        k: &[f64],
        q: &[f64],
        qd: &[f64],
        t: f64,
        dq: &mut [f64],
        dqd: &mut [f64],
    ) {
        let k: &[f64; 51] = k.try_into().expect("k must have 51 entries");
        let q: &[f64; 7] = q.try_into().expect("q must have n_coords entries");
        let qd: &[f64; 7] = qd.try_into().expect("qd must have n_coords entries");
        let _: &mut [f64; 0] = dq.try_into().expect("dq must have 0 entries");
        let _: &mut [f64; 0] = dqd.try_into().expect("dqd must have 0 entries");
        let _ = k;
        let _ = q;
        let _ = qd;
        let _ = t;
    }
    /// Nonzeros of M(q) in the order of `MASS_ROWS`/`MASS_COLS`.
    pub fn mass(k: &[f64], q: &[f64], out: &mut [f64]) {
        let k: &[f64; 51] = k.try_into().expect("k must have 51 entries");
        let q: &[f64; 7] = q.try_into().expect("q must have n_coords entries");
        let out: &mut [f64; 19] = out.try_into().expect("out must have 19 entries");
        mass_part_0(k, q, out);
    }
    #[inline(never)]
    fn mass_part_0(k: &[f64; 51], q: &[f64; 7], out: &mut [f64; 19]) {
        let x153 = q[3] * q[3];
        let x154 = q[4] * q[4];
        let x155 = q[5] * q[5];
        let x156 = q[6] * q[6];
        let x167 = q[4] * q[5];
        let x169 = q[3] * q[6];
        let x174 = q[4] * q[6];
        let x176 = q[3] * q[5];
        let x180 = q[5] * q[6];
        let x182 = q[3] * q[4];
        let x363 = q[3] * 2.0;
        let x364 = q[4] * 2.0;
        let x365 = q[6] * 2.0;
        let x414 = q[5] * 2.0;
        let x415 = 2.0 * x363;
        let x520 = 2.0 * x364;
        let x660 = 2.0 * x365;
        let x1386 = 2.0 * x414;
        let x1389 = x364 * x520;
        let x1393 = x414 * x1386;
        let x1397 = x365 * x660;
        let x1409 = x364 * x415;
        let x1411 = x414 * x660;
        let x1415 = x365 * x1386;
        let x1423 = x364 * x660;
        let x1425 = x414 * x415;
        let x1427 = x365 * x520;
        let x1437 = x364 * x1386;
        let x1441 = x414 * x520;
        let x1443 = x365 * x415;
        let x1451 = x363 * x520;
        let x1464 = x363 * x415;
        let x1474 = x363 * x660;
        let x1486 = x363 * x1386;
        let x2667 = x1389 * k[48];
        let x2668 = x1393 * k[49];
        let x2669 = x1397 * k[48];
        let x2670 = x2667 + x2668;
        let x2671 = x2669 + x2670;
        let x2672 = 0.5 * x2671;
        let x2673 = x153 * k[50];
        let x2674 = x2672 + x2673;
        let x2675 = x1409 * k[48];
        let x2676 = x1411 * k[49];
        let x2678 = x1415 * k[48];
        let x2679 = x2675 - x2676;
        let x2680 = x2678 + x2679;
        let x2681 = 0.5 * x2680;
        let x2683 = x182 * k[50];
        let x2684 = x2683 - x2681;
        let x2685 = x1423 * k[48];
        let x2686 = x1425 * k[49];
        let x2687 = x1427 * k[48];
        let x2689 = x2685 + x2686;
        let x2690 = x2689 - x2687;
        let x2691 = 0.5 * x2690;
        let x2693 = x176 * k[50];
        let x2694 = x2693 - x2691;
        let x2695 = x1437 * k[48];
        let x2697 = x1441 * k[49];
        let x2698 = x1443 * k[48];
        let x2699 = x2697 - x2695;
        let x2700 = x2698 + x2699;
        let x2701 = 0.5 * x2700;
        let x2703 = x169 * k[50];
        let x2704 = x2703 - x2701;
        let x2705 = x1451 * k[48];
        let x2707 = x1415 * k[49];
        let x2708 = x1411 * k[48];
        let x2710 = x2707 - x2705;
        let x2711 = x2710 - x2708;
        let x2712 = 0.5 * x2711;
        let x2713 = x2683 + x2712;
        let x2714 = x1464 * k[48];
        let x2715 = x1397 * k[49];
        let x2716 = x1393 * k[48];
        let x2717 = x2714 + x2715;
        let x2718 = x2716 + x2717;
        let x2719 = 0.5 * x2718;
        let x2720 = x154 * k[50];
        let x2721 = x2719 + x2720;
        let x2722 = x1474 * k[48];
        let x2723 = x1443 * k[49];
        let x2725 = x1441 * k[48];
        let x2727 = x2722 - x2723;
        let x2728 = x2727 - x2725;
        let x2729 = 0.5 * x2728;
        let x2730 = x167 * k[50];
        let x2731 = x2729 + x2730;
        let x2732 = x1486 * k[48];
        let x2733 = x1427 * k[49];
        let x2734 = x1425 * k[48];
        let x2735 = x2732 + x2733;
        let x2737 = x2734 - x2735;
        let x2738 = 0.5 * x2737;
        let x2739 = x174 * k[50];
        let x2740 = x2738 + x2739;
        let x2741 = x1486 * k[49];
        let x2742 = x2687 + x2741;
        let x2744 = x2685 - x2742;
        let x2745 = 0.5 * x2744;
        let x2746 = x2693 + x2745;
        let x2747 = x1474 * k[49];
        let x2749 = x2698 - x2747;
        let x2750 = x2749 - x2695;
        let x2751 = 0.5 * x2750;
        let x2752 = x2730 + x2751;
        let x2753 = x1464 * k[49];
        let x2754 = x2669 + x2753;
        let x2755 = x2667 + x2754;
        let x2756 = 0.5 * x2755;
        let x2757 = x155 * k[50];
        let x2758 = x2756 + x2757;
        let x2760 = x1451 * k[49];
        let x2762 = x2760 - x2678;
        let x2763 = x2762 - x2675;
        let x2764 = 0.5 * x2763;
        let x2765 = x180 * k[50];
        let x2766 = x2764 + x2765;
        let x2767 = x1437 * k[49];
        let x2770 = x2725 - x2767;
        let x2771 = x2770 - x2722;
        let x2772 = 0.5 * x2771;
        let x2773 = x2703 + x2772;
        let x2774 = x1423 * k[49];
        let x2775 = x2734 + x2774;
        let x2777 = x2732 - x2775;
        let x2778 = 0.5 * x2777;
        let x2779 = x2739 + x2778;
        let x2780 = x1409 * k[49];
        let x2781 = x2780 - x2708;
        let x2782 = x2781 - x2705;
        let x2783 = 0.5 * x2782;
        let x2784 = x2765 + x2783;
        let x2785 = x1389 * k[49];
        let x2786 = x2716 + x2785;
        let x2787 = x2714 + x2786;
        let x2788 = 0.5 * x2787;
        let x2789 = x156 * k[50];
        let x2790 = x2788 + x2789;
        out[0] = 1.5;
        out[1] = 1.5;
        out[2] = 1.5;
        out[3] = x2674;
        out[4] = x2684;
        out[5] = x2694;
        out[6] = x2704;
        out[7] = x2713;
        out[8] = x2721;
        out[9] = x2731;
        out[10] = x2740;
        out[11] = x2746;
        out[12] = x2752;
        out[13] = x2758;
        out[14] = x2766;
        out[15] = x2773;
        out[16] = x2779;
        out[17] = x2784;
        out[18] = x2790;
    }
    /// Generalized forces Q(q, q̇, t): gravity and velocity-dependent terms.
    pub fn force(k: &[f64], q: &[f64], qd: &[f64], t: f64, out: &mut [f64]) {
        let k: &[f64; 51] = k.try_into().expect("k must have 51 entries");
        let q: &[f64; 7] = q.try_into().expect("q must have n_coords entries");
        let qd: &[f64; 7] = qd.try_into().expect("qd must have n_coords entries");
        let out: &mut [f64; 7] = out.try_into().expect("out must have 7 entries");
        let _ = t;
        force_part_0(k, q, qd, out);
    }
    #[inline(never)]
    fn force_part_0(k: &[f64; 51], q: &[f64; 7], qd: &[f64; 7], out: &mut [f64; 7]) {
        let x363 = q[3] * 2.0;
        let x364 = q[4] * 2.0;
        let x365 = q[6] * 2.0;
        let x414 = q[5] * 2.0;
        let x790 = q[5] * qd[4];
        let x791 = q[4] * qd[5];
        let x794 = q[6] * qd[3];
        let x795 = q[3] * qd[6];
        let x798 = q[6] * qd[4];
        let x799 = q[4] * qd[6];
        let x802 = q[5] * qd[3];
        let x803 = q[3] * qd[5];
        let x808 = q[6] * qd[5];
        let x809 = q[5] * qd[6];
        let x812 = q[4] * qd[3];
        let x813 = q[3] * qd[4];
        let x936 = 2.0 * qd[3];
        let x937 = 2.0 * qd[4];
        let x938 = 2.0 * qd[6];
        let x981 = 2.0 * qd[5];
        let x1062 = qd[4] * qd[5];
        let x1065 = qd[3] * qd[6];
        let x1068 = qd[4] * qd[6];
        let x1071 = qd[3] * qd[5];
        let x1277 = x813 - x812;
        let x1278 = x808 + x1277;
        let x1279 = x1278 - x809;
        let x1280 = 2.0 * x1279;
        let x1283 = x798 + x802;
        let x1285 = x803 - x1283;
        let x1286 = x799 + x1285;
        let x1287 = 2.0 * x1286;
        let x1290 = x790 - x794;
        let x1291 = x1290 - x791;
        let x1292 = x795 + x1291;
        let x1293 = 2.0 * x1292;
        let x1314 = 2.0 * x1280;
        let x1316 = 2.0 * x1287;
        let x1318 = 2.0 * x1293;
        let x1558 = x1068 + x1071;
        let x1560 = x1071 - x1558;
        let x1561 = x1068 + x1560;
        let x1562 = 2.0 * x1561;
        let x1565 = x1062 - x1065;
        let x1566 = x1565 - x1062;
        let x1567 = x1065 + x1566;
        let x1568 = 2.0 * x1567;
        let x1569 = 2.0 * x1562;
        let x1570 = 2.0 * x1568;
        let x1571 = x937 * x1314;
        let x1573 = x981 * x1316;
        let x1574 = x414 * x1569;
        let x1575 = x1573 + x1574;
        let x1577 = x938 * x1318;
        let x1578 = x365 * x1570;
        let x1579 = x1577 + x1578;
        let x1585 = x936 * x1314;
        let x1587 = x938 * x1316;
        let x1588 = x365 * x1569;
        let x1589 = x1587 + x1588;
        let x1592 = x981 * x1318;
        let x1593 = x414 * x1570;
        let x1594 = x1592 + x1593;
        let x1599 = x938 * x1314;
        let x1601 = x936 * x1316;
        let x1602 = x363 * x1569;
        let x1603 = x1601 + x1602;
        let x1605 = x937 * x1318;
        let x1606 = x364 * x1570;
        let x1607 = x1605 + x1606;
        let x1613 = x981 * x1314;
        let x1616 = x937 * x1316;
        let x1617 = x364 * x1569;
        let x1618 = x1616 + x1617;
        let x1620 = x936 * x1318;
        let x1621 = x363 * x1570;
        let x1622 = x1620 + x1621;
        let x1627 = qd[3] * qd[3];
        let x1628 = qd[4] * qd[4];
        let x1629 = qd[5] * qd[5];
        let x1630 = qd[6] * qd[6];
        let x1631 = x1627 + x1628;
        let x1632 = x1629 + x1631;
        let x1633 = x1630 + x1632;
        let x2791 = x1571 * k[48];
        let x2792 = x1575 * k[49];
        let x2793 = x1579 * k[48];
        let x2794 = x2791 + x2792;
        let x2795 = x2793 + x2794;
        let x2796 = 0.5 * x2795;
        let x2797 = x1585 * k[48];
        let x2798 = x1589 * k[49];
        let x2800 = x1594 * k[48];
        let x2801 = x2797 - x2798;
        let x2802 = x2800 + x2801;
        let x2803 = 0.5 * x2802;
        let x2804 = x1599 * k[48];
        let x2805 = x1603 * k[49];
        let x2806 = x1607 * k[48];
        let x2808 = x2804 + x2805;
        let x2809 = x2808 - x2806;
        let x2810 = 0.5 * x2809;
        let x2811 = x1613 * k[48];
        let x2813 = x1618 * k[49];
        let x2814 = x1622 * k[48];
        let x2815 = x2813 - x2811;
        let x2816 = x2814 + x2815;
        let x2817 = 0.5 * x2816;
        let x2818 = x1573 * k[49];
        let x2819 = x1577 * k[48];
        let x2820 = x2791 + x2818;
        let x2821 = x2819 + x2820;
        let x2822 = 0.5 * x2821;
        let x2823 = x2796 + x2822;
        let x2824 = q[3] * k[50];
        let x2825 = x1633 * x2824;
        let x2827 = x2823 - x2825;
        let x2829 = x1587 * k[49];
        let x2830 = x1592 * k[48];
        let x2832 = x2829 - x2797;
        let x2833 = x2832 - x2830;
        let x2834 = 0.5 * x2833;
        let x2836 = x2834 - x2803;
        let x2837 = q[4] * k[50];
        let x2838 = x1633 * x2837;
        let x2840 = x2836 - x2838;
        let x2841 = x1601 * k[49];
        let x2842 = x1605 * k[48];
        let x2843 = x2804 + x2841;
        let x2845 = x2842 - x2843;
        let x2846 = 0.5 * x2845;
        let x2848 = x2846 - x2810;
        let x2849 = q[5] * k[50];
        let x2850 = x1633 * x2849;
        let x2852 = x2848 - x2850;
        let x2853 = x1616 * k[49];
        let x2855 = x1620 * k[48];
        let x2857 = x2811 - x2853;
        let x2858 = x2857 - x2855;
        let x2859 = 0.5 * x2858;
        let x2861 = x2859 - x2817;
        let x2862 = q[6] * k[50];
        let x2863 = x1633 * x2862;
        let x2865 = x2861 - x2863;
        out[0] = 0.0;
        out[1] = -14.715;
        out[2] = 0.0;
        out[3] = x2827;
        out[4] = x2840;
        out[5] = x2852;
        out[6] = x2865;
    }
    /// Φ, Φq, M and Q at one state in one pass: what one Newton iteration needs.
    pub fn eval_newton(
        k: &[f64],
        q: &[f64],
        qd: &[f64],
        t: f64,
        phi: &mut [f64],
        phi_q: &mut [f64],
        mass: &mut [f64],
        force: &mut [f64],
    ) {
        let k: &[f64; 51] = k.try_into().expect("k must have 51 entries");
        let q: &[f64; 7] = q.try_into().expect("q must have n_coords entries");
        let qd: &[f64; 7] = qd.try_into().expect("qd must have n_coords entries");
        let phi: &mut [f64; 7] = phi.try_into().expect("phi must have 7 entries");
        let phi_q: &mut [f64; 46] = phi_q
            .try_into()
            .expect("phi_q must have 46 entries");
        let mass: &mut [f64; 19] = mass.try_into().expect("mass must have 19 entries");
        let force: &mut [f64; 7] = force.try_into().expect("force must have 7 entries");
        let mut s = [0.0f64; 46];
        eval_newton_shared_0(k, q, qd, t, &mut s);
        eval_newton_part_0(k, q, t, &s, phi, phi_q, mass);
        eval_newton_part_1(k, q, qd, &s, mass, force);
    }
    #[inline(never)]
    fn eval_newton_shared_0(
        k: &[f64; 51],
        q: &[f64; 7],
        _qd: &[f64; 7],
        _t: f64,
        s: &mut [f64; 46],
    ) {
        let x155 = q[5] * q[5];
        s[0] = x155;
        let x156 = q[6] * q[6];
        s[1] = x156;
        let x167 = q[4] * q[5];
        s[2] = x167;
        let x169 = q[3] * q[6];
        s[3] = x169;
        let x174 = q[4] * q[6];
        s[4] = x174;
        let x180 = q[5] * q[6];
        s[5] = x180;
        let x363 = q[3] * 2.0;
        s[6] = x363;
        let x364 = q[4] * 2.0;
        s[7] = x364;
        let x365 = q[6] * 2.0;
        s[8] = x365;
        let x414 = q[5] * 2.0;
        s[9] = x414;
        let x415 = 2.0 * x363;
        s[10] = x415;
        let x520 = 2.0 * x364;
        s[11] = x520;
        let x660 = 2.0 * x365;
        s[12] = x660;
        let x1386 = 2.0 * x414;
        s[13] = x1386;
        let x1389 = x364 * x520;
        s[14] = x1389;
        let x1393 = x414 * x1386;
        s[15] = x1393;
        let x1397 = x365 * x660;
        s[16] = x1397;
        let x1409 = x364 * x415;
        s[17] = x1409;
        let x1411 = x414 * x660;
        s[18] = x1411;
        let x1415 = x365 * x1386;
        s[19] = x1415;
        let x1423 = x364 * x660;
        s[20] = x1423;
        let x1425 = x414 * x415;
        s[21] = x1425;
        let x1437 = x364 * x1386;
        s[22] = x1437;
        let x1441 = x414 * x520;
        s[23] = x1441;
        let x1443 = x365 * x415;
        s[24] = x1443;
        let x1451 = x363 * x520;
        s[25] = x1451;
        let x1464 = x363 * x415;
        s[26] = x1464;
        let x1474 = x363 * x660;
        s[27] = x1474;
        let x1486 = x363 * x1386;
        s[28] = x1486;
        let x2667 = x1389 * k[48];
        s[29] = x2667;
        let x2669 = x1397 * k[48];
        s[30] = x2669;
        let x2675 = x1409 * k[48];
        s[31] = x2675;
        let x2678 = x1415 * k[48];
        s[32] = x2678;
        let x2695 = x1437 * k[48];
        s[33] = x2695;
        let x2698 = x1443 * k[48];
        s[34] = x2698;
        let x2703 = x169 * k[50];
        s[35] = x2703;
        let x2705 = x1451 * k[48];
        s[36] = x2705;
        let x2708 = x1411 * k[48];
        s[37] = x2708;
        let x2714 = x1464 * k[48];
        s[38] = x2714;
        let x2716 = x1393 * k[48];
        s[39] = x2716;
        let x2722 = x1474 * k[48];
        s[40] = x2722;
        let x2725 = x1441 * k[48];
        s[41] = x2725;
        let x2730 = x167 * k[50];
        s[42] = x2730;
        let x2732 = x1486 * k[48];
        s[43] = x2732;
        let x2734 = x1425 * k[48];
        s[44] = x2734;
        let x2739 = x174 * k[50];
        s[45] = x2739;
    }
    #[inline(never)]
    fn eval_newton_part_0(
        k: &[f64; 51],
        q: &[f64; 7],
        t: f64,
        s: &[f64; 46],
        phi: &mut [f64; 7],
        phi_q: &mut [f64; 46],
        mass: &mut [f64; 19],
    ) {
        let x7 = 0.8726646259971648 * t;
        let x153 = q[3] * q[3];
        let x154 = q[4] * q[4];
        let x157 = x153 + x154;
        let x158 = 2.0 * x157;
        let x160 = x158 - 1.0;
        let x164 = x153 + s[1];
        let x165 = 2.0 * x164;
        let x166 = x165 - 1.0;
        let x168 = 2.0 * s[2];
        let x171 = 2.0 * s[3];
        let x175 = 2.0 * s[4];
        let x176 = q[3] * q[5];
        let x177 = 2.0 * x176;
        let x178 = x175 + x177;
        let x179 = x168 + x171;
        let x181 = 2.0 * s[5];
        let x182 = q[3] * q[4];
        let x184 = 2.0 * x182;
        let x186 = x181 - x184;
        let x189 = x175 - x177;
        let x360 = s[0] + x157;
        let x361 = s[1] + x360;
        let x362 = x361 - 1.0;
        let x1427 = s[8] * s[11];
        let x1702 = x7 + k[3];
        let x1703 = k[2] + x1702;
        let x1704 = x1703.cos();
        let x1705 = k[1] * x1704;
        let x1707 = k[0] - x1705;
        let x1708 = x1707.sqrt();
        let x1713 = x7 + k[7];
        let x1714 = k[6] + x1713;
        let x1715 = x1714.cos();
        let x1716 = k[5] * x1715;
        let x1718 = k[4] - x1716;
        let x1719 = x1718.sqrt();
        let x1724 = x7 + k[11];
        let x1725 = k[10] + x1724;
        let x1726 = x1725.cos();
        let x1727 = k[9] * x1726;
        let x1729 = k[8] - x1727;
        let x1730 = x1729.sqrt();
        let x1735 = x7 + k[15];
        let x1736 = k[14] + x1735;
        let x1737 = x1736.cos();
        let x1738 = k[13] * x1737;
        let x1740 = k[12] - x1738;
        let x1741 = x1740.sqrt();
        let x1746 = x7 + k[19];
        let x1747 = k[18] + x1746;
        let x1748 = x1747.cos();
        let x1749 = k[17] * x1748;
        let x1751 = k[16] - x1749;
        let x1752 = x1751.sqrt();
        let x1757 = x7 + k[23];
        let x1758 = k[22] + x1757;
        let x1759 = x1758.cos();
        let x1760 = k[21] * x1759;
        let x1762 = k[20] - x1760;
        let x1763 = x1762.sqrt();
        let x1766 = x160 * k[24];
        let x1767 = x178 * k[25];
        let x1768 = x1766 + x1767;
        let x1769 = x179 * k[24];
        let x1770 = x186 * k[25];
        let x1771 = x1769 + x1770;
        let x1772 = x189 * k[24];
        let x1773 = x166 * k[25];
        let x1774 = x1772 + x1773;
        let x1775 = q[0] + x1768;
        let x1776 = q[1] + x1771;
        let x1777 = q[2] + x1774;
        let x1779 = x1775 + k[26];
        let x1781 = x1777 + k[27];
        let x1782 = x1779 * x1779;
        let x1783 = x1776 * x1776;
        let x1784 = x1781 * x1781;
        let x1785 = x1782 + x1783;
        let x1786 = x1784 + x1785;
        let x1787 = x1786.sqrt();
        let x1789 = x1787 - x1708;
        let x1792 = x160 * k[28];
        let x1793 = x178 * k[29];
        let x1794 = x1792 + x1793;
        let x1795 = x179 * k[28];
        let x1796 = x186 * k[29];
        let x1797 = x1795 + x1796;
        let x1798 = x189 * k[28];
        let x1799 = x166 * k[29];
        let x1800 = x1798 + x1799;
        let x1801 = q[0] + x1794;
        let x1802 = q[1] + x1797;
        let x1803 = q[2] + x1800;
        let x1805 = x1801 + k[30];
        let x1807 = x1803 + k[31];
        let x1808 = x1805 * x1805;
        let x1809 = x1802 * x1802;
        let x1810 = x1807 * x1807;
        let x1811 = x1808 + x1809;
        let x1812 = x1810 + x1811;
        let x1813 = x1812.sqrt();
        let x1815 = x1813 - x1719;
        let x1818 = x160 * k[32];
        let x1819 = x178 * k[33];
        let x1820 = x1818 + x1819;
        let x1821 = x179 * k[32];
        let x1822 = x186 * k[33];
        let x1823 = x1821 + x1822;
        let x1824 = x189 * k[32];
        let x1825 = x166 * k[33];
        let x1826 = x1824 + x1825;
        let x1827 = q[0] + x1820;
        let x1828 = q[1] + x1823;
        let x1829 = q[2] + x1826;
        let x1831 = x1827 + k[34];
        let x1833 = x1829 + k[35];
        let x1834 = x1831 * x1831;
        let x1835 = x1828 * x1828;
        let x1836 = x1833 * x1833;
        let x1837 = x1834 + x1835;
        let x1838 = x1836 + x1837;
        let x1839 = x1838.sqrt();
        let x1841 = x1839 - x1730;
        let x1844 = x160 * k[36];
        let x1845 = x178 * k[37];
        let x1846 = x1844 + x1845;
        let x1847 = x179 * k[36];
        let x1848 = x186 * k[37];
        let x1849 = x1847 + x1848;
        let x1850 = x189 * k[36];
        let x1851 = x166 * k[37];
        let x1852 = x1850 + x1851;
        let x1853 = q[0] + x1846;
        let x1854 = q[1] + x1849;
        let x1855 = q[2] + x1852;
        let x1857 = x1853 + k[38];
        let x1859 = x1855 + k[39];
        let x1860 = x1857 * x1857;
        let x1861 = x1854 * x1854;
        let x1862 = x1859 * x1859;
        let x1863 = x1860 + x1861;
        let x1864 = x1862 + x1863;
        let x1865 = x1864.sqrt();
        let x1867 = x1865 - x1741;
        let x1870 = x160 * k[40];
        let x1871 = x178 * k[41];
        let x1872 = x1870 + x1871;
        let x1873 = x179 * k[40];
        let x1874 = x186 * k[41];
        let x1875 = x1873 + x1874;
        let x1876 = x189 * k[40];
        let x1877 = x166 * k[41];
        let x1878 = x1876 + x1877;
        let x1879 = q[0] + x1872;
        let x1880 = q[1] + x1875;
        let x1881 = q[2] + x1878;
        let x1883 = x1879 + k[42];
        let x1885 = x1881 + k[43];
        let x1886 = x1883 * x1883;
        let x1887 = x1880 * x1880;
        let x1888 = x1885 * x1885;
        let x1889 = x1886 + x1887;
        let x1890 = x1888 + x1889;
        let x1891 = x1890.sqrt();
        let x1893 = x1891 - x1752;
        let x1896 = x160 * k[44];
        let x1897 = x178 * k[45];
        let x1898 = x1896 + x1897;
        let x1899 = x179 * k[44];
        let x1900 = x186 * k[45];
        let x1901 = x1899 + x1900;
        let x1902 = x189 * k[44];
        let x1903 = x166 * k[45];
        let x1904 = x1902 + x1903;
        let x1905 = q[0] + x1898;
        let x1906 = q[1] + x1901;
        let x1907 = q[2] + x1904;
        let x1909 = x1905 + k[46];
        let x1911 = x1907 + k[47];
        let x1912 = x1909 * x1909;
        let x1913 = x1906 * x1906;
        let x1914 = x1911 * x1911;
        let x1915 = x1912 + x1913;
        let x1916 = x1914 + x1915;
        let x1917 = x1916.sqrt();
        let x1919 = x1917 - x1763;
        let x1920 = 2.0 * x1779;
        let x1921 = 2.0 * x1776;
        let x1922 = 2.0 * x1781;
        let x1923 = 2.0 * x1787;
        let x1924 = 1.0 / x1923;
        let x1925 = x1920 * x1924;
        let x1926 = 2.0 * x1805;
        let x1927 = 2.0 * x1802;
        let x1928 = 2.0 * x1807;
        let x1929 = 2.0 * x1813;
        let x1930 = 1.0 / x1929;
        let x1931 = x1926 * x1930;
        let x1932 = 2.0 * x1831;
        let x1933 = 2.0 * x1828;
        let x1934 = 2.0 * x1833;
        let x1935 = 2.0 * x1839;
        let x1936 = 1.0 / x1935;
        let x1937 = x1932 * x1936;
        let x1938 = 2.0 * x1857;
        let x1939 = 2.0 * x1854;
        let x1940 = 2.0 * x1859;
        let x1941 = 2.0 * x1865;
        let x1942 = 1.0 / x1941;
        let x1943 = x1938 * x1942;
        let x1944 = 2.0 * x1883;
        let x1945 = 2.0 * x1880;
        let x1946 = 2.0 * x1885;
        let x1947 = 2.0 * x1891;
        let x1948 = 1.0 / x1947;
        let x1949 = x1944 * x1948;
        let x1950 = 2.0 * x1909;
        let x1951 = 2.0 * x1906;
        let x1952 = 2.0 * x1911;
        let x1953 = 2.0 * x1917;
        let x1954 = 1.0 / x1953;
        let x1955 = x1950 * x1954;
        let x1956 = x1921 * x1924;
        let x1957 = x1927 * x1930;
        let x1958 = x1933 * x1936;
        let x1959 = x1939 * x1942;
        let x1960 = x1945 * x1948;
        let x1961 = x1951 * x1954;
        let x1962 = x1922 * x1924;
        let x1963 = x1928 * x1930;
        let x1964 = x1934 * x1936;
        let x1965 = x1940 * x1942;
        let x1966 = x1946 * x1948;
        let x1967 = x1952 * x1954;
        let x1968 = s[10] * k[24];
        let x1969 = s[9] * k[25];
        let x1970 = x1968 + x1969;
        let x1971 = s[8] * k[24];
        let x1972 = s[7] * k[25];
        let x1974 = x1971 - x1972;
        let x1975 = s[9] * k[24];
        let x1977 = s[10] * k[25];
        let x1978 = x1977 - x1975;
        let x1979 = x1920 * x1970;
        let x1980 = x1921 * x1974;
        let x1981 = x1922 * x1978;
        let x1982 = x1979 + x1980;
        let x1983 = x1981 + x1982;
        let x1984 = x1924 * x1983;
        let x1985 = s[10] * k[28];
        let x1986 = s[9] * k[29];
        let x1987 = x1985 + x1986;
        let x1988 = s[8] * k[28];
        let x1989 = s[7] * k[29];
        let x1991 = x1988 - x1989;
        let x1992 = s[9] * k[28];
        let x1994 = s[10] * k[29];
        let x1995 = x1994 - x1992;
        let x1996 = x1926 * x1987;
        let x1997 = x1927 * x1991;
        let x1998 = x1928 * x1995;
        let x1999 = x1996 + x1997;
        let x2000 = x1998 + x1999;
        let x2001 = x1930 * x2000;
        let x2002 = s[10] * k[32];
        let x2003 = s[9] * k[33];
        let x2004 = x2002 + x2003;
        let x2005 = s[8] * k[32];
        let x2006 = s[7] * k[33];
        let x2008 = x2005 - x2006;
        let x2009 = s[9] * k[32];
        let x2011 = s[10] * k[33];
        let x2012 = x2011 - x2009;
        let x2013 = x1932 * x2004;
        let x2014 = x1933 * x2008;
        let x2015 = x1934 * x2012;
        let x2016 = x2013 + x2014;
        let x2017 = x2015 + x2016;
        let x2018 = x1936 * x2017;
        let x2019 = s[10] * k[36];
        let x2020 = s[9] * k[37];
        let x2021 = x2019 + x2020;
        let x2022 = s[8] * k[36];
        let x2023 = s[7] * k[37];
        let x2025 = x2022 - x2023;
        let x2026 = s[9] * k[36];
        let x2028 = s[10] * k[37];
        let x2029 = x2028 - x2026;
        let x2030 = x1938 * x2021;
        let x2031 = x1939 * x2025;
        let x2032 = x1940 * x2029;
        let x2033 = x2030 + x2031;
        let x2034 = x2032 + x2033;
        let x2035 = x1942 * x2034;
        let x2036 = s[10] * k[40];
        let x2037 = s[9] * k[41];
        let x2038 = x2036 + x2037;
        let x2039 = s[8] * k[40];
        let x2040 = s[7] * k[41];
        let x2042 = x2039 - x2040;
        let x2043 = s[9] * k[40];
        let x2045 = s[10] * k[41];
        let x2046 = x2045 - x2043;
        let x2047 = x1944 * x2038;
        let x2048 = x1945 * x2042;
        let x2049 = x1946 * x2046;
        let x2050 = x2047 + x2048;
        let x2051 = x2049 + x2050;
        let x2052 = x1948 * x2051;
        let x2053 = s[10] * k[44];
        let x2054 = s[9] * k[45];
        let x2055 = x2053 + x2054;
        let x2056 = s[8] * k[44];
        let x2057 = s[7] * k[45];
        let x2059 = x2056 - x2057;
        let x2060 = s[9] * k[44];
        let x2062 = s[10] * k[45];
        let x2063 = x2062 - x2060;
        let x2064 = x1950 * x2055;
        let x2065 = x1951 * x2059;
        let x2066 = x1952 * x2063;
        let x2067 = x2064 + x2065;
        let x2068 = x2066 + x2067;
        let x2069 = x1954 * x2068;
        let x2070 = s[11] * k[24];
        let x2071 = s[8] * k[25];
        let x2072 = x2070 + x2071;
        let x2073 = s[6] * k[25];
        let x2075 = x1975 - x2073;
        let x2076 = x1920 * x2072;
        let x2077 = x1921 * x2075;
        let x2078 = x1922 * x1971;
        let x2079 = x2076 + x2077;
        let x2080 = x2078 + x2079;
        let x2081 = x1924 * x2080;
        let x2082 = s[11] * k[28];
        let x2083 = s[8] * k[29];
        let x2084 = x2082 + x2083;
        let x2085 = s[6] * k[29];
        let x2087 = x1992 - x2085;
        let x2088 = x1926 * x2084;
        let x2089 = x1927 * x2087;
        let x2090 = x1928 * x1988;
        let x2091 = x2088 + x2089;
        let x2092 = x2090 + x2091;
        let x2093 = x1930 * x2092;
        let x2094 = s[11] * k[32];
        let x2095 = s[8] * k[33];
        let x2096 = x2094 + x2095;
        let x2097 = s[6] * k[33];
        let x2099 = x2009 - x2097;
        let x2100 = x1932 * x2096;
        let x2101 = x1933 * x2099;
        let x2102 = x1934 * x2005;
        let x2103 = x2100 + x2101;
        let x2104 = x2102 + x2103;
        let x2105 = x1936 * x2104;
        let x2106 = s[11] * k[36];
        let x2107 = s[8] * k[37];
        let x2108 = x2106 + x2107;
        let x2109 = s[6] * k[37];
        let x2111 = x2026 - x2109;
        let x2112 = x1938 * x2108;
        let x2113 = x1939 * x2111;
        let x2114 = x1940 * x2022;
        let x2115 = x2112 + x2113;
        let x2116 = x2114 + x2115;
        let x2117 = x1942 * x2116;
        let x2118 = s[11] * k[40];
        let x2119 = s[8] * k[41];
        let x2120 = x2118 + x2119;
        let x2121 = s[6] * k[41];
        let x2123 = x2043 - x2121;
        let x2124 = x1944 * x2120;
        let x2125 = x1945 * x2123;
        let x2126 = x1946 * x2039;
        let x2127 = x2124 + x2125;
        let x2128 = x2126 + x2127;
        let x2129 = x1948 * x2128;
        let x2130 = s[11] * k[44];
        let x2131 = s[8] * k[45];
        let x2132 = x2130 + x2131;
        let x2133 = s[6] * k[45];
        let x2135 = x2060 - x2133;
        let x2136 = x1950 * x2132;
        let x2137 = x1951 * x2135;
        let x2138 = x1952 * x2056;
        let x2139 = x2136 + x2137;
        let x2140 = x2138 + x2139;
        let x2141 = x1954 * x2140;
        let x2142 = s[7] * k[24];
        let x2143 = x2071 + x2142;
        let x2144 = s[6] * k[24];
        let x2145 = x1920 * x2073;
        let x2146 = x1921 * x2143;
        let x2147 = x1922 * x2144;
        let x2149 = x2145 + x2146;
        let x2150 = x2149 - x2147;
        let x2151 = x1924 * x2150;
        let x2152 = s[7] * k[28];
        let x2153 = x2083 + x2152;
        let x2154 = s[6] * k[28];
        let x2155 = x1926 * x2085;
        let x2156 = x1927 * x2153;
        let x2157 = x1928 * x2154;
        let x2159 = x2155 + x2156;
        let x2160 = x2159 - x2157;
        let x2161 = x1930 * x2160;
        let x2162 = s[7] * k[32];
        let x2163 = x2095 + x2162;
        let x2164 = s[6] * k[32];
        let x2165 = x1932 * x2097;
        let x2166 = x1933 * x2163;
        let x2167 = x1934 * x2164;
        let x2169 = x2165 + x2166;
        let x2170 = x2169 - x2167;
        let x2171 = x1936 * x2170;
        let x2172 = s[7] * k[36];
        let x2173 = x2107 + x2172;
        let x2174 = s[6] * k[36];
        let x2175 = x1938 * x2109;
        let x2176 = x1939 * x2173;
        let x2177 = x1940 * x2174;
        let x2179 = x2175 + x2176;
        let x2180 = x2179 - x2177;
        let x2181 = x1942 * x2180;
        let x2182 = s[7] * k[40];
        let x2183 = x2119 + x2182;
        let x2184 = s[6] * k[40];
        let x2185 = x1944 * x2121;
        let x2186 = x1945 * x2183;
        let x2187 = x1946 * x2184;
        let x2189 = x2185 + x2186;
        let x2190 = x2189 - x2187;
        let x2191 = x1948 * x2190;
        let x2192 = s[7] * k[44];
        let x2193 = x2131 + x2192;
        let x2194 = s[6] * k[44];
        let x2195 = x1950 * x2133;
        let x2196 = x1951 * x2193;
        let x2197 = x1952 * x2194;
        let x2199 = x2195 + x2196;
        let x2200 = x2199 - x2197;
        let x2201 = x1954 * x2200;
        let x2202 = x1969 + x2144;
        let x2203 = s[12] * k[25];
        let x2204 = x2142 + x2203;
        let x2205 = x1920 * x1972;
        let x2206 = x1921 * x2202;
        let x2207 = x1922 * x2204;
        let x2208 = x2205 + x2206;
        let x2209 = x2207 + x2208;
        let x2210 = x1924 * x2209;
        let x2211 = x1986 + x2154;
        let x2212 = s[12] * k[29];
        let x2213 = x2152 + x2212;
        let x2214 = x1926 * x1989;
        let x2215 = x1927 * x2211;
        let x2216 = x1928 * x2213;
        let x2217 = x2214 + x2215;
        let x2218 = x2216 + x2217;
        let x2219 = x1930 * x2218;
        let x2220 = x2003 + x2164;
        let x2221 = s[12] * k[33];
        let x2222 = x2162 + x2221;
        let x2223 = x1932 * x2006;
        let x2224 = x1933 * x2220;
        let x2225 = x1934 * x2222;
        let x2226 = x2223 + x2224;
        let x2227 = x2225 + x2226;
        let x2228 = x1936 * x2227;
        let x2229 = x2020 + x2174;
        let x2230 = s[12] * k[37];
        let x2231 = x2172 + x2230;
        let x2232 = x1938 * x2023;
        let x2233 = x1939 * x2229;
        let x2234 = x1940 * x2231;
        let x2235 = x2232 + x2233;
        let x2236 = x2234 + x2235;
        let x2237 = x1942 * x2236;
        let x2238 = x2037 + x2184;
        let x2239 = s[12] * k[41];
        let x2240 = x2182 + x2239;
        let x2241 = x1944 * x2040;
        let x2242 = x1945 * x2238;
        let x2243 = x1946 * x2240;
        let x2244 = x2241 + x2242;
        let x2245 = x2243 + x2244;
        let x2246 = x1948 * x2245;
        let x2247 = x2054 + x2194;
        let x2248 = s[12] * k[45];
        let x2249 = x2192 + x2248;
        let x2250 = x1950 * x2057;
        let x2251 = x1951 * x2247;
        let x2252 = x1952 * x2249;
        let x2253 = x2250 + x2251;
        let x2254 = x2252 + x2253;
        let x2255 = x1954 * x2254;
        let x2668 = s[15] * k[49];
        let x2670 = s[29] + x2668;
        let x2671 = s[30] + x2670;
        let x2672 = 0.5 * x2671;
        let x2673 = x153 * k[50];
        let x2674 = x2672 + x2673;
        let x2676 = s[18] * k[49];
        let x2679 = s[31] - x2676;
        let x2680 = s[32] + x2679;
        let x2681 = 0.5 * x2680;
        let x2683 = x182 * k[50];
        let x2684 = x2683 - x2681;
        let x2685 = s[20] * k[48];
        let x2686 = s[21] * k[49];
        let x2687 = x1427 * k[48];
        let x2689 = x2685 + x2686;
        let x2690 = x2689 - x2687;
        let x2691 = 0.5 * x2690;
        let x2693 = x176 * k[50];
        let x2694 = x2693 - x2691;
        let x2697 = s[23] * k[49];
        let x2699 = x2697 - s[33];
        let x2700 = s[34] + x2699;
        let x2701 = 0.5 * x2700;
        let x2704 = s[35] - x2701;
        let x2707 = s[19] * k[49];
        let x2710 = x2707 - s[36];
        let x2711 = x2710 - s[37];
        let x2712 = 0.5 * x2711;
        let x2713 = x2683 + x2712;
        let x2715 = s[16] * k[49];
        let x2717 = s[38] + x2715;
        let x2718 = s[39] + x2717;
        let x2719 = 0.5 * x2718;
        let x2720 = x154 * k[50];
        let x2721 = x2719 + x2720;
        let x2723 = s[24] * k[49];
        let x2727 = s[40] - x2723;
        let x2728 = x2727 - s[41];
        let x2729 = 0.5 * x2728;
        let x2731 = x2729 + s[42];
        let x2733 = x1427 * k[49];
        let x2735 = s[43] + x2733;
        let x2737 = s[44] - x2735;
        let x2738 = 0.5 * x2737;
        let x2740 = x2738 + s[45];
        let x2741 = s[28] * k[49];
        let x2742 = x2687 + x2741;
        let x2744 = x2685 - x2742;
        let x2745 = 0.5 * x2744;
        let x2746 = x2693 + x2745;
        phi[0] = x1789;
        phi_q[0] = x1925;
        phi_q[1] = x1956;
        phi_q[2] = x1962;
        phi_q[3] = x1984;
        phi_q[4] = x2081;
        phi_q[5] = x2151;
        phi_q[6] = x2210;
        phi[1] = x1815;
        phi_q[7] = x1931;
        phi_q[8] = x1957;
        phi_q[9] = x1963;
        phi_q[10] = x2001;
        phi_q[11] = x2093;
        phi_q[12] = x2161;
        phi_q[13] = x2219;
        phi[2] = x1841;
        phi_q[14] = x1937;
        phi_q[15] = x1958;
        phi_q[16] = x1964;
        phi_q[17] = x2018;
        phi_q[18] = x2105;
        phi_q[19] = x2171;
        phi_q[20] = x2228;
        phi[3] = x1867;
        phi_q[21] = x1943;
        phi_q[22] = x1959;
        phi_q[23] = x1965;
        phi_q[24] = x2035;
        phi_q[25] = x2117;
        phi_q[26] = x2181;
        phi_q[27] = x2237;
        phi[4] = x1893;
        phi_q[28] = x1949;
        phi_q[29] = x1960;
        phi_q[30] = x1966;
        phi_q[31] = x2052;
        phi_q[32] = x2129;
        phi_q[33] = x2191;
        phi_q[34] = x2246;
        phi[5] = x1919;
        phi_q[35] = x1955;
        phi_q[36] = x1961;
        phi_q[37] = x1967;
        phi_q[38] = x2069;
        phi_q[39] = x2141;
        phi_q[40] = x2201;
        phi_q[41] = x2255;
        phi[6] = x362;
        phi_q[42] = s[6];
        phi_q[43] = s[7];
        phi_q[44] = s[9];
        phi_q[45] = s[8];
        mass[0] = 1.5;
        mass[1] = 1.5;
        mass[2] = 1.5;
        mass[3] = x2674;
        mass[4] = x2684;
        mass[5] = x2694;
        mass[6] = x2704;
        mass[7] = x2713;
        mass[8] = x2721;
        mass[9] = x2731;
        mass[10] = x2740;
        mass[11] = x2746;
    }
    #[inline(never)]
    fn eval_newton_part_1(
        k: &[f64; 51],
        q: &[f64; 7],
        qd: &[f64; 7],
        s: &[f64; 46],
        mass: &mut [f64; 19],
        force: &mut [f64; 7],
    ) {
        let x790 = q[5] * qd[4];
        let x791 = q[4] * qd[5];
        let x794 = q[6] * qd[3];
        let x795 = q[3] * qd[6];
        let x798 = q[6] * qd[4];
        let x799 = q[4] * qd[6];
        let x802 = q[5] * qd[3];
        let x803 = q[3] * qd[5];
        let x808 = q[6] * qd[5];
        let x809 = q[5] * qd[6];
        let x812 = q[4] * qd[3];
        let x813 = q[3] * qd[4];
        let x936 = 2.0 * qd[3];
        let x937 = 2.0 * qd[4];
        let x938 = 2.0 * qd[6];
        let x981 = 2.0 * qd[5];
        let x1062 = qd[4] * qd[5];
        let x1065 = qd[3] * qd[6];
        let x1068 = qd[4] * qd[6];
        let x1071 = qd[3] * qd[5];
        let x1277 = x813 - x812;
        let x1278 = x808 + x1277;
        let x1279 = x1278 - x809;
        let x1280 = 2.0 * x1279;
        let x1283 = x798 + x802;
        let x1285 = x803 - x1283;
        let x1286 = x799 + x1285;
        let x1287 = 2.0 * x1286;
        let x1290 = x790 - x794;
        let x1291 = x1290 - x791;
        let x1292 = x795 + x1291;
        let x1293 = 2.0 * x1292;
        let x1314 = 2.0 * x1280;
        let x1316 = 2.0 * x1287;
        let x1318 = 2.0 * x1293;
        let x1558 = x1068 + x1071;
        let x1560 = x1071 - x1558;
        let x1561 = x1068 + x1560;
        let x1562 = 2.0 * x1561;
        let x1565 = x1062 - x1065;
        let x1566 = x1565 - x1062;
        let x1567 = x1065 + x1566;
        let x1568 = 2.0 * x1567;
        let x1569 = 2.0 * x1562;
        let x1570 = 2.0 * x1568;
        let x1571 = x937 * x1314;
        let x1573 = x981 * x1316;
        let x1574 = s[9] * x1569;
        let x1575 = x1573 + x1574;
        let x1577 = x938 * x1318;
        let x1578 = s[8] * x1570;
        let x1579 = x1577 + x1578;
        let x1585 = x936 * x1314;
        let x1587 = x938 * x1316;
        let x1588 = s[8] * x1569;
        let x1589 = x1587 + x1588;
        let x1592 = x981 * x1318;
        let x1593 = s[9] * x1570;
        let x1594 = x1592 + x1593;
        let x1599 = x938 * x1314;
        let x1601 = x936 * x1316;
        let x1602 = s[6] * x1569;
        let x1603 = x1601 + x1602;
        let x1605 = x937 * x1318;
        let x1606 = s[7] * x1570;
        let x1607 = x1605 + x1606;
        let x1613 = x981 * x1314;
        let x1616 = x937 * x1316;
        let x1617 = s[7] * x1569;
        let x1618 = x1616 + x1617;
        let x1620 = x936 * x1318;
        let x1621 = s[6] * x1570;
        let x1622 = x1620 + x1621;
        let x1627 = qd[3] * qd[3];
        let x1628 = qd[4] * qd[4];
        let x1629 = qd[5] * qd[5];
        let x1630 = qd[6] * qd[6];
        let x1631 = x1627 + x1628;
        let x1632 = x1629 + x1631;
        let x1633 = x1630 + x1632;
        let x2747 = s[27] * k[49];
        let x2749 = s[34] - x2747;
        let x2750 = x2749 - s[33];
        let x2751 = 0.5 * x2750;
        let x2752 = s[42] + x2751;
        let x2753 = s[26] * k[49];
        let x2754 = s[30] + x2753;
        let x2755 = s[29] + x2754;
        let x2756 = 0.5 * x2755;
        let x2757 = s[0] * k[50];
        let x2758 = x2756 + x2757;
        let x2760 = s[25] * k[49];
        let x2762 = x2760 - s[32];
        let x2763 = x2762 - s[31];
        let x2764 = 0.5 * x2763;
        let x2765 = s[5] * k[50];
        let x2766 = x2764 + x2765;
        let x2767 = s[22] * k[49];
        let x2770 = s[41] - x2767;
        let x2771 = x2770 - s[40];
        let x2772 = 0.5 * x2771;
        let x2773 = s[35] + x2772;
        let x2774 = s[20] * k[49];
        let x2775 = s[44] + x2774;
        let x2777 = s[43] - x2775;
        let x2778 = 0.5 * x2777;
        let x2779 = s[45] + x2778;
        let x2780 = s[17] * k[49];
        let x2781 = x2780 - s[37];
        let x2782 = x2781 - s[36];
        let x2783 = 0.5 * x2782;
        let x2784 = x2765 + x2783;
        let x2785 = s[14] * k[49];
        let x2786 = s[39] + x2785;
        let x2787 = s[38] + x2786;
        let x2788 = 0.5 * x2787;
        let x2789 = s[1] * k[50];
        let x2790 = x2788 + x2789;
        let x2791 = x1571 * k[48];
        let x2792 = x1575 * k[49];
        let x2793 = x1579 * k[48];
        let x2794 = x2791 + x2792;
        let x2795 = x2793 + x2794;
        let x2796 = 0.5 * x2795;
        let x2797 = x1585 * k[48];
        let x2798 = x1589 * k[49];
        let x2800 = x1594 * k[48];
        let x2801 = x2797 - x2798;
        let x2802 = x2800 + x2801;
        let x2803 = 0.5 * x2802;
        let x2804 = x1599 * k[48];
        let x2805 = x1603 * k[49];
        let x2806 = x1607 * k[48];
        let x2808 = x2804 + x2805;
        let x2809 = x2808 - x2806;
        let x2810 = 0.5 * x2809;
        let x2811 = x1613 * k[48];
        let x2813 = x1618 * k[49];
        let x2814 = x1622 * k[48];
        let x2815 = x2813 - x2811;
        let x2816 = x2814 + x2815;
        let x2817 = 0.5 * x2816;
        let x2818 = x1573 * k[49];
        let x2819 = x1577 * k[48];
        let x2820 = x2791 + x2818;
        let x2821 = x2819 + x2820;
        let x2822 = 0.5 * x2821;
        let x2823 = x2796 + x2822;
        let x2824 = q[3] * k[50];
        let x2825 = x1633 * x2824;
        let x2827 = x2823 - x2825;
        let x2829 = x1587 * k[49];
        let x2830 = x1592 * k[48];
        let x2832 = x2829 - x2797;
        let x2833 = x2832 - x2830;
        let x2834 = 0.5 * x2833;
        let x2836 = x2834 - x2803;
        let x2837 = q[4] * k[50];
        let x2838 = x1633 * x2837;
        let x2840 = x2836 - x2838;
        let x2841 = x1601 * k[49];
        let x2842 = x1605 * k[48];
        let x2843 = x2804 + x2841;
        let x2845 = x2842 - x2843;
        let x2846 = 0.5 * x2845;
        let x2848 = x2846 - x2810;
        let x2849 = q[5] * k[50];
        let x2850 = x1633 * x2849;
        let x2852 = x2848 - x2850;
        let x2853 = x1616 * k[49];
        let x2855 = x1620 * k[48];
        let x2857 = x2811 - x2853;
        let x2858 = x2857 - x2855;
        let x2859 = 0.5 * x2858;
        let x2861 = x2859 - x2817;
        let x2862 = q[6] * k[50];
        let x2863 = x1633 * x2862;
        let x2865 = x2861 - x2863;
        mass[12] = x2752;
        mass[13] = x2758;
        mass[14] = x2766;
        mass[15] = x2773;
        mass[16] = x2779;
        mass[17] = x2784;
        mass[18] = x2790;
        force[0] = 0.0;
        force[1] = -14.715;
        force[2] = 0.0;
        force[3] = x2827;
        force[4] = x2840;
        force[5] = x2852;
        force[6] = x2865;
    }
}
/// `hexapod_twist` with the `exact` formulation.
#[derive(Debug, Clone, Copy, Default)]
pub struct Exact;
impl Mechanism for Exact {
    fn info(&self) -> &'static MechanismInfo {
        &exact::INFO
    }
    fn phi(&self, q: &[f64], t: f64, out: &mut [f64]) {
        phi(&K, q, t, out)
    }
    fn phi_q(&self, q: &[f64], t: f64, out: &mut [f64]) {
        phi_q(&K, q, t, out)
    }
    fn phi_t(&self, q: &[f64], t: f64, out: &mut [f64]) {
        phi_t(&K, q, t, out)
    }
    fn gamma(&self, q: &[f64], qd: &[f64], t: f64, out: &mut [f64]) {
        gamma(&K, q, qd, t, out)
    }
    fn mass(&self, q: &[f64], out: &mut [f64]) {
        exact::mass(&K, q, out)
    }
    fn force(&self, q: &[f64], qd: &[f64], t: f64, out: &mut [f64]) {
        exact::force(&K, q, qd, t, out)
    }
    fn force_jacobian(
        &self,
        q: &[f64],
        qd: &[f64],
        t: f64,
        dq: &mut [f64],
        dqd: &mut [f64],
    ) {
        exact::force_jacobian(&K, q, qd, t, dq, dqd)
    }
    fn potential(&self, q: &[f64]) -> f64 {
        potential(&K, q)
    }
    fn power_nc(&self, q: &[f64], qd: &[f64], t: f64) -> f64 {
        power_nc(&K, q, qd, t)
    }
    fn eval_newton(&self, q: &[f64], qd: &[f64], t: f64, out: NewtonOutputs<'_>) {
        exact::eval_newton(&K, q, qd, t, out.phi, out.phi_q, out.mass, out.force)
    }
    fn eval_kinematics(&self, q: &[f64], qd: &[f64], t: f64, out: KinematicOutputs<'_>) {
        eval_kinematics(&K, q, qd, t, out.phi, out.phi_q, out.phi_t, out.gamma)
    }
}
impl Exact {
    /// This formulation with some run-time parameters (`PARAMETERS`) set, the others
    /// at the file's values; a name or value that is refused changes nothing.
    pub fn with_parameters(set: &[(&str, f64)]) -> Result<ExactAt, ParameterError> {
        Parameters::at(set).map(ExactAt)
    }
}
/// `hexapod_twist` with the `exact` formulation. At run-time parameter values (`Exact::with_parameters`).
#[derive(Debug, Clone)]
pub struct ExactAt(pub Parameters);
impl Mechanism for ExactAt {
    fn info(&self) -> &'static MechanismInfo {
        &exact::INFO
    }
    fn phi(&self, q: &[f64], t: f64, out: &mut [f64]) {
        phi(&self.0.k, q, t, out)
    }
    fn phi_q(&self, q: &[f64], t: f64, out: &mut [f64]) {
        phi_q(&self.0.k, q, t, out)
    }
    fn phi_t(&self, q: &[f64], t: f64, out: &mut [f64]) {
        phi_t(&self.0.k, q, t, out)
    }
    fn gamma(&self, q: &[f64], qd: &[f64], t: f64, out: &mut [f64]) {
        gamma(&self.0.k, q, qd, t, out)
    }
    fn mass(&self, q: &[f64], out: &mut [f64]) {
        exact::mass(&self.0.k, q, out)
    }
    fn force(&self, q: &[f64], qd: &[f64], t: f64, out: &mut [f64]) {
        exact::force(&self.0.k, q, qd, t, out)
    }
    fn force_jacobian(
        &self,
        q: &[f64],
        qd: &[f64],
        t: f64,
        dq: &mut [f64],
        dqd: &mut [f64],
    ) {
        exact::force_jacobian(&self.0.k, q, qd, t, dq, dqd)
    }
    fn potential(&self, q: &[f64]) -> f64 {
        potential(&self.0.k, q)
    }
    fn power_nc(&self, q: &[f64], qd: &[f64], t: f64) -> f64 {
        power_nc(&self.0.k, q, qd, t)
    }
    fn eval_newton(&self, q: &[f64], qd: &[f64], t: f64, out: NewtonOutputs<'_>) {
        exact::eval_newton(&self.0.k, q, qd, t, out.phi, out.phi_q, out.mass, out.force)
    }
    fn eval_kinematics(&self, q: &[f64], qd: &[f64], t: f64, out: KinematicOutputs<'_>) {
        eval_kinematics(&self.0.k, q, qd, t, out.phi, out.phi_q, out.phi_t, out.gamma)
    }
}
/// The formulation listed first in the mechanism file.
pub type DefaultFormulation = Exact;
/// This mechanism in the registries (`symbody_runtime::Registry`).
pub static ENTRY: Entry = Entry {
    name: "hexapod_twist",
    t_end: T_END,
    formulations: &[(Formulation::Exact, &Exact as &(dyn Mechanism + Sync))],
    reduced: None,
    origin: Origin::Compiled {
        file: concat!(
            env!("CARGO_MANIFEST_DIR"), "/../../../", "mechanisms/hexapod_twist.toml"
        ),
        hash: 13001661441132106976u64,
        parameters: &[],
    },
    run_time: Some(&RUN_TIME_ENTRY),
};
