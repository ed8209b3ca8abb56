// NIST StRD linear-regression sets for the polyfit exercise, embedded verbatim (the same files as
// fitting/data/nist/*.dat, from https://www.itl.nist.gov/div898/strd/lls/lls.shtml) so the checker
// works wherever numlab is installed. Read with numlab's own NIST parser.

#include "exercises/nist_polynomial_sets.hpp"

#include "numlab/fitting/data_set.hpp"

namespace numlab::exercises {

namespace {
constexpr const char* norris_dat = R"nist(NIST/ITL StRD
Dataset Name:  Norris (Norris.dat)

File Format:   ASCII
               Certified Values  (lines 31 to 46)
               Data              (lines 61 to 96)

Procedure:     Linear Least Squares Regression

Reference:     Norris, J., NIST.
               Calibration of Ozone Monitors.

Data:          1 Response Variable (y)
               1 Predictor Variable (x)
               36 Observations
               Lower Level of Difficulty
               Observed Data

Model:         Linear Class
               2 Parameters (B0,B1)

               y = B0 + B1*x + e



               Certified Regression Statistics

                                          Standard Deviation
     Parameter          Estimate             of Estimate

        B0        -0.262323073774029     0.232818234301152
        B1         1.00211681802045      0.429796848199937E-03

     Residual
     Standard Deviation   0.884796396144373

     R-Squared            0.999993745883712


               Certified Analysis of Variance Table

Source of Degrees of    Sums of             Mean
Variation  Freedom      Squares            Squares           F Statistic

Regression    1     4255954.13232369   4255954.13232369   5436385.54079785
Residual     34     26.6173985294224   0.782864662630069













Data:       y          x
           0.1        0.2
         338.8      337.4
         118.1      118.2
         888.0      884.6
           9.2       10.1
         228.1      226.5
         668.5      666.3
         998.5      996.3
         449.1      448.6
         778.9      777.0
         559.2      558.2
           0.3        0.4
           0.1        0.6
         778.1      775.5
         668.8      666.9
         339.3      338.0
         448.9      447.5
          10.8       11.6
         557.7      556.0
         228.3      228.1
         998.0      995.8
         888.8      887.6
         119.6      120.2
           0.3        0.3
           0.6        0.3
         557.6      556.8
         339.3      339.1
         888.0      887.2
         998.5      999.0
         778.9      779.0
          10.2       11.1
         117.6      118.3
         228.9      229.2
         668.4      669.1
         449.2      448.9
           0.2        0.5

)nist";
constexpr const char* pontius_dat = R"nist(NIST/ITL StRD
Dataset Name:  Pontius

File Format:   ASCII
               Certified Values  (lines 31 to 47)
               Data              (lines 61 to 100)

Procedure:     Linear Least Squares Regression

Reference:     Pontius, P., NIST. 
               Load Cell Calibration.

Data:          1 Response Variable (y)
               1 Predictor Variable (x)
               40 Observations
               Lower Level of Difficulty
               Observed Data

Model:         Quadratic Class
               3 Parameters (B0,B1,B2)
               y = B0 + B1*x + B2*(x**2)




               Certified Regression Statistics

                                          Standard Deviation
     Parameter          Estimate             of Estimate

        B0      0.673565789473684E-03    0.107938612033077E-03
        B1      0.732059160401003E-06    0.157817399981659E-09
        B2     -0.316081871345029E-14    0.486652849992036E-16                

     Residual
     Standard Deviation   0.205177424076185E-03     

     R-Squared            0.999999900178537


               Certified Analysis of Variance Table

Source of Degrees of     Sums of               Mean   
Variation  Freedom       Squares              Squares             F Statistic

Regression    2     15.6040343244198      7.80201716220991      185330865.995752
Residual     37     0.155761768796992E-05 0.420977753505385E-07          












Data:       y             x
         .11019        150000
         .21956        300000
         .32949        450000
         .43899        600000
         .54803        750000
         .65694        900000
         .76562       1050000
         .87487       1200000
         .98292       1350000
        1.09146       1500000
        1.20001       1650000
        1.30822       1800000
        1.41599       1950000
        1.52399       2100000
        1.63194       2250000
        1.73947       2400000
        1.84646       2550000
        1.95392       2700000
        2.06128       2850000
        2.16844       3000000
         .11052        150000
         .22018        300000
         .32939        450000
         .43886        600000
         .54798        750000
         .65739        900000
         .76596       1050000
         .87474       1200000
         .98300       1350000
        1.09150       1500000
        1.20004       1650000
        1.30818       1800000
        1.41613       1950000
        1.52408       2100000
        1.63159       2250000
        1.73965       2400000
        1.84696       2550000
        1.95445       2700000
        2.06177       2850000
        2.16829       3000000
)nist";
constexpr const char* wampler1_dat = R"nist(NIST/ITL StRD
Dataset Name:  Wampler1 (Wampler1.dat)

File Format:   ASCII
               Certified Values  (lines 31 to 50)
               Data              (lines 61 to 81)

Procedure:     Linear Least Squares Regression

Reference:     Wampler, R. H. (1970). 
               A Report of the Accuracy of Some Widely-Used Least 
               Squares Computer Programs. 
               Journal of the American Statistical Association, 65, pp. 549-565.
           
Data:          1 Response Variable (y)
               1 Predictor Variable (x)
               21 Observations
               Higher Level of Difficulty
               Generated Data

