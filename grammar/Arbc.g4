// The arbc behaviour spec language (docs/language.md describes it).
//
// Notes for the next engineer:
// - Type names (bool, int, float, string, vec3, list) are ordinary identifiers here; semantic
//   analysis resolves them, so `string` can still name a record field.
// - Else-if chains are a loop, not recursion, so a long chain cannot exhaust the parser's stack.
// - Nesting depth (brackets, prefix operators) is bounded on the token stream before parsing
//   (compiler/frontend/nesting.cc): the generated recursive descent never sees deeper input.
// - BAD_NUMBER, UNTERMINATED_STRING, UNTERMINATED_COMMENT and ERROR_CHAR exist only so the
//   front end can name lexical mistakes in words; the parser never expects them.
grammar Arbc;

spec : decl* EOF ;

// One top-level declaration; also the unit of error recovery (one syntax error per declaration).
declOnly : decl EOF ;

decl
  : appDecl
  | useDecl
  | typeDecl
  | constDecl
  | moduleDecl
  | eventDecl
  | derivedEventDecl
  | lockEventDecl
  | statusEventsDecl
  | exclusiveDecl
  | invariantDecl
  | neverDecl
  | onlyAfterDecl
  | assumeDecl
  | responseDecl
  | stableDecl
  | givenDecl
  | arbitrateDecl
  | connectDecl
  | assertDecl
  | resourceDecl
  | testDecl
  | testsForDecl
  ;

appDecl          : 'app' ID STRING? ';' ;
// A message type read from its definition (docs/language.md#ros-2-messages):
// `use ros2 geometry_msgs/msg/TwistStamped;` (sema checks the word `ros2`; `pkg/Name` also).
useDecl          : 'use' ID msgName ';' ;
msgName          : ID '/' ID ('/' ID)? ;
typeDecl         : 'type' ID '=' typeExpr ';' ;
constDecl        : 'const' ID '=' expr ';' ;
moduleDecl       : 'module' ID STRING? '{' portDecl* '}' ;
portDecl         : direction=('in' | 'out') ID ':' typeExpr ';' ;
eventDecl        : 'event' ID (',' ID)* ('lifetime' duration)? ';' ;
derivedEventDecl : 'event' ID '=' portRef ':' expr ('for' duration)? failOpen? ';' ;
// A lock (docs/language.md#locks): `event estop = lock EStop.engaged [: PRED] [timeout D];`.
// `lock` and `timeout` are read as IDs and checked by the AST builder (no new keyword, so no
// name users chose becomes one: a port may be called `lock`).
lockEventDecl    : 'event' ID '=' ID portRef (':' expr)? (ID duration)? failOpen? ';' ;
statusEventsDecl : 'events' 'from' portRef '{' statusEntry (',' statusEntry)* ','? '}'
                   ('lifetime' duration)? failOpen? ';' ;
// A feed that may never speak (docs/language.md#a-feed-that-may-fail-open): after a start, its
// events count as absent once it has been silent this long. The word is `absent` (sema checks
// it: no new keyword, so no name users chose becomes one).
failOpen         : 'otherwise' ID 'after' duration ;
statusEntry      : ID ('=' STRING)? ;
exclusiveDecl    : 'exclusive' '{' ID (',' ID)* ','? '}' ';' ;
invariantDecl    : 'invariant' expr ';' ;
// Properties over time (docs/language.md#properties-over-time): spacing
// `never two take within 1s;` and `never search within 1s after track;`, absence
// `never search while act_track;`, precedence `only put after take;`.
neverDecl        : 'never' ('two' ID 'within' duration | ID ('within' duration 'after' ID | 'while' ID))
                   ';' ;
