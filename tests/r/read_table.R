# An analysis API table read as an R user reads it: httr2 asks with the
# token (HRI_TOKEN), readr reads the CSV and guesses each column's type.
# Prints each column's name and class, then "--", then the column named by
# the second argument, one value a line.
library(httr2)
library(readr)

args <- commandArgs(trailingOnly = TRUE)
body <- request(args[1]) |>
  req_auth_bearer_token(Sys.getenv("HRI_TOKEN")) |>
  req_perform() |>
  resp_body_string()
table <- read_csv(I(body), show_col_types = FALSE)
for (column in names(table)) cat(column, "\t", class(table[[column]])[1], "\n", sep = "")
cat("--\n")
writeLines(as.character(table[[args[2]]]))