Model:         Polynomial Class
               6 Parameters (B0,B1,...,B5)

               y = B0 + B1*x + B2*(x**2) + B3*(x**3)+ B4*(x**4) + B5*(x**5)

               Certified Regression Statistics

                                          Standard Deviation
     Parameter        Estimate               of Estimate

        B0        1.00000000000000        0.000000000000000
        B1        1.00000000000000        0.000000000000000
        B2        1.00000000000000        0.000000000000000
        B3        1.00000000000000        0.000000000000000
        B4        1.00000000000000        0.000000000000000
        B5        1.00000000000000        0.000000000000000

     Residual
     Standard Deviation   0.000000000000000

     R-Squared            1.00000000000000


               Certified Analysis of Variance Table

Source of Degrees of     Sums of               Mean  
Variation  Freedom       Squares              Squares           F Statistic
              
Regression    5      18814317208116.7     3762863441623.33       Infinity
Residual     15      0.000000000000000    0.000000000000000
              








Data:            y     x
                 1     0
                 6     1
                63     2
               364     3
              1365     4
              3906     5
              9331     6
             19608     7
             37449     8
             66430     9
            111111    10
            177156    11
            271453    12
            402234    13
            579195    14
            813616    15
           1118481    16
           1508598    17
           2000719    18
           2613660    19
           3368421    20
)nist";
constexpr const char* wampler4_dat = R"nist(NIST/ITL StRD
Dataset Name:  Wampler4 (Wampler4.dat)

File Format:   ASCII
               Certified Values  (lines 31 to 50)
               Data              (lines 61 to 81)

Procedure:     Linear Least Squares Regression

Reference:     Wampler, R. H. (1970).
               A Report of the Accuracy of Some Widely-Used Least
               Squares Computer Programs.
               Journal of the American Statistical Association, 65, pp. 549-565.

Data:          1 Response Variable (y)
               1 Predictor Variable (x)
               21 Observations
               Higher Level of Difficulty
               Generated Data

Model:         Polynomial Class
               6 Parameters (B0,B1,...,B5)

               y = B0 + B1*x + B2*(x**2) + B3*(x**3)+ B4*(x**4) + B5*(x**5)

              Certified Regression Statistics

                                          Standard Deviation
     Parameter          Estimate             of Estimate

        B0        1.00000000000000         215232.624678170
        B1        1.00000000000000         236355.173469681
        B2        1.00000000000000         77934.3524331583
        B3        1.00000000000000         10147.5507550350
        B4        1.00000000000000         564.566512170752
        B5        1.00000000000000         11.2324854679312

     Residual
     Standard Deviation   236014.502379268

     R-Squared            0.957478440825662


               Certified Analysis of Variance Table

Source of Degrees of     Sums of                Mean
Variation  Freedom       Squares               Squares          F Statistic

Regression    5      18814317208116.7      3762863441623.33   67.5524458240122
Residual     15      835542680000.000      55702845333.3333









Data:            y     x
              75901    0
            -204794    1
             204863    2
            -204436    3
             253665    4
            -200894    5
             214131    6
            -185192    7
             221249    8
            -138370    9
             315911   10
             -27644   11
             455253   12
             197434   13
             783995   14
             608816   15
            1370781   16
            1303798   17
            2205519   18
            2408860   19
            3444321   20
)nist";
constexpr const char* wampler5_dat = R"nist(NIST/ITL StRD
Dataset Name:  Wampler5 (Wampler5.dat)

File Format:   ASCII
               Certified Values  (lines 31 to 50)
               Data              (lines 61 to 81)

Procedure:     Linear Least Squares Regression

Reference:     Wampler, R. H. (1970).
               A Report of the Accuracy of Some Widely-Used Least
               Squares Computer Programs.
               Journal of the American Statistical Association, 65, pp. 549-565.

Data:          1 Response Variable (y)
               1 Predictor Variable (x)
               21 Observations
               Higher Level of Difficulty
               Generated Data

Model:         Polynomial Class
               6 Parameters (B0,B1,...,B5)

               y = B0 + B1*x + B2*(x**2) + B3*(x**3)+ B4*(x**4) + B5*(x**5)

               Certified Regression Statistics

                                          Standard Deviation
     Parameter          Estimate             of Estimate

        B0        1.00000000000000         21523262.4678170
        B1        1.00000000000000         23635517.3469681
        B2        1.00000000000000         7793435.24331583
        B3        1.00000000000000         1014755.07550350
        B4        1.00000000000000         56456.6512170752
        B5        1.00000000000000         1123.24854679312

     Residual
     Standard Deviation   23601450.2379268

     R-Squared            0.224668921574940E-02


               Certified Analysis of Variance Table

Source of Degrees of    Sums of               Mean
Variation  Freedom      Squares              Squares           F Statistic

Regression    5    18814317208116.7      3762863441623.33 6.7552445824012241E-03
Residual     15    0.835542680000000E+16 557028453333333.









Data:            y     x
             7590001     0
           -20479994     1
            20480063     2
           -20479636     3
            25231365     4
           -20476094     5
            20489331     6
           -20460392     7
            18417449     8
           -20413570     9
            20591111    10
           -20302844    11
            18651453    12
           -20077766    13
            21059195    14
           -19666384    15
            26348481    16
           -18971402    17
            22480719    18
           -17866340    19
            10958421    20
)nist";
}  // namespace

std::vector<fitting::DataSet> nist_polynomial_sets() {
  std::vector<fitting::DataSet> sets;
  sets.push_back(fitting::parse_nist_data(norris_dat, "Norris"));
  sets.push_back(fitting::parse_nist_data(pontius_dat, "Pontius"));
  sets.push_back(fitting::parse_nist_data(wampler1_dat, "Wampler1"));
  sets.push_back(fitting::parse_nist_data(wampler4_dat, "Wampler4"));
  sets.push_back(fitting::parse_nist_data(wampler5_dat, "Wampler5"));
  return sets;
}

}  // namespace numlab::exercises