onlyAfterDecl    : 'only' ID 'after' ID ';' ;
// An environment assumption (docs/language.md#environment-assumptions): the feeds make EVENT
// present only after a delivery of the first rule and, with `until`, absent after a delivery of
// the second until the first delivers again: `assume e_taken only after take until put;`; or
// they keep EVENT absent for D after each delivery of the rule:
// `assume not e_arm_idle for 1s after take;`.
assumeDecl       : 'assume' (ID 'only' 'after' ID ('until' ID)? | 'not' ID 'for' duration 'after' ID)
                   ';' ;
// Response `after track stops, search within 1.2s while e_unreachable;` (RULE delivers within D
// of each delivery of the trigger, or of its last one with `stops`, while the condition holds).
// The trigger may be an event (its becoming present in the port's container) and the answer a
// port (any of its rules delivers): `after e_link_lost, Base.cmd within 200ms;`.
responseDecl     : 'after' ID stops='stops'? ',' (ID | served=portRef) 'within' duration
                   ('while' expr)? ';' ;
// Stability `stable HeadControl.gaze for 500ms;`: the port's deliverer changes at most once per D.
stableDecl       : 'stable' portRef 'for' duration ';' ;
// An environment rate: `given LookAround.gaze every 200ms;` (the source publishes at least
// every D from the start), which response properties rely on.
givenDecl        : 'given' portRef 'every' duration ';' ;
arbitrateDecl    : 'arbitrate' portRef (byPriority='by' 'priority')? isComplete='complete'? '{' ruleDecl* '}' ;
ruleDecl         : ID ':' 'from' portRef ('when' expr)? ('hold' duration)? onDelivery? (block | ';') ;
// What the runtime does to the port's events each time the rule delivers, after the decision
// (docs/language.md#events-set-on-delivery): `then set e_owns`, `then unset e_owns`.
onDelivery       : 'then' deliveryEffect (',' deliveryEffect)* ;
deliveryEffect   : op=('set' | 'unset') ID ;
connectDecl      : 'connect' portRef '->' portRef (block | ';') ;
assertDecl       : 'assert' portRef ':' ID '->' expr ';' ;
// A resource shared by several ports: at most one of them receives a command that uses it.
resourceDecl     : 'resource' ID '{' portRef (',' portRef)* ','? '}' ('when' expr)? ';' ;

// `arbc test` (docs/testing.md): timed inputs and expectations, checked by the front end and
// run on the embedded runtime in simulated time. Not part of the app: lowering ignores them.
testDecl : 'test' STRING ('on' ID)? '{' testStep* '}' ;
// A tests file: `tests for "app.spec";` then only `test` declarations, checked against that app.
testsForDecl : 'tests' 'for' STRING ';' ;
testStep
  : 'at' duration portRef '<-' expr ';'                                  # testInput
  | 'at' duration op=('set' | 'unset') ID ';'                            # testEvent
  | 'expect' portRef 'receives' (nothing='nothing' | expr)? testWindow? ';' # expectReceives
  | 'expect' ID 'drops' STRING? testWindow? ';'                          # expectDrops
  | 'expect' ID 'delivers' nothing='nothing'? testWindow? ';'            # expectDelivers
  | 'expect' (neverDecl | onlyAfterDecl | responseDecl | stableDecl)     # expectProperty
  // A claim about single decisions, judged on the run as the runtime checks judge it
  // (runtime/decision_watch.h): the port's exclusivity, or an assert over events.
  | 'expect' 'exclusive' portRef ';'                                     # expectExclusive
  | 'expect' assertDecl                                                  # expectAssert
  // A resource's claim (docs/checks.md#resource), judged as the runtime checks judge it
  // (runtime/delivery_watch.h): no two of its ports receive a command that uses it in one state.
  | 'expect' 'resource' ID ';'                                           # expectResource
  // An event state at an instant, read in the container of the port after `in` (each
  // arbitrated port holds its own events: docs/design.md#feeds).
  | 'expect' expr ('in' portRef)? testWindow ';'                        # expectState
  ;
testWindow : 'at' duration | 'within' duration '..' duration ;

