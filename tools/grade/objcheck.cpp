// The object check (objcheck.h): ELF and ar readers, the rules, and the list of the C and C++
// runtime's names that graded code may use.
#include "objcheck.h"

#include <cxxabi.h>

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <memory>
#include <sstream>
#include <stdexcept>

namespace fs = std::filesystem;

namespace grade {

namespace {

// ---- Reading ELF64 little-endian relocatable objects, every read bounds-checked. ----

std::uint64_t le(const std::string& b, std::uint64_t at, int bytes) {
    if (at > b.size() || std::uint64_t(bytes) > b.size() - at) throw std::runtime_error("truncated ELF file");
    std::uint64_t v = 0;
    for (int i = bytes - 1; i >= 0; --i) v = (v << 8) | static_cast<unsigned char>(b[size_t(at) + size_t(i)]);
    return v;
}

// The NUL-terminated string at `at` of the table [begin, begin + size).
std::string tableString(const std::string& b, std::uint64_t begin, std::uint64_t size, std::uint64_t at) {
    if (begin > b.size() || size > b.size() - begin || at >= size) throw std::runtime_error("a name outside its table");
    const char* p = b.data() + begin + at;
    const size_t n = strnlen(p, size_t(size - at));
    if (n == size - at) throw std::runtime_error("an unterminated name");
    return std::string(p, n);
}

constexpr std::uint32_t kSymtab = 2;
constexpr std::uint64_t kShfWrite = 1, kShfExec = 4;

// A name as graded code may have it: printable ASCII without spaces (what compilers emit).
bool plainSymbol(const std::string& s) {
    return !s.empty() && std::all_of(s.begin(), s.end(), [](char c) { return c > ' ' && c < 127; });
}

std::string readFile(const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    if (!in) throw std::runtime_error("cannot read " + p.string());
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

// ---- What graded code may use of the C and C++ runtime. ----
// Exact names (C functions and the C++ ABI's), then prefixes of a name after "_Z" (C++ names:
// after "_Z", a leading T[VIST] of vtables and typeinfo, N and K are skipped) in which '#'
// stands for a decimal length, then prefixes of C names.

// The C library and the compiler's runtime: math, memory and strings, formatting into memory,
// printing to the terminal (stdout and stderr: a FILE that fopen gives is not here), the C++
// ABI (new and delete are below), threads' locks and once-only calls, time.
const char* const kExact[] = {
    // <math.h> and its float and long double forms are the kMath list below.
    // memory and strings
    "memcpy", "memmove", "memset", "memcmp", "bcmp", "memchr", "strlen", "strnlen", "strcmp", "strncmp", "strcpy",
    "strncpy", "strcat", "strncat", "strchr", "strrchr", "strstr", "strspn", "strcspn", "strpbrk", "strtod", "strtof",
    "strtold", "strtol", "strtoll", "strtoul", "strtoull", "atoi", "atol", "atoll", "atof", "abs", "labs", "llabs",
    "div", "ldiv", "malloc", "calloc", "realloc", "free", "aligned_alloc", "posix_memalign", "qsort", "bsearch", "rand",
    "srand", "snprintf", "vsnprintf", "sprintf", "vsprintf", "sscanf", "__isoc99_sscanf", "__isoc23_sscanf",
    "__isoc23_strtol", "__isoc23_strtoll", "__isoc23_strtoul", "__isoc23_strtoull", "__memcpy_chk", "__memmove_chk",
    "__memset_chk", "__strcpy_chk", "__strncpy_chk", "__strcat_chk", "__strncat_chk", "__snprintf_chk",
    "__vsnprintf_chk", "__sprintf_chk", "__vsprintf_chk", "__errno_location", "__ctype_b_loc", "__ctype_tolower_loc",
    "__ctype_toupper_loc", "tolower", "toupper", "isalpha", "isdigit", "isspace", "isalnum",
    // printing to the terminal
    "printf", "vprintf", "puts", "putchar", "fprintf", "vfprintf", "fputs", "fputc", "putc", "fwrite", "fflush",
    "stdout", "stderr", "__printf_chk", "__fprintf_chk", "__vprintf_chk", "__vfprintf_chk",
    // the C++ ABI, unwinding, stack protection, assert(), thread-local storage
    "__gxx_personality_v0", "_Unwind_Resume", "__dynamic_cast", "__dso_handle", "_GLOBAL_OFFSET_TABLE_",
    "__stack_chk_fail", "__stack_chk_guard", "__assert_fail", "__tls_get_addr", "__libc_single_threaded",
    // threads: locks, once-only calls (std::call_once, the skeleton's PS_TODO), yielding, sleeping
    "pthread_once", "__once_proxy", "pthread_mutex_lock", "pthread_mutex_unlock", "pthread_mutex_trylock",
    "__pthread_key_create", "pthread_self", "pthread_equal", "sched_yield", "nanosleep", "pthread_create",
    "pthread_join", "pthread_detach", "pthread_key_create", "pthread_setspecific", "pthread_getspecific",
    "pthread_mutex_init", "pthread_mutex_destroy", "pthread_cond_wait", "pthread_cond_signal", "pthread_cond_broadcast",
    "pthread_cond_destroy",
    // time
    "clock", "time", "clock_gettime",
    // libgcc's comparisons of 128-bit floats
    "__addtf3", "__subtf3", "__eqtf2", "__netf2", "__lttf2", "__letf2", "__gttf2", "__getf2", "__unordtf2",
    "__cpu_model", "__cpu_indicator_init", "__cpu_features2"};

// C99's <math.h> and <complex.h>, each also with the suffixes f and l; and GNU's sincos, exp10.
const char* const kMath[] = {"acos", "asin", "atan", "atan2", "cos", "sin", "tan", "acosh", "asinh", "atanh", "cosh",
                             "sinh", "tanh", "exp", "exp2", "expm1", "frexp", "ilogb", "ldexp", "log", "log10", "log1p",
                             "log2", "logb", "modf", "scalbn", "scalbln", "cbrt", "fabs", "hypot", "pow", "sqrt", "erf",
                             "erfc", "lgamma", "tgamma", "ceil", "floor", "nearbyint", "rint", "lrint", "llrint",
                             "round", "lround", "llround", "trunc", "fmod", "remainder", "remquo", "copysign", "nan",
                             "nextafter", "nexttoward", "fdim", "fmax", "fmin", "fma", "sincos", "exp10", "__isnan",
                             "__isinf", "__finite", "__signbit", "__fpclassify",
                             // <complex.h>, which std::complex may call
                             "cabs", "carg", "cexp", "clog", "cpow", "csqrt", "csin", "ccos", "ctan", "casin", "cacos",
                             "catan", "csinh", "ccosh", "ctanh", "casinh", "cacosh", "catanh", "cproj"};

// Prefixes of C names: the C++ ABI (exceptions, guards of static locals, destructors at exit),
// OpenMP (the lessons compile with -fopenmp: GCC's libgomp, LLVM's libomp), atomics, libgcc's
// arithmetic.
const char* const kCPrefix[] = {"__cxa_", "GOMP_",  "__kmpc_",  "omp_",    "__atomic_", "__sync_",    "__mul",
                                "__div",  "__udiv", "__umod",   "__mod",   "__pow",     "__popcount", "__clz",
                                "__ctz",  "__ffs",  "__parity", "__bswap", "__ashl",    "__ashr",     "__lshr",
                                "__neg",  "__cmp",  "__ucmp",   "__fix",   "__float",   "__extend",   "__trunc"};

// Prefixes of C++ names (after "_Z", see above, and with the standard library's inline namespace
// taken out: libstdc++'s std::__cxx11, libc++'s std::__1), '#' = a length. operator new and
// delete; the standard library's exceptions and typeinfo; std::string and the containers'
// out-of-line parts; streams to memory and to the terminal (std::cout, std::cerr; no file
// streams, no std::cin); std::thread, locks, clocks, random_device, number conversions. Names
// of libstdc++ (GCC) and of libc++ (clang's -stdlib=libc++), whose internals differ.
const char* const kCxxPrefix[] = {
    "nw", "na", "dl", "da",  // operator new, new[], delete, delete[]
    "Sa",                    // std::allocator (out of line at -O0)
    "St#terminate", "St#__throw_", "St#__once_call", "St#__once_callable", "St#__call_once", "St#uncaught_exception",
    "10__cxxabiv1",  // typeinfo classes
    "St#exception", "St#runtime_error", "St#logic_error", "St#invalid_argument", "St#out_of_range", "St#domain_error",
    "St#range_error", "St#overflow_error", "St#underflow_error", "St#length_error", "St#bad_alloc",
    "St#bad_array_new_length", "St#bad_cast", "St#bad_typeid", "St#bad_function_call", "St#bad_optional_access",
    "St#bad_variant_access", "St#bad_exception", "St#system_error", "St3_V2", "St#error_category", "St#basic_stringIc",
    "Ss",
    // the containers' and smart pointers' out-of-line parts
    "St#_Rb_tree_", "St#__detail#_List_node_base", "St#__detail#_Prime_rehash_policy", "St#_Hash_bytes",
    "St#_Fnv_hash_bytes", "St#__next_prime", "St#__shared_weak_count", "St#__shared_count", "St#__sort",
    // streams: std::ostream (So), istream (Si), iostream (Sd), their bases, string streams, <<, >>, endl
    "So", "Si", "Sd", "St#basic_ostreamIc", "St#basic_istreamIc", "St#basic_iostreamIc", "St#basic_iosIc",
    "St#ios_base", "St#locale", "St#ctypeIcE", "St#basic_streambufIc", "St#basic_stringbufIc",
    "St#basic_ostringstreamIc", "St#basic_istringstreamIc", "St#basic_stringstreamIc", "St#__ostream_insert",
    "St#__istream_extract", "Stls", "Strs", "St#endl", "St#ends", "St#flush", "St#cout", "St#cerr", "St#clog",
    "St#use_facet", "St#has_facet", "Stpl",  // std::operator+ of strings (out of line in libc++)
    // numbers to text and back
    "St#to_chars", "St#from_chars", "St#to_string", "St#sto", "St#__itoa",
    // threads, locks, clocks, random_device
    "St#thread", "St#__thread_struct", "St#__thread_local_data", "St#condition_variable", "St#mutex",
    "St#recursive_mutex", "St#chrono", "St#random_device"};

// s without the leading "_Z" and, after it, the marks of vtables, typeinfo and thunks (with their
// offsets), nested names and const; the standard library's inline namespace (std::__cxx11,
// std::__1) taken out of a leading "St".
std::string cxxCore(const std::string& s) {
    size_t i = 2;
    auto offset = [&] {  // a thunk's call offset: [n]digits '_'
        if (i < s.size() && s[i] == 'n') ++i;
        while (i < s.size() && s[i] >= '0' && s[i] <= '9') ++i;
        if (i < s.size() && s[i] == '_') ++i;
    };
    if (s.size() > i + 1 && s[i] == 'T' && std::strchr("VIST", s[i + 1])) i += 2;
    else if (s.size() > i + 1 && s[i] == 'T' && s[i + 1] == 'h') i += 2, offset();
    else if (s.size() > i + 1 && s[i] == 'T' && s[i + 1] == 'v') i += 2, offset(), offset();
    else if (s.size() > i + 1 && s[i] == 'T' && s[i + 1] == 'c') i += 2, offset(), offset(), offset(), offset();
    if (i < s.size() && s[i] == 'N') ++i;
    while (i < s.size() && (s[i] == 'K' || s[i] == 'V' || s[i] == 'r')) ++i;
    std::string core = s.substr(i);
    for (const char* inlineNamespace : {"St7__cxx11", "St3__1"})
        if (core.rfind(inlineNamespace, 0) == 0) core = "St" + core.substr(std::strlen(inlineNamespace));
    return core;
}

// Whether `s` begins with `pattern`, where '#' in the pattern stands for one or more digits.
bool prefixMatch(const std::string& s, const char* pattern) {
    size_t i = 0;
    for (const char* p = pattern; *p; ++p) {
        if (*p == '#') {
            const size_t from = i;
            while (i < s.size() && s[i] >= '0' && s[i] <= '9') ++i;
            if (i == from) return false;
        } else if (i >= s.size() || s[i++] != *p) return false;
    }
    return true;
}

// Why a name is not allowed, for the message: the kind of thing it is, when it is a common one.
std::string kindOf(const std::string& name) {
    static const std::set<std::string> process = {
        "exit",   "_exit", "_Exit",  "abort",  "quick_exit", "atexit", "at_quick_exit", "fork",
        "vfork",  "clone", "execve", "execv",  "execvp",     "execl",  "execlp",        "system",
        "popen",  "kill",  "raise",  "signal", "sigaction",  "setjmp", "longjmp",       "_setjmp",
        "ptrace", "prctl", "setsid", "pause",  "alarm",      "wait",   "waitpid",       "sleep"};
    static const std::set<std::string> descriptors = {
        "syscall",  "write",   "read",  "open",     "open64",  "openat",     "close",   "dup",
        "dup2",     "dup3",    "pipe",  "pipe2",    "socket",  "socketpair", "connect", "send",
        "sendto",   "sendmsg", "recv",  "recvfrom", "recvmsg", "ioctl",      "fcntl",   "mmap",
        "mprotect", "munmap",  "lseek", "pread",    "pwrite",  "writev",     "readv",   "fdopen"};
    static const std::set<std::string> files = {"fopen",   "fopen64", "freopen", "fread",  "fgets",  "fgetc",  "getc",
                                                "getchar", "scanf",   "fscanf",  "remove", "rename", "unlink", "mkdir",
                                                "opendir", "readdir", "stat",    "getenv", "setenv", "tmpfile"};
    if (process.count(name)) return " (process control)";
    if (descriptors.count(name)) return " (system calls and file descriptors)";
    if (files.count(name) || name.find("fstream") != std::string::npos || name.find("filebuf") != std::string::npos)
        return " (files and the environment)";
    if (name.rfind("dl", 0) == 0) return " (dynamic loading)";
    return "";
}

bool isDoctest(const std::string& name) { return name.find("doctest") != std::string::npos; }

// Names a compiler emits as global definitions in a C++ object that are not C++ names.
// "DW.ref.X": a hidden word that exception tables use to point at X (the personality routine, the
// typeinfo of a caught exception).
// ".gomp_critical_user_...": the lock clang's OpenMP makes for a reduction.
bool compilerHelper(const std::string& name) {
    return name.rfind("DW.ref.", 0) == 0 || name == "__clang_call_terminate" ||
           name.rfind(".gomp_critical_user_", 0) == 0;
}

}  // namespace

ElfObject readElf(const std::string& b) {
    if (b.size() < 64 || b.compare(0, 4,
                                   "\x7f"
                                   "ELF") != 0)
        throw std::runtime_error("not an ELF file");
    if (b[4] != 2 || b[5] != 1) throw std::runtime_error("not a 64-bit little-endian ELF file");
    if (le(b, 16, 2) != 1) throw std::runtime_error("not a relocatable object");
    const std::uint64_t shoff = le(b, 0x28, 8), shentsize = le(b, 0x3a, 2);
    std::uint64_t shnum = le(b, 0x3c, 2), shstrndx = le(b, 0x3e, 2);
    if (shentsize != 64) throw std::runtime_error("unexpected section header size");
    if (shnum == 0 && shoff != 0) shnum = le(b, shoff + 32, 8);  // more than 0xff00 sections
    if (shstrndx == 0xffff) shstrndx = le(b, shoff + 40, 4);
    if (shoff > b.size() || shnum > (b.size() - shoff) / 64 || shstrndx >= shnum)
        throw std::runtime_error("section headers outside the file");
    auto sh = [&](std::uint64_t i, std::uint64_t field, int bytes) { return le(b, shoff + i * 64 + field, bytes); };
    const std::uint64_t strOff = sh(shstrndx, 24, 8), strSize = sh(shstrndx, 32, 8);
    ElfObject o;
    std::uint64_t symtab = 0;
    for (std::uint64_t i = 1; i < shnum; ++i) {
        ElfSection s;
        s.name = tableString(b, strOff, strSize, sh(i, 0, 4));
        s.flags = sh(i, 8, 8);
        o.sections.push_back(s);
        if (sh(i, 4, 4) == kSymtab && symtab == 0) symtab = i;
    }
    if (symtab == 0) return o;
    const std::uint64_t symOff = sh(symtab, 24, 8), symSize = sh(symtab, 32, 8), link = sh(symtab, 40, 4);
    if (link == 0 || link >= shnum) throw std::runtime_error("a symbol table without its names");
    const std::uint64_t namesOff = sh(link, 24, 8), namesSize = sh(link, 32, 8);
    if (symOff > b.size() || symSize > b.size() - symOff) throw std::runtime_error("a symbol table outside the file");
    for (std::uint64_t at = symOff + 24; at + 24 <= symOff + symSize; at += 24) {  // entry 0 is empty
        const unsigned bind = unsigned(le(b, at + 4, 1)) >> 4;
        if (bind != 1 && bind != 2 && bind != 10) continue;  // GLOBAL, WEAK, GNU_UNIQUE
        ElfSymbol s;
        s.name = tableString(b, namesOff, namesSize, le(b, at, 4));
        s.defined = le(b, at + 6, 2) != 0;  // SHN_UNDEF
        s.weak = bind != 1;
        if (!s.name.empty()) o.globals.push_back(s);
    }
    return o;
}

std::vector<ElfObject> readArchive(const std::string& b) {
    if (b.compare(0, 8, "!<arch>\n") != 0) throw std::runtime_error("not an ar archive");
    std::vector<ElfObject> objects;
    for (size_t at = 8; at + 60 <= b.size();) {
        const std::string sizeField = b.substr(at + 48, 10);
        char* end = nullptr;
        const unsigned long long size = std::strtoull(sizeField.c_str(), &end, 10);
        if (end == sizeField.c_str() || size > b.size() - at - 60) throw std::runtime_error("a truncated archive");
        const std::string data = b.substr(at + 60, size_t(size));
        if (data.compare(0, 4,
                         "\x7f"
                         "ELF") == 0)
            objects.push_back(readElf(data));
        at += 60 + size_t(size) + (size & 1);
    }
    return objects;
}

CourseSymbols courseSymbols(const fs::path& tree, const std::string& lesson) {
    const std::string nn = lesson.substr(0, 2);
    // Parsed once per grading: every lesson's test program links most of the same objects.
    static std::map<fs::path, std::vector<ElfObject>> cache;
    auto objects = [&](const fs::path& p) -> const std::vector<ElfObject>& {
        auto it = cache.find(p);
        if (it != cache.end()) return it->second;
        const std::string bytes = readFile(p);
        return cache[p] = p.extension() == ".a" ? readArchive(bytes) : std::vector<ElfObject>{readElf(bytes)};
    };
    auto folder = [&](const fs::path& dir) {
        std::vector<fs::path> files;
        std::error_code ec;
        for (const auto& e : fs::directory_iterator(dir, ec))
            if (e.path().extension() == ".o") files.push_back(e.path());
        std::sort(files.begin(), files.end());
        return files;
    };
    // The rest of the program, and which part of it is the course's callable code.
    std::vector<std::pair<fs::path, bool>> rest;  // (file, callable)
    rest.push_back({tree / "lib" / "framework.a", true});
    rest.push_back({tree / "lib" / "test_support.a", true});
    for (const fs::path& f : folder(tree / "lib" / "main")) rest.push_back({f, false});
    for (const fs::path& f : folder(tree / "lib" / nn / "tests")) rest.push_back({f, false});
    std::error_code ec;
    for (const auto& e : fs::directory_iterator(tree / "lib", ec)) {
        if (!e.is_directory()) continue;
        for (const fs::path& f : folder(e.path() / "plumbing")) rest.push_back({f, true});
        if (e.path().filename() != nn)
            for (const fs::path& f : folder(e.path() / "reference")) rest.push_back({f, true});
    }
    CourseSymbols c;
    std::set<std::string> used;
    for (const auto& [file, callable] : rest)
        for (const ElfObject& o : objects(file))
            for (const ElfSymbol& s : o.globals) {
                if (!s.defined) {
                    used.insert(s.name);
                    continue;
                }
                c.defined[s.name] = c.defined[s.name] || !s.weak;
                if (callable && !isDoctest(s.name)) c.api.insert(s.name);
            }
    for (const std::string& n : used)
        if (!c.defined.count(n)) c.needed.insert(n);
    for (const fs::path& f : folder(tree / "lib" / nn / "reference"))
        for (const ElfObject& o : objects(f))
            for (const ElfSymbol& s : o.globals)
                if (s.defined) c.pieces.insert(s.name);
    return c;
}

bool allowedRuntime(const std::string& name) {
    for (const char* e : kExact)
        if (name == e) return true;
    for (const char* m : kMath)
        for (const char* suffix : {"", "f", "l"})
            if (name == std::string(m) + suffix) return true;
    if (name.rfind("_Z", 0) == 0) {
        const std::string core = cxxCore(name);
        // typeinfo of a fundamental type or a pointer to one (a thrown int, a const char*)
        if ((name.rfind("_ZTI", 0) == 0 || name.rfind("_ZTS", 0) == 0) && !core.empty() &&
            core.find_first_not_of("PK") == core.size() - 1 && core.back() >= 'a' && core.back() <= 'z')
            return true;
        for (const char* p : kCxxPrefix)
            if (prefixMatch(core, p)) return true;
        return false;
    }
    for (const char* p : kCPrefix)
        if (name.rfind(p, 0) == 0 && name.size() > std::strlen(p) &&
            std::all_of(name.begin() + std::strlen(p), name.end(),
                        [](char c) { return (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '_'; }))
            return true;
    return false;
}

std::string demangle(const std::string& name) {
    std::string shown = name;
    if (name.rfind("_Z", 0) == 0 && name.size() < 4096) {
        int status = 0;
        std::unique_ptr<char, void (*)(void*)> d(abi::__cxa_demangle(name.c_str(), nullptr, nullptr, &status),
                                                 std::free);
        if (status == 0 && d) shown = d.get();
    }
    if (shown.size() > 200) shown = shown.substr(0, 200) + "...";
    return shown;
}

std::vector<Finding> checkObjects(const std::vector<std::pair<std::string, ElfObject>>& objects,
                                  const CourseSymbols& course) {
    std::vector<Finding> out;
    std::set<std::string> own;  // what the submission's objects define
    for (const auto& [file, o] : objects)
        for (const ElfSymbol& s : o.globals)
            if (s.defined) own.insert(s.name);
    for (const auto& object : objects) {
        const std::string& file = object.first;
        const ElfObject& o = object.second;
        std::set<std::string> said;  // one finding per name and file
        auto find = [&](const std::string& name, const std::string& what) {
            if (said.insert(name).second) out.push_back({file, what});
        };
        for (const ElfSection& s : o.sections) {
            const std::string& n = s.name;
            if (!plainSymbol(n)) find("section " + n, "has a section whose name has unusual characters");
            else if (n.rfind(".preinit_array", 0) == 0 || n == ".init" || n == ".fini" || n.rfind(".ctors", 0) == 0 ||
                     n.rfind(".dtors", 0) == 0)
                find("section " + n, "has a section " + n + " (code that would run before the test harness)");
            else if ((s.flags & kShfWrite) && (s.flags & kShfExec))
                find("section " + n, "has a section " + n + " that is both writable and executable");
        }
        for (const ElfSymbol& s : o.globals) {
            const std::string& n = s.name;
            const std::string shown = "'" + demangle(n) + "'";
            if (!plainSymbol(n)) {
                find(n, "has a symbol whose name has unusual characters");
            } else if (isDoctest(n) || n.find("gradechannel") != std::string::npos) {
                find(n, std::string(s.defined ? "defines " : "uses ") + shown +
                            ", part of the test framework: graded code may not touch it");
            } else if (s.defined) {
                // a piece of the lesson (or a copy the reference has too), or a compiler's helper
                if (course.pieces.count(n) || compilerHelper(n)) continue;
                auto d = course.defined.find(n);
                if (n.rfind("_Z", 0) != 0)
                    find(n,
                         "defines " + shown + " with C linkage (extern \"C\"): graded code may define only C++ names");
                else if (d != course.defined.end() && (!s.weak || d->second))
                    find(n, "defines " + shown + ", which the course's code defines: a graded file may not replace it");
                else if (d == course.defined.end() && course.needed.count(n))
                    find(n, "defines " + shown +
                                ", which the test program takes from a library: a graded file may not replace it");
            } else if (!own.count(n) && !course.pieces.count(n) && !course.api.count(n) && !allowedRuntime(n)) {
                find(n, "uses " + shown + kindOf(demangle(n)) + ", which graded code may not use");
            }
        }
    }
    return out;
}

std::vector<Finding> checkDisassembly(const std::string& text) {
    std::vector<Finding> out;
    std::string file, section;
    std::set<std::uint64_t> starts;                              // instruction starts in this section
    std::uint64_t sectionEnd = 0;                                // the end of its last instruction
    std::vector<std::pair<std::uint64_t, std::string>> targets;  // direct branch targets, with the branch
    std::set<std::string> said;
    auto find = [&](const std::string& what) {
        if (!file.empty() && said.insert(file + what).second && out.size() < 100) out.push_back({file, what});
    };
    auto endSection = [&] {
        for (const auto& [t, insn] : targets)
            if (!starts.count(t) && t != sectionEnd)
                find("jumps into the middle of an instruction ('" + insn + "' in " + section +
                     "): machine code written to hide what it does");
        starts.clear();
        targets.clear();
        sectionEnd = 0;
    };
    static const std::set<std::string> prefixes = {
        "lock", "rep", "repz", "repe", "repnz", "repne", "data16",  "data32", "addr16",   "addr32",
        "cs",   "ds",  "es",   "ss",   "fs",    "gs",    "notrack", "bnd",    "xacquire", "xrelease"};
    static const std::set<std::string> forbidden = {"syscall", "sysenter", "sysexit", "sysret",
                                                    "int",     "svc",      "hvc",     "smc"};
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);) {
        if (line.empty()) continue;
        const std::string fileFormat = ":     file format ";
        if (line[0] != ' ' && line.find(fileFormat) != std::string::npos) {
            endSection();
            file = line.substr(0, line.find(fileFormat));
            // "rays.o" (the grader's build) or "rays.cpp.o" (CMake's): "rays.cpp"
            if (file.size() > 6 && file.compare(file.size() - 6, 6, ".cpp.o") == 0) file.resize(file.size() - 2);
            else if (file.size() > 2 && file.compare(file.size() - 2, 2, ".o") == 0)
                file.replace(file.size() - 2, 2, ".cpp");
            continue;
        }
        if (line.rfind("Disassembly of section ", 0) == 0) {
            endSection();
            section = line.substr(23, line.size() > 24 ? line.size() - 24 : 0);
            continue;
        }
        if (line[0] != ' ') continue;  // "0000000000000000 <name>:" and the like
        // "  1f:\t48 89 f8             \tmov    %rdi,%rax"
        const size_t colon = line.find(":\t");
        if (colon == std::string::npos) continue;
        const std::string addrText = line.substr(line.find_first_not_of(' '), colon - line.find_first_not_of(' '));
        char* end = nullptr;
        const std::uint64_t addr = std::strtoull(addrText.c_str(), &end, 16);
        if (addrText.empty() || *end != '\0') continue;
        const size_t tab = line.find('\t', colon + 2);
        const std::string bytes =
            line.substr(colon + 2, tab == std::string::npos ? std::string::npos : tab - colon - 2);
        std::uint64_t length = 0;
        for (size_t i = 0; i + 1 < bytes.size(); ++i)
            if (std::isxdigit(static_cast<unsigned char>(bytes[i])) &&
                std::isxdigit(static_cast<unsigned char>(bytes[i + 1])))
                ++length, ++i;
        starts.insert(addr);
        sectionEnd = std::max(sectionEnd, addr + length);
        if (tab == std::string::npos) continue;
        std::string insn = line.substr(tab + 1);
        insn = insn.substr(0, insn.find('#'));  // objdump's comment: "# 1d <name+0x1d>"
        std::istringstream words(insn);
        std::string word, mnemonic, operand;
        while (words >> word) {
            if (prefixes.count(word) || word.rfind("rex", 0) == 0 || word[0] == '{') continue;
            mnemonic = word;
            words >> operand;
            break;
        }
        if (mnemonic.empty()) continue;
        if (mnemonic == "(bad)") find("holds bytes that are no instruction (in " + section + ")");
        else if (forbidden.count(mnemonic))
            find("holds a system-call instruction ('" + mnemonic + (operand.empty() ? "" : " " + operand) + "' in " +
                 section + ")");
        else if ((mnemonic[0] == 'j' || mnemonic.rfind("call", 0) == 0 || mnemonic.rfind("loop", 0) == 0 ||
                  mnemonic == "xbegin") &&
                 !operand.empty() && std::isxdigit(static_cast<unsigned char>(operand[0]))) {
            const std::uint64_t target = std::strtoull(operand.c_str(), &end, 16);
            if (*end == '\0') targets.push_back({target, mnemonic + " " + operand});
        }
    }
    endSection();
    return out;
}

}  // namespace grade
