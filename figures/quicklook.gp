# Quick look at one `springblock run --series FILE` output: mu(t) and the sliding count.
# Called by quicklook.sh, which sets: file (TSV), out (PNG path or ''), term ('png' or 'dumb').
if (term eq 'png') {
    set terminal pngcairo size 900,560 font ",10"
    set output out
} else {
    set terminal dumb size 110,34
}
set datafile separator "\t"
set datafile commentschars "#"
# The first non-comment line is the column header t_s mu mu_signed n_sliding.
set key autotitle columnhead
set multiplot layout 2,1 title file noenhanced
set ylabel "mu(t)"
unset xlabel
plot file using ($1*1e3):2 with lines lw 1 title "mu", \
     file using ($1*1e3):3 with lines lw 1 dt 2 title "mu signed"
set ylabel "sliding blocks"
set xlabel "time (ms)"
plot file using ($1*1e3):4 with lines lw 1 title "n sliding"
unset multiplot