portRef  : ID '.' ID ;
duration : DURATION | NUMBER | ID ;

// `list<T>`, `list<T, N>` (at most N), `string<N>` (at most N bytes), `T[N]` (exactly N).
typeExpr
  : ID ('<' (typeExpr | size=NUMBER) (',' bound=NUMBER)? '>')? arraySize?   # namedType
  | '{' (fieldType (',' fieldType)* ','?)? '}' arraySize?                   # recordType
  ;
arraySize : '[' NUMBER ']' ;
fieldType : ID ':' typeExpr ;

block : '{' stmt* '}' ;

stmt
  : 'let' ID '=' expr ';'                                         # letStmt
  | 'var' ID '=' expr ';'                                         # varStmt
  | ID '=' expr ';'                                               # assignStmt
  | 'accept' expr ';'                                             # acceptStmt
  | 'set' ID ('for' duration)? ';'                                # setStmt
  | 'unset' ID ';'                                                # unsetStmt
  | 'if' expr block ('else' 'if' expr block)* ('else' block)?     # ifStmt
  | 'emit' expr ';'                                               # emitStmt
  | 'throttle' duration ';'                                       # throttleStmt
  | 'every' duration block                                        # everyStmt
  | 'script' STRING ';'                                           # scriptStmt
  ;

// Highest precedence first. `not` binds looser than comparison: `not x < 3` is `not (x < 3)`,
// `not a and b` is `(not a) and b`.
expr
  : expr '.' ID                                                   # fieldExpr
  | expr '[' expr ']'                                             # indexExpr
  | '-' expr                                                      # negExpr
  | expr op=('*' | '/' | '%') expr                                # mulExpr
  | expr op=('+' | '-') expr                                      # addExpr
  | expr op=('<' | '<=' | '>' | '>=' | '==' | '!=') expr          # compareExpr
  | 'not' expr                                                    # notExpr
  | expr 'and' expr                                               # andExpr
  | expr 'or' expr                                                # orExpr
  | ID '=>' expr                                                  # lambdaExpr
  | primary                                                       # primaryExpr
  ;

primary
  : NUMBER                                                        # numberLit
  | DURATION                                                      # durationLit
  | STRING                                                        # stringLit
  | 'true'                                                        # trueLit
  | 'false'                                                       # falseLit
  | 'otherwise'                                                   # otherwiseLit
  | ID '(' (expr (',' expr)*)? ')'                                # callExpr
  | ID                                                            # nameExpr
  | '(' expr ')'                                                  # parenExpr
  | '{' (fieldInit (',' fieldInit)* ','?)? '}'                    # recordLit
  | '[' (expr (',' expr)* ','?)? ']'                              # listLit
  ;
fieldInit : ID ':' expr ;

// ---- Lexer ----------------------------------------------------------------------------------
DURATION : DIGITS ('.' DIGITS)? ('ms' | 's' | 'min') ;
NUMBER   : DIGITS ('.' DIGITS)? ([eE] [+-]? DIGITS)? ;
// A number glued to letters that are not a unit (`2m`, `5sec`): named by the front end.
BAD_NUMBER : DIGITS ('.' DIGITS)? [a-zA-Z_] [a-zA-Z_0-9]* ;
ID       : [a-zA-Z_] [a-zA-Z_0-9]* ;
STRING   : '"' (~["\\\r\n] | '\\' ~[\r\n])* '"' ;
UNTERMINATED_STRING : '"' (~["\\\r\n] | '\\' ~[\r\n])* ;

LINE_COMMENT  : '//' ~[\r\n]* -> skip ;
BLOCK_COMMENT : '/*' .*? '*/' -> skip ;
UNTERMINATED_COMMENT : '/*' (~'*' | '*'+ ~[*/])* '*'* EOF ;
WS            : [ \t\r\n\f]+ -> skip ;
ERROR_CHAR    : . ;

fragment DIGITS : [0-9]+ ;
