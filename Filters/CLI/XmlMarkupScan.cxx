// SPDX-License-Identifier: BSD-3-Clause
#include "XmlMarkupScan.h"

#include <cstdint>
#include <cstring>
#include <fstream>
#include <vector>

namespace meshfiles
{
namespace
{
/// A file's bytes one at a time, read in blocks, with the offset of the next one.
class ByteStream
{
public:
  explicit ByteStream(const std::string& path)
    : In(path, std::ios::binary)
    , Buffer(1 << 16)
  {
  }

  /// The next byte, or -1 at the end of the file.
  int Next()
  {
    if (this->At == this->End)
    {
      this->In.read(this->Buffer.data(), static_cast<std::streamsize>(this->Buffer.size()));
      this->At = 0;
      this->End = static_cast<std::size_t>(this->In.gcount());
      if (this->End == 0)
      {
        return -1;
      }
    }
    ++this->Offset;
    return static_cast<unsigned char>(this->Buffer[this->At++]);
  }

  std::uintmax_t Offset = 0; // of the next byte

private:
  std::ifstream In;
  std::vector<char> Buffer;
  std::size_t At = 0, End = 0;
};

/// What one token told: how it ended, and for a start tag its name and whether it closed itself.
struct Token
{
  enum Kind
  {
    Other, // comment, CDATA, processing instruction, declaration
    Start,
    End,
  } Type = Other;
  std::string Name;
  bool SelfClosing = false;
  bool Complete = false; // false: the file ended inside it
};

class MarkupScanner
{
public:
  explicit MarkupScanner(const std::string& path)
    : Bytes(path)
  {
  }

  std::string Run()
  {
    for (int c = this->Bytes.Next(); c >= 0; c = this->Bytes.Next())
    {
      if (c != '<')
      {
        continue;
      }
      this->TokenStart = this->Bytes.Offset - 1;
      Token token;
      std::string problem = this->ReadToken(token);
      if (!problem.empty() || !token.Complete)
      {
        return problem;
      }
      if (token.Type == Token::Start && !token.SelfClosing)
      {
        if (token.Name == "AppendedData")
        {
          return ""; // raw or base64 data up to the end, which no XML parser reads
        }
        if (++this->Depth > MaximumXmlDepth)
        {
          return this->Where() + "elements nest deeper than " + std::to_string(MaximumXmlDepth);
        }
      }
      this->Depth -= token.Type == Token::End;
    }
    return "";
  }

private:
  std::string Where() const { return "byte " + std::to_string(this->TokenStart) + ": "; }

  /// The next byte of the current token; -1 at the end of the file, -2 past the length limit.
  int NextInToken()
  {
    const int c = this->Bytes.Next();
    return c >= 0 && this->Bytes.Offset - this->TokenStart > MaximumXmlToken ? -2 : c;
  }

  std::string TooLong() const
  {
    return this->Where() + "a markup token longer than " +
      std::to_string(MaximumXmlToken / 1024) + " KiB (XML parsers take minutes on such)";
  }

  /// The token after its '<', by the bytes that open it.
  std::string ReadToken(Token& token)
  {
    int c = this->NextInToken();
    if (c == '!')
    {
      return this->ReadDeclaration(token);
    }
    if (c == '?')
    {
      return this->SkipPast("?>", token);
    }
    if (c == '/')
    {
      token.Type = Token::End;
      return this->SkipPast(">", token);
    }
    token.Type = Token::Start;
    return this->ReadStartTag(c, token);
  }

  /// After "<!": a comment, a CDATA section, or another declaration; DOCTYPE is refused.
  std::string ReadDeclaration(Token& token)
  {
    std::string opening;
    for (int c = 0; opening.size() < 7 && opening != "--" && (c = this->NextInToken()) >= 0;)
    {
      opening += static_cast<char>(c);
      if (opening == "DOCTYPE")
      {
        return this->Where() + "a document type declaration (VTK files have none)";
      }
    }
    if (opening == "--")
    {
      return this->SkipPast("-->", token);
    }
    return this->SkipPast(opening == "[CDATA[" ? "]]>" : ">", token);
  }

  /// Bytes up to and including closing.
  std::string SkipPast(const char* closing, Token& token)
  {
    const std::size_t length = std::strlen(closing);
    std::string last;
    for (int c = this->NextInToken(); c != -1; c = this->NextInToken())
    {
      if (c == -2)
      {
        return this->TooLong();
      }
      last = (last + static_cast<char>(c)).substr(last.size() + 1 > length ? 1 : 0);
      if (last == closing)
      {
        token.Complete = true;
        return "";
      }
    }
    return "";
  }

  /// A start tag from its first name byte c: the name, then attributes up to a '>' outside
  /// quotes.
  std::string ReadStartTag(int c, Token& token)
  {
    char quote = 0, previous = 0;
    bool inName = true;
    for (; c != -1; previous = static_cast<char>(c), c = this->NextInToken())
    {
      if (c == -2)
      {
        return this->TooLong();
      }
      inName = inName && c != '>' && c != '/' && !std::strchr(" \t\r\n", c);
      if (inName)
      {
        token.Name += static_cast<char>(c);
      }
      else if (quote == 0 && (c == '"' || c == '\''))
      {
        quote = static_cast<char>(c);
      }
      else if (c == quote)
      {
        quote = 0;
      }
      else if (quote == 0 && c == '>')
      {
        token.SelfClosing = previous == '/';
        token.Complete = true;
        return "";
      }
    }
    return "";
  }

  ByteStream Bytes;
  std::uintmax_t TokenStart = 0;
  int Depth = 0;
};
}

std::string ScanXmlMarkup(const std::string& path)
{
  return MarkupScanner(path).Run();
}

} // namespace meshfiles
