// Writes the command-line tool's web page (viewer_page.h) with the three.js scripts of a given
// directory, for the test of how the page inlines them (check_viewer_page.py):
//   page_probe THREE_DIRECTORY OUT.html
// The model is a few bytes, not a glb: the test reads the page, it does not show it.

#include "viewer_page.h"

#include <iostream>
#include <string>
#include <vector>

int main(int argc, char** argv)
{
  if(argc != 3)
  {
    std::cerr << "usage: page_probe THREE_DIRECTORY OUT.html\n";
    return 2;
  }
  if(const auto problem = np_examples::viewer_scripts_problem(argv[1]))
  {
    std::cerr << *problem << '\n';
    return 1;
  }
  const std::vector<unsigned char> model = {'g', 'l', 'T', 'F', '<', '/', '>'};
  return np_examples::write_viewer_page(argv[2], "a <title> & more", model, argv[1]) ? 0 : 1;
}
