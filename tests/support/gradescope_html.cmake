# What is left of a test's HTML output in results.json (output_format "html") once the grader's
# own markup is taken out: exactly the tags autograder_output.cpp writes (a <pre> of text, a
# caption's <p>, a figure's <img> whose source is a base64 PNG). Every
# text, the student's first of all, is HTML-escaped inside them, so what is left holds no < or >:
# a tag of the student's, or any other tag, would show there.
#   opspace_grader_markup_removed("${output}" rest)
function(opspace_grader_markup_removed text out)
  string(REGEX REPLACE "<img alt=\"[^\"<>]*\" src=\"data:image/png;base64,[A-Za-z0-9+/=]*\">" "" text "${text}")
  foreach(tag pre p)
    string(REPLACE "<${tag}>" "" text "${text}")
    string(REPLACE "</${tag}>" "" text "${text}")
  endforeach()
  set(${out} "${text}" PARENT_SCOPE)
endfunction()
